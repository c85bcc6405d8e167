//! The Stephenson III six-bar of `examples/stephenson.rs` (scene
//! `common::stephenson::Stephenson`, a `triad` statement) against the
//! independent double-double reference (`mechanism_reference::triad`: Newton
//! on the loop closure in the four link angles, rates from its Jacobian),
//! and the generated tracking form and forces.

use crate::common::stephenson::{self as st, Stephenson, StephensonInput, StephensonLoads};
use mechanism::{Error, Fault};
use mechanism_reference::triad::{self as rt, Pose, TriadRef};
use mechanism_reference::Dd;

/// The reference triad at link 6's angle `phi` (rad): `C` in double-double
/// from the exact `f64` input, P's place as the definition folds it.
fn reference(phi: f64) -> (TriadRef, [[Dd; 2]; 3]) {
    let d = 40f64.to_radians();
    let mut t = TriadRef::new(
        [[0.0, 0.0], [0.30, 0.0], [0.0, 0.0]],
        [0.08, 0.20, 0.28],
        0.26,
        [0.15 * d.cos(), 0.15 * d.sin()],
    );
    let (s, c) = Dd::from(phi).sin_cos();
    let r = Dd::from(0.24);
    t.k[2] = [Dd::from(0.05) + r * c, Dd::from(0.42) + r * s];
    // C's velocity and acceleration: phi' = 1.5, phi'' = -0.5.
    let (w, al) = (Dd::from(st::PHI_DOT), Dd::from(st::PHI_DDOT));
    let vc = [-(r * w * s), r * w * c];
    let ac = [-(r * al * s) - r * w * w * c, r * al * c - r * w * w * s];
    (t, [[Dd::ZERO; 2], vc, ac])
}

/// The reference's 16 columns at a row, polished by its own Newton from the
/// row's angles (the generated code's answer only picks the assembly).
fn reference_columns(row: &st::Row) -> [f64; 16] {
    let (t, [_, vc, ac]) = reference(row.phi);
    let p = &row.p;
    let start = [p.crank2, p.rocker, p.link5, p.coupler].map(Dd::from);
    let pose: Pose = rt::newton(&t, start).expect("the reference closes the loop there");
    let z = [Dd::ZERO; 2];
    let (w, _) = rt::rates(&t, &pose, [z, z, vc]).expect("regular inside the swing");
    let (al, _) = rt::accelerations(&t, &pose, &w, [z, z, ac]).expect("regular");
    let [a, b, pp] = pose.joints.map(|j| j.map(Dd::to_f64));
    let deg = |x: Dd| {
        let x = x.to_f64();
        x.sin().atan2(x.cos()).to_degrees()
    };
    [
        row.phi.to_degrees(),
        a[0],
        a[1],
        b[0],
        b[1],
        pp[0],
        pp[1],
        deg(pose.q[0]),
        deg(pose.q[3]),
        deg(pose.q[1]),
        w[0].to_f64(),
        w[3].to_f64(),
        w[1].to_f64(),
        al[0].to_f64(),
        al[3].to_f64(),
        al[1].to_f64(),
    ]
}

#[test]
fn every_column_matches_the_double_double_reference() {
    // Proves each of the example's 16 CSV columns, over 64 rows across link
    // 6's whole swing, agrees with the double-double reference to 1e-13 of
    // the column's largest magnitude (the rates grow without bound towards
    // the swing's ends, where two assemblies meet, so a row-wise relative
    // error near a column's zero crossing would measure nothing); and the
    // swing's ends the example prints are where the reference's assembly
    // meets another (its Jacobian's determinant vanishes, to 1e-10 of the
    // angle).
    let m = Stephenson::<f64>::default();
    let (lo, hi) = st::swing(&m);
    for (end, want) in [(lo, -50.4365077489), (hi, -2.6333554164)] {
        assert!(
            (end.to_degrees() - want).abs() < 1e-9,
            "{}",
            end.to_degrees()
        );
    }
    let rows = st::rows(&m, (lo, hi), 64);
    let got: Vec<[f64; 16]> = rows.iter().map(st::Row::columns).collect();
    let want: Vec<[f64; 16]> = rows.iter().map(reference_columns).collect();
    for c in 0..16 {
        let scale = want.iter().map(|r| r[c].abs()).fold(0.0, f64::max);
        let worst = got
            .iter()
            .zip(&want)
            .map(|(g, w)| (g[c] - w[c]).abs())
            .fold(0.0, f64::max);
        println!(
            "{:>18}: worst {:.1e} of {scale:.3e}",
            st::COLUMNS[c],
            worst / scale
        );
        assert!(
            worst <= 1e-13 * scale,
            "{}: {worst:e} of {scale:e}",
            st::COLUMNS[c]
        );
    }
}

