//! A group's assembly mode as a run-time parameter: `params { circuit =
//! left }` and `rrr(.., circuit)`.

use mechanism::{mechanism, Mode};

mechanism! {
    /// Seed 002's crank-rocker (mm), the circuit chosen at run time.
    pub Switched {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8, circuit = left }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, circuit) as (link3, link4);
        let P = point(link3, from A, 120.0, 30 deg);
    }
}

mechanism! {
    /// The same, closed left at compile time.
    pub Left {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        let P = point(link3, from A, 120.0, 30 deg);
    }
}

mechanism! {
    /// The same, closed right at compile time.
    pub Right {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, right) as (link3, link4);
        let P = point(link3, from A, 120.0, 30 deg);
    }
}

/// The crank angles of the sweep: 3600 over a turn and a bit beyond.
fn angles() -> impl Iterator<Item = f64> {
    (0..3600).map(|k| -3.2 + k as f64 * (6.4 / 3599.0))
}

// Proves the parameter's default is the literal written, and that each value
// of the parameter gives, at every crank angle of a full turn, the same bits
// (every output of position, velocity and acceleration: `Debug` prints each
// number's shortest round-trip form, so equal text is equal bits) as the
// definition with that mode fixed; and that the two circuits differ.
#[test]
fn each_circuit_agrees_to_the_bit_with_its_fixed_definition() {
    let mut switched = Switched::<f64>::default();
    assert_eq!(switched.circuit, Mode::Plus);
    let (left, right) = (Left::<f64>::default(), Right::<f64>::default());
    for theta2 in angles() {
        let (rates, accels) = (
            SwitchedInput { theta2: 250.0 },
            SwitchedInput { theta2: -40.0 },
        );
        let input = SwitchedInput { theta2 };
        let fixed = |f: &dyn Fn() -> String| f();
        switched.circuit = Mode::Plus;
        let l = format!("{:?}", switched.solve(&input, &rates, &accels).unwrap());
        let want_l = fixed(&|| {
            let (i, r, a) = (
                LeftInput { theta2 },
                LeftInput { theta2: 250.0 },
                LeftInput { theta2: -40.0 },
            );
            format!("{:?}", left.solve(&i, &r, &a).unwrap())
        });
        assert_eq!(
            l.replace("Switched", ""),
            want_l.replace("Left", ""),
            "left at {theta2}"
        );
        switched.circuit = Mode::Minus;
        let r = format!("{:?}", switched.solve(&input, &rates, &accels).unwrap());
        let want_r = fixed(&|| {
            let (i, rr, a) = (
                RightInput { theta2 },
                RightInput { theta2: 250.0 },
                RightInput { theta2: -40.0 },
            );
            format!("{:?}", right.solve(&i, &rr, &a).unwrap())
        });
        assert_eq!(
            r.replace("Switched", ""),
            want_r.replace("Right", ""),
            "right at {theta2}"
        );
        assert_ne!(l.replace("Switched", ""), want_r.replace("Right", ""));
    }
}

// Proves the batch's lane kernel reads the parameter too: every column of a
// 3600-element batch is bit for bit the fixed definition's, for each value.
#[cfg(feature = "alloc")]
#[test]
fn the_batch_agrees_to_the_bit_for_each_circuit() {
    let n = angles().count();
    let run_switched = |mode: Mode| {
        let fb = Switched::<f64> {
            circuit: mode,
            ..Default::default()
        };
        let mut b = Switched::<f64>::batch(n);
        b.in_theta2 = angles().collect();
        b.rate_theta2 = vec![250.0; n];
        b.accel_theta2 = vec![-40.0; n];
        assert_eq!(fb.solve_columns(&mut b).unwrap(), 0);
        format!("{b:?}")
    };
    let mut l = Left::<f64>::batch(n);
    l.in_theta2 = angles().collect();
    l.rate_theta2 = vec![250.0; n];
    l.accel_theta2 = vec![-40.0; n];
    assert_eq!(Left::<f64>::default().solve_columns(&mut l).unwrap(), 0);
    let mut r = Right::<f64>::batch(n);
    r.in_theta2 = angles().collect();
    r.rate_theta2 = vec![250.0; n];
    r.accel_theta2 = vec![-40.0; n];
    assert_eq!(Right::<f64>::default().solve_columns(&mut r).unwrap(), 0);
    assert_eq!(
        run_switched(Mode::Plus).replace("Switched", ""),
        format!("{l:?}").replace("Left", "")
    );
    assert_eq!(
        run_switched(Mode::Minus).replace("Switched", ""),
        format!("{r:?}").replace("Right", "")
    );
}

mechanism! {
    /// The same crank-rocker with literal dimensions: the circuit is the one
    /// parameter, so the struct has no field of the scalar type.
    pub ModeOnly {
        params { circuit = left }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(304.8, 0.0);
        let A = crank(O2, 101.6, theta2) as link2;
        let B = rrr(A, 254.0, O4, 177.8, circuit) as (link3, link4);
    }
}

