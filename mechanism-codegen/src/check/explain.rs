//! What a failing or singular group means, in the user's words and numbers:
//! the distances that do not close, the links that align, the four-bar's
//! Grashof condition, and a `range` statement that would pass.

use crate::diag::show_num;
use crate::keys::Name;
use crate::kinds::{self};
use crate::model::{Input, Model, StmtId};
use crate::plan::Plan;
use mechanism_core::Fault;
use syn::Ident;

/// A range statement for a hint: the interval shrunk inward to whole tenths
/// (deg for angles), strictly inside; `None` when nothing is left.
pub fn suggest(input: &Input, lo: f64, hi: f64) -> Option<String> {
    let (lo, hi, unit) = if input.angle {
        (lo.to_degrees(), hi.to_degrees(), " deg")
    } else {
        (lo, hi, "")
    };
    let scale = if input.angle {
        10.0
    } else {
        // Two significant digits of the width below its leading digit.
        let w = hi - lo;
        if w <= 0.0 {
            return None;
        }
        10f64.powi(2 - w.log10().ceil() as i32)
    };
    let a = (lo * scale).floor() / scale + 1.0 / scale;
    let b = (hi * scale).ceil() / scale - 1.0 / scale;
    (a < b).then(|| {
        format!(
            "`range {} = ({}{unit}, {}{unit});`",
            input.name,
            show_num(a),
            show_num(b)
        )
    })
}

/// What the failing group's fault means, in the user's words (as its kind
/// says, or the fault's own text), with what the check knows of it.
pub fn explain(
    model: &Model,
    known: &kinds::Known,
    stmt_index: StmtId,
    fault: &Fault,
    at: &str,
) -> String {
    kinds::of_known(&model.stmts, stmt_index, known)
        .explain_fault(fault, at)
        .unwrap_or_else(|| format!("at {at}: {fault}"))
}

/// Why a group is singular, in the user's words.
pub fn singular_meaning(model: &Model, stmt_index: StmtId) -> String {
    kinds::of(&model.stmts[stmt_index])
        .singular_meaning()
        .unwrap_or_else(|| "its rate system is singular".into())
}

/// For a crank driving an RRR group onto a ground point: the four-bar's
/// Grashof condition, in numbers (the RRR's `GroupKind::full_turn_hint`).
pub fn grashof(model: &Model, plan: &Plan, stmt_index: StmtId) -> Option<String> {
    let find = |n: &Ident| plan.defined.get(&Name::of(n)).map(|&i| &model.stmts[i]);
    kinds::of(&model.stmts[stmt_index]).full_turn_hint(&find)
}
