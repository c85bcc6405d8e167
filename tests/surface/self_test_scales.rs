//! `#[self_test]` at scales 1e-9, 1e-3, 1 and 1e9 (the same two mechanisms,
//! every length times the scale): the generated tests (loop closure in f32
//! and f64, velocities and accelerations against finite differences, f32
//! against f64, the check) must pass at every scale, since each tolerance is
//! the rounding of its own quantity: 64 eps for a guide direction (a
//! difference of unit vectors), 64 eps times the size for a length, the size
//! over the shortest link for a direction turned from a link's axis, and for
//! a rate the finite difference's truncation and rounding plus the rate's
//! own rounding. Before, a length tolerance on the fixed guide's direction
//! failed at 1e-3 in f32 and at 1e-9, and the finite differences failed at
//! 1e9 (a rounding term divided by a step of 1e5). `cargo test --test
//! self_test_scales` runs them (the tests are in the generated modules).

use mechanism::mechanism;

mechanism! {
    /// A crank driving an RRP on a guide carried by the crank (30 deg to its
    /// axis) and an RPR, scaled by 1e-9 (lengths in m times 1e-9).
    #[self_test]
    pub CarriedNano {
        const k = 1e-9;
        let O = ground(0.0, 0.0);
        let E = ground(0.25 * k, 0.05 * k);
        let A = crank(O, 0.1 * k, phi) as arm;
        let line = guide(A, arm, 30 deg);
        let F = rrp(E, 0.2 * k, line, minus, 0.01 * k) as (rod, block) slide sf;
        let r = rpr(F, O, plus, 0.01 * k) as (pin, rocker);
        let G = point(rocker, from O, 0.3 * k, 0 deg);
        range phi = (-30 deg, 30 deg);
    }
}

mechanism! {
    /// A slider on a fixed guide at 30 deg (the input, a displacement)
    /// driving an RRR to a ground pivot, scaled by 1e-9.
    #[self_test]
    pub SlideNano {
        const k = 1e-9;
        let line = guide((0.0, 0.0), 30 deg);
        let P = ground(0.0, 1.0 * k);
        let C = slider(line, s) as block;
        let B = rrr(C, 1.2 * k, P, 0.9 * k, left) as (l1, l2);
        range s = (0.5 * k, 1.5 * k);
    }
}

mechanism! {
    /// A crank driving an RRP on a guide carried by the crank (30 deg to its
    /// axis) and an RPR, scaled by 1e-3 (lengths in m times 1e-3).
    #[self_test]
    pub CarriedMilli {
        const k = 1e-3;
        let O = ground(0.0, 0.0);
        let E = ground(0.25 * k, 0.05 * k);
        let A = crank(O, 0.1 * k, phi) as arm;
        let line = guide(A, arm, 30 deg);
        let F = rrp(E, 0.2 * k, line, minus, 0.01 * k) as (rod, block) slide sf;
        let r = rpr(F, O, plus, 0.01 * k) as (pin, rocker);
        let G = point(rocker, from O, 0.3 * k, 0 deg);
        range phi = (-30 deg, 30 deg);
    }
}

mechanism! {
    /// A slider on a fixed guide at 30 deg (the input, a displacement)
    /// driving an RRR to a ground pivot, scaled by 1e-3.
    #[self_test]
    pub SlideMilli {
        const k = 1e-3;
        let line = guide((0.0, 0.0), 30 deg);
        let P = ground(0.0, 1.0 * k);
        let C = slider(line, s) as block;
        let B = rrr(C, 1.2 * k, P, 0.9 * k, left) as (l1, l2);
        range s = (0.5 * k, 1.5 * k);
    }
}

mechanism! {
    /// A crank driving an RRP on a guide carried by the crank (30 deg to its
    /// axis) and an RPR, scaled by 1.0 (lengths in m times 1.0).
    #[self_test]
    pub CarriedUnit {
        const k = 1.0;
        let O = ground(0.0, 0.0);
        let E = ground(0.25 * k, 0.05 * k);
        let A = crank(O, 0.1 * k, phi) as arm;
        let line = guide(A, arm, 30 deg);
        let F = rrp(E, 0.2 * k, line, minus, 0.01 * k) as (rod, block) slide sf;
        let r = rpr(F, O, plus, 0.01 * k) as (pin, rocker);
        let G = point(rocker, from O, 0.3 * k, 0 deg);
        range phi = (-30 deg, 30 deg);
    }
}

mechanism! {
    /// A slider on a fixed guide at 30 deg (the input, a displacement)
    /// driving an RRR to a ground pivot, scaled by 1.0.
    #[self_test]
    pub SlideUnit {
        const k = 1.0;
        let line = guide((0.0, 0.0), 30 deg);
        let P = ground(0.0, 1.0 * k);
        let C = slider(line, s) as block;
        let B = rrr(C, 1.2 * k, P, 0.9 * k, left) as (l1, l2);
        range s = (0.5 * k, 1.5 * k);
    }
}

mechanism! {
    /// A crank driving an RRP on a guide carried by the crank (30 deg to its
    /// axis) and an RPR, scaled by 1e9 (lengths in m times 1e9).
    #[self_test]
    pub CarriedGiga {
        const k = 1e9;
        let O = ground(0.0, 0.0);
        let E = ground(0.25 * k, 0.05 * k);
        let A = crank(O, 0.1 * k, phi) as arm;
        let line = guide(A, arm, 30 deg);
        let F = rrp(E, 0.2 * k, line, minus, 0.01 * k) as (rod, block) slide sf;
        let r = rpr(F, O, plus, 0.01 * k) as (pin, rocker);
        let G = point(rocker, from O, 0.3 * k, 0 deg);
        range phi = (-30 deg, 30 deg);
    }
}

mechanism! {
    /// A slider on a fixed guide at 30 deg (the input, a displacement)
    /// driving an RRR to a ground pivot, scaled by 1e9.
    #[self_test]
    pub SlideGiga {
        const k = 1e9;
        let line = guide((0.0, 0.0), 30 deg);
        let P = ground(0.0, 1.0 * k);
        let C = slider(line, s) as block;
        let B = rrr(C, 1.2 * k, P, 0.9 * k, left) as (l1, l2);
        range s = (0.5 * k, 1.5 * k);
    }
}
