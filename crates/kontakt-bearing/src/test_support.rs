//! Checks shared by the roller and ball bearing tests.

type LoadAndStiffness = ([f64; 5], [[f64; 5]; 5]);

/// `g` equals the load `f` to `tol` of the load scale (forces to the largest force or
/// moment over `r`, moments to that times `r`).
pub(crate) fn assert_same_load(g: &[f64; 5], f: &[f64; 5], r: f64, tol: f64) {
    let f_ref = f[..3]
        .iter()
        .fold(0.0_f64, |m, v| m.max(v.abs()))
        .max(f[3].hypot(f[4]) / r);
    for i in 0..5 {
        let scale = if i < 3 { f_ref } else { f_ref * r };
        assert!(
            (g[i] - f[i]).abs() <= tol * scale,
            "{i}: {} vs {}",
            g[i],
            f[i]
        );
    }
}

/// The displacement `got` is `want` to 1e-11 mm and 1e-13 rad.
pub(crate) fn assert_same_displacement(got: &[f64; 5], want: &[f64; 5]) {
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        let tol = if i < 3 { 1e-11 } else { 1e-13 };
        assert!((g - w).abs() < tol, "{i}: {got:?} vs {want:?}");
    }
}

/// The stiffness at `u` against central differences of the carried load (h = 1e-7 mm,
/// 1e-9 rad) to 1e-6 of `√(K_ii K_jj)`, and symmetric to 1e-12.
pub(crate) fn assert_stiffness_matches_central_differences(
    mut load_at: impl FnMut([f64; 5]) -> LoadAndStiffness,
    u: [f64; 5],
) {
    let (_, k) = load_at(u);
    let h = [1e-7, 1e-7, 1e-7, 1e-9, 1e-9];
    for j in 0..5 {
        let (mut up, mut um) = (u, u);
        up[j] += h[j];
        um[j] -= h[j];
        let (fp, _) = load_at(up);
        let (fm, _) = load_at(um);
        for i in 0..5 {
            let fd = (fp[i] - fm[i]) / (2.0 * h[j]);
            let scale = k[i][i].abs().sqrt() * k[j][j].abs().sqrt();
            assert!(
                (fd - k[i][j]).abs() < 1e-6 * scale,
                "K[{i}][{j}] = {} vs {fd}",
                k[i][j]
            );
            assert!((k[i][j] - k[j][i]).abs() <= 1e-12 * scale);
        }
    }
}
