//! The Rust code samples of `README.md` and `docs/*.md`, compiled and run, with
//! the values their prose claims checked against quantities computed here
//! independently (closed forms, loop closure, virtual work).
//!
//! Each sample is copied verbatim into a module below (with the variables it
//! assumes defined before it). `every_rust_block_of_the_docs_is_in_this_file`
//! keeps the copies honest: every paragraph (run of non-blank lines) of every
//! ```` ```rust ```` block of the docs must occur in this file, line for line
//! (indentation aside), unless the block is listed in `SCHEMATIC` with the
//! reason it cannot compile as written. A sample edited in a doc without this
//! file fails that test. The same file also checks that the paths, test
//! targets, examples and benches the docs name exist.

#![allow(non_snake_case)]

use std::path::Path;

/// Degrees to radians.
fn rad(deg: f64) -> f64 {
    deg.to_radians()
}

/// README.md: the four-bar of seed 002 with a coupler point.
mod readme {
    use mechanism::mechanism;

    mechanism! {
        /// Crank-rocker four-bar with a coupler point P (mm).
        pub FourBar {
            params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
            let O2 = ground(0.0, 0.0);
            let O4 = ground(ground, 0.0);
            let A = crank(O2, crank, theta2) as link2;
            let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
            let P = point(link3, from A, 120.0, 30 deg);
        }
    }

    type Sample = (FourBar<f64>, FourBarPosition<f64>, FourBarVelocity<f64>);

    #[rustfmt::skip] // verbatim from README.md
    fn main() -> Result<(), mechanism::Error> {
        let fb = FourBar::<f64>::default();                     // parameters at their literal values
        let input = FourBarInput { theta2: 0.5 };
        let p = fb.position(&input)?;                           // p.B, p.P: Point2; p.link3: angle (rad)
        let v = fb.velocity(&p, &FourBarInput { theta2: 250.0 })?;   // v.link3: rad/s, v.P: mm/s
        println!("B = ({:.3}, {:.3}) mm, theta3 = {:.3} deg, omega3 = {:.3} rad/s",
            p.B.x, p.B.y, p.link3.to_degrees(), v.link3);
        Ok(())
    }

    #[test]
    fn readme_program_runs() {
        main().expect("the README's program returns Ok");
    }

    /// The same as `main`, returning what it computes.
    pub fn sample() -> Result<Sample, mechanism::Error> {
        let fb = FourBar::<f64>::default();
        let p = fb.position(&FourBarInput { theta2: 0.5 })?;
        let v = fb.velocity(&p, &FourBarInput { theta2: 250.0 })?;
        Ok((fb, p, v))
    }

    /// docs/checks.md, `check()` at run time, on this four-bar (the sample
    /// leaves the loop variable to a comment).
    #[allow(unused_variables)]
    #[rustfmt::skip] // verbatim from docs/checks.md
    pub fn checks_run_time() -> Option<([f64; 1], [f64; 1])> {
        let mut found = None;
        let m = FourBar::<f64> { coupler: 200.0, ..Default::default() };
        let report = m.check();            // mechanism::sweep::Report<G, D>, no heap
        if !report.assembles() {
            for g in report.groups.iter().filter(|g| g.failures > 0) {
                // g.group: "B"; g.failure: Some(([lo], [hi])) in rad; g.fault
            }
        }
        for g in report.groups.iter().filter(|g| g.failures > 0) {
            assert_eq!(g.group, "B");
            found = g.failure;
        }
        found
    }
}

#[test]
fn readme_sample_runs_and_closes_the_loop() {
    let (fb, p, v) = readme::sample().expect("the README's pose assembles");
    // "parameters at their literal values"
    assert_eq!(
        (fb.ground, fb.crank, fb.coupler, fb.rocker),
        (304.8, 101.6, 254.0, 177.8)
    );
    // Loop closure from the definition: |A - O2| = 101.6 at 0.5 rad, |B - A| = 254,
    // |B - O4| = 177.8, B left of A -> O4, P at (120, 30 deg) in link3's frame
    // (x from A to B). Tolerance: 64 eps of the mechanism's size (305 mm), a few
    // roundings of the closure.
    let tol = 64.0 * f64::EPSILON * 305.0;
    let (ax, ay) = (101.6 * 0.5f64.cos(), 101.6 * 0.5f64.sin());
    assert!((p.A.x - ax).abs() < tol && (p.A.y - ay).abs() < tol);
    let dist = |x: f64, y: f64| x.hypot(y);
    assert!((dist(p.B.x - ax, p.B.y - ay) - 254.0).abs() < tol);
    assert!((dist(p.B.x - 304.8, p.B.y) - 177.8).abs() < tol);
    let cross = (304.8 - ax) * (p.B.y - ay) - (0.0 - ay) * (p.B.x - ax);
    assert!(cross > 0.0, "`left`: B left of A -> O4");
    let t3 = (p.B.y - ay).atan2(p.B.x - ax);
    assert!(
        (p.link3 - t3).abs() < 1e-14,
        "link3 is the angle of A -> B (rad)"
    );
    let (px, py) = (
        ax + 120.0 * (t3 + rad(30.0)).cos(),
        ay + 120.0 * (t3 + rad(30.0)).sin(),
    );
    assert!((p.P.x - px).abs() < tol && (p.P.y - py).abs() < tol);
    // Velocities at 250 rad/s: A moves at 250 x 101.6 perpendicular to O2 -> A;
    // the rigid coupler keeps |B - A| (relative velocity perpendicular to it),
    // and P's velocity is A's plus omega3 x (P - A). Tolerance: 64 eps of the
    // speeds' size (250 x 305 mm/s).
    let tolv = 64.0 * f64::EPSILON * 250.0 * 305.0;
    assert!((v.A.x + 250.0 * ay).abs() < tolv && (v.A.y - 250.0 * ax).abs() < tolv);
    let rel = (v.B.x - v.A.x) * (p.B.x - ax) + (v.B.y - v.A.y) * (p.B.y - ay);
    assert!(rel.abs() < tolv * 254.0);
    let (vpx, vpy) = (
        v.A.x - v.link3 * (p.P.y - ay),
        v.A.y + v.link3 * (p.P.x - ax),
    );
    assert!((v.P.x - vpx).abs() < tolv && (v.P.y - vpy).abs() < tolv);
}

