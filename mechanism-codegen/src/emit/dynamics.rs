//! Stage 6c, emit the forward dynamics (`analysis dynamics;`): the equations
//! of motion in the inputs' coordinates `q` (Eksergian's equation and its
//! n-input form), from what the kinematics already generate.
//!
//! - Velocity coefficients: the velocity analysis at a unit rate of input
//!   `i` (the others zero) gives `v_G,i` of every mass centre, `w_L,i` of
//!   every turning link, `v_P,i` of every loaded point.
//! - Mass matrix: `M_ij = sum_parts m v_G,i . v_G,j + j w_L,i w_L,j`.
//! - Velocity-product terms: the acceleration analysis at the actual rates
//!   and zero input accelerations gives `a_G(q''=0)`, `alpha_L(q''=0)`;
//!   `h_i = sum_parts m v_G,i . a_G + j w_L,i alpha_L`.
//! - Generalized forces by virtual power: `Q_i = sum m g . v_G,i + sum F .
//!   v_P,i + sum T w_L,i`.
//! - `M q'' = tau + Q - h`: closed form for one input, the core's pivoting
//!   elimination (`mechanism::linsolve::solve`) for several.
//!
//! The force analysis' driving efforts obey the same power balance
//! (`drive . q' + Q . q' - (M q'' + h) . q' = 0` for every `q'`), so
//! `forces` at the computed `q''` gives back `tau`.

use super::forces::masses_by_link;
use super::names::TypeNames;
use crate::keys::{LinkName, PointName};
use crate::kinds::reads::Reads;
use crate::model::{ForceSpecValue, MassSpec, Model};
use crate::names::Family;
use crate::plan::Plan;
use crate::value::{lit, Value};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use std::collections::BTreeSet;
use syn::Ident;

/// The generated dynamics: the result struct and the `dynamics` method.
pub struct DynamicsCode {
    /// `NameDynamics`.
    pub items: TokenStream,
    /// `dynamics(...)`.
    pub methods: TokenStream,
}

/// A rate the velocity coefficients are made of.
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord)]
enum Coefficient {
    /// `vel.vel_P` of a moving point.
    Point(PointName),
    /// `vel.omega_L` of a turning link.
    Link(LinkName),
}

impl Coefficient {
    /// The field of the velocity struct.
    fn field(&self) -> Ident {
        match self {
            Coefficient::Point(p) => Family::Vel.of(p),
            Coefficient::Link(l) => Family::Omega.of(l),
        }
    }
}

/// One term of the equations: what multiplies which coefficients.
enum Term {
    /// A mass part: `m` at the moving centre `G` (`m v_G,i . v_G,j`,
    /// `m v_G,i . a_G`, weight `m g . v_G,i`).
    Translation { mass: TokenStream, at: PointName },
    /// A moment of inertia `j` of a turning link (`j w_i w_j`, `j w_i alpha`).
    Rotation {
        inertia: TokenStream,
        link: LinkName,
    },
    /// An external force (code of its `Vector2`) at a moving point.
    Force { value: TokenStream, at: PointName },
    /// An external couple on a turning link.
    Couple { value: TokenStream, link: LinkName },
}

struct Terms<'a> {
    model: &'a Model,
    plan: &'a Plan,
    moving: &'a BTreeSet<PointName>,
    terms: Vec<Term>,
    /// Run-time checks of masses and inertias not known at expansion.
    checks: TokenStream,
    /// The recorder of the code's reads of `pos`, `vel` and `acc`.
    reads: &'a Reads,
}

