//! The classical Runge-Kutta method of order 4 with a fixed step (Kutta,
//! 1901; Hairer, Norsett and Wanner, *Solving Ordinary Differential
//! Equations I*, table II.1.2): four evaluations a step, a global error of
//! order `h^4`, no error estimate. For a control loop with a fixed period
//! on a microcontroller: no heap, no data-dependent branches besides the
//! error checks.

use super::{all_finite, combine, Halt, System};
use crate::scalar::Real;

/// One step of size `h` (time units, any sign) from `(t, y)`: the state at
/// `t + h`. Errors: the system's, with the time of the failing stage; a
/// non-finite result.
pub fn step<T: Real, const N: usize, S: System<T, N>>(
    sys: &mut S,
    t: T,
    y: &[T; N],
    h: T,
) -> Result<[T; N], Halt<T, S::Error>> {
    let half = T::lit(0.5);
    let (th, t1) = (t + half * h, t + h);
    let eval =
        |sys: &mut S, t: T, y: &[T; N]| sys.rate(t, y).map_err(|error| Halt::System { t, error });
    let k1 = eval(sys, t, y)?;
    let k2 = eval(sys, th, &combine(y, h, &[(half, &k1)]))?;
    let k3 = eval(sys, th, &combine(y, h, &[(half, &k2)]))?;
    let k4 = eval(sys, t1, &combine(y, h, &[(T::one(), &k3)]))?;
    let sixth = T::lit(1.0 / 6.0);
    let third = T::lit(1.0 / 3.0);
    let out = combine(
        y,
        h,
        &[(sixth, &k1), (third, &k2), (third, &k3), (sixth, &k4)],
    );
    if all_finite(&out) {
        Ok(out)
    } else {
        Err(Halt::NonFinite { t: t1 })
    }
}

/// `steps` equal steps from `(t0, y0)` to `t1`: the state at `t1` (`y0`
/// for no steps). Errors as [`step`]'s.
pub fn integrate<T: Real, const N: usize, S: System<T, N>>(
    sys: &mut S,
    t0: T,
    y0: &[T; N],
    t1: T,
    steps: u32,
) -> Result<[T; N], Halt<T, S::Error>> {
    let mut y = *y0;
    if steps == 0 {
        return Ok(y);
    }
    let h = (t1 - t0) / T::lit(f64::from(steps));
    for k in 0..steps {
        let t = t0 + T::lit(f64::from(k)) * h;
        y = step(sys, t, &y, h)?;
    }
    Ok(y)
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

    // Proves the order: halving the step divides the error of the harmonic
    // oscillator over one period by 16 (to within 5 %), against the exact
    // solution cos, -sin.
    #[test]
    fn fourth_order_on_the_harmonic_oscillator() {
        let tau = 2.0 * core::f64::consts::PI;
        let err = |n| {
            let y = integrate(&mut Oscillator, 0.0, &[1.0, 0.0], tau, n).unwrap();
            ((y[0] - 1.0).powi(2) + y[1].powi(2)).sqrt()
        };
        let ratio = err(50) / err(100);
        assert!((ratio - 16.0).abs() < 0.8, "ratio {ratio}");
    }

    struct Fails;
    impl System<f32, 1> for Fails {
        type Error = &'static str;
        fn rate(&mut self, t: f32, _y: &[f32; 1]) -> Result<[f32; 1], &'static str> {
            if t > 0.5 {
                Err("cannot assemble")
            } else {
                Ok([1.0])
            }
        }
    }

    // Proves a system error stops the integration with the stage's time
    // (f32: the generic path compiles and runs in single precision).
    #[test]
    fn a_system_error_carries_its_time() {
        let halt = integrate(&mut Fails, 0.0f32, &[0.0], 1.0, 4).unwrap_err();
        assert_eq!(
            halt,
            Halt::System {
                t: 0.625,
                error: "cannot assemble"
            }
        );
    }
}
