//! `linsolve::solve` (row equilibration + partial pivoting) against nalgebra's
//! LU, on structured failure cases of naive elimination, and on garbage input.
//!
//! Tolerances, and why:
//!
//! - against nalgebra (partial-pivoting LU, f64): both methods are backward
//!   stable, so each computed `x` has `|x - x*|_inf / |x*|_inf <~ c N eps
//!   kappa_inf(A)` with a small constant `c` (Higham, *Accuracy and Stability of
//!   Numerical Algorithms*, 2nd ed., Thm 9.5 with a growth factor ~1 for random
//!   matrices, and Thm 7.2; row equilibration changes `kappa_inf` by at most a
//!   factor `N`, van der Sluis 1969). Their difference is therefore allowed
//!   `8 N^2 eps kappa_inf(A)` relative (`kappa_inf` computed by nalgebra from
//!   the inverse). Systems with `kappa_inf > 1e12` are skipped (nothing is left
//!   to compare at that point) after checking that `solve` does not panic.
//! - row-wise backward error of `solve`: for every row
//!   `|(A x - b)_i| <= 8 N eps (sum_j |a_ij| |x_j| + |b_i|)`. Scaled pivoting is
//!   row-wise backward stable for these sizes; the residual is evaluated in f64
//!   itself (its own rounding is `~N eps` of the same sum), hence `8 N`.
//!   Independent of the conditioning, so it is a tight test even for badly
//!   scaled rows.

use mechanism_core::linsolve::{solve, Solution, PIVOT_TOLERANCE};
use mechanism_core::{Error, Fault, Primitive};
use mechanism_reference::naive::{solve_unpivoted_unscaled, NaiveError};
use nalgebra::{DMatrix, DVector};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

fn to_system<const N: usize>(v: &[f64]) -> ([[f64; N]; N], [f64; N]) {
    let a = core::array::from_fn(|i| core::array::from_fn(|j| v[i * N + j]));
    let b = core::array::from_fn(|i| v[N * N + i]);
    (a, b)
}

fn inf_norm(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |m: f64, x| m.max(x.abs()))
}

/// nalgebra's LU solution and `kappa_inf(A)`.
fn reference<const N: usize>(a: &[[f64; N]; N], b: &[f64; N]) -> Option<(Vec<f64>, f64)> {
    let m = DMatrix::from_fn(N, N, |i, j| a[i][j]);
    let rhs = DVector::from_column_slice(b);
    let x = m.clone().lu().solve(&rhs)?;
    let inv = m.clone().try_inverse()?;
    let norm = |m: &DMatrix<f64>| {
        (0..N)
            .map(|i| (0..N).map(|j| m[(i, j)].abs()).sum::<f64>())
            .fold(0.0, f64::max)
    };
    Some((x.iter().copied().collect(), norm(&m) * norm(&inv)))
}

fn check_against_nalgebra<const N: usize>(
    a: [[f64; N]; N],
    b: [f64; N],
) -> Result<(), TestCaseError> {
    let ours = solve(a, b);
    let Some((x_ref, kappa)) = reference(&a, &b) else {
        return Ok(());
    };
    prop_assume!(kappa.is_finite() && kappa < 1e12);
    let Solution { x, min_pivot_ratio } =
        ours.map_err(|e| TestCaseError::fail(format!("{e} at kappa {kappa:e}")))?;
    let diff: Vec<f64> = x.iter().zip(&x_ref).map(|(p, q)| p - q).collect();
    let rel = inf_norm(&diff) / inf_norm(&x_ref).max(f64::MIN_POSITIVE);
    let tol = 8.0 * (N * N) as f64 * f64::EPSILON * kappa;
    prop_assert!(
        rel <= tol,
        "N={N} rel {rel:e} > tol {tol:e} (kappa {kappa:e})"
    );
    // The indicator is a lower bound of the condition of the equilibrated
    // matrix, which is at most N kappa_inf(A) (van der Sluis).
    prop_assert!(
        1.0 / min_pivot_ratio <= N as f64 * kappa * (1.0 + 1e-9),
        "1/min_pivot_ratio {:e} > N kappa {:e}",
        1.0 / min_pivot_ratio,
        N as f64 * kappa
    );
    check_backward_error(&a, &b, &x)
}

