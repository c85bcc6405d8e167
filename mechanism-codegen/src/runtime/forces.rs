//! The force analysis of the run-time mechanism: the known loads of every
//! link (inertia forces and couples, weights, external forces and couples,
//! as `emit::forces::loads` writes them), then each solved statement's
//! `run::RunKind::run_forces` in the reverse of the solve order, then the
//! motors of an inverse-kinematics definition, the conditioning and the
//! power balance: the generated `forces()` step for step, in `f64`, with
//! the same core calls on the same arguments in the same order.
//!
//! # Units and signs
//!
//! Forces are in the definition's force units (mass x length / time^2:
//! N with kg, m, s), moments and torques in force x length, counter-clockwise
//! positive, in the global frame. A reaction `r_FROM_TO` is the force of
//! body `FROM` (or the ground) on body `TO` at their joint; a driving effort
//! `drive_INPUT` is applied to the driven link by its driver (a torque for
//! a crank, a push along the line for a slider or an actuator, positive
//! when it pushes the actuator's ends apart). A prismatic pair's reaction is
//! a signed normal force along the left normal of its direction and a
//! couple about the joint the generated field's doc names.

use super::{intern, Column, Mechanism, Position, Rates};
use crate::emit::forces::ForceField;
use crate::keys::{GuideName, LinkName, PointName};
use crate::kinds::forces::Held;
use crate::kinds::run::{ForceRunCx, GuideSlot, Layout, LinkSlot, PointSlot, PowerSum, RunningMin};
use crate::model::{ForceSpecValue, MassSpec};
use crate::names::Family;
use crate::value::{Value, ValueKind};
use mechanism_core::force::Wrench;
use mechanism_core::{geometry, Error, Primitive, Vector2};
use std::collections::BTreeMap;
use syn::Ident;

/// The force analysis at one pose: the joint reactions and driving efforts
/// in [`Mechanism::force_columns`] order (its last two: `condition` and
/// `power_residual`).
#[derive(Clone, Debug, PartialEq)]
pub struct Forces {
    /// The values, as `force_columns()`.
    pub values: Vec<f64>,
    /// Conditioning in (0, 1]: the smaller of the velocity's `condition` and
    /// the groups' force indicators (`min_pivot_ratio`; tends to 0 at a
    /// toggle or a dead centre).
    pub condition: f64,
    /// |sum of the powers of drives, loads, weights and inertia| over the
    /// largest of them (0 when all vanish; a few eps when consistent).
    pub power_residual: f64,
    scratch: Scratch,
}

/// What one force evaluation works in, kept between evaluations: each
/// link's load and the velocities at unit rates of an inverse-kinematics
/// definition's motors.
#[derive(Clone, Debug, Default)]
struct Scratch {
    loads: Vec<Option<Wrench<f64>>>,
    unit: Vec<Rates>,
}

impl PartialEq for Scratch {
    /// Scratch space compares equal: only the results count.
    fn eq(&self, _other: &Self) -> bool {
        true
    }
}

/// `v` with every `loads.NAME` replaced by its value.
fn with_loads(v: &Value, loads: &BTreeMap<String, f64>) -> Value {
    let kind = match &v.kind {
        ValueKind::Load(n) => {
            ValueKind::Lit(loads.get(&n.to_string()).copied().unwrap_or(f64::NAN))
        }
        ValueKind::Neg(a) => ValueKind::Neg(Box::new(with_loads(a, loads))),
        ValueKind::Bin(a, op, b) => ValueKind::Bin(
            Box::new(with_loads(a, loads)),
            *op,
            Box::new(with_loads(b, loads)),
        ),
        ValueKind::Call(f, args) => {
            ValueKind::Call(*f, args.iter().map(|a| with_loads(a, loads)).collect())
        }
        other => other.clone(),
    };
    Value {
        kind,
        span: v.span,
        tokens: v.tokens.clone(),
    }
}

/// The core's tag named `name` (`GroupKind::primitive`).
fn primitive_named(name: &str) -> Primitive {
    [
        Primitive::Crank,
        Primitive::Slider,
        Primitive::Actuator,
        Primitive::Target,
        Primitive::Rrr,
        Primitive::Rrp,
        Primitive::Rpr,
        Primitive::Prp,
        Primitive::Rpp,
        Primitive::Triad,
    ]
    .into_iter()
    .find(|p| format!("{p:?}") == name)
    .unwrap_or(Primitive::LinkPoint)
}

