//! The mechanism's own items: its struct (run-time parameters, the structure
//! listing in its doc comment) with `Default`, the inputs struct, and, with
//! accelerations, the solution struct and `solve`.

use super::forces::ForcesCode;
use super::names::{allow_literal_lints, marker, Generated, TypeNames};
use crate::kinds;
use crate::kinds::tokens::mode_tokens;
use crate::model::{Level, Model, Stmt};
use crate::plan::Plan;
use crate::value::lit;
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// The doc text that lists the statements in solve order and the analyses
/// generated.
fn structure_doc(model: &Model, plan: &Plan) -> String {
    let mut structure = String::from("Structure found by `mechanism!` (solve order):\n\n");
    for (k, &i) in plan.solve.iter().enumerate() {
        structure.push_str(&format!("{}. {}\n", k + 1, describe(&model.stmts[i])));
    }
    structure.push_str(&format!(
        "\nAnalyses generated: {}.",
        match model.level {
            Level::Position => "position",
            Level::Velocity => "position, velocity",
            Level::Acceleration => "position, velocity, acceleration",
            Level::Forces =>
                "position, velocity, acceleration, forces (joint reactions and driving efforts)",
            Level::Dynamics =>
                "position, velocity, acceleration, forces (joint reactions and driving efforts), dynamics (the equations of motion in the inputs' coordinates)",
        }
    ));
    structure
}

/// The mechanism's struct with its `Default` (the definition's parameter
/// values), and the inputs struct.
pub(super) fn own_items(model: &Model, plan: &Plan, inputs: &[Ident]) -> Generated {
    let names = TypeNames::of(model);
    let (name, vis, docs, input_ty) = (&names.name, &model.vis, &model.docs, &names.input);
    let param_names: Vec<&Ident> = model.params.iter().map(|(n, _)| n).collect();
    let param_defaults: Vec<TokenStream> = model.params.iter().map(|(_, v)| lit(*v)).collect();
    // With `params` the struct can be written out in full
    // (`FourBar { ground: 0.3, crank: 0.1, .. }`, no hidden field).
    let (params_marker, params_marker_init) =
        marker(param_names.is_empty() && model.modes.is_empty());
    let mode_names: Vec<&Ident> = model.modes.iter().map(|(n, _)| n).collect();
    let mode_defaults: Vec<TokenStream> =
        model.modes.iter().map(|(_, m)| mode_tokens(*m)).collect();
    let structure = structure_doc(model, plan);
    let derives = super::interop::passed_on(model);
    let input_doc = format!("Inputs of [`{name}`], one per driver: angles in rad, lengths in the definition's unit. The same struct carries their rates and accelerations.");
    let allow_lints = allow_literal_lints();
    let items = quote! {
        #(#docs)*
        #[doc = ""]
        #[doc = #structure]
        #[derive(Clone, Copy, Debug, PartialEq)]
        #derives
        #vis struct #name<T = ::core::primitive::f64> {
            #(#[doc = "Run-time parameter (default from the definition)."] pub #param_names: T,)*
            #(#[doc = "Run-time assembly mode of the groups that name it (default from the definition; see `docs/assembly-modes.md`)."] pub #mode_names: ::mechanism::Mode,)*
            #params_marker
        }

        #allow_lints
        impl<T: ::mechanism::Real> ::core::default::Default for #name<T> {
            #[inline]
            fn default() -> Self {
                #name { #(#param_names: #param_defaults,)* #(#mode_names: #mode_defaults,)* #params_marker_init }
            }
        }

        #[doc = #input_doc]
        #[derive(Clone, Copy, Debug, PartialEq)]
        #derives
        #[allow(non_snake_case)]
        #vis struct #input_ty<T = ::core::primitive::f64> {
            #(#[doc = "Driver input (or its rate / acceleration)."] pub #inputs: T,)*
        }
    };
    Generated {
        items,
        methods: TokenStream::new(),
    }
}

