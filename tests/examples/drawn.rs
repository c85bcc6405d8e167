//! The examples' mechanisms written as drawn (`joints`, `links`, `slider`,
//! `input`; joints taken from the grouped scenes at one input, 18 digits)
//! against the grouped scenes of `examples/common/scenes.rs`, over their
//! input ranges. The drawings' lengths are the scenes' to the rounding of
//! 18 digits (about 1e-16 relative), so every joint agrees to that times
//! the growth through the groups.

use crate::scenes::{
    FiveBar, FiveBarInput, FourBar, FourBarInput, Shaper, ShaperForces, ShaperForcesInput,
    ShaperForcesLoads, ShaperInput, SineMechanism, SineMechanismInput, SixBar, SixBarInput,
    SliderCrank, SliderCrankInput,
};
use mechanism::mechanism;

use crate::columns::Columns;

mechanism! {
    /// The four-bar of seed 002 (mm), drawn at theta2 = 1 rad.
    pub DrawnFourBar {
        joints {
            O2 = (0.0, 0.0),
            O4 = (304.8, 0.0),
            A = (5.48947142762029969e1, 8.54934520564822833e1),
            B = (2.91715884121574788e2, 1.77317923266882246e2),
        }
        links { ground = [O2, O4], link2 = [O2, A], link3 = [A, B], link4 = [O4, B] }
        input theta2 = angle(link2);
    }
}

mechanism! {
    /// The five-bar robot (m), drawn at q1 = 1.8 rad, q2 = 0.9 rad.
    pub DrawnFiveBar {
        joints {
            O1 = (0.0, 0.0),
            O2 = (0.08, 0.0),
            A = (-2.27202094693087116e-2, 9.73847630878195147e-2),
            C = (1.42160996827066455e-1, 7.83326909627483498e-2),
            P = (7.54225873770696387e-2, 2.23749281158243524e-1),
        }
        links {
            ground = [O1, O2],
            arm1 = [O1, A],
            arm2 = [O2, C],
            forearm1 = [A, P],
            forearm2 = [C, P],
        }
        input q1 = angle(arm1);
        input q2 = angle(arm2);
        range q1 = (60 deg, 150 deg);
        range q2 = (0 deg, 90 deg);
    }
}

#[test]
fn the_drawn_four_bar_is_the_example_four_bar() {
    // Proves: the seed-002 four-bar drawn at one crank angle is the example's
    // over a full turn: joints, link angles and rates within 1e-13 of the
    // scale (304.8 mm; 250 rad/s), measured a few 1e-16.
    let (d, g) = (DrawnFourBar::<f64>::default(), FourBar::<f64>::default());
    let mut worst = 0.0f64;
    for k in 0..3600 {
        let theta2 = (k as f64 / 10.0).to_radians();
        let pd = d.position(&DrawnFourBarInput { theta2 }).unwrap();
        let pg = g.position(&FourBarInput { theta2 }).unwrap();
        let vd = d
            .velocity(&pd, &DrawnFourBarInput { theta2: 250.0 })
            .unwrap();
        let vg = g.velocity(&pg, &FourBarInput { theta2: 250.0 }).unwrap();
        worst = worst
            .max((pd.B - pg.B).norm() / 304.8)
            .max((pd.link3 - pg.link3).abs())
            .max((vd.link4 - vg.link4).abs() / 250.0);
    }
    eprintln!("drawn four-bar: largest difference {worst:e} of the scale");
    assert!(worst < 1e-13, "{worst:e}");
}

#[test]
fn the_drawn_five_bar_is_the_example_five_bar() {
    // Proves: the two-input five-bar drawn at one pose is the example's over
    // its declared ranges (a 46 x 46 grid): the end point within 1e-13 of
    // the base, 0.08 m, measured a few 1e-16.
    let (d, g) = (DrawnFiveBar::<f64>::default(), FiveBar::<f64>::default());
    let mut worst = 0.0f64;
    for i in 0..=45 {
        for k in 0..=45 {
            let (q1, q2) = (
                (60.0 + 2.0 * i as f64).to_radians(),
                (2.0 * k as f64).to_radians(),
            );
            let pd = d.position(&DrawnFiveBarInput { q1, q2 }).unwrap();
            let pg = g.position(&FiveBarInput { q1, q2 }).unwrap();
            worst = worst.max((pd.P - pg.P).norm() / 0.08);
        }
    }
    eprintln!("drawn five-bar: largest difference {worst:e} of the base");
    assert!(worst < 1e-13, "{worst:e}");
}

