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
/// On a logarithmic axis (`log`) the values are log10 of the data and are labelled with the
/// data value (see [`format_log`]).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Ticks {
    pub values: Vec<f64>,
    pub decimals: usize,
    pub exponent: Option<i32>,
    pub log: bool,
}

impl Ticks {
    /// Label of a value with this tick set's precision (no "-0").
    pub fn format(&self, v: f64) -> String {
        if self.log {
            return format_log(v);
        }
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
            log: false,
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
            log: false,
        }
    } else {
        let e = mag.log10().floor() as i32;
        Ticks {
            values,
            decimals: decimals_of(step / 10f64.powi(e)),
            exponent: Some(e),
            log: false,
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

/// Superscript form of an integer (for exponents: `-3` → `⁻³`).
fn superscript(k: i32) -> String {
    k.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            _ => '⁹',
        })
        .collect()
}

/// Label of the data value `10^v` at a tick of a logarithmic axis: plain numbers from 0.001
/// to 100000 (`0.1`, `1`, `20`, `5000`), `10ᵏ` or `m·10ᵏ` beyond.
pub(crate) fn format_log(v: f64) -> String {
    let e = (v + 1e-9).floor();
    let mantissa = 10f64.powf(v - e);
    let m = mantissa.round();
    let (m, e) = if m >= 10.0 { (1.0, e + 1.0) } else { (m, e) };
    let e = e as i32;
    if (-3..=5).contains(&e) {
        let value = m * 10f64.powi(e);
        format_fixed(value, (-e).max(0) as usize)
    } else if m == 1.0 {
        format!("10{}", superscript(e))
    } else {
        format!("{m:.0}·10{}", superscript(e))
    }
}

/// Ticks of a logarithmic axis over the data range `[10^lo, 10^hi]` (`lo`, `hi` are log10 of
/// the data), as log10 values: the decades (every decade, or every 2nd, 5th, ... if they
/// would be closer than `min_spacing_px` on an axis of `length_px` pixels), with 2 and 5
/// times each decade added when fewer than three decades are in range, and 1 to 9 times
/// each decade when the range is narrower than that still.
pub(crate) fn log_ticks(lo: f64, hi: f64, length_px: f64, min_spacing_px: f64) -> Ticks {
    let make = |values: Vec<f64>| Ticks {
        values,
        decimals: 0,
        exponent: None,
        log: true,
    };
    if !(hi > lo) || !lo.is_finite() || !hi.is_finite() {
        return make(vec![if lo.is_finite() { lo } else { 0.0 }]);
    }
    let px_per_decade = length_px / (hi - lo);
    let (d0, d1) = ((lo - 1e-9).ceil() as i64, (hi + 1e-9).floor() as i64);
    let in_range = |v: f64| v >= lo - 1e-9 && v <= hi + 1e-9;
    let with = |mults: &[f64]| -> Vec<f64> {
        let mut values = Vec::new();
        for d in (lo.floor() as i64)..=(hi.ceil() as i64) {
            for &m in mults {
                let v = d as f64 + m.log10();
                if in_range(v) {
                    values.push(v);
                }
            }
        }
        values
    };
    let decades = d1 - d0 + 1;
    if decades >= 3 {
        // Every k-th decade, k from 1, 2, 5, 10, ... so that labels do not collide.
        let step = [1i64, 2, 5, 10, 20, 50, 100]
            .into_iter()
            .find(|&k| k as f64 * px_per_decade >= min_spacing_px)
            .unwrap_or(100);
        let first = d0.div_euclid(step) * step;
        let values = (0..)
            .map(|n| first + n * step)
            .take_while(|&d| d <= d1)
            .filter(|&d| d >= d0)
            .map(|d| d as f64)
            .collect();
        return make(values);
    }
    for mults in [
        &[1.0, 2.0, 5.0][..],
        &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0],
    ] {
        let values = with(mults);
        let spaced = values
            .windows(2)
            .all(|w| (w[1] - w[0]) * px_per_decade >= min_spacing_px);
        if values.len() >= 3 && spaced {
            return make(values);
        }
        if values.len() >= 3 {
            // Dense enough already; thin to what fits (decades first).
            return make(with(&mults[..1]).into_iter().chain(values).fold(
                Vec::new(),
                |mut acc: Vec<f64>, v| {
                    if acc
                        .iter()
                        .all(|&a| (a - v).abs() * px_per_decade >= min_spacing_px)
                    {
                        acc.push(v);
                    }
                    acc
                },
            ))
            .sorted();
        }
    }
    // Less than a factor of about 2.5: linear ticks of the data, as log10.
    let t = nice_ticks(10f64.powf(lo), 10f64.powf(hi), 4);
    make(
        t.values
            .into_iter()
            .filter(|v| *v > 0.0)
            .map(f64::log10)
            .collect(),
    )
}

impl Ticks {
    /// The same ticks in increasing order.
    fn sorted(mut self) -> Self {
        self.values.sort_by(f64::total_cmp);
        self
    }
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
    fn log_axis_ticks_are_decades_labelled_as_numbers() {
        // 50 to 6000 r/min: two decades in range, so 2 and 5 times each are added.
        let (lo, hi) = (50f64.log10(), 6000f64.log10());
        let t = log_ticks(lo, hi, 600.0, 40.0);
        assert_eq!(
            t.labels(),
            vec!["50", "100", "200", "500", "1000", "2000", "5000"]
        );
        // Many decades: decades only, labelled 10ᵏ outside 0.001..100000.
        let t = log_ticks(-9.0, 9.0, 800.0, 30.0);
        assert_eq!(t.values.len(), 19);
        assert_eq!(t.labels()[0], "10⁻⁹");
        assert_eq!(t.labels()[8], "0.1");
        assert_eq!(t.labels()[9], "1");
        assert_eq!(t.labels()[14], "100000");
        assert_eq!(t.labels()[18], "10⁹");
        // The same on a short axis: every 2nd or 5th decade.
        let t = log_ticks(-9.0, 9.0, 200.0, 30.0);
        assert!(t.values.len() < 10, "{:?}", t.labels());
        assert!(t.values.iter().all(|v| v.fract() == 0.0));
        // One decade: 1, 2, 5 times it; narrower: 1..9 times.
        let t = log_ticks(0.0, 1.0, 800.0, 30.0);
        assert_eq!(t.labels(), vec!["1", "2", "5", "10"]);
        let t = log_ticks(2f64.log10(), 4.5f64.log10(), 800.0, 30.0);
        assert_eq!(t.labels(), vec!["2", "3", "4"]);
        assert_eq!(format_log(-1.0), "0.1");
        assert_eq!(format_log(7.0 + 5f64.log10()), "5·10⁷");
    }

    #[test]
    fn degenerate_ranges() {
        assert_eq!(nice_ticks(1.0, 1.0, 5).values, vec![1.0]);
        assert_eq!(nice_ticks(f64::NAN, 1.0, 5).values, vec![0.0]);
        assert_eq!(format_fixed(-0.0001, 2), "0.00");
    }
}
