//! The assembly-range checks on mechanisms written for this file: the
//! generated `check()` (the run-time sweep of `mechanism::sweep`), the
//! run-time errors of `position()` at either side of the limits it reports,
//! ranges suggested by the expansion-time check (`tests/ui/sweep_*.rs`)
//! written back into definitions that must compile, and `#[self_test]` on
//! the same definitions.
//!
//! Every expected limit is an independent closed form written here:
//!
//! - four-bar (crank `r` about O2, ground `g` to O4, coupler `l3`, rocker
//!   `l4`): `|A - O4|^2 = r^2 + g^2 - 2 r g cos(theta)` (law of cosines); the
//!   RRR assembles while `|l3 - l4| <= |A - O4| <= l3 + l4`, and its rate
//!   system is singular (toggle) where either bound is met;
//! - offset slider-crank (guide line `y = e`): `A` is `|r sin(theta) - e|`
//!   from the line; the RRP assembles while that is at most the rod `l`;
//! - RPR (block at the crank pin `A` sliding on a rocker through `B`, slide
//!   line `e` from `B`): assembles while `|A - B| >= |e|`;
//! - PRP: the two guides' directions are parallel at isolated inputs;
//! - five-bar: the distal RRR's `|A - C|` against `l3 + l4`;
//! - six-bar: the second RRR, on the four-bar's rocker tip, fails where
//!   `|B - O6| > l5 + l6`, i.e. past a rocker angle from the law of cosines,
//!   mapped back to the crank angle by intersecting two circles.
//!
//! Tolerance of an interval's end: docs/checks.md and the module doc of
//! `mechanism::sweep` say the ends are bisected to `1e-10` of the range's
//! width (in `f64`); bisection returns the midpoint of a bracket narrower
//! than that, so the claim is an error of at most `1e-10 x width`; the
//! closed forms here are good to a few eps of an angle, far below it.
use mechanism::mechanism;
use mechanism::{Fault, Point2};
use std::f64::consts::PI;

/// The documented accuracy of an interval's end: `1e-10` of the range's
/// width (docs/checks.md, "bisected to 1e-10 of the range").
const EDGE: f64 = 1e-10;

fn deg(x: f64) -> f64 {
    x.to_radians()
}

/// Wraps an angle into `[0, 2 pi)`.
fn wrap(x: f64) -> f64 {
    x.rem_euclid(2.0 * PI)
}

/// Asserts `got` is within `tol` of `want`, with a message that shows both
/// in degrees.
fn near_angle(got: f64, want: f64, tol: f64, what: &str) {
    assert!(
        (got - want).abs() <= tol,
        "{what}: got {got} rad ({} deg), closed form {want} rad ({} deg), error {:e} > {:e}",
        got.to_degrees(),
        want.to_degrees(),
        (got - want).abs(),
        tol
    );
}

// ---------------------------------------------------------------------------
// Four-bars with run-time dimensions: double rocker, crank-rocker, change
// point, and (changed parameters) an inner limit whose interval wraps over 0.
// ---------------------------------------------------------------------------

mechanism! {
    /// A four-bar whose dimensions are all run-time parameters; the crank's
    /// range is the default full turn. Default: a non-Grashof double rocker
    /// (s + l = 40 + 130 = 170 > p + q = 90 + 70 = 160).
    pub Quad {
        params { base = 130.0, crank = 40.0, coupler = 90.0, rocker = 70.0 }
        analysis position;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(base, 0.0);
        let A = crank(O2, crank, theta) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
    }
}

/// The crank angles in `[0, pi]` where `|A - O4| = d` (law of cosines);
/// `None` when the crank never puts `A` at that distance.
fn quad_angle_at_distance(g: f64, r: f64, d: f64) -> Option<f64> {
    let c = (r * r + g * g - d * d) / (2.0 * r * g);
    (-1.0..=1.0).contains(&c).then(|| c.acos())
}

fn quad(base: f64, crank: f64, coupler: f64, rocker: f64) -> Quad<f64> {
    Quad {
        base,
        crank,
        coupler,
        rocker,
    }
}

/// Whether the four-bar assembles at `theta` by the closed form, with the
/// signed margin (positive: assembles) in length units.
fn quad_margin(m: &Quad<f64>, theta: f64) -> f64 {
    let (g, r) = (m.base, m.crank);
    let d = (r * r + g * g - 2.0 * r * g * theta.cos()).sqrt();
    let outer = m.coupler + m.rocker - d;
    let inner = d - (m.coupler - m.rocker).abs();
    outer.min(inner)
}