mechanism! {
    /// The offset slider-crank (m), drawn at theta = 1 rad: the block slides
    /// on the ground along +x through B's drawn place (y = 0.02).
    pub DrawnSliderCrank {
        joints { O = (0.0, 0.0), A = (5.40302305868139779e-2, 8.41470984807896616e-2), B = (4.48853165275891919e-1, 0.02) }
        links { ground = [O], link2 = [O, A], link3 = [A, B] }
        slider slider at B on ground along 0 deg;
        input theta = angle(link2);
    }
}

#[test]
fn the_drawn_slider_crank_is_the_example_slider_crank() {
    // Proves: a block on a ground line in the drawn form becomes the RRP the
    // example writes, in its assembly: the block's pin within 1e-13 of the
    // crank (0.1 m) over a full turn, measured a few 1e-16.
    let (d, g) = (
        DrawnSliderCrank::<f64>::default(),
        SliderCrank::<f64>::default(),
    );
    let mut worst = 0.0f64;
    for k in 0..3600 {
        let theta = (k as f64 / 10.0).to_radians();
        let pd = d.position(&DrawnSliderCrankInput { theta }).unwrap();
        let pg = g.position(&SliderCrankInput { theta }).unwrap();
        worst = worst.max((pd.B - pg.B).norm() / 0.1);
    }
    eprintln!("drawn slider-crank: largest difference {worst:e} of the crank");
    assert!(worst < 1e-13, "{worst:e}");
}

mechanism! {
    /// The Stephenson III six-bar of `examples/stephenson.rs`, drawn at
    /// phi = -28.402242220599071 deg (its joints from the example's table):
    /// the triad and its assembly are found from the drawing.
    pub DrawnStephenson {
        const phi0 = -28.402242220599071 * pi / 180.0;
        joints {
            O2 = (0.0, 0.0),
            O4 = (0.30, 0.0),
            O6 = (0.05, 0.42),
            C = (0.05 + 0.24 * cos(phi0), 0.42 + 0.24 * sin(phi0)),
            A = (-5.9201362974731851e-2, 5.3807049927811955e-2),
            B = (1.7859606664268302e-1, 1.5893736176674175e-1),
            P = (6.9064856947974249e-3, 1.8845381871298039e-1),
        }
        links {
            ground = [O2, O4, O6],
            link6 = [O6, C],
            crank2 = [O2, A],
            rocker = [O4, B],
            link5 = [C, P],
            coupler = [A, B, P],
        }
        input phi = angle(link6);
        range phi = (-50.43 deg, -2.64 deg);
    }
}

#[test]
fn a_drawn_stephenson_is_the_example_with_its_triad() {
    // Proves: a drawing whose only decomposition is a triad becomes the
    // triad statement, in the drawn assembly: over link 6's swing its joints
    // agree with the example's (written with lengths, not coordinates) to
    // the rounding of the 17-digit drawing times the conditioning.
    let d = DrawnStephenson::<f64>::default();
    let g = crate::common::stephenson::Stephenson::<f64>::default();
    for k in 0..=100 {
        let phi = (-50.43 + (50.43 - 2.64) * k as f64 / 100.0).to_radians();
        let pd = d.position(&DrawnStephensonInput { phi }).unwrap();
        let pg = g
            .position(&crate::common::stephenson::StephensonInput { phi })
            .unwrap();
        for (x, y, what) in [(pd.A, pg.A, "A"), (pd.B, pg.B, "B"), (pd.P, pg.P, "P")] {
            assert!((x - y).norm() < 1e-12, "{what} at {k}: {x} vs {y}");
        }
    }
}

