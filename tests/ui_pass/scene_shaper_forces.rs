//! The definition of `ShaperForces` in `examples/common/scenes.rs` (copied): it
//! passes the expansion-time checks and its generated code compiles.
use mechanism::mechanism;

mechanism! {
    /// The shaper of seed 001 with masses (m, kg, N): rocker 20 kg at its
    /// midpoint S3 (J = m L^2 / 12 = 0.6 kg m^2), connecting rod 3 kg at its
    /// midpoint S4 (J = 0.005625 kg m^2), ram 60 kg at E; crank and block
    /// massless; gravity 9.81 m/s^2 down. The cutting force on the ram is a
    /// per-evaluation load `cut` (N, along the ram guide's direction, which
    /// points to -x), so the caller applies it on the working stroke only.
    #[self_test]
    pub ShaperForces {
        params { m3 = 20.0, j3 = 0.6, m4 = 3.0, j4 = 0.005625, m5 = 60.0 }
        loads { cut = 0.0 }
        dof 1;
        let A = ground(0.0, 0.0);
        let C = ground(0.0, -0.275);
        let ram = guide((0.0, 0.3), 180 deg);
        let B = crank(A, 0.125, crank) as link2;
        let cb = rpr(B, C, plus) as (block, link3);
        let D = point(link3, from C, 0.6, 0 deg);
        let S3 = point(link3, from C, 0.3, 0 deg);
        let E = rrp(D, 0.15, ram, plus) as (link4, ram_block) slide s_ram;
        let S4 = point(link4, from D, 0.075, 0 deg);
        mass link3 { m = m3, at = S3, j = j3 };
        mass link4 { m = m4, at = S4, j = j4 };
        mass ram_block { m = m5, at = E };
        gravity (0.0, -9.81);
        force at E on ram_block along ram = cut;
        outputs { D, E, S3, S4, link3, link4, s_ram }
    }
}

fn main() {
    let report = ShaperForces::<f64>::default().check();
    assert!(report.assembles());
}
