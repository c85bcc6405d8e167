//! The working range each core primitive's doc comment promises, checked at
//! its boundaries: just inside, the result is accurate against an
//! independent computation (the double-double reference of
//! `mechanism-reference`, carried to the boundary by an exact power-of-two
//! scaling of a unit-scale case, or `std`'s `f64` functions for `f32`
//! results, or a closed form); just outside, the typed error the doc
//! promises, or, where the doc promises nothing beyond, at least no silent
//! answer (an `Err`, or an `Ok` that is finite and closes). One module per
//! primitive: crank (angle, `(cos, sin)` pair, link angle), slider, linear
//! actuator, RRR, RRP, RPR, PRP, RPP, link points, linsolve, force groups.
//! The regressions of the findings that set these ranges are in
//! `edge_regressions.rs`.

use mechanism_core::driver::{actuator, crank, slider};
use mechanism_core::dyad::{prp, rpp, rpr, rrp, rrr};
use mechanism_core::geometry::wrap_angle;
use mechanism_core::guide::Line;
use mechanism_core::{link, linsolve, Error, Fault, Mode, Point2, Real, Vector2};
use mechanism_reference::groups as reference;
use mechanism_reference::Dd;

/// `2^j` as an `f64` (exact for `j` in -1074 ..= 1023).
fn pow2(j: i32) -> f64 {
    if j < -1000 {
        2f64.powi(j + 100) * 2f64.powi(-100)
    } else {
        2f64.powi(j)
    }
}

fn p<T: Real>(x: f64, y: f64) -> Point2<T> {
    Point2::new(T::lit(x), T::lit(y))
}

fn vec2<T: Real>(x: f64, y: f64) -> Vector2<T> {
    Vector2::new(T::lit(x), T::lit(y))
}

/// `|got - want| / |want|`, componentwise largest over the pairs, in f64.
fn rel<T: Real>(got: &[T], want: &[f64]) -> f64 {
    let scale = want.iter().fold(0.0f64, |m, w| m.max(w.abs()));
    got.iter()
        .zip(want)
        .map(|(g, w)| (g.as_f64() - w).abs())
        .fold(0.0, f64::max)
        / scale
}

/// The fault kind of an error, for assertions.
fn kind<T: Real>(e: &Error<T>) -> &'static str {
    match e.fault {
        Fault::CannotAssemble { .. } => "CannotAssemble",
        Fault::Singular { .. } => "Singular",
        Fault::NonFinite { .. } => "NonFinite",
        Fault::NonPositive { .. } => "NonPositive",
        Fault::Negative { .. } => "Negative",
        _ => "another fault",
    }
}

mod crank_driver {
    use super::*;

    /// `crank::position`: angles below `angle_limit` (f32 2^24, f64 2^53)
    /// and positive lengths whose tip is finite. Inside: the tip within 2
    /// ulp of `r (cos, sin)` of the angle (against `std`'s `f64` sine and
    /// cosine, exact enough for an `f32` result), at angles from 0 to just
    /// below the limit and lengths from the smallest normal number to a
    /// quarter of the largest. Outside: an angle at or beyond the limit, a
    /// non-finite angle or length, or a tip that overflows is `NonFinite`,
    /// a length `<= 0` `NonPositive`.
    fn position_range<T: Real>(angles: &[f64], beyond: &[f64], max: f64, min_normal: f64) {
        let eps = T::eps().as_f64();
        for &th in angles {
            for r in [min_normal, 1.0, max / 4.0] {
                let th_t = T::lit(th);
                let got = crank::position(&p::<T>(0.0, 0.0), T::lit(r), th_t)
                    .unwrap_or_else(|e| panic!("theta {th:e}, r {r:e}: {e:?}"));
                let (s, c) = th_t.as_f64().sin_cos();
                let err = rel(&[got.tip.x, got.tip.y], &[r * c, r * s]);
                // rel is against max(|r c|, |r s|) >= r / sqrt 2: 2 ulp of
                // r in the worst component, sqrt 2 for the normalization.
                assert!(err <= 3.0 * eps, "theta {th:e}, r {r:e}: {err:e}");
            }
        }
        let o = p::<T>(0.0, 0.0);
        let e = |r: Result<crank::CrankPosition<T>, Error<T>>| kind(&r.unwrap_err());
        for &th in beyond {
            for th in [th, -th] {
                let got = crank::position(&o, T::one(), T::lit(th));
                assert_eq!(e(got), "NonFinite", "{th:e}");
            }
        }
        assert_eq!(
            e(crank::position(&o, T::lit(1.0), T::lit(f64::NAN))),
            "NonFinite"
        );
        assert_eq!(
            e(crank::position(&o, T::one(), T::lit(f64::INFINITY))),
            "NonFinite"
        );
        assert_eq!(e(crank::position(&o, T::zero(), T::one())), "NonPositive");
        assert_eq!(
            e(crank::position(&o, T::lit(-1.0), T::one())),
            "NonPositive"
        );
        assert_eq!(
            e(crank::position(&o, T::lit(f64::NAN), T::one())),
            "NonFinite"
        );
        // Pivot and length both near the largest number: the tip overflows.
        let far = p::<T>(max, 0.0);
        assert_eq!(
            e(crank::position(&far, T::lit(max), T::zero())),
            "NonFinite"
        );
    }

