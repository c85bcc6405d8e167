//! The batch API's length check and its owned form (feature `alloc`), by
//! subject:
//!
//! 1. lengths: a slice of another length than the first input slice, of
//!    each kind (input, rate, acceleration input, output, status), is a
//!    `BatchError` naming it, its length and the expected one, returned
//!    before anything is written; a short first input names the next slice;
//! 2. owned form: `FourBar::batch(n)` gives `n` zeroed elements,
//!    `solve_columns` writes bit for bit what `solve_batch` writes into
//!    borrowed slices, and every element agrees with the scalar `solve`
//!    (status exactly; values bit for bit where the element failed, within
//!    the kernel's bound where it did not) over a sweep with failures at
//!    each level;
//! 3. `par_solve` (feature `rayon`): mismatched lengths are an error before
//!    any piece is evaluated;
//! 4. `Debug` of both batch types shows the fields and values;
//! 5. without the feature `alloc` (`cargo test --no-default-features --test
//!    batch_owned`, run by `.ci/run`) the owned form does not exist: the
//!    module `without_alloc` declares `FourBar::batch` and
//!    `FourBar::solve_columns` itself, which compiles only when the macro
//!    emitted neither; the borrowed form still checks lengths.

use mechanism::mechanism;

mechanism! {
    // Seed 002's crank-rocker (inches as mm): every crank angle assembles,
    // with a transmission condition above 0.3 (docs/performance.md).
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
    }
}

#[cfg(feature = "alloc")]
mod lengths {
    use super::*;

    /// `n` elements of a valid sweep, outputs at 7.0 and status at 9 (so a
    /// write shows up).
    fn sweep(n: usize) -> FourBarColumns {
        let mut c = FourBar::<f64>::batch(n);
        c.in_theta2 = (0..n).map(|k| k as f64 * 0.1).collect();
        c.rate_theta2 = vec![250.0; n];
        for v in [&mut c.pos_B_x, &mut c.vel_link4, &mut c.acc_A_y] {
            v.iter_mut().for_each(|x| *x = 7.0);
        }
        c.status = vec![9; n];
        c
    }

    /// Shortens one column per kind of slice by one element: the error
    /// names that column, and the batch is untouched.
    #[test]
    fn a_short_slice_of_each_kind_is_named() {
        type Cut = fn(&mut FourBarColumns);
        let cases: [(&str, Cut); 6] = [
            ("rate_theta2", |c| c.rate_theta2.truncate(7)),
            ("accel_theta2", |c| c.accel_theta2.truncate(7)),
            ("pos_B_x", |c| c.pos_B_x.truncate(7)),
            ("vel_link4", |c| c.vel_link4.truncate(7)),
            ("acc_A_y", |c| c.acc_A_y.truncate(7)),
            ("status", |c| c.status.truncate(7)),
        ];
        let m = FourBar::<f64>::default();
        for (name, cut) in cases {
            let mut c = sweep(8);
            cut(&mut c);
            let before = c.clone();
            let e = m.solve_columns(&mut c).unwrap_err();
            assert_eq!(
                (e.slice, e.len, e.reference, e.expected),
                (name, 7, "in_theta2", 8)
            );
            assert_eq!(c, before, "{name}: nothing written");
            // The borrowed form and BatchSplit say the same.
            assert_eq!(m.solve_batch(&mut c.as_batch()), Err(e));
            assert_eq!(mechanism::BatchSplit::check(&c.as_batch()), Err(e));
        }
    }

    /// The first input slice sets the length: when it is the short one, the
    /// first other slice is named, with the longer length.
    #[test]
    fn a_short_first_input_names_the_next_slice() {
        let mut c = sweep(8);
        c.in_theta2.truncate(5);
        let e = FourBar::<f64>::default().solve_columns(&mut c).unwrap_err();
        assert_eq!(
            (e.slice, e.len, e.reference, e.expected),
            ("rate_theta2", 8, "in_theta2", 5)
        );
        assert_eq!(
            e.to_string(),
            "batch slice `rate_theta2` has 8 elements but `in_theta2` has 5: every slice of a batch needs the same length"
        );
        assert!(c.status.iter().all(|s| *s == 9));
    }

    /// Equal lengths pass: `check` gives the length, an empty batch is fine.
    #[test]
    fn equal_lengths_pass() {
        let m = FourBar::<f64>::default();
        assert_eq!(sweep(8).as_batch().check(), Ok(8));
        assert_eq!(m.solve_columns(&mut sweep(8)), Ok(0));
        let mut empty = FourBar::<f64>::batch(0);
        assert!(empty.is_empty() && empty.as_batch().is_empty());
        assert_eq!(m.solve_columns(&mut empty), Ok(0));
    }
}

#[cfg(feature = "alloc")]
mod owned {
    use super::*;

