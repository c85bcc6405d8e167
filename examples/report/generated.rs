//! The generated code of each example scene, evaluated at one grid point and
//! flattened to the report's columns (in the order of `reference::scenes`)
//! plus the positions of every point of the reference's description (for the
//! loop-closure residual and the reference's starting guess).

use crate::scenes::*;
use crate::variants::FourBarPoints;
use mechanism::{Point2, Real, Vector2};

/// A method's answer at one grid point.
#[derive(Clone, Debug)]
pub struct Sample {
    /// One entry per report column; `None` when the method does not give it.
    pub cols: Vec<Option<f64>>,
    /// One pair per point of the reference's description.
    pub points: Vec<(f64, f64)>,
}

fn l<T: Real>(x: f64) -> T {
    T::lit(x)
}
fn p<T: Real>(v: &Point2<T>) -> (f64, f64) {
    (v.x.as_f64(), v.y.as_f64())
}
fn xy<T: Real>(v: &Vector2<T>) -> [Option<f64>; 2] {
    [Some(v.x.as_f64()), Some(v.y.as_f64())]
}
fn pt<T: Real>(v: &Point2<T>) -> [Option<f64>; 2] {
    [Some(v.x.as_f64()), Some(v.y.as_f64())]
}
fn s<T: Real>(x: T) -> Option<f64> {
    Some(x.as_f64())
}
fn polar(r: f64, a: f64) -> (f64, f64) {
    (r * a.cos(), r * a.sin())
}

/// `FourBar` (with angles). `None` when the generated code returns an error.
pub fn fourbar<T: Real>(m: &FourBar<T>, q: &[f64], w: &[f64], a: &[f64]) -> Option<Sample> {
    let i = |x: &[f64]| FourBarInput {
        theta2: l::<T>(x[0]),
    };
    let s3 = m.solve(&i(q), &i(w), &i(a)).ok()?;
    let (ps, v, ac) = (s3.position, s3.velocity, s3.acceleration);
    let mut cols = Vec::new();
    cols.extend(pt(&ps.B));
    cols.extend([s(ps.link3), s(ps.link4)]);
    cols.extend(xy(&v.B));
    cols.extend([s(v.link3), s(v.link4)]);
    cols.extend(xy(&ac.B));
    cols.extend([s(ac.link3), s(ac.link4)]);
    Some(Sample {
        cols,
        points: vec![(0.0, 0.0), (304.8, 0.0), p(&ps.A), p(&ps.B)],
    })
}

/// `FourBarPoints` (no angle outputs): B and its derivatives only.
pub fn fourbar_points<T: Real>(
    m: &FourBarPoints<T>,
    q: &[f64],
    w: &[f64],
    a: &[f64],
) -> Option<Sample> {
    use crate::variants::FourBarPointsInput as In;
    let i = |x: &[f64]| In {
        theta2: l::<T>(x[0]),
    };
    let s3 = m.solve(&i(q), &i(w), &i(a)).ok()?;
    let (ps, v, ac) = (s3.position, s3.velocity, s3.acceleration);
    let mut cols = Vec::new();
    cols.extend(pt(&ps.B));
    cols.extend([None, None]);
    cols.extend(xy(&v.B));
    cols.extend([None, None]);
    cols.extend(xy(&ac.B));
    cols.extend([None, None]);
    let q0 = l::<T>(q[0]).as_f64();
    Some(Sample {
        cols,
        points: vec![(0.0, 0.0), (304.8, 0.0), polar(101.6, q0), p(&ps.B)],
    })
}

pub fn sixbar<T: Real>(m: &SixBar<T>, q: &[f64], w: &[f64], a: &[f64]) -> Option<Sample> {
    let i = |x: &[f64]| SixBarInput { phi1: l::<T>(x[0]) };
    let s3 = m.solve(&i(q), &i(w), &i(a)).ok()?;
    let (ps, v, ac) = (s3.position, s3.velocity, s3.acceleration);
    let mut cols = Vec::new();
    cols.extend(pt(&ps.C));
    cols.extend(pt(&ps.F));
    cols.extend([s(ps.link2), s(ps.link3), s(ps.link4), s(ps.af)]);
    cols.extend(xy(&v.C));
    cols.extend(xy(&v.F));
    cols.extend([s(v.link2), s(v.link3), s(v.link4), s(v.af)]);
    cols.extend(xy(&ac.C));
    cols.extend(xy(&ac.F));
    cols.extend([s(ac.link2), s(ac.link3), s(ac.link4), s(ac.af)]);
    let q0 = l::<T>(q[0]).as_f64();
    let k = polar(40.0, q0);
    let f = p(&ps.F);
    let l4 = ps.link4.as_f64();
    Some(Sample {
        cols,
        points: vec![
            (0.0, 0.0),
            (70.0, 0.0),
            k,
            (-k.0, -k.1),
            f,
            (70.0 - 35.0 * l4.cos(), -35.0 * l4.sin()),
            p(&ps.C),
        ],
    })
}