#[test]
fn readme_program_prints_what_the_readme_says() {
    // The line the README says it prints, recomputed here from the dimensions
    // alone: B by the law of cosines (left of A -> O4), omega3 from the
    // velocity loop v_A + w3 x (B - A) = w4 x (B - O4), by Cramer's rule.
    let md = std::fs::read_to_string(root().join("README.md")).unwrap();
    let claimed = md
        .lines()
        .find(|l| l.starts_with("B = ("))
        .expect("README.md shows the program's output");
    let (ax, ay) = (101.6 * 0.5f64.cos(), 101.6 * 0.5f64.sin());
    let (dx, dy) = (304.8 - ax, -ay);
    let d = dx.hypot(dy);
    let a = (254.0f64.powi(2) - 177.8f64.powi(2) + d * d) / (2.0 * d);
    let h = (254.0f64.powi(2) - a * a).sqrt();
    let (ex, ey) = (dx / d, dy / d);
    let (bx, by) = (ax + a * ex - h * ey, ay + a * ey + h * ex);
    let theta3 = (by - ay).atan2(bx - ax).to_degrees();
    // Unknowns w3, w4: -w3 (B-A).y + w4 (B-O4).y = -vA.x; w3 (B-A).x - w4 (B-O4).x = -vA.y.
    let (vax, vay) = (-250.0 * ay, 250.0 * ax);
    let (r3x, r3y, r4x, r4y) = (bx - ax, by - ay, bx - 304.8, by);
    let det = -r3y * -r4x - r4y * r3x;
    let w3 = (-vax * -r4x - r4y * -vay) / det;
    let line =
        format!("B = ({bx:.3}, {by:.3}) mm, theta3 = {theta3:.3} deg, omega3 = {w3:.3} rad/s");
    assert_eq!(claimed, line);
}

#[test]
fn seed_002_angles_at_theta2_zero() {
    // docs/seeds.md: at theta2 = 0, theta3 = 44.0486, theta4 = 96.6654 deg (ours,
    // printed to 4 decimals: half a unit of the last digit), the document's 44.05
    // and 96.67 (2 decimals).
    let fb = readme::FourBar::<f64>::default();
    let p = fb.position(&readme::FourBarInput { theta2: 0.0 }).unwrap();
    let (t3, t4) = (p.link3.to_degrees(), p.link4.to_degrees());
    assert!((t3 - 44.0486).abs() <= 5e-5, "theta3 = {t3}");
    assert!((t4 - 96.6654).abs() <= 5e-5, "theta4 = {t4}");
    assert!((t3 - 44.05).abs() <= 5e-3 && (t4 - 96.67).abs() <= 5e-3);
}

#[test]
fn checks_run_time_sample_finds_the_non_grashof_interval() {
    // docs/checks.md's `check()` sample: coupler 200 makes |A - O4| exceed
    // 200 + 177.8 for crank angles around 180 deg. The limits from the law of
    // cosines: |A - O4|^2 = g^2 + c^2 - 2 g c cos(theta) = 377.8^2.
    let (g, c, reach) = (304.8f64, 101.6f64, 377.8f64);
    let lim = ((g * g + c * c - reach * reach) / (2.0 * g * c)).acos();
    let (lo, hi) = readme::checks_run_time().expect("group B fails somewhere");
    // The sweep bisects to 1e-10 of the range (2 pi): 1e-9 rad covers it.
    assert!((lo[0] - lim).abs() < 1e-9, "lo {} vs {}", lo[0], lim);
    assert!((hi[0] - (std::f64::consts::TAU - lim)).abs() < 1e-9);
}

/// docs/dsl.md, the first sample: every optional item of a definition.
mod dsl_intro {
    use mechanism::mechanism;

    mechanism! {
        /// Crank-rocker four-bar (mm).            <- doc comments go onto the generated type
        pub FourBar {                               // visibility and type name
            params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
            const offset = 0.0;                     // folded at compile time
            dof 1;                                  // optional: checked against Gruebler's count
            analysis acceleration;                  // position | velocity | acceleration (default)
            outputs { B, P, link3, link4 }          // optional: default is every named thing
            let O2 = ground(0.0, offset);
            let O4 = ground(ground, 0.0);
            let A  = crank(O2, crank, theta2) as link2;
            let B  = rrr(A, coupler, O4, rocker, left) as (link3, link4);
            let P  = point(link3, from A, 120.0, 30 deg);
        }
    }

    #[test]
    fn dsl_intro_outputs_and_analyses() {
        let m = FourBar::<f64>::default();
        let s = m
            .solve(
                &FourBarInput { theta2: 0.0 },
                &FourBarInput { theta2: 250.0 },
                &FourBarInput { theta2: 0.0 },
            )
            .unwrap();
        // The outputs listed, at every level (a missing one would not compile).
        let _ = (
            s.position.B,
            s.position.P,
            s.position.link3,
            s.position.link4,
        );
        let _ = (
            s.velocity.B,
            s.velocity.P,
            s.velocity.link3,
            s.velocity.link4,
        );
        let _ = (s.acceleration.B, s.acceleration.P, s.acceleration.link3);
        // Same four-bar as the README's: seed 002's theta3 at theta2 = 0 (seeds.md).
        assert!((s.position.link3.to_degrees() - 44.0486).abs() <= 5e-5);
        // The velocity's `condition` is in (16 eps, 1].
        assert!(s.velocity.condition > 16.0 * f64::EPSILON && s.velocity.condition <= 1.0);
    }
}

/// docs/dsl.md, the drawn four-bar (the sample verbatim).
mod dsl_drawn {
    use mechanism::mechanism;

    mechanism! {
        pub FourBar {
            joints { O2 = (0.0, 0.0), O4 = (4.0, 0.0), A = (0.5, 0.9), B = (3.2, 2.1), P = (2.0, 2.9) }
            links {
                ground = [O2, O4],          // the fixed link
                crank = [O2, A],
                coupler = [A, B, P],        // a ternary link: P is a point of it
                rocker = [O4, B],
            }
            input theta = angle(crank);     // the crank's angle from +x (about 61 deg as drawn)
        }
    }

