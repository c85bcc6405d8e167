//! Kinetostatics of a slider driver: a block translating along a guide of
//! direction `dir` on the body carrying it, driven by a force along the guide.
//!
//! Unknowns: the guide's normal force `N` (along `perp(dir)`, through the
//! block's pin `P`) and couple `M` (about `P`), both the action of the guide on
//! the block, and the driving force `D` on the block along `dir` (through `P`;
//! a drive acting along a parallel line differs only by a couple, which the
//! guide takes). With the block's known load reduced to `P` (force `F`,
//! moment `M_P`): `N perp(dir) + D dir + F = 0`, `M + M_P = 0`. The columns
//! `perp(dir)`, `dir` are orthonormal, so the 3x3 system is solved exactly by
//! projection: `N = -dot(F, perp(dir))`, `D = -dot(F, dir)`, `M = -M_P`;
//! the conditioning indicator is 1.

use crate::error::{Error, Fault, Primitive};
use crate::force::body::Wrench;
use crate::force::group::unit_direction;
use crate::force::PrismaticReaction;
use crate::geometry::{dot, perp};
use crate::scalar::Real;
use nalgebra::Vector2;

const P: Primitive = Primitive::Slider;

/// Reactions of a slider driver.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct SliderReactions<T: Real> {
    /// Reaction of the guide on the block: normal force along `perp(dir)`
    /// through the pin `P`, couple about `P`.
    pub guide: PrismaticReaction<T>,
    /// Driving force on the block along `dir` (`M L / s^2`); its power is
    /// `drive * s_dot` with `s_dot` the slide rate relative to the guide.
    pub drive: T,
    /// Always 1: the system is orthogonal (kept for a uniform interface).
    pub min_pivot_ratio: T,
}

/// Guide reaction and driving force of a slider with guide direction `dir`
/// (any length; normalized here) whose known load is `load`, a wrench about the
/// block's pin `P`.
///
/// Errors ([`Primitive::Slider`]): `NonFinite`; `NonPositive` for a zero `dir`.
#[inline]
pub fn reactions<T: Real>(
    dir: &Vector2<T>,
    load: &Wrench<T>,
) -> Result<SliderReactions<T>, Error<T>> {
    let dir = unit_direction(dir, P, "slider guide direction")?;
    if !load.is_finite() {
        return Err(Error::new(
            P,
            Fault::NonFinite {
                what: "slider load",
            },
        ));
    }
    let normal = -dot(&load.force, &perp(&dir));
    Ok(SliderReactions {
        guide: PrismaticReaction::new(normal, -load.moment, &dir),
        drive: -dot(&load.force, &dir),
        min_pivot_ratio: T::one(),
    })
}