#[test]
fn tracking_stays_on_its_assembly_and_reports_the_swing_ends() {
    // Proves `position_near` followed in 0.05 deg steps over the swing stays
    // on the stated assembly (each pose within 1e-13 of the reference's
    // Newton continuation from the previous one), that the stateless
    // `position` finds the same assembly at every row, and that a step past
    // either end of the swing is a typed error naming the triad, never a
    // jump to another assembly.
    let m = Stephenson::<f64>::default();
    let (lo, hi) = st::swing(&m);
    let q0 = st::stated_phi();
    let start = m.position(&StephensonInput { phi: q0 }).unwrap();
    for (end, dir) in [(lo, -1.0), (hi, 1.0)] {
        let (mut pos, mut q) = (start, q0);
        let mut refq = [pos.crank2, pos.rocker, pos.link5, pos.coupler].map(Dd::from);
        let step = 0.05f64.to_radians();
        while (end - q) * dir > step {
            q += dir * step;
            pos = m.position_near(&pos, &StephensonInput { phi: q }).unwrap();
            let (t, _) = reference(q);
            let r = rt::newton(&t, refq).expect("the reference continues");
            refq = r.q;
            let a = r.joints[0].map(Dd::to_f64);
            let miss = (pos.A.x - a[0]).abs().max((pos.A.y - a[1]).abs());
            assert!(miss <= 1e-13, "at {} deg: {miss:e}", q.to_degrees());
            let fresh = m.position(&StephensonInput { phi: q });
            if let Ok(f) = fresh {
                assert!(
                    (f.A - pos.A).amax() <= 1e-13,
                    "position() at {}",
                    q.to_degrees()
                );
            }
        }
        let past = end + dir * 1e-6;
        let last = st::follow(&m, &pos, q, end - dir * 1e-9).unwrap();
        match m.position_near(&last, &StephensonInput { phi: past }) {
            Err(Error {
                group: "A", fault, ..
            }) => assert!(
                matches!(fault, Fault::NotNear { .. } | Fault::CannotAssemble { .. }),
                "{fault:?}"
            ),
            other => panic!("past the end {}: {other:?}", past.to_degrees()),
        }
        assert!(m.position(&StephensonInput { phi: past }).is_err());
    }
}

#[test]
fn forces_pass_the_power_balance() {
    // Proves the triad's reactions with masses, gravity and a 20 N load at P
    // balance the power of every load against the driving torque's to 8 eps
    // (the generated relative residual) at every row of the swing, and the
    // driving torque is not zero (the balance is not met trivially).
    let m = Stephenson::<f64>::default();
    let swing = st::swing(&m);
    let loads = StephensonLoads { fp: -20.0 };
    for row in st::rows(&m, swing, 64) {
        let f = m.forces(&row.p, &row.v, &row.a, &loads).unwrap();
        assert!(
            f.power_residual.abs() <= 8.0 * f64::EPSILON,
            "{}",
            f.power_residual
        );
        assert!(f.drive_phi.abs() > 1e-3, "{}", f.drive_phi);
    }
}

#[test]
fn batch_solves_each_triad_element_like_the_scalar_path() {
    // Proves the batch form (a scalar per-element path: the triad has no
    // lane kernel) gives, bit for bit, what `position`, `velocity` and
    // `acceleration` give at 32 inputs inside the swing, and marks an input
    // beyond the swing's end as failed rather than writing another
    // assembly.
    let m = Stephenson::<f64>::default();
    let (lo, hi) = st::swing(&m);
    let n = 33;
    let mut c = Stephenson::<f64>::batch(n);
    for k in 0..n {
        c.in_phi[k] = if k == n - 1 {
            hi + 0.01
        } else {
            lo + (hi - lo) * (k as f64 + 0.5) / (n - 1) as f64
        };
        c.rate_phi[k] = st::PHI_DOT;
        c.accel_phi[k] = st::PHI_DDOT;
    }
    assert_eq!(m.solve_columns(&mut c), Ok(1));
    for k in 0..n - 1 {
        let input = StephensonInput { phi: c.in_phi[k] };
        let p = m.position(&input).unwrap();
        let v = m
            .velocity(&p, &StephensonInput { phi: st::PHI_DOT })
            .unwrap();
        let a = m
            .acceleration(&p, &v, &StephensonInput { phi: st::PHI_DDOT })
            .unwrap();
        assert_eq!(c.status[k], 0);
        assert_eq!((c.pos_P_x[k], c.pos_P_y[k]), (p.P.x, p.P.y));
        assert_eq!((c.vel_coupler[k], c.acc_rocker[k]), (v.coupler, a.rocker));
    }
    assert_ne!(c.status[n - 1], 0);
    assert_eq!(c.pos_A_x[n - 1], 0.0);
}
