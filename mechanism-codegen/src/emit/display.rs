//! `Display` of the result structs: one line per struct, its label and the
//! user's fields with their units: the definition's `units` statement
//! (`units { length = "mm", force = "N" }` shows `mm`, `mm/s`, `N mm`), or
//! without one `L` standing for the definition's length unit and `F` for its
//! force unit (mass x L / s^2):
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
use crate::model::units::UnitNames;
use crate::model::{Level, Model};
use crate::plan::Plan;
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// How one field is written (each unit with its leading space, `" mm/s"`;
/// `""` for a ratio).
enum Shown {
    /// A point or a vector: `NAME = (x, y) UNIT`.
    Pair(String),
    /// A number: `NAME = x UNIT`.
    Scalar(String),
    /// A prismatic pair's reaction: its force and moment units.
    Prismatic(String, String),
}

/// `unit` with its leading space.
fn spaced(unit: &str) -> String {
    format!(" {unit}")
}

/// The `Display` impls of the definition's result structs (and solution),
/// as far as its analysis level goes; `forces`: the forces struct's fields.
pub fn emit(model: &Model, plan: &Plan, forces: Option<&[(Ident, ForceField)]>) -> TokenStream {
    let names = TypeNames::of(model);
    let u = &model.units;
    let mut out = line_impl(&names.position, "position", &outputs(plan, u, 0));
    if model.level >= Level::Velocity {
        let mut fields = outputs(plan, u, 1);
        fields.push((
            quote::format_ident!("condition"),
            Shown::Scalar(String::new()),
        ));
        out.extend(line_impl(&names.velocity, "velocity", &fields));
    }
    if model.level < Level::Acceleration {
        return out;
    }
    out.extend(line_impl(
        &names.acceleration,
        "acceleration",
        &outputs(plan, u, 2),
    ));
    let mut parts = vec![quote!(position), quote!(velocity), quote!(acceleration)];
    if let Some(f) = forces {
        let mut fields: Vec<(Ident, Shown)> = f
            .iter()
            .map(|(n, held)| {
                let shown = match held {
                    ForceField::Force => Shown::Pair(spaced(&u.force)),
                    ForceField::Prismatic => {
                        Shown::Prismatic(spaced(&u.force), spaced(&u.moment()))
                    }
                    ForceField::Torque => Shown::Scalar(spaced(&u.moment())),
                    ForceField::Push => Shown::Scalar(spaced(&u.force)),
                };
                (n.clone(), shown)
            })
            .collect();
        for extra in ["condition", "power_residual"] {
            fields.push((
                quote::format_ident!("{}", extra),
                Shown::Scalar(String::new()),
            ));
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
fn outputs(plan: &Plan, u: &UnitNames, level: usize) -> Vec<(Ident, Shown)> {
    let l = u.length();
    let (length, angle) = match level {
        0 => (l.to_string(), "rad".to_string()),
        1 => (u.per_time(l), u.per_time("rad")),
        _ => (u.per_time_squared(l), u.per_time_squared("rad")),
    };
    let o = &plan.outputs;
    let points = o
        .points
        .iter()
        .map(|p| (p.clone(), Shown::Pair(spaced(&length))));
    let links = o
        .links
        .iter()
        .map(|k| (k.clone(), Shown::Scalar(spaced(&angle))));
    let slides = o
        .slides
        .iter()
        .map(|s| (s.name.clone(), Shown::Scalar(spaced(&length))));
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
            Shown::Prismatic(force, moment) => {
                quote!(#i::prismatic(f, #sep, #text, self.#name.normal, self.#name.moment, #force, #moment)?;)
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
