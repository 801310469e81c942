//! A whole bearing solved for many loads: [`BearingModel`] holds the solver plan of a
//! bearing case (`method = "bearing"`, [`crate::bearing_case`]) and warm-starts every solve
//! from the last equilibrium (`RollerBearingSolver::solve_from`). Each solve gives the
//! [`BearingReport`] that [`crate::run_bearing_case`] gives for the same case and load (the
//! same keys and, up to the last digits of the Newton iteration, the same numbers); only
//! `solver.iterations` tells a warm solve from a cold one.
//!
//! The Python class `kontakt.Bearing` and a multi-body bearing element are built on this.

use crate::bearing_case::{
    BearingCase, BearingLoadSpec, BearingReport, BearingSolverEcho, BearingSpec, ProfileSpec,
    RollerRow, STEEL_CONTACT_MODULUS_MPA, SliceTable,
};
use crate::common::{SCHEMA_VERSION, in_degrees};
use crate::validity::checked;
use kontakt::solve::Termination;
use kontakt::{Error, Result};
use kontakt_bearing::equilibrium::{
    DISPLACEMENT_NAMES, Dof, FORCE_NAMES, RingLoad, RollerBearingSolver,
};
use kontakt_bearing::geometry::{DEFAULT_SLICES, RollerBearing, RollerBearingKind};
use kontakt_bearing::profile::{Profile, TabulatedProfile};

/// The order of the stiffness matrix's rows and columns.
const DOFS: [&str; 5] = ["x_mm", "y_mm", "z_mm", "tilt_x_rad", "tilt_y_rad"];

/// A bearing of a case, planned once and solved for many loads of its inner ring.
#[derive(Debug, Clone)]
pub struct BearingModel {
    name: Option<String>,
    label: &'static str,
    solver: RollerBearingSolver,
    /// The displacement of the last converged solve, the start of the next one.
    last: Option<[f64; 5]>,
}

impl BearingModel {
    /// Plan the bearing of `case` (its `[load]` is not used: see [`BearingModel::solve`]).
    ///
    /// # Errors
    /// As [`crate::run_bearing_case`] for the `[bearing]` table and `method`: errors name
    /// the case key (`bearing.roller_diameter_mm`, `bearing.roller_profile.load_n`).
    pub fn new(case: &BearingCase) -> Result<Self> {
        if case.method != "bearing" {
            return Err(Error::invalid(
                "method",
                &case.method,
                "\"bearing\" for this schema",
            ));
        }
        let (bearing, label) = roller_bearing(&case.bearing)?;
        let solver = RollerBearingSolver::new(bearing).map_err(map_bearing_field)?;
        Ok(BearingModel {
            name: case.name.clone(),
            label,
            solver,
            last: None,
        })
    }

