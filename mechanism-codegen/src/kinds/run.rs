//! What the kinds' run-time rate steps need ([`RunCx`]): the `f64` twin of
//! [`super::rates::RateCx`]. Where a kind's `rates` writes the core call of
//! the generated `velocity()` or `acceleration()`, its `run_rates` makes the
//! same call with the same arguments on the values found so far (the
//! position in a [`Pose`], the velocity level in a [`Motion`]), and records
//! what it finds under the same names.

use super::Pose;
use crate::model::Stmt;
use crate::names::Family;
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

    /// Its joint reactions and driving efforts in the force analysis: what
    /// its `GroupKind::forces` emits, computed with the same core call on
    /// the same loads, passing the same reactions to the same bodies. A
    /// kind without forces (a ground point, a guide, a point on a link)
    /// does nothing.
    fn run_forces(&self, cx: &mut ForceRunCx<'_>) -> Result<(), mechanism_core::Error<f64>>;

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

/// A reaction or driving effort the run-time force walk found: the value
/// of one field of the generated forces struct.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ForceValue {
    /// A revolute joint's force (force units, global frame).
    Force(Vector2<f64>),
    /// A prismatic pair's reaction (normal force, couple about its point).
    Prismatic(mechanism_core::force::PrismaticReaction<f64>),
    /// A driving torque (force x length) or a push along a line (force).
    Scalar(f64),
}

/// One field of the forces struct, as the run-time walk finds it.
#[derive(Clone, Debug, PartialEq)]
pub struct RunReaction {
    /// The field's name (`r_ground_link2`, `drive_theta`), before the
    /// numbering of repeated names.
    pub name: String,
    /// What it holds.
    pub held: super::forces::Held,
    /// Its value.
    pub value: ForceValue,
}

/// What a kind's run-time force step reads and where it writes: the `f64`
/// twin of [`super::forces::ForceCx`]. Loads are accumulated per link as a
/// wrench about the link's reference point (its first point), in the order
/// and with the operations the emitted `forces()` uses.
pub struct ForceRunCx<'r> {
    /// The position.
    pub pose: &'r Pose,
    /// The velocity level.
    pub vel: &'r Motion,
    /// The acceleration level.
    pub acc: &'r Motion,
    /// The plan (bodies of points and guides, links' points and rates).
    pub plan: &'r crate::plan::Plan,
    /// The points that move.
    pub moving: &'r BTreeSet<String>,
    /// The inputs' rates (rad/s, L/s), by input name.
    pub rate: &'r dyn Fn(&Ident) -> f64,
    /// The load of each loaded link, about its reference point.
    pub loads: BTreeMap<String, mechanism_core::force::Wrench<f64>>,
    /// The fields found, in order.
    pub reactions: Vec<RunReaction>,
    /// The power terms of the balance, in order.
    pub power: Vec<f64>,
    /// The groups' force-system conditioning, in order.
    pub conditions: Vec<f64>,
}

/// An identifier for a name the plan holds as text.
fn ident(name: &str) -> Ident {
    Ident::new(name, proc_macro2::Span::call_site())
}

