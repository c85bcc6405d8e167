//! Double-double arithmetic and functions against astro-float at 256 bits.
//!
//! Tolerance: a double-double result carries about 106 bits; each operation
//! here is a handful of error-free transformations, so the relative error of
//! one operation is bounded by a few units of 2^-104 (4.9e-32). We allow
//! 1e-30 relative (about 20 such units) for the series and Newton-refined
//! functions and 2e-31 for the four basic operations. A bug (wrong constant,
//! a dropped `lo` term) shows up as an error of 1e-17 or worse.

use astro_float::{BigFloat, Consts, RoundingMode};
use mechanism_reference::Dd;

const P: usize = 256;
const RM: RoundingMode = RoundingMode::ToEven;

fn big(x: Dd) -> BigFloat {
    BigFloat::from_f64(x.hi, P).add(&BigFloat::from_f64(x.lo, P), P, RM)
}

/// |got - want| <= tol * |want| (or tol absolute when want is tiny).
fn close(got: Dd, want: &BigFloat, tol: f64) -> bool {
    let diff = big(got).sub(want, P, RM).abs();
    let scale = want.abs();
    let one = BigFloat::from_f64(1.0, P);
    let scale = if scale < one.mul(&BigFloat::from_f64(1e-300, P), P, RM) {
        one
    } else {
        scale
    };
    diff <= scale.mul(&BigFloat::from_f64(tol, P), P, RM)
}

/// |got - want| <= tol.
fn close_abs(got: Dd, want: &BigFloat, tol: f64) -> bool {
    big(got).sub(want, P, RM).abs() <= BigFloat::from_f64(tol, P)
}

/// Deterministic spread of arguments: a linear congruential sequence mapped
/// to [lo, hi], plus exact hi+lo pairs so the `lo` parts matter.
fn samples(n: usize, lo: f64, hi: f64) -> Vec<Dd> {
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    (0..n)
        .map(|_| {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let u = (state >> 11) as f64 / (1u64 << 53) as f64;
            let x = lo + (hi - lo) * u;
            Dd::sum(x, x * 1.1e-17)
        })
        .collect()
}

#[test]
fn basic_operations_are_exact_to_106_bits() {
    let xs = samples(400, -1e3, 1e3);
    for w in xs.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (ba, bb) = (big(a), big(b));
        assert!(
            close(a + b, &ba.add(&bb, P, RM), 2e-31) || (a + b).hi.abs() < 1e-10,
            "add {a} {b}"
        );
        assert!(close(a * b, &ba.mul(&bb, P, RM), 2e-31), "mul {a} {b}");
        assert!(close(a / b, &ba.div(&bb, P, RM), 2e-31), "div {a} {b}");
        assert!(
            close(a.abs().sqrt(), &ba.abs().sqrt(P, RM), 2e-31),
            "sqrt {a}"
        );
    }
}

#[test]
fn sine_and_cosine_over_many_turns() {
    let mut cc = Consts::new().expect("astro-float constants");
    // The reduction x - k pi/2 rounds k * (pi/2) to 106 bits, an absolute
    // error of a few 2^-104 |x|: the tolerance is relative to max(1, |x|)
    // (the argument itself is only known to that precision).
    for x in samples(300, -200.0, 200.0) {
        let (s, c) = x.sin_cos();
        let bx = big(x);
        let tol = 1e-30 * x.hi.abs().max(1.0);
        assert!(close_abs(s, &bx.sin(P, RM, &mut cc), tol), "sin {x}");
        assert!(close_abs(c, &bx.cos(P, RM, &mut cc), tol), "cos {x}");
    }
}

#[test]
fn atan2_in_all_four_quadrants() {
    let mut cc = Consts::new().expect("astro-float constants");
    let pi = cc.pi(P, RM);
    let ys = samples(200, -5.0, 5.0);
    let xs = samples(201, -5.0, 5.0);
    for (&y, &x) in ys.iter().zip(xs.iter().skip(1)) {
        let got = Dd::atan2(y, x);
        let base = big(y).div(&big(x), P, RM).atan(P, RM, &mut cc);
        let want = if x.hi > 0.0 {
            base
        } else if y.hi >= 0.0 {
            base.add(&pi, P, RM)
        } else {
            base.sub(&pi, P, RM)
        };
        assert!(close(got, &want, 1e-30), "atan2({y}, {x})");
    }
}

#[test]
fn constants_are_pi_to_106_bits() {
    let mut cc = Consts::new().expect("astro-float constants");
    let pi = cc.pi(P, RM);
    assert!(close(Dd::PI, &pi, 2e-32));
    assert!(close(
        Dd::FRAC_PI_2,
        &pi.div(&BigFloat::from_f64(2.0, P), P, RM),
        2e-32
    ));
    assert!(close(
        Dd::TAU,
        &pi.mul(&BigFloat::from_f64(2.0, P), P, RM),
        2e-32
    ));
}

#[test]
fn linear_solve_recovers_a_known_solution() {
    // A Hilbert-like 6x6 (condition ~1.5e7): x = (1, -2, 3, -4, 5, -6) is
    // recovered to about cond * 1e-32 = 1e-24 relative.
    let n = 6;
    let x_true: Vec<Dd> = (0..n)
        .map(|i| Dd::from_f64(((i + 1) as f64) * if i % 2 == 0 { 1.0 } else { -1.0 }))
        .collect();
    let a: Vec<Vec<Dd>> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| Dd::ONE / Dd::from_f64((i + j + 1) as f64))
                .collect()
        })
        .collect();
    let b: Vec<Dd> = a
        .iter()
        .map(|row| {
            row.iter()
                .zip(&x_true)
                .fold(Dd::ZERO, |acc, (&aij, &xj)| acc + aij * xj)
        })
        .collect();
    let x = mechanism_reference::linear::solve(a, b).expect("regular");
    for (got, want) in x.iter().zip(&x_true) {
        assert!(
            (*got - *want).abs().to_f64() < 1e-22 * want.abs().to_f64(),
            "{got} vs {want}"
        );
    }
}