mechanism! {
    /// The quick-return shaper of seed 001 (m), drawn at crank = 1 rad: the
    /// block at B slides in link 3's slot, drawn along C -> B; the ram's
    /// block at E on the ground along 180 deg (y = 0.3).
    pub DrawnShaper {
        joints {
            A = (0.0, 0.0),
            C = (0.0, -0.275),
            B = (6.75377882335174706e-2, 1.05183873100987063e-1),
            D = (1.04944000747898045e-1, 3.15751010754129036e-1),
            E = (-4.42267258046776385e-2, 0.3),
        }
        links { ground = [A, C], link2 = [A, B], link3 = [C, D], link4 = [D, E] }
        slider block at B on link3 along 1.3949853527537055;
        slider ram_block at E on ground along 180 deg;
        input crank = angle(link2);
    }
}

#[test]
fn the_drawn_shaper_is_the_example_shaper() {
    // Proves: a block drawn on a moving link, pinned at a crank's tip,
    // becomes the example's RPR (its mode and zero offset read from the
    // drawing, the slotted link's axis along the drawn slot), and D a point
    // of it: over a full turn the ram, both link angles and their rates and
    // accelerations agree within 1e-14 of the scale (0.6 m, 10 rad/s,
    // 100 rad/s^2); measured 2.3e-15.
    let (d, g) = (DrawnShaper::<f64>::default(), Shaper::<f64>::default());
    let mut worst = 0.0f64;
    for k in 0..3600 {
        let crank = (k as f64 / 10.0).to_radians();
        let pd = d.position(&DrawnShaperInput { crank }).unwrap();
        let pg = g.position(&ShaperInput { crank }).unwrap();
        let vd = d.velocity(&pd, &DrawnShaperInput { crank: 10.0 }).unwrap();
        let vg = g.velocity(&pg, &ShaperInput { crank: 10.0 }).unwrap();
        let ad = d
            .acceleration(&pd, &vd, &DrawnShaperInput { crank: 0.0 })
            .unwrap();
        let ag = g
            .acceleration(&pg, &vg, &ShaperInput { crank: 0.0 })
            .unwrap();
        worst = worst
            .max((pd.E - pg.E).norm() / 0.6)
            .max((pd.D - pg.D).norm() / 0.6)
            .max((pd.link3 - pg.link3).abs())
            .max((pd.link4 - pg.link4).abs())
            .max((vd.link3 - vg.link3).abs() / 10.0)
            .max((vd.link4 - vg.link4).abs() / 10.0)
            .max((ad.link3 - ag.link3).abs() / 100.0)
            .max((ad.link4 - ag.link4).abs() / 100.0);
    }
    eprintln!("drawn shaper: largest difference {worst:e} of the scale");
    assert!(worst < 1e-14, "{worst:e}");
}

mechanism! {
    /// The shaper with masses of `examples/shaper_forces.rs` (m, kg, N),
    /// drawn at crank = 1 rad: S3 and S4, the links' centres of mass, are
    /// joints of link 3 and link 4; the cut acts along the ram block's line.
    pub DrawnShaperForces {
        params { m3 = 20.0, j3 = 0.6, m4 = 3.0, j4 = 0.005625, m5 = 60.0 }
        loads { cut = 0.0 }
        joints {
            A = (0.0, 0.0),
            C = (0.0, -0.275),
            B = (6.75377882335174706e-2, 1.05183873100987063e-1),
            D = (1.04944000747898045e-1, 3.15751010754129036e-1),
            E = (-4.42267258046776385e-2, 0.3),
            S3 = (5.24720003739490223e-2, 2.03755053770645067e-2),
            S4 = (3.03586374716102031e-2, 3.07875505377064540e-1),
        }
        links { ground = [A, C], link2 = [A, B], link3 = [C, D, S3], link4 = [D, E, S4] }
        slider block at B on link3 along 1.3949853527537055;
        slider ram_block at E on ground along 180 deg;
        input crank = angle(link2);
        mass link3 { m = m3, at = S3, j = j3 };
        mass link4 { m = m4, at = S4, j = j4 };
        mass ram_block { m = m5, at = E };
        gravity (0.0, -9.81);
        force at E on ram_block along ram_block_line = cut;
    }
}