impl ForceRunCx<'_> {
    /// Point `p` of the position.
    pub fn at(&self, p: &Ident) -> mechanism_core::Point2<f64> {
        self.pose.point(p)
    }

    /// The body owning a point (`None`: the ground).
    pub fn body_of_point(&self, point: &Ident) -> Option<String> {
        self.plan.body_of_point(&point.to_string())
    }

    /// The body carrying a guide (`None`: the ground).
    pub fn body_of_guide(&self, guide: &Ident) -> Option<String> {
        self.plan.body_of_guide(&guide.to_string())
    }

    /// The reference point of `link`'s load: its first point.
    pub fn reference(&self, link: &str) -> Option<Ident> {
        let info = self.plan.links.get(link)?;
        info.points.first().map(|p| ident(p))
    }

    /// The velocity of point `p` (`None`: it never moves).
    pub fn velocity_of(&self, p: &Ident) -> Option<Vector2<f64>> {
        let name = p.to_string();
        self.moving.contains(&name).then(|| {
            let nan = Vector2::new(f64::NAN, f64::NAN);
            self.vel.points.get(&name).copied().unwrap_or(nan)
        })
    }

    /// The acceleration of point `p` (NaN when unknown).
    pub fn acceleration_of(&self, p: &Ident) -> Vector2<f64> {
        let nan = Vector2::new(f64::NAN, f64::NAN);
        self.acc.points.get(&p.to_string()).copied().unwrap_or(nan)
    }

    /// The angular velocity and acceleration of `link` (`None`: it does
    /// not turn).
    pub fn rates_of(&self, link: &Ident) -> Option<(f64, f64)> {
        let l = self.plan.turning_link(&link.to_string())?;
        let w = self.vel.links.get(&l).copied().unwrap_or(f64::NAN);
        let a = self.acc.links.get(&l).copied().unwrap_or(f64::NAN);
        Some((w, a))
    }

    /// The load of `link` as a wrench about `point` (zero when it carries
    /// none yet).
    pub fn load_about(&self, link: &Ident, point: &Ident) -> mechanism_core::force::Wrench<f64> {
        let l = link.to_string();
        let (Some(load), Some(r)) = (self.loads.get(&l), self.reference(&l)) else {
            return mechanism_core::force::Wrench::zero();
        };
        if *point == r {
            *load
        } else {
            load.moved(&self.at(&r), &self.at(point))
        }
    }

    /// The loads of a group's two links about `point`.
    pub fn loads_about(
        &self,
        stmt: &Stmt,
        point: &Ident,
    ) -> (
        mechanism_core::force::Wrench<f64>,
        mechanism_core::force::Wrench<f64>,
    ) {
        (
            self.load_about(&stmt.links[0], point),
            self.load_about(&stmt.links[1], point),
        )
    }

    /// Adds a wrench (about the link's reference point) to a link's load.
    pub fn add(&mut self, link: &str, wrench: mechanism_core::force::Wrench<f64>) {
        match self.loads.get_mut(link) {
            Some(load) => *load += wrench,
            None => {
                self.loads.insert(link.to_string(), wrench);
            }
        }
    }

    /// A force acting on `link` at point `at`, added to its load.
    pub fn force_on(&mut self, link: &str, force: Vector2<f64>, at: &Ident) {
        use mechanism_core::force::Wrench;
        let Some(r) = self.reference(link) else {
            return;
        };
        let wrench = if *at == r {
            Wrench::new(force, 0.0)
        } else {
            Wrench::force_at(&force, &self.at(at), &self.at(&r))
        };
        self.add(link, wrench);
    }

    /// A prismatic reaction (about point `about`) negated onto `body`.
    pub fn prismatic_on(
        &mut self,
        body: Option<String>,
        rx: &mechanism_core::force::PrismaticReaction<f64>,
        about: &Ident,
    ) {
        let Some(body) = body else {
            return;
        };
        let Some(r) = self.reference(&body) else {
            return;
        };
        let wrench = if *about == r {
            -rx.wrench()
        } else {
            -rx.wrench_about(&self.at(about), &self.at(&r))
        };
        self.add(&body, wrench);
    }

    /// An outer revolute joint at `point` whose reaction on the group is
    /// `force`: passes it, negated, to the body owning the point (nothing
    /// for the ground) and returns that body.
    pub fn pass_revolute(&mut self, point: &Ident, force: Vector2<f64>) -> Option<String> {
        let body = self.body_of_point(point);
        if let Some(b) = &body {
            self.force_on(b, -force, point);
        }
        body
    }

    /// A revolute reaction: the force of `from` (a body or the ground) on
    /// `to`.
    pub fn revolute(&mut self, from: &Option<String>, to: &Ident, force: Vector2<f64>) {
        self.field(
            Family::Reaction.pair_text(super::forces::body_name(from), to),
            super::forces::Held::Force,
            ForceValue::Force(force),
        );
    }

    /// A prismatic pair's reaction of `from` on `to`.
    pub fn prismatic(
        &mut self,
        from: &Option<String>,
        to: &Ident,
        rx: mechanism_core::force::PrismaticReaction<f64>,
    ) {
        self.field(
            Family::Reaction.pair_text(super::forces::body_name(from), to),
            super::forces::Held::Prismatic,
            ForceValue::Prismatic(rx),
        );
    }

    /// The joint between a group's two links (the force of the first on
    /// the second).
    pub fn inner(&mut self, links: &[Ident], value: ForceValue) {
        let held = match value {
            ForceValue::Prismatic(_) => super::forces::Held::Prismatic,
            _ => super::forces::Held::Force,
        };
        self.field(
            Family::Reaction.pair_text(&links[0], &links[1]),
            held,
            value,
        );
    }

    /// A driving effort of `input` (`drive_INPUT`).
    pub fn drive(&mut self, input: &Ident, held: super::forces::Held, value: f64) {
        self.field(Family::Drive.text(input), held, ForceValue::Scalar(value));
    }

    /// A field of the forces struct.
    pub fn field(&mut self, name: String, held: super::forces::Held, value: ForceValue) {
        self.reactions.push(RunReaction { name, held, value });
    }
}
