//! Lane versions of the guide line ([`crate::guide`]) and of the body terms
//! every primitive that slides on a guide shares
//! ([`crate::driver::slider::transport_velocity`],
//! [`crate::driver::slider::transport_acceleration`]).
//!
//! As in the scalar code, a fixed guide passes `None` for its body's motion,
//! so that the terms vanish at compile time (the generated kernel writes the
//! `None` literally).

use crate::scalar::Real;

/// A straight guide: `origin` (L) and unit direction `dir`; a point at
/// displacement `s` and offset `e` (left of `dir` positive) is
/// `origin + s dir + e perp(dir)`.
#[derive(Clone, Copy, Debug)]
pub struct Line<T> {
    /// Origin (L).
    pub ox: T,
    /// Origin (L).
    pub oy: T,
    /// Unit direction.
    pub dx: T,
    /// Unit direction.
    pub dy: T,
}

impl<T: Real> Line<T> {
    /// `origin + s dir + e perp(dir)` (L).
    #[inline(always)]
    pub fn at(&self, s: T, e: T) -> (T, T) {
        (
            self.ox + self.dx * s - self.dy * e,
            self.oy + self.dy * s + self.dx * e,
        )
    }
}

/// Velocity state of the body carrying a guide: the origin's velocity (L/s)
/// and the body's angular velocity (rad/s).
#[derive(Clone, Copy, Debug)]
pub struct LineVelocity<T> {
    /// Velocity of the origin (L/s).
    pub vx: T,
    /// Velocity of the origin (L/s).
    pub vy: T,
    /// Angular velocity of the body (rad/s, counter-clockwise positive).
    pub omega: T,
}

/// Acceleration state of the body carrying a guide.
#[derive(Clone, Copy, Debug)]
pub struct LineAcceleration<T> {
    /// Acceleration of the origin (L/s^2).
    pub ax: T,
    /// Acceleration of the origin (L/s^2).
    pub ay: T,
    /// Angular acceleration of the body (rad/s^2).
    pub alpha: T,
}

/// A guide carried by a link: `dir = local.x axis + local.y perp(axis)`
/// (`axis` the link's unit axis, `local` the guide's unit direction in the
/// link's frame), as the scalar `link::local_offset`.
#[inline(always)]
pub fn carried<T: Real>(ox: T, oy: T, axis: (T, T), local: (T, T)) -> Line<T> {
    let ((ax, ay), (lx, ly)) = (axis, local);
    Line {
        ox,
        oy,
        dx: ax * lx - ay * ly,
        dy: ay * lx + ax * ly,
    }
}

/// Velocity (L/s) of the body's material point at `(px, py)`:
/// `v_origin + omega perp(p - origin)`; `None` for a fixed guide.
#[inline(always)]
pub fn transport_velocity<T: Real>(
    g: &Line<T>,
    px: T,
    py: T,
    gv: Option<&LineVelocity<T>>,
) -> Option<(T, T)> {
    gv.map(|v| {
        let (rx, ry) = (px - g.ox, py - g.oy);
        (v.vx - ry * v.omega, v.vy + rx * v.omega)
    })
}

/// Acceleration (L/s^2) of a point at `(px, py)` moving at `rel` (L/s)
/// relative to the guide's body, apart from its relative acceleration:
/// `a_origin + alpha perp(r) - omega^2 r + 2 omega perp(rel)`,
/// `r = p - origin`; the same cases as the scalar function (`gv = None`:
/// `omega = 0`; `ga = None`: `a_origin = 0`, `alpha = 0`; both: `None`).
#[inline(always)]
pub fn transport_acceleration<T: Real>(
    g: &Line<T>,
    px: T,
    py: T,
    gv: Option<&LineVelocity<T>>,
    ga: Option<&LineAcceleration<T>>,
    rel: (T, T),
) -> Option<(T, T)> {
    let (rx, ry) = (px - g.ox, py - g.oy);
    let two = T::lit(2.0);
    match (gv, ga) {
        (None, None) => None,
        (Some(v), None) => {
            let (w2, c) = (v.omega * v.omega, two * v.omega);
            Some((-rel.1 * c - rx * w2, rel.0 * c - ry * w2))
        }
        (None, Some(a)) => Some((a.ax - ry * a.alpha, a.ay + rx * a.alpha)),
        (Some(v), Some(a)) => {
            let (w2, c) = (v.omega * v.omega, two * v.omega);
            Some((
                a.ax - ry * a.alpha - rx * w2 - rel.1 * c,
                a.ay + rx * a.alpha - ry * w2 + rel.0 * c,
            ))
        }
    }
}

/// `x - y`, `None` standing for zero (as [`crate::geometry::difference`]).
#[inline(always)]
pub fn difference<T: Real>(x: Option<(T, T)>, y: Option<(T, T)>) -> (T, T) {
    match (x, y) {
        (Some(x), Some(y)) => (x.0 - y.0, x.1 - y.1),
        (Some(x), None) => x,
        (None, Some(y)) => (-y.0, -y.1),
        (None, None) => (T::zero(), T::zero()),
    }
}

/// `x + v`, `None` standing for zero (as [`crate::geometry::plus`]).
#[inline(always)]
pub fn plus<T: Real>(x: Option<(T, T)>, v: (T, T)) -> (T, T) {
    match x {
        Some(x) => (x.0 + v.0, x.1 + v.1),
        None => v,
    }
}
