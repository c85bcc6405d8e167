//! Extreme surface: definitions and inputs the stability suite does not use,
//! against the double-double reference (`mechanism_reference`, about 106
//! bits: Newton on the loop closure for whole definitions, `groups` for single
//! groups, `newton_euler` for forces).
//!
//! Every case asserts: an `Ok` answer is finite and within a bound of the form
//! `c eps (1 / kappa)^k` of the reference (`kappa` the exact condition of the
//! pose, `k` and `c` stated per case with the reason), an `Err` is typed (it
//! names the group, its `Fault` is the one the geometry calls for), nothing
//! panics. Errors are normwise relative per stage: `max |x - ref| / max |ref|`
//! over the points (positions, velocities, accelerations separately) and over
//! the angular quantities.
//!
//! `cargo test --release --test extreme_surface -- --nocapture` prints the
//! measured worst figures.

use mechanism::{mechanism, Error, Fault, Real};
use mechanism_reference::constraint::{Constraint, Linkage, Point, Side, V2};
use mechanism_reference::loop_closure;
use mechanism_reference::Dd;

#[path = "common/extreme.rs"]
mod extreme;
use extreme::{all_finite, decades, typed, Worst};

// ---------------------------------------------------------------------------
// Helpers.

/// A fixed reference point.
fn fixed(x: f64, y: f64) -> Point {
    Point::Fixed(V2::new(x, y))
}

/// The reference's positions, velocities and accelerations of every point.
struct Reference {
    p: Vec<V2>,
    v: Vec<V2>,
    a: Vec<V2>,
}

/// Solves the reference linkage for inputs `q` (rad), rates `w`, accelerations
/// `al`, from the start guess `start` (the code under test's answer: it only
/// picks the branch).
fn reference(
    l: &Linkage,
    q: &[f64],
    w: &[f64],
    al: &[f64],
    start: &[(f64, f64)],
) -> Option<Reference> {
    let dd = |x: &[f64]| x.iter().map(|&v| Dd::from_f64(v)).collect::<Vec<_>>();
    let (q, w, al) = (dd(q), dd(w), dd(al));
    let pose = loop_closure::position(l, &q, start).ok()?;
    let v = loop_closure::velocity(l, &pose, &q, &w).ok()?;
    let a = loop_closure::acceleration(l, &pose, &v, &q, &w, &al).ok()?;
    Some(Reference {
        p: pose.points,
        v,
        a,
    })
}

/// `|V2|` in double-double.
fn norm(v: V2) -> Dd {
    v.dot(v).sqrt()
}

/// Normwise relative error of `got` against `r`: `max |got - r| / max |r|`.
fn rel_pts(got: &[(f64, f64)], r: &[V2]) -> f64 {
    let mut e = 0.0f64;
    let mut s = 0.0f64;
    for (g, r) in got.iter().zip(r) {
        e = e.max(norm(V2::new(g.0, g.1).minus(*r)).to_f64());
        s = s.max(norm(*r).to_f64());
    }
    if s > 0.0 {
        e / s
    } else {
        e
    }
}

/// Normwise relative error of scalars.
fn rel_scalars(got: &[f64], r: &[Dd]) -> f64 {
    let mut e = 0.0f64;
    let mut s = 0.0f64;
    for (g, r) in got.iter().zip(r) {
        e = e.max((Dd::from_f64(*g) - *r).abs().to_f64());
        s = s.max(r.abs().to_f64());
    }
    if s > 0.0 {
        e / s
    } else {
        e
    }
}

/// `sin` of the angle between two vectors, exact to double-double.
fn sin_between(a: V2, b: V2) -> f64 {
    (a.cross(b).abs() / (norm(a) * norm(b))).to_f64()
}

fn pt<T: Real>(p: &mechanism::Point2<T>) -> (f64, f64) {
    (p.x.as_f64(), p.y.as_f64())
}

fn vc<T: Real>(p: &mechanism::Vector2<T>) -> (f64, f64) {
    (p.x.as_f64(), p.y.as_f64())
}

// ---------------------------------------------------------------------------
// 1. Scales through run-time params: 1e-9 .. 1e9, f64 and f32; mixed scales.

