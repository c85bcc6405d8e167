//! The force analysis on loaded definitions the zoo (`tests/zoo`) does not
//! have: forces at joints shared by two links (with `on`), at points of
//! blocks and at a ground pivot; `force along` a carried guide; couples on
//! blocks, on group links and on the driven crank; masses with their centres
//! off the pins of the RRP, RPR, PRP and RPP blocks; a ternary coupler with
//! three joints and a point load; an actuator-driven boom with a coupled
//! group and a second actuator whose pivot and base both ride on the boom;
//! two inputs (two cranks; a crank and a slider); `loads { }` in several
//! forces and a couple; `params` masses and gravity changed at run time;
//! masses from 1e-6 kg to 1e6 kg in t, mm, s; poses approaching a singular
//! force system.
//!
//! Every check is independent of the generated code: Newton-Euler for every
//! body with each reaction applied at the point its doc comment names (the
//! prismatic couples included), every weight, inertia force and couple and
//! external load; the power balance from the outputs; f32 against f64.
//!
//! Tolerances. Equilibrium and power residuals use the zoo's `TOL` = 1e-13
//! relative to the largest term of each body (a sum of a handful of products
//! of generated values, each within a few eps times the conditioning of its
//! system; the poses checked keep `condition` above 0.05, so a few hundred
//! eps at most; see `tests/zoo/main.rs`). Each definition's checker is also
//! run once with one deliberate mistake (a centre of mass moved, a couple
//! dropped, a force put on the other link of its joint) and must then fail:
//! the mistakes are at least 1e-3 of the largest term, 1e10 times `TOL`.

use crate::equilibrium::*;
use mechanism::{mechanism, Vector2};
use std::panic::{catch_unwind, AssertUnwindSafe};

/// `true` when `f` panics (a checker run with a deliberate mistake).
fn fails(f: impl FnOnce()) -> bool {
    catch_unwind(AssertUnwindSafe(f)).is_err()
}

fn unit_at(deg: f64) -> Vector2<f64> {
    let r = deg.to_radians();
    Vector2::new(r.cos(), r.sin())
}

fn zero() -> Vector2<f64> {
    Vector2::zeros()
}

// ---------------------------------------------------------------------------
// 1. Forces at a joint shared by two links, at a ground pivot; couples on the
//    driven crank and on a group's link.

mechanism! {
    /// A crank-rocker four-bar (m, kg, N) with forces at the shared joint A
    /// on each of its two links, at the rocker's end of B, at the crank's
    /// ground pivot O2 (the crank is the one link with O2), couples on the
    /// crank and the coupler.
    pub SharedJoint {
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.5, 0.05);
        let A = crank(O2, 0.12, theta) as crank;
        let B = rrr(A, 0.45, O4, 0.3, left) as (coupler, rocker);
        let Gc = point(crank, from O2, 0.05, 10 deg);
        let G3 = point(coupler, from A, 0.2, 15 deg);
        let G4 = point(rocker, from O4, 0.14, -5 deg);
        mass crank { m = 0.4, at = Gc, j = 0.0008 };
        mass coupler { m = 1.3, at = G3, j = 0.025 };
        mass rocker { m = 0.9, at = G4, j = 0.008 };
        gravity (0.0, -9.81);
        force at A on crank = (6.0, -4.0);
        force at A on coupler = (-2.0, 7.0);
        force at B on rocker = (5.0, 3.0);
        force at O2 = (1.0, 2.0);
        torque on crank = 2.5;
        torque on coupler = -1.2;
    }
}

/// Mistake 1: the force "at A on crank" put on the coupler instead.
fn check_shared(s: &SharedJointSolution, w: f64, mistake: bool) {
    let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
    let (fa_crank, fa_coupler) = (Vector2::new(6.0, -4.0), Vector2::new(-2.0, 7.0));
    let (on_crank, on_coupler) = if mistake {
        (zero(), fa_coupler + fa_crank)
    } else {
        (fa_crank, fa_coupler)
    };
    Body::default()
        .force(p.O2, f.r_ground_crank)
        .force(p.A, -f.r_crank_coupler)
        .force(p.A, on_crank)
        .force(p.O2, Vector2::new(1.0, 2.0))
        .couple(f.drive_theta)
        .couple(2.5)
        .inertia(0.4, 0.0008, p.Gc, a.Gc, a.crank, G)
        .balances("crank");
    Body::default()
        .force(p.A, f.r_crank_coupler)
        .force(p.B, -f.r_coupler_rocker)
        .force(p.A, on_coupler)
        .couple(-1.2)
        .inertia(1.3, 0.025, p.G3, a.G3, a.coupler, G)
        .balances("coupler");
    Body::default()
        .force(p.O4, f.r_ground_rocker)
        .force(p.B, f.r_coupler_rocker)
        .force(p.B, Vector2::new(5.0, 3.0))
        .inertia(0.9, 0.008, p.G4, a.G4, a.rocker, G)
        .balances("rocker");
    power_balances(
        &[
            f.drive_theta * w,
            2.5 * w,
            -1.2 * v.coupler,
            fa_crank.dot(&v.A),
            fa_coupler.dot(&v.A),
            Vector2::new(5.0, 3.0).dot(&v.B),
            inertial(0.4, 0.0008, v.Gc, a.Gc, v.crank, a.crank, G),
            inertial(1.3, 0.025, v.G3, a.G3, v.coupler, a.coupler, G),
            inertial(0.9, 0.008, v.G4, a.G4, v.rocker, a.rocker, G),
        ],
        "SharedJoint",
    );
    assert!(f.power_residual <= TOL, "{}", f.power_residual);
}

#[test]
fn forces_at_a_shared_joint_go_to_the_link_named() {
    let m = SharedJoint::<f64>::default();
    let (w, al) = (7.0, -20.0);
    let mut checked = 0;
    for k in 0..72 {
        let q = f64::to_radians(5.0 * k as f64 + 1.0);
        let s = m
            .solve(
                &SharedJointInput { theta: q },
                &SharedJointInput { theta: w },
                &SharedJointInput { theta: al },
            )
            .unwrap();
        if s.forces.condition < 0.05 {
            continue;
        }
        checked += 1;
        check_shared(&s, w, false);
        if k == 10 {
            assert!(fails(|| check_shared(&s, w, true)));
        }
    }
    assert!(checked >= 60, "only {checked} of 72 poses checked");
}

// ---------------------------------------------------------------------------
// 2. An RRP on an inclined guide: the block's centre off its pin, a force at
//    a point of the block, a force along the guide, couples on the block
//    (taken by the guide) and on the rod from `loads`; the block's mass and
//    gravity (any direction) from `params`, changed at run time.

mechanism! {
    /// An inclined press (m, kg, N).
    pub InclinedPress {
        dof 1;
        params { gx = 3.0, gy = -9.0, mb = 4.0 }
        loads { push = 0.0, twist = 0.0 }
        let O = ground(0.0, 0.0);
        let line = guide((0.02, -0.05), 20 deg);
        let A = crank(O, 0.08, theta) as crank;
        let B = rrp(A, 0.3, line, plus) as (rod, ram) slide x;
        let Gr = point(rod, from A, 0.1, 5 deg);
        let Gb = point(ram, from B, (0.03, 0.02));
        let Pb = point(ram, from B, (-0.04, 0.05));
        mass rod { m = 0.7, at = Gr, j = 0.006 };
        mass ram { m = mb, at = Gb, j = 0.01 };
        gravity (gx, gy);
        force at Pb = (push, 0.5 * push);
        force at B on ram along line = -push;
        torque on ram = twist;
        torque on rod = 0.5 * twist;
    }
}