    #[test]
    fn the_drawn_four_bar_is_where_it_is_drawn() {
        // At the drawn crank angle every joint is where the sample draws it;
        // a quarter turn later B is still at its drawn distances from A and
        // O4 (the lengths are read from the drawing).
        let m = FourBar::<f64>::default();
        let theta = 0.9f64.atan2(0.5);
        let p = m.position(&FourBarInput { theta }).unwrap();
        assert!(
            (p.B - mechanism::Point2::new(3.2, 2.1)).norm() < 1e-14,
            "{}",
            p.B
        );
        assert!(
            (p.P - mechanism::Point2::new(2.0, 2.9)).norm() < 1e-14,
            "{}",
            p.P
        );
        let q = m.position(&FourBarInput { theta: theta + 1.5 }).unwrap();
        let ab = (3.2f64 - 0.5).hypot(2.1 - 0.9);
        assert!(((q.B - q.A).norm() - ab).abs() < 1e-14);
        assert!(((q.B - q.O4).norm() - 0.8f64.hypot(2.1)).abs() < 1e-14);
    }
}

/// docs/dsl.md, `Display` of a solution (the sample verbatim).
mod dsl_display {
    use mechanism::mechanism;

    mechanism! {
        pub Crank {
            outputs { A, link2 }
            let O = ground(0.0, 0.0);
            let A = crank(O, 1.0, th) as link2;
            mass link2 { m = 2.0, at = A };
            gravity (0.0, -10.0);
        }
    }

    #[rustfmt::skip] // verbatim from docs/dsl.md
    #[test]
    fn display_sample() {
        let i = |th| CrankInput { th };
        let s = Crank::<f64>::default().solve(&i(60f64.to_radians()), &i(1.0), &i(0.0)).unwrap();
        assert_eq!(format!("{s:.3}"), "\
position: A = (0.500, 0.866) L, link2 = 1.047 rad
velocity: A = (-0.866, 0.500) L/s, link2 = 1.000 rad/s, condition = 1.000
acceleration: A = (-0.500, -0.866) L/s^2, link2 = 0.000 rad/s^2
forces: r_ground_link2 = (-1.000, 18.268) F, drive_th = 10.000 F L, condition = 1.000, power_residual = 0.000");
    }
}

/// docs/assembly-modes.md, the mode at run time (the sample verbatim).
mod assembly_modes_runtime {
    use mechanism::mechanism;

    mechanism! {
        pub FourBar {
            params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8, circuit = left }
            let O2 = ground(0.0, 0.0);
            let O4 = ground(ground, 0.0);
            let A = crank(O2, crank, theta2) as link2;
            let B = rrr(A, coupler, O4, rocker, circuit) as (link3, link4);
        }
    }

    #[rustfmt::skip] // verbatim from docs/assembly-modes.md
    #[test]
    fn runtime_mode_sample() -> Result<(), mechanism::Error> {
        let mut fb = FourBar::<f64>::default();          // fb.circuit == Mode::Plus (`left`)
        let left = fb.position(&FourBarInput { theta2: 0.5 })?;
        fb.circuit = mechanism::Mode::Minus;             // the other circuit, same dimensions
        let right = fb.position(&FourBarInput { theta2: 0.5 })?;
        assert_eq!(FourBar::<f64>::default().circuit, mechanism::Mode::Plus);
        // This crank-rocker's two circuits lie on either side of the ground line.
        assert!(left.B.y > 0.0 && right.B.y < 0.0);
        Ok(())
    }
}

/// docs/dsl.md, the force analysis sample.
mod dsl_press {
    use mechanism::mechanism;

    mechanism! {
        pub Press {
            params { crank = 0.1, rod = 0.4 }
            loads { press = 0.0 }
            let O = ground(0.0, 0.0);
            let line = guide((0.0, 0.0), 0 deg);
            let A = crank(O, crank, theta) as link2;
            let B = rrp(A, rod, line, plus) as (link3, ram) slide x;
            let G3 = point(link3, from A, 0.2, 0 deg);
            mass link3 { m = 2.0, at = G3, j = 0.03 };
            mass ram { m = 5.0, at = B };
            gravity (0.0, -9.81);
            force at B on ram along line = -press;
        }
    }
    // let f = press.forces(&pos, &vel, &acc, &PressLoads { press: 1000.0 })?;
    // f.drive_theta (N m), f.r_ground_ram.normal (N), f.r_link2_link3 (N), f.power_residual

    #[test]
    fn press_static_torque_by_virtual_work() {
        let press = Press::<f64>::default();
        let (theta, loads) = (1.0, PressLoads { press: 1000.0 });
        // At rest (rate 0, acceleration 0) there are no inertia loads: the
        // driving torque balances the press force on the ram and link3's
        // weight. Virtual work with the velocities at a unit crank rate:
        // T * 1 + F . v_B + m3 g . v_G3 = 0 (the ram's weight does no work on
        // a horizontal guide).
        let pos = press.position(&PressInput { theta }).unwrap();
        let unit = press.velocity(&pos, &PressInput { theta: 1.0 }).unwrap();
        let t_expected = -(-1000.0 * unit.B.x + 2.0 * -9.81 * unit.G3.y);
        let vel = press.velocity(&pos, &PressInput { theta: 0.0 }).unwrap();
        let acc = press
            .acceleration(&pos, &vel, &PressInput { theta: 0.0 })
            .unwrap();
        let f = press.forces(&pos, &vel, &acc, &loads).unwrap();
        // The fields the sample names: N m, N, N.
        let _ = (f.r_ground_ram.normal, f.r_link2_link3);
        // 1e-12 relative: the torque (about 100 N m) is a sum of a few products
        // of loads up to 1000 N and lengths up to 0.5 m, each with a few
        // roundings; 1e-12 leaves a factor 20 over 256 eps.
        assert!(
            (f.drive_theta - t_expected).abs() <= 1e-12 * t_expected.abs(),
            "{} vs {}",
            f.drive_theta,
            t_expected
        );
        assert!(f.power_residual >= 0.0 && f.power_residual < 1e-13);
    }
}

/// docs/dsl.md, the cylinder with mass (and two masses on the boom).
mod dsl_excavator {
    use mechanism::mechanism;

