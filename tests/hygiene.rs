//! Hygiene: the generated code still compiles, and works, when the user's
//! module shadows the prelude names it could otherwise depend on. If the macro
//! wrote `Result`, `Ok`, `Some`, `None` or `f64` without a full path, this file
//! would not compile. Nor would it if the macro bound the user's names as
//! locals (`let G = ..`): the module `named_alike` has constants, a static and
//! a unit struct with the names of its points, a guide, links and a slide
//! (upper case, as Rust names constants, statics and unit structs), which
//! would turn such a `let` into a pattern.
#![allow(non_camel_case_types, dead_code, clippy::disallowed_names)]

mod shadowed {
    pub struct Result;
    pub struct Option;
    pub struct Ok;
    pub struct Err;
    pub struct Some;
    pub struct None;
    pub type f64 = u8;
    pub type f32 = u8;
    pub mod core {}

    use mechanism::mechanism;

    mechanism! {
        /// A four-bar defined where the prelude is shadowed (with its
        /// generated tests, which must not depend on the prelude either).
        #[self_test]
        pub Shadowed {
            params { crank = 1.0 }
            const coupler = 3.0;
            let O2 = ground(0.0, 0.0);
            let O4 = ground(3.0, 0.0);
            let A = crank(O2, crank, theta) as link2;
            let B = rrr(A, coupler, O4, 2.5, left) as (link3, link4);
            let P = point(link3, from A, 1.0, 30 deg);
        }
    }
}

#[test]
fn generated_code_ignores_shadowed_prelude() {
    let m = shadowed::Shadowed::<f64>::default();
    let input = shadowed::ShadowedInput { theta: 0.3 };
    let s = m.solve(&input, &input, &input).unwrap();
    // Loop closure holds: the code did run, not only compile.
    assert!(((s.position.B - s.position.A).norm() - 3.0).abs() < 1e-14);
}

mod named_alike {
    use mechanism::mechanism;

    pub const G: f64 = 9.81;
    pub const A: f64 = 1.0;
    pub static B: f64 = 2.0;
    pub struct P;
    pub const LINE: u8 = 0;
    pub const X: u8 = 0;
    pub const L2: u8 = 0;
    pub const L3: u8 = 0;

    mechanism! {
        /// A slider-crank with a coupler point, its centre of mass `G`, a
        /// weight and a load, every name of which is also an item here.
        #[self_test]
        pub NamedAlike {
            let O = ground(0.0, 0.0);
            let LINE = guide((0.0, 0.0), 0 deg);
            let A = crank(O, 0.1, theta) as L2;
            let B = rrp(A, 0.4, LINE, plus) as (L3, slider) slide X;
            let P = point(L3, from A, 0.1, 20 deg);
            let G = point(L3, from A, 0.2, 0 deg);
            mass L3 { m = 1.5, at = G, j = 0.02 };
            mass slider { m = 0.8, at = B };
            gravity (0.0, -9.81);
            force at B on slider along LINE = -30.0;
        }
    }
}

#[test]
fn generated_code_binds_no_name_of_the_users_scope() {
    let m = named_alike::NamedAlike::<f64>::default();
    let input = named_alike::NamedAlikeInput { theta: 0.7 };
    let s = m.solve(&input, &input, &input).unwrap();
    let p = &s.position;
    // The rod closes, the slide is B's abscissa, and the force analysis ran.
    assert!(((p.B - p.A).norm() - 0.4).abs() < 1e-15);
    assert!((p.X - p.B.x).abs() < 1e-15);
    assert!(s.forces.power_residual < 1e-13);
}

/// Clippy: the generated code of a definition whose angles fold to long
/// constants (the cosine and sine of 45 deg are `FRAC_1_SQRT_2`, which
/// clippy's `approx_constant`, deny by default, would flag in the user's
/// crate) passes clippy's default lints. `.ci/run` runs `cargo clippy
/// --all-targets -- -D warnings`, so a lint in the generated code of this
/// module fails CI. Without the generated impls' allowance of these two
/// lints, this definition makes `cargo clippy` fail with two errors.
mod lint_clean {
    use mechanism::mechanism;

    mechanism! {
        /// A four-bar's coupler point at 45 deg drives an RRP on a guide at
        /// 45 deg (batch, check, forces and self-tests generated too).
        #[self_test]
        pub Tilted {
            let O2 = ground(0.0, 0.0);
            let O4 = ground(3.0, 0.0);
            let A = crank(O2, 1.0, theta) as link2;
            let B = rrr(A, 3.0, O4, 2.0, left) as (link3, link4);
            let P = point(link3, from A, 1.0, 45 deg);
            let g = guide(O4, 45 deg);
            let Q = rrp(P, 2.5, g, plus) as (link5, block6);
            range theta = (-100 deg, 40 deg);
            mass link3 { m = 1.0, at = P };
            gravity (0.0, -9.81);
        }
    }
}

#[test]
fn folded_45_degree_constants_are_right() {
    let m = lint_clean::Tilted::<f64>::default();
    let p = m.position(&lint_clean::TiltedInput { theta: 0.3 }).unwrap();
    // P is 45 deg off the coupler's axis A -> B, at 1 from A: the cosine
    // between them is sqrt(1/2), to a few eps of the unit lengths.
    let (ap, ab) = (p.P - p.A, p.B - p.A);
    let cos = ap.dot(&ab) / (ap.norm() * ab.norm());
    assert!((cos - std::f64::consts::FRAC_1_SQRT_2).abs() < 4.0 * f64::EPSILON);
    // Q lies on the guide through O4 at 45 deg.
    let oq = p.Q - p.O4;
    assert!((oq.x - oq.y).abs() < 8.0 * f64::EPSILON * oq.norm());
}
