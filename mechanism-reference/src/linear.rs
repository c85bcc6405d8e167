//! Dense linear systems in double-double: Gaussian elimination with partial
//! pivoting on a heap matrix of any size (the reference solves Newton steps
//! and the Newton-Euler equations of whole mechanisms with it).

use crate::Dd;

/// The matrix had no usable pivot in this column (exact or numerical
/// singularity at double-double precision).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SingularMatrix {
    /// Column of elimination where every remaining pivot candidate was zero.
    pub column: usize,
}

/// Solves `a x = b` for square `a` (rows of equal length `b.len()`).
///
/// # Errors
/// [`SingularMatrix`] when a column has no non-zero pivot left.
pub fn solve(mut a: Vec<Vec<Dd>>, mut b: Vec<Dd>) -> Result<Vec<Dd>, SingularMatrix> {
    let n = b.len();
    assert!(
        a.len() == n && a.iter().all(|row| row.len() == n),
        "square system expected"
    );
    for col in 0..n {
        let pivot_row = (col..n)
            .max_by(|&i, &j| {
                a[i][col]
                    .abs()
                    .partial_cmp(&a[j][col].abs())
                    .unwrap_or(core::cmp::Ordering::Equal)
            })
            .unwrap_or(col);
        if a[pivot_row][col].hi == 0.0 {
            return Err(SingularMatrix { column: col });
        }
        a.swap(col, pivot_row);
        b.swap(col, pivot_row);
        let (upper, lower) = a.split_at_mut(col + 1);
        let pivot = &upper[col];
        for (offset, row) in lower.iter_mut().enumerate() {
            let factor = row[col] / pivot[col];
            if factor.hi == 0.0 {
                continue;
            }
            for (entry, &p) in row[col..].iter_mut().zip(&pivot[col..]) {
                *entry -= factor * p;
            }
            let sub = factor * b[col];
            b[col + 1 + offset] -= sub;
        }
    }
    let mut x = vec![Dd::ZERO; n];
    for row in (0..n).rev() {
        let mut acc = b[row];
        for k in row + 1..n {
            acc -= a[row][k] * x[k];
        }
        x[row] = acc / a[row][row];
    }
    Ok(x)
}
