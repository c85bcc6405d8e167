//! Regressions of silently wrong `Ok` answers at the edges of the core's
//! ranges: the run-time findings of fuzzing (a tiny `(cos, sin)` pair, an
//! RRR whose known joints are far closer than its links, a crank angle
//! outside `(-pi, pi]` for huge inputs) and what the run-time fuzzer
//! (`fuzz/src/bin/runtime.rs`) found after them. Each test failed before
//! its fix (the figure it got is in its comment) and checks the answer
//! against an independent computation: `f64` (for `f32` results) or the
//! double-double reference, or the constraint the answer must satisfy.

use mechanism_core::driver::crank;
use mechanism_core::dyad::{rrp, rrr};
use mechanism_core::geometry::{angle, wrap_angle};
use mechanism_core::guide::Line;
use mechanism_core::{Fault, Mode, Point2, Real, Vector2};

fn p<T: Real>(x: f64, y: f64) -> Point2<T> {
    Point2::new(T::lit(x), T::lit(y))
}

/// `|a - b|` in f64.
fn dist<T: Real>(a: &Point2<T>, b: &Point2<T>) -> f64 {
    (a.x.as_f64() - b.x.as_f64()).hypot(a.y.as_f64() - b.y.as_f64())
}

/// Fuzzed: `position_cos_sin` with a tiny pair put the tip at the wrong
/// radius (the squared length was formed unscaled): f64 `(0.8775825618903728e-161,
/// 0.479425538604203e-161)` gave `|A - O2| = 99.745` for a crank of 101.6,
/// f32 `(4.33e-23, 2.17e-23)` gave 131.45. Now within 2 eps of 101.6, and
/// along the pair.
#[test]
fn tiny_cos_sin_pair_keeps_the_crank_length() {
    fn check<T: Real>(c: f64, s: f64) {
        let o = p::<T>(0.0, 0.0);
        let got = crank::position_cos_sin(&o, T::lit(101.6), T::lit(c), T::lit(s)).unwrap();
        let r = dist(&got.tip, &o);
        let eps = T::eps().as_f64();
        assert!(
            (r - 101.6).abs() <= 2.0 * eps * 101.6,
            "({c:e}, {s:e}): radius {r}"
        );
        let (cd, sd) = (T::lit(c).as_f64(), T::lit(s).as_f64());
        let n = cd.hypot(sd);
        let off = (cd / n) * got.tip.y.as_f64() - (sd / n) * got.tip.x.as_f64();
        assert!(
            off.abs() <= 2.0 * eps * 101.6,
            "({c:e}, {s:e}): off by {off:e}"
        );
    }
    check::<f64>(0.8775825618903728e-161, 0.479425538604203e-161);
    check::<f32>(4.33e-23, 2.17e-23);
    // And the huge and subnormal ends of the same promise.
    check::<f64>(0.8775825618903728e300, 0.479425538604203e300);
    check::<f64>(4e-320, 2e-320);
    check::<f32>(4.33e37, 2.17e37);
    check::<f32>(4e-44, 2e-44);
}

