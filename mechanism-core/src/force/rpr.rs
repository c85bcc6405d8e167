//! Kinetostatics of the RPR group: a block (link 1) pinned to the outside at
//! `A` slides along a rocker (link 2) pinned to the outside at `B`; the slide
//! direction `dir` is the rocker's axis `u` (the joint names of
//! `crate::dyad::rpr`).
//!
//! ```text
//!                  A
//!                [=o=]  block 1        loads on both links: wrenches about A
//!     B o----------+------> dir        reactions: outside -> block at A,
//!        rocker 2                      outside -> rocker at B,
//!                                      block -> rocker (slide), about A
//! ```
//!
//! Moments about `A`: the block's moment equation fixes the slide couple
//! (`M = M1`, the couple the block passes on); the rocker's fixes `F_B` across
//! `AB`; force balances fix the rest. Singular when `A` coincides with `B`
//! or, with an offset slide line, when the slide direction is perpendicular to
//! `AB` (the rate system of the dyad is singular there too).

use crate::error::{Error, Primitive};
use crate::force::body::Wrench;
use crate::force::group::{self, unit_direction, Connection, Joint, Pair};
use crate::force::PrismaticReaction;
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::Rpr;

/// Reactions of an RPR group (forces `M L / s^2`, moments `M L^2 / s^2`).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct RprReactions<T: Real> {
    /// Force of the outside body on the block (link 1), at `A`.
    pub a: Vector2<T>,
    /// Force of the outside body on the rocker (link 2), at `B`.
    pub b: Vector2<T>,
    /// Reaction of the block (link 1) on the rocker (link 2) in the slide:
    /// normal force along `perp(dir)` through `A`, couple about `A`. The block
    /// receives the opposite.
    pub slide: PrismaticReaction<T>,
    /// Conditioning indicator, see [`crate::linsolve::Solution::min_pivot_ratio`].
    pub min_pivot_ratio: T,
}

/// Reactions of an RPR group from the pins `A` (block) and `B` (rocker), the
/// slide direction `dir` along the rocker (any length; normalized here) and the
/// known loads on the block and on the rocker as wrenches about `A`.
///
/// Errors ([`Primitive::Rpr`]): `NonFinite`; `NonPositive` for a zero `dir`;
/// `Singular` (see the module documentation).
#[inline]
pub fn reactions<T: Real>(
    a: &Point2<T>,
    b: &Point2<T>,
    dir: &Vector2<T>,
    load1: &Wrench<T>,
    load2: &Wrench<T>,
) -> Result<RprReactions<T>, Error<T>> {
    let dir = unit_direction(dir, P, "RPR slide direction")?;
    let joints = [
        Joint {
            pair: Pair::Revolute { point: *a },
            connection: Connection::OutsideToLink1,
        },
        Joint {
            pair: Pair::Revolute { point: *b },
            connection: Connection::OutsideToLink2,
        },
        Joint {
            pair: Pair::Prismatic { point: *a, dir },
            connection: Connection::Link1ToLink2,
        },
    ];
    let s = group::solve(&joints, a, load1, load2, P)?;
    let [[ax, ay], [bx, by], [n, m]] = s.unknowns;
    Ok(RprReactions {
        a: Vector2::new(ax, ay),
        b: Vector2::new(bx, by),
        slide: PrismaticReaction::new(n, m, &dir),
        min_pivot_ratio: s.min_pivot_ratio,
    })
}
