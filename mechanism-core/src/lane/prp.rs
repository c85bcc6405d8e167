//! Lane version of the PRP group ([`crate::dyad::prp`]): two blocks on the
//! guides `g1`, `g2` (each shifted left by its offset), joined at `C`, the
//! intersection of the two offset lines.
//!
//! The scalar primitive's formulas: `q = g2.origin + offset2 perp(dir2) -
//! g1.origin - offset1 perp(dir1)`, `D = cross(dir1, dir2)`,
//! `s1 = cross(q, dir2) / D`, `s2 = cross(q, dir1) / D`; the rates solve the
//! same matrix.

use super::guide::{difference, plus, transport_acceleration, transport_velocity};
use super::{select, Line, LineAcceleration, LineVelocity};
use crate::geometry::SINGULAR_RELATIVE;
use crate::scalar::Real;

/// A closed PRP group.
#[derive(Clone, Copy, Debug)]
pub struct Prp<T> {
    /// The joint `C` (L).
    pub x: T,
    /// The joint `C` (L).
    pub y: T,
    /// Displacement of `C` along `g1` (L).
    pub s1: T,
    /// Displacement of `C` along `g2` (L).
    pub s2: T,
    /// `1 / cross(dir1, dir2)` (1 where the check failed).
    pub inv_det: T,
    /// `cross(dir1, dir2)^2 > (2 16 eps)^2 |dir1|^2 |dir2|^2`: twice the
    /// scalar threshold, which the scalar primitive applies to the position
    /// already (so one flag serves every level).
    pub ok: bool,
}

/// Closes the group (offsets in L, left of each guide's direction positive).
#[inline(always)]
pub fn prp<T: Real>(g1: &Line<T>, offset1: T, g2: &Line<T>, offset2: T) -> Prp<T> {
    // q = (o2 - o1) + offset2 perp(d2) - offset1 perp(d1), perp(d) = (-dy, dx).
    let qx = (g2.ox - g1.ox) - g2.dy * offset2 + g1.dy * offset1;
    let qy = (g2.oy - g1.oy) + g2.dx * offset2 - g1.dx * offset1;
    let det = g1.dx * g2.dy - g1.dy * g2.dx;
    let scale_sq = (g1.dx * g1.dx + g1.dy * g1.dy) * (g2.dx * g2.dx + g2.dy * g2.dy);
    let kk = T::lit(2.0 * SINGULAR_RELATIVE) * T::eps();
    let ok = det * det > kk * kk * scale_sq;
    let inv_det = T::one() / select(ok, det, T::one());
    let s1 = (qx * g2.dy - qy * g2.dx) * inv_det;
    let s2 = (qx * g1.dy - qy * g1.dx) * inv_det;
    let (x, y) = g1.at(s1, offset1);
    Prp {
        x,
        y,
        s1,
        s2,
        inv_det,
        ok,
    }
}

/// `(s1_dot, s2_dot, vcx, vcy)` (L/s) from the guides' bodies' motions
/// (`None`: fixed guide).
#[inline(always)]
pub fn prp_rates<T: Real>(
    g: &Prp<T>,
    g1: &Line<T>,
    g2: &Line<T>,
    gv1: Option<&LineVelocity<T>>,
    gv2: Option<&LineVelocity<T>>,
) -> (T, T, T, T) {
    let vm1 = transport_velocity(g1, g.x, g.y, gv1);
    let vm2 = transport_velocity(g2, g.x, g.y, gv2);
    let (wx, wy) = difference(vm2, vm1);
    let s1_dot = (wx * g2.dy - wy * g2.dx) * g.inv_det;
    let s2_dot = (wx * g1.dy - wy * g1.dx) * g.inv_det;
    let (vx, vy) = plus(vm1, (g1.dx * s1_dot, g1.dy * s1_dot));
    (s1_dot, s2_dot, vx, vy)
}

/// `(s1_ddot, s2_ddot, acx, acy)` (L/s^2) from the rates and the guides'
/// bodies' motions.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub fn prp_accels<T: Real>(
    g: &Prp<T>,
    g1: &Line<T>,
    g2: &Line<T>,
    s1_dot: T,
    s2_dot: T,
    gv1: Option<&LineVelocity<T>>,
    ga1: Option<&LineAcceleration<T>>,
    gv2: Option<&LineVelocity<T>>,
    ga2: Option<&LineAcceleration<T>>,
) -> (T, T, T, T) {
    let am1 = transport_acceleration(g1, g.x, g.y, gv1, ga1, (g1.dx * s1_dot, g1.dy * s1_dot));
    let am2 = transport_acceleration(g2, g.x, g.y, gv2, ga2, (g2.dx * s2_dot, g2.dy * s2_dot));
    let (wx, wy) = difference(am2, am1);
    let s1_ddot = (wx * g2.dy - wy * g2.dx) * g.inv_det;
    let s2_ddot = (wx * g1.dy - wy * g1.dx) * g.inv_det;
    let (ax, ay) = plus(am1, (g1.dx * s1_ddot, g1.dy * s1_ddot));
    (s1_ddot, s2_ddot, ax, ay)
}
