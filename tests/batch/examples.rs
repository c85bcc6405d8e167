//! The batch API against the scalar path, element by element, on every
//! example scene (`examples/common/scenes.rs`) and on definitions that use
//! the drivers and groups the scenes do not (slider driver, actuator, PRP, a
//! guide carried at an angle, run-time parameters for directions and
//! offsets), over grids that include failing poses (cannot assemble,
//! singular, non-finite and out-of-range inputs, non-finite rates):
//!
//! 1. every definition has a lane kernel (`__solve_batch_lane_only` returns
//!    `true`), so these are comparisons of the lane primitives with the
//!    scalar ones, not of the scalar path with itself;
//! 2. the kernel accepts only elements the scalar path solves, and nearly all
//!    of them (it hands the scalar path only elements inside the scalar
//!    rounding bands or within twice the singular threshold);
//! 3. `solve_batch` gives every element the scalar path's status (0 ok, 1, 2,
//!    3 the level that failed), the scalar path's values bit for bit on the
//!    levels before a failure and zeros from the failing level on;
//! 4. where the element is ok, the outputs agree with the scalar path's
//!    within the tolerance below.
//!
//! # Tolerance
//!
//! The lane primitives use the scalar primitives' formulas with elementary
//! functions within 1 to 2.5 ulp of libm's (`mechanism::__private::lane`'s tests) and
//! reciprocals where the scalar code divides, so every intermediate value
//! differs from the scalar one by a few ulp of its own magnitude. A group
//! solve amplifies such differences by at most `1 / condition` (the rate
//! system's scaled determinant, the `condition` of the scalar velocity: the
//! same number governs how the position depends on its inputs near the edge
//! of assembly), and a chain of groups (the six-bar, the shaper) compounds
//! them: the shaper's RRP sits on the RPR's output. So the error of an output
//! is measured in `eps` of the size of the terms summed into the outputs of
//! its level (positions, velocities, accelerations: the element's largest
//! output of that level, but at least the median of that over the grid,
//! since near a dead point the outputs are small differences of larger
//! terms), times the element's condition squared (one factor for each of two
//! nested solves), and bounded by `K = 64`: the worst found is 16 (f32, the
//! five-bar near the edge of its workspace) and below 17 everywhere, in f64
//! and in f32, on every grid below (printed with `--nocapture`). A wrong
//! formula gives errors of order `1 / eps`: with the Coriolis term of the
//! RPR's accelerations negated, the shaper fails at its first element.

use mechanism::mechanism;
use std::collections::HashMap;

// `compare!`, `one_input!` (declared in `main.rs`) and their helpers.
use crate::batch_compare::*;

#[path = "../../examples/common/scenes.rs"]
pub(crate) mod scenes;
use scenes::*;

mechanism! {
    /// Grashof-violating four-bar (mm): the coupler cannot reach the rocker
    /// over part of the crank's turn (a run-time parameter, so the macro does
    /// not reject it at expansion time), with a polar and a Cartesian
    /// coupler point.
    pub Stuck {
        params { ground = 100.0 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, 80.0, theta) as link2;
        let B = rrr(A, 60.0, O4, 50.0, left) as (link3, link4);
        let P = point(link3, from A, 30.0, 40 deg);
        let Q = point(link4, from O4, (10.0, -5.0));
        outputs { A, B, P, Q, link2, link3, link4 }
    }
}

mechanism! {
    /// A slider input drives an RRR (m): block P on a 30-degree line whose
    /// direction is a run-time parameter, links to a ground pivot; the
    /// links cannot reach for part of the stroke.
    pub SliderDriven {
        params { slope = 0.5235987755982988 }
        dof 1;
        let O = ground(0.0, 0.0);
        let line = guide((0.5, 0.1), slope);
        let P = slider(line, s, 0.02) as block;
        let C = rrr(P, 0.6, O, 0.5, right) as (link1, link2);
        outputs { P, C, block, link1, link2 }
    }
}

