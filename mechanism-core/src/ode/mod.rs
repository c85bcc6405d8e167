//! Integrators for ordinary differential equations `y' = f(t, y)` of a
//! fixed size `N`, generic over [`Real`] (`f32`, `f64`), without heap and
//! without panics: the forward dynamics of a generated mechanism
//! (`analysis dynamics`) as a state `y = (q, q')` moved in time.
//!
//! - [`rk4`]: the classical fixed-step Runge-Kutta method of order 4, for a
//!   microcontroller's control loop (four evaluations a step, no error
//!   estimate, no branch on the data).
//! - [`dopri5`]: the Dormand-Prince 5(4) pair with error control (the
//!   embedded fourth-order solution's difference, mixed absolute and
//!   relative tolerance, root-mean-square norm), the continuous extension
//!   of order 4 for dense output, stepping exactly onto requested times and
//!   events located on the dense output (an input reaching a value, a full
//!   turn, an extremum of the speed).
//! - [`drive`]: efforts as functions of the state: a DC motor's
//!   torque-speed line, a linear spring and viscous damper on an input.
//!
//! Why hand-written: the well-kept Rust crates need `std` and the heap and
//! fix the scalar type. `ode_solvers` (DOPRI5, DOP853, RK4) stores its
//! output in `Vec`s and takes `nalgebra` `SVector<f64, N>`; `diffsol` (BDF,
//! SDIRK) is built on dynamic matrices and `std`; `russell_ode` on `std`
//! and dynamic vectors. The generated mechanisms run on a Cortex-M in `f32`
//! with neither, so the two methods here are a few hundred lines over
//! `[T; N]`, their coefficients from the sources each module cites.
//!
//! Failures are typed ([`Halt`]): the system's own error (a pose that
//! cannot be assembled, a dead point) with the time it happened, a step size
//! that collapses below `16 eps |t|` (never a hang), a step budget spent,
//! a non-finite state.

pub mod dopri5;
pub mod drive;
pub mod machine;
pub mod rk4;

use crate::geometry::abs;
use crate::scalar::Real;

/// A system `y' = f(t, y)` of `N` first-order equations.
pub trait System<T: Real, const N: usize> {
    /// The system's own error (for a mechanism: [`crate::Error`], naming
    /// the group that cannot be assembled or is singular).
    type Error;

    /// The derivative `f(t, y)` (the state's units per unit time).
    fn rate(&mut self, t: T, y: &[T; N]) -> Result<[T; N], Self::Error>;
}

/// Why an integration stopped before its end.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Halt<T, E> {
    /// The system failed at time `t` (the state it was evaluated at is
    /// within the last step): for a mechanism a pose that cannot be
    /// assembled or a singular mass matrix, the error naming the group.
    System {
        /// The time of the failing evaluation.
        t: T,
        /// The system's error.
        error: E,
    },
    /// The step size fell below `16 eps |t|` (or the minimum asked for)
    /// at time `t`: a singularity of the solution, or a tolerance the
    /// precision `T` cannot meet.
    StepSize {
        /// The time reached.
        t: T,
        /// The step size that was rejected.
        h: T,
    },
    /// The step budget (`max_steps`) was spent at time `t`.
    Steps {
        /// The time reached.
        t: T,
    },
    /// A state or derivative was NaN or infinite at time `t`.
    NonFinite {
        /// The time reached.
        t: T,
    },
}

/// `true` when every entry is finite.
pub(crate) fn all_finite<T: Real, const N: usize>(y: &[T; N]) -> bool {
    y.iter().all(|v| v.finite())
}

/// `y + h * sum_k c_k k_k` over the stages with a coefficient.
#[inline]
pub(crate) fn combine<T: Real, const N: usize>(y: &[T; N], h: T, terms: &[(T, &[T; N])]) -> [T; N] {
    let mut out = *y;
    for (i, o) in out.iter_mut().enumerate() {
        let mut s = T::zero();
        for (c, k) in terms {
            s += *c * k[i];
        }
        *o += h * s;
    }
    out
}

/// The larger of two values (the first when either is NaN).
#[inline]
pub(crate) fn max<T: Real>(a: T, b: T) -> T {
    if b > a {
        b
    } else {
        a
    }
}

/// The smaller of two values (the first when either is NaN).
#[inline]
pub(crate) fn min<T: Real>(a: T, b: T) -> T {
    if b < a {
        b
    } else {
        a
    }
}

/// The smallest step accepted at time `t`: `16 eps max(|t|, |span|)`.
#[inline]
pub(crate) fn min_step<T: Real>(t: T, span: T) -> T {
    T::lit(16.0) * T::eps() * max(abs(t), abs(span))
}
