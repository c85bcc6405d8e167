//! `ground(x, y)`: a fixed point.

use super::group::{GroupKind, Role, Solve};
use super::lane::{Lane, PointLocals, Step};
use super::run::{Compile, ForceRunCx, Me, RunCx, RunPose};
use crate::keys::LinkName;
use crate::model::Stmt;
use crate::value::Value;
use mechanism_core::Point2;
use quote::quote;
use syn::Ident;

/// How `ground` is written: its word, usage, arity and links.
pub(crate) const SPEC: super::word::Spec = super::word::Spec {
    word: super::word::KindWord::Ground,
    text: "ground",
    usage: "ground(x, y)",
    arity: super::word::Arity::Range(2, 2),
    links: "",
    inputs: &[],
    mode_at: None,
    mode_words: &[],
    group: None,
};

/// A `ground` statement.
pub(super) struct Ground<'a> {
    pub stmt: &'a Stmt,
    pub x: &'a Value,
    pub y: &'a Value,
}

impl<'a> GroupKind<'a> for Ground<'a> {
    fn references(&self) -> Vec<(&'a Ident, Role)> {
        vec![]
    }

    fn point_owner(&self) -> Option<Option<LinkName>> {
        Some(None)
    }

    fn position_values(&self) -> Vec<Value> {
        vec![self.x.clone(), self.y.clone()]
    }

    fn position(&self, _cos_sin: bool) -> Solve {
        let (x, y) = (self.x.emit(), self.y.emit());
        Solve::Own {
            expr: quote!(::mechanism::Point2::new(#x, #y)),
            ty: quote!(::mechanism::Point2<T>),
        }
    }

    fn describe(&self) -> String {
        format!("ground point `{}`", self.stmt.name)
    }

    fn point_kind(&self) -> Option<&'static str> {
        Some("Ground")
    }

    fn point_moves(
        &self,
        _link_turns: &dyn Fn(&Ident) -> bool,
        _moves: &dyn Fn(&Ident) -> bool,
    ) -> bool {
        false
    }

    fn given_by_caller(&self, output: &Ident) -> bool {
        self.stmt.name == *output
    }

    /// Its lane code in the batch kernel (`None`: an argument the kernel
    /// does not know; the batch then takes the scalar path).
    fn lane(&self, _lane: &mut Lane, s: &mut Step<'_>) -> Option<()> {
        lane_steps(s, self.x, self.y);
        Some(())
    }

    linkless_facets!('a);
}

/// A ground point at `(x, y)` (length unit): its position locals are the
/// coordinates, its velocity and acceleration locals `zero` (later code
/// reads them like any point's; the compiler folds them). No core call,
/// nothing to check beyond the coordinates (see `Lane::commit`).
fn lane_steps(s: &mut Step, x: &Value, y: &Value) {
    let PointLocals {
        px,
        py,
        vx,
        vy,
        ax,
        ay,
    } = s.own.clone();
    let (x, y) = (x.emit(), y.emit());
    s.emit(quote! {
        let #px = #x; let #py = #y;
        let #vx = zero; let #vy = zero;
        let #ax = zero; let #ay = zero;
    });
}

impl super::run::RunKind for Ground<'_> {
    fn compile(&self, cx: &Compile<'_>) -> Box<dyn super::run::Step> {
        Box::new(GroundRun {
            me: cx.me(self.stmt),
            at: Point2::new(cx.num(self.x), cx.num(self.y)),
        })
    }
}

/// A ground point, compiled: its slots and its place (L).
struct GroundRun {
    me: Me,
    at: Point2<f64>,
}

impl super::run::Step for GroundRun {
    fn group(&self) -> &'static str {
        self.me.group
    }

    fn walks(&self) -> super::run::Walks {
        super::run::Walks {
            rates: false,
            forces: false,
        }
    }

    fn position(&self, pose: &mut RunPose) -> Result<Option<f64>, mechanism_core::Error<f64>> {
        pose.found(&self.me, self.at, &[]);
        Ok(None)
    }

    fn rates(&self, _cx: &mut RunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        Ok(())
    }

    fn forces(&self, _cx: &mut ForceRunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        Ok(())
    }

    fn link_dir(&self, _index: usize, _pose: &RunPose) -> mechanism_core::Vector2<f64> {
        mechanism_core::Vector2::x()
    }
}
