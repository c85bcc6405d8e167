//! Stage 4, plan: the solve order (statements sorted by dependency), and what
//! each point, link and guide is: which link a point rides on, how each link
//! turns (its own angular velocity, a guide's, or none), which guides move.

use crate::model::{Kind, Model, Origin, Stmt};
use std::collections::BTreeMap;
use syn::Ident;

/// How a link turns.
#[derive(Clone, Debug, PartialEq)]
pub enum Turn {
    /// It never turns (a block on a fixed guide).
    None,
    /// It has its own angular velocity, found by the statement that creates it.
    Own,
    /// It turns with another link (a block on a carried guide).
    With(String),
}

/// What the plan knows of a link.
#[derive(Clone, Debug)]
pub struct LinkInfo {
    /// Statement index that creates it.
    pub stmt: usize,
    /// Position among the statement's links.
    pub index: usize,
    /// Points fixed on it.
    pub points: Vec<String>,
    /// How it turns.
    pub turn: Turn,
    /// Whether the user named it.
    pub named: bool,
}

/// What the plan knows of a guide.
#[derive(Clone, Debug)]
pub struct GuideInfo {
    /// Link carrying it (None: fixed).
    pub carrier: Option<String>,
}

/// The plan.
pub struct Plan {
    /// Statement indices in solve order.
    pub order: Vec<usize>,
    /// Statement index by defined name.
    pub defined: BTreeMap<String, usize>,
    /// Links by name.
    pub links: BTreeMap<String, LinkInfo>,
    /// Guides by name.
    pub guides: BTreeMap<String, GuideInfo>,
    /// Points on the ground.
    pub ground: Vec<String>,
    /// The link each point belongs to for the force analysis (`None`: the
    /// ground). A joint of two links belongs to the first link of the
    /// statement that defines it; see [`point_owner`].
    pub owner: BTreeMap<String, Option<String>>,
}

/// The body a statement's point belongs to when another group is pinned there:
/// ground points to the ground, a driver's joint to the driven link, a
/// group's joint to its first link (the link that reaches the point from
/// the group's first known joint), the reference point of an RPP to its
/// second link (the yoke), a link point to its link. `None` for statements
/// that define no point (guides, RPR slides).
pub fn point_owner(stmt: &Stmt) -> Option<Option<String>> {
    let link = |k: usize| Some(Some(stmt.links[k].to_string()));
    match &stmt.kind {
        Kind::Ground { .. } => Some(None),
        Kind::Guide { .. } | Kind::Rpr { .. } => None,
        Kind::Crank { .. }
        | Kind::Slider { .. }
        | Kind::Actuator { .. }
        | Kind::Rrr { .. }
        | Kind::Rrp { .. }
        | Kind::Prp { .. } => link(0),
        Kind::Rpp { .. } => link(1),
        Kind::Point { link, .. } => Some(Some(link.to_string())),
    }
}

/// Names a statement refers to (points, guides, links), with their tokens.
pub fn references(stmt: &Stmt) -> Vec<&Ident> {
    match &stmt.kind {
        Kind::Ground { .. } => vec![],
        Kind::Guide {
            origin, carrier, ..
        } => {
            let mut r = vec![];
            if let Origin::Point(p) = origin {
                r.push(p);
            }
            r.extend(carrier.iter());
            r
        }
        Kind::Crank { pivot, .. } => vec![pivot],
        Kind::Slider { guide, .. } => vec![guide],
        Kind::Actuator { a, b, .. } | Kind::Rrr { a, b, .. } | Kind::Rpr { a, b, .. } => vec![a, b],
        Kind::Rrp { a, guide, .. } | Kind::Rpp { a, guide, .. } => vec![a, guide],
        Kind::Prp { g1, g2, .. } => vec![g1, g2],
        Kind::Point { link, from, .. } => vec![link, from],
    }
}

/// The points on each link a statement creates, its first point being the
/// link's origin, and how each link turns.
fn link_shapes(stmt: &Stmt) -> Vec<(Vec<String>, Turn, Option<String>)> {
    let n = stmt.name.to_string();
    let s = |i: &Ident| i.to_string();
    match &stmt.kind {
        Kind::Crank { pivot, .. } => vec![(vec![s(pivot), n], Turn::Own, None)],
        Kind::Slider { guide, .. } => vec![(vec![n], Turn::None, Some(s(guide)))],
        Kind::Actuator { a, b, .. } | Kind::Rrr { a, b, .. } => vec![
            (vec![s(a), n.clone()], Turn::Own, None),
            (vec![s(b), n], Turn::Own, None),
        ],
        Kind::Rrp { a, guide, .. } => vec![
            (vec![s(a), n.clone()], Turn::Own, None),
            (vec![n], Turn::None, Some(s(guide))),
        ],
        Kind::Rpr { a, b, .. } => {
            vec![(vec![s(a)], Turn::Own, None), (vec![s(b)], Turn::Own, None)]
        }
        Kind::Prp { g1, g2, .. } => vec![
            (vec![n.clone()], Turn::None, Some(s(g1))),
            (vec![n], Turn::None, Some(s(g2))),
        ],
        Kind::Rpp { a, guide, .. } => vec![
            (vec![s(a)], Turn::None, Some(s(guide))),
            (vec![n], Turn::None, Some(s(guide))),
        ],
        _ => vec![],
    }
}

