//! What the derives written on a definition generate (`parse::attrs`):
//!
//! - `Serialize`: an impl over the user's fields only, for every public data
//!   type the definition generates (the mechanism's parameters and modes, the
//!   inputs, the loads, the position, velocity, acceleration, forces and
//!   solution structs): the keys are the definition's names, the hidden
//!   values the structs keep for later analyses are not written, so
//!   `serde_json::to_string(&solution)` holds the user's outputs and nothing
//!   else.
//! - `Deserialize`: for the types that hold only the user's values (the
//!   mechanism, the inputs, the loads), through a private struct with serde's
//!   own derive (unknown keys are errors, a missing key too).
//! - any other derive: passed on to the mechanism's struct and its inputs
//!   struct, whose fields are all the user's.
//!
//! The serde impls name serde through the facade
//! (`::mechanism::__interop::serde`), inside `::mechanism::__with_serde!`,
//! which emits nothing with the facade's feature `serde` off; a call of
//! `::mechanism::__interop::serde_feature` on the derive's tokens is then a
//! compile error there saying how to turn it on.

use super::forces::ForceField;
use super::names::TypeNames;
use crate::model::{Level, Model};
use crate::parse::DeriveKind;
use crate::plan::Plan;
use proc_macro2::{Span, TokenStream};
use quote::{format_ident, quote, quote_spanned};
use syn::Ident;

/// The attributes of the derives passed on as written (`#[derive(PATH)]`,
/// `#[cfg_attr(PRED, derive(PATH))]`), for the mechanism's and the inputs'
/// structs.
pub fn passed_on(model: &Model) -> TokenStream {
    model
        .derives
        .iter()
        .filter(|d| d.kind == DeriveKind::Other)
        .map(|d| d.attribute())
        .collect()
}

/// A generated data type and its fields (the user's), in order.
struct DataType {
    ty: Ident,
    fields: Vec<Ident>,
    /// Holds only the user's values, so it can be deserialized.
    owned: bool,
}

/// The definition's data types, as far as its analysis level goes;
/// `forces`: the forces struct's reaction and effort fields, with a force
/// analysis.
fn data_types(model: &Model, plan: &Plan, forces: Option<&[(Ident, ForceField)]>) -> Vec<DataType> {
    let names = TypeNames::of(model);
    let own = |ty: &Ident, fields: Vec<Ident>| DataType {
        ty: ty.clone(),
        fields,
        owned: true,
    };
    let result = |ty: &Ident, fields: Vec<Ident>| DataType {
        ty: ty.clone(),
        fields,
        owned: false,
    };
    let mut params: Vec<Ident> = model.params.iter().map(|(n, _)| n.clone()).collect();
    params.extend(model.modes.iter().map(|(n, _)| n.clone()));
    let inputs = super::names::input_names(model);
    let mut out = vec![own(&names.name, params), own(&names.input, inputs)];
    let loads = &model.kinetics.loads;
    if model.has_forces() && !loads.is_empty() {
        out.push(own(
            &names.loads,
            loads.iter().map(|(n, _)| n.clone()).collect(),
        ));
    }
    let o = &plan.outputs;
    let outputs: Vec<Ident> = o
        .points
        .iter()
        .chain(&o.links)
        .cloned()
        .chain(o.slides.iter().map(|s| s.name.clone()))
        .collect();
    out.push(result(&names.position, outputs.clone()));
    if model.level >= Level::Velocity {
        let mut v = outputs.clone();
        v.push(format_ident!("condition"));
        out.push(result(&names.velocity, v));
    }
    if model.level >= Level::Acceleration {
        out.push(result(&names.acceleration, outputs));
        let mut parts: Vec<Ident> = ["position", "velocity", "acceleration"]
            .iter()
            .map(|p| format_ident!("{}", p))
            .collect();
        if let Some(f) = forces {
            let mut fields: Vec<Ident> = f.iter().map(|(n, _)| n.clone()).collect();
            fields.extend([format_ident!("condition"), format_ident!("power_residual")]);
            out.push(result(&names.forces, fields));
            parts.push(format_ident!("forces"));
        }
        out.push(result(&names.solution, parts));
    }
    out
}

