//! Function generation by a four-bar: the rocker's angle follows a
//! prescribed function of the crank's angle, `psi_k - psi0 = y_k` when
//! `phi_k - phi0 = x_k` (Freudenstein's problem), at any number of
//! precision points, in the least-squares sense.
//!
//! The four-bar is [`FourBarPath`] with its ground link `r1 = 1` along +x
//! (the problem is scale-free: only angles are prescribed). Design variables
//! `x = [r2, r3, r4, phi0, psi0]`: the lengths in `[lo, hi]` (in units of
//! `r1`), the two reference angles free (rad). Residuals, per point: the
//! chord between the rocker's direction and the target direction
//! `psi0 + y_k` on the unit circle (`cos`, `sin` differences), which is the
//! angle error to first order and has no jump at the wrap.

use std::f64::consts::TAU;

use mechanism::{Mode, Real};

use crate::fourbar::{FourBarPath, FourBarPathInput};
use crate::problem::Problem;

/// A function-generation problem.
#[derive(Clone, Debug)]
pub struct FunctionProblem {
    /// Crank angles from the first (rad), `x_k`.
    pub inputs: Vec<f64>,
    /// Rocker angles from the first (rad), `y_k`.
    pub outputs: Vec<f64>,
    /// The assembly mode.
    pub mode: Mode,
    lo: Vec<f64>,
    hi: Vec<f64>,
}

impl FunctionProblem {
    /// A problem: `inputs` and `outputs` pairwise, link lengths in `links`
    /// (units of `r1`).
    pub fn new(inputs: Vec<f64>, outputs: Vec<f64>, links: (f64, f64), mode: Mode) -> Self {
        let inf = f64::INFINITY;
        FunctionProblem {
            inputs,
            outputs,
            mode,
            lo: vec![links.0, links.0, links.0, -inf, -inf],
            hi: vec![links.1, links.1, links.1, inf, inf],
        }
    }

    /// The four-bar of design `x` (`r1 = 1`, ground along +x, at the origin).
    pub fn mechanism<T: Real>(&self, x: &[T]) -> FourBarPath<T> {
        FourBarPath {
            r1: T::one(),
            r2: x[0],
            r3: x[1],
            r4: x[2],
            rcx: T::zero(),
            rcy: T::zero(),
            theta0: T::zero(),
            x0: T::zero(),
            y0: T::zero(),
            circuit: self.mode,
        }
    }

    /// The rocker's unit direction `O4 -> B` at crank angle `phi` (rad).
    pub fn rocker<T: Real>(fb: &FourBarPath<T>, phi: T) -> Option<[T; 2]> {
        let p = fb.position(&FourBarPathInput { phi }).ok()?;
        Some([(p.B.x - p.O4.x) / fb.r4, (p.B.y - p.O4.y) / fb.r4])
    }
}

impl Problem for FunctionProblem {
    fn dim(&self) -> usize {
        5
    }
    fn residual_count(&self) -> usize {
        2 * self.inputs.len()
    }
    fn lower(&self) -> &[f64] {
        &self.lo
    }
    fn upper(&self) -> &[f64] {
        &self.hi
    }
    /// The lengths' bounds, the two angles in `[0, 2 pi]`.
    fn search_box(&self) -> (Vec<f64>, Vec<f64>) {
        let (mut lo, mut hi) = (self.lo.clone(), self.hi.clone());
        for j in [3, 4] {
            (lo[j], hi[j]) = (0.0, TAU);
        }
        (lo, hi)
    }
    fn residuals<T: Real>(&self, x: &[T], out: &mut [T]) -> bool {
        let fb = self.mechanism(x);
        for (k, (&xi, &yi)) in self.inputs.iter().zip(&self.outputs).enumerate() {
            let Some(u) = Self::rocker(&fb, x[3] + T::lit(xi)) else {
                return false;
            };
            let (s, c) = (x[4] + T::lit(yi)).sin_cos();
            out[2 * k] = u[0] - c;
            out[2 * k + 1] = u[1] - s;
        }
        true
    }
    fn canonical(&self, x: &mut [f64]) {
        for j in [3, 4] {
            x[j] = x[j].rem_euclid(TAU);
        }
    }
}
