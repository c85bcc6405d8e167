//! The drawn form (joints at a reference pose, links as joint sets, inputs):
//! each drawn definition here against the same mechanism written with group
//! statements, its lengths and offsets computed from the same coordinates in
//! the test, over the input range.

use mechanism::mechanism;

#[path = "../common/columns.rs"]
mod columns;
use columns::Columns;

mechanism! {
    /// A crank-rocker four-bar with a coupler point, as drawn.
    pub DrawnFourBar {
        joints {
            O2 = (0.0, 0.0),
            O4 = (4.0, 0.0),
            A = (0.5, 0.8660254037844386),
            B = (3.2, 2.1),
            P = (2.0, 2.9),
        }
        links {
            ground = [O2, O4],
            crank = [O2, A],
            coupler = [A, B, P],
            rocker = [O4, B],
        }
        input theta = angle(crank);
    }
}

mechanism! {
    /// The same four-bar written as groups.
    pub GroupedFourBar {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(4.0, 0.0);
        let A = crank(O2, hypot(0.5, 0.8660254037844386), theta) as crank;
        const ux = 3.2 - 0.5;
        const uy = 2.1 - 0.8660254037844386;
        const dx = 2.0 - 0.5;
        const dy = 2.9 - 0.8660254037844386;
        let B = rrr(A, hypot(ux, uy), O4, hypot(3.2 - 4.0, 2.1), left) as (coupler, rocker);
        let P = point(coupler, from A, ((dx * ux + dy * uy) / hypot(ux, uy), (ux * dy - uy * dx) / hypot(ux, uy)));
    }
}

#[test]
fn a_drawn_four_bar_is_the_grouped_one() {
    // Proves: the drawn four-bar decomposes into the crank and RRR a user
    // would write, with the lengths and the assembly of the drawing: both
    // forms give the same joints over a full turn.
    let (d, g) = (
        DrawnFourBar::<f64>::default(),
        GroupedFourBar::<f64>::default(),
    );
    for k in 0..360 {
        let theta = (k as f64).to_radians();
        let pd = d.position(&DrawnFourBarInput { theta }).unwrap();
        let pg = g.position(&GroupedFourBarInput { theta }).unwrap();
        assert!(
            (pd.B - pg.B).norm() <= 4.0 * f64::EPSILON * 4.0,
            "{k}: {} {}",
            pd.B,
            pg.B
        );
        assert!((pd.A - pg.A).norm() <= 4.0 * f64::EPSILON, "{k}");
        assert!(
            (pd.P - pg.P).norm() <= 16.0 * f64::EPSILON,
            "{k}: {} {}",
            pd.P,
            pg.P
        );
    }
    // At the drawn input the joints are where they are drawn.
    let at = d
        .position(&DrawnFourBarInput {
            theta: 60f64.to_radians(),
        })
        .unwrap();
    assert!(
        (at.B - mechanism::Point2::new(3.2, 2.1)).norm() < 1e-14,
        "{}",
        at.B
    );
    assert!(
        (at.P - mechanism::Point2::new(2.0, 2.9)).norm() < 1e-14,
        "{}",
        at.P
    );
}

mechanism! {
    /// The 2R leg of `relative_drivers::Leg` drawn with its knee bent, the
    /// hip and knee motors as inputs (the knee's angle from the thigh), its
    /// masses and load written as for the grouped form.
    pub DrawnLeg {
        dof 2;
        joints { H = (0.0, 0.0), K = (0.4, 0.0), F = (0.4, 0.35) }
        links { ground = [H], thigh = [H, K], shank = [K, F] }
        input q1 = angle(thigh);
        input q2 = angle(shank, thigh);
        let G1 = point(thigh, from H, 0.17, 4 deg);
        let G2 = point(shank, from K, 0.15, -6 deg);
        mass thigh { m = 7.0, at = G1, j = 0.11 };
        mass shank { m = 3.2, at = G2, j = 0.045 };
        gravity (0.0, -9.81);
        force at F = (30.0, 250.0);
    }
}

mechanism! {
    /// The same leg with the thigh's joints listed knee first: the knee's
    /// angle is then measured from the line K -> H, half a turn from H -> K.
    pub DrawnLegReversed {
        joints { H = (0.0, 0.0), K = (0.4, 0.0), F = (0.4, 0.35) }
        links { ground = [H], thigh = [K, H], shank = [K, F] }
        input q1 = angle(thigh);
        input q2 = angle(shank, thigh);
    }
}

#[test]
fn a_drawn_leg_with_a_knee_motor_is_the_grouped_leg() {
    // Proves: a relative input in the drawn form becomes a crank carried by
    // the named link, measured from that link's first two joints as listed,
    // and masses and loads written beside a drawing act as on the grouped
    // form: same foot, rates and motor torques over a grid of both angles.
    use crate::relative_drivers::{Leg, LegInput};
    let (d, g) = (DrawnLeg::<f64>::default(), Leg::<f64>::default());
    let r = DrawnLegReversed::<f64>::default();
    for i in 0..24 {
        for k in 0..24 {
            let (q1, q2) = (
                (15.0 * i as f64 - 170.0).to_radians(),
                (15.0 * k as f64 - 175.0).to_radians(),
            );
            let (w, al) = ((2.5, -4.0), (-30.0, 45.0));
            let sd = d
                .solve(
                    &DrawnLegInput { q1, q2 },
                    &DrawnLegInput { q1: w.0, q2: w.1 },
                    &DrawnLegInput { q1: al.0, q2: al.1 },
                )
                .unwrap();
            let sg = g
                .solve(
                    &LegInput { q1, q2 },
                    &LegInput { q1: w.0, q2: w.1 },
                    &LegInput { q1: al.0, q2: al.1 },
                )
                .unwrap();
            let tol = 8.0 * f64::EPSILON;
            assert!((sd.position.F - sg.position.F).norm() <= tol, "{i} {k}");
            assert!(
                (sd.velocity.F - sg.velocity.F).norm() <= 8.0 * tol,
                "{i} {k}"
            );
            let scale = sg.forces.drive_q1.abs().max(100.0);
            assert!(
                (sd.forces.drive_q1 - sg.forces.drive_q1).abs() <= tol * scale,
                "{i} {k}"
            );
            assert!(
                (sd.forces.drive_q2 - sg.forces.drive_q2).abs() <= tol * scale,
                "{i} {k}"
            );
            // Listed knee first, the thigh's listed line is K -> H: q2 is
            // measured from it, half a turn from H -> K; q1 is still the
            // angle of the line from the thigh's ground joint H to K.
            let pr = r
                .position(&DrawnLegReversedInput {
                    q1,
                    q2: q2 - std::f64::consts::PI,
                })
                .unwrap();
            assert!(
                (pr.F - sg.position.F).norm() <= tol,
                "reversed {i} {k}: {} {}",
                pr.F,
                sg.position.F
            );
        }
    }
}

mechanism! {
    /// The Jansen leg of `describe::JansenLeg` drawn at theta = 1 rad (its
    /// joints from that definition, 18 digits): six RRR dyads found, one of
    /// them at a joint where a third link waits (B on j, b and e).
    pub DrawnJansen {
        joints {
            O = (0.0, 0.0),
            Z = (-38.0, -7.8),
            A = (8.10453458802209603e0, 1.26220647721184474e1),
            B = (-3.72387663497084631e1, 3.36930177660008709e1),
            C = (-1.97996845852679613e1, -4.26315735906988067e1),
            D = (-7.79603734559143504e1, -4.45656564834064284e0),
            E = (-5.61009738318693962e1, -3.72365389258816606e1),
            F = (-1.92498433595316314e1, -9.16284885407901157e1),
        }
        links {
            ground = [O, Z],
            crank = [O, A],
            j = [A, B], b = [Z, B],
            k = [A, C], c = [Z, C],
            e = [B, D], d = [Z, D],
            f = [D, E], g = [C, E],
            h = [E, F], i = [C, F],
        }
        input theta = angle(crank);
    }
}

