//! The shape of a contact zone from a sampled pressure field: area, extents, centre of
//! pressure, separate patches and the curvature of the zone's centre line.

use crate::error::Result;
use crate::gap::check_len;
use crate::geometry::Grid2;

/// Shape statistics of a pressure field on a grid (all in the grid's frame).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ContactZone {
    /// Contact area: the number of loaded cells times the cell area \[mm²\].
    pub area: f64,
    /// Resultant normal force, the sum of pressure times cell area \[N\].
    pub force: f64,
    /// Largest cell pressure \[MPa\].
    pub max_pressure: f64,
    /// Where the largest pressure acts `[x, y]` \[mm\].
    pub max_pressure_at: [f64; 2],
    /// `[[x_min, x_max], [y_min, y_max]]` \[mm\] of the loaded cells (cell edges).
    pub extents: [[f64; 2]; 2],
    /// Centre of pressure `[x, y]` \[mm\].
    pub centroid: [f64; 2],
    /// Number of separate loaded patches (cells joined through their edges).
    pub patches: usize,
    /// Curvature \[1/mm\] at `x = centroid` of the zone's centre line `y_c(x)`, the
    /// force-weighted mean `y` of each column, fitted by a weighted parabola; positive
    /// when the zone bends towards `+y` at its ends. `None` with fewer than 5 loaded
    /// columns. Zero for an ellipse aligned with the grid, non-zero for the curved
    /// ("banana") zones of tori.
    pub centre_line_curvature: Option<f64>,
    /// Whether loaded cells lie in the outermost column (`[0]`) or row (`[1]`) of the
    /// grid: the zone may be cut off by the grid border.
    pub touches_border: [bool; 2],
}

impl ContactZone {
    /// The zone of a field with no loaded cell: zero area, force and pressure, no patch.
    pub const EMPTY: ContactZone = ContactZone {
        area: 0.0,
        force: 0.0,
        max_pressure: 0.0,
        max_pressure_at: [0.0; 2],
        extents: [[0.0; 2]; 2],
        centroid: [0.0; 2],
        patches: 0,
        centre_line_curvature: None,
        touches_border: [false; 2],
    };

    /// Analyse `pressure` \[MPa\] sampled on `grid` (row-major, x fastest).
    ///
    /// Allocates the patch count's work arrays; a caller that analyses many fields keeps a
    /// [`ZoneScratch`] and calls [`ContactZone::analyse_in`].
    ///
    /// # Errors
    /// [`crate::Error::InvalidInput`] when the lengths disagree.
    pub fn analyse(grid: &Grid2, pressure: &[f64]) -> Result<Self> {
        Self::analyse_in(grid, pressure, &mut ZoneScratch::default())
    }

    /// [`ContactZone::analyse`] with caller-owned work arrays: after the first call on a
    /// grid of a given size, a call allocates nothing.
    ///
    /// # Errors
    /// [`crate::Error::InvalidInput`] when the lengths disagree.
    pub fn analyse_in(grid: &Grid2, pressure: &[f64], scratch: &mut ZoneScratch) -> Result<Self> {
        let mut zone = Self::summarise(grid, pressure)?;
        if zone.patches > 0 {
            let (nx, ny) = (grid.nx(), grid.ny());
            zone.patches = count_patches(nx, ny, pressure, scratch);
            zone.centre_line_curvature = centre_line_curvature(grid, pressure, zone.centroid[0]);
        }
        Ok(zone)
    }

    /// The one-pass part of [`ContactZone::analyse`]: area, force, largest pressure and
    /// where it acts, extents, centre of pressure and border contact, the same values bit
    /// for bit; the patches are not counted (`patches` is 1 when a cell is loaded, 0
    /// otherwise) and the centre line's curvature is `None`. For callers that need no
    /// shape (the contact element's warm half-space calls); allocates nothing.
    ///
    /// # Errors
    /// [`crate::Error::InvalidInput`] when the lengths disagree.
    pub(crate) fn summarise(grid: &Grid2, pressure: &[f64]) -> Result<Self> {
        check_len(grid, pressure)?;
        let (nx, ny) = (grid.nx(), grid.ny());
        let da = grid.cell_area();
        let (mut force, mut cells, mut pmax, mut at) = (0.0, 0usize, 0.0, [0.0; 2]);
        let (mut mx, mut my) = (0.0, 0.0);
        let (mut i0, mut i1, mut j0, mut j1) = (usize::MAX, 0, usize::MAX, 0);
        let mut border = [false; 2];
        for j in 0..ny {
            for i in 0..nx {
                let p = pressure[j * nx + i];
                if p > 0.0 {
                    let (x, y) = (grid.x(i), grid.y(j));
                    cells += 1;
                    force += p * da;
                    mx += p * x;
                    my += p * y;
                    if p > pmax {
                        pmax = p;
                        at = [x, y];
                    }
                    i0 = i0.min(i);
                    i1 = i1.max(i);
                    j0 = j0.min(j);
                    j1 = j1.max(j);
                    border[0] |= i == 0 || i + 1 == nx;
                    border[1] |= j == 0 || j + 1 == ny;
                }
            }
        }
        if cells == 0 {
            return Ok(ContactZone::EMPTY);
        }
        let (dx, dy) = (grid.dx(), grid.dy());
        let psum = force / da;
        let centroid = [mx / psum, my / psum];
        Ok(ContactZone {
            area: cells as f64 * da,
            force,
            max_pressure: pmax,
            max_pressure_at: at,
            extents: [
                [grid.x(i0) - 0.5 * dx, grid.x(i1) + 0.5 * dx],
                [grid.y(j0) - 0.5 * dy, grid.y(j1) + 0.5 * dy],
            ],
            centroid,
            patches: 1,
            centre_line_curvature: None,
            touches_border: border,
        })
    }

