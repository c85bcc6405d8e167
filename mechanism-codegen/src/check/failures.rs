//! The compile errors of the expansion-time check: one per group that cannot
//! be assembled somewhere in the swept range, with every failing interval,
//! what fails in the user's numbers, and where the group does assemble (with
//! a `range` that passes).

use super::explain::{explain, grashof, suggest};
use super::{Found, Sweep};
use crate::diag::{show_interval, show_num, show_value, Diagnostics};
use crate::kinds;
use crate::model::{group_kind, Input, StmtId};
use mechanism_core::sweep::{self, Range};
use mechanism_core::Fault;
use proc_macro2::Span;
use std::collections::BTreeMap;
use std::f64::consts::PI;

/// Reports every group that fails somewhere; `true` when one does.
pub(super) fn report(s: &Sweep<'_>, errors: &mut Diagnostics) -> bool {
    let mut by_group: BTreeMap<usize, Vec<&Found>> = BTreeMap::new();
    for e in s.events.iter().filter(|e| !e.singular) {
        by_group.entry(e.group).or_default().push(e);
    }
    for (g, list) in &by_group {
        let stmt_index = s.checked.groups[*g];
        let (span, message) = if s.model.inputs.len() == 1 {
            one_input(s, stmt_index, list)
        } else {
            (
                s.model.stmts[stmt_index].name.span(),
                two_inputs(s, stmt_index, list),
            )
        };
        errors.error(syn::Error::new(span, message));
    }
    !by_group.is_empty()
}

/// The error of a group that fails over one input: its span (the group's
/// name, unless a declared range is to blame: the group assembles somewhere
/// in it; then the end of the range it fails at, or the range's input when
/// it fails inside) and its message.
fn one_input(s: &Sweep<'_>, stmt_index: StmtId, list: &[&Found]) -> (Span, String) {
    let model = s.model;
    let stmt = &model.stmts[stmt_index];
    let kind = group_kind(&stmt.kind).unwrap_or("group");
    let input = &model.inputs[0];
    let name = &input.name;
    let r = s.ranges[0];
    let intervals: Vec<String> = list
        .iter()
        .map(|e| {
            if e.hi[0] - e.lo[0] <= 1e-9 * (r.hi - r.lo) {
                format!("at {}", show_value(0.5 * (e.lo[0] + e.hi[0]), input.angle))
            } else {
                format!("in {}", show_interval(e.lo[0], e.hi[0], input.angle))
            }
        })
        .collect();
    let worst = list
        .iter()
        .max_by(|x, y| (x.hi[0] - x.lo[0]).total_cmp(&(y.hi[0] - y.lo[0])))
        .expect("non-empty");
    let mid = 0.5 * (worst.lo[0] + worst.hi[0]);
    let mid_show = format!("{name} = {}", show_value(mid, input.angle));
    let why = match s.ev.solve(&[mid]) {
        Err((_, fault)) => explain(model, &s.ev.known, stmt_index, &fault, &mid_show),
        // A failure at one input (a joint at infinity between two
        // samples) is explained where it was found.
        Ok(_) if worst.hi[0] == worst.lo[0] => {
            explain(model, &s.ev.known, stmt_index, &worst.fault, &mid_show)
        }
        Ok(_) => explain(
            model,
            &s.ev.known,
            stmt_index,
            &worst.fault,
            "the first failing sample",
        ),
    };
    let best = widest_assembling(s, input);
    let mut span = stmt.name.span();
    let where_ok = match best {
        Some(interval) => where_it_assembles(s, input, interval, list, &mut span),
        None => "it assembles nowhere in the range: check the dimensions".into(),
    };
    // Guides parallel at every pose checked (a PRP whose guides turn
    // together, or keep their directions): said directly, not as a failure
    // at one input.
    let singular_everywhere =
        best.is_none() && matches!(s.ev.solve(&[mid]), Err((_, Fault::Singular { .. })));
    if singular_everywhere {
        let over = format!("{name} in {}", show_interval(r.lo, r.hi, input.angle));
        if let Some(text) = kinds::of(stmt).singular_everywhere(&over) {
            return (span, text);
        }
    }
    let grashof = if !input.declared {
        grashof(model, s.plan, stmt_index)
            .map(|g| format!("{g}; "))
            .unwrap_or_default()
    } else {
        String::new()
    };
    let over = if input.declared {
        format!(
            "the declared range {}",
            show_interval(r.lo, r.hi, input.angle)
        )
    } else {
        format!(
            "a full turn {}, the default for a crank",
            show_interval(r.lo, r.hi, true)
        )
    };
    let message = format!(
        "cannot assemble group `{}` ({kind}) for {name} {} (checked over {over})\n  = note: {why}\n  = help: {grashof}{where_ok}",
        stmt.name,
        intervals.join(" and "),
    );
    (span, message)
}

