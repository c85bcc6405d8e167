//! The definition of `SixBar` in `examples/common/scenes.rs` (copied): it
//! passes the expansion-time checks and its generated code compiles.
use mechanism::mechanism;

mechanism! {
    /// Six-bar of seed 000, problem 3-28 (mm): the crank turns about A; B is on
    /// the crank opposite its slide line; the block F slides along the crank's
    /// line and is pinned to the rocker E-F (60) whose other arm E-D is 35; the
    /// RRR group B-C-D (50, 75) closes the loop.
    #[self_test]
    pub SixBar {
        dof 1;
        let A = ground(0.0, 0.0);
        let E = ground(70.0, 0.0);
        let K = crank(A, 40.0, phi1) as link1;
        let B = point(link1, from A, 40.0, 180 deg);
        let crank_line = guide(A, link1);
        let F = rrp(E, 60.0, crank_line, plus) as (link4, block5) slide af;
        let D = point(link4, from E, 35.0, 180 deg);
        let C = rrr(B, 50.0, D, 75.0, left) as (link2, link3);
        // F assembles only while the crank line passes within 60 of E
        // (|sin phi1| <= 6/7): the document's 40..55 deg.
        range phi1 = (40 deg, 55 deg);
        outputs { C, F, link2, link3, link4, af }
    }
}

fn main() {
    let report = SixBar::<f64>::default().check();
    assert!(report.assembles());
}
