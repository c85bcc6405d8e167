//! The drawn form (joints at a reference pose, links as joint sets, inputs):
//! each drawn definition here against the same mechanism written with group
//! statements, its lengths and offsets computed from the same coordinates in
//! the test, over the input range.

use mechanism::mechanism;

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
        "m",
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
