//! Dense linear systems `A x = b` of a fixed size `N` (const generic), solved by
//! Gaussian elimination with row equilibration and partial pivoting, on the
//! stack: no allocation, no panics.
//!
//! The kinetostatic systems of [`crate::force`] mix rows of different units:
//! force balances (entries about 1, right-hand sides in N) and moment balances
//! (entries equal to lever arms in the user's length unit, right-hand sides in
//! N L). With lengths in millimetres the moment rows are a thousand times
//! larger than the force rows, and plain partial pivoting, which compares
//! entries across rows, then picks pivots by unit rather than by merit. So
//! [`solve`] first divides every row (and its right-hand side) by the largest
//! absolute entry of that row (row equilibration, as in Forsythe and Moler,
//! *Computer Solution of Linear Algebraic Systems*, 1967, ch. 11, and Golub and
//! Van Loan, *Matrix Computations*, 4th ed., section 3.5.2), which makes the
//! subsequent partial pivoting equivalent to scaled partial pivoting. The
//! division changes every entry by at most half an ulp, a relative backward
//! perturbation far below the elimination's own.
//!
//! Elimination follows the textbook (Golub and Van Loan, algorithm 3.4.1, row
//! form): at step `k`, swap into row `k` the remaining row whose column-`k`
//! entry is largest in magnitude, subtract multiples of it from the rows below,
//! then back-substitute.
//!
//! The naive elimination without pivoting or scaling, which the tests and
//! the report show failing, is `mechanism_reference::naive`.

use crate::error::{Error, Fault, Primitive};
use crate::geometry::abs;
use crate::scalar::Real;

const P: Primitive = Primitive::LinearSystem;

/// The solution of `A x = b` with a cheap conditioning indicator.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Solution<T, const N: usize> {
    /// The solution `x`, in the units of `b` divided by those of `A`'s columns.
    #[cfg_attr(feature = "serde", serde(serialize_with = "crate::ser::array"))]
    pub x: [T; N],
    /// The smallest pivot of the elimination of the row-equilibrated matrix,
    /// in absolute value: `min_k |u_kk|`, where `U` is the upper-triangular
    /// factor of `D A` (with `D` = diagonal of `1 / max_j |a_ij|`, so that every
    /// row of `D A` has largest absolute entry 1) under partial pivoting.
    /// Equivalently, each pivot measured against the largest absolute entry of
    /// the original row it came from.
    ///
    /// In `(N eps, 1]` for a solved system (`1` when no pivot shrank, for
    /// example a permutation of a diagonal matrix). Since the pivot is the largest entry
    /// of its column in the remaining submatrix, a pivot `p` exhibits a vector
    /// `z` with `|z|_inf >= 1` and `|D A z|_inf = |p|`, so
    /// `1 / min_pivot_ratio <= cond_inf(D A)` (up to rounding in the
    /// factors): a small ratio proves ill-conditioning (the relative error of
    /// `x` may be up to about `eps / min_pivot_ratio`); a ratio near 1 is good
    /// evidence, not proof, of a well-conditioned system. At most 1 because
    /// the first pivot is an entry of `D A`; `1` for `N = 0`.
    pub min_pivot_ratio: T,
}

/// Multiplier of `N * eps` below which a relative pivot counts as zero:
/// [`solve`] reports `Singular` when `|u_kk| <= PIVOT_TOLERANCE * N * eps`.
/// At that level `cond_inf(D A) >= 1 / (N eps)`: the solution could be wrong in
/// every digit, so a typed error is more honest than a number.
pub const PIVOT_TOLERANCE: f64 = 1.0;

/// `Err(NonFinite)` unless every entry of `a` and `b` is finite.
#[inline]
fn check_input<T: Real, const N: usize>(a: &[[T; N]; N], b: &[T; N]) -> Result<(), Error<T>> {
    let finite = a.iter().flatten().chain(b.iter()).all(|v| v.finite());
    if finite {
        Ok(())
    } else {
        Err(Error::new(
            P,
            Fault::NonFinite {
                what: "linear system input",
            },
        ))
    }
}

/// Largest absolute entry of a row (0 for an empty row).
#[inline]
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

/// Back substitution on an upper-triangular `u` (entries below the diagonal
/// are ignored): `x_k = (y_k - sum_{j>k} u_kj x_j) / u_kk`, overwriting `y`
/// with `x` (`x_k` needs only `y_k` and the `x_j`, `j > k`, already stored).
#[inline]
fn back_substitute_in_place<T: Real, const N: usize>(u: &[[T; N]; N], y: &mut [T; N]) {
    // Index loops (every index is below `N` by its range): the iterator form
    // (`skip` on a `zip`) compiles to a slower loop at `opt-level = "s"`.
    for k in (0..N).rev() {
        let row = &u[k];
        let mut acc = y[k];
        for j in k + 1..N {
            acc -= row[j] * y[j];
        }
        y[k] = acc / row[k];
    }
}

