//! Definitions with `analysis dynamics`, one per kind of drive and group:
//! a four-bar with a load, a slider-crank with a mass on the slider, the
//! Stephenson III six-bar (a triad), a 2R leg (a motor carried by a moving
//! link), an actuator with masses, the five-bar given its end point, the
//! five-bar given its motors.
#![allow(dead_code, non_snake_case)]

use mechanism::mechanism;

mechanism! {
    /// The `run_up` four-bar (m, kg), with an external couple on the rocker.
    pub FourBar {
        analysis dynamics;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.30, 0.0);
        let A = crank(O2, 0.10, phi) as crank;
        let B = rrr(A, 0.25, O4, 0.18, left) as (coupler, rocker);
        let G2 = point(crank, from O2, 0.05, 0 deg);
        let G3 = point(coupler, from A, 0.125, 0 deg);
        let G4 = point(rocker, from O4, 0.09, 0 deg);
        mass crank { m = 0.5, at = G2, j = 4.0e-4 };
        mass crank { m = 2.0, at = O2, j = 0.02 };
        mass coupler { m = 1.2, at = G3, j = 6.5e-3 };
        mass rocker { m = 0.9, at = G4, j = 2.5e-3 };
        gravity (0.0, -9.81);
        torque on rocker = -0.3;
        force at G3 on coupler = (2.0, 1.0);
    }
}

mechanism! {
    /// A slider-crank (m, kg) with a mass on the slider and a press load.
    pub SliderCrank {
        analysis dynamics;
        loads { press = 0.0 }
        let O = ground(0.0, 0.0);
        let line = guide(O, 0 deg);
        let A = crank(O, 0.05, theta) as crank;
        let B = rrp(A, 0.2, line, plus) as (rod, ram) slide x;
        let G2 = point(crank, from O, 0.02, 0 deg);
        let G3 = point(rod, from A, 0.06, 0 deg);
        mass crank { m = 0.8, at = G2, j = 1.0e-3 };
        mass rod { m = 0.6, at = G3, j = 2.5e-3 };
        mass ram { m = 1.5, at = B };
        gravity (0.0, -9.81);
        force at B on ram = (-press, 0.0);
    }
}

mechanism! {
    /// The Stephenson III six-bar of `examples/common/stephenson.rs` (m, kg).
    pub Stephenson {
        analysis dynamics;
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
        mass crank2 { m = 0.4, at = G2, j = 2.2e-4 };
        mass coupler { m = 1.2, at = G3, j = 7.5e-3 };
        mass rocker { m = 0.8, at = G4, j = 2.7e-3 };
        mass link5 { m = 1.0, at = G5, j = 6.5e-3 };
        mass link6 { m = 0.9, at = G6, j = 4.3e-3 };
        gravity (0.0, -9.81);
        range phi = (-50.43 deg, -2.64 deg);
    }
}

mechanism! {
    /// A 2R leg (m, kg): hip motor on the ground, knee motor carried by the
    /// thigh, a foot mass.
    pub Leg {
        analysis dynamics;
        dof 2;
        let H = ground(0.0, 0.0);
        let K = crank(H, 0.40, hip) as thigh;
        let F = crank(K, 0.38, knee, thigh) as shank;
        let Gt = point(thigh, from H, 0.18, 0 deg);
        let Gs = point(shank, from K, 0.16, 0 deg);
        mass thigh { m = 2.0, at = Gt, j = 0.03 };
        mass shank { m = 1.2, at = Gs, j = 0.015 };
        mass shank { m = 0.3, at = F };
        gravity (0.0, -9.81);
    }
}

mechanism! {
    /// The excavator boom of `tests/surface/drawn.rs` (m, kg): an actuator
    /// whose barrel and rod carry masses.
    pub Boom {
        analysis dynamics;
        dof 1;
        let A = ground(0.0, 0.0);
        let B = ground(0.8, -0.9);
        let C = actuator(A, 2.2, B, len, left) as (boom, barrel, rod);
        let Gb = point(boom, from A, 2.5, 8 deg);
        let Tip = point(boom, from A, 5.0, 0 deg);
        let G1 = point(barrel, from B, 0.6, 0 deg);
        let G2 = point(rod, from C, 0.5, 180 deg);
        mass boom { m = 1800.0, at = Gb, j = 4500.0 };
        mass boom { m = 600.0, at = Tip };
        mass barrel { m = 220.0, at = G1, j = 30.0 };
        mass rod { m = 140.0, at = G2, j = 18.0 };
        gravity (0.0, -9.81);
        range len = (1.9, 3.0);
    }
}

mechanism! {
    /// The five-bar robot given its end point (m, kg): inputs `x`, `y`.
    pub FiveBarIk {
        analysis dynamics;
        dof 2;
        let O1 = ground(0.0, 0.0);
        let O2 = ground(0.08, 0.0);
        let P = target(x, y) as effector;
        let A = rrr(O1, 0.1, P, 0.16, left) as (arm1, forearm1);
        let C = rrr(O2, 0.1, P, 0.16, right) as (arm2, forearm2);
        let G1 = point(arm1, from O1, 0.05, 0 deg);
        let G2 = point(arm2, from O2, 0.05, 0 deg);
        let H1 = point(forearm1, from P, 0.08, 0 deg);
        let H2 = point(forearm2, from P, 0.08, 0 deg);
        mass arm1 { m = 0.12, at = G1, j = 1.1e-4 };
        mass arm2 { m = 0.12, at = G2, j = 1.1e-4 };
        mass forearm1 { m = 0.09, at = H1, j = 2.0e-4 };
        mass forearm2 { m = 0.09, at = H2, j = 2.0e-4 };
        mass effector { m = 0.05, at = P };
        gravity (0.0, -9.81);
        force at P on effector = (1.5, -4.0);
        range x = (0.0, 0.08);
        range y = (0.16, 0.22);
    }
}

mechanism! {
    /// The same five-bar driven by its motors (m, kg).
    pub FiveBarFk {
        analysis dynamics;
        dof 2;
        let O1 = ground(0.0, 0.0);
        let O2 = ground(0.08, 0.0);
        let A = crank(O1, 0.1, q1) as arm1;
        let C = crank(O2, 0.1, q2) as arm2;
        let P = rrr(A, 0.16, C, 0.16, left) as (forearm1, forearm2);
        let G1 = point(arm1, from O1, 0.05, 0 deg);
        let G2 = point(arm2, from O2, 0.05, 0 deg);
        let H1 = point(forearm1, from A, 0.08, 0 deg);
        let H2 = point(forearm2, from C, 0.08, 0 deg);
        mass arm1 { m = 0.12, at = G1, j = 1.1e-4 };
        mass arm2 { m = 0.12, at = G2, j = 1.1e-4 };
        mass forearm1 { m = 0.09, at = H1, j = 2.0e-4 };
        mass forearm1 { m = 0.05, at = P };
        mass forearm2 { m = 0.09, at = H2, j = 2.0e-4 };
        gravity (0.0, -9.81);
    }
}
