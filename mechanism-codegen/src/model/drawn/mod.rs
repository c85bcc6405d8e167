//! The drawn form of a definition: the joints where the drawing has them
//! (the reference pose), the links as sets of joints (the fixed one named
//! `ground`) and the inputs (a link's angle from the ground, or from the link
//! that carries its motor, a block's slide, a cylinder's length), the blocks
//! sliding on the ground or in slots of moving links (`slider B at J on LINK
//! along angle`), the cylinders (`cylinder C from J1 to J2`) and the gear
//! pairs (`gear L to MESH ratio R`). It is decomposed into the group
//! statements (`ground`, `guide`, `crank`, `slider`, `actuator`, `target`,
//! `gear`, `rrr`, `rrp`, `rpr`, `rpp`, `prp`, `triad`, `point`)
//! a user would write by hand,
//! in solve order, every length, offset and assembly mode read from the
//! drawing; the rest of the macro sees only those statements.
//!
//! Stages, each looking only forward: [`read`] (the items into a
//! [`Drawing`]), [`decompose`] (its structure and count of freedoms checked
//! by the drawing's [`rules`], then the solve order as [`steps::Step`]s, the
//! next group each time found by [`groups`]), [`emit`] (each step as the
//! `let` statement a user would write).

mod decompose;
mod emit;
mod exprs;
mod gear;
mod groups;
mod modes;
mod read;
mod rules;
mod steps;

use super::args::NumberScope;
use super::{Failed, FailedKind, Mode};
use crate::diag::Diagnostics;
use crate::parse::Item;
use proc_macro2::Span;
use syn::{Expr, Ident};

/// The name of the fixed link.
use crate::keys::GROUND;

/// A joint of the drawing, by its place in [`Drawing::joints`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct JointId(usize);

/// A link of the drawing, by its place in [`Drawing::links`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct LinkId(usize);

/// An input of the drawing, by its place in [`Drawing::inputs`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct InputId(usize);

/// A joint of the drawing: its name, its coordinates as written and their
/// values at the parameters' defaults (length units).
struct Joint {
    name: Ident,
    x: Expr,
    y: Expr,
    at: (f64, f64),
}

/// A link of the drawing: its name and its joints, in the order written.
struct Link {
    name: Ident,
    joints: Vec<JointId>,
}

/// An input of the drawing: `angle(link)` or `angle(link, carrier)`, or
/// `slide(block)` (`slide`: the block's displacement along its line, from
/// its drawn place), or a joint's coordinate, `J.x` or `J.y` (`coordinate`;
/// `link` is then the joint's name): inverse kinematics.
struct Input {
    name: Ident,
    link: Ident,
    carrier: Option<Ident>,
    slide: bool,
    coordinate: Option<Coordinate>,
    /// `length(cylinder)`: the cylinder's length (`link` names the cylinder).
    length: bool,
}

/// Which coordinate of a joint an input is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Coordinate {
    X,
    Y,
}

/// A block of the drawing: its link (whose one joint is `at`), and its line
/// through `at`'s drawn place at `angle` (absolute, counter-clockwise from
/// +x; `unit` `deg` or radians), the direction's value at the parameters'
/// defaults; `on`: the moving link whose slot that line is (`None`: the
/// ground).
struct Slider {
    link: LinkId,
    at: JointId,
    angle: Expr,
    unit: Option<Ident>,
    dir: (f64, f64),
    on: Option<LinkId>,
}

/// A cylinder of the drawing (`cylinder CYL from B to C;`): its barrel is
/// pinned at joint `from`, its rod at joint `to`; `names`: the cylinder as
/// one link, or its barrel and its rod.
struct Cylinder {
    names: Vec<Ident>,
    from: JointId,
    to: JointId,
}

/// The drawing, read.
struct Drawing {
    joints: Vec<Joint>,
    links: Vec<Link>,
    inputs: Vec<Input>,
    sliders: Vec<Slider>,
    cylinders: Vec<Cylinder>,
    gears: Vec<gear::Gear>,
    /// Where to point a message about the whole drawing (the `links` keyword).
    span: Span,
}

impl Drawing {
    fn joint(&self, j: JointId) -> &Joint {
        &self.joints[j.0]
    }

    fn link(&self, l: LinkId) -> &Link {
        &self.links[l.0]
    }

    fn input(&self, i: InputId) -> &Input {
        &self.inputs[i.0]
    }

    fn link_ids(&self) -> impl Iterator<Item = LinkId> {
        (0..self.links.len()).map(LinkId)
    }

    fn input_ids(&self) -> impl Iterator<Item = InputId> {
        (0..self.inputs.len()).map(InputId)
    }

    /// The link named `name`.
    fn link_named(&self, name: &Ident) -> Option<LinkId> {
        self.links.iter().position(|l| &l.name == name).map(LinkId)
    }

