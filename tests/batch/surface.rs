//! The batch API (`solve_batch` and its lane kernel) against the scalar
//! path, element by element, on definitions `examples.rs` does not
//! cover: the unusual ones of `tests/surface/dsl.rs` (unicode and DSL words
//! as names, statements out of order, parameters everywhere, group offsets
//! and a slot angle from parameters, a guide carried by a block, two cranks
//! one read `as cos_sin`, a slider on a carried guide, output subsets down
//! to none at the position and velocity levels) and more: guides carried by
//! a group's second link, a PRP between two carried guides, an RPP on a
//! carried guide with its slot angle and offset from parameters, points on
//! blocks, an actuator between a ground pivot and a crank tip, a crank and a
//! slider as the two inputs; every one in f64 and f32, with parameters
//! changed from their defaults, over grids that include poses that cannot
//! assemble, singular ones, NaN, infinite and huge inputs and infinite
//! rates.
//!
//! The comparison (`compare!`, shared with `examples.rs` through
//! `tests/common/batch_compare.rs`) checks the four points of
//! `examples.rs`'s module documentation: a lane kernel exists, it accepts
//! only elements the scalar path solves and hands back at most 1 % of the
//! others, statuses and failed levels match the scalar path bit for bit, and
//! ok elements agree within `K = 64` eps of the level's scale times
//! condition^2 (the justification is there). The worst scaled error per
//! definition and precision is printed with `--nocapture`.
#![allow(non_snake_case)]
// `both!` takes parameters as `field: value` (it casts the value for f32).
#![allow(clippy::redundant_field_names)]

use crate::batch_compare::*;
use crate::surface_defs::*;
use mechanism::mechanism;
use std::collections::HashMap;

// ------------------------------------------- from tests/surface/dsl.rs

// ------------------------------------------------------------- new ones

mechanism! {
    /// A slot carried by a four-bar's rocker (the RRR's second link) at a
    /// parameter angle, through the moving joint B, with an RRP on it (an
    /// offset from a parameter) and a point on its block; a PRP between the
    /// crank's line and a line carried by the rocker through its ground
    /// pivot (both guides move), with a polar point on its second block.
    pub RockerSlot {
        params { tilt = 40.0, off = -0.01, o1 = 0.005, o2 = -0.01, rod = 0.3 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.4, 0.0);
        let A = crank(O2, 0.1, theta) as crank;
        let B = rrr(A, 0.35, O4, 0.25, left) as (coupler, rocker);
        let slot = guide(B, rocker, tilt deg);
        let E = ground(0.1, 0.3);
        let F = rrp(E, rod, slot, minus, off) as (link5, block) slide u;
        let Pb = point(block, from F, (0.03, -0.02));
        let crank_line = guide(O2, crank);
        let rocker_line = guide(O4, rocker, 90 deg);
        let X = prp(crank_line, rocker_line, o1, o2) as (b1, b2) slide (s1, s2);
        let Xp = point(b2, from X, 0.02, 30 deg);
    }
}

mechanism! {
    /// An RPP on a guide carried by the crank (at a parameter angle to it,
    /// through the crank's tip), its slot angle and
    /// offset from parameters, pinned at a coupler point; a point on its
    /// yoke and one on its block.
    pub CarriedRpp {
        params { gangle = 15.0, slot = 70.0, off = 0.02 }
        dof 1;
        let O = ground(0.0, 0.0);
        let A = crank(O, 0.08, phi) as arm;
        let O4 = ground(0.3, 0.05);
        let B = rrr(A, 0.3, O4, 0.2, right) as (coupler, rocker);
        let P = point(coupler, from A, 0.15, -20 deg);
        let line = guide(A, arm, gangle deg);
        let Q = rpp(P, line, slot deg, off) as (blk, yoke) slide (t1, t2);
        let Y = point(yoke, from Q, (0.01, 0.04));
        let Z = point(blk, from P, 0.03, 0.0);
    }
}

mechanism! {
    /// An RPR between a crank tip and a coupler point with a guide carried
    /// by its second link (the rod, at a parameter angle) and an RRP from a
    /// ground pivot on it; the RPR's offset from a parameter.
    pub RprCarrier {
        params { off = 0.01, ang = -30.0 }
        dof 1;
        let O = ground(0.0, 0.0);
        let C = ground(0.0, -0.3);
        let A = crank(O, 0.1, phi) as link2;
        let s = rpr(A, C, minus, off) as (sleeve, rod);
        let track = guide(C, rod, ang deg);
        let E = ground(0.2, 0.1);
        let F = rrp(E, 0.35, track, plus) as (link5, shoe) slide u;
        let R = point(rod, from C, (0.2, 0.01));
        let S = point(sleeve, from A, 0.05, 90 deg);
    }
}

