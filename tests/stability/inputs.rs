//! Part 5: bad run-time inputs. NaN, infinities, zero and negative lengths
//! given as run-time parameters of the generated scenes must come back as
//! typed errors; random (absurd) parameters must never panic and never put a
//! non-finite number inside `Ok`.
//!
//! "Non-finite inside `Ok`" is checked on the results' `Debug` text (every
//! field of every generated and core result struct is printed by its derived
//! `Debug`, and Rust prints non-finite floats as `NaN`, `inf`, `-inf`), so
//! no field can be forgotten.

use crate::scenes::*;
use mechanism::driver::actuator;
use mechanism::dyad::{prp, rpp, rpr, rrp, rrr};
use mechanism::guide::Line;
use mechanism::{Error, Fault, Mode, Point2, Vector2};
use proptest::prelude::*;

fn finite_text(s: &str) -> bool {
    !(s.contains("NaN") || s.contains("inf"))
}

/// `true` when the `Debug` text of `x` shows no NaN or infinity.
fn fin<T: core::fmt::Debug>(x: &T) -> bool {
    finite_text(&format!("{x:?}"))
}

fn is_non_finite(e: &Error) -> bool {
    matches!(e.fault, Fault::NonFinite { .. })
}

fn is_non_positive(e: &Error) -> bool {
    matches!(e.fault, Fault::NonPositive { .. })
}

/// Proves: every length parameter of the four-bar and the slider-crank given
/// as NaN or +-infinity yields `NonFinite`, and as 0 or negative yields
/// `NonPositive` (naming the group), from `position`; the ground coordinate
/// and the slide offset (which may be any finite number) yield `NonFinite`
/// for NaN and infinities; non-finite inputs (angle, speed, acceleration)
/// yield `NonFinite` from the analysis that takes them.
#[test]
fn bad_runtime_parameters_are_typed_errors() {
    let bad = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 0.0, -1.0, -0.0];
    let input = FourBarInput { theta2: 0.7 };
    for x in bad {
        let non_finite = !x.is_finite();
        for which in 0..3 {
            let mut m = FourBar::<f64>::default();
            match which {
                0 => m.crank = x,
                1 => m.coupler = x,
                _ => m.rocker = x,
            }
            let e = m.position(&input).expect_err("bad length");
            assert!(
                if non_finite {
                    is_non_finite(&e)
                } else {
                    is_non_positive(&e)
                },
                "four-bar length #{which} = {x}: {e}"
            );
            assert!(!e.group.is_empty(), "error names its group: {e}");
        }
        if non_finite {
            let m = FourBar::<f64> {
                ground: x,
                ..FourBar::default()
            };
            assert!(is_non_finite(&m.position(&input).expect_err("bad ground")));
            let m = SliderCrank::<f64> {
                offset: x,
                ..SliderCrank::default()
            };
            assert!(is_non_finite(
                &m.position(&SliderCrankInput { theta: 0.3 })
                    .expect_err("bad offset")
            ));
            // Inputs.
            let m = FourBar::<f64>::default();
            assert!(is_non_finite(
                &m.position(&FourBarInput { theta2: x })
                    .expect_err("bad angle")
            ));
            let p = m.position(&input).unwrap();
            assert!(is_non_finite(
                &m.velocity(&p, &FourBarInput { theta2: x })
                    .expect_err("bad speed")
            ));
            let v = m.velocity(&p, &input).unwrap();
            assert!(is_non_finite(
                &m.acceleration(&p, &v, &FourBarInput { theta2: x })
                    .expect_err("bad acceleration")
            ));
        }
        for which in 0..2 {
            let mut m = SliderCrank::<f64>::default();
            if which == 0 {
                m.crank = x;
            } else {
                m.rod = x;
            }
            let e = m
                .position(&SliderCrankInput { theta: 0.3 })
                .expect_err("bad length");
            assert!(
                if non_finite {
                    is_non_finite(&e)
                } else {
                    is_non_positive(&e)
                },
                "slider-crank length #{which} = {x}: {e}"
            );
        }
    }
}

