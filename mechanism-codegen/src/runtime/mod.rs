//! The run-time mechanism: a definition read from text at run time, through
//! the macro's own stages (parse, model, validate, plan, check: the same
//! rules and messages, every error at once), evaluated in `f64` by walking
//! the plan compiled into each kind's `run::Step` (defined in the kind's
//! file): its position, rates and forces call the `mechanism-core`
//! primitive the generated code calls, with the same arguments, in the same
//! order. The expansion-time check walks the same steps' positions; no
//! second solver.
//!
//! ```
//! use mechanism_codegen::runtime::Mechanism;
//! let m = Mechanism::new(
//!     "let O2 = ground(0.0, 0.0);
//!      let O4 = ground(3.0, 0.0);
//!      let A = crank(O2, 1.0, theta) as link2;
//!      let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);",
//! )
//! .unwrap();
//! let pos = m.position(&[0.5]).unwrap();
//! let b_x = pos.values[m.columns(mechanism_codegen::runtime::Analysis::Position)
//!     .iter().position(|c| c.name == "B.x").unwrap()];
//! assert!((b_x - 2.1).abs() < 1.0);
//! ```

pub mod forces;
pub mod layout;
pub mod text;

use crate::diag::Diagnostics;
use crate::keys::{LinkName, PointName};
use crate::kinds;
use crate::kinds::run::{
    self, Compile, LinkSlot, Motion, PointSlot, RunCx, RunPose, Step, StepSlot, Walks,
};
use crate::model::{Mode, Model, StmtId};
use crate::plan::Plan;
pub use forces::Forces;
use mechanism_core::{geometry, Error};
use std::collections::BTreeMap;
use std::sync::Arc;
pub use text::{Diagnostic, Errors};

/// Which analysis a column belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Analysis {
    /// Positions (L), angles (rad), slides (L).
    Position,
    /// Velocities (L/s), angular velocities (rad/s), slide rates (L/s).
    Velocity,
    /// Accelerations (L/s^2, rad/s^2).
    Acceleration,
}

/// One output number: its name as the generated struct spells the field
/// (`B.x`, `link3`, `s`), and its unit.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Column {
    /// The field path in the generated struct of its analysis.
    pub name: String,
    /// Its unit: `L` (the definition's length unit, as its `units`
    /// statement names it: `mm`), `rad`, `L/s`, `rad/s`, `L/s^2`, `rad/s^2`
    /// (`s` the time unit's name); force columns: the force unit `F` and
    /// `F L` (`N mm`), `1` for a ratio.
    pub unit: &'static str,
}

/// A driver input of the definition.
#[derive(Clone, Debug, PartialEq)]
pub struct InputInfo {
    /// Its name (a field of the generated input struct).
    pub name: String,
    /// `true` for an angle (rad), `false` for a length (L).
    pub angle: bool,
    /// The range the definition declares or implies (a crank's full turn),
    /// `(lo, hi)` in rad or L; `None` when it has none.
    pub range: Option<(f64, f64)>,
}

/// The position at one input: the outputs in [`Mechanism::columns`] order
/// and the state the rates read, in storage made once
/// ([`Mechanism::new_position`]) and filled by each
/// [`Mechanism::position_into`].
#[derive(Clone, Debug)]
pub struct Position {
    /// The output values, as `columns(Analysis::Position)`.
    pub values: Vec<f64>,
    pose: RunPose,
    slots: Arc<run::Layout>,
    /// `true` once solved; `false` after a failed solve.
    solved: bool,
}

/// The velocity or acceleration at one input, in storage made once
/// ([`Mechanism::new_rates`]).
#[derive(Clone, Debug)]
pub struct Rates {
    /// The output values, as `columns` of its analysis.
    pub values: Vec<f64>,
    /// The smallest scaled determinant of the groups' velocity systems, in
    /// (0, 1] (the generated struct's `condition`); 1 in an acceleration.
    pub condition: f64,
    motion: Motion,
    /// `true` once computed; `false` after a failure.
    solved: bool,
}

/// Where a position output comes from.
#[derive(Clone, Copy, Debug)]
enum PosOut {
    /// A point's coordinates.
    Point(PointSlot),
    /// The angle of link `index` of statement `stmt`.
    Angle { stmt: StmtId, index: usize },
    /// Slide `k` of statement `stmt`.
    Slide { stmt: StmtId, k: usize },
}

