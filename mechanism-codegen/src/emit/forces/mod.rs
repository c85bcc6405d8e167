//! Stage 6b, emit the force analysis: the known load of every link (inertia,
//! weight, external forces and couples), then the groups and drivers in the
//! reverse of the solve order, each through its fixed-size system in
//! `mechanism::force`, passing its outer reactions (negated) to the bodies it
//! is attached to; then the driving efforts and the power balance.
//!
//! Only the terms a definition has are generated: no gravity statement, no
//! weight terms; a link without mass, no inertia terms (its load starts with
//! the first reaction passed to it); no moment of inertia or a link that does
//! not turn, no inertia couple; a fixed centre of mass, no `m a` term.

mod groups;
mod loads;

use super::describe::{fields_impl, FieldEntry};
use super::names::TypeNames;
use crate::keys::{GuideName, LinkName, PointName};
use crate::kinds::{self, forces::ForceCx, reads::Reads};
use crate::model::Model;
use crate::names::Family;
use crate::plan::Plan;
use crate::value::lit;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use std::collections::BTreeSet;
use syn::Ident;

/// The generated force analysis: items (structs) and methods.
pub struct ForcesCode {
    /// `NameForces` and, with a `loads` block, `NameLoads`.
    pub items: TokenStream,
    /// `forces(...)`.
    pub methods: TokenStream,
    /// The extra parameter of `forces` and `solve` (`loads: &NameLoads<T>`),
    /// empty without a `loads` block.
    pub loads_param: TokenStream,
    /// The matching argument (`loads`), empty without a `loads` block.
    pub loads_arg: TokenStream,
    /// The forces struct's reaction and effort fields, in order, with what
    /// each holds (for `Display` and serde, `emit::display`, `emit::interop`).
    pub fields: Vec<(Ident, ForceField)>,
}

/// What a field of the forces struct holds, as `Display` shows it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ForceField {
    /// A revolute joint's force (`Vector2`, force units).
    Force,
    /// A prismatic pair's `PrismaticReaction` (normal force and couple).
    Prismatic,
    /// A driving torque (force x length).
    Torque,
    /// A driving force along a line (force units).
    Push,
}

pub(crate) use crate::kinds::forces::{Held, Reaction};
pub(crate) use loads::masses_by_link;

struct ForceEmitter<'a> {
    model: &'a Model,
    plan: &'a Plan,
    moving: &'a BTreeSet<PointName>,
    /// Links whose load local exists (the others carry no load yet).
    loaded: BTreeSet<LinkName>,
    code: TokenStream,
    /// Power terms (expressions) for the balance.
    power: Vec<TokenStream>,
    /// The forces struct's reaction and effort fields, in the order found.
    reactions: Vec<Reaction>,
    /// The groups' force-system conditioning (`min_pivot_ratio`).
    conditions: Vec<TokenStream>,
    /// Methods beside `forces` (the motors' rate map).
    extra_methods: TokenStream,
    /// The recorder of the code's reads of `pos`, `vel` and `acc`.
    reads: &'a Reads,
}

