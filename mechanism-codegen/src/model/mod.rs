//! Stage 2, model: the parse tree lowered into typed statements. Arguments are
//! checked for arity, role (point, guide, link, number, mode) and literal
//! positivity here; names are resolved across statements in `validate`.
//!
//! This file holds the typed model; the lowering is in [`lower`] (the
//! definition's phases), `kinds` (one function per statement kind), `args`
//! (reading arguments by role, numbers and their scope), `kinetics` (masses
//! and loads) and `inputs` (input ranges and allowances).

mod args;
mod drawn;
mod inputs;
mod kinds;
mod kinetics;
mod lower;
pub mod modes;
pub mod units;

pub use inputs::{Allowed, Input, RangeSpans};
pub use lower::lower;

use crate::kinds::word::KindWord;
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
    /// Everything, the force analysis and the forward dynamics in the
    /// inputs' coordinates (`analysis dynamics;`, with masses).
    Dynamics,
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
    /// The derives written on the definition (`emit::interop`).
    pub derives: Vec<crate::parse::Derive>,
    /// Visibility of the generated items.
    pub vis: Visibility,
    /// Type name.
    pub name: Ident,
    /// Run-time parameters with their (folded) default values.
    pub params: Vec<(Ident, f64)>,
    /// Run-time assembly modes (`params { circuit = left }`): fields of
    /// type `mechanism::Mode` with their defaults, after `params`.
    pub modes: Vec<(Ident, Mode)>,
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
    /// The names of the definition's units (`units { .. }`; the symbols
    /// `L`, `F`, `M`, `s` without it).
    pub units: units::UnitNames,
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
    /// The motors (`motor`), of an inverse-kinematics definition.
    pub motors: Vec<MotorSpec>,
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

/// A motor of an inverse-kinematics definition: its torque on `link`
/// (reacting on `carrier`, or the ground) is what holds the target driver's
/// point on its path.
pub struct MotorSpec {
    /// Its name (the forces struct's `drive_NAME`).
    pub name: Ident,
    /// The link it turns.
    pub link: Ident,
    /// The link carrying it (`None`: the ground).
    pub carrier: Option<Ident>,
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
        self.level >= Level::Forces
    }
}

/// A statement whose arguments were rejected (an error is already reported).
pub struct Failed {
    /// The name it defines.
    pub name: Ident,
    /// What it was written as.
    pub kind: FailedKind,
    /// Links it names.
    pub links: Vec<Ident>,
    /// Slides it names.
    pub slides: Vec<Ident>,
    /// Its input names, for a driver.
    pub inputs: Vec<Ident>,
}

/// What a rejected statement was written as.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FailedKind {
    /// A `let` of this kind (`None`: a word the language does not know).
    Let(Option<KindWord>),
    /// A joint of the drawn form.
    DrawnJoint,
    /// A link of the drawn form (or a coordinate input's effector).
    DrawnLink,
    /// A cylinder of the drawn form.
    DrawnCylinder,
    /// An input of the drawn form.
    DrawnInput,
}

impl Failed {
    /// Whether its name is a point (the `let` of a point-placing kind, or a
    /// drawing's joint), rather than a guide, an RPR's slide, or a drawing's
    /// link, cylinder or input, whose names are in `links` and `inputs`.
    pub fn names_point(&self) -> bool {
        !matches!(
            self.kind,
            FailedKind::Let(Some(KindWord::Guide | KindWord::Rpr))
                | FailedKind::DrawnLink
                | FailedKind::DrawnCylinder
                | FailedKind::DrawnInput
        )
    }
}

/// A `let` statement of the definition, by its place in the order written
/// (`Model::stmts[id]`). The plan's solve order, the owners of points and
/// the findings of the expansion-time check name statements by it.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Debug)]
pub struct StmtId(pub usize);

impl StmtId {
    /// Every statement of `stmts`, in the order written.
    pub fn all(stmts: &[Stmt]) -> impl Iterator<Item = StmtId> + '_ {
        (0..stmts.len()).map(StmtId)
    }
}

impl std::ops::Index<StmtId> for Vec<Stmt> {
    type Output = Stmt;
    fn index(&self, id: StmtId) -> &Stmt {
        &self[id.0]
    }
}