/// Solves `A x = b` (`a[i][j]` is row `i`, column `j`) by Gaussian elimination
/// with row equilibration and partial pivoting; see the module documentation.
///
/// Cost: about `2 N^3 / 3` multiply-adds plus `N^2` divisions for the scaling;
/// everything lives on the stack (`a` and `b` are taken by value). The work is
/// [`solve_in_place`]'s, which this wraps; the two give identical results.
///
/// Errors (with [`Primitive::LinearSystem`]):
/// - `NonFinite { what: "linear system input" }` when any entry of `a` or `b`
///   is NaN or infinite (checked first, so nothing else sees NaN);
/// - `Singular { det, scale }` when a row of `a` is all zeros (`det = 0`,
///   `scale = 0`), or when a pivot of the equilibrated elimination satisfies
///   `|u_kk| <= PIVOT_TOLERANCE * N * eps`; then `scale` is the largest
///   absolute entry of the original row the pivot came from and
///   `det = u_kk * scale` is the pivot in that row's units, so that
///   `det / scale` is the relative pivot;
/// - `NonFinite { what: "linear system solution" }` when the solution
///   overflows.
#[inline]
pub fn solve<T: Real, const N: usize>(
    mut a: [[T; N]; N],
    mut b: [T; N],
) -> Result<Solution<T, N>, Error<T>> {
    let min_pivot_ratio = solve_in_place(&mut a, &mut b)?;
    Ok(Solution {
        x: b,
        min_pivot_ratio,
    })
}

/// [`solve`] without moving arrays: eliminates in `a` and `b` where they are
/// and leaves the solution `x` in `b`; returns
/// [`Solution::min_pivot_ratio`]. On return `a` holds the row-equilibrated,
/// row-permuted upper-triangular factor on and above its diagonal and
/// unspecified values below it; `b` is unspecified after an error.
///
/// Rows are exchanged element by element, and only in the columns still
/// active (`k..N` at step `k`; the columns before are eliminated and never
/// read again), so the elimination moves no whole rows or arrays. Errors and
/// results: those of [`solve`], bit for bit.
#[inline]
pub fn solve_in_place<T: Real, const N: usize>(
    a: &mut [[T; N]; N],
    b: &mut [T; N],
) -> Result<T, Error<T>> {
    check_input(a, b)?;

    // Row equilibration; `scale[i]` travels with row `i` through the swaps.
    let mut scale = [T::zero(); N];
    for ((row, bi), si) in a.iter_mut().zip(b.iter_mut()).zip(scale.iter_mut()) {
        let s = row_max(row);
        // Inputs are finite, so `s` is not NaN.
        if s <= T::zero() {
            return Err(Error::new(
                P,
                Fault::Singular {
                    det: T::zero(),
                    scale: T::zero(),
                },
            ));
        }
        // One division per row: the scaling only equilibrates, so the
        // rounding of `1 / s` (at most half an ulp per entry) is immaterial,
        // and a power-of-two `s` still scales exactly.
        let inv = T::one() / s;
        for v in row.iter_mut() {
            *v *= inv;
        }
        *bi *= inv;
        *si = s;
    }

    let threshold = T::lit(PIVOT_TOLERANCE * N as f64) * T::eps();
    let mut min_pivot_ratio = T::one();
    for k in 0..N {
        // Partial pivoting: the row (at or below k) with the largest |a_ik|.
        let (p, best) = a
            .iter()
            .enumerate()
            .skip(k)
            .fold((k, -T::one()), |(p, best), (i, row)| {
                let v = abs(row[k]);
                if v > best {
                    (i, v)
                } else {
                    (p, best)
                }
            });
        // p is in k..N by construction; saying so lets the optimizer drop the
        // bounds checks of the exchange (no panic path: see tests/no_panic).
        let p = if p < N { p } else { k };
        if p != k {
            // Two rows of the same array: indices are the plain way (every
            // one is below `N`).
            #[allow(clippy::needless_range_loop)]
            for j in k..N {
                let t = a[k][j];
                a[k][j] = a[p][j];
                a[p][j] = t;
            }
            b.swap(k, p);
            scale.swap(k, p);
        }
        let pivot = a[k][k];
        if best < min_pivot_ratio {
            min_pivot_ratio = best;
        }
        // `best` is never NaN: NaN entries lose every `>` in the search, and
        // `best` starts at -1 (so an all-NaN column counts as singular).
        if best <= threshold {
            return Err(Error::new(
                P,
                Fault::Singular {
                    det: pivot * scale[k],
                    scale: scale[k],
                },
            ));
        }
        // The pivot row is read in place (rows `..=k`), the rows below are
        // updated (rows `k + 1..`); a zero entry below the pivot (frequent:
        // the kinetostatic systems are sparse) skips its row.
        let (upper, lower) = a.split_at_mut(k + 1);
        let (b_upper, b_lower) = b.split_at_mut(k + 1);
        let (Some(pivot_row), Some(&bk)) = (upper.last(), b_upper.last()) else {
            continue;
        };
        let inv_pivot = T::one() / pivot;
        for (row, bi) in lower.iter_mut().zip(b_lower.iter_mut()) {
            let e = row[k];
            if e != T::zero() {
                let m = e * inv_pivot;
                for j in k + 1..N {
                    row[j] -= m * pivot_row[j];
                }
                *bi -= m * bk;
            }
        }
    }

    back_substitute_in_place(a, b);
    if b.iter().all(|v| v.finite()) {
        Ok(min_pivot_ratio)
    } else {
        Err(Error::new(
            P,
            Fault::NonFinite {
                what: "linear system solution",
            },
        ))
    }
}