    mechanism! {
        /// Boom (m, kg, N), lifted by a cylinder from the ground point B.
        pub Excavator {
            let A = ground(0.0, 0.0);
            let B = ground(0.8, -0.9);
            let C = actuator(A, 2.2, B, len, left) as (boom, barrel, rod);
            let Gb = point(boom, from A, 2.5, 8 deg);
            let Tip = point(boom, from A, 5.0, 0 deg);
            let G1 = point(barrel, from B, 0.6, 0 deg);   // 0.6 from B towards C
            let G2 = point(rod, from C, 0.5, 180 deg);    // 0.5 from C towards B
            mass boom { m = 1800.0, at = Gb, j = 4500.0 };
            mass boom { m = 600.0, at = Tip };            // the payload: a second part
            mass barrel { m = 220.0, at = G1, j = 30.0 };
            mass rod { m = 140.0, at = G2, j = 18.0 };
            gravity (0.0, -9.81);
            range len = (1.9, 3.0);
        }
    }
    // f.r_ground_boom, f.r_boom_rod, f.r_ground_barrel (N), f.r_barrel_rod.normal (N),
    // f.r_barrel_rod.moment (N m), f.drive_len (N, positive pushing)

    // Proves the sample's axial force at rest is the virtual-work one (the
    // weights' power at a unit rate of `len`, every part and the cylinder's
    // included), that it pushes (holds the boom up), and that the ground's
    // forces at A and B carry the whole weight.
    #[test]
    fn excavator_static_axial_force_by_virtual_work() {
        let m = Excavator::<f64>::default();
        let pos = m.position(&ExcavatorInput { len: 2.4 }).unwrap();
        let unit = m.velocity(&pos, &ExcavatorInput { len: 1.0 }).unwrap();
        let g = -9.81;
        let weights_power =
            g * (1800.0 * unit.Gb.y + 600.0 * unit.Tip.y + 220.0 * unit.G1.y + 140.0 * unit.G2.y);
        let vel = m.velocity(&pos, &ExcavatorInput { len: 0.0 }).unwrap();
        let acc = m
            .acceleration(&pos, &vel, &ExcavatorInput { len: 0.0 })
            .unwrap();
        let f = m.forces(&pos, &vel, &acc).unwrap();
        // 1e-13 relative: a sum of four products against a few solves of
        // 3 x 3 systems, each a few eps times the lever ratios (under 10).
        assert!((f.drive_len + weights_power).abs() <= 1e-13 * weights_power.abs());
        assert!(f.drive_len > 0.0);
        let ground = f.r_ground_boom + f.r_ground_barrel;
        assert!((ground.y + g * 2760.0).abs() <= 1e-13 * 2760.0 * 9.81 && ground.x.abs() <= 1e-9);
        let _ = (f.r_boom_rod, f.r_barrel_rod.normal, f.r_barrel_rod.moment);
    }
}

/// docs/checks.md: a rocking crank with a declared range.
mod checks_rocker {
    use mechanism::mechanism;

    mechanism! {
        pub Rocker {
            let O2 = ground(0.0, 0.0);
            let O4 = ground(130.0, 0.0);
            let A = crank(O2, 40.0, theta2) as link2;
            let B = rrr(A, 90.0, O4, 70.0, left) as (link3, link4);
            range theta2 = (-133 deg, 133 deg);     // the crank rocks
        }
    }

    #[test]
    fn rocker_assembles_over_its_range_and_not_past_the_limit() {
        // The limit the messages of checks.md quote (133.054389 deg): |A - O4|
        // = 90 + 70 by the law of cosines.
        let lim = ((40.0f64 * 40.0 + 130.0 * 130.0 - 160.0 * 160.0) / (2.0 * 40.0 * 130.0))
            .acos()
            .to_degrees();
        assert!((lim - 133.054389).abs() < 5e-7, "limit {lim}");
        let m = Rocker::<f64>::default();
        assert!(m.check().assembles());
        // 1e-6 deg on either side of the limit: far outside the rounding band
        // (4 eps of the lengths) and the bisection's 1e-10 of the range.
        assert!(m
            .position(&RockerInput {
                theta2: super::rad(lim - 1e-6)
            })
            .is_ok());
        let e = m
            .position(&RockerInput {
                theta2: super::rad(lim + 1e-6),
            })
            .unwrap_err();
        assert_eq!(e.group, "B");
        assert!(matches!(e.fault, mechanism::Fault::CannotAssemble { .. }));
    }
}

/// docs/checks.md: the slider's stroke the message suggests compiles (the
/// definition is `tests/ui/check_slider_range_beyond_reach.rs` with it).
mod checks_slider_stroke {
    use mechanism::mechanism;

    mechanism! {
        pub SliderRocker {
            let O = ground(0.0, 0.0);
            let line = guide((0.0, -0.05), 0 deg);
            let P = slider(line, x) as block;
            let B = rrr(P, 0.12, O, 0.06, left) as (rod, rocker);
            range x = (0.04, 0.17);                          // a slider's stroke
        }
    }

    #[test]
    fn suggested_stroke_assembles() {
        assert!(SliderRocker::<f64>::default().check().assembles());
    }
}

/// docs/checks.md: `allow singular` (the parallelogram of
/// `tests/ui/check_singular_parallelogram.rs`, which warns without it).
#[deny(deprecated)]
mod checks_allow_singular {
    use mechanism::mechanism;

    mechanism! {
        pub Parallelogram {
            let O2 = ground(0.0, 0.0);
            let O4 = ground(100.0, 0.0);
            let A = crank(O2, 40.0, theta2) as link2;
            let B = rrr(A, 100.0, O4, 40.0, left) as (link3, link4);
            allow singular B;      // this group passes its toggle on purpose
            allow singular;        // every group
        }
    }

    #[test]
    fn allowed_singular_positions_are_still_reported() {
        // checks.md: "`check()` still reports allowed singular positions":
        // the parallelogram folds at theta2 = 0 and 180 deg.
        let r = Parallelogram::<f64>::default().check();
        assert!(r.assembles());
        assert_eq!(r.groups[1].group, "B");
        assert_eq!(r.groups[1].singular, 2);
    }
}

/// docs/performance.md: the batch API and `par_solve`, on the example
/// four-bar (outputs A, B, link3, link4: the sample's 18 buffers). The doc's
/// sample elides the output fields (`SCHEMATIC`); this is it in full.
mod performance_batch {
    use mechanism::mechanism;

