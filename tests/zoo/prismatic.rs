//! Prismatic pairs and linear drives: `PistonDriven`, `LoadedBoom`,
//! `LoadedYoke`, `SlottedRocker`, `LoadedCrossSlide`, `CarriedYoke` (see
//! `main.rs`). Each prismatic reaction is applied as its normal force at its
//! stated reference point plus its couple.

use crate::equilibrium::*;
use mechanism::mechanism;
use mechanism::Vector2;

mechanism! {
    /// Offset engine (m, kg, N) driven by the force on its piston: crank
    /// 0.1 about O, rod 0.4, slide line y = 0.01; a 15 N m load torque on
    /// the crank, gravity.
    pub PistonDriven {
        dof 1;
        let O = ground(0.0, 0.0);
        let line = guide((0.0, 0.01), 0 deg);
        let P = slider(line, s) as piston;
        let A = rrr(P, 0.4, O, 0.1, right) as (rod, crank);
        let Gr = point(rod, from P, 0.15, 0 deg);
        let Gc = point(crank, from O, 0.02, 0 deg);
        mass piston { m = 0.5, at = P };
        mass rod { m = 0.9, at = Gr, j = 0.012 };
        mass crank { m = 2.0, at = Gc, j = 0.02 };
        torque on crank = -15.0;
        gravity (0.0, -9.81);
        range s = (0.32, 0.48);
    }
}

mechanism! {
    /// Boom (m, kg, N) pivoted at A and lifted by a cylinder from B to C,
    /// 120 kg, a 2 kN load at its tip, gravity.
    pub LoadedBoom {
        dof 1;
        let A = ground(0.0, 0.0);
        let B = ground(0.8, -0.2);
        let C = actuator(A, 1.2, B, len, left) as (boom, cylinder);
        let tip = point(boom, from A, 2.5, 10 deg);
        let Gb = point(boom, from A, 1.2, 5 deg);
        mass boom { m = 120.0, at = Gb, j = 60.0 };
        gravity (0.0, -9.81);
        force at tip = (0.0, -2000.0);
        range len = (0.9, 1.6);
    }
}

mechanism! {
    /// Scotch yoke (m, kg, N): crank 0.1, a 0.2 kg block, a 3 kg yoke, a
    /// 40 N force resisting the yoke's upward motion along its guide.
    pub LoadedYoke {
        dof 1;
        let O = ground(0.0, 0.0);
        let vertical = guide(O, 90 deg);
        let A = crank(O, 0.1, phi) as crank_link;
        let Q = rpp(A, vertical, -90 deg) as (block, yoke) slide (s_slot, s_yoke);
        let Gy = point(yoke, from Q, (0.0, 0.05));
        mass yoke { m = 3.0, at = Gy, j = 0.01 };
        mass block { m = 0.2, at = A };
        gravity (0.0, -9.81);
        force at Gy on yoke along vertical = -40.0;
    }
}

mechanism! {
    /// A slotted rocker (m, kg, N): the crank's block slides along the rocker
    /// (RPR about O4); the rocker carries a slot at right angles through its
    /// point D, in which a slider closes an RRP group with a link from O6.
    /// The slot is a guide carried by a moving link, so its reaction loads
    /// the rocker, which also carries the block's. Masses on every moving
    /// body but the crank, gravity, a force on the slider along the slot.
    pub SlottedRocker {
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.0, -0.3);
        let O6 = ground(0.35, 0.1);
        let A = crank(O2, 0.1, theta) as crank;
        let s = rpr(A, O4, plus) as (block, rocker);
        let D = point(rocker, from O4, 0.5, 0 deg);
        let slot = guide(D, rocker, 90 deg);
        let E = rrp(O6, 0.25, slot, plus) as (link5, slider5) slide u;
        let G4 = point(rocker, from O4, 0.3, 0 deg);
        let G5 = point(link5, from O6, 0.12, 0 deg);
        mass rocker { m = 2.0, at = G4, j = 0.05 };
        mass block { m = 0.3, at = A };
        mass link5 { m = 0.6, at = G5, j = 0.004 };
        mass slider5 { m = 0.4, at = E };
        gravity (0.0, -9.81);
        force at E on slider5 along slot = -20.0;
    }
}

