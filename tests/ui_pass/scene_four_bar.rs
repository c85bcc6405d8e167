//! The definition of `FourBar` in `examples/common/scenes.rs` (copied): it
//! passes the expansion-time checks and its generated code compiles.
use mechanism::mechanism;

mechanism! {
    /// Crank-rocker four-bar of seed 002 (mm). Ground O2-O4 = 304.8, crank
    /// O2-A = 101.6, coupler A-B = 254.0, rocker O4-B = 177.8; the document's
    /// branch has B above the line A-O4 (`left`).
    #[self_test]
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
    }
}

fn main() {
    let report = FourBar::<f64>::default().check();
    assert!(report.assembles());
}