/// Mistake: the guide's couple dropped (the block's centre is off its pin and
/// it carries a couple, so the couple is large).
fn check_press(
    s: &InclinedPressSolution,
    m: &InclinedPress<f64>,
    l: &InclinedPressLoads,
    w: f64,
    mistake: bool,
) {
    let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
    let grav = Vector2::new(m.gx, m.gy);
    let dir = unit_at(20.0);
    let fp = Vector2::new(l.push, 0.5 * l.push);
    let along = dir * -l.push;
    Body::default()
        .force(p.O, f.r_ground_crank)
        .force(p.A, -f.r_crank_rod)
        .couple(f.drive_theta)
        .balances("crank (massless)");
    Body::default()
        .force(p.A, f.r_crank_rod)
        .force(p.B, -f.r_rod_ram)
        .couple(0.5 * l.twist)
        .inertia(0.7, 0.006, p.Gr, a.Gr, a.rod, grav)
        .balances("rod");
    let guide = if mistake {
        mechanism::force::PrismaticReaction::new(f.r_ground_ram.normal, 0.0, &dir)
    } else {
        f.r_ground_ram
    };
    Body::default()
        .force(p.B, f.r_rod_ram)
        .prismatic(&guide, p.B, 1.0)
        .force(p.Pb, fp)
        .force(p.B, along)
        .couple(l.twist)
        .inertia(m.mb, 0.01, p.Gb, a.Gb, 0.0, grav)
        .balances("ram");
    power_balances(
        &[
            f.drive_theta * w,
            0.5 * l.twist * v.rod,
            fp.dot(&v.Pb),
            along.dot(&v.B),
            inertial(0.7, 0.006, v.Gr, a.Gr, v.rod, a.rod, grav),
            inertial(m.mb, 0.01, v.Gb, a.Gb, 0.0, 0.0, grav),
        ],
        "InclinedPress",
    );
}

#[test]
fn press_block_off_its_pin_with_run_time_mass_and_gravity() {
    let (w, al) = (12.0, 30.0);
    let variants = [
        (InclinedPress::<f64>::default(), 150.0, 4.0),
        (
            InclinedPress::<f64> {
                gx: -5.0,
                gy: 8.0,
                mb: 9.5,
            },
            -80.0,
            -2.5,
        ),
    ];
    for (m, push, twist) in &variants {
        let l = InclinedPressLoads {
            push: *push,
            twist: *twist,
        };
        for k in 0..72 {
            let q = f64::to_radians(5.0 * k as f64 + 2.0);
            let s = m
                .solve(
                    &InclinedPressInput { theta: q },
                    &InclinedPressInput { theta: w },
                    &InclinedPressInput { theta: al },
                    &l,
                )
                .unwrap();
            check_press(&s, m, &l, w, false);
            if k == 5 {
                assert!(fails(|| check_press(&s, m, &l, w, true)));
            }
        }
    }
}

// ---------------------------------------------------------------------------
// 3. RPR (quick return) with an offset slide line, the block's centre off its
//    pin, a couple on the block and on the lever, a force at the block's pin
//    (on the block), the crank's centre at its ground pivot.

mechanism! {
    /// A quick-return lever (m, kg, N).
    pub QuickReturn {
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.0, -0.25);
        let A = crank(O2, 0.1, theta) as crank;
        let s = rpr(A, O4, plus, 0.015) as (block, lever);
        let Gk = point(block, from A, (0.01, -0.008));
        let D = point(lever, from O4, 0.5, 0 deg);
        let Gl = point(lever, from O4, 0.25, 3 deg);
        mass crank { m = 0.5, at = O2, j = 0.002 };
        mass block { m = 0.3, at = Gk, j = 0.0005 };
        mass lever { m = 2.2, at = Gl, j = 0.05 };
        gravity (0.0, -9.81);
        force at D = (-30.0, 5.0);
        force at A on block = (2.0, 1.0);
        torque on block = 0.4;
        torque on lever = -3.0;
    }
}

/// Mistake: the block's centre of mass taken at its pin.
fn check_quick(s: &QuickReturnSolution, w: f64, mistake: bool) {
    let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
    let fd = Vector2::new(-30.0, 5.0);
    let fa = Vector2::new(2.0, 1.0);
    let gk = if mistake { p.A } else { p.Gk };
    Body::default()
        .force(p.O2, f.r_ground_crank)
        .force(p.A, -f.r_crank_block)
        .couple(f.drive_theta)
        .inertia(0.5, 0.002, p.O2, zero(), a.crank, G)
        .balances("crank");
    Body::default()
        .force(p.A, f.r_crank_block)
        .prismatic(&f.r_block_lever, p.A, -1.0)
        .force(p.A, fa)
        .couple(0.4)
        .inertia(0.3, 0.0005, gk, a.Gk, a.block, G)
        .balances("block");
    Body::default()
        .force(p.O4, f.r_ground_lever)
        .prismatic(&f.r_block_lever, p.A, 1.0)
        .force(p.D, fd)
        .couple(-3.0)
        .inertia(2.2, 0.05, p.Gl, a.Gl, a.lever, G)
        .balances("lever");
    power_balances(
        &[
            f.drive_theta * w,
            fd.dot(&v.D),
            fa.dot(&v.A),
            0.4 * v.block,
            -3.0 * v.lever,
            inertial(0.5, 0.002, zero(), zero(), v.crank, a.crank, G),
            inertial(0.3, 0.0005, v.Gk, a.Gk, v.block, a.block, G),
            inertial(2.2, 0.05, v.Gl, a.Gl, v.lever, a.lever, G),
        ],
        "QuickReturn",
    );
    assert!(f.power_residual <= TOL, "{}", f.power_residual);
}

#[test]
fn quick_return_block_off_its_pin_balances() {
    let m = QuickReturn::<f64>::default();
    let (w, al) = (9.0, 15.0);
    let mut checked = 0;
    for k in 0..72 {
        let q = f64::to_radians(5.0 * k as f64 + 0.5);
        let s = m
            .solve(
                &QuickReturnInput { theta: q },
                &QuickReturnInput { theta: w },
                &QuickReturnInput { theta: al },
            )
            .unwrap();
        if s.forces.condition < 0.05 {
            continue;
        }
        checked += 1;
        check_quick(&s, w, false);
        if k == 7 {
            assert!(fails(|| check_quick(&s, w, true)));
        }
    }
    assert!(checked >= 60, "only {checked} of 72 poses checked");
}

// ---------------------------------------------------------------------------
// 4. PRP: one guide carried by the crank at 30 degrees to its axis, the
//    other fixed at 100 degrees; both blocks' centres off the pin; couples on
//    the turning block and on the one that does not turn; a force at the pin
//    on block 1; a force along the fixed guide.

mechanism! {
    /// A skew cross-slide (m, kg, N).
    pub SkewCross {
        dof 1;
        let O = ground(0.0, 0.0);
        let V = ground(0.25, 0.02);
        let g2 = guide(V, 100 deg);
        let A = crank(O, 0.1, phi) as crank;
        let g1 = guide(A, crank, 30 deg);
        let C = prp(g1, g2, 0.005, -0.01) as (b1, b2) slide (s1, s2);
        let Gc = point(crank, from O, 0.03, 0 deg);
        let G1 = point(b1, from C, (0.02, 0.01));
        let G2 = point(b2, from C, (-0.01, 0.03));
        mass crank { m = 0.6, at = Gc, j = 0.001 };
        mass b1 { m = 0.3, at = G1, j = 0.0004 };
        mass b2 { m = 1.1, at = G2, j = 0.003 };
        gravity (0.0, -9.81);
        force at G2 on b2 along g2 = -15.0;
        force at C on b1 = (1.0, -2.0);
        torque on b1 = 0.3;
        torque on b2 = 0.7;
        range phi = (-80 deg, 30 deg);
    }
}