mechanism! {
    /// A cylinder between a ground pivot and a crank tip (both its length
    /// and its far pivot move: two inputs), with a tip point on the boom.
    pub CrankActuator {
        params { boom = 0.5 }
        dof 2;
        let O = ground(0.0, 0.0);
        let B = ground(0.6, -0.1);
        let K = crank(B, 0.1, theta) as wheel;
        let C = actuator(O, boom, K, len, right) as (boomlink, cylinder);
        let tip = point(boomlink, from O, 0.8, 5 deg);
    }
}

mechanism! {
    /// Two cranks both read `as cos_sin` driving a five-bar, with a guide
    /// carried by the second distal link (through P) and a slider on it
    /// would need a third input: instead an RRP from a ground pivot.
    pub CosSinPair {
        params { base = 0.08 }
        dof 2;
        let O1 = ground(0.0, 0.0);
        let O2 = ground(base, 0.0);
        let A = crank(O1, 0.1, q1 as cos_sin) as arm1;
        let C = crank(O2, 0.1, q2 as cos_sin) as arm2;
        let P = rrr(A, 0.16, C, 0.16, left) as (fore1, fore2);
        let g = guide(P, fore2, 90 deg);
        let E = ground(0.0, 0.25);
        let F = rrp(E, 0.1, g, plus) as (link5, shoe) slide u;
    }
}

// -------------------------- position- and velocity-level subsets of the above

mechanism! {
    /// `RockerSlot` at the position level with the outputs `F, Pb, u,
    /// block, b2` only (not the PRP's point and slides: they pass through
    /// singular poses, and at the position level `compare!` has no
    /// condition to scale their errors by; `b2`'s angle is its guide's).
    pub RockerSlotPos {
        analysis position;
        outputs { F, Pb, u, block, b2 }
        params { tilt = 40.0, off = -0.01, o1 = 0.005, o2 = -0.01, rod = 0.3 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.4, 0.0);
        let A = crank(O2, 0.1, theta) as crank;
        let B = rrr(A, 0.35, O4, 0.25, left) as (coupler, rocker);
        let slot = guide(B, rocker, tilt deg);
        let E = ground(0.1, 0.3);
        let F = rrp(E, rod, slot, minus, off) as (link5, block) slide u;
        let Pb = point(block, from F, (0.03, -0.02));
        let crank_line = guide(O2, crank);
        let rocker_line = guide(O4, rocker, 90 deg);
        let X = prp(crank_line, rocker_line, o1, o2) as (b1, b2) slide (s1, s2);
        let Xp = point(b2, from X, 0.02, 30 deg);
    }
}

mechanism! {
    /// `RockerSlot` at the velocity level with the outputs `Xp, link5, s1, rocker` only.
    pub RockerSlotVel {
        analysis velocity;
        outputs { Xp, link5, s1, rocker }
        params { tilt = 40.0, off = -0.01, o1 = 0.005, o2 = -0.01, rod = 0.3 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.4, 0.0);
        let A = crank(O2, 0.1, theta) as crank;
        let B = rrr(A, 0.35, O4, 0.25, left) as (coupler, rocker);
        let slot = guide(B, rocker, tilt deg);
        let E = ground(0.1, 0.3);
        let F = rrp(E, rod, slot, minus, off) as (link5, block) slide u;
        let Pb = point(block, from F, (0.03, -0.02));
        let crank_line = guide(O2, crank);
        let rocker_line = guide(O4, rocker, 90 deg);
        let X = prp(crank_line, rocker_line, o1, o2) as (b1, b2) slide (s1, s2);
        let Xp = point(b2, from X, 0.02, 30 deg);
    }
}