    #[test]
    fn f64_crank_position_range() {
        let angles = [
            0.0,
            1.0,
            -3.0,
            core::f64::consts::PI,
            1e5,
            1.0e5 + 1.0,
            4e12,
            9_007_199_254_740_990.0,
        ];
        let beyond = [9_007_199_254_740_992.0, 1.3e17, f64::MAX, f64::INFINITY];
        position_range::<f64>(&angles, &beyond, f64::MAX, f64::MIN_POSITIVE);
    }

    #[test]
    fn f32_crank_position_range() {
        let angles = [
            0.0,
            1.0,
            -3.0,
            core::f32::consts::PI as f64,
            1e5,
            1.0e5 + 1.0,
            16_777_215.0,
        ];
        let beyond = [16_777_216.0, 2.2e8, 4e12, f32::MAX as f64];
        position_range::<f32>(&angles, &beyond, f32::MAX as f64, f32::MIN_POSITIVE as f64);
    }

    /// `crank::position_cos_sin`: "any positive multiple" of the pair, for
    /// every finite non-zero pair, from the smallest subnormal to the
    /// largest finite components. Inside: `|tip - O| = r` within 2 eps and
    /// the tip along the pair (cross product within 2 eps of `r`), against
    /// the pair's direction in `f64` (`hypot`, which scales). Outside: a
    /// zero pair is `NonPositive`, a non-finite one `NonFinite`.
    fn cos_sin_range<T: Real>(mults: &[f64]) {
        let eps = T::eps().as_f64();
        let r = 101.6;
        for &m in mults {
            for th in [0.5f64, 2.0, -1.0, 3.0] {
                let (c, s) = (T::lit(th.cos() * m), T::lit(th.sin() * m));
                if c == T::zero() && s == T::zero() {
                    continue;
                }
                let got = crank::position_cos_sin(&p::<T>(0.0, 0.0), T::lit(r), c, s)
                    .unwrap_or_else(|e| panic!("pair x {m:e}: {e:?}"));
                let (cd, sd) = (c.as_f64(), s.as_f64());
                let n = cd.hypot(sd);
                let (ux, uy) = (cd / n, sd / n);
                let (x, y) = (got.tip.x.as_f64(), got.tip.y.as_f64());
                let radius = x.hypot(y);
                assert!(
                    (radius - r).abs() <= 2.0 * eps * r,
                    "pair ({cd:e}, {sd:e}): radius {radius} for {r}"
                );
                let off = (ux * y - uy * x).abs();
                assert!(
                    off <= 2.0 * eps * r,
                    "pair ({cd:e}, {sd:e}): off its direction by {off:e}"
                );
            }
        }
        let o = p::<T>(0.0, 0.0);
        let e = |r: Result<crank::CrankPosition<T>, Error<T>>| kind(&r.unwrap_err());
        assert_eq!(
            e(crank::position_cos_sin(&o, T::one(), T::zero(), T::zero())),
            "NonPositive"
        );
        assert_eq!(
            e(crank::position_cos_sin(
                &o,
                T::one(),
                T::lit(f64::NAN),
                T::one()
            )),
            "NonFinite"
        );
        assert_eq!(
            e(crank::position_cos_sin(
                &o,
                T::one(),
                T::one(),
                T::lit(f64::INFINITY)
            )),
            "NonFinite"
        );
    }

    #[test]
    fn f64_cos_sin_range() {
        cos_sin_range::<f64>(&[
            pow2(-1074) * 3.0,
            pow2(-1060),
            1e-161,
            1e-150,
            1.0,
            1e150,
            1e300,
            f64::MAX / 1.5,
        ]);
    }

    #[test]
    fn f32_cos_sin_range() {
        cos_sin_range::<f32>(&[
            pow2(-149) * 3.0,
            pow2(-140),
            4e-23,
            1e-19,
            1.0,
            1e19,
            1e37,
            f32::MAX as f64 / 1.5,
        ]);
    }