// Proves a definition whose only parameter is a mode compiles (its struct
// has no field of type `T`), that flipping the field at run time flips the
// assembly: for each value `B` closes both links (|AB| = 254, |O4 B| =
// 177.8) on the side of `A -> O4` the mode names, and the two values give
// the two circuits of the parametric definition's fixed-mode twins.
#[test]
fn a_mode_as_the_only_parameter_flips_the_circuit_at_run_time() {
    let mut m = ModeOnly::<f64>::default();
    assert_eq!(m.circuit, Mode::Plus);
    let (left, right) = (Left::<f64>::default(), Right::<f64>::default());
    // The dimensions are a few hundred mm and every step is a handful of
    // operations: 1e-9 mm is some 10^4 ulps of them.
    let tol = 1e-9;
    for theta2 in angles() {
        for (mode, side) in [(Mode::Plus, 1.0), (Mode::Minus, -1.0)] {
            m.circuit = mode;
            let p = m.position(&ModeOnlyInput { theta2 }).unwrap();
            let (a, b) = (p.A, p.B);
            let o4 = mechanism::Point2::new(304.8, 0.0);
            assert!(((b - a).norm() - 254.0).abs() < tol, "{theta2}");
            assert!(((b - o4).norm() - 177.8).abs() < tol, "{theta2}");
            let (u, w) = (o4 - a, b - a);
            assert!(side * (u.x * w.y - u.y * w.x) > 0.0, "{mode:?} at {theta2}");
            let twin = if mode == Mode::Plus {
                left.position(&LeftInput { theta2 }).unwrap().B
            } else {
                right.position(&RightInput { theta2 }).unwrap().B
            };
            assert!((b - twin).norm() < tol, "{mode:?} at {theta2}");
        }
    }
}

mechanism! {
    /// The five-bar robot of `scenes::FiveBarIk` as drawn (m), given its end
    /// point, each elbow's side a run-time field: `mode elbow1 =
    /// assembly(A)` for the RRR the decomposition finds to place `A`.
    pub DrawnElbows {
        joints {
            O1 = (0.0, 0.0),
            O2 = (0.08, 0.0),
            A = (-0.017364817766693034885, 0.098480775301220805937),
            C = (0.15071067811865475244, 0.07071067811865475244),
            P = (0.088752052427120438854, 0.2182272151659171658),
        }
        links { ground = [O1, O2], arm1 = [O1, A], arm2 = [O2, C], forearm1 = [A, P], forearm2 = [C, P] }
        input x = P.x;
        input y = P.y;
        mode elbow1 = assembly(A);
        mode elbow2 = assembly(C);
    }
}

mechanism! {
    /// The same robot with groups, the elbows' sides run-time parameters
    /// whose defaults are the sides drawn.
    pub GroupedElbows {
        params { elbow1 = left, elbow2 = right }
        let O1 = ground(0.0, 0.0);
        let O2 = ground(0.08, 0.0);
        let P = target(x, y) as P_effector;
        let A = rrr(O1, 0.1, P, 0.16, elbow1) as (arm1, forearm1);
        let C = rrr(O2, 0.1, P, 0.16, elbow2) as (arm2, forearm2);
    }
}

/// `d`'s side of the directed line `from -> to` (+1 left, -1 right).
fn side(
    from: mechanism::Point2<f64>,
    to: mechanism::Point2<f64>,
    d: mechanism::Point2<f64>,
) -> f64 {
    let (u, w) = (to - from, d - from);
    (u.x * w.y - u.y * w.x).signum()
}

// Proves the drawn form's `mode` statement makes a run-time field per elbow
// whose default is the side drawn, and that each of the four combinations
// of the two fields is the grouped form with the same combination of its
// parameters: over a grid of end points, the elbows and the motor angles
// agree within 8 ulps of their scale (0.3 m for points, pi for angles: the
// drawing's lengths are 0.1 and 0.16 to the last bit, so only the order of
// the decomposition's arguments rounds differently), and flipping a field
// moves its elbow to the other side of the line from its base pivot to `P`.
#[test]
fn the_drawn_elbows_flip_at_run_time_as_the_grouped_ones_do() {
    let mut drawn = DrawnElbows::<f64>::default();
    let mut grouped = GroupedElbows::<f64>::default();
    let (d1, d2) = (drawn.elbow1, drawn.elbow2);
    let (o1, o2) = (
        mechanism::Point2::new(0.0, 0.0),
        mechanism::Point2::new(0.08, 0.0),
    );
    let (point_tol, angle_tol) = (8.0 * f64::EPSILON * 0.3, 8.0 * f64::EPSILON * 3.2);
    for (f1, f2) in [(false, false), (true, false), (false, true), (true, true)] {
        drawn.elbow1 = if f1 { d1.flipped() } else { d1 };
        drawn.elbow2 = if f2 { d2.flipped() } else { d2 };
        grouped.elbow1 = if f1 { Mode::Minus } else { Mode::Plus };
        grouped.elbow2 = if f2 { Mode::Plus } else { Mode::Minus };
        for i in 0..=8 {
            for k in 0..=10 {
                let (x, y) = (i as f64 * 0.01, 0.12 + k as f64 * 0.01);
                let d = drawn.position(&DrawnElbowsInput { x, y }).unwrap();
                let g = grouped.position(&GroupedElbowsInput { x, y }).unwrap();
                for (a, b) in [(d.A, g.A), (d.C, g.C)] {
                    assert!((a - b).norm() <= point_tol, "{f1} {f2} at ({x}, {y})");
                }
                for (a, b) in [(d.arm1, g.arm1), (d.arm2, g.arm2)] {
                    assert!((a - b).abs() <= angle_tol, "{f1} {f2} at ({x}, {y})");
                }
                // The drawing has `A` left of O1 -> P and `C` right of O2 -> P.
                let want1 = if f1 { -1.0 } else { 1.0 };
                let want2 = if f2 { 1.0 } else { -1.0 };
                assert_eq!(side(o1, d.P, d.A), want1, "{f1} at ({x}, {y})");
                assert_eq!(side(o2, d.P, d.C), want2, "{f2} at ({x}, {y})");
            }
        }
    }
}