    /// 2000 crank angles over several turns, with failures at each level:
    /// a NaN angle every 97th element (position fails), a NaN rate every
    /// 89th (velocity), a NaN angular acceleration every 83rd
    /// (acceleration); an angle beyond the kernel's 1e5 rad range every
    /// 101st (the scalar path evaluates it).
    fn inputs(n: usize) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let q = (0..n)
            .map(|k| match k {
                _ if k % 97 == 5 => f64::NAN,
                _ if k % 101 == 3 => 2.5e5 + k as f64,
                _ => k as f64 * 0.0123 - 7.0,
            })
            .collect();
        let w = (0..n)
            .map(|k| {
                if k % 89 == 7 {
                    f64::NAN
                } else {
                    250.0 - k as f64 * 0.1
                }
            })
            .collect();
        let a = (0..n)
            .map(|k| {
                if k % 83 == 11 {
                    f64::NAN
                } else {
                    k as f64 * 0.5 - 300.0
                }
            })
            .collect();
        (q, w, a)
    }

    #[test]
    fn batch_gives_zeroed_columns() {
        let c = FourBar::<f64>::batch(3);
        assert_eq!(c.len(), 3);
        assert_eq!(c.in_theta2, [0.0; 3]);
        assert_eq!(c.acc_link4, [0.0; 3]);
        assert_eq!(c.status, [0; 3]);
        assert_eq!(c, FourBarColumns::<f64>::zeros(3));
    }

    /// The owned columns against hand-made slices (bit for bit: the same
    /// code on the same values) and against the scalar `solve`.
    #[test]
    fn owned_sweep_matches_borrowed_slices_and_the_scalar_path() {
        let n = 2000;
        let m = FourBar::<f64>::default();
        let (q, w, a) = inputs(n);
        let mut c = FourBar::<f64>::batch(n);
        (c.in_theta2, c.rate_theta2, c.accel_theta2) = (q.clone(), w.clone(), a.clone());
        let failed = m.solve_columns(&mut c).unwrap();

        let mut out = vec![vec![f64::NAN; n]; 18];
        let mut status = vec![9u8; n];
        let mut o = out.iter_mut().map(|v| v.as_mut_slice());
        let mut nx = || o.next().unwrap();
        let mut b = FourBarBatch {
            in_theta2: &q,
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
        assert_eq!(m.solve_batch(&mut b), Ok(failed));
        let owned = [
            &c.pos_A_x,
            &c.pos_A_y,
            &c.pos_B_x,
            &c.pos_B_y,
            &c.pos_link3,
            &c.pos_link4,
            &c.vel_A_x,
            &c.vel_A_y,
            &c.vel_B_x,
            &c.vel_B_y,
            &c.vel_link3,
            &c.vel_link4,
            &c.acc_A_x,
            &c.acc_A_y,
            &c.acc_B_x,
            &c.acc_B_y,
            &c.acc_link3,
            &c.acc_link4,
        ];
        for (col, (mine, theirs)) in owned.iter().zip(&out).enumerate() {
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(mine), bits(theirs), "column {col}");
        }
        assert_eq!(c.status, status);

        let mut levels = [0usize; 4];
        for k in 0..n {
            let i = |x: f64| FourBarInput { theta2: x };
            let scalar = m.solve(&i(q[k]), &i(w[k]), &i(a[k]));
            // The level that failed, from the scalar functions one by one.
            let p = m.position(&i(q[k]));
            let v = p.as_ref().ok().map(|p| m.velocity(p, &i(w[k])));
            let want = match (&p, &v, &scalar) {
                (Err(_), _, _) => 1,
                (_, Some(Err(_)), _) => 2,
                (_, _, Err(_)) => 3,
                _ => 0,
            };
            assert_eq!(c.status[k], want, "element {k}");
            levels[want as usize] += 1;
            let row: Vec<f64> = owned.iter().map(|col| col[k]).collect();
            match (want, &scalar) {
                (0, Ok(s)) => {
                    let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
                    let exact = [
                        p.A.x, p.A.y, p.B.x, p.B.y, p.link3, p.link4, v.A.x, v.A.y, v.B.x, v.B.y,
                        v.link3, v.link4, a.A.x, a.A.y, a.B.x, a.B.y, a.link3, a.link4,
                    ];
                    // The kernel's bound (docs/performance.md): 64 eps of the
                    // level's magnitude over the condition squared, the
                    // condition above 0.3 on this crank-rocker; magnitudes
                    // 305 mm, 250 rad/s times it, 250^2 + 700 rad/s^2 times it.
                    for (j, (got, exp)) in row.iter().zip(exact).enumerate() {
                        let scale = [305.0, 305.0 * 250.0, 305.0 * 63_200.0][j / 6];
                        let bound = 64.0 * f64::EPSILON * scale / 0.09;
                        assert!(
                            (got - exp).abs() <= bound,
                            "element {k} column {j}: {got} {exp}"
                        );
                    }
                }
                (level, _) => {
                    // Failed at `level`: the levels before it come from the
                    // scalar path (bit for bit), the others are zero.
                    let p = p.as_ref().ok();
                    let before: Vec<f64> = match (level, p, &v) {
                        (1, _, _) => vec![],
                        (2, Some(p), _) => vec![p.A.x, p.A.y, p.B.x, p.B.y, p.link3, p.link4],
                        (3, Some(p), Some(Ok(v))) => vec![
                            p.A.x, p.A.y, p.B.x, p.B.y, p.link3, p.link4, v.A.x, v.A.y, v.B.x,
                            v.B.y, v.link3, v.link4,
                        ],
                        _ => unreachable!("level {level} at element {k}"),
                    };
                    let mut exp = before;
                    exp.resize(18, 0.0);
                    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
                    assert_eq!(bits(&row), bits(&exp), "element {k}");
                }
            }
        }
        assert_eq!(failed, n - levels[0]);
        assert!(
            levels.iter().all(|l| *l > 0),
            "every status occurs: {levels:?}"
        );
    }
}

