//! The Dormand-Prince 5(4) pair (Dormand and Prince, *A family of embedded
//! Runge-Kutta formulae*, J. Comp. Appl. Math. 6, 1980) with the error
//! control, starting step and dense output of Hairer, Norsett and Wanner,
//! *Solving Ordinary Differential Equations I* (2nd ed., section II.4 and
//! II.6; the continuous extension's coefficients as in their code DOPRI5).
//!
//! Seven stages, the last reused as the next step's first (FSAL): six new
//! evaluations a step. The step is accepted when the root-mean-square of
//! `err_i / (atol + rtol max(|y_i|, |y_i new|))` is at most 1, and the next
//! step is `h 0.9 err^(-1/5)`, at most 10 and at least 0.2 times `h`.
//!
//! The integrator steps exactly onto the times it is asked to reach (no
//! interpolation error at a requested time), keeps the last step's dense
//! output (order 4, [`Dopri5::dense`]) and locates events (the sign change
//! of a function of `(t, y)`) on it by the Illinois variant of regula falsi.

use super::{all_finite, combine, max, min, min_step, Halt, System};
use crate::geometry::abs;
use crate::scalar::Real;

/// Tolerances and limits of [`Dopri5`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options<T> {
    /// Relative tolerance (per step, on each component). At least `10 eps`;
    /// `1e-13` is the tightest useful in `f64`.
    pub rtol: T,
    /// Absolute tolerance (per step, in the state's units), > 0.
    pub atol: T,
    /// The first step's size; 0 to choose it (Hairer's starting step).
    pub h0: T,
    /// The largest step size (time units), > 0.
    pub h_max: T,
    /// Steps (accepted and rejected) allowed over one call of
    /// [`Dopri5::advance`] before [`Halt::Steps`].
    pub max_steps: u32,
}

impl<T: Real> Options<T> {
    /// `rtol` and `atol` with a chosen first step, no step size limit and
    /// 100 000 steps a call.
    pub fn new(rtol: T, atol: T) -> Self {
        Options {
            rtol,
            atol,
            h0: T::zero(),
            h_max: T::lit(f64::MAX),
            max_steps: 100_000,
        }
    }
}

/// Where [`Dopri5::advance`] stopped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Stop<T, const N: usize> {
    /// The time asked for was reached exactly.
    Reached,
    /// The event function changed sign: at time `t` (located to a few eps
    /// relative on the dense output) with the dense state `y`. The
    /// integrator stays at the end of the step that contains `t`.
    Event {
        /// Time of the event.
        t: T,
        /// The state there (dense output).
        y: [T; N],
    },
}

// The Butcher tableau (Dormand and Prince 1980, table 2 of HNW II.5).
const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const A71: f64 = 35.0 / 384.0;
const A73: f64 = 500.0 / 1113.0;
const A74: f64 = 125.0 / 192.0;
const A75: f64 = -2187.0 / 6784.0;
const A76: f64 = 11.0 / 84.0;
// Fifth order less fourth order weights: the error estimate.
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
// The continuous extension (HNW's DOPRI5, its `d` coefficients).
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

/// A trial step's fifth-order state, error estimate and seven stages.
type Trial<T, const N: usize> = ([T; N], [T; N], [[T; N]; 7]);

/// The integrator's state: time, state, derivative there, the next step
/// size, and the last step's dense output.
#[derive(Clone, Copy, Debug)]
pub struct Dopri5<T, const N: usize> {
    options: Options<T>,
    t: T,
    y: [T; N],
    /// `f(t, y)` (first stage of the next step).
    k1: [T; N],
    h: T,
    /// The last accepted step's start and size, and its dense output's
    /// coefficients.
    t_old: T,
    h_old: T,
    dense: [[T; N]; 5],
    /// Accepted and rejected steps since the start.
    accepted: u64,
    rejected: u64,
}

