//! Lane version of the RPR group ([`crate::dyad::rpr`]): link 2 turns about
//! `B`, a block pinned at `A` slides along it on a line at `offset` from `B`.
//!
//! The scalar primitive's formulas: with `p = A - B`,
//! `s = m sqrt((|p| - |offset|)(|p| + |offset|))`, the axis
//! `u = (s p - offset perp(p)) / |p|` normalized; rates from the system with
//! columns `u`, `perp(p)`, determinant `dot(u, p) = s`.

use super::{abs, select, sqrt};
use crate::geometry::{normal_range, SINGULAR_RELATIVE};
use crate::scalar::Real;

/// A closed RPR group.
#[derive(Clone, Copy, Debug)]
pub struct Rpr<T> {
    /// Unit axis `u` of link 2 (and of the block).
    pub ux: T,
    /// Unit axis `u`.
    pub uy: T,
    /// Place of the block along link 2 (L), signed by the mode.
    pub s: T,
    /// `A - B` (L).
    pub px: T,
    /// `A - B` (L).
    pub py: T,
    /// `1 / dot(u, A - B)` (1 where the rate check failed).
    pub inv_det: T,
    /// `|A - B|^2` above `1e-300` (f64; 0 for f32, whose squares are normal
    /// `f64` numbers where the square root is taken), and `A` outside the
    /// circle of radius `|offset|` about `B` by more than the scalar rounding
    /// band `4 eps |offset|` (elements in the band go to the scalar path).
    pub ok: bool,
    /// `dot(u, p)^2 > (2 16 eps)^2 |u|^2 |p|^2`: twice the scalar threshold.
    pub ok_rate: bool,
}

/// Closes the group; `sign` is `+1` for `Mode::Plus` (`s > 0`), `-1` for
/// `Mode::Minus`; `offset` (L) is the slide line's distance from `B`, left of
/// `u` positive.
#[inline(always)]
pub fn rpr<T: Real>(ax: T, ay: T, bx: T, by: T, offset: T, sign: T) -> Rpr<T> {
    let (px, py) = (ax - bx, ay - by);
    let d2 = px * px + py * py;
    let spread = d2 > T::lit(1e-300);
    let dist = select(spread, sqrt(d2), T::one());
    let e = select(offset < T::zero(), -offset, offset);
    let gap = dist - e;
    let band = T::lit(4.0) * T::eps() * e;
    // `A - B` well above the rounding of the coordinates (the scalar path
    // says `Singular` at 16 eps of the largest; twice that here).
    let big = |x: T, y: T| select(x > y, x, y);
    let size = big(big(abs(ax), abs(ay)), big(abs(bx), abs(by)));
    let apart = dist > T::lit(2.0 * SINGULAR_RELATIVE) * T::eps() * size;
    let ok = spread & (gap > band) & apart;
    let gap = select(gap > T::zero(), gap, T::zero());
    let s = sign * sqrt(gap * (dist + e));
    // (s p - offset perp(p)) / |p|, perp(p) = (-py, px).
    let inv = T::one() / dist;
    let vx = (px * s + py * offset) * inv;
    let vy = (py * s - px * offset) * inv;
    let n2 = vx * vx + vy * vy;
    let ok = ok & (n2 > T::lit(1e-300));
    let inv_n = T::one() / sqrt(select(ok, n2, T::one()));
    let (ux, uy) = (vx * inv_n, vy * inv_n);
    let det = ux * px + uy * py;
    let scale_sq = (ux * ux + uy * uy) * d2;
    let kk = T::lit(2.0 * SINGULAR_RELATIVE) * T::eps();
    // A fourth power of the lengths: outside the normal range the products
    // above lose bits or overflow; the scalar path scales them (`dyad::rpr`).
    let (lo, hi) = normal_range::<T>();
    let ok = ok & (scale_sq >= lo) & (scale_sq <= hi);
    let ok_rate = det * det > kk * kk * scale_sq;
    Rpr {
        ux,
        uy,
        s,
        px,
        py,
        inv_det: T::one() / select(ok_rate, det, T::one()),
        ok,
        ok_rate,
    }
}

/// `(omega, s_dot)`: link 2's (and the block's) angular velocity (rad/s) and
/// the block's sliding speed along link 2 (L/s) from `dv = vA - vB` (L/s).
#[inline(always)]
pub fn rpr_rates<T: Real>(g: &Rpr<T>, dvx: T, dvy: T) -> (T, T) {
    (
        (g.ux * dvy - g.uy * dvx) * g.inv_det,
        (dvx * g.px + dvy * g.py) * g.inv_det,
    )
}

/// `(alpha, s_ddot)` from `da = aA - aB` (L/s^2) and the rates: the system's
/// right-hand side is `da + omega^2 p - 2 omega s_dot perp(u)`.
#[inline(always)]
pub fn rpr_accels<T: Real>(g: &Rpr<T>, dax: T, day: T, omega: T, s_dot: T) -> (T, T) {
    let w2 = omega * omega;
    let c = T::lit(2.0) * omega * s_dot;
    // - c perp(u) = (c uy, -c ux).
    let wx = dax + g.px * w2 + g.uy * c;
    let wy = day + g.py * w2 - g.ux * c;
    (
        (g.ux * wy - g.uy * wx) * g.inv_det,
        (wx * g.px + wy * g.py) * g.inv_det,
    )
}