#[test]
fn the_drawn_shaper_forces_are_the_example_forces() {
    // Proves: the drawn slotted link carries its reactions as the grouped
    // RPR does: over a full turn at 10 rad/s with a 3 kN cut, the driving
    // torque and the ground's reactions at C and on the ram agree within
    // 5e-14 of the larger of the torque and the reaction at C at each angle
    // (up to 3.0 kN m and 20 kN over the turn); measured 1.2e-14.
    let (d, g) = (
        DrawnShaperForces::<f64>::default(),
        ShaperForces::<f64>::default(),
    );
    let mut worst = 0.0f64;
    for k in 0..720 {
        let crank = (k as f64 / 2.0).to_radians();
        let pd = d.position(&DrawnShaperForcesInput { crank }).unwrap();
        let pg = g.position(&ShaperForcesInput { crank }).unwrap();
        let vd = d
            .velocity(&pd, &DrawnShaperForcesInput { crank: 10.0 })
            .unwrap();
        let vg = g.velocity(&pg, &ShaperForcesInput { crank: 10.0 }).unwrap();
        let ad = d
            .acceleration(&pd, &vd, &DrawnShaperForcesInput { crank: 0.0 })
            .unwrap();
        let ag = g
            .acceleration(&pg, &vg, &ShaperForcesInput { crank: 0.0 })
            .unwrap();
        let fd = d
            .forces(&pd, &vd, &ad, &DrawnShaperForcesLoads { cut: 3000.0 })
            .unwrap();
        let fg = g
            .forces(&pg, &vg, &ag, &ShaperForcesLoads { cut: 3000.0 })
            .unwrap();
        let scale = fg.drive_crank.abs().max(fg.r_ground_link3.norm()).max(1.0);
        worst = worst
            .max((fd.drive_crank - fg.drive_crank).abs() / scale)
            .max((fd.r_ground_link3 - fg.r_ground_link3).norm() / scale)
            .max((fd.r_ground_ram_block.normal - fg.r_ground_ram_block.normal).abs() / scale);
    }
    eprintln!("drawn shaper forces: largest difference {worst:e} of the largest");
    assert!(worst < 5e-14, "{worst:e}");
}

mechanism! {
    /// The sine mechanism of seed 000 (m, kg, N), drawn at phi1 = 0.5 rad:
    /// the block at B slides in link 3's horizontal slot, link 3 slides on
    /// the ground along x = 0; Q, link 3's joint, is where its slot crosses
    /// that line.
    pub DrawnSineMechanism {
        params { m2 = 4.0, m3 = 10.0, fr = 400.0 }
        joints { A = (0.0, 0.0), B = (0.1 * cos(0.5), 0.1 * sin(0.5)), Q = (0.0, 0.1 * sin(0.5)) }
        links { ground = [A], link1 = [A, B] }
        slider block2 at B on link3 along 0 deg;
        slider link3 at Q on ground along 90 deg;
        input phi1 = angle(link1);
        mass block2 { m = m2, at = B };
        mass link3 { m = m3, at = Q };
        force at Q = (0.0, -fr);
    }
}

