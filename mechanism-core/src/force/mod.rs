//! Kinetostatics: joint reactions and driving efforts from the motion, by
//! d'Alembert's principle.
//!
//! For every link, known loads (external forces and couples, the reactions of
//! groups solved before, with the sign flipped) plus the inertia load
//! (`-m a_G` through the centre of mass `G`, couple `-J alpha`) plus the weight
//! (`m g` through `G`) plus the unknown joint reactions are in equilibrium
//! (three equations: `Fx`, `Fy`, moment). A class II group has two links and
//! three pairs of two unknowns each: a 6x6 system ([`group`] assembles it and
//! solves it by pivoted elimination, for any three joints). With moments
//! taken about one of its joints, each of the five groups' systems decouples
//! into couples read off directly and at most two unknowns from a 2x2 system
//! with a determinant of the group's geometry, so each group's file solves it
//! in closed form (derived there; [`group::solve`] stays the independent
//! check of the tests); a driver link adds its driving effort to its pivot's
//! two unknowns: 3x3, solved exactly. Groups are solved in the reverse of the
//! kinematic order (the last group first), each passing its outer reactions,
//! negated, to the links it is attached to.
//!
//! # Units and signs
//!
//! Units are the user's and must be consistent (see [`body`]). Global frame;
//! moments and couples counter-clockwise positive.
//!
//! # Reaction convention
//!
//! A reaction is "the force of link i on link j", in the global frame:
//!
//! - at a group's outer joint: the force of the outside body (the ground or a
//!   link of an earlier group) on the group's link there (link 1 at `A`, link 2
//!   at its outer joint). The outside body receives the opposite;
//! - at a group's inner joint: the force of link 1 on link 2 (link 1 receives
//!   the opposite);
//! - at a driver: the force of the body carrying the pivot or the guide on the
//!   driven link, and the driving effort applied *to* the driven link (the
//!   carrying body receives the opposite).
//!
//! A revolute pair transmits a force through its centre. A frictionless
//! prismatic pair with unit direction `dir` transmits, on the body the
//! convention above names as receiving it, a [`PrismaticReaction`]: a normal
//! force `normal * perp(dir)` (signed: positive along `perp(dir)`, the left
//! normal of `dir`) acting through a stated reference point, plus a couple
//! `moment` (counter-clockwise positive): the moment of the contact pressure
//! about that point. The resultant normal force therefore crosses the line
//! through the reference point along `dir` at `point + (moment / normal) dir`
//! (a block is in a stable contact while that lies within its length). Each
//! group and driver names its reference point; it is always one of its joints.
//!
//! # Loads
//!
//! Each function takes the known loads on its links as [`Wrench`]es about a
//! point it names (a joint of the group, so that moment rows stay well scaled),
//! built with [`Wrench::force_at`], [`body::inertia_and_gravity`] and the
//! arithmetic operators, and returns the named reactions plus
//! `min_pivot_ratio`, a conditioning indicator in `(0, 1]`: small near a
//! singular pose (toggle, dead centre, parallel guides), where the
//! reactions' relative error may grow as `eps / min_pivot_ratio`. For the
//! five groups it is the determinant of their reduced system relative to
//! its Hadamard bound, `|sin|` or `|cos|` of an angle of the group (each
//! group's file says which); for the actuator, the smallest relative pivot
//! of [`crate::linsolve::Solution`]; 1 for the crank and slider drivers,
//! whose equations are orthogonal.
//!
//! Errors: `NonFinite` for non-finite loads or geometry, `NonPositive` for a
//! zero guide direction, `Singular` when the pose admits no unique reactions
//! (relative determinant below `6 eps` for the groups, the level at which
//! [`group::solve`] refuses a relative pivot of the same equations; relative
//! pivot below `3 eps` for the actuator), each tagged with the group's
//! [`crate::Primitive`].

pub mod actuator;
pub mod body;
mod closed;
pub mod crank;
pub mod gear;
pub mod group;
pub mod prp;
pub mod rpp;
pub mod rpr;
pub mod rrp;
pub mod rrr;
pub mod slider;
pub mod target;

pub use body::{inertia_and_gravity, moment_of, Wrench};

use crate::geometry::perp;
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

/// The reaction of a frictionless prismatic pair on the body the convention
/// names (see the module documentation), reduced to the pair's stated
/// reference point.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct PrismaticReaction<T: Real> {
    /// Signed normal force (N in SI): the force is `normal * perp(dir)` with
    /// `dir` the pair's unit direction.
    pub normal: T,
    /// Couple about the stated reference point (N m in SI), counter-clockwise
    /// positive.
    pub moment: T,
    /// The normal force as a vector, `normal * perp(dir)`.
    pub force: Vector2<T>,
}

impl<T: Real> PrismaticReaction<T> {
    /// Builds the reaction from `normal`, `moment` and the pair's unit direction.
    #[inline(always)]
    pub fn new(normal: T, moment: T, dir: &Vector2<T>) -> Self {
        PrismaticReaction {
            normal,
            moment,
            force: perp(dir) * normal,
        }
    }

    /// The reaction as a wrench about its reference point.
    #[inline(always)]
    pub fn wrench(&self) -> Wrench<T> {
        Wrench::new(self.force, self.moment)
    }

    /// The reaction as a wrench about `to`, given the reference point `point`
    /// it is stated about.
    #[inline(always)]
    pub fn wrench_about(&self, point: &Point2<T>, to: &Point2<T>) -> Wrench<T> {
        self.wrench().moved(point, to)
    }
}
