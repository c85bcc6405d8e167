//! Lane version of the RPP group ([`crate::dyad::rpp`]): a block pinned at
//! `A` slides in a slot of link 2 (direction `w`, fixed on link 2 at the
//! angle `beta` from the guide), link 2 translates along the guide `g`
//! (shifted left by `offset`); `Q` is link 2's reference point on the offset
//! line.
//!
//! The scalar primitive's formulas: `w = cos(beta) dir + sin(beta) perp(dir)`,
//! `q = A - origin - offset perp(dir)`, `D = cross(dir, w)`,
//! `s1 = cross(dir, q) / D`, `s2 = cross(q, w) / D`, `Q = g.at(s2, offset)`.

use super::guide::{difference, plus, transport_acceleration, transport_velocity};
use super::{select, Line, LineAcceleration, LineVelocity};
use crate::geometry::SINGULAR_RELATIVE;
use crate::scalar::Real;

/// A closed RPP group.
#[derive(Clone, Copy, Debug)]
pub struct Rpp<T> {
    /// Link 2's reference point `Q` (L).
    pub x: T,
    /// Link 2's reference point `Q` (L).
    pub y: T,
    /// The slot's unit direction `w` (world axes).
    pub wx: T,
    /// The slot's unit direction `w`.
    pub wy: T,
    /// Place of the block in the slot (L): `A = Q + s1 w`.
    pub s1: T,
    /// Displacement of link 2 along the guide (L).
    pub s2: T,
    /// `1 / cross(dir, w)` (1 where the check failed).
    pub inv_det: T,
    /// `cross(dir, w)^2 > (2 16 eps)^2 |dir|^2 |w|^2`: twice the scalar
    /// threshold, which the scalar primitive applies to the position already.
    pub ok: bool,
}

/// Closes the group; `(lx, ly) = (cos beta, sin beta)` is the slot's
/// direction in the guide's frame, `offset` (L) the guide's shift.
#[inline(always)]
pub fn rpp<T: Real>(ax: T, ay: T, g: &Line<T>, offset: T, lx: T, ly: T) -> Rpp<T> {
    // n = perp(dir) = (-dy, dx); w = lx dir + ly n.
    let (nx, ny) = (-g.dy, g.dx);
    let (wx, wy) = (g.dx * lx + nx * ly, g.dy * lx + ny * ly);
    let qx = (ax - g.ox) - nx * offset;
    let qy = (ay - g.oy) - ny * offset;
    let det = g.dx * wy - g.dy * wx;
    let scale_sq = (g.dx * g.dx + g.dy * g.dy) * (wx * wx + wy * wy);
    let kk = T::lit(2.0 * SINGULAR_RELATIVE) * T::eps();
    let ok = det * det > kk * kk * scale_sq;
    let inv_det = T::one() / select(ok, det, T::one());
    let s1 = (g.dx * qy - g.dy * qx) * inv_det;
    let s2 = (qx * wy - qy * wx) * inv_det;
    let (x, y) = g.at(s2, offset);
    Rpp {
        x,
        y,
        wx,
        wy,
        s1,
        s2,
        inv_det,
        ok,
    }
}

/// `(s1_dot, s2_dot, vqx, vqy)` (L/s) from the pin `A`, its velocity and the
/// guide body's motion (`None`: fixed guide).
#[inline(always)]
pub fn rpp_rates<T: Real>(
    g: &Rpp<T>,
    line: &Line<T>,
    ax: T,
    ay: T,
    vax: T,
    vay: T,
    gv: Option<&LineVelocity<T>>,
) -> (T, T, T, T) {
    let vma = transport_velocity(line, ax, ay, gv);
    let (rx, ry) = difference(Some((vax, vay)), vma);
    let s1_dot = (line.dx * ry - line.dy * rx) * g.inv_det;
    let s2_dot = (rx * g.wy - ry * g.wx) * g.inv_det;
    let vmq = transport_velocity(line, g.x, g.y, gv);
    let (vx, vy) = plus(vmq, (line.dx * s2_dot, line.dy * s2_dot));
    (s1_dot, s2_dot, vx, vy)
}

/// `(s1_ddot, s2_ddot, aqx, aqy)` (L/s^2) from the pin's acceleration, the
/// rates and the guide body's motion.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub fn rpp_accels<T: Real>(
    g: &Rpp<T>,
    line: &Line<T>,
    ax: T,
    ay: T,
    aax: T,
    aay: T,
    s1_dot: T,
    s2_dot: T,
    gv: Option<&LineVelocity<T>>,
    ga: Option<&LineAcceleration<T>>,
) -> (T, T, T, T) {
    let rel = (
        g.wx * s1_dot + line.dx * s2_dot,
        g.wy * s1_dot + line.dy * s2_dot,
    );
    let ama = transport_acceleration(line, ax, ay, gv, ga, rel);
    let (rx, ry) = difference(Some((aax, aay)), ama);
    let s1_ddot = (line.dx * ry - line.dy * rx) * g.inv_det;
    let s2_ddot = (rx * g.wy - ry * g.wx) * g.inv_det;
    let rq = (line.dx * s2_dot, line.dy * s2_dot);
    let amq = transport_acceleration(line, g.x, g.y, gv, ga, rq);
    let (qx, qy) = plus(amq, (line.dx * s2_ddot, line.dy * s2_ddot));
    (s1_ddot, s2_ddot, qx, qy)
}
