//! The loop-closure residuals of `#[self_test]`: each kind's constraints,
//! written from the definition (not from the generated position code) as
//! `f64` residuals recomputed from the solved points, and its links' unit
//! axes from those points. Helpers (`pt`, `vc`, `sub`, `norm`, `cross`,
//! `dot`, `turn`, `unit_of`, `wrong_side`) are those of the generated
//! self-test module.

use super::reads::Reads;
use crate::model::Mode;
use crate::value::Value;
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// What a residual's rounding scales with (its tolerance is 64 eps times
/// this): a length residual with the mechanism's size; a guide direction
/// (the difference of two unit vectors, dimensionless) computed from an
/// angle with 1; one turned from a link's axis, recomputed from two solved
/// points, with the size over the shortest link (the axis's rounding).
#[derive(Clone, Copy)]
pub enum Scale {
    /// With the mechanism's size.
    Length,
    /// With 1.
    Direction,
    /// With the size over the shortest link.
    CarriedDirection,
}

impl Scale {
    /// The scale as code of the generated `loop_closure` (`size`, the
    /// mechanism's size at the pose, and `L_MIN` in scope).
    pub fn emit(self) -> TokenStream {
        match self {
            Scale::Length => quote!(size),
            Scale::Direction => quote!(1.0),
            Scale::CarriedDirection => quote!(size / L_MIN),
        }
    }
}

/// One constraint of one statement.
pub struct Residual {
    /// `"<statement>: <constraint>"`, for the failure message.
    pub label: String,
    /// Code of an `f64` residual, zero when the constraint holds (lengths in
    /// the definition's unit; reads `pos`).
    pub code: TokenStream,
    /// What its rounding scales with.
    pub scale: Scale,
}

/// Residuals of one statement, labelled with its name.
pub struct Residuals<'a> {
    /// The statement's (point's) name.
    pub n: &'a Ident,
    /// Its constraints, in the generated order.
    pub list: Vec<Residual>,
    /// The recorder of the residuals' reads of `pos`.
    pub reads: &'a Reads,
}

impl<'a> Residuals<'a> {
    /// No residuals yet for statement `n`; `reads` records their reads.
    pub fn new(n: &'a Ident, reads: &'a Reads) -> Self {
        Residuals {
            n,
            list: Vec::new(),
            reads,
        }
    }

    /// `pos.FIELD`, recorded (see [`Reads::pos`]).
    pub fn pos(&self, field: &Ident) -> TokenStream {
        self.reads.pos(field)
    }

    /// Adds the constraint `what` with residual `code` and its scale.
    pub fn push_scaled(&mut self, what: &str, code: TokenStream, scale: Scale) {
        let label = format!("{}: {what}", self.n);
        self.list.push(Residual { label, code, scale });
    }

    /// Adds a length constraint (its rounding scales with the size).
    pub fn push(&mut self, what: &str, code: TokenStream) {
        self.push_scaled(what, code, Scale::Length);
    }

    /// The assembly branch of a dyad on the two points `a`, `b`: the point
    /// on the side of `a -> b` that `mode` names.
    pub fn dyad_branch(&mut self, a: &Ident, b: &Ident, mode: Mode) {
        let (n, m) = (self.pos(self.n), mode_sign(mode));
        let (a, b) = (self.pos(a), self.pos(b));
        self.push(
            "assembly branch",
            quote!(wrong_side(#m * cross(sub(pt(&#b), pt(&#a)), sub(pt(&#n), pt(&#a))) / norm(sub(pt(&#b), pt(&#a))))),
        );
    }

    /// The point on a guide's offset line: `cross(dir, P - origin) = offset`.
    pub fn on_offset_line(&mut self, what: &str, guide: &Ident, offset: &Value) {
        let (n, o) = (self.pos(self.n), f(offset));
        let guide = self.pos(guide);
        self.push(
            what,
            quote!(cross(vc(&#guide.dir), sub(pt(&#n), pt(&#guide.origin))) - #o),
        );
    }

    /// The point at `length` from `from`: `|P - from| = length`.
    pub fn at_length(&mut self, what: &str, from: &Ident, length: TokenStream) {
        let (n, from) = (self.pos(self.n), self.pos(from));
        self.push(what, quote!(norm(sub(pt(&#n), pt(&#from))) - #length));
    }
}

/// Code of a definition value as an `f64` (`T` is the mechanism's scalar).
pub fn f(v: &Value) -> TokenStream {
    let e = v.emit();
    quote!(<T as ::mechanism::Real>::as_f64(#e))
}

/// The sign of an assembly mode: +1 for `Plus`, -1 for `Minus`.
pub fn mode_sign(m: Mode) -> f64 {
    match m {
        Mode::Plus => 1.0,
        Mode::Minus => -1.0,
    }
}

/// The unit axis from point `from` to point `to` (code, from the solved
/// points; `reads` records the reads).
pub fn axis_between(from: &Ident, to: &Ident, reads: &Reads) -> TokenStream {
    let (from, to) = (reads.pos(from), reads.pos(to));
    quote!(unit_of(sub(pt(&#to), pt(&#from))))
}

/// A guide's unit direction (code; `reads` records the read).
pub fn guide_axis(guide: &Ident, reads: &Reads) -> TokenStream {
    let guide = reads.pos(guide);
    quote!(unit_of(vc(&#guide.dir)))
}
