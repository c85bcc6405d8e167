//! The gear pair (`gear(..)`) against an independent double-double
//! reference written in its own formulation (`mechanism_reference::Dd`,
//! nothing shared with the core):
//!
//! - the geared five-bar: two cranks on the ground geared together, one
//!   motor. The reference places the second crank from the gear law
//!   `theta5 = phase - ratio theta`, solves the loop closure
//!   `|B - A| = l3`, `|B - C| = l4` by Newton in double-double, its rates
//!   from the differentiated closure, and the motor's torque by finite
//!   virtual work (central differences of the reference pose);
//! - the planetary arm: a planet gear carried by a crank, meshing with a
//!   fixed sun: the planet's angle `phase + (1 + ratio) theta`, and the
//!   motor's torque against a couple on the planet by virtual work.

use mechanism::mechanism;
use mechanism_reference::constraint::V2;
use mechanism_reference::Dd;

mechanism! {
    /// A geared five-bar (m, N): the crank `link2` about `O2` and the gear
    /// `link5` about `O5` mesh at ratio 2 (external: `link5` turns at
    /// `30 deg - 2 theta`), the RRR `link3`, `link4` closes the loop. A
    /// force at `B` on `link3` and a couple on `link4` load it; the one
    /// motor is the crank's.
    pub GearedFiveBar {
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O5 = ground(3.0, 0.0);
        let A = crank(O2, 1.0, theta) as link2;
        let C = gear(O5, 0.8, link2, 2.0, 30 deg, ground, 20 deg) as link5;
        let B = rrr(A, 3.2, C, 2.6, left) as (link3, link4);
        force at B on link3 = (3.0, -5.0);
        torque on link4 = 2.0;
    }
}

mechanism! {
    /// A planetary arm (m, N): the arm `arm` turns about the sun's center
    /// `O`; the planet, pivoted at the arm's tip `A`, meshes with the fixed
    /// sun at ratio 1.5 (sun over planet pitch radius), so it turns at
    /// `(1 + 1.5) theta` plus its phase. A couple on the planet loads it.
    pub PlanetaryArm {
        dof 1;
        let O = ground(0.0, 0.0);
        let A = crank(O, 1.0, theta) as arm;
        let P = gear(A, 0.3, ground, 1.5, 10 deg, arm) as planet;
        torque on planet = -0.7;
    }
}

mechanism! {
    /// The geared five-bar of `GearedFiveBar` as drawn at `theta = 20 deg`:
    /// `C` where the gear law puts it (`30 deg - 2 * 20 deg` from `O5`, at
    /// 0.8), `B` where the RRR closes on the left of `A -> C` (3.2 from `A`,
    /// 2.6 from `C`, to the last digit written). The gear's pivot `O5`,
    /// pitch-circle radius 0.8 and phase 30 deg are read from the drawing.
    pub DrawnGearedFiveBar {
        joints {
            O2 = (0.0, 0.0),
            O5 = (3.0, 0.0),
            A = (cos(0.3490658503988659), sin(0.3490658503988659)),
            C = (3.0 + 0.8 * cos(-0.17453292519943295), 0.8 * sin(-0.17453292519943295)),
            B = (3.3673413602541498, 2.4268514549089972),
        }
        links {
            ground = [O2, O5],
            link2 = [O2, A],
            link5 = [O5, C],
            link3 = [A, B],
            link4 = [C, B],
        }
        input theta = angle(link2);
        gear link5 to link2 ratio 2.0 pressure 20 deg;
        force at B on link3 = (3.0, -5.0);
        torque on link4 = 2.0;
    }
}

mechanism! {
    /// The planetary arm of `PlanetaryArm` as drawn at `theta = 30 deg`: the
    /// planet's point 0.3 from the arm's tip at `10 deg + 2.5 * 30 deg`.
    pub DrawnPlanetaryArm {
        joints {
            O = (0.0, 0.0),
            A = (cos(0.5235987755982988), sin(0.5235987755982988)),
            P = (
                cos(0.5235987755982988) + 0.3 * cos(1.4835298641951802),
                sin(0.5235987755982988) + 0.3 * sin(1.4835298641951802),
            ),
        }
        links { ground = [O], arm = [O, A], planet = [A, P] }
        input theta = angle(arm);
        gear planet to ground ratio 1.5 on arm;
        torque on planet = -0.7;
    }
}