/// One part of a link's mass, compiled: its centre (and whether it
/// moves), its mass and, for a link's only part, its moment of inertia
/// when the link turns (checked when compiled: [`ForcePlan::error`]).
#[derive(Clone, Copy, Debug)]
struct MassPart {
    at: PointSlot,
    moving: bool,
    mass: f64,
    j: Option<f64>,
}

/// A link's masses, compiled: the link, the slot of the link whose rates
/// its inertia couple reads (`None`: it never turns), its parts and, for
/// several parts, their moments of inertia summed (`None`: none has one,
/// or the link does not turn).
#[derive(Clone, Debug)]
struct LinkMasses {
    link: LinkSlot,
    turning: Option<LinkSlot>,
    parts: Vec<MassPart>,
    inertia: Option<f64>,
}

/// An external force's value: components (force units), or a magnitude
/// along a guide's direction.
#[derive(Clone, Copy, Debug)]
enum ForceVal {
    Components(Vector2<f64>),
    Along(GuideSlot, f64),
}

/// An external force, compiled: the link it acts on, its point, its value.
#[derive(Clone, Copy, Debug)]
struct ExtForce {
    link: LinkSlot,
    at: PointSlot,
    value: ForceVal,
}

/// The motors of an inverse-kinematics definition, compiled: the target's
/// group name, the unit rates of its two inputs, each motor's link and
/// carrier (the links whose rates they share), the places of the target's
/// two driving forces among the values.
#[derive(Clone, Debug)]
struct Motors {
    group: &'static str,
    unit: [Vec<f64>; 2],
    links: Vec<(Option<LinkSlot>, Option<LinkSlot>)>,
    drive: [Option<usize>; 2],
}

/// The force analysis compiled with the current loads and parameters: the
/// known loads in the order `emit::forces::loads` writes them (masses by
/// link, then forces, then couples), and the motors.
#[derive(Clone, Debug, Default)]
pub(super) struct ForcePlan {
    /// The error the generated code's checks of the masses and moments of
    /// inertia give first, in the order it makes them (a value known once
    /// the parameters are: each evaluation returns it before any load).
    error: Option<Error<f64>>,
    gravity: Option<Vector2<f64>>,
    masses: Vec<LinkMasses>,
    forces: Vec<ExtForce>,
    torques: Vec<(LinkSlot, f64)>,
    motors: Option<Motors>,
}

impl ForcePlan {
    /// The plan of `m`'s force analysis (empty without one).
    pub(super) fn new(m: &Mechanism) -> Self {
        if !m.has_forces() {
            return ForcePlan::default();
        }
        let k = &m.model.kinetics;
        let slots: &Layout = &m.solver.slots;
        let gravity = k
            .gravity
            .as_ref()
            .map(|(_, gx, gy)| Vector2::new(m.value(gx), m.value(gy)));
        let mut error = None;
        let masses = crate::emit::forces::masses_by_link(&k.masses)
            .into_iter()
            .map(|(link, parts)| m.link_masses(&link, &parts, &mut error))
            .collect();
        let forces = k
            .forces
            .iter()
            .filter_map(|f| {
                let link = match &f.on {
                    Some(l) => LinkName::of(l),
                    None => m
                        .plan
                        .links_with_point(&PointName::of(&f.at))
                        .first()?
                        .clone(),
                };
                let value = match &f.value {
                    ForceSpecValue::Components(x, y) => {
                        ForceVal::Components(Vector2::new(m.value(x), m.value(y)))
                    }
                    ForceSpecValue::Along(guide, v) => {
                        ForceVal::Along(slots.guide_named(&GuideName::of(guide)), m.value(v))
                    }
                };
                Some(ExtForce {
                    link: slots.link_named(&link),
                    at: slots.point_named(&PointName::of(&f.at)),
                    value,
                })
            })
            .collect();
        let torques = k
            .torques
            .iter()
            .map(|t| (slots.link_named(&LinkName::of(&t.on)), m.value(&t.value)))
            .collect();
        ForcePlan {
            error,
            gravity,
            masses,
            forces,
            torques,
            motors: m.motor_plan(),
        }
    }