fn check_backward_error<const N: usize>(
    a: &[[f64; N]; N],
    b: &[f64; N],
    x: &[f64; N],
) -> Result<(), TestCaseError> {
    for (row, bi) in a.iter().zip(b) {
        let r: f64 = row.iter().zip(x).map(|(aij, xj)| aij * xj).sum::<f64>() - bi;
        let scale: f64 = row
            .iter()
            .zip(x)
            .map(|(aij, xj)| (aij * xj).abs())
            .sum::<f64>()
            + bi.abs();
        let tol = 8.0 * N as f64 * f64::EPSILON * scale;
        prop_assert!(r.abs() <= tol, "row residual {:e} > {tol:e}", r.abs());
    }
    Ok(())
}

/// Random entries in [-1, 1], each row then multiplied by 10^k, k in [-6, 6].
fn system(n: usize) -> impl Strategy<Value = (Vec<f64>, Vec<i32>)> {
    (
        prop::collection::vec(-1.0f64..1.0, n * n + n),
        prop::collection::vec(-6i32..=6, n),
    )
}

fn row_scaled<const N: usize>(v: &[f64], k: &[i32]) -> ([[f64; N]; N], [f64; N]) {
    let (mut a, mut b) = to_system::<N>(v);
    for ((row, bi), k) in a.iter_mut().zip(b.iter_mut()).zip(k) {
        let s = 10f64.powi(*k);
        row.iter_mut().for_each(|v| *v *= s);
        *bi *= s;
    }
    (a, b)
}

macro_rules! agreement {
    ($($name:ident, $scaled:ident: $n:literal;)*) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(256))]
            $(
                #[test]
                fn $name(v in prop::collection::vec(-1.0f64..1.0, $n * $n + $n)) {
                    let (a, b) = to_system::<$n>(&v);
                    check_against_nalgebra(a, b)?;
                }

                #[test]
                fn $scaled((v, k) in system($n)) {
                    let (a, b) = row_scaled::<$n>(&v, &k);
                    check_against_nalgebra(a, b)?;
                }
            )*
        }
    };
}

agreement! {
    agrees_with_nalgebra_3, agrees_with_nalgebra_row_scaled_3: 3;
    agrees_with_nalgebra_4, agrees_with_nalgebra_row_scaled_4: 4;
    agrees_with_nalgebra_5, agrees_with_nalgebra_row_scaled_5: 5;
    agrees_with_nalgebra_6, agrees_with_nalgebra_row_scaled_6: 6;
    agrees_with_nalgebra_7, agrees_with_nalgebra_row_scaled_7: 7;
    agrees_with_nalgebra_8, agrees_with_nalgebra_row_scaled_8: 8;
}

#[test]
fn zero_leading_pivot_is_solved() {
    // x = (1, 2, 3); a_00 = 0, so naive elimination cannot start.
    let a: [[f64; 3]; 3] = [[0.0, 2.0, 1.0], [1.0, 0.0, 3.0], [4.0, 5.0, 0.0]];
    let b = [7.0, 10.0, 14.0];
    let s = solve(a, b).unwrap();
    for (x, e) in s.x.iter().zip([1.0, 2.0, 3.0]) {
        assert!((x - e).abs() <= 4.0 * f64::EPSILON * 3.0, "{:?}", s.x);
    }
    assert!(s.min_pivot_ratio > 0.3, "{}", s.min_pivot_ratio);
    assert_eq!(
        solve_unpivoted_unscaled(a, b),
        Err(NaiveError::ZeroPivot { step: 0 })
    );
}

