//! RPP group: a block (link 1) pinned at the known point `A` slides in a
//! straight slot of link 2; link 2 translates along the guide `g` (it turns
//! with `g`'s body). The sine mechanism / Scotch yoke.
//!
//! ```text
//!               ^ g.dir: link 2 translates along the guide
//!               |
//!               Q=========[=A=]=========>  slot of link 2, direction w
//!               |    s1    block           (g.dir turned by beta)
//!               | s2                       A = Q + s1 w
//!      g.origin o                          Q = g.at(s2, offset)
//! ```
//!
//! `Q` is link 2's reference point, on the guide's offset line; the slot passes
//! through `Q` with the unit direction `w = cos(beta) dir + sin(beta) perp(dir)`,
//! given by `slot_dir_local = (cos beta, sin beta)` (fixed on link 2). The
//! closure is unique: there is no mode.
//!
//! Position: `s1 w + s2 dir = A - g.origin - offset perp(dir) = q`; crossing with
//! `dir` and `w`: `s1 = cross(dir, q) / D`, `s2 = cross(q, w) / D`,
//! `D = cross(dir, w) = sin(beta)`: zero when the slot is parallel to the guide.
//!
//! Rates: relative to `g`'s body, `A` moves at `s1_dot w + s2_dot dir` (`w` is
//! fixed in that body), so `s1_dot w + s2_dot dir = vA - v_body(A)`: the same
//! matrix. Accelerations add the Coriolis term of that relative velocity.
//! Units: lengths in the user's unit L, rates per second.
//!
//! Range of scale: every product pairs a length or a speed with a unit
//! direction (no product of two lengths), so the group is exact under
//! powers of two and as accurate at any scale as at 1 while the
//! coordinates and results are normal numbers of `T`: f32 lengths about
//! 1e-30 .. 1e36, f64 1e-300 .. 1e306 (bit for bit scale-invariant there:
//! the test below).

use crate::driver::slider::{transport_acceleration, transport_velocity};
use crate::error::{Error, Primitive};
use crate::geometry::{
    check_det_condition, cross, difference, finite, finite_point, finite_vec, length, perp, plus,
};
use crate::guide::{Line, LineAcceleration, LineVelocity};
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::Rpp;

/// Closed RPP group.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RppPosition<T: Real> {
    /// Link 2's reference point `Q = g.at(s2, offset)` (L), where the slot
    /// crosses the guide's offset line.
    pub q: Point2<T>,
    /// The slot's unit direction `w` in world axes.
    pub slot: Vector2<T>,
    /// Place of the block in the slot (L): `A = Q + s1 w`.
    pub s1: T,
    /// Displacement of link 2 along `g.dir` from `g.origin` (L).
    pub s2: T,
}

/// Rates of the RPP group.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RppVelocity<T: Real> {
    /// Sliding speed of the block in the slot, relative to link 2 (L/s).
    pub s1_dot: T,
    /// Sliding speed of link 2 along `g`, relative to `g`'s body (L/s).
    pub s2_dot: T,
    /// Absolute velocity of `Q` (L/s).
    pub vq: Vector2<T>,
    /// Condition indicator of the rate system, `|det| / scale` in `(16 eps, 1]`:
    /// `|sin beta|`: `|sin|` of the angle between the slot and the guide. `1` is
    /// the best-conditioned pose, `0` the singular one (below `16 eps` velocity
    /// returns `Singular`); the rates' relative error is about `eps / condition` at
    /// most (`docs/stability.md`). The same number governs the accelerations (same
    /// matrix).
    pub condition: T,
}

/// Accelerations of the RPP group.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RppAcceleration<T: Real> {
    /// Sliding acceleration of the block relative to link 2 (L/s^2).
    pub s1_ddot: T,
    /// Sliding acceleration of link 2 relative to `g`'s body (L/s^2).
    pub s2_ddot: T,
    /// Absolute acceleration of `Q` (L/s^2).
    pub aq: Vector2<T>,
}