    /// The known loads onto the links' loads, their powers in order.
    fn known_loads(&self, cx: &mut ForceRunCx<'_>) -> Result<(), Error<f64>> {
        if let Some(e) = self.error {
            return Err(e);
        }
        for lm in &self.masses {
            masses(cx, lm, self.gravity);
        }
        for f in &self.forces {
            let value = match f.value {
                ForceVal::Components(v) => v,
                ForceVal::Along(guide, v) => cx.pose.line(guide).dir * v,
            };
            if let Some(v) = cx.velocity_of(f.at) {
                cx.power.push(geometry::dot(&value, &v));
            }
            cx.force_on(f.link, value, f.at);
        }
        for &(on, value) in &self.torques {
            if let Some((w, _)) = cx.rates_of(on) {
                cx.power.push(value * w);
            }
            cx.add(on, Wrench::couple(value));
        }
        Ok(())
    }
}

/// The masses of one link (`loads::mass`, `loads::mass_parts`): each
/// part's inertia force and weight at its centre; the inertia couple (the
/// parts' `j` summed) when the link turns. Powers and loads in the
/// generated order (the checks are [`ForcePlan::error`]).
fn masses(cx: &mut ForceRunCx<'_>, lm: &LinkMasses, gravity: Option<Vector2<f64>>) {
    let turning = lm.turning.map(|l| cx.link_rates(l));
    for part in &lm.parts {
        let mass = part.mass;
        let v_g = part.moving.then(|| cx.vel.point(part.at));
        let mut terms = [Vector2::zeros(); 2];
        let mut n = 0;
        if v_g.is_some() {
            terms[n] = cx.acceleration_of(part.at) * (-mass);
            n += 1;
        }
        if let Some(g) = gravity {
            terms[n] = g * mass;
            n += 1;
        }
        // A link's only mass: its couple comes before its forces.
        let mut couple = None;
        if let (Some(j), Some((w, alpha))) = (part.j, turning) {
            let c = -(j * alpha);
            cx.power.push(c * w);
            couple = Some(c);
        }
        if let Some(v) = v_g {
            for t in &terms[..n] {
                cx.power.push(geometry::dot(t, &v));
            }
        }
        if let Some((first, rest)) = terms[..n].split_first() {
            let total = rest.iter().fold(*first, |acc, t| acc + t);
            cx.force_on(lm.link, total, part.at);
        }
        if let Some(c) = couple {
            cx.add(lm.link, Wrench::couple(c));
        }
    }
    let (Some((w, alpha)), Some(j)) = (turning, lm.inertia) else {
        return;
    };
    let c = -(j * alpha);
    cx.power.push(c * w);
    cx.add(lm.link, Wrench::couple(c));
}

impl Mechanism {
    /// `true` when the definition has a force analysis (masses, loads or
    /// `analysis forces;`/`dynamics;`).
    pub fn has_forces(&self) -> bool {
        self.solver.forces
    }

    /// The `loads { .. }` values with their current values.
    pub fn loads(&self) -> Vec<(String, f64)> {
        self.model
            .kinetics
            .loads
            .iter()
            .map(|(n, _)| {
                let n = n.to_string();
                let v = self.loads.get(&n).copied().unwrap_or(f64::NAN);
                (n, v)
            })
            .collect()
    }

    /// Sets load value `name` (a finite number, in the units the definition
    /// uses it in). `Err`: the names there are, or why not.
    pub fn set_load(&mut self, name: &str, value: f64) -> Result<(), String> {
        if !value.is_finite() {
            return Err(format!("load `{name}`: {value} is not a finite number"));
        }
        match self.loads.get_mut(name) {
            Some(v) => {
                *v = value;
                let forces = ForcePlan::new(self);
                match std::sync::Arc::get_mut(&mut self.solver.compiled) {
                    Some(c) => c.forces = forces,
                    // A clone of the solver is in use elsewhere: a fresh
                    // compiled plan for this definition, the clone keeps its own.
                    None => self.compile(),
                }
                Ok(())
            }
            None => Err(format!(
                "no load `{name}`; the loads are: {}",
                super::names(self.loads.keys())
            )),
        }
    }