mechanism! {
    /// A cross-slide (m, kg, N): a PRP group joins a block on the crank's
    /// own line (a guide carried by the crank) and a block on a fixed
    /// vertical guide through (0.3, 0); the joint C is 0.01 off the vertical
    /// guide's line. Masses on the crank and both blocks, gravity, a 30 N
    /// force resisting the vertical block's upward motion.
    pub LoadedCrossSlide {
        dof 1;
        let O = ground(0.0, 0.0);
        let V = ground(0.3, 0.0);
        let vertical = guide(V, 90 deg);
        let A = crank(O, 0.1, phi) as crank_link;
        let rod_line = guide(O, crank_link);
        let C = prp(rod_line, vertical, 0.0, 0.01) as (b1, b2) slide (s1, s2);
        let Gc = point(crank_link, from O, 0.05, 0 deg);
        let G2 = point(b2, from C, (0.0, 0.04));
        mass crank_link { m = 0.8, at = Gc, j = 0.002 };
        mass b1 { m = 0.25, at = C };
        mass b2 { m = 1.5, at = G2, j = 0.006 };
        gravity (0.0, -9.81);
        force at G2 on b2 along vertical = -30.0;
        range phi = (-80 deg, 80 deg);
    }
}

mechanism! {
    /// An RPP on a carried guide (m, kg, N): a frame slides along the
    /// crank's own line and has a slot at right angles to it, in which a
    /// block pinned to the ground at P slides. The guide is carried by the
    /// crank, so the frame's reaction along it loads the crank. Masses on
    /// the crank and the frame, gravity, a force on the frame along the
    /// crank's line.
    pub CarriedYoke {
        dof 1;
        let O = ground(0.0, 0.0);
        let P = ground(0.25, 0.05);
        let A = crank(O, 0.1, phi) as crank_link;
        let line = guide(A, crank_link);
        let Q = rpp(P, line, 90 deg) as (block, frame) slide (s_slot, s_frame);
        let Gc = point(crank_link, from O, 0.04, 0 deg);
        let Gf = point(frame, from Q, (0.03, 0.01));
        mass crank_link { m = 0.6, at = Gc, j = 0.001 };
        mass block { m = 0.1, at = P };
        mass frame { m = 1.2, at = Gf, j = 0.004 };
        gravity (0.0, -9.81);
        force at Gf on frame along line = -8.0;
    }
}

#[test]
fn piston_driven_engine_balances() {
    let m = PistonDriven::<f64>::default();
    let dir = Vector2::new(1.0, 0.0);
    let mut checked = 0;
    for k in 0..=32 {
        let (s0, sd, sdd) = (0.32 + 0.005 * k as f64, 1.5, -40.0);
        let s = m
            .solve(
                &PistonDrivenInput { s: s0 },
                &PistonDrivenInput { s: sd },
                &PistonDrivenInput { s: sdd },
            )
            .unwrap();
        let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
        if f.condition < 0.05 {
            continue;
        }
        checked += 1;
        Body::default()
            .prismatic(&f.r_ground_piston, p.P, 1.0)
            .force(p.P, -f.r_piston_rod)
            .force(p.P, dir * f.drive_s)
            .inertia(0.5, 0.0, p.P, a.P, 0.0, G)
            .balances("piston");
        Body::default()
            .force(p.P, f.r_piston_rod)
            .force(p.A, -f.r_rod_crank)
            .inertia(0.9, 0.012, p.Gr, a.Gr, a.rod, G)
            .balances("rod");
        Body::default()
            .force(p.O, f.r_ground_crank)
            .force(p.A, f.r_rod_crank)
            .couple(-15.0)
            .inertia(2.0, 0.02, p.Gc, a.Gc, a.crank, G)
            .balances("crank");
        power_balances(
            &[
                f.drive_s * sd,
                -15.0 * v.crank,
                inertial(0.5, 0.0, v.P, a.P, 0.0, 0.0, G),
                inertial(0.9, 0.012, v.Gr, a.Gr, v.rod, a.rod, G),
                inertial(2.0, 0.02, v.Gc, a.Gc, v.crank, a.crank, G),
            ],
            "PistonDriven",
        );
    }
    assert!(checked >= 25, "only {checked} of 33 poses checked");
}

