//! Part 3: extreme scales and ratios, through the macro-generated scenes, in
//! `f32` and `f64`.
//!
//! Scale invariance: scaling every length by `s` must scale every point (and
//! its velocity and acceleration) by `s` and leave angles and angular rates
//! unchanged. With `s` a power of two every operation of the generated code is
//! exactly scale-equivariant (sums, products, quotients and square roots of
//! homogeneous quantities just shift exponents), so the results must agree
//! *bit for bit*; with `s` a power of ten the parameters themselves round
//! (half an ulp each), and the results may differ by that rounding times the
//! pose's modest conditioning: a few ulp.

use crate::scenes::{FourBar, FourBarInput, SliderCrank, SliderCrankInput};
use mechanism::Real;
use mechanism_reference::groups as refg;
use mechanism_reference::Dd;

/// A four-bar's outputs split into lengths (scale with `s`) and angles (do
/// not), positions, velocities and accelerations together.
fn fourbar<T: Real>(s: f64, theta: f64) -> (Vec<f64>, Vec<f64>) {
    let base = FourBar::<f64>::default();
    let m = FourBar::<T> {
        ground: T::lit(base.ground * s),
        crank: T::lit(base.crank * s),
        coupler: T::lit(base.coupler * s),
        rocker: T::lit(base.rocker * s),
    };
    let r = m
        .solve(
            &FourBarInput {
                theta2: T::lit(theta),
            },
            &FourBarInput {
                theta2: T::lit(37.0),
            },
            &FourBarInput {
                theta2: T::lit(-120.0),
            },
        )
        .expect("the seed's four-bar assembles at every angle");
    let (p, v, a) = (&r.position, &r.velocity, &r.acceleration);
    let lengths = [
        p.A.x, p.A.y, p.B.x, p.B.y, v.A.x, v.A.y, v.B.x, v.B.y, a.A.x, a.A.y, a.B.x, a.B.y,
    ];
    let angles = [p.link3, p.link4, v.link3, v.link4, a.link3, a.link4];
    (
        lengths.iter().map(|x| x.as_f64() / s).collect(),
        angles.iter().map(|x| x.as_f64()).collect(),
    )
}

fn check_powers_of_two<T: Real>() {
    for theta in [0.3, 1.7, 4.4] {
        let (l0, a0) = fourbar::<T>(1.0, theta);
        // 2^-20 ~ 1e-6 (mm -> MEMS) to 2^20 ~ 1e6 (a crane in mm).
        for k in -20..=20 {
            let s = 2f64.powi(k);
            let (l, a) = fourbar::<T>(s, theta);
            assert_eq!(l, l0, "lengths / s at s = 2^{k}, theta {theta}");
            assert_eq!(a, a0, "angles at s = 2^{k}, theta {theta}");
        }
    }
}

/// Proves: scaling all lengths by a power of two from 2^-20 to 2^20 scales
/// every point, velocity and acceleration of the four-bar by exactly `s` and
/// leaves every angle, angular rate and angular acceleration bit-identical, in
/// `f64` and in `f32` (no hidden absolute tolerance or scale-dependent
/// constant in the generated code).
#[test]
fn scale_invariance_powers_of_two_is_exact() {
    check_powers_of_two::<f64>();
    check_powers_of_two::<f32>();
}

/// Worst difference, in units of `eps` of `T`, over scales 1e-6 .. 1e6
/// (powers of ten), relative to each column's largest magnitude.
fn powers_of_ten<T: Real>() -> (f64, f64) {
    let eps = T::eps().as_f64();
    let (mut wl, mut wa): (f64, f64) = (0.0, 0.0);
    for theta in [0.3, 1.7, 4.4] {
        let (l0, a0) = fourbar::<T>(1.0, theta);
        let lmax = l0.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        for k in -6..=6 {
            let (l, a) = fourbar::<T>(10f64.powi(k), theta);
            for (x, y) in l.iter().zip(&l0) {
                wl = wl.max((x - y).abs() / lmax / eps);
            }
            for (x, y) in a.iter().zip(&a0) {
                wa = wa.max((x - y).abs() / y.abs().max(1.0) / eps);
            }
        }
    }
    (wl, wa)
}

/// Proves: with scales 1e-6 .. 1e6 (powers of ten, so the parameters round),
/// lengths / s and angles agree with the unscaled mechanism to a few ulp, in
/// `f64` and `f32`. Bound 32 eps (measured 16.7, f32 angles): each of four parameters rounds by half an
/// ulp and the pose amplifies by its condition (the seed's transmission
/// angles keep `kappa > 0.3`) times the acceleration's chain of two 2x2
/// solves; measured worst cases printed and in `docs/stability.md`.
#[test]
fn scale_invariance_powers_of_ten_few_ulp() {
    let (l64, a64) = powers_of_ten::<f64>();
    let (l32, a32) = powers_of_ten::<f32>();
    println!("powers of ten: f64 lengths {l64:.2} eps, angles {a64:.2} eps; f32 lengths {l32:.2} eps, angles {a32:.2} eps");
    for (name, w) in [
        ("f64 lengths", l64),
        ("f64 angles", a64),
        ("f32 lengths", l32),
        ("f32 angles", a32),
    ] {
        assert!(w <= 32.0, "{name}: {w} eps");
    }
}

