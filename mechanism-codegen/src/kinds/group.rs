//! What a statement kind is to the stages that read it: the [`GroupKind`]
//! trait each kind's file implements, and the vocabulary of its methods
//! (how a link turns, what a referred name must be, a link's shape, how a
//! position is emitted, what tracking found). The kinds' files import this
//! and not `kinds/mod.rs`, whose dispatcher ([`super::of`]) imports them.

use super::run::NamedPose;
use super::{closure, forces, lane, rates, reads, run};
use crate::diag::Diagnostics;
use crate::keys::{GuideName, LinkName, PointName};
use crate::model::Stmt;
use crate::value::Value;
use proc_macro2::TokenStream;
use syn::Ident;

/// How a link turns.
#[derive(Clone, Debug, PartialEq)]
pub enum Turn {
    /// It never turns (a block on a fixed guide).
    None,
    /// It has its own angular velocity, found by the statement that creates it.
    Own,
    /// It turns with another link (a block on a carried guide).
    With(LinkName),
}

/// What the rules that need the plan ask of it (implemented by `plan::Plan`).
pub trait Placed {
    /// The points on `link`, `None` for an unknown link.
    fn link_points(&self, link: &Ident) -> Option<&[PointName]>;
    /// `true` when a statement defines `name`.
    fn is_defined(&self, name: &Ident) -> bool;
    /// `true` when `point` never moves.
    fn is_ground_point(&self, point: &PointName) -> bool;
    /// The links that have `point` among their points.
    fn links_with_point(&self, point: &PointName) -> Vec<LinkName>;
}

/// A guide's line as written.
pub struct GuideLine<'a> {
    /// The link carrying it (`None`: fixed).
    pub carrier: Option<&'a Ident>,
    /// The point it passes through (`None`: literal or parametric coordinates).
    pub through: Option<&'a Ident>,
    /// Its angle (rad, counter-clockwise from +x, or from the carrier's axis).
    pub angle: &'a Value,
}

/// What a name a statement refers to must be.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// A point.
    Point,
    /// A guide.
    Guide,
    /// A link.
    Link,
}

/// A link a statement creates: the points fixed on it (the first is the
/// link's origin), how it turns (before guide carriers are resolved), and
/// the guide it slides on (a block), if any.
pub struct LinkShape {
    /// Points fixed on the link, its origin first.
    pub points: Vec<PointName>,
    /// How it turns, a block on a guide as `Turn::None`.
    pub turn: Turn,
    /// The guide it slides on.
    pub guide: Option<GuideName>,
}

impl LinkShape {
    /// A link through `points` that turns as `turn` and slides on `guide`.
    pub(super) fn new(points: &[&Ident], turn: Turn, guide: Option<&Ident>) -> Self {
        LinkShape {
            points: points.iter().map(|p| PointName::of(p)).collect(),
            turn,
            guide: guide.map(GuideName::of),
        }
    }
}

/// How a statement's position is emitted.
pub enum Solve {
    /// `let pos_NAME = EXPR;`, a value of type `ty` (a point or a line).
    Own {
        /// The expression (tagged, if it can fail).
        expr: TokenStream,
        /// Its type.
        ty: TokenStream,
    },
    /// `let grp_NAME = CALL TAG;`, then `let pos_NAME = grp_NAME.JOINT;`
    /// when the statement names a point.
    Group {
        /// The core call, untagged.
        call: TokenStream,
        /// The field of its result that is the statement's point.
        joint: Option<&'static str>,
    },
}