mechanism! {
    /// A planet carried by the arm meshing with a driven sun (two motors on
    /// the ground at `O`): the planet turns at
    /// `10 deg - 1.5 sun + 2.5 theta`.
    pub DrivenSun {
        let O = ground(0.0, 0.0);
        let S = crank(O, 0.5, sun_q) as sun;
        let A = crank(O, 1.0, theta) as arm;
        let P = gear(A, 0.3, sun, 1.5, 10 deg, arm) as planet;
        torque on planet = -0.7;
    }
}

mechanism! {
    /// `DrivenSun` as drawn with the arm at 30 deg and the sun at 50 deg, so
    /// the planet at `10 deg - 1.5 x 50 deg + 2.5 x 30 deg = 10 deg`.
    pub DrawnDrivenSun {
        joints {
            O = (0.0, 0.0),
            S = (0.5 * cos(0.8726646259971648), 0.5 * sin(0.8726646259971648)),
            A = (cos(0.5235987755982988), sin(0.5235987755982988)),
            P = (
                cos(0.5235987755982988) + 0.3 * cos(0.17453292519943295),
                sin(0.5235987755982988) + 0.3 * sin(0.17453292519943295),
            ),
        }
        links { ground = [O], sun = [O, S], arm = [O, A], planet = [A, P] }
        input sun_q = angle(sun);
        input theta = angle(arm);
        gear planet to sun ratio 1.5 on arm;
        torque on planet = -0.7;
    }
}

fn d(x: f64) -> Dd {
    Dd::from_f64(x)
}

fn polar(at: V2, r: f64, angle: Dd) -> V2 {
    let (s, c) = angle.sin_cos();
    at.plus(V2 { x: c, y: s }.scale(d(r)))
}

/// The reference geared five-bar at `theta` (rad), from the guess `b`
/// (the code under test's `B`: it picks the branch only; the side is
/// checked): the points `A`, `C`, `B`.
fn five_bar(theta: Dd, b: (f64, f64)) -> (V2, V2, V2) {
    let a = polar(V2::new(0.0, 0.0), 1.0, theta);
    let phase = d(30f64.to_radians());
    let c = polar(V2::new(3.0, 0.0), 0.8, phase - d(2.0) * theta);
    let mut p = V2::new(b.0, b.1);
    for _ in 0..60 {
        let (ra, rc) = (p.minus(a), p.minus(c));
        let f1 = ra.dot(ra) - d(3.2 * 3.2);
        let f2 = rc.dot(rc) - d(2.6 * 2.6);
        // J = 2 [ra; rc]; solve J dp = -f by Cramer's rule.
        let det = (ra.x * rc.y - ra.y * rc.x) * d(2.0);
        let dx = -(f1 * rc.y - f2 * ra.y) / det;
        let dy = -(ra.x * f2 - rc.x * f1) / det;
        p = p.plus(V2 { x: dx, y: dy });
    }
    // `left`: B on the left of A -> C.
    assert!(c.minus(a).cross(p.minus(a)).to_f64() > 0.0, "wrong branch");
    (a, c, p)
}

/// The rates of the reference five-bar at `theta` with crank rate `w` and
/// acceleration `al`: `(vB, aB)` from `(B - A).(vB - vA) = 0`,
/// `(B - C).(vB - vC) = 0` and their derivatives.
fn five_bar_rates(theta: Dd, b: (f64, f64), w: f64, al: f64) -> (V2, V2) {
    let (a, c, p) = five_bar(theta, b);
    let (ua, uc) = (a.minus(V2::new(0.0, 0.0)), c.minus(V2::new(3.0, 0.0)));
    let (w5, al5) = (d(-2.0 * w), d(-2.0 * al));
    let va = ua.perp().scale(d(w));
    let vc = uc.perp().scale(w5);
    let aa = ua.perp().scale(d(al)).minus(ua.scale(d(w) * d(w)));
    let ac = uc.perp().scale(al5).minus(uc.scale(w5 * w5));
    let (ra, rc) = (p.minus(a), p.minus(c));
    let solve = |k1: Dd, k2: Dd| {
        let det = ra.x * rc.y - ra.y * rc.x;
        V2 {
            x: (k1 * rc.y - k2 * ra.y) / det,
            y: (ra.x * k2 - rc.x * k1) / det,
        }
    };
    let vb = solve(ra.dot(va), rc.dot(vc));
    let (da, dc) = (vb.minus(va), vb.minus(vc));
    let ab = solve(ra.dot(aa) - da.dot(da), rc.dot(ac) - dc.dot(dc));
    (vb, ab)
}

