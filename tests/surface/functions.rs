//! Functions in dimensions (`sqrt`, `sin`, `cos`, `tan`, `atan2`, `hypot`,
//! `abs`, `min`, `max`, and `pi`): a triangle coupler given by its three
//! sides, whose third vertex is written with the law of cosines and `sqrt`,
//! folded when the sides are literal and computed per call when they are
//! parameters (in `f64` and `f32`). Checked against the triangle's sides
//! measured on the solved points, never against the macro's own numbers.
#![allow(non_snake_case)]
use mechanism::mechanism;
use mechanism::Point2;

mechanism! {
    /// Four-bar whose coupler is the triangle A-B-P with |AB| = 2.54,
    /// |AP| = 1.8, |BP| = 1.2; P's place in the coupler's frame from the
    /// three sides. The ground pivot O4 is at `hypot(3.0, 0.48)` (3.0381...)
    /// and the crank's angle offset by `atan2` of nothing but numbers.
    pub TriangleLiteral {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(hypot(3.0, 0.48), 0.0);
        let A = crank(O2, 1.016, theta) as link2;
        let B = rrr(A, 2.54, O4, 1.778, left) as (link3, link4);
        let P = point(link3, from A, (
            (1.8 * 1.8 + 2.54 * 2.54 - 1.2 * 1.2) / (2.0 * 2.54),
            sqrt(1.8 * 1.8 - ((1.8 * 1.8 + 2.54 * 2.54 - 1.2 * 1.2) / (2.0 * 2.54)) * ((1.8 * 1.8 + 2.54 * 2.54 - 1.2 * 1.2) / (2.0 * 2.54)))
        ));
    }
}

mechanism! {
    /// The same with the three sides as run-time parameters.
    pub TriangleParams {
        params { ab = 2.54, ap = 1.8, bp = 1.2, gx = 3.0, gy = 0.48 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(hypot(gx, gy), 0.0);
        let A = crank(O2, 1.016, theta) as link2;
        let B = rrr(A, ab, O4, 1.778, left) as (link3, link4);
        let P = point(link3, from A, (
            (ap * ap + ab * ab - bp * bp) / (2.0 * ab),
            sqrt(ap * ap - ((ap * ap + ab * ab - bp * bp) / (2.0 * ab)) * ((ap * ap + ab * ab - bp * bp) / (2.0 * ab)))
        ));
    }
}

fn dist(a: Point2<f64>, b: Point2<f64>) -> f64 {
    (a - b).norm()
}

fn widen(p: Point2<f32>) -> Point2<f64> {
    Point2::new(p.x as f64, p.y as f64)
}

#[test]
fn a_triangle_vertex_from_its_three_sides() {
    // Proves `sqrt` and `hypot` in dimensions: P is at 1.8 from A and 1.2
    // from B (the triangle's sides, measured on the solved points) and O4 at
    // hypot(3, 0.48) = 3.03815... from O2, over a turn of the crank, with
    // literal sides (folded) and parameter sides (computed per call) alike.
    // Tolerance: a few roundings of coordinates of size 3 (f64: 8 eps * 3).
    let want_o4 = (3.0f64 * 3.0 + 0.48 * 0.48).sqrt();
    for k in 0..72 {
        let theta = k as f64 * 5f64.to_radians();
        let lit = TriangleLiteral::<f64>::default()
            .position(&TriangleLiteralInput { theta })
            .unwrap();
        let par = TriangleParams::<f64>::default()
            .position(&TriangleParamsInput { theta })
            .unwrap();
        for (what, p) in [("literal", &lit.P), ("params", &par.P)] {
            let (a, b) = if what == "literal" {
                (lit.A, lit.B)
            } else {
                (par.A, par.B)
            };
            assert!(
                (dist(*p, a) - 1.8).abs() <= 8.0 * f64::EPSILON * 3.0,
                "{what} |AP| at {k}"
            );
            assert!(
                (dist(*p, b) - 1.2).abs() <= 8.0 * f64::EPSILON * 3.0,
                "{what} |BP| at {k}"
            );
        }
        assert!((lit.B.x - par.B.x).abs() <= 8.0 * f64::EPSILON * 3.0);
        assert!((dist(lit.B, Point2::new(want_o4, 0.0)) - 1.778).abs() <= 8.0 * f64::EPSILON * 3.0);
        // f32: the kernels of the scalar type; a few f32 roundings.
        let p32 = TriangleParams::<f32>::default()
            .position(&TriangleParamsInput {
                theta: theta as f32,
            })
            .unwrap();
        let tol = 16.0 * f32::EPSILON as f64 * 3.0;
        assert!(
            (dist(widen(p32.P), widen(p32.A)) - 1.8).abs() <= tol,
            "f32 |AP| at {k}"
        );
        assert!(
            (dist(widen(p32.P), widen(p32.B)) - 1.2).abs() <= tol,
            "f32 |BP| at {k}"
        );
    }
}

#[test]
fn a_negative_root_of_parameters_is_a_typed_error() {
    // Proves a parameter that makes the triangle impossible (|AP| + |BP| <
    // |AB|: the root's argument is negative) gives a typed error naming
    // the link point, not NaN in an `Ok`.
    let m = TriangleParams::<f64> {
        ap: 0.5,
        bp: 0.5,
        ..Default::default()
    };
    let err = m.position(&TriangleParamsInput { theta: 0.3 }).unwrap_err();
    assert!(
        matches!(err.fault, mechanism::Fault::NonFinite { .. }),
        "{err}"
    );
}