/// Where the rate outputs come from, by kind, in the order of the values
/// (every point's two, then every link's, then every slide's): each kind
/// read in its own loop, without a dispatch per output.
#[derive(Clone, Debug, Default)]
struct RateOut {
    /// Each output point's slot (`None`: it does not move; zero).
    points: Vec<Option<PointSlot>>,
    /// Each output link's rate slot (`None`: it does not turn; zero).
    links: Vec<Option<LinkSlot>>,
    /// Each output slide: its statement and its slide.
    slides: Vec<(StepSlot, usize)>,
}

impl RateOut {
    /// The number of values.
    fn len(&self) -> usize {
        2 * self.points.len() + self.links.len() + self.slides.len()
    }
}

/// The plan compiled: one step per statement (by statement index), the
/// statements `position()` solves, in order, those of them whose rates and
/// whose forces do something ([`Step::walks`]), in the same order, and
/// where each output is.
struct Compiled {
    steps: Vec<Box<dyn Step>>,
    solve: Vec<StmtId>,
    rate_walk: Vec<StmtId>,
    force_walk: Vec<StmtId>,
    pos_out: Vec<PosOut>,
    rate_out: RateOut,
    /// The force analysis' loads and motors ([`forces::ForcePlan`]).
    forces: forces::ForcePlan,
}

/// A mechanism read from text at run time.
pub struct Mechanism {
    model: Model,
    plan: Plan,
    params: BTreeMap<String, f64>,
    /// What the check found (the triads' tracked assemblies) and the
    /// modes set at run time ([`Mechanism::set_mode`]), which the position
    /// reads in place of the defaults.
    known: kinds::Known,
    /// The `loads { .. }` values ([`Mechanism::set_load`]).
    loads: BTreeMap<String, f64>,
    /// The compiled plan and slots ([`Solver`]).
    solver: Solver,
}

/// The name `s` with a `'static` lifetime (errors name their group so).
fn intern(s: &str) -> &'static str {
    run::intern(s)
}

impl Mechanism {
    /// Reads a definition: the text between the braces of `mechanism! {
    /// ... }` or the whole `pub Name { ... }` item. Every error of every
    /// stage, as the macro reports them, with their places in `text`.
    pub fn new(text: &str) -> Result<Self, Errors> {
        let tokens = text::tokens(text).map_err(|e| Errors::new(text, vec![e]))?;
        let definition =
            crate::parse::definition(tokens).map_err(|e| Errors::new(text, vec![e]))?;
        let mut diag = Diagnostics::new();
        let model = crate::model::lower(definition, &mut diag);
        crate::validate::model(&model, &mut diag);
        let plan = crate::plan::plan(&model, &mut diag);
        if let Some(plan) = &plan {
            crate::validate::planned(&model, plan, &mut diag);
        }
        let plan = match plan {
            Some(plan) if diag.is_empty() => plan,
            _ => return Err(Errors::new(text, diag.finish())),
        };
        let findings = crate::check::expansion_check(&model, &plan, &mut diag);
        crate::check::modes::other_modes(&model, &plan, &mut diag);
        let errors = diag.finish();
        if !errors.is_empty() {
            return Err(Errors::new(text, errors));
        }
        let params = model
            .params
            .iter()
            .map(|(n, v)| (n.to_string(), *v))
            .collect();
        let loads = model
            .kinetics
            .loads
            .iter()
            .map(|(n, v)| (n.to_string(), *v))
            .collect();
        let slots = Arc::new(crate::slots::layout(&model, &plan));
        let solver = Solver {
            compiled: Arc::new(Compiled {
                steps: Vec::new(),
                solve: Vec::new(),
                rate_walk: Vec::new(),
                force_walk: Vec::new(),
                pos_out: Vec::new(),
                rate_out: RateOut::default(),
                forces: forces::ForcePlan::default(),
            }),
            slots,
            inputs: model.inputs.len(),
            forces: model.level >= crate::model::Level::Forces,
        };
        let mut m = Mechanism {
            model,
            plan,
            params,
            known: findings.known,
            loads,
            solver,
        };
        m.compile();
        Ok(m)
    }