/// Builds the plan. Errors: dependency cycles (with the cycle spelled out).
/// Undefined names were reported by `validate`; they are skipped here.
pub fn plan(model: &Model) -> Result<Plan, Vec<syn::Error>> {
    let mut defined = BTreeMap::new();
    let mut links = BTreeMap::new();
    let mut guides = BTreeMap::new();
    let mut ground = Vec::new();
    for (i, stmt) in model.stmts.iter().enumerate() {
        defined.insert(stmt.name.to_string(), i);
        for (j, l) in stmt.links.iter().enumerate() {
            defined.insert(l.to_string(), i);
            let _ = j;
        }
        if let Kind::Ground { .. } = stmt.kind {
            ground.push(stmt.name.to_string());
        }
        if let Kind::Guide { carrier, .. } = &stmt.kind {
            guides.insert(
                stmt.name.to_string(),
                GuideInfo {
                    carrier: carrier.as_ref().map(Ident::to_string),
                },
            );
        }
    }
    // Link shapes need guide carriers resolved: Turn::None + guide -> With(carrier).
    for (i, stmt) in model.stmts.iter().enumerate() {
        for (j, (points, turn, guide)) in link_shapes(stmt).into_iter().enumerate() {
            let turn = match guide
                .and_then(|g| guides.get(&g))
                .and_then(|g| g.carrier.clone())
            {
                Some(carrier) => Turn::With(carrier),
                None => turn,
            };
            links.insert(
                stmt.links[j].to_string(),
                LinkInfo {
                    stmt: i,
                    index: j,
                    points,
                    turn,
                    named: stmt.links_named[j],
                },
            );
        }
    }
    let mut owner = BTreeMap::new();
    for stmt in &model.stmts {
        if let Some(body) = point_owner(stmt) {
            owner.insert(stmt.name.to_string(), body);
        }
    }
    for stmt in &model.stmts {
        if let Kind::Point { link, .. } = &stmt.kind {
            if let Some(info) = links.get_mut(&link.to_string()) {
                info.points.push(stmt.name.to_string());
            }
        }
    }
    // Topological sort (Kahn), stable in the written order.
    let n = model.stmts.len();
    let deps: Vec<Vec<usize>> = model
        .stmts
        .iter()
        .map(|s| {
            references(s)
                .into_iter()
                .filter_map(|r| defined.get(&r.to_string()).copied())
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
                order.push(i);
            }
            _ => {
                // Everything left waits on something left: report the cycle.
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
                let mut errors = Vec::new();
                let first = &model.stmts[cycle[0]];
                errors.push(syn::Error::new(
                    first.name.span(),
                    format!(
                        "dependency cycle: {} -> {}; each statement may use only names that do not, in turn, need it: break the cycle by fixing one of them to the ground or to a driver",
                        names.join(" -> "),
                        names[0]
                    ),
                ));
                return Err(errors);
            }
        }
    }
    Ok(Plan {
        order,
        defined,
        links,
        guides,
        ground,
        owner,
    })
}

impl Plan {
    /// The body a point belongs to (`None`: the ground or unknown).
    pub fn body_of_point(&self, point: &str) -> Option<String> {
        self.owner.get(point).cloned().flatten()
    }

    /// The body carrying a guide (`None`: the ground).
    pub fn body_of_guide(&self, guide: &str) -> Option<String> {
        self.guides.get(guide).and_then(|g| g.carrier.clone())
    }

    /// The links that have `point` among their points.
    pub fn links_with_point(&self, point: &str) -> Vec<String> {
        self.links
            .iter()
            .filter(|(_, info)| info.points.iter().any(|p| p == point))
            .map(|(name, _)| name.clone())
            .collect()
    }

    /// `true` when a point never moves.
    pub fn is_ground(&self, point: &str) -> bool {
        self.ground.iter().any(|g| g == point)
    }

    /// The link whose angular velocity a link shares (itself, another link, or
    /// none when it never turns).
    pub fn turning_link(&self, link: &str) -> Option<String> {
        let mut at = link.to_string();
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