    /// Half-extents `[(x_max - x_min)/2, (y_max - y_min)/2]` \[mm\]: the semi-axes for an
    /// elliptical zone aligned with the grid.
    pub fn half_extents(&self) -> [f64; 2] {
        [
            0.5 * (self.extents[0][1] - self.extents[0][0]),
            0.5 * (self.extents[1][1] - self.extents[1][0]),
        ]
    }
}

/// The work arrays of [`ContactZone::analyse_in`]'s patch count (a flag and a stack entry
/// per cell at most), kept between calls so that the analysis allocates nothing.
#[derive(Debug, Clone, Default)]
pub struct ZoneScratch {
    seen: Vec<bool>,
    stack: Vec<usize>,
}

/// Connected components of the loaded cells (4-neighbourhood): 1 at once for a zone that
/// [`one_run_per_row`] shows to be one patch (every convex zone, the Hertz ellipse), else
/// by flood fill.
fn count_patches(nx: usize, ny: usize, pressure: &[f64], scratch: &mut ZoneScratch) -> usize {
    if one_run_per_row(nx, ny, pressure) {
        return 1;
    }
    flood_fill_patches(nx, ny, pressure, scratch)
}

/// Whether the loaded cells (`p > 0`), at least one, lie in consecutive rows, in one run
/// of adjacent cells per row, each run sharing a column with the run of the row before:
/// then every run is joined to the one before through an edge, and the cells form one
/// patch. `false` says nothing (the flood fill counts). One pass over the rows, no memory.
fn one_run_per_row(nx: usize, ny: usize, pressure: &[f64]) -> bool {
    // The run [first, last] of the last loaded row, and whether an empty row followed it.
    let mut before: Option<(usize, usize)> = None;
    let mut gap = false;
    for row in pressure.chunks_exact(nx).take(ny) {
        let Some(first) = row.iter().position(|&p| p > 0.0) else {
            gap |= before.is_some();
            continue;
        };
        let run = row[first..].iter().take_while(|&&p| p > 0.0).count();
        let last = first + run - 1;
        if gap || row[last + 1..].iter().any(|&p| p > 0.0) {
            return false;
        }
        if let Some((f, l)) = before
            && (first > l || last < f)
        {
            return false;
        }
        before = Some((first, last));
    }
    before.is_some()
}

/// Connected components of the loaded cells (4-neighbourhood), by flood fill.
fn flood_fill_patches(nx: usize, ny: usize, pressure: &[f64], scratch: &mut ZoneScratch) -> usize {
    let ZoneScratch { seen, stack } = scratch;
    seen.clear();
    seen.resize(pressure.len(), false);
    stack.clear();
    // Every cell is pushed at most once, so this capacity is never exceeded.
    stack.reserve(pressure.len());
    let mut patches = 0;
    for start in 0..pressure.len() {
        if seen[start] || !(pressure[start] > 0.0) {
            continue;
        }
        patches += 1;
        seen[start] = true;
        stack.push(start);
        while let Some(k) = stack.pop() {
            let (i, j) = (k % nx, k / nx);
            let neighbours = [
                (i > 0).then(|| k - 1),
                (i + 1 < nx).then(|| k + 1),
                (j > 0).then(|| k - nx),
                (j + 1 < ny).then(|| k + nx),
            ];
            for n in neighbours.into_iter().flatten() {
                if !seen[n] && pressure[n] > 0.0 {
                    seen[n] = true;
                    stack.push(n);
                }
            }
        }
    }
    patches
}