    /// Compiles the plan with the current parameters, modes and loads:
    /// every name resolved to its slot, every dimension valued.
    fn compile(&mut self) {
        let cx = Compile {
            layout: &self.solver.slots,
            params: &self.params,
        };
        let stmts = &self.model.stmts;
        let steps: Vec<Box<dyn Step>> = StmtId::all(stmts)
            .map(|i| kinds::of_known(stmts, i, &self.known).compile(&cx))
            .collect();
        let solve = self.plan.solve.clone();
        let walk = |takes: fn(Walks) -> bool| -> Vec<StmtId> {
            solve
                .iter()
                .copied()
                .filter(|i| takes(steps[i.0].walks()))
                .collect()
        };
        let (rate_walk, force_walk) = (walk(|w| w.rates), walk(|w| w.forces));
        let out = &self.plan.outputs;
        let mut pos_out = Vec::new();
        let mut rate_out = RateOut::default();
        for p in &out.points {
            let slot = self.solver.slots.point_named(&PointName::of(p));
            pos_out.push(PosOut::Point(slot));
            let moving = self.solver.slots.moving[slot.index()];
            rate_out.points.push(moving.then_some(slot));
        }
        for link in &out.links {
            let name = LinkName::of(link);
            if let Some(info) = self.plan.links.get(&name) {
                pos_out.push(PosOut::Angle {
                    stmt: info.stmt,
                    index: info.index,
                });
            }
            let turning = self.plan.turning_link(&name);
            rate_out
                .links
                .push(turning.map(|l| self.solver.slots.link_named(&l)));
        }
        for s in &out.slides {
            pos_out.push(PosOut::Slide {
                stmt: s.stmt,
                k: s.slot,
            });
            let step = self
                .solver
                .slots
                .point_named(&PointName::of(&self.model.stmts[s.stmt].name));
            rate_out.slides.push((StepSlot::of(step), s.slot));
        }
        let forces = forces::ForcePlan::new(self);
        self.solver.compiled = Arc::new(Compiled {
            steps,
            solve,
            rate_walk,
            force_walk,
            pos_out,
            rate_out,
            forces,
        });
    }

    /// The type name of the definition (`Mechanism` for a body alone).
    pub fn name(&self) -> String {
        self.model.name.to_string()
    }

    /// The driver inputs, in the order of the generated input struct.
    pub fn inputs(&self) -> Vec<InputInfo> {
        self.model
            .inputs
            .iter()
            .map(|i| InputInfo {
                name: i.name.to_string(),
                angle: i.angle,
                range: i.range.map(|r| (r.lo, r.hi)),
            })
            .collect()
    }

    /// The deepest analysis the definition asks for (`analysis` statement,
    /// or its default); forces count as acceleration here.
    pub fn level(&self) -> Analysis {
        match self.model.level {
            crate::model::Level::Position => Analysis::Position,
            crate::model::Level::Velocity => Analysis::Velocity,
            _ => Analysis::Acceleration,
        }
    }

    /// The run-time parameters with their current values.
    pub fn params(&self) -> Vec<(String, f64)> {
        self.model
            .params
            .iter()
            .map(|(n, _)| {
                let n = n.to_string();
                let v = self.params[&n];
                (n, v)
            })
            .collect()
    }

    /// Sets parameter `name` (finite). `Err`: the names there are, or why not.
    pub fn set_param(&mut self, name: &str, value: f64) -> Result<(), String> {
        if !value.is_finite() {
            return Err(format!(
                "parameter `{name}`: {value} is not a finite number"
            ));
        }
        match self.params.get_mut(name) {
            Some(v) => {
                *v = value;
                self.compile();
                Ok(())
            }
            None => Err(format!(
                "no parameter `{name}`; the parameters are: {}",
                names(self.params.keys())
            )),
        }
    }

    /// The run-time assembly modes with their current values (`true`:
    /// `left`/`plus`).
    pub fn modes(&self) -> Vec<(String, bool)> {
        self.model
            .modes
            .iter()
            .map(|(n, default)| {
                let current = self.known.modes.get(&n.to_string()).copied();
                (n.to_string(), current.unwrap_or(*default) == Mode::Plus)
            })
            .collect()
    }