#[test]
fn a_drawn_jansen_leg_is_the_grouped_one() {
    // Proves: a drawing of six dyads in a chain, with joints shared by three
    // links, decomposes into the grouped leg's dyads in their assemblies:
    // the foot agrees over a full turn to the rounding of the 18-digit
    // drawing (lengths within 1e-16 relative) times the chain's growth.
    use crate::describe::{JansenLeg, JansenLegInput};
    let (d, g) = (DrawnJansen::<f64>::default(), JansenLeg::<f64>::default());
    let mut worst = 0.0f64;
    for k in 0..3600 {
        let theta = (k as f64 / 10.0).to_radians();
        let pd = d.position(&DrawnJansenInput { theta }).unwrap();
        let pg = g.position(&JansenLegInput { theta }).unwrap();
        worst = worst.max((pd.F - pg.F).norm() / 100.0);
    }
    eprintln!("drawn Jansen: largest foot difference {worst:e} of the size");
    // 1e-13 of the leg's size (100).
    assert!(
        worst < 1e-13,
        "largest foot difference {worst:e} of the size"
    );
}

mechanism! {
    /// The drawn four-bar of `docs/dsl.md` ("Say it as drawn").
    pub DocFourBar {
        joints { O2 = (0.0, 0.0), O4 = (4.0, 0.0), A = (0.5, 0.9), B = (3.2, 2.1), P = (2.0, 2.9) }
        links {
            ground = [O2, O4],
            crank = [O2, A],
            coupler = [A, B, P],
            rocker = [O4, B],
        }
        input theta = angle(crank);
    }
}

#[test]
fn the_drawn_four_bar_of_the_docs_draws_itself() {
    // Proves: the docs' drawn four-bar turns fully (a Grashof crank-rocker
    // read from the drawing: 1.03 + 4 <= 2.95 + 2.25) and draws its links
    // and the path of P at the drawn pose, legibly (rendered and looked at;
    // with MECHANISM_DOC_PNGS set, written as docs/drawn-fourbar.png).
    let m = DocFourBar::<f64>::default();
    let drawn = 0.9f64.atan2(0.5);
    let poses: Vec<(f64, Option<DocFourBarPosition>)> = (0..=72)
        .map(|k| {
            let t = drawn + k as f64 * std::f64::consts::TAU / 72.0;
            (t, m.position(&DocFourBarInput { theta: t }).ok())
        })
        .collect();
    assert!(
        poses.iter().all(|(_, p)| p.is_some()),
        "the crank turns fully"
    );
    let sketch = mechanism_plot::any::sketch_with::<DocFourBar, _>(
        "The four-bar as drawn",
        &poses,
        &["P"],
        |t| format!("θ = {:.0}°", t.to_degrees()),
    )
    .unwrap();
    let drawing = sketch.drawing(0).unwrap();
    for link in ["crank", "coupler", "rocker"] {
        assert!(
            drawing.contains(&format!("\"{link}\"")),
            "link {link} drawn"
        );
    }
    let png = crate::render::look(&drawing, "drawn four-bar", 0.01);
    crate::render::save_for_docs(&png, "drawn-fourbar.png");
}

mechanism! {
    /// A piston-driven crank, drawn: the block B slides on the ground along
    /// 10 deg through its drawn place, driven by its slide `s`; the rod and
    /// the crank close on it.
    pub DrawnPiston {
        joints { O = (0.0, 0.0), A = (0.06, 0.08), B = (0.42, 0.05) }
        links { ground = [O], crank = [O, A], rod = [A, B] }
        slider piston at B on ground along 10 deg;
        input s = slide(piston);
    }
}

mechanism! {
    /// The same, written with groups (its dimensions from the same drawing).
    pub GroupedPiston {
        let O = ground(0.0, 0.0);
        let line = guide((0.42, 0.05), 10 deg);
        let B = slider(line, s) as piston;
        let A = rrr(O, hypot(0.06, 0.08), B, hypot(0.42 - 0.06, 0.05 - 0.08), left) as (crank, rod);
    }
}

#[test]
fn a_drawn_slider_driven_by_its_slide_is_the_grouped_one() {
    // Proves: `input s = slide(block)` drives the block from its drawn place
    // along its line (s = 0 as drawn), and the dyad closing on it takes the
    // drawn side: the same joints as the grouped form, and at s = 0 the
    // drawing itself.
    let (d, g) = (
        DrawnPiston::<f64>::default(),
        GroupedPiston::<f64>::default(),
    );
    // From -0.1 to 0.03 m: the rod and crank reach B there (|OB| between
    // 0.26 and 0.46 m).
    for k in 0..=65 {
        let s = -0.1 + 0.002 * k as f64;
        let pd = d.position(&DrawnPistonInput { s }).unwrap();
        let pg = g.position(&GroupedPistonInput { s }).unwrap();
        assert!(
            (pd.A - pg.A).norm() <= 4.0 * f64::EPSILON,
            "{s}: {} {}",
            pd.A,
            pg.A
        );
    }
    let at = d.position(&DrawnPistonInput { s: 0.0 }).unwrap();
    assert!(
        (at.A - mechanism::Point2::new(0.06, 0.08)).norm() < 1e-15,
        "{}",
        at.A
    );
}

mechanism! {
    /// A block on a moving link closing an RRP: the crank link2 (O2-A, 0.1)
    /// carries a slot parallel to its axis, 0.05 to its left; the rocker
    /// O4-J (0.4) holds the block at J. Drawn at theta = 0.8 rad.
    pub DrawnCarriedSlot {
        joints {
            O2 = (0.0, 0.0),
            O4 = (0.3, 0.0),
            A = (6.96706709347165443e-2, 7.17356090899522875e-2),
            J = (3.18375316783644169e-1, 3.99577711757175935e-1),
        }
        links { ground = [O2, O4], link2 = [O2, A], link4 = [O4, J] }
        slider block at J on link2 along 0.8;
        input theta = angle(link2);
    }
}

mechanism! {
    /// The same mechanism written as groups: a guide carried by link2
    /// through O2 along its axis, the RRP on it at the offset 0.05.
    pub GroupedCarriedSlot {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.3, 0.0);
        let A = crank(O2, 0.1, theta) as link2;
        let slot = guide(O2, link2, 0.0);
        let J = rrp(O4, 0.4, slot, plus, 0.05) as (link4, block);
    }
}

#[test]
fn a_drawn_block_on_a_turning_link_is_the_grouped_rrp() {
    // Proves: a block drawn on a placed moving link, pinned to a rocker,
    // becomes an RRP on the line that link carries, with the offset and the
    // assembly of the drawing: J, the rocker's angle and rate agree with the
    // grouped form over a full turn within 4e-15 of the scale (0.4 m,
    // 1 rad/s); measured 8.9e-16.
    let (d, g) = (
        DrawnCarriedSlot::<f64>::default(),
        GroupedCarriedSlot::<f64>::default(),
    );
    let mut worst = 0.0f64;
    for k in 0..360 {
        let theta = (k as f64).to_radians();
        let pd = d.position(&DrawnCarriedSlotInput { theta }).unwrap();
        let pg = g.position(&GroupedCarriedSlotInput { theta }).unwrap();
        let vd = d.velocity(&pd, &DrawnCarriedSlotInput { theta: 1.0 });
        let vg = g.velocity(&pg, &GroupedCarriedSlotInput { theta: 1.0 });
        worst = worst
            .max((pd.J - pg.J).norm() / 0.4)
            .max((pd.link4 - pg.link4).abs())
            .max((vd.unwrap().link4 - vg.unwrap().link4).abs());
    }
    eprintln!("drawn carried slot: largest difference {worst:e}");
    assert!(worst < 4e-15, "{worst:e}");
}