impl<T: Real, const N: usize> Dopri5<T, N> {
    /// Starts at `(t0, y0)`; evaluates `f(t0, y0)`. Errors: the system's at
    /// `t0`; a non-finite state or derivative.
    pub fn new<S: System<T, N>>(
        sys: &mut S,
        t0: T,
        y0: [T; N],
        options: Options<T>,
    ) -> Result<Self, Halt<T, S::Error>> {
        let k1 = sys
            .rate(t0, &y0)
            .map_err(|error| Halt::System { t: t0, error })?;
        if !(all_finite(&y0) && all_finite(&k1)) {
            return Err(Halt::NonFinite { t: t0 });
        }
        Ok(Dopri5 {
            options,
            t: t0,
            y: y0,
            k1,
            h: options.h0,
            t_old: t0,
            h_old: T::zero(),
            dense: [y0; 5],
            accepted: 0,
            rejected: 0,
        })
    }

    /// The current time.
    pub fn t(&self) -> T {
        self.t
    }

    /// The current state.
    pub fn y(&self) -> &[T; N] {
        &self.y
    }

    /// The derivative at the current state.
    pub fn rate(&self) -> &[T; N] {
        &self.k1
    }

    /// Steps accepted and rejected since the start.
    pub fn steps(&self) -> (u64, u64) {
        (self.accepted, self.rejected)
    }

    /// The dense output at `t` in the last accepted step (order 4 within
    /// the step; extrapolated outside it, which is not accurate).
    pub fn dense(&self, t: T) -> [T; N] {
        let d = &self.dense;
        if self.h_old == T::zero() {
            return self.y;
        }
        let s = (t - self.t_old) / self.h_old;
        let s1 = T::one() - s;
        core::array::from_fn(|i| {
            d[0][i] + s * (d[1][i] + s1 * (d[2][i] + s * (d[3][i] + s1 * d[4][i])))
        })
    }

    /// The weighted root-mean-square norm of `v` with the scales of `y`.
    fn norm(&self, v: &[T; N], y: &[T; N], y1: &[T; N]) -> T {
        let o = &self.options;
        let mut s = T::zero();
        for i in 0..N {
            let sc = o.atol + o.rtol * max(abs(y[i]), abs(y1[i]));
            let r = v[i] / sc;
            s += r * r;
        }
        (s / T::lit(N as f64)).sqrt()
    }

    /// Hairer's starting step towards `t_end` (HNW II.4, algorithm
    /// "starting step size"), at least the smallest step accepted.
    fn start<S: System<T, N>>(&self, sys: &mut S, dir: T) -> Result<T, Halt<T, S::Error>> {
        let (y, f0) = (&self.y, &self.k1);
        let d0 = self.norm(y, y, y);
        let d1 = self.norm(f0, y, y);
        let small = T::lit(1e-5);
        let h0 = if d0 < small || d1 < small {
            T::lit(1e-6)
        } else {
            T::lit(0.01) * d0 / d1
        };
        let h0 = min(h0, self.options.h_max);
        let y1 = combine(y, dir * h0, &[(T::one(), f0)]);
        let f1 = sys
            .rate(self.t + dir * h0, &y1)
            .map_err(|error| Halt::System { t: self.t, error })?;
        let diff: [T; N] = core::array::from_fn(|i| f1[i] - f0[i]);
        let d2 = self.norm(&diff, y, y) / h0;
        let big = max(d1, d2);
        let h1 = if big <= T::lit(1e-15) {
            max(T::lit(1e-6), h0 * T::lit(1e-3))
        } else {
            (T::lit(0.01) / big).powf(T::lit(0.2))
        };
        Ok(min(min(T::lit(100.0) * h0, h1), self.options.h_max))
    }

