//! Unit tests of the batch emitter.

/// A slide named `B_x` beside a point `B`: both would be the batch
/// field `pos_B_x`. One clear error on the slide's name, not rustc's
/// duplicate-field errors inside the macro.
#[test]
fn scalar_named_like_a_point_coordinate() {
    let out = crate::expand(quote::quote! {
        pub SlideNamedLikeCoord {
            let O = ground(0.0, 0.0);
            let line = guide(O, 0 deg);
            let A = crank(O, 0.1, theta) as link2;
            let B = rrp(A, 0.4, line, plus) as (link3, slider) slide B_x;
        }
    })
    .to_string();
    assert!(out.contains("compile_error"), "{out}");
    assert!(
        out.contains("`B_x` and the coordinates of point `B`"),
        "{out}"
    );
    assert_eq!(out.matches("compile_error").count(), 1, "{out}");
}

use super::kernel::{kernel, statement};
use crate::diag::Diagnostics;
use crate::kinds::lane::{tree_sum, Lane, OutputShape};
use crate::model::Model;
use crate::plan::Plan;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// The four-bar of seed 002 (mm), with `scene` (analysis level, outputs)
/// appended, lowered and planned; panics on a definition error.
fn four_bar(scene: TokenStream) -> (Model, Plan) {
    let definition = syn::parse2(quote! {
        pub FourBar {
            params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
            let O2 = ground(0.0, 0.0);
            let O4 = ground(ground, 0.0);
            let A = crank(O2, crank, theta2) as link2;
            let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
            let P = point(link3, from A, 120.0, 30 deg);
            #scene
        }
    })
    .expect("the four-bar parses");
    let mut diag = Diagnostics::new();
    let model = crate::model::lower(definition, &mut diag);
    crate::validate::model(&model, &mut diag);
    let plan = crate::plan::plan(&model, &mut diag);
    let errors = diag.finish();
    assert!(errors.is_empty(), "{:?}", errors);
    (model, plan.expect("the four-bar has a plan"))
}

/// The kernel method of `model` at `levels` (1 position, 2 velocity, 3
/// acceleration) for the point output `B`, as text without spaces.
fn kernel_text(model: &Model, plan: &Plan, levels: usize) -> Option<String> {
    let ins: Vec<_> = ["in", "rate", "accel"][..levels]
        .iter()
        .map(|p| format_ident!("{}_theta2", p))
        .collect();
    let ins: Vec<_> = ins.iter().collect();
    let outputs = [(format_ident!("B"), OutputShape::Point)];
    let k = kernel(model, plan, &ins, &outputs, levels)?;
    Some(k.method.to_string().replace(' ', ""))
}

/// A group whose joints the kernel has not solved yet has no lane code (it
/// would read undefined locals): the RRR alone in a fresh kernel is refused,
/// so the batch falls back to the scalar path; after the statements that
/// define its joints it is accepted.
#[test]
fn a_group_before_its_joints_falls_back() {
    let (model, _) = four_bar(quote! { analysis acceleration; });
    let rrr = model
        .stmts
        .iter()
        .position(|s| s.name == "B")
        .expect("statement B");
    assert!(statement(&mut Lane::new(3), &model.stmts[rrr]).is_none());
    let mut lane = Lane::new(3);
    for s in &model.stmts[..rrr] {
        assert!(statement(&mut lane, s).is_some(), "{}", s.name);
    }
    assert!(statement(&mut lane, &model.stmts[rrr]).is_some());
}

/// The kernel of a position-only scene computes no rates: no input rate or
/// acceleration is read, no `_rates` / `_accels` primitive called, no
/// angular velocity local made. The same definition at the acceleration
/// level has them all (so the absence is the level's doing, not a missing
/// kernel).
#[test]
fn a_position_only_kernel_has_no_rate_terms() {
    let (model, plan) = four_bar(quote! { analysis position; });
    let pos = kernel_text(&model, &plan, 1).expect("a lane kernel");
    let (model, plan) = four_bar(quote! { analysis acceleration; });
    let acc = kernel_text(&model, &plan, 3).expect("a lane kernel");
    for term in [
        "rate_theta2",
        "accel_theta2",
        "rrr_rates",
        "rrr_accels",
        "w_link3",
        "al_link3",
        "v_B_x",
        "a_B_x",
    ] {
        assert!(!pos.contains(term), "{term} in {pos}");
        assert!(acc.contains(term), "{term} not in {acc}");
    }
    assert!(pos.contains("::mechanism::__private::lane::rrr("), "{pos}");
}

/// An output the kernel does not compute (here a point no statement
/// defines) refuses the whole kernel: the batch then runs on the scalar
/// path alone instead of writing an undefined value.
#[test]
fn an_output_the_kernel_lacks_falls_back() {
    let (model, plan) = four_bar(quote! { analysis position; });
    let ins = [&format_ident!("in_theta2")];
    let outputs = [(format_ident!("Q"), OutputShape::Point)];
    assert!(kernel(&model, &plan, &ins, &outputs, 1).is_none());
    assert!(kernel_text(&model, &plan, 1).is_some());
}