fn close(got: f64, want: Dd, tol: f64, what: &str) {
    let e = (got - want.to_f64()).abs();
    assert!(e <= tol, "{what}: {got} vs {want}: {e:e} > {tol:e}");
}

#[test]
fn the_geared_five_bar_matches_the_double_double_closure() {
    // Proves the gear's point follows `theta5 = phase - ratio theta` and the
    // whole geared five-bar closes where the reference's Newton solve in
    // double-double closes it: positions to 1e-13 (f64 rounding of numbers
    // of size 4 through a few dozen operations), velocities to 1e-12 and
    // accelerations to 1e-10 (rates of size 10 and 300 through the
    // same), over a turn of the crank.
    let m = GearedFiveBar::<f64>::default();
    let (w, al) = (3.0, -20.0);
    let mut checked = 0;
    for k in 0..36 {
        let q = f64::to_radians(10.0 * k as f64);
        let s = match m.solve(
            &GearedFiveBarInput { theta: q },
            &GearedFiveBarInput { theta: w },
            &GearedFiveBarInput { theta: al },
        ) {
            Ok(s) => s,
            // Where the loop cannot close the error names the RRR.
            Err(e) => {
                assert_eq!(e.group, "B", "{e}");
                continue;
            }
        };
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        let (ra, rc, rb) = five_bar(d(q), (p.B.x, p.B.y));
        for (got, want, what) in [(p.A, ra, "A"), (p.C, rc, "C"), (p.B, rb, "B")] {
            close(got.x, want.x, 1e-13, what);
            close(got.y, want.y, 1e-13, what);
        }
        let (vb, ab) = five_bar_rates(d(q), (p.B.x, p.B.y), w, al);
        close(v.B.x, vb.x, 1e-12, "vB");
        close(v.B.y, vb.y, 1e-12, "vB");
        close(a.B.x, ab.x, 1e-10, "aB");
        close(a.B.y, ab.y, 1e-10, "aB");
        close(v.link5, d(-2.0 * w), 1e-14, "omega5");
        close(a.link5, d(-2.0 * al), 1e-13, "alpha5");
        checked += 1;
    }
    assert!(checked >= 18, "only {checked} poses closed");
}

#[test]
fn the_geared_five_bar_motor_torque_is_the_virtual_work_of_its_loads() {
    // Proves the tooth force carries the gear's load to the crank: the
    // motor's torque equals minus the virtual work of the force at B and
    // the couple on link4 per unit crank rotation, taken by central
    // differences of the reference pose (h = 1e-5 rad in double-double:
    // truncation h^2/6 times a third derivative of size 100, below 1e-8;
    // the tolerance 1e-7 of torques of size 10). It also checks the tooth
    // force lies on the line of action, 20 deg from the common tangent.
    let m = GearedFiveBar::<f64>::default();
    let f = V2::new(3.0, -5.0);
    let mut checked = 0;
    for k in 0..36 {
        let q = f64::to_radians(10.0 * k as f64 + 5.0);
        let zero = GearedFiveBarInput { theta: 0.0 };
        let Ok(s) = m.solve(&GearedFiveBarInput { theta: q }, &zero, &zero) else {
            continue;
        };
        let (p, fs) = (&s.position, &s.forces);
        let b = (p.B.x, p.B.y);
        let h = 1e-5;
        let (_, c1, b1) = five_bar(d(q) + d(h), b);
        let (_, c0, b0) = five_bar(d(q) - d(h), b);
        let (u1, u0) = (b1.minus(c1), b0.minus(c0));
        let turn4 = Dd::atan2(u0.cross(u1), u0.dot(u1));
        let work = f.dot(b1.minus(b0)) + d(2.0) * turn4;
        let torque = -work / d(2.0 * h);
        close(fs.drive_theta, torque, 1e-7, "drive_theta");
        // The tooth force on link5 from link2's gear, on the line of action.
        let t = fs.r_link2_link5;
        let e = (p.O2 - p.O5).normalize();
        let (radial, tangential) = (t.dot(&e), e.perp(&t));
        let angle = (radial.abs() / tangential.abs()).atan();
        assert!((angle - 20f64.to_radians()).abs() <= 1e-12, "{angle}");
        checked += 1;
    }
    assert!(checked >= 18, "only {checked} poses closed");
}