    /// The seven stages of a step of size `h`: the fifth-order state, the
    /// error estimate and the stages the dense output needs.
    fn trial<S: System<T, N>>(&self, sys: &mut S, h: T) -> Result<Trial<T, N>, (T, S::Error)> {
        let (t, y, k1) = (self.t, &self.y, &self.k1);
        let l = T::lit;
        let mut eval = |tt: T, yy: &[T; N]| sys.rate(tt, yy).map_err(|e| (tt, e));
        let k2 = eval(t + l(C2) * h, &combine(y, h, &[(l(A21), k1)]))?;
        let k3 = eval(
            t + l(C3) * h,
            &combine(y, h, &[(l(A31), k1), (l(A32), &k2)]),
        )?;
        let y4 = combine(y, h, &[(l(A41), k1), (l(A42), &k2), (l(A43), &k3)]);
        let k4 = eval(t + l(C4) * h, &y4)?;
        let y5 = combine(
            y,
            h,
            &[(l(A51), k1), (l(A52), &k2), (l(A53), &k3), (l(A54), &k4)],
        );
        let k5 = eval(t + l(C5) * h, &y5)?;
        let y6 = combine(
            y,
            h,
            &[
                (l(A61), k1),
                (l(A62), &k2),
                (l(A63), &k3),
                (l(A64), &k4),
                (l(A65), &k5),
            ],
        );
        let k6 = eval(t + h, &y6)?;
        let y7 = combine(
            y,
            h,
            &[
                (l(A71), k1),
                (l(A73), &k3),
                (l(A74), &k4),
                (l(A75), &k5),
                (l(A76), &k6),
            ],
        );
        let k7 = eval(t + h, &y7)?;
        let zero = [T::zero(); N];
        let err = combine(
            &zero,
            h,
            &[
                (l(E1), k1),
                (l(E3), &k3),
                (l(E4), &k4),
                (l(E5), &k5),
                (l(E6), &k6),
                (l(E7), &k7),
            ],
        );
        Ok((y7, err, [*k1, k2, k3, k4, k5, k6, k7]))
    }

    /// Records the accepted step `(t, y) -> (t + h, y1)`'s dense output.
    fn keep_dense(&mut self, h: T, y1: &[T; N], k: &[[T; N]; 7]) {
        let l = T::lit;
        let y0 = self.y;
        let zero = [T::zero(); N];
        let d5 = combine(
            &zero,
            h,
            &[
                (l(D1), &k[0]),
                (l(D3), &k[2]),
                (l(D4), &k[3]),
                (l(D5), &k[4]),
                (l(D6), &k[5]),
                (l(D7), &k[6]),
            ],
        );
        for i in 0..N {
            let diff = y1[i] - y0[i];
            let bspl = h * k[0][i] - diff;
            self.dense[0][i] = y0[i];
            self.dense[1][i] = diff;
            self.dense[2][i] = bspl;
            self.dense[3][i] = diff - h * k[6][i] - bspl;
            self.dense[4][i] = d5[i];
        }
    }

    /// One accepted step towards `t_end`, not past it (exactly onto it when
    /// it is within the step). Rejected trials shrink the step; a system
    /// error in a trial stage (a pose beyond the mechanism's reach in an
    /// overshooting stage) shrinks it by 4 and retries, and is reported when
    /// the step has collapsed. `budget` counts the trials.
    fn step<S: System<T, N>>(
        &mut self,
        sys: &mut S,
        t_end: T,
        budget: &mut u32,
    ) -> Result<(), Halt<T, S::Error>> {
        let span = t_end - self.t;
        let dir = if span < T::zero() {
            -T::one()
        } else {
            T::one()
        };
        if self.h <= T::zero() {
            self.h = self.start(sys, dir)?;
        }
        loop {
            if *budget == 0 {
                return Err(Halt::Steps { t: self.t });
            }
            *budget -= 1;
            let h_min = min_step(self.t, span);
            let mut h = min(self.h, self.options.h_max);
            let last = h >= abs(span);
            if last {
                h = abs(span);
            }
            if h < h_min && !last {
                return Err(Halt::StepSize { t: self.t, h });
            }
            let hs = dir * h;
            match self.trial(sys, hs) {
                Err((t, error)) => {
                    self.rejected += 1;
                    self.h = h * T::lit(0.25);
                    if self.h < h_min {
                        return Err(Halt::System { t, error });
                    }
                }
                Ok((y1, err, k)) => {
                    let e = self.norm(&err, &self.y, &y1);
                    if !(e.finite() && all_finite(&y1) && all_finite(&k[6])) {
                        self.rejected += 1;
                        self.h = h * T::lit(0.25);
                        if self.h < h_min {
                            return Err(Halt::NonFinite { t: self.t });
                        }
                        continue;
                    }
                    let fac = if e == T::zero() {
                        T::lit(10.0)
                    } else {
                        min(
                            T::lit(10.0),
                            max(T::lit(0.2), T::lit(0.9) * e.powf(T::lit(-0.2))),
                        )
                    };
                    if e <= T::one() {
                        self.keep_dense(hs, &y1, &k);
                        self.t_old = self.t;
                        self.h_old = hs;
                        self.t = if last { t_end } else { self.t + hs };
                        self.y = y1;
                        self.k1 = k[6];
                        self.accepted += 1;
                        // After a clipped last step keep the larger of the
                        // step proposed before and the one the error asks for.
                        self.h = if last { max(self.h, h * fac) } else { h * fac };
                        return Ok(());
                    }
                    self.rejected += 1;
                    self.h = h * max(T::lit(0.2), T::lit(0.9) * e.powf(T::lit(-0.2)));
                    if self.h < h_min {
                        return Err(Halt::StepSize {
                            t: self.t,
                            h: self.h,
                        });
                    }
                }
            }
        }
    }