impl std::ops::Index<StmtId> for [Stmt] {
    type Output = Stmt;
    fn index(&self, id: StmtId) -> &Stmt {
        &self[id.0]
    }
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
    /// The run-time mode parameter this group's assembly mode reads
    /// (`rrr(A, l1, B, l2, circuit)`), `None` for a literal mode. The
    /// kind's `mode` then holds the parameter's default.
    pub mode_param: Option<Ident>,
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
    /// `carrier`: the moving link that carries it (its input is then the
    /// angle from that link's axis turned by `zero`); `None` on the ground.
    Crank {
        pivot: Ident,
        radius: Value,
        input: Ident,
        cos_sin: bool,
        carrier: Option<Ident>,
        zero: Value,
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
    /// Target driver: a point placed by two inputs, its coordinates `x`
    /// and `y` (length units, global frame); its link is the effector, a
    /// body that translates with it and does not turn.
    Target { x: Ident, y: Ident },
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
    /// The triad (class III group): the statement of its joint `A`; its
    /// joints `B` and `P` are lowered as points on the ternary link.
    Triad(Box<Triad>),
    /// A gear pair: a link turning about `pivot`, geared to the link `mesh`
    /// (`kinds::gear`).
    Gear(Box<Gear>),
}

/// A `gear` statement's arguments (lengths in L, angles in rad).
///
/// Both gears turn about points of one common link, the carrier (the
/// ground when `carrier` is `None`). Measured from the carrier, the new
/// link's angle is `phase - ratio * (angle of mesh)`: `ratio` is the pitch
/// radius of `mesh`'s gear over the new link's (positive: external gears,
/// turning opposite ways; negative: an internal pair, turning the same way).
pub struct Gear {
    /// The point the new link turns about (on the carrier).
    pub pivot: Ident,
    /// The distance from the pivot to the point the statement defines.
    pub radius: Value,
    /// The link geared to it (`None`: the ground, a fixed gear).
    pub mesh: Option<Ident>,
    /// Where `mesh` is written (the link's name or `ground`).
    pub mesh_span: Span,
    /// Pitch radius of `mesh`'s gear over the new link's, signed (never 0
    /// or -1).
    pub ratio: Value,
    /// The new link's angle from the carrier when `mesh`'s is 0.
    pub phase: Value,
    /// The common link both turn on (`None`: the ground).
    pub carrier: Option<Ident>,
    /// The pressure angle of the teeth (rad, in (0, pi/2)): the tooth force
    /// is along the line of action, this far from the common tangent.
    pub pressure: Value,
    /// The crank of `mesh` (its input is `mesh`'s angle, its pivot the
    /// center of `mesh`'s gear), resolved when lowering.
    pub mesh_crank: Option<GearCrank>,
    /// The crank of `carrier`, resolved when lowering.
    pub carrier_crank: Option<GearCrank>,
}

/// A crank on the ground as a gear reads it: the input that is its angle
/// (rad) and its pivot.
#[derive(Clone)]
pub struct GearCrank {
    /// The crank's input (its link's angle from +x, rad, unwrapped).
    pub input: Ident,
    /// Its pivot (a ground point).
    pub pivot: Ident,
}

/// A `triad` statement's arguments (lengths in L, angles in rad).
pub struct Triad {
    /// The known points of the three legs.
    pub k: [Ident; 3],
    /// The legs' lengths `|A - K1|`, `|B - K2|`, `|P - K3|`.
    pub l: [Value; 3],
    /// The ternary link's side `|B - A|`.
    pub ab: Value,
    /// `P` in the ternary's frame (origin `A`, x along `A -> B`).
    pub p_local: Local,
    /// The joints `B` and `P` (defined by the same statement).
    pub b: Ident,
    /// See `b`.
    pub p: Ident,
    /// The input and its value at which the pose hint holds.
    pub at: (Ident, Value),
    /// The approximate `A`, `B`, `P` at `at` (L).
    pub near: [(Value, Value); 3],
}

impl Kind {
    /// The word of this kind (its descriptor: `self.word().spec()`).
    pub fn word(&self) -> KindWord {
        match self {
            Kind::Ground { .. } => KindWord::Ground,
            Kind::Guide { .. } => KindWord::Guide,
            Kind::Crank { .. } => KindWord::Crank,
            Kind::Slider { .. } => KindWord::Slider,
            Kind::Actuator { .. } => KindWord::Actuator,
            Kind::Target { .. } => KindWord::Target,
            Kind::Rrr { .. } => KindWord::Rrr,
            Kind::Rrp { .. } => KindWord::Rrp,
            Kind::Rpr { .. } => KindWord::Rpr,
            Kind::Prp { .. } => KindWord::Prp,
            Kind::Rpp { .. } => KindWord::Rpp,
            Kind::Point { .. } => KindWord::Point,
            Kind::Triad(_) => KindWord::Triad,
            Kind::Gear(_) => KindWord::Gear,
        }
    }

    /// Number of links the statement creates.
    pub fn link_count(&self) -> usize {
        match self {
            Kind::Ground { .. } | Kind::Guide { .. } | Kind::Point { .. } => 0,
            Kind::Crank { .. } | Kind::Slider { .. } | Kind::Target { .. } | Kind::Gear(_) => 1,
            Kind::Triad(_) => 4,
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
            Kind::Crank { .. } | Kind::Slider { .. } | Kind::Actuator { .. } | Kind::Target { .. }
        )
    }

