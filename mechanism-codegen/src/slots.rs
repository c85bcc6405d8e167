//! The compiled plan's slots laid out from the plan: which name is in which
//! slot of flat storage (`kinds::run::Layout`), and the facts by slot the
//! compiled steps read (which points move, which guides are carried, the
//! body owning each point and guide, the link whose rate each link shares,
//! each link's reference point). Built here, above the plan, so that
//! `kinds::run` does not read it; read by the expansion-time check (its
//! position walk) and by the run-time mechanism.

use crate::keys::{GuideName, InputName, PointName};
use crate::kinds::run::Layout;
use crate::model::Model;
use crate::plan::Plan;

/// The layout of `model` planned as `plan`.
pub fn layout(model: &Model, plan: &Plan) -> Layout {
    let stmts = model.stmts.len();
    let defined = plan.defined.iter().map(|(n, id)| (n.clone(), id.0));
    let inputs = model.inputs.iter().map(|i| InputName::of(&i.name));
    let mut l = Layout::with_names(stmts, plan.links.keys().cloned().collect(), defined, inputs);
    let moving = plan.moving_points(model);
    for (k, s) in model.stmts.iter().enumerate() {
        let (point, guide) = (PointName::of(&s.name), GuideName::of(&s.name));
        l.moving[k] = moving.contains(&point);
        l.carried[k] = plan.guides.get(&guide).is_some_and(|g| g.carrier.is_some());
        l.point_body[k] = plan.body_of_point(&point).map(|b| l.link_named(&b));
        l.guide_body[k] = plan.body_of_guide(&guide).map(|b| l.link_named(&b));
    }
    for (k, n) in plan.links.keys().enumerate() {
        l.turning[k] = plan.turning_link(n).map(|t| l.link_named(&t));
        let first = plan.links.get(n).and_then(|i| i.points.first());
        l.reference[k] = first.map(|p| l.point_named(p));
    }
    l
}
