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
