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
//! Unknowns: the three joint forces (6). Moments are taken about `C`, so each
//! link's moment equation holds only its outer force:
//! `cross(A - C, F_A) = -M1` fixes `F_A`'s component across link 1, likewise
//! for `F_B`; the force balance of the whole group then fixes the components
//! along the links. That last step is singular when the links are aligned
//! (toggle, `C` on the line `AB`), where the indicator tends to 0.

use crate::error::{Error, Primitive};
use crate::force::body::Wrench;
use crate::force::group::{self, Pair};
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
    /// Conditioning indicator: [`crate::linsolve::Solution::min_pivot_ratio`] of
    /// the reduced 4x4 system of [`crate::force::group::solve_inner_revolute`].
    pub min_pivot_ratio: T,
}

/// Reactions of an RRR group with joints `A`, `B` (outer) and `C` (inner),
/// given the known loads `load1` on link 1 and `load2` on link 2 as wrenches
/// about `C` (inertia, weight, external loads, and the reactions of later
/// groups attached to these links, negated).
///
/// Errors ([`Primitive::Rrr`]): `NonFinite` for non-finite input or result;
/// `Singular` at toggle (links aligned) or when `C` coincides with `A` or `B`.
#[inline]
pub fn reactions<T: Real>(
    a: &Point2<T>,
    b: &Point2<T>,
    c: &Point2<T>,
    load1: &Wrench<T>,
    load2: &Wrench<T>,
) -> Result<RrrReactions<T>, Error<T>> {
    let s = group::solve_inner_revolute(
        &Pair::Revolute { point: *a },
        &Pair::Revolute { point: *b },
        c,
        load1,
        load2,
        P,
    )?;
    let [[ax, ay], [bx, by], [cx, cy]] = s.unknowns;
    Ok(RrrReactions {
        a: Vector2::new(ax, ay),
        b: Vector2::new(bx, by),
        c: Vector2::new(cx, cy),
        min_pivot_ratio: s.min_pivot_ratio,
    })
}