#[test]
fn boom_lifted_by_its_cylinder_balances() {
    let m = LoadedBoom::<f64>::default();
    for k in 0..=35 {
        let (l0, ld, ldd) = (0.9 + 0.02 * k as f64, 0.05, 0.3);
        let s = m
            .solve(
                &LoadedBoomInput { len: l0 },
                &LoadedBoomInput { len: ld },
                &LoadedBoomInput { len: ldd },
            )
            .unwrap();
        let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
        let axis = (p.C - p.B) / (p.C - p.B).norm();
        let tip = Vector2::new(0.0, -2000.0);
        Body::default()
            .force(p.A, f.r_ground_boom)
            .force(p.C, axis * f.drive_len)
            .force(p.tip, tip)
            .inertia(120.0, 60.0, p.Gb, a.Gb, a.boom, G)
            .balances("boom");
        power_balances(
            &[
                f.drive_len * ld,
                tip.dot(&v.tip),
                inertial(120.0, 60.0, v.Gb, a.Gb, v.boom, a.boom, G),
            ],
            "LoadedBoom",
        );
    }
}

#[test]
fn scotch_yoke_with_masses_balances() {
    let m = LoadedYoke::<f64>::default();
    let up = Vector2::new(0.0, 1.0);
    for k in 0..72 {
        let (q, w, al) = (f64::to_radians(5.0 * k as f64 + 1.0), 30.0, 200.0);
        let s = m
            .solve(
                &LoadedYokeInput { phi: q },
                &LoadedYokeInput { phi: w },
                &LoadedYokeInput { phi: al },
            )
            .unwrap();
        let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
        Body::default()
            .force(p.O, f.r_ground_crank_link)
            .force(p.A, -f.r_crank_link_block)
            .couple(f.drive_phi)
            .balances("crank (massless)");
        Body::default()
            .force(p.A, f.r_crank_link_block)
            .prismatic(&f.r_block_yoke, p.A, -1.0)
            .inertia(0.2, 0.0, p.A, a.A, a.block, G)
            .balances("block");
        Body::default()
            .prismatic(&f.r_block_yoke, p.A, 1.0)
            .prismatic(&f.r_ground_yoke, p.A, 1.0)
            .force(p.Gy, up * -40.0)
            .inertia(3.0, 0.01, p.Gy, a.Gy, a.yoke, G)
            .balances("yoke");
        power_balances(
            &[
                f.drive_phi * w,
                -40.0 * up.dot(&v.Gy),
                inertial(0.2, 0.0, v.A, a.A, v.block, a.block, G),
                inertial(3.0, 0.01, v.Gy, a.Gy, v.yoke, a.yoke, G),
            ],
            "LoadedYoke",
        );
    }
}

