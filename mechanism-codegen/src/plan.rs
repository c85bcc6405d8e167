//! Stage 4, plan: the solve order (statements sorted by dependency), and what
//! each point, link and guide is: which link a point rides on, how each link
//! turns (its own angular velocity, a guide's, or none), which guides move.

use crate::diag::Diagnostics;
use crate::keys::{GuideName, LinkName, Name, PointName};
use crate::kinds::{self, LinkShape};
use crate::model::{ForceSpecValue, Model, Stmt, StmtId};
use std::collections::{BTreeMap, BTreeSet};
use syn::Ident;

pub use crate::kinds::Turn;

/// What the plan knows of a link.
#[derive(Clone, Debug)]
pub struct LinkInfo {
    /// The statement that creates it.
    pub stmt: StmtId,
    /// Position among the statement's links.
    pub index: usize,
    /// Points fixed on it.
    pub points: Vec<PointName>,
    /// How it turns.
    pub turn: Turn,
    /// Whether the user named it.
    pub named: bool,
    /// The guide it slides on (a block), if any.
    pub guide: Option<GuideName>,
}

/// What the plan knows of a guide.
#[derive(Clone, Debug)]
pub struct GuideInfo {
    /// Link carrying it (None: fixed).
    pub carrier: Option<LinkName>,
}

/// The plan.
pub struct Plan {
    /// The statements in solve order.
    pub order: Vec<StmtId>,
    /// The statement defining each name.
    pub defined: BTreeMap<Name, StmtId>,
    /// Links by name.
    pub links: BTreeMap<LinkName, LinkInfo>,
    /// Guides by name.
    pub guides: BTreeMap<GuideName, GuideInfo>,
    /// Points on the ground.
    pub ground: Vec<PointName>,
    /// The link each point belongs to for the force analysis (`None`: the
    /// ground). A joint of two links belongs to the first link of the
    /// statement that defines it; see [`point_owner`].
    pub owner: BTreeMap<PointName, Option<LinkName>>,
    /// What the definition asks to see: its outputs.
    pub outputs: Outputs,
    /// The statements the outputs and the force analysis need, in solve
    /// order: what `position()` solves (a coupler point nobody asked for is
    /// left out).
    pub solve: Vec<StmtId>,
}

/// The body a statement's point belongs to when another group is pinned there:
/// ground points to the ground, a driver's joint to the driven link, a
/// group's joint to its first link (the link that reaches the point from
/// the group's first known joint), the reference point of an RPP to its
/// second link (the yoke), a link point to its link. `None` for statements
/// that define no point (guides, RPR slides). Each kind says which
/// (`kinds::GroupKind::point_owner`).
pub fn point_owner(stmt: &Stmt) -> Option<Option<LinkName>> {
    kinds::of(stmt).point_owner()
}

/// Names a statement refers to (points, guides, links), with their tokens.
pub fn references(stmt: &Stmt) -> Vec<&Ident> {
    kinds::of(stmt)
        .references()
        .into_iter()
        .map(|(r, _)| r)
        .collect()
}

