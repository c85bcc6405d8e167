//! Stage 2b, kinds: everything the macro knows about one statement kind, one
//! module per kind behind the [`GroupKind`] trait: the names it refers to,
//! the links it creates and how they turn, which body owns its point, the
//! values its position uses, its position in `f64` at expansion time (the
//! evaluator of `check`) and the core call it emits for `position()` (the
//! emitter), both calling the same `mechanism-core` primitive with the same
//! arguments.
//!
//! [`of`] is the one place where a [`Kind`] is dispatched to its module.
//! This stage reads `model` and `value` only; `validate`, `plan`, `check`
//! and `emit` read it.

/// The structure facets of a statement that creates no link and solves no
/// group of its own (`ground`, `guide`, `point`): no link shapes, lengths or
/// directions, no position type, no rate system, no determinant (1), no
/// mobility (0 bodies, 0 pairs). Written once here; each such kind invokes
/// it inside its `GroupKind` impl (with the impl's lifetime), so that the
/// trait itself has no default for any of them.
macro_rules! linkless_facets {
    ($l:lifetime) => {
        fn link_shapes(&self) -> Vec<super::LinkShape> {
            Vec::new()
        }

        fn position_type(&self) -> ::proc_macro2::TokenStream {
            ::quote::quote!(())
        }

        fn link_direction(
            &self,
            _index: usize,
        ) -> (::proc_macro2::TokenStream, ::proc_macro2::TokenStream) {
            (
                ::quote::quote!(::mechanism::Vector2::x()),
                ::quote::quote!(::mechanism::Vector2::x()),
            )
        }

        fn slide_field(&self, _slot: usize) -> ::proc_macro2::TokenStream {
            ::quote::quote!(s)
        }

        fn rate_system(&self) -> bool {
            false
        }

        fn closure_axis(&self, _index: usize) -> ::proc_macro2::TokenStream {
            ::quote::quote!([1.0, 0.0])
        }

        fn link_lengths(&self) -> Vec<&$l crate::value::Value> {
            Vec::new()
        }

        fn primitive(&self) -> &'static str {
            "LinkPoint"
        }

        fn det_code(&self) -> ::proc_macro2::TokenStream {
            ::quote::quote!(1.0)
        }

        fn link_kind(&self, _index: usize) -> &'static str {
            "Bar"
        }

        fn input_is_angle(&self) -> bool {
            false
        }

        fn bodies_and_pairs(&self) -> (i64, i64, i64) {
            (0, 0, 0)
        }
    };
}

/// The point facets of a group whose point is a joint that always moves and
/// whose links are bars, with no input of its own read as an angle (the
/// dyads, the slider, the triad). Stated once here and invoked inside each
/// such kind's `GroupKind` impl, so that the trait has no default for them.
macro_rules! moving_joint_facets {
    () => {
        fn point_kind(&self) -> Option<&'static str> {
            Some("Joint")
        }

        fn point_moves(
            &self,
            _link_turns: &dyn Fn(&::syn::Ident) -> bool,
            _moves: &dyn Fn(&::syn::Ident) -> bool,
        ) -> bool {
            true
        }

        fn link_kind(&self, _index: usize) -> &'static str {
            "Bar"
        }

        fn input_is_angle(&self) -> bool {
            false
        }
    };
}

mod actuator;
pub mod closure;
mod crank;
pub mod forces;
pub(crate) mod gear;
mod ground;
mod guide;
pub mod lane;
mod lane_shapes;
pub mod motors;
mod point;
pub mod pose;
mod prp;
pub mod rates;
mod rpp;
mod rpr;
mod rrp;
mod rrr;
pub mod run;
mod slider;
mod target;
pub(crate) mod tokens;
pub mod triad;
pub mod word;

