//! What the closed-form kinetostatics of the five class II groups share: the
//! checks of their inputs, the test of their reduced determinant with its
//! conditioning indicator, and the check of their results.
//!
//! Each group's six equilibrium equations (see [`super::group`] for the
//! general system) decouple once the moments are taken about one of its
//! joints: a link whose other joints all sit at that point has a moment
//! equation in one couple alone, the force balances express the remaining
//! joint forces through one of them, and what is left is a system of at most
//! two unknowns whose determinant `det` is a cross or dot product of the
//! group's lines (two links, a link and a guide, two guides). Each group's
//! file derives its formulas.
//!
//! That small system is solved in the global frame by Gaussian elimination
//! with scaled partial pivoting ([`solve2`]), written out for two unknowns:
//! like the row-equilibrated, pivoted elimination of [`crate::linsolve`] it
//! is backward stable (each computed reaction satisfies its link's
//! equations to a few rounding errors of their terms at any pose, including
//! near a singular one, where Cramer's rule, the adjugate over the
//! determinant, only guarantees `eps / indicator` of them), and it keeps the
//! zeros of the global frame: a link or guide along an axis decouples a
//! component, which then comes out of one division, as accurate as its own
//! size allows even beside reactions ten million times larger (the stiff
//! RRR of `kinetostatics.rs`). `mechanism-core/tests/primitives/closed_forms.rs`
//! checks every group against [`super::group::solve`], the general
//! elimination, over random and near-singular poses.

use crate::error::{Error, Fault, Primitive};
use crate::force::body::Wrench;
use crate::geometry::{abs, all_finite, max, normal_range};
use crate::linsolve::PIVOT_TOLERANCE;
use crate::scalar::Real;
use nalgebra::Point2;

/// The size of the system whose relative pivot [`super::group::solve`]
/// compares with `PIVOT_TOLERANCE * SIZE * eps`: the six equations of a
/// class II group. [`relative_det`] refuses at the same level.
const SIZE: f64 = 6.0;

/// `Err(NonFinite { what: "group load" })` (tagged with `primitive`) unless
/// both loads are finite.
#[inline(always)]
pub(crate) fn check_loads<T: Real>(
    load1: &Wrench<T>,
    load2: &Wrench<T>,
    primitive: Primitive,
) -> Result<(), Error<T>> {
    if all_finite([
        load1.force.x,
        load1.force.y,
        load1.moment,
        load2.force.x,
        load2.force.y,
        load2.moment,
    ]) {
        Ok(())
    } else {
        Err(Error::new(
            primitive,
            Fault::NonFinite { what: "group load" },
        ))
    }
}

/// `Err(NonFinite { what: "group geometry" })` (tagged with `primitive`)
/// unless every coordinate of `points` is finite (directions are checked by
/// [`super::group::unit_direction`]).
#[inline(always)]
pub(crate) fn check_points<T: Real, const N: usize>(
    points: [&Point2<T>; N],
    primitive: Primitive,
) -> Result<(), Error<T>> {
    if points.iter().all(|p| all_finite([p.x, p.y])) {
        Ok(())
    } else {
        Err(Error::new(
            primitive,
            Fault::NonFinite {
                what: "group geometry",
            },
        ))
    }
}

/// The reduced determinant `det` against its `scale` (the product of the
/// lengths of the two vectors it is made of, so `|det| <= scale` by
/// Hadamard's inequality): `Ok(min(|det| / scale, 1))`, the group's
/// `min_pivot_ratio`, when `|det| > PIVOT_TOLERANCE * 6 * eps * scale` and
/// both are normal numbers; otherwise `Err(Singular { det, scale })` tagged
/// with `primitive`.
///
/// The threshold is the one at which [`super::group::solve`] refuses a
/// relative pivot of the same six equations. The indicator is `|sin|` (or
/// `|cos|`) of the angle between the two lines that make the determinant, so
/// it lies in `(6 eps, 1]` when the check passes; for the 2x2 systems with
/// unit rows (or columns) `u`, `v` at that angle the 2-norm condition number
/// is `(1 + |cos|) / |sin|`, so `1 / indicator <= cond <= 2 / indicator`;
/// for the groups reduced to one unknown it is the relative size of that
/// unknown's coefficient. A `det` or `scale` below the normal range (lengths
/// below about 1e-19 in `f32`, 1e-154 in `f64`, whose squares underflow)
/// counts as singular: its bits are lost and its reciprocal may overflow.
#[inline(always)]
pub(crate) fn relative_det<T: Real>(det: T, scale: T, primitive: Primitive) -> Result<T, Error<T>> {
    let tolerance = T::lit(PIVOT_TOLERANCE * SIZE) * T::eps();
    let smallest = normal_range::<T>().0;
    let size = abs(det);
    // `>` and `>=` are false for NaN: a NaN `det` or `scale` is singular.
    if size > tolerance * scale && size >= smallest && scale >= smallest {
        let ratio = size / scale;
        // Rounding can put the ratio a few ulp above Hadamard's bound 1.
        Ok(if ratio > T::one() { T::one() } else { ratio })
    } else {
        Err(Error::new(primitive, Fault::Singular { det, scale }))
    }
}

/// `Err(NonFinite { what: "group reaction" })` (tagged with `primitive`)
/// unless every value of `xs` is finite (a result that overflowed).
#[inline(always)]
pub(crate) fn check_result<T: Real, const N: usize>(
    xs: [T; N],
    primitive: Primitive,
) -> Result<(), Error<T>> {
    if all_finite(xs) {
        Ok(())
    } else {
        Err(Error::new(
            primitive,
            Fault::NonFinite {
                what: "group reaction",
            },
        ))
    }
}

/// Solves the 2x2 system `u1 x + v1 y = p`, `u2 x + v2 y = q` (each `row` is
/// `[u, v, rhs]`) by Gaussian elimination with scaled partial pivoting: the
/// pivot row is the one whose `|u|` is the larger fraction of its row's
/// largest coefficient (compared by cross-multiplying, without dividing),
/// the other row loses its `u` by one multiplier, `y` comes from what is
/// left and `x` by back substitution. Two divisions: the pivot's reciprocal
/// (for the multiplier and the back substitution) and the reduced
/// coefficient.
///
/// The caller has checked the determinant (`u1 v2 - u2 v1`) against its
/// scale with [`relative_det`], so the pivot and the reduced coefficient are
/// nonzero; the results are finite unless they overflow (the caller checks).
#[inline(always)]
pub(crate) fn solve2<T: Real>(row1: [T; 3], row2: [T; 3]) -> (T, T) {
    let [u1, v1, _] = row1;
    let [u2, v2, _] = row2;
    // |u2| / max2 > |u1| / max1, without the divisions.
    let swap = abs(u2) * max(abs(u1), abs(v1)) > abs(u1) * max(abs(u2), abs(v2));
    let ([u, v, p], [w, z, q]) = if swap { (row2, row1) } else { (row1, row2) };
    let inv = T::one() / u;
    let l = w * inv;
    let y = (q - l * p) / (z - l * v);
    let x = (p - v * y) * inv;
    (x, y)
}