#[test]
fn the_drawn_sine_mechanism_is_the_example_one() {
    // Proves: a block in the slot of a block that slides on the ground
    // becomes the example's RPP (the slot's angle to the yoke's line read
    // from the drawing): over a full turn at 10 rad/s and 5 rad/s^2, Q, its
    // velocity and acceleration, the driving torque and the ground's
    // reaction on link 3 agree within 1e-15 of their scales (0.1 m, 1 m/s,
    // 10 m/s^2, the larger of the torque over 0.1 m and the reaction);
    // measured 1.4e-16.
    let (d, g) = (
        DrawnSineMechanism::<f64>::default(),
        SineMechanism::<f64>::default(),
    );
    let mut worst = 0.0f64;
    for k in 0..720 {
        let phi1 = (k as f64 / 2.0).to_radians();
        let pd = d.position(&DrawnSineMechanismInput { phi1 }).unwrap();
        let pg = g.position(&SineMechanismInput { phi1 }).unwrap();
        let vd = d.velocity(&pd, &DrawnSineMechanismInput { phi1: 10.0 });
        let vg = g.velocity(&pg, &SineMechanismInput { phi1: 10.0 });
        let (vd, vg) = (vd.unwrap(), vg.unwrap());
        let ad = d.acceleration(&pd, &vd, &DrawnSineMechanismInput { phi1: 5.0 });
        let ag = g.acceleration(&pg, &vg, &SineMechanismInput { phi1: 5.0 });
        let (ad, ag) = (ad.unwrap(), ag.unwrap());
        let fd = d.forces(&pd, &vd, &ad).unwrap();
        let fg = g.forces(&pg, &vg, &ag).unwrap();
        let scale = (fg.drive_phi1.abs() / 0.1).max(fg.r_ground_link3.normal.abs());
        worst = worst
            .max((pd.Q - pg.Q).norm() / 0.1)
            .max((vd.Q - vg.Q).norm())
            .max((ad.Q - ag.Q).norm() / 10.0)
            .max((fd.drive_phi1 - fg.drive_phi1).abs() / 0.1 / scale)
            .max((fd.r_ground_link3.normal - fg.r_ground_link3.normal).abs() / scale);
    }
    eprintln!("drawn sine mechanism: largest difference {worst:e}");
    assert!(worst < 1e-15, "{worst:e}");
}

mechanism! {
    /// The six-bar of seed 000, problem 3-28 (mm), drawn at phi1 = 0.8 rad:
    /// the block at F slides on the crank's own line (drawn at 0.8 rad
    /// through A, the crank's pivot); K is the crank's tip, which sets its
    /// axis, and B its other arm.
    pub DrawnSixBar {
        joints {
            A = (0.0, 0.0),
            E = (70.0, 0.0),
            K = (2.78682683738866168e1, 2.86942436359809105e1),
            B = (-2.78682683738866168e1, -2.86942436359809105e1),
            F = (5.68578180665687726e1, 5.85430017510939889e1),
            D = (7.76662727945015493e1, -3.41500843548048268e1),
            C = (1.18074683039585743e1, 1.73330833703015909),
        }
        links {
            ground = [A, E],
            link1 = [A, K, B],
            link4 = [E, F, D],
            link2 = [B, C],
            link3 = [D, C],
        }
        slider block5 at F on link1 along 0.8;
        input phi1 = angle(link1);
        range phi1 = (40 deg, 55 deg);
    }
}

#[test]
fn the_drawn_six_bar_is_the_example_six_bar() {
    // Proves: a block drawn on the crank's own line (a slot of the crank,
    // through its pivot) becomes the example's RRP on the line the crank
    // carries, in its assembly, and the rest its points and RRR: over the
    // declared range (1501 angles, at 10 rad/s and 5 rad/s^2) C, D, F, their
    // velocities and accelerations and links 2, 3, 4's angles, rates and
    // accelerations agree within 256 ulps of each column's scale (its
    // largest grouped magnitude); measured 56 ulps (aC). The drawing's
    // lengths are the scene's within about an ulp (hypot of 18-digit
    // coordinates), and the mechanism amplifies them: a grouped copy whose
    // rod E-F is one ulp longer (60 (1 + eps)) moves aC by 87 ulps and
    // alpha2 by 82; 256 allows about three such length errors.
    let (d, g) = (DrawnSixBar::<f64>::default(), SixBar::<f64>::default());
    let mut c = Columns::default();
    for k in 0..=1500 {
        let phi1 = (40.0 + 15.0 * k as f64 / 1500.0).to_radians();
        let pd = d.position(&DrawnSixBarInput { phi1 }).unwrap();
        let pg = g.position(&SixBarInput { phi1 }).unwrap();
        let vd = d.velocity(&pd, &DrawnSixBarInput { phi1: 10.0 }).unwrap();
        let vg = g.velocity(&pg, &SixBarInput { phi1: 10.0 }).unwrap();
        let ad = d.acceleration(&pd, &vd, &DrawnSixBarInput { phi1: 5.0 });
        let ag = g.acceleration(&pg, &vg, &SixBarInput { phi1: 5.0 });
        let (ad, ag) = (ad.unwrap(), ag.unwrap());
        c.point("C", pd.C, pg.C);
        c.point("D", pd.D, pg.D);
        c.point("F", pd.F, pg.F);
        c.vector("vC", vd.C, vg.C);
        c.vector("vD", vd.D, vg.D);
        c.vector("vF", vd.F, vg.F);
        c.vector("aC", ad.C, ag.C);
        c.vector("aD", ad.D, ag.D);
        c.vector("aF", ad.F, ag.F);
        c.scalar("link2", pd.link2, pg.link2);
        c.scalar("link3", pd.link3, pg.link3);
        c.scalar("link4", pd.link4, pg.link4);
        c.scalar("omega2", vd.link2, vg.link2);
        c.scalar("omega3", vd.link3, vg.link3);
        c.scalar("omega4", vd.link4, vg.link4);
        c.scalar("alpha2", ad.link2, ag.link2);
        c.scalar("alpha3", ad.link3, ag.link3);
        c.scalar("alpha4", ad.link4, ag.link4);
    }
    let ulps = c.report("drawn six-bar");
    assert!(ulps < 256.0, "{ulps}");
}