    /// The columns of [`Mechanism::forces`], in the order of the generated
    /// forces struct, named as its `mechanism::structure::Fields` reads them:
    /// each revolute reaction `r_FROM_TO` as `.x`, `.y` (force), each
    /// prismatic one as `.force.x`, `.force.y` (its normal force as a
    /// vector) and `.moment` (its couple, force x length), each driving torque (force x
    /// length) or push (force) by its name, then `condition` and
    /// `power_residual` (unit `1`). Units: the definition's `units { force,
    /// length }` names, else `F` and `L`. Empty without a force analysis.
    pub fn force_columns(&self) -> Vec<Column> {
        if !self.has_forces() {
            return Vec::new();
        }
        let units = &self.model.units;
        let (f, m) = (intern(&units.force), intern(&units.moment()));
        let moving = self.plan.moving_points(&self.model);
        // Only the fields are used: the code's reads go nowhere.
        let reads = crate::kinds::reads::Reads::default();
        let code = crate::emit::forces::emit(&self.model, &self.plan, &moving, &reads);
        let mut cols = Vec::new();
        let mut push = |name: String, unit| cols.push(Column { name, unit });
        for (n, held) in &code.fields {
            match held {
                ForceField::Force => {
                    push(format!("{n}.x"), f);
                    push(format!("{n}.y"), f);
                }
                ForceField::Prismatic => {
                    push(format!("{n}.force.x"), f);
                    push(format!("{n}.force.y"), f);
                    push(format!("{n}.moment"), m);
                }
                ForceField::Torque => push(n.to_string(), m),
                ForceField::Push => push(n.to_string(), f),
            }
        }
        push("condition".into(), "1");
        push("power_residual".into(), "1");
        cols
    }

    /// A load value (`Value`) with the current parameters and loads.
    fn value(&self, v: &Value) -> f64 {
        if let Some(x) = v.fold() {
            return x;
        }
        with_loads(v, &self.loads)
            .eval_with(&|n| self.params.get(&n.to_string()).copied())
            .unwrap_or(f64::NAN)
    }

    /// A mass (`positive`) or moment of inertia (`non_negative`) of `link`
    /// as the generated code checks one that is not literal, the error
    /// named by the group that creates the link; `part`: ` (part k)` or
    /// empty.
    fn checked(
        &self,
        v: &Value,
        link: &LinkName,
        part: &str,
        mass: bool,
    ) -> Result<f64, Error<f64>> {
        let x = self.value(v);
        if v.fold().is_some() {
            return Ok(x);
        }
        let Some(stmt) = self
            .model
            .stmts
            .iter()
            .find(|s| s.links.iter().any(|l| *link == *l))
        else {
            return Ok(x);
        };
        let primitive = primitive_named(crate::kinds::of(stmt).primitive());
        let group = intern(&stmt.name.to_string());
        if mass {
            let what = intern(&format!("mass of `{link}`{part}"));
            geometry::positive(x, primitive, what).map_err(|e| e.in_group(group))
        } else {
            let what = intern(&format!("moment of inertia of `{link}`{part}"));
            geometry::non_negative(x, primitive, what).map_err(|e| e.in_group(group))
        }
    }