/// Builds the plan. Errors: dependency cycles (with the cycle spelled out).
/// Undefined names were reported by `validate`; they are skipped here.
pub fn plan(model: &Model, errors: &mut Diagnostics) -> Option<Plan> {
    let mut defined = BTreeMap::new();
    let mut links = BTreeMap::new();
    let mut guides = BTreeMap::new();
    let mut ground = Vec::new();
    for (id, stmt) in StmtId::all(&model.stmts).zip(&model.stmts) {
        defined.insert(Name::of(&stmt.name), id);
        for l in &stmt.links {
            defined.insert(Name::of(l), id);
        }
        let kind = kinds::of(stmt);
        if kind.point_owner() == Some(None) {
            ground.push(PointName::of(&stmt.name));
        }
        if let Some(carrier) = kinds::guide_carrier(stmt) {
            guides.insert(
                GuideName::of(&stmt.name),
                GuideInfo {
                    carrier: carrier.map(LinkName::of),
                },
            );
        }
    }
    // Link shapes need guide carriers resolved: Turn::None + guide -> With(carrier).
    for (id, stmt) in StmtId::all(&model.stmts).zip(&model.stmts) {
        for (j, shape) in kinds::of(stmt).link_shapes().into_iter().enumerate() {
            let LinkShape {
                points,
                turn,
                guide,
            } = shape;
            let turn = match guide
                .as_ref()
                .and_then(|g| guides.get(g))
                .and_then(|g| g.carrier.clone())
            {
                Some(carrier) => Turn::With(carrier),
                None => turn,
            };
            links.insert(
                LinkName::of(&stmt.links[j]),
                LinkInfo {
                    stmt: id,
                    index: j,
                    points,
                    turn,
                    named: stmt.links_named[j],
                    guide,
                },
            );
        }
    }
    let mut owner = BTreeMap::new();
    for stmt in &model.stmts {
        if let Some(body) = point_owner(stmt) {
            owner.insert(PointName::of(&stmt.name), body);
        }
    }
    for stmt in &model.stmts {
        if let Some(link) = kinds::on_link(stmt) {
            if let Some(info) = links.get_mut(&LinkName::of(link)) {
                info.points.push(PointName::of(&stmt.name));
            }
        }
    }
    // Topological sort (Kahn), stable in the written order, on the
    // statements' places (`StmtId::0`).
    let n = model.stmts.len();
    let deps: Vec<Vec<usize>> = model
        .stmts
        .iter()
        .map(|s| {
            references(s)
                .into_iter()
                .filter_map(|r| defined.get(&Name::of(r)).map(|d: &StmtId| d.0))
                .collect()
        })
        .collect();
    let mut done = vec![false; n];
    let mut order = Vec::with_capacity(n);
    while order.len() < n {
        let next = (0..n).find(|&i| !done[i] && deps[i].iter().all(|&d| done[d] || d == i));
        match next {
            Some(i) if !deps[i].contains(&i) => {
                done[i] = true;
                order.push(StmtId(i));
            }
            _ => {
                // Everything left waits on something left: report the cycle,
                // unless an error is already reported (a duplicate name reads
                // as a statement that needs itself: a follow-on, not a cycle).
                if !errors.is_empty() {
                    return None;
                }
                let left: Vec<usize> = (0..n).filter(|&i| !done[i]).collect();
                let start = left[0];
                let mut cycle = vec![start];
                let mut at = start;
                while let Some(&d) = deps[at].iter().find(|d| !done[**d]) {
                    if let Some(pos) = cycle.iter().position(|&c| c == d) {
                        cycle.drain(..pos);
                        break;
                    }
                    cycle.push(d);
                    at = d;
                }
                let names: Vec<String> = cycle
                    .iter()
                    .map(|&i| model.stmts[i].name.to_string())
                    .collect();
                let first = &model.stmts[cycle[0]];
                let stmts: Vec<&Stmt> = cycle.iter().map(|&i| &model.stmts[i]).collect();
                let fix = kinds::of(first).cycle_hint(&stmts).unwrap_or_else(|| {
                    "each statement may use only names that do not, in turn, need it: break the cycle by fixing one of them to the ground or to a driver".into()
                });
                errors.error(syn::Error::new(
                    first.name.span(),
                    format!(
                        "dependency cycle: {} -> {}; {fix}",
                        names.join(" -> "),
                        names[0]
                    ),
                ));
                return None;
            }
        }
    }
    let mut plan = Plan {
        order,
        defined,
        links,
        guides,
        ground,
        owner,
        outputs: Outputs::default(),
        solve: Vec::new(),
    };
    plan.outputs = outputs(model, &plan);
    let needed = needed_statements(model, &plan, &plan.outputs);
    plan.solve = plan
        .order
        .iter()
        .copied()
        .filter(|i| needed.contains(i))
        .collect();
    Some(plan)
}