#[test]
fn the_planet_turns_with_the_arm_and_its_couple_loads_the_motor() {
    // Proves the planetary arm: the planet's point at its radius from the
    // arm's tip at the angle `10 deg + 2.5 theta` (the sun fixed, ratio
    // 1.5), its angular rate 2.5 times the arm's (1e-14: one product), and
    // the motor's torque `-(1 + ratio)` times the planet's couple (the
    // virtual work of a couple on a link turning 2.5 times as fast; 1e-13,
    // a few roundings of numbers of size 1).
    let m = PlanetaryArm::<f64>::default();
    for k in 0..24 {
        let q = f64::to_radians(15.0 * k as f64);
        let s = m
            .solve(
                &PlanetaryArmInput { theta: q },
                &PlanetaryArmInput { theta: 4.0 },
                &PlanetaryArmInput { theta: 0.0 },
            )
            .unwrap();
        let (p, v, fs) = (&s.position, &s.velocity, &s.forces);
        let a = polar(V2::new(0.0, 0.0), 1.0, d(q));
        let planet = polar(a, 0.3, d(10f64.to_radians()) + d(2.5) * d(q));
        close(p.P.x, planet.x, 1e-14, "P");
        close(p.P.y, planet.y, 1e-14, "P");
        close(v.planet, d(10.0), 1e-14, "omega planet");
        close(fs.drive_theta, d(2.5 * 0.7), 1e-13, "drive_theta");
    }
}

/// The geared five-bar's body as text, for the run-time reader.
const FIVE_BAR_TEXT: &str = "pub GearedFiveBar {
    let O2 = ground(0.0, 0.0);
    let O5 = ground(3.0, 0.0);
    let A = crank(O2, 1.0, theta) as link2;
    let C = gear(O5, 0.8, link2, 2.0, 30 deg, ground, 20 deg) as link5;
    let B = rrr(A, 3.2, C, 2.6, left) as (link3, link4);
}";

#[test]
fn the_run_time_reader_and_the_batch_agree_with_the_generated_gear() {
    // Proves the gear's run-time path (`mechanism_codegen::runtime`: its
    // `RunKind`) and the batch (`solve_columns`, the gear's lane step) give
    // the generated scalar code's numbers: the same formulas, so to 1e-12
    // (a few roundings of numbers of size 10; the batch's own sin and cos
    // are within 1.5 ulp of the scalar's).
    use mechanism_codegen::runtime::{Analysis, Mechanism};
    let rt = Mechanism::new(FIVE_BAR_TEXT).unwrap_or_else(|e| panic!("{e}"));
    let m = GearedFiveBar::<f64>::default();
    let cols = |a| rt.columns(a);
    let (pc, vc) = (cols(Analysis::Position), cols(Analysis::Velocity));
    let at = |cols: &[mechanism_codegen::runtime::Column], values: &[f64], name: &str| {
        let k = cols.iter().position(|c| c.name == name).expect(name);
        values[k]
    };
    let mut b = GearedFiveBar::<f64>::batch(36);
    b.in_theta = (0..36).map(|k| f64::to_radians(10.0 * k as f64)).collect();
    b.rate_theta = vec![3.0; 36];
    let _ = m.solve_columns(&mut b);
    let mut checked = 0;
    for k in 0..36 {
        let q = b.in_theta[k];
        let w = GearedFiveBarInput { theta: 3.0 };
        let Ok(p) = m.position(&GearedFiveBarInput { theta: q }) else {
            assert!(rt.position(&[q]).is_err());
            assert_ne!(b.status[k], 0);
            continue;
        };
        let v = m.velocity(&p, &w).unwrap();
        let rp = rt.position(&[q]).unwrap();
        let rv = rt.velocity(&rp, &[3.0]).unwrap();
        for (got, name) in [
            (p.C.x, "C.x"),
            (p.C.y, "C.y"),
            (p.B.x, "B.x"),
            (p.link5, "link5"),
        ] {
            let want = at(&pc, &rp.values, name);
            assert!((got - want).abs() <= 1e-12, "{name}: {got} vs {want}");
        }
        for (got, name) in [(v.C.x, "C.x"), (v.C.y, "C.y"), (v.link5, "link5")] {
            let want = at(&vc, &rv.values, name);
            assert!((got - want).abs() <= 1e-12, "v {name}: {got} vs {want}");
        }
        assert_eq!(b.status[k], 0);
        assert!((b.pos_C_x[k] - p.C.x).abs() <= 1e-12);
        assert!((b.vel_C_y[k] - v.C.y).abs() <= 1e-12);
        checked += 1;
    }
    assert!(checked >= 18, "only {checked} poses closed");
}