impl Terms<'_> {
    fn turning(&self, link: &Ident) -> Option<LinkName> {
        self.plan.turning_link(&LinkName::of(link))
    }

    /// A mass or moment of inertia, checked at run time when not literal
    /// (the same checks as the force analysis': a typed error naming the
    /// group that creates the link).
    fn checked(&mut self, value: &Value, link: &LinkName, part: &str, mass: bool) -> TokenStream {
        if value.fold().is_some() {
            return value.emit();
        }
        let Some(stmt) = self
            .model
            .stmts
            .iter()
            .find(|s| s.links.iter().any(|l| *link == *l))
        else {
            return value.emit();
        };
        let v = value.emit();
        let name = format_ident!("{}", crate::kinds::of(stmt).primitive());
        let t = crate::emit::tag(stmt);
        let (local, check, what) = if mass {
            (Family::DynMass.of(part), quote!(positive), "mass")
        } else {
            (
                Family::DynInertia.of(part),
                quote!(non_negative),
                "moment of inertia",
            )
        };
        let what = format!("{what} of `{link}`");
        self.checks.extend(quote!(
            let #local = ::mechanism::geometry::#check(#v, ::mechanism::Primitive::#name, #what) #t;
        ));
        quote!(#local)
    }

    fn mass(&mut self, link: &LinkName, part: &str, m: &MassSpec) {
        if self.moving.contains(&PointName::of(&m.at)) {
            let mass = self.checked(&m.mass, link, part, true);
            self.terms.push(Term::Translation {
                mass,
                at: PointName::of(&m.at),
            });
        }
        if let (Some(j), Some(turning)) = (&m.inertia, self.turning(&m.link)) {
            if j.fold() != Some(0.0) {
                let inertia = self.checked(j, link, part, false);
                self.terms.push(Term::Rotation {
                    inertia,
                    link: turning,
                });
            }
        }
    }

    fn collect(&mut self) {
        let k = &self.model.kinetics;
        for (link, parts) in masses_by_link(&k.masses) {
            for (n, m) in parts.iter().enumerate() {
                let part = if parts.len() == 1 {
                    link.to_string()
                } else {
                    format!("{link}_{}", n + 1)
                };
                self.mass(&link, &part, m);
            }
        }
        for f in &k.forces {
            if !self.moving.contains(&PointName::of(&f.at)) {
                continue;
            }
            let value = match &f.value {
                ForceSpecValue::Components(x, y) => {
                    let (x, y) = (x.emit(), y.emit());
                    quote!(::mechanism::Vector2::new(#x, #y))
                }
                ForceSpecValue::Along(guide, v) => {
                    let (guide, v) = (self.reads.pos(guide), v.emit());
                    quote!((#guide.dir * #v))
                }
            };
            self.terms.push(Term::Force {
                value,
                at: PointName::of(&f.at),
            });
        }
        for t in &k.torques {
            if let Some(link) = self.turning(&t.on) {
                self.terms.push(Term::Couple {
                    value: t.value.emit(),
                    link,
                });
            }
        }
    }

    /// The coefficients the terms read, each once, in a fixed order.
    fn coefficients(&self) -> Vec<Coefficient> {
        let set: BTreeSet<Coefficient> = self
            .terms
            .iter()
            .map(|t| match t {
                Term::Translation { at, .. } | Term::Force { at, .. } => {
                    Coefficient::Point(at.clone())
                }
                Term::Rotation { link, .. } | Term::Couple { link, .. } => {
                    Coefficient::Link(link.clone())
                }
            })
            .collect();
        set.into_iter().collect()
    }
}

/// `a + b + ..` of `terms`, the literal 0 for none.
fn sum(terms: Vec<TokenStream>) -> TokenStream {
    let mut it = terms.into_iter();
    match it.next() {
        None => lit(0.0),
        Some(first) => it.fold(first, |acc, t| quote!(#acc + #t)),
    }
}

/// The code of `M`, `h`, `Q` and the right-hand side `tau + Q - h` from the
/// velocity coefficients `c_I_K` (coefficient `K` at a unit rate of input `I`).
fn equations(cx: &Terms<'_>, coefficients: &[Coefficient], n: usize) -> TokenStream {
    let index = |c: &Coefficient| coefficients.iter().position(|x| x == c).unwrap_or(0);
    let c = |i: usize, k: usize| Family::Coef.pair(i, k);
    let gravity = cx.model.kinetics.gravity.is_some();
    let mut code = TokenStream::new();
    let mut mass_entries = Vec::new();
    let mut h = Vec::new();
    let mut q = Vec::new();
    for i in 0..n {
        let mut row = Vec::new();
        for j in 0..n {
            if j < i {
                row.push(quote!(m_mat[#j][#i]));
                continue;
            }
            let terms = cx.terms.iter().filter_map(|t| match t {
                Term::Translation { mass, at } => {
                    let k = index(&Coefficient::Point(at.clone()));
                    let (a, b) = (c(i, k), c(j, k));
                    Some(quote!(#mass * ::mechanism::geometry::dot(&#a, &#b)))
                }
                Term::Rotation { inertia, link } => {
                    let k = index(&Coefficient::Link(link.clone()));
                    let (a, b) = (c(i, k), c(j, k));
                    Some(quote!(#inertia * (#a * #b)))
                }
                _ => None,
            });
            row.push(sum(terms.collect()));
        }
        mass_entries.push(row);
        let hi = cx.terms.iter().filter_map(|t| match t {
            Term::Translation { mass, at } => {
                let (ci, a) = (
                    c(i, index(&Coefficient::Point(at.clone()))),
                    cx.reads.acc(&Family::Acc.of(at)),
                );
                Some(quote!(#mass * ::mechanism::geometry::dot(&#ci, &#a)))
            }
            Term::Rotation { inertia, link } => {
                let (ci, a) = (
                    c(i, index(&Coefficient::Link(link.clone()))),
                    cx.reads.acc(&Family::Alpha.of(link)),
                );
                Some(quote!(#inertia * (#ci * #a)))
            }
            _ => None,
        });
        h.push(sum(hi.collect()));
        let qi = cx.terms.iter().filter_map(|t| match t {
            Term::Translation { mass, at } if gravity => {
                let ci = c(i, index(&Coefficient::Point(at.clone())));
                Some(quote!(#mass * ::mechanism::geometry::dot(&gravity, &#ci)))
            }
            Term::Force { value, at } => {
                let ci = c(i, index(&Coefficient::Point(at.clone())));
                Some(quote!(::mechanism::geometry::dot(&(#value), &#ci)))
            }
            Term::Couple { value, link } => {
                let ci = c(i, index(&Coefficient::Link(link.clone())));
                Some(quote!((#value) * #ci))
            }
            _ => None,
        });
        q.push(sum(qi.collect()));
    }
    // Rows one at a time (an entry below the diagonal reads the one above it).
    let rows = mass_entries.iter().enumerate().map(|(i, row)| {
        let sets = row
            .iter()
            .enumerate()
            .map(|(j, e)| quote!(m_mat[#i][#j] = #e;));
        quote!(#(#sets)*)
    });
    code.extend(quote! {
        let mut m_mat = [[<T as ::mechanism::Real>::lit(0.0); #n]; #n];
        #(#rows)*
        let h_vec: [T; #n] = [#(#h),*];
        let q_vec: [T; #n] = [#(#q),*];
        let rhs: [T; #n] = ::core::array::from_fn(|k| efforts_vec[k] + q_vec[k] - h_vec[k]);
    });
    code
}

/// The code solving `M x = rhs` (closed form for one input, the core's
/// elimination for several): `x` and `condition`, or the typed error.
fn solve_code(inputs: &[Ident]) -> TokenStream {
    let n = inputs.len();
    let group = inputs
        .iter()
        .map(|i| i.to_string())
        .collect::<Vec<_>>()
        .join(", ");
    if n == 1 {
        quote! {
            let m = m_mat[0][0];
            // A sum of non-negative terms: zero only when no mass moves with
            // the input (a massless chain), never negative.
            if !(m > <T as ::mechanism::Real>::lit(0.0) && m.finite()) {
                return ::core::result::Result::Err(::mechanism::Error::new(
                    ::mechanism::Primitive::MassMatrix,
                    ::mechanism::Fault::Singular { det: m, scale: <T as ::mechanism::Real>::lit(1.0) },
                ).in_group(#group));
            }
            let x = [rhs[0] / m];
            let condition = <T as ::mechanism::Real>::lit(1.0);
        }
    } else {
        quote! {
            let solved = ::mechanism::linsolve::solve(m_mat, rhs).map_err(|e| ::mechanism::Error::new(::mechanism::Primitive::MassMatrix, e.fault).in_group(#group))?;
            let x = solved.x;
            let condition = solved.min_pivot_ratio;
        }
    }
}

/// Emits the dynamics of a valid, planned model at `analysis dynamics`.
/// `moving` holds the points that move; `loads_param` is the force
/// analysis' extra parameter (empty without a `loads` block); `reads`
/// records the code's reads of the analyses' structs.
pub fn emit(
    model: &Model,
    plan: &Plan,
    moving: &BTreeSet<PointName>,
    loads_param: &TokenStream,
    reads: &Reads,
) -> DynamicsCode {
    let mut cx = Terms {
        model,
        plan,
        moving,
        terms: Vec::new(),
        checks: TokenStream::new(),
        reads,
    };
    cx.collect();
    let names = TypeNames::of(model);
    let inputs = super::names::input_names(model);
    let n = inputs.len();
    let coefficients = cx.coefficients();
    // c_I_K: coefficient K at a unit rate of input I.
    let c = |i: usize, k: usize| Family::Coef.pair(i, k);
    let input_ty = &names.input;
    let unit = |i: usize| {
        let fields = inputs.iter().enumerate().map(|(k, name)| {
            let v = lit(if k == i { 1.0 } else { 0.0 });
            quote!(#name: #v)
        });
        quote!(#input_ty { #(#fields),* })
    };
    let mut code = cx.checks.clone();
    if let Some((_, gx, gy)) = &model.kinetics.gravity {
        let (gx, gy) = (gx.emit(), gy.emit());
        code.extend(quote!(let gravity = ::mechanism::Vector2::new(#gx, #gy);));
    }
    for i in 0..n {
        let locals: Vec<Ident> = (0..coefficients.len()).map(|k| c(i, k)).collect();
        let fields: Vec<TokenStream> = coefficients
            .iter()
            .map(|k| cx.reads.vel(&k.field()))
            .collect();
        let u = unit(i);
        code.extend(quote! {
            let (#(#locals,)*) = {
                let vel = self.velocity(pos, &#u)?;
                (#(#fields,)*)
            };
        });
    }
    let needs_bias = cx
        .terms
        .iter()
        .any(|t| matches!(t, Term::Translation { .. } | Term::Rotation { .. }));
    if needs_bias {
        let zero = {
            let fields = inputs
                .iter()
                .map(|name| quote!(#name: <T as ::mechanism::Real>::lit(0.0)));
            quote!(#input_ty { #(#fields),* })
        };
        code.extend(quote! {
            let vel = self.velocity(pos, rates)?;
            let acc = self.acceleration(pos, &vel, &#zero)?;
        });
    }
    code.extend(equations(&cx, &coefficients, n));
    code.extend(solve_code(&inputs));
    let k: Vec<usize> = (0..n).collect();
    let group = inputs
        .iter()
        .map(|i| i.to_string())
        .collect::<Vec<_>>()
        .join(", ");
    let dynamics_ty = format_ident!("{}Dynamics", model.name);
    let (position_ty, vis, name) = (&names.position, &model.vis, &names.name);
    let input_list = inputs
        .iter()
        .map(|i| format!("`{i}`"))
        .collect::<Vec<_>>()
        .join(", ");
    let struct_doc = format!(
        "Equations of motion of [`{name}`] in its inputs' coordinates `q` ({input_list}, in this order): `M(q) q'' = tau + Q(q) - h(q, q')`. Units: an angle input's row in moments (force x length), a length input's in forces; `M` in mass x length^2 (angle, angle), mass x length (angle, length) or mass (length, length). The force analysis' driving efforts at `accels` give back `tau`."
    );
    let items = quote! {
        #[doc = #struct_doc]
        #[derive(Clone, Copy, Debug, PartialEq)]
        #vis struct #dynamics_ty<T: ::mechanism::Real = ::core::primitive::f64> {
            /// The inputs' accelerations `q''` (rad/s^2 or length units/s^2).
            pub accels: #input_ty<T>,
            /// The generalized mass matrix `M(q)`, symmetric, positive
            /// semi-definite (`M[i][j]`: input `i`'s row, input `j`'s column);
            /// `q'^T M q' / 2` is the kinetic energy.
            pub mass: [[T; #n]; #n],
            /// The velocity-product terms `h(q, q')` (centripetal and Coriolis):
            /// the inertia loads' generalized force at zero input accelerations.
            pub velocity_terms: [T; #n],
            /// The generalized forces `Q(q)` of gravity and the definition's
            /// external forces and couples, by virtual power.
            pub generalized_forces: [T; #n],
            /// Conditioning of `M`: the smallest relative pivot of its
            /// elimination (1 for a single input; tending to 0 towards a
            /// pose where the inputs' inertia degenerates).
            pub condition: T,
        }
    };
    let doc = format!(
        "Forward dynamics at the pose `pos` with the inputs' rates `rates` and the drives' efforts `efforts` (each input's driving torque or force, as the force analysis' `drive_<input>`: positive in the sense of the input's increase): `q'' = M^-1 (tau + Q - h)` ({n} velocity evaluations at unit rates, one at `rates`, one acceleration at zero input accelerations). Errors: those of `velocity` and `acceleration`; a mass or moment of inertia from `params` that is not positive; `Singular` with `Primitive::MassMatrix` in group `{group}` when `M` is singular (no inertia moves with some input, or a dead point of the drive)."
    );
    let position_arg = quote!(pos: &#position_ty<T>);
    let methods = quote! {
        #[doc = #doc]
        #[inline(always)]
        #[allow(non_snake_case, unused_variables, clippy::too_many_arguments, clippy::needless_range_loop)]
        pub fn dynamics(&self, #position_arg, rates: &#input_ty<T>, efforts: &#input_ty<T> #loads_param) -> ::core::result::Result<#dynamics_ty<T>, ::mechanism::Error<T>> {
            let efforts_vec: [T; #n] = [#(efforts.#inputs),*];
            #code
            ::core::result::Result::Ok(#dynamics_ty {
                accels: #input_ty { #(#inputs: x[#k]),* },
                mass: m_mat,
                velocity_terms: h_vec,
                generalized_forces: q_vec,
                condition,
            })
        }
    };
    DynamicsCode { items, methods }
}

#[cfg(test)]
mod tests {
    use crate::emit::test_support::{flat, four_bar};
    use proc_macro2::TokenStream;
    use std::str::FromStr;

    fn expand(src: &str) -> String {
        flat(&crate::expand(TokenStream::from_str(src).unwrap()))
    }

    // Proves `analysis dynamics` alone generates the `dynamics` method and
    // its struct (a force analysis alone does not), with one velocity
    // evaluation at a unit rate per input, the acceleration at zero input
    // accelerations, the closed form for one input and weights only with
    // gravity.
    #[test]
    fn dynamics_only_when_asked() {
        let forces = expand(&four_bar("mass link3 { m = 2.0, at = P, j = 0.1 };"));
        assert!(!forces.contains("fndynamics("), "{forces}");
        let dynamics = expand(&four_bar(
            "analysis dynamics; mass link3 { m = 2.0, at = P, j = 0.1 };",
        ));
        assert!(dynamics.contains("fndynamics(") && dynamics.contains("structFourBarDynamics"));
        assert!(
            dynamics.contains(
                "self.velocity(pos,&FourBarInput{theta2:<Tas::mechanism::Real>::lit(1f64)})?"
            ),
            "{dynamics}"
        );
        assert!(dynamics.contains("letx=[rhs[0]/m];"));
        assert!(!dynamics.contains("letgravity"), "{dynamics}");
        let weighed = expand(&four_bar(
            "analysis dynamics; mass link3 { m = 2.0, at = P }; gravity (0.0, -9.81);",
        ));
        assert!(
            weighed.contains("::mechanism::geometry::dot(&gravity,&c_0_0)"),
            "{weighed}"
        );
    }

    // Proves a definition asked for dynamics with no inertia that moves is
    // a compile error naming the links to give a mass.
    #[test]
    fn no_moving_inertia_is_an_error() {
        let out = expand(&four_bar(
            "analysis dynamics; mass link2 { m = 2.0, at = O2 };",
        ));
        assert!(out.contains("compile_error"), "{out}");
        assert!(out.contains("`link2`,`link3`,`link4`"), "{out}");
        let fine = expand(&four_bar(
            "analysis dynamics; mass link2 { m = 2.0, at = O2, j = 0.1 };",
        ));
        assert!(!fine.contains("compile_error"), "{fine}");
    }
}