/// What the macro knows about one statement kind. Implemented once per
/// kind, on a view of one statement of that kind ([`of`]).
pub trait GroupKind<'a>: run::RunKind {
    /// Names the statement refers to, with their tokens and what each must
    /// name.
    fn references(&self) -> Vec<(&'a Ident, Role)>;

    /// The links the statement creates, in the order of `Stmt::links`.
    fn link_shapes(&self) -> Vec<LinkShape>;

    /// The body the statement's point belongs to when another group is
    /// pinned there (`Some(None)`: the ground); `None` for statements that
    /// define no point (guides, RPR slides). See `plan::point_owner`.
    fn point_owner(&self) -> Option<Option<LinkName>>;

    /// Every value its position uses, in the order the evaluator reads them.
    fn position_values(&self) -> Vec<Value>;

    /// The core type of its solved position state (`grp_NAME`), `()` for none.
    fn position_type(&self) -> TokenStream;

    /// Its position code; `cos_sin`: emitting `position_cos_sin`.
    fn position(&self, cos_sin: bool) -> Solve;

    /// Its position code in the tracking form (`position_near`), which
    /// stays on the assembly of the previous position `pos`; `None`: the
    /// same as `position` (kinds with a single assembly per mode). `reads`
    /// records its reads of `pos`.
    fn position_tracking(&self, _reads: &reads::Reads) -> Option<Solve> {
        None
    }

    /// Unit axis and raw direction of its link `index`, in position scope.
    fn link_direction(&self, _index: usize) -> (TokenStream, TokenStream);

    /// The field of its position state holding its slide `slot`.
    fn slide_field(&self, _slot: usize) -> TokenStream;

    /// The angle output of its link, when not the angle of the link's
    /// direction (a crank's is its input). `cos_sin`: in `position_cos_sin`.
    fn link_angle(&self, _cos_sin: bool) -> Option<TokenStream> {
        None
    }

    /// Its velocity code (`cx.accel()` false) or acceleration code.
    fn rates(&self, _cx: &mut dyn rates::RateCx) {}

    /// `true` for the groups with a rate system (the dyads and the
    /// actuator): their velocity's `condition` joins the mechanism's.
    fn rate_system(&self) -> bool;

    /// Its loop-closure residuals for `#[self_test]`; `link_axis` gives a
    /// link's unit axis from the solved points (code).
    fn residuals(
        &self,
        _r: &mut closure::Residuals<'_>,
        _link_axis: &dyn Fn(&Ident) -> TokenStream,
    ) {
    }

    /// The unit axis of its link `index` from the solved points (code of
    /// the self-test module); `reads` records its reads of `pos`.
    fn closure_axis(&self, _index: usize, _reads: &reads::Reads) -> TokenStream;

    /// Its link lengths (for the shortest link of the self-test tolerances).
    fn link_lengths(&self) -> Vec<&'a Value>;

    /// What a fault of its position means, in the user's words and numbers
    /// (`at`: where, as the user reads it); `None`: the fault's own text.
    fn explain_fault(&self, _fault: &mechanism_core::Fault, _at: &str) -> Option<String> {
        None
    }

    /// Why its rate system is singular, in the user's words; `None`: a
    /// generic text.
    fn singular_meaning(&self) -> Option<String> {
        None
    }

    /// Its lane code in the batch kernel (`None`: it has none, or an
    /// argument the kernel does not know; the batch then takes the scalar
    /// path).
    fn lane(&self, lane: &mut lane::Lane, s: &mut lane::Step<'_>) -> Option<()>;

    /// The core's tag of the primitive it calls (`mechanism::Primitive`),
    /// for run-time errors.
    fn primitive(&self) -> &'static str;

    /// Its scaled determinant (the same as its `eval`'s) from the generated
    /// position struct `pos` (code of `check()`); 1 without a rate system.
    /// `reads` records its reads of `pos`.
    fn det_code(&self, _reads: &reads::Reads) -> TokenStream;

    /// Its line in the structure listing of the generated type's doc comment.
    fn describe(&self) -> String;

    /// The kind of point it defines (`mechanism::structure::PointKind`),
    /// `None` when it defines none (a guide, an RPR's slide).
    fn point_kind(&self) -> Option<&'static str>;

    /// Whether the point it defines moves, given which links turn and
    /// which points move before it.
    fn point_moves(
        &self,
        _link_turns: &dyn Fn(&Ident) -> bool,
        _moves: &dyn Fn(&Ident) -> bool,
    ) -> bool;

    /// The kind of its link `index` (`mechanism::structure::LinkKind`) when
    /// it does not slide on a guide.
    fn link_kind(&self, _index: usize) -> &'static str;

    /// `true` when its input is an angle (rad), `false` a length.
    fn input_is_angle(&self) -> bool;

    /// `true` for an output the batch leaves out because the caller has it
    /// already (a ground point, a crank's link).
    fn given_by_caller(&self, _output: &Ident) -> bool {
        false
    }

    /// `true` when its slide without a name of its own is an output under
    /// the statement's name (an RPR's).
    fn names_slide(&self) -> bool {
        false
    }

    /// The bodies it adds, the lower pairs and the higher pairs (a gear
    /// mesh) it closes, for the mobility count (Gruebler: `3 (n - 1) - 2 j
    /// - h`).
    fn bodies_and_pairs(&self) -> (i64, i64, i64);

    /// For a group on two known places: the two and what they are, for the
    /// rule that they differ (`validate`).
    fn distinct_pair(&self) -> Option<(&'a Ident, &'a Ident, &'static str)> {
        None
    }

    /// `true` for a group whose joint can be at infinity (its position
    /// itself fails at a singular pose: the PRP, the RPP).
    fn joint_at_infinity(&self) -> bool {
        false
    }

    /// Why it cannot assemble when it is singular at every pose checked
    /// (`over`: the inputs checked, as the user reads them), `None` when
    /// that says nothing more than a failure at one input.
    fn singular_everywhere(&self, _over: &str) -> Option<String> {
        None
    }

    /// A hint on why it does not assemble over a crank's full turn, when
    /// there is one in numbers (an RRR driven by a crank onto a ground
    /// point: the four-bar's Grashof condition). `find` gives the statement
    /// that defines a name.
    fn full_turn_hint(&self, _find: &dyn Fn(&Ident) -> Option<&'a Stmt>) -> Option<String> {
        None
    }

    /// Its own rules on its arguments as written (`validate::model`).
    fn check(&self, _errors: &mut Diagnostics) {}

    /// For a dependency cycle `cycle` that starts at this statement: what
    /// the cycle is and what to write instead, when the kind knows (three
    /// RRR pinned outside the cycle: a triad); `None` otherwise.
    fn cycle_hint(&self, _cycle: &[&Stmt]) -> Option<String> {
        None
    }

    /// Its own rules on the inputs it names beside its driven one, against
    /// the definition's `inputs` (`validate::model`): a triad's pose is
    /// given at a value of one of them.
    fn check_inputs(&self, _inputs: &[crate::model::Input], _errors: &mut Diagnostics) {}

    /// Its own rules that need the plan (`validate::planned`): where its
    /// points lie.
    fn check_placed(&self, _plan: &dyn Placed, _errors: &mut Diagnostics) {}

    /// For a statement whose assembly is followed at expansion time (the
    /// triad): follows it over the single input's `range` (`(lo, hi)`, rad
    /// when `angle`, else length units), `before(q)` giving the pose of the
    /// statements solved before it at input `q`, and keeps what the emitted
    /// code reads. [`Tracking::Failed`] with an error reported when the
    /// stated assembly cannot be followed. Others have nothing to follow.
    fn track<'l>(
        &self,
        _before: &dyn Fn(f64) -> Option<NamedPose<'l>>,
        _range: (f64, f64),
        _angle: bool,
        _errors: &mut Diagnostics,
    ) -> Tracking {
        Tracking::Nothing
    }

    /// Its part of the force analysis (drivers and groups): its reactions
    /// from the loads of its links, passed (negated) to the bodies it is
    /// attached to, its fields in the forces struct, its conditioning and
    /// its driving power.
    fn forces(&self, _cx: &mut dyn forces::ForceCx) {}

    /// The link whose unit axis its position reads (a link point's link, a
    /// carried guide's carrier).
    fn reads_axis(&self) -> Option<&'a Ident> {
        None
    }
}