impl Plan {
    /// The body a point belongs to (`None`: the ground or unknown).
    pub fn body_of_point(&self, point: &PointName) -> Option<LinkName> {
        self.owner.get(point).cloned().flatten()
    }

    /// The body carrying a guide (`None`: the ground).
    pub fn body_of_guide(&self, guide: &GuideName) -> Option<LinkName> {
        self.guides.get(guide).and_then(|g| g.carrier.clone())
    }

    /// The links that have `point` among their points.
    pub fn links_with_point(&self, point: &PointName) -> Vec<LinkName> {
        self.links
            .iter()
            .filter(|(_, info)| info.points.contains(point))
            .map(|(name, _)| name.clone())
            .collect()
    }

    /// `true` when a point never moves.
    pub fn is_ground(&self, point: &PointName) -> bool {
        self.ground.contains(point)
    }

    /// The link whose angular velocity a link shares (itself, another link, or
    /// none when it never turns).
    pub fn turning_link(&self, link: &LinkName) -> Option<LinkName> {
        let mut at = link.clone();
        for _ in 0..64 {
            match &self.links.get(&at)?.turn {
                Turn::None => return None,
                Turn::Own => return Some(at),
                Turn::With(other) => at = other.clone(),
            }
        }
        None
    }
}

impl kinds::Placed for Plan {
    fn link_points(&self, link: &Ident) -> Option<&[PointName]> {
        self.links
            .get(&LinkName::of(link))
            .map(|l| l.points.as_slice())
    }

    fn is_defined(&self, name: &Ident) -> bool {
        self.defined.contains_key(&Name::of(name))
    }

    fn is_ground_point(&self, point: &PointName) -> bool {
        self.is_ground(point)
    }

    fn links_with_point(&self, point: &PointName) -> Vec<LinkName> {
        Plan::links_with_point(self, point)
    }
}

/// A slide displacement the user named: its name, the statement that
/// solves it and which of the statement's slides it is (0 or 1; an RPR's
/// slide is its defined name, slot 0).
#[derive(Clone, Debug)]
pub struct Slide {
    /// The user's name (a field of the output structs).
    pub name: Ident,
    /// The statement (index into `Model::stmts`).
    pub stmt: StmtId,
    /// Which of the statement's slides.
    pub slot: usize,
}

/// Which names the user wants in the output structs.
#[derive(Default)]
pub struct Outputs {
    /// Points, in solve order.
    pub points: Vec<Ident>,
    /// Named links, in solve order.
    pub links: Vec<Ident>,
    /// Slide displacements.
    pub slides: Vec<Slide>,
}

fn outputs(model: &Model, plan: &Plan) -> Outputs {
    let wanted = |name: &Ident| match &model.outputs {
        None => true,
        Some(list) => list.iter().any(|o| o == name),
    };
    let mut out = Outputs {
        points: vec![],
        links: vec![],
        slides: vec![],
    };
    for &i in &plan.order {
        let stmt = &model.stmts[i];
        let kind = kinds::of(stmt);
        if kind.names_slide() && wanted(&stmt.name) {
            out.slides.push(Slide {
                name: stmt.name.clone(),
                stmt: i,
                slot: 0,
            });
        } else if kind.point_kind().is_some() && wanted(&stmt.name) {
            out.points.push(stmt.name.clone());
        }
        for (link, named) in stmt.links.iter().zip(&stmt.links_named) {
            if *named && wanted(link) {
                out.links.push(link.clone());
            }
        }
        for (slot, slide) in stmt.slides.iter().enumerate() {
            if let Some(s) = slide {
                if wanted(s) {
                    out.slides.push(Slide {
                        name: s.clone(),
                        stmt: i,
                        slot,
                    });
                }
            }
        }
    }
    out
}

