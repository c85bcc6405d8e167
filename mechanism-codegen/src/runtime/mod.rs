//! The run-time mechanism: a definition read from text at run time, through
//! the macro's own stages (parse, model, validate, plan, check: the same
//! rules and messages, every error at once), evaluated in `f64` by walking
//! the plan: each statement's position is its kind's `GroupKind::eval` (the
//! expansion-time evaluator's step), its rates its kind's
//! `run::RunKind::run_rates`; both call the `mechanism-core` primitive the
//! generated code calls, with the same arguments, in the same order. It is
//! the third walker of the plan, beside the emitter and the check; no
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
use crate::kinds::{self, run::Motion, run::RunCx, Pose};
use crate::model::{Mode, Model};
use crate::plan::Plan;
pub use forces::Forces;
use mechanism_core::{geometry, Error, Vector2};
use std::collections::{BTreeMap, BTreeSet};
use std::sync::{Mutex, PoisonError};
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
/// and the state the rates read.
pub struct Position {
    /// The output values, as `columns(Analysis::Position)`.
    pub values: Vec<f64>,
    inputs: Vec<f64>,
    pose: Pose,
}

/// The velocity or acceleration at one input.
pub struct Rates {
    /// The output values, as `columns` of its analysis.
    pub values: Vec<f64>,
    /// The smallest scaled determinant of the groups' velocity systems, in
    /// (0, 1] (the generated struct's `condition`); 1 in an acceleration.
    pub condition: f64,
    rates: Vec<f64>,
    motion: Motion,
}

/// A mechanism read from text at run time.
pub struct Mechanism {
    model: Model,
    plan: Plan,
    moving: BTreeSet<String>,
    params: BTreeMap<String, f64>,
    /// What the check found (the triads' tracked assemblies) and the
    /// modes set at run time ([`Mechanism::set_mode`]), which the position
    /// reads in place of the defaults.
    known: kinds::Known,
    /// The `loads { .. }` values ([`Mechanism::set_load`]).
    loads: BTreeMap<String, f64>,
}