mechanism! {
    /// An excavator-like boom lifted by a hydraulic cylinder from B to C
    /// (m), with a tip point at a parametric polar offset.
    pub Boom {
        params { reach = 2.5 }
        dof 1;
        let A = ground(0.0, 0.0);
        let B = ground(0.8, -0.2);
        let C = actuator(A, 1.2, B, len, left) as (boom, cylinder);
        let tip = point(boom, from A, reach, 10 deg);
        outputs { C, tip, boom, cylinder }
    }
}

mechanism! {
    /// PRP (m): a block on a fixed vertical guide and a block on the crank's
    /// line (a guide carried by the crank); near 90 and 270 deg the lines
    /// are parallel (singular).
    pub CrossSlide {
        dof 1;
        let O = ground(0.0, 0.0);
        let V = ground(0.3, 0.0);
        let vertical = guide(V, 90 deg);
        let A = crank(O, 0.1, phi) as crank_link;
        let rod_line = guide(O, crank_link);
        let C = prp(rod_line, vertical, 0.0, 0.01) as (b1, b2) slide (s1, s2);
        range phi = (-80 deg, 80 deg);
        outputs { C, b1, b2, s1, s2 }
    }
}

mechanism! {
    /// An RRP on a guide carried by a crank at 30 deg to its axis, through
    /// the crank's tip, and an RPR with an offset slide line (m): every
    /// transport term (origin velocity, turning direction, Coriolis).
    pub Carried {
        params { offset = 0.01 }
        dof 1;
        let O = ground(0.0, 0.0);
        let E = ground(0.25, 0.05);
        let A = crank(O, 0.1, phi) as arm;
        let line = guide(A, arm, 30 deg);
        let F = rrp(E, 0.2, line, minus, offset) as (rod, block) slide sf;
        let r = rpr(F, O, plus, offset) as (pin, rocker);
        let G = point(rocker, from O, 0.3, 0 deg);
        outputs { F, G, rod, block, rocker, sf, r }
    }
}

mechanism! {
    /// A floating cylinder (m): an RPR between a four-bar's coupler point P
    /// and rocker point E (both pins of the group move) and an RRP pinned to
    /// the crank whose block runs in a slot carried by the rod (its pin and
    /// its guide both move). The kinematics of `tests/zoo/floating.rs`.
    pub Floating {
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.4, 0.0);
        let A = crank(O2, 0.1, theta) as crank;
        let B = rrr(A, 0.35, O4, 0.25, left) as (coupler, rocker);
        let P = point(coupler, from A, 0.2, 25 deg);
        let E = point(rocker, from O4, 0.12, -40 deg);
        let s = rpr(P, E, plus) as (sleeve, rod);
        let slot = guide(E, rod, 90 deg);
        let K = point(crank, from O2, 0.06, 90 deg);
        let F = rrp(K, 0.5, slot, plus) as (link7, slider7) slide u;
        outputs { P, E, F, rod, link7, s, u }
    }
}

#[test]
fn four_bar() {
    one_input!(
        FourBar::<f64>::default(),
        FourBar::<f32>::default(),
        FourBar,
        theta2,
        [A, B],
        [link3, link4],
        angles(2000),
        100,
        200,
        4
    );
    // Coupler too short for part of the turn: cannot assemble there.
    one_input!(
        FourBar::<f64> {
            coupler: 150.0,
            ..Default::default()
        },
        FourBar::<f32> {
            coupler: 150.0,
            ..Default::default()
        },
        FourBar,
        theta2,
        [A, B],
        [link3, link4],
        angles(2000),
        100,
        200,
        300
    );
    one_input!(
        Stuck::<f64>::default(),
        Stuck::<f32>::default(),
        Stuck,
        theta,
        [A, B, P, Q],
        [link3, link4],
        angles(2000),
        1300,
        1350,
        300
    );
}

#[test]
fn six_bar() {
    // F assembles only while |sin phi1| <= 6/7: most of the turn fails.
    one_input!(
        SixBar::<f64>::default(),
        SixBar::<f32>::default(),
        SixBar,
        phi1,
        [C, F, K, B, D],
        [link2, link3, link4, af],
        angles(2000),
        300,
        330,
        500
    );
}