    /// The link angle (`geometry::wrap_angle`, what the generated code
    /// reports for a crank): in `(-pi, pi]` of the type for every finite
    /// input; below `angle_limit` (f32 2^24, f64 2^53) within `2 |theta|
    /// eps` of the angle of `(cos theta, sin theta)` from `std`'s `f64`
    /// functions (exact for `f32` inputs, glibc's reduction for `f64`
    /// ones): the documented `|theta| eps` and one rounding; beyond (the
    /// crank reports such an angle as an error), in the range only.
    fn wrap_range<T: Real>(inputs: &[f64]) {
        let eps = T::eps().as_f64();
        let pi = T::pi();
        for &x in inputs {
            for x in [x, -x] {
                let xt = T::lit(x);
                let got = wrap_angle(xt);
                assert!(got <= pi && got > -pi, "{x:e}: {got:e}");
                let xd = xt.as_f64();
                let (s, c) = xd.sin_cos();
                let want = s.atan2(c);
                // Compare as directions (a result near +-pi may be on
                // either side of the cut).
                let d = (got.as_f64() - want).sin().abs();
                let limit = mechanism_core::geometry::angle_limit::<T>().as_f64();
                if xd.abs() < limit {
                    let bound = 2.0 * eps * xd.abs().max(4.0);
                    assert!(
                        d <= bound,
                        "{x:e}: {got:e} against {want:e} ({d:e} > {bound:e})"
                    );
                }
            }
        }
        assert!(wrap_angle(T::lit(f64::NAN)).as_f64().is_nan());
        assert!(wrap_angle(T::lit(f64::INFINITY)).as_f64().is_nan());
    }

    #[test]
    fn f32_wrap_angle_range() {
        wrap_range::<f32>(&[
            0.0,
            1.0,
            core::f32::consts::PI as f64,
            f32::from_bits(core::f32::consts::PI.to_bits() + 1) as f64,
            7.0,
            1e3,
            99_999.99,
            1e5,
            100_000.01,
            2.2e8,
            4e12,
            1e30,
            f32::MAX as f64,
        ]);
    }

    #[test]
    fn f64_wrap_angle_range() {
        wrap_range::<f64>(&[
            0.0,
            1.0,
            core::f64::consts::PI,
            f64::from_bits(core::f64::consts::PI.to_bits() + 1),
            7.0,
            1e3,
            99_999.999,
            1e5,
            100_000.000_001,
            1e12,
            1.3e17,
            1e300,
            f64::MAX,
        ]);
    }
}

mod slider_driver {
    use super::*;

    /// `slider::position`: any finite displacement and offset whose pin is
    /// finite, exact to one rounding per term (against the double-double
    /// `origin + s dir + offset perp(dir)`), at `s` up to a quarter of the
    /// largest number; a non-finite `s` or offset is `NonFinite`, and so is
    /// a pin that overflows.
    fn range<T: Real>(max: f64) {
        let eps = T::eps().as_f64();
        let g = Line {
            origin: p::<T>(0.5, -0.25),
            dir: vec2::<T>(0.6, 0.8),
        };
        for s in [0.0, 1e-30, 1.0, -3.0, max / 4.0] {
            let pin = slider::position(&g, T::lit(0.125), T::lit(s)).unwrap().p;
            let (ox, oy, dx, dy) = (
                g.origin.x.as_f64(),
                g.origin.y.as_f64(),
                g.dir.x.as_f64(),
                g.dir.y.as_f64(),
            );
            let sd = T::lit(s).as_f64();
            let want = [
                (Dd::from(ox) + Dd::from(sd) * Dd::from(dx) - Dd::from(0.125) * Dd::from(dy))
                    .to_f64(),
                (Dd::from(oy) + Dd::from(sd) * Dd::from(dy) + Dd::from(0.125) * Dd::from(dx))
                    .to_f64(),
            ];
            assert!(rel(&[pin.x, pin.y], &want) <= 3.0 * eps, "s {s:e}");
        }
        let e = |r: Result<slider::SliderPosition<T>, Error<T>>| kind(&r.unwrap_err());
        assert_eq!(
            e(slider::position(&g, T::zero(), T::lit(f64::NAN))),
            "NonFinite"
        );
        assert_eq!(
            e(slider::position(&g, T::lit(f64::INFINITY), T::one())),
            "NonFinite"
        );
        let far = Line {
            origin: p::<T>(max, max),
            dir: g.dir,
        };
        assert_eq!(
            e(slider::position(&far, T::zero(), T::lit(max))),
            "NonFinite"
        );
    }

    #[test]
    fn f64_slider_range() {
        range::<f64>(f64::MAX);
    }

    #[test]
    fn f32_slider_range() {
        range::<f32>(f32::MAX as f64);
    }
}

/// A unit-scale RRR (and actuator) case: `A = (0.3, -0.2)`, `l1 = 1.3`,
/// `l2 = 0.9`, `B` at distance 1.5 from `A` at 0.4 rad; all scaled by `2^j`.
fn rrr_case<T: Real>(j: i32) -> (Point2<T>, T, Point2<T>, T) {
    let s = pow2(j);
    let (sin, cos) = 0.4f64.sin_cos();
    (
        p(0.3 * s, -0.2 * s),
        T::lit(1.3 * s),
        p((0.3 + 1.5 * cos) * s, (-0.2 + 1.5 * sin) * s),
        T::lit(0.9 * s),
    )
}

