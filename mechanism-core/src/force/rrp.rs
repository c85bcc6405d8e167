//! Kinetostatics of the RRP group: link 1 pinned to the outside at `A` and to
//! a block (link 2) at `C`; the block slides on a guide of the outside body
//! with direction `dir` (the joint names of `crate::dyad::rrp`).
//!
//! ```text
//!        A
//!         \  1                 loads on both links: wrenches about C
//!          \
//!    -------C[2]------> dir     reactions: outside -> 1 at A, 1 -> 2 at C,
//!                               guide (outside) -> block, about C
//! ```
//!
//! Moments about `C`: link 1's moment equation fixes `F_A` across link 1; the
//! block's fixes the guide couple (`M = -M2`); the force balance of the group
//! fixes `F_A` along link 1 and the normal force. Singular when link 1 is
//! perpendicular to the guide (its axial force then has no component that the
//! guide cannot take, and nothing balances a load along the guide).

use crate::error::{Error, Primitive};
use crate::force::body::Wrench;
use crate::force::group::{self, unit_direction, Pair};
use crate::force::PrismaticReaction;
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::Rrp;

/// Reactions of an RRP group (forces `M L / s^2`, moments `M L^2 / s^2`).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RrpReactions<T: Real> {
    /// Force of the outside body on link 1, at `A`.
    pub a: Vector2<T>,
    /// Force of link 1 on the block (link 2) at `C` (link 1 receives `-c`).
    pub c: Vector2<T>,
    /// Reaction of the guide (outside body) on the block: normal force along
    /// `perp(dir)` through `C`, couple about `C`.
    pub guide: PrismaticReaction<T>,
    /// Conditioning indicator: [`crate::linsolve::Solution::min_pivot_ratio`] of
    /// the reduced 4x4 system of [`crate::force::group::solve_inner_revolute`].
    pub min_pivot_ratio: T,
}

/// Reactions of an RRP group from the joints `A`, `C`, the guide direction
/// `dir` (any length; normalized here) and the known loads on link 1 and on the
/// block as wrenches about `C`.
///
/// Errors ([`Primitive::Rrp`]): `NonFinite`; `NonPositive` for a zero `dir`;
/// `Singular` when link 1 is perpendicular to the guide or `A = C`.
#[inline]
pub fn reactions<T: Real>(
    a: &Point2<T>,
    c: &Point2<T>,
    dir: &Vector2<T>,
    load1: &Wrench<T>,
    load2: &Wrench<T>,
) -> Result<RrpReactions<T>, Error<T>> {
    let dir = unit_direction(dir, P, "RRP guide direction")?;
    let s = group::solve_inner_revolute(
        &Pair::Revolute { point: *a },
        &Pair::Prismatic { point: *c, dir },
        c,
        load1,
        load2,
        P,
    )?;
    let [[ax, ay], [n, m], [cx, cy]] = s.unknowns;
    Ok(RrpReactions {
        a: Vector2::new(ax, ay),
        c: Vector2::new(cx, cy),
        guide: PrismaticReaction::new(n, m, &dir),
        min_pivot_ratio: s.min_pivot_ratio,
    })
}
