//! Proves the generated `dynamics` and the force analysis agree: at random
//! states and efforts, the driving efforts `forces` computes at the `q''`
//! that `dynamics` returns are the efforts given, for every kind of drive
//! (crank, slider-crank with a slider mass, triad, carried motor, actuator,
//! target) and with gravity, couples, forces and per-evaluation loads.
//!
//! The two are independent computations: `forces` solves each group's
//! d'Alembert reactions in reverse solve order; `dynamics` sums
//! virtual powers over velocity coefficients. They agree only if both are
//! right (a wrong sign, a missing `m a` or weight term, a wrong `h` shows).
//! Tolerance 1e-13 relative to the largest of `|tau|`, `|Q|`, `|h|` and `|M q''|`
//! terms: each side is a few dozen products of rounded kinematics
//! (relative error a few eps each, cond of the velocity systems below ~10
//! at the poses used), so agreement to ~100 eps is what rounding allows.
use super::defs::*;

/// Deterministic pseudo-random numbers in [0, 1) (xorshift64*).
pub struct Rng(pub u64);
impl Rng {
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }
    pub fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
}

/// Relative mismatch of two effort vectors against `scale`.
fn check(name: &str, tau: &[f64], back: &[f64], scale: f64) -> f64 {
    let worst = tau
        .iter()
        .zip(back)
        .map(|(a, b)| (a - b).abs() / scale)
        .fold(0.0, f64::max);
    assert!(
        worst <= 1e-13,
        "{name}: tau {tau:?} back {back:?} (rel {worst:e})"
    );
    worst
}

/// The largest magnitude among the dynamics' terms, for the relative error.
fn scale(mass: &[&[f64]], qdd: &[f64], h: &[f64], q: &[f64], tau: &[f64]) -> f64 {
    let mut s: f64 = 0.0;
    for (row, hi) in mass.iter().zip(h) {
        let mq: f64 = row.iter().zip(qdd).map(|(m, a)| (m * a).abs()).sum();
        s = s.max(mq).max(hi.abs());
    }
    for v in q.iter().chain(tau) {
        s = s.max(v.abs());
    }
    s
}

macro_rules! one_input {
    ($test:ident, $ty:ident, $input:ident, $field:ident, $drive:ident, $lo:expr, $hi:expr, $rate:expr, $tau:expr $(, $loads:expr)?) => {
        #[test]
        fn $test() {
            let m = $ty::<f64>::default();
            let mut rng = Rng(0x1234_5678_9abc_def1);
            for _ in 0..200 {
                let input = $input { $field: rng.range($lo, $hi) };
                let rates = $input { $field: rng.range(-$rate, $rate) };
                let tau = $input { $field: rng.range(-$tau, $tau) };
                let pos = m.position(&input).unwrap();
                let d = m.dynamics(&pos, &rates, &tau $(, &$loads)?).unwrap();
                let vel = m.velocity(&pos, &rates).unwrap();
                let acc = m.acceleration(&pos, &vel, &d.accels).unwrap();
                let f = m.forces(&pos, &vel, &acc $(, &$loads)?).unwrap();
                let s = scale(&[&d.mass[0]], &[d.accels.$field], &d.velocity_terms, &d.generalized_forces, &[tau.$field]);
                check(stringify!($ty), &[tau.$field], &[f.$drive], s);
                assert!(d.mass[0][0] > 0.0);
            }
        }
    };
}

one_input!(
    four_bar_with_couple_and_force,
    FourBar,
    FourBarInput,
    phi,
    drive_phi,
    -4.0,
    4.0,
    40.0,
    2.0
);
one_input!(
    slider_crank_with_slider_mass_and_press,
    SliderCrank,
    SliderCrankInput,
    theta,
    drive_theta,
    -4.0,
    4.0,
    100.0,
    5.0,
    SliderCrankLoads { press: 300.0 }
);
one_input!(
    stephenson_triad,
    Stephenson,
    StephensonInput,
    phi,
    drive_phi,
    -50.0f64.to_radians(),
    -3.0f64.to_radians(),
    5.0,
    1.0
);
one_input!(
    actuator_with_masses,
    Boom,
    BoomInput,
    len,
    drive_len,
    2.0,
    2.9,
    0.5,
    1.0e5
);

/// A two-input definition's round trip at random states.
macro_rules! two_inputs {
    ($test:ident, $ty:ident, $input:ident, ($a:ident, $b:ident), ($da:ident, $db:ident), $ra:expr, $rb:expr, $rate:expr, $tau:expr) => {
        #[test]
        fn $test() {
            let m = $ty::<f64>::default();
            let mut rng = Rng(0x0fed_cba9_8765_4321);
            for _ in 0..200 {
                let input = $input {
                    $a: rng.range($ra.0, $ra.1),
                    $b: rng.range($rb.0, $rb.1),
                };
                let rates = $input {
                    $a: rng.range(-$rate, $rate),
                    $b: rng.range(-$rate, $rate),
                };
                let tau = $input {
                    $a: rng.range(-$tau, $tau),
                    $b: rng.range(-$tau, $tau),
                };
                let pos = m.position(&input).unwrap();
                let d = m.dynamics(&pos, &rates, &tau).unwrap();
                let vel = m.velocity(&pos, &rates).unwrap();
                let acc = m.acceleration(&pos, &vel, &d.accels).unwrap();
                let f = m.forces(&pos, &vel, &acc).unwrap();
                let s = scale(
                    &[&d.mass[0], &d.mass[1]],
                    &[d.accels.$a, d.accels.$b],
                    &d.velocity_terms,
                    &d.generalized_forces,
                    &[tau.$a, tau.$b],
                );
                check(stringify!($ty), &[tau.$a, tau.$b], &[f.$da, f.$db], s);
                // M is symmetric and positive definite.
                assert_eq!(d.mass[0][1], d.mass[1][0]);
                assert!(d.mass[0][0] > 0.0 && d.mass[0][0] * d.mass[1][1] > d.mass[0][1].powi(2));
            }
        }
    };
}

two_inputs!(
    leg_with_a_carried_knee_motor,
    Leg,
    LegInput,
    (hip, knee),
    (drive_hip, drive_knee),
    (-2.5, -0.5),
    (0.2, 2.5),
    6.0,
    30.0
);
two_inputs!(
    five_bar_given_its_end_point,
    FiveBarIk,
    FiveBarIkInput,
    (x, y),
    (drive_x, drive_y),
    (0.0, 0.08),
    (0.16, 0.22),
    0.5,
    10.0
);
two_inputs!(
    five_bar_given_its_motors,
    FiveBarFk,
    FiveBarFkInput,
    (q1, q2),
    (drive_q1, drive_q2),
    (1.6, 2.0),
    (1.1, 1.5),
    5.0,
    1.0
);