/// Statements the outputs need, directly or through the statements they use.
/// The rest (a coupler point nobody asked for) is left out.
fn needed_statements(model: &Model, plan: &Plan, out: &Outputs) -> BTreeSet<StmtId> {
    let mut stack: Vec<StmtId> = roots(model, plan);
    for p in &out.points {
        stack.extend(plan.defined.get(&Name::of(p)));
    }
    for l in &out.links {
        stack.extend(plan.links.get(&LinkName::of(l)).map(|i| i.stmt));
    }
    stack.extend(out.slides.iter().map(|s| s.stmt));
    let mut needed = BTreeSet::new();
    while let Some(i) = stack.pop() {
        if needed.insert(i) {
            for r in references(&model.stmts[i]) {
                stack.extend(plan.defined.get(&Name::of(r)));
            }
        }
    }
    needed
}

/// Statements the force analysis needs besides those of the outputs: every
/// statement that creates a link (all reactions are outputs), the centres of
/// mass, the points where forces act and the guides forces follow.
fn roots(model: &Model, plan: &Plan) -> Vec<StmtId> {
    if !model.has_forces() {
        return Vec::new();
    }
    let k = &model.kinetics;
    let mut roots: Vec<StmtId> = StmtId::all(&model.stmts)
        .filter(|&i| !model.stmts[i].links.is_empty())
        .collect();
    let named = k
        .masses
        .iter()
        .map(|m| Name::of(&m.at))
        .chain(k.forces.iter().map(|f| Name::of(&f.at)))
        .chain(k.forces.iter().filter_map(|f| match &f.value {
            ForceSpecValue::Along(g, _) => Some(Name::of(g)),
            ForceSpecValue::Components(..) => None,
        }));
    roots.extend(named.filter_map(|n| plan.defined.get(&n).copied()));
    roots
}

/// The statements the generated `position()` solves (those the outputs
/// need), in solve order, and among them the checked groups.
pub struct Checked {
    /// The statements in solve order.
    pub order: Vec<StmtId>,
    /// The checked groups among them (drivers, groups, link points).
    pub groups: Vec<StmtId>,
}

/// The statements `position()` solves and the checked groups among them.
pub fn checked(model: &Model, plan: &Plan) -> Checked {
    let order = plan.solve.clone();
    let groups = order
        .iter()
        .copied()
        .filter(|&i| crate::model::group_kind(&model.stmts[i].kind).is_some())
        .collect();
    Checked { order, groups }
}