/// Fuzzed: the five-bar `{ base: 1e-150, proximal: 1e-153, distal: 1e-51 }`
/// at `q = (1.8, 0.8)` (f64), and `{ base: 8.852912e-30, proximal:
/// 1.1069633e-18, distal: 6.565753e-13 }` at `q = (5.02377e-6, 0.8000002)`
/// (f32): the RRR of the two distal links, whose known joints are far
/// closer than the links are long, returned `Ok` with `P` on `A` (`|P - A|
/// = 0`, `|P - C| = 1e-150` instead of 1e-51): `2 |B - A|^2 l1`, the size
/// of the position's third powers, is below the normal range, where their
/// bits are lost. Now a typed `NonFinite` that names the range, as for
/// lengths outside it; and just inside (`|B - A|` raised until `2 |B -
/// A|^2 l1` is normal) the position is accurate: both distances the
/// distal length within 4 eps.
#[test]
fn rrr_with_joints_far_closer_than_its_links() {
    fn check<T: Real>(base: f64, prox: f64, distal: f64, q1: f64, q2: f64) {
        let (o1, o2) = (p::<T>(0.0, 0.0), p::<T>(base, 0.0));
        let a = crank::position(&o1, T::lit(prox), T::lit(q1)).unwrap().tip;
        let c = crank::position(&o2, T::lit(prox), T::lit(q2)).unwrap().tip;
        let l = T::lit(distal);
        let err = rrr::position(&a, l, &c, l, Mode::Plus).unwrap_err();
        assert!(
            matches!(err.fault, Fault::NonFinite { what } if what.contains("range")),
            "{err}"
        );
    }
    check::<f64>(1e-150, 1e-153, 1e-51, 1.8, 0.8);
    check::<f32>(
        8.852912e-30,
        1.1069633e-18,
        6.565753e-13,
        5.02377e-6,
        0.8000002,
    );
    // Inside the range: `|B - A|` of 1e-100 (f64) and 1e-11 (f32) under
    // links of 1e-51 and 6.6e-13 (`2 |B - A|^2 l1` = 2e-251, 1.3e-34).
    fn inside<T: Real>(d: f64, l: f64) {
        let (a, c) = (p::<T>(0.0, 0.0), p::<T>(d * 0.6, d * 0.8));
        let l = T::lit(l);
        let got = rrr::position(&a, l, &c, l, Mode::Plus).unwrap();
        let eps = T::eps().as_f64();
        let l = l.as_f64();
        for (what, r) in [("|P - A|", dist(&got.c, &a)), ("|P - C|", dist(&got.c, &c))] {
            assert!((r - l).abs() <= 4.0 * eps * l, "{what} = {r:e} for {l:e}");
        }
    }
    inside::<f64>(1e-100, 1e-51);
    inside::<f32>(1e-11, 6.565753e-13 * 16.0);
}

/// Found while fixing the above: inside the rounding band of the inner
/// edge (`|B - A|` below `|l1 - l2|` by less than `4 eps (l1 + l2)`), with
/// `|B - A|` far below the band, the foot of `C` on `AB` (`(l1^2 - l2^2 +
/// D) / 2 |B - A|`) was not bounded by `l1`: `l1 = 1`, `l2 = 1 - eps`,
/// `|B - A| = 1e-20` gave `|C - A| = 2.2e4`. Now `C` is put on the line at
/// `l1` from `A`; with `|B - A|^2` below the normal range (1e-300) the
/// joints count as coincident, `Singular`.
#[test]
fn rrr_in_the_band_keeps_c_at_l1() {
    let (l1, l2) = (1.0f64, 1.0 - f64::EPSILON);
    for d in [1e-20, 1e-17, 1e-150] {
        let a = Point2::new(0.0, 0.0);
        let b = Point2::new(d, 0.0);
        let got = rrr::position(&a, l1, &b, l2, Mode::Plus).unwrap();
        let r = dist(&got.c, &a);
        assert!(
            (r - l1).abs() <= 2.0 * f64::EPSILON,
            "|B - A| = {d:e}: |C - A| = {r}"
        );
    }
    let far = rrr::position(
        &Point2::origin(),
        l1,
        &Point2::new(1e-300, 0.0),
        l2,
        Mode::Plus,
    );
    assert!(matches!(far.unwrap_err().fault, Fault::Singular { .. }));
}

/// Fuzzed: a crank's link angle (`wrap_angle` of the input) left `(-pi,
/// pi]`: f32 2.2e8 gave -9.716814, 4e12 gave -262137.72, f64 1.3e17 gave
/// -9.7168. Decided: an input at or beyond `angle_limit` (f32 2^24, f64
/// 2^53, where the input's spacing is 2 rad or more) is a typed error of
/// the crank, and `wrap_angle` stays in the range for every finite input;
/// below the limit the link angle is the direction of the crank's tip
/// within `2 |theta| eps` (its documented error; against `std`'s `f64`
/// sine and cosine, exact for the `f32` inputs).
#[test]
fn crank_link_angle_of_huge_inputs() {
    fn in_range<T: Real>(theta: f64) {
        let a = wrap_angle(T::lit(theta));
        assert!(a <= T::pi() && a > -T::pi(), "{theta:e}: {a:e}");
    }
    fn beyond<T: Real>(theta: f64) {
        in_range::<T>(theta);
        let e = crank::position(&p::<T>(0.0, 0.0), T::one(), T::lit(theta)).unwrap_err();
        assert!(
            matches!(e.fault, mechanism_core::Fault::NonFinite { .. }),
            "{e:?}"
        );
    }
    fn below<T: Real>(theta: f64) {
        in_range::<T>(theta);
        let t = T::lit(theta);
        let a = wrap_angle(t).as_f64();
        let tip = crank::position(&p::<T>(0.0, 0.0), T::one(), t).unwrap().tip;
        let off = (a.cos() * tip.y.as_f64() - a.sin() * tip.x.as_f64()).abs();
        let bound = 2.0 * T::eps().as_f64() * t.as_f64().abs() + 4.0 * T::eps().as_f64();
        assert!(off <= bound, "{theta:e}: the tip is {off:e} off the angle");
    }
    beyond::<f32>(2.2e8);
    beyond::<f32>(4e12);
    beyond::<f64>(1.3e17);
    beyond::<f32>(-3.3e38);
    beyond::<f64>(-1.7e308);
    below::<f32>(1.6e7);
    below::<f32>(-2.5e5);
    below::<f64>(9.0e15);
    below::<f64>(1.0e10);
}