    mechanism! {
        pub FourBar {
            params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
            dof 1;
            let O2 = ground(0.0, 0.0);
            let O4 = ground(ground, 0.0);
            let A = crank(O2, crank, theta2) as link2;
            let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        }
    }

    #[test]
    fn owned_sample_matches_the_scalar_path() -> Result<(), mechanism::BatchError> {
        let m = FourBar::<f64>::default();
        let mut b = FourBar::<f64>::batch(3600); // FourBarColumns: every column and status zero
        b.in_theta2 = (0..3600).map(|k| k as f64 * 1e-3).collect();
        let failed = m.solve_columns(&mut b)?; // elements whose status is not 0

        // Seed 002's four-bar is a crank-rocker: every pose assembles. B.x
        // against the scalar path with the bound of the borrowed sample below.
        assert_eq!(failed, 0);
        assert!(b.status.iter().all(|&s| s == 0));
        for k in [0, 900, 1234, 3599] {
            let p = m
                .position(&FourBarInput {
                    theta2: b.in_theta2[k],
                })
                .unwrap();
            assert!((b.pos_B_x[k] - p.B.x).abs() < 64.0 * f64::EPSILON * 305.0 / 0.09);
        }
        Ok(())
    }

    #[test]
    fn batch_sample_in_full_matches_the_scalar_path() -> Result<(), mechanism::BatchError> {
        let m = FourBar::<f64>::default();
        let n = 3600;
        let theta: Vec<f64> = (0..n)
            .map(|k| k as f64 * core::f64::consts::TAU / n as f64)
            .collect();
        let (w, a) = (vec![250.0; n], vec![0.0; n]);
        let mut out = vec![vec![0.0; n]; 18]; // A, B (x, y), link3, link4 at 3 levels
        let mut status = vec![0u8; n];
        let mut o = out.iter_mut();
        let mut b = FourBarBatch {
            in_theta2: &theta,
            rate_theta2: &w,
            accel_theta2: &a,
            pos_B_x: o.next().unwrap(),
            pos_A_x: o.next().unwrap(),
            pos_A_y: o.next().unwrap(),
            pos_B_y: o.next().unwrap(),
            pos_link3: o.next().unwrap(),
            pos_link4: o.next().unwrap(),
            vel_A_x: o.next().unwrap(),
            vel_A_y: o.next().unwrap(),
            vel_B_x: o.next().unwrap(),
            vel_B_y: o.next().unwrap(),
            vel_link3: o.next().unwrap(),
            vel_link4: o.next().unwrap(),
            acc_A_x: o.next().unwrap(),
            acc_A_y: o.next().unwrap(),
            acc_B_x: o.next().unwrap(),
            acc_B_y: o.next().unwrap(),
            acc_link3: o.next().unwrap(),
            acc_link4: o.next().unwrap(),
            status: &mut status,
        };
        assert!(o.next().is_none(), "18 buffers, as the sample says");
        assert_eq!(b.len(), n);
        let failed = m.solve_batch(&mut b)?; // elements whose status is not 0

        // Seed 002's four-bar is a crank-rocker: every pose assembles.
        assert_eq!(failed, 0);
        assert!(status.iter().all(|&s| s == 0));
        // B.x (out[0]) against the scalar path at a few poses; the batch agrees
        // to a few ulp times the conditioning (performance.md: 64 eps of the
        // magnitude over condition^2, condition above 0.3 on this crank-rocker).
        for k in [0, 900, 1234, 3599] {
            let p = m.position(&FourBarInput { theta2: theta[k] }).unwrap();
            assert!((out[0][k] - p.B.x).abs() < 64.0 * f64::EPSILON * 305.0 / 0.09);
        }
        Ok(())
    }

    #[cfg(feature = "rayon")]
    #[test]
    fn par_solve_sample() -> Result<(), mechanism::BatchError> {
        let m = FourBar::<f64>::default();
        let n = 10_000;
        let theta: Vec<f64> = (0..n).map(|k| k as f64 * 1e-3).collect();
        let (w, a) = (vec![250.0; n], vec![0.0; n]);
        let mut out = vec![vec![0.0; n]; 18];
        let mut status = vec![0u8; n];
        let mut o = out.iter_mut();
        let mut nx = || o.next().unwrap().as_mut_slice();
        let b = FourBarBatch {
            in_theta2: &theta,
            rate_theta2: &w,
            accel_theta2: &a,
            pos_A_x: nx(),
            pos_A_y: nx(),
            pos_B_x: nx(),
            pos_B_y: nx(),
            pos_link3: nx(),
            pos_link4: nx(),
            vel_A_x: nx(),
            vel_A_y: nx(),
            vel_B_x: nx(),
            vel_B_y: nx(),
            vel_link3: nx(),
            vel_link4: nx(),
            acc_A_x: nx(),
            acc_A_y: nx(),
            acc_B_x: nx(),
            acc_B_y: nx(),
            acc_link3: nx(),
            acc_link4: nx(),
            status: &mut status,
        };
        let failed = mechanism::par_solve(b, 4096, &|mut chunk| m.solve_batch(&mut chunk))?;
        assert_eq!(failed, 0);
        // The owned form, as the doc writes it.
        let mut b = FourBar::<f64>::batch(n);
        b.in_theta2 = theta;
        let failed = mechanism::par_solve(b.as_batch(), 0, &|mut chunk| m.solve_batch(&mut chunk))?;
        assert_eq!(failed, 0);
        assert_eq!(b.pos_B_x, out[2]);
        Ok(())
    }
}

/// docs/performance.md, "Bound by memory": the block reduction (the sample
/// verbatim) gives the range of `B.x` that the scalar path gives over the
/// same inputs, without storing a row per element.
#[cfg(feature = "rayon")]
mod performance_blocks {
    use mechanism::mechanism;

    mechanism! {
        pub FourBar {
            params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
            analysis position;
            outputs { B }
            let O2 = ground(0.0, 0.0);
            let O4 = ground(ground, 0.0);
            let A = crank(O2, crank, theta2) as link2;
            let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        }
    }

