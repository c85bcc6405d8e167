//! RRP group: link 1 turns about the known point `A` and carries, at distance
//! `l`, the revolute `C` of a block (link 2) that slides on a guide `g`.
//!
//! ```text
//!           A
//!           |\  l (link 1)         Mode::Plus : C ahead of F along g.dir
//!           | \                    Mode::Minus: C behind F (mirror image)
//!   --------F--C[block]-------->  offset line: g shifted left by `offset`
//!
//!   g.origin o----------------->  guide g, direction g.dir
//! ```
//!
//! `F` is the foot of the perpendicular from `A` on the offset line, the line
//! that `C` travels on: `C = g.at(s, offset) = g.origin + s dir + offset perp(dir)`.
//!
//! Position in vector form: with `p = A - g.origin`, `A`'s coordinates in the
//! guide's frame are `t = dot(p, dir)` along and `k = dot(p, perp(dir)) - offset`
//! across the offset line; `|C - A| = l` gives `(s - t)^2 + k^2 = l^2`, so
//! `s = t + m sqrt((l - |k|)(l + |k|))` (`m = +1` for `Plus`), the factored
//! form losing no digits near tangency (`|k| = l`).
//!
//! Near tangency the half chord `sqrt(l^2 - k^2)` amplifies an error `dk` of
//! `k` by `|k| / sqrt(l^2 - k^2)`. In f32, where that matters, `l - |k|` is
//! then formed from `k` carried as `kh + kl` (the products' and sums'
//! rounding errors kept by Dekker's product and Knuth's two-sum: no fused
//! multiply-add needed), and from the guide's direction divided by its
//! length: a direction rounded from `(cos, sin)` is off unit length by up to
//! an ulp, which taken as exact scales `k` by the same relative amount. In
//! the f32 six-bar (`docs/stability.md`, "f32 six-bar") the two together were
//! half of the largest rate error.
//!
//! Rates: differentiating `A + r1 = C` (`r1 = C - A`, turning at `omega1`) and
//! `C = g.at(s, offset)` on a guide body moving at `(v_origin, omega)` gives
//! `omega1 perp(r1) - s_dot dir = v_body(C) - vA`, a 2x2 system with columns
//! `perp(r1)`, `-dir` and determinant `dot(r1, dir) = m sqrt(l^2 - k^2)`: zero
//! when link 1 is perpendicular to the guide (the block cannot be pushed along).
//! The block turns with the guide body; its angular rates are the guide's.
//! Units: lengths in the user's unit L, rates per second; angular rates in rad/s.

use crate::driver::slider::{transport_acceleration, transport_velocity};
use crate::eft::{compensated, half_excess, split, two_product_split, two_sum};
use crate::error::{Error, Fault, Primitive};
use crate::geometry::{
    abs, check_det_condition, cross, difference, dot, finite, finite_point, finite_vec, length,
    perp, plus, positive,
};
use crate::guide::{Line, LineAcceleration, LineVelocity};
use crate::link::{relative_acceleration, relative_velocity};
use crate::mode::Mode;
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::Rrp;

/// Closed RRP group.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RrpPosition<T: Real> {
    /// The revolute `C` between link 1 and the block (L).
    pub c: Point2<T>,
    /// `C - A`: link 1 as a vector, length `l` (L). Its direction is link 1's axis.
    pub r1: Vector2<T>,
    /// Displacement of `C` along `g.dir` from `g.origin` (L): `C = g.at(s, offset)`.
    pub s: T,
}

/// Rates of the RRP group.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RrpVelocity<T: Real> {
    /// Angular velocity of link 1 (rad/s, counter-clockwise positive).
    pub omega1: T,
    /// Sliding speed of the block along the guide, relative to the guide's body
    /// (L/s, positive along `g.dir`).
    pub s_dot: T,
    /// Absolute velocity of `C` (L/s).
    pub vc: Vector2<T>,
    /// Condition indicator of the rate system, `|det| / scale` in `(16 eps, 1]`:
    /// `|dot(r1, dir)| / l`: `|cos|` of the angle between link 1 and the guide. `1`
    /// is the best-conditioned pose, `0` the singular one (below `16 eps` velocity
    /// returns `Singular`); the rates' relative error is about `eps / condition` at
    /// most (`docs/stability.md`). The same number governs the accelerations (same
    /// matrix).
    pub condition: T,
}