/// The elimination of one matrix kept for several right-hand sides: what
/// [`solve_in_place`] does to `a`, recorded ([`factor`]), and what it does
/// to `b`, replayed on each new `b` ([`Factored::solve`]). For systems that
/// share a matrix (a group's velocity and acceleration): the matrix is
/// checked, scaled and eliminated once.
///
/// A solve performs [`solve`]'s operations on `b` in the same order but
/// for the back substitution's divisions by the pivots, which become
/// multiplications by their reciprocals (formed in the elimination, where
/// [`solve`] forms them too for the multipliers): one more rounding per
/// component (a relative `eps / 2`, within the elimination's own backward
/// error) and no chain of `N` divisions on the way to the solution. A
/// multiplier that underflowed to zero (an entry below the pivot about
/// `2^-1022` times smaller in `f64`) skips its update, which [`solve`]
/// applies as a subtraction of zero.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Factored<T, const N: usize> {
    /// `1 / max_j |a_ij|` of each row `i` of the original matrix.
    inv_scale: [T; N],
    /// The row exchanged with row `k` at step `k` (`k` itself for none).
    swap: [usize; N],
    /// The factors in one square: above the diagonal the upper-triangular
    /// factor; on it the pivots' reciprocals; below it, at `[i][k]`, the
    /// multiple of row `k` subtracted from the row at position `i > k` at
    /// step `k` (0 where the entry was already zero; later steps exchange
    /// only the columns after theirs, so it stays where it was made).
    lu: [[T; N]; N],
}

/// Eliminates `a` as [`solve`] does and keeps the elimination; returns it
/// with [`Solution::min_pivot_ratio`].
///
/// Errors: those of [`solve`] for `a` (`NonFinite` input, `Singular`); the
/// right-hand sides are checked by [`Factored::solve`].
#[inline]
pub fn factor<T: Real, const N: usize>(
    mut a: [[T; N]; N],
) -> Result<(Factored<T, N>, T), Error<T>> {
    check_input(&a, &[T::zero(); N])?;
    let mut inv_scale = [T::zero(); N];
    let mut scale = [T::zero(); N];
    for ((row, inv_i), si) in a.iter_mut().zip(inv_scale.iter_mut()).zip(scale.iter_mut()) {
        let s = row_max(row);
        if s <= T::zero() {
            return Err(Error::new(
                P,
                Fault::Singular {
                    det: T::zero(),
                    scale: T::zero(),
                },
            ));
        }
        let inv = T::one() / s;
        for v in row.iter_mut() {
            *v *= inv;
        }
        *inv_i = inv;
        *si = s;
    }
    let threshold = T::lit(PIVOT_TOLERANCE * N as f64) * T::eps();
    let mut min_pivot_ratio = T::one();
    let mut swap = [0; N];
    for k in 0..N {
        let (p, best) = a
            .iter()
            .enumerate()
            .skip(k)
            .fold((k, -T::one()), |(p, best), (i, row)| {
                let v = abs(row[k]);
                if v > best {
                    (i, v)
                } else {
                    (p, best)
                }
            });
        let p = if p < N { p } else { k };
        if let Some(s) = swap.get_mut(k) {
            *s = p;
        }
        if p != k {
            #[allow(clippy::needless_range_loop)]
            for j in k..N {
                let t = a[k][j];
                a[k][j] = a[p][j];
                a[p][j] = t;
            }
            scale.swap(k, p);
        }
        let pivot = a[k][k];
        if best < min_pivot_ratio {
            min_pivot_ratio = best;
        }
        if best <= threshold {
            return Err(Error::new(
                P,
                Fault::Singular {
                    det: pivot * scale[k],
                    scale: scale[k],
                },
            ));
        }
        let (upper, lower) = a.split_at_mut(k + 1);
        let Some(pivot_row) = upper.last_mut() else {
            continue;
        };
        let inv_pivot = T::one() / pivot;
        for row in lower.iter_mut() {
            let e = row[k];
            if e != T::zero() {
                let m = e * inv_pivot;
                for j in k + 1..N {
                    row[j] -= m * pivot_row[j];
                }
                row[k] = m;
            }
        }
        pivot_row[k] = inv_pivot;
    }
    Ok((
        Factored {
            inv_scale,
            swap,
            lu: a,
        },
        min_pivot_ratio,
    ))
}