    #[test]
    fn block_reduction_sample_gives_the_scalar_range() -> Result<(), mechanism::BatchError> {
        use rayon::prelude::*;

        const BLOCK: usize = 4096;
        let m = FourBar::<f64>::default();
        let theta: Vec<f64> = (0..1_000_000).map(|k| k as f64 * 1e-5).collect(); // rad
        let (lo, hi, failed) = theta
            .par_chunks(BLOCK)
            .map_init(
                || (vec![0.0; BLOCK], vec![0.0; BLOCK], vec![0u8; BLOCK]), // one thread's columns
                |(bx, by, status), chunk| {
                    let k = chunk.len();
                    let mut b = FourBarBatch {
                        in_theta2: chunk,
                        pos_B_x: &mut bx[..k],
                        pos_B_y: &mut by[..k],
                        status: &mut status[..k],
                    };
                    let failed = m.solve_batch(&mut b)?;
                    // A failed element's outputs are 0: only the solved ones count.
                    let solved = bx[..k].iter().zip(&status[..k]).filter(|(_, &s)| s == 0);
                    let (lo, hi) =
                        solved.fold((f64::MAX, f64::MIN), |(l, h), (&x, _)| (l.min(x), h.max(x)));
                    Ok::<_, mechanism::BatchError>((lo, hi, failed))
                },
            )
            .try_reduce(
                || (f64::MAX, f64::MIN, 0),
                |a, b| Ok((a.0.min(b.0), a.1.max(b.1), a.2 + b.2)),
            )?;

        // The inputs cover 10 rad (more than a turn) of a crank-rocker: every
        // pose assembles, and the range is the scalar path's over the same
        // inputs, to the batch's agreement with it (64 eps of the magnitude
        // over condition^2, the bound of `performance_batch`).
        assert_eq!(failed, 0);
        let bx = |t: f64| m.position(&FourBarInput { theta2: t }).unwrap().B.x;
        let (slo, shi) = theta.iter().fold((f64::MAX, f64::MIN), |(l, h), &t| {
            (l.min(bx(t)), h.max(bx(t)))
        });
        let tol = 64.0 * f64::EPSILON * 305.0 / 0.09;
        assert!(
            (lo - slo).abs() < tol && (hi - shi).abs() < tol,
            "{lo} {hi} against {slo} {shi}"
        );
        // The coupler's far joint swings over tens of millimetres.
        assert!(hi - lo > 10.0, "{lo} {hi}");
        Ok(())
    }
}

/// docs/performance.md: the force analysis in a batch (the sample verbatim),
/// on the press of docs/dsl.md's force analysis sample.
mod performance_forces_batch {
    use mechanism::mechanism;
    use std::f64::consts::TAU;

    mechanism! {
        pub Press {
            params { crank = 0.1, rod = 0.4 }
            loads { press = 0.0 }
            let O = ground(0.0, 0.0);
            let line = guide((0.0, 0.0), 0 deg);
            let A = crank(O, crank, theta) as link2;
            let B = rrp(A, rod, line, plus) as (link3, ram) slide x;
            let G3 = point(link3, from A, 0.2, 0 deg);
            mass link3 { m = 2.0, at = G3, j = 0.03 };
            mass ram { m = 5.0, at = B };
            gravity (0.0, -9.81);
            force at B on ram along line = -press;
        }
    }

    /// A process force (N): 10 kN over the 30 deg before bottom dead centre
    /// (theta = pi), none elsewhere.
    fn process_force(theta: f64) -> f64 {
        if (TAU / 2.0 - 30f64.to_radians()..TAU / 2.0).contains(&theta) {
            10_000.0
        } else {
            0.0
        }
    }

    #[test]
    #[rustfmt::skip] // the sample verbatim from docs/performance.md
    fn torque_curve_sample_is_the_scalar_solve() -> Result<(), mechanism::BatchError> {
        let m = Press::<f64>::default();
        let mut b = Press::<f64>::batch(100_000); // load_* columns at the definition's values
        b.in_theta = (0..100_000).map(|k| k as f64 * TAU / 1e5).collect();
        b.rate_theta = vec![10.0; 100_000];
        b.load_press = b.in_theta.iter().map(|q| process_force(*q)).collect();
        let failed = m.solve_columns(&mut b)?; // kinematics and forces of every element
        // b.drive_theta[k]: the crank torque; b.forces_at(k): element k as the scalar PressForces

        // No offset and rod > crank: every angle assembles, and no force
        // system is singular away from the dead centres (0 and pi, which
        // the grid hits only at k = 0 and 50000, where the crank and rod are
        // aligned: the force system is still regular for a slider-crank).
        assert_eq!(failed, 0);
        for k in [1, 12_345, 45_000, 49_999, 77_777] {
            let i = |x: f64| PressInput { theta: x };
            let s = m
                .solve(&i(b.in_theta[k]), &i(10.0), &i(0.0), &PressLoads { press: b.load_press[k] })
                .expect("assembles");
            assert_eq!(b.drive_theta[k].to_bits(), s.forces.drive_theta.to_bits());
            assert_eq!(b.forces_at(k), Some(s.forces));
        }
        // The process force shows in the torque: it opposes the ram's motion.
        assert!(b.load_press[45_000] > 0.0 && b.drive_theta[45_000].abs() > 100.0);
        Ok(())
    }
}

