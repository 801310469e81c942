//! The viridis colour map (matplotlib's default; perceptually uniform, readable in grey scale
//! and by colour-blind readers).

/// viridis sampled at 17 evenly spaced points (matplotlib's table at t = k/16).
const VIRIDIS: [(u8, u8, u8); 17] = [
    (0x44, 0x01, 0x54),
    (0x48, 0x18, 0x6a),
    (0x47, 0x2d, 0x7b),
    (0x42, 0x40, 0x86),
    (0x3b, 0x52, 0x8b),
    (0x33, 0x63, 0x8d),
    (0x2c, 0x72, 0x8e),
    (0x26, 0x82, 0x8e),
    (0x21, 0x91, 0x8c),
    (0x1f, 0xa0, 0x88),
    (0x28, 0xae, 0x80),
    (0x3f, 0xbc, 0x73),
    (0x5e, 0xc9, 0x62),
    (0x84, 0xd4, 0x4b),
    (0xad, 0xdc, 0x30),
    (0xd8, 0xe2, 0x19),
    (0xfd, 0xe7, 0x25),
];

/// Colour of `t` in [0, 1] (clamped; NaN gives the bottom colour).
pub(crate) fn viridis(t: f64) -> (u8, u8, u8) {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let last = VIRIDIS.len() - 1;
    let s = t * last as f64;
    let k = (s.floor() as usize).min(last - 1);
    let f = s - k as f64;
    let (a, b) = (VIRIDIS[k], VIRIDIS[k + 1]);
    let mix = |p: u8, q: u8| (f64::from(p) + f * (f64::from(q) - f64::from(p))).round() as u8;
    (mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ends_and_clamping() {
        assert_eq!(viridis(0.0), (68, 1, 84));
        assert_eq!(viridis(1.0), (253, 231, 37));
        assert_eq!(viridis(2.0), (253, 231, 37));
        assert_eq!(viridis(-1.0), (68, 1, 84));
        assert_eq!(viridis(f64::NAN), (68, 1, 84));
        assert_eq!(viridis(0.5), (0x21, 0x91, 0x8c));
    }
}