    /// The input variables of a driver (one, or a target's two), none for
    /// the other statements.
    pub fn inputs(&self) -> Vec<&Ident> {
        match self {
            Kind::Crank { input, .. }
            | Kind::Slider { input, .. }
            | Kind::Actuator { input, .. } => vec![input],
            Kind::Target { x, y } => vec![x, y],
            _ => Vec::new(),
        }
    }
}

/// The kind name of a statement that can fail (drivers, groups, link points)
/// as messages give it (its kind's `Spec::group`); `None` for ground points
/// and guides.
pub fn group_kind(kind: &Kind) -> Option<&'static str> {
    kind.word().spec().group
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::Diagnostics;
    use crate::value::ValueKind;
    use mechanism_core::sweep::Range;
    use std::f64::consts::PI;

    /// The definition `src` lowered, and the messages of its errors.
    fn lower(src: &str) -> (Model, Vec<String>) {
        let def = syn::parse_str::<crate::parse::Definition>(src).unwrap();
        let mut diag = Diagnostics::new();
        let model = super::lower(def, &mut diag);
        let errors = diag.finish().iter().map(ToString::to_string).collect();
        (model, errors)
    }

    /// The names of `idents`.
    fn names(idents: &[Ident]) -> Vec<String> {
        idents.iter().map(ToString::to_string).collect()
    }

