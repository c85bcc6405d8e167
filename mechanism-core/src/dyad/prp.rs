//! PRP group: two blocks joined by the revolute `C`; block 1 (link 1) slides on
//! guide `g1`, block 2 (link 2) on guide `g2`. Each guide may be carried by a
//! moving body.
//!
//! ```text
//!                     g2 (dir2)
//!                    /
//!                 [=C=]          C = g1.at(s1, offset1) = g2.at(s2, offset2)
//!                  /
//!   ===[=]========/===========>  g1 (dir1)
//!      block 1   /  block 2
//! ```
//!
//! `C` is the intersection of the two offset lines (each guide shifted left of
//! its direction by its offset). The closure is unique: there is no mode.
//!
//! Position: `s1 dir1 - s2 dir2 = q`, with `q` the offset origin of `g2` minus
//! that of `g1`, `q = g2.origin + offset2 perp(dir2) - g1.origin -
//! offset1 perp(dir1)`; crossing with `dir2` and `dir1` gives
//! `s1 = cross(q, dir2) / D`, `s2 = cross(q, dir1) / D`, `D = cross(dir1, dir2)`
//! (the sine of the angle between the guides: zero when they are parallel).
//!
//! Rates: `vC = v_body1(C) + s1_dot dir1 = v_body2(C) + s2_dot dir2`, so
//! `s1_dot dir1 - s2_dot dir2 = v_body2(C) - v_body1(C)`: the same matrix.
//! Each block turns with its guide's body; their angular rates are the guides'.
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

const P: Primitive = Primitive::Prp;

/// Closed PRP group.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PrpPosition<T: Real> {
    /// The revolute `C` between the blocks (L).
    pub c: Point2<T>,
    /// Displacement of `C` along `g1.dir` from `g1.origin` (L).
    pub s1: T,
    /// Displacement of `C` along `g2.dir` from `g2.origin` (L).
    pub s2: T,
}

/// Rates of the PRP group.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PrpVelocity<T: Real> {
    /// Sliding speed of block 1 along `g1`, relative to `g1`'s body (L/s).
    pub s1_dot: T,
    /// Sliding speed of block 2 along `g2`, relative to `g2`'s body (L/s).
    pub s2_dot: T,
    /// Absolute velocity of `C` (L/s).
    pub vc: Vector2<T>,
    /// Condition indicator of the rate system, `|det| / scale` in `(16 eps, 1]`:
    /// `|cross(dir1, dir2)|`: `|sin|` of the angle between the guides. `1` is the
    /// best-conditioned pose, `0` the singular one (below `16 eps` velocity returns
    /// `Singular`); the rates' relative error is about `eps / condition` at most
    /// (`docs/stability.md`). The same number governs the accelerations (same
    /// matrix).
    pub condition: T,
}

/// Accelerations of the PRP group.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PrpAcceleration<T: Real> {
    /// Sliding acceleration of block 1 relative to `g1`'s body (L/s^2).
    pub s1_ddot: T,
    /// Sliding acceleration of block 2 relative to `g2`'s body (L/s^2).
    pub s2_ddot: T,
    /// Absolute acceleration of `C` (L/s^2).
    pub ac: Vector2<T>,
}

/// Determinant `cross(dir1, dir2)`, checked against `16 eps |dir1| |dir2|`.
#[inline(always)]
fn determinant<T: Real>(g1: &Line<T>, g2: &Line<T>) -> Result<(T, T), Error<T>> {
    check_det_condition(
        cross(&g1.dir, &g2.dir),
        length(&g1.dir) * length(&g2.dir),
        P,
    )
}

/// Closes the group: `C = g1.at(s1, offset1) = g2.at(s2, offset2)` (offsets in
/// L, left of each guide's direction positive). Both directions must be unit
/// vectors.
///
/// Errors: `NonFinite` for non-finite inputs or results; `Singular` when the
/// guides are parallel to rounding (`|cross(dir1, dir2)| <= 16 eps`).
#[inline(always)]
pub fn position<T: Real>(
    g1: &Line<T>,
    offset1: T,
    g2: &Line<T>,
    offset2: T,
) -> Result<PrpPosition<T>, Error<T>> {
    let offset1 = finite(offset1, P, "PRP offset 1")?;
    let offset2 = finite(offset2, P, "PRP offset 2")?;
    let d1 = finite_vec(g1.dir, P, "PRP guide 1 direction")?;
    let d2 = finite_vec(g2.dir, P, "PRP guide 2 direction")?;
    let q = finite_vec(
        (g2.origin - g1.origin) + perp(&d2) * offset2 - perp(&d1) * offset1,
        P,
        "PRP distance between the guides",
    )?;
    let (det, _) = determinant(g1, g2)?;
    let s1 = finite(cross(&q, &d2) / det, P, "PRP displacement s1")?;
    let s2 = finite(cross(&q, &d1) / det, P, "PRP displacement s2")?;
    let c = finite_point(g1.at(s1, offset1), P, "PRP joint C")?;
    Ok(PrpPosition { c, s1, s2 })
}

