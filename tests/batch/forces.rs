//! The batch form of the force analysis (`solve_batch_forces`, through the
//! owned columns' `solve_columns`) against the scalar path, element by
//! element, on the definitions with masses of the batch scenes: the press
//! with masses, gravity and two run-time loads (`LoadedPress`), the shaper
//! with its cutting load (`ShaperForces`) and the sine mechanism (no loads
//! block), in f64 and f32, over the grids of the kinematic comparison
//! (poses that cannot assemble, non-finite and out-of-range angles,
//! non-finite rates) with loads that change per element and one NaN load.
//!
//! Checked for every element:
//!
//! 1. the status is the scalar path's: 1, 2, 3 for the kinematic level that
//!    failed, 4 where `forces` fails (the NaN load), 0 otherwise;
//! 2. where it is 0, the element's forces (`forces_at(k)`, rebuilt from the
//!    columns) are the scalar `forces`' bit for bit (compared by their
//!    `Debug` text, which tells `-0.0` from `0.0`): the batch calls the same
//!    `position`, `velocity`, `acceleration` and `forces` as `solve`, in the
//!    same order, so no tolerance is needed, and a column written from the
//!    wrong field or element differs;
//! 3. where it is not 0, every force column is zero.
//!
//! With the feature `rayon`, `mechanism::par_solve` over the forces batch
//! writes the serial result bit for bit.

use crate::batch_compare::{angles, rates};
use crate::surface_defs::LoadedPress;
use mechanism::mechanism;

use crate::examples::scenes::{
    ShaperForces, ShaperForcesInput, ShaperForcesLoads, SineMechanism, SineMechanismInput,
};
use crate::surface_defs::{LoadedPressInput, LoadedPressLoads};

/// Every number in a `Debug` text is zero (and there is at least one).
fn all_zero(text: &str) -> bool {
    let numbers: Vec<f64> = text
        .split(|c: char| " ,:[]{}()".contains(c))
        .filter_map(|t| t.parse::<f64>().ok())
        .collect();
    !numbers.is_empty() && numbers.iter().all(|x| *x == 0.0)
}

/// Runs the forces batch of one-input definition `$ty` (precision `$t`,
/// input `$i`) over `q`, `w`, `a` (one value per element) with the
/// run-time loads `$l` (one value per element each), checks points 1 to 3,
/// and returns the counts of elements per status.
macro_rules! forces_case {
    ($m:expr, $t:ty, $ty:ident, $i:ident, $q:expr, $w:expr, $a:expr $(, loads { $($l:ident = $lv:expr),* })?) => {{
        paste::paste! {
            let m: $ty<$t> = $m;
            let (q, w, a): (&[f64], &[f64], &[f64]) = (&$q, &$w, &$a);
            let n = q.len();
            let cast = |v: &[f64]| -> Vec<$t> { v.iter().map(|x| *x as $t).collect() };
            let mut c = $ty::<$t>::batch(n);
            c.[<in_ $i>] = cast(q);
            c.[<rate_ $i>] = cast(w);
            c.[<accel_ $i>] = cast(a);
            $($(
                let $l: Vec<$t> = cast(&$lv);
                c.[<load_ $l>] = $l.clone();
            )*)?
            let failed = m.solve_columns(&mut c).expect("columns of one length");
            let mut counts = [0usize; 5];
            for k in 0..n {
                let at = |v: &[f64]| [<$ty Input>] { $i: v[k] as $t };
                let (code, want) = match m.position(&at(q)) {
                    Err(_) => (1u8, None),
                    Ok(p) => match m.velocity(&p, &at(w)) {
                        Err(_) => (2, None),
                        Ok(v) => match m.acceleration(&p, &v, &at(a)) {
                            Err(_) => (3, None),
                            Ok(ac) => match m.forces(&p, &v, &ac $(, &[<$ty Loads>] { $($l: $l[k]),* })?) {
                                Err(_) => (4, None),
                                Ok(f) => (0, Some(f)),
                            },
                        },
                    },
                };
                let what = concat!(stringify!($ty), " ", stringify!($t));
                assert_eq!(c.status[k], code, "{what} element {k}");
                counts[code as usize] += 1;
                // 2: bit for bit where ok.
                assert_eq!(format!("{:?}", c.forces_at(k)), format!("{:?}", want), "{what} element {k}");
                if code != 0 {
                    // 3: the columns of a failed element are zero (read
                    // through `forces_at` with the status set to 0).
                    let mut d = c.clone();
                    d.status[k] = 0;
                    let text = format!("{:?}", d.forces_at(k).expect("status 0"));
                    assert!(all_zero(&text), "{what} element {k}: {text}");
                }
            }
            assert_eq!(failed, n - counts[0]);
            println!("{} {}: statuses 0..4 {:?}", stringify!($ty), stringify!($t), counts);
            (counts, c)
        }
    }};
}

/// The grid of `tests/batch`: a turn and a half with failing inputs, an
/// infinite rate at element 100 and a NaN acceleration at 200.
fn grid() -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let q = angles(2000);
    let n = q.len();
    (q, rates(n, 3.0, Some(100)), rates(n, -2.0, Some(200)))
}

/// A load per element: `scale * sin(k / 7)`, NaN at element `bad`.
fn load(n: usize, scale: f64, bad: Option<usize>) -> Vec<f64> {
    let mut v: Vec<f64> = (0..n).map(|k| scale * (k as f64 / 7.0).sin()).collect();
    if let Some(b) = bad {
        v[b] = f64::NAN;
    }
    v
}