    /// The bearing type of the case: `"cylindrical"`, `"tapered"` or `"thrust"`.
    pub fn bearing_type(&self) -> &'static str {
        self.label
    }

    /// Forget the last equilibrium: the next solve starts from the closed forms.
    pub fn reset(&mut self) {
        self.last = None;
    }

    /// The displacement the next solve starts from, `(δx, δy, δz, θx, θy)` mm and rad;
    /// `None` before the first converged solve, after [`BearingModel::reset`] and after a
    /// solve with every roller lifted off (then the next solve starts from the closed forms).
    pub fn warm_start(&self) -> Option<[f64; 5]> {
        self.last
    }

    /// Solve the equilibrium under `load` (forces N, moments N·mm, prescribed
    /// displacements mm and rad, as the case's `[load]`), from the last converged
    /// equilibrium when there is one, and report it as [`crate::run_bearing_case`] does.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the case key of the load (`load.force_n[2]`,
    /// `load.prescribed.tilt_x_rad`); [`Error::NotConverged`] for an equilibrium that ends
    /// at the iteration limit or diverges (the warm start is kept).
    pub fn solve(&mut self, load: &BearingLoadSpec) -> Result<BearingReport> {
        let report = checked(self.solve_unchecked(load)?)?;
        // with every roller lifted off the displacement says nothing about the next load:
        // the closed-form start is the better one
        self.last = (report.max_roller_load_n > 0.0).then_some([
            report.displacement_mm[0],
            report.displacement_mm[1],
            report.displacement_mm[2],
            report.tilt_rad[0],
            report.tilt_rad[1],
        ]);
        Ok(report)
    }

    fn solve_unchecked(&mut self, l: &BearingLoadSpec) -> Result<BearingReport> {
        let load = ring_load(l)?;
        let map_load = |e: Error| e.map_field(|f| load_key(f).unwrap_or_else(|| f.to_string()));
        let solver = &mut self.solver;
        // zero load: the closed-form start is the exact answer (every roller lifted off);
        // Newton from an old equilibrium would end at the round-off floor instead
        let p = &l.prescribed;
        let unloaded = l.force_n.iter().chain(&l.moment_nmm).all(|f| *f == 0.0)
            && [p.dx_mm, p.dy_mm, p.dz_mm, p.tilt_x_rad, p.tilt_y_rad]
                .iter()
                .all(|u| u.is_none_or(|u| u == 0.0));
        let start = if unloaded { None } else { self.last };
        let sol = match start {
            Some(start) => solver.solve_from(&load, start),
            None => solver.solve(&load),
        }
        .map_err(map_load)?;
        let mut warnings = Vec::new();
        match sol.status.termination {
            Termination::Converged => {}
            Termination::Stagnated => warnings.push(format!(
                "the equilibrium stagnated at the round-off floor after {} iterations (residual {:.1e} of the load, tolerance 1e-11)",
                sol.status.iterations, sol.status.residual
            )),
            _ => {
                let what = format!(
                    "bearing equilibrium: {}",
                    sol.note.unwrap_or("no equilibrium")
                );
                sol.status.require_converged(what)?;
            }
        }
        if let Some(note) = sol.note
            && sol.status.termination == Termination::Converged
        {
            warnings.push(note.to_string());
        }
        let b = solver.bearing();
        if b.slices < DEFAULT_SLICES {
            warnings.push(format!(
                "{} slices per roller: fewer than the recommended {DEFAULT_SLICES}, the roller loads are coarse (docs/bearing-model.md §6)",
                b.slices
            ));
        }
        let ns = b.slices;
        let width = b.effective_length_mm / ns as f64;
        let loads = solver.slice_loads();
        let approaches = solver.slice_approaches();
        let mut rows = Vec::with_capacity(b.rollers);
        let mut most = 0;
        let mut q_max = f64::NEG_INFINITY;
        for (j, r) in solver.roller_loads().iter().enumerate() {
            let slice_max = loads[j * ns..(j + 1) * ns]
                .iter()
                .copied()
                .fold(0.0, f64::max);
            if r.outer_n > q_max {
                q_max = r.outer_n;
                most = j;
            }
            rows.push(RollerRow {
                azimuth_deg: r.azimuth_rad.to_degrees(),
                inner_load_n: r.inner_n,
                outer_load_n: r.outer_n,
                rib_load_n: r.rib_n,
                max_load_per_length_n_per_mm: slice_max / width,
                approach_mm: r.max_approach_mm,
            });
        }
        let slice_loads = loads[most * ns..(most + 1) * ns].to_vec();
        let most_loaded = SliceTable {
            roller: most,
            position_mm: solver.slice_positions().to_vec(),
            load_per_length_n_per_mm: slice_loads.iter().map(|q| q / width).collect(),
            load_n: slice_loads,
            approach_mm: approaches[most * ns..(most + 1) * ns].to_vec(),
        };
        let u = sol.displacement;
        Ok(BearingReport {
            kontakt_version: kontakt::VERSION,
            schema_version: SCHEMA_VERSION,
            name: self.name.clone(),
            method: "bearing",
            bearing_type: self.label,
            rollers: b.rollers,
            slices: ns,
            contact_angle_deg: b.contact_angle_rad.to_degrees(),
            cone_angle_deg: b.cone_angle_rad.to_degrees(),
            roller_stiffness_n_per_mm10_9: b.roller_stiffness(),
            displacement_mm: [u[0], u[1], u[2]],
            tilt_rad: [u[3], u[4]],
            force_n: [sol.load[0], sol.load[1], sol.load[2]],
            moment_nmm: [sol.load[3], sol.load[4]],
            solver: BearingSolverEcho {
                converged: sol.status.converged(),
                termination: sol.status.termination.as_str(),
                iterations: sol.status.iterations,
                residual: sol.status.residual,
            },
            load_zone_epsilon: sol.load_zone,
            max_roller_load_n: sol.max_roller_load_n,
            max_load_per_length_n_per_mm: rows
                .iter()
                .map(|r| r.max_load_per_length_n_per_mm)
                .fold(0.0, f64::max),
            roller_loads: rows,
            most_loaded_roller: most_loaded,
            stiffness_dofs: DOFS,
            stiffness_matrix: sol.stiffness,
            stiffness_units: stiffness_units(),
            warnings,
            contacts: Vec::new(),
        })
    }
}