    #[test]
    fn statements_are_lowered_with_their_links() {
        // Proves each `let` becomes a statement of its kind in the order
        // written, with its arguments by role (a parameter kept as one, a
        // constant expression folded, an angle in rad), its named links and
        // generated names for the links it creates without `as`.
        let (model, errors) = lower(
            "pub M {
                params { r = 1.0 }
                const l = 3.0;
                let O2 = ground(0.0, 0.0);
                let O4 = ground(4.0, 0.0);
                let A = crank(O2, r, theta) as link2;
                let B = rrr(A, l, O4, l / 2.0 + 1.0, right);
                let P = point(link2, from A, 2.0, 90 deg);
            }",
        );
        assert!(errors.is_empty(), "{errors:?}");
        let stmts: Vec<String> = model.stmts.iter().map(|s| s.name.to_string()).collect();
        assert_eq!(stmts, ["O2", "O4", "A", "B", "P"]);
        let Kind::Crank {
            pivot,
            radius,
            input,
            cos_sin: false,
            carrier: None,
            ..
        } = &model.stmts[2].kind
        else {
            panic!("A is no crank");
        };
        assert_eq!(
            (pivot.to_string(), input.to_string()),
            ("O2".into(), "theta".into())
        );
        assert!(matches!(&radius.kind, ValueKind::Param(p) if p == "r"));
        assert_eq!(names(&model.stmts[2].links), ["link2"]);
        assert_eq!(model.stmts[2].links_named, [true]);
        let Kind::Rrr {
            l1,
            l2,
            mode: Mode::Minus,
            ..
        } = &model.stmts[3].kind
        else {
            panic!("B is no `rrr(.., right)`");
        };
        assert_eq!((l1.fold(), l2.fold()), (Some(3.0), Some(2.5)));
        assert_eq!(names(&model.stmts[3].links), ["B_link1", "B_link2"]);
        assert_eq!(model.stmts[3].links_named, [false, false]);
        let Kind::Point {
            local: Local::Polar(d, angle),
            ..
        } = &model.stmts[4].kind
        else {
            panic!("P is no polar link point");
        };
        assert_eq!((d.fold(), angle.fold()), (Some(2.0), Some(PI / 2.0)));
        assert!(model.stmts[4].links.is_empty());
        assert_eq!(model.level, Level::Acceleration);
    }

    #[test]
    fn inputs_get_their_ranges() {
        // Proves the driver inputs come in the order written, a crank's with a
        // declared range in rad, a slider's with its declared range, and a
        // slider without one with none (a crank's default would be a full
        // turn, periodic).
        let (model, errors) = lower(
            "pub M {
                let O = ground(0.0, 0.0);
                let A = crank(O, 1.0, theta) as link2;
                let line = guide((0.0, 0.0), 0 deg);
                let S = slider(line, s) as block;
                let T = slider(line, u) as block2;
                range s = (0.0, 0.1);
                range theta = (-40 deg, 40 deg);
            }",
        );
        assert!(errors.is_empty(), "{errors:?}");
        let inputs: Vec<(String, bool, Option<Range>, bool)> = model
            .inputs
            .iter()
            .map(|i| (i.name.to_string(), i.angle, i.range, i.declared))
            .collect();
        let range = |lo: f64, hi: f64| {
            Some(Range {
                lo,
                hi,
                periodic: false,
            })
        };
        assert_eq!(
            inputs,
            [
                (
                    "theta".into(),
                    true,
                    range(-40f64.to_radians(), 40f64.to_radians()),
                    true
                ),
                ("s".into(), false, range(0.0, 0.1), true),
                ("u".into(), false, None, false),
            ]
        );
        let (model, _) =
            lower("pub M { let O = ground(0.0, 0.0); let A = crank(O, 1.0, theta) as link2; }");
        let full = Range {
            lo: 0.0,
            hi: 2.0 * PI,
            periodic: true,
        };
        assert_eq!(model.inputs[0].range, Some(full));
        assert!(!model.inputs[0].declared);
    }

    #[test]
    fn constants_and_defaults_are_folded() {
        // Proves constants fold with the constants written before them, and
        // parameter and load defaults with the constants; a constant that uses
        // a later one is an error, and is kept as 0.
        let (model, errors) = lower(
            "pub M {
                const a = 2.0 * 3.0;
                const b = a + 1.0;
                params { p = b * 2.0 }
                loads { cut = -a }
                const c = d;
                const d = 1.0;
            }",
        );
        assert_eq!(
            errors,
            ["cannot find parameter or constant `d` (a `const` may use literals and constants defined before it)"]
        );
        let consts: Vec<(String, f64)> = model
            .consts
            .iter()
            .map(|(k, (_, x))| (k.clone(), *x))
            .collect();
        assert_eq!(
            consts,
            [
                ("a".into(), 6.0),
                ("b".into(), 7.0),
                ("c".into(), 0.0),
                ("d".into(), 1.0)
            ]
        );
        assert_eq!(model.params.len(), 1);
        assert_eq!(
            (model.params[0].0.to_string(), model.params[0].1),
            ("p".into(), 14.0)
        );
        assert_eq!(model.kinetics.loads.len(), 1);
        assert_eq!(model.kinetics.loads[0].1, -6.0);
    }

    #[test]
    fn rejected_arguments_keep_the_statements_names() {
        // Proves a statement with too few arguments and one with a negative
        // length are each reported, and not lowered: their names stay defined
        // (as failed statements) so that nothing else is blamed for them.
        let (model, errors) = lower(
            "pub M {
                let O = ground(0.0, 0.0);
                let B = rrr(O, 1.0, O, left) as (link3, link4);
                let C = rrr(O, -1.0, O, 1.0, left);
            }",
        );
        assert_eq!(
            errors,
            [
                "missing argument(s) for `rrr`: 4 given, it takes 5; usage: `rrr(A, l1, B, l2, left|right) as (LINK1, LINK2)`",
                "the first link length must be positive, got -1.0; a link length is a distance > 0",
            ]
        );
        assert_eq!(model.stmts.len(), 1);
        let failed: Vec<(String, Vec<String>)> = model
            .failed
            .iter()
            .map(|f| (f.name.to_string(), names(&f.links)))
            .collect();
        assert_eq!(
            failed,
            [
                ("B".into(), vec!["link3".to_string(), "link4".into()]),
                ("C".into(), vec![])
            ]
        );
    }

    #[test]
    fn masses_and_loads_are_lowered() {
        // Proves `mass`, `force` and `torque` become the force analysis'
        // masses and loads (a load value kept as one, to be supplied per
        // evaluation), and ask for the force analysis; a load value used as a
        // dimension is an error.
        let (model, errors) = lower(
            "pub M {
                loads { cut = 10.0 }
                let O = ground(0.0, 0.0);
                let A = crank(O, cut, theta) as link2;
                mass link2 { m = 2.0, at = A, j = 0.5 }
                force at A on link2 = (cut, 0.0);
                torque on link2 = 3.0;
            }",
        );
        assert_eq!(
            errors,
            ["`cut` is a load value (from `loads`): it may appear in `force` and `torque` statements only; dimensions are `params` or `const`"]
        );
        assert_eq!(model.level, Level::Forces);
        let k = &model.kinetics;
        let [m] = k.masses.as_slice() else {
            panic!("{} masses", k.masses.len());
        };
        assert_eq!(
            (m.link.to_string(), m.at.to_string()),
            ("link2".into(), "A".into())
        );
        assert_eq!(
            (m.mass.fold(), m.inertia.as_ref().and_then(Value::fold)),
            (Some(2.0), Some(0.5))
        );
        let [f] = k.forces.as_slice() else {
            panic!("{} forces", k.forces.len());
        };
        assert_eq!(
            f.on.as_ref().map(ToString::to_string).as_deref(),
            Some("link2")
        );
        let ForceSpecValue::Components(x, y) = &f.value else {
            panic!("not by components");
        };
        assert!(matches!(&x.kind, ValueKind::Load(l) if l == "cut"));
        assert_eq!(y.fold(), Some(0.0));
        assert_eq!(k.torques.len(), 1);
        assert_eq!(k.torques[0].value.fold(), Some(3.0));
    }
}
