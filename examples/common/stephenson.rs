//! The Stephenson III six-bar of issue 22 (m, kg): a triad (class III
//! group) driven by link 6's angle. Shared by `examples/stephenson.rs` and
//! its tests (`tests/examples/stephenson.rs`).
#![allow(dead_code)]

use mechanism::mechanism;

mechanism! {
    /// Stephenson III six-bar (m): ground pivots O2 = (0, 0), O4 = (0.30, 0),
    /// O6 = (0.05, 0.42); link 6 (O6-C, 0.24) is driven by its angle `phi`
    /// (rad, counter-clockwise from +x). The triad: crank2 O2-A (0.08),
    /// rocker O4-B (0.20), link5 C-P (0.28) on the ternary coupler A-B
    /// (0.26) with P at 0.15 from A, 40 deg counter-clockwise from A -> B;
    /// its assembly is the one with, at phi = -49.48 deg, A near
    /// (-0.061, -0.052), B near (0.137, 0.116), P near (-0.036, 0.096).
    /// Link 6 swings between about -50.4365 deg and -2.6334 deg on it.
    #[self_test]
    pub Stephenson {
        params { m2 = 0.4, j2 = 2.2e-4, m3 = 1.2, j3 = 7.5e-3, m4 = 0.8, j4 = 2.7e-3,
                 m5 = 1.0, j5 = 6.5e-3, m6 = 0.9, j6 = 4.3e-3 }
        loads { fp = 0.0 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.30, 0.0);
        let O6 = ground(0.05, 0.42);
        let C = crank(O6, 0.24, phi) as link6;
        let (A, B, P) = triad(O2, 0.08, O4, 0.20, C, 0.28, 0.26, 0.15, 40 deg,
                              phi = -49.48 deg, (-0.061, -0.052), (0.137, 0.116), (-0.036, 0.096))
            as (crank2, rocker, link5, coupler);
        let G2 = point(crank2, from O2, 0.04, 0 deg);
        let G3 = point(coupler, from A, (0.13, 0.03));
        let G4 = point(rocker, from O4, 0.10, 0 deg);
        let G5 = point(link5, from C, 0.14, 0 deg);
        let G6 = point(link6, from O6, 0.12, 0 deg);
        mass crank2 { m = m2, at = G2, j = j2 };
        mass coupler { m = m3, at = G3, j = j3 };
        mass rocker { m = m4, at = G4, j = j4 };
        mass link5 { m = m5, at = G5, j = j5 };
        mass link6 { m = m6, at = G6, j = j6 };
        gravity (0.0, -9.81);
        force at P on coupler = (0.0, fp);
        range phi = (-50.43 deg, -2.64 deg);
        outputs { A, B, P, C, crank2, coupler, rocker, link5, link6 }
    }
}
