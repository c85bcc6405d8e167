//! What the kinds' run-time rate steps need ([`RunCx`]): the `f64` twin of
//! [`super::rates::RateCx`]. Where a kind's `rates` writes the core call of
//! the generated `velocity()` or `acceleration()`, its `run_rates` makes the
//! same call with the same arguments on the values found so far (the
//! position in a [`Pose`], the velocity level in a [`Motion`]), and records
//! what it finds under the same names.

use super::Pose;
use crate::model::Stmt;
use mechanism_core::guide::{LineAcceleration, LineVelocity};
use mechanism_core::Vector2;
use std::any::Any;
use std::collections::{BTreeMap, BTreeSet};
use syn::Ident;

/// The rates found at one level (velocity or acceleration), by name: the
/// moving points' motions (`vel_NAME`/`acc_NAME`), the links' rates
/// (`omega_LINK`/`alpha_LINK`), the carried guides' motions, the groups'
/// rate states (`grp_v_NAME`/`grp_a_NAME`) and the slides' rates.
#[derive(Default)]
pub struct Motion {
    /// Motion of each moving point (L/s or L/s^2).
    pub points: BTreeMap<String, Vector2<f64>>,
    /// Rate of each link that has its own (rad/s or rad/s^2).
    pub links: BTreeMap<String, f64>,
    /// Velocity of each carried guide (velocity level only).
    pub guide_vel: BTreeMap<String, LineVelocity<f64>>,
    /// Acceleration of each carried guide (acceleration level only).
    pub guide_acc: BTreeMap<String, LineAcceleration<f64>>,
    /// The core's rate state of each group.
    pub groups: BTreeMap<String, Box<dyn Any>>,
    /// Rate of each statement's slide (statement name, slot).
    pub slides: BTreeMap<(String, usize), f64>,
    /// Conditioning of each group's velocity system (velocity level only).
    pub conditions: Vec<f64>,
}

impl Motion {
    /// The rate state kept for the statement named `name`.
    pub fn group<S: Any>(&self, name: &Ident) -> Option<&S> {
        self.groups.get(&name.to_string())?.downcast_ref()
    }
}

/// What a kind's run-time rate step reads and where it writes.
pub struct RunCx<'r> {
    /// The position.
    pub pose: &'r Pose,
    /// The velocity level, when computing accelerations.
    pub vel: Option<&'r Motion>,
    /// The level being computed.
    pub out: &'r mut Motion,
    /// The points that move.
    pub moving: &'r BTreeSet<String>,
    /// The link whose rate a link shares (`plan::Plan::turning_link`).
    pub turning: &'r dyn Fn(&str) -> Option<String>,
    /// `true` for a guide carried by a link.
    pub carried: &'r dyn Fn(&str) -> bool,
    /// The inputs' values, rates and accelerations, by input name.
    pub inputs: &'r dyn Fn(&Ident) -> [f64; 3],
}

/// A NaN vector: what a motion not (yet) known reads as; the primitives
/// reject it with a typed error.
fn nan2() -> Vector2<f64> {
    Vector2::new(f64::NAN, f64::NAN)
}