/// Accelerations of the RRP group.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RrpAcceleration<T: Real> {
    /// Angular acceleration of link 1 (rad/s^2).
    pub alpha1: T,
    /// Sliding acceleration of the block relative to the guide's body (L/s^2).
    pub s_ddot: T,
    /// Absolute acceleration of `C` (L/s^2).
    pub ac: Vector2<T>,
}

/// Closes the group: finds `C` on the line `g` shifted by `offset` (L, left of
/// `g.dir` positive) with `|C - A| = l` (L), ahead of the foot `F` of the
/// perpendicular from `A` along `g.dir` for `Mode::Plus` (`dot(C - A, dir) >= 0`),
/// behind it for `Mode::Minus`. `g.dir` must be a unit vector.
///
/// Errors: `NonPositive` for `l <= 0`; `NonFinite` for non-finite inputs;
/// `CannotAssemble { miss: |k| - l, reach: l }` when `A` lies farther than `l`
/// from the offset line (distance `|k|`) by more than `4 eps l` (inside that
/// rounding band `C` is put at `F`, the tangent position).
#[inline(always)]
pub fn position<T: Real>(
    a: &Point2<T>,
    l: T,
    g: &Line<T>,
    offset: T,
    mode: Mode,
) -> Result<RrpPosition<T>, Error<T>> {
    let l = positive(l, P, "RRP length l")?;
    let offset = finite(offset, P, "RRP guide offset")?;
    let dir = finite_vec(g.dir, P, "RRP guide direction")?;
    let p = finite_vec(a - g.origin, P, "RRP distance from the guide origin")?;
    let n = perp(&dir);
    let k0 = dot(&p, &n) - offset;
    // Near tangency (`l - |k| < l / 4`, where the half chord amplifies an
    // error of `k` by more than 1.1) and in f32, `k` is carried as `kh + kl`:
    // `dot(p, n) / |dir| - offset` with the roundings of the products and sums
    // kept, and the division by `|dir|` done to first order, `x / |dir| =
    // x - x he` with `he = (|dir|^2 - 1) / 2` computed exactly enough (its
    // error `(3/8)(2 he)^2 x` is below the rounding while `|dir|^2 - 1` is
    // below `sqrt(eps)`; a direction rounded from `(cos, sin)` is off unit
    // length by about an ulp). Elsewhere both corrections stay below an ulp.
    let (kh, kl, he) = if compensated::<T>() && l - abs(k0) < T::lit(0.25) * l {
        let (xh, xl) = split(dir.x);
        let (yh, yl) = split(dir.y);
        let he = half_excess(dir.x, xh, xl, dir.y, yh, yl);
        let (q1, e1) = two_product_split(p.y, dir.x, xh, xl);
        let (q2, e2) = two_product_split(p.x, dir.y, yh, yl);
        let (pn, e3) = two_sum(q1, -q2);
        let (kh, e4) = two_sum(pn, -offset);
        (kh, (e1 - e2 + e3 + e4) - pn * he, he)
    } else {
        (k0, T::zero(), T::zero())
    };
    let (h, hl) = if kh < T::zero() { (-kh, -kl) } else { (kh, kl) };
    // `l - h` is exact where it matters (h within a factor 2 of l: Sterbenz).
    let gap = (l - h) - hl; // < 0: the circle about A misses the line
    let band = T::lit(4.0) * T::eps() * l;
    // (A NaN `gap`, from an overflowing product, flows on to the finite checks.)
    if gap < -band {
        return Err(Error::new(
            P,
            Fault::CannotAssemble {
                miss: -gap,
                reach: l,
            },
        ));
    }
    let gap = if gap < T::zero() { T::zero() } else { gap };
    // Half chord, sqrt(l^2 - k^2) factored: no cancellation near tangency.
    let half = mode.sign::<T>() * (gap * (l + h)).sqrt_kernel();
    let k = kh + kl;
    // `dir half - n k` over `|dir|`, and `t = dot(p, dir) / |dir|`.
    let r = dir * half - n * k;
    let t = dot(&p, &dir);
    let (r1, t) = if he != T::zero() {
        (r - r * he, t - t * he)
    } else {
        (r, t)
    };
    let s = finite(t + half, P, "RRP slide displacement s")?;
    let c = finite_point(a + r1, P, "RRP joint C")?;
    Ok(RrpPosition { c, r1, s })
}

