//! The position analysis: the code that solves each statement in solve order,
//! the position struct (outputs, and the hidden values later code reads), and
//! the `position` and `position_cos_sin` methods.

use super::names::{debug_impl, grp, local, marker, output_docs, tag, Generated, TypeNames};
use crate::keys::LinkName;
use crate::kinds::reads::{Analysis, Reads};
use crate::kinds::{self, lane::OutputShape, tokens::axis, Known, Solve};
use crate::model::{Model, StmtId};
use crate::plan::Plan;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use std::collections::BTreeSet;
use syn::Ident;

/// A value of the position code the position struct may keep: its field
/// name, the local that holds it, and its type.
#[derive(Clone)]
pub(super) struct Stored {
    field: Ident,
    local: Ident,
    ty: TokenStream,
}

impl Stored {
    fn new(field: &Ident, local: &Ident, ty: TokenStream) -> Self {
        Stored {
            field: field.clone(),
            local: local.clone(),
            ty,
        }
    }
}

/// The position code of one definition, before the struct's fields are chosen.
pub(super) struct PositionCode {
    /// Every statement's position code, in solve order.
    pub code: TokenStream,
    /// The values the position struct may keep (those a later reader reads).
    pub stored: Vec<Stored>,
    /// The output locals: link angles and slides.
    pub out_code: TokenStream,
    /// The struct's output fields (name, type): points, links, slides.
    pub outputs: Vec<(Ident, OutputShape)>,
}

/// Emits the position code of every statement (and, for `velocity` and
/// `acceleration`, answers which link a direction comes from).
pub(super) struct Emitter<'a> {
    pub model: &'a Model,
    pub plan: &'a Plan,
    /// What the check found that the position code reads (the triads'
    /// tracked assemblies).
    pub known: &'a Known,
    /// Links whose unit axis is needed in position (points on them, carried guides).
    axes: BTreeSet<LinkName>,
    /// Emitting `position_cos_sin`: cranks marked `as cos_sin` read
    /// `input_cs.NAME.cos` and `.sin`.
    cos_sin: bool,
    /// Emitting `position_near`: kinds with several assemblies follow the
    /// previous position's (`GroupKind::position_tracking`), their reads
    /// of it recorded here.
    tracking: Option<&'a Reads>,
}

impl<'a> Emitter<'a> {
    /// The emitter of `position` (`cos_sin` false) or `position_cos_sin`.
    pub fn new(model: &'a Model, plan: &'a Plan, known: &'a Known, cos_sin: bool) -> Self {
        // Which link axes are needed in position.
        let mut axes = BTreeSet::new();
        for stmt in plan.solve.iter().map(|&i| &model.stmts[i]) {
            if let Some(link) = kinds::of(stmt).reads_axis() {
                axes.insert(LinkName::of(link));
            }
        }
        Emitter {
            model,
            plan,
            known,
            axes,
            cos_sin,
            tracking: None,
        }
    }

    /// The position code of the whole definition.
    pub fn code(&self) -> PositionCode {
        let mut code = TokenStream::new();
        let mut stored = Vec::new();
        for &i in &self.plan.solve {
            let (c, fields) = self.position(i);
            code.extend(c);
            stored.extend(fields);
        }
        let out = &self.plan.outputs;
        let mut outputs: Vec<(Ident, OutputShape)> = Vec::new();
        for p in &out.points {
            outputs.push((p.clone(), OutputShape::Point));
        }
        for link in &out.links {
            outputs.push((link.clone(), OutputShape::Scalar));
        }
        for slide in out.slides.iter().map(|s| &s.name) {
            outputs.push((slide.clone(), OutputShape::Scalar));
        }
        PositionCode {
            code,
            stored,
            out_code: self.outputs_code(false),
            outputs,
        }
    }

