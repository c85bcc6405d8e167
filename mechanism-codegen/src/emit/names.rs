//! Names and small token helpers shared by the emitters: the generated types'
//! names, the locals of the position code, the error tag of a statement.

use crate::keys::PointName;
use crate::model::Model;
use crate::names::Family;
use crate::plan::Outputs;
use crate::value::lit;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use std::collections::BTreeSet;
use syn::Ident;

/// The inputs of the drivers, in statement order.
pub(super) fn input_names(model: &Model) -> Vec<Ident> {
    model
        .stmts
        .iter()
        .flat_map(|s| s.kind.inputs().into_iter().cloned())
        .collect()
}

/// The names of the generated types of one mechanism (`FourBar`,
/// `FourBarPosition`, ...).
pub(super) struct TypeNames {
    /// The mechanism's own struct (the user's name).
    pub name: Ident,
    pub position: Ident,
    pub velocity: Ident,
    pub acceleration: Ident,
    pub input: Ident,
    pub solution: Ident,
    pub forces: Ident,
    pub loads: Ident,
    pub cos_sin: Ident,
}

impl TypeNames {
    pub fn of(model: &Model) -> Self {
        let name = &model.name;
        TypeNames {
            name: name.clone(),
            position: format_ident!("{}Position", name),
            velocity: format_ident!("{}Velocity", name),
            acceleration: format_ident!("{}Acceleration", name),
            input: format_ident!("{}Input", name),
            solution: format_ident!("{}Solution", name),
            forces: format_ident!("{}Forces", name),
            loads: format_ident!("{}Loads", name),
            cos_sin: format_ident!("{}CosSin", name),
        }
    }
}

/// Generated code of one item family: items (structs, impls of traits) and
/// the inherent methods that go into the mechanism's `impl`.
#[derive(Default)]
pub(super) struct Generated {
    pub items: TokenStream,
    pub methods: TokenStream,
}

impl Generated {
    /// Appends `other`'s items and methods after this one's.
    pub fn push(&mut self, other: Generated) {
        self.items.extend(other.items);
        self.methods.extend(other.methods);
    }
}

/// The lints the generated impls allow: folded constants (the cosine of 45
/// deg, say) are long literals that clippy's `approx_constant` (deny by
/// default), `excessive_precision` and `unreadable_literal` would flag in the
/// user's crate (`tests/hygiene.rs`, `lint_clean`).
pub(crate) fn allow_literal_lints() -> TokenStream {
    quote!(#[allow(clippy::approx_constant, clippy::excessive_precision, clippy::unreadable_literal)])
}

pub(crate) use crate::kinds::tokens::{grp, local, tag};

/// The motion of a known point as an optional argument of a core call:
/// `Some(&SCOPE PREFIX_POINT)` when it moves, `None` when it is still.
pub(super) fn opt_point(
    point: &Ident,
    moving: &BTreeSet<PointName>,
    family: Family,
    scope: &TokenStream,
) -> TokenStream {
    if moving.contains(&PointName::of(point)) {
        let v = family.of(point);
        quote!(::core::option::Option::Some(&#scope #v))
    } else {
        quote!(::core::option::Option::None)
    }
}

/// The marker field (and its initializer) of a struct none of whose fields
/// has the type `T` (`outputs { }`, or only what no later code reads):
/// without it rustc rejects the unused parameter. Empty when `empty` is false.
pub(super) fn marker(empty: bool) -> (TokenStream, TokenStream) {
    if empty {
        (
            quote!(#[doc(hidden)] pub _scalar: ::core::marker::PhantomData<T>,),
            quote!(_scalar: ::core::marker::PhantomData,),
        )
    } else {
        (TokenStream::new(), TokenStream::new())
    }
}

/// Doc comments of the output fields at `level` (0 position, 1 velocity, 2
/// acceleration), in the order points, links, slides.
pub(super) fn output_docs(out: &Outputs, level: usize) -> Vec<String> {
    let (p, l, s) = match level {
        0 => (
            "Point `{}` (length units).",
            "Angle of link `{}` from +x (rad, in (-pi, pi], counter-clockwise).",
            "Slide displacement `{}` (length units).",
        ),
        1 => (
            "Velocity of point `{}` (length units/s).",
            "Angular velocity of link `{}` (rad/s, counter-clockwise positive).",
            "Rate of slide displacement `{}` (length units/s).",
        ),
        _ => (
            "Acceleration of point `{}` (length units/s^2).",
            "Angular acceleration of link `{}` (rad/s^2).",
            "Second derivative of slide displacement `{}` (length units/s^2).",
        ),
    };
    let fill = |t: &str, n: &Ident| t.replace("{}", &n.to_string());
    out.points
        .iter()
        .map(|n| fill(p, n))
        .chain(out.links.iter().map(|n| fill(l, n)))
        .chain(out.slides.iter().map(|n| fill(s, &n.name)))
        .collect()
}

/// The literal 0 of the scalar type.
pub(super) fn lit_zero() -> TokenStream {
    lit(0.0)
}

/// `Debug` for a result struct that shows the user's fields only (the
/// outputs, and `extra` such as the velocity's `condition`), not the
/// solver state the struct keeps for later analyses.
pub fn debug_impl(ty: &Ident, outputs: &[Ident], extra: &[&str]) -> TokenStream {
    let text = ty.to_string();
    let names = outputs.iter().map(|o| o.to_string());
    let extra_idents = extra.iter().map(|e| format_ident!("{}", e));
    quote! {
        impl<T: ::mechanism::Real> ::core::fmt::Debug for #ty<T> {
            fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
                f.debug_struct(#text)
                    #(.field(#names, &self.#outputs))*
                    #(.field(#extra, &self.#extra_idents))*
                    .finish()
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flat(code: &TokenStream) -> String {
        code.to_string().split_whitespace().collect()
    }

    // Proves the marker is added only to a struct with no field of type `T`,
    // with its initializer.
    #[test]
    fn marker_only_when_empty() {
        let (field, init) = marker(true);
        assert!(flat(&field).contains("PhantomData<T>"));
        assert_eq!(flat(&init), "_scalar:::core::marker::PhantomData,");
        let (field, init) = marker(false);
        assert!(field.is_empty() && init.is_empty());
    }
}