mod rrr_group {
    use super::*;

    /// The RRR's position at scale `2^j` against the double-double
    /// reference for its own rounded inputs (scaled back to unit size by
    /// `2^-j`, exact): the error in units of `eps l1 / kappa` (kappa is 0.75
    /// here), `dyad::rrr`'s own measure.
    fn position_at<T: Real>(j: i32) -> Result<f64, Error<T>> {
        let (a, l1, b, l2) = rrr_case::<T>(j);
        let got = rrr::position(&a, l1, &b, l2, Mode::Plus)?;
        let s = pow2(j);
        let u = |x: T| x.as_f64() / s;
        let want = reference::rrr_position(
            reference::v(u(a.x), u(a.y)),
            u(l1),
            reference::v(u(b.x), u(b.y)),
            u(l2),
            true,
        )
        .expect("the reference assembles");
        let w = reference::to_f64(want);
        let err = (u(got.c.x) - w[0]).abs().max((u(got.c.y) - w[1]).abs());
        Ok(err / (T::eps().as_f64() * 1.3 / 0.75))
    }

    /// Position: the group's scale `l1 + l2` within `2^-42 .. 2^42` in f32
    /// (2.3e-13 .. 4.4e12), `2^-340 .. 2^340` in f64, where its third powers
    /// are normal numbers (`dyad::rrr`'s documented range; `l1 + l2` is
    /// `2.2 2^j` here). Inside, within 4 of the unit above, at both ends and
    /// between; beyond either end `NonFinite`, or `Singular` where `|B - A|^2` itself
    /// leaves the normal range (never a silent answer).
    #[test]
    fn position_range() {
        for j in [-42, -36, -20, 0, 20, 36, 40] {
            let w = position_at::<f32>(j).unwrap_or_else(|e| panic!("f32 2^{j}: {e:?}"));
            assert!(w <= 4.0, "f32 2^{j}: {w}");
        }
        for j in [-341, -300, 0, 300, 338] {
            let w = position_at::<f64>(j).unwrap_or_else(|e| panic!("f64 2^{j}: {e:?}"));
            assert!(w <= 4.0, "f64 2^{j}: {w}");
        }
        for j in [-126, -64, -45, 42, 60] {
            let k = kind(&position_at::<f32>(j).unwrap_err());
            assert!(["NonFinite", "Singular"].contains(&k), "f32 2^{j}: {k}");
        }
        for j in [-1000, -343, 341, 500] {
            let k = kind(&position_at::<f64>(j).unwrap_err());
            assert!(["NonFinite", "Singular"].contains(&k), "f64 2^{j}: {k}");
        }
    }

    /// Below the normal range (subnormal lengths) nothing is promised but
    /// no silent answer: an `Err`, or an `Ok` whose joint is within 16
    /// subnormal spacings (2^-149 in f32, 2^-1074 in f64: the absolute
    /// rounding there, against which a length of 2^-145 has 4 bits) plus
    /// `4 eps l1 / kappa` of the reference for its own rounded inputs.
    #[test]
    fn below_the_normal_range_no_silent_answer() {
        fn check<T: Real>(j: i32, spacing: f64) {
            if let Ok(w) = position_at::<T>(j) {
                let unit = T::eps().as_f64() * 1.3 / 0.75;
                let err = w * unit * pow2(j);
                assert!(
                    err <= 16.0 * spacing + 4.0 * unit * pow2(j),
                    "2^{j}: {err:e}"
                );
            }
        }
        for j in [-130, -135, -140, -145] {
            check::<f32>(j, pow2(-149));
        }
        for j in [-1030, -1050, -1070] {
            check::<f64>(j, pow2(-1074));
        }
    }

    /// Rates, over the position's range of scale (where the determinant
    /// `cross(r1, r2)`, L^2, is a normal number too): `omega1`, `omega2` at
    /// scale `2^j` (rates of the joints times `2^j`, so the angular rates
    /// are scale-free) equal the unit-scale double-double rates within `8
    /// eps / kappa^2`, at both ends; beyond, the position's error.
    fn rates_at<T: Real>(j: i32) -> Result<f64, Error<T>> {
        let (a, l1, b, l2) = rrr_case::<T>(j);
        let pos = rrr::position(&a, l1, &b, l2, Mode::Plus)?;
        let s = pow2(j);
        let vb = vec2::<T>(0.7 * s, -0.3 * s);
        let got = rrr::velocity_lengths(&pos, l1, l2, None, Some(&vb))?;
        let (a0, l10, b0, l20) = rrr_case::<f64>(0);
        let (va0, vb0) = (reference::v(a0.x, a0.y), reference::v(b0.x, b0.y));
        let c = reference::rrr_position(va0, l10, vb0, l20, true).unwrap();
        let (w1, w2) =
            reference::rrr_rates(va0, vb0, c, reference::v(0.0, 0.0), reference::v(0.7, -0.3))
                .unwrap();
        let err = (got.omega1.as_f64() - w1.to_f64())
            .abs()
            .max((got.omega2.as_f64() - w2.to_f64()).abs());
        Ok(err / (T::eps().as_f64() / (0.75 * 0.75)))
    }

