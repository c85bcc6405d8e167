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
//! Position uses the law of cosines in vector form on squared lengths (no
//! trigonometry, one square root): with `d = B - A` and `D = |d|^2`, the foot
//! of `C` on `AB` is at `k / (2 sqrt D)` from `A`, `k = l1^2 - l2^2 + D =
//! (l1 - l2)(l1 + l2) + D`, and the height is `sqrt(16 area^2) / (2 sqrt D)`,
//! Heron's formula as `16 area^2 = ((l1+l2)^2 - D) (D - (l1-l2)^2)`: each
//! factor is the difference of two quantities known to a rounding or two,
//! clamped at zero inside the rounding band, so the group never returns NaN
//! where it assembles (the textbook `sqrt(l1^2 - a^2)` does, one ulp inside
//! the edge). Near the edge the height's relative error grows as
//! `eps / delta` (`delta` the relative distance to the edge), which is the
//! conditioning of the problem itself for inputs known to an ulp: the same
//! as the form with `l1 + l2 - |d|`, one square root more
//! (`tests/stability/assembly.rs`). Both lengths lie along `d / sqrt D`, so
//! `r1 = C - A = (k d + s sqrt(16 area^2) perp(d)) / (2 D)`, `s = +-1` the
//! mode: no normalized vector, one reciprocal.
//!
//! Rates: differentiating `A + r1 = B + r2` (with `r1 = C - A`, `r2 = C - B`)
//! gives `w1 perp(r1) - w2 perp(r2) = vB - vA`; dotting with `r2` and `r1`
//! solves the 2x2 system in closed form with determinant `cross(r1, r2)`
//! (`l1 l2 sin` of the angle between the links: zero at toggle).
//! Units: lengths in the user's unit L, rates per second; angular rates in rad/s.
//!
//! Range of scale: the position's ordinary path forms `|B - A|^2`, Heron's
//! product (a fourth power) and `d along` (a third power); where one of
//! them would leave the normal range of `T` (f32 lengths beyond about
//! 1e-10 .. 4e9, f64 1e-77 .. 1e77, or `|B - A|` far below the links) or at
//! the edge of assembly, a cold path solves with products of first powers
//! only (`|B - A|` divided by its larger component, Heron's factors as lengths,
//! the foot clamped to `[-l1, l1]`). So the position is accurate (within
//! `2 eps l1 / kappa` of the double-double reference, measured 1.94) for
//! every normal length, f32 from 1.2e-38 and f64 from 2.2e-308, up to where
//! `cross(r1, r2)` (L^2, a field of the result) overflows, f32 about 1.8e19
//! and f64 1.3e154 (`NonFinite` beyond, except next to the edges where it
//! is small). The rates divide `r1` and `r2` by the determinant before the
//! dot products (no L^2/s product), and form a joint's velocity from `r1 /
//! det` where the rate itself is below the normal range (slow speeds on
//! long links); the determinant must be a normal number: f32 lengths above
//! about 1.1e-19, f64 1.5e-154 (below, `Singular`).
//! `tests/working_ranges.rs` checks these ends.

use crate::error::{Error, Fault, Primitive};
use crate::geometry::{
    abs, all_finite, check_det, cross, difference, dot, length, max, min, normal_range, perp, plus,
};
use crate::link::{relative_acceleration, relative_velocity};
use crate::mode::Mode;
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::Rrr;

/// Closed RRR group.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RrrPosition<T: Real> {
    /// The inner joint `C` (L).
    pub c: Point2<T>,
    /// `C - A`: link 1 as a vector, length `l1` (L). Its direction is link 1's axis.
    pub r1: Vector2<T>,
    /// `C - B`: link 2 as a vector, length `l2` (L). Its direction is link 2's axis.
    pub r2: Vector2<T>,
    /// `cross(r1, r2)` (L^2): the determinant of the rate system (twice the
    /// signed area of the triangle A, C, B; positive for [`Mode::Plus`]).
    /// [`position`] takes it from its square root, `height / 2`, which equals
    /// `cross(r1, r2)` exactly in real arithmetic and up to `O(eps l1 l2)` in
    /// floating point (both carry the same rounded height), so [`velocity`]'s
    /// reciprocal starts right after the square root instead of waiting for
    /// `C`, `r2` and the cross product. A position built by hand must set it
    /// to `cross(r1, r2)`: use [`RrrPosition::new`].
    pub det: T,
}