/// `got` within `tol` of `want` at element `k` of a batch column `what`.
fn near(got: f64, want: f64, tol: f64, what: &str, k: usize) {
    assert!((got - want).abs() <= tol, "{what}[{k}]: {got} vs {want}");
}

#[test]
fn the_batch_turns_a_gear_as_the_scalar_code_does() {
    // Proves the gear's lane step (its angle, rate and acceleration linear
    // in the cranks' inputs, then the crank's lane step) gives the scalar
    // code's positions, velocities, accelerations and link angles, for a
    // gear on the ground meshing with a crank (the geared five-bar, which
    // assembles at every one of these inputs) and for a
    // planet carried by a crank meshing with a fixed sun (its pivot moves
    // and its angle reads the carrier's input times `1 + ratio`). Tolerance
    // 1e-13 relative: the batch's sin and cos are within 1.5 ulp of the
    // scalar's and the RRR amplifies that by its conditioning (under 10
    // here), so 1e-14 at most; on this machine the two agree bit for bit.
    let n = 72;
    let theta: Vec<f64> = (0..n)
        .map(|k| 0.1 + f64::to_radians(5.0 * k as f64))
        .collect();
    let (w, al) = (3.0, -20.0);
    let five = GearedFiveBar::<f64>::default();
    let mut b = GearedFiveBar::<f64>::batch(n);
    b.in_theta.clone_from(&theta);
    b.rate_theta = vec![w; n];
    b.accel_theta = vec![al; n];
    let failed = five.solve_columns(&mut b).expect("one length");
    let mut solved = 0;
    for (k, &q) in theta.iter().enumerate() {
        let i = |x| GearedFiveBarInput { theta: x };
        let Ok(s) = five.solve(&i(q), &i(w), &i(al)) else {
            assert_ne!(b.status[k], 0, "element {k} fails in the scalar code");
            continue;
        };
        assert_eq!(b.status[k], 0, "element {k}");
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        for (got, want, what) in [
            (b.pos_C_x[k], p.C.x, "pos_C_x"),
            (b.pos_C_y[k], p.C.y, "pos_C_y"),
            (b.pos_link5[k], p.link5, "pos_link5"),
            (b.pos_B_x[k], p.B.x, "pos_B_x"),
            (b.vel_C_x[k], v.C.x, "vel_C_x"),
            (b.vel_link5[k], v.link5, "vel_link5"),
            (b.vel_B_y[k], v.B.y, "vel_B_y"),
            (b.acc_C_y[k], a.C.y, "acc_C_y"),
            (b.acc_link5[k], a.link5, "acc_link5"),
            (b.acc_B_x[k], a.B.x, "acc_B_x"),
        ] {
            near(got, want, 1e-13 * (1.0 + want.abs()), what, k);
        }
        solved += 1;
    }
    assert_eq!((solved, failed), (n, 0));

    let arm = PlanetaryArm::<f64>::default();
    let mut b = PlanetaryArm::<f64>::batch(n);
    b.in_theta.clone_from(&theta);
    b.rate_theta = vec![w; n];
    b.accel_theta = vec![al; n];
    assert_eq!(arm.solve_columns(&mut b), Ok(0));
    for (k, &q) in theta.iter().enumerate() {
        let i = |x| PlanetaryArmInput { theta: x };
        let s = arm
            .solve(&i(q), &i(w), &i(al))
            .expect("the arm always turns");
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        for (got, want, what) in [
            (b.pos_P_x[k], p.P.x, "pos_P_x"),
            (b.pos_planet[k], p.planet, "pos_planet"),
            (b.vel_P_y[k], v.P.y, "vel_P_y"),
            (b.vel_planet[k], v.planet, "vel_planet"),
            (b.acc_P_x[k], a.P.x, "acc_P_x"),
            (b.acc_planet[k], a.planet, "acc_planet"),
        ] {
            near(got, want, 1e-13 * (1.0 + want.abs()), what, k);
        }
    }
}