/// The solution struct (every analysis together) and `solve`, for a
/// definition with accelerations; `forces`: its force analysis, if any.
pub(super) fn solve_items(model: &Model, forces: Option<&ForcesCode>) -> Generated {
    let names = TypeNames::of(model);
    let vis = &model.vis;
    let (input_ty, position_ty, velocity_ty, acceleration_ty, solution_ty, forces_ty) = (
        &names.input,
        &names.position,
        &names.velocity,
        &names.acceleration,
        &names.solution,
        &names.forces,
    );
    let (forces_field, forces_call, forces_value, loads_param) = match forces {
        Some(f) => {
            let arg = &f.loads_arg;
            (
                quote! {
                    /// Force analysis.
                    pub forces: #forces_ty<T>,
                },
                quote!(let forces = self.forces(&position, &velocity, &acceleration #arg)?;),
                quote!(forces,),
                f.loads_param.clone(),
            )
        }
        None => (quote!(), quote!(), quote!(), quote!()),
    };
    let solution_doc = if forces.is_some() {
        " Position, velocity, acceleration and forces together."
    } else {
        " Position, velocity and acceleration together."
    };
    let items = quote! {
        #[doc = #solution_doc]
        #[derive(Clone, Copy, Debug, PartialEq)]
        #vis struct #solution_ty<T: ::mechanism::Real = ::core::primitive::f64> {
            /// Position analysis.
            pub position: #position_ty<T>,
            /// Velocity analysis.
            pub velocity: #velocity_ty<T>,
            /// Acceleration analysis.
            pub acceleration: #acceleration_ty<T>,
            #forces_field
        }
    };
    let methods = quote! {
        /// Every analysis the definition asks for, at once.
        // Always inlined, as the analyses and the primitives are: their
        // results are large structs, returned through memory when a call
        // stays a call (in the report's program the compiler kept them
        // calls, and the six-bar and shaper took 1.6 times as long;
        // docs/performance.md).
        #[inline(always)]
        pub fn solve(&self, input: &#input_ty<T>, rates: &#input_ty<T>, accels: &#input_ty<T> #loads_param) -> ::core::result::Result<#solution_ty<T>, ::mechanism::Error<T>> {
            let position = self.position(input)?;
            let velocity = self.velocity(&position, rates)?;
            let acceleration = self.acceleration(&position, &velocity, accels)?;
            #forces_call
            ::core::result::Result::Ok(#solution_ty { position, velocity, acceleration, #forces_value })
        }
    };
    Generated { items, methods }
}

/// One line of the structure listing in the generated type's doc comment.
fn describe(stmt: &Stmt) -> String {
    kinds::of(stmt).describe()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::emit::test_support::{flat, four_bar, planned};

    // Proves the structure listing numbers the statements in solve order, one
    // line each, and names the analyses the definition asks for.
    #[test]
    fn structure_listing_in_solve_order() {
        let (model, plan) = planned(&four_bar("analysis velocity;"));
        let doc = structure_doc(&model, &plan);
        let lines: Vec<&str> = doc.lines().collect();
        assert_eq!(lines[0], "Structure found by `mechanism!` (solve order):");
        assert_eq!(lines[2], "1. ground point `O2`");
        assert_eq!(
            lines[4],
            "3. driver: crank `link2` about `O2`, input `theta2`, tip `A`"
        );
        assert_eq!(
            lines[5],
            "4. RRR group `link3, link4`: `A`, `O4` -> `B`, mode plus (m = +1)"
        );
        assert_eq!(lines[6], "5. point `P` on `link3` (from `A`)");
        assert_eq!(
            lines.last().unwrap(),
            &"Analyses generated: position, velocity."
        );
    }

    // Proves the mechanism struct has one field per parameter and no marker,
    // and a definition without parameters gets the `PhantomData` marker (else
    // rustc would reject the unused `T`).
    #[test]
    fn parameters_or_a_marker() {
        let (model, plan) = planned(&four_bar(""));
        let inputs = crate::emit::names::input_names(&model);
        assert_eq!(inputs, ["theta2"]);
        let items = flat(&own_items(&model, &plan, &inputs).items);
        assert!(items.contains("pubground:T,"), "{items}");
        assert!(!items.contains("_scalar"), "{items}");
        let (model, plan) =
            planned("pub Crank { let O = ground(0.0, 0.0); let A = crank(O, 1.0, t) as link; }");
        let items = flat(&own_items(&model, &plan, &crate::emit::names::input_names(&model)).items);
        assert!(
            items.contains("pub_scalar:::core::marker::PhantomData<T>,"),
            "{items}"
        );
    }

    // Proves `solve` without a force analysis takes no loads and its solution
    // has no `forces` field.
    #[test]
    fn solve_without_forces_has_no_forces_field() {
        let (model, _) = planned(&four_bar(""));
        let code = solve_items(&model, None);
        let (items, methods) = (flat(&code.items), flat(&code.methods));
        assert!(!items.contains("forces"), "{items}");
        assert!(methods.contains("accels:&FourBarInput<T>)->"), "{methods}");
        assert!(!methods.contains("self.forces"), "{methods}");
    }
}