mechanism! {
    /// A polar arm: link2 turns about O2 by `theta`, a block at J slides
    /// along it by `s`; drawn at theta = 0 with J at (0.25, 0.03), the slot
    /// along 0 deg (0.03 to the left of link2's axis O2 -> A).
    pub DrawnPolarArm {
        joints { O2 = (0.0, 0.0), A = (0.1, 0.0), J = (0.25, 0.03) }
        links { ground = [O2], link2 = [O2, A] }
        slider block at J on link2 along 0 deg;
        input theta = angle(link2);
        input s = slide(block);
    }
}

#[test]
fn a_drawn_block_driven_along_a_turning_link_slides_from_its_drawn_place() {
    // Proves: `slide(BLOCK)` of a block on a moving link is its travel along
    // the carried line from its drawn place: J = R(theta) (0.25 + s, 0.03)
    // (worked by hand) within 4 ulps of the arm's reach, and the slide rate
    // moves J along the turned slot.
    let d = DrawnPolarArm::<f64>::default();
    for i in 0..36 {
        for k in -4..=4 {
            let (theta, s) = ((10.0 * i as f64).to_radians(), 0.05 * k as f64);
            let p = d.position(&DrawnPolarArmInput { theta, s }).unwrap();
            let (c, n) = (theta.cos(), theta.sin());
            let (x, y) = (0.25 + s, 0.03);
            let hand = mechanism::Point2::new(c * x - n * y, n * x + c * y);
            assert!(
                (p.J - hand).norm() <= 4.0 * f64::EPSILON * 0.5,
                "{theta} {s}: {} {hand}",
                p.J
            );
            let v = d
                .velocity(&p, &DrawnPolarArmInput { theta: 0.0, s: 1.0 })
                .unwrap();
            let along = mechanism::Vector2::new(c, n);
            assert!((v.J - along).norm() <= 4.0 * f64::EPSILON, "{}", v.J);
        }
    }
}

mechanism! {
    /// The Whitworth quick return of `tests/zoo/quick_return.rs` (m, kg, N),
    /// as written there with groups.
    pub GroupedWhitworth {
        params {
            r = 0.2, dd = 0.07, arm = 0.25, rod = 0.6, g1 = 0.1, g3 = 0.05,
            m1 = 1.0, j1 = 0.004, m2 = 0.3, m3 = 4.0, j3 = 0.08, m4 = 1.5, j4 = 0.045,
            m5 = 20.0, cut = 2000.0
        }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.0, -dd);
        let ram_line = guide(O4, 0 deg);
        let B = crank(O2, r, theta) as crank;
        let sb = rpr(B, O4, plus) as (block, slotted);
        let D = point(slotted, from O4, arm, 180 deg);
        let E = rrp(D, rod, ram_line, plus) as (link4, ram) slide x;
        let G1 = point(crank, from O2, g1, 0 deg);
        let G3 = point(slotted, from O4, g3, 0 deg);
        let G4 = point(link4, from D, rod * 0.5, 0 deg);
        mass crank { m = m1, at = G1, j = j1 };
        mass block { m = m2, at = B };
        mass slotted { m = m3, at = G3, j = j3 };
        mass link4 { m = m4, at = G4, j = j4 };
        mass ram { m = m5, at = E };
        gravity (0.0, -9.81);
        force at E on ram along ram_line = -cut;
    }
}

mechanism! {
    /// The same Whitworth as drawn at theta = 1 rad: the block at B in the
    /// slot of `slotted` (drawn along O4 -> B), the arm's end D behind O4 on
    /// the slot's line, the ram's block at E on the ground along 0 deg.
    pub DrawnWhitworth {
        params { m1 = 1.0, j1 = 0.004, m2 = 0.3, m3 = 4.0, j3 = 0.08, m4 = 1.5, j4 = 0.045, m5 = 20.0, cut = 2000.0 }
        joints {
            O2 = (0.0, 0.0),
            O4 = (0.0, -0.07),
            B = (1.08060461173627956e-1, 1.68294196961579323e-1),
            D = (-1.03248704501835334e-1, -2.97683343744536311e-1),
            E = (4.51873169487388204e-1, -0.07),
            G1 = (5.40302305868139779e-2, 8.41470984807896616e-2),
            G3 = (2.06497409003670689e-2, -2.44633312510927417e-2),
            G4 = (1.74312232492776442e-1, -1.83841671872268159e-1),
        }
        links {
            ground = [O2, O4],
            crank = [O2, B, G1],
            slotted = [O4, D, G3],
            link4 = [D, E, G4],
        }
        slider block at B on slotted along 1.1450563481441915;
        slider ram at E on ground along 0 deg;
        input theta = angle(crank);
        mass crank { m = m1, at = G1, j = j1 };
        mass block { m = m2, at = B };
        mass slotted { m = m3, at = G3, j = j3 };
        mass link4 { m = m4, at = G4, j = j4 };
        mass ram { m = m5, at = E };
        gravity (0.0, -9.81);
        force at E on ram along ram_line = -cut;
    }
}

#[test]
fn a_drawn_whitworth_is_the_grouped_one_with_its_forces() {
    // Proves: the Whitworth's slotted link, drawn with its arm behind the
    // pivot, becomes the zoo's RPR and points: over a full turn at 5 rad/s
    // and 2 rad/s^2 the ram, the slotted link's angle, the driving torque and
    // the ground's reactions at O4 and on the ram agree within 3e-15 of
    // their scales (0.6 m, the larger of the torque and the reaction at O4
    // at each angle); measured 5.6e-16 (motion) and 6.6e-16 (forces).
    let (d, g) = (
        DrawnWhitworth::<f64>::default(),
        GroupedWhitworth::<f64>::default(),
    );
    let mut worst = [0.0f64; 2];
    for k in 0..720 {
        let theta = (k as f64 / 2.0).to_radians();
        let pd = d.position(&DrawnWhitworthInput { theta }).unwrap();
        let pg = g.position(&GroupedWhitworthInput { theta }).unwrap();
        let vd = d.velocity(&pd, &DrawnWhitworthInput { theta: 5.0 });
        let vg = g.velocity(&pg, &GroupedWhitworthInput { theta: 5.0 });
        let (vd, vg) = (vd.unwrap(), vg.unwrap());
        let ad = d.acceleration(&pd, &vd, &DrawnWhitworthInput { theta: 2.0 });
        let ag = g.acceleration(&pg, &vg, &GroupedWhitworthInput { theta: 2.0 });
        let (ad, ag) = (ad.unwrap(), ag.unwrap());
        let fd = d.forces(&pd, &vd, &ad).unwrap();
        let fg = g.forces(&pg, &vg, &ag).unwrap();
        worst[0] = worst[0]
            .max((pd.E - pg.E).norm() / 0.6)
            .max((pd.slotted - pg.slotted).abs());
        let scale = fg.drive_theta.abs().max(fg.r_ground_slotted.norm());
        worst[1] = worst[1]
            .max((fd.drive_theta - fg.drive_theta).abs() / scale)
            .max((fd.r_ground_slotted - fg.r_ground_slotted).norm() / scale)
            .max((fd.r_ground_ram.normal - fg.r_ground_ram.normal).abs() / scale);
    }
    eprintln!(
        "drawn Whitworth: largest differences {:e} {:e}",
        worst[0], worst[1]
    );
    assert!(
        worst[0] < 3e-15 && worst[1] < 3e-15,
        "{:e} {:e}",
        worst[0],
        worst[1]
    );
}

