//! The mechanism's description of itself (`mechanism::structure`): its
//! structure as a constant (`Describe`) and its position, velocity and
//! acceleration structs readable by field name with units (`Fields`), for code
//! that draws or tabulates any mechanism. Unused, it costs nothing: a constant
//! and trait methods nobody calls.

use crate::keys::{LinkName, PointName};
use crate::kinds::{self, GuideLine};
use crate::model::units::UnitNames;
use crate::model::{Level, Model};
use crate::plan::Plan;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// The `Describe` impl of the mechanism and the `Fields` impls of its result
/// structs (those the definition's analysis level generates).
pub fn emit(model: &Model, plan: &Plan) -> TokenStream {
    let name = &model.name;
    let structure = structure(model, plan);
    let allow_lints = super::allow_literal_lints();
    let mut out = quote! {
        #allow_lints
        impl<T: ::mechanism::Real> ::mechanism::structure::Describe for #name<T> {
            const STRUCTURE: ::mechanism::structure::Structure = #structure;
        }
    };
    let levels = [
        (Level::Position, "Position"),
        (Level::Velocity, "Velocity"),
        (Level::Acceleration, "Acceleration"),
    ];
    for (k, (level, suffix)) in levels.into_iter().enumerate() {
        if model.level >= level {
            out.extend(fields(model, plan, &format_ident!("{}{}", name, suffix), k));
        }
    }
    out
}