/// Mistake: block 2's couple (it does not turn, so its guide takes it)
/// dropped.
fn check_cross(s: &SkewCrossSolution, w: f64, mistake: bool) {
    let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
    let along = unit_at(100.0) * -15.0;
    let fc = Vector2::new(1.0, -2.0);
    Body::default()
        .force(p.O, f.r_ground_crank)
        .prismatic(&f.r_crank_b1, p.C, -1.0)
        .couple(f.drive_phi)
        .inertia(0.6, 0.001, p.Gc, a.Gc, a.crank, G)
        .balances("crank (carries guide 1)");
    Body::default()
        .prismatic(&f.r_crank_b1, p.C, 1.0)
        .force(p.C, -f.r_b1_b2)
        .force(p.C, fc)
        .couple(0.3)
        .inertia(0.3, 0.0004, p.G1, a.G1, a.crank, G)
        .balances("b1");
    Body::default()
        .force(p.C, f.r_b1_b2)
        .prismatic(&f.r_ground_b2, p.C, 1.0)
        .force(p.G2, along)
        .couple(if mistake { 0.0 } else { 0.7 })
        .inertia(1.1, 0.003, p.G2, a.G2, 0.0, G)
        .balances("b2");
    power_balances(
        &[
            f.drive_phi * w,
            along.dot(&v.G2),
            fc.dot(&v.C),
            0.3 * w,
            inertial(0.6, 0.001, v.Gc, a.Gc, v.crank, a.crank, G),
            inertial(0.3, 0.0004, v.G1, a.G1, v.crank, a.crank, G),
            inertial(1.1, 0.003, v.G2, a.G2, 0.0, 0.0, G),
        ],
        "SkewCross",
    );
    assert!(f.power_residual <= TOL, "{}", f.power_residual);
}

#[test]
fn skew_cross_slide_blocks_off_their_pin_balance() {
    let m = SkewCross::<f64>::default();
    let (w, al) = (4.0, -6.0);
    for k in 0..=44 {
        let q = f64::to_radians(-79.0 + 2.5 * k as f64);
        let s = m
            .solve(
                &SkewCrossInput { phi: q },
                &SkewCrossInput { phi: w },
                &SkewCrossInput { phi: al },
            )
            .unwrap();
        assert!(s.forces.condition > 0.05, "{}", s.forces.condition);
        check_cross(&s, w, false);
        if k == 3 {
            assert!(fails(|| check_cross(&s, w, true)));
        }
    }
}

// ---------------------------------------------------------------------------
// 5. RPP with a moving pin (the crank's tip), a skew slot and an offset
//    guide line: the block's centre off its pin, a point load on the yoke,
//    couples on both (neither turns).

mechanism! {
    /// A skew Scotch yoke (m, kg, N).
    pub SkewYoke {
        dof 1;
        let O = ground(0.0, 0.0);
        let g = guide((0.0, 0.0), 80 deg);
        let A = crank(O, 0.1, phi) as crank;
        let Q = rpp(A, g, -60 deg, 0.02) as (block, yoke) slide (s1, s2);
        let Gb = point(block, from A, (0.01, 0.005));
        let Gy = point(yoke, from Q, (0.03, 0.08));
        let Py = point(yoke, from Q, (-0.05, 0.12));
        mass block { m = 0.2, at = Gb, j = 0.0002 };
        mass yoke { m = 2.5, at = Gy, j = 0.02 };
        gravity (0.0, -9.81);
        force at Py = (4.0, -25.0);
        torque on yoke = 1.1;
        torque on block = -0.2;
    }
}

/// Mistake: the slot's reaction applied to the yoke with the wrong sign of
/// its couple only.
fn check_yoke(s: &SkewYokeSolution, w: f64, mistake: bool) {
    let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
    let fy = Vector2::new(4.0, -25.0);
    let mut slot = f.r_block_yoke;
    if mistake {
        slot.moment = -slot.moment;
    }
    Body::default()
        .force(p.O, f.r_ground_crank)
        .force(p.A, -f.r_crank_block)
        .couple(f.drive_phi)
        .balances("crank (massless)");
    Body::default()
        .force(p.A, f.r_crank_block)
        .prismatic(&f.r_block_yoke, p.A, -1.0)
        .couple(-0.2)
        .inertia(0.2, 0.0002, p.Gb, a.Gb, 0.0, G)
        .balances("block");
    Body::default()
        .prismatic(&slot, p.A, 1.0)
        .prismatic(&f.r_ground_yoke, p.A, 1.0)
        .force(p.Py, fy)
        .couple(1.1)
        .inertia(2.5, 0.02, p.Gy, a.Gy, 0.0, G)
        .balances("yoke");
    power_balances(
        &[
            f.drive_phi * w,
            fy.dot(&v.Py),
            inertial(0.2, 0.0002, v.Gb, a.Gb, 0.0, 0.0, G),
            inertial(2.5, 0.02, v.Gy, a.Gy, 0.0, 0.0, G),
        ],
        "SkewYoke",
    );
    assert!(f.power_residual <= TOL, "{}", f.power_residual);
}

#[test]
fn skew_yoke_with_a_moving_pin_balances() {
    let m = SkewYoke::<f64>::default();
    let (w, al) = (25.0, 100.0);
    for k in 0..72 {
        let q = f64::to_radians(5.0 * k as f64 + 1.5);
        let s = m
            .solve(
                &SkewYokeInput { phi: q },
                &SkewYokeInput { phi: w },
                &SkewYokeInput { phi: al },
            )
            .unwrap();
        check_yoke(&s, w, false);
        if k == 9 {
            assert!(fails(|| check_yoke(&s, w, true)));
        }
    }
}

// ---------------------------------------------------------------------------
// 6. A ternary coupler carrying three joints (A, B and the pin P of a second
//    RRR group) and a point load at a fourth point Q; forces at P on each of
//    its two links; a couple on the last link.

mechanism! {
    /// A Stephenson-type six-bar (m, kg, N).
    pub TernaryCoupler {
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.38, 0.0);
        let O6 = ground(0.2, 0.45);
        let A = crank(O2, 0.08, theta) as crank;
        let B = rrr(A, 0.3, O4, 0.22, left) as (coupler, rocker);
        let P = point(coupler, from A, 0.15, 40 deg);
        let Q = point(coupler, from A, 0.22, -20 deg);
        let E = rrr(P, 0.25, O6, 0.2, right) as (link5, link6);
        let G3 = point(coupler, from A, 0.14, 10 deg);
        let G4 = point(rocker, from O4, 0.1, 0 deg);
        let G5 = point(link5, from P, 0.12, 0 deg);
        let G6 = point(link6, from O6, 0.1, 0 deg);
        mass coupler { m = 1.4, at = G3, j = 0.015 };
        mass rocker { m = 0.8, at = G4, j = 0.004 };
        mass link5 { m = 0.5, at = G5, j = 0.003 };
        mass link6 { m = 0.45, at = G6, j = 0.0025 };
        gravity (0.0, -9.81);
        force at Q = (0.0, -40.0);
        force at P on link5 = (3.0, 3.0);
        force at P on coupler = (-1.0, 4.0);
        torque on link6 = 0.8;
    }
}