/// The serde impls the definition's `Serialize` and `Deserialize` derives
/// ask for (nothing without them).
pub fn emit(model: &Model, plan: &Plan, forces: Option<&[(Ident, ForceField)]>) -> TokenStream {
    let mut out = TokenStream::new();
    let types = data_types(model, plan, forces);
    for d in &model.derives {
        let span = d
            .path
            .segments
            .last()
            .map_or_else(Span::call_site, |s| s.ident.span());
        let impls: TokenStream = match d.kind {
            DeriveKind::Serialize => types.iter().map(serialize_impl).collect(),
            DeriveKind::Deserialize => types
                .iter()
                .filter(|t| t.owned)
                .map(|t| deserialize_impl(model, t))
                .collect(),
            DeriveKind::Other => continue,
        };
        let cfg = d.cfg_attr();
        // Without the facade's feature `serde`: an error on the derive.
        let feature = quote_spanned!(span=> ::mechanism::__interop::serde_feature::<()>());
        out.extend(quote! {
            #cfg
            const _: () = #feature;
            #cfg
            ::mechanism::__with_serde! { #impls }
        });
    }
    out
}

/// `Serialize` for `t`: a struct of its fields, keyed by their names.
fn serialize_impl(t: &DataType) -> TokenStream {
    let (ty, n) = (&t.ty, t.fields.len());
    let text = ty.to_string();
    let keys = t.fields.iter().map(Ident::to_string);
    let fields = &t.fields;
    quote! {
        impl<T: ::mechanism::Real + ::mechanism::__interop::serde::Serialize>
            ::mechanism::__interop::serde::Serialize for #ty<T>
        {
            fn serialize<S: ::mechanism::__interop::serde::Serializer>(
                &self,
                serializer: S,
            ) -> ::core::result::Result<S::Ok, S::Error> {
                use ::mechanism::__interop::serde::ser::SerializeStruct as _;
                let mut state = serializer.serialize_struct(#text, #n)?;
                #(state.serialize_field(#keys, &self.#fields)?;)*
                state.end()
            }
        }
    }
}

/// `Deserialize` for `t` (a type of the user's values only): serde's derive
/// on a private struct of the same fields, then moved over.
fn deserialize_impl(model: &Model, t: &DataType) -> TokenStream {
    let ty = &t.ty;
    let text = ty.to_string();
    let fields = &t.fields;
    let types: Vec<TokenStream> = fields
        .iter()
        .map(|f| {
            if model.modes.iter().any(|(m, _)| m == f) && *ty == model.name {
                quote!(::mechanism::Mode)
            } else {
                quote!(T)
            }
        })
        .collect();
    // The mechanism's struct without numeric parameters (none, or modes
    // only) has a marker field.
    let marker = (*ty == model.name && model.params.is_empty())
        .then(|| quote!(_scalar: ::core::marker::PhantomData,));
    let serde_path = "::mechanism::__interop::serde";
    quote! {
        const _: () = {
            #[derive(::mechanism::__interop::serde::Deserialize)]
            #[serde(crate = #serde_path, rename = #text, deny_unknown_fields)]
            #[allow(non_snake_case)]
            struct Fields<T> {
                #(#fields: #types,)*
                #[serde(skip)]
                _scalar: ::core::marker::PhantomData<T>,
            }
            impl<'de, T: ::mechanism::Real + ::mechanism::__interop::serde::Deserialize<'de>>
                ::mechanism::__interop::serde::Deserialize<'de> for #ty<T>
            {
                fn deserialize<D: ::mechanism::__interop::serde::Deserializer<'de>>(
                    deserializer: D,
                ) -> ::core::result::Result<Self, D::Error> {
                    let v = <Fields<T> as ::mechanism::__interop::serde::Deserialize<'de>>::deserialize(deserializer)?;
                    ::core::result::Result::Ok(#ty { #(#fields: v.#fields,)* #marker })
                }
            }
        };
    }
}

#[cfg(test)]
mod tests {
    use crate::emit::test_support::{flat, four_bar};
    use proc_macro2::TokenStream;
    use std::str::FromStr;

    /// The expansion of `src` without whitespace.
    fn expand(src: &str) -> String {
        flat(&crate::expand(TokenStream::from_str(src).unwrap()))
    }

    // Proves a derive the macro does not generate goes, as written (with its
    // `cfg_attr`), onto the mechanism's and the inputs' structs only.
    #[test]
    fn other_derives_go_onto_the_parameter_and_input_structs() {
        let code = expand(&format!(
            "#[derive(my::Thing)] #[cfg_attr(feature = \"x\", derive(Other))] {}",
            four_bar("")
        ));
        let thing = "#[derive(my::Thing)]#[cfg_attr(feature=\"x\",derive(Other))]";
        assert_eq!(code.matches(thing).count(), 2, "{code}");
        assert!(
            code.contains(&format!("{thing}pubstructFourBar<")),
            "{code}"
        );
        assert!(
            code.contains(&format!(
                "{thing}#[allow(non_snake_case)]pubstructFourBarInput<"
            )),
            "{code}"
        );
    }

    // Proves `Serialize` writes the user's names of each struct and none of
    // the hidden fields the structs keep (`grp_B` is kept in the position for
    // the velocity code), behind the feature gate and its `cfg`; and that a
    // definition without derives has no serde code at all.
    #[test]
    fn serialize_writes_user_fields_only_behind_the_gates() {
        let code = expand(&format!(
            "#[cfg_attr(feature = \"x\", derive(serde::Serialize))] {}",
            four_bar("")
        ));
        assert!(
            code.contains(
                "#[cfg(feature=\"x\")]const_:()=::mechanism::__interop::serde_feature::<()>();"
            ),
            "{code}"
        );
        assert!(
            code.contains("#[cfg(feature=\"x\")]::mechanism::__with_serde!{"),
            "{code}"
        );
        assert!(
            code.contains("serialize_struct(\"FourBarPosition\",8usize)"),
            "{code}"
        );
        assert!(
            code.contains("serialize_field(\"condition\",&self.condition)"),
            "{code}"
        );
        assert!(!code.contains("serialize_field(\"grp_"), "{code}");
        assert!(
            code.contains("pubgrp_B:"),
            "the position keeps grp_B: {code}"
        );
        let plain = expand(&four_bar(""));
        assert!(!plain.contains("serde"), "{plain}");
    }
}
