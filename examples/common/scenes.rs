//! The examples' definitions, gathered from `examples/<name>.rs` for what
//! cannot mount an example (the firmware, the no-panic build, the
//! benchmarks, the report and the tests). Generated: do not edit; change the
//! example and run `MECHANISM_BLESS=1 cargo test -p mechanism-dev --test
//! examples scenes_file` (the test fails while this file is out of date).
#![allow(dead_code)]

use mechanism::mechanism;

// examples/fourbar.rs
mechanism! {
    /// Crank-rocker four-bar of seed 002 (mm). Ground O2-O4 = 304.8, crank
    /// O2-A = 101.6, coupler A-B = 254.0, rocker O4-B = 177.8; the document's
    /// branch has B above the line A-O4 (`left`).
    #[self_test]
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        units { length = "mm" }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
    }
}

// examples/sixbar.rs
mechanism! {
    /// Six-bar of seed 000, problem 3-28 (mm): the crank turns about A; B is on
    /// the crank opposite its slide line; the block F slides along the crank's
    /// line and is pinned to the rocker E-F (60) whose other arm E-D is 35; the
    /// RRR group B-C-D (50, 75) closes the loop.
    #[self_test]
    pub SixBar {
        units { length = "mm" }
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
        outputs { C, F, link2, link3, link4, af, A, E, K, B, D, link1 }
    }
}

// examples/shaper.rs
mechanism! {
    /// Quick-return shaper of seed 001 (m): crank AB = 0.125 about A; the block
    /// at B slides on the rocker pivoted at C = (0, -0.275); D on the rocker at
    /// CD = 0.6; the connecting rod DE = 0.15 drives the ram E along y = 0.3
    /// (guide direction 180 deg, as in the document).
    #[self_test]
    pub Shaper {
        units { length = "m" }
        dof 1;
        let A = ground(0.0, 0.0);
        let C = ground(0.0, -0.275);
        let ram = guide((0.0, 0.3), 180 deg);
        let B = crank(A, 0.125, crank) as link2;
        let cb = rpr(B, C, plus) as (block, link3);
        let D = point(link3, from C, 0.6, 0 deg);
        let E = rrp(D, 0.15, ram, plus) as (link4, ram_block) slide s_ram;
        outputs { E, link3, link4, A, C, B, D }
    }
}

// examples/slider_crank.rs
mechanism! {
    /// Offset slider-crank (m): crank 0.1, connecting rod 0.4, slide line at
    /// y = 0.02 along +x.
    #[self_test]
    pub SliderCrank {
        params { crank = 0.1, rod = 0.4, offset = 0.02 }
        units { length = "m" }
        dof 1;
        let O = ground(0.0, 0.0);
        let line = guide((0.0, offset), 0 deg);
        let A = crank(O, crank, theta) as link2;
        let B = rrp(A, rod, line, plus) as (link3, slider) slide x;
        outputs { B, link3, x, O, A }
    }
}

// examples/five_bar.rs
mechanism! {
    /// Two-input five-bar robot (m): cranks of 0.1 about O1 = (0, 0) and
    /// O2 = (0.08, 0), distal links of 0.16 meeting at the end point P above
    /// the base (`left` of the directed line A -> C).
    #[self_test]
    pub FiveBar {
        params { base = 0.08, proximal = 0.1, distal = 0.16 }
        units { length = "m" }
        dof 2;
        let O1 = ground(0.0, 0.0);
        let O2 = ground(base, 0.0);
        let A = crank(O1, proximal, q1) as arm1;
        let C = crank(O2, proximal, q2) as arm2;
        let P = rrr(A, distal, C, distal, left) as (forearm1, forearm2);
        range q1 = (60 deg, 150 deg);
        range q2 = (0 deg, 90 deg);
        outputs { P, O1, O2, A, C }
    }
}

// examples/geared_five_bar.rs
mechanism! {
    /// A geared five-bar (m): the crank `link2` about O2 = (0, 0) and the
    /// gear `link5` about O5 = (0.3, 0) mesh at ratio 2 (external: `link5`
    /// turns at 30 deg - 2 theta, its point C at 0.08 from O5); the RRR
    /// `link3`, `link4` closes the loop at B, left of the directed line
    /// A -> C. It assembles over the whole turn: |AC| stays within 0.12 to
    /// 0.48, inside the 0.06 to 0.58 the dyad reaches.
    #[self_test]
    pub GearedFiveBar {
        units { length = "m" }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O5 = ground(0.3, 0.0);
        let A = crank(O2, 0.1, theta) as link2;
        let C = gear(O5, 0.08, link2, 2.0, 30 deg, ground) as link5;
        let B = rrr(A, 0.32, C, 0.26, left) as (link3, link4);
        outputs { B, link3, link4, link5, A, C, O2, O5 }
    }
}

// examples/sine_mechanism.rs
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
        units { length = "m", force = "N", mass = "kg" }
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

// examples/shaper_forces.rs
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
        units { length = "m", force = "N", mass = "kg" }
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
        outputs { D, E, S3, S4, link3, link4, s_ram, A, C, B }
    }
}

// examples/five_bar_ik.rs
mechanism! {
    /// The five-bar robot of the `five_bar` example given its end point (m, kg, N):
    /// inverse kinematics, written as drawn. The drawing is the robot at
    /// q1 = 100 deg, q2 = 45 deg (coordinates to 20 digits, so the lengths
    /// read from it are 0.1 and 0.16 to the last bit); the end point `P`
    /// is the input, `input x = P.x; input y = P.y;`, and each motor link
    /// hangs on it by an RRR whose elbow is on the side drawn. Masses at
    /// the links' midpoints (`G1`, `G2`, `H1`, `H2`, drawn as points of
    /// their links) and on the effector (`P_effector`, the body moving
    /// with `P`: a pen holder), gravity along -y and a 2 N payload at `P`.
    /// The motors turning `arm1` and `arm2` about the base pivots hold `P`
    /// on its path: their torques are the forces' `drive_q1`, `drive_q2`.
    pub FiveBarIk {
        units { length = "m", force = "N", mass = "kg" }
        joints {
            O1 = (0.0, 0.0),
            O2 = (0.08, 0.0),
            A = (-0.017364817766693034885, 0.098480775301220805937),
            C = (0.15071067811865475244, 0.07071067811865475244),
            P = (0.088752052427120438854, 0.2182272151659171658),
            G1 = (-0.0086824088833465174425, 0.049240387650610402968),
            G2 = (0.11535533905932737622, 0.03535533905932737622),
            H1 = (0.035693617330213701984, 0.15835399523356898587),
            H2 = (0.11973136527288759565, 0.14446894664228595912),
        }
        links {
            ground = [O1, O2],
            arm1 = [O1, A, G1],
            arm2 = [O2, C, G2],
            forearm1 = [A, P, H1],
            forearm2 = [C, P, H2],
        }
        input x = P.x;
        input y = P.y;
        motor q1 = angle(arm1);
        motor q2 = angle(arm2);
        mass arm1 { m = 0.12, at = G1, j = 1.1e-4 };
        mass arm2 { m = 0.12, at = G2, j = 1.1e-4 };
        mass forearm1 { m = 0.09, at = H1, j = 2.0e-4 };
        mass forearm2 { m = 0.09, at = H2, j = 2.0e-4 };
        mass P_effector { m = 0.05, at = P };
        gravity (0.0, -9.81);
        force at P on P_effector = (0.0, -2.0);
    }
}