/// Determinant of the rate system, `dot(r1, dir) = +-sqrt(l^2 - k^2)`, checked
/// against `16 eps |r1| |dir|`.
#[inline(always)]
fn determinant<T: Real>(pos: &RrpPosition<T>, g: &Line<T>) -> Result<(T, T), Error<T>> {
    check_det_condition(dot(&pos.r1, &g.dir), length(&pos.r1) * length(&g.dir), P)
}

/// Rates of the group from the velocity of `A` (L/s; `None`: fixed) and the
/// motion of the guide's body (`None`: fixed guide).
///
/// With `w = v_body(C) - vA`: `omega1 = cross(dir, w) / det`,
/// `s_dot = -dot(w, r1) / det`, `det = dot(r1, dir)`; `vc = vA + omega1 perp(r1)`
/// (which equals `v_body(C) + s_dot dir`).
///
/// Errors: `Singular` when `|dot(r1, dir)| <= 16 eps l` (link 1 perpendicular to
/// the guide: tangency); `NonFinite` for a non-finite input or result.
#[inline(always)]
pub fn velocity<T: Real>(
    pos: &RrpPosition<T>,
    g: &Line<T>,
    va: Option<&Vector2<T>>,
    gv: Option<&LineVelocity<T>>,
) -> Result<RrpVelocity<T>, Error<T>> {
    let (det, condition) = determinant(pos, g)?;
    let vm = transport_velocity(g, &pos.c, gv);
    let w = finite_vec(difference(vm.as_ref(), va), P, "RRP joint velocity")?;
    let omega1 = finite(cross(&g.dir, &w) / det, P, "RRP angular velocity")?;
    let s_dot = finite(-dot(&w, &pos.r1) / det, P, "RRP sliding speed")?;
    let vc = finite_vec(
        plus(va, relative_velocity(&pos.r1, omega1)),
        P,
        "RRP velocity of C",
    )?;
    Ok(RrpVelocity {
        omega1,
        s_dot,
        vc,
        condition,
    })
}

/// Accelerations of the group from the acceleration of `A` (L/s^2; `None`:
/// fixed), the rates, and the guide body's motion (`gv`/`ga`; either `None`
/// counts as zero).
///
/// Differentiating once more (the guide direction turns at the body's `omega`):
/// `alpha1 perp(r1) - s_ddot dir = a_body(C) + 2 omega s_dot perp(dir) - aA +
/// omega1^2 r1`, the same matrix as for the rates. Errors as for [`velocity`].
#[inline(always)]
pub fn acceleration<T: Real>(
    pos: &RrpPosition<T>,
    g: &Line<T>,
    vel: &RrpVelocity<T>,
    aa: Option<&Vector2<T>>,
    gv: Option<&LineVelocity<T>>,
    ga: Option<&LineAcceleration<T>>,
) -> Result<RrpAcceleration<T>, Error<T>> {
    let (det, _) = determinant(pos, g)?;
    let am = transport_acceleration(g, &pos.c, gv, ga, &(g.dir * vel.s_dot));
    let w = finite_vec(
        difference(am.as_ref(), aa) + pos.r1 * (vel.omega1 * vel.omega1),
        P,
        "RRP joint acceleration",
    )?;
    let alpha1 = finite(cross(&g.dir, &w) / det, P, "RRP angular acceleration")?;
    let s_ddot = finite(-dot(&w, &pos.r1) / det, P, "RRP sliding acceleration")?;
    let ac = finite_vec(
        plus(aa, relative_acceleration(&pos.r1, vel.omega1, alpha1)),
        P,
        "RRP acceleration of C",
    )?;
    Ok(RrpAcceleration { alpha1, s_ddot, ac })
}
