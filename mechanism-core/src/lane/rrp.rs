//! Lane version of the RRP group ([`crate::dyad::rrp`]): link 1 about `A`
//! with length `l`, its far joint `C` on a block sliding on the guide `g`
//! shifted left by `offset`.
//!
//! The scalar primitive's formulas: with `p = A - origin`, `t = dot(p, dir)`,
//! `k = dot(p, perp(dir)) - offset`, the half chord
//! `m sqrt((l - |k|)(l + |k|))`, `r1 = half dir - k perp(dir)`,
//! `s = t + half`; rates from the system with columns `perp(r1)`, `-dir`,
//! determinant `dot(r1, dir)`.

use super::guide::{difference, transport_acceleration, transport_velocity};
use super::{select, sqrt, Line, LineAcceleration, LineVelocity};
use crate::eft::{compensated, half_excess, split, two_product_split, two_sum};
use crate::geometry::{normal_range, SINGULAR_RELATIVE};
use crate::scalar::Real;

/// A closed RRP group.
#[derive(Clone, Copy, Debug)]
pub struct Rrp<T> {
    /// The joint `C` (L).
    pub x: T,
    /// The joint `C` (L).
    pub y: T,
    /// `C - A` (L), length `l`: link 1's direction.
    pub r1x: T,
    /// `C - A` (L).
    pub r1y: T,
    /// Displacement of `C` along the guide from its origin (L).
    pub s: T,
    /// `1 / dot(r1, dir)` (1 where the rate check failed).
    pub inv_det: T,
    /// `l > 0` and `A` strictly nearer the offset line than `l` by more than
    /// the scalar rounding band `4 eps l` (elements in the band, which the
    /// scalar primitive puts at the tangent position, go to the scalar path).
    pub ok: bool,
    /// `dot(r1, dir)^2 > (2 16 eps)^2 |r1|^2 |dir|^2`: twice the scalar
    /// threshold (as [`super::Rrr::ok_rate`]).
    pub ok_rate: bool,
}

/// Closes the group; `sign` is `+1` for `Mode::Plus` (`C` ahead of the foot
/// of the perpendicular from `A` along `g.dir`), `-1` for `Mode::Minus`.
#[inline(always)]
pub fn rrp<T: Real>(ax: T, ay: T, l: T, g: &Line<T>, offset: T, sign: T) -> Rrp<T> {
    let (px, py) = (ax - g.ox, ay - g.oy);
    let t = px * g.dx + py * g.dy;
    // perp(dir) = (-dy, dx).
    let k = py * g.dx - px * g.dy - offset;
    // In f32, `k` is carried as `kh + kl` and the direction is divided by
    // its length to first order (`x / |dir| = x - x he`), as the scalar
    // primitive does near tangency (see there); here for every element, no
    // branch. The f64 code is the plain form (`compensated` folds at compile
    // time).
    let (kh, kl, he) = if compensated::<T>() {
        let (xh, xl) = split(g.dx);
        let (yh, yl) = split(g.dy);
        let he = half_excess(g.dx, xh, xl, g.dy, yh, yl);
        let (q1, e1) = two_product_split(py, g.dx, xh, xl);
        let (q2, e2) = two_product_split(px, g.dy, yh, yl);
        let (pn, e3) = two_sum(q1, -q2);
        let (kh, e4) = two_sum(pn, -offset);
        (kh, (e1 - e2 + e3 + e4) - pn * he, he)
    } else {
        (k, T::zero(), T::zero())
    };
    let negative = kh < T::zero();
    let (h, hl) = (select(negative, -kh, kh), select(negative, -kl, kl));
    // `l - h` is exact where it matters (Sterbenz), as in the scalar form.
    let gap = (l - h) - hl;
    let band = T::lit(4.0) * T::eps() * l;
    let ok = (l > T::zero()) & (gap > band);
    let gap = select(gap > T::zero(), gap, T::zero());
    let half = sign * sqrt(gap * (l + h));
    let k = kh + kl;
    let r1x = g.dx * half + g.dy * k;
    let r1y = g.dy * half - g.dx * k;
    let (r1x, r1y, t) = if compensated::<T>() {
        (r1x - r1x * he, r1y - r1y * he, t - t * he)
    } else {
        (r1x, r1y, t)
    };
    let det = r1x * g.dx + r1y * g.dy;
    let scale_sq = (r1x * r1x + r1y * r1y) * (g.dx * g.dx + g.dy * g.dy);
    let kk = T::lit(2.0 * SINGULAR_RELATIVE) * T::eps();
    // `scale_sq` is a fourth power of the lengths: outside the normal range
    // (f32 lengths below about 1e-10 or above 4e9) the products above lose
    // bits or overflow, and the element goes to the scalar path, which
    // scales them exactly (`dyad::rrp`).
    let (lo, hi) = normal_range::<T>();
    let ok = ok & (scale_sq >= lo) & (scale_sq <= hi);
    let ok_rate = det * det > kk * kk * scale_sq;
    Rrp {
        x: ax + r1x,
        y: ay + r1y,
        r1x,
        r1y,
        s: t + half,
        inv_det: T::one() / select(ok_rate, det, T::one()),
        ok,
        ok_rate,
    }
}

/// `(omega1, s_dot, vcx, vcy)`: link 1's angular velocity (rad/s), the
/// block's speed along the guide relative to the guide's body (L/s) and the
/// velocity of `C` (L/s), from the velocity of `A` and the guide body's
/// motion (`None`: fixed guide).
#[inline(always)]
pub fn rrp_rates<T: Real>(
    g: &Rrp<T>,
    line: &Line<T>,
    vax: T,
    vay: T,
    gv: Option<&LineVelocity<T>>,
) -> (T, T, T, T) {
    let vm = transport_velocity(line, g.x, g.y, gv);
    let (wx, wy) = difference(vm, Some((vax, vay)));
    let omega1 = (line.dx * wy - line.dy * wx) * g.inv_det;
    let s_dot = -(wx * g.r1x + wy * g.r1y) * g.inv_det;
    (omega1, s_dot, vax - g.r1y * omega1, vay + g.r1x * omega1)
}

/// `(alpha1, s_ddot, acx, acy)` from the acceleration of `A`, the rates and
/// the guide body's motion.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub fn rrp_accels<T: Real>(
    g: &Rrp<T>,
    line: &Line<T>,
    aax: T,
    aay: T,
    omega1: T,
    s_dot: T,
    gv: Option<&LineVelocity<T>>,
    ga: Option<&LineAcceleration<T>>,
) -> (T, T, T, T) {
    let rel = (line.dx * s_dot, line.dy * s_dot);
    let am = transport_acceleration(line, g.x, g.y, gv, ga, rel);
    let (dx, dy) = difference(am, Some((aax, aay)));
    let w2 = omega1 * omega1;
    let (wx, wy) = (dx + g.r1x * w2, dy + g.r1y * w2);
    let alpha1 = (line.dx * wy - line.dy * wx) * g.inv_det;
    let s_ddot = -(wx * g.r1x + wy * g.r1y) * g.inv_det;
    let (tx, ty) = super::rel_acc(g.r1x, g.r1y, omega1, alpha1);
    (alpha1, s_ddot, aax + tx, aay + ty)
}