    /// The masses of `link`, compiled: each part's checked mass and (for
    /// a link's only part, when the link turns) moment of inertia, and the
    /// parts' moments of inertia summed as the generated code sums them
    /// (folded when every one is literal, else each checked). The first
    /// failed check, in the order the generated code makes them, into
    /// `error` unless it holds one.
    fn link_masses(
        &self,
        link: &LinkName,
        parts: &[&MassSpec],
        error: &mut Option<Error<f64>>,
    ) -> LinkMasses {
        let mut first = |r: Result<f64, Error<f64>>| {
            r.unwrap_or_else(|e| {
                error.get_or_insert(e);
                f64::NAN
            })
        };
        let turning_name = parts
            .first()
            .map_or_else(|| LinkName::new(""), |p| LinkName::of(&p.link));
        let turning =
            self.solver.slots.turning[self.solver.slots.link_named(&turning_name).index()];
        let one = parts.len() == 1;
        let mut out = Vec::new();
        let mut inertias = Vec::new();
        for (k, m) in parts.iter().enumerate() {
            let part = if one {
                String::new()
            } else {
                format!(" (part {})", k + 1)
            };
            let j = m.inertia.as_ref().filter(|j| j.fold() != Some(0.0));
            let at = self.solver.slots.point_named(&PointName::of(&m.at));
            let mass = first(self.checked(&m.mass, link, &part, true));
            let j_one = j
                .filter(|_| one && turning.is_some())
                .map(|j| first(self.checked(j, link, "", false)));
            out.push(MassPart {
                at,
                moving: self.solver.slots.moving[at.index()],
                mass,
                j: j_one,
            });
            if let (false, Some(j)) = (one, j) {
                inertias.push((part, j));
            }
        }
        let inertia = (turning.is_some() && !inertias.is_empty()).then(|| {
            let folded: Option<f64> = inertias.iter().map(|(_, j)| j.fold()).sum();
            match folded {
                Some(sum) => sum,
                None => {
                    let mut total: Option<f64> = None;
                    for (part, j) in &inertias {
                        let x = first(self.checked(j, link, part, false));
                        total = Some(total.map_or(x, |t| t + x));
                    }
                    total.unwrap_or(f64::NAN)
                }
            }
        });
        LinkMasses {
            link: self.solver.slots.link_named(link),
            turning,
            parts: out,
            inertia,
        }
    }

    /// The motors of an inverse-kinematics definition, compiled (`None`:
    /// not one, or no motors).
    fn motor_plan(&self) -> Option<Motors> {
        let model = &self.model;
        let (target, x, y) = crate::kinds::motors::held_target(model)?;
        if crate::kinds::motors::reactions(model).is_empty() {
            return None;
        }
        let unit = |axis: &Ident| -> Vec<f64> {
            model
                .inputs
                .iter()
                .map(|i| if i.name == *axis { 1.0 } else { 0.0 })
                .collect()
        };
        let turning = |link: &Ident| {
            self.plan
                .turning_link(&LinkName::of(link))
                .map(|l| self.solver.slots.link_named(&l))
        };
        let links = model
            .kinetics
            .motors
            .iter()
            .take(2)
            .map(|m| (turning(&m.link), m.carrier.as_ref().and_then(turning)))
            .collect();
        let cols = self.force_columns();
        let drive = |input: &Ident| {
            let name = Family::Drive.text(input);
            cols.iter().position(|c| c.name == name)
        };
        Some(Motors {
            group: intern(&target.name.to_string()),
            unit: [unit(x), unit(y)],
            links,
            drive: [drive(x), drive(y)],
        })
    }
}
impl super::Solver {
    /// The motors' torques of an inverse-kinematics definition
    /// (`ForceEmitter::motors`): the rate map from two velocity
    /// evaluations at unit rates of the target's inputs (into `unit`),
    /// then `force::target::motor_torques` on the target's driving force.
    fn motors(
        &self,
        pos: &Position,
        cx: &mut ForceRunCx<'_>,
        unit: &mut [Rates],
    ) -> Result<(), Error<f64>> {
        let Some(m) = &self.compiled.forces.motors else {
            return Ok(());
        };
        let [ux, uy] = unit else {
            return Ok(());
        };
        self.velocity_into(pos, &m.unit[0], ux)?;
        self.velocity_into(pos, &m.unit[1], uy)?;
        let motor_rates = |vel: &Rates| -> [f64; 2] {
            let mut out = [0.0; 2];
            for (o, (link, carrier)) in out.iter_mut().zip(&m.links) {
                let own = link.map_or(0.0, |l| vel.motion.link(l));
                *o = match carrier {
                    Some(c) => own - vel.motion.link(*c),
                    None => own,
                };
            }
            out
        };
        let (k_x, k_y) = (motor_rates(ux), motor_rates(uy));
        let drive_of = |at: Option<usize>| at.and_then(|k| cx.values.get(k).copied());
        let drive = Vector2::new(
            drive_of(m.drive[0]).unwrap_or(f64::NAN),
            drive_of(m.drive[1]).unwrap_or(f64::NAN),
        );
        let rx = mechanism_core::force::target::motor_torques(k_x, k_y, &drive)
            .map_err(|e| e.in_group(m.group))?;
        cx.conditions.push(rx.min_pivot_ratio);
        for t in rx.torque.iter().take(m.links.len()) {
            cx.values.push(*t);
        }
        Ok(())
    }

