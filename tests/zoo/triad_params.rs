//! The triad (class III group) where its dimensions are run-time `params`
//! (one through `sqrt`), and in a mechanism with two inputs (link 6's angle
//! and a second crank carrying the triad's second known point), against
//! the double-double reference `mechanism_reference::triad` (its own Newton
//! on the loop closure in the four link angles, rates and accelerations from
//! its Jacobian; the assembly picked from its own scan of every assembly);
//! and the typed errors where no pose exists.
//!
//! Tolerance. Every compared column is held to 1e-13 of its largest
//! magnitude over the compared inputs (angles: 1e-13 rad), the figure the
//! Stephenson example meets over its whole swing: the generated position is
//! Newton-polished to a few eps of the lengths, and the sweeps here (link 6
//! from -46 to -12 deg) stop short of the swings' ends (the example's: -50.4
//! and -2.6 deg), where the rate systems' condition grows without bound, so
//! a rate carries tens of eps of its column's scale
//! (the worst measured here is 1.4e-14, 63 eps); 1e-13 is 450 eps. A wrong
//! term shows at its own size: reading leg 3 at its default in the second
//! parameter set moves A by 8e-2 of its scale, and dropping the second
//! crank's angular acceleration moves the accelerations by 2e-3 of theirs.

use mechanism::{mechanism, Error, Fault, Point2, Primitive, Vector2};
use mechanism_reference::groups::{add, perp, scale, sub, V};
use mechanism_reference::triad::{self as rt, Pose, TriadRef};
use mechanism_reference::Dd;

mechanism! {
    /// The Stephenson III six-bar of `examples/stephenson.rs` (m) with the
    /// triad's leg 1 (`l1`), leg 3 (`l3`), the coupler's `|AB|` (`ab`) and
    /// P's place in the coupler's frame (`pu`, `pv`: origin A, x along
    /// A -> B) as run-time parameters, and leg 2 from its squared length
    /// (`sqrt(l2sq)`).
    pub TriadParams {
        params { l1 = 0.08, l2sq = 0.04, l3 = 0.28, ab = 0.26, pu = 0.115, pv = 0.096 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.30, 0.0);
        let O6 = ground(0.05, 0.42);
        let C = crank(O6, 0.24, phi) as link6;
        let (A, B, P) = triad(O2, l1, O4, sqrt(l2sq), C, l3, ab, (pu, pv),
                              phi = -30 deg, (-0.063, 0.050), (0.175, 0.156), (0.003, 0.185))
            as (crank2, rocker, link5, coupler);
    }
}

mechanism! {
    /// The same six-bar with two inputs: link 6's angle `phi` and a crank
    /// `link7` (0.02 m about (0.30, -0.02), angle `psi`) whose tip `K2` is the
    /// rocker's pivot (at `psi` = 90 deg, where the example has `O4`).
    pub TriadTwoInputs {
        let O2 = ground(0.0, 0.0);
        let Q = ground(0.30, -0.02);
        let O6 = ground(0.05, 0.42);
        let K2 = crank(Q, 0.02, psi) as link7;
        let C = crank(O6, 0.24, phi) as link6;
        let (A, B, P) = triad(O2, 0.08, K2, 0.20, C, 0.28, 0.26, 0.15, 40 deg,
                              phi = -30 deg, (-0.063, 0.050), (0.175, 0.156), (0.003, 0.185))
            as (crank2, rocker, link5, coupler);
    }
}

/// The stated input (deg) and the stated approximate joints A, B, P (m) at
/// it, read to three digits off the example's table. Mid-swing: at the
/// example's -49.48 deg, 0.96 deg from the swing's end, changed dimensions
/// or a moved `K2` shift the end past the stated input, and `position()`
/// rightly answers `NotNear` there.
const PHI0_DEG: f64 = -30.0;
const STATED: [[f64; 2]; 3] = [[-0.063, 0.050], [0.175, 0.156], [0.003, 0.185]];

