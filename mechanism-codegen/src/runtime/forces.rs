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
use crate::kinds::{
    self,
    forces::Held,
    run::{ForceRunCx, ForceValue, RunReaction},
};
use crate::model::{ForceSpecValue, Level, MassSpec};
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
    /// Conditioning in (0, 1]: the velocity's `condition` and the groups'
    /// force systems' smallest relative pivot (tends to 0 at a toggle or a
    /// dead centre).
    pub condition: f64,
    /// |sum of the powers of drives, loads, weights and inertia| over the
    /// largest of them (0 when all vanish; a few eps when consistent).
    pub power_residual: f64,
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

/// Field names unique as the emitter makes them: a repeated name gets
/// `_2`, `_3`, ...
fn unique_names(reactions: &mut [RunReaction]) {
    let mut seen = std::collections::BTreeSet::new();
    for r in reactions {
        let mut candidate = r.name.clone();
        let mut k = 2;
        while !seen.insert(candidate.clone()) {
            candidate = format!("{}_{k}", r.name);
            k += 1;
        }
        r.name = candidate;
    }
}

/// The power residual of the terms, as the generated code computes it.
fn power_residual(terms: &[f64]) -> f64 {
    let Some((&first, rest)) = terms.split_first() else {
        return 0.0;
    };
    let scale = terms
        .iter()
        .map(|t| geometry::abs(*t))
        .fold(0.0, |m: f64, a| if a > m { a } else { m });
    let sum = rest.iter().fold(first, |acc, t| acc + t);
    if !(scale.is_finite() && sum.is_finite()) {
        1.0
    } else if scale > 0.0 {
        geometry::abs(sum) / scale
    } else {
        0.0
    }
}

