//! The drawn form (joints at a reference pose, links as joint sets, inputs):
//! each drawn definition here against the same mechanism written with group
//! statements, its lengths and offsets computed from the same coordinates in
//! the test, over the input range.

use mechanism::mechanism;

mechanism! {
    /// A crank-rocker four-bar with a coupler point, as drawn.
    pub DrawnFourBar {
        joints {
            O2 = (0.0, 0.0),
            O4 = (4.0, 0.0),
            A = (0.5, 0.8660254037844386),
            B = (3.2, 2.1),
            P = (2.0, 2.9),
        }
        links {
            ground = [O2, O4],
            crank = [O2, A],
            coupler = [A, B, P],
            rocker = [O4, B],
        }
        input theta = angle(crank);
    }
}

mechanism! {
    /// The same four-bar written as groups.
    pub GroupedFourBar {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(4.0, 0.0);
        let A = crank(O2, hypot(0.5, 0.8660254037844386), theta) as crank;
        const ux = 3.2 - 0.5;
        const uy = 2.1 - 0.8660254037844386;
        const dx = 2.0 - 0.5;
        const dy = 2.9 - 0.8660254037844386;
        let B = rrr(A, hypot(ux, uy), O4, hypot(3.2 - 4.0, 2.1), left) as (coupler, rocker);
        let P = point(coupler, from A, ((dx * ux + dy * uy) / hypot(ux, uy), (ux * dy - uy * dx) / hypot(ux, uy)));
    }
}

#[test]
fn a_drawn_four_bar_is_the_grouped_one() {
    // Proves: the drawn four-bar decomposes into the crank and RRR a user
    // would write, with the lengths and the assembly of the drawing: both
    // forms give the same joints over a full turn.
    let (d, g) = (DrawnFourBar::<f64>::default(), GroupedFourBar::<f64>::default());
    for k in 0..360 {
        let theta = (k as f64).to_radians();
        let pd = d.position(&DrawnFourBarInput { theta }).unwrap();
        let pg = g.position(&GroupedFourBarInput { theta }).unwrap();
        assert!((pd.B - pg.B).norm() <= 4.0 * f64::EPSILON * 4.0, "{k}: {} {}", pd.B, pg.B);
        assert!((pd.A - pg.A).norm() <= 4.0 * f64::EPSILON, "{k}");
        assert!((pd.P - pg.P).norm() <= 16.0 * f64::EPSILON, "{k}: {} {}", pd.P, pg.P);
    }
    // At the drawn input the joints are where they are drawn.
    let at = d
        .position(&DrawnFourBarInput {
            theta: 60f64.to_radians(),
        })
        .unwrap();
    assert!((at.B - mechanism::Point2::new(3.2, 2.1)).norm() < 1e-14, "{}", at.B);
    assert!((at.P - mechanism::Point2::new(2.0, 2.9)).norm() < 1e-14, "{}", at.P);
}