/// Every status appears where the grid puts it: the kinematic failures of
/// the grid (non-finite angles, the rate at 100, the acceleration at 200)
/// and the force failure at the NaN load (element 300).
fn every_status(counts: [usize; 5], what: &str) {
    assert!(counts[0] > 1500, "{what}: {counts:?}");
    for (s, c) in counts.iter().enumerate().skip(1) {
        assert!(*c >= 1, "{what}: no status {s}: {counts:?}");
    }
}

#[test]
fn loaded_press() {
    let (q, w, a) = grid();
    let n = q.len();
    let (press, t) = (load(n, 800.0, Some(300)), load(n, 5.0, None));
    let (c64, _) = forces_case!(LoadedPress { crank: 0.12, g: 3.0, ..Default::default() }, f64, LoadedPress, theta, q, w, a, loads { press = press, t = t });
    every_status(c64, "LoadedPress f64");
    let (c32, _) = forces_case!(LoadedPress { crank: 0.12, g: 3.0, ..Default::default() }, f32, LoadedPress, theta, q, w, a, loads { press = press, t = t });
    every_status(c32, "LoadedPress f32");
}

#[test]
fn shaper_forces() {
    let (q, w, a) = grid();
    let n = q.len();
    let cut = load(n, 2000.0, Some(300));
    let (c64, _) = forces_case!(ShaperForces::default(), f64, ShaperForces, crank, q, w, a, loads { cut = cut });
    every_status(c64, "ShaperForces f64");
    let (c32, _) = forces_case!(ShaperForces::default(), f32, ShaperForces, crank, q, w, a, loads { cut = cut });
    every_status(c32, "ShaperForces f32");
}

/// No loads block: no `load_*` column, the statuses 0 to 3 only.
#[test]
fn sine_mechanism() {
    let (q, w, a) = grid();
    for (counts, t) in [
        forces_case!(SineMechanism::default(), f64, SineMechanism, phi1, q, w, a).0,
        forces_case!(SineMechanism::default(), f32, SineMechanism, phi1, q, w, a).0,
    ]
    .into_iter()
    .zip(["f64", "f32"])
    {
        assert!(
            counts[0] > 1500 && counts[1..4].iter().all(|c| *c >= 1),
            "{t}: {counts:?}"
        );
        assert_eq!(counts[4], 0, "{t}");
    }
}

mechanism! {
    /// A press whose one run-time load has a default other than zero (N):
    /// `batch(n)` must start the load column at it.
    pub DefaultLoads {
        loads { push = 250.0 }
        let O = ground(0.0, 0.0);
        let line = guide((0.0, -0.02), 0 deg);
        let A = crank(O, 0.1, theta) as link2;
        let B = rrp(A, 0.4, line, plus) as (link3, ram) slide x;
        mass ram { m = 5.0, at = B };
        force at B on ram along line = push;
    }
}

/// `batch(n)` fills the load columns with the definition's values (not
/// zero), so a caller who does not set them gets the scalar default; and
/// the batch's kinematic columns of the forces path are the scalar `solve`'s
/// bit for bit (the same calls).
#[test]
fn load_columns_start_at_the_definitions_values() {
    let n = 64;
    let m = DefaultLoads::<f64>::default();
    let mut c = DefaultLoads::<f64>::batch(n);
    assert!(c.load_push.iter().all(|x| *x == 250.0));
    c.in_theta = (0..n).map(|k| k as f64 * 0.1).collect();
    c.rate_theta = vec![10.0; n];
    assert_eq!(m.solve_columns(&mut c), Ok(0));
    for k in 0..n {
        let i = |x: f64| DefaultLoadsInput { theta: x };
        let s = m
            .solve(
                &i(c.in_theta[k]),
                &i(10.0),
                &i(0.0),
                &DefaultLoadsLoads::default(),
            )
            .expect("assembles");
        assert_eq!(
            format!("{:?}", c.forces_at(k)),
            format!("{:?}", Some(s.forces))
        );
        assert_eq!(c.pos_B_x[k].to_bits(), s.position.B.x.to_bits());
        assert_eq!(c.acc_link3[k].to_bits(), s.acceleration.link3.to_bits());
    }
    // A column of another length: the error names it, nothing written.
    c.load_push.pop();
    let before = c.clone();
    let e = m.solve_columns(&mut c).unwrap_err();
    assert!(format!("{e}").contains("load_push"), "{e}");
    assert_eq!(c, before);
}

/// `mechanism::par_solve` over the forces batch (split at the same index
/// in every column, the kinematic batch's included) writes what the serial
/// loop writes, bit for bit.
#[cfg(feature = "rayon")]
#[test]
fn par_solve_over_the_forces_batch() {
    let n = 20_000;
    let m = LoadedPress::<f64>::default();
    let mut serial = LoadedPress::<f64>::batch(n);
    serial.in_theta = (0..n).map(|k| k as f64 * 1e-3).collect();
    serial.rate_theta = vec![12.0; n];
    serial.load_press = load(n, 500.0, Some(7000));
    let mut par = serial.clone();
    let f1 = m.solve_columns(&mut serial).unwrap();
    let f2 = mechanism::par_solve(par.as_forces_batch(), 0, &|mut b| {
        m.solve_batch_forces(&mut b)
    })
    .unwrap();
    assert_eq!(f1, 1);
    assert_eq!(f2, f1);
    assert_eq!(format!("{serial:?}"), format!("{par:?}"));
}