mechanism! {
    /// `CarriedRpp` at the position level with the outputs `Y, Z, t1, yoke` only.
    pub CarriedRppPos {
        analysis position;
        outputs { Y, Z, t1, yoke }
        params { gangle = 15.0, slot = 70.0, off = 0.02 }
        dof 1;
        let O = ground(0.0, 0.0);
        let A = crank(O, 0.08, phi) as arm;
        let O4 = ground(0.3, 0.05);
        let B = rrr(A, 0.3, O4, 0.2, right) as (coupler, rocker);
        let P = point(coupler, from A, 0.15, -20 deg);
        let line = guide(A, arm, gangle deg);
        let Q = rpp(P, line, slot deg, off) as (blk, yoke) slide (t1, t2);
        let Y = point(yoke, from Q, (0.01, 0.04));
        let Z = point(blk, from P, 0.03, 0.0);
    }
}

mechanism! {
    /// `CarriedRpp` at the velocity level with the outputs `Y, t2, blk` only.
    pub CarriedRppVel {
        analysis velocity;
        outputs { Y, t2, blk }
        params { gangle = 15.0, slot = 70.0, off = 0.02 }
        dof 1;
        let O = ground(0.0, 0.0);
        let A = crank(O, 0.08, phi) as arm;
        let O4 = ground(0.3, 0.05);
        let B = rrr(A, 0.3, O4, 0.2, right) as (coupler, rocker);
        let P = point(coupler, from A, 0.15, -20 deg);
        let line = guide(A, arm, gangle deg);
        let Q = rpp(P, line, slot deg, off) as (blk, yoke) slide (t1, t2);
        let Y = point(yoke, from Q, (0.01, 0.04));
        let Z = point(blk, from P, 0.03, 0.0);
    }
}

mechanism! {
    /// `RprCarrier` at the position level with the outputs `F, R, s, shoe` only.
    pub RprCarrierPos {
        analysis position;
        outputs { F, R, s, shoe }
        params { off = 0.01, ang = -30.0 }
        dof 1;
        let O = ground(0.0, 0.0);
        let C = ground(0.0, -0.3);
        let A = crank(O, 0.1, phi) as link2;
        let s = rpr(A, C, minus, off) as (sleeve, rod);
        let track = guide(C, rod, ang deg);
        let E = ground(0.2, 0.1);
        let F = rrp(E, 0.35, track, plus) as (link5, shoe) slide u;
        let R = point(rod, from C, (0.2, 0.01));
        let S = point(sleeve, from A, 0.05, 90 deg);
    }
}

mechanism! {
    /// `RprCarrier` at the velocity level with the outputs `S, u, sleeve` only.
    pub RprCarrierVel {
        analysis velocity;
        outputs { S, u, sleeve }
        params { off = 0.01, ang = -30.0 }
        dof 1;
        let O = ground(0.0, 0.0);
        let C = ground(0.0, -0.3);
        let A = crank(O, 0.1, phi) as link2;
        let s = rpr(A, C, minus, off) as (sleeve, rod);
        let track = guide(C, rod, ang deg);
        let E = ground(0.2, 0.1);
        let F = rrp(E, 0.35, track, plus) as (link5, shoe) slide u;
        let R = point(rod, from C, (0.2, 0.01));
        let S = point(sleeve, from A, 0.05, 90 deg);
    }
}

mechanism! {
    /// `SliderOnCarried` at the position level with the outputs `Q, block` only.
    pub SliderOnCarriedPos {
        analysis position;
        outputs { Q, block }
        dof 2;
        let O = ground(0.0, 0.0);
        let A = crank(O, 0.1, theta) as link2;
        let g = guide(O, link2, 20 deg);
        let P = slider(g, s, 0.01) as block;
        let Q = point(block, from P, (0.02, 0.03));
    }
}

mechanism! {
    /// `SliderOnCarried` at the velocity level with the outputs `P, Q, block` only.
    pub SliderOnCarriedVel {
        analysis velocity;
        outputs { P, Q, block }
        dof 2;
        let O = ground(0.0, 0.0);
        let A = crank(O, 0.1, theta) as link2;
        let g = guide(O, link2, 20 deg);
        let P = slider(g, s, 0.01) as block;
        let Q = point(block, from P, (0.02, 0.03));
    }
}

