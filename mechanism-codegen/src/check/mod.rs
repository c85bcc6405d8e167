//! Stage 5, check: the declared input ranges, and the mechanism assembled over
//! them at expansion time.
//!
//! The input ranges and the allowed singular positions are read by the model
//! (`model::Input`, `model::Allowed`).
//!
//! - [`expansion_check`]: when every dimension the position analysis uses is
//!   known at expansion time (literals and `const`s, no `params`), the
//!   mechanism is solved in `f64` through the same `mechanism-core` primitives
//!   the generated code calls, in the plan's solve order, over the input range,
//!   by the sweep of `mechanism_core::sweep` (the one the generated `check()`
//!   runs). A group that cannot be assembled somewhere is a compile error on
//!   the group's name, with the input interval and a hint computed from the
//!   numbers; a singular position (toggle, dead centre) is a warning
//!   (`#[deprecated]` on a generated item used at the group's name: the only
//!   warning a stable proc macro can raise).
//! - the generated `check()` (`emit::check_fn`) runs the same sweep at run
//!   time through the generated `position()`, for any parameters.
//!
//! Files: `eval` solves the position in `f64`; `failures` and `singular`
//! turn the sweep's findings into errors and warnings; `explain` says what a
//! finding means in the user's numbers.
//!
//! Two inputs are checked only when both have declared ranges (a grid over the
//! box); three or more are not checked.

mod eval;
mod explain;
mod failures;
pub mod modes;
mod singular;

use crate::diag::{show_interval, Diagnostics};
use crate::kinds;
use crate::model::{Input, Mode, Model};
use crate::plan::{checked, Checked, Plan};
use eval::{position_values, Evaluator, MAX_GROUPS};
use mechanism_core::sweep::{self, Event, Range, Tolerances};
use mechanism_core::Fault;
use proc_macro2::TokenStream;
use std::collections::BTreeMap;

/// One sweep finding for a checked group: a failure to assemble over an
/// interval (one input) or at grid points (two), or a singular position.
pub struct Found {
    /// The group's index among the checked groups.
    pub group: usize,
    /// The lower corner of the failing interval or box; the input of a
    /// singular position.
    pub lo: Vec<f64>,
    /// The upper corner (equal to `lo` at a single input).
    pub hi: Vec<f64>,
    /// What failed.
    pub fault: Fault,
    /// Failing grid points, or sign changes of the determinant.
    pub count: u32,
    /// `true` for a singular position, `false` for a failure to assemble.
    pub singular: bool,
}

/// The expansion-time check's findings.
#[derive(Default)]
pub struct Findings {
    /// Warning items (`#[deprecated]` uses).
    pub warnings: TokenStream,
    /// What was checked, for the generated doc comment.
    pub summary: String,
    /// Singular inputs found (allowed or not): (group index, input).
    pub singular: Vec<(usize, Vec<f64>)>,
    /// `true` when the check ran at expansion time.
    pub ran: bool,
    /// What the check found of each statement that its code reads (the
    /// triads' tracked assemblies), passed forward to emit.
    pub known: kinds::Known,
}

/// Everything the reports of one sweep read.
struct Sweep<'a> {
    model: &'a Model,
    plan: &'a Plan,
    checked: &'a Checked,
    ev: Evaluator<'a>,
    /// The swept range of each input.
    ranges: Vec<Range>,
    /// What the sweep found, in the order found.
    events: Vec<Found>,
}

/// Per checked group: `true` for a group whose joint runs off to infinity
/// where its determinant vanishes (PRP: parallel guides; RPP: the slot
/// parallel to the guide): there the position itself fails, whether or not a
/// sample lands on it.
pub fn joints_at_infinity(model: &Model, checked: &Checked) -> Vec<bool> {
    checked
        .groups
        .iter()
        .map(|&i| kinds::of(&model.stmts[i]).joint_at_infinity())
        .collect()
}

/// A sweep event as a finding. A singular position of a group whose joint is
/// at infinity there is a failure at that one input (so the verdict does not
/// depend on whether a sample lands on the point).
fn found<const D: usize>(at_infinity: &[bool], event: Event<D>) -> Found {
    match event {
        Event::Fails {
            group,
            lo,
            hi,
            fault,
            count,
        } => Found {
            group,
            lo: lo.to_vec(),
            hi: hi.to_vec(),
            fault,
            count,
            singular: false,
        },
        Event::Singular {
            group,
            at,
            count,
            det,
        } => Found {
            group,
            lo: at.to_vec(),
            hi: at.to_vec(),
            fault: if at_infinity[group] {
                Fault::Singular { det, scale: 1.0 }
            } else {
                Fault::NonFinite { what: "" }
            },
            count,
            singular: !at_infinity[group],
        },
    }
}

