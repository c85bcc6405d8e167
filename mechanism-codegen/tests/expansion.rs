//! Expansion snapshots: what the macro writes for three scenes of one four-bar.
//! They show that a scene gets only what it asks for:
//! - `position_only`: no velocity or acceleration code, and no `atan2`
//!   (`geometry::angle`) since no link angle is an output;
//! - `velocity_angles`: velocity code, angles computed because links are outputs,
//!   no acceleration code;
//! - `acceleration_full`: everything; fixed points pass `None`.
//! - `forces_coupler_mass`: the force analysis with a mass on the coupler only
//!   and no gravity: inertia terms for `link3` only, no weight terms, no
//!   loads argument; `forces_gravity_loads`: gravity and a per-call load;
//! - `inverse_five_bar_motors`: a target driver (inverse kinematics) and the
//!   motors' torques.
//!
//! Review changes with `cargo insta review` (or `INSTA_UPDATE=always`).

use quote::quote;

fn expand(tokens: proc_macro2::TokenStream) -> String {
    let out = mechanism_codegen::expand(tokens);
    let file: syn::File = syn::parse2(out).expect("expansion is valid Rust");
    prettyplease::unparse(&file)
}

fn four_bar(scene: proc_macro2::TokenStream) -> String {
    expand(quote! {
        /// Four-bar of seed 002 (mm).
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
}

#[test]
fn position_only() {
    let code = four_bar(quote! { analysis position; outputs { B, P } });
    assert!(
        !code.contains("fn velocity"),
        "a position-only scene has no velocity code"
    );
    assert!(
        !code.contains("geometry::angle"),
        "no angle output, so no atan2"
    );
    insta::assert_snapshot!(code);
}

#[test]
fn velocity_angles() {
    let code = four_bar(quote! { analysis velocity; outputs { B, link3, link4 } });
    assert!(code.contains("fn velocity"));
    assert!(!code.contains("fn acceleration"));
    assert!(code.contains("geometry::angle"), "link angles are outputs");
    assert!(
        !code.contains("let pos_P ="),
        "P is not an output and nothing needs it: left out"
    );
    insta::assert_snapshot!(code);
}

#[test]
fn acceleration_full() {
    let code = four_bar(quote! {});
    assert!(code.contains("fn acceleration") && code.contains("fn solve"));
    // O2 and O4 are fixed: the crank and the RRR group get `None` for them.
    let flat: String = code.split_whitespace().collect();
    assert!(flat.contains("crank::velocity(&pos.grp_A,::core::option::Option::None"));
    // The RRR's link lengths are its determinant's scale (no square root).
    assert!(flat.contains("rrr::velocity_lengths(&pos.grp_B,self.coupler,self.rocker,::core::option::Option::Some(&vel_A),::core::option::Option::None"));
    insta::assert_snapshot!(code);
}

#[test]
fn forces_coupler_mass() {
    let code = four_bar(quote! {
        mass link3 { m = 2.0, at = P, j = 0.05 };
        outputs { B }
    });
    assert!(
        code.contains("fn forces("),
        "masses ask for the force analysis"
    );
    assert!(
        !code.contains("gravity"),
        "no gravity statement: no weight terms"
    );
    assert!(
        !code.contains("load_link4 ="),
        "the rocker carries no mass: no inertia load is built for it"
    );
    assert!(
        code.contains("let pos_P ="),
        "the centre of mass is computed although not an output"
    );
    assert!(
        !code.contains("loads:"),
        "no `loads` block: no loads argument"
    );
    insta::assert_snapshot!(code);
}

#[test]
fn forces_gravity_loads() {
    let code = four_bar(quote! {
        loads { brake = 0.0 }
        mass link3 { m = 2.0, at = P, j = 0.05 };
        mass link4 { m = 1.0, at = O4 };
        gravity (0.0, -9810.0);
        torque on link4 = brake;
        outputs { B }
    });
    assert!(code.contains("let gravity ="));
    assert!(code.contains("loads: &FourBarLoads<T>"));
    assert!(
        !code.contains("pw_inertia_force_link4"),
        "the rocker's centre of mass is its fixed pivot: no m a term"
    );
    insta::assert_snapshot!(code);
}

#[test]
fn inverse_five_bar_motors() {
    // The five-bar robot given its end point, with a payload and its two
    // motors: the target's point is its inputs, each arm an RRR on it; the
    // forces end with the rate map at unit rates of the target's inputs
    // (two velocity calls) and the motors' torques from the target's drive.
    let code = expand(quote! {
        pub Robot {
            let O1 = ground(0.0, 0.0);
            let O2 = ground(0.08, 0.0);
            let P = target(x, y) as effector;
            let A = rrr(O1, 0.1, P, 0.16, left) as (arm1, fore1);
            let C = rrr(O2, 0.1, P, 0.16, right) as (arm2, fore2);
            force at P on effector = (0.0, -2.0);
            motor q1 = angle(arm1);
            motor q2 = angle(arm2);
            outputs { arm1, arm2 }
        }
    });
    assert!(code.contains("driver::target::position(input.x, input.y)"));
    assert!(code.contains("let k_x") && code.contains("let k_y"));
    assert!(code.contains("force::target::motor_torques("));
    assert!(code.contains("pub drive_q1: T") && code.contains("pub drive_q2: T"));
    insta::assert_snapshot!(code);
}