/// Mistake: the point load taken at P instead of Q.
fn check_ternary(s: &TernaryCouplerSolution, w: f64, mistake: bool) {
    let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
    let fq = Vector2::new(0.0, -40.0);
    let (f5, f3) = (Vector2::new(3.0, 3.0), Vector2::new(-1.0, 4.0));
    let q = if mistake { p.P } else { p.Q };
    Body::default()
        .force(p.O2, f.r_ground_crank)
        .force(p.A, -f.r_crank_coupler)
        .couple(f.drive_theta)
        .balances("crank (massless)");
    Body::default()
        .force(p.A, f.r_crank_coupler)
        .force(p.B, -f.r_coupler_rocker)
        .force(p.P, -f.r_coupler_link5)
        .force(q, fq)
        .force(p.P, f3)
        .inertia(1.4, 0.015, p.G3, a.G3, a.coupler, G)
        .balances("coupler (ternary)");
    Body::default()
        .force(p.O4, f.r_ground_rocker)
        .force(p.B, f.r_coupler_rocker)
        .inertia(0.8, 0.004, p.G4, a.G4, a.rocker, G)
        .balances("rocker");
    Body::default()
        .force(p.P, f.r_coupler_link5)
        .force(p.E, -f.r_link5_link6)
        .force(p.P, f5)
        .inertia(0.5, 0.003, p.G5, a.G5, a.link5, G)
        .balances("link5");
    Body::default()
        .force(p.O6, f.r_ground_link6)
        .force(p.E, f.r_link5_link6)
        .couple(0.8)
        .inertia(0.45, 0.0025, p.G6, a.G6, a.link6, G)
        .balances("link6");
    power_balances(
        &[
            f.drive_theta * w,
            fq.dot(&v.Q),
            (f5 + f3).dot(&v.P),
            0.8 * v.link6,
            inertial(1.4, 0.015, v.G3, a.G3, v.coupler, a.coupler, G),
            inertial(0.8, 0.004, v.G4, a.G4, v.rocker, a.rocker, G),
            inertial(0.5, 0.003, v.G5, a.G5, v.link5, a.link5, G),
            inertial(0.45, 0.0025, v.G6, a.G6, v.link6, a.link6, G),
        ],
        "TernaryCoupler",
    );
    assert!(f.power_residual <= TOL, "{}", f.power_residual);
}

#[test]
fn ternary_coupler_with_a_point_load_balances() {
    let m = TernaryCoupler::<f64>::default();
    let (w, al) = (6.0, 10.0);
    let mut checked = 0;
    for k in 0..72 {
        let q = f64::to_radians(5.0 * k as f64 + 0.5);
        let s = m
            .solve(
                &TernaryCouplerInput { theta: q },
                &TernaryCouplerInput { theta: w },
                &TernaryCouplerInput { theta: al },
            )
            .unwrap();
        if s.forces.condition < 0.05 {
            continue;
        }
        checked += 1;
        check_ternary(&s, w, false);
        if k == 12 {
            assert!(fails(|| check_ternary(&s, w, true)));
        }
    }
    assert!(checked >= 60, "only {checked} of 72 poses checked");
}

// ---------------------------------------------------------------------------
// 7. Two cranks (a five-bar): two driving torques, loads on both sides, a
//    force at the tip of one crank (on that crank), at the middle joint on
//    link 4, couples on both cranks.

mechanism! {
    /// A loaded five-bar with two motors (m, kg, N).
    pub TwinMotor {
        dof 2;
        let O1 = ground(0.0, 0.0);
        let O2 = ground(0.2, 0.0);
        let A = crank(O1, 0.06, t1) as left_crank;
        let B = crank(O2, 0.06, t2) as right_crank;
        let C = rrr(A, 0.2, B, 0.2, left) as (l3, l4);
        let G1 = point(left_crank, from O1, 0.03, 0 deg);
        let G2 = point(right_crank, from O2, 0.03, 0 deg);
        let G3 = point(l3, from A, 0.1, 0 deg);
        let G4 = point(l4, from B, 0.1, 0 deg);
        mass left_crank { m = 0.3, at = G1, j = 0.0002 };
        mass right_crank { m = 0.35, at = G2, j = 0.00025 };
        mass l3 { m = 0.5, at = G3, j = 0.002 };
        mass l4 { m = 0.55, at = G4, j = 0.0022 };
        gravity (0.0, -9.81);
        force at C on l4 = (10.0, -20.0);
        force at B on right_crank = (-4.0, 2.0);
        torque on left_crank = -0.7;
        torque on right_crank = 0.4;
    }
}

/// Mistake: the two driving torques swapped.
fn check_twin(s: &TwinMotorSolution, w: (f64, f64), mistake: bool) {
    let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
    let (fc, fb) = (Vector2::new(10.0, -20.0), Vector2::new(-4.0, 2.0));
    let (d1, d2) = if mistake {
        (f.drive_t2, f.drive_t1)
    } else {
        (f.drive_t1, f.drive_t2)
    };
    Body::default()
        .force(p.O1, f.r_ground_left_crank)
        .force(p.A, -f.r_left_crank_l3)
        .couple(d1)
        .couple(-0.7)
        .inertia(0.3, 0.0002, p.G1, a.G1, a.left_crank, G)
        .balances("left crank");
    Body::default()
        .force(p.O2, f.r_ground_right_crank)
        .force(p.B, -f.r_right_crank_l4)
        .force(p.B, fb)
        .couple(d2)
        .couple(0.4)
        .inertia(0.35, 0.00025, p.G2, a.G2, a.right_crank, G)
        .balances("right crank");
    Body::default()
        .force(p.A, f.r_left_crank_l3)
        .force(p.C, -f.r_l3_l4)
        .inertia(0.5, 0.002, p.G3, a.G3, a.l3, G)
        .balances("l3");
    Body::default()
        .force(p.B, f.r_right_crank_l4)
        .force(p.C, f.r_l3_l4)
        .force(p.C, fc)
        .inertia(0.55, 0.0022, p.G4, a.G4, a.l4, G)
        .balances("l4");
    power_balances(
        &[
            f.drive_t1 * w.0,
            f.drive_t2 * w.1,
            -0.7 * w.0,
            0.4 * w.1,
            fc.dot(&v.C),
            fb.dot(&v.B),
            inertial(0.3, 0.0002, v.G1, a.G1, v.left_crank, a.left_crank, G),
            inertial(0.35, 0.00025, v.G2, a.G2, v.right_crank, a.right_crank, G),
            inertial(0.5, 0.002, v.G3, a.G3, v.l3, a.l3, G),
            inertial(0.55, 0.0022, v.G4, a.G4, v.l4, a.l4, G),
        ],
        "TwinMotor",
    );
    assert!(f.power_residual <= TOL, "{}", f.power_residual);
}

#[test]
fn five_bar_with_two_motors_balances() {
    let m = TwinMotor::<f64>::default();
    let (w, al) = ((5.0, -3.0), (20.0, 8.0));
    let mut checked = 0;
    for k in 0..144 {
        let (q1, q2) = (
            f64::to_radians(5.0 * k as f64 + 1.0),
            f64::to_radians(-7.0 * k as f64 + 40.0),
        );
        let s = m
            .solve(
                &TwinMotorInput { t1: q1, t2: q2 },
                &TwinMotorInput { t1: w.0, t2: w.1 },
                &TwinMotorInput { t1: al.0, t2: al.1 },
            )
            .unwrap();
        if s.forces.condition < 0.05 {
            continue;
        }
        checked += 1;
        check_twin(&s, w, false);
        if k == 3 {
            assert!(fails(|| check_twin(&s, w, true)));
        }
    }
    assert!(checked >= 120, "only {checked} of 144 poses checked");
}

// ---------------------------------------------------------------------------
// 8. A crank and a slider (two inputs of different kinds): a driving torque
//    and a driving force; gravity along the inclined slide (from params),
//    the slider's mass from params; `loads` in two forces and a couple.

mechanism! {
    /// A crank and an inclined piston joined by an RRR (m, kg, N).
    pub CrankAndPiston {
        dof 2;
        params { g = 9.81, mp = 0.8 }
        loads { cut = 0.0, hold = 0.0 }
        let O = ground(0.0, 0.0);
        let line = guide((0.3, -0.1), 30 deg);
        let P = slider(line, s) as piston;
        let A = crank(O, 0.08, theta) as crank;
        let C = rrr(A, 0.3, P, 0.25, left) as (l3, l4);
        let Gp = point(piston, from P, (0.02, -0.01));
        let G3 = point(l3, from A, 0.15, 0 deg);
        let G4 = point(l4, from P, 0.1, 0 deg);
        mass piston { m = mp, at = Gp, j = 0.001 };
        mass l3 { m = 0.4, at = G3, j = 0.003 };
        mass l4 { m = 0.35, at = G4, j = 0.002 };
        mass crank { m = 0.2, at = A };
        gravity (g * 0.8660254037844386, g * 0.5);
        force at P on piston along line = -cut;
        force at C on l3 = (hold, -cut);
        torque on crank = -hold;
        range s = (-0.1, 0.1);
    }
}