/// Determinant `cross(dir, w) = sin(beta)`, checked against `16 eps |dir| |w|`.
#[inline(always)]
fn determinant<T: Real>(dir: &Vector2<T>, w: &Vector2<T>) -> Result<(T, T), Error<T>> {
    check_det_condition(cross(dir, w), length(dir) * length(w), P)
}

/// Closes the group: finds `s1`, `s2` with `A = g.at(s2, offset) + s1 w`,
/// `w = slot_dir_local.x dir + slot_dir_local.y perp(dir)` (`offset` in L, left
/// of `g.dir` positive; `g.dir` and `slot_dir_local` unit vectors).
///
/// Errors: `NonFinite` for non-finite inputs or results; `Singular` when the
/// slot is parallel to the guide to rounding (`|sin beta| <= 16 eps`).
#[inline(always)]
pub fn position<T: Real>(
    a: &Point2<T>,
    g: &Line<T>,
    offset: T,
    slot_dir_local: &Vector2<T>,
) -> Result<RppPosition<T>, Error<T>> {
    let offset = finite(offset, P, "RPP guide offset")?;
    let dir = finite_vec(g.dir, P, "RPP guide direction")?;
    let local = finite_vec(*slot_dir_local, P, "RPP slot direction")?;
    let n = perp(&dir);
    let w = dir * local.x + n * local.y;
    let q = finite_vec(
        (a - g.origin) - n * offset,
        P,
        "RPP distance from the guide",
    )?;
    let (det, _) = determinant(&dir, &w)?;
    let s1 = finite(cross(&dir, &q) / det, P, "RPP displacement s1")?;
    let s2 = finite(cross(&q, &w) / det, P, "RPP displacement s2")?;
    let qp = finite_point(g.at(s2, offset), P, "RPP point Q")?;
    Ok(RppPosition {
        q: qp,
        slot: w,
        s1,
        s2,
    })
}

/// Rates of the group from the velocity of `A` (L/s; `None`: fixed) and the
/// motion of `g`'s body (`None`: fixed guide).
///
/// With `r = vA - v_body(A)`: `s1_dot = cross(dir, r) / D`,
/// `s2_dot = cross(r, w) / D`; `vq = v_body(Q) + s2_dot dir`.
/// Link 2's angular velocity is the guide body's.
///
/// Errors: `Singular` when the slot is parallel to the guide; `NonFinite` for a
/// non-finite input or result.
#[inline(always)]
pub fn velocity<T: Real>(
    pos: &RppPosition<T>,
    a: &Point2<T>,
    g: &Line<T>,
    va: Option<&Vector2<T>>,
    gv: Option<&LineVelocity<T>>,
) -> Result<RppVelocity<T>, Error<T>> {
    let (det, condition) = determinant(&g.dir, &pos.slot)?;
    let vma = transport_velocity(g, a, gv);
    let r = finite_vec(difference(va, vma.as_ref()), P, "RPP relative velocity")?;
    let s1_dot = finite(cross(&g.dir, &r) / det, P, "RPP sliding speed 1")?;
    let s2_dot = finite(cross(&r, &pos.slot) / det, P, "RPP sliding speed 2")?;
    let vmq = transport_velocity(g, &pos.q, gv);
    let vq = finite_vec(plus(vmq.as_ref(), g.dir * s2_dot), P, "RPP velocity of Q")?;
    Ok(RppVelocity {
        s1_dot,
        s2_dot,
        vq,
        condition,
    })
}

