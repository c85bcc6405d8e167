//! Token helpers shared by every kind's emitted code: the generated locals
//! (`pos_NAME`, `grp_NAME`), the error tag of a core call, assembly modes and
//! unit vectors folded when literal.

use crate::model::{Mode, Stmt};
use crate::names::Family;
use crate::value::{lit, Value};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

/// `::mechanism::Mode::Plus` or `Minus`.
pub(crate) fn mode_tokens(mode: Mode) -> TokenStream {
    match mode {
        Mode::Plus => quote!(::mechanism::Mode::Plus),
        Mode::Minus => quote!(::mechanism::Mode::Minus),
    }
}

/// The assembly mode argument of a statement's core call: its literal
/// `mode` (`::mechanism::Mode::Plus`), or `self.PARAM` when the definition
/// makes it a run-time parameter (`params { circuit = left }`).
pub(crate) fn mode_arg(stmt: &Stmt, mode: Mode) -> TokenStream {
    match &stmt.mode_param {
        Some(param) => quote!(self.#param),
        None => mode_tokens(mode),
    }
}

/// A unit vector at a given angle: folded at expansion time when literal.
pub(crate) fn unit_vector(angle: &Value) -> TokenStream {
    match angle.fold() {
        Some(a) => {
            let (s, c) = a.sin_cos();
            let (c, s) = (lit(c), lit(s));
            quote!(::mechanism::Vector2::new(#c, #s))
        }
        None => {
            let a = angle.emit();
            quote!(::mechanism::geometry::unit(#a))
        }
    }
}

/// The local variable of the position code that holds the user's name
/// `name` (a point, a guide, a link angle or a slide): `pos_NAME`. A bare
/// `let NAME = ..` would be a pattern, not a binding, wherever a constant,
/// static or unit struct of that name is in scope (`const G: f64 = 9.81;`
/// beside a point `G`), and would not compile. The velocity and acceleration
/// code already use `vel_NAME` and `acc_NAME`.
pub(crate) fn local(name: &Ident) -> Ident {
    Family::Pos.of(name)
}

/// `grp_NAME`: the solved position state of a statement's group or driver.
pub(crate) fn grp(stmt: &Stmt) -> Ident {
    Family::Grp.of(&stmt.name)
}

/// `.map_err(|e| e.in_group(NAME))?`: tags a core error with the statement's name.
pub(crate) fn tag(stmt: &Stmt) -> TokenStream {
    let name = stmt.name.to_string();
    quote!(.map_err(|e| e.in_group(#name))?)
}

/// `axis_LINK`: the local (and hidden position field) holding a link's unit axis.
pub(crate) fn axis(link: &Ident) -> Ident {
    Family::Axis.of(link)
}

/// `(unit, raw)` direction of a link along a guide: the guide's direction.
pub(crate) fn along(guide: &Ident) -> (TokenStream, TokenStream) {
    let guide = local(guide);
    (quote!(#guide.dir), quote!(#guide.dir))
}

/// `(unit, raw)` direction of a link that is a group's vector `field`
/// (`r1`, `r2`) of length `length`.
pub(crate) fn arm(stmt: &Stmt, field: &str, length: TokenStream) -> (TokenStream, TokenStream) {
    let (g, f) = (grp(stmt), format_ident!("{}", field));
    (quote!(#g.#f / #length), quote!(#g.#f))
}

/// `(unit, raw)` direction of a link that is a group's unit vector `field`.
pub(crate) fn unit_field(stmt: &Stmt, field: &str) -> (TokenStream, TokenStream) {
    let (g, f) = (grp(stmt), format_ident!("{}", field));
    (quote!(#g.#f), quote!(#g.#f))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::value::ValueKind;
    use proc_macro2::Span;

    fn flat(code: &TokenStream) -> String {
        code.to_string().split_whitespace().collect()
    }

    // Proves a literal angle's unit vector is folded at expansion into two
    // literals (sin 90 deg exactly 1) while a parameter angle calls
    // `geometry::unit` at run time.
    #[test]
    fn unit_vector_folds_literal_angles_only() {
        let right = Value::lit(std::f64::consts::FRAC_PI_2, Span::call_site());
        let folded = flat(&unit_vector(&right));
        assert!(folded.starts_with("::mechanism::Vector2::new("), "{folded}");
        assert!(
            folded.ends_with(",<Tas::mechanism::Real>::lit(1f64))"),
            "{folded}"
        );
        assert!(!folded.contains("unit("), "{folded}");
        let param = Value {
            kind: ValueKind::Param(format_ident!("phi")),
            span: Span::call_site(),
            tokens: quote!(phi),
        };
        assert_eq!(
            flat(&unit_vector(&param)),
            "::mechanism::geometry::unit(self.phi)"
        );
    }
}
