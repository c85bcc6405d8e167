//! What the solvers need of a synthesis problem.

use mechanism::Real;

/// A least-squares design problem: `dim()` design variables in a box, and
/// `residual_count()` residuals whose sum of squares is the objective.
///
/// `residuals` is generic over the scalar so that one implementation gives the
/// values (`f64`) and, through [`crate::jacobian`], the exact Jacobian
/// (`Dual<N>`). It returns `false` when the design cannot be evaluated (a
/// group that does not assemble): the solvers treat that as an infinite
/// objective, never as a value.
pub trait Problem {
    /// Number of design variables.
    fn dim(&self) -> usize;
    /// Number of residuals.
    fn residual_count(&self) -> usize;
    /// Lower bounds of the design variables (`dim()` of them; `-inf` for none).
    fn lower(&self) -> &[f64];
    /// Upper bounds of the design variables (`dim()` of them; `+inf` for none).
    fn upper(&self) -> &[f64];
    /// A finite box that holds the designs worth sampling (for a population
    /// method that draws uniformly): `(lower, upper)`. The default is the
    /// problem's bounds, which must then be finite; a problem with unbounded
    /// variables (a periodic angle, a scale-free group) states its own.
    fn search_box(&self) -> (Vec<f64>, Vec<f64>) {
        (self.lower().to_vec(), self.upper().to_vec())
    }
    /// Writes the residuals of design `x` (`dim()` values) into `out`
    /// (`residual_count()` values); `false` if the design cannot be evaluated.
    fn residuals<T: Real>(&self, x: &[T], out: &mut [T]) -> bool;
    /// Maps a design to its canonical form without changing its residuals
    /// (a periodic angle into its period, a scale-free group rescaled). The
    /// default leaves it unchanged.
    fn canonical(&self, _x: &mut [f64]) {}
    /// Re-solves, in place, the variables of `x` that have a cheap global
    /// sub-problem given the others (free input values: the best ordered
    /// positions on the output's curve), so that a perturbed design starts its
    /// local solve with them in their best basin. The default leaves `x`
    /// unchanged.
    fn reseat(&self, _x: &mut [f64]) {}
}

/// The objective: the sum of squared residuals, or `+inf` when the design
/// cannot be evaluated or a residual is not finite.
pub fn objective<P: Problem>(p: &P, x: &[f64], buf: &mut [f64]) -> f64 {
    if !p.residuals(x, buf) {
        return f64::INFINITY;
    }
    let s: f64 = buf.iter().map(|r| r * r).sum();
    if s.is_finite() {
        s
    } else {
        f64::INFINITY
    }
}
