//! Issue 28, bearing sweeps: a sweep whose base case is a bearing solves its cases on a
//! planned bearing with warm starts; every row must be the equilibrium of the cold
//! `run_bearing_case` of the same case (to the solver's tolerance), a case whose elements
//! all lift off a `lifted_off` row with zero force, a load the bearing cannot carry an
//! `invalid` row in the middle of the sweep, the numbers independent of the thread count,
//! and a case allocates nothing.

#![allow(clippy::unwrap_used)] // test helpers: a panic is a test failure with its message

#[path = "../../kontakt/tests/support/counting_alloc.rs"]
mod counting_alloc;

use arrow_array::{Array, BooleanArray, Float64Array, Int64Array, RecordBatch, StringArray};
use kontakt_case::sweep::Sweep;
use kontakt_case::{BearingReport, Case, run_bearing_case};
use std::path::{Path, PathBuf};

fn sweeps_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/sweeps")
}

fn example(name: &str) -> Sweep {
    Sweep::from_path(&sweeps_dir().join(name)).unwrap()
}

/// A sweep over `params` (TOML of `[[parameter]]` tables) of the example bearing `base`.
fn sweep(base: &str, params: &str) -> Sweep {
    Sweep::from_toml_str(&format!("base = \"../{base}\"\n{params}"), &sweeps_dir()).unwrap()
}

/// All chunks' tables on a pool of `threads` threads.
fn tables(s: &Sweep, threads: usize) -> Vec<RecordBatch> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    pool.install(|| {
        (0..s.chunk_count())
            .map(|c| s.chunk_table(c).unwrap())
            .collect()
    })
}

fn f64s(b: &RecordBatch, name: &str) -> Vec<Option<f64>> {
    let a = b
        .column_by_name(name)
        .unwrap_or_else(|| panic!("no {name}"));
    let a = a.as_any().downcast_ref::<Float64Array>().unwrap();
    (0..a.len())
        .map(|i| a.is_valid(i).then(|| a.value(i)))
        .collect()
}

fn strs(b: &RecordBatch, name: &str) -> Vec<Option<String>> {
    let a = b
        .column_by_name(name)
        .unwrap_or_else(|| panic!("no {name}"));
    let a = a.as_any().downcast_ref::<StringArray>().unwrap();
    (0..a.len())
        .map(|i| a.is_valid(i).then(|| a.value(i).to_string()))
        .collect()
}

fn ints(b: &RecordBatch, name: &str) -> Vec<Option<i64>> {
    let a = b.column_by_name(name).unwrap();
    let a = a.as_any().downcast_ref::<Int64Array>().unwrap();
    (0..a.len())
        .map(|i| a.is_valid(i).then(|| a.value(i)))
        .collect()
}

fn report(s: &Sweep, i: u64) -> kontakt::Result<BearingReport> {
    match s.case(i).unwrap() {
        Case::Bearing(c) => run_bearing_case(&c),
        other => panic!("case {i} is {}", other.method()),
    }
}

/// The example bearing `name` with a rating: its own, else a copy with `[bearing.rating]`
/// appended (representative capacities: test inputs that set the rating's scales, not a
/// catalogue's).
fn rated(name: &str) -> PathBuf {
    let examples = sweeps_dir().join("..");
    let text = std::fs::read_to_string(examples.join(name)).unwrap();
    if text.contains("\n[bearing.rating]") {
        return examples.join(name);
    }
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("sweep_bearing_rated");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    let rating = "\n[bearing.rating]\ndynamic_n = 60000.0\nstatic_n = 50000.0\n";
    // tests run in parallel: write aside, then rename (atomic)
    let aside = dir.join(format!("{name}.{:?}", std::thread::current().id()));
    std::fs::write(&aside, text + rating).unwrap();
    std::fs::rename(&aside, &path).unwrap();
    path
}

