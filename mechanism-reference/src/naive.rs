//! Naive Gaussian elimination in `f64`: no pivoting, no scaling (row `k` is
//! always the pivot row at step `k`). It is what the core's
//! `linsolve::solve` guards against, kept here so that the tests and the
//! report can show how it fails: a zero leading pivot stops it, and a pivot
//! that is small relative to its row (typical of force/moment mixes and of
//! poses near a singularity) produces multipliers that swamp the other
//! rows, losing most digits without any warning. Not a reference of
//! accuracy: do not use it to check anything but its own failure.

/// Why [`solve_unpivoted_unscaled`] gave no solution.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NaiveError {
    /// An entry of the matrix or the right-hand side is not finite.
    NonFiniteInput,
    /// An entry of the solution is not finite (overflow in elimination).
    NonFiniteSolution,
    /// The pivot of step `step` (the diagonal entry of row `step` after the
    /// earlier steps) is exactly zero.
    ZeroPivot {
        /// The elimination step, from 0.
        step: usize,
    },
}

/// Solves `a x = b` (`a[i][j]` row `i`, column `j`) by elimination without
/// row exchanges or scaling, then back-substitution.
///
/// # Errors
/// [`NaiveError`]: a non-finite input or solution, or an exactly zero pivot.
pub fn solve_unpivoted_unscaled<const N: usize>(
    mut a: [[f64; N]; N],
    mut b: [f64; N],
) -> Result<[f64; N], NaiveError> {
    if !a.iter().flatten().chain(b.iter()).all(|v| v.is_finite()) {
        return Err(NaiveError::NonFiniteInput);
    }
    for k in 0..N {
        let pivot = a[k][k];
        if pivot == 0.0 {
            return Err(NaiveError::ZeroPivot { step: k });
        }
        let pivot_row = a[k];
        let bk = b[k];
        for i in k + 1..N {
            let m = a[i][k] / pivot;
            for j in k + 1..N {
                a[i][j] -= m * pivot_row[j];
            }
            b[i] -= m * bk;
            a[i][k] = 0.0;
        }
    }
    // Back-substitution: x_k from row k and the x_j, j > k, found before.
    let mut x = b;
    for k in (0..N).rev() {
        let mut acc = x[k];
        for j in k + 1..N {
            acc -= a[k][j] * x[j];
        }
        x[k] = acc / a[k][k];
    }
    if x.iter().all(|v| v.is_finite()) {
        Ok(x)
    } else {
        Err(NaiveError::NonFiniteSolution)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_zero_leading_pivot_stops_it() {
        // Proves the elimination takes row 0 as the first pivot row whatever
        // its entry: the system is regular (x = (1, 2)) but starts with 0.
        let a = [[0.0, 1.0], [1.0, 0.0]];
        assert_eq!(
            solve_unpivoted_unscaled(a, [2.0, 1.0]),
            Err(NaiveError::ZeroPivot { step: 0 })
        );
    }

    #[test]
    fn a_triangular_system_is_solved_exactly() {
        // Proves the back-substitution: an upper triangular system with
        // power-of-two entries, whose solution (1, 2, 3) every step meets
        // exactly.
        let a = [[2.0, 1.0, 0.5], [0.0, 4.0, 1.0], [0.0, 0.0, 0.5]];
        let b = [2.0 + 2.0 + 1.5, 8.0 + 3.0, 1.5];
        assert_eq!(solve_unpivoted_unscaled(a, b), Ok([1.0, 2.0, 3.0]));
    }

    #[test]
    fn non_finite_input_and_overflow_are_errors() {
        // Proves the two non-finite cases: an infinite entry in, and a
        // solution 1e300 / 1e-300 that overflows.
        let id = [[1.0, 0.0], [0.0, 1.0]];
        assert_eq!(
            solve_unpivoted_unscaled(id, [f64::NAN, 0.0]),
            Err(NaiveError::NonFiniteInput)
        );
        assert_eq!(
            solve_unpivoted_unscaled([[1e-300, 0.0], [0.0, 1.0]], [1e300, 0.0]),
            Err(NaiveError::NonFiniteSolution)
        );
    }
}
