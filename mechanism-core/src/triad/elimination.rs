//! The triad's 3x3 rate matrix eliminated in registers.
//!
//! [`crate::linsolve::factor`] and [`crate::linsolve::Factored::solve`] for
//! `N = 3`, operation for operation, unrolled: row equilibration (each row
//! divided by its largest absolute entry), partial pivoting (the first row
//! of largest magnitude wins a tie), the relative pivot threshold
//! `PIVOT_TOLERANCE * 3 eps`, the multipliers' and the reciprocal pivots'
//! roundings, the skipped update of a zero multiplier, and the same typed
//! errors (`Singular { det, scale }` at the same pivot with the same
//! payload, `NonFinite` for the same inputs and results), so the results
//! are the same bit for bit (the tests compare them). What changes is the
//! form: named rows instead of index loops, rows exchanged whole (the
//! multipliers with them, as LAPACK's `getrf` does) so that a solve
//! applies the row order once at its start and runs straight through, and
//! the rate matrix's zero in its first row (leg 1's row has no ternary
//! column) left out of the input check and of that row's largest entry.
//!
//! The matrix: rows the three legs, columns `A`'s two components and the
//! ternary's rate times `|AB|` (see [`super::rates`]).

use super::PRIM;
use crate::error::{Error, Fault};
use crate::geometry::{abs, all_finite};
use crate::linsolve::PIVOT_TOLERANCE;
use crate::scalar::Real;

/// The elimination of one rate matrix, kept for the velocity's and the
/// acceleration's right-hand sides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Eliminated<T> {
    /// The row exchanged with the first at the first step (0, 1 or 2).
    first: u8,
    /// Whether the last two rows were exchanged at the second step.
    second: bool,
    /// `1 / max_j |a_ij|` of the original rows, in the final row order.
    inv_scale: [T; 3],
    /// The rows in the final order: above the diagonal the upper factor, on
    /// it the pivots' reciprocals, below it the multipliers (0 where the
    /// entry was already zero).
    lu: [[T; 3]; 3],
}

/// The largest absolute entry of a row, as `linsolve` folds it (from 0,
/// the first of equal magnitudes kept).
#[inline(always)]
fn row_max<T: Real>(row: &[T]) -> T {
    row.iter().fold(T::zero(), |m, &v| {
        let v = abs(v);
        if v > m {
            v
        } else {
            m
        }
    })
}

/// `Singular` at a pivot: `det` the pivot in its row's units, `scale` that
/// row's largest absolute entry.
fn singular<T: Real>(pivot: T, scale: T) -> Error<T> {
    Error::new(
        PRIM,
        Fault::Singular {
            det: pivot * scale,
            scale,
        },
    )
}

/// Subtracts `m` times `pivot`'s columns after `k` from `row`'s and stores
/// `m = row[k] / pivot[k]` (with `inv = 1 / pivot[k]`) in `row[k]`, unless
/// `row[k]` is zero (then nothing changes).
#[inline(always)]
fn update<T: Real>(row: &mut [T; 3], pivot: &[T; 3], k: usize, inv: T) {
    let e = row[k];
    if e != T::zero() {
        let m = e * inv;
        for j in k + 1..3 {
            row[j] -= m * pivot[j];
        }
        row[k] = m;
    }
}

