//! The items emitted instead of the mechanism when the definition has errors:
//! the `compile_error!`s, and stubs with the real names and fields so the
//! user's own code reports no follow-on errors.

use super::stub_fields::FieldsOnly;
use crate::kinds;
use crate::kinds::word::KindWord;
use crate::model::{FailedKind, Level, Model};
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
    let modes: Vec<&Ident> = model.modes.iter().map(|(n, _)| n).collect();
    let mut seen = BTreeSet::new();
    let mut unique = |i: &Ident| seen.insert(i.to_string());
    let inputs: Vec<Ident> = model
        .stmts
        .iter()
        .flat_map(|s| s.kind.inputs().into_iter().cloned())
        .chain(model.failed.iter().flat_map(|f| f.inputs.iter().cloned()))
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
        .filter(|s| kinds::of(s).point_kind().is_some())
        .map(|s| &s.name)
        .chain(
            model
                .failed
                .iter()
                .filter(|f| f.names_point())
                .map(|f| &f.name),
        )
        .filter(|i| unique(i))
        .collect();
    let scalars: Vec<&Ident> = model
        .stmts
        .iter()
        .flat_map(|s| {
            let rpr = kinds::of(s).names_slide().then_some(&s.name);
            s.links
                .iter()
                .zip(&s.links_named)
                .filter(|(_, n)| **n)
                .map(|(l, _)| l)
                .chain(s.slides.iter().flatten())
                .chain(rpr)
        })
        .chain(model.failed.iter().flat_map(|f| {
            let rpr = (f.kind == FailedKind::Let(Some(KindWord::Rpr))).then_some(&f.name);
            f.links.iter().chain(f.slides.iter()).chain(rpr)
        }))
        .filter(|i| unique(i))
        .collect();
    // With a force analysis the stub keeps its shape too: `NameLoads` with
    // `Default`, `solve` taking the loads, a `forces` field in the solution,
    // and the reactions and efforts of every statement that lowered (named
    // by the same per-kind code as the real forces struct).
    let (forces_stub, stub_loads_param, stub_forces_field) = if model.kinetics.declared
        || model.level >= Level::Forces
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
        let mut reactions = FieldsOnly::of(model);
        reactions.extend(kinds::motors::reactions(model));
        super::forces::unique_names(&mut reactions);
        let fields = reactions.iter().map(|r| &r.name);
        let types = reactions.iter().map(|r| &r.ty);
        let stub = quote! {
            #loads_item
            #[allow(non_snake_case, dead_code)]
            #vis struct #forces_ty<T: ::mechanism::Real = ::core::primitive::f64> { #(pub #fields: #types,)* pub condition: T, pub power_residual: T }
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
        #vis struct #name<T = ::core::primitive::f64> { #(pub #params: T,)* #(pub #modes: ::mechanism::Mode,)* #params_marker }
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
    let forces = model.kinetics.declared || model.level >= Level::Forces;
    let units = super::describe::units_of(model);
    let fields = ["Position", "Velocity", "Acceleration", "Forces"]
        .iter()
        .take(if forces { 4 } else { 3 })
        .map(|s| super::describe::fields_impl(&format_ident!("{}{}", name, s), &[], &units));
    quote! {
        impl<T: ::mechanism::Real> #st::Describe for #name<T> {
            const STRUCTURE: #st::Structure = #st::Structure {
                name: #text, points: &[], links: &[], guides: &[], inputs: &[], masses: &[],
                units: #st::Units::SYMBOLS,
            };
        }
        #(#fields)*
    }
}

#[cfg(test)]
mod tests {
    use crate::emit::test_support::{four_bar, planned};
    use proc_macro2::TokenStream;
    use std::str::FromStr;

    /// The fields (`name:type`, sorted) of the struct `ty` in `code`, doc
    /// attributes left out.
    fn fields(code: &TokenStream, ty: &str) -> Vec<String> {
        let flat: String = code.to_string().split_whitespace().collect();
        let start = flat
            .find(&format!("struct{ty}<"))
            .unwrap_or_else(|| panic!("no struct {ty}"));
        let open = start + flat[start..].find('{').expect("a body") + 1;
        let close = open + flat[open..].find('}').expect("a closed body");
        let mut body = flat[open..close].to_string();
        while let Some(a) = body.find("#[doc=") {
            let b = a + body[a..].find("\"]").expect("a closed doc") + 2;
            body.replace_range(a..b, "");
        }
        let mut fields: Vec<String> = body
            .split(',')
            .filter(|f| !f.is_empty())
            .map(|f| f.trim_start_matches("pub").to_string())
            .collect();
        fields.sort();
        fields
    }

    /// The forces struct of the valid definition `src` as expanded, and as
    /// the stub emitted on error builds it from the same statements.
    fn real_and_stub(src: &str, ty: &str) -> (Vec<String>, Vec<String>) {
        let real = crate::expand(TokenStream::from_str(src).expect("tokens"));
        assert!(!real.to_string().contains("compile_error"), "{ty}: {real}");
        let (model, _) = planned(src);
        (fields(&real, ty), fields(&super::emit(&model, vec![]), ty))
    }

    // Proves the stub's forces struct carries exactly the real one's
    // reaction and effort fields, names and types, for every kind with
    // reactions (crank, RRR; slider, RRP; RPR; RPP, PRP; actuator): user
    // code that reads a reaction compiles against either.
    #[test]
    fn stub_forces_fields_are_the_real_ones() {
        let four_bar = four_bar("mass link3 { m = 2.0, at = P };");
        let shaper = "pub Shaper {
            params { ab = 0.125, yc = -0.275, cd = 0.6, de = 0.15 }
            let A = ground(0.0, 0.0);
            let C = ground(0.0, yc);
            let ram = guide((0.0, 0.3), 180 deg);
            let B = crank(A, ab, theta) as link1;
            let s3 = rpr(B, C, plus) as (block, link3);
            let D = point(link3, from C, cd, 0 deg);
            let E = rrp(D, de, ram, plus) as (link4, tool) slide x;
            mass link3 { m = 20.0, at = D };
        }";
        let slots = "pub Slots {
            let O = ground(0.0, 0.0);
            let line = guide((0.0, 0.0), 0 deg);
            let S = slider(line, s) as block;
            let gv = guide((3.0, 0.0), 90 deg);
            let Q = rpp(S, gv, 90 deg) as (pin, yoke) slide (q1, q2);
            let gy = guide(Q, yoke, 45 deg);
            let gh = guide((0.0, 1.0), 0 deg);
            let F = prp(gy, gh) as (pa, pb) slide (u, v);
            mass pb { m = 1.0, at = F };
            range s = (0.0, 0.5);
        }";
        let boom = "pub Boom {
            let A = ground(0.0, 0.0);
            let B = ground(0.8, -0.2);
            let C = actuator(A, 1.2, B, len, left) as (boom, cylinder);
            let tip = point(boom, from A, 2.5, 10 deg);
            mass boom { m = 120.0, at = tip };
            range len = (0.9, 1.6);
        }";
        for (src, ty) in [
            (four_bar.as_str(), "FourBarForces"),
            (shaper, "ShaperForces"),
            (slots, "SlotsForces"),
            (boom, "BoomForces"),
        ] {
            let (real, stub) = real_and_stub(src, ty);
            assert!(real.len() > 2, "{ty}: {real:?}");
            assert_eq!(real, stub, "{ty}");
        }
    }
}