impl RunCx<'_> {
    /// `true` in the acceleration analysis.
    pub fn accel(&self) -> bool {
        self.vel.is_some()
    }

    /// `true` when point `p` moves.
    pub fn moves(&self, p: &Ident) -> bool {
        self.moving.contains(&p.to_string())
    }

    /// The motion of point `p` at this level (zero when it does not move).
    pub fn motion_of(&self, p: &Ident) -> Vector2<f64> {
        if !self.moves(p) {
            return Vector2::zeros();
        }
        self.out
            .points
            .get(&p.to_string())
            .copied()
            .unwrap_or_else(nan2)
    }

    /// The motion of a known point as the optional argument of a core call
    /// (`None` for a point that does not move, as the generated code).
    pub fn point_arg(&self, p: &Ident) -> Option<Vector2<f64>> {
        self.moves(p).then(|| self.motion_of(p))
    }

    /// A carried guide's velocity (`None` for a fixed guide).
    pub fn guide_vel(&self, g: &Ident) -> Option<LineVelocity<f64>> {
        if !(self.carried)(&g.to_string()) {
            return None;
        }
        let level = self.vel.unwrap_or(&*self.out);
        level.guide_vel.get(&g.to_string()).copied()
    }

    /// A carried guide's acceleration (`None` for a fixed guide).
    pub fn guide_acc(&self, g: &Ident) -> Option<LineAcceleration<f64>> {
        if !(self.carried)(&g.to_string()) {
            return None;
        }
        self.out.guide_acc.get(&g.to_string()).copied()
    }

    /// The rate of `link` at this level (`None`: it does not turn).
    pub fn link_rate(&self, link: &Ident) -> Option<f64> {
        let l = (self.turning)(&link.to_string())?;
        Some(self.out.links.get(&l).copied().unwrap_or(f64::NAN))
    }

    /// The angular velocity of `link`, read in the acceleration analysis
    /// (`None`: it does not turn).
    pub fn link_omega_in_accel(&self, link: &Ident) -> Option<f64> {
        let l = (self.turning)(&link.to_string())?;
        let vel = self.vel?;
        Some(vel.links.get(&l).copied().unwrap_or(f64::NAN))
    }

    /// Input `n`'s rate.
    pub fn rate(&self, n: &Ident) -> f64 {
        (self.inputs)(n)[1]
    }

    /// Input `n`'s acceleration.
    pub fn accel_of(&self, n: &Ident) -> f64 {
        (self.inputs)(n)[2]
    }

    /// Input `n`'s value (`pos.input.NAME`).
    pub fn value(&self, n: &Ident) -> f64 {
        (self.inputs)(n)[0]
    }

    /// Records the motion of `stmt`'s point.
    pub fn set_motion(&mut self, stmt: &Stmt, v: Vector2<f64>) {
        self.out.points.insert(stmt.name.to_string(), v);
    }

    /// Records the rate of `stmt`'s link `k`.
    pub fn set_own(&mut self, stmt: &Stmt, k: usize, w: f64) {
        if let Some(link) = stmt.links.get(k) {
            self.out.links.insert(link.to_string(), w);
        }
    }

    /// Records the rate of `stmt`'s slide `slot`.
    pub fn set_slide(&mut self, stmt: &Stmt, slot: usize, v: f64) {
        self.out.slides.insert((stmt.name.to_string(), slot), v);
    }

    /// Keeps `stmt`'s group rate state; `condition`: its velocity system's
    /// conditioning (joins the mechanism's).
    pub fn keep<S: Any>(&mut self, stmt: &Stmt, state: S, condition: Option<f64>) {
        self.out
            .groups
            .insert(stmt.name.to_string(), Box::new(state));
        if let (false, Some(c)) = (self.accel(), condition) {
            self.out.conditions.push(c);
        }
    }

    /// The velocity-level rate state of the statement named `name`.
    pub fn vel_group<S: Any>(&self, name: &Ident) -> Option<&S> {
        self.vel?.group(name)
    }
}

/// The error of a run-time step that finds a state missing (a plan the
/// evaluator cannot walk: a bug of the evaluator, reported, not a panic).
pub fn missing(primitive: mechanism_core::Primitive) -> mechanism_core::Error<f64> {
    mechanism_core::Error::new(
        primitive,
        mechanism_core::Fault::NonFinite {
            what: "state of an earlier step",
        },
    )
}

/// A kind's run-time facet: the `f64` twin of its emitted rate, link-angle
/// and slide code, calling the same core primitives with the same
/// arguments (the position is its `GroupKind::eval`, on a
/// [`Pose::keeping`]).
pub trait RunKind {
    /// Its velocity (`cx.accel()` false) or acceleration: what its `rates`
    /// emits, computed. A kind without rates (a ground point) does nothing.
    fn run_rates(&self, cx: &mut RunCx<'_>) -> Result<(), mechanism_core::Error<f64>>;

    /// The raw direction of its link `index` (the second of
    /// `GroupKind::link_direction`), from the position.
    fn run_link_dir(&self, index: usize, pose: &Pose) -> Vector2<f64>;

    /// The angle output of its link when not the angle of its direction
    /// (a crank's: its input reduced to (-pi, pi]); `value` reads an input.
    fn run_link_angle(&self, _value: &dyn Fn(&Ident) -> f64) -> Option<f64> {
        None
    }

    /// Its slide `slot` (length units) from the position; `None` for a kind
    /// without slides.
    fn run_slide(&self, _slot: usize, _pose: &Pose) -> Option<f64> {
        None
    }
}