/// The columns that must equal the cold report's numbers, with the report's value.
fn expected(r: &BearingReport) -> Vec<(String, f64)> {
    let mut v = Vec::new();
    for i in 0..3 {
        v.push((format!("displacement_mm[{i}]"), r.displacement_mm[i]));
        v.push((format!("force_n[{i}]"), r.force_n[i]));
    }
    for i in 0..2 {
        v.push((format!("tilt_rad[{i}]"), r.tilt_rad[i]));
        v.push((format!("moment_nmm[{i}]"), r.moment_nmm[i]));
    }
    let q = r.rollers().map_or(0.0, |p| p.max_roller_load_n)
        + r.balls().map_or(0.0, |p| p.max_ball_load_n);
    v.push(("max_element_load_n".into(), q));
    if let Some(p) = r.rollers() {
        v.push((
            "max_load_per_length_n_per_mm".into(),
            p.max_load_per_length_n_per_mm,
        ));
        let rib = p
            .roller_loads
            .iter()
            .map(|q| q.rib_load_n)
            .fold(0.0, f64::max);
        v.push(("max_rib_load_n".into(), rib));
    }
    if let Some(p) = r.rollers() {
        v.push(("max_inner_pressure_mpa".into(), p.max_inner_pressure_mpa));
        v.push(("max_outer_pressure_mpa".into(), p.max_outer_pressure_mpa));
    }
    if let Some(p) = r.balls() {
        v.push(("max_inner_pressure_mpa".into(), p.max_inner_pressure_mpa));
        v.push(("max_outer_pressure_mpa".into(), p.max_outer_pressure_mpa));
    }
    let names = [
        "stiffness_x_n_per_mm",
        "stiffness_y_n_per_mm",
        "stiffness_z_n_per_mm",
        "stiffness_tilt_x_nmm_per_rad",
        "stiffness_tilt_y_nmm_per_rad",
    ];
    for (i, n) in names.iter().enumerate() {
        v.push(((*n).into(), r.stiffness_matrix[i][i]));
    }
    if let Some(e) = r.load_zone_epsilon {
        v.push(("load_zone_epsilon".into(), e));
    }
    v
}

/// Every row of `s` against the cold report of its case: the same status, and the numbers
/// to `tol` relative to the column's scale over the sweep (a displacement of 1e-19 mm next
/// to one of 1e-2 mm is round-off of the warm start). Returns the rows' and the cold
/// solves' iteration counts.
fn rows_match_the_cold_reports(s: &Sweep, tol: f64) -> (i64, i64) {
    let batch = &tables(s, 2)[0];
    assert_eq!(batch.num_rows() as u64, s.len());
    let status = strs(batch, "status");
    let iterations = ints(batch, "solver.iterations");
    let (mut warm, mut cold) = (0, 0);
    let reports: Vec<_> = (0..s.len()).map(|i| report(s, i)).collect();
    // the scale of a quantity (all components of a vector together) over the sweep
    let group = |name: &str| name.split('[').next().unwrap().to_string();
    let mut scale = std::collections::HashMap::<String, f64>::new();
    for r in reports.iter().flatten() {
        for (name, v) in expected(r) {
            let e = scale.entry(group(&name)).or_insert(0.0);
            *e = e.max(v.abs());
        }
    }
    // a moment against the forces over 10 mm, a tilt against the displacements over 10 mm
    let f = scale.get("force_n").copied().unwrap_or(0.0);
    let d = scale.get("displacement_mm").copied().unwrap_or(0.0);
    for (g, floor) in [("moment_nmm", 10.0 * f), ("tilt_rad", 0.1 * d)] {
        let e = scale.entry(g.to_string()).or_insert(0.0);
        *e = e.max(floor);
    }
    for (i, r) in reports.iter().enumerate() {
        let st = status[i].as_deref().unwrap();
        match r {
            Err(e) => {
                assert_eq!(st, "invalid", "case {i}: {e}");
                assert_eq!(
                    strs(batch, "error")[i].as_deref(),
                    Some(e.to_string().as_str())
                );
            }
            Ok(r) => {
                let lifted = expected(r)
                    .iter()
                    .any(|(n, v)| n == "max_element_load_n" && *v == 0.0);
                let want = if lifted {
                    "lifted_off"
                } else if r.warnings.is_empty() {
                    "ok"
                } else {
                    "warning"
                };
                assert_eq!(st, want, "case {i}: {:?}", r.warnings);
                let joined = (!r.warnings.is_empty()).then(|| r.warnings.join("; "));
                assert_eq!(strs(batch, "warnings")[i], joined, "case {i}");
                for (name, v) in expected(r) {
                    let got = f64s(batch, &name)[i].unwrap();
                    let floor = scale[&group(&name)].max(1e-300);
                    assert!(
                        (got - v).abs() <= tol * floor,
                        "case {i} {name}: sweep {got}, report {v} (scale {floor})"
                    );
                }
                // the rating: null where the report has none, else its value (a life
                // scales as a power of the load: relative to the value itself)
                let g = &r.rating;
                for (name, want) in [
                    ("static_safety_from_pressure", g.static_safety_from_pressure),
                    ("static_safety", g.static_safety),
                    ("l10_mrev", g.l10_mrev),
                    ("l10r_mrev", g.l10r_mrev),
                ] {
                    let got = f64s(batch, name)[i];
                    match (got, want) {
                        (None, None) => {}
                        (Some(got), Some(want)) => assert!(
                            (got - want).abs() <= 1e3 * tol * want.abs(),
                            "case {i} {name}: sweep {got}, report {want}"
                        ),
                        _ => panic!("case {i} {name}: sweep {got:?}, report {want:?}"),
                    }
                }
                warm += iterations[i].unwrap();
                cold += r.solver.iterations as i64;
            }
        }
    }
    (warm, cold)
}