/// Fuzzer (f32 shaper, rod angle): a vector just below `-x` had its angle
/// rounded to `-pi` of `f32` (`-3.1415927`), outside `(-pi, pi]`. Now `pi`.
#[test]
fn angle_just_below_minus_x() {
    let a = angle(&Vector2::new(-0.5f32, -1e-12));
    assert!(
        a > -core::f32::consts::PI && a <= core::f32::consts::PI,
        "{a}"
    );
    let a = angle(&Vector2::new(-0.5f64, -1e-300));
    assert!(
        a > -core::f64::consts::PI && a <= core::f64::consts::PI,
        "{a}"
    );
}

/// Fuzzer (f64 slider-crank, seed 1 case 1378): a 7.1e-260 crank at 66.7
/// rad/s driving an RRP with a 4.3e68 rod: the rod's angular velocity
/// (1e-326 rad/s) underflowed to 0, and the slider's velocity came out as
/// the crank tip's (`vc = va + omega1 perp(r1)`), 44 % off its guide. Now
/// `vc` is formed from `perp(r1 / det)` without the rate: along the guide
/// within 4 eps, and of the size the constraint gives.
#[test]
fn rrp_slow_crank_on_a_long_rod() {
    let line = Line {
        origin: Point2::new(5.378353554472883e-260, 4.044796746611344e-260),
        dir: Vector2::new(0.14255010142310076f64.cos(), 0.14255010142310076f64.sin()),
    };
    let o = Point2::new(0.0, 0.0);
    let (r, theta, omega) = (7.14050873496136e-260, 5.307579458781303, -66.67395185456759);
    let cr = crank::position(&o, r, theta).unwrap();
    let va = crank::velocity(&cr, None, omega).unwrap();
    let pos = rrp::position(
        &cr.tip,
        4.2896715268258184e68,
        &line,
        2.2175085314116414e-260,
        Mode::Plus,
    )
    .unwrap();
    let v = rrp::velocity(&pos, &line, Some(&va), None).unwrap();
    // `hypot`, not `norm`: the square of 5e-258 underflows.
    let speed = va.x.hypot(va.y);
    let across = line.dir.x * v.vc.y - line.dir.y * v.vc.x;
    assert!(
        across.abs() <= 4.0 * f64::EPSILON * speed,
        "across the guide: {across:e}"
    );
    // (vc - va) . r1 = 0 (the rod's length is fixed), so the slide speed
    // is dot(va, r1 / |r1|) / dot(dir, r1 / |r1|).
    let u = pos.r1 / pos.r1.x.hypot(pos.r1.y);
    let want = va.dot(&u) / line.dir.dot(&u);
    assert!(
        (v.s_dot - want).abs() <= 4.0 * f64::EPSILON * speed,
        "{} vs {want}",
        v.s_dot
    );
}

