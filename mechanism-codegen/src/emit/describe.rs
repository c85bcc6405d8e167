//! The mechanism's description of itself (`mechanism::structure`): its
//! structure as a constant (`Describe`) and its position, velocity and
//! acceleration structs readable by field name with units (`Fields`), for code
//! that draws or tabulates any mechanism. Unused, it costs nothing: a constant
//! and trait methods nobody calls.

use crate::model::{Kind, Level, Model, Origin};
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
            out.extend(fields(plan, &format_ident!("{}{}", name, suffix), k));
        }
    }
    out
}

fn path(item: &str) -> TokenStream {
    let item = format_ident!("{}", item);
    quote!(::mechanism::structure::#item)
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
        let kind = match stmt.kind {
            Kind::Guide { .. } | Kind::Rpr { .. } => continue,
            Kind::Ground { .. } => quote!(Ground),
            Kind::Point { .. } => quote!(OnLink),
            _ => quote!(Joint),
        };
        let n = stmt.name.to_string();
        points.push(quote!(#point { name: #n, kind: #point_kind::#kind }));
    }
    let (link, link_kind) = (path("Link"), path("LinkKind"));
    let mut links = Vec::new();
    for &i in &plan.order {
        let stmt = &model.stmts[i];
        for (j, l) in stmt.links.iter().enumerate() {
            let Some(info) = plan.links.get(&l.to_string()) else {
                continue;
            };
            let (kind, guide) = match (&stmt.kind, j) {
                (Kind::Crank { .. }, _) => (quote!(Crank), None),
                (Kind::Actuator { .. }, 1) => (quote!(Cylinder), None),
                (Kind::Slider { guide, .. }, _)
                | (Kind::Rrp { guide, .. }, 1)
                | (Kind::Rpp { guide, .. }, _) => (quote!(Block), Some(guide.to_string())),
                (Kind::Prp { g1, .. }, 0) => (quote!(Block), Some(g1.to_string())),
                (Kind::Prp { g2, .. }, _) => (quote!(Block), Some(g2.to_string())),
                (Kind::Rpr { .. }, 0) => (quote!(Block), None),
                _ => (quote!(Bar), None),
            };
            let n = l.to_string();
            let named = info.named;
            let pts = &info.points;
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
        if let Kind::Guide {
            origin,
            angle,
            carrier,
        } = &stmt.kind
        {
            let n = stmt.name.to_string();
            let carrier = option_str(carrier.as_ref().map(|c| c.to_string()));
            let through = option_str(match origin {
                Origin::Point(p) => Some(p.to_string()),
                Origin::Coords(..) => None,
            });
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
    let inputs = model.stmts.iter().filter_map(|s| {
        let q = match s.kind {
            Kind::Crank { .. } => quote!(Angle),
            _ => quote!(Length),
        };
        let driver = s.name.to_string();
        s.kind.input().map(|i| {
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
    quote! {
        #structure {
            name: #name,
            points: &[#(#points),*],
            links: &[#(#links),*],
            guides: &[#(#guides),*],
            inputs: &[#(#inputs),*],
            masses: &[#(#masses),*],
        }
    }
}

/// The `Fields` impl of one result struct: `level` 0 position, 1 velocity,
/// 2 acceleration. Its fields are the definition's outputs (points, named
/// links' angles and rates, slides), in the struct's order.
fn fields(plan: &Plan, ty: &syn::Ident, level: usize) -> TokenStream {
    let out = &plan.outputs;
    let (field, quantity, value) = (path("Field"), path("Quantity"), path("Value"));
    let [point_q, angle_q, slide_q] = [
        ["Length", "Angle", "Length"],
        ["Velocity", "AngularVelocity", "Velocity"],
        ["Acceleration", "AngularAcceleration", "Acceleration"],
    ][level]
        .map(|q| format_ident!("{}", q));
    let point_value = if level == 0 {
        quote!(Point)
    } else {
        quote!(Vector)
    };
    let mut infos = Vec::new();
    let mut arms = Vec::new();
    for p in &out.points {
        let n = p.to_string();
        infos.push(quote!(#field { name: #n, quantity: #quantity::#point_q, planar: true }));
        arms.push(quote!(#n => ::core::option::Option::Some(#value::#point_value(self.#p)),));
    }
    let scalars = out
        .links
        .iter()
        .map(|l| (l, &angle_q))
        .chain(out.slides.iter().map(|s| (&s.name, &slide_q)));
    for (s, q) in scalars {
        let n = s.to_string();
        infos.push(quote!(#field { name: #n, quantity: #quantity::#q, planar: false }));
        arms.push(quote!(#n => ::core::option::Option::Some(#value::Scalar(self.#s)),));
    }
    if level == 1 {
        infos.push(quote!(#field { name: "condition", quantity: #quantity::Ratio, planar: false }));
        arms.push(
            quote!("condition" => ::core::option::Option::Some(#value::Scalar(self.condition)),),
        );
    }
    quote! {
        impl<T: ::mechanism::Real> ::mechanism::structure::Fields<T> for #ty<T> {
            const FIELDS: &'static [#field] = &[#(#infos),*];
            fn get(&self, name: &::core::primitive::str) -> ::core::option::Option<#value<T>> {
                match name {
                    #(#arms)*
                    _ => ::core::option::Option::None,
                }
            }
        }
    }
}