mechanism! {
    /// `BlockGuide` at the position level with the outputs `E, y, block6` only.
    pub BlockGuidePos {
        analysis position;
        outputs { E, y, block6 }
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
    /// `BlockGuide` at the velocity level with the outputs `F, link8` only.
    pub BlockGuideVel {
        analysis velocity;
        outputs { F, link8 }
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
    /// `CrankActuator` at the velocity level with the outputs `tip, cylinder` only.
    pub CrankActuatorVel {
        analysis velocity;
        outputs { tip, cylinder }
        params { boom = 0.5 }
        dof 2;
        let O = ground(0.0, 0.0);
        let B = ground(0.6, -0.1);
        let K = crank(B, 0.1, theta) as wheel;
        let C = actuator(O, boom, K, len, right) as (boomlink, cylinder);
        let tip = point(boomlink, from O, 0.8, 5 deg);
    }
}

mechanism! {
    /// The five-bar robot given its end point (inverse kinematics): a
    /// target driver and two RRRs hanging on it.
    pub FiveBarTarget {
        params { prox = 0.1 }
        let O1 = ground(0.0, 0.0);
        let O2 = ground(0.08, 0.0);
        let P = target(x, y) as effector;
        let A = rrr(O1, prox, P, 0.16, left) as (arm1, fore1);
        let C = rrr(O2, prox, P, 0.16, right) as (arm2, fore2);
    }
}

// ------------------------------------------------------------- helpers

/// `len` inputs from `lo` to `hi`, then NaN, infinite and huge ones.
fn stroke(n: usize, lo: f64, hi: f64) -> Vec<f64> {
    let mut v: Vec<f64> = (0..n)
        .map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64)
        .collect();
    v.extend([f64::NAN, f64::INFINITY, -1e300, 1e300]);
    v
}

/// A grid of two inputs (`n` by `n` over the given intervals, then NaN,
/// infinite and huge rows) and their rates and accelerations, one infinite
/// rate (element `bad_w`) and one NaN acceleration (element `bad_a`).
#[allow(clippy::type_complexity)]
fn grid2(
    (i1, lo1, hi1): (&'static str, f64, f64),
    (i2, lo2, hi2): (&'static str, f64, f64),
    n: usize,
    bad_w: usize,
    bad_a: usize,
) -> [HashMap<&'static str, Vec<f64>>; 3] {
    let (mut a, mut b) = (Vec::new(), Vec::new());
    for i in 0..n {
        for j in 0..n {
            a.push(lo1 + (hi1 - lo1) * i as f64 / (n - 1) as f64);
            b.push(lo2 + (hi2 - lo2) * j as f64 / (n - 1) as f64);
        }
    }
    for (x, y) in [
        (f64::NAN, 0.1),
        (0.1, f64::INFINITY),
        (2e5, 0.1),
        (0.1, -1e300),
        (1e300, 1e300),
    ] {
        a.push(x);
        b.push(y);
    }
    let m = a.len();
    [
        HashMap::from([(i1, a), (i2, b)]),
        HashMap::from([(i1, rates(m, 2.0, Some(bad_w))), (i2, rates(m, -1.5, None))]),
        HashMap::from([(i1, rates(m, 1.0, None)), (i2, rates(m, -3.0, Some(bad_a)))]),
    ]
}

/// The same for one input.
fn grid1(
    i: &'static str,
    q: Vec<f64>,
    bad_w: usize,
    bad_a: usize,
) -> [HashMap<&'static str, Vec<f64>>; 3] {
    let n = q.len();
    [
        one(i, q),
        one(i, rates(n, 3.0, Some(bad_w))),
        one(i, rates(n, -2.0, Some(bad_a))),
    ]
}

/// Runs `compare!` on definition `$ty` at level `$lv` in f64 and f32 with
/// the parameters `$f: $v` (the rest at their defaults; `f64` values
/// rounded to the precision), over the grid `$g` (`[inputs, rates,
/// accelerations]`); asserts at least `$min_fail` failed elements and at
/// most 1 % handed back by the kernel.
macro_rules! both {
    ($lv:ident; $ty:ident { $($f:ident: $v:expr),* }, $i:tt, $p:tt, $s:tt, $g:expr, $min_fail:expr) => {{
        let [q, w, a] = $g;
        let n = q.values().next().unwrap().len();
        let least: usize = $min_fail;
        // `..Default::default()` fills what `$f` leaves out (nothing, for
        // some definitions).
        #[allow(clippy::needless_update)]
        for (found, t) in [
            compare!($lv; $ty::<f64> { $($f: $v,)* ..Default::default() }, f64, $ty, $i, $p, $s, q, w, a),
            compare!($lv; $ty::<f32> { $($f: $v as f32,)* ..Default::default() }, f32, $ty, $i, $p, $s, q, w, a),
        ]
        .into_iter()
        .zip(["f64", "f32"])
        {
            assert!(found.2 >= least, "{} {t}: {} failures", stringify!($ty), found.2);
            assert!(found.1 <= n / 100, "{} {t}: {} handed back", stringify!($ty), found.1);
            // Never all: the grid must reach poses that assemble.
            assert!(found.2 < n, "{} {t}: all failed", stringify!($ty));
        }
    }};
}

// ---------------------------------------------------------------- tests

#[test]
fn names_dsl_words_unicode_underscores() {
    both!(acc; KwNames {}, [analysis], [crank, point], [range, outputs], grid1("analysis", angles(2000), 100, 200), 4);
    for länge in [1.0, 0.4, 0.3] {
        both!(
            acc; Unicode { länge: länge },
            [θ],
            [a, A, a_very_long_name_for_a_coupler_point_that_goes_on_and_on_and_on],
            [koppel, schwinge],
            grid1("θ", angles(2000), 100, 200),
            4
        );
    }
    both!(acc; Underscore {}, [theta], [A, _scalar], [link3, link4], grid1("theta", angles(2000), 100, 200), 4);
}

#[test]
fn out_of_order_with_params_changed() {
    both!(acc; OutOfOrder {}, [theta], [P, Q], [x], grid1("theta", angles(2000), 100, 200), 4);
    // A rod shorter than crank + offset: cannot assemble over part of the turn.
    both!(
        acc; OutOfOrder { crank: 0.7, offset: -0.05, gangle: -25.0 },
        [theta], [P, Q], [x], grid1("theta", angles(2000), 100, 200), 4
    );
    // The guide 3 below the x axis, the rod's pin 3 to its left: the rod
    // (4) reaches only while the crank is below y = -0.5 + ... : fails over
    // part of the turn.
    both!(
        acc; OutOfOrder { offset: -1.6 },
        [theta], [P, Q], [x], grid1("theta", angles(2000), 100, 200), 100
    );
}

#[test]
fn output_subsets_at_the_position_and_velocity_levels() {
    both!(pos; SlideOnly {}, [theta], [], [x], grid1("theta", angles(2000), 100, 200), 2);
    both!(vel; AngleOnly {}, [theta], [], [link4], grid1("theta", angles(2000), 100, 200), 3);
    // Nothing to compute (the ground point is given): even NaN inputs are
    // ok, in the scalar path too.
    both!(vel; GroundOnly {}, [theta], [], [], grid1("theta", angles(2000), 100, 200), 0);
    // No kinematic output (the forces alone): the statuses still follow the
    // scalar path's (NaN and infinite angles, the bad rate and acceleration).
    both!(acc; TorqueOnly {}, [theta], [], [], grid1("theta", angles(2000), 100, 200), 2);
}

#[test]
fn guide_on_a_block() {
    for tilt in [0.3, 0.0, -1.2] {
        both!(
            acc; BlockGuide { tilt: tilt },
            [theta],
            [A, B, C, D, E, F],
            // The slider and block6 never turn: no columns.
            [link3, link5, link7, link8, x, y],
            grid1("theta", angles(2000), 100, 200),
            4
        );
    }
}

#[test]
fn two_cranks_one_as_cos_sin() {
    // |A - C| <= 0.3 < 0.32 everywhere, or up to 0.42: fails over part.
    for (base, least) in [(0.08, 4), (0.2, 100)] {
        both!(
            acc; TwoCranks { base: base, arm: 0.11 },
            [q1, q2],
            [A, C, P, Tp],
            [fore1, fore2],
            grid2(("q1", -0.5, 3.5), ("q2", -1.5, 2.5), 60, 7, 9),
            least
        );
    }
    both!(
        acc; CosSinPair {},
        [q1, q2],
        [A, C, P, F],
        [fore1, fore2, link5, shoe, u],
        grid2(("q1", -0.5, 3.5), ("q2", -1.5, 2.5), 60, 7, 9),
        5
    );
}

#[test]
fn slider_on_a_guide_at_a_param_angle() {
    for (slope, off) in [(30.0, -0.02), (-50.0, 0.05), (90.0, 0.0)] {
        both!(
            acc; SliderParamAngle { slope: slope, off: off },
            [s],
            [P, C, D],
            [link1, link2], // the block never turns: no column
            grid1("s", stroke(2000, -1.5, 1.5), 900, 1000),
            300
        );
    }
}

#[test]
fn slider_on_a_carried_guide_and_crank_with_slider() {
    both!(
        acc; SliderOnCarried {},
        [theta, s],
        [A, P, Q],
        [block],
        grid2(("theta", -4.0, 4.0), ("s", -0.3, 0.3), 60, 7, 9),
        4
    );
    both!(
        acc; SliderCrankDof2 {},
        [s, theta],
        [P, A, B],
        [link3, link4], // the block never turns: no column
        grid2(("s", -0.8, 0.8), ("theta", -4.0, 4.0), 60, 7, 9),
        300
    );
}

#[test]
fn actuators() {
    for (boom, bx) in [(1.2, 0.8), (0.9, 1.1)] {
        both!(
            acc; ActuatorParams { boom: boom, bx: bx },
            [len],
            [C, tip],
            [boomlink, cylinder],
            grid1("len", stroke(2000, 0.0, 2.5), 900, 1000),
            300
        );
    }
    both!(
        acc; CrankActuator {},
        [theta, len],
        [K, C, tip],
        [boomlink, cylinder],
        // Lengths from 0.25 (the scaled error grows as the cylinder gets
        // short beside the coordinates, |O - K| ~ 0.6: the rounding of
        // C - K is a few ulp of 0.6, relative to |C - K| = len; measured
        // 9 from 0.4 up, 19 from 0.2, 56 from 0.1, 114 from 0.01) to 1.2
        // (too long for part of the wheel's turn).
        grid2(("theta", -4.0, 4.0), ("len", 0.25, 1.2), 60, 7, 9),
        300
    );
}

#[test]
fn group_offsets_and_slot_angle_from_params() {
    both!(
        acc; ParamGroups {},
        [phi],
        [A, D, E, Q],
        // b2, b5 and the yoke never turn: no columns.
        [block, link3, b1, s, s1, s2, t1, t2],
        grid1("phi", angles(2000), 100, 200),
        4
    );
    both!(
        acc; ParamGroups { off: 0.03, o1: -0.01, o2: 0.04, slot: 35.0, ay: -0.1, gx: -0.2 },
        [phi],
        [A, D, E, Q],
        // b2, b5 and the yoke never turn: no columns.
        [block, link3, b1, s, s1, s2, t1, t2],
        grid1("phi", angles(2000), 100, 200),
        4
    );
}

#[test]
fn carried_guides_on_second_links_prp_and_rpp() {
    for (tilt, off, rod) in [(40.0, -0.01, 0.3), (-70.0, 0.02, 0.2), (0.0, 0.0, 0.5)] {
        both!(
            acc; RockerSlot { tilt: tilt, off: off, rod: rod },
            [theta],
            [A, B, F, Pb, X, Xp],
            [coupler, rocker, link5, block, b1, b2, u, s1, s2],
            grid1("theta", angles(2000), 100, 200),
            4
        );
    }
    for (gangle, slot, off) in [(15.0, 70.0, 0.02), (-30.0, 120.0, -0.05), (0.0, 90.0, 0.0)] {
        both!(
            acc; CarriedRpp { gangle: gangle, slot: slot, off: off },
            [phi],
            [A, B, P, Q, Y, Z],
            [coupler, rocker, blk, yoke, t1, t2],
            grid1("phi", angles(2000), 100, 200),
            4
        );
    }
    for (off, ang) in [(0.01, -30.0), (-0.05, 10.0)] {
        both!(
            acc; RprCarrier { off: off, ang: ang },
            [phi],
            [A, F, R, S],
            [sleeve, rod, link5, shoe, s, u],
            grid1("phi", angles(2000), 100, 200),
            4
        );
    }
}

#[test]
fn loaded_press_kinematics() {
    both!(
        acc; LoadedPress { crank: 0.12, g: 3.0 },
        [theta],
        [A, B, G3],
        [link3, x], // the ram on its fixed guide has no column
        grid1("theta", angles(2000), 100, 200),
        4
    );
}

/// The position- and velocity-level definitions with output subsets: the
/// kernel evaluates only what the outputs need, without the rate locals a
/// carried guide's motion would otherwise read.
#[test]
fn subsets_at_lower_levels_with_carried_guides() {
    let g1 = || grid1("theta", angles(2000), 100, 200);
    let p1 = || grid1("phi", angles(2000), 100, 200);
    both!(pos; RockerSlotPos { tilt: -20.0 }, [theta], [F, Pb], [u, block, b2], g1(), 2);
    both!(vel; RockerSlotVel { tilt: -20.0 }, [theta], [Xp], [link5, s1, rocker], g1(), 3);
    both!(pos; CarriedRppPos { slot: 100.0 }, [phi], [Y, Z], [t1, yoke], p1(), 2);
    both!(vel; CarriedRppVel { slot: 100.0 }, [phi], [Y], [t2, blk], p1(), 3);
    both!(pos; RprCarrierPos {}, [phi], [F, R], [s, shoe], p1(), 2);
    both!(vel; RprCarrierVel {}, [phi], [S], [u, sleeve], p1(), 3);
    both!(pos; BlockGuidePos { tilt: 0.5 }, [theta], [E], [y], g1(), 2); // block6 never turns: no column
    both!(vel; BlockGuideVel { tilt: 0.5 }, [theta], [F], [link8], g1(), 3);
    let g2 = || grid2(("theta", -4.0, 4.0), ("s", -0.3, 0.3), 60, 7, 9);
    both!(pos; SliderOnCarriedPos {}, [theta, s], [Q], [block], g2(), 2);
    both!(vel; SliderOnCarriedVel {}, [theta, s], [P, Q], [block], g2(), 3);
    both!(
        vel; CrankActuatorVel {},
        [theta, len],
        [tip],
        [cylinder],
        grid2(("theta", -4.0, 4.0), ("len", 0.25, 1.2), 60, 7, 9),
        100
    );
}

/// Slices of different lengths are an error naming the first one that
/// differs (here an output slice), returned before the kernel or the scalar
/// path writes anything; with every slice as long as the input, a NaN
/// acceleration fails every element at level 3 (tests/batch_owned.rs covers
/// every kind of slice).
#[test]
fn a_short_slice_is_an_error_before_any_write() {
    let m = OutOfOrder::<f64>::default();
    let q: Vec<f64> = (0..200).map(|i| i as f64 * 0.05).collect();
    let (w, a) = (vec![1.0; 200], vec![f64::NAN; 200]);
    let mut bufs = vec![vec![7.0; 200]; 15];
    bufs[4].truncate(150);
    let mut status = vec![9u8; 200];
    macro_rules! batch {
        () => {{
            let mut it = bufs.iter_mut();
            let mut nx = || it.next().unwrap().as_mut_slice();
            OutOfOrderBatch {
                in_theta: &q,
                rate_theta: &w,
                accel_theta: &a,
                pos_P_x: nx(),
                pos_P_y: nx(),
                pos_Q_x: nx(),
                pos_Q_y: nx(),
                pos_x: nx(),
                vel_P_x: nx(),
                vel_P_y: nx(),
                vel_Q_x: nx(),
                vel_Q_y: nx(),
                vel_x: nx(),
                acc_P_x: nx(),
                acc_P_y: nx(),
                acc_Q_x: nx(),
                acc_Q_y: nx(),
                acc_x: nx(),
                status: &mut status,
            }
        }};
    }
    let mut b = batch!();
    assert_eq!(b.len(), 200);
    let e = m.solve_batch(&mut b).unwrap_err();
    assert_eq!(
        (e.slice, e.len, e.reference, e.expected),
        ("pos_x", 150, "in_theta", 200)
    );
    assert!(status.iter().all(|s| *s == 9));
    assert!(bufs.iter().all(|v| v.iter().all(|x| *x == 7.0)));
    bufs[4].resize(200, 7.0);
    // A NaN acceleration everywhere: every element fails at level 3, after
    // the kernel handed it to the scalar path, with zero accelerations.
    assert_eq!(m.solve_batch(&mut batch!()), Ok(200));
    assert!(status.iter().all(|s| *s == 3));
    assert!(bufs[10].iter().all(|x| *x == 0.0));
}

#[test]
fn a_target_and_two_dyads_on_it() {
    // The end point over a box that reaches beyond the arms (x -0.2..0.3,
    // y -0.1..0.35: many end points out of reach), with the edge rows.
    both!(
        acc; FiveBarTarget { prox: 0.1 },
        [x, y],
        [P, A, C],
        [arm1, arm2, fore1, fore2], // the effector translates: no column
        grid2(("x", -0.2, 0.3), ("y", -0.1, 0.35), 60, 7, 9),
        300
    );
}
