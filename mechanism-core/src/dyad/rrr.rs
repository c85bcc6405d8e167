//! RRR group: two links joined by a revolute at `C`, pinned at known points `A`
//! and `B`.
//!
//! ```text
//!             C
//!        l1  / \  l2          Mode::Plus : C to the left of the directed line A -> B
//!           /   \             Mode::Minus: C to the right
//!          A ---- B
//! ```
//!
//! Position uses the law of cosines in vector form (no trigonometry): with
//! `d = B - A`, the foot of `C` on `AB` is at `a = (l1^2 - l2^2 + |d|^2) / (2|d|)`
//! from `A`, and the height is `h = 2 * area / |d|`, the area from Heron's
//! formula in the factored form `(l1+l2+d)(l1+l2-d)(d+l1-l2)(d-l1+l2)`, which
//! loses no digits to cancellation near the edge of assembly.
//!
//! Rates: differentiating `A + r1 = B + r2` (with `r1 = C - A`, `r2 = C - B`)
//! gives `w1 perp(r1) - w2 perp(r2) = vB - vA`; dotting with `r2` and `r1`
//! solves the 2x2 system in closed form with determinant `cross(r1, r2)`
//! (`l1 l2 sin` of the angle between the links: zero at toggle).
//! Units: lengths in the user's unit L, rates per second; angular rates in rad/s.

use crate::error::{Error, Fault, Primitive};
use crate::geometry::{
    abs, check_det_sq, condition_from_sq, cross, difference, dot, finite, finite_point, finite_vec,
    length, perp, plus, positive,
};
use crate::link::{relative_acceleration, relative_velocity};
use crate::mode::Mode;
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::Rrr;

/// Closed RRR group.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RrrPosition<T: Real> {
    /// The inner joint `C` (L).
    pub c: Point2<T>,
    /// `C - A`: link 1 as a vector, length `l1` (L). Its direction is link 1's axis.
    pub r1: Vector2<T>,
    /// `C - B`: link 2 as a vector, length `l2` (L). Its direction is link 2's axis.
    pub r2: Vector2<T>,
}

/// Angular velocities of the two links and the velocity of `C`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RrrVelocity<T: Real> {
    /// Angular velocity of link 1 (rad/s, counter-clockwise positive).
    pub omega1: T,
    /// Angular velocity of link 2 (rad/s).
    pub omega2: T,
    /// Velocity of `C` (L/s).
    pub vc: Vector2<T>,
    /// Condition indicator of the rate system, `|det| / scale` in `(16 eps, 1]`:
    /// `|cross(r1, r2)| / (l1 l2)`: `|sin|` of the angle between the two links. `1`
    /// is the best-conditioned pose, `0` the singular one (below `16 eps` velocity
    /// returns `Singular`); the rates' relative error is about `eps / condition` at
    /// most (`docs/stability.md`). The same number governs the accelerations (same
    /// matrix).
    pub condition: T,
}

/// Angular accelerations of the two links and the acceleration of `C`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RrrAcceleration<T: Real> {
    /// Angular acceleration of link 1 (rad/s^2).
    pub alpha1: T,
    /// Angular acceleration of link 2 (rad/s^2).
    pub alpha2: T,
    /// Acceleration of `C` (L/s^2).
    pub ac: Vector2<T>,
}

/// Closes the group: finds `C` with `|C - A| = l1`, `|C - B| = l2`, on the side
/// of `A -> B` chosen by `mode`.
///
/// Errors: `NonPositive` for `l1` or `l2 <= 0`; `NonFinite` for non-finite
/// points; `CannotAssemble` when `|B - A|` lies outside `[|l1 - l2|, l1 + l2]`
/// by more than `4 eps (l1 + l2)` (inside that rounding band the joint is put on
/// the line, `h = 0`); `Singular` when `A` and `B` coincide (the direction of
/// the line is undefined).
#[inline]
pub fn position<T: Real>(
    a: &Point2<T>,
    l1: T,
    b: &Point2<T>,
    l2: T,
    mode: Mode,
) -> Result<RrrPosition<T>, Error> {
    let l1 = positive(l1, P, "RRR length l1")?;
    let l2 = positive(l2, P, "RRR length l2")?;
    let d = finite_vec(b - a, P, "RRR joint distance")?;
    let dist = length(&d);
    let sum = l1 + l2;
    // Also catches NaN (dist was checked finite, but stay defensive).
    if dist.partial_cmp(&T::zero()) != Some(core::cmp::Ordering::Greater) {
        return Err(Error::new(
            P,
            Fault::Singular {
                det: 0.0,
                scale: sum.as_f64(),
            },
        ));
    }
    // Heron's factors; each negative one means the triangle does not close.
    let outer = sum - dist; // < 0: too far apart
    let inner1 = dist + l1 - l2; // < 0: l2 too long
    let inner2 = dist - l1 + l2; // < 0: l1 too long
    let band = T::lit(4.0) * T::eps() * sum;
    let inner = inner1.min(inner2);
    if outer.min(inner) < -band {
        let (miss, reach) = if outer <= inner {
            (-outer, sum)
        } else {
            (-inner, abs(l1 - l2))
        };
        return Err(Error::new(
            P,
            Fault::CannotAssemble {
                miss: miss.as_f64(),
                reach: reach.as_f64(),
            },
        ));
    }
    let clamp = |x: T| if x < T::zero() { T::zero() } else { x };
    // 16 area^2 = (l1+l2+d)(l1+l2-d)(d+l1-l2)(d-l1+l2); h = 2 area / d.
    let area16 = (sum + dist) * clamp(outer) * clamp(inner1) * clamp(inner2);
    let h = area16.sqrt_kernel() / (T::lit(2.0) * dist);
    // Foot of C on AB, from A: (l1^2 - l2^2 + d^2) / (2d) = ((l1-l2)(l1+l2) + d^2) / (2d).
    let along = ((l1 - l2) * sum + dist * dist) / (T::lit(2.0) * dist);
    let e = d / dist;
    let r1 = e * along + perp(&e) * (mode.sign::<T>() * h);
    let c = finite_point(a + r1, P, "RRR joint C")?;
    Ok(RrrPosition { c, r1, r2: c - b })
}