fn path(item: &str) -> TokenStream {
    let item = format_ident!("{}", item);
    quote!(::mechanism::structure::#item)
}

/// The `mechanism::structure::Units` of the definition (its `units`
/// statement; `Units::SYMBOLS` without one), for its `Structure`.
fn units(model: &Model) -> TokenStream {
    let u = &model.units;
    let ty = path("Units");
    if *u == UnitNames::symbols() {
        return quote!(#ty::SYMBOLS);
    }
    let (length, force, mass, time) = (&u.length, &u.force, &u.mass, &u.time);
    quote!(#ty { length: #length, force: #force, mass: #mass, time: #time })
}

/// The units of the result structs' `Fields` impls: the structure's, read
/// from the mechanism's `Describe` impl (written once).
pub fn units_of(model: &Model) -> TokenStream {
    let name = &model.name;
    quote!(<#name<T> as ::mechanism::structure::Describe>::STRUCTURE.units)
}

fn option_str(s: Option<String>) -> TokenStream {
    match s {
        Some(s) => quote!(::core::option::Option::Some(#s)),
        None => quote!(::core::option::Option::None),
    }
}

/// The `Structure` constant.
fn structure(model: &Model, plan: &Plan) -> TokenStream {
    let (point, point_kind) = (path("Point"), path("PointKind"));
    let mut points = Vec::new();
    for &i in &plan.order {
        let stmt = &model.stmts[i];
        let Some(kind) = kinds::of(stmt).point_kind() else {
            continue;
        };
        let kind = format_ident!("{}", kind);
        let n = stmt.name.to_string();
        points.push(quote!(#point { name: #n, kind: #point_kind::#kind }));
    }
    let (link, link_kind) = (path("Link"), path("LinkKind"));
    let mut links = Vec::new();
    for &i in &plan.order {
        let stmt = &model.stmts[i];
        for (j, l) in stmt.links.iter().enumerate() {
            let Some(info) = plan.links.get(&LinkName::of(l)) else {
                continue;
            };
            // A link on a guide is a block (the plan knows which guide); so
            // is an RPR's first link, sliding along its second.
            let kind = match &info.guide {
                Some(_) => format_ident!("Block"),
                None => format_ident!("{}", kinds::of(stmt).link_kind(j)),
            };
            let guide = info.guide.as_ref().map(ToString::to_string);
            let n = l.to_string();
            let named = info.named;
            let pts = info.points.iter().map(PointName::as_str);
            let guide = option_str(guide);
            links.push(quote! {
                #link { name: #n, named: #named, kind: #link_kind::#kind, points: &[#(#pts),*], guide: #guide }
            });
        }
    }
    let guide_ty = path("Guide");
    let mut guides = Vec::new();
    for &i in &plan.order {
        let stmt = &model.stmts[i];
        if let Some(GuideLine {
            carrier,
            through,
            angle,
        }) = kinds::as_guide(stmt)
        {
            let n = stmt.name.to_string();
            let carrier = option_str(carrier.map(|c| c.to_string()));
            let through = option_str(through.map(|p| p.to_string()));
            let angle = match angle.fold().filter(|a| a.is_finite()) {
                Some(a) => {
                    let a = proc_macro2::Literal::f64_suffixed(a);
                    quote!(::core::option::Option::Some(#a))
                }
                None => quote!(::core::option::Option::None),
            };
            guides.push(quote! {
                #guide_ty { name: #n, carrier: #carrier, through: #through, angle: #angle }
            });
        }
    }
    let (input, quantity) = (path("Input"), path("Quantity"));
    let inputs = model.stmts.iter().flat_map(|s| {
        let q = if kinds::of(s).input_is_angle() {
            quote!(Angle)
        } else {
            quote!(Length)
        };
        let driver = s.name.to_string();
        let (input, quantity) = (&input, &quantity);
        s.kind.inputs().into_iter().map(move |i| {
            let i = i.to_string();
            quote!(#input { name: #i, quantity: #quantity::#q, driver: #driver })
        })
    });
    let mass = path("Mass");
    let masses = model.kinetics.masses.iter().map(|m| {
        let (l, at) = (m.link.to_string(), m.at.to_string());
        quote!(#mass { link: #l, at: #at })
    });
    let name = model.name.to_string();
    let structure = path("Structure");
    let units = units(model);
    quote! {
        #structure {
            name: #name,
            points: &[#(#points),*],
            links: &[#(#links),*],
            guides: &[#(#guides),*],
            inputs: &[#(#inputs),*],
            masses: &[#(#masses),*],
            units: #units,
        }
    }
}

/// One field of a `Fields` impl: its name, what it measures (a
/// `mechanism::structure::Quantity` variant), whether it is planar (a point
/// or a vector), and the `Value` that reads it (code in terms of `self`).
pub struct FieldEntry {
    /// The name `get` answers to.
    pub name: String,
    /// The `Quantity` variant.
    pub quantity: &'static str,
    /// `true` for a point or a vector.
    pub planar: bool,
    /// The `mechanism::structure::Value` expression.
    pub value: TokenStream,
}

impl FieldEntry {
    /// A field read as `Value::KIND(self.READ)`, `KIND` one of `Point`,
    /// `Vector`, `Scalar`.
    pub fn new(name: String, quantity: &'static str, kind: &str, read: TokenStream) -> Self {
        let (value, kind) = (path("Value"), format_ident!("{}", kind));
        FieldEntry {
            name,
            quantity,
            planar: kind != "Scalar",
            value: quote!(#value::#kind(self.#read)),
        }
    }
}

/// The `Fields` impl of the struct `ty` with `entries`, in order (empty for
/// the stubs emitted on error), in the definition's `units` ([`units`]).
pub fn fields_impl(ty: &syn::Ident, entries: &[FieldEntry], units: &TokenStream) -> TokenStream {
    let (field, quantity, value) = (path("Field"), path("Quantity"), path("Value"));
    let infos = entries.iter().map(|e| {
        let (n, q, planar) = (&e.name, format_ident!("{}", e.quantity), e.planar);
        quote!(#field { name: #n, quantity: #quantity::#q, planar: #planar })
    });
    let arms = entries.iter().map(|e| {
        let (n, v) = (&e.name, &e.value);
        quote!(#n => ::core::option::Option::Some(#v),)
    });
    // No field: no `match` of one wildcard arm (clippy's
    // `match_single_binding` in the user's crate).
    let body = if entries.is_empty() {
        quote!(::core::option::Option::None)
    } else {
        quote!(match name { #(#arms)* _ => ::core::option::Option::None, })
    };
    quote! {
        impl<T: ::mechanism::Real> ::mechanism::structure::Fields<T> for #ty<T> {
            const FIELDS: &'static [#field] = &[#(#infos),*];
            const UNITS: ::mechanism::structure::Units = #units;
            #[allow(unused_variables)]
            fn get(&self, name: &::core::primitive::str) -> ::core::option::Option<#value<T>> {
                #body
            }
        }
    }
}

/// The `Fields` impl of one result struct: `level` 0 position, 1 velocity,
/// 2 acceleration. Its fields are the definition's outputs (points, named
/// links' angles and rates, slides), in the struct's order.
fn fields(model: &Model, plan: &Plan, ty: &syn::Ident, level: usize) -> TokenStream {
    let out = &plan.outputs;
    let [point_q, angle_q, slide_q] = [
        ["Length", "Angle", "Length"],
        ["Velocity", "AngularVelocity", "Velocity"],
        ["Acceleration", "AngularAcceleration", "Acceleration"],
    ][level];
    let point_kind = if level == 0 { "Point" } else { "Vector" };
    let mut entries = Vec::new();
    for p in &out.points {
        entries.push(FieldEntry::new(
            p.to_string(),
            point_q,
            point_kind,
            quote!(#p),
        ));
    }
    let scalars = out
        .links
        .iter()
        .map(|l| (l, angle_q))
        .chain(out.slides.iter().map(|s| (&s.name, slide_q)));
    for (s, q) in scalars {
        entries.push(FieldEntry::new(s.to_string(), q, "Scalar", quote!(#s)));
    }
    if level == 1 {
        let read = quote!(condition);
        entries.push(FieldEntry::new("condition".into(), "Ratio", "Scalar", read));
    }
    fields_impl(ty, &entries, &units_of(model))
}
