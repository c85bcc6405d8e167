//! The statements of the force analysis lowered: `mass`, `gravity`, `force`
//! and `torque` (their links and points are checked in `validate`, once the
//! plan knows which points each link has).

use super::args::NumberScope;
use super::lower::{once, Body};
use super::{ForceSpec, ForceSpecValue, MassSpec, TorqueSpec};
use crate::diag::{did_you_mean, Diagnostics};
use crate::parse::{self, Arg};
use crate::value::convert;
use proc_macro2::Span;
use syn::{Expr, Ident};

impl Body<'_> {
    /// `mass LINK { m = .., at = POINT, j = .. }`.
    pub(super) fn mass(&mut self, m: &parse::Mass, errors: &mut Diagnostics) {
        self.kinetics.declared = true;
        if let Some(spec) = lower_mass(m, self.scope, errors) {
            self.kinetics.masses.push(spec);
        }
    }

    /// `gravity (gx, gy);`, once in a definition.
    pub(super) fn gravity(&mut self, span: Span, x: Expr, y: Expr, errors: &mut Diagnostics) {
        self.kinetics.declared = true;
        let written = || {
            // Tokens print `- 9.81`: close up a leading minus.
            let show = |e: &syn::Expr| {
                let t = quote::ToTokens::to_token_stream(e).to_string();
                match t.strip_prefix("- ") {
                    Some(rest) => format!("-{rest}"),
                    None => t,
                }
            };
            format!("gravity ({}, {});", show(&x), show(&y))
        };
        if !once(&mut self.seen, "gravity", written, span, errors) {
            return;
        }
        match (convert(&x, self.scope), convert(&y, self.scope)) {
            (Ok(x), Ok(y)) => self.kinetics.gravity = Some((span, x, y)),
            (Err(e), _) | (_, Err(e)) => errors.error(e),
        }
    }

    /// `force at POINT (on LINK)? = (fx, fy);` or `.. along GUIDE = f;`: its
    /// values may use the load values.
    pub(super) fn force(&mut self, f: parse::Force, errors: &mut Diagnostics) {
        self.kinetics.declared = true;
        let load_scope = self.load_scope;
        let value = match f.value {
            parse::ForceValue::Components(x, y) => {
                match (convert(&x, load_scope), convert(&y, load_scope)) {
                    (Ok(x), Ok(y)) => Some(ForceSpecValue::Components(x, y)),
                    (Err(e), _) | (_, Err(e)) => {
                        errors.error(e);
                        None
                    }
                }
            }
            parse::ForceValue::Along(guide, v) => match convert(&v, load_scope) {
                Ok(v) => Some(ForceSpecValue::Along(guide, v)),
                Err(e) => {
                    errors.error(e);
                    None
                }
            },
        };
        if let Some(value) = value {
            self.kinetics.forces.push(ForceSpec {
                at: f.at,
                on: f.on,
                value,
            });
        }
    }

    /// `torque on LINK = value;`: its value may use the load values.
    pub(super) fn torque(&mut self, on: Ident, value: Expr, errors: &mut Diagnostics) {
        self.kinetics.declared = true;
        match convert(&value, self.load_scope) {
            Ok(value) => self.kinetics.torques.push(TorqueSpec { on, value }),
            Err(e) => errors.error(e),
        }
    }
}

/// Lowers `mass LINK { m = .., at = POINT, j = .. }`: `m` and `at` required,
/// `j` optional; literal values must be positive (`j` may be zero).
fn lower_mass(
    m: &parse::Mass,
    scope: &NumberScope<'_>,
    errors: &mut Diagnostics,
) -> Option<MassSpec> {
    const FIELDS: [&str; 3] = ["m", "at", "j"];
    let usage = "`mass LINK { m = mass, at = CENTRE_POINT, j = inertia_about_centre }`";
    let mut mass = None;
    let mut at = None;
    let mut inertia = None;
    let mut ok = true;
    let mut given: Vec<String> = Vec::new();
    for (name, arg) in &m.fields {
        let field = name.to_string();
        if FIELDS.contains(&field.as_str()) && given.contains(&field) {
            ok = false;
            errors.push(
                name.span(),
                format!("`{field}` is given twice in this `mass`; keep one"),
            );
            continue;
        }
        given.push(field.clone());
        match (field.as_str(), arg) {
            ("at", Arg::Value(Expr::Path(p), None)) if p.path.get_ident().is_some() => {
                at = p.path.get_ident().cloned();
            }
            ("at", _) => {
                ok = false;
                errors.push(name.span(), format!("`at` names the centre of mass, a point of the link (write `let G = point(LINK, from A, d, angle);` and `at = G`); usage: {usage}"));
            }
            ("m" | "j", Arg::Value(expr, None)) => match convert(expr, scope) {
                Ok(v) => {
                    let literal = v.fold();
                    let bad = match literal {
                        Some(x) if field == "m" => !(x > 0.0 && x.is_finite()),
                        Some(x) => !(x >= 0.0 && x.is_finite()),
                        None => false,
                    };
                    if bad {
                        ok = false;
                        errors.error(syn::Error::new_spanned(
                            &v.tokens,
                            if field == "m" {
                                format!("a mass must be positive, got {:?}; leave out the `mass` statement for a massless link", literal.unwrap_or_default())
                            } else {
                                format!("a moment of inertia must be zero or positive, got {:?}", literal.unwrap_or_default())
                            },
                        ));
                    } else if field == "m" {
                        mass = Some(v);
                    } else {
                        inertia = Some(v);
                    }
                }
                Err(e) => {
                    ok = false;
                    errors.error(e);
                }
            },
            ("m" | "j", _) => {
                ok = false;
                errors.push(
                    name.span(),
                    format!("`{field}` takes a number; usage: {usage}"),
                );
            }
            (other, _) => {
                ok = false;
                errors.push(
                    name.span(),
                    format!(
                        "unknown mass property `{other}`; write `m` (mass), `at` (centre of mass) or `j` (moment of inertia about it){}",
                        did_you_mean(other, FIELDS)
                    ),
                );
            }
        }
    }
    if ok && (mass.is_none() || at.is_none()) {
        let missing = if mass.is_none() { "`m`" } else { "`at`" };
        errors.push(
            m.link.span(),
            format!("`mass` is missing {missing}; usage: {usage}"),
        );
        return None;
    }
    Some(MassSpec {
        link: m.link.clone(),
        mass: mass?,
        at: at?,
        inertia: if ok { inertia } else { None },
    })
}