/// Eliminates the rate matrix with rows `[r0[0], r0[1], 0]`, `r1`, `r2`.
///
/// Errors ([`super::Primitive::Triad`], the faults of
/// [`crate::linsolve::factor`]): `NonFinite { what: "linear system input" }`
/// for a non-finite entry; `Singular { det: 0, scale: 0 }` for an all-zero
/// row; `Singular { det, scale }` when a pivot of the equilibrated matrix is
/// at most `PIVOT_TOLERANCE * 3 eps` in magnitude (`det`: the pivot in its
/// original row's units, `scale`: that row's largest absolute entry).
#[inline(always)]
pub(super) fn eliminate<T: Real>(
    r0: [T; 2],
    r1: [T; 3],
    r2: [T; 3],
) -> Result<Eliminated<T>, Error<T>> {
    let entries = [r0[0], r0[1], r1[0], r1[1], r1[2], r2[0], r2[1], r2[2]];
    if !all_finite(entries) {
        return Err(Error::new(
            PRIM,
            Fault::NonFinite {
                what: "linear system input",
            },
        ));
    }
    let mut scale = [row_max(&r0), row_max(&r1), row_max(&r2)];
    if scale.iter().any(|s| *s <= T::zero()) {
        return Err(Error::new(
            PRIM,
            Fault::Singular {
                det: T::zero(),
                scale: T::zero(),
            },
        ));
    }
    let mut inv_scale = scale.map(|s| T::one() / s);
    let [i0, i1, i2] = inv_scale;
    // The first row's third entry scaled too (a zero, or NaN for an
    // infinite `i0`, as `linsolve` makes it).
    let mut a0 = [r0[0] * i0, r0[1] * i0, T::zero() * i0];
    let mut a1 = r1.map(|v| v * i1);
    let mut a2 = r2.map(|v| v * i2);
    let threshold = T::lit(PIVOT_TOLERANCE * 3.0) * T::eps();

    // Step 1: the largest |a_i0| (a NaN never wins: `best` stays -1).
    let mut first = 0u8;
    let mut best = -T::one();
    for (i, v) in [abs(a0[0]), abs(a1[0]), abs(a2[0])].into_iter().enumerate() {
        if v > best {
            first = i as u8;
            best = v;
        }
    }
    match first {
        1 => {
            core::mem::swap(&mut a0, &mut a1);
            scale.swap(0, 1);
            inv_scale.swap(0, 1);
        }
        2 => {
            core::mem::swap(&mut a0, &mut a2);
            scale.swap(0, 2);
            inv_scale.swap(0, 2);
        }
        _ => {}
    }
    if best <= threshold {
        return Err(singular(a0[0], scale[0]));
    }
    let inv = T::one() / a0[0];
    update(&mut a1, &a0, 0, inv);
    update(&mut a2, &a0, 0, inv);
    a0[0] = inv;

    // Step 2: rows 1 and 2, column 1; the exchange takes the multipliers
    // along (each stays with the right-hand side entry it updates).
    let (v1, v2) = (abs(a1[1]), abs(a2[1]));
    let mut best = -T::one();
    if v1 > best {
        best = v1;
    }
    let second = v2 > best;
    if second {
        best = v2;
        core::mem::swap(&mut a1, &mut a2);
        scale.swap(1, 2);
        inv_scale.swap(1, 2);
    }
    if best <= threshold {
        return Err(singular(a1[1], scale[1]));
    }
    let inv = T::one() / a1[1];
    update(&mut a2, &a1, 1, inv);
    a1[1] = inv;

    // Step 3: the last pivot.
    let v = abs(a2[2]);
    let best = if v > -T::one() { v } else { -T::one() };
    if best <= threshold {
        return Err(singular(a2[2], scale[2]));
    }
    a2[2] = T::one() / a2[2];
    Ok(Eliminated {
        first,
        second,
        inv_scale,
        lu: [a0, a1, a2],
    })
}

