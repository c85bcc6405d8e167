//! Axis ranges and tick values on a "nice" grid.
//!
//! Steps are 1, 2 or 5 times a power of ten (the usual choice of plotting programs, e.g.
//! Heckbert, "Nice numbers for graph labels", Graphics Gems, 1990); for angles in degrees
//! spanning 30 deg or more, 15, 30, 45, 90 and 180 are candidates too, so that a full turn
//! reads 0, 45, 90, ... The step is the smallest candidate giving at most
//! [`MAX_INTERVALS`] intervals.

/// Upper bound on the number of tick intervals across an axis.
pub const MAX_INTERVALS: f64 = 8.0;

/// Relative slack when comparing a bound with a multiple of the step, so that a value
/// that is a multiple up to rounding (`0.1 * 3`) counts as one. Far above f64 rounding
/// (1e-16) and far below a visible fraction of a tick interval.
const SLACK: f64 = 1e-9;

/// An axis: its range, tick values and how to print them.
#[derive(Clone, Debug, PartialEq)]
pub struct Ticks {
    /// Lower end of the axis, in data units.
    pub lo: f64,
    /// Upper end of the axis, in data units (`hi > lo`).
    pub hi: f64,
    /// Distance between ticks, in data units.
    pub step: f64,
    /// Tick values, increasing, all within `[lo, hi]`.
    pub values: Vec<f64>,
    /// Tick labels show `value / 10^exponent`; the axis label carries `10^exponent`
    /// (engineering exponents: multiples of 3; 0 for values between 0.01 and 10^4).
    pub exponent: i32,
    /// Decimals printed in tick labels.
    pub decimals: usize,
}

impl Ticks {
    /// The label of tick value `v`: scaled by the exponent, fixed decimals, a true minus
    /// sign (U+2212), never `-0`.
    pub fn label(&self, v: f64) -> String {
        let scaled = v / 10f64.powi(self.exponent);
        let mut s = format!("{:.*}", self.decimals, scaled);
        if s.starts_with('-') {
            if s[1..].chars().all(|c| c == '0' || c == '.') {
                s.remove(0);
            } else {
                s.replace_range(0..1, "\u{2212}");
            }
        }
        s
    }
}

