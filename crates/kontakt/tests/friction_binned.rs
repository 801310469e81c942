#![allow(clippy::unwrap_used)]
//! The friction integral of the contact element's PimP back-end, 2 × 2 cells per evaluation
//! of the Coulomb law (`friction::grid_friction_binned`, issue 12), against the cell-by-cell
//! sums of `grid_friction` on the same field: a Hertz ellipse (a = 0.7 mm, b = 0.2 mm, turned
//! by 0.4 rad, p₀ = 1200 MPa) spinning about poles from 2 to 400 mm away, even and odd grids.
//! Errors are relative to the friction's own scales: force to `T = Σ |τ| ΔA`, moment to
//! `T a`, power to `T v_max`. Units: mm, N, MPa, mm/s; power in W.

use kontakt::friction::{
    BINNED_TOLERANCE, CellLaw, FilmState, FrictionLaw, GridFriction, binning_error, grid_friction,
    grid_friction_binned,
};
use kontakt::geometry::{Grid2, VelocityField};

const A: f64 = 0.7;
const B: f64 = 0.2;
const TURN: f64 = 0.4;
const P0: f64 = 1200.0;

/// A spin `ω` \[rad/s\] about the in-plane pole `(xp, yp)` \[mm\].
fn pole(omega: f64, xp: f64, yp: f64) -> VelocityField {
    VelocityField {
        sliding: [[omega * yp, -omega * xp], [0.0, omega], [-omega, 0.0]],
        entrainment: [[0.0; 2]; 3],
    }
}

/// The Hertz pressure on `nx × ny` cells over the ellipse's bounding box (+5 %).
fn hertz(nx: usize, ny: usize) -> (Grid2, Vec<f64>) {
    let (s, c) = TURN.sin_cos();
    let hx = (A * A * c * c + B * B * s * s).sqrt() * 1.05;
    let hy = (A * A * s * s + B * B * c * c).sqrt() * 1.05;
    let grid = Grid2::centered(hx, hy, nx, ny).unwrap();
    let pressure = grid
        .points()
        .map(|(x, y)| {
            let (xp, yp) = (c * x + s * y, -s * x + c * y);
            let r2 = (xp / A).powi(2) + (yp / B).powi(2);
            if r2 < 1.0 {
                P0 * (1.0 - r2).sqrt()
            } else {
                0.0
            }
        })
        .collect();
    (grid, pressure)
}

fn coulomb() -> CellLaw {
    FrictionLaw::coulomb(0.1)
        .unwrap()
        .with_film(&FilmState::dry())
        .unwrap()
}

/// Errors of `got` against `want` relative to T, T a and T v_max.
fn errors(got: &GridFriction, want: &GridFriction, f: &VelocityField, grid: &Grid2) -> f64 {
    let t = 0.1 * want.normal_force;
    let vmax = grid
        .points()
        .map(|(x, y)| {
            let [vx, vy] = f.sliding_at(x, y);
            vx.hypot(vy)
        })
        .fold(0.0, f64::max);
    let df = (got.force[0] - want.force[0]).hypot(got.force[1] - want.force[1]);
    let e: [f64; 4] = [
        df / t,
        (got.moment - want.moment).abs() / (t * A),
        (got.power - want.power).abs() / (t * vmax / 1e3),
        (got.normal_force - want.normal_force).abs() / want.normal_force,
    ];
    println!(
        "  force / moment / power / load: {:.2e} {:.2e} {:.2e} {:.2e}",
        e[0], e[1], e[2], e[3]
    );
    e.into_iter().fold(0.0, f64::max)
}

/// Poles from 2 to 400 mm away (10 rad/s), 64² and odd 63 × 45 grids: wherever the bound
/// allows the blocks (at most `BINNED_TOLERANCE`), the error is at most the bound (and so
/// at most the tolerance); the bench's pole (37.8 mm, the torus roller end at its pitch
/// radius) is among them and does use the blocks.
#[test]
fn binned_friction_matches_the_cell_sums_within_its_bound() {
    let law = coulomb();
    let mut binned = 0;
    for (nx, ny) in [(64, 64), (63, 45)] {
        let (grid, pressure) = hertz(nx, ny);
        for dist in [2.0, 5.0, 10.0, 20.0, 37.8, 100.0, 400.0] {
            for angle in [0.0f64, 1.0, 2.5] {
                let f = pole(10.0, dist * angle.cos(), dist * angle.sin());
                let want = grid_friction(&grid, &pressure, &f, &law).unwrap();
                let got = grid_friction_binned(&grid, &pressure, &f, &law).unwrap();
                let bound = binning_error(&grid, &f);
                let e = errors(&got, &want, &f, &grid);
                println!(
                    "{nx} x {ny}, pole {dist:6.1} mm at {angle} rad: bound {bound:.2e}, error {e:.2e}"
                );
                if bound <= BINNED_TOLERANCE {
                    binned += 1;
                    assert!(e <= bound, "{dist} mm: {e} > bound {bound}");
                    assert!(e > 0.0, "the blocks were not used at {dist} mm");
                } else {
                    assert_eq!(got, want, "{dist} mm: not the cell sums beyond the bound");
                }
            }
        }
        // The bench's contact (pole 37.8 mm from a 1.4 mm wide zone, 64 cells across).
        let f = pole(10.0, 0.0, 37.75);
        if nx == 64 {
            assert!(binning_error(&grid, &f) <= BINNED_TOLERANCE);
        }
    }
    assert!(binned >= 18, "only {binned} cases used the blocks");
}

