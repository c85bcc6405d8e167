//! Lane version of the linear actuator ([`crate::driver::actuator`]): its
//! position is the RRR group's with the input length as second length
//! ([`super::rrr`]); the rates are the RRR's with the extension terms added
//! to the right-hand side.
//!
//! With `e2 = r2 / L`: rates from `w = vB - vA + L_dot e2`, accelerations from
//! `aB - aA + L_ddot e2 + 2 L_dot omega2 perp(e2)` (plus the RRR's centripetal
//! terms, added by [`super::rrr_accels`]). The scalar primitive divides by
//! `|r2|` where this divides by `L`: the two agree to rounding wherever the
//! group assembled (`|r2| = L` to a few ulp).

use super::{rrr_accels, rrr_rates, Rrr};
use crate::scalar::Real;

/// `(omega1, omega2)` (rad/s) from `dv = vB - vA` (L/s), the length `length`
/// (L, the input) and its rate `length_dot` (L/s).
#[inline(always)]
pub fn actuator_rates<T: Real>(g: &Rrr<T>, dvx: T, dvy: T, length: T, length_dot: T) -> (T, T) {
    let k = length_dot / length;
    rrr_rates(g, dvx + g.r2x * k, dvy + g.r2y * k)
}

/// `(alpha1, alpha2)` (rad/s^2) from `da = aB - aA` (L/s^2), the length and
/// its derivatives (L, L/s, L/s^2) and the rates.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub fn actuator_accels<T: Real>(
    g: &Rrr<T>,
    dax: T,
    day: T,
    length: T,
    length_dot: T,
    length_ddot: T,
    w1: T,
    w2: T,
) -> (T, T) {
    let inv = T::one() / length;
    let (ex, ey) = (g.r2x * inv, g.r2y * inv);
    let c = T::lit(2.0) * length_dot * w2;
    rrr_accels(
        g,
        dax + ex * length_ddot - ey * c,
        day + ey * length_ddot + ex * c,
        w1,
        w2,
    )
}
