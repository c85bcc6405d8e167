//! Definitions shared by `tests/surface/dsl.rs` (values checked against
//! constraints, literal twins, finite differences and power balances) and
//! `tests/batch/surface.rs` (`solve_batch` against the scalar path): unusual
//! corners of the definition language (DSL words and unicode as names,
//! statements out of order, params and expressions everywhere, output subsets,
//! guides on blocks and carried guides, two inputs, forces only).
#![allow(dead_code, non_snake_case)]

use mechanism::mechanism;

mechanism! {
    pub KwNames {
        let ground = ground(0.0, 0.0);
        let guide = ground(3.0, 0.0);
        let crank = crank(ground, 1.0, analysis) as mass;
        let point = rrr(crank, 3.0, guide, 2.5, left) as (range, outputs);
    }
}

mechanism! {
    pub Unicode {
        params { länge = 1.0 }
        let Ö = ground(0.0, 0.0);
        let Ω = ground(3.0, 0.0);
        let a = crank(Ö, länge, θ) as kurbel;
        let A = rrr(a, 3.0, Ω, 2.5, left) as (koppel, schwinge);
        let a_very_long_name_for_a_coupler_point_that_goes_on_and_on_and_on = point(koppel, from A, 1.0, 0.5 rad);
    }
}

mechanism! {
    pub OutOfOrder {
        params { crank = 1.0, offset = 0.2, gangle = 10.0 }
        const rod = 4.0;
        let B = rrp(A, 2.0 * crank + rod - 2.0, line, minus, -offset) as (link3, block) slide x;
        let P = point(block, from B, (0.1, -(offset)));
        let Q = point(link3, from B, 0.5, -gangle deg);
        let A = crank(O, crank, theta) as link2;
        let line = guide((0.5, -offset), gangle deg);
        let O = ground(0.0, 0.0);
        outputs { P, Q, x }
    }
}

mechanism! {
    pub SlideOnly {
        analysis position;
        outputs { x }
        let O = ground(0.0, 0.0);
        let line = guide(O, 0 deg);
        let A = crank(O, 0.1, theta) as link2;
        let B = rrp(A, 0.4, line, plus) as (link3, slider) slide x;
    }
}

mechanism! {
    pub AngleOnly {
        analysis velocity;
        outputs { link4 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.0, 0.0);
        let A = crank(O2, 1.0, theta) as link2;
        let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
    }
}

mechanism! {
    pub GroundOnly {
        analysis velocity;
        outputs { O4 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.0, 0.0);
        let A = crank(O2, 1.0, theta) as link2;
        let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);
    }
}

mechanism! {
    pub BlockGuide {
        params { tilt = 0.3 }
        let O = ground(0.0, 0.0);
        let line = guide(O, 0 deg);
        let A = crank(O, 0.1, theta) as link2;
        let B = rrp(A, 0.4, line, plus) as (link3, slider) slide x;
        let carried = guide(B, slider, tilt rad);
        let O3 = ground(0.2, 0.5);
        let C = rrp(O3, 0.6, carried, plus) as (link5, block6) slide y;
        let D = point(link3, from B, 0.1, 0.0);
        let E = point(link5, from C, (0.05, 0.02));
        let F = rrr(D, 0.5, E, 0.5, left) as (link7, link8);
        let ignored = ground(1.0, 1.0);
    }
}

mechanism! {
    #[self_test]
    pub TwoCranks {
        params { base = 0.08, arm = 0.1 }
        dof 2;
        let O1 = ground(0.0, 0.0);
        let O2 = ground(base, 0.0);
        let A = crank(O1, arm, q1 as cos_sin) as arm1;
        let C = crank(O2, arm, q2) as arm2;
        let P = rrr(A, 0.16, C, 0.16, left) as (fore1, fore2);
        let Tp = point(fore1, from P, 0.05, 0.0);
        range q1 = (60 deg, 150 deg);
        range q2 = (0 deg, 90 deg);
    }
}

mechanism! {
    #[self_test]
    pub SliderParamAngle {
        params { slope = 30.0, off = -0.02 }
        let O = ground(0.0, 0.0);
        let line = guide((0.5, 0.1), slope deg);
        let P = slider(line, s, off) as block;
        let C = rrr(P, 0.6, O, 0.5, right) as (link1, link2);
        let D = point(block, from P, (0.0, 0.1));
        range s = (-0.2, 0.1);
    }
}

