//! Stage 2, model: the parse tree lowered into typed statements. Arguments are
//! checked for arity, role (point, guide, link, number, mode) and literal
//! positivity here; names are resolved across statements in `validate`.
//!
//! This file holds the typed model; the lowering is in [`lower`] (the
//! definition's phases), `kinds` (one function per statement kind), `args`
//! (reading arguments by role, numbers and their scope), `kinetics` (masses
//! and loads) and `inputs` (input ranges and allowances).

mod args;
mod inputs;
mod kinds;
mod kinetics;
mod lower;

pub use inputs::{Allowed, Input, RangeSpans};
pub use lower::lower;

use crate::value::Value;
use proc_macro2::Span;
use std::collections::BTreeMap;
use syn::{Attribute, Ident, LitInt, Visibility};

/// How far the generated code goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Level {
    /// `position` only.
    Position,
    /// `position` and `velocity`.
    Velocity,
    /// `position`, `velocity`, `acceleration` (the default without loads).
    Acceleration,
    /// Everything, and the force analysis (the default with loads).
    Forces,
}

/// Assembly mode as written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// `plus` / `left`: m = +1.
    Plus,
    /// `minus` / `right`: m = -1.
    Minus,
}

/// A whole mechanism.
pub struct Model {
    /// Doc comments of the definition.
    pub docs: Vec<Attribute>,
    /// Visibility of the generated items.
    pub vis: Visibility,
    /// Type name.
    pub name: Ident,
    /// Run-time parameters with their (folded) default values.
    pub params: Vec<(Ident, f64)>,
    /// Compile-time constants (folded).
    pub consts: BTreeMap<String, (Ident, f64)>,
    /// `let` statements, in the order written.
    pub stmts: Vec<Stmt>,
    /// Requested analysis level and the token that asked.
    pub level: Level,
    /// Span of the `analysis` statement's value.
    pub level_span: Option<Span>,
    /// Requested outputs (`None`: everything named).
    pub outputs: Option<Vec<Ident>>,
    /// Declared mobility.
    pub dof: Option<LitInt>,
    /// Statements whose arguments were rejected: their names stay defined.
    pub failed: Vec<Failed>,
    /// Masses, gravity and loads (the force analysis).
    pub kinetics: Kinetics,
    /// The driver inputs, in the order of the generated input struct, with
    /// the ranges the checks sweep.
    pub inputs: Vec<Input>,
    /// The groups whose singular positions are allowed (`allow singular`).
    pub allowed: Allowed,
    /// `#[self_test]`: the span of the attribute.
    pub self_test: Option<Span>,
    /// A statement's kind is unknown (reported): no other statement is
    /// blamed for what it would have defined (a missing driver, say).
    pub unknown_kinds: bool,
}

/// What the force analysis needs: masses, gravity and external loads.
#[derive(Default)]
pub struct Kinetics {
    /// `mass LINK { m, at, j }`.
    pub masses: Vec<MassSpec>,
    /// `gravity (gx, gy)`, with the span of the keyword.
    pub gravity: Option<(Span, Value, Value)>,
    /// `force at P ...`.
    pub forces: Vec<ForceSpec>,
    /// `torque on LINK = t`.
    pub torques: Vec<TorqueSpec>,
    /// `loads { name = default }`: values supplied per evaluation.
    pub loads: Vec<(Ident, f64)>,
    /// A load statement was written (even one that was rejected).
    pub declared: bool,
}

/// Mass properties of one link.
pub struct MassSpec {
    /// The link.
    pub link: Ident,
    /// Mass (M).
    pub mass: Value,
    /// Centre of mass: a point of the link.
    pub at: Ident,
    /// Moment of inertia about the centre of mass (M L^2); `None`: a point mass.
    pub inertia: Option<Value>,
}

/// An external force.
pub struct ForceSpec {
    /// Point of application.
    pub at: Ident,
    /// The link it acts on (`None`: the only link that has the point).
    pub on: Option<Ident>,
    /// The force.
    pub value: ForceSpecValue,
}

/// The value of an external force.
pub enum ForceSpecValue {
    /// Global components (force units).
    Components(Value, Value),
    /// Signed magnitude along a guide's unit direction.
    Along(Ident, Value),
}

/// An external couple on a link (force x length, counter-clockwise positive).
pub struct TorqueSpec {
    /// The link.
    pub on: Ident,
    /// The couple.
    pub value: Value,
}

impl Model {
    /// `true` when the definition asks for the force analysis.
    pub fn has_forces(&self) -> bool {
        self.level == Level::Forces
    }
}

