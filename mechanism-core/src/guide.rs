//! Straight guides (slide lines) for prismatic pairs, fixed or carried by a
//! moving link.
//!
//! A guide is a line on some body: a reference point `origin` and a unit
//! direction `dir`. A point on the guide at displacement `s` and signed offset
//! `e` (left of `dir` positive) is `origin + s dir + e perp(dir)`.
//!
//! When the guide is carried by a moving link (the six-bar of seed 000 slides a
//! block along its crank), the body's motion enters every rate through
//! [`LineVelocity`] and [`LineAcceleration`]; primitives take them as `Option`,
//! `None` meaning a fixed guide, so that a fixed guide's terms vanish at compile
//! time after inlining.

use crate::geometry::perp;
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

/// A straight guide: `origin` (L) and unit direction `dir`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Line<T: Real> {
    /// A reference point on the line (L); slider displacements are measured from it.
    pub origin: Point2<T>,
    /// Unit direction of the line; positive displacement is along it.
    pub dir: Vector2<T>,
}

impl<T: Real> Line<T> {
    /// The point at displacement `s` along the line and signed offset `offset`
    /// to its left (L).
    #[inline(always)]
    pub fn at(&self, s: T, offset: T) -> Point2<T> {
        self.origin + self.dir * s + perp(&self.dir) * offset
    }
}

/// Velocity state of the body carrying a guide.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LineVelocity<T: Real> {
    /// Velocity of the line's `origin` (L/s).
    pub v_origin: Vector2<T>,
    /// Angular velocity of the carrying body (rad/s).
    pub omega: T,
}

/// Acceleration state of the body carrying a guide.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct LineAcceleration<T: Real> {
    /// Acceleration of the line's `origin` (L/s^2).
    pub a_origin: Vector2<T>,
    /// Angular acceleration of the carrying body (rad/s^2).
    pub alpha: T,
}

impl<T: Real> LineVelocity<T> {
    /// Velocity of the body's material point at `p` (L/s).
    #[inline(always)]
    pub fn velocity_at(&self, origin: &Point2<T>, p: &Point2<T>) -> Vector2<T> {
        self.v_origin + perp(&(p - origin)) * self.omega
    }
}

impl<T: Real> LineAcceleration<T> {
    /// Acceleration of the body's material point at `p` (L/s^2), given its
    /// angular velocity `omega`.
    #[inline(always)]
    pub fn acceleration_at(&self, origin: &Point2<T>, p: &Point2<T>, omega: T) -> Vector2<T> {
        let r = p - origin;
        self.a_origin + perp(&r) * self.alpha - r * (omega * omega)
    }
}