impl<T: Real> RrrPosition<T> {
    /// A position from its joint and link vectors (a hand-made or transformed
    /// one), with `det = cross(r1, r2)`.
    #[inline]
    pub fn new(c: Point2<T>, r1: Vector2<T>, r2: Vector2<T>) -> Self {
        RrrPosition {
            c,
            r1,
            r2,
            det: cross(&r1, &r2),
        }
    }
}

/// Angular velocities of the two links and the velocity of `C`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
    /// `1 / cross(r1, r2)` at the position these rates were computed at
    /// (1/L^2): [`acceleration`] has the same matrix and reuses it, so it
    /// neither recomputes nor re-checks the determinant.
    pub inv_det: T,
}

/// Angular accelerations of the two links and the acceleration of `C`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
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
/// by more than `4 eps (l1 + l2)` (inside that rounding band the joint is put
/// on the line, `h = 0`); `Singular` when `A` and `B` coincide (the direction of
/// the line is undefined).
#[inline(always)]
pub fn position<T: Real>(
    a: &Point2<T>,
    l1: T,
    b: &Point2<T>,
    l2: T,
    mode: Mode,
) -> Result<RrrPosition<T>, Error<T>> {
    let d = b - a;
    let dsq = dot(&d, &d);
    let sum = l1 + l2;
    let diff = l1 - l2;
    let (lo, hi) = normal_range::<T>();
    // Heron's factors; a negative one means the triangle does not close.
    let outer = sum * sum - dsq; // < 0: too far apart
    let inner = dsq - diff * diff; // < 0: one link too long
                                   // The band `4 eps (l1 + l2)` on `|d|`, to first order on `D`: `D` moves
                                   // by `2 |d| delta` when `|d|` moves by `delta`, and `|d|` is `l1 + l2` or
                                   // `|l1 - l2|` at the two edges.
    let band = T::lit(8.0) * T::eps() * sum;
    // sqrt(16 area^2) = 4 area, signed by the mode: the product is of the
    // fourth power of the lengths. Where it is a normal number, and `D` is
    // too, the third powers below are normal as well (`d * along` and
    // `perp(d) * height` make a vector of length `2 D l1`, and `prod <= (l1
    // + l2)^2 D`), so every product keeps full precision.
    let clamp = |x: T| if x < T::zero() { T::zero() } else { x };
    let prod = clamp(outer) * clamp(inner);
    // The ordinary case in one test (NaN fails it). Anything else goes to
    // the cold path, which checks the inputs in the order of the doc
    // comment, checks the band on `|d|` itself and reports the miss, or
    // solves in a form without powers above the first: a bad input, `A =
    // B`, `|B - A|^2` below the normal range, a distance outside the reach,
    // the edge of assembly (a factor 0 or in the band), lengths beyond
    // about f32 1e-10 .. 4e9 (f64 1e-77 .. 1e77), or `|B - A|` far below the
    // links, where `d * along` would be subnormal (at f64 |B - A| = 1e-150
    // and links of 1e-51, `C` came out on `A`).
    let ordinary = l1 > T::zero()
        && l2 > T::zero()
        && dsq >= lo
        && outer >= -(band * sum)
        && inner >= -(band * abs(diff))
        && prod >= lo
        && prod <= hi;
    if !ordinary {
        return position_cold(a, &d, l1, l2, mode);
    }
    let height = mode.sign::<T>() * prod.sqrt_kernel();
    let along = diff * sum + dsq;
    // The reciprocal runs beside the square root (one rounding more than two
    // divisions, off the critical path).
    let inv_2dsq = T::one() / (T::lit(2.0) * dsq);
    // Scaling the coefficients instead of the sum would round twice where a
    // 3-4-5 triangle is now exact.
    let r1 = (d * along + perp(&d) * height) * inv_2dsq;
    let c = a + r1;
    // One test for every non-finite input that got this far (an infinite
    // length or coordinate makes `c` NaN or infinite) and for overflow.
    if !all_finite([c.x, c.y]) {
        return Err(position_error(d, l1, l2, Check::JointFinite));
    }
    // cross(r1, r2) = cross(B - A, r1) = height cross(d, perp(d)) / (2 |d|^2)
    // = height / 2 (substitute r1 above; r2 = r1 - d). `r2` as `r1 - d`
    // rather than `C - B`: link-sized vectors only (no rounding at the
    // coordinates' magnitude), and it does not wait for `C`.
    Ok(RrrPosition {
        c,
        r1,
        r2: r1 - d,
        det: T::lit(0.5) * height,
    })
}

