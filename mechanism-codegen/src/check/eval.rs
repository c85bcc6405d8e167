//! The expansion-time evaluator: the position analysis in `f64`, walking the
//! plan's solve order with the compiled steps of the run-time mechanism
//! (`kinds::run::Step::position`, one per kind, in the kind's file), which
//! call the same `mechanism-core` primitives, with the same arguments, as
//! the generated `position()`.

use crate::kinds::run::{Compile, Layout, NamedPose, RunPose, Step};
use crate::kinds::{self, Known, Tracked, Tracking};
use crate::model::{Model, StmtId};
use crate::plan::{Checked, Plan};
use crate::value::Value;
use mechanism_core::sweep::Outcome;
use std::collections::BTreeMap;

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
    /// The plan's names in slots.
    layout: Layout,
    /// Each statement compiled (by statement index) with the assumed modes
    /// and the assemblies tracked so far; every dimension folds (the check
    /// runs only then), so no parameter is needed.
    steps: Vec<Box<dyn Step>>,
    /// The assumed modes, and the assemblies tracked so far.
    pub known: Known,
}

impl<'a> Evaluator<'a> {
    /// The evaluator of the statements `checked` solves, with the inputs in
    /// the order of the model's input struct; `known.modes` are the run-time
    /// modes assumed in place of their defaults.
    pub fn new(model: &'a Model, plan: &Plan, checked: &'a Checked, known: Known) -> Self {
        let mut ev = Evaluator {
            model,
            order: &checked.order,
            group: checked
                .groups
                .iter()
                .enumerate()
                .map(|(k, &i)| (i, k))
                .collect(),
            layout: crate::slots::layout(model, plan),
            steps: Vec::new(),
            known,
        };
        ev.steps = StmtId::all(&model.stmts).map(|i| ev.compile(i)).collect();
        ev
    }

    /// Statement `i` compiled with what is known.
    fn compile(&self, i: StmtId) -> Box<dyn Step> {
        let params = BTreeMap::new();
        let cx = Compile {
            layout: &self.layout,
            params: &params,
        };
        kinds::of_known(&self.model.stmts, i, &self.known).compile(&cx)
    }

    /// Keeps what statement `i` tracked, and compiles it again with it.
    pub fn set_tracked(&mut self, i: StmtId, tracked: Tracked) {
        self.known.tracked.insert(i, tracked);
        let step = self.compile(i);
        if let Some(slot) = self.steps.get_mut(i.0) {
            *slot = step;
        }
    }

    /// Storage for one position at inputs `q` (one value per input, in the
    /// order of the input struct; a missing one reads NaN).
    fn pose(&self, q: &[f64]) -> RunPose {
        let mut pose = RunPose::new(&self.layout, self.model.inputs.len());
        for (slot, &x) in pose
            .q
            .iter_mut()
            .zip(q.iter().take(self.model.inputs.len()))
        {
            *slot = x;
        }
        pose
    }

    /// The pose of the statements solved before statement `stop` at inputs
    /// `q` (`None` when one of them fails).
    pub fn pose_before(&self, q: &[f64], stop: StmtId) -> Option<NamedPose<'_>> {
        let mut pose = self.pose(q);
        for &i in self.order {
            if i == stop {
                return Some(NamedPose {
                    pose,
                    layout: &self.layout,
                });
            }
            self.steps[i.0].position(&mut pose).ok()?;
        }
        None
    }

    /// Solves the position at inputs `q`: each checked group's scaled
    /// determinant, or the first failing group with its fault.
    pub fn solve(&self, q: &[f64]) -> Outcome<MAX_GROUPS> {
        let mut pose = self.pose(q);
        let mut dets = [1.0; MAX_GROUPS];
        for &i in self.order {
            let g = self.group.get(&i).copied().unwrap_or(0);
            if let Some(det) = self.steps[i.0]
                .position(&mut pose)
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
            Tracking::Tracked(tracked) => ev.set_tracked(i, tracked),
            Tracking::Failed => ok = false,
        }
    }
    ok
}

#[cfg(test)]
mod tests {
    use super::Evaluator;
    use crate::diag::Diagnostics;
    use crate::kinds::Known;
    use crate::model::StmtId;

    #[test]
    fn the_compiled_steps_close_the_four_bar() {
        // Proves the check's walk (the kinds' compiled steps) solves a
        // four-bar at theta = 0.7: the crank tip at (cos, sin) of the input,
        // the RRR joint at l1 = 3 from `A` and l2 = 2.5 from `O4` (1e-12: a
        // few roundings of numbers of size 3), on the left of `A -> O4`, and
        // its determinant in (0, 1] where the crank has none.
        let src = "pub M {
            let O = ground(0.0, 0.0);
            let O4 = ground(3.0, 0.0);
            let A = crank(O, 1.0, theta) as link2;
            let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
        }";
        let mut diag = Diagnostics::new();
        let definition = syn::parse_str(src).expect("parses");
        let model = crate::model::lower(definition, &mut diag);
        let plan = crate::plan::plan(&model, &mut diag).expect("a plan");
        assert!(diag.finish().is_empty());
        let checked = crate::plan::checked(&model, &plan);
        let ev = Evaluator::new(&model, &plan, &checked, Known::default());
        let theta: f64 = 0.7;
        let dets = ev.solve(&[theta]).expect("assembles");
        // The pose before a statement past the last: every point solved.
        let past = StmtId(model.stmts.len());
        assert!(ev.pose_before(&[theta], past).is_none());
        let before_b = ev.pose_before(&[theta], StmtId(3)).expect("A solved");
        let id = |n: &str| syn::Ident::new(n, proc_macro2::Span::call_site());
        let (a, o4) = (before_b.point(&id("A")), before_b.point(&id("O4")));
        assert!((a.x - theta.cos()).abs() <= 1e-15 && (a.y - theta.sin()).abs() <= 1e-15);
        assert!(before_b.point(&id("B")).x.is_nan(), "B is not solved yet");
        let mut pose = ev.pose(&[theta]);
        for &i in ev.order {
            ev.steps[i.0].position(&mut pose).expect("assembles");
        }
        let all = crate::kinds::run::NamedPose {
            pose,
            layout: &ev.layout,
        };
        let b = all.point(&id("B"));
        assert!(((b - a).norm() - 3.0).abs() <= 1e-12);
        assert!(((b - o4).norm() - 2.5).abs() <= 1e-12);
        let (r, s) = (o4 - a, b - a);
        assert!(r.x * s.y - r.y * s.x > 0.0, "B is not left of A -> O4");
        // The checked groups in order: the crank (no rate system: its entry
        // stays 1), then the RRR.
        assert_eq!(checked.groups.len(), 2);
        assert_eq!(dets[0], 1.0);
        let det = dets[1];
        assert!(det > 0.0 && det < 1.0, "{det}");
    }
}