/// Weighted least-squares parabola through the column centres `y_c(x)`, curvature at
/// `x0`: `kappa = y'' / (1 + y'^2)^(3/2)`. (Gathering the column sums row by row in
/// memory order gave the same bits and 9 % on a bearing's Hertz rib fields, but made
/// PimP's rib fields 35 % slower: measured, and left column by column.)
fn centre_line_curvature(grid: &Grid2, pressure: &[f64], x0: f64) -> Option<f64> {
    let (nx, ny) = (grid.nx(), grid.ny());
    // Normal equations of y = c0 + c1 t + c2 t², t = x - x0, weights = column force.
    let mut s = [0.0f64; 5]; // sums of w t^k, k = 0..4
    let mut r = [0.0f64; 3]; // sums of w t^k y_c
    let mut columns = 0;
    for i in 0..nx {
        let (mut w, mut wy) = (0.0, 0.0);
        for j in 0..ny {
            let p = pressure[j * nx + i];
            if p > 0.0 {
                w += p;
                wy += p * grid.y(j);
            }
        }
        if w > 0.0 {
            columns += 1;
            let (t, yc) = (grid.x(i) - x0, wy / w);
            let mut tk = 1.0;
            for (k, sk) in s.iter_mut().enumerate() {
                *sk += w * tk;
                if k < 3 {
                    r[k] += w * tk * yc;
                }
                tk *= t;
            }
        }
    }
    if columns < 5 {
        return None;
    }
    let m = nalgebra::Matrix3::new(s[0], s[1], s[2], s[1], s[2], s[3], s[2], s[3], s[4]);
    let c = m.lu().solve(&nalgebra::Vector3::new(r[0], r[1], r[2]))?;
    let slope = c[1];
    Some(2.0 * c[2] / (1.0 + slope * slope).powf(1.5))
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    /// A uniform number in [0, 1) from a 64-bit LCG (Knuth's MMIX constants).
    fn uniform(state: &mut u64) -> f64 {
        *state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (*state >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Fields that exercise both paths of the patch count: turned and banana-shaped
    /// ellipses (one run per row), rings, two blobs, cells touching at a corner only,
    /// random speckle, NaN cells, and zones with an empty row between loaded ones.
    fn fields(grid: &Grid2, state: &mut u64) -> Vec<Vec<f64>> {
        let mut out = Vec::new();
        let points: Vec<(f64, f64)> = grid.points().collect();
        for _ in 0..40 {
            let (a, b) = (0.2 + uniform(state), 0.2 + uniform(state));
            let (cx, cy) = (uniform(state) - 0.5, uniform(state) - 0.5);
            let (s, c) = (6.0 * uniform(state)).sin_cos();
            let bend = 2.0 * uniform(state) - 1.0;
            let hole = 0.8 * uniform(state);
            let ellipse = |&(x, y): &(f64, f64)| {
                let (x, y) = (x - cx, y - cy);
                let (u, v) = (c * x + s * y, -s * x + c * y - bend * x * x);
                1.0 - (u / a).powi(2) - (v / b).powi(2)
            };
            out.push(points.iter().map(|p| 1e3 * ellipse(p).max(0.0)).collect());
            out.push(
                points
                    .iter()
                    .map(|p| {
                        let e = ellipse(p);
                        if e > 0.0 && e < hole { 5.0 } else { 0.0 }
                    })
                    .collect(),
            );
            let density = uniform(state);
            out.push(
                points
                    .iter()
                    .map(|_| if uniform(state) < density { 1.0 } else { -1.0 })
                    .collect(),
            );
        }
        let nx = grid.nx();
        out.push(vec![0.0; grid.len()]);
        if nx < 4 || grid.ny() < 3 {
            return out;
        }
        let mut corner = vec![0.0; grid.len()];
        corner[nx + 1] = 1.0;
        corner[2 * nx + 2] = 1.0;
        out.push(corner.clone());
        corner[2 * nx + 1] = f64::NAN;
        out.push(corner.clone());
        corner[2 * nx + 1] = 2.0;
        out.push(corner);
        let mut gap = vec![0.0; grid.len()];
        gap[3] = 1.0;
        gap[2 * nx + 3] = 1.0;
        out.push(gap.clone());
        gap[nx + 3] = 1.0;
        out.push(gap);
        out
    }

    /// The row-run shortcut of the patch count says 1 only where the flood fill counts one
    /// patch, and the count with it equals the flood fill's on every field.
    #[test]
    fn shortcuts_equal_the_full_analysis() {
        let mut state = 29;
        let mut scratch = ZoneScratch::default();
        let (mut shortcut, mut filled) = (0, 0);
        for (nx, ny) in [(64, 64), (17, 9), (5, 31), (1, 12), (12, 1)] {
            let grid = Grid2::centered(1.3, 0.9, nx, ny).unwrap();
            for p in fields(&grid, &mut state) {
                let flood = flood_fill_patches(nx, ny, &p, &mut scratch);
                if one_run_per_row(nx, ny, &p) {
                    assert_eq!(flood, 1, "{nx} x {ny}");
                    shortcut += 1;
                } else {
                    filled += 1;
                }
                assert_eq!(count_patches(nx, ny, &p, &mut scratch), flood);
                let zone = ContactZone::analyse_in(&grid, &p, &mut scratch).unwrap();
                assert_eq!(zone.patches, flood);
            }
        }
        // Both paths taken, many times.
        assert!(shortcut > 50 && filled > 50, "{shortcut} {filled}");
    }
}