/// Mistake: the piston's weight left out (gravity along the slide: the
/// drive takes all of it).
fn check_crank_piston(
    s: &CrankAndPistonSolution,
    m: &CrankAndPiston<f64>,
    l: &CrankAndPistonLoads,
    r: &CrankAndPistonInput,
    mistake: bool,
) {
    let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
    let dir = unit_at(30.0);
    let grav = dir * m.g;
    let along = dir * -l.cut;
    let fc = Vector2::new(l.hold, -l.cut);
    let gp = if mistake { zero() } else { grav };
    Body::default()
        .prismatic(&f.r_ground_piston, p.P, 1.0)
        .force(p.P, dir * f.drive_s)
        .force(p.P, -f.r_piston_l4)
        .force(p.P, along)
        .inertia(m.mp, 0.001, p.Gp, a.Gp, 0.0, gp)
        .balances("piston");
    Body::default()
        .force(p.O, f.r_ground_crank)
        .force(p.A, -f.r_crank_l3)
        .couple(f.drive_theta)
        .couple(-l.hold)
        .inertia(0.2, 0.0, p.A, a.A, 0.0, grav)
        .balances("crank");
    Body::default()
        .force(p.A, f.r_crank_l3)
        .force(p.C, -f.r_l3_l4)
        .force(p.C, fc)
        .inertia(0.4, 0.003, p.G3, a.G3, a.l3, grav)
        .balances("l3");
    Body::default()
        .force(p.P, f.r_piston_l4)
        .force(p.C, f.r_l3_l4)
        .inertia(0.35, 0.002, p.G4, a.G4, a.l4, grav)
        .balances("l4");
    power_balances(
        &[
            f.drive_theta * r.theta,
            f.drive_s * r.s,
            -l.hold * r.theta,
            along.dot(&v.P),
            fc.dot(&v.C),
            inertial(m.mp, 0.001, v.Gp, a.Gp, 0.0, 0.0, grav),
            inertial(0.2, 0.0, v.A, a.A, 0.0, 0.0, grav),
            inertial(0.4, 0.003, v.G3, a.G3, v.l3, a.l3, grav),
            inertial(0.35, 0.002, v.G4, a.G4, v.l4, a.l4, grav),
        ],
        "CrankAndPiston",
    );
    assert!(f.power_residual <= TOL, "{}", f.power_residual);
}

#[test]
fn crank_and_piston_two_drives_with_gravity_along_the_slide() {
    let r = CrankAndPistonInput { theta: 4.0, s: 0.3 };
    let acc = CrankAndPistonInput {
        theta: -10.0,
        s: 2.0,
    };
    let variants = [
        (CrankAndPiston::<f64>::default(), 35.0, 2.0),
        (CrankAndPiston::<f64> { g: 3.7, mp: 6.0 }, -12.0, 0.0),
    ];
    let mut checked = 0;
    for (m, cut, hold) in &variants {
        let l = CrankAndPistonLoads {
            cut: *cut,
            hold: *hold,
        };
        for k in 0..72 {
            for j in 0..5 {
                let q = CrankAndPistonInput {
                    theta: f64::to_radians(5.0 * k as f64 + 0.5),
                    s: -0.1 + 0.05 * j as f64,
                };
                let s = m.solve(&q, &r, &acc, &l).unwrap();
                if s.forces.condition < 0.05 {
                    continue;
                }
                checked += 1;
                check_crank_piston(&s, m, &l, &r, false);
                if k == 4 && j == 2 {
                    assert!(fails(|| check_crank_piston(&s, m, &l, &r, true)));
                }
            }
        }
    }
    assert!(checked >= 600, "only {checked} of 720 poses checked");
}

// ---------------------------------------------------------------------------
// 9. An actuator-driven boom that also drives a coupled RRR group (a four-bar
//    whose input link is the boom), and a stick driven by a second actuator
//    whose pivot E and base F both ride on the boom.

mechanism! {
    /// A two-cylinder arm (m, kg, N).
    pub TwoCylinderArm {
        dof 2;
        let A = ground(0.0, 0.0);
        let B = ground(0.6, -0.3);
        let O6 = ground(1.2, -0.3);
        let C = actuator(A, 1.0, B, len1, left) as (boom, cyl1);
        let E = point(boom, from A, 2.0, 0 deg);
        let F = point(boom, from A, 1.4, 12 deg);
        let D = point(boom, from A, 0.8, -15 deg);
        let H = actuator(E, 0.4, F, len2, right) as (stick, cyl2);
        let Tip = point(stick, from E, 1.2, 20 deg);
        let K = rrr(D, 0.8, O6, 0.7, right) as (link5, link6);
        let Gb = point(boom, from A, 1.1, 4 deg);
        let Gs = point(stick, from E, 0.5, 10 deg);
        let G5 = point(link5, from D, 0.35, 0 deg);
        let G6 = point(link6, from O6, 0.3, 0 deg);
        mass boom { m = 150.0, at = Gb, j = 50.0 };
        mass stick { m = 60.0, at = Gs, j = 8.0 };
        mass link5 { m = 12.0, at = G5, j = 0.5 };
        mass link6 { m = 10.0, at = G6, j = 0.3 };
        gravity (0.0, -9.81);
        force at Tip = (200.0, -3000.0);
        torque on link6 = 50.0;
        range len1 = (0.9, 1.3);
        range len2 = (0.45, 0.8);
    }
}

/// Mistake: the second cylinder's reaction on the boom (at its base F) left
/// out.
fn check_arm(s: &TwoCylinderArmSolution, r: &TwoCylinderArmInput, mistake: bool) {
    let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
    let ft = Vector2::new(200.0, -3000.0);
    let u1 = (p.C - p.B) / (p.C - p.B).norm();
    let u2 = (p.H - p.F) / (p.H - p.F).norm();
    let base = if mistake { zero() } else { -u2 * f.drive_len2 };
    Body::default()
        .force(p.A, f.r_ground_boom)
        .force(p.C, u1 * f.drive_len1)
        .force(p.E, -f.r_boom_stick)
        .force(p.F, base)
        .force(p.D, -f.r_boom_link5)
        .inertia(150.0, 50.0, p.Gb, a.Gb, a.boom, G)
        .balances("boom");
    Body::default()
        .force(p.E, f.r_boom_stick)
        .force(p.H, u2 * f.drive_len2)
        .force(p.Tip, ft)
        .inertia(60.0, 8.0, p.Gs, a.Gs, a.stick, G)
        .balances("stick");
    Body::default()
        .force(p.D, f.r_boom_link5)
        .force(p.K, -f.r_link5_link6)
        .inertia(12.0, 0.5, p.G5, a.G5, a.link5, G)
        .balances("link5");
    Body::default()
        .force(p.O6, f.r_ground_link6)
        .force(p.K, f.r_link5_link6)
        .couple(50.0)
        .inertia(10.0, 0.3, p.G6, a.G6, a.link6, G)
        .balances("link6");
    power_balances(
        &[
            f.drive_len1 * r.len1,
            f.drive_len2 * r.len2,
            ft.dot(&v.Tip),
            50.0 * v.link6,
            inertial(150.0, 50.0, v.Gb, a.Gb, v.boom, a.boom, G),
            inertial(60.0, 8.0, v.Gs, a.Gs, v.stick, a.stick, G),
            inertial(12.0, 0.5, v.G5, a.G5, v.link5, a.link5, G),
            inertial(10.0, 0.3, v.G6, a.G6, v.link6, a.link6, G),
        ],
        "TwoCylinderArm",
    );
    assert!(f.power_residual <= TOL, "{}", f.power_residual);
}