#[test]
fn slotted_rocker_with_a_carried_guide_balances() {
    let m = SlottedRocker::<f64>::default();
    let (w, al) = (5.0, 2.0);
    let mut checked = 0;
    for k in 0..72 {
        let q = f64::to_radians(5.0 * k as f64 + 0.5);
        let at = |t: f64| SlottedRockerInput {
            theta: q + w * t + 0.5 * al * t * t,
        };
        let rate = |t: f64| SlottedRockerInput { theta: w + al * t };
        let s = m
            .solve(&at(0.0), &rate(0.0), &SlottedRockerInput { theta: al })
            .unwrap();
        let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
        if f.condition < 0.05 || v.condition < 0.05 {
            continue;
        }
        checked += 1;
        assert_len(p.E, p.O6, 0.25, "link5");
        let pos = |t: f64| m.position(&at(t)).unwrap();
        let vel = |t: f64| m.velocity(&pos(t), &rate(t)).unwrap();
        close_fd(v.E, (pos(H).E - pos(-H).E) / (2.0 * H), 10.0, "vE");
        close_fd(a.E, (vel(H).E - vel(-H).E) / (2.0 * H), 100.0, "aE");

        // The slot's direction: the rocker's axis turned by 90 degrees.
        let axis = (p.D - p.O4) / (p.D - p.O4).norm();
        let slot = Vector2::new(-axis.y, axis.x);
        let push = slot * -20.0;
        Body::default()
            .force(p.O2, f.r_ground_crank)
            .force(p.A, -f.r_crank_block)
            .couple(f.drive_theta)
            .balances("crank (massless)");
        Body::default()
            .force(p.A, f.r_crank_block)
            .prismatic(&f.r_block_rocker, p.A, -1.0)
            .inertia(0.3, 0.0, p.A, a.A, a.block, G)
            .balances("block");
        Body::default()
            .force(p.O4, f.r_ground_rocker)
            .prismatic(&f.r_block_rocker, p.A, 1.0)
            .prismatic(&f.r_rocker_slider5, p.E, -1.0)
            .inertia(2.0, 0.05, p.G4, a.G4, a.rocker, G)
            .balances("rocker (carries the slot)");
        Body::default()
            .force(p.O6, f.r_ground_link5)
            .force(p.E, -f.r_link5_slider5)
            .inertia(0.6, 0.004, p.G5, a.G5, a.link5, G)
            .balances("link5");
        Body::default()
            .force(p.E, f.r_link5_slider5)
            .prismatic(&f.r_rocker_slider5, p.E, 1.0)
            .force(p.E, push)
            .inertia(0.4, 0.0, p.E, a.E, a.slider5, G)
            .balances("slider5");
        power_balances(
            &[
                f.drive_theta * w,
                inertial(0.3, 0.0, v.A, a.A, v.block, a.block, G),
                inertial(2.0, 0.05, v.G4, a.G4, v.rocker, a.rocker, G),
                inertial(0.6, 0.004, v.G5, a.G5, v.link5, a.link5, G),
                inertial(0.4, 0.0, v.E, a.E, v.slider5, a.slider5, G),
                push.dot(&v.E),
            ],
            "SlottedRocker",
        );
    }
    assert!(checked >= 36, "only {checked} of 72 poses checked");
}

#[test]
fn cross_slide_with_a_carried_guide_balances() {
    let m = LoadedCrossSlide::<f64>::default();
    let (w, al) = (4.0, -3.0);
    let up = Vector2::new(0.0, 1.0);
    let mut checked = 0;
    for k in 0..64 {
        // -78.75 .. 78.75 deg, inside the definition's range.
        let q = f64::to_radians(-78.75 + 2.5 * k as f64);
        let at = |t: f64| LoadedCrossSlideInput {
            phi: q + w * t + 0.5 * al * t * t,
        };
        let rate = |t: f64| LoadedCrossSlideInput { phi: w + al * t };
        let s = m
            .solve(&at(0.0), &rate(0.0), &LoadedCrossSlideInput { phi: al })
            .unwrap();
        let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
        if f.condition < 0.05 || v.condition < 0.05 {
            continue;
        }
        checked += 1;
        // C.y goes as tan(phi): near +-79 deg its third time derivative
        // reaches about 1e5 m/s^3 (sec^2 phi = 26, w = 4 rad/s), so the
        // central difference's truncation, H^2 / 6 times that, is 1.3e-6
        // with the shared H = 1e-5, above the 1e-6 of `close_fd`; h = 1e-6
        // makes it 1.3e-8, and the rounding, eps |C| / h, stays near 1e-10.
        let h = 1e-6;
        let pos = |t: f64| m.position(&at(t)).unwrap();
        let vel = |t: f64| m.velocity(&pos(t), &rate(t)).unwrap();
        close_fd(v.C, (pos(h).C - pos(-h).C) / (2.0 * h), 10.0, "vC");
        close_fd(a.C, (vel(h).C - vel(-h).C) / (2.0 * h), 100.0, "aC");
        // C stays 0.01 off the vertical guide's line x = 0.3.
        assert!(
            ((p.C.x - 0.3).abs() - 0.01).abs() <= 1e-15,
            "C.x = {}",
            p.C.x
        );

        let push = up * -30.0;
        Body::default()
            .force(p.O, f.r_ground_crank_link)
            .prismatic(&f.r_crank_link_b1, p.C, -1.0)
            .couple(f.drive_phi)
            .inertia(0.8, 0.002, p.Gc, a.Gc, a.crank_link, G)
            .balances("crank (carries the rod line)");
        Body::default()
            .prismatic(&f.r_crank_link_b1, p.C, 1.0)
            .force(p.C, -f.r_b1_b2)
            .inertia(0.25, 0.0, p.C, a.C, a.b1, G)
            .balances("b1");
        Body::default()
            .force(p.C, f.r_b1_b2)
            .prismatic(&f.r_ground_b2, p.C, 1.0)
            .force(p.G2, push)
            .inertia(1.5, 0.006, p.G2, a.G2, a.b2, G)
            .balances("b2");
        power_balances(
            &[
                f.drive_phi * w,
                push.dot(&v.G2),
                inertial(0.8, 0.002, v.Gc, a.Gc, v.crank_link, a.crank_link, G),
                inertial(0.25, 0.0, v.C, a.C, v.b1, a.b1, G),
                inertial(1.5, 0.006, v.G2, a.G2, v.b2, a.b2, G),
            ],
            "LoadedCrossSlide",
        );
    }
    assert!(checked >= 48, "only {checked} of 64 poses checked");
}