    /// One accepted step towards `t_end` (onto it when within reach), for a
    /// caller that watches several events itself (with [`Dopri5::dense`]
    /// and [`Dopri5::locate`] over the step from [`Dopri5::t_old`] to
    /// [`Dopri5::t`]). Errors as [`Dopri5::advance`]'s, with a budget of
    /// [`Options::max_steps`] trials for this one step.
    pub fn step_towards<S: System<T, N>>(
        &mut self,
        sys: &mut S,
        t_end: T,
    ) -> Result<(), Halt<T, S::Error>> {
        let mut budget = self.options.max_steps;
        if self.t != t_end {
            self.step(sys, t_end, &mut budget)?;
        }
        Ok(())
    }

    /// The start of the last accepted step (its end is [`Dopri5::t`]).
    pub fn t_old(&self) -> T {
        self.t_old
    }

    /// Integrates to `t_end` (either direction), stepping exactly onto it.
    /// Errors: [`Halt`] (the system's error with its time, a collapsed step,
    /// the step budget of [`Options::max_steps`] spent, non-finite values).
    pub fn advance<S: System<T, N>>(
        &mut self,
        sys: &mut S,
        t_end: T,
    ) -> Result<(), Halt<T, S::Error>> {
        let mut budget = self.options.max_steps;
        while self.t != t_end {
            self.step(sys, t_end, &mut budget)?;
        }
        Ok(())
    }

    /// Integrates towards `t_end`, stopping at the first sign change of
    /// `event(t, y)` (from its value at the start: a zero there does not
    /// count), located on the dense output to a few eps relative in `t`.
    /// `event` may fail (its error is the system's, reported at its time).
    /// After an event the integrator is at the end of the step containing
    /// it; a further call looks for the next sign change after that step's
    /// end (so an event is found once).
    pub fn advance_until<S, G>(
        &mut self,
        sys: &mut S,
        t_end: T,
        mut event: G,
    ) -> Result<Stop<T, N>, Halt<T, S::Error>>
    where
        S: System<T, N>,
        G: FnMut(&mut S, T, &[T; N]) -> Result<T, S::Error>,
    {
        let mut budget = self.options.max_steps;
        let mut g0 =
            event(sys, self.t, &self.y).map_err(|error| Halt::System { t: self.t, error })?;
        while self.t != t_end {
            self.step(sys, t_end, &mut budget)?;
            let g1 =
                event(sys, self.t, &self.y).map_err(|error| Halt::System { t: self.t, error })?;
            let crossed =
                (g0 < T::zero() && g1 >= T::zero()) || (g0 > T::zero() && g1 <= T::zero());
            if crossed {
                let t = self.locate(sys, &mut event, g0, g1)?;
                return Ok(Stop::Event {
                    t,
                    y: self.dense(t),
                });
            }
            if g1 != T::zero() {
                g0 = g1;
            }
        }
        Ok(Stop::Reached)
    }