#[test]
fn boom_with_a_coupled_group_and_a_riding_cylinder_balances() {
    let m = TwoCylinderArm::<f64>::default();
    let r = TwoCylinderArmInput {
        len1: 0.05,
        len2: -0.08,
    };
    let acc = TwoCylinderArmInput {
        len1: 0.2,
        len2: 0.4,
    };
    let mut checked = 0;
    for i in 0..=8 {
        for j in 0..=7 {
            let q = TwoCylinderArmInput {
                len1: 0.9 + 0.05 * i as f64,
                len2: 0.45 + 0.05 * j as f64,
            };
            let s = m.solve(&q, &r, &acc).unwrap();
            if s.forces.condition < 0.05 {
                continue;
            }
            checked += 1;
            check_arm(&s, &r, false);
            if i == 4 && j == 3 {
                assert!(fails(|| check_arm(&s, &r, true)));
            }
        }
    }
    assert!(checked >= 60, "only {checked} of 72 poses checked");
}

// ---------------------------------------------------------------------------
// 10. f32 powers that overflow: a finite 1e38 N force at a tip moving at
//     10 m/s has a power of 1e39 W, beyond f32; the reactions are finite,
//     so the result is `Ok` and its residual must be a number (1: no
//     balance can be shown), not NaN.

mechanism! {
    /// A crank with a huge load (m, N).
    pub HugeLoad {
        dof 1;
        loads { f = 0.0 }
        let O = ground(0.0, 0.0);
        let A = crank(O, 0.1, th) as crank;
        force at A = (f, f);
    }
}

#[test]
fn overflowing_f32_powers_give_a_residual_not_nan() {
    let m = HugeLoad::<f32>::default();
    // (force, speed, whether a power overflows f32): 1e38 N at 100 rad/s
    // on a 0.1 crank is 1e39 W; 1e30 N at 1 rad/s is 1e29 W, finite.
    for (f, w, overflows) in [
        (1e38f32, 100.0f32, true),
        (3.4e38, 3e15, true),
        (1e30, 1.0, false),
    ] {
        let s = m
            .solve(
                &HugeLoadInput { th: 0.5 },
                &HugeLoadInput { th: w },
                &HugeLoadInput { th: 0.0 },
                &HugeLoadLoads { f },
            )
            .unwrap();
        let r = s.forces.power_residual;
        if overflows {
            // No balance can be shown: 1, never NaN.
            assert_eq!(r, 1.0, "f = {f}, w = {w}");
        } else {
            // The drive balances the load's moment: its power is the
            // load's with the opposite sign, so the residual is a few f32
            // eps (1.2e-7) of the largest term: 8 eps leaves room for the
            // two products and the sum.
            assert!(r <= 1e-6, "f = {f}, w = {w}: {r}");
        }
    }
}

// ---------------------------------------------------------------------------
// 11. A slider driven along a guide carried by a crank (two inputs): the
//     slider's guide reaction and its drive's reaction load the crank.

mechanism! {
    /// A telescopic arm (m, kg, N): a block driven along the crank's line.
    pub Telescope {
        dof 2;
        let O = ground(0.0, 0.0);
        let A = crank(O, 0.1, th) as crank;
        let line = guide(A, crank, 10 deg);
        let P = slider(line, s, 0.01) as block;
        let Gb = point(block, from P, (0.01, 0.02));
        let Gc = point(crank, from O, 0.05, 0 deg);
        mass block { m = 1.2, at = Gb, j = 0.01 };
        mass crank { m = 0.9, at = Gc, j = 0.004 };
        gravity (0.0, -9.81);
        force at Gb on block = (3.0, 4.0);
        force at P on block along line = -6.0;
        torque on block = 0.25;
        range s = (0.0, 0.2);
    }
}

/// Mistake: the block's couple (it turns with the crank) dropped.
fn check_telescope(s: &TelescopeSolution, r: &TelescopeInput, mistake: bool) {
    let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
    let dir = unit_at(p.crank.to_degrees() + 10.0);
    let (fg, along) = (Vector2::new(3.0, 4.0), dir * -6.0);
    Body::default()
        .force(p.O, f.r_ground_crank)
        .prismatic(&f.r_crank_block, p.P, -1.0)
        .force(p.P, dir * -f.drive_s)
        .couple(f.drive_th)
        .inertia(0.9, 0.004, p.Gc, a.Gc, a.crank, G)
        .balances("crank (carries the line)");
    Body::default()
        .prismatic(&f.r_crank_block, p.P, 1.0)
        .force(p.P, dir * f.drive_s)
        .force(p.Gb, fg)
        .force(p.P, along)
        .couple(if mistake { 0.0 } else { 0.25 })
        .inertia(1.2, 0.01, p.Gb, a.Gb, a.crank, G)
        .balances("block");
    power_balances(
        &[
            f.drive_th * r.th,
            f.drive_s * r.s,
            fg.dot(&v.Gb),
            along.dot(&v.P),
            0.25 * r.th,
            inertial(0.9, 0.004, v.Gc, a.Gc, v.crank, a.crank, G),
            inertial(1.2, 0.01, v.Gb, a.Gb, v.crank, a.crank, G),
        ],
        "Telescope",
    );
    assert!(f.power_residual <= TOL, "{}", f.power_residual);
}

#[test]
fn slider_on_a_carried_guide_loads_the_crank() {
    let m = Telescope::<f64>::default();
    let r = TelescopeInput { th: 3.0, s: -0.4 };
    let acc = TelescopeInput { th: 5.0, s: 1.5 };
    for k in 0..72 {
        for j in 0..=4 {
            let q = TelescopeInput {
                th: f64::to_radians(5.0 * k as f64 + 0.5),
                s: 0.05 * j as f64,
            };
            let s = m.solve(&q, &r, &acc).unwrap();
            check_telescope(&s, &r, false);
            if k == 1 && j == 1 {
                assert!(fails(|| check_telescope(&s, &r, true)));
            }
        }
    }
}

// ---------------------------------------------------------------------------
// 12. Extreme but valid numbers: t, mm, s (forces in N, moments in N mm),
//     masses from 1e-9 t (1e-6 kg) to 1e3 t (1e6 kg) in one slider-crank.

mechanism! {
    /// A heavy ram behind a feather-light crank (t, mm, s).
    pub MillimetreRam {
        dof 1;
        let O = ground(0.0, 0.0);
        let line = guide((0.0, 10.0), 0 deg);
        let A = crank(O, 50.0, theta) as crank;
        let B = rrp(A, 200.0, line, plus) as (rod, ram) slide x;
        let Gr = point(rod, from A, 80.0, 0 deg);
        let Gb = point(ram, from B, (15.0, 10.0));
        mass crank { m = 1e-9, at = A, j = 1e-6 };
        mass rod { m = 1e-3, at = Gr, j = 3.0 };
        mass ram { m = 1e3, at = Gb, j = 1e5 };
        gravity (0.0, -9810.0);
        force at B on ram along line = -5000.0;
    }
}