/// The inputs' ranges as the summary shows them.
fn show_ranges(inputs: &[Input]) -> String {
    inputs
        .iter()
        .filter_map(|i| {
            let r = i.range?;
            Some(format!(
                "`{}` in {}{}",
                i.name,
                show_interval(r.lo, r.hi, i.angle),
                if i.declared {
                    ""
                } else {
                    " (a crank's full turn, the default)"
                }
            ))
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// The ranges to sweep, or why the mechanism is not checked at expansion
/// time (the summary for the generated doc comment).
fn sweepable(model: &Model, checked: &Checked) -> Result<Vec<Range>, String> {
    let inputs = &model.inputs;
    let ranges: Vec<Range> = inputs.iter().filter_map(|i| i.range).collect();
    if ranges.len() != inputs.len() || inputs.is_empty() {
        let missing: Vec<String> = inputs
            .iter()
            .filter(|i| i.range.is_none())
            .map(|i| format!("`{}`", i.name))
            .collect();
        return Err(format!(
            "Not checked: no range is declared for {} (declare one with `range INPUT = (lo, hi);`).",
            missing.join(", ")
        ));
    }
    if inputs.len() > 2 {
        return Err(
            "Not checked: the checks sweep one or two inputs, this mechanism has more.".into(),
        );
    }
    if inputs.len() == 2 && inputs.iter().any(|i| !i.declared) {
        return Err("Not checked: a mechanism with two inputs is checked over a box of declared ranges; declare `range` for both inputs.".into());
    }
    let show_ranges = show_ranges(inputs);
    if checked.groups.len() > MAX_GROUPS {
        return Err(format!("Not checked at expansion time: more than {MAX_GROUPS} groups; `check()` sweeps {show_ranges} at run time."));
    }
    if position_values(model, &checked.order)
        .iter()
        .any(|v| v.fold().is_none())
    {
        return Err(format!("Not checked at expansion time (the dimensions include run-time `params`): `check()` sweeps {show_ranges} for the parameters it is called on."));
    }
    Ok(ranges)
}

/// Sweeps the ranges (`mechanism_core::sweep`, as the generated `check()`
/// does) and collects what it finds.
fn run(ev: &Evaluator<'_>, at_infinity: &[bool], ranges: &[Range]) -> Vec<Found> {
    let mut events: Vec<Found> = Vec::new();
    if ranges.len() == 1 {
        let tol = Tolerances::for_eps(f64::EPSILON);
        sweep::sweep_1d(
            &ranges[0],
            sweep::SAMPLES_1D,
            &tol,
            |q| ev.solve(q),
            |e| events.push(found(at_infinity, e)),
        );
    } else {
        sweep::sweep_2d(
            &[ranges[0], ranges[1]],
            sweep::SAMPLES_2D,
            |q| ev.solve(q),
            |e| events.push(found(at_infinity, e)),
        );
    }
    events
}

/// Runs the expansion-time check (see the module documentation): failures
/// to assemble go to `errors`, singular positions become warnings.
pub fn expansion_check(model: &Model, plan: &Plan, errors: &mut Diagnostics) -> Findings {
    check_assuming(model, plan, BTreeMap::new(), errors)
}

/// The expansion-time check with the run-time mode parameters valued as in
/// `modes` (by name; those absent at their defaults).
fn check_assuming(
    model: &Model,
    plan: &Plan,
    modes: BTreeMap<String, Mode>,
    errors: &mut Diagnostics,
) -> Findings {
    let mut findings = Findings::default();
    let checked = checked(model, plan);
    let ranges = match sweepable(model, &checked) {
        Ok(ranges) => ranges,
        Err(summary) => {
            findings.summary = summary;
            return findings;
        }
    };
    findings.ran = true;
    let known = kinds::Known {
        modes,
        ..kinds::Known::default()
    };
    let mut ev = Evaluator::new(model, plan, &checked, known);
    if !eval::track_assemblies(model, &mut ev, &ranges, errors) {
        return findings;
    }
    findings.known.tracked.clone_from(&ev.known.tracked);
    let events = run(&ev, &joints_at_infinity(model, &checked), &ranges);
    findings.summary = format!(
        "Checked at expansion time over {} ({}): every group assembles.",
        show_ranges(&model.inputs),
        if ranges.len() == 1 {
            format!("{} samples, edges bisected", sweep::SAMPLES_1D + 1)
        } else {
            format!("a {0} x {0} grid", sweep::SAMPLES_2D + 1)
        }
    );
    let sweep = Sweep {
        model,
        plan,
        checked: &checked,
        ev,
        ranges,
        events,
    };
    if failures::report(&sweep, errors) {
        return findings;
    }
    singular::warn(&sweep, &mut findings);
    let n_sing: usize = findings.singular.iter().map(|(_, v)| v.len()).sum();
    if n_sing > 0 {
        findings
            .summary
            .push_str(&format!(" Singular positions found: {n_sing}."));
    } else {
        findings.summary.push_str(" No singular position found.");
    }
    findings
}
