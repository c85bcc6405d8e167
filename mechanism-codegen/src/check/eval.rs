//! The expansion-time evaluator: the position analysis in `f64`, walking the
//! plan's solve order and calling the same `mechanism-core` primitives, with
//! the same arguments, as the generated `position()`.

use crate::kinds::{self, Pose};
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
    input: BTreeMap<String, usize>,
}

impl<'a> Evaluator<'a> {
    /// The evaluator of the statements `checked` solves, with the inputs in
    /// the order of the model's input struct.
    pub fn new(model: &'a Model, checked: &'a Checked) -> Self {
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
                .map(|(k, i)| (i.name.to_string(), k))
                .collect(),
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
            kinds::of(&self.model.stmts[i])
                .eval(&mut pose, &input)
                .ok()?;
        }
        None
    }

    /// The value of input `n` in `q` (NaN when `n` is not an input).
    fn input_value(&self, q: &[f64], n: &Ident) -> f64 {
        self.input
            .get(&n.to_string())
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
            let stmt = &self.model.stmts[i];
            let g = self.group.get(&i).copied().unwrap_or(0);
            let input = |n: &Ident| {
                self.input
                    .get(&n.to_string())
                    .and_then(|&k| q.get(k))
                    .copied()
                    .unwrap_or(f64::NAN)
            };
            if let Some(det) = kinds::of(stmt)
                .eval(&mut pose, &input)
                .map_err(|e| (g, e.fault))?
            {
                dets[g] = det;
            }
        }
        Ok(dets)
    }
}

/// Tracks each triad's stated assembly over its input's range (one input)
/// and stores the tracked poses in the statement (`kinds::triad::track`),
/// which the sweep and the generated `position()` then read. A stated input
/// outside the range, or a stated pose that selects no assembly, is an
/// error on the statement (`false` returned).
pub fn track_triads(
    model: &Model,
    ev: &Evaluator<'_>,
    ranges: &[mechanism_core::sweep::Range],
    errors: &mut crate::diag::Diagnostics,
) -> bool {
    let mut ok = true;
    for &i in ev.order {
        let stmt = &model.stmts[i];
        let crate::model::Kind::Triad(t) = &stmt.kind else {
            continue;
        };
        let (Some(range), true) = (ranges.first(), ranges.len() == 1) else {
            continue;
        };
        let ks = |q: f64| {
            let pose = ev.pose_before(&[q], i)?;
            Some(t.k.each_ref().map(|k| pose.point(k)))
        };
        match kinds::triad::track(t, range.lo, range.hi, &ks) {
            Ok(tracked) => {
                *t.table.borrow_mut() = crate::model::Tracked {
                    angle: model.inputs.first().is_some_and(|i| i.angle),
                    ..tracked
                }
            }
            Err(e) => {
                ok = false;
                let q = t.at.1.fold().unwrap_or(f64::NAN);
                let angle = model.inputs.first().is_some_and(|i| i.angle);
                let shown = |x: f64| {
                    if angle {
                        format!("{} deg", crate::diag::show_num(x.to_degrees()))
                    } else {
                        crate::diag::show_num(x)
                    }
                };
                let inside = q >= range.lo && q <= range.hi;
                // On the pose's first coordinate, or on the input's value.
                let span = if inside {
                    t.near[0].0.span
                } else {
                    t.at.1.span
                };
                let message = if inside {
                    format!(
                        "the approximate pose of `{}`, `{}`, `{}` given at `{} = {}` selects no assembly of the triad there ({}); give the joints' positions at that input to within a fraction of the legs' lengths",
                        stmt.name, t.b, t.p, t.at.0, shown(q), why(&e.fault)
                    )
                } else {
                    format!(
                        "the pose is given at `{} = {}`, outside the range checked, {} .. {}: give it at an input inside the range, or widen the range",
                        t.at.0,
                        shown(q),
                        shown(range.lo),
                        shown(range.hi)
                    )
                };
                errors.push(span, message);
            }
        }
    }
    ok
}

/// Why a triad's stated pose selects no assembly, in numbers.
fn why(fault: &mechanism_core::Fault) -> String {
    use crate::diag::show_num;
    match fault {
        mechanism_core::Fault::NotNear { nearest, next } => format!(
            "the nearest assembly is {} from it, more than {} (half the shortest link) or not half as far as the next",
            show_num(*nearest),
            show_num(*next)
        ),
        mechanism_core::Fault::CannotAssemble { .. } => "it has no assembly at that input".into(),
        other => other.to_string(),
    }
}
