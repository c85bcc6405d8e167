//! Lane version of the slider driver ([`crate::driver::slider`]): the pin
//! `P = g.at(s, offset)`, `vP = v_body(P) + s_dot dir`,
//! `aP = a_body(P) + 2 omega s_dot perp(dir) + s_ddot dir`. The scalar
//! driver's only checks are finiteness, which the generated kernel checks on
//! every value it computes.

use super::guide::{plus, transport_acceleration, transport_velocity};
use super::{Line, LineAcceleration, LineVelocity};
use crate::scalar::Real;

/// The pin at displacement `s` (L) along `g` and offset `offset` (L, left of
/// `g.dir` positive).
#[inline(always)]
pub fn slider<T: Real>(g: &Line<T>, offset: T, s: T) -> (T, T) {
    g.at(s, offset)
}

/// Velocity of the pin at `(px, py)` (L/s) for the speed `s_dot` (L/s).
#[inline(always)]
pub fn slider_velocity<T: Real>(
    g: &Line<T>,
    px: T,
    py: T,
    s_dot: T,
    gv: Option<&LineVelocity<T>>,
) -> (T, T) {
    let vm = transport_velocity(g, px, py, gv);
    plus(vm, (g.dx * s_dot, g.dy * s_dot))
}

/// Acceleration of the pin (L/s^2) for `s_dot` (L/s) and `s_ddot` (L/s^2).
#[inline(always)]
pub fn slider_acceleration<T: Real>(
    g: &Line<T>,
    px: T,
    py: T,
    s_dot: T,
    s_ddot: T,
    gv: Option<&LineVelocity<T>>,
    ga: Option<&LineAcceleration<T>>,
) -> (T, T) {
    let am = transport_acceleration(g, px, py, gv, ga, (g.dx * s_dot, g.dy * s_dot));
    plus(am, (g.dx * s_ddot, g.dy * s_ddot))
}
