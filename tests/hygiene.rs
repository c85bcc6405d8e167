//! Hygiene: the generated code still compiles, and works, when the user's
//! module shadows the prelude names it could otherwise depend on. If the macro
//! wrote `Result`, `Ok`, `Some`, `None` or `f64` without a full path, this file
//! would not compile.
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