/// Rates of the group from the motions of the guides' bodies (`None`: fixed).
///
/// With `w = v_body2(C) - v_body1(C)`: `s1_dot = cross(w, dir2) / D`,
/// `s2_dot = cross(w, dir1) / D`; `vc = v_body1(C) + s1_dot dir1`.
///
/// Errors: `Singular` for parallel guides; `NonFinite` for a non-finite input
/// or result.
#[inline(always)]
pub fn velocity<T: Real>(
    pos: &PrpPosition<T>,
    g1: &Line<T>,
    g2: &Line<T>,
    gv1: Option<&LineVelocity<T>>,
    gv2: Option<&LineVelocity<T>>,
) -> Result<PrpVelocity<T>, Error<T>> {
    let (det, condition) = determinant(g1, g2)?;
    let vm1 = transport_velocity(g1, &pos.c, gv1);
    let vm2 = transport_velocity(g2, &pos.c, gv2);
    let w = finite_vec(
        difference(vm2.as_ref(), vm1.as_ref()),
        P,
        "PRP guide velocity",
    )?;
    let s1_dot = finite(cross(&w, &g2.dir) / det, P, "PRP sliding speed 1")?;
    let s2_dot = finite(cross(&w, &g1.dir) / det, P, "PRP sliding speed 2")?;
    let vc = finite_vec(plus(vm1.as_ref(), g1.dir * s1_dot), P, "PRP velocity of C")?;
    Ok(PrpVelocity {
        s1_dot,
        s2_dot,
        vc,
        condition,
    })
}

/// Accelerations of the group from the guides' bodies' motions (`gv`/`ga`;
/// `None` counts as zero) and the rates.
///
/// Differentiating once more (each direction turns at its body's `omega`):
/// `s1_ddot dir1 - s2_ddot dir2 = [a_body2(C) + 2 omega2 s2_dot perp(dir2)] -
/// [a_body1(C) + 2 omega1 s1_dot perp(dir1)]`, the same matrix as for the rates.
/// Errors as for [`velocity`].
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub fn acceleration<T: Real>(
    pos: &PrpPosition<T>,
    g1: &Line<T>,
    g2: &Line<T>,
    vel: &PrpVelocity<T>,
    gv1: Option<&LineVelocity<T>>,
    ga1: Option<&LineAcceleration<T>>,
    gv2: Option<&LineVelocity<T>>,
    ga2: Option<&LineAcceleration<T>>,
) -> Result<PrpAcceleration<T>, Error<T>> {
    let (det, _) = determinant(g1, g2)?;
    let am1 = transport_acceleration(g1, &pos.c, gv1, ga1, &(g1.dir * vel.s1_dot));
    let am2 = transport_acceleration(g2, &pos.c, gv2, ga2, &(g2.dir * vel.s2_dot));
    let w = finite_vec(
        difference(am2.as_ref(), am1.as_ref()),
        P,
        "PRP guide acceleration",
    )?;
    let s1_ddot = finite(cross(&w, &g2.dir) / det, P, "PRP sliding acceleration 1")?;
    let s2_ddot = finite(cross(&w, &g1.dir) / det, P, "PRP sliding acceleration 2")?;
    let ac = finite_vec(
        plus(am1.as_ref(), g1.dir * s1_ddot),
        P,
        "PRP acceleration of C",
    )?;
    Ok(PrpAcceleration {
        s1_ddot,
        s2_ddot,
        ac,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// With every coordinate, offset and guide speed times `2^j`, `C`,
    /// `s1`, `s2` and the sliding speeds and accelerations scale by exactly
    /// `2^j` (f32 `j` in -100 ..= 120, lengths 8e-31 .. 1e36; f64 -1000 ..=
    /// 1000), guides at 0.3 and 1.9 rad (directions rounded from `(cos,
    /// sin)`), guide 1 on a body turning at 0.8 rad/s and 0.3 rad/s^2.
    #[test]
    fn power_of_two_scaling_is_exact() {
        fn check<T: Real>(range: core::ops::RangeInclusive<i32>) -> usize {
            let line = |x: f64, y: f64, angle: f64, f: T| Line {
                origin: Point2::new(T::lit(x), T::lit(y)) * f,
                dir: Vector2::new(T::lit(angle.cos()), T::lit(angle.sin())),
            };
            let solve = |f: T| {
                let (g1, g2) = (line(0.3, -0.2, 0.3, f), line(-0.5, 0.7, 1.9, f));
                let gv = LineVelocity {
                    v_origin: Vector2::new(T::lit(0.4), T::lit(-0.6)) * f,
                    omega: T::lit(0.8),
                };
                let ga = LineAcceleration {
                    a_origin: Vector2::new(T::lit(-0.1), T::lit(0.2)) * f,
                    alpha: T::lit(0.3),
                };
                let p = position(&g1, T::lit(0.05) * f, &g2, T::lit(-0.02) * f).unwrap();
                let v = velocity(&p, &g1, &g2, Some(&gv), None).unwrap();
                let a = acceleration(&p, &g1, &g2, &v, Some(&gv), Some(&ga), None, None).unwrap();
                (p, v, a)
            };
            let (p1, v1, a1) = solve(T::one());
            let mut n = 0;
            for j in range.step_by(7) {
                let f = T::lit(2f64.powi(j));
                let (p, v, a) = solve(f);
                assert_eq!((p.c, p.s1, p.s2), (p1.c * f, p1.s1 * f, p1.s2 * f), "2^{j}");
                assert_eq!(
                    (v.s1_dot, v.s2_dot, v.vc),
                    (v1.s1_dot * f, v1.s2_dot * f, v1.vc * f),
                    "2^{j}"
                );
                assert_eq!(v.condition, v1.condition, "2^{j}");
                assert_eq!(
                    (a.s1_ddot, a.s2_ddot, a.ac),
                    (a1.s1_ddot * f, a1.s2_ddot * f, a1.ac * f),
                    "2^{j}"
                );
                n += 1;
            }
            n
        }
        assert!(check::<f32>(-100..=120) + check::<f64>(-1000..=1000) > 300);
    }
}
