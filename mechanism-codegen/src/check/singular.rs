//! The warnings of the expansion-time check: one per group that passes
//! through a singular position (toggle, dead centre) the definition does not
//! allow, as a `#[deprecated]` item used at the group's name (the only warning
//! a stable procedural macro can raise).

use super::explain::singular_meaning;
use super::{Findings, Sweep};
use crate::diag::{show_num, show_value};
use crate::model::group_kind;
use quote::{quote, quote_spanned};
use std::collections::BTreeMap;
use std::f64::consts::PI;

/// Records every singular position in `findings.singular` and warns of those
/// not allowed.
pub(super) fn warn(s: &Sweep<'_>, findings: &mut Findings) {
    let mut sing: BTreeMap<usize, Vec<(Vec<f64>, u32)>> = BTreeMap::new();
    for e in s.events.iter().filter(|e| e.singular) {
        sing.entry(e.group)
            .or_default()
            .push((e.lo.clone(), e.count));
    }
    for (g, list) in &sing {
        let stmt_index = s.checked.groups[*g];
        let stmt = &s.model.stmts[stmt_index];
        findings
            .singular
            .push((*g, list.iter().map(|(at, _)| at[0]).collect()));
        if s.model.allowed.allows(&stmt.name.to_string()) {
            continue;
        }
        let kind = group_kind(&stmt.kind).unwrap_or("group");
        let at = where_singular(s, list);
        let count = if s.model.inputs.len() == 2 {
            format!(" ({} sign changes on the grid)", list[0].1)
        } else {
            String::new()
        };
        let note = format!(
            "group `{}` ({kind}) passes through a singular position at {}{count}: {}; `velocity()` and `acceleration()` return `Singular` there and lose accuracy near it. If the motion is meant to pass there, write `allow singular {};` in the definition",
            stmt.name,
            at.join(" and "),
            singular_meaning(s.model, stmt_index),
            stmt.name
        );
        let span = stmt.name.span();
        let use_it = quote_spanned!(span=> singular_position);
        findings.warnings.extend(quote! {
            const _: () = {
                #[deprecated(note = #note)]
                #[allow(non_upper_case_globals)]
                const singular_position: () = ();
                #use_it
            };
        });
    }
}

/// Where a group is singular, as the warning shows it: one input to 1e-4
/// (deg for an angle; the determinant is exactly zero over a rounding band
/// about a fold, where the search may stop), sorted; two inputs as pairs.
fn where_singular(s: &Sweep<'_>, list: &[(Vec<f64>, u32)]) -> Vec<String> {
    let inputs = &s.model.inputs;
    if inputs.len() == 1 {
        let r = s.ranges[0];
        let unit = if inputs[0].angle { 180.0 / PI } else { 1.0 };
        let mut at1: Vec<f64> = list
            .iter()
            .map(|(at, _)| {
                let x = (at[0] * unit * 1e4).round() / 1e4;
                if r.periodic && x >= r.hi * unit {
                    x - (r.hi - r.lo) * unit
                } else {
                    x
                }
            })
            .collect();
        at1.sort_by(f64::total_cmp);
        at1.iter()
            .map(|x| {
                format!(
                    "{} = {}{}",
                    inputs[0].name,
                    show_num(*x),
                    if inputs[0].angle { " deg" } else { "" }
                )
            })
            .collect()
    } else {
        list.iter()
            .map(|(at, _)| {
                format!(
                    "({}, {}) = ({}, {})",
                    inputs[0].name,
                    inputs[1].name,
                    show_value(at[0], inputs[0].angle),
                    show_value(at[1], inputs[1].angle)
                )
            })
            .collect()
    }
}