    /// Storage for [`Mechanism::forces_into`].
    pub fn new_forces(&self) -> Forces {
        let unit = match &self.compiled.forces.motors {
            Some(_) => vec![self.new_rates(), self.new_rates()],
            None => Vec::new(),
        };
        Forces {
            values: Vec::new(),
            condition: f64::NAN,
            power_residual: f64::NAN,
            scratch: Scratch {
                loads: vec![None; self.slots.link_names.len() + 1],
                unit,
            },
        }
    }

    /// The force analysis at a solved pose `pos`, its velocity `vel` and
    /// acceleration `acc` (from [`Mechanism::velocity`] and
    /// [`Mechanism::acceleration`]), with the current load values
    /// ([`Mechanism::set_load`]) and parameters. The values in
    /// [`Mechanism::force_columns`] order; signs and units in the module
    /// documentation. Errors as the generated `forces()`: the group whose
    /// force system is singular or whose loads are not finite, a mass not
    /// positive or a moment of inertia negative (named by the group that
    /// creates its link). A definition without a force analysis: an error
    /// (`NonFinite`, "force analysis (the definition has no masses or
    /// loads)").
    pub fn forces(&self, pos: &Position, vel: &Rates, acc: &Rates) -> Result<Forces, Error<f64>> {
        let mut out = self.new_forces();
        self.forces_into(pos, vel, acc, &mut out)?;
        Ok(out)
    }

    /// [`Mechanism::forces`] into `out` (from [`Mechanism::new_forces`]),
    /// allocating nothing once its buffers have grown to their size: the
    /// known loads, each solved step's `forces` in the reverse of the solve
    /// order, then the motors.
    pub fn forces_into(
        &self,
        pos: &Position,
        vel: &Rates,
        acc: &Rates,
        out: &mut Forces,
    ) -> Result<(), Error<f64>> {
        self.force_walk(pos, vel, acc, out, None)
    }

    /// The walk of [`Mechanism::forces_into`]; with `names`, each field's
    /// name and kind as the walk writes it.
    fn force_walk(
        &self,
        pos: &Position,
        vel: &Rates,
        acc: &Rates,
        out: &mut Forces,
        names: Option<&mut Vec<(String, Held)>>,
    ) -> Result<(), Error<f64>> {
        if !self.forces {
            return Err(Error::new(
                Primitive::LinkPoint,
                mechanism_core::Fault::NonFinite {
                    what: "force analysis (the definition has no masses or loads)",
                },
            ));
        }
        let n = self.inputs;
        let Scratch { loads, unit } = &mut out.scratch;
        self.fits(
            pos.solved
                && vel.solved
                && acc.solved
                && pos.pose.fits(&self.slots, n)
                && vel.motion.fits(&self.slots, n)
                && acc.motion.fits(&self.slots, n)
                && loads.len() == self.slots.link_names.len() + 1
                && unit.len()
                    == if self.compiled.forces.motors.is_some() {
                        2
                    } else {
                        0
                    },
        )?;
        loads.fill(None);
        out.values.clear();
        let (mut power, mut conditions) = (PowerSum::default(), RunningMin(vel.condition));
        let mut cx = ForceRunCx {
            pose: &pos.pose,
            vel: &vel.motion,
            acc: &acc.motion,
            layout: &self.slots,
            loads,
            values: &mut out.values,
            power: &mut power,
            conditions: &mut conditions,
            names,
        };
        let c = &self.compiled;
        c.forces.known_loads(&mut cx)?;
        for &i in c.force_walk.iter().rev() {
            let step = &c.steps[i.0];
            step.forces(&mut cx).map_err(|e| e.in_group(step.group()))?;
        }
        self.motors(pos, &mut cx, unit)?;
        let (condition, power_residual) = (conditions.0, power.residual());
        out.values.extend([condition, power_residual]);
        if let Some(bad) = super::first_non_finite(&out.values) {
            return Err(super::non_finite(bad));
        }
        out.condition = condition;
        out.power_residual = power_residual;
        Ok(())
    }
}