    /// Position statements for one statement; returns the code and the values
    /// the position struct may keep (those a later reader reads).
    fn position(&self, id: StmtId) -> (TokenStream, Vec<Stored>) {
        let stmt = &self.model.stmts[id];
        let (name, g, t) = (&local(&stmt.name), grp(stmt), tag(stmt));
        let kind = kinds::of_known(&self.model.stmts, id, self.known);
        let solve = match self
            .tracking
            .and_then(|reads| kind.position_tracking(reads))
        {
            Some(solve) => solve,
            None => kind.position(self.cos_sin),
        };
        let (code, mut fields) = match solve {
            Solve::Own { expr, ty } => (
                quote!(let #name = #expr;),
                vec![Stored::new(&stmt.name, name, ty)],
            ),
            Solve::Group { call, joint: None } => (
                quote!(let #g = #call #t;),
                vec![Stored::new(&g, &g, kind.position_type())],
            ),
            Solve::Group {
                call,
                joint: Some(joint),
            } => {
                let joint = format_ident!("{}", joint);
                let own_ty = quote!(::mechanism::Point2<T>);
                (
                    quote! {
                        let #g = #call #t;
                        let #name = #g.#joint;
                    },
                    vec![
                        Stored::new(&g, &g, kind.position_type()),
                        Stored::new(&stmt.name, name, own_ty),
                    ],
                )
            }
        };
        // Unit axes of the links this statement creates, where needed.
        let mut axes = TokenStream::new();
        for (j, link) in stmt.links.iter().enumerate() {
            if self.axes.contains(&LinkName::of(link)) {
                let axis = axis(link);
                let (unit, _) = kind.link_direction(j);
                axes.extend(quote!(let #axis = #unit;));
                fields.push(Stored::new(&axis, &axis, quote!(::mechanism::Vector2<T>)));
            }
        }
        (quote!(#code #axes), fields)
    }

    /// Output locals: link angles and slides. `cos_sin`: the code for
    /// `position_cos_sin`, where a marked crank's angle is its axis' angle.
    fn outputs_code(&self, cos_sin: bool) -> TokenStream {
        let (model, plan, out) = (self.model, self.plan, &self.plan.outputs);
        let mut code = TokenStream::new();
        for link in &out.links {
            let info = &plan.links[&LinkName::of(link)];
            let kind = kinds::of(&model.stmts[info.stmt]);
            let (_, dir) = kind.link_direction(info.index);
            // A crank's angle is its input: reduced to (-pi, pi], no atan2.
            let value = kind
                .link_angle(cos_sin)
                .unwrap_or_else(|| quote!(::mechanism::geometry::angle(&#dir)));
            let l = local(link);
            code.extend(quote!(let #l = #value;));
        }
        for crate::plan::Slide {
            name: slide,
            stmt: i,
            slot,
        } in &out.slides
        {
            let g = grp(&model.stmts[*i]);
            let field = kinds::of(&model.stmts[*i]).slide_field(*slot);
            let l = local(slide);
            code.extend(quote!(let #l = #g.#field;));
        }
        code
    }
}

/// The position struct, built from the outputs and the stored values later
/// code reads.
struct PositionStruct<'a> {
    /// Stored values that are read and are not outputs.
    hidden: Vec<&'a Stored>,
    /// The inputs are kept (`pos.input`): a later analysis reads them.
    keep_input: bool,
}

impl<'a> PositionStruct<'a> {
    fn new(code: &'a PositionCode, reads: &Reads) -> Self {
        let out_names: BTreeSet<String> = code.outputs.iter().map(|(n, _)| n.to_string()).collect();
        let hidden = code
            .stored
            .iter()
            .filter(|f| {
                !out_names.contains(&f.field.to_string())
                    && reads.reads(Analysis::Position, &f.field)
            })
            .collect();
        PositionStruct {
            hidden,
            keep_input: reads.reads(Analysis::Position, &format_ident!("input")),
        }
    }

    /// `(field, init)` of the kept inputs, empty when they are not kept.
    fn input(&self, input_ty: &Ident) -> (TokenStream, TokenStream) {
        if self.keep_input {
            (
                quote!(#[doc(hidden)] pub input: #input_ty<T>,),
                quote!(input,),
            )
        } else {
            (TokenStream::new(), TokenStream::new())
        }
    }
}

/// The position struct and the `position` method; with cranks marked
/// `as cos_sin`, also the `CosSin` input struct and `position_cos_sin`;
/// with `tracking` (the code of [`tracking_code`]), `position_near`.
/// `reads`: what every later reader reads of the struct.
pub(super) fn items(
    em: &Emitter<'_>,
    code: &PositionCode,
    tracking: Option<&TokenStream>,
    reads: &Reads,
    inputs: &[Ident],
) -> Generated {
    let model = em.model;
    let names = TypeNames::of(model);
    let (name, vis, position_ty, input_ty) =
        (&names.name, &model.vis, &names.position, &names.input);
    let layout = PositionStruct::new(code, reads);
    let (input_field, input_init) = layout.input(input_ty);
    let (out_names, out_types): (Vec<Ident>, Vec<TokenStream>) = code
        .outputs
        .iter()
        .map(|(n, s)| (n.clone(), s.ty()))
        .unzip();
    let hidden: Vec<&Ident> = layout.hidden.iter().map(|f| &f.field).collect();
    let hidden_locals: Vec<&Ident> = layout.hidden.iter().map(|f| &f.local).collect();
    let hidden_types: Vec<&TokenStream> = layout.hidden.iter().map(|f| &f.ty).collect();
    let (pos_marker, pos_marker_init) =
        marker(out_names.is_empty() && hidden.is_empty() && !layout.keep_input);
    let pos_docs = output_docs(&em.plan.outputs, 0);
    let pos_doc = format!("Position of [`{name}`]: points in the definition's length unit, link angles in rad in (-pi, pi] from +x, counter-clockwise; slide displacements in length units.");
    let mut out = Generated::default();
    out.items.extend(quote! {
        #[doc = #pos_doc]
        #[derive(Clone, Copy, PartialEq)]
        #[allow(non_snake_case)]
        #vis struct #position_ty<T: ::mechanism::Real = ::core::primitive::f64> {
            #(#[doc = #pos_docs] pub #out_names: #out_types,)*
            #(#[doc(hidden)] pub #hidden: #hidden_types,)*
            #input_field
            #pos_marker
        }
    });
    out.items.extend(debug_impl(position_ty, &out_names, &[]));
    // Field names and the position code's locals that hold them.
    let out_locals: Vec<Ident> = out_names.iter().map(local).collect();
    let init: Vec<TokenStream> = out_names
        .iter()
        .chain(hidden.iter().copied())
        .zip(out_locals.iter().chain(hidden_locals.iter().copied()))
        .map(|(field, value)| {
            if field == value {
                quote!(#field)
            } else {
                quote!(#field: #value)
            }
        })
        .collect();
    let value = quote!(#position_ty { #(#init,)* #input_init #pos_marker_init });
    let (pos_code, pos_out_code) = (&code.code, &code.out_code);
    out.methods.extend(quote! {
        /// Solves the position analysis for the driver inputs (rad or length units).
        ///
        /// Errors name the group that cannot be assembled or is singular.
        #[inline(always)]
        #[allow(non_snake_case, unused_variables)]
        pub fn position(&self, input: &#input_ty<T>) -> ::core::result::Result<#position_ty<T>, ::mechanism::Error<T>> {
            let input = *input;
            #pos_code
            #pos_out_code
            ::core::result::Result::Ok(#value)
        }
    });
    out.push(cos_sin_items(em, &names, inputs, layout.keep_input, &value));
    if let Some(code) = tracking {
        let doc = "Solves the position analysis on the same assembly as `previous` (a triad's: Newton from its pose, falling back to the full search, `NotNear` when that assembly has met another one or vanished): the form for sweeps and real-time loops, where `position` picks the assembly from the pose tracked at expansion time.";
        out.methods.extend(quote! {
            #[doc = #doc]
            #[inline(always)]
            #[allow(non_snake_case, unused_variables)]
            pub fn position_near(&self, previous: &#position_ty<T>, input: &#input_ty<T>) -> ::core::result::Result<#position_ty<T>, ::mechanism::Error<T>> {
                let input = *input;
                let pos = previous;
                #code
                #pos_out_code
                ::core::result::Result::Ok(#value)
            }
        });
    }
    out
}

/// The code of `position_near` (its reads of `pos`, recorded in `reads`,
/// are among those that decide the position struct's hidden fields), `None`
/// when no statement has several assemblies.
pub(super) fn tracking_code(em: &Emitter<'_>, reads: &Reads) -> Option<TokenStream> {
    let (model, plan) = (em.model, em.plan);
    // Whether a statement has a tracking form; the code that asks goes
    // nowhere, so its reads are recorded apart.
    let probe = Reads::default();
    plan.solve
        .iter()
        .any(|&i| {
            kinds::of(&model.stmts[i])
                .position_tracking(&probe)
                .is_some()
        })
        .then(|| {
            let mut tr = Emitter::new(model, plan, em.known, false);
            tr.tracking = Some(reads);
            tr.code().code
        })
}

/// The inputs of cranks marked `as cos_sin`.
fn marked_cranks(model: &Model) -> Vec<&Ident> {
    model
        .stmts
        .iter()
        .filter_map(kinds::cos_sin_input)
        .collect()
}

/// `NameCosSin` and `position_cos_sin`, when a crank is marked `as cos_sin`
/// (nothing otherwise). `value`: the position struct's value at the end.
fn cos_sin_items(
    em: &Emitter<'_>,
    names: &TypeNames,
    inputs: &[Ident],
    keep_input: bool,
    value: &TokenStream,
) -> Generated {
    let (model, plan) = (em.model, em.plan);
    let marked = marked_cranks(model);
    let mut out = Generated::default();
    if marked.is_empty() {
        return out;
    }
    let em_cs = Emitter::new(model, plan, em.known, true);
    let mut cs_code = TokenStream::new();
    for &i in &plan.solve {
        cs_code.extend(em_cs.position(i).0);
    }
    let cs_out = em.outputs_code(true);
    let (name, vis, cs_ty, input_ty, position_ty) = (
        &names.name,
        &model.vis,
        &names.cos_sin,
        &names.input,
        &names.position,
    );
    let field_ty: Vec<TokenStream> = inputs
        .iter()
        .map(|i| {
            if marked.contains(&i) {
                quote!(::mechanism::driver::crank::CosSin<T>)
            } else {
                quote!(T)
            }
        })
        .collect();
    let copied: Vec<TokenStream> = inputs
        .iter()
        .map(|i| {
            if marked.contains(&i) {
                quote!(#i: <T as ::mechanism::Real>::lit(0.0))
            } else {
                quote!(#i: input_cs.#i)
            }
        })
        .collect();
    let cs_input = if keep_input {
        quote!(let input = #input_ty { #(#copied,)* };)
    } else {
        TokenStream::new()
    };
    let cs_doc = format!("Driver inputs of [`{name}`] for `position_cos_sin`: the cranks written `INPUT as cos_sin` take their angle as `(cos, sin)` (need not be unit: it is normalized), the other inputs as in [`{input_ty}`].");
    out.items.extend(quote! {
        #[doc = #cs_doc]
        #[derive(Clone, Copy, Debug, PartialEq)]
        #[allow(non_snake_case)]
        #vis struct #cs_ty<T = ::core::primitive::f64> {
            #(#[doc = "Driver input."] pub #inputs: #field_ty,)*
        }
    });
    out.methods.extend(quote! {
        /// Solves the position analysis with the marked cranks' angles
        /// given as `(cos, sin)` (no sine or cosine is evaluated for
        /// them; their link angle, if an output, is one `atan2`). Where
        /// the position records the inputs (for a slider driver's rates),
        /// the marked cranks' entries are 0: nothing reads them.
        #[inline(always)]
        #[allow(non_snake_case, unused_variables)]
        pub fn position_cos_sin(&self, input: &#cs_ty<T>) -> ::core::result::Result<#position_ty<T>, ::mechanism::Error<T>> {
            let input_cs = *input;
            #cs_input
            #cs_code
            #cs_out
            ::core::result::Result::Ok(#value)
        }
    });
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::emit::test_support::{flat, four_bar, planned};

    /// The statement named `name`.
    fn stmt(model: &Model, name: &str) -> StmtId {
        StmtId(model.stmts.iter().position(|s| s.name == name).unwrap())
    }

    // Proves a crank marked `as cos_sin` reads `input_cs.NAME.cos/.sin` only in
    // `position_cos_sin`, and its angle in `position` as before.
    #[test]
    fn a_marked_crank_reads_cos_sin_only_in_position_cos_sin() {
        let src = four_bar("").replace("theta2) as link2", "theta2 as cos_sin) as link2");
        let (model, plan) = planned(&src);
        let crank = stmt(&model, "A");
        let plain = flat(
            &Emitter::new(&model, &plan, &Known::default(), false)
                .position(crank)
                .0,
        );
        let cs = flat(
            &Emitter::new(&model, &plan, &Known::default(), true)
                .position(crank)
                .0,
        );
        assert!(
            plain.contains("crank::position(&pos_O2,self.crank,input.theta2)"),
            "{plain}"
        );
        assert!(
            cs.contains(
                "position_cos_sin(&pos_O2,self.crank,input_cs.theta2.cos,input_cs.theta2.sin)"
            ),
            "{cs}"
        );
    }

    // Proves a link's unit axis is computed only when something in position
    // needs it: a point on the coupler asks for `axis_link3`, and nothing asks
    // for the rocker's.
    #[test]
    fn link_axes_only_where_a_point_or_guide_needs_them() {
        let (model, plan) = planned(&four_bar(""));
        let code = flat(
            &Emitter::new(&model, &plan, &Known::default(), false)
                .code()
                .code,
        );
        assert!(
            code.contains("letaxis_link3=grp_B.r1/self.coupler;"),
            "{code}"
        );
        assert!(!code.contains("axis_link4"), "{code}");
        let no_point = four_bar("").replace("let P = point(link3, from A, 120.0, 30 deg);", "");
        let (model, plan) = planned(&no_point);
        let code = flat(
            &Emitter::new(&model, &plan, &Known::default(), false)
                .code()
                .code,
        );
        assert!(!code.contains("axis_"), "{code}");
    }

    // Proves the position struct keeps, besides the outputs, exactly the
    // stored values some reader reads: with no reader it has no hidden field;
    // a read of `pos.grp_B` keeps the RRR's state with its core type.
    #[test]
    fn the_struct_keeps_only_the_values_read() {
        let (model, plan) = planned(&four_bar("analysis position; outputs { B }"));
        let known = Known::default();
        let em = Emitter::new(&model, &plan, &known, false);
        let code = em.code();
        let inputs = crate::emit::names::input_names(&model);
        let none = flat(&items(&em, &code, None, &Reads::default(), &inputs).items);
        assert!(!none.contains("doc(hidden)"), "{none}");
        let reads = Reads::default();
        let _ = reads.pos(&format_ident!("grp_B"));
        let kept = flat(&items(&em, &code, None, &reads, &inputs).items);
        assert!(
            kept.contains("#[doc(hidden)]pubgrp_B:::mechanism::dyad::rrr::RrrPosition<T>,"),
            "{kept}"
        );
        assert!(!kept.contains("grp_A"), "{kept}");
    }
}