    #[test]
    fn rates_range() {
        for j in [-42, -20, 0, 20, 40] {
            let w = rates_at::<f32>(j).unwrap_or_else(|e| panic!("f32 2^{j}: {e:?}"));
            assert!(w <= 8.0, "f32 2^{j}: {w}");
        }
        for j in [-341, -200, 0, 200, 338] {
            let w = rates_at::<f64>(j).unwrap_or_else(|e| panic!("f64 2^{j}: {e:?}"));
            assert!(w <= 8.0, "f64 2^{j}: {w}");
        }
        for j in [-66, -45, 42] {
            assert!(rates_at::<f32>(j).is_err(), "f32 2^{j}");
        }
    }

    /// Assembly: inside the rounding band `4 eps (l1 + l2)` beyond either
    /// edge the joint is put on the line at `l1` from `A` (`|C - A| = l1`
    /// within 2 eps); beyond the band `CannotAssemble`.
    #[test]
    fn assembly_edges() {
        let eps = f64::EPSILON;
        let a = Point2::new(0.0, 0.0);
        for (l1, l2) in [(1.0, 2.0), (2.0, 1.0), (1.0, 1.0 - 2.0 * eps)] {
            let (sum, diff) = (l1 + l2, f64::abs(l1 - l2));
            for (edge, sign) in [(sum, 1.0), (diff, -1.0)] {
                for k in [0.5, 2.0, 3.5] {
                    let d = edge + sign * k * eps * sum;
                    if d <= 0.0 {
                        continue;
                    }
                    let c = rrr::position(&a, l1, &Point2::new(d, 0.0), l2, Mode::Plus)
                        .unwrap_or_else(|e| panic!("{l1} {l2} at {d:e}: {e:?}"));
                    let r = c.c.coords.norm();
                    assert!(
                        (r - l1).abs() <= 2.0 * eps * l1,
                        "{l1} {l2} at {d:e}: |C - A| = {r}"
                    );
                }
                let d = edge + sign * 5.0 * eps * sum;
                if d > 0.0 {
                    let e =
                        rrr::position(&a, l1, &Point2::new(d, 0.0), l2, Mode::Plus).unwrap_err();
                    assert_eq!(kind(&e), "CannotAssemble", "{l1} {l2} at {d:e}");
                }
            }
        }
    }
}

mod actuator_driver {
    use super::*;

    /// The actuator's position is the RRR's (cylinder length as `l2`): the
    /// same range, checked at its ends against the RRR at unit scale times
    /// `2^j` (bit for bit: both scalings exact, and the same code); beyond
    /// the top, `NonFinite` attributed to the actuator.
    #[test]
    fn position_range() {
        for j in [-42, 0, 40] {
            let (a, l, b, len) = rrr_case::<f32>(j);
            let got = actuator::position(&a, l, &b, len, Mode::Minus).unwrap();
            let unit = {
                let (a, l, b, len) = rrr_case::<f32>(0);
                actuator::position(&a, l, &b, len, Mode::Minus).unwrap()
            };
            let s = pow2(j) as f32;
            let close = |x: f32, y: f32| (x - y * s).abs() <= 4.0 * f32::EPSILON * 1.3 * s;
            assert!(
                close(got.c.x, unit.c.x) && close(got.c.y, unit.c.y),
                "2^{j}"
            );
        }
        let (a, l, b, len) = rrr_case::<f32>(42);
        let e = actuator::position(&a, l, &b, len, Mode::Minus).unwrap_err();
        assert_eq!(
            (e.primitive, kind(&e)),
            (mechanism_core::Primitive::Actuator, "NonFinite")
        );
    }
}

/// Unit-scale cases of the groups that slide, scaled by `2^j`.
mod sliding_groups {
    use super::*;

    fn line<T: Real>(s: f64, ox: f64, oy: f64, angle: f64) -> Line<T> {
        Line {
            origin: p(ox * s, oy * s),
            dir: vec2(angle.cos(), angle.sin()),
        }
    }

    /// `x` (at `2^j`) equals `x0` (at 1) times `2^j`, to `4 eps` of the
    /// largest (documented: bit for bit for the scalings of the group's
    /// range; 4 eps allows other platforms' libm in the unit case only).
    fn scaled<T: Real>(j: i32, got: &[T], unit: &[T]) -> bool {
        let s = pow2(j);
        let want: Vec<f64> = unit.iter().map(|u| u.as_f64() * s).collect();
        rel(got, &want) <= 4.0 * T::eps().as_f64()
    }

