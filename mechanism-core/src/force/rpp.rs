//! Kinetostatics of the RPP group: a block (link 1) pinned to the outside at
//! `A` slides in a slot of link 2 (slot direction `slot_dir`), and link 2
//! slides on an outside guide (direction `guide_dir`), as in the sine and
//! tangent mechanisms (the joint names of `crate::dyad::rpp`).
//!
//! ```text
//!              | slot_dir
//!            [=A=]  block 1          loads on both links: wrenches about A
//!              |   link 2            reactions: outside -> block at A,
//!     =========+==========> guide_dir          block -> link 2 (slot),
//!                                              guide (outside) -> link 2,
//!                                              both about A
//! ```
//!
//! # The closed form
//!
//! Unknowns: `F_A` (outside on the block, through `A`); the slot's reaction
//! of the block on link 2, normal force `Ns ns` through `A` (`ds` =
//! `slot_dir` normalized, `ns = perp(ds)`) and couple `Ms` about `A` (the
//! block receives the opposite); the guide's reaction on link 2, `Ng ng`
//! through `A` (`dg`, `ng = perp(dg)` likewise) and couple `Mg` about `A`.
//! Known loads `(F1, M1)` on the block and `(F2, M2)` on link 2, moments
//! about `A`:
//!
//! ```text
//! block:   F_A - Ns ns + F1 = 0              -Ms + M1 = 0
//! link 2:  Ns ns + Ng ng + F2 = 0            Ms + Mg + M2 = 0
//! ```
//!
//! The block's moment gives the slot couple `Ms = M1`, then link 2's the
//! guide couple `Mg = -(M1 + M2)`. Link 2's force balance,
//!
//! ```text
//! Ns ns + Ng ng = -F2
//! ```
//!
//! is a 2x2 system (its `x` and `y` rows) with unit columns and determinant
//! `cross(ns, ng) = cross(ds, dg)`, solved by elimination with scaled partial
//! pivoting (see `force::closed`; with the slot and the guide along the axes,
//! as in the sine mechanism, each normal force is one component of `F2`);
//! the block's force balance then gives `F_A = Ns ns - F1`. Singular when the
//! slot is parallel to the guide. `min_pivot_ratio` is `|cross(ds, dg)|`,
//! `|sin|` of the angle between slot and guide: the 2x2 system's 2-norm
//! condition lies between `1 / min_pivot_ratio` and `2 / min_pivot_ratio`.

use crate::error::{Error, Primitive};
use crate::force::body::Wrench;
use crate::force::closed;
use crate::force::group::unit_direction;
use crate::force::PrismaticReaction;
use crate::geometry::{cross, perp};
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::Rpp;

/// Reactions of an RPP group (forces `M L / s^2`, moments `M L^2 / s^2`).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RppReactions<T: Real> {
    /// Force of the outside body on the block (link 1), at `A`.
    pub a: Vector2<T>,
    /// Reaction of the block (link 1) on link 2 in the slot: normal force along
    /// `perp(slot_dir)` through `A`, couple about `A`. The block receives the
    /// opposite.
    pub slot: PrismaticReaction<T>,
    /// Reaction of the guide (outside body) on link 2: normal force along
    /// `perp(guide_dir)` through `A`, couple about `A` (use
    /// [`PrismaticReaction::wrench_about`] for another point).
    pub guide: PrismaticReaction<T>,
    /// Conditioning indicator in `(6 eps, 1]`: `|sin|` of the angle between
    /// the slot and the guide (see the module documentation); 1 when they are
    /// perpendicular (the sine mechanism), tending to 0 as they turn parallel.
    pub min_pivot_ratio: T,
}

/// Reactions of an RPP group from the pin `A`, the slot and guide directions
/// (any length; normalized here) and the known loads on the block and on link
/// 2 as wrenches about `A`. The closed form of the module documentation.
///
/// Errors ([`Primitive::Rpp`]): `NonFinite`; `NonPositive` for a zero
/// direction; `Singular { det: cross(ds, dg), scale: 1 }` when the slot is
/// parallel to the guide to within `|det| <= 6 eps`.
#[inline(always)]
pub fn reactions<T: Real>(
    a: &Point2<T>,
    slot_dir: &Vector2<T>,
    guide_dir: &Vector2<T>,
    load1: &Wrench<T>,
    load2: &Wrench<T>,
) -> Result<RppReactions<T>, Error<T>> {
    let slot_dir = unit_direction(slot_dir, P, "RPP slot direction")?;
    let guide_dir = unit_direction(guide_dir, P, "RPP guide direction")?;
    closed::check_loads(load1, load2, P)?;
    closed::check_points([a], P)?;
    let det = cross(&slot_dir, &guide_dir);
    let min_pivot_ratio = closed::relative_det(det, T::one(), P)?;
    let (ns, ng) = (perp(&slot_dir), perp(&guide_dir));
    let f2 = load2.force;
    let (slot, guide) = closed::solve2([ns.x, ng.x, -f2.x], [ns.y, ng.y, -f2.y]);
    let fa = ns * slot - load1.force;
    closed::check_result([fa.x, fa.y, slot, guide], P)?;
    Ok(RppReactions {
        a: fa,
        slot: PrismaticReaction::new(slot, load1.moment, &slot_dir),
        guide: PrismaticReaction::new(guide, -(load1.moment + load2.moment), &guide_dir),
        min_pivot_ratio,
    })
}
