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
        fn link_shapes(&self) -> Vec<super::group::LinkShape> {
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

        fn closure_axis(
            &self,
            _index: usize,
            _reads: &super::reads::Reads,
        ) -> ::proc_macro2::TokenStream {
            ::quote::quote!([1.0, 0.0])
        }

        fn link_lengths(&self) -> Vec<&$l crate::value::Value> {
            Vec::new()
        }

        fn primitive(&self) -> &'static str {
            "LinkPoint"
        }

        fn det_code(&self, _reads: &super::reads::Reads) -> ::proc_macro2::TokenStream {
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

mod accessors;
mod actuator;
pub mod closure;
mod crank;
pub mod forces;
pub(crate) mod gear;
mod ground;
mod group;
mod guide;
pub mod lane;
mod lane_shapes;
pub mod motors;
mod point;
pub mod pose;
mod prp;
pub mod rates;
pub mod reads;
mod rpp;
mod rpr;
mod rrp;
mod rrr;
pub mod run;
mod slider;
mod specs;
mod target;
pub(crate) mod tokens;
pub mod triad;
pub mod word;

pub use accessors::{as_guide, cos_sin_input, cylinder, guide_carrier, literal_ground, on_link};
pub use group::{GroupKind, GuideLine, LinkShape, Placed, Role, Solve, Tracked, Tracking, Turn};

use crate::model::{Kind, Mode, Stmt, StmtId};
use std::collections::BTreeMap;

/// What the later stages know of the statements beside the model: the
/// findings of the check that a statement's evaluation and code read, and
/// the run-time modes assumed in place of their defaults. Passed forward
/// (the check to the sweep, to emit and to the run-time evaluator), never
/// written into the model.
#[derive(Clone, Default)]
pub struct Known {
    /// Each triad's assembly tracked over the input's range, by statement.
    pub tracked: BTreeMap<StmtId, Tracked>,
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
fn view<'a>(stmt: &'a Stmt, given: Option<Mode>, tracked: Option<&'a Tracked>) -> View<'a> {
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
    use crate::keys::PointName;
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
}