/// The force analysis through [`Mechanism::solver`] (documented there).
impl Mechanism {
    /// [`super::Solver::new_forces`].
    pub fn new_forces(&self) -> Forces {
        self.solver.new_forces()
    }

    /// [`super::Solver::forces`].
    pub fn forces(&self, pos: &Position, vel: &Rates, acc: &Rates) -> Result<Forces, Error<f64>> {
        self.solver.forces(pos, vel, acc)
    }

    /// [`super::Solver::forces_into`].
    pub fn forces_into(
        &self,
        pos: &Position,
        vel: &Rates,
        acc: &Rates,
        out: &mut Forces,
    ) -> Result<(), Error<f64>> {
        self.solver.forces_into(pos, vel, acc, out)
    }
}

#[cfg(test)]
mod tests {
    use super::{Held, Mechanism, PowerSum};

    /// A block slid along a ground line drives a rocker through a rod,
    /// with masses, gravity and a couple: a push, a prismatic reaction,
    /// revolute ones.
    const PRESS: &str = "let O = ground(0.0, 0.0);
        let O4 = ground(0.5, 0.4);
        let line = guide(O, 0 deg);
        let P = slider(line, s) as block;
        let B = rrr(P, 0.5, O4, 0.3, left) as (rod, rocker);
        let G = point(rod, from P, 0.25, 0 deg);
        mass block { m = 2.0, at = P };
        mass rod { m = 1.0, at = G, j = 0.02 };
        mass rocker { m = 0.5, at = B, j = 0.01 };
        gravity (0.0, -9.81);
        torque on rocker = 3.0;
        range s = (0.0, 0.6);";

    // Proves the run-time force walk writes its fields under the names and
    // with the kinds of the generated forces struct, in its order: the
    // names the walk gives (`r_FROM_TO`, `drive_INPUT`) are the columns
    // `force_columns` reads from the emitter, one value per column.
    #[test]
    fn the_walk_names_its_fields_as_the_generated_struct() {
        let m = Mechanism::new(PRESS).unwrap();
        let p = m.position(&[0.3]).unwrap();
        assert!(m.has_forces());
        let v = m.velocity(&p, &[2.0]).unwrap();
        let a = m.acceleration(&p, &v, &[0.5]).unwrap();
        let mut out = m.new_forces();
        let mut names = Vec::new();
        m.solver
            .force_walk(&p, &v, &a, &mut out, Some(&mut names))
            .unwrap();
        let mut cols = Vec::new();
        for (n, held) in &names {
            match held {
                Held::Force => cols.extend([format!("{n}.x"), format!("{n}.y")]),
                Held::Prismatic => cols.extend([
                    format!("{n}.force.x"),
                    format!("{n}.force.y"),
                    format!("{n}.moment"),
                ]),
                Held::Torque | Held::Push => cols.push(n.clone()),
            }
        }
        cols.extend(["condition".into(), "power_residual".into()]);
        let want: Vec<String> = m.force_columns().into_iter().map(|c| c.name).collect();
        assert_eq!(cols, want);
        assert_eq!(out.values.len(), want.len());
    }

    // Proves the power residual's edge cases match the generated code's: no
    // term gives 0, all-zero terms 0, an overflowing sum 1, else |sum|/max.
    #[test]
    fn power_residual_as_generated() {
        let residual = |terms: &[f64]| {
            let mut p = PowerSum::default();
            terms.iter().for_each(|&t| p.push(t));
            p.residual()
        };
        assert_eq!(residual(&[]), 0.0);
        assert_eq!(residual(&[0.0, 0.0]), 0.0);
        assert_eq!(residual(&[f64::MAX, f64::MAX]), 1.0);
        assert_eq!(residual(&[2.0, -1.5]), 0.25);
        assert_eq!(residual(&[3.0, f64::NAN]), 1.0);
    }
}
