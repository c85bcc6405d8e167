//! What a drawing of the run-time mechanism needs: its named points and
//! moving links with their kinds (the `mechanism::structure::Structure`
//! the generated code describes itself with, owned), and, at a solved
//! pose, any point, guide or link direction by name.

use super::{Mechanism, Position};
use crate::keys::{GuideName, LinkName, PointName};
use crate::kinds;
use mechanism_core::geometry;
pub use mechanism_core::structure::{LinkKind, PointKind};

/// A named point of the definition.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LayoutPoint {
    /// Its name.
    pub name: String,
    /// Ground, a joint a driver or group finds, or a point fixed on a link.
    pub kind: PointKind,
}

/// A moving link of the definition.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LayoutLink {
    /// Its name (the user's, or the one the macro gives an unnamed link).
    pub name: String,
    /// Crank, bar (or plate), block, cylinder.
    pub kind: LinkKind,
    /// The named points fixed on it.
    pub points: Vec<String>,
    /// The guide a block slides on.
    pub guide: Option<String>,
}

/// A guide of the definition.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LayoutGuide {
    /// Its name.
    pub name: String,
    /// The link carrying it (`None`: fixed to the ground).
    pub carrier: Option<String>,
}

/// The points, links and guides, in solve order, and the length unit's name.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Layout {
    /// Every named point.
    pub points: Vec<LayoutPoint>,
    /// Every moving link.
    pub links: Vec<LayoutLink>,
    /// Every guide.
    pub guides: Vec<LayoutGuide>,
    /// The definition's length unit (`units { length = .. }`; `L` without).
    pub length_unit: String,
}

/// The point kind `GroupKind::point_kind` names.
fn point_kind(name: &str) -> PointKind {
    match name {
        "Ground" => PointKind::Ground,
        "OnLink" => PointKind::OnLink,
        _ => PointKind::Joint,
    }
}

/// The link kind `GroupKind::link_kind` names.
fn link_kind(name: &str) -> LinkKind {
    match name {
        "Crank" => LinkKind::Crank,
        "Block" => LinkKind::Block,
        "Cylinder" => LinkKind::Cylinder,
        _ => LinkKind::Bar,
    }
}

impl Mechanism {
    /// The points and links, as the generated `Structure` lists them.
    pub fn layout(&self) -> Layout {
        let mut points = Vec::new();
        let mut links = Vec::new();
        for &i in &self.plan.order {
            let stmt = &self.model.stmts[i];
            let kind = kinds::of(stmt);
            if let Some(k) = kind.point_kind() {
                points.push(LayoutPoint {
                    name: stmt.name.to_string(),
                    kind: point_kind(k),
                });
            }
            for (j, l) in stmt.links.iter().enumerate() {
                let Some(info) = self.plan.links.get(&LinkName::of(l)) else {
                    continue;
                };
                links.push(LayoutLink {
                    name: l.to_string(),
                    kind: match &info.guide {
                        Some(_) => LinkKind::Block,
                        None => link_kind(kind.link_kind(j)),
                    },
                    points: info.points.iter().map(ToString::to_string).collect(),
                    guide: info.guide.as_ref().map(ToString::to_string),
                });
            }
        }
        let guides = self
            .plan
            .guides
            .iter()
            .map(|(name, g)| LayoutGuide {
                name: name.to_string(),
                carrier: g.carrier.as_ref().map(ToString::to_string),
            })
            .collect();
        Layout {
            points,
            links,
            guides,
            length_unit: self.model.units.length.clone(),
        }
    }

    /// The direction of link `link` at `pos` (rad, counter-clockwise from
    /// +x): its axis, a block's along its guide. `None`: no such link.
    pub fn link_direction(&self, pos: &Position, link: &str) -> Option<f64> {
        let info = self.plan.links.get(&LinkName::new(link))?;
        let step = self.solver.compiled.steps.get(info.stmt.0)?;
        let d = step.link_dir(info.index, &pos.pose);
        let a = geometry::angle(&d);
        a.is_finite().then_some(a)
    }
}

impl Position {
    /// Point `name` (L); `None` when the definition has no such point.
    pub fn point(&self, name: &str) -> Option<[f64; 2]> {
        let p = self
            .pose
            .point(self.slots.point_named(&PointName::new(name)));
        (p.x.is_finite() && p.y.is_finite()).then_some([p.x, p.y])
    }

    /// Guide `name`: a point of its line (L) and its direction (rad);
    /// `None` when the definition has no such guide.
    pub fn guide(&self, name: &str) -> Option<([f64; 2], f64)> {
        let line = self
            .pose
            .line(self.slots.guide_named(&GuideName::new(name)));
        let a = line.dir.y.atan2(line.dir.x);
        let ok = line.origin.x.is_finite() && line.origin.y.is_finite() && a.is_finite();
        ok.then_some(([line.origin.x, line.origin.y], a))
    }

    /// The input values this pose was solved at (rad, L).
    pub fn inputs(&self) -> &[f64] {
        let n = self.pose.q.len().saturating_sub(1);
        &self.pose.q[..n]
    }
}
