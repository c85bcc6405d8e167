//! Kinetostatics of the PRP group: link 1 slides on outside guide 1
//! (direction `dir1`), link 2 on outside guide 2 (`dir2`), and the two are
//! pinned together at `C` (the joint names of `crate::dyad::prp`).
//!
//! ```text
//!                \ dir2
//!       ----[1]---C---------> dir1     loads on both links: wrenches about C
//!                  \[2]                reactions: guide 1 -> link 1 and
//!                   \                  guide 2 -> link 2, both about C;
//!                                      link 1 -> link 2 at C
//! ```
//!
//! Moments about `C`: each link's moment equation gives its guide couple
//! (`M_i = -M_load_i`); the force balances give the two normal forces and the
//! pin force. Singular when the guides are parallel (nothing balances a load
//! along them).

use crate::error::{Error, Primitive};
use crate::force::body::Wrench;
use crate::force::group::{self, unit_direction, Pair};
use crate::force::PrismaticReaction;
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

const P: Primitive = Primitive::Prp;

/// Reactions of a PRP group (forces `M L / s^2`, moments `M L^2 / s^2`).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PrpReactions<T: Real> {
    /// Reaction of guide 1 (outside body) on link 1: normal force along
    /// `perp(dir1)` through `C`, couple about `C`.
    pub guide1: PrismaticReaction<T>,
    /// Reaction of guide 2 (outside body) on link 2: normal force along
    /// `perp(dir2)` through `C`, couple about `C`.
    pub guide2: PrismaticReaction<T>,
    /// Force of link 1 on link 2 at `C` (link 1 receives `-c`).
    pub c: Vector2<T>,
    /// Conditioning indicator: [`crate::linsolve::Solution::min_pivot_ratio`] of
    /// the reduced 4x4 system of [`crate::force::group::solve_inner_revolute`].
    pub min_pivot_ratio: T,
}

/// Reactions of a PRP group from the pin `C`, the guide directions (any
/// length; normalized here) and the known loads on links 1 and 2 as wrenches
/// about `C`.
///
/// Errors ([`Primitive::Prp`]): `NonFinite`; `NonPositive` for a zero
/// direction; `Singular` for parallel guides.
#[inline]
pub fn reactions<T: Real>(
    c: &Point2<T>,
    dir1: &Vector2<T>,
    dir2: &Vector2<T>,
    load1: &Wrench<T>,
    load2: &Wrench<T>,
) -> Result<PrpReactions<T>, Error<T>> {
    let dir1 = unit_direction(dir1, P, "PRP guide 1 direction")?;
    let dir2 = unit_direction(dir2, P, "PRP guide 2 direction")?;
    let s = group::solve_inner_revolute(
        &Pair::Prismatic {
            point: *c,
            dir: dir1,
        },
        &Pair::Prismatic {
            point: *c,
            dir: dir2,
        },
        c,
        load1,
        load2,
        P,
    )?;
    let [[n1, m1], [n2, m2], [cx, cy]] = s.unknowns;
    Ok(PrpReactions {
        guide1: PrismaticReaction::new(n1, m1, &dir1),
        guide2: PrismaticReaction::new(n2, m2, &dir2),
        c: Vector2::new(cx, cy),
        min_pivot_ratio: s.min_pivot_ratio,
    })
}