/// [`position`] where its ordinary path does not apply (cold path): a bad
/// input, `A = B`, a distance outside the reach, the rounding band at the
/// edge of assembly, or scales where a square or a fourth power of the
/// lengths leaves the normal range. Solves in a form whose products are of
/// first powers of the lengths only, so it is accurate for every normal
/// length (and any `|B - A|` down to the subnormal ones) as long as
/// `l1 + l2 + |B - A|` is finite:
///
/// `dist = |d|` (scaled), `e = d / dist`, the foot of `C` on `AB` at
/// `f = (l1 - l2) / dist (l1 + l2) / 2 + dist / 2` from `A` (clamped to
/// `[-l1, l1]`: inside the rounding band it could otherwise exceed the link,
/// where `dist` is far below `l1 - l2`), the height `h = sqrt(l1 + l2 -
/// dist) sqrt(l1 + l2 + dist) (sqrt(dist - |l1 - l2|) sqrt(dist + |l1 -
/// l2|) / dist) / 2` (Heron, each factor a length, clamped at zero in the
/// band), `r1 = f e + s h perp(e)`, and `cross(r1, r2) = s h dist`.
#[cold]
#[inline(never)]
fn position_cold<T: Real>(
    a: &Point2<T>,
    d: &Vector2<T>,
    l1: T,
    l2: T,
    mode: Mode,
) -> Result<RrrPosition<T>, Error<T>> {
    let good = |x: T| x.finite() && x > T::zero();
    let zero = T::zero();
    if !(good(l1) && good(l2) && all_finite([d.x, d.y])) || (d.x == zero && d.y == zero) {
        return Err(position_error(*d, l1, l2, Check::Degenerate));
    }
    let (e, dist) = unit_and_length(d);
    let (sum, diff) = (l1 + l2, l1 - l2);
    let adiff = abs(diff);
    let (outer, inner) = (sum - dist, dist - adiff);
    let band = T::lit(4.0) * T::eps() * sum;
    if outer < -band || inner < -band {
        return Err(position_error(*d, l1, l2, Check::Reach));
    }
    let clamp = |x: T| max(x, zero);
    let half = T::lit(0.5);
    let foot = (diff / dist) * (sum * half) + dist * half;
    let foot = min(max(foot, -l1), l1);
    let wide = clamp(outer).sqrt_kernel() * (sum + dist).sqrt_kernel();
    let narrow = clamp(inner).sqrt_kernel() * (dist + adiff).sqrt_kernel() / dist;
    let h = mode.sign::<T>() * (wide * narrow * half);
    let r1 = e * foot + perp(&e) * h;
    let c = a + r1;
    if !all_finite([c.x, c.y, h * dist]) {
        return Err(position_error(*d, l1, l2, Check::JointFinite));
    }
    Ok(RrrPosition {
        c,
        r1,
        r2: r1 - d,
        det: h * dist,
    })
}