/// The case's `[load]` as the library's [`RingLoad`]; a degree of freedom is force- or
/// displacement-controlled, not both.
fn ring_load(l: &BearingLoadSpec) -> Result<RingLoad> {
    let applied = [
        l.force_n[0],
        l.force_n[1],
        l.force_n[2],
        l.moment_nmm[0],
        l.moment_nmm[1],
    ];
    let p = &l.prescribed;
    let prescribed = [p.dx_mm, p.dy_mm, p.dz_mm, p.tilt_x_rad, p.tilt_y_rad];
    let mut dofs = [Dof::Force(0.0); 5];
    for i in 0..5 {
        dofs[i] = match prescribed[i] {
            Some(u) => {
                if applied[i] != 0.0 {
                    return Err(Error::invalid(
                        force_key(i),
                        applied[i],
                        format!(
                            "0 where load.prescribed.{} holds the displacement (a degree of freedom is force- or displacement-controlled)",
                            DISPLACEMENT_NAMES[i]
                        ),
                    ));
                }
                Dof::Displacement(u)
            }
            None => Dof::Force(applied[i]),
        };
    }
    Ok(RingLoad { dofs })
}

fn stiffness_units() -> [[&'static str; 5]; 5] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| match (i < 3, j < 3) {
            (true, true) => "N/mm",
            (true, false) => "N/rad",
            (false, true) => "N",
            (false, false) => "N*mm/rad",
        })
    })
}

/// The case-file key of a load component `i` (0..5): `load.force_n[2]`, `load.moment_nmm[0]`.
fn force_key(i: usize) -> String {
    if i < 3 {
        format!("load.force_n[{i}]")
    } else {
        format!("load.moment_nmm[{}]", i - 3)
    }
}

/// The library's load field (`load.fz_n`, `load.tilt_x_rad`) as the case file's key.
fn load_key(field: &str) -> Option<String> {
    let name = field.strip_prefix("load.")?;
    if let Some(i) = FORCE_NAMES.iter().position(|n| *n == name) {
        return Some(force_key(i));
    }
    DISPLACEMENT_NAMES
        .iter()
        .position(|n| *n == name)
        .map(|i| format!("load.prescribed.{}", DISPLACEMENT_NAMES[i]))
}

/// The library profile for a roller of length `l` and diameter `d` (mm); errors named by
/// the library's field (`x_mm[2]`), prefixed by the caller.
fn profile(p: &ProfileSpec, l: f64, d: f64) -> Result<Profile> {
    let e = |m: Option<f64>| m.unwrap_or(STEEL_CONTACT_MODULUS_MPA);
    Ok(match p {
        ProfileSpec::Straight => Profile::Straight,
        ProfileSpec::Iso => Profile::iso(l, d),
        ProfileSpec::LogarithmicFlat {
            drop_scale_mm,
            length_mm,
            flat_length_mm,
        } => Profile::Logarithmic {
            drop_scale_mm: *drop_scale_mm,
            length_mm: length_mm.unwrap_or(l),
            flat_length_mm: *flat_length_mm,
        },
        ProfileSpec::Lundberg {
            load_n,
            length_mm,
            contact_modulus_mpa,
        } => Profile::Lundberg {
            load_n: *load_n,
            length_mm: length_mm.unwrap_or(l),
            contact_modulus_mpa: e(*contact_modulus_mpa),
        },
        ProfileSpec::JohnsGohar {
            load_n,
            length_mm,
            contact_modulus_mpa,
            reduced_radius_mm,
        } => Profile::JohnsGohar {
            load_n: *load_n,
            length_mm: length_mm.unwrap_or(l),
            contact_modulus_mpa: e(*contact_modulus_mpa),
            reduced_radius_mm: *reduced_radius_mm,
        },
        ProfileSpec::Fujiwara {
            load_n,
            length_mm,
            contact_modulus_mpa,
            k1,
            k2,
            edge_drop_mm,
        } => Profile::Fujiwara {
            load_n: *load_n,
            length_mm: length_mm.unwrap_or(l),
            contact_modulus_mpa: e(*contact_modulus_mpa),
            k1: *k1,
            k2: *k2,
            edge_drop_mm: *edge_drop_mm,
        },
        ProfileSpec::Circular {
            radius_mm,
            flat_length_mm,
        } => Profile::Circular {
            radius_mm: *radius_mm,
            flat_length_mm: *flat_length_mm,
        },
        ProfileSpec::EdgeRadii {
            length_mm,
            edge_radius_mm,
            edge_length_mm,
        } => Profile::EdgeRadii {
            length_mm: length_mm.unwrap_or(l),
            edge_radius_mm: *edge_radius_mm,
            edge_length_mm: *edge_length_mm,
        },
        ProfileSpec::Tabulated { x_mm, drop_mm } => {
            Profile::Tabulated(TabulatedProfile::new(x_mm.clone(), drop_mm.clone())?)
        }
    })
}

