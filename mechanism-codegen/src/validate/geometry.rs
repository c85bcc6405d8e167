//! The rules on geometry: a group's two known joints are two places, a link
//! point is measured from a point of its link, a crank turns about a ground
//! point, a guide passes through a point of what carries it.

use crate::diag::Diagnostics;
use crate::kinds;
use crate::model::Model;
use crate::plan::Plan;
use syn::Ident;

/// The literal coordinates of a ground point, when it is one.
fn literal_ground(model: &Model, name: &Ident) -> Option<(f64, f64)> {
    model
        .stmts
        .iter()
        .filter(|s| s.name == *name)
        .find_map(kinds::literal_ground)
}

/// Rule: the two known joints of a group (or the two guides of a PRP) are two
/// different points (guides), and not two ground points at the same place.
pub(super) fn distinct_joints(model: &Model, errors: &mut Diagnostics) {
    for stmt in &model.stmts {
        let Some((a, b, what)) = kinds::of(stmt).distinct_pair() else {
            continue;
        };
        let kind = &stmt.kind_token;
        if a == b {
            errors.push(
                b.span(),
                format!("`{b}` is given twice: the two {what} of this `{kind}` must be different"),
            );
            continue;
        }
        if let (Some(pa), Some(pb)) = (literal_ground(model, a), literal_ground(model, b)) {
            if pa == pb {
                errors.push(
                    b.span(),
                    format!(
                        "`{a}` and `{b}` are both the ground point ({}, {}): the two {what} of this `{kind}` must be at different places; move one",
                        pa.0, pa.1
                    ),
                );
            }
        }
    }
}

/// Rule (after planning): a link point is measured from a point of that link,
/// a crank turns about a ground point, a guide passes through a point of
/// what carries it; each kind states its own (`GroupKind::check_placed`).
pub(super) fn geometry_consistent(model: &Model, plan: &Plan, errors: &mut Diagnostics) {
    for stmt in &model.stmts {
        kinds::of(stmt).check_placed(plan, errors);
    }
}
