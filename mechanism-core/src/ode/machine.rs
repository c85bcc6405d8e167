//! Machine design on one input driven through a full turn (a crank): the
//! periodic steady state by shooting and the coefficient of speed
//! fluctuation.
//!
//! The state is `y = (phi, omega)`: the crank's angle (rad, continuous) and
//! speed (rad/s), `omega > 0` (the machine turns counter-clockwise; mirror
//! the definition for the other sense). A machine whose drive and loads
//! depend on the angle and speed only (not on time) has a periodic steady
//! state: the speed `omega_0` at `phi = 0` that one turn brings back,
//! `P(omega_0) = omega_0` with `P` the return map (speed at `phi = 2 pi`
//! from speed `omega_0` at `phi = 0`). Shooting solves it by the secant
//! method on `P(w) - w`, each evaluation one turn integrated by
//! [`Dopri5`] up to the event `phi = 2 pi`.
//!
//! `delta = (omega_max - omega_min) / omega_mean` with `omega_mean = 2 pi /
//! period` (the coefficient of speed fluctuation; Shigley and Uicker,
//! *Theory of Machines and Mechanisms*, chapter 16).

use super::dopri5::{Dopri5, Options};
use super::{max, min, Halt, System};
use crate::geometry::abs;
use crate::scalar::Real;

/// The periodic steady state of a crank-driven machine.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Steady<T> {
    /// Time of one turn (s).
    pub period: T,
    /// Speed at `phi = 0` (rad/s).
    pub omega_0: T,
    /// `2 pi / period` (rad/s).
    pub mean_speed: T,
    /// Largest and smallest speed over the turn (rad/s), at stationary
    /// points of the speed located on the dense output, or at the turn's
    /// ends when larger (smaller).
    pub max_speed: T,
    /// See [`Steady::max_speed`].
    pub min_speed: T,
    /// Coefficient of speed fluctuation `(max - min) / mean`.
    pub delta: T,
    /// `|P(omega_0) - omega_0|` at the solution (rad/s).
    pub residual: T,
    /// Secant iterations taken.
    pub iterations: u32,
}

/// Why the steady state was not found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SteadyError<T, E> {
    /// The integration of a turn stopped ([`Halt`]).
    Halt(Halt<T, E>),
    /// The crank did not complete a turn within `t_max` from speed `omega`
    /// (it stalls: the drive cannot overcome the loads).
    Stalls {
        /// The starting speed at `phi = 0`.
        omega: T,
    },
    /// The secant iteration did not converge in the iterations allowed; the
    /// last residual.
    NoConvergence {
        /// `|P(w) - w|` at the last iterate (rad/s).
        residual: T,
    },
}

impl<T, E> From<Halt<T, E>> for SteadyError<T, E> {
    fn from(h: Halt<T, E>) -> Self {
        SteadyError::Halt(h)
    }
}

/// The end of a turn: its time and speed, the largest and smallest speed.
type TurnEnd<T> = (T, T, T, T);

/// One turn from `(phi0, omega)` at time 0: the time to reach `phi0 + 2
/// pi` and the speed there; with `extremes`, also the largest and smallest
/// speed on the way (the speed's stationary points, where `omega'` changes
/// sign, located on the dense output, and the turn's ends). `None` when the
/// turn takes longer than `t_max`.
fn turn<T: Real, S: System<T, 2>>(
    sys: &mut S,
    phi0: T,
    omega: T,
    options: Options<T>,
    t_max: T,
    extremes: bool,
) -> Result<Option<TurnEnd<T>>, Halt<T, S::Error>> {
    let target = phi0 + T::lit(core::f64::consts::TAU);
    let mut ode = Dopri5::new(sys, T::zero(), [phi0, omega], options)?;
    let (mut hi, mut lo) = (omega, omega);
    let mut g0 = ode.rate()[1];
    while ode.t() < t_max {
        ode.step_towards(sys, t_max)?;
        let done = ode.y()[0] >= target;
        let end = if done {
            Some(end_of_turn(&ode, target))
        } else {
            None
        };
        let g1 = ode.rate()[1];
        if extremes && ((g0 < T::zero()) != (g1 < T::zero())) {
            let t = ode.locate(
                sys,
                &mut |s: &mut S, t, y: &[T; 2]| s.rate(t, y).map(|r| r[1]),
                g0,
                g1,
            )?;
            if end.is_none_or(|(t_end, _)| t <= t_end) {
                let w = ode.dense(t)[1];
                hi = max(hi, w);
                lo = min(lo, w);
            }
        }
        g0 = g1;
        if let Some((t, w)) = end {
            hi = max(hi, w);
            lo = min(lo, w);
            return Ok(Some((t, w, hi, lo)));
        }
    }
    Ok(None)
}

/// The time and speed where `phi` reaches `target` in the integrator's last
/// step (by bisection on the dense output, to the resolution of `T`; `phi`
/// increases over the step).
fn end_of_turn<T: Real>(ode: &Dopri5<T, 2>, target: T) -> (T, T) {
    let (mut a, mut b) = (ode.t_old(), ode.t());
    for _ in 0..200 {
        let m = (a + b) * T::lit(0.5);
        if m <= a || m >= b {
            break;
        }
        if ode.dense(m)[0] < target {
            a = m;
        } else {
            b = m;
        }
    }
    // The nearer of the two bracketing times.
    let (pa, pb) = (ode.dense(a)[0], ode.dense(b)[0]);
    let t = if abs(target - pa) < abs(pb - target) {
        a
    } else {
        b
    };
    (t, ode.dense(t)[1])
}

