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
