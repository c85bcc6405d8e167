//! Errors against the double-double references, shared by
//! `scale_definitions.rs` and `singular_definitions.rs`: the loop-closure
//! reference of a whole definition (`mechanism_reference::loop_closure`,
//! Newton on every constraint), normwise relative errors of points and of
//! scalars, the exact angle between two vectors.

use mechanism::Real;
use mechanism_reference::constraint::{Linkage, Point, V2};
use mechanism_reference::groups::V;
use mechanism_reference::loop_closure;
use mechanism_reference::Dd;

/// A fixed reference point.
pub fn fixed(x: f64, y: f64) -> Point {
    Point::Fixed(V2::new(x, y))
}

/// The reference's positions, velocities and accelerations of every point.
pub struct Reference {
    pub p: Vec<V2>,
    pub v: Vec<V2>,
    pub a: Vec<V2>,
}

/// Solves the reference linkage for inputs `q` (rad), rates `w`, accelerations
/// `al`, from the start guess `start` (the code under test's answer: it only
/// picks the branch).
pub fn reference(
    l: &Linkage,
    q: &[f64],
    w: &[f64],
    al: &[f64],
    start: &[(f64, f64)],
) -> Option<Reference> {
    let dd = |x: &[f64]| x.iter().map(|&v| Dd::from_f64(v)).collect::<Vec<_>>();
    let (q, w, al) = (dd(q), dd(w), dd(al));
    let pose = loop_closure::position(l, &q, start).ok()?;
    let v = loop_closure::velocity(l, &pose, &q, &w).ok()?;
    let a = loop_closure::acceleration(l, &pose, &v, &q, &w, &al).ok()?;
    Some(Reference {
        p: pose.points,
        v,
        a,
    })
}

/// `|V2|` in double-double.
pub fn norm(v: V2) -> Dd {
    v.dot(v).sqrt()
}

/// Normwise relative error of `got` against `r`: `max |got - r| / max |r|`.
pub fn rel_pts(got: &[(f64, f64)], r: &[V2]) -> f64 {
    let mut e = 0.0f64;
    let mut s = 0.0f64;
    for (g, r) in got.iter().zip(r) {
        e = e.max(norm(V2::new(g.0, g.1).minus(*r)).to_f64());
        s = s.max(norm(*r).to_f64());
    }
    if s > 0.0 {
        e / s
    } else {
        e
    }
}

/// Normwise relative error of scalars.
pub fn rel_scalars(got: &[f64], r: &[Dd]) -> f64 {
    let mut e = 0.0f64;
    let mut s = 0.0f64;
    for (g, r) in got.iter().zip(r) {
        e = e.max((Dd::from_f64(*g) - *r).abs().to_f64());
        s = s.max(r.abs().to_f64());
    }
    if s > 0.0 {
        e / s
    } else {
        e
    }
}

/// `sin` of the angle between two vectors, exact to double-double.
pub fn sin_between(a: V2, b: V2) -> f64 {
    (a.cross(b).abs() / (norm(a) * norm(b))).to_f64()
}

pub fn pt<T: Real>(p: &mechanism::Point2<T>) -> (f64, f64) {
    (p.x.as_f64(), p.y.as_f64())
}

pub fn vc<T: Real>(p: &mechanism::Vector2<T>) -> (f64, f64) {
    (p.x.as_f64(), p.y.as_f64())
}

pub fn d(x: f64) -> Dd {
    Dd::from_f64(x)
}

/// Normwise relative error of scalars `got` against `r`: `max |got - r| /
/// max |r|` (the absolute error when every `r` is 0).
pub fn rel(got: &[f64], r: &[Dd]) -> f64 {
    let mut e = 0.0f64;
    let mut s = 0.0f64;
    for (g, r) in got.iter().zip(r) {
        e = e.max((d(*g) - *r).abs().to_f64());
        s = s.max(r.abs().to_f64());
    }
    if s > 0.0 {
        e / s
    } else {
        e
    }
}

/// The components of reference vectors, flattened.
pub fn flat(vs: &[V]) -> Vec<Dd> {
    vs.iter().flat_map(|v| [v[0], v[1]]).collect()
}
