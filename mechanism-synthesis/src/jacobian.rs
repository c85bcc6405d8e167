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

/// The forward-difference Jacobian of `p` at `x` (for comparison with the
/// exact one: `n + 1` objective-cost passes, and about half the digits):
/// column `j` is `(r(x + h_j e_j) - r(x)) / h_j` with `h_j = sqrt(eps)
/// max(|x_j|, 1)`, stepping down instead where `x + h_j` would leave the
/// box. Writes `r(x)` into `r`; `false` if a design cannot be evaluated.
pub fn forward_difference<P: Problem>(
    p: &P,
    x: &[f64],
    r: &mut DVector<f64>,
    jac: &mut DMatrix<f64>,
    buf: &mut [f64],
) -> bool {
    let n = p.dim();
    if !p.residuals(x, buf) {
        return false;
    }
    r.as_mut_slice().copy_from_slice(buf);
    let mut y = x.to_vec();
    for j in 0..n {
        let mut h = f64::EPSILON.sqrt() * x[j].abs().max(1.0);
        if x[j] + h > p.upper()[j] {
            h = -h;
        }
        y[j] = x[j] + h;
        let ok = p.residuals(&y, buf);
        y[j] = x[j];
        if !ok {
            return false;
        }
        for (i, v) in buf.iter().enumerate() {
            jac[(i, j)] = (v - r[i]) / h;
        }
    }
    r.iter().all(|v| v.is_finite()) && jac.iter().all(|v| v.is_finite())
}