    /// The root of `event` in the last step (a sign change between its
    /// ends, `g0` at [`Dopri5::t_old`] and `g1` at [`Dopri5::t`]) by the
    /// Illinois method on the dense output, to a few eps relative in `t`.
    pub fn locate<S, G>(
        &self,
        sys: &mut S,
        event: &mut G,
        g0: T,
        g1: T,
    ) -> Result<T, Halt<T, S::Error>>
    where
        S: System<T, N>,
        G: FnMut(&mut S, T, &[T; N]) -> Result<T, S::Error>,
    {
        let (mut a, mut b) = (self.t_old, self.t);
        let (mut ga, mut gb) = (g0, g1);
        if gb == T::zero() {
            return Ok(b);
        }
        let mut side = 0i8;
        for _ in 0..200 {
            let width = abs(b - a);
            if width <= T::lit(4.0) * T::eps() * max(abs(a), abs(b)) {
                break;
            }
            let mut t = b - gb * (b - a) / (gb - ga);
            let lo = min(a, b);
            let hi = max(a, b);
            if !(t > lo && t < hi) {
                t = (a + b) * T::lit(0.5);
            }
            let y = self.dense(t);
            let g = event(sys, t, &y).map_err(|error| Halt::System { t, error })?;
            if g == T::zero() {
                return Ok(t);
            }
            if (g < T::zero()) == (gb < T::zero()) {
                b = t;
                gb = g;
                if side == 1 {
                    ga *= T::lit(0.5);
                }
                side = 1;
            } else {
                a = t;
                ga = g;
                if side == -1 {
                    gb *= T::lit(0.5);
                }
                side = -1;
            }
        }
        Ok(b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Oscillator;
    impl System<f64, 2> for Oscillator {
        type Error = ();
        fn rate(&mut self, _t: f64, y: &[f64; 2]) -> Result<[f64; 2], ()> {
            Ok([y[1], -y[0]])
        }
    }

    // Proves the tolerance is met: the harmonic oscillator over ten
    // periods against cos, -sin, at rtol 1e-12 (global error a few times
    // the tolerance times the number of periods' growth: below 1e-10).
    #[test]
    fn meets_a_tight_tolerance_on_the_oscillator() {
        let mut ode =
            Dopri5::new(&mut Oscillator, 0.0, [1.0, 0.0], Options::new(1e-12, 1e-14)).unwrap();
        let t1 = 20.0 * core::f64::consts::PI;
        ode.advance(&mut Oscillator, t1).unwrap();
        assert_eq!(ode.t(), t1);
        let y = ode.y();
        assert!((y[0] - 1.0).abs() < 1e-10 && y[1].abs() < 1e-10, "{y:?}");
    }

    // Proves the dense output is of order 4 inside a step (error below 1e-9
    // at rtol 1e-10, where the step error is about 1e-10), and events are
    // found at the dense output's root: y0 = cos t crosses 0 at pi/2.
    #[test]
    fn dense_output_and_an_event() {
        let mut ode =
            Dopri5::new(&mut Oscillator, 0.0, [1.0, 0.0], Options::new(1e-10, 1e-12)).unwrap();
        let stop = ode
            .advance_until(&mut Oscillator, 10.0, |_, _, y| Ok(y[0]))
            .unwrap();
        let Stop::Event { t, y } = stop else {
            panic!("no event")
        };
        assert!((t - core::f64::consts::FRAC_PI_2).abs() < 1e-9, "{t}");
        assert!((y[1] + 1.0).abs() < 1e-9, "{y:?}");
        let mid = 0.5 * (t + ode.t());
        let d = ode.dense(mid);
        assert!((d[0] - mid.cos()).abs() < 1e-9);
    }

    struct Blows;
    impl System<f64, 1> for Blows {
        type Error = ();
        fn rate(&mut self, _t: f64, y: &[f64; 1]) -> Result<[f64; 1], ()> {
            Ok([y[0] * y[0]])
        }
    }

    // Proves a solution that blows up (y' = y^2, y(0) = 1: infinite at
    // t = 1) stops with a typed halt near t = 1, never a hang.
    #[test]
    fn a_collapsing_step_is_an_error() {
        let mut ode = Dopri5::new(&mut Blows, 0.0, [1.0], Options::new(1e-10, 1e-10)).unwrap();
        let halt = ode.advance(&mut Blows, 2.0).unwrap_err();
        let t = match halt {
            Halt::StepSize { t, .. } | Halt::NonFinite { t } | Halt::Steps { t } => t,
            Halt::System { .. } => panic!("no system error"),
        };
        assert!((t - 1.0).abs() < 1e-3, "{halt:?}");
    }
}