/// The tests that run samples writing to relative paths change the process'
/// working directory: one at a time.
static CWD: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// docs/plots.md: both samples, with the data they assume made up here, run in
/// a temporary directory (the drawing sample writes to relative paths).
#[test]
fn plots_samples_write_their_files() {
    let _cwd = CWD.lock().unwrap_or_else(|e| e.into_inner());
    let dir = std::env::temp_dir().join(format!("doc_samples_plots_{}", std::process::id()));
    std::fs::create_dir_all(dir.join("target/plots/mine")).unwrap();
    std::env::set_current_dir(&dir).unwrap();
    figure_sample().unwrap();
    sketch_sample().unwrap();
    for f in [
        "target/plots/mine/kinematics.svg",
        "drawing.svg",
        "animation.svg",
    ] {
        let svg = std::fs::read_to_string(dir.join(f)).unwrap();
        assert!(svg.starts_with("<svg") || svg.starts_with("<?xml"), "{f}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[rustfmt::skip] // verbatim from docs/plots.md
fn figure_sample() -> Result<(), mechanism_plot::PlotError> {
    let theta2: Vec<f64> = (0..72).map(|k| 5.0 * k as f64).collect();
    let theta3: Vec<f64> = theta2.iter().map(|t| 30.0 + 10.0 * rad(*t).sin()).collect();
    let theta4: Vec<f64> = theta2.iter().map(|t| 90.0 + 20.0 * rad(*t).cos()).collect();
    let torque: Vec<f64> = theta2.iter().map(|t| 5.0 * rad(2.0 * t).sin()).collect();
    use mechanism_plot::{Figure, Plot};

    let fig = Figure::new("Four-bar of seed 002, crank at 250 rad/s")
        .panel(
            Plot::new("Angles")
                .x_axis("crank angle θ2", "deg")
                .y_axis("angle", "deg")
                .series("θ3 (coupler)", &theta2, &theta3)
                .series("θ4 (rocker)", &theta2, &theta4),
        )
        .panel(
            Plot::new("Driving torque")
                .x_axis("crank angle θ2", "deg")
                .y_axis("torque", "N m")
                .series("T12", &theta2, &torque),
        );
    fig.write("target/plots/mine/kinematics.svg")?;   // or fig.to_svg()? -> String
    Ok(())
}

struct Pose {
    deg: f64,
}

#[rustfmt::skip] // verbatim from docs/plots.md
fn sketch_sample() -> Result<(), mechanism_plot::PlotError> {
    let poses: Vec<Pose> = (0..36).map(|k| Pose { deg: 10.0 * k as f64 }).collect();
    let coupler_points: Vec<[f64; 2]> = poses
        .iter()
        .map(|p| [0.1 * rad(p.deg).cos() + 0.2, 0.1 * rad(p.deg).sin() + 0.05])
        .collect();
    let (o, a, b, p, far) = ([0.0, 0.0], [0.1, 0.0], [0.5, 0.02], [0.3, 0.05], [0.6, 0.1]);
    use mechanism_plot::{Frame, Sketch};

    let mut sk = Sketch::new("Offset slider-crank (m)", "m");      // title, length unit
    sk.ground_pivot("O", [0.0, 0.0])
      .ground_guide([-0.1, 0.02], [0.6, 0.02])                     // hatched on the right of a -> b
      .path("P", &coupler_points);                                  // dashed, under the links
    for pose in &poses {
        sk.frame(
            Frame::new(&format!("θ = {:.0}°", pose.deg))            // caption, bottom right
                .link("link2", &[o, a])                             // 2 points: a bar
                .link("link3", &[a, b, p])                          // 3 or more: a plate
                .slider("slider", b, 0.0)                           // block along a guide at 0 rad
                .guide(a, far)                                      // a guide carried by a link
                .joint("A", a)                                      // revolute joint, labelled
                .point("P", p),                                     // tracer point
        );
    }
    sk.write_drawing(15, "drawing.svg")?;     // pose 15
    sk.write_animation(4.0, "animation.svg")?; // all poses, 4 s per cycle
    Ok(())
}

// ---------------------------------------------------------------------------
// The guards: the docs' samples are the ones above, and the names they use exist.

/// Blocks of the docs that cannot compile as written, each with the reason
/// (matched on the block's full text, so an edit to one shows up here).
const SCHEMATIC: &[(&str, &str, &str)] = &[
    (
        "docs/checks.md",
        "mechanism! {\n    #[self_test]\n    pub FourBar { ... }\n}",
        "`{ ... }` stands for any definition",
    ),
    (
        "docs/performance.md",
        "let m = FourBar::<f64>::default();\nlet n = 3600;\nlet theta: Vec<f64> = (0..n).map(|k| k as f64 * core::f64::consts::TAU / n as f64).collect();\nlet (w, a) = (vec![250.0; n], vec![0.0; n]);\nlet mut out = vec![vec![0.0; n]; 18];           // A, B (x, y), link3, link4 at 3 levels\nlet mut status = vec![0u8; n];\nlet mut o = out.iter_mut();\nlet mut b = FourBarBatch {\n    in_theta2: &theta, rate_theta2: &w, accel_theta2: &a,\n    pos_B_x: o.next().unwrap(), /* ... every pos_*, vel_*, acc_* output ... */\n    status: &mut status,\n};\nlet failed = m.solve_batch(&mut b)?;             // elements whose status is not 0",
        "the output fields are elided; `performance_batch` has them all",
    ),
    (
        "docs/performance.md",
        "let failed = mechanism::par_solve(b.as_batch(), 0, &|mut chunk| m.solve_batch(&mut chunk))?;",
        "needs the feature `rayon`; `performance_batch::par_solve_sample` runs it with the feature",
    ),
];

const DOCS: &[&str] = &[
    "README.md",
    "docs/dsl.md",
    "docs/checks.md",
    "docs/assembly-modes.md",
    "docs/seeds.md",
    "docs/stability.md",
    "docs/performance.md",
    "docs/embedded.md",
    "docs/plots.md",
];

fn root() -> &'static Path {
    mechanism_dev::workspace_root()
}

/// The fenced code blocks of a markdown text: (info string, body).
fn blocks(md: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut cur: Option<(String, usize, Vec<&str>)> = None;
    for line in md.lines() {
        let t = line.trim_start();
        match &mut cur {
            None => {
                if let Some(info) = t.strip_prefix("```") {
                    let indent = line.len() - t.len();
                    cur = Some((info.trim().to_string(), indent, Vec::new()));
                }
            }
            Some((info, indent, body)) => {
                if t.starts_with("```") {
                    out.push((info.clone(), body.join("\n")));
                    cur = None;
                } else {
                    let cut = line.len().min(*indent);
                    body.push(if line[..cut].trim().is_empty() {
                        &line[cut..]
                    } else {
                        line
                    });
                }
            }
        }
    }
    out
}

#[test]
fn every_rust_block_of_the_docs_is_in_this_file() {
    let this: Vec<&str> = include_str!("doc_samples.rs")
        .lines()
        .map(str::trim)
        .collect();
    let mut missing = Vec::new();
    let mut schematic_seen = 0;
    for doc in DOCS {
        let md = std::fs::read_to_string(root().join(doc)).unwrap();
        for (info, body) in blocks(&md) {
            if info != "rust" {
                continue;
            }
            if SCHEMATIC.iter().any(|(d, b, _)| d == doc && *b == body) {
                schematic_seen += 1;
                continue;
            }
            let lines: Vec<&str> = body.lines().map(str::trim).collect();
            for para in lines.split(|l| l.is_empty()).filter(|p| !p.is_empty()) {
                if !this.windows(para.len()).any(|w| w == para) {
                    missing.push(format!("{doc}:\n{}", para.join("\n")));
                }
            }
        }
    }
    assert!(
        missing.is_empty(),
        "samples not in tests/doc_samples.rs:\n{}",
        missing.join("\n---\n")
    );
    assert_eq!(
        schematic_seen,
        SCHEMATIC.len(),
        "a SCHEMATIC block is no longer in its doc"
    );
}

/// Every `cargo ... --test X`, `--example X`, `--bench X` and `-p X` in the
/// docs' text names a real target or package, and every backticked
/// repository path exists.
#[test]
fn named_targets_and_paths_exist() {
    let mut bad = Vec::new();
    let exists = |p: &str| root().join(p).exists();
    for doc in DOCS {
        let md = std::fs::read_to_string(root().join(doc)).unwrap();
        // Commands may wrap over lines in prose: look at whitespace-separated words.
        let words: Vec<&str> = md.split_whitespace().collect();
        for w in words.windows(2) {
            let name = w[1].trim_matches(|c: char| "`(),.;:".contains(c));
            // `<name>` is a placeholder.
            let ok = name.starts_with('<')
                || match w[0].trim_matches('`') {
                    "--test" => {
                        exists(&format!("tests/{name}.rs"))
                            || exists(&format!("tests/{name}/main.rs"))
                    }
                    // An example of the root package or of any member crate.
                    "--example" => ["", "mechanism-codegen/", "mechanism-synthesis/"]
                        .iter()
                        .any(|dir| {
                            exists(&format!("{dir}examples/{name}.rs"))
                                || exists(&format!("{dir}examples/{name}/main.rs"))
                        }),
                    "--bench" => exists(&format!("benches/{name}.rs")),
                    "-p" => exists(&format!("{name}/Cargo.toml")),
                    "--features" => ["rayon", "no-panic"].contains(&name),
                    _ => true,
                };
            if !ok {
                bad.push(format!("{doc}: {} {}", w[0], w[1]));
            }
        }
        // Backticked repository paths in the prose (fenced blocks left out):
        // `dir/...` with a known top-level directory.
        let mut prose = String::new();
        let mut fenced = false;
        for line in md.lines() {
            if line.trim_start().starts_with("```") {
                fenced = !fenced;
            } else if !fenced {
                prose.push_str(line);
                prose.push('\n');
            }
        }
        for (i, piece) in prose.split('`').enumerate() {
            if i % 2 == 0 || piece.contains(' ') || piece.contains('<') || piece.contains('*') {
                continue;
            }
            let p = piece.split("::").next().unwrap().trim_end_matches(':');
            let top = p.split('/').next().unwrap();
            let known = [
                "tests",
                "examples",
                "benches",
                "scripts",
                "docs",
                "src",
                "mechanism-core",
                "mechanism-codegen",
                "mechanism-macros",
                "mechanism-reference",
                "mechanism-plot",
                "mechanism-synthesis",
                "mechanism-cli",
                "mechanism-python",
            ];
            // The README's `src/main.rs` is the user's new crate's.
            let users = doc == &"README.md" && p == "src/main.rs";
            if p.contains('/') && known.contains(&top) && !exists(p) && !users {
                bad.push(format!("{doc}: `{piece}`"));
            }
        }
    }
    assert!(
        bad.is_empty(),
        "names in the docs that do not exist:\n{}",
        bad.join("\n")
    );
}

mechanism::mechanism! {
    /// The Jansen leg of `tests/surface/describe.rs`, for the docs/plots.md sample.
    pub JansenLeg {
        units { length = "cm" }
        let O = ground(0.0, 0.0);
        let Z = ground(-38.0, -7.8);
        let A = crank(O, 15.0, theta) as crank;
        let B = rrr(A, 50.0, Z, 41.5, right) as (j, b);
        let C = rrr(A, 61.9, Z, 39.3, left) as (k, c);
        let D = rrr(B, 55.8, Z, 40.1, right) as (e, d);
        let E = rrr(D, 39.4, C, 36.7, right) as (f, g);
        let F = rrr(E, 65.7, C, 49.0, right) as (h, i);
    }
}

/// docs/plots.md, "Any mechanism": the sample writes the animation and the
/// table of a mechanism it has no drawing code for.
#[test]
fn any_mechanism_sample_writes_its_files() {
    let _cwd = CWD.lock().unwrap_or_else(|e| e.into_inner());
    let dir = std::env::temp_dir().join(format!("doc_samples_any_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let here = std::env::current_dir().unwrap();
    std::env::set_current_dir(&dir).unwrap();
    let written = any_sample();
    std::env::set_current_dir(here).unwrap();
    written.unwrap();
    let svg = std::fs::read_to_string(dir.join("jansen.svg")).unwrap();
    assert!(svg.starts_with("<svg") || svg.starts_with("<?xml"));
    let csv = std::fs::read_to_string(dir.join("jansen.csv")).unwrap();
    assert_eq!(csv.lines().count(), 74, "a header and 73 poses");
    let foot = std::fs::read_to_string(dir.join("foot.svg")).unwrap();
    assert!(
        foot.contains("\"F.x\"") && foot.contains("\"F.y\""),
        "the foot's chart"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[rustfmt::skip] // verbatim from docs/plots.md
fn any_sample() -> Result<(), Box<dyn std::error::Error>> {
    let leg = JansenLeg::<f64>::default();
    let poses: Vec<(f64, Option<JansenLegPosition>)> = (0..=72)
        .map(|k| { let t = k as f64 * std::f64::consts::TAU / 72.0;
                   (t, leg.position(&JansenLegInput { theta: t }).ok()) })
        .collect();
    mechanism_plot::any::sketch::<JansenLeg, _>("Jansen leg", &poses, &["F"])?
        .write_animation(4.0, "jansen.svg")?;
    std::fs::write("jansen.csv", mechanism_plot::any::csv("theta", "rad", &poses))?;
    mechanism_plot::any::chart("Jansen leg", ("θ", "rad"), &poses, &["F"])?.write("foot.svg")?;
    Ok(())
}