    /// RRP: documented accurate at f32 lengths 1e-30 .. 1e34 and f64
    /// 1e-150 .. 1e150 against the reference, bit for bit scale-invariant
    /// for f32 1.7e-23 .. 1.6e30 and f64 1e-301 .. 1e295. Checked: the
    /// unit case against the double-double reference (within `2 eps l /
    /// kappa`, kappa 0.8 here), and at the ends of the invariant range
    /// against it times `2^j` (positions and rates); beyond the top (f32
    /// 2^125), no silent answer.
    #[test]
    fn rrp_range() {
        fn at<T: Real>(j: i32) -> Result<Vec<T>, Error<T>> {
            let s = pow2(j);
            let g = line::<T>(s, 0.0, 0.3, 0.2);
            let a = p::<T>(0.1 * s, -0.4 * s);
            let pos = rrp::position(&a, T::lit(1.0 * s), &g, T::lit(0.05 * s), Mode::Plus)?;
            let va = vec2::<T>(0.3 * s, 0.2 * s);
            let v = rrp::velocity(&pos, &g, Some(&va), None)?;
            Ok(vec![pos.c.x, pos.c.y, v.vc.x, v.vc.y, v.s_dot])
        }
        let unit32 = at::<f32>(0).unwrap();
        let unit64 = at::<f64>(0).unwrap();
        let g = reference::Line::new([0.0, 0.3], [0.2f64.cos(), 0.2f64.sin()]);
        let (c, _) = reference::rrp_position(reference::v(0.1, -0.4), 1.0, &g, 0.05, true).unwrap();
        let c = reference::to_f64(c);
        assert!(rel(&unit64[..2], &c) <= 2.0 * f64::EPSILON / 0.8);
        assert!(rel(&unit32[..2], &c) <= 2.0 * f32::EPSILON as f64 / 0.8);
        for j in [-76, -40, 40, 100] {
            assert!(scaled(j, &at::<f32>(j).unwrap(), &unit32), "f32 2^{j}");
        }
        for j in [-1000, -500, 500, 980] {
            assert!(scaled(j, &at::<f64>(j).unwrap(), &unit64), "f64 2^{j}");
        }
        if let Ok(x) = at::<f32>(125) {
            assert!(scaled(125, &x, &unit32), "f32 2^125: a silent answer");
        }
    }

    /// RPR: accurate f32 1e-30 .. 1e34, f64 1e-150 .. 1e150; bit for bit
    /// scale-invariant f32 1e-30 .. 1e30 (2^-100 ..= 2^100), f64 1e-301 ..
    /// 1e295. The unit case against the reference's slide, the ends
    /// against it times `2^j`.
    #[test]
    fn rpr_range() {
        fn at<T: Real>(j: i32) -> Result<Vec<T>, Error<T>> {
            let s = pow2(j);
            let (a, b) = (p::<T>(0.4 * s, 0.9 * s), p::<T>(-0.2 * s, 0.1 * s));
            let pos = rpr::position(&a, &b, T::lit(0.1 * s), Mode::Plus)?;
            let va = vec2::<T>(0.5 * s, -0.1 * s);
            let v = rpr::velocity(&pos, &a, &b, Some(&va), None)?;
            Ok(vec![pos.s, v.s_dot])
        }
        let (unit32, unit64) = (at::<f32>(0).unwrap(), at::<f64>(0).unwrap());
        let (_, s) =
            reference::rpr_position(reference::v(0.4, 0.9), reference::v(-0.2, 0.1), 0.1, true)
                .unwrap();
        assert!(rel(&unit64[..1], &[s.to_f64()]) <= 2.0 * f64::EPSILON);
        assert!(rel(&unit32[..1], &[s.to_f64()]) <= 2.0 * f32::EPSILON as f64);
        for j in [-100, 100] {
            assert!(scaled(j, &at::<f32>(j).unwrap(), &unit32), "f32 2^{j}");
        }
        for j in [-1000, 980] {
            assert!(scaled(j, &at::<f64>(j).unwrap(), &unit64), "f64 2^{j}");
        }
    }

