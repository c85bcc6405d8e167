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
