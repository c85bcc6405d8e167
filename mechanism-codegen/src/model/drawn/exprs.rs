//! The pieces of a written statement: a joint's name or a generated
//! expression as an argument, and the drawn distances and angles that the
//! statements' arguments are computed from (`hypot`, `atan2` of the joints'
//! coordinates, folded later as numbers). Shared by `emit.rs` and `gear.rs`.

use super::steps::Frame;
use super::{Drawing, Joint};
use crate::parse::Arg;
use proc_macro2::{Group, Span, TokenStream, TokenTree};
use quote::quote;
use syn::{Expr, Ident};

/// A generated expression as an argument, every token of it spanned on
/// `at` (the user's name it is computed for), so that a message about it
/// (an overflow, a value outside a range) points into the definition.
pub(super) fn value(t: TokenStream, at: Span) -> Arg {
    Arg::Value(
        syn::parse2(respan(t, at)).expect("a generated expression parses"),
        None,
    )
}

/// `t` with every token spanned on `at`.
fn respan(t: TokenStream, at: Span) -> TokenStream {
    t.into_iter()
        .map(|tree| match tree {
            TokenTree::Group(g) => {
                let mut group = Group::new(g.delimiter(), respan(g.stream(), at));
                group.set_span(at);
                TokenTree::Group(group)
            }
            mut other => {
                other.set_span(at);
                other
            }
        })
        .collect()
}

/// A joint's name as an argument.
pub(super) fn name(j: &Joint) -> Arg {
    name_arg(&j.name)
}

/// A name as an argument.
pub(super) fn name_arg(i: &Ident) -> Arg {
    Arg::Value(Expr::Path(syn::parse_quote!(#i)), None)
}

/// `hypot(xb - xa, yb - ya)`.
pub(super) fn distance(a: &Joint, b: &Joint) -> TokenStream {
    let (ax, ay, bx, by) = (&a.x, &a.y, &b.x, &b.y);
    quote!(hypot((#bx) - (#ax), (#by) - (#ay)))
}

/// The drawn angle of frame `f`'s axis (rad, counter-clockwise from +x, in
/// (-pi, pi]): `atan2(ty - oy, tx - ox)`.
pub(super) fn angle_of(d: &Drawing, f: Frame) -> TokenStream {
    let (o, t) = (d.joint(f.origin), d.joint(f.toward));
    let (ox, oy, tx, ty) = (&o.x, &o.y, &t.x, &t.y);
    quote!(atan2((#ty) - (#oy), (#tx) - (#ox)))
}

/// The angle (rad, counter-clockwise) from the direction of frame `a` to
/// that of frame `b`: `atan2(a x b, a . b)`.
pub(super) fn turn(d: &Drawing, a: Frame, b: Frame) -> TokenStream {
    let v = |f: Frame| {
        let (o, t) = (d.joint(f.origin), d.joint(f.toward));
        let (ox, oy, tx, ty) = (&o.x, &o.y, &t.x, &t.y);
        (quote!(((#tx) - (#ox))), quote!(((#ty) - (#oy))))
    };
    let ((ax, ay), (bx, by)) = (v(a), v(b));
    quote!(atan2(#ax * #by - #ay * #bx, #ax * #bx + #ay * #by))
}