/// The widest interval of the range where no group fails (the complement of
/// the failing intervals; over a turn, what assembles at its end continues at
/// its start), a turn's interval shown with its middle in (-180, 180] deg.
fn widest_assembling(s: &Sweep<'_>, input: &Input) -> Option<(f64, f64)> {
    let r = s.ranges[0];
    let mut fails: Vec<(f64, f64)> = s
        .events
        .iter()
        .filter(|e| !e.singular)
        .map(|e| (e.lo[0], e.hi[0]))
        .collect();
    fails.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut free: Vec<(f64, f64)> = Vec::new();
    let (start, end) = if r.periodic && fails.first().is_some_and(|f| f.0 < r.lo) {
        let first = fails.remove(0);
        (first.1, first.0 + (r.hi - r.lo))
    } else {
        (r.lo, r.hi)
    };
    let mut at = start;
    for (a, b) in fails.iter().chain(std::iter::once(&(end, end))) {
        if *a > at {
            free.push((at, *a));
        }
        at = at.max(*b);
    }
    // A turn: what assembles at its end continues at its start.
    if r.periodic && free.len() > 1 {
        let (first, last) = (free[0], free[free.len() - 1]);
        if first.0 <= r.lo && last.1 >= r.hi {
            free.pop();
            free[0] = (last.0 - (r.hi - r.lo), first.1);
        }
    }
    free.iter()
        .max_by(|x, y| (x.1 - x.0).total_cmp(&(y.1 - y.0)))
        .map(|&(a, b)| {
            // A middle at 180 deg to rounding (an interval symmetric about
            // 180 deg, whose ends were bisected to 1e-10 of the turn) stays
            // at 180, not -180.
            if input.angle && r.periodic {
                let k = ((0.5 * (a + b) - PI) / (2.0 * PI) - 1e-9).ceil();
                (a - 2.0 * PI * k, b - 2.0 * PI * k)
            } else {
                (a, b)
            }
        })
}

/// The help for where the group assembles (`(a, b)`), with a `range` that
/// passes; moves `span` to the declared range's end (or input) to blame.
fn where_it_assembles(
    s: &Sweep<'_>,
    input: &Input,
    (a, b): (f64, f64),
    list: &[&Found],
    span: &mut Span,
) -> String {
    let r: Range = s.ranges[0];
    let name = &input.name;
    // An end where the group fails at a single input (a PRP's parallel
    // guides) is not part of where it assembles: shown open, `(60, 240)
    // deg`, not `[60, 240] deg`.
    let width = r.hi - r.lo;
    let point_failure = |x: f64| {
        s.events.iter().filter(|e| !e.singular).any(|e| {
            let (lo, hi) = (e.lo[0], e.hi[0]);
            let mut d = (0.5 * (lo + hi) - x).abs();
            if r.periodic {
                d = d.rem_euclid(width);
                d = d.min(width - d);
            }
            hi - lo <= 1e-9 * width && d <= 1e-9 * width
        })
    };
    let mut shown = show_interval(a, b, input.angle);
    if point_failure(a) {
        shown.replace_range(..1, "(");
    }
    if point_failure(b) {
        if let Some(k) = shown.find(']') {
            shown.replace_range(k..k + 1, ")");
        }
    }
    let verb = if input.declared {
        "narrow the declared range to it"
    } else {
        "declare a range inside it"
    };
    if let (true, Some(at)) = (input.declared, input.spans) {
        let tiny = 1e-9 * width;
        let at_lo = list.iter().all(|e| e.lo[0] <= r.lo + tiny);
        let at_hi = list.iter().all(|e| e.hi[0] >= r.hi - tiny);
        *span = match (at_lo && !r.periodic, at_hi && !r.periodic) {
            (true, false) => at.lo,
            (false, true) => at.hi,
            _ => at.input,
        };
    }
    match suggest(input, a, b) {
        Some(range) => format!("it assembles for {name} in {shown}: {verb}, e.g. {range}"),
        None => format!("it assembles only for {name} in {shown}; change the dimensions"),
    }
}

/// The message of a group that fails at grid points of a two-input box.
fn two_inputs(s: &Sweep<'_>, stmt_index: StmtId, list: &[&Found]) -> String {
    let model = s.model;
    let stmt = &model.stmts[stmt_index];
    let kind = group_kind(&stmt.kind).unwrap_or("group");
    let (inputs, ranges) = (&model.inputs, &s.ranges);
    let e = list[0];
    let unit = |i: usize| if inputs[i].angle { " deg" } else { "" };
    let v = |i: usize, x: f64| show_num(if inputs[i].angle { x.to_degrees() } else { x });
    let total = (sweep::SAMPLES_2D + 1) * (sweep::SAMPLES_2D + 1);
    format!(
        "cannot assemble group `{}` ({kind}) at {} of the {total} grid points of the declared box {} x {}: they span {} in [{}, {}]{}, {} in [{}, {}]{}\n  = note: {}\n  = help: narrow the declared ranges or change the dimensions",
        stmt.name,
        e.count,
        show_interval(ranges[0].lo, ranges[0].hi, inputs[0].angle),
        show_interval(ranges[1].lo, ranges[1].hi, inputs[1].angle),
        inputs[0].name, v(0, e.lo[0]), v(0, e.hi[0]), unit(0),
        inputs[1].name, v(1, e.lo[1]), v(1, e.hi[1]), unit(1),
        explain(model, &s.ev.known, stmt_index, &e.fault, "the first failing grid point"),
    )
}