/// Mistake: the ram's centre of mass taken at its pin.
fn check_mm(s: &MillimetreRamSolution, w: f64, mistake: bool) {
    let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
    let g = Vector2::new(0.0, -9810.0);
    let along = Vector2::new(-5000.0, 0.0);
    let gb = if mistake { p.B } else { p.Gb };
    Body::default()
        .force(p.O, f.r_ground_crank)
        .force(p.A, -f.r_crank_rod)
        .couple(f.drive_theta)
        .inertia(1e-9, 1e-6, p.A, a.A, a.crank, g)
        .balances("crank (1e-6 kg)");
    // The RRP's system mixes the ram's load (1e7 N of weight, 1e9 N mm of
    // moment) into the rows that give the rod's reactions (700 N), which
    // therefore carry rounding of eps times the group's largest load, not
    // the rod's (measured 4.6e-13 of the rod's own scale). The opposite pair
    // below adds that scale to the rod's check and nothing to its sums.
    let ram_load = Vector2::new(0.0, 1e3 * 9810.0);
    Body::default()
        .force(p.A, f.r_crank_rod)
        .force(p.B, -f.r_rod_ram)
        .force(p.Gb, ram_load)
        .force(p.Gb, -ram_load)
        .inertia(1e-3, 3.0, p.Gr, a.Gr, a.rod, g)
        .balances("rod (1 kg)");
    Body::default()
        .force(p.B, f.r_rod_ram)
        .prismatic(&f.r_ground_ram, p.B, 1.0)
        .force(p.B, along)
        .inertia(1e3, 1e5, gb, a.Gb, 0.0, g)
        .balances("ram (1e6 kg)");
    // The power balance near the crank's dead centres: the drive torque is
    // the small difference of moments of the rod's force (1e5 N here)
    // about O, so its relative rounding grows as 1 / s, s = |sin| of the
    // angle between crank and rod (s = 0.09 at 5 deg past bottom dead
    // centre gives 530 eps, measured). `TOL / s` keeps the check as tight
    // as the equilibria elsewhere; the generated residual obeys the same.
    let s_lever = cross(&((p.A - p.O) / 50.0), &((p.B - p.A) / 200.0)).abs();
    let tol = TOL / s_lever.max(1e-3);
    let terms = [
        f.drive_theta * w,
        along.dot(&v.B),
        inertial(1e-9, 1e-6, v.A, a.A, v.crank, a.crank, g),
        inertial(1e-3, 3.0, v.Gr, a.Gr, v.rod, a.rod, g),
        inertial(1e3, 1e5, v.Gb, a.Gb, 0.0, 0.0, g),
    ];
    let scale = terms.iter().fold(0.0f64, |m, t| m.max(t.abs()));
    let sum: f64 = terms.iter().sum();
    assert!(
        sum.abs() <= tol * scale,
        "power residual {sum:e} of {scale:e}"
    );
    assert!(f.power_residual <= tol, "{}", f.power_residual);
}

#[test]
fn masses_from_a_milligram_to_a_thousand_tonnes_in_mm() {
    let m = MillimetreRam::<f64>::default();
    let (w, al) = (3.0, -2.0);
    for k in 0..72 {
        let q = f64::to_radians(5.0 * k as f64 + 0.25);
        let s = m
            .solve(
                &MillimetreRamInput { theta: q },
                &MillimetreRamInput { theta: w },
                &MillimetreRamInput { theta: al },
            )
            .unwrap();
        check_mm(&s, w, false);
        if k == 11 {
            assert!(fails(|| check_mm(&s, w, true)));
        }
    }
}

// ---------------------------------------------------------------------------
// 13. Towards a singular force system: a four-bar whose crank approaches the
//     angle where coupler and rocker align (the limit of its motion). The
//     reactions grow as 1 / sin of the angle between them; the generated ones
//     must match a closed form derived here to about eps / condition of the
//     largest, or be a typed error; never NaN.

mechanism! {
    /// A double-rocker (m, N) loaded statically at a coupler point and by a
    /// couple on the rocker.
    pub NearToggle {
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.4, 0.0);
        let A = crank(O2, 0.25, theta) as crank;
        let B = rrr(A, 0.3, O4, 0.2, left) as (coupler, rocker);
        let P = point(coupler, from A, 0.15, 30 deg);
        force at P = (5.0, -12.0);
        torque on rocker = 1.5;
        range theta = (-60 deg, 60 deg);
    }
}

/// `(force of the crank on the coupler at A, force of the ground on the
/// rocker at O4)` from each link's moment about B (the components across
/// the links) and the group's force balance (the components along them, a
/// 2x2 system whose determinant is the sine between the links).
fn toggle_reference(p: &NearTogglePosition) -> (Vector2<f64>, Vector2<f64>) {
    let f = Vector2::new(5.0, -12.0);
    let perp = |u: Vector2<f64>| Vector2::new(-u.y, u.x);
    let (l1, l2) = ((p.B - p.A).norm(), (p.B - p.O4).norm());
    let (u1, u2) = ((p.B - p.A) / l1, (p.B - p.O4) / l2);
    // Coupler about B: cross(A - B, F_A) + cross(P - B, f) = 0, with
    // cross(A - B, beta n1) = -l1 beta.
    let beta = cross(&(p.P - p.B), &f) / l1;
    // Rocker about B: cross(O4 - B, F_O4) + 1.5 = 0.
    let delta = 1.5 / l2;
    let h = -f - perp(u1) * beta - perp(u2) * delta;
    let det = cross(&u1, &u2);
    let (alpha, gamma) = (cross(&h, &u2) / det, cross(&u1, &h) / det);
    (u1 * alpha + perp(u1) * beta, u2 * gamma + perp(u2) * delta)
}

#[test]
fn near_toggle_reactions_are_accurate_to_eps_over_condition() {
    let m = NearToggle::<f64>::default();
    let zero_rates = NearToggleInput { theta: 0.0 };
    let at = |q: f64| m.position(&NearToggleInput { theta: q });
    // The limit: the largest angle that assembles, by bisection (it is near
    // 97.9 deg: |A - O4| = 0.5 there).
    let (mut lo, mut hi) = (1.5, 2.0);
    assert!(at(lo).is_ok() && at(hi).is_err());
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if at(mid).is_ok() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let mut worst = 0.0f64;
    let mut smallest_condition = 1.0f64;
    for k in 1..=16 {
        let q = lo - 10f64.powi(-k);
        let q = if k == 16 { lo } else { q };
        let pos = at(q).unwrap();
        let result = m.velocity(&pos, &zero_rates).and_then(|vel| {
            let acc = m.acceleration(&pos, &vel, &zero_rates)?;
            m.forces(&pos, &vel, &acc)
        });
        let f = match result {
            Ok(f) => f,
            // A typed error naming the group or the crank is an answer.
            Err(e) => {
                let text = e.to_string();
                assert!(text.contains('B') || text.contains('A'), "{text}");
                continue;
            }
        };
        let (fa, fo4) = toggle_reference(&pos);
        let scale = fa.norm().max(fo4.norm());
        let err = (f.r_crank_coupler - fa)
            .norm()
            .max((f.r_ground_rocker - fo4).norm())
            .max((f.r_coupler_rocker + f.r_ground_rocker).norm());
        assert!(f.condition > 0.0 && f.condition <= 1.0, "{}", f.condition);
        // Both answers carry rounding of a few eps amplified by 1 / condition
        // (the reference through its 2x2 determinant, the generated code
        // through its pivots); 64 eps / condition covers both with room, and
        // a wrong term is off by the scale itself.
        let ratio = err / (scale * f64::EPSILON / f.condition);
        worst = worst.max(ratio);
        smallest_condition = smallest_condition.min(f.condition);
        assert!(
            ratio <= 64.0,
            "k = {k}: error {err:e} of {scale:e}, condition {:e}",
            f.condition
        );
        assert!(f.power_residual.is_finite());
    }
    println!("near toggle: worst error {worst:.1} eps / condition, smallest condition {smallest_condition:e}");
    assert!(smallest_condition < 1e-5, "{smallest_condition}");
}

// ---------------------------------------------------------------------------
// 14. f32 against f64 on the shared-joint four-bar and the inclined press.