mechanism! {
    /// A planetary arm with its ratio a run-time parameter, a planet with
    /// mass under gravity, and the generated self-test (loop closure,
    /// finite differences, power balance) over a turn of the arm.
    #[self_test]
    pub PlanetSelfTest {
        params { ratio = 1.5 }
        let O = ground(0.0, 0.0);
        let A = crank(O, 1.0, theta) as arm;
        let P = gear(A, 0.3, ground, ratio, 10 deg, arm) as planet;
        mass planet { m = 0.4, at = P, j = 0.002 };
        gravity (0.0, -9.81);
    }
}

#[test]
fn a_run_time_ratio_changes_the_planet_s_rate() {
    // Proves the ratio read at run time: the planet turns at `1 + ratio`
    // times the arm (exact: one product and one sum of small numbers).
    let m = PlanetSelfTest::<f64> { ratio: 3.0 };
    let p = m.position(&PlanetSelfTestInput { theta: 0.4 }).unwrap();
    let v = m.velocity(&p, &PlanetSelfTestInput { theta: 2.0 }).unwrap();
    assert!((v.planet - 8.0).abs() <= 1e-14, "{}", v.planet);
}

#[test]
fn the_drawn_geared_five_bar_is_the_grouped_one() {
    // Proves `gear link5 to link2 ratio 2.0` lowers to the grouped
    // `gear(O5, 0.8, link2, 2.0, 30 deg, ground, 20 deg)`: positions,
    // rates, the motor's torque and the tooth force equal the grouped
    // form's over a turn. Not bit for bit: the drawing's lengths and phase
    // are computed from its coordinates (|O5 C| = 0.8 - 2.2e-16, the phase
    // 30 deg + 1.1e-16, |A B| = 3.2 + 4.4e-16, |C B| = 2.6 + 4.4e-16, each
    // an ulp or two of the decimal written), which the solve carries with
    // the loop's conditioning: positions (size 4) to 4e-15, velocities
    // (size 10) to 2e-14, accelerations (size 300) to 5e-13, the torque and
    // the tooth force (size 10) to 3e-14, about four times the largest
    // differences over the turn (8.9e-16, 3.6e-15, 4.3e-14, 5.3e-15,
    // 2.7e-15); the gear's rate is linear in the input's, so exact. Drawn
    // at 20 deg, so the phase's term `ratio * (angle of link2 as drawn)`
    // counts.
    let (g, m) = (
        GearedFiveBar::<f64>::default(),
        DrawnGearedFiveBar::<f64>::default(),
    );
    let (w, al) = (3.0, -20.0);
    let mut checked = 0;
    for k in 0..36 {
        let q = f64::to_radians(10.0 * k as f64 + 5.0);
        let want = g.solve(
            &GearedFiveBarInput { theta: q },
            &GearedFiveBarInput { theta: w },
            &GearedFiveBarInput { theta: al },
        );
        let got = m.solve(
            &DrawnGearedFiveBarInput { theta: q },
            &DrawnGearedFiveBarInput { theta: w },
            &DrawnGearedFiveBarInput { theta: al },
        );
        let (Ok(want), Ok(got)) = (want, got) else {
            continue;
        };
        let near = |a: f64, b: f64, tol: f64, what: &str| {
            assert!((a - b).abs() <= tol, "{what} at {q}: {a} vs {b}");
        };
        let (p, wp) = (&got.position, &want.position);
        for (a, b, what) in [(p.A, wp.A, "A"), (p.B, wp.B, "B"), (p.C, wp.C, "C")] {
            near(a.x, b.x, 4e-15, what);
            near(a.y, b.y, 4e-15, what);
        }
        near(p.link5, wp.link5, 4e-15, "link5");
        let (v, wv) = (&got.velocity, &want.velocity);
        near(v.B.x, wv.B.x, 2e-14, "vB");
        near(v.B.y, wv.B.y, 2e-14, "vB");
        near(v.link5, wv.link5, 0.0, "omega5");
        let (a, wa) = (&got.acceleration, &want.acceleration);
        near(a.B.x, wa.B.x, 5e-13, "aB");
        near(a.B.y, wa.B.y, 5e-13, "aB");
        let (f, wf) = (&got.forces, &want.forces);
        near(f.drive_theta, wf.drive_theta, 3e-14, "drive_theta");
        near(f.r_link2_link5.x, wf.r_link2_link5.x, 3e-14, "tooth force");
        near(f.r_link2_link5.y, wf.r_link2_link5.y, 3e-14, "tooth force");
        checked += 1;
    }
    assert!(checked >= 18, "only {checked} poses closed");
}