/// Ticks for data spanning `[lo, hi]` (finite, `lo <= hi`).
///
/// `degrees` adds the 15/30/45/90/180 steps. With `expand`, the axis grows to the
/// enclosing multiples of the step (y axes); without, it is exactly `[lo, hi]` (x axes,
/// or a range the caller chose). A zero-width range is widened by 10 % of its value
/// (by 1 when the value is 0) each way. `step`, when given (positive, finite), is used
/// instead of the automatic choice.
pub fn nice_ticks(lo: f64, hi: f64, degrees: bool, expand: bool, step: Option<f64>) -> Ticks {
    let (mut lo, mut hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
    if hi - lo <= f64::EPSILON * (lo.abs() + hi.abs()) {
        let pad = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
        lo -= pad;
        hi += pad;
    }
    let span = hi - lo;
    let step = match step {
        Some(s) if s.is_finite() && s > 0.0 && span / s <= 1000.0 => s,
        _ if !expand => aligned_step(lo, hi, degrees).unwrap_or_else(|| auto_step(span, degrees)),
        _ => auto_step(span, degrees),
    };
    if expand {
        lo = (lo / step + SLACK).floor() * step;
        hi = (hi / step - SLACK).ceil() * step;
    }
    let first = (lo / step - SLACK).ceil() as i64;
    let last = (hi / step + SLACK).floor() as i64;
    let values: Vec<f64> = (first..=last)
        .map(|k| k as f64 * step)
        .map(|v| v.clamp(lo, hi))
        .collect();
    let m = lo.abs().max(hi.abs());
    let exponent = if !(1e-2..1e4).contains(&m) {
        3 * (m.log10() / 3.0).floor() as i32
    } else {
        0
    };
    let scaled_step = step / 10f64.powi(exponent);
    let decimals = (-scaled_step.log10() - SLACK).ceil().max(0.0) as usize;
    // A degree step such as 15 is an integer; 2.5 never occurs (1-2-5 steps have one
    // significant digit), so `decimals` shows every step exactly.
    Ticks {
        lo,
        hi,
        step,
        values,
        exponent,
        decimals,
    }
}

/// For an axis that is not widened: the smallest candidate step of which both ends are
/// multiples, giving 3 to [`MAX_INTERVALS`] intervals (40..55 -> 5, so that the last
/// tick sits on the end of the axis).
fn aligned_step(lo: f64, hi: f64, degrees: bool) -> Option<f64> {
    let span = hi - lo;
    let mag = 10f64.powf((span / MAX_INTERVALS).log10().floor());
    let mut cands: Vec<f64> = [mag, 10.0 * mag, 100.0 * mag]
        .iter()
        .flat_map(|m| [1.0, 2.0, 5.0].map(|f| f * m))
        .collect();
    if degrees && span >= 30.0 {
        cands.extend([15.0, 30.0, 45.0, 90.0, 180.0]);
    }
    let multiple =
        |v: f64, s: f64| ((v / s) - (v / s).round()).abs() < SLACK * (1.0 + (v / s).abs());
    cands
        .into_iter()
        .filter(|&s| {
            let n = span / s;
            (3.0 - SLACK..=MAX_INTERVALS + SLACK).contains(&n) && multiple(lo, s) && multiple(hi, s)
        })
        .fold(None, |best: Option<f64>, s| {
            Some(best.map_or(s, |b| b.min(s)))
        })
}

/// The smallest candidate step giving at most [`MAX_INTERVALS`] intervals over `span`.
fn auto_step(span: f64, degrees: bool) -> f64 {
    let raw = span / MAX_INTERVALS;
    let mag = 10f64.powf(raw.log10().floor());
    let mut best = f64::INFINITY;
    for m in [mag, 10.0 * mag] {
        for f in [1.0, 2.0, 5.0] {
            let s = f * m;
            if s >= raw * (1.0 - SLACK) && s < best {
                best = s;
            }
        }
    }
    if degrees && span >= 30.0 {
        for s in [15.0, 30.0, 45.0, 90.0, 180.0] {
            if s >= raw * (1.0 - SLACK) && s < best {
                best = s;
            }
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_two_five_steps() {
        let t = nice_ticks(0.0, 1.0, false, true, None);
        assert_eq!(t.step, 0.2);
        assert_eq!(t.values.len(), 6);
        assert_eq!(t.label(t.values[3]), "0.6");
        let t = nice_ticks(-3.3, 7.1, false, true, None);
        assert_eq!((t.lo, t.hi, t.step), (-4.0, 8.0, 2.0));
        assert_eq!(t.label(-4.0), "\u{2212}4");
    }

    #[test]
    fn degrees_read_in_quarters() {
        let t = nice_ticks(0.0, 360.0, true, false, None);
        assert_eq!(t.step, 45.0);
        assert_eq!(t.values.first(), Some(&0.0));
        assert_eq!(t.values.last(), Some(&360.0));
        // The same span without the degree candidates takes 50.
        assert_eq!(nice_ticks(0.0, 360.0, false, false, None).step, 50.0);
    }

    #[test]
    fn unwidened_axes_end_on_a_tick() {
        let t = nice_ticks(40.0, 55.0, true, false, None);
        assert_eq!(t.step, 5.0);
        assert_eq!(t.values.last(), Some(&55.0));
        let t = nice_ticks(60.0, 150.0, true, false, None);
        assert_eq!(t.step, 15.0);
        // No step fits both ends: the automatic step, ticks inside.
        let t = nice_ticks(0.1, 0.73, false, false, None);
        assert!(t.values.iter().all(|v| (0.1..=0.73).contains(v)));
    }

    #[test]
    fn large_values_get_an_exponent() {
        let t = nice_ticks(-2.0e5, 3.1e5, false, true, None);
        assert_eq!(t.exponent, 3);
        assert_eq!(t.label(t.values[1]), "\u{2212}100");
        let t = nice_ticks(0.0, 0.004, false, true, None);
        assert_eq!(t.exponent, -3);
        assert_eq!(t.label(0.002), "2.0");
    }

    #[test]
    fn constant_data_gets_a_range() {
        let t = nice_ticks(5.0, 5.0, false, true, None);
        assert!(t.lo < 5.0 && t.hi > 5.0);
        let t = nice_ticks(0.0, 0.0, false, true, None);
        assert!(t.lo <= -1.0 && t.hi >= 1.0);
    }
}