#[test]
fn f32_matches_f64() {
    let (m64, m32) = (SharedJoint::<f64>::default(), SharedJoint::<f32>::default());
    let mut worst = 0.0f64;
    for k in 0..72 {
        let q = 5.0 * k as f64 + 1.0;
        let s64 = m64
            .solve(
                &SharedJointInput {
                    theta: q.to_radians(),
                },
                &SharedJointInput { theta: 7.0 },
                &SharedJointInput { theta: -20.0 },
            )
            .unwrap();
        if s64.forces.condition < 0.2 {
            continue;
        }
        let s32 = m32
            .solve(
                &SharedJointInput {
                    theta: (q as f32).to_radians(),
                },
                &SharedJointInput { theta: 7.0 },
                &SharedJointInput { theta: -20.0 },
            )
            .unwrap();
        let (a, b) = (&s64.forces, &s32.forces);
        let w = |v: Vector2<f32>| Vector2::new(v.x as f64, v.y as f64);
        let pairs = [
            (a.r_ground_crank, w(b.r_ground_crank)),
            (a.r_crank_coupler, w(b.r_crank_coupler)),
            (a.r_coupler_rocker, w(b.r_coupler_rocker)),
            (a.r_ground_rocker, w(b.r_ground_rocker)),
            (
                Vector2::new(a.drive_theta, 0.0),
                Vector2::new(b.drive_theta as f64, 0.0),
            ),
        ];
        let scale = pairs.iter().fold(0.0f64, |m, (x, _)| m.max(x.norm()));
        let err = pairs.iter().fold(0.0f64, |m, (x, y)| m.max((x - y).norm()));
        worst = worst.max(err / scale);
        assert!(
            b.power_residual <= 1e-5,
            "f32 power residual {}",
            b.power_residual
        );
    }
    println!("f32 vs f64: worst {worst:e} of the largest reaction");
    // f32 rounding (6e-8) of the pose, the rates and the loads, amplified by
    // the two systems' conditioning (>= 0.2 here): measured 1e-6 at worst;
    // 2e-5 (170 f32 eps) leaves room, and any wrong term is 1e-3 or more.
    assert!(worst <= 2e-5, "{worst:e}");
}

// ---------------------------------------------------------------------------
// 14. The force result's `condition` at parallel guides, in any frame; masses
//     and moments of inertia given at run time are checked.

mechanism! {
    /// Two blocks joined at `C`: one on a line turning with the crank, one
    /// on a fixed guide through `G = (gx, gy)` at `gangle`; the whole
    /// drawing turned by `rot` (enter the crank angle plus `rot`, and `G`
    /// turned). m, kg, N.
    pub TurnedCross {
        params { gx = 0.3, gy = 0.0, gangle = 0.0, rot = 0.0 }
        let O = ground(0.0, 0.0);
        let G = ground(gx, gy);
        let fixed_line = guide(G, gangle + rot);
        let A = crank(O, 0.1, th) as crank_link;
        let rod_line = guide(O, crank_link);
        let C = prp(rod_line, fixed_line) as (block1, block2);
        mass block1 { m = 1.0, at = C };
        mass block2 { m = 2.0, at = C };
        force at C on block2 = (5.0, -3.0);
    }
}

/// Towards parallel guides the PRP's reactions grow as `1 / delta` (`delta`
/// the angle between the guides), and `condition` must say so in every
/// frame. With the guides along the x axis the force solve's row-scaled
/// pivots do not see it (the x balance's entries all vanish together and the
/// row scaling lifts them back to 1): before the velocity's indicator was
/// folded in, `condition` read 1.0 there at `delta = 1e-9` while the
/// reactions were 1e9 times the loads. The velocity's indicator is `|sin
/// delta|` of the guides' unit directions, so the forces' must be at most
/// that (to the rounding of the directions, a few eps relative: 1e-6 of
/// `delta` is far above that and far below the 1 it read), the same in a
/// frame turned by 0.7 rad, and the reactions must be of the size `F /
/// delta` they are (a factor of 4 either way: the load's component along
/// the guides over `sin delta`).
#[test]
fn forces_condition_falls_at_parallel_guides_in_any_frame() {
    for delta in [1e-3, 1e-6, 1e-9] {
        let mut conditions = Vec::new();
        for rot in [0.0f64, 0.7] {
            // The fixed guide passes through the crank's pivot, so `C`
            // stays at `O` and the loads stay the same as the guides turn
            // parallel: only the reactions grow.
            let m = TurnedCross::<f64> {
                gx: 0.3 * rot.cos(),
                gy: 0.3 * rot.sin(),
                rot,
                ..Default::default()
            };
            let s = m
                .solve(
                    &TurnedCrossInput { th: rot + delta },
                    &TurnedCrossInput { th: 1.0 },
                    &TurnedCrossInput { th: 0.0 },
                )
                .unwrap();
            let c = s.forces.condition;
            assert!(
                c <= delta * (1.0 + 1e-6),
                "rot {rot} delta {delta:e}: condition {c:e}"
            );
            let n = s.forces.r_ground_block2.normal.abs();
            assert!(
                n > 0.25 * 5.0 / delta && n < 4.0 * 5.0 / delta,
                "rot {rot} delta {delta:e}: normal {n:e}"
            );
            conditions.push(c);
        }
        let (a, b) = (conditions[0], conditions[1]);
        assert!(
            (a - b).abs() <= 1e-6 * a,
            "delta {delta:e}: {a:e} against {b:e} turned"
        );
    }
}

mechanism! {
    /// A crank and an RRR with run-time masses and moments of inertia
    /// (m, kg).
    pub RunTimeMasses {
        params { m2 = 1.0, j2 = 0.01, m3 = 2.0, j3 = 0.0 }
        let O = ground(0.0, 0.0);
        let Q = ground(1.0, 0.0);
        let A = crank(O, 0.3, th) as crank_link;
        let B = rrr(A, 1.0, Q, 0.8, left) as (coupler, rocker);
        let G3 = point(coupler, from A, (0.5, 0.0));
        mass crank_link { m = m2, at = A, j = j2 };
        mass coupler { m = m3, at = G3, j = j3 };
        gravity (0.0, -9.81);
    }
}

/// A literal mass that is not positive is a compile error; one from `params`
/// must be a run-time error naming the group that creates the link: a
/// negative mass gives finite, balanced and wrong reactions (unchecked, `m =
/// -1` returns `Ok` with a power residual of 1e-16). Zero is not a mass
/// (leave the statement out), a moment of inertia may be zero, and NaN is
/// `NonFinite`.
#[test]
fn run_time_masses_and_inertias_are_checked() {
    use mechanism::{Fault, Primitive};
    let solve = |m: RunTimeMasses<f64>| {
        m.solve(
            &RunTimeMassesInput { th: 1.0 },
            &RunTimeMassesInput { th: 2.0 },
            &RunTimeMassesInput { th: 0.5 },
        )
    };
    let base = RunTimeMasses::<f64>::default();
    assert!(solve(base).is_ok());
    let zero_inertia = RunTimeMasses { j2: 0.0, ..base };
    assert!(solve(zero_inertia).is_ok());
    let cases = [
        (RunTimeMasses { m3: -1.0, ..base }, "B", Primitive::Rrr),
        (RunTimeMasses { m3: 0.0, ..base }, "B", Primitive::Rrr),
        (RunTimeMasses { m2: -1e-30, ..base }, "A", Primitive::Crank),
        (
            RunTimeMasses {
                m2: f64::NAN,
                ..base
            },
            "A",
            Primitive::Crank,
        ),
        (RunTimeMasses { j3: -0.5, ..base }, "B", Primitive::Rrr),
        (
            RunTimeMasses {
                j2: f64::INFINITY,
                ..base
            },
            "A",
            Primitive::Crank,
        ),
    ];
    for (m, group, primitive) in cases {
        let e = solve(m).expect_err("a bad mass or inertia");
        assert_eq!((e.group, e.primitive), (group, primitive), "{e}");
        let shown = e.to_string();
        match e.fault {
            Fault::NonPositive { what, value } => {
                assert!(what.starts_with("mass of `") && value <= 0.0, "{shown}")
            }
            Fault::Negative { what, value } => {
                assert!(
                    what.starts_with("moment of inertia of `") && value < 0.0,
                    "{shown}"
                )
            }
            Fault::NonFinite { what } => assert!(what.contains(" of `"), "{shown}"),
            other => panic!("unexpected fault {other:?}"),
        }
    }
}
