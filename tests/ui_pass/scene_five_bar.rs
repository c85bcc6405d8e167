//! The definition of `FiveBar` in `examples/common/scenes.rs` (copied): it
//! passes the expansion-time checks and its generated code compiles.
use mechanism::mechanism;

mechanism! {
    /// Two-input five-bar robot (m): cranks of 0.1 about O1 = (0, 0) and
    /// O2 = (0.08, 0), distal links of 0.16 meeting at the end point P above
    /// the base (`left` of the directed line A -> C).
    #[self_test]
    pub FiveBar {
        params { base = 0.08, proximal = 0.1, distal = 0.16 }
        dof 2;
        let O1 = ground(0.0, 0.0);
        let O2 = ground(base, 0.0);
        let A = crank(O1, proximal, q1) as arm1;
        let C = crank(O2, proximal, q2) as arm2;
        let P = rrr(A, distal, C, distal, left) as (forearm1, forearm2);
        range q1 = (60 deg, 150 deg);
        range q2 = (0 deg, 90 deg);
        outputs { P }
    }
}

fn main() {
    let report = FiveBar::<f64>::default().check();
    assert!(report.assembles());
}