/// Absurd numbers: anything `f64` can hold (NaN, infinities, subnormals,
/// zeros), magnitudes 1e-300 .. 1e300 of either sign, and ordinary values.
fn absurd() -> impl Strategy<Value = f64> {
    prop_oneof![
        any::<f64>(),
        (-300.0f64..300.0, any::<bool>()).prop_map(|(e, neg)| {
            let v = 10f64.powf(e);
            if neg {
                -v
            } else {
                v
            }
        }),
        -10.0f64..10.0,
        Just(0.0),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    /// Proves: the generated four-bar, slider-crank and five-bar, with every
    /// run-time parameter and input drawn from `absurd()`, never panic, and
    /// every `Ok` (position, velocity, acceleration, in `f64` and in `f32`)
    /// holds only finite numbers.
    #[test]
    fn macro_scenes_never_panic_never_non_finite(v in prop::collection::vec(absurd(), 10)) {
        let fb = FourBar::<f64> { ground: v[0], crank: v[1], coupler: v[2], rocker: v[3] };
        let r = fb.solve(&FourBarInput { theta2: v[4] }, &FourBarInput { theta2: v[5] }, &FourBarInput { theta2: v[6] });
        if let Ok(s) = r { prop_assert!(fin(&s), "{:?}", s); }
        let fb32 = FourBar::<f32> { ground: v[0] as f32, crank: v[1] as f32, coupler: v[2] as f32, rocker: v[3] as f32 };
        let r = fb32.solve(&FourBarInput { theta2: v[4] as f32 }, &FourBarInput { theta2: v[5] as f32 }, &FourBarInput { theta2: v[6] as f32 });
        if let Ok(s) = r { prop_assert!(fin(&s), "{:?}", s); }
        let sc = SliderCrank::<f64> { crank: v[7], rod: v[8], offset: v[9] };
        let r = sc.solve(&SliderCrankInput { theta: v[4] }, &SliderCrankInput { theta: v[5] }, &SliderCrankInput { theta: v[6] });
        if let Ok(s) = r { prop_assert!(fin(&s), "{:?}", s); }
        let five = FiveBar::<f64> { base: v[0], proximal: v[7], distal: v[8] };
        let (q, w) = (FiveBarInput { q1: v[4], q2: v[9] }, FiveBarInput { q1: v[5], q2: v[1] });
        if let Ok(p) = five.position(&q) {
            prop_assert!(fin(&p), "{:?}", p);
            if let Ok(vel) = five.velocity(&p, &w) {
                prop_assert!(fin(&vel), "{:?}", vel);
            }
        }
    }

    /// Proves: every core group and the actuator, called directly with
    /// absurd points, lengths, offsets, directions and velocities, never
    /// panic; every `Ok` is finite, and every velocity's `condition` lies in
    /// `(16 eps, 1]`.
    #[test]
    fn core_groups_never_panic_never_non_finite(v in prop::collection::vec(absurd(), 16)) {
        let pt = |i: usize| Point2::new(v[i], v[i + 1]);
        let vc = |i: usize| Vector2::new(v[i], v[i + 1]);
        let mode = if v[15] > 0.0 { Mode::Plus } else { Mode::Minus };
        let cond_ok = |c: f64| c > 16.0 * f64::EPSILON && c <= 1.0;
        let g1 = Line { origin: pt(0), dir: vc(2) };
        let g2 = Line { origin: pt(4), dir: vc(6) };
        if let Ok(pos) = rrr::position(&pt(0), v[8], &pt(2), v[9], mode) {
            prop_assert!(fin(&pos));
            if let Ok(vel) = rrr::velocity(&pos, Some(&vc(10)), Some(&vc(12))) {
                prop_assert!(fin(&vel) && cond_ok(vel.condition));
                if let Ok(acc) = rrr::acceleration(&pos, &vel, Some(&vc(12)), None) {
                    prop_assert!(fin(&acc));
                }
            }
        }
        if let Ok(pos) = actuator::position(&pt(0), v[8], &pt(2), v[9], mode) {
            if let Ok(vel) = actuator::velocity(&pos, Some(&vc(10)), None, v[14]) {
                prop_assert!(fin(&vel) && cond_ok(vel.condition));
            }
        }
        if let Ok(pos) = rrp::position(&pt(10), v[8], &g1, v[9], mode) {
            prop_assert!(fin(&pos));
            if let Ok(vel) = rrp::velocity(&pos, &g1, Some(&vc(12)), None) {
                prop_assert!(fin(&vel) && cond_ok(vel.condition));
            }
        }
        if let Ok(pos) = rpr::position(&pt(10), &pt(0), v[8], mode) {
            prop_assert!(fin(&pos));
            if let Ok(vel) = rpr::velocity(&pos, &pt(10), &pt(0), Some(&vc(12)), None) {
                prop_assert!(fin(&vel) && cond_ok(vel.condition));
            }
        }
        if let Ok(pos) = prp::position(&g1, v[8], &g2, v[9]) {
            prop_assert!(fin(&pos));
            if let Ok(vel) = prp::velocity(&pos, &g1, &g2, None, None) {
                prop_assert!(fin(&vel) && cond_ok(vel.condition));
            }
        }
        if let Ok(pos) = rpp::position(&pt(10), &g1, v[8], &vc(6)) {
            prop_assert!(fin(&pos));
            if let Ok(vel) = rpp::velocity(&pos, &pt(10), &g1, Some(&vc(12)), None) {
                prop_assert!(fin(&vel) && cond_ok(vel.condition));
            }
        }
    }
}