#[test]
fn the_drawn_planetary_arm_is_the_grouped_one() {
    // Proves `gear planet to ground ratio 1.5 on arm` lowers to the grouped
    // `gear(A, 0.3, ground, 1.5, 10 deg, arm)`: the planet's point, its
    // rate and the motor's torque equal the grouped form's over a turn: the
    // point and angle to 1e-15 (the drawn radius and phase are computed
    // from the drawn coordinates, within an ulp of 0.3 and 10 deg; the
    // largest difference is 8.9e-16, two ulps of an angle near pi), the
    // rate and the torque, which do not read them, exactly. Drawn at 30
    // deg, so the phase's term `-ratio * (angle of arm as drawn)` counts.
    let (g, m) = (
        PlanetaryArm::<f64>::default(),
        DrawnPlanetaryArm::<f64>::default(),
    );
    for k in 0..24 {
        let q = f64::to_radians(15.0 * k as f64);
        let want = g
            .solve(
                &PlanetaryArmInput { theta: q },
                &PlanetaryArmInput { theta: 4.0 },
                &PlanetaryArmInput { theta: 0.0 },
            )
            .unwrap();
        let got = m
            .solve(
                &DrawnPlanetaryArmInput { theta: q },
                &DrawnPlanetaryArmInput { theta: 4.0 },
                &DrawnPlanetaryArmInput { theta: 0.0 },
            )
            .unwrap();
        let near = |a: f64, b: f64, what: &str| {
            assert!((a - b).abs() <= 1e-15, "{what} at {q}: {a} vs {b}");
        };
        near(got.position.P.x, want.position.P.x, "P");
        near(got.position.P.y, want.position.P.y, "P");
        near(got.position.planet, want.position.planet, "planet");
        assert_eq!(got.velocity.planet, want.velocity.planet, "omega planet");
        assert_eq!(got.forces.drive_theta, want.forces.drive_theta);
    }
}

#[test]
fn the_drawn_planet_on_a_driven_sun_is_the_grouped_one() {
    // Proves the phase of a gear whose mesh and carrier both turn,
    // `(planet - arm) + ratio (sun - arm)` as drawn: the drawn planet's
    // point and angle equal the grouped form's over a grid of both inputs,
    // to 2e-15 (the drawn radius and phase within an ulp or two of 0.3 and
    // 10 deg, carried into an angle of size up to pi and a point of size 1),
    // and its rates, which do not read them, exactly.
    let (g, m) = (
        DrivenSun::<f64>::default(),
        DrawnDrivenSun::<f64>::default(),
    );
    for k in 0..12 {
        for n in 0..12 {
            let (q, s) = (
                f64::to_radians(30.0 * k as f64),
                f64::to_radians(-30.0 * n as f64),
            );
            let (want_in, got_in) = (
                DrivenSunInput { sun_q: s, theta: q },
                DrawnDrivenSunInput { sun_q: s, theta: q },
            );
            let (want_w, got_w) = (
                DrivenSunInput {
                    sun_q: -1.0,
                    theta: 4.0,
                },
                DrawnDrivenSunInput {
                    sun_q: -1.0,
                    theta: 4.0,
                },
            );
            let want = g.position(&want_in).unwrap();
            let got = m.position(&got_in).unwrap();
            let near = |a: f64, b: f64, what: &str| {
                assert!((a - b).abs() <= 2e-15, "{what} at {q}, {s}: {a} vs {b}");
            };
            near(got.P.x, want.P.x, "P");
            near(got.P.y, want.P.y, "P");
            near(got.planet, want.planet, "planet");
            let (wv, gv) = (
                g.velocity(&want, &want_w).unwrap(),
                m.velocity(&got, &got_w).unwrap(),
            );
            assert_eq!(gv.planet, wv.planet, "omega planet");
        }
    }
}