impl<T: Real> Eliminated<T> {
    /// `x` with `A x = b` for the eliminated `A`.
    ///
    /// Errors ([`super::Primitive::Triad`]): `NonFinite { what: "linear
    /// system input" }` for a non-finite `b`, `NonFinite { what: "linear
    /// system solution" }` for an overflowing `x`.
    #[inline(always)]
    pub(super) fn solve(&self, b: [T; 3]) -> Result<[T; 3], Error<T>> {
        if !all_finite(b) {
            return Err(Error::new(
                PRIM,
                Fault::NonFinite {
                    what: "linear system input",
                },
            ));
        }
        let [mut y0, mut y1, mut y2] = b;
        match self.first {
            1 => core::mem::swap(&mut y0, &mut y1),
            2 => core::mem::swap(&mut y0, &mut y2),
            _ => {}
        }
        if self.second {
            core::mem::swap(&mut y1, &mut y2);
        }
        let [s0, s1, s2] = self.inv_scale;
        let [u0, u1, u2] = self.lu;
        let (y0, mut y1, mut y2) = (y0 * s0, y1 * s1, y2 * s2);
        if u1[0] != T::zero() {
            y1 -= u1[0] * y0;
        }
        if u2[0] != T::zero() {
            y2 -= u2[0] * y0;
        }
        if u2[1] != T::zero() {
            y2 -= u2[1] * y1;
        }
        let x2 = y2 * u2[2];
        let x1 = (y1 - u1[2] * x2) * u1[1];
        let x0 = (y0 - u0[1] * x1 - u0[2] * x2) * u0[0];
        let x = [x0, x1, x2];
        if all_finite(x) {
            Ok(x)
        } else {
            Err(Error::new(
                PRIM,
                Fault::NonFinite {
                    what: "linear system solution",
                },
            ))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::linsolve;

    /// The elimination's error, or the four right-hand sides' solutions.
    type Solves = Result<[Result<[f64; 3], Error<f64>>; 4], Error<f64>>;

    /// `linsolve`'s elimination and solve of the same matrix, its errors
    /// attributed to the triad as [`super::super::rates`] did.
    fn reference(a: [[f64; 3]; 3], rhs: &[[f64; 3]; 4]) -> Solves {
        let to_triad = |e: Error<f64>| Error::new(PRIM, e.fault);
        let (f, _) = linsolve::factor(a).map_err(to_triad)?;
        Ok(rhs.map(|b| f.solve(b).map_err(to_triad)))
    }

    fn ours(a: [[f64; 3]; 3], rhs: &[[f64; 3]; 4]) -> Solves {
        let e = eliminate([a[0][0], a[0][1]], a[1], a[2])?;
        Ok(rhs.map(|b| e.solve(b)))
    }

    /// Equal bit for bit (the zeros' signs too), or the same error.
    fn same(a: [[f64; 3]; 3], rhs: &[[f64; 3]; 4]) {
        let (want, got) = (reference(a, rhs), ours(a, rhs));
        match (&want, &got) {
            (Ok(w), Ok(g)) => {
                for (w, g) in w.iter().zip(g) {
                    match (w, g) {
                        (Ok(w), Ok(g)) => {
                            let bits = |x: &[f64; 3]| x.map(f64::to_bits);
                            assert_eq!(bits(w), bits(g), "{a:?}: {w:?} vs {g:?}");
                        }
                        _ => assert_eq!(w, g, "{a:?}"),
                    }
                }
            }
            _ => assert_eq!(want, got, "{a:?}"),
        }
    }

    /// A deterministic pseudo-random number in `[-1, 1)` (64-bit LCG).
    fn next(state: &mut u64) -> f64 {
        *state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((*state >> 11) as f64) / (1u64 << 52) as f64 - 1.0
    }

    #[test]
    fn same_as_linsolve_bit_for_bit() {
        // Proves the unrolled elimination is `linsolve::factor` and
        // `Factored::solve` for the rate matrix's shape (zero at [0][2]):
        // the same solution to the last bit and the same typed error, over
        // random matrices that pivot every way (every row order occurs),
        // rows of unlike scales, zero entries below a pivot (skipped
        // updates), exact ties in a pivot column, and singular, nearly
        // singular, zero-row and non-finite matrices and right-hand sides.
        let mut s = 7u64;
        let mut rhs = [[0.0; 3]; 4];
        for n in 0..20_000 {
            let mut a = [[0.0; 3]; 3];
            for row in a.iter_mut() {
                let scale = 10f64.powi((next(&mut s) * 4.0) as i32);
                for v in row.iter_mut() {
                    *v = next(&mut s) * scale;
                }
            }
            a[0][2] = 0.0;
            match n % 10 {
                // A zero below a pivot, or a zero pivot column entry.
                1 => a[(n / 10) % 3][(n / 30) % 2] = 0.0,
                // Ties in the first column (after scaling, equal rows).
                2 => a[1] = [a[0][0], a[0][1], a[1][2]],
                // Singular: row 2 a multiple of row 1, or nearly so.
                3 => a[2] = a[1].map(|v| 3.0 * v),
                4 => a[2] = a[1].map(|v| v * (1.0 + 1e-16 * next(&mut s))),
                // A zero row.
                5 => a[(n / 10) % 3] = [0.0; 3],
                // Non-finite entries.
                6 => a[(n / 10) % 3][(n / 30) % 2] = [f64::NAN, f64::INFINITY][(n / 60) % 2],
                // Tiny and huge rows (scales near the ends of the range).
                7 => a[(n / 10) % 3] = a[(n / 10) % 3].map(|v| v * 1e-300),
                8 => a[(n / 10) % 3] = a[(n / 10) % 3].map(|v| v * 1e300),
                _ => {}
            }
            for b in rhs.iter_mut() {
                *b = [next(&mut s), next(&mut s), next(&mut s)].map(|v| v * 1e3);
            }
            rhs[3] = match n % 7 {
                0 => [f64::NAN, 0.0, 1.0],
                1 => [1e308, -1e308, 1e308],
                2 => [0.0, -0.0, 0.0],
                _ => rhs[3],
            };
            same(a, &rhs);
        }
    }

    #[test]
    fn singular_payload_names_the_pivot_row() {
        // Proves the error of a singular rate matrix carries the pivot in
        // its row's units and that row's scale, as `linsolve` reports it,
        // at each of the three steps (a singular first column, a singular
        // second step, a singular last pivot).
        let cases = [
            [[0.0, 1.0, 0.0], [0.0, 2.0, 1.0], [0.0, 3.0, 5.0]],
            [[1.0, 2.0, 0.0], [2.0, 4.0, 1.0], [3.0, 6.0, 5.0]],
            [[1.0, 0.0, 0.0], [0.0, 1.0, 1.0], [0.0, 2.0, 2.0]],
        ];
        for a in cases {
            let got = ours(a, &[[1.0, 1.0, 1.0]; 4]).unwrap_err();
            assert!(matches!(got.fault, Fault::Singular { .. }), "{got:?}");
            assert_eq!(Err(got), reference(a, &[[1.0, 1.0, 1.0]; 4]));
        }
    }
}