#[test]
fn trb_rows_are_the_cold_reports_with_fewer_iterations() {
    let s = example("bearing_trb_loads.toml");
    assert_eq!(s.len(), 165);
    let (warm, cold) = rows_match_the_cold_reports(&s, 1e-9);
    // warm starts along the radial load (and across a clearance, planned again): fewer
    // Newton iterations in all (measured: see the report of the change)
    assert!(warm < cold, "warm {warm} cold {cold}");
}

#[test]
fn crb_through_its_clearance_lifts_off_as_a_row() {
    let s = example("bearing_crb_lift_off.toml");
    let batch = &tables(&s, 2)[0];
    let status = strs(batch, "status");
    let dx = f64s(batch, "load.prescribed.dx_mm");
    let lifted = batch
        .column_by_name("lifted_off")
        .unwrap()
        .as_any()
        .downcast_ref::<BooleanArray>()
        .unwrap()
        .clone();
    for i in 0..batch.num_rows() {
        // half the diametral clearance of 0.02 mm
        let off = dx[i].unwrap() <= 0.01 + 1e-15;
        assert_eq!(
            status[i].as_deref(),
            Some(if off { "lifted_off" } else { "ok" })
        );
        assert_eq!(lifted.value(i), off);
        if off {
            assert_eq!(f64s(batch, "force_n[0]")[i], Some(0.0));
            assert_eq!(f64s(batch, "max_element_load_n")[i], Some(0.0));
            assert_eq!(ints(batch, "loaded_elements")[i], Some(0));
            assert_eq!(
                strs(batch, "warnings")[i].as_deref(),
                Some("every roller is lifted off: zero load")
            );
        }
    }
    rows_match_the_cold_reports(&s, 1e-9);
}

/// A ball bearing, and loads the bearing cannot carry in the middle of the sweep: those
/// rows are `invalid` with the case's one-line error, the rows after them are solved.
#[test]
fn ball_bearing_and_refused_loads_in_the_middle() {
    let s = sweep(
        "bearing_6205.toml",
        "[[parameter]]\nkey = \"load.force_n[0]\"\nvalues = [0.0, 500.0, 1000.0, 2000.0, 4000.0, 20000.0, 60000.0]\n\
         [[parameter]]\nkey = \"load.force_n[2]\"\nvalues = [0.0, 300.0, -300.0]\n",
    );
    rows_match_the_cold_reports(&s, 1e-9);
    // the validity check of the most loaded ball's Hertz contacts: warned at 20 kN, refused
    // at 60 kN (docs/case-schema.md), the same texts as the report's
    let batch = &tables(&s, 1)[0];
    let status = strs(batch, "status");
    assert_eq!(status[15].as_deref(), Some("warning"));
    assert!(
        strs(batch, "warnings")[15]
            .as_deref()
            .unwrap()
            .contains("contact size")
    );
    assert_eq!(status[18].as_deref(), Some("invalid"));
    let s = sweep(
        "bearing_32008x.toml",
        "[[parameter]]\nkey = \"load.force_n[2]\"\nvalues = [3000.0, 1000.0, 3000.0]\n",
    );
    let batch = &tables(&s, 1)[0];
    let status = strs(batch, "status");
    assert_eq!(status, ["ok", "invalid", "ok"].map(|x| Some(x.to_string())));
    let e = strs(batch, "error")[1].clone().unwrap();
    assert!(
        e.starts_with("invalid load.force_n[2] = 1000: expected an axial load > F_r tan(alpha)"),
        "{e}"
    );
    rows_match_the_cold_reports(&s, 1e-9);
}