/// Accelerations of the group from the acceleration of `A` (L/s^2; `None`:
/// fixed), the rates and the guide body's motion (`gv`/`ga`; `None` counts as
/// zero).
///
/// Differentiating once more in the guide body's frame:
/// `s1_ddot w + s2_ddot dir = aA - a_body(A) - 2 omega perp(s1_dot w + s2_dot dir)`,
/// the same matrix; `aq = a_body(Q) + 2 omega s2_dot perp(dir) + s2_ddot dir`.
/// Errors as for [`velocity`].
#[inline(always)]
pub fn acceleration<T: Real>(
    pos: &RppPosition<T>,
    a: &Point2<T>,
    g: &Line<T>,
    vel: &RppVelocity<T>,
    aa: Option<&Vector2<T>>,
    gv: Option<&LineVelocity<T>>,
    ga: Option<&LineAcceleration<T>>,
) -> Result<RppAcceleration<T>, Error<T>> {
    let (det, _) = determinant(&g.dir, &pos.slot)?;
    let rel_a = pos.slot * vel.s1_dot + g.dir * vel.s2_dot;
    let ama = transport_acceleration(g, a, gv, ga, &rel_a);
    let r = finite_vec(difference(aa, ama.as_ref()), P, "RPP relative acceleration")?;
    let s1_ddot = finite(cross(&g.dir, &r) / det, P, "RPP sliding acceleration 1")?;
    let s2_ddot = finite(cross(&r, &pos.slot) / det, P, "RPP sliding acceleration 2")?;
    let amq = transport_acceleration(g, &pos.q, gv, ga, &(g.dir * vel.s2_dot));
    let aq = finite_vec(
        plus(amq.as_ref(), g.dir * s2_ddot),
        P,
        "RPP acceleration of Q",
    )?;
    Ok(RppAcceleration {
        s1_ddot,
        s2_ddot,
        aq,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// With every coordinate, the offset and the speeds times `2^j`, `Q`,
    /// `s1`, `s2` and the sliding speeds and accelerations scale by exactly
    /// `2^j` (f32 `j` in -100 ..= 120, lengths 8e-31 .. 1e36; f64 -1000 ..=
    /// 1000): guide at 0.3 rad on a body turning at 0.8 rad/s and 0.3
    /// rad/s^2, slot at 1.1 rad to it.
    #[test]
    fn power_of_two_scaling_is_exact() {
        fn check<T: Real>(range: core::ops::RangeInclusive<i32>) -> usize {
            let solve = |f: T| {
                let g = Line {
                    origin: Point2::new(T::lit(0.3), T::lit(-0.2)) * f,
                    dir: Vector2::new(T::lit(0.3f64.cos()), T::lit(0.3f64.sin())),
                };
                let slot = Vector2::new(T::lit(1.1f64.cos()), T::lit(1.1f64.sin()));
                let a = Point2::new(T::lit(0.9), T::lit(0.6)) * f;
                let va = Vector2::new(T::lit(-0.3), T::lit(0.5)) * f;
                let aa = Vector2::new(T::lit(0.2), T::lit(0.1)) * f;
                let gv = LineVelocity {
                    v_origin: Vector2::new(T::lit(0.4), T::lit(-0.6)) * f,
                    omega: T::lit(0.8),
                };
                let ga = LineAcceleration {
                    a_origin: Vector2::new(T::lit(-0.1), T::lit(0.2)) * f,
                    alpha: T::lit(0.3),
                };
                let p = position(&a, &g, T::lit(0.05) * f, &slot).unwrap();
                let v = velocity(&p, &a, &g, Some(&va), Some(&gv)).unwrap();
                let acc = acceleration(&p, &a, &g, &v, Some(&aa), Some(&gv), Some(&ga)).unwrap();
                (p, v, acc)
            };
            let (p1, v1, a1) = solve(T::one());
            let mut n = 0;
            for j in range.step_by(7) {
                let f = T::lit(2f64.powi(j));
                let (p, v, a) = solve(f);
                assert_eq!((p.q, p.s1, p.s2), (p1.q * f, p1.s1 * f, p1.s2 * f), "2^{j}");
                assert_eq!(p.slot, p1.slot, "2^{j}");
                assert_eq!(
                    (v.s1_dot, v.s2_dot, v.vq),
                    (v1.s1_dot * f, v1.s2_dot * f, v1.vq * f),
                    "2^{j}"
                );
                assert_eq!(v.condition, v1.condition, "2^{j}");
                assert_eq!(
                    (a.s1_ddot, a.s2_ddot, a.aq),
                    (a1.s1_ddot * f, a1.s2_ddot * f, a1.aq * f),
                    "2^{j}"
                );
                n += 1;
            }
            n
        }
        assert!(check::<f32>(-100..=120) + check::<f64>(-1000..=1000) > 300);
    }
}