#[test]
fn shaper() {
    one_input!(
        Shaper::<f64>::default(),
        Shaper::<f32>::default(),
        Shaper,
        crank,
        [E, B, D],
        [link3, link4],
        angles(2000),
        100,
        200,
        4
    );
    one_input!(
        ShaperForces::<f64>::default(),
        ShaperForces::<f32>::default(),
        ShaperForces,
        crank,
        [D, E, S3, S4, B],
        [link3, link4, s_ram],
        angles(2000),
        100,
        200,
        4
    );
}

#[test]
fn slider_crank() {
    one_input!(
        SliderCrank::<f64>::default(),
        SliderCrank::<f32>::default(),
        SliderCrank,
        theta,
        [B, A],
        [link3, x],
        angles(2000),
        100,
        200,
        4
    );
    // A rod shorter than crank + offset: cannot assemble near the top.
    one_input!(
        SliderCrank::<f64> {
            rod: 0.1,
            ..Default::default()
        },
        SliderCrank::<f32> {
            rod: 0.1,
            ..Default::default()
        },
        SliderCrank,
        theta,
        [B, A],
        [link3, x],
        angles(2000),
        100,
        1900,
        200
    );
}

#[test]
fn sine_mechanism() {
    one_input!(
        SineMechanism::<f64>::default(),
        SineMechanism::<f32>::default(),
        SineMechanism,
        phi1,
        [B, Q],
        // block2 and link3 never turn (link3 slides along the fixed frame,
        // block2 in its slot): no batch column.
        [s_slot, s_yoke],
        angles(2000),
        100,
        200,
        4
    );
}

#[test]
fn five_bar() {
    // A grid of both inputs over more than the workspace: the distal links
    // cannot reach over part of it.
    let (mut q1, mut q2) = (Vec::new(), Vec::new());
    for i in 0..60 {
        for j in 0..60 {
            q1.push(-0.5 + i as f64 * 0.07);
            q2.push(-1.5 + j as f64 * 0.07);
        }
    }
    let n = q1.len();
    let q = HashMap::from([("q1", q1), ("q2", q2)]);
    let w = HashMap::from([("q1", rates(n, 1.0, Some(7))), ("q2", rates(n, -0.5, None))]);
    let a = HashMap::from([("q1", rates(n, 2.0, None)), ("q2", rates(n, -3.0, Some(9)))]);
    for distal in [0.16, 0.09] {
        let f64s = compare!(
            FiveBar::<f64> {
                distal,
                ..Default::default()
            },
            f64,
            FiveBar,
            [q1, q2],
            [P, A, C],
            [],
            q,
            w,
            a
        );
        let f32s = compare!(
            FiveBar::<f32> {
                distal: distal as f32,
                ..Default::default()
            },
            f32,
            FiveBar,
            [q1, q2],
            [P, A, C],
            [],
            q,
            w,
            a
        );
        for found in [f64s, f32s] {
            // Reachable everywhere but for the bad rates, or over part.
            let least = if distal > 0.1 { 2 } else { 100 };
            assert!(
                found.2 >= least && found.2 < n,
                "{distal}: {} failures",
                found.2
            );
            assert!(found.1 <= n / 100, "{distal}: {} handed back", found.1);
        }
    }
}

#[test]
fn slider_driver() {
    // Strokes from -1 to 1.5 m: the links (0.6, 0.5 from O) reach only part.
    let mut s: Vec<f64> = (0..2000).map(|i| -1.0 + i as f64 * 1.25e-3).collect();
    s.extend([f64::NAN, f64::INFINITY, -1e300]);
    one_input!(
        SliderDriven::<f64>::default(),
        SliderDriven::<f32>::default(),
        SliderDriven,
        s,
        [P, C],
        [link1, link2], // the block on the fixed line has no column
        s,
        900,
        1000,
        300
    );
}

#[test]
fn actuator() {
    // Cylinder lengths from 0 to 2.5 m: too short, reachable, too long.
    let mut len: Vec<f64> = (0..2000).map(|i| i as f64 * 1.25e-3).collect();
    len.extend([f64::NAN, -1.0, f64::INFINITY]);
    one_input!(
        Boom::<f64>::default(),
        Boom::<f32>::default(),
        Boom,
        len,
        [C, tip],
        [boom, cylinder],
        len,
        900,
        1000,
        300
    );
}