/// The name `s` with a `'static` lifetime (errors name their group so);
/// each distinct name is kept once for the life of the program.
fn intern(s: &str) -> &'static str {
    static NAMES: Mutex<BTreeSet<&'static str>> = Mutex::new(BTreeSet::new());
    let mut names = NAMES.lock().unwrap_or_else(PoisonError::into_inner);
    if let Some(n) = names.get(s) {
        return n;
    }
    let n: &'static str = Box::leak(s.to_owned().into_boxed_str());
    names.insert(n);
    n
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
        let moving = crate::emit::moving_points(&model, &plan);
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
        Ok(Mechanism {
            model,
            plan,
            moving,
            params,
            known: findings.known,
            loads,
        })
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

    /// The input struct's value of each input, by name.
    fn input_index(&self, n: &syn::Ident) -> Option<usize> {
        self.model.inputs.iter().position(|i| i.name == *n)
    }

    /// Checks that `q` has one value per input.
    fn arity(&self, q: &[f64]) -> Result<(), Error<f64>> {
        if q.len() == self.model.inputs.len() {
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

    /// The position at inputs `q` (in the order of [`Mechanism::inputs`]:
    /// rad for angles, L for lengths); the typed error of the first group
    /// that fails, naming it.
    pub fn position(&self, q: &[f64]) -> Result<Position, Error<f64>> {
        self.arity(q)?;
        let mut pose = Pose::keeping();
        let input = |n: &syn::Ident| self.input_index(n).map_or(f64::NAN, |k| q[k]);
        kinds::pose::with_params(&self.params, || {
            for &i in &self.plan.solve {
                kinds::of_known(&self.model.stmts, i, &self.known)
                    .eval(&mut pose, &input)
                    .map_err(|e| e.in_group(intern(&self.model.stmts[i].name.to_string())))?;
            }
            Ok::<(), Error<f64>>(())
        })?;
        let out = &self.plan.outputs;
        let mut values = Vec::new();
        for p in &out.points {
            let pt = pose.point(p);
            values.extend([pt.x, pt.y]);
        }
        for link in &out.links {
            let info = &self.plan.links[&link.to_string()];
            let kind = kinds::of(&self.model.stmts[info.stmt]);
            let angle = kind
                .run_link_angle(&input)
                .unwrap_or_else(|| geometry::angle(&kind.run_link_dir(info.index, &pose)));
            values.push(angle);
        }
        for s in &out.slides {
            let kind = kinds::of(&self.model.stmts[s.stmt]);
            values.push(kind.run_slide(s.slot, &pose).unwrap_or(f64::NAN));
        }
        if let Some(bad) = values.iter().find(|v| !v.is_finite()) {
            return Err(non_finite(*bad));
        }
        Ok(Position {
            values,
            inputs: q.to_vec(),
            pose,
        })
    }

    /// The velocity at `pos` for the input rates `rates` (rad/s, L/s).
    pub fn velocity(&self, pos: &Position, rates: &[f64]) -> Result<Rates, Error<f64>> {
        self.arity(rates)?;
        self.rates(pos, None, rates, &[])
    }

    /// The acceleration at `pos`, `vel` for the input accelerations
    /// `accels` (rad/s^2, L/s^2).
    pub fn acceleration(
        &self,
        pos: &Position,
        vel: &Rates,
        accels: &[f64],
    ) -> Result<Rates, Error<f64>> {
        self.arity(accels)?;
        self.rates(pos, Some(vel), &vel.rates, accels)
    }

    /// One rate level: every solved statement's `run_rates`, in solve order.
    fn rates(
        &self,
        pos: &Position,
        vel: Option<&Rates>,
        rates: &[f64],
        accels: &[f64],
    ) -> Result<Rates, Error<f64>> {
        let mut motion = Motion::default();
        let turning = |l: &str| self.plan.turning_link(l);
        let carried = |g: &str| self.plan.guides.get(g).is_some_and(|i| i.carrier.is_some());
        let inputs = |n: &syn::Ident| {
            self.input_index(n).map_or([f64::NAN; 3], |k| {
                [
                    pos.inputs[k],
                    rates[k],
                    accels.get(k).copied().unwrap_or(f64::NAN),
                ]
            })
        };
        kinds::pose::with_params(&self.params, || {
            let mut cx = RunCx {
                pose: &pos.pose,
                vel: vel.map(|v| &v.motion),
                out: &mut motion,
                moving: &self.moving,
                turning: &turning,
                carried: &carried,
                inputs: &inputs,
            };
            for &i in &self.plan.solve {
                kinds::of(&self.model.stmts[i])
                    .run_rates(&mut cx)
                    .map_err(|e| e.in_group(intern(&self.model.stmts[i].name.to_string())))?;
            }
            Ok::<(), Error<f64>>(())
        })?;
        let values = self.rate_values(&motion);
        if let Some(bad) = values.iter().find(|v| !v.is_finite()) {
            return Err(non_finite(*bad));
        }
        // As the generated `__condition`: the first group's, then `min`.
        let condition = match motion.conditions.split_first() {
            Some((&first, rest)) => rest.iter().fold(first, |c, &x| geometry::min(c, x)),
            None => 1.0,
        };
        Ok(Rates {
            values,
            condition,
            rates: rates.to_vec(),
            motion,
        })
    }

    /// The rate outputs of one level, in column order.
    fn rate_values(&self, motion: &Motion) -> Vec<f64> {
        let out = &self.plan.outputs;
        let mut values = Vec::new();
        for p in &out.points {
            let v = if self.moving.contains(&p.to_string()) {
                motion
                    .points
                    .get(&p.to_string())
                    .copied()
                    .unwrap_or(Vector2::new(f64::NAN, f64::NAN))
            } else {
                Vector2::zeros()
            };
            values.extend([v.x, v.y]);
        }
        for link in &out.links {
            let w = match self.plan.turning_link(&link.to_string()) {
                Some(l) => motion.links.get(&l).copied().unwrap_or(f64::NAN),
                None => 0.0,
            };
            values.push(w);
        }
        for s in &out.slides {
            let name = self.model.stmts[s.stmt].name.to_string();
            values.push(motion.slides.get(&(name, s.slot)).copied().unwrap_or(0.0));
        }
        values
    }
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