/// The case's bearing as the library's [`RollerBearing`]: errors named by the case key.
fn roller_bearing(spec: &BearingSpec) -> Result<(RollerBearing, &'static str)> {
    let (kind, s, label) = match spec {
        BearingSpec::Cylindrical(s) => (RollerBearingKind::Cylindrical, s, "cylindrical"),
        BearingSpec::Tapered(s) => (RollerBearingKind::Tapered, s, "tapered"),
        BearingSpec::Thrust(s) => (RollerBearingKind::Thrust, s, "thrust"),
    };
    let (l, d) = (s.roller_length_mm, s.roller_diameter_mm);
    let mut b = match kind {
        RollerBearingKind::Cylindrical => {
            RollerBearing::cylindrical(s.pitch_diameter_mm, s.rollers, d, l)
        }
        RollerBearingKind::Thrust => RollerBearing::thrust(s.pitch_diameter_mm, s.rollers, d, l),
        RollerBearingKind::Tapered => {
            let need = |v: Option<f64>, key: &str| {
                v.ok_or_else(|| Error::CaseFile {
                    line: None,
                    key: format!("bearing.{key}").into(),
                    message: format!(
                        "missing key `bearing.{key}`: a tapered roller bearing needs its cup and cone angles [deg]"
                    ),
                })
            };
            let cup = need(s.cup_angle_deg, "cup_angle_deg")?;
            let cone = need(s.cone_angle_deg, "cone_angle_deg")?;
            let mut b = RollerBearing::tapered(
                s.pitch_diameter_mm,
                s.rollers,
                d,
                l,
                cup.to_radians(),
                cone.to_radians(),
            );
            b.rib_angle_rad = s.rib_angle_deg.map(f64::to_radians);
            b
        }
    };
    if kind != RollerBearingKind::Tapered {
        for (key, v) in [
            ("cup_angle_deg", s.cup_angle_deg),
            ("cone_angle_deg", s.cone_angle_deg),
            ("rib_angle_deg", s.rib_angle_deg),
        ] {
            if let Some(v) = v {
                return Err(Error::invalid(
                    format!("bearing.{key}"),
                    v,
                    format!(
                        "no {key} for type = \"{label}\" (its contact angle is fixed; the angles are for type = \"tapered\")"
                    ),
                ));
            }
        }
    }
    b.clearance_mm = s.clearance_mm;
    b.slices = s.slices;
    b.first_roller_azimuth_rad = s.first_roller_azimuth_deg.to_radians();
    // the profiles take the roller's length and diameter; `validate` checks those first
    for (name, p, slot) in [
        ("roller_profile", &s.roller_profile, 0),
        ("inner_profile", &s.inner_profile, 1),
        ("outer_profile", &s.outer_profile, 2),
    ] {
        let profile =
            profile(p, l, d).map_err(|e| e.map_field(|f| format!("bearing.{name}.{f}")))?;
        match slot {
            0 => b.roller_profile = profile,
            1 => b.inner_profile = profile,
            _ => b.outer_profile = profile,
        }
    }
    if s.rollers.saturating_mul(s.slices) > crate::bearing_case::MAX_BEARING_SLICES {
        return Err(Error::invalid(
            "bearing.slices",
            s.slices,
            format!(
                "rollers × slices <= {} (here {} rollers)",
                crate::bearing_case::MAX_BEARING_SLICES,
                s.rollers
            ),
        ));
    }
    b.validate().map_err(|e| {
        let e = map_bearing_field(e);
        // the angles are typed in degrees
        let e = in_degrees(
            e,
            "bearing.cup_angle_deg",
            "bearing.cup_angle_deg",
            s.cup_angle_deg.unwrap_or(0.0),
        );
        // the library's range names the cup angle in rad: say it in the file's degrees
        let e = match e {
            Error::InvalidInput { field, .. } if field == "bearing.cone_angle_deg" => {
                Error::invalid(
                    "bearing.cone_angle_deg",
                    s.cone_angle_deg.unwrap_or(0.0),
                    format!(
                        "0 < cone angle < cup_angle_deg = {} deg for a tapered roller bearing",
                        s.cup_angle_deg.unwrap_or(0.0)
                    ),
                )
            }
            other => other,
        };
        let rib = b.rib_angle().to_degrees();
        let e = in_degrees(e, "bearing.rib_angle_deg", "bearing.rib_angle_deg", rib);
        in_degrees(
            e,
            "bearing.first_roller_azimuth_deg",
            "bearing.first_roller_azimuth_deg",
            s.first_roller_azimuth_deg,
        )
    })?;
    Ok((b, label))
}

/// The library's field names of [`RollerBearing`] as the case file's keys.
fn map_bearing_field(e: Error) -> Error {
    e.map_field(|f| {
        let key = match f {
            "effective_length_mm" => "roller_length_mm",
            "contact_angle_rad" => "cup_angle_deg",
            "cone_angle_rad" => "cone_angle_deg",
            "rib_angle_rad" => "rib_angle_deg",
            "first_roller_azimuth_rad" => "first_roller_azimuth_deg",
            other => other,
        };
        format!("bearing.{key}")
    })
}

#[cfg(test)]
mod tests;
