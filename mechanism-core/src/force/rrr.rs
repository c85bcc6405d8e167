//! Kinetostatics of the RRR group: link 1 pinned to the outside at `A`, link 2
//! pinned to the outside at `B`, the links pinned together at `C` (the joint
//! names of `crate::dyad::rrr`).
//!
//! ```text
//!              C            loads on both links: wrenches about C
//!         1   / \   2
//!            /   \
//!           A     B         reactions: outside -> 1 at A, outside -> 2 at B,
//!                           1 -> 2 at C
//! ```
//!
//! # The closed form
//!
//! Unknowns (each the force of the giver on the receiver, through the joint
//! centre): `F_A`, `F_B`, `F_C`. Known loads: `(F1, M1)` on link 1, `(F2, M2)`
//! on link 2, moments about `C` (counter-clockwise positive). With
//! `a = A - C`, `b = B - C`, d'Alembert's equilibrium of each link reads
//!
//! ```text
//! link 1:  F_A - F_C + F1 = 0        cross(a, F_A) + M1 = 0
//! link 2:  F_B + F_C + F2 = 0        cross(b, F_B) + M2 = 0
//! ```
//!
//! (the six equations of [`crate::force::group`] with moments about `C`,
//! where `F_C` has no moment). The force balances give `F_A = F_C - F1` and
//! `F_B = -F_C - F2`; in the moment equations they leave two equations in
//! `F_C` alone, the moments of each link about the middle joint:
//!
//! ```text
//! cross(a, F_C) = cross(a, F1) - M1 =: p        (N m)
//! cross(b, F_C) = M2 - cross(b, F2) =: q
//! ```
//!
//! a 2x2 system with rows `(-a.y, a.x)` and `(-b.y, b.x)` in the components
//! of `F_C` and determinant `cross(a, b)` (zero at toggle: `C` on the line
//! `AB`), solved by elimination with scaled partial pivoting (backward
//! stable near toggle, and exact in its zeros: with link 2 along an axis, the
//! component of `F_C` across it is `q` over one length; see `force::closed`);
//! then `F_A` and `F_B` from the force balances.
//!
//! `min_pivot_ratio` is `|cross(a, b)| / (|a| |b|)`, `|sin|` of the angle
//! between the links at `C` (for a four-bar, of its transmission angle), the
//! same number as the RRR rate system's `condition`: the 2x2 system in `F_C`
//! with its rows scaled to unit length has 2-norm condition between
//! `1 / min_pivot_ratio` and `2 / min_pivot_ratio`.

use crate::error::{Error, Primitive};
use crate::force::body::Wrench;
use crate::force::closed;
use crate::geometry::{cross, length};
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::Rrr;

/// Reactions of an RRR group (forces in `M L / s^2`, N in SI; global frame).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RrrReactions<T: Real> {
    /// Force of the outside body (the body carrying `A`) on link 1, at `A`.
    pub a: Vector2<T>,
    /// Force of the outside body (the body carrying `B`) on link 2, at `B`.
    pub b: Vector2<T>,
    /// Force of link 1 on link 2 at `C` (link 1 receives `-c`).
    pub c: Vector2<T>,
    /// Conditioning indicator in `(6 eps, 1]`: `|sin|` of the angle between
    /// the links at `C`, `|cross(A - C, B - C)| / (|A - C| |B - C|)` (see the
    /// module documentation); 1 with the links perpendicular, tending to 0 at
    /// toggle, where the reactions' relative error grows as
    /// `eps / min_pivot_ratio`.
    pub min_pivot_ratio: T,
}

/// Reactions of an RRR group with joints `A`, `B` (outer) and `C` (inner),
/// given the known loads `load1` on link 1 and `load2` on link 2 as wrenches
/// about `C` (inertia, weight, external loads, and the reactions of later
/// groups attached to these links, negated). The closed form of the module
/// documentation.
///
/// Errors ([`Primitive::Rrr`]): `NonFinite` for non-finite input or result;
/// `Singular { det: cross(A - C, B - C), scale: |A - C| |B - C| }` when
/// `|det| <= 6 eps scale` (toggle, or `C` on `A` or `B`), the level at which
/// [`crate::force::group::solve`] refuses the same equations, or when `det`
/// or `scale` is below the normal range (lengths below about 1e-19 in
/// `f32`, 1e-154 in `f64`).
#[inline(always)]
pub fn reactions<T: Real>(
    a: &Point2<T>,
    b: &Point2<T>,
    c: &Point2<T>,
    load1: &Wrench<T>,
    load2: &Wrench<T>,
) -> Result<RrrReactions<T>, Error<T>> {
    closed::check_loads(load1, load2, P)?;
    closed::check_points([a, b, c], P)?;
    let ra = a - c;
    let rb = b - c;
    let det = cross(&ra, &rb);
    let min_pivot_ratio = closed::relative_det(det, length(&ra) * length(&rb), P)?;
    let p = cross(&ra, &load1.force) - load1.moment;
    let q = load2.moment - cross(&rb, &load2.force);
    let (x, y) = closed::solve2([-ra.y, ra.x, p], [-rb.y, rb.x, q]);
    let fc = Vector2::new(x, y);
    let fa = fc - load1.force;
    let fb = -fc - load2.force;
    closed::check_result([fa.x, fa.y, fb.x, fb.y, fc.x, fc.y], P)?;
    Ok(RrrReactions {
        a: fa,
        b: fb,
        c: fc,
        min_pivot_ratio,
    })
}
