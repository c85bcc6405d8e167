//! The max error instead of the sum of squares: a [`Problem`] wrapper whose
//! least-squares objective is a high power of the errors, so that the local
//! solver that minimizes it (unchanged: the bounded LM on the exact Jacobian)
//! minimizes, in the limit, the largest error.
//!
//! The inner problem's residuals are taken in groups of `group` (two: the
//! `x` and `y` of a point's miss; the residuals left after the last whole
//! group are groups of one); group `g`'s squared error is `s_g = sum r_i^2`
//! and its residual `(s_g / scale^2)^q`, so the objective is
//! `sum_g (e_g / scale)^(4 q)`, the `p = 4 q` power of the `p`-norm of the
//! errors `e_g = sqrt(s_g)` over `scale`. Its `p`-th root is within a factor
//! `G^(1/p)` of the largest `e_g / scale` (`G` groups): for 18 points and
//! `q = 4`, within 20 %, and the minimizer's largest error is that much
//! closer still (the error of the p-norm approximation of a minimax problem).
//! An integer power keeps every residual smooth (the polynomial of a sum of
//! squares). `scale` (in the residuals' units) keeps the residuals near one
//! at the designs of interest, away from the solver's absolute stopping test
//! and from overflow: the largest error of a least-squares design is a good
//! choice.

use mechanism::Real;

use crate::problem::Problem;

/// The `p = 4 q` power of the grouped errors of `inner` (see the module).
#[derive(Clone, Debug)]
pub struct MaxError<P> {
    /// The problem whose errors are measured.
    pub inner: P,
    /// Residuals per error (2 for a point).
    pub group: usize,
    /// The power of the squared errors (`p = 4 q`; at least 1).
    pub q: u32,
    /// The error that counts as one (in the residuals' units, positive).
    pub scale: f64,
}

impl<P: Problem> MaxError<P> {
    /// Groups of the inner problem's residuals.
    fn groups(&self) -> usize {
        let (m, g) = (self.inner.residual_count(), self.group.max(1));
        m / g + m % g
    }

    /// The largest error (`sqrt(s_g)`, the inner problem's units) of design
    /// `x`, or `+inf` when it cannot be evaluated.
    pub fn max_error(&self, x: &[f64]) -> f64 {
        let mut r = vec![0.0; self.inner.residual_count()];
        if !self.inner.residuals(x, &mut r) {
            return f64::INFINITY;
        }
        let g = self.group.max(1);
        let whole = r.len() / g * g;
        let mut worst: f64 = 0.0;
        for c in r[..whole].chunks(g).chain(r[whole..].chunks(1)) {
            worst = worst.max(c.iter().map(|v| v * v).sum::<f64>().sqrt());
        }
        worst
    }
}

impl<P: Problem> Problem for MaxError<P> {
    fn dim(&self) -> usize {
        self.inner.dim()
    }
    fn residual_count(&self) -> usize {
        self.groups()
    }
    fn lower(&self) -> &[f64] {
        self.inner.lower()
    }
    fn upper(&self) -> &[f64] {
        self.inner.upper()
    }
    fn search_box(&self) -> (Vec<f64>, Vec<f64>) {
        self.inner.search_box()
    }
    fn residuals<T: Real>(&self, x: &[T], out: &mut [T]) -> bool {
        let mut r = [T::zero(); 256];
        let m = self.inner.residual_count();
        if m > r.len() || !self.inner.residuals(x, &mut r[..m]) {
            return false;
        }
        let g = self.group.max(1);
        let whole = m / g * g;
        let inv = T::lit(1.0 / (self.scale * self.scale));
        let groups = r[..whole].chunks(g).chain(r[whole..m].chunks(1));
        for (o, c) in out.iter_mut().zip(groups) {
            let s = c.iter().fold(T::zero(), |a, v| a + *v * *v) * inv;
            let mut p = s;
            for _ in 1..self.q.max(1) {
                p *= s;
            }
            *o = p;
        }
        true
    }
    fn canonical(&self, x: &mut [f64]) {
        self.inner.canonical(x);
    }
    fn reseat(&self, x: &mut [f64]) {
        self.inner.reseat(x);
    }
}