/// A statement whose arguments were rejected (an error is already reported).
pub struct Failed {
    /// The name it defines.
    pub name: Ident,
    /// Its kind token.
    pub kind: Ident,
    /// Links it names.
    pub links: Vec<Ident>,
    /// Slides it names.
    pub slides: Vec<Ident>,
    /// Its input name, for a driver.
    pub input: Option<Ident>,
}

/// One `let` statement.
pub struct Stmt {
    /// The defined name.
    pub name: Ident,
    /// The kind token (`rrr`, ...).
    pub kind_token: Ident,
    /// What the statement is.
    pub kind: Kind,
    /// Names of the links it creates (user-given or generated).
    pub links: Vec<Ident>,
    /// Which of `links` the user named (only those become outputs).
    pub links_named: Vec<bool>,
    /// Names of slide displacements (user-given) by slot.
    pub slides: Vec<Option<Ident>>,
}

/// Origin of a guide.
pub enum Origin {
    /// A named point.
    Point(Ident),
    /// Literal or parametric coordinates.
    Coords(Value, Value),
}

/// A point's local coordinates on a link.
pub enum Local {
    /// Distance and angle from the link's axis.
    Polar(Value, Value),
    /// `(x, y)` along the axis and its left normal.
    Cartesian(Value, Value),
}

/// The statement kinds.
pub enum Kind {
    /// A fixed point.
    Ground { x: Value, y: Value },
    /// A guide line, fixed (`carrier == None`) or carried by a link.
    Guide {
        origin: Origin,
        angle: Value,
        carrier: Option<Ident>,
    },
    /// Crank driver. `cos_sin`: the definition wrote `INPUT as cos_sin`, so a
    /// `position_cos_sin` entry point takes this input as `(cos, sin)`.
    Crank {
        pivot: Ident,
        radius: Value,
        input: Ident,
        cos_sin: bool,
    },
    /// Slider driver.
    Slider {
        guide: Ident,
        input: Ident,
        offset: Value,
    },
    /// Linear actuator driver.
    Actuator {
        a: Ident,
        l: Value,
        b: Ident,
        input: Ident,
        mode: Mode,
    },
    /// RRR group.
    Rrr {
        a: Ident,
        l1: Value,
        b: Ident,
        l2: Value,
        mode: Mode,
    },
    /// RRP group.
    Rrp {
        a: Ident,
        l: Value,
        guide: Ident,
        mode: Mode,
        offset: Value,
    },
    /// RPR group.
    Rpr {
        a: Ident,
        b: Ident,
        mode: Mode,
        offset: Value,
    },
    /// PRP group.
    Prp {
        g1: Ident,
        g2: Ident,
        offset1: Value,
        offset2: Value,
    },
    /// RPP group.
    Rpp {
        a: Ident,
        guide: Ident,
        slot: Value,
        offset: Value,
    },
    /// A point fixed on a link.
    Point {
        link: Ident,
        from: Ident,
        local: Local,
    },
}

impl Kind {
    /// Number of links the statement creates.
    pub fn link_count(&self) -> usize {
        match self {
            Kind::Ground { .. } | Kind::Guide { .. } | Kind::Point { .. } => 0,
            Kind::Crank { .. } | Kind::Slider { .. } => 1,
            _ => 2,
        }
    }

    /// Number of slide displacements the statement creates.
    pub fn slide_count(&self) -> usize {
        match self {
            Kind::Rrp { .. } => 1,
            Kind::Prp { .. } | Kind::Rpp { .. } => 2,
            _ => 0,
        }
    }

    /// `true` for drivers.
    pub fn is_driver(&self) -> bool {
        matches!(
            self,
            Kind::Crank { .. } | Kind::Slider { .. } | Kind::Actuator { .. }
        )
    }

    /// The input variable of a driver.
    pub fn input(&self) -> Option<&Ident> {
        match self {
            Kind::Crank { input, .. }
            | Kind::Slider { input, .. }
            | Kind::Actuator { input, .. } => Some(input),
            _ => None,
        }
    }
}

/// The kind name of a statement that can fail (drivers, groups, link points).
pub fn group_kind(kind: &Kind) -> Option<&'static str> {
    Some(match kind {
        Kind::Crank { .. } => "crank",
        Kind::Slider { .. } => "slider",
        Kind::Actuator { .. } => "actuator",
        Kind::Rrr { .. } => "RRR",
        Kind::Rrp { .. } => "RRP",
        Kind::Rpr { .. } => "RPR",
        Kind::Prp { .. } => "PRP",
        Kind::Rpp { .. } => "RPP",
        Kind::Point { .. } => "link point",
        Kind::Ground { .. } | Kind::Guide { .. } => return None,
    })
}