/// Link 6's angles of a sweep (rad): from the stated input down to -46 deg,
/// then again from the stated input up to -12 deg, in steps of `step` deg;
/// `true` marks each leg's first input (the stated one).
fn sweep(step: f64) -> Vec<(f64, bool)> {
    let mut out = Vec::new();
    for end in [-46.0, -12.0] {
        let n = ((end - PHI0_DEG) / step).abs().round() as usize;
        for k in 0..=n {
            let x = PHI0_DEG + (end - PHI0_DEG) * k as f64 / n as f64;
            out.push((x.to_radians(), k == 0));
        }
    }
    out
}

/// The tip of a crank of length `r` (m) about `centre` at angle `x` (rad),
/// turning at `w` (rad/s) and `al` (rad/s^2): its position, velocity and
/// acceleration in double-double.
fn tip(centre: [f64; 2], r: f64, x: f64, w: f64, al: f64) -> [V; 3] {
    let (s, c) = Dd::from(x).sin_cos();
    let arm = [Dd::from(r) * c, Dd::from(r) * s];
    let (w, al) = (Dd::from(w), Dd::from(al));
    [
        add([Dd::from(centre[0]), Dd::from(centre[1])], arm),
        scale(w, perp(arm)),
        sub(scale(al, perp(arm)), scale(w * w, arm)),
    ]
}

/// One compared row: A, B, P, then the angles of crank2, rocker, link5 and
/// the coupler; positions, velocities, accelerations (30 values).
type Row = [f64; 30];

fn row(joints: [[[f64; 2]; 3]; 3], angles: [[f64; 4]; 3]) -> Row {
    let mut r = [0.0; 30];
    for o in 0..3 {
        for i in 0..3 {
            r[10 * o + 2 * i] = joints[o][i][0];
            r[10 * o + 2 * i + 1] = joints[o][i][1];
        }
        r[10 * o + 6..10 * o + 10].copy_from_slice(&angles[o]);
    }
    r
}

/// The generated answer as a [`Row`]: the joints' positions, velocities
/// and accelerations, and the link angles' (crank2, rocker, link5, coupler).
fn generated_row(
    p: [Point2<f64>; 3],
    v: [Vector2<f64>; 3],
    a: [Vector2<f64>; 3],
    angles: [[f64; 4]; 3],
) -> Row {
    let xy = |v: Vector2<f64>| [v.x, v.y];
    row([p.map(|p| xy(p.coords)), v.map(xy), a.map(xy)], angles)
}

/// The reference's row at a pose: rates and accelerations from the known
/// points' motion `k = [[vK1, vK2, vK3], [aK1, aK2, aK3]]`.
fn reference_row(t: &TriadRef, pose: &Pose, k: [[V; 3]; 2]) -> Row {
    let (w, vj) = rt::rates(t, pose, k[0]).expect("regular in the compared sweep");
    let (al, aj) = rt::accelerations(t, pose, &w, k[1]).expect("regular");
    let f = |v: [V; 3]| v.map(|p| p.map(Dd::to_f64));
    row(
        [f(pose.joints), f(vj), f(aj)],
        [pose.q, w, al].map(|a| a.map(Dd::to_f64)),
    )
}

/// The reference assembly nearest the stated joints (root-sum-square over A,
/// B, P), from the reference's own scan of every assembly.
fn nearest_stated(t: &TriadRef) -> Pose {
    let all = rt::assemblies(t, 4096);
    let dist = |p: &Pose| {
        (0..3)
            .map(|i| {
                let d = [0, 1].map(|c| p.joints[i][c].to_f64() - STATED[i][c]);
                d[0] * d[0] + d[1] * d[1]
            })
            .sum::<f64>()
    };
    *all.iter()
        .min_by(|a, b| dist(a).total_cmp(&dist(b)))
        .expect("the triad assembles at the stated input")
}

fn wrap(d: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    d - tau * (d / tau).round()
}