#[test]
fn yoke_on_a_carried_guide_balances() {
    let m = CarriedYoke::<f64>::default();
    let (w, al) = (6.0, 1.5);
    let mut checked = 0;
    for k in 0..72 {
        let q = f64::to_radians(5.0 * k as f64 + 2.5);
        let at = |t: f64| CarriedYokeInput {
            phi: q + w * t + 0.5 * al * t * t,
        };
        let rate = |t: f64| CarriedYokeInput { phi: w + al * t };
        let s = m
            .solve(&at(0.0), &rate(0.0), &CarriedYokeInput { phi: al })
            .unwrap();
        let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
        if f.condition < 0.05 || v.condition < 0.05 {
            continue;
        }
        checked += 1;
        let pos = |t: f64| m.position(&at(t)).unwrap();
        let vel = |t: f64| m.velocity(&pos(t), &rate(t)).unwrap();
        close_fd(v.Q, (pos(H).Q - pos(-H).Q) / (2.0 * H), 10.0, "vQ");
        close_fd(a.Q, (vel(H).Q - vel(-H).Q) / (2.0 * H), 100.0, "aQ");
        // Q is on the crank's line and P on the slot through Q at right
        // angles to it: Q is the foot of the perpendicular from P.
        let u = (p.A - p.O) / (p.A - p.O).norm();
        assert!(cross(&u, &(p.Q - p.O)).abs() <= 1e-15, "Q off the line");
        assert!(u.dot(&(p.P - p.Q)).abs() <= 1e-15, "P off the slot");

        let push = u * -8.0;
        Body::default()
            .force(p.O, f.r_ground_crank_link)
            .prismatic(&f.r_crank_link_frame, p.P, -1.0)
            .couple(f.drive_phi)
            .inertia(0.6, 0.001, p.Gc, a.Gc, a.crank_link, G)
            .balances("crank (carries the frame's guide)");
        Body::default()
            .force(p.P, f.r_ground_block)
            .prismatic(&f.r_block_frame, p.P, -1.0)
            .inertia(0.1, 0.0, p.P, a.P, a.block, G)
            .balances("block");
        Body::default()
            .prismatic(&f.r_block_frame, p.P, 1.0)
            .prismatic(&f.r_crank_link_frame, p.P, 1.0)
            .force(p.Gf, push)
            .inertia(1.2, 0.004, p.Gf, a.Gf, a.frame, G)
            .balances("frame");
        power_balances(
            &[
                f.drive_phi * w,
                push.dot(&v.Gf),
                inertial(0.6, 0.001, v.Gc, a.Gc, v.crank_link, a.crank_link, G),
                inertial(0.1, 0.0, v.P, a.P, v.block, a.block, G),
                inertial(1.2, 0.004, v.Gf, a.Gf, v.frame, a.frame, G),
            ],
            "CarriedYoke",
        );
    }
    assert!(checked >= 60, "only {checked} of 72 poses checked");
}
