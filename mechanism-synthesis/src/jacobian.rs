//! The exact Jacobian of a [`Problem`]'s residuals by forward-mode dual
//! numbers: the design variables are seeded `CHUNK` at a time (one pass of the
//! residual code on [`Dual<CHUNK>`] per chunk), so a problem of `n` variables
//! costs `ceil(n / CHUNK)` dual evaluations.

use mechanism::dual::Dual;
use nalgebra::{DMatrix, DVector};

use crate::problem::Problem;

/// Derivative components per pass. 8: `Dual<8>` is 72 bytes, its arithmetic
/// vectorizes, and the four-bar's nine dimensions take two passes.
pub const CHUNK: usize = 8;

/// Reusable buffers for [`jacobian`].
pub struct Workspace {
    x: Vec<Dual<CHUNK>>,
    r: Vec<Dual<CHUNK>>,
}

impl Workspace {
    /// Buffers for a problem of `n` variables and `m` residuals.
    pub fn new(n: usize, m: usize) -> Self {
        Workspace {
            x: vec![Dual::cst(0.0); n],
            r: vec![Dual::cst(0.0); m],
        }
    }
}

/// Writes the residuals at `x` into `r` and their Jacobian (`m x n`, row i =
/// gradient of residual i) into `jac`; `false` if the design cannot be
/// evaluated.
pub fn jacobian<P: Problem>(
    p: &P,
    x: &[f64],
    ws: &mut Workspace,
    r: &mut DVector<f64>,
    jac: &mut DMatrix<f64>,
) -> bool {
    let n = p.dim();
    let mut start = 0;
    while start < n {
        for (j, (d, v)) in ws.x.iter_mut().zip(x.iter()).enumerate() {
            *d = if j >= start && j < start + CHUNK {
                Dual::var(*v, j - start)
            } else {
                Dual::cst(*v)
            };
        }
        if !p.residuals(&ws.x, &mut ws.r) {
            return false;
        }
        for (i, ri) in ws.r.iter().enumerate() {
            r[i] = ri.re;
            for (k, d) in ri.eps.iter().take(n - start).enumerate() {
                jac[(i, start + k)] = *d;
            }
        }
        start += CHUNK;
    }
    r.iter().all(|v| v.is_finite()) && jac.iter().all(|v| v.is_finite())
}
