//! The batch API against the scalar path, element by element: the same status
//! everywhere (the vectorized kernel of `solve_batch` hands every element it
//! cannot vouch for to the scalar path), outputs within a few ulp of the
//! scalar ones where the element is ok, zeros (never NaN) where it failed.
//! Scenes: a four-bar with a coupler point and a crank-rocker that cannot
//! turn fully (lane kernel, with failures), a five-bar (lane kernel, two
//! inputs), a slider-crank (no lane version: scalar path only).

use mechanism::mechanism;

mechanism! {
    /// Grashof-violating four-bar (mm): the coupler cannot reach the rocker
    /// over part of the crank's turn (a run-time parameter, so the macro does
    /// not reject it at expansion time).
    pub Stuck {
        params { ground = 100.0 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, 80.0, theta) as link2;
        let B = rrr(A, 60.0, O4, 50.0, left) as (link3, link4);
        let P = point(link3, from A, 30.0, 40 deg);
        let Q = point(link4, from O4, (10.0, -5.0));
        outputs { A, B, P, Q, link2, link3, link4 }
    }
}

mechanism! {
    /// Five-bar (m) with distal links that reach only part of the workspace
    /// (a parameter: not rejected at expansion time).
    pub Five {
        params { distal = 0.1 }
        dof 2;
        let O1 = ground(0.0, 0.0);
        let O2 = ground(0.08, 0.0);
        let A = crank(O1, 0.1, q1) as arm1;
        let C = crank(O2, 0.1, q2) as arm2;
        let P = rrr(A, distal, C, distal, right) as (fore1, fore2);
        outputs { P, fore1, fore2 }
    }
}

mechanism! {
    /// Slider-crank (m): RRP, so the scalar path only.
    pub Slide {
        dof 1;
        let O = ground(0.0, 0.0);
        let line = guide((0.0, 0.02), 0 deg);
        let A = crank(O, 0.1, theta) as link2;
        let B = rrp(A, 0.4, line, plus) as (link3, slider) slide x;
        outputs { B, link3, x }
    }
}

/// Relative agreement of two values at the scale of the scene: `|a - b| <=
/// tol * max(1, |b|, scale)`.
fn close(a: f64, b: f64, tol: f64, scale: f64) -> bool {
    (a - b).abs() <= tol * b.abs().max(scale).max(1.0)
}

/// The inputs: a dense turn and a half, a few out-of-range and non-finite
/// angles (the lane kernel's range is |x| <= 1e5).
fn angles() -> Vec<f64> {
    let mut v: Vec<f64> = (0..5000).map(|i| -3.0 + i as f64 * 0.0019).collect();
    v.extend([2.0e5, -1.0e6, f64::NAN, f64::INFINITY, 1.0e5]);
    v
}