    /// PRP and RPP: "f32 lengths 1e-30 .. 1e36, f64 1e-300 .. 1e306, bit
    /// for bit scale-invariant there": checked at 2^-100 and 2^119 (f32),
    /// 2^-996 and 2^1016 (f64) against the unit case times `2^j`, and the
    /// unit case against the reference.
    #[test]
    fn prp_and_rpp_range() {
        fn prp_at<T: Real>(j: i32) -> Result<Vec<T>, Error<T>> {
            let s = pow2(j);
            let (g1, g2) = (line::<T>(s, 0.0, 0.0, 0.3), line::<T>(s, 1.0, 0.2, 1.9));
            let pos = prp::position(&g1, T::lit(0.1 * s), &g2, T::lit(-0.05 * s))?;
            Ok(vec![pos.c.x, pos.c.y, pos.s1, pos.s2])
        }
        fn rpp_at<T: Real>(j: i32) -> Result<Vec<T>, Error<T>> {
            let s = pow2(j);
            let g = line::<T>(s, 0.0, 0.0, 1.5);
            let a = p::<T>(0.7 * s, 0.3 * s);
            let slot = vec2::<T>(0.0, -1.0);
            let pos = rpp::position(&a, &g, T::lit(0.02 * s), &slot)?;
            Ok(vec![pos.q.x, pos.q.y, pos.s1, pos.s2])
        }
        let (u32p, u64p) = (prp_at::<f32>(0).unwrap(), prp_at::<f64>(0).unwrap());
        let (g1, g2) = (
            reference::Line::new([0.0, 0.0], [0.3f64.cos(), 0.3f64.sin()]),
            reference::Line::new([1.0, 0.2], [1.9f64.cos(), 1.9f64.sin()]),
        );
        let (c, _, _) = reference::prp_position(&g1, 0.1, &g2, -0.05).unwrap();
        let c = reference::to_f64(c);
        assert!(rel(&u64p[..2], &c) <= 4.0 * f64::EPSILON);
        assert!(rel(&u32p[..2], &c) <= 4.0 * f32::EPSILON as f64);
        let (u32r, u64r) = (rpp_at::<f32>(0).unwrap(), rpp_at::<f64>(0).unwrap());
        for j in [-100, 119] {
            assert!(
                scaled(j, &prp_at::<f32>(j).unwrap(), &u32p),
                "PRP f32 2^{j}"
            );
            assert!(
                scaled(j, &rpp_at::<f32>(j).unwrap(), &u32r),
                "RPP f32 2^{j}"
            );
        }
        for j in [-996, 1016] {
            assert!(
                scaled(j, &prp_at::<f64>(j).unwrap(), &u64p),
                "PRP f64 2^{j}"
            );
            assert!(
                scaled(j, &rpp_at::<f64>(j).unwrap(), &u64r),
                "RPP f64 2^{j}"
            );
        }
    }
}

mod link_points {
    use super::*;

    /// `link::point_position`, `point_velocity`, `point_sum`: any finite
    /// inputs whose result is finite, to one rounding per term (against
    /// the double-double `origin + x axis + y perp(axis)`); a result that
    /// overflows is `NonFinite` (f32 and f64).
    fn range<T: Real>(max: f64) {
        let eps = T::eps().as_f64();
        let axis = vec2::<T>(0.6, 0.8);
        for s in [1e-30, 1.0, max / 8.0] {
            let o = p::<T>(0.5 * s, -0.25 * s);
            let local = vec2::<T>(1.5 * s, -0.75 * s);
            let got = link::point_position(&o, &axis, &local).unwrap();
            let d = |x: T| Dd::from(x.as_f64());
            let want = [
                (d(o.x) + d(axis.x) * d(local.x) - d(axis.y) * d(local.y)).to_f64(),
                (d(o.y) + d(axis.y) * d(local.x) + d(axis.x) * d(local.y)).to_f64(),
            ];
            assert!(rel(&[got.x, got.y], &want) <= 4.0 * eps, "scale {s:e}");
        }
        let o = p::<T>(max, max);
        let local = vec2::<T>(max, 0.0);
        assert_eq!(
            kind(&link::point_position(&o, &axis, &local).unwrap_err()),
            "NonFinite"
        );
        let off = vec2::<T>(max / 2.0, max / 2.0);
        assert_eq!(
            kind(&link::point_velocity(&off, T::lit(4.0)).unwrap_err()),
            "NonFinite"
        );
        let base = vec2::<T>(max / 1.5, 0.0);
        assert_eq!(
            kind(&link::point_sum(&base, vec2::<T>(max / 1.5, 0.0)).unwrap_err()),
            "NonFinite"
        );
        assert!(link::point_sum(&base, vec2::<T>(-max / 1.5, 1.0)).is_ok());
    }

    #[test]
    fn f64_link_point_range() {
        range::<f64>(f64::MAX);
    }

    #[test]
    fn f32_link_point_range() {
        range::<f32>(f32::MAX as f64);
    }
}

mod linear_solver {
    use super::*;