mechanism! {
    /// The excavator boom of `tests/zoo/excavator.rs` (m, kg, N), as written
    /// there with groups.
    pub GroupedBoom {
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
    /// The same boom as drawn, at 0.3 rad: the cylinder's barrel pinned to
    /// the ground at B, its rod to the boom at C; the cylinder's own points
    /// are written with `point`, mixing the two forms.
    pub DrawnBoom {
        joints {
            A = (0.0, 0.0),
            B = (0.8, -0.9),
            C = (2.10174027607633329, 6.50144454654947079e-1),
            Gb = (2.26227689131837018, 1.06400341494136730),
            Tip = (4.77668244562802968, 1.47760103330669779),
        }
        links { ground = [A, B], boom = [A, C, Gb, Tip] }
        cylinder (barrel, rod) from B to C;
        input len = length(barrel);
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

#[test]
fn a_drawn_boom_with_a_cylinder_is_the_grouped_actuator() {
    // Proves: a drawn cylinder driven by its length becomes the zoo's
    // actuator (the boom's length and the side of A -> B read from the
    // drawing): over the stroke (1.9 m to 3.0 m) the tip, the boom's angle
    // and rate, the cylinder's axial force (its driving effort) and the
    // ground's reaction at A agree within 1e-15 (motion) and 2e-15 (forces) of their scales (5 m,
    // 1 rad/s, the larger of the two forces); measured 0 (motion) and
    // 4.9e-16 (forces).
    let (d, g) = (DrawnBoom::<f64>::default(), GroupedBoom::<f64>::default());
    let mut worst = [0.0f64; 2];
    for k in 0..=1100 {
        let len = 1.9 + 1.1 * k as f64 / 1100.0;
        let pd = d.position(&DrawnBoomInput { len }).unwrap();
        let pg = g.position(&GroupedBoomInput { len }).unwrap();
        let vd = d.velocity(&pd, &DrawnBoomInput { len: 0.2 }).unwrap();
        let vg = g.velocity(&pg, &GroupedBoomInput { len: 0.2 }).unwrap();
        let ad = d.acceleration(&pd, &vd, &DrawnBoomInput { len: 0.1 });
        let ag = g.acceleration(&pg, &vg, &GroupedBoomInput { len: 0.1 });
        let (ad, ag) = (ad.unwrap(), ag.unwrap());
        let fd = d.forces(&pd, &vd, &ad).unwrap();
        let fg = g.forces(&pg, &vg, &ag).unwrap();
        worst[0] = worst[0]
            .max((pd.Tip - pg.Tip).norm() / 5.0)
            .max((pd.boom - pg.boom).abs())
            .max((vd.boom - vg.boom).abs());
        let scale = fg.drive_len.abs().max(fg.r_ground_boom.norm());
        worst[1] = worst[1]
            .max((fd.drive_len - fg.drive_len).abs() / scale)
            .max((fd.r_ground_boom - fg.r_ground_boom).norm() / scale);
    }
    eprintln!(
        "drawn boom: largest differences {:e} {:e}",
        worst[0], worst[1]
    );
    assert!(
        worst[0] < 1e-15 && worst[1] < 2e-15,
        "{:e} {:e}",
        worst[0],
        worst[1]
    );
}

mechanism! {
    /// A PRP: C is pinned to a block in a slot of the crank link2 (square
    /// to its axis, through A) and to a block on the ground's x axis. Drawn
    /// at theta = 0.3 rad.
    pub DrawnCrossSlide {
        joints {
            O2 = (0.0, 0.0),
            A = (0.1 * cos(0.3), 0.1 * sin(0.3)),
            C = (0.1 / cos(0.3), 0.0),
        }
        links { ground = [O2], link2 = [O2, A] }
        slider b1 at C on link2 along 0.3 + pi / 2.0;
        slider b2 at C on ground along 0 deg;
        input theta = angle(link2);
        range theta = (-60 deg, 60 deg);
    }
}

#[test]
fn a_drawn_joint_on_two_blocks_is_a_prp() {
    // Proves: a joint pinned to two blocks, one in a slot of a turning link
    // and one on the ground, becomes a PRP on the carried and the fixed
    // line: C = (0.1 / cos(theta), 0) (worked by hand: the slot square to
    // the crank through its tip meets the x axis there) within 8 ulps of
    // C's distance over theta in [-60 deg, 60 deg].
    let d = DrawnCrossSlide::<f64>::default();
    for k in -60..=60 {
        let theta = (k as f64).to_radians();
        let p = d.position(&DrawnCrossSlideInput { theta }).unwrap();
        let hand = mechanism::Point2::new(0.1 / theta.cos(), 0.0);
        let tol = 8.0 * f64::EPSILON * hand.x;
        assert!((p.C - hand).norm() <= tol, "{k}: {} {hand}", p.C);
    }
}

mechanism! {
    /// A slot in a block: the cart slides on the ground along +x (driven by
    /// `s`), the block at J slides in its vertical slot and is pinned to
    /// the rod O-J (0.5), which turns about O.
    pub DrawnCartSlot {
        joints { O = (0.0, 0.0), Q = (0.0, -0.2), J = (0.3, 0.4) }
        links { ground = [O], rod = [O, J] }
        slider cart at Q on ground along 0 deg;
        slider b2 at J on cart along 90 deg;
        input s = slide(cart);
        range s = (-0.7, 0.15);
    }
}

#[test]
fn a_drawn_slot_in_a_sliding_block_turns_with_the_block_s_line() {
    // Proves: a slot in a block is carried by the block, whose axis is its
    // line (not two of its joints: it has one): J = (0.3 + s, sqrt(0.25 -
    // (0.3 + s)^2)) (worked by hand: the slot x = 0.3 + s meets the rod's
    // circle above O, as drawn) within 8 ulps of the rod over the stroke.
    let d = DrawnCartSlot::<f64>::default();
    for k in 0..=85 {
        let s = -0.7 + 0.01 * k as f64;
        let p = d.position(&DrawnCartSlotInput { s }).unwrap();
        let x = 0.3 + s;
        let hand = mechanism::Point2::new(x, (0.25 - x * x).sqrt());
        assert!(
            (p.J - hand).norm() <= 8.0 * f64::EPSILON * 0.5,
            "{s}: {} {hand}",
            p.J
        );
    }
}

mechanism! {
    /// A one-name cylinder: `lift` from the ground joint B to the boom's
    /// joint C (the boom turns about A), drawn with C at 0.3 rad.
    pub DrawnLift {
        joints {
            A = (0.0, 0.0),
            B = (0.8, -0.9),
            C = (2.2 * cos(0.3), 2.2 * sin(0.3)),
        }
        links { ground = [A, B], boom = [A, C] }
        cylinder lift from B to C;
        input len = length(lift);
        range len = (1.9, 3.0);
    }
}

#[test]
fn a_drawn_cylinder_places_its_rod_end_on_the_drawn_side() {
    // Proves: `length(lift)` drives the boom so that |C - B| = len and
    // |C - A| = 2.2 with C on the drawn side of A -> B (its left): C from the
    // law of cosines (worked here) within 8 ulps of the boom over the
    // stroke, and the cylinder's angle is that of B -> C.
    let d = DrawnLift::<f64>::default();
    let (b, r) = (mechanism::Vector2::<f64>::new(0.8, -0.9), 2.2);
    let ab = b.norm();
    for k in 0..=110 {
        let len = 1.9 + 0.01 * k as f64;
        let p = d.position(&DrawnLiftInput { len }).unwrap();
        let along = (r * r - len * len + ab * ab) / (2.0 * ab);
        let h = (r * r - along * along).sqrt();
        let (u, n) = (b / ab, mechanism::Vector2::new(0.9, 0.8) / ab);
        let hand = mechanism::Point2::origin() + u * along + n * h;
        assert!(
            (p.C - hand).norm() <= 8.0 * f64::EPSILON * r,
            "{len}: {} {hand}",
            p.C
        );
        let axis = (p.C.y + 0.9).atan2(p.C.x - 0.8);
        assert!((p.lift - axis).abs() <= 8.0 * f64::EPSILON, "{len}");
    }
}

mechanism! {
    /// The carried yoke of `tests/zoo/prismatic.rs` (m, kg, N), as written
    /// there with groups.
    pub GroupedCarriedYoke {
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

mechanism! {
    /// The same carried yoke as drawn at phi = 0.5 rad: the frame slides on
    /// the crank's line (Q, its joint, at the foot of P on that line), the
    /// ground-pinned block at P in the frame's slot square to it.
    pub DrawnCarriedYoke {
        joints {
            O = (0.0, 0.0),
            P = (0.25, 0.05),
            A = (8.77582561890372786e-2, 4.79425538604203033e-2),
            Q = (2.13574562853714900e-1, 1.16676315454283572e-1),
            Gc = (3.51033024756149115e-2, 1.91770215441681192e-2),
        }
        links { ground = [O, P], crank_link = [O, A, Gc] }
        slider frame at Q on crank_link along 0.5;
        slider block at P on frame along 0.5 + pi / 2.0;
        input phi = angle(crank_link);
        let Gf = point(frame, from Q, (0.03, 0.01));
        mass crank_link { m = 0.6, at = Gc, j = 0.001 };
        mass block { m = 0.1, at = P };
        mass frame { m = 1.2, at = Gf, j = 0.004 };
        gravity (0.0, -9.81);
        force at Gf on frame along frame_line = -8.0;
    }
}

#[test]
fn a_drawn_yoke_on_a_turning_link_is_the_grouped_carried_rpp() {
    // Proves: a yoke drawn sliding on a moving link, with a block in its
    // slot pinned at a ground joint, becomes the zoo's RPP on the carried
    // line (its slot angle and its offset from the crank's pivot read from
    // the drawing): over a full turn at 3 rad/s and 1 rad/s^2 the frame's
    // point Gf, the driving torque and the ground's reaction at O agree
    // within 2e-15 (motion) and 4e-15 (forces) of their scales (0.3 m; the larger of the torque over
    // 0.1 m and the reaction); measured 3.8e-16 (motion) and 1.0e-15
    // (forces).
    let (d, g) = (
        DrawnCarriedYoke::<f64>::default(),
        GroupedCarriedYoke::<f64>::default(),
    );
    let mut worst = [0.0f64; 2];
    for k in 0..720 {
        let phi = (k as f64 / 2.0).to_radians();
        let pd = d.position(&DrawnCarriedYokeInput { phi }).unwrap();
        let pg = g.position(&GroupedCarriedYokeInput { phi }).unwrap();
        let vd = d.velocity(&pd, &DrawnCarriedYokeInput { phi: 3.0 });
        let vg = g.velocity(&pg, &GroupedCarriedYokeInput { phi: 3.0 });
        let (vd, vg) = (vd.unwrap(), vg.unwrap());
        let ad = d.acceleration(&pd, &vd, &DrawnCarriedYokeInput { phi: 1.0 });
        let ag = g.acceleration(&pg, &vg, &GroupedCarriedYokeInput { phi: 1.0 });
        let (ad, ag) = (ad.unwrap(), ag.unwrap());
        let fd = d.forces(&pd, &vd, &ad).unwrap();
        let fg = g.forces(&pg, &vg, &ag).unwrap();
        worst[0] = worst[0].max((pd.Gf - pg.Gf).norm() / 0.3);
        let scale = (fg.drive_phi.abs() / 0.1).max(fg.r_ground_crank_link.norm());
        worst[1] = worst[1]
            .max((fd.drive_phi - fg.drive_phi).abs() / 0.1 / scale)
            .max((fd.r_ground_crank_link - fg.r_ground_crank_link).norm() / scale);
    }
    eprintln!(
        "drawn carried yoke: largest differences {:e} {:e}",
        worst[0], worst[1]
    );
    assert!(
        worst[0] < 2e-15 && worst[1] < 4e-15,
        "{:e} {:e}",
        worst[0],
        worst[1]
    );
}

mechanism! {
    /// The slotted rocker of `tests/zoo/prismatic.rs` (m, kg, N), as
    /// written there with groups.
    pub GroupedSlottedRocker {
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
    /// The same slotted rocker as drawn at theta = 1 rad: the crank's block
    /// in the rocker's slot (along O4 -> A), a second slot of the rocker
    /// square to it through D, holding the block at E of the link from O6.
    pub DrawnSlottedRocker {
        joints {
            O2 = (0.0, 0.0),
            O4 = (0.0, -0.3),
            O6 = (0.35, 0.1),
            A = (5.40302305868139779e-2, 8.41470984807896616e-2),
            D = (6.96394794715609194e-2, 1.95126592801204757e-1),
            E = (1.16217213755165749e-1, 1.88575441605459443e-1),
            G4 = (4.17836876829365475e-2, -2.92404431927717479e-3),
            G5 = (2.37784262602479535e-1, 1.42516211970620532e-1),
        }
        links {
            ground = [O2, O4, O6],
            crank = [O2, A],
            rocker = [O4, D, G4],
            link5 = [O6, E, G5],
        }
        slider block at A on rocker along 1.4310630875220756;
        slider slider5 at E on rocker along 3.001859414316972;
        input theta = angle(crank);
        mass rocker { m = 2.0, at = G4, j = 0.05 };
        mass block { m = 0.3, at = A };
        mass link5 { m = 0.6, at = G5, j = 0.004 };
        mass slider5 { m = 0.4, at = E };
        gravity (0.0, -9.81);
        force at E on slider5 along slider5_line = -20.0;
    }
}

#[test]
fn a_drawn_slot_in_a_slotted_rocker_is_the_grouped_one() {
    // Proves: a second slot on an RPR's rocker (whose axis is its first
    // slot) is carried at the drawn angle between the two slots and the
    // drawn offset from the pivot: over a full turn at 4 rad/s and 1 rad/s^2
    // E, the driving torque and the ground's reactions at O4 and O6 agree
    // with the zoo's grouped form within 2e-14 (motion) and 1e-13 (forces) of their scales (0.25 m; the
    // larger of the torque over 0.1 m and the reactions); measured 4.3e-15
    // (motion) and 2.4e-14 (forces): the two slots' drawn angles, 17 digits
    // each, make their right angle to about 2e-16 rad.
    let (d, g) = (
        DrawnSlottedRocker::<f64>::default(),
        GroupedSlottedRocker::<f64>::default(),
    );
    let mut worst = [0.0f64; 2];
    for k in 0..720 {
        let theta = (k as f64 / 2.0).to_radians();
        let pd = d.position(&DrawnSlottedRockerInput { theta }).unwrap();
        let pg = g.position(&GroupedSlottedRockerInput { theta }).unwrap();
        let vd = d.velocity(&pd, &DrawnSlottedRockerInput { theta: 4.0 });
        let vg = g.velocity(&pg, &GroupedSlottedRockerInput { theta: 4.0 });
        let (vd, vg) = (vd.unwrap(), vg.unwrap());
        let ad = d.acceleration(&pd, &vd, &DrawnSlottedRockerInput { theta: 1.0 });
        let ag = g.acceleration(&pg, &vg, &GroupedSlottedRockerInput { theta: 1.0 });
        let (ad, ag) = (ad.unwrap(), ag.unwrap());
        let fd = d.forces(&pd, &vd, &ad).unwrap();
        let fg = g.forces(&pg, &vg, &ag).unwrap();
        worst[0] = worst[0].max((pd.E - pg.E).norm() / 0.25);
        let scale = (fg.drive_theta.abs() / 0.1)
            .max(fg.r_ground_rocker.norm())
            .max(fg.r_ground_link5.norm());
        worst[1] = worst[1]
            .max((fd.drive_theta - fg.drive_theta).abs() / 0.1 / scale)
            .max((fd.r_ground_rocker - fg.r_ground_rocker).norm() / scale)
            .max((fd.r_ground_link5 - fg.r_ground_link5).norm() / scale);
    }
    eprintln!(
        "drawn slotted rocker: largest differences {:e} {:e}",
        worst[0], worst[1]
    );
    assert!(
        worst[0] < 2e-14 && worst[1] < 1e-13,
        "{:e} {:e}",
        worst[0],
        worst[1]
    );
}

mechanism! {
    /// A boom and a stick, each lifted by a cylinder (m, kg, N): the boom
    /// cylinder from the ground at B to the boom at C, the stick cylinder
    /// from the boom at F to the stick at G; the stick turns about the
    /// boom's tip K.
    pub GroupedBoomStick {
        let A = ground(0.0, 0.0);
        let B = ground(0.8, -0.9);
        let C = actuator(A, 2.2, B, len1, left) as (boom, cyl1);
        let K = point(boom, from A, 5.0, 0 deg);
        let F = point(boom, from A, 3.0, 10 deg);
        let G = actuator(K, 0.6, F, len2, left) as (stick, cyl2);
        let Tip = point(stick, from K, 3.0, 150 deg);
        mass boom { m = 1800.0, at = F, j = 4500.0 };
        mass stick { m = 700.0, at = Tip, j = 600.0 };
        gravity (0.0, -9.81);
        range len1 = (1.9, 3.0);
        range len2 = (1.6, 2.6);
    }
}

mechanism! {
    /// The same boom and stick as drawn, the boom at 0.3 rad and the stick
    /// at 3.8 rad (K -> G).
    pub DrawnBoomStick {
        joints {
            A = (0.0, 0.0),
            B = (0.8, -0.9),
            C = (2.10174027607633329, 6.50144454654947079e-1),
            K = (4.77668244562802968, 1.47760103330669779),
            F = (2.66851870762759047, 1.37076909326172558),
            G = (4.30210181847937978, 1.11048629874106641),
            Tip = (7.74946367831551708, 1.88080289662216105),
        }
        links { ground = [A, B], boom = [A, C, K, F], stick = [K, G, Tip] }
        cylinder cyl1 from B to C;
        cylinder cyl2 from F to G;
        input len1 = length(cyl1);
        input len2 = length(cyl2);
        mass boom { m = 1800.0, at = F, j = 4500.0 };
        mass stick { m = 700.0, at = Tip, j = 600.0 };
        gravity (0.0, -9.81);
        range len1 = (1.9, 3.0);
        range len2 = (1.6, 2.6);
    }
}

#[test]
fn a_drawn_boom_and_stick_with_two_cylinders_is_the_grouped_arm() {
    // Proves: a cylinder whose barrel is pinned to a moving link (the stick
    // cylinder on the boom) is placed after that link: over a 23 x 21 grid
    // of the two strokes, the stick's tip, both link angles and the two
    // cylinders' driving forces (static, under gravity) agree with the
    // grouped arm within 8e-15 (motion) and 2.5e-14 (forces) of their scales (the 8 m reach; the larger
    // force); measured 2.0e-15 (motion) and 5.5e-15 (forces), the rounding
    // of the 18-digit drawing carried through two groups.
    let (d, g) = (
        DrawnBoomStick::<f64>::default(),
        GroupedBoomStick::<f64>::default(),
    );
    let mut worst = [0.0f64; 2];
    for i in 0..=22 {
        for k in 0..=20 {
            let (len1, len2) = (1.9 + 0.05 * i as f64, 1.6 + 0.05 * k as f64);
            let pd = d.position(&DrawnBoomStickInput { len1, len2 }).unwrap();
            let pg = g.position(&GroupedBoomStickInput { len1, len2 }).unwrap();
            let zd = DrawnBoomStickInput {
                len1: 0.0,
                len2: 0.0,
            };
            let zg = GroupedBoomStickInput {
                len1: 0.0,
                len2: 0.0,
            };
            let (vd, vg) = (d.velocity(&pd, &zd).unwrap(), g.velocity(&pg, &zg).unwrap());
            let ad = d.acceleration(&pd, &vd, &zd).unwrap();
            let ag = g.acceleration(&pg, &vg, &zg).unwrap();
            let fd = d.forces(&pd, &vd, &ad).unwrap();
            let fg = g.forces(&pg, &vg, &ag).unwrap();
            worst[0] = worst[0]
                .max((pd.Tip - pg.Tip).norm() / 8.0)
                .max((pd.boom - pg.boom).abs())
                .max((pd.stick - pg.stick).abs());
            let scale = fg.drive_len1.abs().max(fg.drive_len2.abs());
            worst[1] = worst[1]
                .max((fd.drive_len1 - fg.drive_len1).abs() / scale)
                .max((fd.drive_len2 - fg.drive_len2).abs() / scale);
        }
    }
    eprintln!(
        "drawn boom and stick: largest differences {:e} {:e}",
        worst[0], worst[1]
    );
    assert!(
        worst[0] < 8e-15 && worst[1] < 2.5e-14,
        "{:e} {:e}",
        worst[0],
        worst[1]
    );
}

mechanism! {
    /// The loaded cross-slide of `tests/zoo/prismatic.rs` (m, kg, N), as
    /// written there with groups.
    pub GroupedCrossSlide {
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
    /// The same cross-slide as drawn at phi = 0.4 rad: C on a block in the
    /// crank's slot (its own line) and on a block on the vertical x = 0.29.
    pub DrawnLoadedCrossSlide {
        joints {
            O = (0.0, 0.0),
            A = (9.21060994002885214e-2, 3.89418342308650578e-2),
            Gc = (4.60530497001442607e-2, 1.94709171154325289e-2),
            C = (0.29, 1.22610033434066915e-1),
        }
        links { ground = [O], crank_link = [O, A, Gc] }
        slider b1 at C on crank_link along 0.4;
        slider b2 at C on ground along 90 deg;
        input phi = angle(crank_link);
        let G2 = point(b2, from C, (0.0, 0.04));
        mass crank_link { m = 0.8, at = Gc, j = 0.002 };
        mass b1 { m = 0.25, at = C };
        mass b2 { m = 1.5, at = G2, j = 0.006 };
        gravity (0.0, -9.81);
        force at G2 on b2 along b2_line = -30.0;
        range phi = (-80 deg, 80 deg);
    }
}

#[test]
fn a_drawn_cross_slide_is_the_grouped_prp_with_its_forces() {
    // Proves: the PRP found at a joint on two blocks carries the reactions
    // as the zoo's grouped cross-slide does: over phi in [-80, 80] deg at
    // 2 rad/s and 1 rad/s^2, G2, the driving torque and the ground's
    // reactions at O and on b2 agree within 2e-16 (motion) and 1e-15 (forces) of their scales (0.3 m;
    // the larger of the torque over 0.1 m and the reactions); measured
    // 4.6e-17 (motion) and 2.5e-16 (forces).
    let (d, g) = (
        DrawnLoadedCrossSlide::<f64>::default(),
        GroupedCrossSlide::<f64>::default(),
    );
    let mut worst = [0.0f64; 2];
    for k in -160..=160 {
        let phi = (k as f64 / 2.0).to_radians();
        let pd = d.position(&DrawnLoadedCrossSlideInput { phi }).unwrap();
        let pg = g.position(&GroupedCrossSlideInput { phi }).unwrap();
        let vd = d.velocity(&pd, &DrawnLoadedCrossSlideInput { phi: 2.0 });
        let vg = g.velocity(&pg, &GroupedCrossSlideInput { phi: 2.0 });
        let (vd, vg) = (vd.unwrap(), vg.unwrap());
        let ad = d.acceleration(&pd, &vd, &DrawnLoadedCrossSlideInput { phi: 1.0 });
        let ag = g.acceleration(&pg, &vg, &GroupedCrossSlideInput { phi: 1.0 });
        let (ad, ag) = (ad.unwrap(), ag.unwrap());
        let fd = d.forces(&pd, &vd, &ad).unwrap();
        let fg = g.forces(&pg, &vg, &ag).unwrap();
        worst[0] = worst[0].max((pd.G2 - pg.G2).norm() / 0.3);
        let scale = (fg.drive_phi.abs() / 0.1)
            .max(fg.r_ground_crank_link.norm())
            .max(fg.r_ground_b2.normal.abs());
        worst[1] = worst[1]
            .max((fd.drive_phi - fg.drive_phi).abs() / 0.1 / scale)
            .max((fd.r_ground_crank_link - fg.r_ground_crank_link).norm() / scale)
            .max((fd.r_ground_b2.normal - fg.r_ground_b2.normal).abs() / scale);
    }
    eprintln!(
        "drawn cross-slide: largest differences {:e} {:e}",
        worst[0], worst[1]
    );
    assert!(
        worst[0] < 2e-16 && worst[1] < 1e-15,
        "{:e} {:e}",
        worst[0],
        worst[1]
    );
}

mechanism! {
    /// The Watt II six-bar of `tests/zoo/revolute.rs` (m, kg, N), as written
    /// there with groups: crank O2-A, coupler A-B, ternary rocker O4-B-E,
    /// coupler E-F, output O6-F, masses on every moving link.
    pub GroupedWattII {
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.40, 0.0);
        let O6 = ground(0.78, 0.22);
        let A = crank(O2, 0.10, theta) as crank;
        let B = rrr(A, 0.36, O4, 0.25, left) as (coupler, rocker);
        let E = point(rocker, from O4, 0.18, -35 deg);
        let F = rrr(E, 0.32, O6, 0.22, left) as (coupler2, output);
        let G2 = point(crank, from O2, 0.05, 0 deg);
        let G3 = point(coupler, from A, 0.18, 5 deg);
        let G4 = point(rocker, from O4, 0.12, -15 deg);
        let G5 = point(coupler2, from E, 0.16, 0 deg);
        let G6 = point(output, from O6, 0.11, 0 deg);
        mass crank { m = 0.8, at = G2, j = 0.0012 };
        mass coupler { m = 1.6, at = G3, j = 0.021 };
        mass rocker { m = 1.1, at = G4, j = 0.009 };
        mass coupler2 { m = 1.3, at = G5, j = 0.014 };
        mass output { m = 0.7, at = G6, j = 0.004 };
        gravity (0.0, -9.81);
        force at G5 = (12.0, -30.0);
        torque on output = -4.0;
    }
}

mechanism! {
    /// The same Watt II as drawn at theta = 1 rad (the joints to 18 digits
    /// of the exact pose): the rocker is a ternary link with its mass centre
    /// G4 as a fourth joint; every mass centre is a joint of its link.
    pub DrawnWattII {
        joints {
            O2 = (0.0, 0.0),
            O4 = (0.40, 0.0),
            O6 = (0.78, 0.22),
            A = (5.40302305868139717e-2, 8.41470984807896507e-2),
            B = (3.7423725383147405e-1, 2.48669018797790935e-1),
            E = (4.87499500078601293e-1, 1.57301740251005654e-1),
            F = (6.77599701103903269e-1, 4.14715635699832926e-1),
            G2 = (2.70151152934069859e-2, 4.20735492403948253e-2),
            G3 = (2.06354984929099677e-1, 1.80048971322576803e-1),
            G4 = (4.18948180533527718e-1, 1.18494584072306196e-1),
            G5 = (5.82549600591252281e-1, 2.8600868797541929e-1),
            G6 = (7.28799850551951634e-1, 3.17357817849916463e-1),
        }
        links {
            ground = [O2, O4, O6],
            crank = [O2, A, G2],
            coupler = [A, B, G3],
            rocker = [O4, B, E, G4],
            coupler2 = [E, F, G5],
            output = [O6, F, G6],
        }
        input theta = angle(crank);
        mass crank { m = 0.8, at = G2, j = 0.0012 };
        mass coupler { m = 1.6, at = G3, j = 0.021 };
        mass rocker { m = 1.1, at = G4, j = 0.009 };
        mass coupler2 { m = 1.3, at = G5, j = 0.014 };
        mass output { m = 0.7, at = G6, j = 0.004 };
        gravity (0.0, -9.81);
        force at G5 = (12.0, -30.0);
        torque on output = -4.0;
    }
}

#[test]
fn a_drawn_watt_ii_is_the_grouped_one_with_its_forces() {
    // Proves: a Watt II six-bar drawn with a ternary rocker decomposes into
    // the zoo's crank, two RRRs and points, in their assemblies: over a full
    // turn (1440 angles, at 12 rad/s and -30 rad/s^2) the joints, mass
    // centres, link angles, their rates and accelerations, the driving
    // torque and all seven joint reactions agree within 48 ulps of each
    // column's scale (its largest grouped magnitude); measured 11.8 ulps
    // (aG6, alpha_output). The drawing's lengths and offsets are the zoo's
    // within an ulp or two (hypot and projections of 18-digit coordinates),
    // grown through two RRRs and the force solve; 48 is four times the
    // figure measured.
    let (d, g) = (
        DrawnWattII::<f64>::default(),
        GroupedWattII::<f64>::default(),
    );
    let mut c = Columns::default();
    for k in 0..1440 {
        let theta = (k as f64 / 4.0).to_radians();
        let pd = d.position(&DrawnWattIIInput { theta }).unwrap();
        let pg = g.position(&GroupedWattIIInput { theta }).unwrap();
        let vd = d.velocity(&pd, &DrawnWattIIInput { theta: 12.0 });
        let vg = g.velocity(&pg, &GroupedWattIIInput { theta: 12.0 });
        let (vd, vg) = (vd.unwrap(), vg.unwrap());
        let ad = d.acceleration(&pd, &vd, &DrawnWattIIInput { theta: -30.0 });
        let ag = g.acceleration(&pg, &vg, &GroupedWattIIInput { theta: -30.0 });
        let (ad, ag) = (ad.unwrap(), ag.unwrap());
        let fd = d.forces(&pd, &vd, &ad).unwrap();
        let fg = g.forces(&pg, &vg, &ag).unwrap();
        for (name, x, y) in [
            ("B", pd.B, pg.B),
            ("E", pd.E, pg.E),
            ("F", pd.F, pg.F),
            ("G3", pd.G3, pg.G3),
            ("G4", pd.G4, pg.G4),
            ("G5", pd.G5, pg.G5),
            ("G6", pd.G6, pg.G6),
        ] {
            c.point(name, x, y);
        }
        for (name, x, y) in [
            ("vF", vd.F, vg.F),
            ("vG4", vd.G4, vg.G4),
            ("vG5", vd.G5, vg.G5),
            ("aF", ad.F, ag.F),
            ("aG3", ad.G3, ag.G3),
            ("aG4", ad.G4, ag.G4),
            ("aG5", ad.G5, ag.G5),
            ("aG6", ad.G6, ag.G6),
            ("r_ground_crank", fd.r_ground_crank, fg.r_ground_crank),
            ("r_crank_coupler", fd.r_crank_coupler, fg.r_crank_coupler),
            ("r_coupler_rocker", fd.r_coupler_rocker, fg.r_coupler_rocker),
            ("r_ground_rocker", fd.r_ground_rocker, fg.r_ground_rocker),
            (
                "r_rocker_coupler2",
                fd.r_rocker_coupler2,
                fg.r_rocker_coupler2,
            ),
            (
                "r_coupler2_output",
                fd.r_coupler2_output,
                fg.r_coupler2_output,
            ),
            ("r_ground_output", fd.r_ground_output, fg.r_ground_output),
        ] {
            c.vector(name, x, y);
        }
        for (name, x, y) in [
            ("coupler", pd.coupler, pg.coupler),
            ("rocker", pd.rocker, pg.rocker),
            ("coupler2", pd.coupler2, pg.coupler2),
            ("output", pd.output, pg.output),
            ("omega_coupler", vd.coupler, vg.coupler),
            ("omega_rocker", vd.rocker, vg.rocker),
            ("omega_coupler2", vd.coupler2, vg.coupler2),
            ("omega_output", vd.output, vg.output),
            ("alpha_coupler", ad.coupler, ag.coupler),
            ("alpha_rocker", ad.rocker, ag.rocker),
            ("alpha_coupler2", ad.coupler2, ag.coupler2),
            ("alpha_output", ad.output, ag.output),
            ("drive_theta", fd.drive_theta, fg.drive_theta),
        ] {
            c.scalar(name, x, y);
        }
    }
    let ulps = c.report("drawn Watt II");
    assert!(ulps < 48.0, "{ulps}");
}

mechanism! {
    /// An elliptic trammel (m, kg, N), with groups: block `block_a` slides on
    /// the x axis, driven by its x (`s`), block `block_b` on the y axis; the
    /// rod A-B (0.2) carries the pen P 0.3 from A, beyond B, which traces the
    /// ellipse of semi-axes 0.1 (x) and 0.3 (y).
    pub GroupedTrammel {
        let x_axis = guide((0.0, 0.0), 0 deg);
        let y_axis = guide((0.0, 0.0), 90 deg);
        let A = slider(x_axis, s) as block_a;
        let B = rrp(A, 0.2, y_axis, plus) as (rod, block_b);
        let P = point(rod, from A, 0.3, 0 deg);
        let G = point(rod, from A, 0.1, 0 deg);
        mass block_a { m = 0.4, at = A };
        mass rod { m = 0.3, at = G, j = 0.001 };
        mass block_b { m = 0.4, at = B };
        gravity (0.0, -9.81);
        force at P = (-2.0, 1.5);
    }
}

mechanism! {
    /// The same trammel as drawn with A at x = 0.12: the ground has no pin,
    /// only the blocks' lines (`ground = []`); the rod's joints are on the
    /// blocks, its mass centre G halfway, the pen P beyond B. `s` is A's
    /// slide from its drawn place.
    pub DrawnTrammel {
        joints { A = (0.12, 0.0), B = (0.0, 0.16), G = (0.06, 0.08), P = (-0.06, 0.24) }
        links { ground = [], rod = [A, B, P, G] }
        slider block_a at A on ground along 0 deg;
        slider block_b at B on ground along 90 deg;
        input s = slide(block_a);
        mass block_a { m = 0.4, at = A };
        mass rod { m = 0.3, at = G, j = 0.001 };
        mass block_b { m = 0.4, at = B };
        gravity (0.0, -9.81);
        force at P = (-2.0, 1.5);
    }
}

#[test]
fn a_drawn_rrp_names_its_blocks_slide() {
    // Proves the drawn form gives the RRP it finds a slide output, named as
    // an RPR's is, `BLOCK_slide`: `block_b_slide` is B's displacement up its
    // line (90 deg) from its drawn place (0, 0.16), in position, rate and
    // acceleration, over A's travel. B = origin + slide * dir, so the two
    // differ by the rounding of that sum and of cos(90 deg) ~ 6e-17 times
    // x: 4 ulps of the largest value (0.36) bound it.
    let d = DrawnTrammel::<f64>::default();
    let tol = 4.0 * f64::EPSILON * 0.36;
    for k in -19..=19 {
        let s = k as f64 / 100.0 - 0.12;
        let p = d.position(&DrawnTrammelInput { s }).unwrap();
        let v = d.velocity(&p, &DrawnTrammelInput { s: 0.5 }).unwrap();
        let a = d
            .acceleration(&p, &v, &DrawnTrammelInput { s: -2.0 })
            .unwrap();
        assert!((p.block_b_slide - (p.B.y - 0.16)).abs() <= tol, "{s}");
        assert!((v.block_b_slide - v.B.y).abs() <= tol * 10.0, "{s}");
        assert!((a.block_b_slide - a.B.y).abs() <= tol * 100.0, "{s}");
    }
}

#[test]
fn a_drawn_trammel_is_the_grouped_one_with_its_forces() {
    // Proves: a ground with no pin (`ground = []`, two blocks on its lines)
    // and a rod whose joints are on blocks only decompose into the slider
    // driver, the RRP and the rod's points written by hand, in its
    // assembly: over A's travel from -0.19 to 0.19 (1521 places, short of
    // the dead ends at +-0.2 where the rod lies on the x axis), at 0.5 m/s
    // and -2 m/s^2, B, G, the pen P, their rates and accelerations, the
    // rod's angle, rate and acceleration, the driving force and the
    // reactions agree within 8 ulps of each column's scale (its largest
    // grouped magnitude); measured 1.9 ulps (G). The drawing is exact
    // decimals and both put A at the same float, so only the rounding of
    // the rod's length and P's and G's offsets from the drawing remains.
    // (Given the grouped one x and the drawn one x - 0.12, A differs by up
    // to an ulp, which the near-dead poses grow to 25 ulps in the forces.)
    let (d, g) = (
        DrawnTrammel::<f64>::default(),
        GroupedTrammel::<f64>::default(),
    );
    let mut c = Columns::default();
    for k in -760..=760 {
        // The drawn slide is measured from A's drawn place, x = 0.12: the
        // grouped A is given where the drawn one lands, 0.12 + s, rounded.
        let s = k as f64 / 4000.0 - 0.12;
        let pd = d.position(&DrawnTrammelInput { s }).unwrap();
        let pg = g.position(&GroupedTrammelInput { s: 0.12 + s }).unwrap();
        let vd = d.velocity(&pd, &DrawnTrammelInput { s: 0.5 }).unwrap();
        let vg = g.velocity(&pg, &GroupedTrammelInput { s: 0.5 }).unwrap();
        let ad = d.acceleration(&pd, &vd, &DrawnTrammelInput { s: -2.0 });
        let ag = g.acceleration(&pg, &vg, &GroupedTrammelInput { s: -2.0 });
        let (ad, ag) = (ad.unwrap(), ag.unwrap());
        let fd = d.forces(&pd, &vd, &ad).unwrap();
        let fg = g.forces(&pg, &vg, &ag).unwrap();
        c.point("A", pd.A, pg.A);
        c.point("B", pd.B, pg.B);
        c.point("G", pd.G, pg.G);
        c.point("P", pd.P, pg.P);
        for (name, x, y) in [
            ("vB", vd.B, vg.B),
            ("vP", vd.P, vg.P),
            ("aB", ad.B, ag.B),
            ("aG", ad.G, ag.G),
            ("aP", ad.P, ag.P),
            ("r_block_a_rod", fd.r_block_a_rod, fg.r_block_a_rod),
            ("r_rod_block_b", fd.r_rod_block_b, fg.r_rod_block_b),
        ] {
            c.vector(name, x, y);
        }
        for (name, x, y) in [
            ("rod", pd.rod, pg.rod),
            ("omega_rod", vd.rod, vg.rod),
            ("alpha_rod", ad.rod, ag.rod),
            ("drive_s", fd.drive_s, fg.drive_s),
            (
                "r_ground_block_a",
                fd.r_ground_block_a.normal,
                fg.r_ground_block_a.normal,
            ),
            (
                "m_ground_block_a",
                fd.r_ground_block_a.moment,
                fg.r_ground_block_a.moment,
            ),
            (
                "r_ground_block_b",
                fd.r_ground_block_b.normal,
                fg.r_ground_block_b.normal,
            ),
            (
                "m_ground_block_b",
                fd.r_ground_block_b.moment,
                fg.r_ground_block_b.moment,
            ),
        ] {
            c.scalar(name, x, y);
        }
    }
    let ulps = c.report("drawn trammel");
    assert!(ulps < 8.0, "{ulps}");
}