#[test]
fn prp_on_a_carried_guide() {
    one_input!(
        CrossSlide::<f64>::default(),
        CrossSlide::<f32>::default(),
        CrossSlide,
        phi,
        [C],
        // b2 slides on the fixed vertical guide: no batch column.
        [b1, s1, s2],
        angles(2000),
        100,
        200,
        4
    );
}

#[test]
fn rrp_on_a_carried_guide_and_rpr_with_offset() {
    for offset in [0.01, 0.0, -0.04] {
        one_input!(
            Carried::<f64> { offset },
            Carried::<f32> {
                offset: offset as f32,
            },
            Carried,
            phi,
            [F, G],
            [rod, block, rocker, sf, r],
            angles(2000),
            100,
            200,
            4
        );
    }
}

#[test]
fn rpr_and_rrp_with_every_outer_joint_moving() {
    one_input!(
        Floating::<f64>::default(),
        Floating::<f32>::default(),
        Floating,
        theta,
        [P, E, F],
        [rod, link7, s, u],
        angles(2000),
        100,
        200,
        4
    );
}

mechanism! {
    /// The four-bar's position analysis alone (no rate system to check).
    pub FourBarPosition {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        analysis position;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        outputs { B, link3, link4 }
    }
}

#[test]
fn four_bar_far_from_unit_lengths() {
    // f32 lengths of about 1e-10 and 3e11: the RRR's product of squared
    // lengths (a fourth power) is subnormal or infinite there, and the scalar
    // path takes the two roots apart. The batch must give the scalar path's
    // statuses and values (the comparison's usual bound). Other checks of the
    // kernel already hand these elements back (503 of 505), so this is the
    // end-to-end check; the kernel's own guard on the product is tested in
    // `lane::rrr`'s unit tests.
    macro_rules! scaled {
        ($ty:ident, $k:expr) => {
            $ty::<f32> {
                ground: (304.8 * $k) as f32,
                crank: (101.6 * $k) as f32,
                coupler: (254.0 * $k) as f32,
                rocker: (177.8 * $k) as f32,
            }
        };
    }
    for k in [1.0e-12f64, 1.0e9] {
        let q = angles(500);
        let n = q.len();
        let (w, a) = (rates(n, 3.0, None), rates(n, -2.0, None));
        let found = compare!(
            scaled!(FourBar, k),
            f32,
            FourBar,
            [theta2],
            [A, B],
            [link3, link4],
            one("theta2", q.clone()),
            one("theta2", w.clone()),
            one("theta2", a.clone())
        );
        // NaN and infinite angles fail; every other element is solved.
        assert_eq!(found.2, 2, "scale {k:e}");
        // Position only (no rate system).
        let found = compare!(
            pos;
            scaled!(FourBarPosition, k),
            f32,
            FourBarPosition,
            [theta2],
            [B],
            [link3, link4],
            one("theta2", q),
            one("theta2", w),
            one("theta2", a)
        );
        assert_eq!(found.2, 2, "position only, scale {k:e}");
    }
}

#[test]
fn slider_crank_far_from_unit_lengths() {
    // f32 lengths of about 1e-12 and 1e9: the RRP's fourth powers (its rate
    // system's scale) are subnormal or infinite there, and the scalar path
    // scales them exactly (`dyad::rrp`); the batch must give the scalar
    // path's statuses and values. The end-to-end check, as for the four-bar
    // above: the kernel's rate check already hands these elements back (this
    // passes without its explicit guard on the fourth power, which keeps it
    // so whatever the rounding of that check).
    for k in [1.0e-12f64, 1.0e9] {
        let q = angles(500);
        let n = q.len();
        let (w, a) = (rates(n, 3.0, None), rates(n, -2.0, None));
        let m = SliderCrank::<f32> {
            crank: (0.1 * k) as f32,
            rod: (0.4 * k) as f32,
            offset: (0.02 * k) as f32,
        };
        let found = compare!(
            m,
            f32,
            SliderCrank,
            [theta],
            [B, A],
            [link3, x],
            one("theta", q),
            one("theta", w),
            one("theta", a)
        );
        // NaN and infinite angles fail; every other element is solved.
        assert_eq!(found.2, 2, "scale {k:e}");
    }
}