    /// Sets the run-time mode `name` to `left` (`plus`, `true`) or `right`
    /// (`minus`, `false`). Every combination was checked when read.
    pub fn set_mode(&mut self, name: &str, left: bool) -> Result<(), String> {
        if !self.model.modes.iter().any(|(n, _)| n == name) {
            return Err(format!(
                "no mode parameter `{name}`; the modes are: {}",
                names(self.model.modes.iter().map(|(n, _)| n))
            ));
        }
        let mode = if left { Mode::Plus } else { Mode::Minus };
        self.known.modes.insert(name.to_string(), mode);
        self.compile();
        Ok(())
    }

    /// The output columns of `analysis`, in the order of the generated
    /// struct's fields: points (`.x`, `.y`), link angles, slides.
    pub fn columns(&self, analysis: Analysis) -> Vec<Column> {
        let u = &self.model.units;
        let (l, a) = match analysis {
            Analysis::Position => (intern(u.length()), "rad"),
            Analysis::Velocity => (intern(&u.per_time(u.length())), intern(&u.per_time("rad"))),
            Analysis::Acceleration => (
                intern(&u.per_time_squared(u.length())),
                intern(&u.per_time_squared("rad")),
            ),
        };
        let out = &self.plan.outputs;
        let mut cols = Vec::new();
        for p in &out.points {
            for c in ["x", "y"] {
                cols.push(Column {
                    name: format!("{p}.{c}"),
                    unit: l,
                });
            }
        }
        for link in &out.links {
            cols.push(Column {
                name: link.to_string(),
                unit: a,
            });
        }
        for s in &out.slides {
            cols.push(Column {
                name: s.name.to_string(),
                unit: l,
            });
        }
        cols
    }
}

/// The first value of `values` that is not finite, if any: one pass
/// without a branch per value (`&` of every `is_finite`, which the
/// compiler vectorizes), then a search only when one is found.
fn first_non_finite(values: &[f64]) -> Option<f64> {
    if values.iter().fold(true, |ok, v| ok & v.is_finite()) {
        return None;
    }
    values.iter().copied().find(|v| !v.is_finite())
}

/// The error of an output that is not finite (none of the primitives let
/// one through; the walk checks again, as no `Ok` may hold a NaN).
fn non_finite(_value: f64) -> Error<f64> {
    Error::new(
        mechanism_core::Primitive::LinkPoint,
        mechanism_core::Fault::NonFinite { what: "an output" },
    )
}

/// `a`, `b` (or "none").
fn names<T: std::fmt::Display>(it: impl IntoIterator<Item = T>) -> String {
    let v: Vec<String> = it.into_iter().map(|n| format!("`{n}`")).collect();
    if v.is_empty() {
        "none".into()
    } else {
        v.join(", ")
    }
}

/// The evaluations, through [`Mechanism::solver`]'s methods (documented
/// there).
impl Mechanism {
    /// The evaluation part of this definition, to share with threads (clone
    /// it) or to call directly.
    pub fn solver(&self) -> &Solver {
        &self.solver
    }

    /// [`Solver::new_position`].
    pub fn new_position(&self) -> Position {
        self.solver.new_position()
    }

    /// [`Solver::new_rates`].
    pub fn new_rates(&self) -> Rates {
        self.solver.new_rates()
    }

    /// [`Solver::position`].
    pub fn position(&self, q: &[f64]) -> Result<Position, Error<f64>> {
        self.solver.position(q)
    }

    /// [`Solver::position_into`].
    pub fn position_into(&self, q: &[f64], pos: &mut Position) -> Result<(), Error<f64>> {
        self.solver.position_into(q, pos)
    }

    /// [`Solver::velocity`].
    pub fn velocity(&self, pos: &Position, rates: &[f64]) -> Result<Rates, Error<f64>> {
        self.solver.velocity(pos, rates)
    }

    /// [`Solver::velocity_into`].
    pub fn velocity_into(
        &self,
        pos: &Position,
        rates: &[f64],
        vel: &mut Rates,
    ) -> Result<(), Error<f64>> {
        self.solver.velocity_into(pos, rates, vel)
    }

