//! Helpers shared by the stability tests.
#![allow(dead_code)]

use mechanism::{Point2, Vector2};
use mechanism_reference::groups::{self as refg, V};
use mechanism_reference::Dd;

/// f64 machine epsilon.
pub const EPS: f64 = f64::EPSILON;

/// Relative distances to a limit, 1e-2 down to 1e-14, four per decade with
/// mantissas that are not round binary numbers (so that no sample is exact
/// by luck).
pub fn deltas() -> Vec<f64> {
    let mut out = vec![];
    for k in 2..=14 {
        for m in [1.0, 1.7, 3.1, 5.3] {
            let d = m * 10f64.powi(-k);
            if d >= 0.99e-14 {
                out.push(d);
            }
        }
    }
    out
}

pub fn p(x: f64, y: f64) -> Point2<f64> {
    Point2::new(x, y)
}

pub fn dv(p: &Point2<f64>) -> V {
    refg::v(p.x, p.y)
}

pub fn dvec(v: &Vector2<f64>) -> V {
    refg::v(v.x, v.y)
}

/// `|x - ref|` for a point, in double-double then rounded.
pub fn dist(x: &Point2<f64>, r: V) -> f64 {
    refg::norm(refg::sub(dv(x), r)).to_f64()
}

/// `|x - ref| / |ref|` (absolute when `ref` is 0).
pub fn rel(x: f64, r: Dd) -> f64 {
    let e = (Dd::from(x) - r).abs().to_f64();
    let s = r.abs().to_f64();
    if s > 0.0 {
        e / s
    } else {
        e
    }
}

/// Largest of a slice.
pub fn max(v: &[f64]) -> f64 {
    v.iter().copied().fold(0.0, f64::max)
}