impl Plan {
    /// Points that move (everything but ground points and points on still
    /// links measured from still points), in solve order's terms: a point
    /// moves when its kind says so of the links and points it is found
    /// from.
    pub fn moving_points(&self, model: &Model) -> BTreeSet<PointName> {
        let mut moving: BTreeSet<PointName> = BTreeSet::new();
        for &i in &self.solve {
            let stmt = &model.stmts[i];
            let link_turns = |l: &Ident| self.turning_link(&LinkName::of(l)).is_some();
            let moves = |p: &Ident| moving.contains(&PointName::of(p));
            if kinds::of(stmt).point_moves(&link_turns, &moves) {
                moving.insert(PointName::of(&stmt.name));
            }
        }
        moving
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{model, validate};

    /// The model and plan of the definition `src` (which must be valid).
    fn planned(src: &str) -> (Model, Plan) {
        let def = syn::parse_str::<crate::parse::Definition>(src).unwrap();
        let mut diag = Diagnostics::new();
        let model = model::lower(def, &mut diag);
        validate::model(&model, &mut diag);
        let plan = plan(&model, &mut diag);
        let errors: Vec<String> = diag.finish().iter().map(ToString::to_string).collect();
        assert!(errors.is_empty(), "{errors:?}");
        (model, plan.expect("a plan"))
    }

    /// The names of the statements `order` (indices) of `model`.
    fn names(model: &Model, order: &[StmtId]) -> Vec<String> {
        order
            .iter()
            .map(|&i| model.stmts[i].name.to_string())
            .collect()
    }

    /// A four-bar with a coupler point `P`, its statements in the order
    /// written, and `extra` after them.
    fn four_bar(extra: &str) -> String {
        format!(
            "pub M {{
                let O2 = ground(0.0, 0.0);
                let O4 = ground(4.0, 0.0);
                let A = crank(O2, 1.0, theta) as link2;
                let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
                let P = point(link3, from A, 1.0, 30 deg);
                {extra}
            }}"
        )
    }

    #[test]
    fn statements_written_out_of_order_are_solved_in_dependency_order() {
        // Proves the solve order puts each statement after those it uses,
        // keeping the written order among the ready ones (`O4` before `O2`).
        let (model, plan) = planned(
            "pub M {
                let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
                let A = crank(O2, 1.0, theta) as link2;
                let O4 = ground(4.0, 0.0);
                let O2 = ground(0.0, 0.0);
            }",
        );
        assert_eq!(names(&model, &plan.order), ["O4", "O2", "A", "B"]);
        assert_eq!(names(&model, &plan.solve), ["O4", "O2", "A", "B"]);
    }

    #[test]
    fn a_joint_belongs_to_the_first_link_of_its_group() {
        // Proves the owners: a ground point to the ground, a crank's joint to
        // the crank, a group's joint to its first link, a link point to its
        // link; and the points each link carries.
        let (_, plan) = planned(&four_bar(""));
        let owner = |p: &str| plan.owner.get(&PointName::new(p)).cloned();
        let link = |l: &str| Some(Some(LinkName::new(l)));
        assert_eq!(owner("O2"), Some(None));
        assert_eq!(owner("A"), link("link2"));
        assert_eq!(owner("B"), link("link3"));
        assert_eq!(owner("P"), link("link3"));
        assert_eq!(plan.links[&LinkName::new("link3")].points, ["A", "B", "P"]);
        assert_eq!(plan.links[&LinkName::new("link4")].points, ["O4", "B"]);
        assert_eq!(
            plan.links_with_point(&PointName::new("B")),
            ["link3", "link4"]
        );
        assert!(plan.is_ground(&PointName::new("O4")) && !plan.is_ground(&PointName::new("A")));
    }

    #[test]
    fn solve_leaves_out_a_coupler_point_nobody_needs() {
        // Proves `solve` holds what the outputs need: without `P` among the
        // outputs its statement is left out, with it (or with a mass at it,
        // for the force analysis) it is solved.
        let (model, plan) = planned(&four_bar("outputs { B }"));
        assert_eq!(names(&model, &plan.solve), ["O2", "O4", "A", "B"]);
        assert_eq!(names(&model, &plan.order), ["O2", "O4", "A", "B", "P"]);
        let (model, plan) = planned(&four_bar("outputs { P }"));
        assert_eq!(names(&model, &plan.solve), ["O2", "O4", "A", "B", "P"]);
        let (model, plan) = planned(&four_bar("outputs { B } mass link3 { m = 1.0, at = P }"));
        assert_eq!(names(&model, &plan.solve), ["O2", "O4", "A", "B", "P"]);
    }

    #[test]
    fn a_dependency_cycle_is_spelled_out() {
        // Proves two groups that need each other get no plan but the error
        // naming the cycle, on the first statement of it.
        let def = syn::parse_str::<crate::parse::Definition>(
            "pub M {
                let O = ground(0.0, 0.0);
                let A = crank(O, 1.0, theta) as link2;
                let B = rrr(A, 1.0, C, 1.0, left) as (link3, link4);
                let C = rrr(B, 1.0, O, 1.0, left) as (link5, link6);
            }",
        )
        .unwrap();
        let mut diag = Diagnostics::new();
        let model = model::lower(def, &mut diag);
        assert!(plan(&model, &mut diag).is_none());
        let errors = diag.finish();
        assert_eq!(errors.len(), 1);
        assert_eq!(
            errors[0].to_string(),
            "dependency cycle: B -> C -> B; each statement may use only names that do not, in turn, need it: break the cycle by fixing one of them to the ground or to a driver"
        );
        assert_eq!(errors[0].span().start().line, 4);
    }
}