    /// [`Solver::acceleration`].
    pub fn acceleration(
        &self,
        pos: &Position,
        vel: &Rates,
        accels: &[f64],
    ) -> Result<Rates, Error<f64>> {
        self.solver.acceleration(pos, vel, accels)
    }

    /// [`Solver::acceleration_into`].
    pub fn acceleration_into(
        &self,
        pos: &Position,
        vel: &Rates,
        accels: &[f64],
        acc: &mut Rates,
    ) -> Result<(), Error<f64>> {
        self.solver.acceleration_into(pos, vel, accels, acc)
    }
}

/// What evaluating a definition takes, apart from the definition itself:
/// its compiled steps with the current parameters, modes and loads, and
/// its slot layout. Cheap to clone (shared pointers) and `Send + Sync`,
/// unlike [`Mechanism`] (which holds the parser's tokens): threads that
/// sweep one definition share one (`Mechanism::solver`). A change of a
/// parameter, mode or load on the `Mechanism` does not reach a clone made
/// before it.
#[derive(Clone)]
pub struct Solver {
    compiled: Arc<Compiled>,
    slots: Arc<run::Layout>,
    /// The number of driver inputs.
    inputs: usize,
    /// Whether the definition has a force analysis.
    forces: bool,
}

impl Solver {
    /// The error of a slice that does not hold one value per input.
    fn arity(&self, q: &[f64]) -> Result<(), Error<f64>> {
        if q.len() == self.inputs {
            Ok(())
        } else {
            Err(Error::new(
                mechanism_core::Primitive::LinkPoint,
                mechanism_core::Fault::NonFinite {
                    what: "input values (one per input needed)",
                },
            ))
        }
    }

    /// Storage for [`Mechanism::position_into`] (every value NaN until
    /// solved).
    pub fn new_position(&self) -> Position {
        Position {
            values: Vec::with_capacity(self.compiled.pos_out.len() + 2),
            pose: RunPose::new(&self.slots, self.inputs),
            slots: Arc::clone(&self.slots),
            solved: false,
        }
    }

    /// Storage for [`Mechanism::velocity_into`] and
    /// [`Mechanism::acceleration_into`].
    pub fn new_rates(&self) -> Rates {
        Rates {
            values: Vec::with_capacity(self.compiled.rate_out.len()),
            condition: f64::NAN,
            motion: Motion::new(&self.slots, self.inputs),
            solved: false,
        }
    }

    /// The position at inputs `q` (in the order of [`Mechanism::inputs`]:
    /// rad for angles, L for lengths); the typed error of the first group
    /// that fails, naming it.
    pub fn position(&self, q: &[f64]) -> Result<Position, Error<f64>> {
        let mut pos = self.new_position();
        self.position_into(q, &mut pos)?;
        Ok(pos)
    }

    /// [`Mechanism::position`] into `pos` (from
    /// [`Mechanism::new_position`]), allocating nothing: each compiled
    /// step in solve order, then the outputs.
    pub fn position_into(&self, q: &[f64], pos: &mut Position) -> Result<(), Error<f64>> {
        pos.solved = false;
        self.arity(q)?;
        self.fits(pos.pose.fits(&self.slots, q.len()))?;
        pos.pose.q[..q.len()].copy_from_slice(q);
        let c = &self.compiled;
        for &i in &c.solve {
            let step = &c.steps[i.0];
            step.position(&mut pos.pose)
                .map_err(|e| e.in_group(step.group()))?;
        }
        let values = &mut pos.values;
        values.clear();
        for out in &c.pos_out {
            match *out {
                PosOut::Point(p) => {
                    let pt = pos.pose.point(p);
                    values.extend([pt.x, pt.y]);
                }
                PosOut::Angle { stmt, index } => {
                    let step = &c.steps[stmt.0];
                    let angle = step
                        .link_angle(&pos.pose)
                        .unwrap_or_else(|| geometry::angle(&step.link_dir(index, &pos.pose)));
                    values.push(angle);
                }
                PosOut::Slide { stmt, k } => {
                    values.push(c.steps[stmt.0].slide(k, &pos.pose).unwrap_or(f64::NAN));
                }
            }
        }
        if let Some(bad) = first_non_finite(values) {
            return Err(non_finite(bad));
        }
        pos.solved = true;
        Ok(())
    }

