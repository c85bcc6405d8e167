//! The definition of `SineMechanism` in `examples/common/scenes.rs` (copied): it
//! passes the expansion-time checks and its generated code compiles.
use mechanism::mechanism;

mechanism! {
    /// Sine mechanism of seed 000, problem 4-23 (m, kg, N): crank AB = 0.1
    /// about A = (0, 0); block 2 pinned at B slides in the horizontal slot of
    /// link 3, which slides vertically in the frame along x = 0. Masses
    /// m2 = G2 / g and m3 = G3 / g at B and on x = 0 (the document's weights
    /// G2 = 40 N, G3 = 100 N with g = 10); no weight loads, as in the document;
    /// the resistance Fr = 400 N acts downward on link 3 along x = 0.
    #[self_test]
    pub SineMechanism {
        params { crank = 0.1, m2 = 4.0, m3 = 10.0, fr = 400.0 }
        dof 1;
        let A = ground(0.0, 0.0);
        let frame = guide((0.0, 0.0), 90 deg);
        let B = crank(A, crank, phi1) as link1;
        let Q = rpp(B, frame, -90 deg) as (block2, link3) slide (s_slot, s_yoke);
        mass block2 { m = m2, at = B };
        mass link3 { m = m3, at = Q };
        force at Q = (0.0, -fr);
    }
}

fn main() {
    let report = SineMechanism::<f64>::default().check();
    assert!(report.assembles());
}