macro_rules! stuck_check {
    ($t:ty, $tol:expr) => {{
        let m = Stuck::<$t>::default();
        let th: Vec<$t> = angles().into_iter().map(|x| x as $t).collect();
        let n = th.len();
        let mut w = vec![3.0 as $t; n];
        let mut a = vec![-2.0 as $t; n];
        // Assembled poses (theta near 0.04 and 0.135 rad) with a non-finite
        // rate and acceleration: the velocity and the acceleration fail.
        w[1600] = <$t>::INFINITY;
        a[1650] = <$t>::NAN;
        let mut out = vec![vec![<$t>::NAN; n]; 33];
        let mut status = vec![7u8; n];
        let failed = {
            let mut o = out.iter_mut().map(|v| v.as_mut_slice());
            let mut nx = || o.next().unwrap();
            let mut b = StuckBatch {
                in_theta: &th,
                rate_theta: &w,
                accel_theta: &a,
                pos_A_x: nx(),
                pos_A_y: nx(),
                pos_B_x: nx(),
                pos_B_y: nx(),
                pos_P_x: nx(),
                pos_P_y: nx(),
                pos_Q_x: nx(),
                pos_Q_y: nx(),
                pos_link2: nx(),
                pos_link3: nx(),
                pos_link4: nx(),
                vel_A_x: nx(),
                vel_A_y: nx(),
                vel_B_x: nx(),
                vel_B_y: nx(),
                vel_P_x: nx(),
                vel_P_y: nx(),
                vel_Q_x: nx(),
                vel_Q_y: nx(),
                vel_link2: nx(),
                vel_link3: nx(),
                vel_link4: nx(),
                acc_A_x: nx(),
                acc_A_y: nx(),
                acc_B_x: nx(),
                acc_B_y: nx(),
                acc_P_x: nx(),
                acc_P_y: nx(),
                acc_Q_x: nx(),
                acc_Q_y: nx(),
                acc_link2: nx(),
                acc_link3: nx(),
                acc_link4: nx(),
                status: &mut status,
            };
            m.solve_batch(&mut b)
        };
        let (mut oks, mut fails) = (0, 0);
        for k in 0..n {
            let input = StuckInput { theta: th[k] };
            let sol = m.solve(
                &input,
                &StuckInput { theta: w[k] },
                &StuckInput { theta: a[k] },
            );
            let got: Vec<f64> = out.iter().map(|v| v[k] as f64).collect();
            match sol {
                Ok(s) => {
                    oks += 1;
                    assert_eq!(status[k], 0, "theta {}", th[k]);
                    let (p, v, c) = (s.position, s.velocity, s.acceleration);
                    let want = [
                        p.A.x, p.A.y, p.B.x, p.B.y, p.P.x, p.P.y, p.Q.x, p.Q.y, p.link2, p.link3,
                        p.link4, v.A.x, v.A.y, v.B.x, v.B.y, v.P.x, v.P.y, v.Q.x, v.Q.y, v.link2,
                        v.link3, v.link4, c.A.x, c.A.y, c.B.x, c.B.y, c.P.x, c.P.y, c.Q.x, c.Q.y,
                        c.link2, c.link3, c.link4,
                    ];
                    // Scale 100 (mm): absolute agreement at the scene's size.
                    for (j, (g, w)) in got.iter().zip(want).enumerate() {
                        assert!(
                            close(*g, w as f64, $tol, 100.0),
                            "theta {} output {j}: {g} vs {w}",
                            th[k]
                        );
                    }
                }
                Err(_) => {
                    fails += 1;
                    assert_ne!(status[k], 0, "theta {}", th[k]);
                    // Status 1, 2, 3: that level and the ones after it are
                    // zeros (11 outputs per level); the levels before were
                    // solved (checked against the scalar path by the ok cases).
                    assert!((1..=3).contains(&status[k]), "theta {}", th[k]);
                    let from = 11 * (status[k] as usize - 1);
                    assert!(got[from..].iter().all(|g| *g == 0.0), "theta {}", th[k]);
                    assert!(got.iter().all(|g| g.is_finite()), "theta {}", th[k]);
                }
            }
        }
        assert_eq!((status[1600], status[1650]), (2, 3));
        assert_eq!(failed, fails);
        // The sweep covers both the assembled and the unassemblable poses.
        assert!(oks > 1000 && fails > 100, "{oks} ok, {fails} failed");
    }};
}

#[test]
fn four_bar_batch_matches_the_scalar_path_f64() {
    // The kernel's primitives are within 2 ulp of libm's and the chain is a
    // dozen operations deep; near the edges of assembly and at the toggle the
    // rates amplify rounding by 1 / condition (the lane kernel hands elements
    // within 4x the singular threshold to the scalar path). 1e-9 relative at
    // the scene's scale leaves room for a condition down to about 1e-5.
    stuck_check!(f64, 1e-9);
}

#[test]
fn four_bar_batch_matches_the_scalar_path_f32() {
    // The same at f32 resolution (eps 1.2e-7): 2e-2 relative near the edges
    // of assembly, where the rates grow as 1 / condition.
    stuck_check!(f32, 2e-2);
}