fn expect_singular<const N: usize>(a: [[f64; N]; N], b: [f64; N]) -> (f64, f64) {
    match solve(a, b) {
        Err(Error {
            primitive: Primitive::LinearSystem,
            fault: Fault::Singular { det, scale },
            ..
        }) => (det, scale),
        other => panic!("expected Singular, got {other:?}"),
    }
}

#[test]
fn rank_deficient_is_singular() {
    // Row 3 = 2 row 2 - row 1: rank 2. After equilibration the rows are
    // (1/3, 2/3, 1), (2/3, 5/6, 1), (7/9, 8/9, 1); the last pivot is rounding
    // noise, below 3 eps.
    let (det, scale) = expect_singular(
        [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0], [7.0, 8.0, 9.0]],
        [1.0, 2.0, 3.0],
    );
    // The failing pivot sits in the row (4, 5, 6) after the swaps.
    assert!(scale == 6.0 || scale == 9.0, "{scale}");
    assert!(
        (det / scale).abs() <= PIVOT_TOLERANCE * 3.0 * f64::EPSILON,
        "{det:e}"
    );

    // A 6x6 of rank 5 with rows of very different scales, as a group system:
    // the last row is a combination of the others.
    let mut a = [
        [1.0, 0.0, 0.0, 0.0, -1.0, 0.0],
        [0.0, 1.0, 0.0, 0.0, 0.0, -1.0],
        [-0.4, 0.3, 0.0, 0.0, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0, 0.0, 1.0],
        [0.0; 6],
    ];
    a[5] = core::array::from_fn(|j| 1e3 * (0.25 * a[0][j] - 3.0 * a[2][j] + 0.5 * a[4][j]));
    expect_singular(a, [1.0; 6]);

    // A zero row.
    let (det, scale) = expect_singular([[1.0, 2.0], [0.0, 0.0]], [1.0, 1.0]);
    assert_eq!((det, scale), (0.0, 0.0));
}

/// Partial pivoting without row scaling: a local reference, to show that the
/// scaling matters too (not only the pivoting). Written in textbook index form.
#[allow(clippy::needless_range_loop)]
fn solve_pivoted_unscaled<const N: usize>(mut a: [[f64; N]; N], mut b: [f64; N]) -> [f64; N] {
    for k in 0..N {
        let p = (k..N)
            .max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs()).then(j.cmp(&i)))
            .unwrap();
        a.swap(k, p);
        b.swap(k, p);
        for i in k + 1..N {
            let m = a[i][k] / a[k][k];
            for j in k..N {
                a[i][j] -= m * a[k][j];
            }
            b[i] -= m * b[k];
        }
    }
    let mut x = [0.0; N];
    for k in (0..N).rev() {
        let s: f64 = (k + 1..N).map(|j| a[k][j] * x[j]).sum();
        x[k] = (b[k] - s) / a[k][k];
    }
    x
}

#[test]
fn badly_scaled_force_moment_mix() {
    // Unknowns (F1, F2, M): row 0 is a moment balance whose lever arms are
    // 1e12 times the force rows' coefficients (think a 1e12 N m couple row
    // against rows in N), and in which F1 has a lever arm 1e-12 of the others:
    // its entry 3 is larger than any in the force rows, but tiny within its own
    // row. True solution (1, 2, 3); `b = A x` rounded, so the exact solution of
    // the stored system is (1, 2 + 4e-16, 3) (checked with rational arithmetic).
    let a = [[3.0, 0.7e12, 1.3e12], [1.1, 0.9, 0.3], [0.6, 0.2, 1.7]];
    let truth = [1.0, 2.0, 3.0];
    let b: [f64; 3] = core::array::from_fn(|i| (0..3).map(|j| a[i][j] * truth[j]).sum());
    let err = |x: &[f64; 3]| {
        x.iter()
            .zip(truth)
            .map(|(x, e)| (x - e).abs())
            .fold(0.0, f64::max)
    };

    // Scaled pivoting sees row 0 as (3e-12, 0.54, 1) and takes a force row
    // first. Measured error 2.7e-15 (the equilibrated matrix is well
    // conditioned).
    let s = solve(a, b).unwrap();
    assert!(err(&s.x) <= 1e-14, "solve error {:e}", err(&s.x));
    assert!(s.min_pivot_ratio > 0.1, "{}", s.min_pivot_ratio);

    // Naive elimination pivots on the 3 (1e-12 of its row) and subtracts
    // multiples of 1e12-sized entries from the force rows, whose own entries
    // then survive only in the last ~4 digits. Measured error 2.73e-5:
    // x = (1.0, 2.0000272920607403, 2.999985304274986).
    let naive = solve_unpivoted_unscaled(a, b).unwrap();
    let naive_err = err(&naive);
    assert!(naive_err > 1e-6, "naive error {naive_err:e}");
    // Partial pivoting without scaling also takes row 0 (3 > 1.1 > 0.6):
    // the same failure, the same 2.73e-5. The scaling is what fixes it.
    let pivoted = solve_pivoted_unscaled(a, b);
    assert!(
        err(&pivoted) > 1e-6,
        "pivoted-unscaled error {:e}",
        err(&pivoted)
    );
    println!(
        "solve error {:e}, naive error {naive_err:e}, pivoted-unscaled error {:e}",
        err(&s.x),
        err(&pivoted)
    );
}