#[test]
fn double_rocker_interval_is_the_law_of_cosines_limit() {
    let m = quad(130.0, 40.0, 90.0, 70.0);
    let r = m.check();
    assert_eq!(r.inputs, ["theta"]);
    let names: Vec<&str> = r.groups.iter().map(|g| g.group).collect();
    assert_eq!(
        names,
        ["A", "B"],
        "groups in solve order: the crank, then B"
    );
    assert_eq!(r.groups[0].failures, 0, "the crank itself never fails");
    let b = &r.groups[1];
    assert_eq!(b.failures, 1, "{r:?}");
    let t = quad_angle_at_distance(130.0, 40.0, 160.0).unwrap();
    // 133.054389 deg: the figure docs/checks.md shows for the literal twin.
    assert!((t.to_degrees() - 133.054389).abs() < 1e-6);
    let (lo, hi) = b.failure.unwrap();
    let width = 2.0 * PI;
    let (e_lo, e_hi) = (lo[0] - t, hi[0] - (2.0 * PI - t));
    near_angle(lo[0], t, EDGE * width, "start of B's failure");
    near_angle(hi[0], 2.0 * PI - t, EDGE * width, "end of B's failure");
    eprintln!(
        "double rocker: ends off the closed form by {e_lo:e} and {e_hi:e} rad (claim {:e})",
        EDGE * width
    );
    match b.fault {
        Some(Fault::CannotAssemble { miss, reach }) => {
            assert_eq!(reach, 160.0, "the outer bound l3 + l4");
            assert!(miss > 0.0 && miss.is_finite());
        }
        f => panic!("expected CannotAssemble, got {f:?}"),
    }
    // The limit positions of a double rocker are toggles of the coupler and
    // the rocker, but they are the failing interval's ends, not positions
    // the motion passes: nothing is reported as singular inside the range.
    assert_eq!(b.singular, 0, "{r:?}");
}

#[test]
fn grashof_crank_rocker_has_no_failure_and_no_toggle() {
    // s + l = 40 + 130 = 170 < p + q = 120 + 100; |A - O4| in [90, 170],
    // strictly inside [|120 - 100|, 120 + 100] = [20, 220].
    let m = quad(130.0, 40.0, 120.0, 100.0);
    let r = m.check();
    assert!(r.is_clean(), "{r:?}");
}

#[test]
fn change_point_four_bar_is_singular_at_the_closed_form_angle() {
    // l1 + l2 = l3 + l4: 40 + 100 = 80 + 60. |A - O4| reaches 140 = l3 + l4
    // at theta = 180 deg only (coupler and rocker extended in line): the
    // crank still turns fully, through one toggle.
    let m = quad(100.0, 40.0, 80.0, 60.0);
    let r = m.check();
    assert!(r.assembles(), "{r:?}");
    let b = &r.groups[1];
    assert_eq!((b.group, b.singular), ("B", 1), "{r:?}");
    // Singular positions: docs/checks.md says 1e-4 deg (a fold is exactly
    // singular over a rounding band of about eps^(1/2) rad around it: the
    // distance falls as theta^2 there, so it is within 4 eps of the bound
    // over |theta - pi| < sqrt(4 eps (l3 + l4) / (r g)) = 3.6e-8 rad).
    let at = b.first_singular.unwrap()[0];
    near_angle(at, PI, deg(1e-4), "change point");
    // At the change point and either side of it, `position()` assembles.
    for dt in [0.0, 1e-9, -1e-9, 1e-3, -1e-3] {
        let p = m.position(&QuadInput { theta: PI + dt });
        assert!(p.is_ok(), "at pi + {dt}: {p:?}");
    }
}

#[test]
fn inner_limit_interval_wraps_over_zero() {
    // |l3 - l4| = 100 > g - r = 90: A comes too close to O4 around
    // theta = 0: cos(theta) > (40^2 + 130^2 - 100^2) / (2 40 130).
    let m = quad(130.0, 40.0, 200.0, 100.0);
    let t = quad_angle_at_distance(130.0, 40.0, 100.0).unwrap();
    let r = m.check();
    let b = &r.groups[1];
    assert_eq!(b.failures, 1, "one interval, joined across 0: {r:?}");
    let (lo, hi) = b.failure.unwrap();
    near_angle(lo[0], -t, EDGE * 2.0 * PI, "start (joined over 0)");
    near_angle(hi[0], t, EDGE * 2.0 * PI, "end");
    match b.fault {
        Some(Fault::CannotAssemble { reach, .. }) => assert_eq!(reach, 100.0, "|l3 - l4|"),
        f => panic!("expected CannotAssemble, got {f:?}"),
    }
}

#[test]
fn params_move_the_double_rocker_limits_as_the_closed_form_says() {
    // The same double rocker with the base from 125 to 145: the limit
    // theta* = acos((r^2 + g^2 - (l3 + l4)^2) / (2 r g)) moves from 150.6 to
    // 109.2 deg.
    for base in [125.0, 128.0, 130.0, 135.0, 140.0, 145.0] {
        let m = quad(base, 40.0, 90.0, 70.0);
        let t = quad_angle_at_distance(base, 40.0, 160.0).unwrap();
        let r = m.check();
        let (lo, hi) = r.groups[1].failure.unwrap();
        near_angle(lo[0], t, EDGE * 2.0 * PI, &format!("base {base}: start"));
        near_angle(hi[0], 2.0 * PI - t, EDGE * 2.0 * PI, "end");
    }
    // Base 115: |A - O4| <= 155 < 160, the outer limit is never met; the
    // inner limit |90 - 70| = 20 < 75 neither: a Grashof crank-rocker.
    assert!(quad(115.0, 40.0, 90.0, 70.0).check().is_clean());
}