use crate::diag::Diagnostics;
use crate::keys::{GuideName, LinkName, PointName};
use crate::model::{Kind, Mode, Stmt, StmtId};
use crate::value::Value;
pub use pose::Pose;
use proc_macro2::TokenStream;
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
    fn new(points: &[&Ident], turn: Turn, guide: Option<&Ident>) -> Self {
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

    /// Its position in `f64` at expansion time: what it finds goes into
    /// `pose`; returns its scaled determinant (`None` for statements without
    /// a rate system). `input` reads a driver's input value.
    fn eval(
        &self,
        pose: &mut Pose,
        input: &dyn Fn(&Ident) -> f64,
    ) -> Result<Option<f64>, mechanism_core::Error<f64>>;

    /// The core type of its solved position state (`grp_NAME`), `()` for none.
    fn position_type(&self) -> TokenStream;

    /// Its position code; `cos_sin`: emitting `position_cos_sin`.
    fn position(&self, cos_sin: bool) -> Solve;

    /// Its position code in the tracking form (`position_near`), which
    /// stays on the assembly of the previous position `pos`; `None`: the
    /// same as `position` (kinds with a single assembly per mode).
    fn position_tracking(&self) -> Option<Solve> {
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
    /// the self-test module).
    fn closure_axis(&self, _index: usize) -> TokenStream;

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
    fn det_code(&self) -> TokenStream;

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
    fn track(
        &self,
        _before: &dyn Fn(f64) -> Option<Pose>,
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

/// For a crank on the ground: its pivot and radius (`None` for other
/// statements, and for a crank carried by a moving link).
pub fn crank_arm(stmt: &Stmt) -> Option<(&Ident, &Value)> {
    match &stmt.kind {
        Kind::Crank {
            pivot,
            radius,
            carrier: None,
            ..
        } => Some((pivot, radius)),
        _ => None,
    }
}

/// For a crank whose input is marked `as cos_sin`: its input.
pub fn cos_sin_input(stmt: &Stmt) -> Option<&Ident> {
    match &stmt.kind {
        Kind::Crank {
            input,
            cos_sin: true,
            ..
        } => Some(input),
        _ => None,
    }
}

/// For a ground point: its coordinates (NaN where they do not fold).
pub fn ground_at(stmt: &Stmt) -> Option<(f64, f64)> {
    match &stmt.kind {
        Kind::Ground { x, y } => Some((pose::num(x), pose::num(y))),
        _ => None,
    }
}

/// For a ground point with literal coordinates: where it is.
pub fn literal_ground(stmt: &Stmt) -> Option<(f64, f64)> {
    match &stmt.kind {
        Kind::Ground { x, y } => Some((x.fold()?, y.fold()?)),
        _ => None,
    }
}

/// For a guide: its line as written.
pub fn as_guide(stmt: &Stmt) -> Option<GuideLine<'_>> {
    match &stmt.kind {
        Kind::Guide {
            origin,
            angle,
            carrier,
        } => Some(GuideLine {
            carrier: carrier.as_ref(),
            through: match origin {
                crate::model::Origin::Point(p) => Some(p),
                crate::model::Origin::Coords(..) => None,
            },
            angle,
        }),
        _ => None,
    }
}

/// For a guide: its carrier (`None`: fixed); `None` for other statements.
pub fn guide_carrier(stmt: &Stmt) -> Option<Option<&Ident>> {
    as_guide(stmt).map(|g| g.carrier)
}

/// The link that is a massless two-force member carrying no load: an
/// actuator's cylinder named as one link (`as (LINK, CYLINDER)`; with a
/// barrel and a rod the cylinder has mass).
pub fn cylinder(stmt: &Stmt) -> Option<&Ident> {
    match (&stmt.kind, stmt.links.as_slice()) {
        (Kind::Actuator { .. }, [_, cylinder]) => Some(cylinder),
        _ => None,
    }
}

/// For a point on a link: the link.
pub fn on_link(stmt: &Stmt) -> Option<&Ident> {
    match &stmt.kind {
        Kind::Point { link, .. } => Some(link),
        _ => None,
    }
}

/// The links of a statement, `a, b`, for listings.
fn links_text(stmt: &Stmt) -> String {
    let links: Vec<String> = stmt.links.iter().map(ToString::to_string).collect();
    links.join(", ")
}

/// How the structure listing writes an assembly mode.
fn mode_text(stmt: &Stmt, m: crate::model::Mode) -> String {
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
    Tracked(triad::Tracked),
    /// The stated assembly cannot be followed (an error was reported).
    Failed,
}

/// What the later stages know of the statements beside the model: the
/// findings of the check that a statement's evaluation and code read, and
/// the run-time modes assumed in place of their defaults. Passed forward
/// (the check to the sweep, to emit and to the run-time evaluator), never
/// written into the model.
#[derive(Clone, Default)]
pub struct Known {
    /// Each triad's assembly tracked over the input's range, by statement.
    pub tracked: BTreeMap<StmtId, triad::Tracked>,
    /// The value of each run-time mode parameter (by name) in place of its
    /// default, when checking the other modes (`check::modes`); empty: the
    /// defaults.
    pub modes: BTreeMap<String, Mode>,
}

/// The statement `id` of `stmts` as its kind, with what `known` says of it
/// (its tracked assembly, its assumed mode): the view the evaluator and
/// the position code read.
pub fn of_known<'a>(stmts: &'a [Stmt], id: StmtId, known: &'a Known) -> View<'a> {
    let stmt = &stmts[id];
    let mode = stmt
        .mode_param
        .as_ref()
        .and_then(|p| known.modes.get(&p.to_string()))
        .copied();
    view(stmt, mode, known.tracked.get(&id))
}

/// A statement seen as its kind: the kind's view of it, held by value (no
/// allocation), used through [`GroupKind`] (`View` derefs to it).
pub struct View<'a>(Repr<'a>);

/// The views of the kinds, one variant per kind.
enum Repr<'a> {
    Ground(ground::Ground<'a>),
    Guide(guide::Guide<'a>),
    Crank(crank::Crank<'a>),
    Slider(slider::Slider<'a>),
    Actuator(actuator::Actuator<'a>),
    Target(target::Target<'a>),
    Rrr(rrr::Rrr<'a>),
    Rrp(rrp::Rrp<'a>),
    Rpr(rpr::Rpr<'a>),
    Prp(prp::Prp<'a>),
    Rpp(rpp::Rpp<'a>),
    Point(point::Point<'a>),
    Triad(triad::TriadKind<'a>),
    Gear(gear::GearKind<'a>),
}

impl<'a> std::ops::Deref for View<'a> {
    type Target = dyn GroupKind<'a> + 'a;

    fn deref(&self) -> &Self::Target {
        match &self.0 {
            Repr::Ground(k) => k,
            Repr::Guide(k) => k,
            Repr::Crank(k) => k,
            Repr::Slider(k) => k,
            Repr::Actuator(k) => k,
            Repr::Target(k) => k,
            Repr::Rrr(k) => k,
            Repr::Rrp(k) => k,
            Repr::Rpr(k) => k,
            Repr::Prp(k) => k,
            Repr::Rpp(k) => k,
            Repr::Point(k) => k,
            Repr::Triad(k) => k,
            Repr::Gear(k) => k,
        }
    }
}

/// The statement `stmt` as its kind: the one dispatch from [`Kind`] to the
/// kinds' modules. The view borrows the statement's arguments and is built
/// on the stack (a few references), so a walker may call it per statement
/// and per sample.
pub fn of(stmt: &Stmt) -> View<'_> {
    view(stmt, None, None)
}

/// The view of `stmt` with the mode `given` in place of the written one
/// (when it has one) and its tracked assembly.
fn view<'a>(stmt: &'a Stmt, given: Option<Mode>, tracked: Option<&'a triad::Tracked>) -> View<'a> {
    View(match &stmt.kind {
        Kind::Ground { x, y } => Repr::Ground(ground::Ground { stmt, x, y }),
        Kind::Guide {
            origin,
            angle,
            carrier,
        } => Repr::Guide(guide::Guide {
            stmt,
            origin,
            angle,
            carrier: carrier.as_ref(),
        }),
        Kind::Crank {
            pivot,
            radius,
            input,
            cos_sin,
            carrier,
            zero,
        } => Repr::Crank(crank::Crank {
            stmt,
            pivot,
            radius,
            input,
            cos_sin: *cos_sin,
            carrier: carrier.as_ref(),
            zero,
        }),
        Kind::Slider {
            guide,
            input,
            offset,
        } => Repr::Slider(slider::Slider {
            stmt,
            guide,
            input,
            offset,
        }),
        Kind::Actuator {
            a,
            l,
            b,
            input,
            mode,
        } => Repr::Actuator(actuator::Actuator {
            stmt,
            a,
            l,
            b,
            input,
            mode: given.unwrap_or(*mode),
        }),
        Kind::Target { x, y } => Repr::Target(target::Target { stmt, x, y }),
        Kind::Rrr { a, l1, b, l2, mode } => Repr::Rrr(rrr::Rrr {
            stmt,
            a,
            l1,
            b,
            l2,
            mode: given.unwrap_or(*mode),
        }),
        Kind::Rrp {
            a,
            l,
            guide,
            mode,
            offset,
        } => Repr::Rrp(rrp::Rrp {
            stmt,
            a,
            l,
            guide,
            mode: given.unwrap_or(*mode),
            offset,
        }),
        Kind::Rpr { a, b, mode, offset } => Repr::Rpr(rpr::Rpr {
            stmt,
            a,
            b,
            mode: given.unwrap_or(*mode),
            offset,
        }),
        Kind::Prp {
            g1,
            g2,
            offset1,
            offset2,
        } => Repr::Prp(prp::Prp {
            stmt,
            g1,
            g2,
            offset1,
            offset2,
        }),
        Kind::Rpp {
            a,
            guide,
            slot,
            offset,
        } => Repr::Rpp(rpp::Rpp {
            stmt,
            a,
            guide,
            slot,
            offset,
        }),
        Kind::Point { link, from, local } => Repr::Point(point::Point {
            stmt,
            link,
            from,
            local,
        }),
        Kind::Triad(t) => Repr::Triad(triad::TriadKind { stmt, t, tracked }),
        Kind::Gear(g) => Repr::Gear(gear::GearKind { stmt, g }),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::Diagnostics;
    use crate::model::Model;

    /// The definition `src` lowered (it must have no errors).
    fn lowered(src: &str) -> Model {
        let def = syn::parse_str::<crate::parse::Definition>(src).expect("parses");
        let mut diag = Diagnostics::new();
        let model = crate::model::lower(def, &mut diag);
        let errors: Vec<String> = diag.finish().iter().map(ToString::to_string).collect();
        assert!(errors.is_empty(), "{errors:?}");
        model
    }

    /// One statement of every kind.
    const EVERY_KIND: &str = "pub M {
        let O = ground(0.0, 0.0);
        let O4 = ground(3.0, 0.0);
        let A = crank(O, 1.0, theta) as link2;
        let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
        let P = point(link3, from A, 1.0, 30 deg);
        let line = guide((0.0, -1.0), 0 deg);
        let S = slider(line, s) as block;
        let E = rrp(P, 2.0, line, plus) as (rod, slide);
        let z = rpr(B, O, plus) as (pin, arm);
        let gv = guide((5.0, 0.0), 90 deg);
        let Q = rpp(S, gv, 90 deg) as (qpin, yoke);
        let gy = guide(Q, yoke, 45 deg);
        let F = prp(gy, line) as (pa, pb);
        let C = actuator(O, 1.2, O4, len, left) as (boom, cylinder);
    }";

    #[test]
    fn every_kind_describes_the_links_the_model_gives_it() {
        // Proves each kind's link shapes match the links the lowering gave
        // its statement (one shape per link, in order), and each shape's
        // points are the statement's references or its own point.
        let model = lowered(EVERY_KIND);
        assert_eq!(model.stmts.len(), 14);
        for stmt in &model.stmts {
            let kind = of(stmt);
            let shapes = kind.link_shapes();
            assert_eq!(shapes.len(), stmt.links.len(), "{}", stmt.name);
            assert_eq!(shapes.len(), stmt.kind.link_count(), "{}", stmt.name);
            let refs: Vec<PointName> = kind
                .references()
                .iter()
                .map(|(r, _)| PointName::of(r))
                .collect();
            for shape in &shapes {
                for p in &shape.points {
                    assert!(refs.contains(p) || *p == stmt.name, "{}: {p}", stmt.name);
                }
            }
        }
    }

    #[test]
    fn evaluator_steps_close_the_four_bar() {
        // Proves the kinds' f64 steps solve a four-bar at theta = 0.7: the
        // crank tip at (cos, sin) of the input, the RRR joint at l1 = 3 from
        // `A` and l2 = 2.5 from `O4` (1e-12: a few roundings of numbers of
        // size 3), on the left of `A -> O4`, and its determinant in (0, 1].
        let model = lowered(
            "pub M {
                let O = ground(0.0, 0.0);
                let O4 = ground(3.0, 0.0);
                let A = crank(O, 1.0, theta) as link2;
                let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
            }",
        );
        let theta = 0.7;
        let input = |_: &Ident| theta;
        let mut pose = Pose::default();
        let mut dets = Vec::new();
        for stmt in &model.stmts {
            dets.push(of(stmt).eval(&mut pose, &input).expect("assembles"));
        }
        let id = |n: &str| syn::Ident::new(n, proc_macro2::Span::call_site());
        let (a, b, o4) = (
            pose.point(&id("A")),
            pose.point(&id("B")),
            pose.point(&id("O4")),
        );
        assert!((a.x - theta.cos()).abs() <= 1e-15 && (a.y - theta.sin()).abs() <= 1e-15);
        assert!(((b - a).norm() - 3.0).abs() <= 1e-12);
        assert!(((b - o4).norm() - 2.5).abs() <= 1e-12);
        let (r, s) = (o4 - a, b - a);
        assert!(r.x * s.y - r.y * s.x > 0.0, "B is not left of A -> O4");
        assert_eq!(&dets[..3], &[None, None, None]);
        let det = dets[3].expect("the RRR has a rate system");
        assert!(det > 0.0 && det <= 1.0, "{det}");
    }
}
