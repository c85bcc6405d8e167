//! The rules on geometry: a group's two known joints are two places, a link
//! point is measured from a point of its link, a crank turns about a ground
//! point, a guide passes through a point of what carries it.

use crate::diag::Diagnostics;
use crate::model::{Kind, Model, Origin};
use crate::plan::Plan;
use syn::Ident;

/// The literal coordinates of a ground point, when it is one.
fn literal_ground(model: &Model, name: &Ident) -> Option<(f64, f64)> {
    model.stmts.iter().find_map(|s| match &s.kind {
        Kind::Ground { x, y } if s.name == *name => Some((x.fold()?, y.fold()?)),
        _ => None,
    })
}

/// Rule: the two known joints of a group (or the two guides of a PRP) are two
/// different points (guides), and not two ground points at the same place.
pub(super) fn distinct_joints(model: &Model, errors: &mut Diagnostics) {
    for stmt in &model.stmts {
        let (a, b, what) = match &stmt.kind {
            Kind::Rrr { a, b, .. } => (a, b, "known joints"),
            Kind::Rpr { a, b, .. } => (a, b, "points (the block's pin and the link's pivot)"),
            Kind::Actuator { a, b, .. } => {
                (a, b, "points (the link's pivot and the cylinder's base)")
            }
            Kind::Prp { g1, g2, .. } => (g1, g2, "guides"),
            _ => continue,
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
/// and a crank turns about a ground point.
pub(super) fn geometry_consistent(model: &Model, plan: &Plan, errors: &mut Diagnostics) {
    for stmt in &model.stmts {
        match &stmt.kind {
            Kind::Point { link, from, .. } => {
                if let Some(info) = plan.links.get(&link.to_string()) {
                    let f = from.to_string();
                    if !info.points.contains(&f) && plan.defined.contains_key(&f) {
                        errors.push(
                            from.span(),
                            format!(
                                "`{f}` is not a point of `{link}`; measure from one of its points: {}",
                                info.points
                                    .iter()
                                    .filter(|p| stmt.name != p.as_str())
                                    .map(|p| format!("`{p}`"))
                                    .collect::<Vec<_>>()
                                    .join(", ")
                            ),
                        );
                    }
                }
            }
            Kind::Crank { pivot, .. } => {
                let p = pivot.to_string();
                if plan.defined.contains_key(&p) && !plan.is_ground(&p) {
                    errors.push(
                        pivot.span(),
                        format!("a crank turns about a ground point, and `{p}` moves; define the pivot with `ground(x, y)`"),
                    );
                }
            }
            Kind::Guide {
                origin: Origin::Point(p),
                carrier: Some(link),
                ..
            } => {
                if let Some(info) = plan.links.get(&link.to_string()) {
                    if !info.points.contains(&p.to_string()) {
                        errors.push(
                            p.span(),
                            format!("a guide carried by `{link}` must pass through one of its points, and `{p}` is not on it"),
                        );
                    }
                }
            }
            Kind::Guide {
                origin: Origin::Point(p),
                carrier: None,
                ..
            } => {
                let name = p.to_string();
                if plan.defined.contains_key(&name) && !plan.is_ground(&name) {
                    errors.push(
                        p.span(),
                        format!("a fixed guide must pass through a ground point, and `{name}` moves; to slide on a moving link write `guide({name}, LINK)`"),
                    );
                }
            }
            _ => {}
        }
    }
}