mechanism! {
    /// Crank-rocker four-bar with every dimension a run-time parameter
    /// (lengths in any unit; the defaults are the seed's in decimetres).
    pub ScaledFourBar {
        params { ground = 3.048, crank = 1.016, coupler = 2.54, rocker = 1.778, px = 1.2, py = 0.5 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        let P = point(link3, from A, (px, py));
    }
}

/// The reference of [`ScaledFourBar`] with the given (exact) dimensions:
/// points O2, O4, A, B, P.
fn fourbar_linkage(g: f64, r: f64, c: f64, k: f64, px: f64, py: f64) -> Linkage {
    // P = A + px (B - A) / c + py perp(B - A) / c.
    let (a, b) = (
        Dd::from_f64(px) / Dd::from_f64(c),
        Dd::from_f64(py) / Dd::from_f64(c),
    );
    Linkage {
        points: vec![
            fixed(0.0, 0.0),
            fixed(g, 0.0),
            Point::Unknown,
            Point::Unknown,
            Point::Unknown,
        ],
        constraints: vec![
            Constraint::Crank {
                p: 2,
                o: 0,
                r,
                input: 0,
            },
            Constraint::Distance { p: 3, q: 2, len: c },
            Constraint::Distance { p: 3, q: 1, len: k },
            Constraint::Affine {
                p: 4,
                o: 2,
                q: 3,
                a,
                b,
            },
        ],
        sides: vec![Side::Left {
            p: 3,
            a: 2,
            b: 1,
            sign: 1.0,
        }],
        scale: g,
    }
}

/// One scaled four-bar sample in `T`: errors per stage against the
/// reference, kappa (sine of the transmission angle), or `None` if the
/// reference fails (never expected here).
fn fourbar_sample<T: Real + core::fmt::Debug>(
    m: &ScaledFourBar<T>,
    theta: f64,
    w: f64,
    al: f64,
    what: &str,
) -> ([f64; 3], f64) {
    let inp = |x: f64| ScaledFourBarInput { theta: T::lit(x) };
    let s = m
        .solve(&inp(theta), &inp(w), &inp(al))
        .unwrap_or_else(|e| panic!("{what}: the crank-rocker assembles everywhere: {e:?}"));
    let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
    let gp = [pt(&p.A), pt(&p.B), pt(&p.P)];
    let gv = [vc(&v.A), vc(&v.B), vc(&v.P)];
    let ga = [vc(&a.A), vc(&a.B), vc(&a.P)];
    let ang_v = [v.link3.as_f64(), v.link4.as_f64()];
    let ang_a = [a.link3.as_f64(), a.link4.as_f64()];
    let flat: Vec<f64> = gp
        .iter()
        .chain(&gv)
        .chain(&ga)
        .flat_map(|x| [x.0, x.1])
        .chain(ang_v)
        .chain(ang_a)
        .chain([v.condition.as_f64()])
        .collect();
    all_finite(&flat, what);
    let l = fourbar_linkage(
        m.ground.as_f64(),
        m.crank.as_f64(),
        m.coupler.as_f64(),
        m.rocker.as_f64(),
        m.px.as_f64(),
        m.py.as_f64(),
    );
    // The angle the code used is the T-rounded one.
    let th = T::lit(theta).as_f64();
    let start = [(0.0, 0.0), (0.0, 0.0), gp[0], gp[1], gp[2]];
    let r = reference(
        &l,
        &[th],
        &[T::lit(w).as_f64()],
        &[T::lit(al).as_f64()],
        &start,
    )
    .unwrap_or_else(|| panic!("{what}: reference failed"));
    let ep = rel_pts(&gp, &r.p[2..]);
    let wr = [
        loop_closure::angular_velocity(&r.p, &r.v, 2, 3),
        loop_closure::angular_velocity(&r.p, &r.v, 1, 3),
    ];
    let ar = [
        loop_closure::angular_acceleration(&r.p, &r.v, &r.a, 2, 3),
        loop_closure::angular_acceleration(&r.p, &r.v, &r.a, 1, 3),
    ];
    let ev = rel_pts(&gv, &r.v[2..]).max(rel_scalars(&ang_v, &wr));
    let ea = rel_pts(&ga, &r.a[2..]).max(rel_scalars(&ang_a, &ar));
    let kappa = sin_between(r.p[3].minus(r.p[2]), r.p[3].minus(r.p[1]));
    ([ep, ev, ea], kappa)
}

fn scaled<T: Real>(s: f64) -> ScaledFourBar<T> {
    let b = ScaledFourBar::<f64>::default();
    ScaledFourBar {
        ground: T::lit(b.ground * s),
        crank: T::lit(b.crank * s),
        coupler: T::lit(b.coupler * s),
        rocker: T::lit(b.rocker * s),
        px: T::lit(b.px * s),
        py: T::lit(b.py * s),
    }
}

/// Bound for the whole-definition sweeps at ordinary poses (kappa >= 0.3 for
/// this crank-rocker): positions `c eps / kappa` (the joint's height over the
/// line of centres, see `stability.md`), rates `c eps / kappa^2` and
/// accelerations `c eps / kappa^3` (each stage solves the same 2x2 system,
/// whose inverse has norm `1 / kappa`, on data carrying the previous stage's
/// error). `c = 32`: the parameters themselves round (half an ulp each,
/// relative), the angle's `cos`/`sin` are within an ulp, and a handful of
/// operations per stage each add half an ulp: the measured constants
/// (printed) stay below 8; 32 leaves a factor of four without hiding a lost
/// digit.
const SWEEP_K: [i32; 3] = [1, 2, 3];
const SWEEP_C: [f64; 3] = [32.0, 32.0, 32.0];

fn scales_run<T: Real + core::fmt::Debug>(scales: &[f64], eps: f64, name: &str) {
    for &s in scales {
        let m = scaled::<T>(s);
        let mut worst = Worst::new();
        for i in 0..48 {
            let theta = -3.1 + 0.1311 * i as f64;
            let what = format!("{name} scale {s:e} theta {theta}");
            let (e, kappa) = fourbar_sample(&m, theta, 7.3, -41.0, &what);
            worst.record(e, kappa, SWEEP_K, SWEEP_C, eps, &what);
        }
        worst.print(&format!("{name} four-bar at scale {s:e}"));
    }
}

#[test]
fn scales_1e_minus9_to_1e9_f64() {
    scales_run::<f64>(&[1e-9, 1e-3, 1.0, 1e3, 1e9], f64::EPSILON, "f64");
}

#[test]
fn scales_1e_minus9_to_1e9_f32() {
    // f32 represents 1e-9 .. 1e9 lengths; squared lengths (1e-19 .. 1e19 here
    // with the 0.1 .. 0.3 base) are normal numbers too.
    scales_run::<f32>(&[1e-9, 1e-3, 1.0, 1e3, 1e9], f32::EPSILON as f64, "f32");
}

/// Lengths far from 1 where the RRR's Heron product (fourth power of the
/// lengths) leaves the normal range while every length, square and result is
/// an ordinary number: f32 3e-12 .. 1e12 (before the fix: 5e5 eps wrong,
/// silently, at 3e-12 from a subnormal product; `CannotAssemble`/`Singular`
/// from 3e9 up from an infinite one), f64 1e-100 and 1e100 (a zero or
/// infinite product). Same bound as the ordinary scales.
#[test]
fn rrr_lengths_far_from_one() {
    scales_run::<f32>(
        &[3e-12, 1e-11, 1e-10, 3e9, 1e10, 1e12],
        f32::EPSILON as f64,
        "f32 far",
    );
    scales_run::<f64>(&[1e-100, 1e-80, 1e80, 1e100], f64::EPSILON, "f64 far");
}

/// Mixed scales in one definition: a 1.3e-3 crank on a 1000.3 frame (a
/// crank-rocker: 1.3e-3 + 1000.3 <= 999.1 + 1.7). Errors per stage relative
/// to the stage's largest value: the crank's motion is tiny against the
/// frame, so this checks that nothing is lost against the large lengths.
#[test]
fn mixed_scales_small_crank_large_frame() {
    let m = ScaledFourBar::<f64> {
        ground: 1000.3,
        crank: 1.3e-3,
        coupler: 999.1,
        rocker: 1.7,
        px: 500.0,
        py: 0.01,
    };
    let mut worst = Worst::new();
    for i in 0..48 {
        let theta = -3.1 + 0.1311 * i as f64;
        let what = format!("mixed theta {theta}");
        let (e, kappa) = fourbar_sample(&m, theta, 7.3, -41.0, &what);
        // Positions relative to the frame (1000). The rocker (1.7) is
        // pivoted at 1000.3: its pivot, and B, carry rounding of eps * 1000,
        // which is eps * 1000 / 1.7 of the rocker's direction, hence of the
        // rates and accelerations (inherent: the input O4 itself is rounded
        // so). Bound: `c = 4` times that ratio for rates and accelerations.
        let lratio = m.ground / m.rocker;
        worst.record(
            e,
            kappa,
            SWEEP_K,
            [SWEEP_C[0], 4.0 * lratio, 4.0 * lratio],
            f64::EPSILON,
            &what,
        );
    }
    worst.print("f64 mixed 1.3e-3 crank on 1000.3 frame");
}

// ---------------------------------------------------------------------------
// 2. Toggles and dead centres approached geometrically.

/// Distances from the singular pose: 1e-1 .. 1e-15 (rad), both sides, with a
/// non-round mantissa.
fn approach() -> Vec<f64> {
    let mut out: Vec<f64> = decades().into_iter().flat_map(|d| [d, -d]).collect();
    out.push(0.0);
    out
}

mechanism! {
    /// Five-bar whose forearms are collinear (stretched) at theta1 = theta2
    /// = 0: B1 = (1, 0), B2 = (-3, 0), l1 + l2 = 4.
    pub StretchedFiveBar {
        let O1 = ground(0.0, 0.0);
        let O2 = ground(-4.0, 0.0);
        let B1 = crank(O1, 1.0, t1) as arm1;
        let B2 = crank(O2, 1.0, t2) as arm2;
        let C = rrr(B1, 2.5, B2, 1.5, left) as (fore1, fore2);
    }
}

/// Toggle bound: positions `c eps / kappa`, rates `c eps / kappa^2`,
/// accelerations `c eps / kappa^3` (see `SWEEP_K`): at a toggle reached by
/// the input, `delta ~ kappa^2`, the joint's height has relative error `eps /
/// delta` (stability.md, end to end), which is `eps / kappa^2` in the rates'
/// determinant and, through the `omega^2` terms, `eps / kappa^3` in the
/// accelerations. `c = 8` as the existing end-to-end bound.
const TOGGLE_C: [f64; 3] = [8.0, 8.0, 8.0];

#[test]
fn five_bar_forearms_nearly_collinear() {
    let m = StretchedFiveBar::<f64>::default();
    let l = Linkage {
        points: vec![
            fixed(0.0, 0.0),
            fixed(-4.0, 0.0),
            Point::Unknown,
            Point::Unknown,
            Point::Unknown,
        ],
        constraints: vec![
            Constraint::Crank {
                p: 2,
                o: 0,
                r: 1.0,
                input: 0,
            },
            Constraint::Crank {
                p: 3,
                o: 1,
                r: 1.0,
                input: 1,
            },
            Constraint::Distance {
                p: 4,
                q: 2,
                len: 2.5,
            },
            Constraint::Distance {
                p: 4,
                q: 3,
                len: 1.5,
            },
        ],
        sides: vec![Side::Left {
            p: 4,
            a: 2,
            b: 3,
            sign: 1.0,
        }],
        scale: 4.0,
    };
    let mut worst = Worst::new();
    for d in approach() {
        for t2 in [0.0, 0.37 * d] {
            let what = format!("five-bar t1 {d:e} t2 {t2:e}");
            let inp = |a: f64, b: f64| StretchedFiveBarInput { t1: a, t2: b };
            match m.solve(&inp(d, t2), &inp(3.1, -1.7), &inp(20.0, 5.0)) {
                Ok(s) => {
                    let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
                    let g = [
                        [pt(&p.B1), pt(&p.B2), pt(&p.C)],
                        [vc(&v.B1), vc(&v.B2), vc(&v.C)],
                        [vc(&a.B1), vc(&a.B2), vc(&a.C)],
                    ];
                    let flat: Vec<f64> = g
                        .iter()
                        .flatten()
                        .flat_map(|x| [x.0, x.1])
                        .chain([v.fore1, v.fore2, a.fore1, a.fore2])
                        .collect();
                    all_finite(&flat, &what);
                    let start = [(0.0, 0.0), (0.0, 0.0), g[0][0], g[0][1], g[0][2]];
                    let Some(r) = reference(&l, &[d, t2], &[3.1, -1.7], &[20.0, 5.0], &start)
                    else {
                        // The reference is singular only at the exact toggle
                        // (the code answered inside its rounding band).
                        assert!(d == 0.0 || d.abs() < 1e-7, "{what}: reference failed");
                        continue;
                    };
                    let kappa = sin_between(r.p[4].minus(r.p[2]), r.p[4].minus(r.p[3]));
                    let e = [
                        rel_pts(&g[0], &r.p[2..]),
                        rel_pts(&g[1], &r.v[2..]),
                        rel_pts(&g[2], &r.a[2..]),
                    ];
                    worst.record(e, kappa, SWEEP_K, TOGGLE_C, f64::EPSILON, &what);
                }
                Err(e) => {
                    typed(&e, "C", |f| matches!(f, Fault::Singular { .. }), &what);
                    // Only where the positions themselves are undetermined:
                    // |B2 - B1| within the rounding band `4 eps (l1 + l2)` of
                    // l1 + l2, i.e. delta = 1 - |B2 - B1| / 4 (exact, from
                    // the crank tips in double-double) below 8 eps.
                    let (b1, b2) = (
                        mechanism_reference::groups::crank(
                            mechanism_reference::groups::v(0.0, 0.0),
                            1.0,
                            d,
                            0.0,
                            0.0,
                        )
                        .0,
                        mechanism_reference::groups::crank(
                            mechanism_reference::groups::v(-4.0, 0.0),
                            1.0,
                            t2,
                            0.0,
                            0.0,
                        )
                        .0,
                    );
                    let dist =
                        mechanism_reference::groups::norm(mechanism_reference::groups::sub(b1, b2));
                    let delta = (Dd::ONE - dist / Dd::from_f64(4.0)).to_f64();
                    assert!(
                        delta < 8.0 * f64::EPSILON,
                        "{what}: error far from the toggle (delta {delta:e}): {e:?}"
                    );
                    worst.errs += 1;
                }
            }
        }
    }
    worst.print("five-bar forearms collinear");
}

mechanism! {
    /// Inverted slider-crank: crank 1 about O, the rocker pivoted at B = (b,
    /// 0) carries the block pinned at A along a line `e` to the left of B.
    /// With e = 0 and b = 1 the line passes through the pin at theta = 0
    /// (A = B); with b = 3.5 and e = 2.5 the group is at its edge of
    /// assembly there (|A - B| = |e|).
    pub InvertedSlider {
        params { b = 1.0, e = 0.0 }
        let O = ground(0.0, 0.0);
        let B = ground(b, 0.0);
        let A = crank(O, 1.0, theta) as link2;
        let s = rpr(A, B, plus, e) as (block, rocker);
    }
}

/// The reference of [`InvertedSlider`]: points O, B, A, D = B + u (u the
/// rocker's unit axis), E = B + e perp(u), F = E + u; A on the line E F,
/// `dot(A - B, u) > 0`.
fn inverted_linkage(b: f64, e: f64) -> Linkage {
    let e = Dd::from_f64(e);
    Linkage {
        points: vec![
            fixed(0.0, 0.0),
            fixed(b, 0.0),
            Point::Unknown,
            Point::Unknown,
            Point::Unknown,
            Point::Unknown,
        ],
        constraints: vec![
            Constraint::Crank {
                p: 2,
                o: 0,
                r: 1.0,
                input: 0,
            },
            Constraint::Distance {
                p: 3,
                q: 1,
                len: 1.0,
            },
            Constraint::Affine {
                p: 4,
                o: 1,
                q: 3,
                a: Dd::ZERO,
                b: e,
            },
            Constraint::Affine {
                p: 5,
                o: 1,
                q: 3,
                a: Dd::ONE,
                b: e,
            },
            Constraint::OnLine { p: 2, q1: 4, q2: 5 },
        ],
        sides: vec![Side::Ahead {
            p: 2,
            a: 1,
            from: 1,
            to: 3,
        }],
        scale: 1.0,
    }
}

/// Runs [`InvertedSlider`] at `theta`, compares the slide and the rocker's
/// angle, rate and acceleration with the reference; returns the errors per
/// stage (relative to the stage's largest reference value) and the exact
/// `|A - B|` and slide `s`, or the error.
fn inverted_sample(
    m: &InvertedSlider<f64>,
    theta: f64,
    what: &str,
) -> Result<([f64; 3], f64, f64), Error<f64>> {
    let inp = |x: f64| InvertedSliderInput { theta: x };
    let (w, al) = (2.3, -7.0);
    let s = m.solve(&inp(theta), &inp(w), &inp(al))?;
    let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
    let got_p = [p.s, p.rocker];
    let got_v = [v.s, v.rocker];
    let got_a = [a.s, a.rocker];
    let flat: Vec<f64> = got_p
        .iter()
        .chain(&got_v)
        .chain(&got_a)
        .copied()
        .chain([v.condition])
        .collect();
    all_finite(&flat, what);
    let l = inverted_linkage(m.b, m.e);
    let u = (p.rocker.cos(), p.rocker.sin());
    let start = [
        (0.0, 0.0),
        (0.0, 0.0),
        pt(&p.A),
        (m.b + u.0, u.1),
        (m.b - m.e * u.1, m.e * u.0),
        (m.b + u.0 - m.e * u.1, u.1 + m.e * u.0),
    ];
    let r = match reference(&l, &[theta], &[w], &[al], &start) {
        Some(r) => r,
        None => {
            let q = [Dd::from_f64(theta)];
            let why = loop_closure::position(&l, &q, &start).err();
            // The reference's Newton meets its step test (1e-26) only to
            // within a factor 1 / kappa near the edge: the last step there
            // is ~1e-26 while the residual is at the dd rounding (3e-32).
            // Such samples are skipped (counted by the caller via NaN).
            assert!(
                matches!(why, Some(loop_closure::ReferenceError::NotConverged { residual, .. }) if residual < 1e-30),
                "{what}: reference failed: {why:?}"
            );
            return Ok(([f64::NAN; 3], 0.0, 0.0));
        }
    };
    let ab = r.p[2].minus(r.p[1]);
    let uu = r.p[3].minus(r.p[1]);
    let (va, vu) = (r.v[2], r.v[3]);
    let (aa, au) = (r.a[2], r.a[3]);
    let s_ref = ab.dot(uu);
    let sd = va.dot(uu) + ab.dot(vu);
    let sdd = aa.dot(uu) + Dd::from_f64(2.0) * va.dot(vu) + ab.dot(au);
    let ang = loop_closure::angle(&r.p, 1, 3);
    let om = loop_closure::angular_velocity(&r.p, &r.v, 1, 3);
    let alp = loop_closure::angular_acceleration(&r.p, &r.v, &r.a, 1, 3);
    let e = [
        rel_scalars(&got_p, &[s_ref, ang]),
        rel_scalars(&got_v, &[sd, om]),
        rel_scalars(&got_a, &[sdd, alp]),
    ];
    // The velocity's indicator: the smaller of |s| / |A - B| (the rate
    // system) and |A - B| / size (the rounding of A and B at their
    // coordinates' size). It is itself computed from rounded values, good to
    // about eps / kappa relative: within a factor 2 down to kappa ~ 1e-15.
    let (dist, sr) = (norm(ab).to_f64(), s_ref.to_f64());
    let size = p.A.x.abs().max(p.A.y.abs()).max(m.b.abs());
    let want = (sr.abs() / dist).min(dist / size).min(1.0);
    assert!(
        v.condition >= 0.5 * want && v.condition <= 2.0 * want,
        "{what}: condition {} against {want:e}",
        v.condition
    );
    Ok((e, dist, sr))
}

/// RPR whose slide line passes through the pin (offset 0): the crank tip A
/// passes at distance ~|theta| from the rocker's pivot B. The rate system's
/// condition stays 1, but the data are rounded at the crank's size (A's
/// coordinates, eps each): relative to `kappa = |A - B|` (the distance
/// relative to the crank) that is `eps / kappa` of the rocker's direction
/// (positions, `k = 1`), and the rocker's rate `cross(A - B, vA) / |A -
/// B|^2` cancels (A moves nearly along A - B here, the cross product is
/// `~ kappa^2`) so an error eps in A is `eps / kappa^2` of it (`k = 2`,
/// measured: the ratio to `eps / kappa` grows 10 times per decade);
/// accelerations `k = 3` (the `omega^2` terms on top); `c = 8`. At theta = 0
/// (A = B exactly) and wherever |A - B| is within 16 eps of the coordinates
/// (1.4e-15 rad here): a typed `Singular` naming `s`. The velocity's
/// `condition` follows `kappa` (checked below the table).
#[test]
fn rpr_line_through_the_pin() {
    let m = InvertedSlider::<f64> { b: 1.0, e: 0.0 };
    let mut worst = Worst::new();
    for d in approach() {
        let what = format!("rpr through the pin theta {d:e}");
        match inverted_sample(&m, d, &what) {
            Ok((e, ab, _)) => worst.record(e, ab, SWEEP_K, [8.0; 3], f64::EPSILON, &what),
            Err(e) => {
                typed(&e, "s", |f| matches!(f, Fault::Singular { .. }), &what);
                // Only where |A - B| (the fault's `det`) is within 16 eps of
                // the coordinates' size (its `scale`): A - B is rounding there.
                let Fault::Singular { det, scale } = e.fault else {
                    unreachable!()
                };
                assert!(
                    det <= 16.0 * f64::EPSILON * scale,
                    "{what}: error away from A = B: {e:?}"
                );
                worst.errs += 1;
            }
        }
    }
    worst.print("rpr line through the pin");
}

/// RPR at its edge of assembly with an offset (|A - B| -> |e|, the block's
/// line tangent to the circle |X - B| = |e|), from inside (theta -> 0, and e
/// 1e-1 .. 1e-15 relative below 2.5) and from outside (e above 2.5). The
/// condition is `kappa = |s| / |A - B|`, `s ~ |A - B| sqrt(2 delta)`:
/// positions `c eps / kappa` (the slide is a square root of `delta`), rates
/// `c eps / kappa^2`, accelerations `c eps / kappa^3` (as the RRR, same
/// reasons); `c = 8`. Outside by more than the rounding band: a typed
/// `CannotAssemble` naming `s`; a `Singular` only where `kappa` is at the 16
/// eps threshold.
#[test]
fn rpr_edge_of_assembly_with_offset() {
    let mut worst = Worst::new();
    let mut outside = 0;
    let mut skipped = 0;
    // Inside, approached by the input.
    let m = InvertedSlider::<f64> { b: 3.5, e: 2.5 };
    for d in approach() {
        let what = format!("rpr edge theta {d:e}");
        match inverted_sample(&m, d, &what) {
            Ok((e, _, _)) if e[0].is_nan() => skipped += 1,
            Ok((e, ab, s)) => worst.record(e, s.abs() / ab, SWEEP_K, TOGGLE_C, f64::EPSILON, &what),
            Err(e) => {
                typed(
                    &e,
                    "s",
                    |f| matches!(f, Fault::Singular { .. } | Fault::CannotAssemble { .. }),
                    &what,
                );
                // delta = 7 theta^2 / 12.5: within the rounding band below
                // |theta| ~ 3e-8.
                assert!(d.abs() < 1e-7, "{what}: error away from the edge: {e:?}");
                worst.errs += 1;
            }
        }
    }
    // Both sides by the offset at theta = 0.3 (|A - B|^2 = 13.25 - 7 cos 0.3).
    let ab = (13.25 - 7.0 * 0.3f64.cos()).sqrt();
    for k in 1..=15 {
        let rel = 1.37 * 10f64.powi(-k);
        for sign in [-1.0, 1.0] {
            let e = ab * (1.0 + sign * rel);
            let m = InvertedSlider::<f64> { b: 3.5, e };
            let what = format!("rpr edge e = |A-B| (1 {sign:+} {rel:e})");
            match inverted_sample(&m, 0.3, &what) {
                Ok((err, _, _)) if err[0].is_nan() => skipped += 1,
                Ok((err, abx, s)) => {
                    // Outside by more than the band must not assemble.
                    assert!(!(sign > 0.0 && rel > 1e-13), "{what}: assembled outside");
                    worst.record(err, s.abs() / abx, SWEEP_K, TOGGLE_C, f64::EPSILON, &what)
                }
                Err(er) => {
                    typed(
                        &er,
                        "s",
                        |f| matches!(f, Fault::Singular { .. } | Fault::CannotAssemble { .. }),
                        &what,
                    );
                    assert!(sign > 0.0 || rel < 1e-13, "{what}: inside but {er:?}");
                    if sign > 0.0 && rel > 1e-13 {
                        assert!(
                            matches!(er.fault, Fault::CannotAssemble { .. }),
                            "{what}: {er:?}"
                        );
                        outside += 1;
                    }
                    worst.errs += 1;
                }
            }
        }
    }
    assert!(outside >= 12, "only {outside} outside samples refused");
    worst.print("rpr edge with offset");
    println!("rpr edge with offset: {skipped} samples without a converged reference");
    assert!(skipped <= 6, "{skipped} samples without a reference");
}