impl ForceCx for ForceEmitter<'_> {
    fn body_of_point(&self, point: &Ident) -> Option<LinkName> {
        self.plan.body_of_point(&PointName::of(point))
    }

    fn body_of_guide(&self, guide: &Ident) -> Option<LinkName> {
        self.plan.body_of_guide(&GuideName::of(guide))
    }

    /// The reference point a link's load is accumulated about: its first point.
    fn reference(&self, link: &LinkName) -> Ident {
        self.plan.links[link].points[0].ident()
    }

    /// The load of `link` as a wrench about `point`.
    fn load_about(&self, link: &Ident, point: &Ident) -> TokenStream {
        let l = LinkName::of(link);
        if !self.loaded.contains(&l) {
            return quote!(::mechanism::force::Wrench::zero());
        }
        let local = Family::Load.of(&l);
        let r = self.reference(&l);
        if *point == r {
            quote!(#local)
        } else {
            let (r, point) = (self.reads.pos(&r), self.reads.pos(point));
            quote!(#local.moved(&#r, &#point))
        }
    }

    /// Adds a wrench (given as code about the link's reference point) to a link's load.
    fn add(&mut self, link: &LinkName, wrench: TokenStream) {
        let local = Family::Load.of(link);
        if self.loaded.insert(link.clone()) {
            self.code.extend(quote!(let #local = #wrench;));
        } else {
            self.code.extend(quote!(let #local = #local + #wrench;));
        }
    }

    fn code(&mut self, code: TokenStream) {
        self.code.extend(code);
    }

    fn reaction(&mut self, reaction: Reaction) {
        self.reactions.push(reaction);
    }

    fn power(&mut self, term: TokenStream) {
        self.power.push(term);
    }

    fn condition(&mut self, term: TokenStream) {
        self.conditions.push(term);
    }

    fn reads(&self) -> &Reads {
        self.reads
    }
}

impl ForceEmitter<'_> {
    /// The motors' torques of an inverse-kinematics definition: the rate
    /// map `K = dq/dP` from the velocity at unit rates of the target's
    /// inputs (every other input's rate 0), each motor's rate its link's
    /// angular velocity less its carrier's, then `K^T tau = D` with `D` the
    /// target's driving force (`mechanism::force::target::motor_torques`).
    /// Nothing without motors.
    fn motors(&mut self, names: &TypeNames) {
        let model = self.model;
        let reactions = kinds::motors::reactions(model);
        let Some((target, x, y)) = kinds::motors::held_target(model) else {
            return;
        };
        if reactions.is_empty() {
            return;
        }
        let input_ty = &names.input;
        let unit = |axis: &Ident| {
            let fields = model.inputs.iter().map(|i| {
                let (n, v) = (&i.name, lit(if i.name == *axis { 1.0 } else { 0.0 }));
                quote!(#n: #v)
            });
            quote!(#input_ty { #(#fields),* })
        };
        let rate = |link: &Ident| self.rate_fields(link).map(|(w, _)| self.reads.vel(&w));
        let rates: Vec<TokenStream> = model
            .kinetics
            .motors
            .iter()
            .map(|m| {
                let own = rate(&m.link).unwrap_or_else(|| lit(0.0));
                match m.carrier.as_ref().and_then(rate) {
                    Some(c) => quote!((#own - #c)),
                    None => own,
                }
            })
            .collect();
        let (ux, uy) = (unit(x), unit(y));
        let (rx, local, t) = (
            kinds::forces::rx(target),
            kinds::motors::local(),
            kinds::tokens::tag(target),
        );
        let position_ty = &names.position;
        let doc = format!(
            "The motors' rate map `K = dq/dP` at the pose `pos`: `k[i][j]` is motor `i`'s rate (rad/s; motors in the order declared: {}) per unit rate of the target `{}`'s input `j` (`{x}`, `{y}`; length units/s), from two velocity evaluations. `K` is the inverse of the forward Jacobian `J = dP/dq`; the motors' torques are `tau = K^-T D` (`forces`). Errors as `velocity`'s.",
            model.kinetics.motors.iter().map(|m| format!("`{}`", m.name)).collect::<Vec<_>>().join(", "),
            target.name
        );
        self.extra_methods.extend(quote! {
            #[doc = #doc]
            #[inline(always)]
            #[allow(non_snake_case)]
            pub fn motor_rate_map(&self, pos: &#position_ty<T>) -> ::core::result::Result<[[T; 2]; 2], ::mechanism::Error<T>> {
                let k_x = { let vel = self.velocity(pos, &#ux)?; [#(#rates),*] };
                let k_y = { let vel = self.velocity(pos, &#uy)?; [#(#rates),*] };
                ::core::result::Result::Ok([[k_x[0], k_y[0]], [k_x[1], k_y[1]]])
            }
        });
        self.code.extend(quote! {
            let #local = {
                let k = self.motor_rate_map(pos)?;
                ::mechanism::force::target::motor_torques([k[0][0], k[1][0]], [k[0][1], k[1][1]], &#rx.drive) #t
            };
        });
        self.conditions.push(quote!(#local.min_pivot_ratio));
        self.reactions.extend(reactions);
    }

    /// Velocity of a point (code), `None` when it never moves.
    fn velocity(&self, point: &Ident) -> Option<TokenStream> {
        self.moving
            .contains(&PointName::of(point))
            .then(|| self.reads.vel(&Family::Vel.of(point)))
    }

    /// The fields of a link's angular velocity and acceleration in the
    /// velocity and acceleration structs (`omega_L`, `alpha_L`), `None`
    /// when it does not turn. The code that reads one records it.
    fn rate_fields(&self, link: &Ident) -> Option<(Ident, Ident)> {
        self.plan
            .turning_link(&LinkName::of(link))
            .map(|l| (Family::Omega.of(&l), Family::Alpha.of(&l)))
    }
}

/// Emits the force analysis of a valid, planned model whose definition asks
/// for it. `moving` holds the points that move; `reads` records the code's
/// reads of the analyses' structs.
pub fn emit(model: &Model, plan: &Plan, moving: &BTreeSet<PointName>, reads: &Reads) -> ForcesCode {
    let mut em = ForceEmitter {
        model,
        plan,
        moving,
        loaded: BTreeSet::new(),
        code: TokenStream::new(),
        power: Vec::new(),
        reactions: Vec::new(),
        conditions: Vec::new(),
        extra_methods: TokenStream::new(),
        reads,
    };
    em.known_loads();
    for &i in plan.solve.iter().rev() {
        kinds::of(&model.stmts[i]).forces(&mut em);
    }
    let names = TypeNames::of(model);
    em.motors(&names);
    unique_names(&mut em.reactions);
    let loads = loads_struct(model, &names);
    let mut items = forces_struct(model, &names, &em.reactions, loads.item);
    items.extend(forces_fields(model, &names, &em.reactions));
    let mut methods = forces_method(&names, &em, &loads.param);
    methods.extend(em.extra_methods.clone());
    let fields = em
        .reactions
        .iter()
        .map(|r| {
            let held = match r.held {
                Held::Force => ForceField::Force,
                Held::Prismatic => ForceField::Prismatic,
                Held::Torque => ForceField::Torque,
                Held::Push => ForceField::Push,
            };
            (r.name.clone(), held)
        })
        .collect();
    ForcesCode {
        items,
        methods,
        loads_param: loads.param,
        loads_arg: loads.arg,
        fields,
    }
}

/// Field names must be unique: a second joint between the same two bodies
/// gets a number appended (`r_ground_crank_2`).
pub(crate) fn unique_names(reactions: &mut [Reaction]) {
    let mut seen = BTreeSet::new();
    for r in reactions {
        let mut candidate = r.name.to_string();
        let mut k = 2;
        while !seen.insert(candidate.clone()) {
            candidate = format!("{}_{k}", r.name);
            k += 1;
        }
        r.name = format_ident!("{}", candidate);
    }
}

/// The forces' conditioning indicator: the velocity's first, then each
/// group's force indicator (`min_pivot_ratio`). A group's force system is the
/// transpose of its rate system (virtual work), so it is singular at the same
/// poses, and the scaled determinants see that in any frame; the class II
/// groups' force indicators are the same relative determinants, the
/// actuator's and the triad's the relative pivots of a row-equilibrated
/// elimination, which can miss a singular pose in some frames (a row whose
/// entries all vanish together is lifted back to 1 by the scaling). `reads`
/// records the read of the velocity's `condition`.
fn condition_code(conditions: &[TokenStream], reads: &Reads) -> TokenStream {
    conditions.iter().fold(
        reads.vel(&format_ident!("condition")),
        |acc, c| quote!(::mechanism::geometry::min(#acc, #c)),
    )
}

/// The power-balance residual from the power terms (0 without any).
fn power_code(power_terms: &[TokenStream]) -> TokenStream {
    let terms: Vec<Ident> = (0..power_terms.len()).map(|k| Family::Pw.of(k)).collect();
    if terms.is_empty() {
        return lit(0.0);
    }
    let sum = terms.iter().skip(1).fold(
        {
            let t = &terms[0];
            quote!(#t)
        },
        |acc, t| quote!(#acc + #t),
    );
    // The largest |term| by comparisons (`RealField::max` would call
    // libm's `fmaxf`, about 20 instructions a call on a Cortex-M4F); a
    // NaN term is skipped, as `max` skips it, and shows in the sum.
    let residual = quote! {{
        let pw_scale = [#(::mechanism::geometry::abs(#terms)),*]
            .into_iter()
            .fold(<T as ::mechanism::Real>::lit(0.0), |m, a| if a > m { a } else { m });
        let pw_sum = #sum;
        if !(pw_scale.finite() && pw_sum.finite()) {
            ::core::option::Option::None
        } else if pw_scale > <T as ::mechanism::Real>::lit(0.0) {
            ::core::option::Option::Some(::mechanism::geometry::abs(pw_sum) / pw_scale)
        } else {
            ::core::option::Option::Some(<T as ::mechanism::Real>::lit(0.0))
        }
    }};
    // Reactions, loads and rates are finite here (every group checks
    // them), so only a product that overflows `T` (an `f32` force of
    // 1e38 N at 10 m/s) makes a term infinite: then no balance can be
    // shown, and 1 is reported rather than a NaN (a rescaled second
    // evaluation of every term would double this code for that case).
    quote! {{
        #(let #terms = #power_terms;)*
        match #residual {
            ::core::option::Option::Some(r) => r,
            ::core::option::Option::None => <T as ::mechanism::Real>::lit(1.0),
        }
    }}
}

/// The `NameLoads` struct of a definition with a `loads` block, and the
/// parameter and argument that pass it; all empty without one.
struct LoadsStruct {
    item: TokenStream,
    param: TokenStream,
    arg: TokenStream,
}

fn loads_struct(model: &Model, names: &TypeNames) -> LoadsStruct {
    let loads = &model.kinetics.loads;
    if loads.is_empty() {
        return LoadsStruct {
            item: quote!(),
            param: quote!(),
            arg: quote!(),
        };
    }
    let (name, vis, loads_ty) = (&names.name, &model.vis, &names.loads);
    let fields: Vec<&Ident> = loads.iter().map(|(n, _)| n).collect();
    let defaults: Vec<TokenStream> = loads.iter().map(|(_, v)| lit(*v)).collect();
    let doc = format!("Load values of [`{name}`] supplied per evaluation (declared in `loads {{ }}`); `Default` gives the definition's values.");
    LoadsStruct {
        item: quote! {
            #[doc = #doc]
            #[derive(Clone, Copy, Debug, PartialEq)]
            #[allow(non_snake_case)]
            #vis struct #loads_ty<T = ::core::primitive::f64> {
                #(#[doc = "Load value (force, couple or factor, as the definition uses it)."] pub #fields: T,)*
            }
            impl<T: ::mechanism::Real> ::core::default::Default for #loads_ty<T> {
                #[inline]
                fn default() -> Self {
                    #loads_ty { #(#fields: #defaults,)* }
                }
            }
        },
        param: quote!(, loads: &#loads_ty<T>),
        arg: quote!(, loads),
    }
}

/// The `NameForces` struct (reactions, efforts, condition, power residual),
/// followed by `loads_item`.
fn forces_struct(
    model: &Model,
    names: &TypeNames,
    reactions: &[Reaction],
    loads_item: TokenStream,
) -> TokenStream {
    let (name, vis, forces_ty) = (&names.name, &model.vis, &names.forces);
    let field_names: Vec<&Ident> = reactions.iter().map(|r| &r.name).collect();
    let field_types: Vec<&TokenStream> = reactions.iter().map(|r| &r.ty).collect();
    let field_docs: Vec<&String> = reactions.iter().map(|r| &r.doc).collect();
    let forces_doc = format!("Joint reactions and driving efforts of [`{name}`] (force units: mass x length / s^2 in the definition's units; N with kg, m, s). Each reaction is the force of one body on another in the global frame, as its field says.{}", loads::parts_doc(model));
    quote! {
        #[doc = #forces_doc]
        #[derive(Clone, Copy, Debug, PartialEq)]
        #[allow(non_snake_case)]
        #vis struct #forces_ty<T: ::mechanism::Real = ::core::primitive::f64> {
            #(#[doc = #field_docs] pub #field_names: #field_types,)*
            /// Conditioning indicator: the smaller of the velocity's
            /// `condition` (the groups' scaled determinants, singular at the
            /// same poses as their force systems) and the groups' force
            /// indicators (`min_pivot_ratio`); 1 for a well-conditioned
            /// pose, tending to 0 towards a singular one (toggle, dead centre,
            /// parallel guides).
            pub condition: T,
            /// Power balance residual: |driver power + power of the external
            /// loads, weights, inertia forces and couples| divided by the largest
            /// of those powers (0 when all vanish). A few eps when consistent.
            pub power_residual: T,
        }
        #loads_item
    }
}

/// The forces struct's `Fields` impl (`mechanism::structure`): every
/// reaction and effort by name with its quantity, a prismatic pair's as
/// `NAME.force` and `NAME.moment`, then `condition` and `power_residual`.
fn forces_fields(model: &Model, names: &TypeNames, reactions: &[Reaction]) -> TokenStream {
    let mut entries = Vec::new();
    for r in reactions {
        let (n, text) = (&r.name, r.name.to_string());
        match r.held {
            Held::Force => entries.push(FieldEntry::new(text, "Force", "Vector", quote!(#n))),
            Held::Prismatic => {
                let (force, moment) = (quote!(#n.force), quote!(#n.moment));
                entries.push(FieldEntry::new(
                    format!("{text}.force"),
                    "Force",
                    "Vector",
                    force,
                ));
                let name = format!("{text}.moment");
                entries.push(FieldEntry::new(name, "Moment", "Scalar", moment));
            }
            Held::Torque => entries.push(FieldEntry::new(text, "Moment", "Scalar", quote!(#n))),
            Held::Push => entries.push(FieldEntry::new(text, "Force", "Scalar", quote!(#n))),
        }
    }
    for extra in ["condition", "power_residual"] {
        let f = format_ident!("{}", extra);
        entries.push(FieldEntry::new(extra.into(), "Ratio", "Scalar", quote!(#f)));
    }
    fields_impl(&names.forces, &entries, &super::describe::units_of(model))
}

/// The `forces` method: the emitter's code, then the struct's value.
fn forces_method(
    names: &TypeNames,
    em: &ForceEmitter<'_>,
    loads_param: &TokenStream,
) -> TokenStream {
    let (position_ty, velocity_ty, acceleration_ty, forces_ty) = (
        &names.position,
        &names.velocity,
        &names.acceleration,
        &names.forces,
    );
    let code = &em.code;
    let condition = condition_code(&em.conditions, em.reads);
    let power = power_code(&em.power);
    let field_names: Vec<&Ident> = em.reactions.iter().map(|r| &r.name).collect();
    let field_values: Vec<&TokenStream> = em.reactions.iter().map(|r| &r.value).collect();
    quote! {
        /// Force analysis at a solved pose: joint reactions, driving efforts,
        /// the conditioning indicator and the power-balance residual.
        /// Groups are solved in the reverse of the solve order.
        ///
        /// Errors name the group whose force system is singular or whose
        /// loads are not finite.
        #[inline(always)]
        #[allow(non_snake_case, unused_variables, clippy::too_many_arguments)]
        pub fn forces(&self, pos: &#position_ty<T>, vel: &#velocity_ty<T>, acc: &#acceleration_ty<T> #loads_param) -> ::core::result::Result<#forces_ty<T>, ::mechanism::Error<T>> {
            #code
            let condition = #condition;
            let power_residual = #power;
            ::core::result::Result::Ok(#forces_ty { #(#field_names: #field_values,)* condition, power_residual })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{condition_code, power_code, unique_names, ForcesCode, Held, Reaction, Reads};
    use crate::emit::test_support::{flat, four_bar, planned};
    use proc_macro2::TokenStream;
    use quote::{format_ident, quote};
    use std::str::FromStr;

    /// The messages of the `compile_error!`s in the expansion of `src`.
    fn errors(src: &str) -> Vec<String> {
        let out = crate::expand(TokenStream::from_str(src).unwrap()).to_string();
        out.split("compile_error !")
            .skip(1)
            .map(|rest| rest.split(';').next().unwrap_or("").to_string())
            .collect()
    }

    /// A boom lifted by a cylinder, and an RRR group pinned at `PIN`.
    fn arm(pin: &str) -> String {
        format!(
            "pub Arm {{
                let A = ground(0.0, 0.0);
                let B = ground(0.6, -0.3);
                let O6 = ground(1.2, 0.2);
                let C = actuator(A, 1.0, B, len, left) as (boom, cyl);
                let M = point(cyl, from B, 0.3, 0 deg);
                let N = point(boom, from A, 0.5, 0 deg);
                let K = rrr({pin}, 0.8, O6, 0.7, right) as (link5, link6);
                mass link6 {{ m = 10.0, at = K }};
                range len = (0.9, 1.3);
            }}"
        )
    }

    #[test]
    fn a_group_pinned_to_an_actuators_cylinder_is_an_error() {
        let on_cylinder = errors(&arm("M"));
        assert_eq!(on_cylinder.len(), 1, "{on_cylinder:?}");
        assert!(
            on_cylinder[0].contains("cylinder `cyl`")
                && on_cylinder[0].contains("two-force member"),
            "{on_cylinder:?}"
        );
        // Pinned to the boom instead: no error.
        assert!(errors(&arm("N")).is_empty());
        // Without a force analysis the cylinder's point is fine.
        let kinematic = arm("M").replace("mass link6 { m = 10.0, at = K };", "");
        assert!(errors(&kinematic).is_empty());
    }

    fn forces(scene: &str) -> ForcesCode {
        let (model, plan) = planned(&four_bar(scene));
        let moving = plan.moving_points(&model);
        super::emit(&model, &plan, &moving, &Reads::default())
    }

    // Proves the weight terms come only with a gravity statement: a mass
    // without gravity gives an inertia force and no `gravity` or weight local;
    // with gravity both, and the weight's power in the balance.
    #[test]
    fn weight_terms_only_with_gravity() {
        let without = flat(&forces("mass link3 { m = 2.0, at = P };").methods);
        assert!(
            without.contains(
                "letpw_inertia_force_link3=acc.acc_P*(-<Tas::mechanism::Real>::lit(2f64));"
            ),
            "{without}"
        );
        assert!(
            !without.contains("gravity") && !without.contains("pw_weight"),
            "{without}"
        );
        let with = flat(&forces("mass link3 { m = 2.0, at = P }; gravity (0.0, -9810.0);").methods);
        assert!(
            with.contains("letpw_weight_link3=gravity*<Tas::mechanism::Real>::lit(2f64);"),
            "{with}"
        );
        assert!(with.contains("dot(&pw_weight_link3,&vel.vel_P)"), "{with}");
    }

    // Proves several masses on one link get numbered locals (one inertia
    // force and weight per part) and a single inertia couple whose literal
    // `j`s are folded into one number (0.03 + 0.01), with one power term.
    #[test]
    fn parts_of_a_link_get_numbered_loads_and_one_folded_couple() {
        let code = flat(
            &forces(
                "mass link3 { m = 2.0, at = P, j = 0.03 }; mass link3 { m = 1.0, at = B, j = 0.01 }; gravity (0.0, -9.81);",
            )
            .methods,
        );
        for local in [
            "letpw_inertia_force_link3_1=acc.acc_P*",
            "letpw_inertia_force_link3_2=acc.acc_B*",
            "letpw_weight_link3_1=",
            "letpw_weight_link3_2=",
        ] {
            assert!(code.contains(local), "{local} in {code}");
        }
        let couples = code.matches("letpw_inertia_couple_link3=").count();
        assert_eq!(couples, 1, "{code}");
        assert!(code.contains("letpw_inertia_couple_link3=-((<Tas::mechanism::Real>::lit(0.04f64))*acc.alpha_link3);"), "{code}");
    }

    // Proves the forces struct's doc gives the merged mass, centre (in the
    // link's frame, from the parts' common base) and parallel-axis J of a
    // link's literal parts (here 1 at (40, 0) from A with j 0.01 and 3 at A:
    // M 4, G (10, 0), J 0.01 + 1 * 30^2 + 3 * 10^2 = 1200.01), the count
    // alone when the bases differ, and nothing with one mass per link.
    #[test]
    fn merged_parts_in_the_forces_doc() {
        let two = flat(
            &forces(
                "let Q = point(link3, from A, (40.0, 0.0)); mass link3 { m = 1.0, at = Q, j = 0.01 }; mass link3 { m = 3.0, at = A };",
            )
            .items,
        );
        assert!(
            two.contains(&"`link3` carries 2 masses, combined: mass 4, centre (10, 0) from `A` in `link3`'s frame (along its axis, along its left normal), moment of inertia 1200.01".replace(' ', "")),
            "{two}"
        );
        let bases =
            flat(&forces("mass link3 { m = 1.0, at = P }; mass link3 { m = 3.0, at = B };").items);
        assert!(bases.contains("`link3`carries2masses.\""), "{bases}");
        let one = flat(&forces("mass link3 { m = 1.0, at = P };").items);
        assert!(!one.contains("carries"), "{one}");
    }

    // Proves the `loads` block gives the `NameLoads` struct and the extra
    // parameter of `forces` and `solve`, and its absence neither.
    #[test]
    fn loads_struct_and_parameter_only_with_a_loads_block() {
        let plain = forces("mass link3 { m = 2.0, at = P };");
        assert!(plain.loads_param.is_empty() && plain.loads_arg.is_empty());
        assert!(!flat(&plain.items).contains("FourBarLoads"));
        let loaded = forces(
            "mass link3 { m = 2.0, at = P }; loads { brake = 0.5 } torque on link4 = brake;",
        );
        assert_eq!(flat(&loaded.loads_param), ",loads:&FourBarLoads<T>");
        assert_eq!(flat(&loaded.loads_arg), ",loads");
        assert!(flat(&loaded.items).contains("structFourBarLoads<T=::core::primitive::f64>{"));
    }

    // Proves reaction field names stay unique: a second and third joint
    // between the same two bodies get `_2` and `_3`, other names are kept.
    #[test]
    fn repeated_reaction_names_are_numbered() {
        let reaction = |name: &str| Reaction {
            name: format_ident!("{}", name),
            ty: quote!(T),
            value: quote!(x),
            doc: String::new(),
            held: Held::Force,
        };
        let mut reactions = vec![
            reaction("r_ground_link2"),
            reaction("r_link2_link3"),
            reaction("r_ground_link2"),
            reaction("r_ground_link2"),
        ];
        unique_names(&mut reactions);
        let names: Vec<String> = reactions.iter().map(|r| r.name.to_string()).collect();
        assert_eq!(
            names,
            [
                "r_ground_link2",
                "r_link2_link3",
                "r_ground_link2_2",
                "r_ground_link2_3"
            ]
        );
    }

    // Proves the power residual is the literal 0 when no term has power (no
    // expression to evaluate), and the conditioning starts from the velocity's.
    #[test]
    fn empty_power_balance_and_condition_chain() {
        assert_eq!(flat(&power_code(&[])), "<Tas::mechanism::Real>::lit(0f64)");
        let reads = Reads::default();
        assert_eq!(flat(&condition_code(&[], &reads)), "vel.condition");
        assert_eq!(
            flat(&condition_code(&[quote!(rx_B.min_pivot_ratio)], &reads)),
            "::mechanism::geometry::min(vel.condition,rx_B.min_pivot_ratio)"
        );
    }
}
