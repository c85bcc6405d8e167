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
//! # The closed form
//!
//! Unknowns: `F_A` (outside on link 1, through `A`), `F_C` (link 1 on the
//! block, through `C`), and the guide's reaction on the block: the normal
//! force `N n` through `C` (`d` = `dir` normalized, `n = perp(d)`) and the
//! couple `M` about `C`. Known loads `(F1, M1)` on link 1 and `(F2, M2)` on
//! the block, moments about `C`. With `a = A - C`, each link's equilibrium:
//!
//! ```text
//! link 1:  F_A - F_C + F1 = 0           cross(a, F_A) + M1 = 0
//! block:   N n + F_C + F2 = 0           M + M2 = 0
//! ```
//!
//! The block's moment gives `M = -M2`. The sum of the force balances gives
//! `F_A = -(F1 + F2) - N n`; in link 1's moment, with
//! `cross(a, n) = dot(a, d)`:
//!
//! ```text
//! N = (M1 - cross(a, F1 + F2)) / dot(a, d),    F_C = -F2 - N n
//! ```
//!
//! One unknown, one division: singular when link 1 is perpendicular to the
//! guide (its axial force then has no component that the guide cannot take,
//! and nothing balances a load along the guide), or when `A = C`.
//! `min_pivot_ratio` is `|dot(a, d)| / |a|`, `|cos|` of the angle between
//! link 1 and the guide: the coefficient of `N` relative to its largest
//! possible size `|a|`.

use crate::error::{Error, Primitive};
use crate::force::body::Wrench;
use crate::force::closed;
use crate::force::group::unit_direction;
use crate::force::PrismaticReaction;
use crate::geometry::{cross, dot, length, perp};
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
    /// Conditioning indicator in `(6 eps, 1]`: `|cos|` of the angle between
    /// link 1 and the guide, `|dot(A - C, dir)| / (|A - C| |dir|)` (see the
    /// module documentation); tends to 0 as link 1 turns perpendicular to
    /// the guide.
    pub min_pivot_ratio: T,
}

/// Reactions of an RRP group from the joints `A`, `C`, the guide direction
/// `dir` (any length; normalized here) and the known loads on link 1 and on the
/// block as wrenches about `C`. The closed form of the module documentation.
///
/// Errors ([`Primitive::Rrp`]): `NonFinite`; `NonPositive` for a zero `dir`;
/// `Singular { det: dot(A - C, d), scale: |A - C| }` when
/// `|det| <= 6 eps scale` (link 1 perpendicular to the guide, or `A = C`).
#[inline(always)]
pub fn reactions<T: Real>(
    a: &Point2<T>,
    c: &Point2<T>,
    dir: &Vector2<T>,
    load1: &Wrench<T>,
    load2: &Wrench<T>,
) -> Result<RrpReactions<T>, Error<T>> {
    let dir = unit_direction(dir, P, "RRP guide direction")?;
    closed::check_loads(load1, load2, P)?;
    closed::check_points([a, c], P)?;
    let ra = a - c;
    let det = dot(&ra, &dir);
    let min_pivot_ratio = closed::relative_det(det, length(&ra), P)?;
    let n = perp(&dir);
    let total = load1.force + load2.force;
    let normal = (load1.moment - cross(&ra, &total)) / det;
    let fa = -total - n * normal;
    let fc = -load2.force - n * normal;
    let moment = -load2.moment;
    closed::check_result([fa.x, fa.y, fc.x, fc.y, normal], P)?;
    Ok(RrpReactions {
        a: fa,
        c: fc,
        guide: PrismaticReaction::new(normal, moment, &dir),
        min_pivot_ratio,
    })
}