mechanism! {
    /// The triad of [`DrawnStephenson`] behind a full-turn crank of 0.02 m
    /// drawn below the x axis (at -120 deg): the drawing's input is read in
    /// (-180, 180] deg, the crank's default range is [0, 360] deg.
    pub CrankBelowTriad {
        const phi0 = -28.402242220599071 * pi / 180.0;
        joints {
            O2 = (0.0, 0.0),
            O4 = (0.30, 0.0),
            O6 = (0.05 + 0.24 * cos(phi0) + 0.01, 0.42 + 0.24 * sin(phi0) + 0.01 * sqrt(3.0)),
            C = (0.05 + 0.24 * cos(phi0), 0.42 + 0.24 * sin(phi0)),
            A = (-5.9201362974731851e-2, 5.3807049927811955e-2),
            B = (1.7859606664268302e-1, 1.5893736176674175e-1),
            P = (6.9064856947974249e-3, 1.8845381871298039e-1),
        }
        links {
            ground = [O2, O4, O6],
            crank = [O6, C],
            crank2 = [O2, A],
            rocker = [O4, B],
            link5 = [C, P],
            coupler = [A, B, P],
        }
        input theta = angle(crank);
    }
}

#[test]
fn a_triad_behind_a_full_turn_crank_takes_any_turn_of_the_angle() {
    // Proves: the crank's angle is periodic for the triad's position: at
    // theta, theta - 2 pi and theta + 4 pi the generated position() gives the
    // same assembly (to the rounding of the angle's turns, a few ulps of
    // 4 pi times the joints' rates of 0.02 m/rad at most: 1e-15 m), over
    // the whole turn including (-pi, 0), and at the drawn angle (-120 deg)
    // it is the drawing.
    let m = CrankBelowTriad::<f64>::default();
    let tau = std::f64::consts::TAU;
    for k in 0..72 {
        let theta = tau * (k as f64 + 0.5) / 72.0;
        let p0 = m.position(&CrankBelowTriadInput { theta }).unwrap();
        for turns in [-1.0, 2.0] {
            let p = m
                .position(&CrankBelowTriadInput {
                    theta: theta + turns * tau,
                })
                .unwrap_or_else(|e| panic!("{theta} {turns}: {e}"));
            for (x, y) in [(p.A, p0.A), (p.B, p0.B), (p.P, p0.P)] {
                assert!((x - y).norm() < 1e-14, "{theta} {turns}: {x} vs {y}");
            }
        }
    }
    let drawn = (-120f64).to_radians();
    let p = m.position(&CrankBelowTriadInput { theta: drawn }).unwrap();
    let a = mechanism::Point2::new(-5.920136297473185e-2, 5.3807049927811955e-2);
    assert!((p.A - a).norm() < 1e-12, "{}", p.A);
}
