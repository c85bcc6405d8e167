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
//! Moments about `A`: the block's moment equation gives the slot couple
//! (`M_slot = M1`); link 2's gives the guide couple; the force balances give
//! the pin force and the two normal forces. Singular when the slot is parallel
//! to the guide.

use crate::error::{Error, Primitive};
use crate::force::body::Wrench;
use crate::force::group::{self, unit_direction, Connection, Joint, Pair};
use crate::force::PrismaticReaction;
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
    /// Conditioning indicator, see [`crate::linsolve::Solution::min_pivot_ratio`].
    pub min_pivot_ratio: T,
}

/// Reactions of an RPP group from the pin `A`, the slot and guide directions
/// (any length; normalized here) and the known loads on the block and on link
/// 2 as wrenches about `A`.
///
/// Errors ([`Primitive::Rpp`]): `NonFinite`; `NonPositive` for a zero
/// direction; `Singular` when the slot is parallel to the guide.
#[inline]
pub fn reactions<T: Real>(
    a: &Point2<T>,
    slot_dir: &Vector2<T>,
    guide_dir: &Vector2<T>,
    load1: &Wrench<T>,
    load2: &Wrench<T>,
) -> Result<RppReactions<T>, Error<T>> {
    let slot_dir = unit_direction(slot_dir, P, "RPP slot direction")?;
    let guide_dir = unit_direction(guide_dir, P, "RPP guide direction")?;
    let joints = [
        Joint {
            pair: Pair::Revolute { point: *a },
            connection: Connection::OutsideToLink1,
        },
        Joint {
            pair: Pair::Prismatic {
                point: *a,
                dir: slot_dir,
            },
            connection: Connection::Link1ToLink2,
        },
        Joint {
            pair: Pair::Prismatic {
                point: *a,
                dir: guide_dir,
            },
            connection: Connection::OutsideToLink2,
        },
    ];
    let s = group::solve(&joints, a, load1, load2, P)?;
    let [[ax, ay], [ns, ms], [ng, mg]] = s.unknowns;
    Ok(RppReactions {
        a: Vector2::new(ax, ay),
        slot: PrismaticReaction::new(ns, ms, &slot_dir),
        guide: PrismaticReaction::new(ng, mg, &guide_dir),
        min_pivot_ratio: s.min_pivot_ratio,
    })
}