/// Determinant of the rate system, `cross(r1, r2) = l1 l2 sin(angle between
/// the links)`, checked against `16 eps l1 l2`.
#[inline(always)]
/// The rate system's determinant `cross(r1, r2)`, checked in squared form (no
/// square roots on the hot path: the lengths are l1, l2), and the squared
/// scale `l1^2 l2^2` it was checked against.
fn determinant<T: Real>(pos: &RrrPosition<T>) -> Result<(T, T), Error> {
    let scale_sq = dot(&pos.r1, &pos.r1) * dot(&pos.r2, &pos.r2);
    let det = check_det_sq(cross(&pos.r1, &pos.r2), scale_sq, P)?;
    Ok((det, scale_sq))
}

/// Rates of the group from the velocities of `A` and `B` (L/s); `None` means
/// the point is fixed (its terms vanish at compile time).
///
/// Errors: `Singular` when `|cross(r1, r2)| <= 16 eps l1 l2` (toggle: the two
/// links are aligned); `NonFinite` for a non-finite input.
#[inline]
pub fn velocity<T: Real>(
    pos: &RrrPosition<T>,
    va: Option<&Vector2<T>>,
    vb: Option<&Vector2<T>>,
) -> Result<RrrVelocity<T>, Error> {
    let (det, scale_sq) = determinant(pos)?;
    let condition = condition_from_sq(det, scale_sq);
    let dv = finite_vec(difference(vb, va), P, "RRR joint velocity")?;
    let omega1 = finite(dot(&dv, &pos.r2) / det, P, "RRR omega1")?;
    let omega2 = finite(dot(&dv, &pos.r1) / det, P, "RRR omega2")?;
    let vc = finite_vec(
        plus(va, relative_velocity(&pos.r1, omega1)),
        P,
        "RRR velocity of C",
    )?;
    Ok(RrrVelocity {
        omega1,
        omega2,
        vc,
        condition,
    })
}

/// Accelerations of the group from the accelerations of `A` and `B` (L/s^2;
/// `None`: fixed) and the rates.
///
/// Differentiating once more: `alpha1 perp(r1) - alpha2 perp(r2) =
/// aB - aA + omega1^2 r1 - omega2^2 r2`, the same matrix as for the rates.
/// Errors as for [`velocity`].
#[inline]
pub fn acceleration<T: Real>(
    pos: &RrrPosition<T>,
    vel: &RrrVelocity<T>,
    aa: Option<&Vector2<T>>,
    ab: Option<&Vector2<T>>,
) -> Result<RrrAcceleration<T>, Error> {
    let (det, _) = determinant(pos)?;
    let da = finite_vec(difference(ab, aa), P, "RRR joint acceleration")?;
    let w = da + pos.r1 * (vel.omega1 * vel.omega1) - pos.r2 * (vel.omega2 * vel.omega2);
    let alpha1 = finite(dot(&w, &pos.r2) / det, P, "RRR alpha1")?;
    let alpha2 = finite(dot(&w, &pos.r1) / det, P, "RRR alpha2")?;
    let ac = finite_vec(
        plus(aa, relative_acceleration(&pos.r1, vel.omega1, alpha1)),
        P,
        "RRR acceleration of C",
    )?;
    Ok(RrrAcceleration { alpha1, alpha2, ac })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn three_four_five_triangle_is_exact() {
        // A=(0,0), B=(5,0), l1=3, l2=4: C=(1.8, 2.4) on the left (Plus).
        let p = position(
            &Point2::new(0.0, 0.0),
            3.0,
            &Point2::new(5.0, 0.0),
            4.0,
            Mode::Plus,
        )
        .unwrap();
        assert_eq!(p.c, Point2::new(1.8, 2.4));
        let m = position(
            &Point2::new(0.0, 0.0),
            3.0,
            &Point2::new(5.0, 0.0),
            4.0,
            Mode::Minus,
        )
        .unwrap();
        assert_eq!(m.c, Point2::new(1.8, -2.4));
    }
}