/// Geometry keys: a parameter that changes the bearing plans it again (roller count,
/// profile), one that does not (the case's name) keeps the warm start.
#[test]
fn geometry_parameters_plan_the_bearing_again() {
    let s = sweep(
        "bearing_nu_crb.toml",
        "[[parameter]]\nkey = \"bearing.rollers\"\nvalues = [12, 14, 16]\n\
         [[parameter]]\nkey = \"bearing.roller_length_mm\"\nvalues = [10.0, 11.0]\n\
         [[parameter]]\nkey = \"load.force_n[0]\"\nstart = 1000.0\nstop = 20000.0\ncount = 7\n",
    );
    rows_match_the_cold_reports(&s, 1e-9);
    let s = sweep(
        "bearing_nu_crb.toml",
        "[[parameter]]\nkey = \"name\"\nvalues = [\"a\", \"b\"]\n\
         [[parameter]]\nkey = \"load.force_n[0]\"\nstart = 1000.0\nstop = 20000.0\ncount = 7\n",
    );
    let (warm, cold) = rows_match_the_cold_reports(&s, 1e-9);
    assert!(warm < cold, "warm {warm} cold {cold}");
    // a whole load array as one parameter: read through the case reader, same bearing
    let s = sweep(
        "bearing_nu_crb.toml",
        "[[parameter]]\nkey = \"load.force_n\"\nvalues = [[1000.0, 0.0, 0.0], [0.0, 5000.0, 0.0], [7000.0, 7000.0, 0.0]]\n",
    );
    rows_match_the_cold_reports(&s, 1e-9);
}

/// The blocks of warm starts are fixed by the case indices: 1 and 3 threads, and chunks
/// of another size cut at block boundaries, give the same numbers bit for bit.
#[test]
fn numbers_do_not_depend_on_the_thread_count() {
    let text = "chunk_size = 512\n[[parameter]]\nkey = \"load.force_n[0]\"\nstart = 0.0\nstop = 5000.0\ncount = 40\n\
                [[parameter]]\nkey = \"load.force_n[2]\"\nstart = 2000.0\nstop = 6000.0\ncount = 30\n";
    let s = sweep("bearing_32008x.toml", text);
    let one = tables(&s, 1);
    let three = tables(&s, 3);
    assert_eq!(one, three);
    assert_eq!(one.len(), 3);
}

/// No allocation per case: 16 and 256 cases (one block each) on the current thread make
/// the same allocations but for a few of the table's; one per case would be 240 more. The
/// TRB without a rating, and the CRB, the DGBB and the rib-contact TRB with theirs (the
/// post-solve path: slice pressures, ISO 281/76 and ISO/TS 16281 lives, the contacts'
/// validity check).
#[test]
fn a_case_allocates_nothing() {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .use_current_thread()
        .build()
        .unwrap();
    for (base, from, to) in [
        ("bearing_32008x.toml", 0.0, 5000.0),
        ("bearing_nu_crb.toml", 1000.0, 5000.0),
        ("bearing_6205.toml", 100.0, 3000.0),
        ("bearing_rib_contact_60mm.toml", 1000.0, 6000.0),
    ] {
        // the 32008 X as it is (no rating), the others rated
        let base = match base {
            "bearing_32008x.toml" => sweeps_dir().join("..").join(base),
            _ => rated(base),
        };
        let count = |n: usize| {
            let s = Sweep::from_toml_str(
                &format!(
                    "base = \"{}\"\n[[parameter]]\nkey = \"load.force_n[0]\"\nstart = {from:?}\nstop = {to:?}\ncount = {n}\n",
                    base.display()
                ),
                &sweeps_dir(),
            )
            .unwrap();
            let (t, n) = counting_alloc::allocations(|| pool.install(|| s.chunk_table(0).unwrap()));
            assert_eq!(
                strs(&t, "status")
                    .iter()
                    .flatten()
                    .filter(|s| *s == "ok")
                    .count(),
                t.num_rows(),
                "{}",
                base.display()
            );
            if !base.ends_with("bearing_32008x.toml") {
                assert!(
                    f64s(&t, "l10r_mrev").iter().all(Option::is_some),
                    "{}",
                    base.display()
                );
            }
            n
        };
        let (small, large) = (count(16), count(256));
        assert!(
            large.abs_diff(small) < 24,
            "{}: 16 cases: {small} allocations, 256 cases: {large}",
            base.display()
        );
    }
}