/// Every column of `got` within 1e-13 of the column's largest |reference|
/// (angles: 1e-13 rad); prints the worst per column.
fn compare(what: &str, got: &[Row], want: &[Row]) {
    assert!(!got.is_empty() && got.len() == want.len());
    for c in 0..30 {
        let scale = want.iter().map(|r| r[c].abs()).fold(0.0, f64::max);
        let angle = (6..10).contains(&c);
        let worst = got
            .iter()
            .zip(want)
            .map(|(g, w)| {
                let d = g[c] - w[c];
                if angle {
                    wrap(d).abs()
                } else {
                    d.abs() / scale
                }
            })
            .fold(0.0, f64::max);
        println!("{what} column {c:>2}: worst {worst:.1e} (scale {scale:.3e})");
        assert!(
            worst <= 1e-13,
            "{what}: column {c}: {worst:e} (scale {scale:e})"
        );
    }
}

/// The reference triad of [`TriadParams`] at `phi` for a parameter set
/// `[l1, l2sq, l3, ab, pu, pv]`, and link 6's tip's motion.
fn params_reference(p: [f64; 6], phi: f64, w: f64, al: f64) -> (TriadRef, [V; 3]) {
    let mut t = TriadRef::new(
        [[0.0, 0.0], [0.30, 0.0], [0.0, 0.0]],
        [p[0], 0.0, p[2]],
        p[3],
        [p[4], p[5]],
    );
    t.l[1] = Dd::from(p[1]).sqrt();
    let c = tip([0.05, 0.42], 0.24, phi, w, al);
    t.k[2] = c[0];
    (t, c)
}

#[test]
fn triad_dimensions_from_params_match_the_reference() {
    // Proves a triad whose legs 1 and 3, |AB|, P's place and (through
    // `sqrt`) leg 2 are run-time parameters solves the mechanism those
    // parameters describe: at three parameter sets, `position()` at the
    // stated input picks the reference's assembly nearest the stated pose,
    // and `position_near` followed over link 6 from there (-30 deg) down to
    // -46 deg and up to -12 deg (0.25 deg steps), with `velocity` and `acceleration`, matches the
    // double-double reference's continuation at every step to 1e-13 of each
    // column's scale. The sets differ by 3e-3 m or more in each
    // dimension, so a parameter read at its default would fail the check.
    let sets: [[f64; 6]; 3] = [
        [0.08, 0.04, 0.28, 0.26, 0.115, 0.096],
        [0.083, 0.042, 0.275, 0.256, 0.108, 0.104],
        [0.077, 0.0385, 0.285, 0.264, 0.121, 0.091],
    ];
    let (w6, al6) = (1.5, -0.5);
    for set in sets {
        let mut m = TriadParams::<f64>::default();
        [m.l1, m.l2sq, m.l3, m.ab, m.pu, m.pv] = set;
        let phi0 = PHI0_DEG.to_radians();
        let (t0, _) = params_reference(set, phi0, w6, al6);
        let start = nearest_stated(&t0);
        let first = m
            .position(&TriadParamsInput { phi: phi0 })
            .expect("position() finds the stated assembly at the stated input");
        let (mut pos, mut refq) = (first, start.q);
        let (mut got, mut want) = (Vec::new(), Vec::new());
        for (phi, restart) in sweep(0.25) {
            let input = TriadParamsInput { phi };
            if restart {
                (pos, refq) = (first, start.q);
            } else {
                pos = m
                    .position_near(&pos, &input)
                    .expect("tracks inside the swing");
            }
            let v = m.velocity(&pos, &TriadParamsInput { phi: w6 }).unwrap();
            let a = m
                .acceleration(&pos, &v, &TriadParamsInput { phi: al6 })
                .unwrap();
            let (t, c) = params_reference(set, phi, w6, al6);
            let pose = rt::newton(&t, refq).expect("the reference continues");
            refq = pose.q;
            let z = [Dd::ZERO; 2];
            want.push(reference_row(&t, &pose, [[z, z, c[1]], [z, z, c[2]]]));
            got.push(generated_row(
                [pos.A, pos.B, pos.P],
                [v.A, v.B, v.P],
                [a.A, a.B, a.P],
                [
                    [pos.crank2, pos.rocker, pos.link5, pos.coupler],
                    [v.crank2, v.rocker, v.link5, v.coupler],
                    [a.crank2, a.rocker, a.link5, a.coupler],
                ],
            ));
        }
        compare(&format!("params {set:?}"), &got, &want);
    }
}