#[test]
fn five_bar_batch_matches_the_scalar_path() {
    let m = Five::<f64>::default();
    let (mut q1, mut q2) = (Vec::new(), Vec::new());
    for i in 0..80 {
        for j in 0..80 {
            q1.push(0.5 + i as f64 * 0.03);
            q2.push(-0.5 + j as f64 * 0.03);
        }
    }
    let n = q1.len();
    let ones = vec![1.0; n];
    let mut out = vec![vec![f64::NAN; n]; 12];
    let mut status = vec![9u8; n];
    let failed = {
        let mut o = out.iter_mut().map(|v| v.as_mut_slice());
        let mut nx = || o.next().unwrap();
        let mut b = FiveBatch {
            in_q1: &q1,
            in_q2: &q2,
            rate_q1: &ones,
            rate_q2: &ones,
            accel_q1: &ones,
            accel_q2: &ones,
            pos_P_x: nx(),
            pos_P_y: nx(),
            pos_fore1: nx(),
            pos_fore2: nx(),
            vel_P_x: nx(),
            vel_P_y: nx(),
            vel_fore1: nx(),
            vel_fore2: nx(),
            acc_P_x: nx(),
            acc_P_y: nx(),
            acc_fore1: nx(),
            acc_fore2: nx(),
            status: &mut status,
        };
        m.solve_batch(&mut b)
    };
    let mut fails = 0;
    for k in 0..n {
        let i = FiveInput {
            q1: q1[k],
            q2: q2[k],
        };
        let r = FiveInput { q1: 1.0, q2: 1.0 };
        let got: Vec<f64> = out.iter().map(|v| v[k]).collect();
        match m.solve(&i, &r, &r) {
            Ok(s) => {
                assert_eq!(status[k], 0);
                let (p, v, a) = (s.position, s.velocity, s.acceleration);
                let want = [
                    p.P.x, p.P.y, p.fore1, p.fore2, v.P.x, v.P.y, v.fore1, v.fore2, a.P.x, a.P.y,
                    a.fore1, a.fore2,
                ];
                for (g, w) in got.iter().zip(want) {
                    // As for the four-bar; scale 0.1 m.
                    assert!(close(*g, w, 1e-9, 0.1), "{k}: {g} vs {w}");
                }
            }
            Err(_) => {
                fails += 1;
                assert_ne!(status[k], 0);
                assert!(got.iter().all(|g| *g == 0.0));
            }
        }
    }
    assert_eq!(failed, fails);
    assert!(fails > 0 && fails < n, "{fails}");
}

#[test]
fn slider_crank_batch_uses_the_scalar_path() {
    let m = Slide::<f64>::default();
    let th = angles();
    let n = th.len();
    let zeros = vec![0.0; n];
    let mut out = vec![vec![f64::NAN; n]; 12];
    let mut status = vec![9u8; n];
    let failed = {
        let mut o = out.iter_mut().map(|v| v.as_mut_slice());
        let mut nx = || o.next().unwrap();
        let mut b = SlideBatch {
            in_theta: &th,
            rate_theta: &zeros,
            accel_theta: &zeros,
            pos_B_x: nx(),
            pos_B_y: nx(),
            pos_link3: nx(),
            pos_x: nx(),
            vel_B_x: nx(),
            vel_B_y: nx(),
            vel_link3: nx(),
            vel_x: nx(),
            acc_B_x: nx(),
            acc_B_y: nx(),
            acc_link3: nx(),
            acc_x: nx(),
            status: &mut status,
        };
        m.solve_batch(&mut b)
    };
    let mut fails = 0;
    for k in 0..n {
        let i = SlideInput { theta: th[k] };
        let z = SlideInput { theta: 0.0 };
        match m.solve(&i, &z, &z) {
            Ok(s) => {
                assert_eq!(status[k], 0);
                // The same code path: bit for bit.
                assert_eq!(out[0][k], s.position.B.x);
                assert_eq!(out[3][k], s.position.x);
            }
            Err(_) => {
                fails += 1;
                assert_ne!(status[k], 0);
                assert!(out.iter().all(|v| v[k] == 0.0));
            }
        }
    }
    assert_eq!(failed, fails);
    assert_eq!(fails, 2, "NaN and infinity only");
}