/// The warnings of a row are the report's, whatever adds them (issue 28: the rating's
/// warnings were once added by the report only): every example bearing, with a rating
/// (its own, else representative capacities appended to a copy) from a light load to
/// twenty times the example's, and the coupled slices once. Every row must equal the
/// cold report, warnings and refusals included, and the sweep must meet each kind of
/// warning (pressure above ISO 76's limit, s0 < 1, contact size), for rollers and balls,
/// so that the comparison is not vacuous.
#[test]
fn row_warnings_are_the_reports_for_every_example_bearing() {
    let examples = sweeps_dir().join("..");
    let mut names: Vec<_> = std::fs::read_dir(&examples)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|n| n.starts_with("bearing_") && n.ends_with(".toml"))
        .collect();
    names.sort();
    assert!(names.len() >= 8, "{names:?}");
    let mut seen: Vec<(String, String)> = Vec::new();
    for name in &names {
        let base = rated(name);
        let text = std::fs::read_to_string(&base).unwrap();
        let v: toml::Value = toml::from_str(&text).unwrap();
        let f: Vec<f64> = v["load"]["force_n"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_float().unwrap())
            .collect();
        let loads: Vec<String> = [0.25, 1.0, 4.0, 10.0, 20.0]
            .iter()
            .map(|k| format!("[{}, {}, {}]", k * f[0], k * f[1], k * f[2]))
            .collect();
        let mut variants = vec![(base.clone(), loads.clone())];
        if name == "bearing_32008x.toml" {
            // coupled slices (slower: two loads)
            let coupled = text.replacen("[bearing]\n", "[bearing]\nslice_model = \"coupled\"\n", 1);
            assert_ne!(coupled, text);
            let path = base.with_file_name("coupled_bearing_32008x.toml");
            std::fs::write(&path, coupled).unwrap();
            variants.push((path, vec![loads[1].clone(), loads[4].clone()]));
        }
        for (base, loads) in variants {
            let s = Sweep::from_toml_str(
                &format!(
                    "base = \"{}\"\n[[parameter]]\nkey = \"load.force_n\"\nvalues = [{}]\n",
                    base.display(),
                    loads.join(", ")
                ),
                &sweeps_dir(),
            )
            .unwrap();
            rows_match_the_cold_reports(&s, 1e-9);
            let batch = &tables(&s, 1)[0];
            for w in strs(batch, "warnings").into_iter().flatten() {
                seen.push((name.clone(), w));
            }
            let solved = strs(batch, "status")
                .iter()
                .filter(|s| s.as_deref() != Some("invalid"))
                .count();
            assert!(solved >= 1, "{name}: no case solved");
        }
    }
    let met = |ball: bool, text: &str| {
        seen.iter().any(|(n, w)| {
            let is_ball = n.contains("6205") || n.contains("7205");
            is_ball == ball && w.contains(text)
        })
    };
    for ball in [false, true] {
        assert!(met(ball, "exceeds ISO 76's"), "ball {ball}: {seen:#?}");
        assert!(
            met(ball, "static safety s0 = C0/P0"),
            "ball {ball}: {seen:#?}"
        );
    }
    assert!(met(true, "contact size"), "{seen:#?}");
}

/// A sweep over the ring speed (`speed.inner_rpm`) plans the bearing again for every new
/// `[speed]`: each row is the cold report of its case (displacement, largest load, ε), not
/// the first case's speed (before, every row repeated the rest solution).
#[test]
fn a_speed_sweep_plans_each_speed() {
    let s = sweep(
        "bearing_7205_speed.toml",
        "[[parameter]]\nkey = \"speed.inner_rpm\"\nvalues = [0.0, 5000.0, 12000.0, 30000.0]\n",
    );
    let batch = &tables(&s, 1)[0];
    let dz = f64s(batch, "displacement_mm[2]");
    let eps = f64s(batch, "load_zone_epsilon");
    let text = std::fs::read_to_string(sweeps_dir().join("../bearing_7205_speed.toml")).unwrap();
    for (i, n) in [0.0, 5000.0, 12000.0, 30000.0].iter().enumerate() {
        let case = text.replace("inner_rpm = 15000.0", &format!("inner_rpm = {n:.1}"));
        let Case::Bearing(c) = Case::from_toml_str(&case).unwrap() else {
            panic!("not a bearing case")
        };
        let r = run_bearing_case(&c).unwrap();
        let got = dz[i].unwrap();
        assert!(
            (got - r.displacement_mm[2]).abs() <= 1e-9 * r.displacement_mm[0].abs(),
            "{n} r/min: sweep {got}, report {}",
            r.displacement_mm[2]
        );
        assert!(
            (eps[i].unwrap() - r.load_zone_epsilon.unwrap()).abs() < 1e-9,
            "{n}"
        );
    }
    assert!(eps[3].unwrap() > eps[0].unwrap());
}