    /// `Ok` when storage fits this mechanism; the typed error otherwise.
    fn fits(&self, fits: bool) -> Result<(), Error<f64>> {
        if fits {
            Ok(())
        } else {
            Err(Error::new(
                mechanism_core::Primitive::LinkPoint,
                mechanism_core::Fault::NonFinite {
                    what: "a pose or rates of another mechanism, or not solved",
                },
            ))
        }
    }

    /// The velocity at `pos` for the input rates `rates` (rad/s, L/s).
    pub fn velocity(&self, pos: &Position, rates: &[f64]) -> Result<Rates, Error<f64>> {
        let mut vel = self.new_rates();
        self.velocity_into(pos, rates, &mut vel)?;
        Ok(vel)
    }

    /// [`Mechanism::velocity`] into `vel` (from [`Mechanism::new_rates`]),
    /// allocating nothing.
    pub fn velocity_into(
        &self,
        pos: &Position,
        rates: &[f64],
        vel: &mut Rates,
    ) -> Result<(), Error<f64>> {
        vel.solved = false;
        self.arity(rates)?;
        self.rates(pos, None, rates, vel)
    }

    /// The acceleration at `pos`, `vel` for the input accelerations
    /// `accels` (rad/s^2, L/s^2).
    pub fn acceleration(
        &self,
        pos: &Position,
        vel: &Rates,
        accels: &[f64],
    ) -> Result<Rates, Error<f64>> {
        let mut acc = self.new_rates();
        self.acceleration_into(pos, vel, accels, &mut acc)?;
        Ok(acc)
    }

    /// [`Mechanism::acceleration`] into `acc` (from
    /// [`Mechanism::new_rates`]), allocating nothing.
    pub fn acceleration_into(
        &self,
        pos: &Position,
        vel: &Rates,
        accels: &[f64],
        acc: &mut Rates,
    ) -> Result<(), Error<f64>> {
        acc.solved = false;
        self.arity(accels)?;
        self.fits(vel.solved && vel.motion.fits(&self.slots, accels.len()))?;
        self.rates(pos, Some(vel), accels, acc)
    }

    /// One rate level: every solved step's `rates`, in solve order.
    /// `level`: the input rates (velocity) or accelerations.
    fn rates(
        &self,
        pos: &Position,
        vel: Option<&Rates>,
        level: &[f64],
        out: &mut Rates,
    ) -> Result<(), Error<f64>> {
        let n = level.len();
        self.fits(pos.solved && pos.pose.fits(&self.slots, n) && out.motion.fits(&self.slots, n))?;
        out.motion.q[..n].copy_from_slice(level);
        out.motion.conditions.clear();
        let c = &self.compiled;
        let mut cx = RunCx {
            pose: &pos.pose,
            vel: vel.map(|v| &v.motion),
            out: &mut out.motion,
            layout: &self.slots,
        };
        for &i in &c.rate_walk {
            let step = &c.steps[i.0];
            step.rates(&mut cx).map_err(|e| e.in_group(step.group()))?;
        }
        let (values, motion) = (&mut out.values, &out.motion);
        let o = &c.rate_out;
        // Written in place (the length is fixed by the plan): no capacity
        // check per value.
        values.resize(o.len(), 0.0);
        let (xy, rest) = values.split_at_mut(2 * o.points.len());
        let (links, slides) = rest.split_at_mut(o.links.len());
        for (pair, p) in xy.chunks_exact_mut(2).zip(&o.points) {
            let v = p.map_or_else(mechanism_core::Vector2::zeros, |p| motion.point(p));
            pair.copy_from_slice(&[v.x, v.y]);
        }
        for (x, l) in links.iter_mut().zip(&o.links) {
            *x = l.map_or(0.0, |l| motion.link(l));
        }
        for (x, &(s, k)) in slides.iter_mut().zip(&o.slides) {
            *x = motion.slide(s, k);
        }
        if let Some(bad) = first_non_finite(values) {
            return Err(non_finite(bad));
        }
        // As the generated `__condition`: the first group's, then `min`.
        out.condition = match motion.conditions.split_first() {
            Some((&first, rest)) => rest.iter().fold(first, |c, &x| geometry::min(c, x)),
            None => 1.0,
        };
        out.solved = true;
        Ok(())
    }
}
