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
//! # The closed form
//!
//! Unknowns: each guide's reaction on its link, the normal force `N_i n_i`
//! through `C` (`d_i` = `dir_i` normalized, `n_i = perp(d_i)`) and the couple
//! `G_i` about `C`, and `F_C` (link 1 on link 2). Known loads `(F1, M1)` and
//! `(F2, M2)`, moments about `C`:
//!
//! ```text
//! link 1:  N1 n1 - F_C + F1 = 0          G1 + M1 = 0
//! link 2:  N2 n2 + F_C + F2 = 0          G2 + M2 = 0
//! ```
//!
//! The moments give the couples, `G_i = -M_i`. The sum of the force balances,
//!
//! ```text
//! N1 n1 + N2 n2 = -(F1 + F2)
//! ```
//!
//! is a 2x2 system (its `x` and `y` rows) with unit columns and determinant
//! `cross(n1, n2) = cross(d1, d2)`, solved by elimination with scaled partial
//! pivoting (see `force::closed`); link 2's force balance then gives
//! `F_C = -F2 - N2 n2`. Singular when the
//! guides are parallel (nothing balances a load along them).
//! `min_pivot_ratio` is `|cross(d1, d2)|`, `|sin|` of the angle between the
//! guides: the 2x2 system's 2-norm condition lies between
//! `1 / min_pivot_ratio` and `2 / min_pivot_ratio`.

use crate::error::{Error, Primitive};
use crate::force::body::Wrench;
use crate::force::closed;
use crate::force::group::unit_direction;
use crate::force::PrismaticReaction;
use crate::geometry::{cross, perp};
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
    /// Conditioning indicator in `(6 eps, 1]`: `|sin|` of the angle between
    /// the guides (see the module documentation); tends to 0 as they turn
    /// parallel.
    pub min_pivot_ratio: T,
}

/// Reactions of a PRP group from the pin `C`, the guide directions (any
/// length; normalized here) and the known loads on links 1 and 2 as wrenches
/// about `C`. The closed form of the module documentation.
///
/// Errors ([`Primitive::Prp`]): `NonFinite`; `NonPositive` for a zero
/// direction; `Singular { det: cross(d1, d2), scale: 1 }` for guides parallel
/// to within `|det| <= 6 eps`.
#[inline(always)]
pub fn reactions<T: Real>(
    c: &Point2<T>,
    dir1: &Vector2<T>,
    dir2: &Vector2<T>,
    load1: &Wrench<T>,
    load2: &Wrench<T>,
) -> Result<PrpReactions<T>, Error<T>> {
    let dir1 = unit_direction(dir1, P, "PRP guide 1 direction")?;
    let dir2 = unit_direction(dir2, P, "PRP guide 2 direction")?;
    closed::check_loads(load1, load2, P)?;
    closed::check_points([c], P)?;
    let det = cross(&dir1, &dir2);
    let min_pivot_ratio = closed::relative_det(det, T::one(), P)?;
    let (n1, n2) = (perp(&dir1), perp(&dir2));
    let total = load1.force + load2.force;
    let (normal1, normal2) = closed::solve2([n1.x, n2.x, -total.x], [n1.y, n2.y, -total.y]);
    let fc = -load2.force - n2 * normal2;
    closed::check_result([normal1, normal2, fc.x, fc.y], P)?;
    Ok(PrpReactions {
        guide1: PrismaticReaction::new(normal1, -load1.moment, &dir1),
        guide2: PrismaticReaction::new(normal2, -load2.moment, &dir2),
        c: fc,
        min_pivot_ratio,
    })
}