/// The finiteness checks are summed as a balanced tree: five terms give
/// `((a + b) + (c + (d + e)))` (depth 3, not a chain of 4), one term is
/// itself, none gives no check at all.
#[test]
fn checks_sum_as_a_balanced_tree() {
    let terms: Vec<TokenStream> = ["a", "b", "c", "d", "e"]
        .iter()
        .map(|t| {
            let t = format_ident!("{}", t);
            quote!(#t)
        })
        .collect();
    let sum = tree_sum(&terms)
        .expect("a sum")
        .to_string()
        .replace(' ', "");
    assert_eq!(sum, "((a+b)+(c+(d+e)))");
    assert_eq!(tree_sum(&terms[..1]).expect("one term").to_string(), "a");
    assert!(tree_sum(&[]).is_none());
}

/// Ground points and a crank's link are no batch slices (the caller has
/// their values: the definition's coordinates, the element's input), even
/// when the definition lists them as outputs; the coupler joint is one.
#[test]
fn given_outputs_have_no_slices() {
    let out = crate::expand(quote! {
        pub GivenFourBar {
            let O2 = ground(0.0, 0.0);
            let O4 = ground(0.3048, 0.0);
            let A = crank(O2, 0.1016, theta2) as link2;
            let B = rrr(A, 0.254, O4, 0.1778, left) as (link3, link4);
            analysis velocity;
            outputs { O2, link2, B }
        }
    })
    .to_string();
    let start = out
        .find("pub struct GivenFourBarBatch")
        .expect("a batch struct");
    let end = start + out[start..].find('}').expect("the struct's end");
    let batch = &out[start..end];
    assert!(batch.contains("pos_B_x"), "{batch}");
    assert!(batch.contains("vel_B_y"), "{batch}");
    for absent in ["O2", "link2"] {
        assert!(!batch.contains(absent), "{absent} in {batch}");
    }
}

/// The batch fields of `NAMEBatch` or `NAMEForcesBatch` (`ty`) in the
/// expansion `out` (text without spaces), in order.
fn struct_fields(out: &str, ty: &str) -> Vec<String> {
    let start = out
        .find(&format!("struct{ty}<'a,T=::core::primitive::f64>{{"))
        .unwrap_or_else(|| panic!("{ty} in {out}"));
    let body = &out[start..];
    let body = &body[body.find('{').unwrap() + 1..body.find('}').unwrap()];
    body.split("pub")
        .filter_map(|f| f.split(':').next())
        .map(str::to_string)
        .filter(|f| !f.is_empty())
        .collect()
}

/// A press (slider-crank) with masses on every link, gravity and a
/// run-time load on the ram, every output asked for.
fn press() -> String {
    let out = crate::expand(quote::quote! {
        pub Press {
            loads { cut = 0.0 }
            let O = ground(0.0, 0.0);
            let line = guide((0.0, -0.02), 0 deg);
            let A = crank(O, 0.1, theta) as link2;
            let B = rrp(A, 0.4, line, plus) as (link3, ram) slide x;
            let G3 = point(link3, from A, 0.2, 0 deg);
            mass link2 { m = 0.5, at = A, j = 0.001 };
            mass link3 { m = 2.0, at = G3, j = 0.03 };
            mass ram { m = 5.0, at = B };
            gravity (0.0, -9.81);
            force at B on ram along line = cut;
        }
    });
    let text: String = out.to_string().split_whitespace().collect();
    assert!(!text.contains("compile_error"), "{text}");
    text
}

/// Proves the batch leaves out the columns that never change: the press's
/// ram is a block on a fixed guide, so its angle `ram` (and its rates) has
/// no column, while the coupler's angle, the points and the slide do; the
/// scalar position keeps `ram`. (The crank's link and the ground point are
/// left out as before: the caller has them.)
#[test]
fn constant_columns_are_left_out() {
    let out = press();
    let fields = struct_fields(&out, "PressBatch");
    for absent in ["pos_ram", "vel_ram", "acc_ram", "pos_link2", "pos_O_x"] {
        assert!(
            !fields.iter().any(|f| f == absent),
            "{absent} in {fields:?}"
        );
    }
    for present in [
        "pos_B_x",
        "pos_G3_y",
        "pos_link3",
        "pos_x",
        "vel_x",
        "acc_link3",
    ] {
        assert!(
            fields.iter().any(|f| f == present),
            "{present} not in {fields:?}"
        );
    }
    assert!(
        out.contains("pubram:T"),
        "the scalar position keeps the ram's angle"
    );
}

/// Proves a definition with masses and loads gets the forces batch: the
/// kinematic batch, one `load_*` column per run-time load, and one column
/// per scalar of the forces struct (a joint force as `_x`, `_y`; a
/// prismatic reaction as `_normal`, `_moment`, `_x`, `_y`; the crank's
/// torque; `condition` and `power_residual`), in the forces struct's order;
/// the owned form holds them too; a definition without masses has none.
#[test]
fn forces_batch_fields() {
    let out = press();
    let fields = struct_fields(&out, "PressForcesBatch");
    assert_eq!(
        fields,
        [
            "batch",
            "load_cut",
            "r_link2_link3_x",
            "r_link2_link3_y",
            "r_link3_ram_x",
            "r_link3_ram_y",
            "r_ground_ram_normal",
            "r_ground_ram_moment",
            "r_ground_ram_x",
            "r_ground_ram_y",
            "r_ground_link2_x",
            "r_ground_link2_y",
            "drive_theta",
            "condition",
            "power_residual",
        ]
    );
    assert!(out.contains("pubfnsolve_batch_forces("), "{out}");
    assert!(
        out.contains("pubload_cut:::mechanism::__alloc::Vec<T>,"),
        "{out}"
    );
    assert!(out.contains("pubfnas_forces_batch("), "{out}");
    let plain: String = crate::expand(quote::quote! {
        pub Plain {
            let O = ground(0.0, 0.0);
            let line = guide((0.0, -0.02), 0 deg);
            let A = crank(O, 0.1, theta) as link2;
            let B = rrp(A, 0.4, line, plus) as (link3, ram) slide x;
        }
    })
    .to_string()
    .split_whitespace()
    .collect();
    assert!(!plain.contains("ForcesBatch") && !plain.contains("solve_batch_forces"));
}