#[test]
fn double_rocker_position_just_inside_and_outside_the_limits() {
    let m = quad(130.0, 40.0, 90.0, 70.0);
    let t = quad_angle_at_distance(130.0, 40.0, 160.0).unwrap();
    // 1e-9 rad is 16 times the sweep's edge tolerance and moves |A - O4| by
    // r g sin(t) / d x 1e-9 = 2.4e-8, far beyond the RRR's rounding band
    // 4 eps (l3 + l4) = 1.4e-13.
    for edge in [t, 2.0 * PI - t] {
        for (dt, inside) in [(-1e-9, true), (1e-9, false)] {
            let inside = if edge > PI { !inside } else { inside };
            let theta = edge + dt;
            match m.position(&QuadInput { theta }) {
                Ok(p) => {
                    assert!(inside, "theta {theta} should fail");
                    assert!(p.B.x.is_finite() && p.B.y.is_finite() && p.link4.is_finite());
                }
                Err(e) => {
                    assert!(!inside, "theta {theta} should assemble: {e}");
                    assert_eq!(e.group, "B");
                    assert!(matches!(e.fault, Fault::CannotAssemble { .. }));
                }
            }
        }
    }
    // Deep outside: the fault's miss is the closed form's excess distance.
    let theta = PI;
    let d = 130.0 + 40.0;
    match m.position(&QuadInput { theta }) {
        Err(e) => match e.fault {
            Fault::CannotAssemble { miss, reach } => {
                // A few roundings of a 170-long distance.
                assert!((miss - (d - 160.0)).abs() < 1e-12, "miss {miss}");
                assert_eq!(reach, 160.0);
            }
            f => panic!("{f:?}"),
        },
        Ok(p) => panic!("assembled at 180 deg: {p:?}"),
    }
}

#[test]
fn quad_position_fails_exactly_where_the_closed_form_says() {
    // 7200 inputs over a turn (offset from the sweep's own samples), for
    // four parameter sets: Ok with finite outputs where the closed-form
    // margin is positive, a `B` error where it is negative; inputs within
    // 1e-9 of a limit (margin below 1e-7 in length) are skipped.
    for m in [
        quad(130.0, 40.0, 90.0, 70.0),
        quad(130.0, 40.0, 120.0, 100.0),
        quad(100.0, 40.0, 80.0, 60.0),
        quad(130.0, 40.0, 200.0, 100.0),
    ] {
        for k in 0..7200 {
            let theta = -PI + (k as f64 + 0.37) * (2.0 * PI / 7200.0);
            let margin = quad_margin(&m, theta);
            if margin.abs() < 1e-7 {
                continue;
            }
            match m.position(&QuadInput { theta }) {
                Ok(p) => {
                    assert!(margin > 0.0, "{m:?} at {theta}: assembled, margin {margin}");
                    assert!(p.B.x.is_finite() && p.B.y.is_finite() && p.link4.is_finite());
                }
                Err(e) => {
                    assert!(margin < 0.0, "{m:?} at {theta}: {e}, margin {margin}");
                    assert_eq!(e.group, "B");
                }
            }
        }
    }
}

#[test]
fn double_rocker_f32_check_edges() {
    // The same double rocker in f32. The doc of `check()` says "edges to
    // `max(1e-10, eps)` of the range" (it now says the edge can lie the
    // rounding band beyond): eps32 x 2 pi = 7.5e-7 rad. That is
    // where the bisection stops; but the f32 `position()` decides where the
    // group assembles, and the RRR accepts a distance up to 4 eps (l3 + l4)
    // beyond the bound (its rounding band, 7.6e-5 in f32). |A - O4| grows by
    // r g sin(t) / (l3 + l4) = 23.7 per rad at the limit, so the f32 edge
    // lies band / slope = 3.2e-6 rad outside the exact limit, 4.3 times the
    // documented figure (measured: 3.29e-6 rad). The bound is band / slope
    // plus the bisection's eps32 x 2 pi.
    let m = Quad::<f32>::default();
    let t = quad_angle_at_distance(130.0, 40.0, 160.0).unwrap();
    let eps32 = f32::EPSILON as f64;
    let slope = 40.0 * 130.0 * t.sin() / 160.0;
    let tol = 4.0 * eps32 * 160.0 / slope + eps32 * 2.0 * PI;
    let r = m.check();
    let (lo, hi) = r.groups[1].failure.unwrap();
    eprintln!(
        "f32 double rocker: ends off by {:e} and {:e} rad (bound {tol:e})",
        lo[0] - t,
        hi[0] - (2.0 * PI - t)
    );
    near_angle(lo[0], t, tol, "f32 start");
    near_angle(hi[0], 2.0 * PI - t, tol, "f32 end");
    // Outside, never inside: the band only widens where it assembles.
    assert!(lo[0] > t && hi[0] < 2.0 * PI - t);
}

// ---------------------------------------------------------------------------
// Offset slider-crank: the crank is longer than the rod minus the offset.
// ---------------------------------------------------------------------------