pub fn shaper<T: Real>(m: &Shaper<T>, q: &[f64], w: &[f64], a: &[f64]) -> Option<Sample> {
    let i = |x: &[f64]| ShaperInput {
        crank: l::<T>(x[0]),
    };
    let s3 = m.solve(&i(q), &i(w), &i(a)).ok()?;
    let (ps, v, ac) = (s3.position, s3.velocity, s3.acceleration);
    let mut cols = Vec::new();
    cols.extend(pt(&ps.E));
    cols.extend([s(ps.link3), s(ps.link4)]);
    cols.extend(xy(&v.E));
    cols.extend([s(v.link3), s(v.link4)]);
    cols.extend(xy(&ac.E));
    cols.extend([s(ac.link3), s(ac.link4)]);
    let q0 = l::<T>(q[0]).as_f64();
    let l3 = ps.link3.as_f64();
    let l4 = ps.link4.as_f64();
    let d = (0.6 * l3.cos(), -0.275 + 0.6 * l3.sin());
    let e = p(&ps.E);
    // E from D along link4 (E is an output too; use the output).
    let _ = l4;
    Some(Sample {
        cols,
        points: vec![
            (0.0, 0.0),
            (0.0, -0.275),
            (0.0, 0.3),
            (-1.0, 0.3),
            polar(0.125, q0),
            d,
            e,
        ],
    })
}

pub fn slider_crank<T: Real>(
    m: &SliderCrank<T>,
    q: &[f64],
    w: &[f64],
    a: &[f64],
) -> Option<Sample> {
    let i = |x: &[f64]| SliderCrankInput {
        theta: l::<T>(x[0]),
    };
    let s3 = m.solve(&i(q), &i(w), &i(a)).ok()?;
    let (ps, v, ac) = (s3.position, s3.velocity, s3.acceleration);
    let mut cols = Vec::new();
    cols.extend(pt(&ps.B));
    cols.push(s(ps.link3));
    cols.extend(xy(&v.B));
    cols.push(s(v.link3));
    cols.extend(xy(&ac.B));
    cols.push(s(ac.link3));
    let q0 = l::<T>(q[0]).as_f64();
    Some(Sample {
        cols,
        points: vec![
            (0.0, 0.0),
            (0.0, 0.02),
            (1.0, 0.02),
            polar(0.1, q0),
            p(&ps.B),
        ],
    })
}

pub fn five_bar<T: Real>(m: &FiveBar<T>, q: &[f64], w: &[f64], a: &[f64]) -> Option<Sample> {
    let i = |x: &[f64]| FiveBarInput {
        q1: l::<T>(x[0]),
        q2: l::<T>(x[1]),
    };
    let s3 = m.solve(&i(q), &i(w), &i(a)).ok()?;
    let (ps, v, ac) = (s3.position, s3.velocity, s3.acceleration);
    let mut cols = Vec::new();
    cols.extend(pt(&ps.P));
    cols.extend(xy(&v.P));
    cols.extend(xy(&ac.P));
    let (q0, q1) = (l::<T>(q[0]).as_f64(), l::<T>(q[1]).as_f64());
    let c = polar(0.1, q1);
    Some(Sample {
        cols,
        points: vec![
            (0.0, 0.0),
            (0.08, 0.0),
            polar(0.1, q0),
            (0.08 + c.0, c.1),
            p(&ps.P),
        ],
    })
}

/// `GearedFiveBar`: B, link3, link4 and the gear's link5.
pub fn geared_five_bar<T: Real>(
    m: &GearedFiveBar<T>,
    q: &[f64],
    w: &[f64],
    a: &[f64],
) -> Option<Sample> {
    let i = |x: &[f64]| GearedFiveBarInput {
        theta: l::<T>(x[0]),
    };
    let s3 = m.solve(&i(q), &i(w), &i(a)).ok()?;
    let (ps, v, ac) = (s3.position, s3.velocity, s3.acceleration);
    let mut cols = Vec::new();
    cols.extend(pt(&ps.B));
    cols.extend([s(ps.link3), s(ps.link4), s(ps.link5)]);
    cols.extend(xy(&v.B));
    cols.extend([s(v.link3), s(v.link4), s(v.link5)]);
    cols.extend(xy(&ac.B));
    cols.extend([s(ac.link3), s(ac.link4), s(ac.link5)]);
    Some(Sample {
        cols,
        points: vec![(0.0, 0.0), (0.3, 0.0), p(&ps.A), p(&ps.C), p(&ps.B)],
    })
}

/// The f64 generated code of the scene named `name` at one point (the
/// definitions' own parameters); `None` for an unknown name or an error.
pub fn f64_sample(name: &str, q: &[f64], w: &[f64], a: &[f64]) -> Option<Sample> {
    match name {
        "FourBar" => fourbar(&FourBar::<f64>::default(), q, w, a),
        "SixBar" => sixbar(&SixBar::<f64>::default(), q, w, a),
        "Shaper" => shaper(&Shaper::<f64>::default(), q, w, a),
        "SliderCrank" => slider_crank(&SliderCrank::<f64>::default(), q, w, a),
        "FiveBar" => five_bar(&FiveBar::<f64>::default(), q, w, a),
        "GearedFiveBar" => geared_five_bar(&GearedFiveBar::<f64>::default(), q, w, a),
        _ => None,
    }
}