/// `(d / |d|, |d|)` for a finite non-zero `d` of any size, through `d / m`
/// (`m` its larger component's magnitude; the square of a vector of size 1
/// to `sqrt 2` cannot underflow or overflow): within about 2 ulp (cold
/// paths only).
fn unit_and_length<T: Real>(d: &Vector2<T>) -> (Vector2<T>, T) {
    let m = max(abs(d.x), abs(d.y));
    let u = d / m;
    let ulen = length(&u);
    (u / ulen, ulen * m)
}

/// `sqrt(a) sqrt(b)` for a product `a b` outside the normal range (cold
/// path of [`velocity`]); both factors are `>= 0`.
#[cold]
#[inline(never)]
fn split_root<T: Real>(a: T, b: T) -> T {
    a.sqrt_kernel() * b.sqrt_kernel()
}

/// Which check of [`position`] failed (the cold path's only knowledge of
/// the call site).
#[derive(Clone, Copy)]
enum Check {
    /// Positive lengths and `A != B`.
    Degenerate,
    /// The triangle closes (within the rounding band).
    Reach,
    /// `C` is finite.
    JointFinite,
}

/// The error of a failed [`position`] call, one cold function for every
/// check (cold path). An input error first, in the order of the doc comment:
/// `l1`, then `l2` not positive or not finite, then `B - A` not finite (an
/// infinite one fails any of the checks). Otherwise the check's own fault:
/// `Singular` (`A = B`) with the scale `l1 + l2`; `CannotAssemble` with the
/// miss (L) and the violated reach; `NonFinite` for `C` (an overflow).
#[cold]
#[inline(never)]
fn position_error<T: Real>(d: Vector2<T>, l1: T, l2: T, failed: Check) -> Error<T> {
    let good = |x: T| x.finite() && x > T::zero();
    let sum = l1 + l2;
    let diff = abs(l1 - l2);
    // The fault as (kind, name, first value, second value), built once at
    // the end (one construction of each fault kind in the code).
    let (kind, what, a, b) = if !(good(l1) && good(l2)) {
        // The first bad length.
        let (what, x) = if good(l1) {
            ("RRR length l2", l2)
        } else {
            ("RRR length l1", l1)
        };
        (Kind::Input, what, x, x)
    } else if !all_finite([d.x, d.y]) {
        (Kind::NonFinite, "RRR joint distance", sum, sum)
    } else {
        match failed {
            Check::Degenerate => (Kind::Singular, "", T::zero(), T::zero()),
            Check::Reach => {
                let dist = if d.x == T::zero() && d.y == T::zero() {
                    T::zero()
                } else {
                    unit_and_length(&d).1
                };
                let (outer, inner) = (sum - dist, dist - diff);
                if outer <= inner {
                    (Kind::Reach, "", -outer, sum)
                } else {
                    (Kind::Reach, "", -inner, diff)
                }
            }
            // An overflow: `l1 + l2 + |B - A|` or a coordinate of `C`
            // beyond the largest finite number of `T`.
            Check::JointFinite => (Kind::NonFinite, "RRR joint C (overflow)", sum, sum),
        }
    };
    let fault = match kind {
        Kind::Input if a.finite() => Fault::NonPositive { what, value: a },
        Kind::Input | Kind::NonFinite => Fault::NonFinite { what },
        Kind::Singular => Fault::Singular { det: a, scale: b },
        Kind::Reach => Fault::CannotAssemble { miss: a, reach: b },
    };
    Error::new(P, fault)
}

/// The fault kinds of [`position_error`]: `Input` is `NonPositive` for a
/// finite value, else `NonFinite`.
#[derive(Clone, Copy)]
enum Kind {
    Input,
    NonFinite,
    Singular,
    Reach,
}