/// Double-double slider-crank (offset `e`): `(x, x_dot, x_ddot)` from the
/// group references, with the same `f64` inputs.
fn slider_crank_ref(r: f64, l: f64, e: f64, theta: f64, omega: f64) -> (Dd, Dd, Dd) {
    let (a, va, aa) = refg::crank(refg::v(0.0, 0.0), r, theta, omega, 0.0);
    let g = refg::Line::new([0.0, e], [1.0, 0.0]);
    let (c, s) = refg::rrp_position(a, l, &g, 0.0, true).unwrap();
    let (w1, s_dot) = refg::rrp_rates(a, c, &g, va).unwrap();
    let (_, s_ddot) = refg::rrp_accelerations(a, c, &g, aa, w1).unwrap();
    (s, s_dot, s_ddot)
}

/// Worst errors `(x, x_dot, x_ddot)` in eps of `T` for crank/rod ratios
/// 1e-4 .. 0.5 and speeds `omegas`, against the double-double reference.
/// Scales: `x` against the rod length, `x_dot` against `r omega`, `x_ddot`
/// against `r omega^2` (each rate's natural size: `x_dot = -r omega
/// (sin + ...)`).
fn slider_crank_sweep<T: Real>(omegas: &[f64]) -> [f64; 3] {
    let eps = T::eps().as_f64();
    let l = 0.4;
    let mut worst = [0.0f64; 3];
    for ratio in [1e-4, 3e-4, 1e-3, 1e-2, 0.1, 0.5] {
        for &omega in omegas {
            // Inputs rounded to T first, so the reference sees the same ones.
            let rt = T::lit(ratio * l);
            let (r, lt, et) = (rt.as_f64(), T::lit(l), T::lit(0.25 * ratio * l));
            let (l64, e) = (lt.as_f64(), et.as_f64());
            let m = SliderCrank::<T> {
                crank: rt,
                rod: lt,
                offset: et,
            };
            for theta in [0.0, 0.4, 1.9, 3.3, 5.5] {
                let (th, w) = (T::lit(theta), T::lit(omega));
                let s = m
                    .solve(
                        &SliderCrankInput { theta: th },
                        &SliderCrankInput { theta: w },
                        &SliderCrankInput { theta: T::zero() },
                    )
                    .expect("a short crank always assembles");
                let (x, xd, xdd) = slider_crank_ref(r, l64, e, th.as_f64(), w.as_f64());
                let w = w.as_f64();
                let errs = [
                    (Dd::from(s.position.x.as_f64()) - x).abs().to_f64() / l64,
                    (Dd::from(s.velocity.x.as_f64()) - xd).abs().to_f64() / (r * w),
                    (Dd::from(s.acceleration.x.as_f64()) - xdd).abs().to_f64() / (r * w * w),
                ];
                for (w, e) in worst.iter_mut().zip(errs) {
                    *w = w.max(e / eps);
                }
            }
        }
    }
    worst
}

/// Proves: crank-to-rod ratios down to 1e-4 lose nothing: the slide
/// position, speed and acceleration match the double-double reference to a
/// few eps of their natural sizes, in `f64` and `f32`. Bound 8 eps (measured 2.0): the
/// angle's sine and cosine (about 1 ulp each, `libm`) enter every rate, and
/// the 2x2 solves are well conditioned here (`kappa ~ 1`).
#[test]
fn extreme_crank_to_rod_ratios() {
    let w64 = slider_crank_sweep::<f64>(&[10.0]);
    let w32 = slider_crank_sweep::<f32>(&[10.0]);
    println!("crank ratios 1e-4..0.5: f64 (x, x_dot, x_ddot) = {w64:.2?} eps; f32 {w32:.2?} eps");
    for w in w64.iter().chain(&w32) {
        assert!(*w <= 8.0, "{w64:?} {w32:?}");
    }
}

/// Proves: input speeds from 1e-3 to 1e5 rad/s (rates linear in omega,
/// accelerations quadratic, 1e-6 .. 1e10 in size) stay accurate to a few eps
/// of `r omega` and `r omega^2`, in `f64` and `f32` (`f32` overflows at no
/// point: `r omega^2 ~ 1e9`). Bound as for the crank ratios.
#[test]
fn extreme_speeds() {
    let omegas = [1e-3, 3.7e-2, 1.0, 42.0, 2.9e3, 1e5];
    let w64 = slider_crank_sweep::<f64>(&omegas);
    let w32 = slider_crank_sweep::<f32>(&omegas);
    println!("speeds 1e-3..1e5 rad/s: f64 (x, x_dot, x_ddot) = {w64:.2?} eps; f32 {w32:.2?} eps");
    for w in w64.iter().chain(&w32) {
        assert!(*w <= 8.0, "{w64:?} {w32:?}");
    }
}