#[test]
fn nan_and_infinity_are_non_finite() {
    let nonfinite = |what| {
        Err(Error::new(
            Primitive::LinearSystem,
            Fault::NonFinite { what },
        ))
    };
    let mut a = [[1.0, 2.0], [3.0, 4.0]];
    a[1][0] = f64::NAN;
    assert_eq!(
        solve(a, [1.0, 1.0]).map(|s| s.x),
        nonfinite("linear system input")
    );
    assert_eq!(
        solve([[1.0, 0.0], [0.0, 1.0]], [f64::INFINITY, 0.0]).map(|s| s.x),
        nonfinite("linear system input")
    );
    assert_eq!(
        solve_unpivoted_unscaled(a, [1.0, 1.0]),
        Err(NaiveError::NonFiniteInput)
    );
    // Overflow of the solution: x = 1e300 / 1e-300.
    assert_eq!(
        solve([[1e-300, 0.0], [0.0, 1.0]], [1e300, 0.0]).map(|s| s.x),
        nonfinite("linear system solution")
    );
}

#[test]
fn works_in_f32() {
    let a = [[0.0f32, 2.0, 1.0], [1.0, 0.0, 3.0], [4.0, 5.0, 0.0]];
    let s = solve(a, [7.0, 10.0, 14.0]).unwrap();
    for (x, e) in s.x.iter().zip([1.0f32, 2.0, 3.0]) {
        assert!((x - e).abs() <= 8.0 * f32::EPSILON * 3.0, "{:?}", s.x);
    }
}

fn garbage() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(0.0),
        Just(-0.0),
        Just(f64::MAX),
        Just(f64::MIN_POSITIVE),
        Just(5e-324),
        any::<f64>(),
        -1e3f64..1e3,
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Never panics; an `Ok` never holds NaN or infinity; a NaN or infinity in
    /// the input is always `NonFinite`.
    #[test]
    fn garbage_never_panics(v in prop::collection::vec(garbage(), 6 * 6 + 6)) {
        let (a, b) = to_system::<6>(&v);
        let bad_input = v.iter().any(|x| !x.is_finite());
        match solve(a, b) {
            Ok(s) => {
                prop_assert!(!bad_input);
                prop_assert!(s.x.iter().all(|x| x.is_finite()));
                prop_assert!(s.min_pivot_ratio > 0.0 && s.min_pivot_ratio <= 1.0);
            }
            Err(e) => {
                prop_assert_eq!(e.primitive, Primitive::LinearSystem);
                if bad_input {
                    prop_assert_eq!(e.fault, Fault::NonFinite { what: "linear system input" });
                }
            }
        }
        if let Ok(x) = solve_unpivoted_unscaled(a, b) {
            prop_assert!(x.iter().all(|x| x.is_finite()));
        }
    }
}
