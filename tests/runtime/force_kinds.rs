//! Definitions with masses whose force analysis runs through the kinds the
//! examples' scenes leave out: a slider driver, a PRP on a carried guide, a
//! two-name actuator and a cylinder whose barrel and rod carry masses.
//! `forces` reads their text from this file and compares them.

use mechanism::mechanism;

mechanism! {
    /// A block slid along a ground line drives a rocker through a rod;
    /// gravity, a couple on the rocker.
    pub SliderRocker {
        let O = ground(0.0, 0.0);
        let O4 = ground(0.5, 0.4);
        let line = guide(O, 0 deg);
        let P = slider(line, s) as block;
        let B = rrr(P, 0.5, O4, 0.3, left) as (rod, rocker);
        let G = point(rod, from P, 0.25, 0 deg);
        mass block { m = 2.0, at = P };
        mass rod { m = 1.0, at = G, j = 0.02 };
        mass rocker { m = 0.5, at = B, j = 0.01 };
        gravity (0.0, -9.81);
        torque on rocker = 3.0;
        range s = (0.0, 0.6);
    }
}

mechanism! {
    /// A PRP: a block on a line carried by the crank at 30 deg to it, a
    /// block on a fixed vertical guide (parallel guides only outside the
    /// range).
    pub CrossForces {
        let O = ground(0.0, 0.0);
        let V = ground(0.3, 0.0);
        let vertical = guide(V, 90 deg);
        let A = crank(O, 0.1, theta) as crank_link;
        let rod_line = guide(O, crank_link, 30 deg);
        let C = prp(rod_line, vertical) as (b1, b2) slide (s1, s2);
        mass b1 { m = 0.3, at = C };
        mass b2 { m = 0.4, at = C };
        mass crank_link { m = 1.0, at = A, j = 0.001 };
        gravity (0.0, -9.81);
        range theta = (-20 deg, 40 deg);
    }
}

mechanism! {
    /// A boom lifted by a massless two-name actuator, an RRR hanging from
    /// the boom with a mass.
    pub ArmForces {
        let A = ground(0.0, 0.0);
        let B = ground(0.6, -0.3);
        let O6 = ground(1.2, 0.2);
        let C = actuator(A, 1.0, B, len, left) as (boom, cyl);
        let N = point(boom, from A, 0.5, 0 deg);
        let K = rrr(N, 0.8, O6, 0.7, right) as (link5, link6);
        mass link6 { m = 10.0, at = K };
        mass boom { m = 4.0, at = N, j = 0.3 };
        gravity (0.0, -9.81);
        range len = (0.9, 1.3);
    }
}

mechanism! {
    /// A boom lifted by a cylinder whose barrel and rod carry masses.
    pub BoomForces {
        let A = ground(0.0, 0.0);
        let B = ground(0.8, -0.9);
        let C = actuator(A, 2.2, B, len, left) as (boom, barrel, rod);
        let G1 = point(barrel, from B, 0.6, 0 deg);
        let G2 = point(rod, from C, 0.5, 180 deg);
        mass boom { m = 500.0, at = C, j = 200.0 };
        mass barrel { m = 220.0, at = G1, j = 10.0 };
        mass rod { m = 80.0, at = G2, j = 2.0 };
        gravity (0.0, -9.81);
        range len = (1.9, 3.0);
    }
}