    /// `linsolve::solve`: `Singular` exactly when a pivot of the
    /// equilibrated elimination is at most `PIVOT_TOLERANCE N eps`. The
    /// 2x2 system `[[1, 1], [1, 1 + d]] x = [2, 2 + d]` (solution (1, 1))
    /// has the second pivot `d` after equilibration: `d = 4 eps` (above
    /// the tolerance `2 eps`) is solved, accurate to `eps / d` relative
    /// (its conditioning) against the exact (1, 1); `d = eps` and `d = 0`
    /// are `Singular`; NaN and overflow are `NonFinite`.
    fn range<T: Real>() {
        let eps = T::eps();
        let sys = |d: T| {
            (
                [[T::one(), T::one()], [T::one(), T::one() + d]],
                [T::lit(2.0), T::lit(2.0) + d],
            )
        };
        for k in [4.0, 16.0, 1e3] {
            let d = eps * T::lit(k);
            let (a, b) = sys(d);
            let x = linsolve::solve(a, b)
                .unwrap_or_else(|e| panic!("d = {k} eps: {e:?}"))
                .x;
            let err = rel(&x, &[1.0, 1.0]);
            assert!(
                err <= 4.0 * eps.as_f64() / d.as_f64() + 4.0 * eps.as_f64(),
                "d = {k} eps: {err:e}"
            );
        }
        for d in [eps, T::zero()] {
            let (a, b) = sys(d);
            assert_eq!(kind(&linsolve::solve(a, b).unwrap_err()), "Singular");
        }
        let (mut a, b) = sys(T::one());
        a[0][1] = T::lit(f64::NAN);
        assert_eq!(kind(&linsolve::solve(a, b).unwrap_err()), "NonFinite");
        let big = T::lit(if eps.as_f64() > 1e-10 { 3e38 } else { 1.7e308 });
        let a = [[T::lit(1e-30), T::zero()], [T::zero(), T::one()]];
        assert_eq!(
            kind(&linsolve::solve(a, [big, T::one()]).unwrap_err()),
            "NonFinite"
        );
    }

    #[test]
    fn f64_linsolve_range() {
        range::<f64>();
    }

    #[test]
    fn f32_linsolve_range() {
        range::<f32>();
    }
}

mod force_groups {
    use super::*;
    use mechanism_core::force::{rrr as rrr_force, Wrench};

    /// RRR reactions (the force groups share `group::solve`): accurate
    /// (against the double-double Newton-Euler reference, moments about
    /// each link's outer joint, a different formulation) to `eps / s` of
    /// the loads as the links' angle `s` falls to the documented limit
    /// (relative pivot `4 eps`): at `s` = 1e-2 and 1e-8 within `8 eps / s`
    /// of the largest reaction; at the toggle (`s = 0`) `Singular`; a
    /// non-finite load `NonFinite`.
    #[test]
    fn rrr_reactions_range() {
        let eps = f64::EPSILON;
        for s in [1e-2, 1e-8, 0.0] {
            let (a, b) = (Point2::new(0.0, 0.0), Point2::new(2.0, 0.0));
            // C above the middle: the links' angle is 2 atan(h) ~ s.
            let c = Point2::new(1.0, s / 2.0);
            let f1 = Vector2::new(3.0, -2.0);
            let f2 = Vector2::new(-1.0, 4.0);
            let (p1, p2) = (Point2::new(0.5, s / 4.0), Point2::new(1.5, s / 4.0));
            // Loads as wrenches about C (the group's convention).
            let load1 = Wrench::force_at(&f1, &p1, &c).with_couple(0.3);
            let load2 = Wrench::force_at(&f2, &p2, &c).with_couple(-0.2);
            let got = rrr_force::reactions(&a, &b, &c, &load1, &load2);
            if s == 0.0 {
                assert_eq!(kind(&got.unwrap_err()), "Singular");
                continue;
            }
            let got = got.unwrap_or_else(|e| panic!("s {s:e}: {e:?}"));
            let v = |q: Point2<f64>| reference::v(q.x, q.y);
            let want = reference::rrr_reactions(
                v(a),
                v(b),
                v(c),
                reference::v(f1.x, f1.y),
                v(p1),
                Dd::from(0.3),
                reference::v(f2.x, f2.y),
                v(p2),
                Dd::from(-0.2),
            )
            .unwrap();
            let want: Vec<f64> = want.iter().map(|x| x.to_f64()).collect();
            let gotv = [got.a.x, got.a.y, got.b.x, got.b.y, got.c.x, got.c.y];
            let err = rel(&gotv, &want);
            assert!(err <= 8.0 * eps / s, "s {s:e}: {err:e}");
        }
        let (a, b, c) = (
            Point2::new(0.0, 0.0),
            Point2::new(2.0, 0.0),
            Point2::new(1.0, 1.0),
        );
        let bad = Wrench::new(Vector2::new(f64::NAN, 0.0), 0.0);
        let e = rrr_force::reactions(&a, &b, &c, &bad, &Wrench::zero()).unwrap_err();
        assert_eq!(kind(&e), "NonFinite");
    }
}