/// Fuzzer (f32 four-bar at 1e-19, seed 2 case 1272): the RRR's rates were
/// formed from `dot(vB - vA, r)` (L^2/s), subnormal for lengths of 1e-19
/// turning at 3e-4 rad/s, and lost bits (the rocker's velocity off its
/// constraint by 117 eps). Now the rates are `dot(vB - vA, r / det)` and
/// match `f64` on the same inputs within `8 eps / kappa^2`; shown here
/// inside the position's range of scale (f32 lengths from 2.3e-13), at
/// 1e-12 turning at 3e-15 rad/s, where `dot(vB - vA, r)` (4e-39) is
/// subnormal too.
#[test]
fn rrr_rates_of_tiny_slow_links_f32() {
    let s = 1e-12f64;
    let (a, b) = (p::<f32>(0.3 * s, -0.2 * s), p::<f32>(1.5 * s, 0.4 * s));
    let (l1, l2) = ((1.3 * s) as f32, (0.9 * s) as f32);
    let pos = rrr::position(&a, l1, &b, l2, Mode::Plus).unwrap();
    let va = Vector2::new((3e-15 * s) as f32, (-2e-15 * s) as f32);
    let got = rrr::velocity_lengths(&pos, l1, l2, Some(&va), None).unwrap();
    // f64 on the same f32 joint vectors: the 2x2 solve in closed form.
    let w = |v: Vector2<f32>| Vector2::new(v.x as f64, v.y as f64);
    let (r1, r2, dv) = (w(pos.r1), w(pos.r2), -w(va));
    let det = r1.x * r2.y - r1.y * r2.x;
    let (w1, w2) = (dv.dot(&r2) / det, dv.dot(&r1) / det);
    let kappa = det.abs() / (r1.norm() * r2.norm());
    let tol = 8.0 * f32::EPSILON as f64 / (kappa * kappa) * w1.abs().max(w2.abs());
    assert!(
        (got.omega1 as f64 - w1).abs() <= tol,
        "omega1 {} vs {w1:e}",
        got.omega1
    );
    assert!(
        (got.omega2 as f64 - w2).abs() <= tol,
        "omega2 {} vs {w2:e}",
        got.omega2
    );
}

/// Fuzzer (f32 four-bar, a 1.2e-26 crank at 2.7e-5 rad/s on 1.8e17 links,
/// seed 1 case 62934): the coupler's rate (1.7e-48 rad/s) underflowed to 0
/// and the joint's velocity came out as the crank tip's. Links of 1.8e17
/// are beyond the position's range of scale in f32 (to 4.4e12): a typed
/// error now. At the top of the range (2e12) the same slow crank gives a
/// rate below the normal range whose underflow moves the joint by at most
/// `l` times the subnormal spacing (`2^-149 l`, 3e-33 here), the floating-
/// point model's absolute term: the joint's velocity satisfies both links'
/// constraints within `4 eps |vA| l + 2^-149 l^2`.
#[test]
fn rrr_slow_short_crank_on_long_links_f32() {
    let (a, b) = (p::<f32>(2.0e17, 1.0e5), p::<f32>(3.0e17, 0.0));
    let (l1, l2) = (1.8e17f32, 1.7e17f32);
    let err = rrr::position(&a, l1, &b, l2, Mode::Plus).unwrap_err();
    assert!(matches!(err.fault, Fault::NonFinite { .. }), "{err}");
    let k = 1e-5;
    let (a, b) = (p::<f32>(2.0e17 * k, 1.0), p::<f32>(3.0e17 * k, 0.0));
    let (l1, l2) = (1.8e17f32 * k as f32, 1.7e17f32 * k as f32);
    let pos = rrr::position(&a, l1, &b, l2, Mode::Plus).unwrap();
    let va = Vector2::new(3.2e-31f32, -1.0e-31);
    let v = rrr::velocity_lengths(&pos, l1, l2, Some(&va), None).unwrap();
    let w = |v: Vector2<f32>| Vector2::new(v.x as f64, v.y as f64);
    let l = l1 as f64;
    let tol = 4.0 * f32::EPSILON as f64 * w(va).norm() * l + 2f64.powi(-149) * l * l;
    let c1 = (w(v.vc) - w(va)).dot(&w(pos.r1));
    let c2 = w(v.vc).dot(&w(pos.r2));
    assert!(
        c1.abs() <= tol && c2.abs() <= tol,
        "{c1:e} {c2:e} (tolerance {tol:e})"
    );
}