/// The links of a statement, `a, b`, for listings.
pub(super) fn links_text(stmt: &Stmt) -> String {
    let links: Vec<String> = stmt.links.iter().map(ToString::to_string).collect();
    links.join(", ")
}

/// How the structure listing writes an assembly mode.
pub(super) fn mode_text(stmt: &Stmt, m: crate::model::Mode) -> String {
    let literal = match m {
        crate::model::Mode::Plus => "mode plus (m = +1)",
        crate::model::Mode::Minus => "mode minus (m = -1)",
    };
    match &stmt.mode_param {
        Some(p) => format!("{literal} by default, at run time the parameter `{p}`"),
        None => literal.to_string(),
    }
}

/// What following a statement's assembly over the input range found
/// ([`GroupKind::track`]).
pub enum Tracking {
    /// The kind has one assembly per mode: nothing to follow.
    Nothing,
    /// The tracked poses (a finding of the check, `Known::tracked`).
    Tracked(Tracked),
    /// The stated assembly cannot be followed (an error was reported).
    Failed,
}

/// What tracking a triad's stated assembly over its input's range found
/// (the check's finding for the statement, read by the sweep, the
/// generated `position()` and the messages).
#[derive(Clone, Debug, Default)]
pub struct Tracked {
    /// The pose at the table's inputs (increasing): `[input, ax, ay, bx, by, px, py]`.
    pub rows: Vec<[f64; 7]>,
    /// Where the tracked assembly stops existing: the last input it was
    /// found at and the first it was not, below and above the stated one.
    pub ends: Vec<(f64, f64)>,
    /// `true` when the input is an angle (rad; messages show deg).
    pub angle: bool,
}
