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
//! # The closed form
//!
//! Unknowns: `F_A` (outside on the block, through `A`), `F_B` (outside on the
//! rocker, through `B`), and the slide's reaction of the block on the rocker:
//! the normal force `N n` through `A` (`d` = `dir` normalized, `n = perp(d)`)
//! and the couple `M` about `A` (the block receives the opposite). Known loads
//! `(F1, M1)` on the block and `(F2, M2)` on the rocker, moments about `A`.
//! With `b = B - A`:
//!
//! ```text
//! block:   F_A - N n + F1 = 0           -M + M1 = 0
//! rocker:  F_B + N n + F2 = 0           cross(b, F_B) + M + M2 = 0
//! ```
//!
//! The block's moment gives `M = M1` (the couple the block passes on). The
//! rocker's force balance gives `F_B = -F2 - N n`; in its moment, with
//! `cross(b, n) = dot(b, d)`:
//!
//! ```text
//! N = (M1 + M2 - cross(b, F2)) / dot(b, d),    F_A = N n - F1
//! ```
//!
//! One unknown, one division: singular when `A` coincides with `B` or, with
//! an offset slide line, when the slide direction is perpendicular to `AB`
//! (the rate system of the dyad is singular there too). `min_pivot_ratio` is
//! `|dot(b, d)| / |b|`, `|cos|` of the angle between `AB` and the slide: the
//! coefficient of `N` relative to its largest possible size `|b|`.

use crate::error::{Error, Primitive};
use crate::force::body::Wrench;
use crate::force::closed;
use crate::force::group::unit_direction;
use crate::force::PrismaticReaction;
use crate::geometry::{cross, dot, length, perp};
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
    /// Conditioning indicator in `(6 eps, 1]`: `|cos|` of the angle between
    /// `B - A` and the slide, `|dot(B - A, dir)| / (|B - A| |dir|)` (see the
    /// module documentation); 1 when the slide line passes through `B`.
    pub min_pivot_ratio: T,
}

/// Reactions of an RPR group from the pins `A` (block) and `B` (rocker), the
/// slide direction `dir` along the rocker (any length; normalized here) and the
/// known loads on the block and on the rocker as wrenches about `A`. The
/// closed form of the module documentation.
///
/// Errors ([`Primitive::Rpr`]): `NonFinite`; `NonPositive` for a zero `dir`;
/// `Singular { det: dot(B - A, d), scale: |B - A| }` when
/// `|det| <= 6 eps scale` (see the module documentation).
#[inline(always)]
pub fn reactions<T: Real>(
    a: &Point2<T>,
    b: &Point2<T>,
    dir: &Vector2<T>,
    load1: &Wrench<T>,
    load2: &Wrench<T>,
) -> Result<RprReactions<T>, Error<T>> {
    let dir = unit_direction(dir, P, "RPR slide direction")?;
    closed::check_loads(load1, load2, P)?;
    closed::check_points([a, b], P)?;
    let rb = b - a;
    let det = dot(&rb, &dir);
    let min_pivot_ratio = closed::relative_det(det, length(&rb), P)?;
    let n = perp(&dir);
    let normal = (load1.moment + load2.moment - cross(&rb, &load2.force)) / det;
    let fa = n * normal - load1.force;
    let fb = -load2.force - n * normal;
    closed::check_result([fa.x, fa.y, fb.x, fb.y, normal], P)?;
    Ok(RprReactions {
        a: fa,
        b: fb,
        slide: PrismaticReaction::new(normal, load1.moment, &dir),
        min_pivot_ratio,
    })
}