/// Rates of the group from the velocities of `A` and `B` (L/s); `None` means
/// the point is fixed (its terms vanish at compile time).
///
/// The scale of the determinant (and of the condition indicator) is
/// `|r1| |r2|`, one square root (two where `|r1|^2 |r2|^2` leaves the normal
/// range); [`velocity_lengths`] takes it from the link lengths instead.
///
/// Errors: `Singular` when `|cross(r1, r2)| <= 16 eps l1 l2` (toggle: the two
/// links are aligned); `NonFinite` for a non-finite input.
#[inline(always)]
pub fn velocity<T: Real>(
    pos: &RrrPosition<T>,
    va: Option<&Vector2<T>>,
    vb: Option<&Vector2<T>>,
) -> Result<RrrVelocity<T>, Error<T>> {
    // `|r1|^2 |r2|^2` is a fourth power of the lengths: outside the normal
    // range (f32 lengths below about 1e-10 or above about 4e9) it would be
    // subnormal (the indicator off), zero or infinite (a false `Singular`)
    // while the position is fine; there the two roots are taken apart (cold
    // path, as in `position`).
    let (q1, q2) = (dot(&pos.r1, &pos.r1), dot(&pos.r2, &pos.r2));
    let prod = q1 * q2;
    let (lo, hi) = normal_range::<T>();
    let scale = if prod >= lo && prod <= hi {
        prod.sqrt_kernel()
    } else {
        split_root(q1, q2)
    };
    rates(pos, scale, va, vb)
}

/// [`velocity`] with the determinant's scale `l1 l2` given as the two link
/// lengths of the [`position`] call (the generated code knows them), so no
/// square root is taken: `|r1| = l1` and `|r2| = l2` up to the rounding of
/// the position (a few eps of the coordinates), which is far below what the
/// indicator is for (telling `1` from `1e-3` from `16 eps`).
///
/// Condition indicator: `|cross(r1, r2)| / (l1 l2)`, clamped to 1.
/// Errors as for [`velocity`]; `Singular` also for a non-positive or
/// non-finite `l1 l2`.
#[inline(always)]
pub fn velocity_lengths<T: Real>(
    pos: &RrrPosition<T>,
    l1: T,
    l2: T,
    va: Option<&Vector2<T>>,
    vb: Option<&Vector2<T>>,
) -> Result<RrrVelocity<T>, Error<T>> {
    rates(pos, l1 * l2, va, vb)
}

/// The rates with the determinant's scale given.
#[inline(always)]
fn rates<T: Real>(
    pos: &RrrPosition<T>,
    scale: T,
    va: Option<&Vector2<T>>,
    vb: Option<&Vector2<T>>,
) -> Result<RrrVelocity<T>, Error<T>> {
    let det = check_det(pos.det, scale, P)?;
    let condition = min(abs(det) / scale, T::one());
    let inv_det = T::one() / det;
    let dv = difference(vb, va);
    // `r / det` (1/L) before the dot products: `dot(dv, r2)` (L^2/s) is
    // subnormal for f32 lengths and speeds of about 1e-19 (a four-bar at
    // that scale turning at 1e-4 rad/s lost its rocker's rate), while the
    // rates (1/s) are ordinary numbers there.
    let omega1 = dot(&dv, &(pos.r2 * inv_det));
    let omega2 = dot(&dv, &(pos.r1 * inv_det));
    let mut vc = plus(va, relative_velocity(&pos.r1, omega1));
    if abs(omega1) < normal_range::<T>().0 {
        // `omega1` below the normal range (or zero) while `omega1 r1` may
        // not be: speeds far below long links (f32: 1e-33 L/s on 1e13 L).
        vc = plus(va, rate_times_link(&pos.r1, inv_det, dot(&dv, &pos.r2)));
    }
    // One check for the results: a non-finite `va`, `vb` (so `dv`) makes
    // `omega1` non-finite (`r2 != 0`), and `omega2` (`r1 != 0`); `omega1`
    // is checked itself, as `vc` may come from the cold path without it.
    if all_finite([omega1, omega2, vc.x, vc.y]) {
        Ok(RrrVelocity {
            omega1,
            omega2,
            vc,
            condition,
            inv_det,
        })
    } else {
        Err(Error::new(
            P,
            Fault::NonFinite {
                what: if dv.x.finite() && dv.y.finite() {
                    "RRR rates"
                } else {
                    "RRR joint velocity"
                },
            },
        ))
    }
}