#[cfg(all(feature = "alloc", feature = "rayon"))]
mod par_solve {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// A 10^4-element batch with one short output column: `par_solve`
    /// returns the error without calling the solve function on any piece.
    #[test]
    fn mismatched_lengths_fail_before_any_piece() {
        let m = FourBar::<f64>::default();
        let mut c = FourBar::<f64>::batch(10_000);
        c.status.fill(9);
        c.vel_B_y.pop();
        let calls = AtomicUsize::new(0);
        let r = mechanism::par_solve(c.as_batch(), 512, &|mut b| {
            calls.fetch_add(1, Ordering::Relaxed);
            m.solve_batch(&mut b)
        });
        let e = r.unwrap_err();
        assert_eq!((e.slice, e.len, e.expected), ("vel_B_y", 9_999, 10_000));
        assert_eq!(calls.load(Ordering::Relaxed), 0);
        assert!(c.status.iter().all(|s| *s == 9));
        // Equal lengths: every piece runs. The documented split: the timed
        // probe on the calling thread, then the rest whole or in at most
        // `PAR_PIECES_PER_THREAD` pieces per pool thread, each of at least
        // `min_len` (512) elements (which depends on the time the probe took).
        let rest = 10_000 - mechanism::PAR_PROBE;
        let most =
            1 + (rest / 512).min(mechanism::PAR_PIECES_PER_THREAD * rayon::current_num_threads());
        c.vel_B_y.push(0.0);
        let r = mechanism::par_solve(c.as_batch(), 512, &|mut b| {
            calls.fetch_add(1, Ordering::Relaxed);
            m.solve_batch(&mut b)
        });
        assert_eq!(r, Ok(0));
        let calls = calls.load(Ordering::Relaxed);
        assert!((1..=most).contains(&calls), "{calls} calls");
        assert!(c.status.iter().all(|s| *s == 0));
    }
}

#[cfg(feature = "alloc")]
mod debug {
    use super::*;

    #[test]
    fn both_batch_types_show_their_fields() {
        let mut c = FourBar::<f64>::batch(2);
        c.in_theta2 = vec![0.5, 1.5];
        let owned = format!("{c:?}");
        assert!(
            owned.starts_with("FourBarColumns { in_theta2: [0.5, 1.5], rate_theta2: [0.0, 0.0],"),
            "{owned}"
        );
        assert!(
            owned.ends_with("acc_link4: [0.0, 0.0], status: [0, 0] }"),
            "{owned}"
        );
        let borrowed = format!("{:?}", c.as_batch());
        assert!(
            borrowed.starts_with("FourBarBatch { in_theta2: [0.5, 1.5],"),
            "{borrowed}"
        );
        assert!(borrowed.contains(", pos_B_x: [0.0, 0.0],"), "{borrowed}");
        assert!(borrowed.ends_with("status: [0, 0] }"), "{borrowed}");
    }
}

#[cfg(not(feature = "alloc"))]
mod without_alloc {
    use super::*;

    // Compiles only without the owned form: with it, `batch` and
    // `solve_columns` would be defined twice (E0592, checked by hand with
    // this module's `cfg` removed).
    #[allow(dead_code)]
    impl<T: mechanism::Real> FourBar<T> {
        fn batch() {}
        fn solve_columns() {}
    }

    /// The borrowed form and its length check need no allocation.
    #[test]
    fn borrowed_batch_checks_lengths() {
        let q = [0.0, 1.0, 2.0];
        let w = [1.0; 3];
        let mut out = [[0.0; 3]; 18];
        let mut status = [9u8; 2];
        let mut o = out.iter_mut().map(|v| v.as_mut_slice());
        let mut nx = || o.next().unwrap();
        let mut b = FourBarBatch {
            in_theta2: &q,
            rate_theta2: &w,
            accel_theta2: &w,
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
        let e = FourBar::<f64>::default().solve_batch(&mut b).unwrap_err();
        assert_eq!((e.slice, e.len, e.expected), ("status", 2, 3));
        assert_eq!(status, [9, 9]);
    }
}
