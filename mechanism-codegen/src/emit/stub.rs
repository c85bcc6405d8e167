//! The items emitted instead of the mechanism when the definition has errors:
//! the `compile_error!`s, and stubs with the real names and fields so the
//! user's own code reports no follow-on errors.

use crate::model::{Kind, Level, Model};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use std::collections::BTreeSet;
use syn::Ident;

/// On errors: the errors, plus stub items with the real names and signatures,
/// so that the user's code that uses them reports no cascade of follow-on
/// errors. The stubs' bodies are never compiled into a program (the
/// `compile_error!`s stop the build first).
pub fn emit(model: &Model, errors: Vec<syn::Error>) -> TokenStream {
    let errors = errors.into_iter().map(|e| e.to_compile_error());
    let name = &model.name;
    let vis = &model.vis;
    let position_ty = format_ident!("{}Position", name);
    let velocity_ty = format_ident!("{}Velocity", name);
    let acceleration_ty = format_ident!("{}Acceleration", name);
    let input_ty = format_ident!("{}Input", name);
    let solution_ty = format_ident!("{}Solution", name);
    let params: Vec<&Ident> = model.params.iter().map(|(n, _)| n).collect();
    let mut seen = BTreeSet::new();
    let mut unique = |i: &Ident| seen.insert(i.to_string());
    let inputs: Vec<Ident> = model
        .stmts
        .iter()
        .filter_map(|s| s.kind.input().cloned())
        .chain(model.failed.iter().filter_map(|f| f.input.clone()))
        .filter(|i| unique(i))
        .collect();
    let params_marker = if params.is_empty() {
        quote!(pub _scalar: ::core::marker::PhantomData<T>,)
    } else {
        quote!()
    };
    let scalar_marker = if inputs.is_empty() {
        quote!(pub _scalar: ::core::marker::PhantomData<T>,)
    } else {
        quote!()
    };
    let points: Vec<&Ident> = model
        .stmts
        .iter()
        .filter(|s| !matches!(s.kind, Kind::Guide { .. } | Kind::Rpr { .. }))
        .map(|s| &s.name)
        .chain(
            model
                .failed
                .iter()
                .filter(|f| f.kind != "guide" && f.kind != "rpr")
                .map(|f| &f.name),
        )
        .filter(|i| unique(i))
        .collect();
    let scalars: Vec<&Ident> = model
        .stmts
        .iter()
        .flat_map(|s| {
            let rpr = matches!(s.kind, Kind::Rpr { .. }).then_some(&s.name);
            s.links
                .iter()
                .zip(&s.links_named)
                .filter(|(_, n)| **n)
                .map(|(l, _)| l)
                .chain(s.slides.iter().flatten())
                .chain(rpr)
        })
        .chain(model.failed.iter().flat_map(|f| {
            let rpr = (f.kind == "rpr").then_some(&f.name);
            f.links.iter().chain(f.slides.iter()).chain(rpr)
        }))
        .filter(|i| unique(i))
        .collect();
    // With a force analysis the stub keeps its shape too: `NameLoads` with
    // `Default`, `solve` taking the loads, a `forces` field in the solution
    // (the reactions' own fields come from a valid model only).
    let (forces_stub, stub_loads_param, stub_forces_field) = if model.kinetics.declared
        || model.level == Level::Forces
    {
        let forces_ty = format_ident!("{}Forces", name);
        let loads_ty = format_ident!("{}Loads", name);
        let loads: Vec<&Ident> = model.kinetics.loads.iter().map(|(n, _)| n).collect();
        let (loads_item, loads_param) = if loads.is_empty() {
            (quote!(), quote!())
        } else {
            (
                quote! {
                    #[allow(non_snake_case, dead_code)]
                    #vis struct #loads_ty<T = ::core::primitive::f64> { #(pub #loads: T,)* }
                    impl<T: ::mechanism::Real> ::core::default::Default for #loads_ty<T> {
                        fn default() -> Self { ::core::unimplemented!() }
                    }
                },
                quote!(, loads: &#loads_ty<T>),
            )
        };
        let stub = quote! {
            #loads_item
            #[allow(dead_code)]
            #vis struct #forces_ty<T: ::mechanism::Real = ::core::primitive::f64> { pub condition: T, pub power_residual: T }
            #[allow(dead_code, unused_variables)]
            impl<T: ::mechanism::Real> #name<T> {
                pub fn forces(&self, pos: &#position_ty<T>, vel: &#velocity_ty<T>, acc: &#acceleration_ty<T> #loads_param) -> ::core::result::Result<#forces_ty<T>, ::mechanism::Error<T>> { ::core::unimplemented!() }
            }
        };
        (stub, loads_param, quote!(pub forces: #forces_ty<T>,))
    } else {
        (quote!(), quote!(), quote!())
    };
    let describe = describe_stub(model);
    quote! {
        #(#errors)*
        #describe
        #forces_stub
        #[allow(non_snake_case, dead_code)]
        #vis struct #name<T = ::core::primitive::f64> { #(pub #params: T,)* #params_marker }
        impl<T: ::mechanism::Real> ::core::default::Default for #name<T> {
            fn default() -> Self { ::core::unimplemented!() }
        }
        #[allow(non_snake_case, dead_code)]
        #vis struct #input_ty<T = ::core::primitive::f64> { #(pub #inputs: T,)* #scalar_marker }
        #[allow(non_snake_case, dead_code)]
        #vis struct #position_ty<T: ::mechanism::Real = ::core::primitive::f64> { #(pub #points: ::mechanism::Point2<T>,)* #(pub #scalars: T,)* }
        #[allow(non_snake_case, dead_code)]
        #vis struct #velocity_ty<T: ::mechanism::Real = ::core::primitive::f64> { #(pub #points: ::mechanism::Vector2<T>,)* #(pub #scalars: T,)* pub condition: T }
        #[allow(non_snake_case, dead_code)]
        #vis struct #acceleration_ty<T: ::mechanism::Real = ::core::primitive::f64> { #(pub #points: ::mechanism::Vector2<T>,)* #(pub #scalars: T,)* }
        #[allow(dead_code)]
        #vis struct #solution_ty<T: ::mechanism::Real = ::core::primitive::f64> {
            pub position: #position_ty<T>, pub velocity: #velocity_ty<T>, pub acceleration: #acceleration_ty<T>,
            #stub_forces_field
        }
        #[allow(dead_code, unused_variables)]
        impl<T: ::mechanism::Real> #name<T> {
            pub fn position(&self, input: &#input_ty<T>) -> ::core::result::Result<#position_ty<T>, ::mechanism::Error<T>> { ::core::unimplemented!() }
            pub fn position_cos_sin(&self, input: &#input_ty<T>) -> ::core::result::Result<#position_ty<T>, ::mechanism::Error<T>> { ::core::unimplemented!() }
            pub fn velocity(&self, pos: &#position_ty<T>, rates: &#input_ty<T>) -> ::core::result::Result<#velocity_ty<T>, ::mechanism::Error<T>> { ::core::unimplemented!() }
            pub fn acceleration(&self, pos: &#position_ty<T>, vel: &#velocity_ty<T>, accels: &#input_ty<T>) -> ::core::result::Result<#acceleration_ty<T>, ::mechanism::Error<T>> { ::core::unimplemented!() }
            pub fn solve(&self, input: &#input_ty<T>, rates: &#input_ty<T>, accels: &#input_ty<T> #stub_loads_param) -> ::core::result::Result<#solution_ty<T>, ::mechanism::Error<T>> { ::core::unimplemented!() }
        }
    }
}

/// The self-description impls (`mechanism::structure`), empty: code that
/// draws or tabulates the mechanism reports no follow-on error.
fn describe_stub(model: &Model) -> TokenStream {
    let name = &model.name;
    let text = name.to_string();
    let st = quote!(::mechanism::structure);
    let forces = model.kinetics.declared || model.level == Level::Forces;
    let fields = ["Position", "Velocity", "Acceleration", "Forces"]
        .iter()
        .take(if forces { 4 } else { 3 })
        .map(|s| super::describe::fields_impl(&format_ident!("{}{}", name, s), &[]));
    quote! {
        impl<T: ::mechanism::Real> #st::Describe for #name<T> {
            const STRUCTURE: #st::Structure = #st::Structure {
                name: #text, points: &[], links: &[], guides: &[], inputs: &[], masses: &[],
            };
        }
        #(#fields)*
    }
}