impl<T: Real, const N: usize> Factored<T, N> {
    /// `x` with `A x = b` for the factored `A` (see [`Factored`]).
    ///
    /// Errors: `NonFinite` for a non-finite `b` ("linear system input") or
    /// an overflowing solution ("linear system solution").
    #[inline]
    pub fn solve(&self, mut b: [T; N]) -> Result<[T; N], Error<T>> {
        if !b.iter().all(|v| v.finite()) {
            return Err(Error::new(
                P,
                Fault::NonFinite {
                    what: "linear system input",
                },
            ));
        }
        for (bi, inv) in b.iter_mut().zip(self.inv_scale.iter()) {
            *bi *= *inv;
        }
        for (k, &p) in self.swap.iter().enumerate() {
            if p != k && p < N {
                b.swap(k, p);
            }
            let (b_upper, b_lower) = b.split_at_mut(k + 1);
            let Some(&bk) = b_upper.last() else {
                continue;
            };
            for (bi, row) in b_lower.iter_mut().zip(self.lu.iter().skip(k + 1)) {
                let m = row[k];
                if m != T::zero() {
                    *bi -= m * bk;
                }
            }
        }
        for k in (0..N).rev() {
            let row = &self.lu[k];
            let mut acc = b[k];
            for j in k + 1..N {
                acc -= row[j] * b[j];
            }
            b[k] = acc * row[k];
        }
        if b.iter().all(|v| v.finite()) {
            Ok(b)
        } else {
            Err(Error::new(
                P,
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

    #[test]
    fn permutation_of_diagonal_is_exact() {
        let a = [[0.0, 4.0, 0.0], [0.0, 0.0, 0.5], [2.0, 0.0, 0.0]];
        let s = solve(a, [8.0, 1.0, 6.0]).unwrap();
        assert_eq!(s.x, [3.0, 2.0, 2.0]);
        assert_eq!(s.min_pivot_ratio, 1.0);
    }

    #[test]
    fn factored_solves_agree_with_solve() {
        // Proves that keeping the elimination and replaying it on a new
        // right-hand side gives `solve`'s elimination exactly (the same
        // pivots) and its solution to the one extra rounding per component
        // of the reciprocal pivots (these systems' condition numbers are
        // below 1e4: 64 eps of the largest component bounds it), on systems
        // that pivot at every step, that have zero entries below a pivot
        // (skipped updates), and rows of unlike scales; and that a singular
        // or non-finite matrix is refused as `solve` refuses it.
        let systems: [[[f64; 3]; 3]; 4] = [
            [[1e-3, 2.0, 3.0], [4.0, 5.0, 6.5], [7.0, 8.5, 1e-2]],
            [[0.3, -0.2, 0.0], [-0.1, 0.7, 0.045], [0.25, 0.05, -0.031]],
            [[2.0, 0.0, 1.0], [0.0, 3e3, -2e3], [1e-4, 2e-4, 5e-4]],
            [[0.0, 1.0, 2.0], [3.0, 0.0, 1.0], [1.0, 1.0, 0.0]],
        ];
        let rhs = [[1.0, -2.0, 0.5], [3e-7, 4e5, -1.25], [0.0, 0.0, 1.0]];
        for a in systems {
            let (f, ratio) = factor(a).unwrap();
            for b in rhs {
                let want = solve(a, b).unwrap();
                assert_eq!(ratio, want.min_pivot_ratio);
                let got = f.solve(b).unwrap();
                let big = want.x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                for (g, w) in got.iter().zip(want.x.iter()) {
                    assert!(
                        (g - w).abs() <= 64.0 * f64::EPSILON * big,
                        "{a:?} {b:?}: {g} vs {w}"
                    );
                }
            }
            assert!(f.solve([f64::NAN, 0.0, 0.0]).is_err());
        }
        let singular = [[1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [0.0, 1.0, 1.0]];
        assert!(matches!(
            factor(singular).unwrap_err().fault,
            Fault::Singular { .. }
        ));
        let nan = [[1.0, f64::NAN, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        assert!(matches!(
            factor(nan).unwrap_err().fault,
            Fault::NonFinite { .. }
        ));
    }

    #[test]
    fn empty_system() {
        let s = solve::<f64, 0>([], []).unwrap();
        assert_eq!(s.min_pivot_ratio, 1.0);
    }
}