/// Rates of the two inputs (rad/s) and their accelerations (rad/s^2).
const W: (f64, f64) = (1.5, -2.0);
const AL: (f64, f64) = (-0.5, 3.0);

/// The reference triad of [`TriadTwoInputs`] at `(phi, psi)` and the known
/// points' motion.
fn two_reference(phi: f64, psi: f64) -> (TriadRef, [[V; 3]; 2]) {
    let d = 40f64.to_radians();
    let mut t = TriadRef::new(
        [[0.0, 0.0], [0.0, 0.0], [0.0, 0.0]],
        [0.08, 0.20, 0.28],
        0.26,
        [0.15 * d.cos(), 0.15 * d.sin()],
    );
    let c = tip([0.05, 0.42], 0.24, phi, W.0, AL.0);
    let k2 = tip([0.30, -0.02], 0.02, psi, W.1, AL.1);
    t.k[1] = k2[0];
    t.k[2] = c[0];
    let z = [Dd::ZERO; 2];
    (t, [[z, k2[1], c[1]], [z, k2[2], c[2]]])
}

#[test]
fn triad_with_two_inputs_matches_the_reference_over_a_grid() {
    // Proves a triad whose second known point rides on a second crank (two
    // inputs, `phi` and `psi`) is solved at every point of a 5 x 70 grid
    // (psi 60..120 deg in 15 deg steps; phi -46..-12 deg in 0.5 deg steps,
    // followed from -30 deg in 0.125 deg steps): at each psi, `position()` at
    // the stated phi picks the reference's assembly nearest the stated pose,
    // and `position_near` along phi, `velocity` and `acceleration` with both
    // inputs moving (psi' = -2 rad/s, psi'' = 3 rad/s^2, so K2's motion
    // enters the rates) match the double-double reference, which gets K2's
    // velocity and acceleration from its own crank, to 1e-13 of each
    // column's scale.
    let m = TriadTwoInputs::<f64>::default();
    let (wi, ai) = (
        TriadTwoInputsInput { phi: W.0, psi: W.1 },
        TriadTwoInputsInput {
            phi: AL.0,
            psi: AL.1,
        },
    );
    let (mut got, mut want) = (Vec::new(), Vec::new());
    for j in 0..5 {
        let psi = (60.0 + 15.0 * j as f64).to_radians();
        let phi0 = PHI0_DEG.to_radians();
        let (t0, _) = two_reference(phi0, psi);
        let start = nearest_stated(&t0).q;
        let first = m
            .position(&TriadTwoInputsInput { phi: phi0, psi })
            .expect("position() finds the stated assembly at the stated phi");
        let (mut pos, mut refq) = (first, start);
        for (k, (phi, restart)) in sweep(0.125).into_iter().enumerate() {
            let input = TriadTwoInputsInput { phi, psi };
            if restart {
                (pos, refq) = (first, start);
            } else {
                pos = m
                    .position_near(&pos, &input)
                    .expect("tracks inside the swing");
            }
            let (t, motion) = two_reference(phi, psi);
            let pose = rt::newton(&t, refq).expect("the reference continues");
            refq = pose.q;
            if k % 4 != 0 {
                continue;
            }
            let v = m.velocity(&pos, &wi).unwrap();
            let a = m.acceleration(&pos, &v, &ai).unwrap();
            want.push(reference_row(&t, &pose, motion));
            got.push(generated_row(
                [pos.A, pos.B, pos.P],
                [v.A, v.B, v.P],
                [a.A, a.B, a.P],
                [
                    [pos.crank2, pos.rocker, pos.link5, pos.coupler],
                    [v.crank2, v.rocker, v.link5, v.coupler],
                    [a.crank2, a.rocker, a.link5, a.coupler],
                ],
            ));
        }
    }
    compare("two inputs", &got, &want);
}

/// The error is the triad's (group `A`, primitive `triad`) and says the
/// triad cannot be assembled, by a finite, positive miss (L).
fn assert_cannot_assemble<T: std::fmt::Debug>(r: Result<T, Error>) {
    match r {
        Err(e @ Error { group: "A", .. }) => {
            assert_eq!(e.primitive, Primitive::Triad, "{e:?}");
            assert!(
                matches!(e.fault, Fault::CannotAssemble { miss, .. } if miss.is_finite() && miss > 0.0),
                "{e:?}"
            );
        }
        other => panic!("expected the triad's error, got {other:?}"),
    }
}