/// `perp(r1) n / det` with `r1 / det` (1/L) formed first and `n` (L^2/s or
/// L^2/s^2) the rate's numerator: for a rate `n / det` below the normal
/// range (cold path of [`velocity`] and [`acceleration`]), where the rate
/// itself has lost its bits but the velocity it gives has not.
#[cold]
#[inline(never)]
fn rate_times_link<T: Real>(r1: &Vector2<T>, inv_det: T, n: T) -> Vector2<T> {
    perp(&(r1 * inv_det)) * n
}

/// Accelerations of the group from the accelerations of `A` and `B` (L/s^2;
/// `None`: fixed) and the rates.
///
/// Differentiating once more: `alpha1 perp(r1) - alpha2 perp(r2) =
/// aB - aA + omega1^2 r1 - omega2^2 r2`, the same matrix as for the rates,
/// whose inverse determinant `vel.inv_det` is reused: `vel` must be the
/// result of [`velocity`] or [`velocity_lengths`] at this `pos` (which
/// checked the matrix; it is not re-checked here).
/// Errors: `NonFinite` for a non-finite input or an overflow.
#[inline(always)]
pub fn acceleration<T: Real>(
    pos: &RrrPosition<T>,
    vel: &RrrVelocity<T>,
    aa: Option<&Vector2<T>>,
    ab: Option<&Vector2<T>>,
) -> Result<RrrAcceleration<T>, Error<T>> {
    let da = difference(ab, aa);
    // `omega^2 r` as `(r omega) omega` (a velocity times a rate): `omega^2`
    // alone underflows first. `r / det` first, as in `rates`.
    let w = da + (pos.r1 * vel.omega1) * vel.omega1 - (pos.r2 * vel.omega2) * vel.omega2;
    let alpha1 = dot(&w, &(pos.r2 * vel.inv_det));
    let alpha2 = dot(&w, &(pos.r1 * vel.inv_det));
    let mut ac = plus(aa, relative_acceleration(&pos.r1, vel.omega1, alpha1));
    if abs(alpha1) < normal_range::<T>().0 {
        // As in `rates`: `alpha1 perp(r1)` without `alpha1`.
        let turn = rate_times_link(&pos.r1, vel.inv_det, dot(&w, &pos.r2));
        ac = plus(aa, turn - (pos.r1 * vel.omega1) * vel.omega1);
    }
    // One check, as in `rates`: `w` (so `aa`, `ab` and the rates)
    // propagates into `alpha1` and `alpha2`; `ac` may come from the cold
    // path without `alpha1`.
    if all_finite([alpha1, alpha2, ac.x, ac.y]) {
        Ok(RrrAcceleration { alpha1, alpha2, ac })
    } else {
        Err(Error::new(
            P,
            Fault::NonFinite {
                what: if da.x.finite() && da.y.finite() {
                    "RRR angular accelerations"
                } else {
                    "RRR joint acceleration"
                },
            },
        ))
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    /// `det` (from the square root) against `cross(r1, r2)` of the returned
    /// vectors, from well-conditioned poses to `|sin|` of the links' angle
    /// `1e-7`, near the origin and `1e3` lengths away from it, both modes.
    /// Both come from the same rounded `B - A` and height; they differ by the
    /// rounding of `r1`, of `r2 = r1 - (B - A)` (components below `l1 + l2`
    /// in size) and of the cross product: at most about `2 eps (l1 + l2)^2`,
    /// whatever the distance from the origin (measured 0.52 of
    /// `eps (l1 + l2)^2`). A sign error, a factor (`height` instead of
    /// `height / 2`), a relative change of 1e-9 or `r2` taken as `C - B`
    /// (rounded at the coordinates' magnitude, 1e3 away) fails it.
    #[test]
    fn det_is_the_cross_product_of_the_link_vectors() {
        let mut compared = 0;
        for &offset in &[0.0, 1.0e3] {
            for k in 0..8 {
                // Angle between the links: 1.5 rad, then 0.1 down to 1e-7 rad (toggle).
                let gamma = if k == 0 { 1.5 } else { 10f64.powi(-k) };
                for &(l1, l2) in &[(3.0, 4.0), (1.0, 7.5), (250.0, 0.5)] {
                    for turn in 0..6 {
                        let phi = 0.3 + turn as f64;
                        let a = Point2::new(offset + 0.25, -offset / 3.0);
                        let r1 = Vector2::new(l1 * phi.cos(), l1 * phi.sin());
                        let r2 = Vector2::new(l2 * (phi + gamma).cos(), l2 * (phi + gamma).sin());
                        let b = a + r1 - r2;
                        for mode in [Mode::Plus, Mode::Minus] {
                            let Ok(p) = position(&a, l1, &b, l2, mode) else {
                                continue;
                            };
                            let bound = 2.0 * f64::EPSILON * (l1 + l2) * (l1 + l2);
                            let cr = cross(&p.r1, &p.r2);
                            assert!(
                                (p.det - cr).abs() <= bound,
                                "det {} cross {cr} bound {bound}",
                                p.det
                            );
                            assert!(
                                p.det * mode.sign::<f64>() >= 0.0,
                                "det {} for {mode:?}",
                                p.det
                            );
                            compared += 1;
                        }
                    }
                }
            }
        }
        assert!(compared > 500, "only {compared} poses compared");
    }

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

    /// One RRR at scale `s` (lengths and coordinates times `s`, rounded to
    /// `T`): `A = (0.3, -0.2) s`, `l1 = 1.3 s`, `l2 = 0.9 s`, `B` at
    /// `dist s` from `A` at 0.4 rad; `dist` from the middle of the range to
    /// 1e-6 (relative) inside either edge (0.4 and 2.2).
    fn scaled_case<T: Real>(s: f64, dist: f64) -> (Point2<T>, T, Point2<T>, T) {
        let (sin, cos) = 0.4f64.sin_cos();
        let p = |x: f64, y: f64| Point2::new(T::lit(x), T::lit(y));
        (
            p(0.3 * s, -0.2 * s),
            T::lit(1.3 * s),
            p(0.3 * s + dist * s * cos, -0.2 * s + dist * s * sin),
            T::lit(0.9 * s),
        )
    }

    /// The distances `|B - A| / s` of [`scaled_case`].
    const DISTANCES: [f64; 6] = [1.5, 1.0, 2.19, 0.41, 2.2 * (1.0 - 1e-6), 0.4 * (1.0 + 1e-6)];

    /// Worst `|C - C_ref| / (eps l1 / kappa)` over [`DISTANCES`] and both
    /// modes at scale `s`, against the double-double reference at the
    /// rounded inputs (`kappa = |cross(r1, r2)| / (l1 l2)` of the
    /// reference), or `None` where every case is a typed error (a mix
    /// fails: inside the range nothing may fail).
    fn worst_position_at<T: Real>(s: f64) -> Option<f64> {
        use mechanism_reference::groups as reference;
        let eps = T::eps().as_f64();
        let (mut worst, mut out_of_range) = (0.0f64, 0);
        for dist in DISTANCES {
            for mode in [Mode::Plus, Mode::Minus] {
                let (a, l1, b, l2) = scaled_case::<T>(s, dist);
                let what = std::format!("scale {s:e}, distance {dist}, {mode:?}");
                let got = match position(&a, l1, &b, l2, mode) {
                    Ok(p) => p,
                    Err(_) => {
                        out_of_range += 1;
                        continue;
                    }
                };
                let va = reference::v(a.x.as_f64(), a.y.as_f64());
                let vb = reference::v(b.x.as_f64(), b.y.as_f64());
                let want =
                    reference::rrr_position(va, l1.as_f64(), vb, l2.as_f64(), mode == Mode::Plus)
                        .unwrap_or_else(|| panic!("{what}: the reference does not assemble"));
                let (r1, r2) = (reference::sub(want, va), reference::sub(want, vb));
                let kappa = (reference::cross(r1, r2).abs().to_f64()) / (l1.as_f64() * l2.as_f64());
                let err = reference::norm(reference::sub(
                    reference::v(got.c.x.as_f64(), got.c.y.as_f64()),
                    want,
                ))
                .to_f64();
                worst = worst.max(err / (eps * l1.as_f64() / kappa));
            }
        }
        match out_of_range {
            0 => Some(worst),
            n if n == 2 * DISTANCES.len() => None,
            n => panic!("scale {s:e}: {n} cases out of range, the others not"),
        }
    }

    /// Bound of [`worst_position_at`]: the position's first-order error is a
    /// few roundings of the coordinates (`eps L`) amplified by `1 / kappa`
    /// (measured worst 1.9, printed by the tests); 4 leaves room for other
    /// platforms while a third power gone subnormal (at f32 1e-14 the joint
    /// was 3 % off: 1e5 of this unit) fails it.
    const SCALE_BOUND: f64 = 4.0;

    /// Every decade `10^k` for `k` in `decades`: within [`SCALE_BOUND`] of
    /// the reference inside `[lo, hi]`, a typed error outside it (so never a
    /// silent answer: the `NonFinite` that names the range, or where `|B -
    /// A|^2` itself underflows or overflows, f32 below about 1e-19 or above
    /// 1e19, `Singular` or `CannotAssemble`); returns the worst figure.
    fn sweep<T: Real>(decades: impl Iterator<Item = i32>, lo: i32, hi: i32) -> f64 {
        let mut worst = 0.0f64;
        for k in decades {
            match worst_position_at::<T>(10f64.powi(k)) {
                Some(w) => {
                    assert!(
                        (lo..=hi).contains(&k),
                        "scale 1e{k}: solved ({w:.2}), outside the range"
                    );
                    assert!(
                        w <= SCALE_BOUND,
                        "scale 1e{k}: {w:.2} (bound {SCALE_BOUND})"
                    );
                    worst = worst.max(w);
                }
                None => assert!(
                    !(lo..=hi).contains(&k),
                    "scale 1e{k}: out of range inside it"
                ),
            }
        }
        worst
    }

    /// f32 lengths 1e-36 .. 1e19 at every decade (`l1 = 1.3 s`, `|B - A|`
    /// down to `0.4 s`): accurate throughout, through the cold path where a
    /// square or fourth power of the lengths leaves the normal range (below
    /// about 1e-10 and above about 4e9). Before the check of `in_range`,
    /// lengths below about 4.6e-11 lost bits in `d * along` with no error
    /// (at 1e-18 `C` came out on `A`, at 1e-14 3 % off); with it they were a
    /// typed error outside 1e-12 .. 1e12.
    #[test]
    fn f32_rrr_matches_reference_or_is_out_of_range() {
        // Above 1e19 `cross(r1, r2)` (L^2, in the result) overflows: a
        // typed `NonFinite` except next to the edges, where it is small.
        let w = sweep::<f32>(-36..=19, -36, 19);
        std::println!("f32 RRR 1e-36 .. 1e19: worst position {w:.2} (eps l1 / kappa)");
    }

    /// f64 lengths 1e-150 .. 1e150 every 5 decades (below, the
    /// double-double reference's squares underflow; above 1e154,
    /// `cross(r1, r2)`, L^2, overflows as in f32; `tests/working_ranges.rs`
    /// covers the rest by powers of two): accurate throughout
    /// (before, 1e-150 was off by 4e15 of this unit, with no error; then a
    /// typed error outside 1e-100 .. 1e100).
    #[test]
    fn f64_rrr_matches_reference_or_is_out_of_range() {
        let w = sweep::<f64>((-30..=30).map(|k| 5 * k), -150, 150);
        std::println!("f64 RRR 1e-150 .. 1e150: worst position {w:.2} (eps l1 / kappa)");
    }
}
