//! "Nice" tick positions and their labels, and an axis type that uses them.

use std::ops::Range;

use plotters::coord::ranged1d::{KeyPointHint, NoDefaultFormatting, Ranged, ValueFormatter};
use plotters::coord::types::RangedCoordf64;

/// A linear f64 axis whose ticks are exactly the given [`Ticks`], labelled with their precision.
pub(crate) struct TickAxis {
    inner: RangedCoordf64,
    ticks: Ticks,
}

impl TickAxis {
    pub fn new(lo: f64, hi: f64, ticks: Ticks) -> Self {
        TickAxis {
            inner: (lo..hi).into(),
            ticks,
        }
    }
}

impl Ranged for TickAxis {
    type FormatOption = NoDefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        self.inner.map(value, limit)
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            Vec::new()
        } else {
            self.ticks.values.clone()
        }
    }

    fn range(&self) -> Range<f64> {
        self.inner.range()
    }
}

impl ValueFormatter<f64> for TickAxis {
    fn format_ext(&self, value: &f64) -> String {
        self.ticks.format(*value)
    }
}

/// Tick values inside a range and how to label them: with `decimals` decimals, or, for very
/// large or small magnitudes, as `m e<exponent>` with `decimals` decimals in the mantissa.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Ticks {
    pub values: Vec<f64>,
    pub decimals: usize,
    pub exponent: Option<i32>,
}

impl Ticks {
    /// Label of a value with this tick set's precision (no "-0").
    pub fn format(&self, v: f64) -> String {
        match self.exponent {
            None => format_fixed(v, self.decimals),
            Some(_) if v == 0.0 => "0".to_string(),
            Some(e) => format!("{}e{e}", format_fixed(v / 10f64.powi(e), self.decimals)),
        }
    }

    /// The labels of all ticks.
    pub fn labels(&self) -> Vec<String> {
        self.values.iter().map(|&v| self.format(v)).collect()
    }
}

/// `v` with `decimals` decimals, without a negative zero.
pub(crate) fn format_fixed(v: f64, decimals: usize) -> String {
    let s = format!("{v:.decimals$}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

/// At most `max_n` (at least 2) ticks at multiples of 1, 2, 2.5 or 5 × 10^k within `[lo, hi]`.
pub(crate) fn nice_ticks(lo: f64, hi: f64, max_n: usize) -> Ticks {
    let max_n = max_n.max(2);
    let span = hi - lo;
    if !(span > 0.0) || !span.is_finite() || !lo.is_finite() {
        let v = if lo.is_finite() { lo } else { 0.0 };
        return Ticks {
            values: vec![v],
            decimals: 2,
            exponent: None,
        };
    }
    let raw = span / (max_n - 1) as f64;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 2.5, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| *s >= raw * (1.0 - 1e-9))
        .unwrap_or(10.0 * mag);
    let first = (lo / step - 1e-9).ceil();
    let last = (hi / step + 1e-9).floor();
    let mut values = Vec::new();
    let mut k = first;
    while k <= last && values.len() <= max_n {
        let v = k * step;
        values.push(if v.abs() < step * 1e-9 { 0.0 } else { v });
        k += 1.0;
    }
    // Plain numbers between 0.001 and 10⁶ in magnitude, powers of ten otherwise.
    let mag = lo.abs().max(hi.abs());
    if (1e-3..1e6).contains(&mag) {
        Ticks {
            values,
            decimals: decimals_of(step),
            exponent: None,
        }
    } else {
        let e = mag.log10().floor() as i32;
        Ticks {
            values,
            decimals: decimals_of(step / 10f64.powi(e)),
            exponent: Some(e),
        }
    }
}

/// The most ticks (at most `max_count`) whose spacing on an axis of `length_px` pixels is at
/// least `min_spacing_px`; at least the coarsest set.
pub(crate) fn ticks_fitting(
    lo: f64,
    hi: f64,
    length_px: f64,
    min_spacing_px: f64,
    max_count: usize,
) -> Ticks {
    let mut best = nice_ticks(lo, hi, 2);
    for n in 3..=max_count.max(3) + 3 {
        let t = nice_ticks(lo, hi, n);
        if t.values.len() > max_count || t.values.len() <= best.values.len() {
            continue;
        }
        let spacing = match t.values[..] {
            [a, b, ..] => (b - a) / (hi - lo) * length_px,
            _ => 0.0,
        };
        if spacing >= min_spacing_px {
            best = t;
        }
    }
    best
}

/// Fewest decimals (at most 15) that show multiples of `step` exactly.
fn decimals_of(step: f64) -> usize {
    (0..=15)
        .find(|&d| {
            let x = step * 10f64.powi(d as i32);
            x.round() >= 1.0 && (x - x.round()).abs() < 1e-6 * x
        })
        .unwrap_or(15)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn typical_ranges() {
        let t = nice_ticks(0.0, 1000.0, 6);
        assert_eq!(t.values, vec![0.0, 200.0, 400.0, 600.0, 800.0, 1000.0]);
        assert_eq!(t.labels()[1], "200");
        let t = nice_ticks(0.0, 1234.0, 6);
        assert_eq!(t.values, vec![0.0, 250.0, 500.0, 750.0, 1000.0]);
        let t = nice_ticks(-1.3, 1.3, 7);
        assert_eq!(t.values, vec![-1.0, -0.5, 0.0, 0.5, 1.0]);
        assert_eq!(t.labels(), vec!["-1.0", "-0.5", "0.0", "0.5", "1.0"]);
        let t = nice_ticks(-0.06, 0.06, 6);
        assert_eq!(t.decimals, 3);
        assert_eq!(t.labels()[0], "-0.050");
    }

    #[test]
    fn fitting_ticks() {
        // Plenty of room: as many as allowed.
        let t = ticks_fitting(0.0, 1499.0, 400.0, 30.0, 6);
        assert_eq!(t.values, vec![0.0, 250.0, 500.0, 750.0, 1000.0, 1250.0]);
        // Little room: fewer.
        let t = ticks_fitting(0.0, 1499.0, 100.0, 30.0, 6);
        assert_eq!(t.values, vec![0.0, 500.0, 1000.0]);
        // Short axis: still at least the coarsest set.
        let t = ticks_fitting(-0.5, 0.5, 10.0, 30.0, 6);
        assert!(!t.values.is_empty());
    }

    #[test]
    fn small_and_large_magnitudes() {
        let t = nice_ticks(0.0, 3e-7, 4);
        assert_eq!(t.labels(), vec!["0", "1e-7", "2e-7", "3e-7"]);
        let t = nice_ticks(0.0, 0.3, 4);
        assert_eq!(t.labels(), vec!["0.0", "0.1", "0.2", "0.3"]);
        let t = nice_ticks(-2e300, 2e300, 5);
        assert_eq!(t.labels(), vec!["-2e300", "-1e300", "0", "1e300", "2e300"]);
        let t = nice_ticks(0.0, 2.5e6, 6);
        assert_eq!(t.labels()[1], "0.5e6");
        let t = nice_ticks(1.0, 1.0 + 1e-12, 3);
        assert!(
            t.labels().windows(2).all(|w| w[0] != w[1]),
            "{:?}",
            t.labels()
        );
    }

    #[test]
    fn degenerate_ranges() {
        assert_eq!(nice_ticks(1.0, 1.0, 5).values, vec![1.0]);
        assert_eq!(nice_ticks(f64::NAN, 1.0, 5).values, vec![0.0]);
        assert_eq!(format_fixed(-0.0001, 2), "0.00");
    }
}
