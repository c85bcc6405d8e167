//! `Display` of the result structs: one line per struct, its label and the
//! user's fields with their units, `L` standing for the definition's length
//! unit and `F` for its force unit (mass x L / s^2):
//!
//! ```text
//! position: B = (307.929, 177.772) L, link3 = 0.533 rad, s = 1.250 L
//! velocity: B = (-18.1, 25.0) L/s, link3 = -101.971 rad/s, condition = 0.83
//! acceleration: B = (..) L/s^2, link3 = .. rad/s^2
//! forces: r_ground_link2 = (.., ..) F, r_ground_ram = (normal .. F, moment .. F L), drive_theta = .. F L, condition = .., power_residual = ..
//! ```
//!
//! A solution prints the lines of its parts, one per line. A precision
//! (`{:.3}`) applies to every number. Unused, it costs nothing: impls of a
//! generic trait nobody calls.

use super::forces::ForceField;
use super::names::TypeNames;
use crate::model::{Level, Model};
use crate::plan::Plan;
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// How one field is written.
enum Shown {
    /// A point or a vector: `NAME = (x, y) UNIT`.
    Pair(&'static str),
    /// A number: `NAME = x UNIT`.
    Scalar(&'static str),
    /// A prismatic pair's reaction.
    Prismatic,
}

/// The `Display` impls of the definition's result structs (and solution),
/// as far as its analysis level goes; `forces`: the forces struct's fields.
pub fn emit(model: &Model, plan: &Plan, forces: Option<&[(Ident, ForceField)]>) -> TokenStream {
    let names = TypeNames::of(model);
    let mut out = line_impl(&names.position, "position", &outputs(plan, 0));
    if model.level >= Level::Velocity {
        let mut fields = outputs(plan, 1);
        fields.push((quote::format_ident!("condition"), Shown::Scalar("")));
        out.extend(line_impl(&names.velocity, "velocity", &fields));
    }
    if model.level < Level::Acceleration {
        return out;
    }
    out.extend(line_impl(
        &names.acceleration,
        "acceleration",
        &outputs(plan, 2),
    ));
    let mut parts = vec![quote!(position), quote!(velocity), quote!(acceleration)];
    if let Some(f) = forces {
        let mut fields: Vec<(Ident, Shown)> = f
            .iter()
            .map(|(n, held)| {
                let shown = match held {
                    ForceField::Force => Shown::Pair(" F"),
                    ForceField::Prismatic => Shown::Prismatic,
                    ForceField::Torque => Shown::Scalar(" F L"),
                    ForceField::Push => Shown::Scalar(" F"),
                };
                (n.clone(), shown)
            })
            .collect();
        for extra in ["condition", "power_residual"] {
            fields.push((quote::format_ident!("{}", extra), Shown::Scalar("")));
        }
        out.extend(line_impl(&names.forces, "forces", &fields));
        parts.push(quote!(forces));
    }
    let solution = &names.solution;
    let (first, rest) = parts.split_first().expect("three parts at least");
    out.extend(quote! {
        impl<T: ::mechanism::Real> ::core::fmt::Display for #solution<T> {
            fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
                ::core::fmt::Display::fmt(&self.#first, f)?;
                #(
                    f.write_str("\n")?;
                    ::core::fmt::Display::fmt(&self.#rest, f)?;
                )*
                ::core::result::Result::Ok(())
            }
        }
    });
    out
}

/// The outputs of the position (`level` 0), velocity (1) or acceleration
/// (2) struct, with their units.
fn outputs(plan: &Plan, level: usize) -> Vec<(Ident, Shown)> {
    let [point, angle, slide] = [
        [" L", " rad", " L"],
        [" L/s", " rad/s", " L/s"],
        [" L/s^2", " rad/s^2", " L/s^2"],
    ][level];
    let o = &plan.outputs;
    let points = o.points.iter().map(|p| (p.clone(), Shown::Pair(point)));
    let links = o.links.iter().map(|l| (l.clone(), Shown::Scalar(angle)));
    let slides = o
        .slides
        .iter()
        .map(|s| (s.name.clone(), Shown::Scalar(slide)));
    points.chain(links).chain(slides).collect()
}

/// `Display` for the struct `ty`: `LABEL: ` and its fields separated by
/// commas (`LABEL:` alone without fields).
fn line_impl(ty: &Ident, label: &str, fields: &[(Ident, Shown)]) -> TokenStream {
    let writes = fields.iter().enumerate().map(|(k, (name, shown))| {
        let sep = if k == 0 { " " } else { ", " };
        let text = name.to_string();
        let i = quote!(::mechanism::__interop);
        match shown {
            Shown::Pair(unit) => {
                quote!(#i::pair(f, #sep, #text, self.#name.x, self.#name.y, #unit)?;)
            }
            Shown::Scalar(unit) => quote!(#i::scalar(f, #sep, #text, self.#name, #unit)?;),
            Shown::Prismatic => {
                quote!(#i::prismatic(f, #sep, #text, self.#name.normal, self.#name.moment)?;)
            }
        }
    });
    let label = format!("{label}:");
    quote! {
        impl<T: ::mechanism::Real> ::core::fmt::Display for #ty<T> {
            fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
                f.write_str(#label)?;
                #(#writes)*
                ::core::result::Result::Ok(())
            }
        }
    }
}