/// A pole inside the zone, a fluid law (not linear in the pressure): the cell-by-cell sums,
/// bit for bit; a NaN pressure: the same error.
#[test]
fn binned_friction_falls_back_where_the_blocks_do_not_hold() {
    let (grid, pressure) = hertz(64, 64);
    let law = coulomb();
    let near = pole(10.0, 0.1, 0.05);
    assert_eq!(binning_error(&grid, &near), f64::INFINITY);
    assert_eq!(
        grid_friction_binned(&grid, &pressure, &near, &law).unwrap(),
        grid_friction(&grid, &pressure, &near, &law).unwrap()
    );
    let film = FilmState::new(2e-4, 1.0, 2e-8, 0.015).unwrap();
    let mixed = FrictionLaw::mixed(0.12).unwrap().with_film(&film).unwrap();
    let far = pole(10.0, 0.0, 37.75);
    assert_eq!(
        grid_friction_binned(&grid, &pressure, &far, &mixed).unwrap(),
        grid_friction(&grid, &pressure, &far, &mixed).unwrap()
    );
    let mut bad = pressure.clone();
    bad[2000] = f64::NAN;
    assert!(grid_friction_binned(&grid, &bad, &far, &law).is_err());
}

/// Every block shape of `BLOCK_SHAPES` (2 × 2 to 4 × 4, 2 × 8 and 8 × 2 cells): the Hertz
/// field above on grids of cells from square to 16:1 either way (even and odd counts, so the
/// last blocks are padded), spin poles 10 to 2000 mm away. Wherever a shape is chosen, its
/// bound `block_error` is at most `BINNED_TOLERANCE` (1e-6) and the error against the cell
/// sums (force, moment, power, load, each relative to its scale) is at most that bound; every
/// shape is chosen somewhere, and the largest one the bound allows.
#[test]
fn every_block_shape_matches_the_cell_sums_within_its_bound() {
    use kontakt::friction::{BLOCK_SHAPES, binning_blocks, block_error};
    let law = coulomb();
    let mut seen = Vec::new();
    let mut worst = 0.0f64;
    for (nx, ny) in [
        (64, 64),
        (16, 128),
        (128, 16),
        (33, 97),
        (97, 33),
        (50, 52),
        (24, 192),
        (192, 24),
        (48, 128),
    ] {
        let (grid, pressure) = hertz(nx, ny);
        for dist in [10.0, 20.0, 37.8, 60.0, 100.0, 400.0, 2000.0] {
            let f = pole(10.0, dist * 0.3f64.cos(), dist * 0.3f64.sin());
            let shape = binning_blocks(&grid, &f);
            let want = grid_friction(&grid, &pressure, &f, &law).unwrap();
            let got = grid_friction_binned(&grid, &pressure, &f, &law).unwrap();
            let e = errors(&got, &want, &f, &grid);
            println!("{nx} x {ny}, pole {dist:6.1} mm: blocks {shape:?}, error {e:.2e}");
            let Some(shape) = shape else {
                assert_eq!(got, want, "{nx} x {ny}, {dist} mm: not the cell sums");
                continue;
            };
            let bound = block_error(&grid, &f, shape);
            assert!(bound <= BINNED_TOLERANCE, "{shape:?}: bound {bound}");
            assert_eq!(bound, binning_error(&grid, &f));
            assert!(
                e <= bound,
                "{nx} x {ny}, {dist} mm, {shape:?}: {e} > bound {bound}"
            );
            // No shape with more cells qualifies.
            for other in BLOCK_SHAPES {
                if other[0] * other[1] > shape[0] * shape[1] {
                    assert!(
                        block_error(&grid, &f, other) > BINNED_TOLERANCE,
                        "{other:?}"
                    );
                }
            }
            worst = worst.max(e / bound);
            if !seen.contains(&shape) {
                seen.push(shape);
            }
        }
    }
    println!("shapes used: {seen:?}; largest error / bound {worst:.2e}");
    for shape in BLOCK_SHAPES {
        assert!(seen.contains(&shape), "{shape:?} never chosen");
    }
}