/// The periodic steady state by shooting from the guess `omega_guess` (rad/s
/// at `phi = 0`): secant iterations on `P(w) - w` until the change is below
/// `tol` (rad/s) or `max_iter` iterations; each turn may take at most
/// `t_max` (s). `options`: the integrator's tolerances (the result is as
/// accurate as they allow).
pub fn steady_state<T: Real, S: System<T, 2>>(
    sys: &mut S,
    omega_guess: T,
    options: Options<T>,
    t_max: T,
    tol: T,
    max_iter: u32,
) -> Result<Steady<T>, SteadyError<T, S::Error>> {
    let ret = |sys: &mut S, w: T| -> Result<(T, T), SteadyError<T, S::Error>> {
        match turn(sys, T::zero(), w, options, t_max, false)? {
            Some((t, w1, _, _)) => Ok((t, w1)),
            None => Err(SteadyError::Stalls { omega: w }),
        }
    };
    let mut w0 = omega_guess;
    let (_, p0) = ret(sys, w0)?;
    // The first secant point: one turn of the map (a contraction for a
    // damped drive), then the secant.
    let mut f0 = p0 - w0;
    let mut w1 = p0;
    let mut iterations = 0;
    let residual = loop {
        iterations += 1;
        let (_, p1) = ret(sys, w1)?;
        let f1 = p1 - w1;
        if abs(f1) <= tol || f1 == f0 {
            break abs(f1);
        }
        if iterations >= max_iter {
            return Err(SteadyError::NoConvergence { residual: abs(f1) });
        }
        let w2 = w1 - f1 * (w1 - w0) / (f1 - f0);
        w0 = w1;
        f0 = f1;
        w1 = w2;
    };
    let Some((period, end, hi, lo)) = turn(sys, T::zero(), w1, options, t_max, true)? else {
        return Err(SteadyError::Stalls { omega: w1 });
    };
    let mean = T::lit(core::f64::consts::TAU) / period;
    Ok(Steady {
        period,
        omega_0: w1,
        mean_speed: mean,
        max_speed: hi,
        min_speed: lo,
        delta: (hi - lo) / mean,
        residual: max(residual, abs(end - w1)),
        iterations,
    })
}

/// The flywheel that brings a machine's speed fluctuation to a target, by
/// the energy method ([`flywheel`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Flywheel<T> {
    /// The largest fluctuation of the excess work over a turn (J):
    /// `max W - min W`.
    pub energy: T,
    /// The machine's reduced inertia averaged over the turn (kg m^2).
    pub mean_inertia: T,
    /// The inertia to add on the crank (kg m^2; 0 when the machine already
    /// meets the target).
    pub added: T,
}

/// Flywheel sizing by the energy method at the mean speed `omega_mean`
/// (rad/s) with the drive's torque `drive` there (N m): over `samples`
/// equal steps of a turn, `at(phi)` gives the reduced inertia `I(phi)`, its
/// derivative `I'(phi)` and the generalized force of the loads and gravity
/// `Q(phi)`; the equivalent torque `drive + Q - I' omega_mean^2 / 2` (the
/// inertia's variation as a load at the mean speed), less its mean, is
/// integrated (trapezoids) into the excess work `W(phi)`, and
/// `added = (max W - min W) / (delta omega_mean^2) - mean I`, at least 0.
/// Errors: `at`'s.
pub fn flywheel<T: Real, E>(
    samples: u32,
    omega_mean: T,
    drive: T,
    delta: T,
    mut at: impl FnMut(T) -> Result<(T, T, T), E>,
) -> Result<Flywheel<T>, E> {
    let n = samples.max(8);
    let step = T::lit(core::f64::consts::TAU) / T::lit(f64::from(n));
    let half = T::lit(0.5);
    let torque = |i_prime: T, q: T| drive + q - half * i_prime * omega_mean * omega_mean;
    // First pass: mean inertia and mean torque (rectangle rule = trapezoid
    // rule for a periodic function).
    let (mut sum_i, mut sum_t) = (T::zero(), T::zero());
    for k in 0..n {
        let (i, ip, q) = at(T::lit(f64::from(k)) * step)?;
        sum_i += i;
        sum_t += torque(ip, q);
    }
    let count = T::lit(f64::from(n));
    let (mean_i, mean_t) = (sum_i / count, sum_t / count);
    // Second pass: the excess work by trapezoids.
    let (mut w, mut hi, mut lo) = (T::zero(), T::zero(), T::zero());
    let (_, ip0, q0) = at(T::zero())?;
    let mut prev = torque(ip0, q0) - mean_t;
    for k in 1..=n {
        let (_, ip, q) = at(T::lit(f64::from(k)) * step)?;
        let cur = torque(ip, q) - mean_t;
        w += half * step * (prev + cur);
        hi = max(hi, w);
        lo = min(lo, w);
        prev = cur;
    }
    let energy = hi - lo;
    let added = max(
        T::zero(),
        energy / (delta * omega_mean * omega_mean) - mean_i,
    );
    Ok(Flywheel {
        energy,
        mean_inertia: mean_i,
        added,
    })
}
