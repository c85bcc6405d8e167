//! Loads on one rigid link: the [`Wrench`] (resultant force and moment about a
//! stated point) and the d'Alembert inertia and gravity loads.
//!
//! Units are the user's and must be consistent: with mass `M`, length `L` and
//! seconds, forces are in `M L / s^2` and moments in `M L^2 / s^2` (kg and m give
//! N and N m; tonnes and mm give N and N mm). Moments and couples are
//! counter-clockwise positive (the z component of `r x F`).

use crate::geometry::{cross, perp};
use crate::scalar::Real;
use core::ops::{Add, AddAssign, Neg, Sub, SubAssign};
use nalgebra::{Point2, Vector2};

/// A planar system of loads reduced to a point: the resultant `force` and the
/// resultant `moment` about a reference point that is *not* stored: every
/// function taking or returning a `Wrench` states which point it is about.
///
/// Two wrenches add only when they are about the same point; [`Wrench::moved`]
/// changes the point.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Wrench<T: Real> {
    /// Resultant force (`M L / s^2`, N in SI).
    pub force: Vector2<T>,
    /// Resultant moment about the stated point (`M L^2 / s^2`, N m in SI),
    /// counter-clockwise positive.
    pub moment: T,
}

/// Moment about `about` of `force` acting through `point`:
/// `cross(point - about, force)` (counter-clockwise positive).
#[inline(always)]
pub fn moment_of<T: Real>(force: &Vector2<T>, point: &Point2<T>, about: &Point2<T>) -> T {
    cross(&(point - about), force)
}

impl<T: Real> Wrench<T> {
    /// No load.
    #[inline(always)]
    pub fn zero() -> Self {
        Wrench {
            force: Vector2::zeros(),
            moment: T::zero(),
        }
    }

    /// A wrench from its parts (force; moment about the caller's stated point).
    #[inline(always)]
    pub fn new(force: Vector2<T>, moment: T) -> Self {
        Wrench { force, moment }
    }

    /// A pure couple (counter-clockwise positive); the same about every point.
    #[inline(always)]
    pub fn couple(moment: T) -> Self {
        Wrench {
            force: Vector2::zeros(),
            moment,
        }
    }

    /// `force` acting through `point`, reduced to `about`: moment
    /// `cross(point - about, force)`.
    #[inline(always)]
    pub fn force_at(force: &Vector2<T>, point: &Point2<T>, about: &Point2<T>) -> Self {
        Wrench {
            force: *force,
            moment: moment_of(force, point, about),
        }
    }

    /// `self` plus `force` acting through `point`; `self` and the result are
    /// about `about`.
    #[inline(always)]
    pub fn with_force_at(self, force: &Vector2<T>, point: &Point2<T>, about: &Point2<T>) -> Self {
        self + Self::force_at(force, point, about)
    }

    /// `self` plus a couple `moment` (counter-clockwise positive).
    #[inline(always)]
    pub fn with_couple(self, moment: T) -> Self {
        Wrench {
            force: self.force,
            moment: self.moment + moment,
        }
    }

    /// The same loads reduced to another point: the force is unchanged and the
    /// moment about `to` is `moment + cross(from - to, force)` (the transport
    /// rule of statics).
    #[inline(always)]
    pub fn moved(&self, from: &Point2<T>, to: &Point2<T>) -> Self {
        Wrench {
            force: self.force,
            moment: self.moment + moment_of(&self.force, from, to),
        }
    }

    /// `true` when the force and the moment are finite.
    #[inline(always)]
    pub fn is_finite(&self) -> bool {
        self.force.x.finite() && self.force.y.finite() && self.moment.finite()
    }

    /// Power (`M L^2 / s^3`, W in SI) of these loads acting on a rigid body
    /// whose material point at the reference point moves at `v` (L/s) and which
    /// turns at `omega` (rad/s): `dot(force, v) + moment * omega`.
    #[inline(always)]
    pub fn power(&self, v: &Vector2<T>, omega: T) -> T {
        self.force.x * v.x + self.force.y * v.y + self.moment * omega
    }
}

impl<T: Real> Add for Wrench<T> {
    type Output = Self;
    #[inline(always)]
    fn add(self, rhs: Self) -> Self {
        Wrench {
            force: self.force + rhs.force,
            moment: self.moment + rhs.moment,
        }
    }
}

impl<T: Real> AddAssign for Wrench<T> {
    #[inline(always)]
    fn add_assign(&mut self, rhs: Self) {
        *self = *self + rhs;
    }
}

impl<T: Real> Sub for Wrench<T> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, rhs: Self) -> Self {
        Wrench {
            force: self.force - rhs.force,
            moment: self.moment - rhs.moment,
        }
    }
}

impl<T: Real> SubAssign for Wrench<T> {
    #[inline(always)]
    fn sub_assign(&mut self, rhs: Self) {
        *self = *self - rhs;
    }
}

impl<T: Real> Neg for Wrench<T> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Wrench {
            force: -self.force,
            moment: -self.moment,
        }
    }
}

/// The d'Alembert inertia load and the weight of a link, reduced to `about`.
///
/// - inertia force `-mass * a_g` and weight `mass * g` act through the centre
///   of mass `g_point` (L), with `a_g` its acceleration (L/s^2) and `gravity`
///   the gravitational acceleration vector (L/s^2, for example `(0, -9.81)` with
///   +y up in metres); `None` means no gravity and its terms vanish at compile
///   time;
/// - the inertia couple is `-inertia_j * alpha`, with `inertia_j` the moment
///   of inertia about the centre of mass (`M L^2`) and `alpha` the link's
///   angular acceleration (rad/s^2, counter-clockwise positive).
///
/// So the result is `force = mass (g - a_g)` and
/// `moment = -inertia_j alpha + cross(g_point - about, force)`. With it,
/// d'Alembert's principle turns the link's equations of motion into
/// equilibrium: known loads + this wrench + joint reactions = 0 (the form of
/// every textbook kinetostatic analysis, e.g. Artobolevsky, *Theory of
/// Mechanisms and Machines*, ch. on force analysis; seed 003's
/// `Fu = -m aS`, `Mu = -JS e`, `G = 9.81 m`).
#[inline(always)]
pub fn inertia_and_gravity<T: Real>(
    mass: T,
    inertia_j: T,
    g_point: &Point2<T>,
    a_g: &Vector2<T>,
    alpha: T,
    gravity: Option<&Vector2<T>>,
    about: &Point2<T>,
) -> Wrench<T> {
    let accel = match gravity {
        Some(g) => g - a_g,
        None => -a_g,
    };
    let force = accel * mass;
    Wrench {
        force,
        moment: -(inertia_j * alpha) + moment_of(&force, g_point, about),
    }
}

/// The force `normal * perp(dir)`: a prismatic pair's normal reaction as a
/// vector (`dir` unit, `perp(dir)` its left normal).
#[inline(always)]
pub fn normal_force<T: Real>(normal: T, dir: &Vector2<T>) -> Vector2<T> {
    perp(dir) * normal
}