    /// The slider whose block is `l`.
    fn slider_of(&self, l: LinkId) -> Option<&Slider> {
        self.sliders.iter().find(|s| s.link == l)
    }

    /// The cylinder named `name` (its one name, or its barrel's).
    fn cylinder_named(&self, name: &Ident) -> Option<usize> {
        self.cylinders.iter().position(|c| &c.names[0] == name)
    }

    /// The fixed link.
    fn ground(&self) -> Option<LinkId> {
        self.links.iter().position(|l| l.name == GROUND).map(LinkId)
    }
}

/// Replaces the drawn form's items (`joints`, `links`, `input`) by the group
/// statements they decompose into, placed where the first of them stood;
/// the other items are kept in order. Without a drawn item, `items` comes
/// back as it was. When the drawing is rejected (errors reported), its
/// names come back as failed statements, so that nothing else is blamed
/// for them (a missing driver, an unknown link in a `mass`). The drawing's
/// `mode` statements come back as run-time mode parameters with their
/// defaults (the drawn assemblies), their groups reading them.
pub(super) fn expand(
    items: Vec<Item>,
    scope: &NumberScope<'_>,
    errors: &mut Diagnostics,
) -> (Vec<Item>, Vec<Failed>, Vec<(Ident, Mode)>) {
    let (mode_items, items): (Vec<Item>, Vec<Item>) =
        items.into_iter().partition(|i| matches!(i, Item::Mode(..)));
    let drawn_modes: Vec<modes::DrawnMode> = mode_items
        .into_iter()
        .filter_map(|i| match i {
            Item::Mode(name, at) => Some(modes::DrawnMode { name, at }),
            _ => None,
        })
        .collect();
    let drawn = |i: &Item| {
        matches!(
            i,
            Item::Joints(..)
                | Item::Links(..)
                | Item::Input(..)
                | Item::Slider(..)
                | Item::Cylinder(..)
                | Item::Gear(..)
        )
    };
    let Some(first) = items.iter().position(drawn) else {
        for m in &drawn_modes {
            errors.push(m.name.span(), format!("`mode {} = assembly(..)` belongs to the drawn form (`joints`, `links`, `input`); with group statements, write `params {{ {} = left }}` and the name in the group's mode place, `rrr(A, l1, B, l2, {})`", m.name, m.name, m.name));
        }
        return (items, Vec::new(), Vec::new());
    };
    let (drawing_items, mut rest): (Vec<Item>, Vec<Item>) = items.into_iter().partition(drawn);
    let before = errors.len();
    let drawing = read::read(drawing_items, scope, errors);
    let steps = if errors.len() > before {
        None
    } else {
        decompose::decompose(&drawing, errors)
    };
    let Some(steps) = steps else {
        // The names stay parameters (without a group), so that code reading
        // them reports nothing more.
        let modes = drawn_modes.into_iter().map(|m| (m.name, Mode::Plus));
        return (rest, failed(&drawing), modes.collect());
    };
    let mut lets: Vec<_> = steps.iter().map(|s| emit::statement(&drawing, s)).collect();
    let modes = modes::attach(&mut lets, &drawn_modes, errors);
    let at = first.min(rest.len());
    rest.splice(at..at, lets.into_iter().map(Item::Let));
    (rest, Vec::new(), modes)
}

/// The drawing's names as failed statements: its joints, its links, its
/// inputs (each a driver).
fn failed(d: &Drawing) -> Vec<Failed> {
    let none = |name: &Ident, kind: FailedKind| Failed {
        name: name.clone(),
        kind,
        links: Vec::new(),
        slides: Vec::new(),
        inputs: Vec::new(),
    };
    let mut out: Vec<Failed> = d
        .joints
        .iter()
        .map(|j| none(&j.name, FailedKind::DrawnJoint))
        .collect();
    out.extend(d.links.iter().map(|l| Failed {
        links: vec![l.name.clone()],
        ..none(&l.name, FailedKind::DrawnLink)
    }));
    // A coordinate input's joint has its effector link (`J_effector`).
    let effectors = d.joints.iter().filter(|j| {
        d.inputs
            .iter()
            .any(|i| i.coordinate.is_some() && i.link == j.name)
    });
    out.extend(effectors.map(|j| Failed {
        links: vec![emit::effector(j)],
        ..none(&emit::effector(j), FailedKind::DrawnLink)
    }));
    out.extend(d.cylinders.iter().map(|c| Failed {
        links: c.names.clone(),
        ..none(&c.names[0], FailedKind::DrawnCylinder)
    }));
    out.extend(d.inputs.iter().map(|i| Failed {
        inputs: vec![i.name.clone()],
        ..none(&i.name, FailedKind::DrawnInput)
    }));
    out
}
