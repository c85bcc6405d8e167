//! The expansion-time evaluator: the position analysis in `f64`, walking the
//! plan's solve order and calling the same `mechanism-core` primitives, with
//! the same arguments, as the generated `position()`.

use crate::keys::InputName;
use crate::kinds::{self, Known, Pose, Tracking};
use crate::model::{Model, StmtId};
use crate::plan::Checked;
use crate::value::Value;
use mechanism_core::sweep::Outcome;
use std::collections::BTreeMap;
use syn::Ident;

/// Most groups the expansion-time check handles (more: not checked).
pub const MAX_GROUPS: usize = 64;

/// Every value `position()` uses, for the statements in `order`.
pub fn position_values(model: &Model, order: &[StmtId]) -> Vec<Value> {
    order
        .iter()
        .flat_map(|&i| kinds::of(&model.stmts[i]).position_values())
        .collect()
}

/// The position analysis of the checked statements in `f64`.
pub struct Evaluator<'a> {
    model: &'a Model,
    order: &'a [StmtId],
    /// Group index of each checked statement.
    group: BTreeMap<StmtId, usize>,
    /// Input index by name.
    input: BTreeMap<InputName, usize>,
    /// The assumed modes, and the assemblies tracked so far.
    pub known: Known,
}

impl<'a> Evaluator<'a> {
    /// The evaluator of the statements `checked` solves, with the inputs in
    /// the order of the model's input struct; `known.modes` are the run-time
    /// modes assumed in place of their defaults.
    pub fn new(model: &'a Model, checked: &'a Checked, known: Known) -> Self {
        Evaluator {
            model,
            order: &checked.order,
            group: checked
                .groups
                .iter()
                .enumerate()
                .map(|(k, &i)| (i, k))
                .collect(),
            input: model
                .inputs
                .iter()
                .enumerate()
                .map(|(k, i)| (InputName::of(&i.name), k))
                .collect(),
            known,
        }
    }

    /// The pose of the statements solved before statement `stop` at inputs
    /// `q` (`None` when one of them fails).
    pub fn pose_before(&self, q: &[f64], stop: StmtId) -> Option<Pose> {
        let mut pose = Pose::default();
        for &i in self.order {
            if i == stop {
                return Some(pose);
            }
            let input = |n: &Ident| self.input_value(q, n);
            kinds::of_known(&self.model.stmts, i, &self.known)
                .eval(&mut pose, &input)
                .ok()?;
        }
        None
    }

    /// The value of input `n` in `q` (NaN when `n` is not an input).
    fn input_value(&self, q: &[f64], n: &Ident) -> f64 {
        self.input
            .get(&InputName::of(n))
            .and_then(|&k| q.get(k))
            .copied()
            .unwrap_or(f64::NAN)
    }

    /// Solves the position at inputs `q`: each checked group's scaled
    /// determinant, or the first failing group with its fault.
    pub fn solve(&self, q: &[f64]) -> Outcome<MAX_GROUPS> {
        let mut pose = Pose::default();
        let mut dets = [1.0; MAX_GROUPS];
        for &i in self.order {
            let g = self.group.get(&i).copied().unwrap_or(0);
            let input = |n: &Ident| self.input_value(q, n);
            if let Some(det) = kinds::of_known(&self.model.stmts, i, &self.known)
                .eval(&mut pose, &input)
                .map_err(|e| (g, e.fault))?
            {
                dets[g] = det;
            }
        }
        Ok(dets)
    }
}

/// Lets every statement that follows its assembly over the input range at
/// expansion time do so (a triad: `GroupKind::track`), in solve order, with
/// the pose of the statements before it (which reads the assemblies tracked
/// before); what each finds goes to `ev.known`. Only with one input and its
/// range. `false` when one reported an error (the rest of the check is then
/// moot).
pub fn track_assemblies(
    model: &Model,
    ev: &mut Evaluator<'_>,
    ranges: &[mechanism_core::sweep::Range],
    errors: &mut crate::diag::Diagnostics,
) -> bool {
    let (Some(range), true) = (ranges.first(), ranges.len() == 1) else {
        return true;
    };
    let angle = model.inputs.first().is_some_and(|i| i.angle);
    let mut ok = true;
    for &i in ev.order {
        let before = |q: f64| ev.pose_before(&[q], i);
        let found = kinds::of(&model.stmts[i]).track(&before, (range.lo, range.hi), angle, errors);
        match found {
            Tracking::Nothing => {}
            Tracking::Tracked(tracked) => {
                ev.known.tracked.insert(i, tracked);
            }
            Tracking::Failed => ok = false,
        }
    }
    ok
}