mechanism! {
    #[self_test]
    pub ActuatorParams {
        params { boom = 1.2, bx = 0.8 }
        let A = ground(0.0, 0.0);
        let B = ground(bx, -0.2);
        let C = actuator(A, boom, B, len, left) as (boomlink, cylinder);
        let tip = point(boomlink, from C, 1.3, 10 deg);
        range len = (0.9, 1.5);
    }
}

mechanism! {
    #[self_test]
    pub LoadedPress {
        params { crank = 0.1, g = 9.81, m3 = 2.0 }
        loads { press = 0.0, t = 0.0 }
        let O = ground(0.0, 0.0);
        let line = guide((0.0, 0.0), 0 deg);
        let A = crank(O, crank, theta) as link2;
        let B = rrp(A, 0.4, line, plus) as (link3, ram) slide x;
        let G3 = point(link3, from A, 0.2, 0 deg);
        mass link3 { m = m3, at = G3 };
        mass ram { m = 5.0, at = B };
        mass link2 { m = 0.5, at = A, j = 0.001 };
        gravity (0.0, -g);
        force at B on ram = (-press, 0.5 * press);
        force at A on link3 = (t, 0.0);
        torque on link3 = t * 0.1 - press * 0.001;
    }
}

mechanism! {
    pub ParamGroups {
        params { off = -0.01, o1 = 0.02, o2 = -0.03, slot = -90.0, ay = 0.05, gx = 0.3 }
        const c2 = 2.0;
        const c4 = c2 * 2.0;
        let O = ground(0.0, 0.0);
        let C = ground(0.0, -0.275);
        let A = crank(O, 0.125, phi) as link2;
        let s = rpr(A, C, plus, off) as (block, link3);
        let D = point(link3, from C, 0.6 / c2 * c4 / 4.0 + 0.3, 0 deg);
        let vertical = guide((gx, ay), 90 deg);
        let rod = guide(O, link2);
        let E = prp(rod, vertical, o1, o2) as (b1, b2) slide (s1, s2);
        let horizontal = guide((0.0, -ay), 0.0);
        let Q = rpp(D, horizontal, slot deg, off) as (b5, yoke) slide (t1, t2);
        range phi = (-60 deg, 60 deg);
    }
}

mechanism! {
    pub SliderCrankDof2 {
        dof 2;
        let O = ground(0.0, 0.0);
        let line = guide((0.0, -0.3), 0 deg);
        let P = slider(line, s) as block;
        let A = crank(O, 0.1, theta) as link2;
        let B = rrr(A, 0.4, P, 0.35, left) as (link3, link4);
        mass link3 { m = 1.0, at = B };
        torque on link4 = 0.5;
        range s = (-0.1, 0.1);
        range theta = (0 deg, 360 deg);
    }
}

mechanism! {
    pub Underscore {
        let O = ground(0.0, 0.0);
        let _B = ground(3.0, 0.0);
        let A = crank(O, 1.0, theta) as link2;
        let _scalar = rrr(A, 3.0, _B, 2.5, left) as (link3, link4);
    }
}

mechanism! {
    /// Only the force analysis' results (the drive torque and reactions of a
    /// loaded slider-crank): no point, angle or slide is returned.
    pub TorqueOnly {
        outputs { }
        let O = ground(0.0, 0.0);
        let line = guide(O, 0 deg);
        let A = crank(O, 0.1, theta) as link2;
        let B = rrp(A, 0.4, line, plus) as (link3, slider) slide x;
        let G3 = point(link3, from A, 0.2, 0 deg);
        mass link3 { m = 1.2, at = G3, j = 0.02 };
        mass slider { m = 0.5, at = B };
        gravity (0.0, -9.81);
        force at B on slider along line = -40.0;
    }
}

mechanism! {
    #[self_test]
    pub SliderOnCarried {
        dof 2;
        let O = ground(0.0, 0.0);
        let A = crank(O, 0.1, theta) as link2;
        let g = guide(O, link2, 20 deg);
        let P = slider(g, s, 0.01) as block;
        let Q = point(block, from P, (0.02, 0.03));
        range s = (0.0, 0.2);
        range theta = (0 deg, 360 deg);
    }
}
