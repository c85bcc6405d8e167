//! The reference solver against answers known exactly and against its own
//! positions differentiated numerically (in double-double, so the finite
//! differences are accurate enough to check the rate equations tightly).

use mechanism_reference::constraint::{Constraint, Linkage, Point, Side, V2};
use mechanism_reference::loop_closure::{acceleration, position, velocity, ReferenceError};
use mechanism_reference::Dd;

/// A four-bar: O2 = (0, 0), O4 = (d, 0), crank a, coupler b, rocker c, B left
/// of A -> O4.
fn fourbar(a: f64, b: f64, c: f64, d: f64) -> Linkage {
    Linkage {
        points: vec![
            Point::Fixed(V2::new(0.0, 0.0)),
            Point::Fixed(V2::new(d, 0.0)),
            Point::Unknown,
            Point::Unknown,
        ],
        constraints: vec![
            Constraint::Crank {
                p: 2,
                o: 0,
                r: a,
                input: 0,
            },
            Constraint::Distance { p: 3, q: 2, len: b },
            Constraint::Distance { p: 3, q: 1, len: c },
        ],
        sides: vec![Side::Left {
            p: 3,
            a: 2,
            b: 1,
            sign: 1.0,
        }],
        scale: d,
    }
}

#[test]
fn three_four_five_triangle_from_a_rough_guess() {
    // Crank of length 5 at angle 0 puts A at (5, 0); the coupler (3) from A
    // and the rocker (4) from O4 = (10, 0)... use A = (5, 0), O4 = (10, 0):
    // |C - A| = 3, |C - O4| = 4 with |A - O4| = 5: C = A + (1.8, 2.4) on the
    // left of A -> O4. Exact in binary? 1.8 and 2.4 are not, so compare to
    // 1e-30 (double-double rounding of the decimal).
    let l = fourbar(5.0, 3.0, 4.0, 10.0);
    let start = [(0.0, 0.0), (10.0, 0.0), (4.0, 1.0), (6.0, 3.0)];
    let pose = position(&l, &[Dd::ZERO], &start).expect("converges");
    let c = pose.points[3];
    let ex = Dd::from_f64(68.0) / Dd::from_f64(10.0); // 6.8
    let ey = Dd::from_f64(24.0) / Dd::from_f64(10.0); // 2.4
                                                      // 1e-29 of the length scale: a few double-double rounding units.
    assert!((c.x - ex).abs().to_f64() < 1e-29, "{}", c.x);
    assert!((c.y - ey).abs().to_f64() < 1e-29, "{}", c.y);
}

#[test]
fn wrong_branch_and_unreachable_are_errors() {
    let l = fourbar(5.0, 3.0, 4.0, 10.0);
    // Starting below the line converges to the mirror image: wrong branch.
    let start = [(0.0, 0.0), (10.0, 0.0), (4.0, 1.0), (6.8, -2.4)];
    assert_eq!(
        position(&l, &[Dd::ZERO], &start),
        Err(ReferenceError::WrongBranch { index: 0 })
    );
    // A coupler too short to reach: Newton cannot converge.
    let l = fourbar(5.0, 0.5, 0.5, 10.0);
    let r = position(
        &l,
        &[Dd::ZERO],
        &[(0.0, 0.0), (10.0, 0.0), (5.0, 0.0), (7.0, 0.3)],
    );
    assert!(
        matches!(
            r,
            Err(ReferenceError::NotConverged { .. }) | Err(ReferenceError::Singular(_))
        ),
        "{r:?}"
    );
}

#[test]
fn rates_are_the_derivatives_of_the_positions() {
    let l = fourbar(101.6, 254.0, 177.8, 304.8);
    let (w, al) = (Dd::from_f64(3.0), Dd::from_f64(-7.0));
    let h = Dd::from_f64(1e-9);
    let start = [(0.0, 0.0), (304.8, 0.0), (50.0, 90.0), (250.0, 180.0)];
    for k in 0..12 {
        let t0 = Dd::from_f64(0.1 + 0.5 * k as f64);
        // Motion theta(t) = t0 + w t + al t^2 / 2 around t = 0.
        let at = |t: Dd| {
            let theta = t0 + w * t + al * t * t * Dd::from_f64(0.5);
            position(&l, &[theta], &start).expect("converges").points[3]
        };
        let pose = position(&l, &[t0], &start).expect("converges");
        let v = velocity(&l, &pose, &[t0], &[w]).expect("regular");
        let a = acceleration(&l, &pose, &v, &[t0], &[w], &[al]).expect("regular");
        let (p_plus, p_minus, p0) = (at(h), at(-h), pose.points[3]);
        let two_h = h + h;
        let fd_v = (p_plus.x - p_minus.x) / two_h;
        let fd_a = (p_plus.x - p0.x - p0.x + p_minus.x) / (h * h);
        // Central differences: truncation error h^2 |x'''| / 6 ~ 1e-18 * 1e4
        // for velocities; for accelerations the rounding of 1e-30 / h^2 =
        // 1e-12 dominates. Both far below what an f64 answer gets wrong.
        let ev = (fd_v - v[3].x).abs().to_f64() / v[3].x.abs().to_f64().max(1.0);
        let ea = (fd_a - a[3].x).abs().to_f64() / a[3].x.abs().to_f64().max(1.0);
        assert!(ev < 1e-14, "velocity at {}: {ev:e}", t0);
        assert!(ea < 1e-9, "acceleration at {}: {ea:e}", t0);
    }
}