/// Fuzzer (f32 slider-crank, seed 1 case 348310): a 7.6e29 crank at
/// 5.1e-26 rad/s: `omega^2` underflows and its tip's centripetal
/// acceleration (2e-21) is lost. Decided: within the documented error of
/// `link::relative_acceleration`, the floating-point model's absolute term
/// `2^-149 r` (1.1e-15 here), not a silent answer; `(r omega) omega` would
/// keep it at a cost in ordinary accuracy. At 1e-18 rad/s, where `omega^2`
/// is normal, within 2 eps of `omega^2 r`.
#[test]
fn crank_centripetal_acceleration_of_a_slow_long_crank_f32() {
    let r = 7.604033e29f32;
    let pos = crank::position(&p::<f32>(0.0, 0.0), r, 0.7).unwrap();
    for (omega, floor) in [(5.1090586e-26f32, 2f64.powi(-149) * r as f64), (1e-18, 0.0)] {
        let acc = crank::acceleration(&pos, None, omega, 0.0).unwrap();
        let want = (omega as f64).powi(2) * r as f64;
        let got = (acc.x as f64).hypot(acc.y as f64);
        assert!(
            (got - want).abs() <= 2.0 * f32::EPSILON as f64 * want + floor,
            "{omega:e}: {got:e} vs {want:e}"
        );
    }
}

/// Fuzzer (f32 five-bar, seed 2 case 75246): with the rates formed from
/// `r / det`, an input rate of -3.4e38 made `omega1` infinite while the
/// joint's velocity stayed finite, and the `Ok` carried the infinity. Now a
/// typed `NonFinite`.
#[test]
fn rrr_overflowing_rate_is_an_error() {
    let (a, l1, b, l2) = (
        p::<f32>(0.0, 0.0),
        1.3e-5f32,
        p::<f32>(1.5e-5, 0.0),
        0.9e-5f32,
    );
    let pos = rrr::position(&a, l1, &b, l2, Mode::Plus).unwrap();
    let va = Vector2::new(3.4e33f32, -1.0e33);
    match rrr::velocity_lengths(&pos, l1, l2, Some(&va), None) {
        Ok(v) => assert!(
            [v.omega1, v.omega2, v.vc.x, v.vc.y]
                .iter()
                .all(|x| x.is_finite()),
            "{v:?}"
        ),
        Err(e) => assert!(matches!(e.fault, mechanism_core::Fault::NonFinite { .. })),
    }
}

/// Fuzzer (f64 five-bar, seed 1795688701575150348 case 33748155): an input
/// rate of -1.8e308 made `dot(vB - vA, r2 / det)` NaN (an infinite minus
/// an infinite product) while the joint's velocity, taken by the cold path
/// for a rate below the normal range (NaN compares false), stayed finite:
/// the `Ok` carried `omega1 = NaN`. Likewise for `alpha1`. Now a typed
/// `NonFinite`.
#[test]
fn rrr_nan_rate_is_an_error() {
    // The fuzzer's five-bar, through the core's primitives.
    let (base, prox1, prox2) = (
        0.05897133357513611,
        0.10556718576848685,
        0.11889294866435747,
    );
    let (dist1, dist2) = (0.12492302425891956, 0.17723224999531423);
    let (o1, o2) = (Point2::<f64>::new(0.0, 0.0), Point2::new(base, 0.0));
    let c1 = crank::position(&o1, prox1, 0.7866454115971535).unwrap();
    let c2 = crank::position(&o2, prox2, -4.353719601348215).unwrap();
    let pos = rrr::position(&c1.tip, dist1, &c2.tip, dist2, Mode::Plus).unwrap();
    let va = crank::velocity(&c1, None, 3.8369235967771473).unwrap();
    let vc = crank::velocity(&c2, None, -1.7976931348623157e308).unwrap();
    let no_nan = |xs: [f64; 4]| xs.iter().all(|x| x.is_finite());
    match rrr::velocity_lengths(&pos, dist1, dist2, Some(&va), Some(&vc)) {
        Ok(v) => assert!(no_nan([v.omega1, v.omega2, v.vc.x, v.vc.y]), "{v:?}"),
        Err(e) => assert!(matches!(e.fault, mechanism_core::Fault::NonFinite { .. })),
    }
    // The same rates as accelerations of the joints (alpha1's check).
    let v = rrr::velocity_lengths(&pos, dist1, dist2, None, None).unwrap();
    match rrr::acceleration(&pos, &v, Some(&va), Some(&vc)) {
        Ok(acc) => assert!(
            no_nan([acc.alpha1, acc.alpha2, acc.ac.x, acc.ac.y]),
            "{acc:?}"
        ),
        Err(e) => assert!(matches!(e.fault, mechanism_core::Fault::NonFinite { .. })),
    }
}