impl Mechanism {
    /// `true` when the definition has a force analysis (masses, loads or
    /// `analysis forces;`/`dynamics;`).
    pub fn has_forces(&self) -> bool {
        self.model.level >= Level::Forces
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
        let code = crate::emit::forces::emit(&self.model, &self.plan, &self.moving);
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
        if !self.has_forces() {
            return Err(Error::new(
                Primitive::LinkPoint,
                mechanism_core::Fault::NonFinite {
                    what: "force analysis (the definition has no masses or loads)",
                },
            ));
        }
        let rate = |n: &Ident| {
            self.input_index(n)
                .map_or(f64::NAN, |k| vel.rates.get(k).copied().unwrap_or(f64::NAN))
        };
        let mut cx = ForceRunCx {
            pose: &pos.pose,
            vel: &vel.motion,
            acc: &acc.motion,
            plan: &self.plan,
            moving: &self.moving,
            rate: &rate,
            loads: BTreeMap::new(),
            reactions: Vec::new(),
            power: Vec::new(),
            conditions: Vec::new(),
        };
        self.known_loads(&mut cx)?;
        kinds::pose::with_params(&self.params, || {
            for &i in self.plan.solve.iter().rev() {
                let stmt = &self.model.stmts[i];
                kinds::of(stmt)
                    .run_forces(&mut cx)
                    .map_err(|e| e.in_group(intern(&stmt.name.to_string())))?;
            }
            Ok::<(), Error<f64>>(())
        })?;
        self.motors(pos, &mut cx)?;
        let mut reactions = std::mem::take(&mut cx.reactions);
        unique_names(&mut reactions);
        let condition = cx
            .conditions
            .iter()
            .fold(vel.condition, |c, &x| geometry::min(c, x));
        let power_residual = power_residual(&cx.power);
        let mut values = Vec::new();
        for r in &reactions {
            match r.value {
                ForceValue::Force(v) => values.extend([v.x, v.y]),
                ForceValue::Prismatic(p) => values.extend([p.force.x, p.force.y, p.moment]),
                ForceValue::Scalar(x) => values.push(x),
            }
        }
        values.extend([condition, power_residual]);
        if let Some(bad) = values.iter().find(|v| !v.is_finite()) {
            return Err(super::non_finite(*bad));
        }
        Ok(Forces {
            values,
            condition,
            power_residual,
        })
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
    fn checked(&self, v: &Value, link: &str, part: &str, mass: bool) -> Result<f64, Error<f64>> {
        let x = self.value(v);
        if v.fold().is_some() {
            return Ok(x);
        }
        let Some(stmt) = self
            .model
            .stmts
            .iter()
            .find(|s| s.links.iter().any(|l| l == link))
        else {
            return Ok(x);
        };
        let primitive = primitive_named(kinds::of(stmt).primitive());
        let group = intern(&stmt.name.to_string());
        if mass {
            let what = intern(&format!("mass of `{link}`{part}"));
            geometry::positive(x, primitive, what).map_err(|e| e.in_group(group))
        } else {
            let what = intern(&format!("moment of inertia of `{link}`{part}"));
            geometry::non_negative(x, primitive, what).map_err(|e| e.in_group(group))
        }
    }

    /// The known loads (`emit::forces::loads`): each link's masses, then
    /// the external forces, then the external couples.
    fn known_loads(&self, cx: &mut ForceRunCx<'_>) -> Result<(), Error<f64>> {
        let k = &self.model.kinetics;
        let gravity = k
            .gravity
            .as_ref()
            .map(|(_, gx, gy)| Vector2::new(self.value(gx), self.value(gy)));
        for (link, parts) in crate::emit::forces::masses_by_link(&k.masses) {
            self.masses(cx, &link, &parts, gravity)?;
        }
        for f in &k.forces {
            let link = match &f.on {
                Some(l) => l.to_string(),
                None => match self.plan.links_with_point(&f.at.to_string()).first() {
                    Some(l) => l.clone(),
                    None => continue,
                },
            };
            let value = match &f.value {
                ForceSpecValue::Components(x, y) => Vector2::new(self.value(x), self.value(y)),
                ForceSpecValue::Along(guide, v) => cx.pose.line(guide).dir * self.value(v),
            };
            if let Some(v) = cx.velocity_of(&f.at) {
                cx.power.push(geometry::dot(&value, &v));
            }
            cx.force_on(&link, value, &f.at);
        }
        for t in &k.torques {
            let value = self.value(&t.value);
            if let Some((w, _)) = cx.rates_of(&t.on) {
                cx.power.push(value * w);
            }
            cx.add(&t.on.to_string(), Wrench::couple(value));
        }
        Ok(())
    }

    /// The masses of one link (`loads::mass`, `loads::mass_parts`): each
    /// part's inertia force and weight at its centre; the inertia couple
    /// (the parts' `j` summed) when the link turns. Checks, powers and
    /// loads in the generated order.
    fn masses(
        &self,
        cx: &mut ForceRunCx<'_>,
        link: &str,
        parts: &[&MassSpec],
        gravity: Option<Vector2<f64>>,
    ) -> Result<(), Error<f64>> {
        let one = parts.len() == 1;
        let turning = cx.rates_of(&parts[0].link);
        let mut inertias = Vec::new();
        for (k, m) in parts.iter().enumerate() {
            let part = if one {
                String::new()
            } else {
                format!(" (part {})", k + 1)
            };
            let mass = self.checked(&m.mass, link, &part, true)?;
            let v_g = cx.velocity_of(&m.at);
            let mut terms = Vec::new();
            if v_g.is_some() {
                terms.push(cx.acceleration_of(&m.at) * (-mass));
            }
            if let Some(g) = gravity {
                terms.push(g * mass);
            }
            let j = m.inertia.as_ref().filter(|j| j.fold() != Some(0.0));
            // A link's only mass: its couple comes before its forces.
            let mut couple = None;
            if let (true, Some(j), Some((w, alpha))) = (one, j, turning) {
                let c = -(self.checked(j, link, "", false)? * alpha);
                cx.power.push(c * w);
                couple = Some(c);
            }
            if let Some(v) = v_g {
                for t in &terms {
                    cx.power.push(geometry::dot(t, &v));
                }
            }
            if let Some((first, rest)) = terms.split_first() {
                let total = rest.iter().fold(*first, |acc, t| acc + t);
                cx.force_on(link, total, &m.at);
            }
            if let Some(c) = couple {
                cx.add(link, Wrench::couple(c));
            }
            if let (false, Some(j)) = (one, j) {
                inertias.push((part, j));
            }
        }
        let Some((w, alpha)) = turning else {
            return Ok(());
        };
        if inertias.is_empty() {
            return Ok(());
        }
        let folded: Option<f64> = inertias.iter().map(|(_, j)| j.fold()).sum();
        let j = match folded {
            Some(sum) => sum,
            None => {
                let mut total: Option<f64> = None;
                for (part, j) in &inertias {
                    let x = self.checked(j, link, part, false)?;
                    total = Some(total.map_or(x, |t| t + x));
                }
                total.unwrap_or(f64::NAN)
            }
        };
        let c = -(j * alpha);
        cx.power.push(c * w);
        cx.add(link, Wrench::couple(c));
        Ok(())
    }

    /// The motors' torques of an inverse-kinematics definition
    /// (`ForceEmitter::motors`): the rate map from two velocity
    /// evaluations at unit rates of the target's inputs, then
    /// `force::target::motor_torques` on the target's driving force.
    fn motors(&self, pos: &Position, cx: &mut ForceRunCx<'_>) -> Result<(), Error<f64>> {
        let model = &self.model;
        let Some((target, x, y)) = kinds::motors::held_target(model) else {
            return Ok(());
        };
        if kinds::motors::reactions(model).is_empty() {
            return Ok(());
        }
        let unit = |axis: &Ident| -> Vec<f64> {
            model
                .inputs
                .iter()
                .map(|i| if i.name == *axis { 1.0 } else { 0.0 })
                .collect()
        };
        let motor_rates = |vel: &Rates| -> [f64; 2] {
            let rate = |link: &Ident| {
                self.plan
                    .turning_link(&link.to_string())
                    .map(|l| vel.motion.links.get(&l).copied().unwrap_or(f64::NAN))
            };
            let mut out = [0.0; 2];
            for (o, m) in out.iter_mut().zip(&model.kinetics.motors) {
                let own = rate(&m.link).unwrap_or(0.0);
                *o = match m.carrier.as_ref().and_then(rate) {
                    Some(c) => own - c,
                    None => own,
                };
            }
            out
        };
        let k_x = motor_rates(&self.velocity(pos, &unit(x))?);
        let k_y = motor_rates(&self.velocity(pos, &unit(y))?);
        let drive_of = |input: &Ident| {
            let name = Family::Drive.text(input);
            cx.reactions
                .iter()
                .find(|r| r.name == name)
                .map_or(f64::NAN, |r| match r.value {
                    ForceValue::Scalar(v) => v,
                    _ => f64::NAN,
                })
        };
        let drive = Vector2::new(drive_of(x), drive_of(y));
        let rx = mechanism_core::force::target::motor_torques(k_x, k_y, &drive)
            .map_err(|e| e.in_group(intern(&target.name.to_string())))?;
        cx.conditions.push(rx.min_pivot_ratio);
        for (k, m) in model.kinetics.motors.iter().enumerate() {
            cx.field(
                Family::Drive.text(&m.name),
                Held::Torque,
                ForceValue::Scalar(rx.torque[k]),
            );
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::{power_residual, unique_names};
    use crate::kinds::{forces::Held, run::ForceValue, run::RunReaction};

    // Proves the power residual's edge cases match the generated code's: no
    // term gives 0, all-zero terms 0, an overflowing sum 1, else |sum|/max.
    #[test]
    fn power_residual_as_generated() {
        assert_eq!(power_residual(&[]), 0.0);
        assert_eq!(power_residual(&[0.0, 0.0]), 0.0);
        assert_eq!(power_residual(&[f64::MAX, f64::MAX]), 1.0);
        assert_eq!(power_residual(&[2.0, -1.5]), 0.25);
    }

    // Proves repeated field names are numbered from 2, others kept.
    #[test]
    fn repeated_names_are_numbered() {
        let r = |n: &str| RunReaction {
            name: n.into(),
            held: Held::Force,
            value: ForceValue::Scalar(0.0),
        };
        let mut v = vec![r("a"), r("b"), r("a"), r("a")];
        unique_names(&mut v);
        let names: Vec<&str> = v.iter().map(|r| r.name.as_str()).collect();
        assert_eq!(names, ["a", "b", "a_2", "a_3"]);
    }
}