#[test]
fn unassemblable_triads_are_typed_errors_naming_the_group() {
    // Proves that where the triad cannot be assembled the generated code
    // returns a typed error attributed to the triad (group `A`, primitive
    // `triad`, a finite miss), never NaN or a pose: with leg 3 set by a
    // parameter too short for P to reach C (0.02 m: P stays within
    // 0.08 + 0.15 m of O2, C is 0.31 m from O2 at the stated input) both `position()` and `position_near` from a
    // valid pose fail with `CannotAssemble`; and in the two-input mechanism,
    // link 6 turned to +90 deg (C at (0.05, 0.66), 0.66 m from O2, out of
    // reach of 0.08 + 0.15 + 0.28 = 0.51) fails the same way.
    let phi0 = PHI0_DEG.to_radians();
    let mut m = TriadParams::<f64>::default();
    let good = m.position(&TriadParamsInput { phi: phi0 }).unwrap();
    m.l3 = 0.02;
    assert_cannot_assemble(m.position(&TriadParamsInput { phi: phi0 }));
    assert_cannot_assemble(m.position_near(&good, &TriadParamsInput { phi: phi0 }));

    let two = TriadTwoInputs::<f64>::default();
    let up = TriadTwoInputsInput {
        phi: 90f64.to_radians(),
        psi: 90f64.to_radians(),
    };
    assert_cannot_assemble(two.position(&up));
    let near = two
        .position(&TriadTwoInputsInput {
            phi: phi0,
            psi: 90f64.to_radians(),
        })
        .unwrap();
    assert_cannot_assemble(two.position_near(&near, &up));
}

#[test]
fn bad_parameters_and_inputs_are_typed_errors() {
    // Proves that a non-finite, zero or negative triad dimension set through
    // `params` (a NaN leg, a negative leg, a zero |AB|, and `sqrt` of a
    // negative parameter, which is NaN) is a typed error of the triad
    // (group `A`) naming the dimension, from `position()` and from
    // `position_near`, and that a non-finite input angle or rate is the
    // driver's typed error (group `C`): never a pose holding NaN.
    let phi0 = PHI0_DEG.to_radians();
    let at = TriadParamsInput { phi: phi0 };
    let good = TriadParams::<f64>::default().position(&at).unwrap();
    /// Sets one parameter badly; the dimension the error must name.
    type Case = (fn(&mut TriadParams<f64>), &'static str);
    let cases: [Case; 4] = [
        (|m| m.l1 = f64::NAN, "triad leg length l1"),
        (|m| m.l3 = -0.28, "triad leg length l3"),
        (|m| m.ab = 0.0, "triad side |AB|"),
        (|m| m.l2sq = -0.04, "triad leg length l2"),
    ];
    for (set, what) in cases {
        let mut m = TriadParams::<f64>::default();
        set(&mut m);
        for r in [m.position(&at), m.position_near(&good, &at)] {
            match r {
                Err(Error {
                    group: "A",
                    primitive: Primitive::Triad,
                    fault: Fault::NonFinite { what: w } | Fault::NonPositive { what: w, .. },
                }) => assert_eq!(w, what),
                other => panic!("{what}: {other:?}"),
            }
        }
    }
    let m = TriadParams::<f64>::default();
    let nan = TriadParamsInput { phi: f64::NAN };
    let v = m.velocity(&good, &TriadParamsInput { phi: 1.5 }).unwrap();
    let driver = |r: Result<(), Error>| {
        assert!(
            matches!(
                r,
                Err(Error {
                    group: "C",
                    primitive: Primitive::Crank,
                    ..
                })
            ),
            "{r:?}"
        )
    };
    driver(m.position(&nan).map(|_| ()));
    driver(m.position_near(&good, &nan).map(|_| ()));
    driver(m.velocity(&good, &nan).map(|_| ()));
    driver(m.acceleration(&good, &v, &nan).map(|_| ()));
}
