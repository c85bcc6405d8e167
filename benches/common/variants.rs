//! Variants of the example scenes used by the benchmarks and the report.
#![allow(dead_code)]

use mechanism::mechanism;

mechanism! {
    /// The four-bar of `scenes::FourBar` without angle outputs: only the
    /// coupler joint `B` (position, velocity, acceleration), so no `atan2`.
    pub FourBarPoints {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        outputs { B }
    }
}