mechanism! {
    /// Slider-crank with the guide's offset as a parameter: the slide line is
    /// `y = offset`.
    pub OffsetSlider {
        params { crank = 0.1, rod = 0.12, offset = 0.05 }
        analysis position;
        let O = ground(0.0, 0.0);
        let line = guide((0.0, 0.0), 0 deg);
        let A = crank(O, crank, theta) as link2;
        let B = rrp(A, rod, line, plus, offset) as (link3, slider) slide x;
    }
}

/// Failing intervals of the offset slider-crank by the closed form, each in
/// `[0, 2 pi)` or joined over 0 (start negative): where `r sin(theta) - e`
/// leaves `[-l, l]`.
fn slider_failures(r: f64, l: f64, e: f64) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    // r sin(theta) > e + l: theta in (asin(s), pi - asin(s)).
    let s = (e + l) / r;
    if s < 1.0 {
        let a = s.max(-1.0).asin();
        out.push((a, PI - a));
    }
    // r sin(theta) < e - l: theta in (pi - asin(s), 2 pi + asin(s)).
    let s = (e - l) / r;
    if s > -1.0 {
        let a = s.min(1.0).asin();
        out.push((PI - a, 2.0 * PI + a));
    }
    out
}

#[test]
fn offset_slider_crank_failures_follow_the_guide_distance() {
    for (r, l, e) in [
        (0.1, 0.12, 0.05),  // fails below: sin < -0.7
        (0.1, 0.12, -0.05), // fails above: sin > 0.7
        (0.2, 0.12, 0.05),  // both: sin > 0.85 and sin < -0.35
        (0.1, 0.12, 0.0),   // r < l - |e|: assembles everywhere
    ] {
        let m = OffsetSlider::<f64> {
            crank: r,
            rod: l,
            offset: e,
        };
        let rep = m.check();
        let b = &rep.groups[1];
        assert_eq!(b.group, "B");
        let want = slider_failures(r, l, e);
        assert_eq!(b.failures as usize, want.len(), "{r} {l} {e}: {rep:?}");
        if let Some(&(lo, hi)) = want.first() {
            let (glo, ghi) = b.failure.unwrap();
            near_angle(glo[0], lo, EDGE * 2.0 * PI, "slider: start");
            near_angle(ghi[0], hi, EDGE * 2.0 * PI, "slider: end");
        }
        // The tangent positions are the failures' ends; inside the range the
        // rod is never perpendicular to the guide.
        assert_eq!(b.singular, 0, "{rep:?}");
        for (lo, hi) in want {
            for (x, ok) in [
                (lo - 1e-9, true),
                (lo + 1e-9, false),
                (hi - 1e-9, false),
                (hi + 1e-9, true),
            ] {
                match m.position(&OffsetSliderInput { theta: x }) {
                    Ok(p) => {
                        assert!(ok, "{x} should fail");
                        assert!(p.x.is_finite() && p.B.y.is_finite());
                    }
                    Err(err) => {
                        assert!(!ok, "{x} should assemble: {err}");
                        assert_eq!(err.group, "B");
                        assert!(matches!(err.fault, Fault::CannotAssemble { .. }));
                    }
                }
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Inverted slider (RPR): the slide line's offset circle about the rocker's
// pivot crosses the crank circle.
// ---------------------------------------------------------------------------

mechanism! {
    /// Crank pin A carries a block sliding on a rocker pivoted at B = (d, 0);
    /// the slide line is `offset` from B.
    pub Inverted {
        params { crank = 0.1, d = 0.12, offset = 0.05 }
        analysis position;
        let O = ground(0.0, 0.0);
        let B = ground(d, 0.0);
        let A = crank(O, crank, theta) as link2;
        let s = rpr(A, B, plus, offset) as (block, rocker);
    }
}

#[test]
fn rpr_fails_where_the_pin_passes_inside_the_offset_circle() {
    for (r, d, e) in [(0.1, 0.12, 0.05), (0.1, 0.08, 0.05), (0.1, 0.12, 0.03)] {
        let m = Inverted::<f64> {
            crank: r,
            d,
            offset: e,
        };
        // |A - B|^2 = r^2 + d^2 - 2 r d cos(theta) < e^2.
        let c = (r * r + d * d - e * e) / (2.0 * r * d);
        let rep = m.check();
        let g = &rep.groups[1];
        assert_eq!(g.group, "s", "the RPR is named by its slide");
        if c >= 1.0 {
            assert_eq!(g.failures, 0, "{rep:?}");
            continue;
        }
        let t = c.acos();
        assert_eq!(g.failures, 1, "{r} {d} {e}: {rep:?}");
        let (lo, hi) = g.failure.unwrap();
        near_angle(lo[0], -t, EDGE * 2.0 * PI, "RPR start (joined over 0)");
        near_angle(hi[0], t, EDGE * 2.0 * PI, "RPR end");
        assert_eq!(g.singular, 0, "{rep:?}");
        for (x, ok) in [(t + 1e-9, true), (t - 1e-9, false), (0.0, false)] {
            match m.position(&InvertedInput { theta: x }) {
                Ok(p) => {
                    assert!(ok, "{x} should fail");
                    assert!(p.s.is_finite() && p.rocker.is_finite());
                }
                Err(err) => {
                    assert!(!ok, "{x} should assemble: {err}");
                    assert_eq!(err.group, "s");
                    match err.fault {
                        // miss = |e| - |A - B| (the dyad's doc).
                        Fault::CannotAssemble { miss, reach } => {
                            assert_eq!(reach, e);
                            if x == 0.0 {
                                assert!((miss - (e - (d - r).abs())).abs() < 1e-15);
                            }
                        }
                        f => panic!("{f:?}"),
                    }
                }
            }
        }
    }
}

/// Found by this test: with offset 0 and the rocker's pivot ON the crank circle, the
/// pin passes through the pivot once a turn: there the rocker's direction is
/// undefined (`position()` fails `Singular` within 16 eps) and its angular
/// rate is unbounded (`omega = v / s`, `s -> 0`), and the generated position
/// flips the rocker by 180 deg across it (mode `plus` keeps `s >= 0`). The
/// scaled determinant `det_rpr = s / |A - B|` is 1 on both sides, so the
/// sweep finds nothing unless a sample lands within 16 eps of the point:
/// `check()` reported a clean turn. Fixed: `sweep::det_rpr` is now bounded by
/// `|A - B| / size` as the velocity's `condition` is.
#[test]
fn rpr_pass_through_the_pivot_is_reported() {
    // Pivot at the crank tip for theta = 1 rad (not a sample: samples are
    // multiples of 0.1 deg).
    let r = 0.1;
    let (bx, by) = (r * 1f64.cos(), r * 1f64.sin());
    let m = PivotOnCircle::<f64> { bx, by };
    // The rocker flips by pi across theta = 1 rad.
    let a = m
        .position(&PivotOnCircleInput { theta: 1.0 - 1e-6 })
        .unwrap();
    let b = m
        .position(&PivotOnCircleInput { theta: 1.0 + 1e-6 })
        .unwrap();
    let jump = (b.rocker - a.rocker).rem_euclid(2.0 * PI);
    assert!((jump - PI).abs() < 1e-3, "the rocker flips: {jump}");
    let rep = m.check();
    // Found by the golden-section search on the V-shaped `|A - B| / size`:
    // within the search's tolerance (1e-10 of the turn, 6.3e-10 rad) of the
    // pass; 1e-8 rad leaves room for the flat bottom of a V sampled in f64.
    let g = &rep.groups[1];
    let at = g.first_singular.map(|a| a[0]);
    assert!(
        g.singular == 1 && at.is_some_and(|a| (a - 1.0).abs() < 1e-8),
        "check() must report the pass-through at theta = 1 rad: {rep:?}"
    );
}

mechanism! {
    /// The RPR with its pivot at `(bx, by)` on the crank circle, offset 0.
    pub PivotOnCircle {
        params { bx = 0.054, by = 0.084 }
        analysis position;
        let O = ground(0.0, 0.0);
        let B = ground(bx, by);
        let A = crank(O, 0.1, theta) as link2;
        let s = rpr(A, B, plus) as (block, rocker);
    }
}

// ---------------------------------------------------------------------------
// PRP: two guides, one carried by the crank, are parallel at isolated angles.
// ---------------------------------------------------------------------------

mechanism! {
    /// A block on a fixed vertical guide through (0.3, 0) and a block on a
    /// line through the crank's pivot at `tilt` to the crank: the guides are
    /// parallel where theta + tilt = 90 deg (mod 180).
    pub Cross {
        params { tilt = 0.5235987755982988 }
        analysis position;
        let O = ground(0.0, 0.0);
        let V = ground(0.3, 0.0);
        let vertical = guide(V, 90 deg);
        let A = crank(O, 0.1, theta) as crank_link;
        let rod_line = guide(O, crank_link, tilt);
        let C = prp(rod_line, vertical) as (b1, b2) slide (s1, s2);
    }
}

#[test]
fn prp_parallel_guides_are_found_at_the_closed_form_angles() {
    // tilt 30 deg: parallel at theta = 60 and 240 deg, both multiples of the
    // sweep's 0.1 deg step: the samples there fail (`Singular` within 16 eps)
    // and `check()` reports two failing intervals narrower than the edge
    // tolerance.
    let m = Cross::<f64>::default();
    let rep = m.check();
    let c = &rep.groups[1];
    assert_eq!(c.group, "C");
    assert_eq!(c.failures, 2, "{rep:?}");
    let (lo, hi) = c.failure.unwrap();
    near_angle(lo[0], deg(60.0), EDGE * 2.0 * PI, "PRP start");
    near_angle(hi[0], deg(60.0), EDGE * 2.0 * PI, "PRP end");
    assert!(matches!(c.fault, Some(Fault::Singular { .. })));
    // Run time: a typed error at the parallel angle, Ok 1e-9 away, never NaN.
    for (x, ok) in [
        (deg(60.0), false),
        (deg(60.0) + 1e-9, true),
        (deg(60.0) - 1e-9, true),
    ] {
        match m.position(&CrossInput { theta: x }) {
            Ok(p) => {
                assert!(ok, "{x}");
                assert!(p.C.x.is_finite() && p.C.y.is_finite());
            }
            Err(e) => {
                assert!(!ok, "{x}: {e}");
                assert_eq!(e.group, "C");
            }
        }
    }
}

#[test]
fn prp_parallel_guides_between_samples_are_failures_as_on_samples() {
    // tilt 33.33 deg: parallel at 56.67 and 236.67 deg, between samples. The
    // determinant cross(dir1, dir2) changes sign there; the joint is at
    // infinity, as at the tilt of 30 deg where samples land on it, so the
    // verdict is the same: two failures at single inputs, no singular
    // position (the macro's expansion-time check says the same). Both at the
    // closed form to the edge tolerance.
    let tilt = deg(33.33);
    let m = Cross::<f64> { tilt };
    let rep = m.check();
    let c = &rep.groups[1];
    assert_eq!((c.failures, c.singular), (2, 0), "between samples: {rep:?}");
    assert!(!rep.assembles());
    let (lo, hi) = c.failure.unwrap();
    near_angle(lo[0], PI / 2.0 - tilt, EDGE * 2.0 * PI, "PRP failure start");
    near_angle(hi[0], PI / 2.0 - tilt, EDGE * 2.0 * PI, "PRP failure end");
    assert!(
        matches!(c.fault, Some(Fault::Singular { .. })),
        "{:?}",
        c.fault
    );
    // The crank's own group is not at infinity: nothing recorded for it.
    assert_eq!((rep.groups[0].failures, rep.groups[0].singular), (0, 0));
}

// ---------------------------------------------------------------------------
// Five-bar, two inputs: the grid count against the closed form.
// ---------------------------------------------------------------------------

mechanism! {
    /// Two cranks 0.1 long, pivots `base` apart, distal links `l3`, `l4`.
    pub Five {
        params { base = 0.08, l3 = 0.1, l4 = 0.1 }
        analysis position;
        let O1 = ground(0.0, 0.0);
        let O2 = ground(base, 0.0);
        let A = crank(O1, 0.1, q1) as arm1;
        let C = crank(O2, 0.1, q2) as arm2;
        let P = rrr(A, l3, C, l4, left) as (forearm1, forearm2);
        range q1 = (60 deg, 150 deg);
        range q2 = (0 deg, 90 deg);
    }
}

#[test]
fn five_bar_grid_count_and_box_match_the_closed_form() {
    // 121 x 121 grid (docs/checks.md). A grid point fails where
    // |A - C| > l3 + l4 or < |l3 - l4|; no grid point lies within 1e-9 of
    // either bound for these dimensions (asserted), so the count is exact.
    for (base, l3, l4) in [(0.08, 0.1, 0.1), (0.08, 0.11, 0.1), (0.05, 0.1, 0.12)] {
        let m = Five::<f64> { base, l3, l4 };
        let rep = m.check();
        let (r1, r2) = ((deg(60.0), deg(150.0)), (deg(0.0), deg(90.0)));
        assert_eq!(rep.ranges[0].lo, r1.0);
        assert_eq!(rep.ranges[1].hi, r2.1);
        let n = 120;
        let grid = |r: (f64, f64), i: usize| r.0 + (r.1 - r.0) * i as f64 / n as f64;
        let mut count = 0;
        let mut bbox = [f64::INFINITY, -f64::INFINITY, f64::INFINITY, -f64::INFINITY];
        for i in 0..=n {
            for j in 0..=n {
                let (q1, q2) = (grid(r1, i), grid(r2, j));
                let (ax, ay) = (0.1 * q1.cos(), 0.1 * q1.sin());
                let (cx, cy) = (base + 0.1 * q2.cos(), 0.1 * q2.sin());
                let dist = (ax - cx).hypot(ay - cy);
                let margin = (l3 + l4 - dist).min(dist - (l3 - l4).abs());
                assert!(margin.abs() > 1e-9, "grid point on a limit");
                if margin < 0.0 {
                    count += 1;
                    bbox = [
                        bbox[0].min(q1),
                        bbox[1].max(q1),
                        bbox[2].min(q2),
                        bbox[3].max(q2),
                    ];
                }
                let p = m.position(&FiveInput { q1, q2 });
                assert_eq!(p.is_err(), margin < 0.0, "({q1}, {q2}): {p:?}");
                if let Err(e) = p {
                    assert_eq!(e.group, "P");
                }
            }
        }
        let g = &rep.groups[2];
        assert_eq!(g.group, "P");
        assert_eq!(g.failures, count, "{base} {l3} {l4}: {rep:?}");
        if count > 0 {
            let (lo, hi) = g.failure.unwrap();
            // Grid values: the same formula up to an ulp of rounding.
            for (a, b) in [
                (lo[0], bbox[0]),
                (hi[0], bbox[1]),
                (lo[1], bbox[2]),
                (hi[1], bbox[3]),
            ] {
                assert!((a - b).abs() < 1e-15, "box {lo:?} {hi:?} vs {bbox:?}");
            }
        }
        eprintln!("five-bar base {base} l3 {l3} l4 {l4}: {count} failing grid points");
    }
}

// ---------------------------------------------------------------------------
// Six-bar: the four-bar assembles over the turn; the second RRR, on the
// rocker's tip, does not.
// ---------------------------------------------------------------------------

mechanism! {
    /// Crank-rocker O2-A-B-O4 (130, 40, 120, 100), then an RRR from the
    /// rocker's tip B to a ground pivot O6 = (130, o6y), links `l5`, `l6`.
    pub Six {
        params { o6y = 180.0, l5 = 70.0, l6 = 50.0 }
        analysis position;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(130.0, 0.0);
        let O6 = ground(130.0, o6y);
        let A = crank(O2, 40.0, theta) as link2;
        let B = rrr(A, 120.0, O4, 100.0, left) as (link3, link4);
        let D = rrr(B, l5, O6, l6, left) as (link5, link6);
    }
}

/// The four-bar (130, 40, 120, 100, `left`) solved here: `B` at crank angle
/// `theta` (circle intersection, B to the left of A -> O4).
fn six_b(theta: f64) -> Point2<f64> {
    let a = (40.0 * theta.cos(), 40.0 * theta.sin());
    let (dx, dy) = (130.0 - a.0, -a.1);
    let d = dx.hypot(dy);
    let along = (120.0f64.powi(2) - 100.0f64.powi(2) + d * d) / (2.0 * d);
    let h = (120.0f64.powi(2) - along * along).sqrt();
    let (ex, ey) = (dx / d, dy / d);
    Point2::new(a.0 + along * ex - h * ey, a.1 + along * ey + h * ex)
}

/// The crank angles in `[0, 2 pi)` at which the rocker's tip is at `b`: `A`
/// is where the crank circle meets the coupler circle about `b`; of the two,
/// those whose forward solution is `b` (the `left` branch).
fn six_theta_at(b: Point2<f64>) -> Vec<f64> {
    let d = b.coords.norm();
    let along = (40.0f64.powi(2) - 120.0f64.powi(2) + d * d) / (2.0 * d);
    let h = (40.0f64.powi(2) - along * along).sqrt();
    let (ex, ey) = (b.x / d, b.y / d);
    let mut out = Vec::new();
    for s in [1.0, -1.0] {
        let a = (along * ex - s * h * ey, along * ey + s * h * ex);
        let theta = wrap(a.1.atan2(a.0));
        if (six_b(theta) - b).norm() < 1e-9 {
            out.push(theta);
        }
    }
    out.sort_by(f64::total_cmp);
    out
}

#[test]
fn six_bar_second_group_fails_past_the_rocker_limit() {
    for o6y in [180.0, 175.0, 190.0] {
        let (l5, l6) = (70.0, 50.0);
        let m = Six::<f64> { o6y, l5, l6 };
        let rep = m.check();
        let names: Vec<&str> = rep.groups.iter().map(|g| g.group).collect();
        assert_eq!(names, ["A", "B", "D"]);
        assert_eq!(rep.groups[1].failures, 0, "the four-bar assembles: {rep:?}");
        // |B - O6|^2 = l4^2 + o6y^2 - 2 l4 o6y cos(psi - 90 deg) = (l5 + l6)^2.
        let c = (100.0f64.powi(2) + o6y * o6y - (l5 + l6) * (l5 + l6)) / (2.0 * 100.0 * o6y);
        // The rocker swings over psi in [92.9, 142.0] deg, so only the limit
        // above 90 deg matters.
        let psi = PI / 2.0 + c.acos();
        let b = Point2::new(130.0 + 100.0 * psi.cos(), 100.0 * psi.sin());
        let ends = six_theta_at(b);
        assert_eq!(ends.len(), 2, "the rocker passes the limit twice a turn");
        // The rocker is past psi (D fails) between the two crank angles when
        // it is past psi at their middle; else the interval runs over 0.
        let mid = 0.5 * (ends[0] + ends[1]);
        let past = |theta: f64| {
            let b = six_b(theta);
            (b.x - 130.0).hypot(b.y - o6y) > l5 + l6
        };
        let (lo, hi) = if past(mid) {
            (ends[0], ends[1])
        } else {
            (ends[1] - 2.0 * PI, ends[0])
        };
        let d = &rep.groups[2];
        assert_eq!(d.failures, 1, "o6y {o6y}: {rep:?}");
        let (glo, ghi) = d.failure.unwrap();
        // The closed form inverts the four-bar through a square root that is
        // well conditioned here (the two circle intersections are far apart);
        // its rounding is a few eps, below the 1e-10 x 2 pi edge tolerance.
        near_angle(glo[0], lo, EDGE * 2.0 * PI, &format!("o6y {o6y}: start"));
        near_angle(ghi[0], hi, EDGE * 2.0 * PI, "end");
        for (x, ok) in [(lo - 1e-9, true), (lo + 1e-9, false), (hi + 1e-9, true)] {
            match m.position(&SixInput { theta: x }) {
                Ok(p) => {
                    assert!(ok, "{x} should fail");
                    assert!(p.D.x.is_finite() && p.D.y.is_finite());
                }
                Err(e) => {
                    assert!(!ok, "{x} should assemble: {e}");
                    assert_eq!(e.group, "D", "the second group fails, not B");
                }
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Ranges suggested by the expansion-time check (tests/ui/sweep_*.stderr)
// written back into the definitions: they must compile, and `check()` (the
// same sweep, at run time) finds them clean. `#[self_test]` on each.
// ---------------------------------------------------------------------------

mod suggested {
    use mechanism::mechanism;

    mechanism! {
        /// tests/ui/sweep_double_rocker_range.rs with its suggested range
        /// (the help shows the larger of the two pieces left, [90, 133.05] deg).
        #[self_test]
        pub Rocker {
            let O2 = ground(0.0, 0.0);
            let O4 = ground(130.0, 0.0);
            let A = crank(O2, 40.0, theta) as link2;
            let B = rrr(A, 90.0, O4, 70.0, left) as (link3, link4);
            range theta = (90.1 deg, 133 deg);
        }
    }

    mechanism! {
        /// tests/ui/sweep_offset_slider_range.rs with its suggested range.
        #[self_test]
        pub Slider {
            let O = ground(0.0, 0.0);
            let line = guide((0.0, 0.0), 0 deg);
            let A = crank(O, 0.1, theta) as link2;
            let B = rrp(A, 0.12, line, plus, 0.05) as (link3, slider) slide x;
            range theta = (0.1 deg, 224.4 deg);
        }
    }

    mechanism! {
        /// tests/ui/sweep_rpr_full_turn.rs with its suggested range (shown as
        /// `(-335.8 deg, -24.2 deg)` before the middle-at-180-deg fix in
        /// `check.rs`).
        #[self_test]
        pub Inverted {
            let O = ground(0.0, 0.0);
            let B = ground(0.12, 0.0);
            let A = crank(O, 0.1, theta) as link2;
            let s = rpr(A, B, plus, 0.05) as (block, rocker);
            range theta = (24.2 deg, 335.8 deg);
        }
    }

    mechanism! {
        /// tests/ui/sweep_six_bar_second_group.rs with its suggested range.
        #[self_test]
        pub Six {
            let O2 = ground(0.0, 0.0);
            let O4 = ground(130.0, 0.0);
            let O6 = ground(130.0, 180.0);
            let A = crank(O2, 40.0, theta) as link2;
            let B = rrr(A, 120.0, O4, 100.0, left) as (link3, link4);
            let D = rrr(B, 70.0, O6, 50.0, left) as (link5, link6);
            range theta = (-56.6 deg, 155 deg);
        }
    }

    mechanism! {
        /// tests/ui/sweep_prp_full_turn.rs with its suggested range.
        #[self_test]
        pub Cross {
            let O = ground(0.0, 0.0);
            let V = ground(0.3, 0.0);
            let vertical = guide(V, 90 deg);
            let A = crank(O, 0.1, theta) as crank_link;
            let rod_line = guide(O, crank_link, 30 deg);
            let C = prp(rod_line, vertical) as (b1, b2) slide (s1, s2);
            range theta = (60.1 deg, 239.9 deg);
        }
    }

    mechanism! {
        /// tests/ui/sweep_inner_limit_range.rs with its suggested range.
        #[self_test]
        pub Folded {
            let O2 = ground(0.0, 0.0);
            let O4 = ground(130.0, 0.0);
            let A = crank(O2, 40.0, theta) as link2;
            let B = rrr(A, 200.0, O4, 100.0, left) as (link3, link4);
            range theta = (35.2 deg, 89.9 deg);
        }
    }

    mechanism! {
        /// tests/ui/sweep_rpr_range.rs with its suggested range.
        #[self_test]
        pub InvertedDeclared {
            let O = ground(0.0, 0.0);
            let B = ground(0.12, 0.0);
            let A = crank(O, 0.1, theta) as link2;
            let s = rpr(A, B, plus, 0.05) as (block, rocker);
            range theta = (24.2 deg, 179.9 deg);
        }
    }

    mechanism! {
        /// tests/ui/sweep_prp_between_samples.rs (guides parallel between
        /// two samples, a compile error since the verdict no longer depends
        /// on where the samples fall) with its suggested range.
        #[self_test]
        pub CrossBetween {
            let O = ground(0.0, 0.0);
            let V = ground(0.3, 0.0);
            let vertical = guide(V, 90 deg);
            let A = crank(O, 0.1, theta) as crank_link;
            let rod_line = guide(O, crank_link, 33.33 deg);
            let C = prp(rod_line, vertical) as (b1, b2) slide (s1, s2);
            range theta = (56.7 deg, 236.6 deg);
        }
    }

    #[test]
    fn suggested_ranges_are_clean_at_run_time() {
        assert!(Folded::<f64>::default().check().is_clean());
        assert!(InvertedDeclared::<f64>::default().check().is_clean());
        assert!(Rocker::<f64>::default().check().is_clean());
        assert!(Slider::<f64>::default().check().is_clean());
        assert!(Inverted::<f64>::default().check().is_clean());
        assert!(Six::<f64>::default().check().is_clean());
        assert!(Cross::<f64>::default().check().is_clean());
        assert!(CrossBetween::<f64>::default().check().is_clean());
    }
}
