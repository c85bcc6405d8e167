//! Definitions the stability suite's scenes do not have, driven to their
//! singular poses, against the double-double references: a five-bar whose
//! forearms become collinear, an RPR whose line passes through its pin and
//! an RPR at its edge of assembly with an offset (whole definitions, against
//! the loop-closure reference); a PRP whose guides become parallel (carried
//! and fixed), an RPP whose slot becomes parallel to its guide, a linear
//! actuator at its dead centres, an RRP at its edge with an offset (per
//! group, from exact inputs).
//!
//! Every case asserts: an `Ok` answer is finite and within `c eps / kappa^k`
//! of the reference (normwise relative per stage), `kappa` the exact
//! condition of the pose and `k`, `c` stated per case with the reason; an
//! `Err` names the group and carries the fault the geometry calls for; the
//! velocity's `condition` indicator is within a factor of the exact `kappa`
//! (so it falls when the digits do); nothing panics.
//!
//! `cargo test --release --test stability singular_definitions --
//! --nocapture` prints the measured worst figures.

use super::bounds::{all_finite, decades, typed, Worst};
use super::param_defs::*;
use super::reference_errors::*;
use super::scale_definitions::SWEEP_K;
use mechanism::{mechanism, Error, Fault, Real};
use mechanism_reference::constraint::{Constraint, Linkage, Point, Side};
use mechanism_reference::groups::{self as rg, Line};
use mechanism_reference::loop_closure;
use mechanism_reference::Dd;

// ---------------------------------------------------------------------------
// Toggles and dead centres of whole definitions approached geometrically.

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

// ---------------------------------------------------------------------------
// The parameter definitions (`param_defs.rs`) approaching their singular
// poses.

/// Runs `sample` over `cases` (label, argument); asserts the bound on `Ok`
/// samples and the indicator, `err_ok` on errors (which must be typed for
/// `group`); returns the worst figures.
#[allow(clippy::too_many_arguments)]
fn approach_run<T: Real + core::fmt::Debug>(
    cases: &[(String, f64)],
    sample: impl Fn(f64, &str) -> Sample<T>,
    group: &str,
    k: [i32; 3],
    c: [f64; 3],
    fault_ok: impl Fn(&Fault<T>, f64) -> bool,
    name: &str,
) -> Worst {
    let eps = T::eps().as_f64();
    let mut worst = Worst::new();
    for (label, x) in cases {
        let what = format!("{name} {label}");
        match sample(*x, &what) {
            // No reference (inside the code's rounding band): no figures.
            Ok((e, _, _)) if e[0].is_nan() => {}
            Ok((e, kappa, cond)) => {
                worst.record(e, kappa, k, c, eps, &what);
                worst.indicator(cond, kappa, &what);
            }
            Err(er) => {
                typed(&er, group, |f| fault_ok(f, *x), &what);
                worst.errs += 1;
            }
        }
    }
    worst.print(name);
    worst
}

/// PRP with its guides approaching parallel: the rod (carried by the crank)
/// at `theta = phi + delta`, `delta` 1e-1 .. 1e-15 rad (f32: to 1e-7), both
/// sides. `kappa = |sin delta|`. The determinant `cross(d1, d2)` cancels to
/// `kappa` from unit vectors each rounded to an ulp: `eps / kappa` relative,
/// which is the positions' error (`C ~ h / kappa`, `k = 1`); the rates and
/// accelerations are quotients by the same determinant of data carrying
/// `C`'s relative error (`w ~ omega perp(C)`, no further cancellation), so
/// `k = 1` for them too. `c = 16`: the angle's `sin`/`cos` within an ulp,
/// `phi`'s own, and a handful of roundings (measured constants printed).
/// `Singular` naming C only where `kappa <= 16 eps` (the threshold) up to
/// rounding (2x).
fn prp_parallel_run<T: Real + core::fmt::Debug>(name: &str, smallest: f64) {
    let m = PrpRod::<T>::default();
    let eps = T::eps().as_f64();
    let mut cases = Vec::new();
    for x in decades().into_iter().filter(|&x| x >= smallest) {
        for sign in [1.0, -1.0] {
            cases.push((format!("delta {:e}", sign * x), 0.4 + sign * x));
        }
    }
    // The carried guide and the fixed one: also both carried through the
    // other crossing, theta = phi + pi.
    for x in decades().into_iter().filter(|&x| x >= smallest) {
        cases.push((format!("delta pi + {x:e}"), 0.4 + std::f64::consts::PI + x));
    }
    approach_run::<T>(
        &cases,
        |x, w| prp_sample(&m, x, w),
        "C",
        [1, 1, 1],
        [16.0; 3],
        |f, x| {
            let delta = ((x - 0.4).sin()).abs();
            matches!(f, Fault::Singular { .. }) && delta < 64.0 * eps
        },
        name,
    );
}

#[test]
fn prp_guides_approaching_parallel() {
    prp_parallel_run::<f64>("f64 prp rod to parallel", 0.0);
    prp_parallel_run::<f32>("f32 prp rod to parallel", 1e-7);
}

/// PRP on two fixed guides (the group's primitive, as the generated code
/// calls it for fixed guides): the second guide at `phi + delta`. Position
/// only (the rates of fixed guides are zero): `k = 1`, `c = 16` as above.
#[test]
fn prp_fixed_guides_approaching_parallel() {
    use mechanism::dyad::prp;
    use mechanism::guide::Line as CLine;
    use nalgebra::{Point2, Vector2};
    let mut worst = Worst::new();
    for x in decades() {
        for sign in [1.0, -1.0] {
            let what = format!("prp fixed delta {:e}", sign * x);
            let (p1, p2) = (0.4f64, 0.4 + sign * x);
            let g1 = CLine {
                origin: Point2::new(0.0, 0.0),
                dir: Vector2::new(p1.cos(), p1.sin()),
            };
            let g2 = CLine {
                origin: Point2::new(0.3, 1.0),
                dir: Vector2::new(p2.cos(), p2.sin()),
            };
            match prp::position(&g1, 0.1, &g2, -0.2) {
                Ok(p) => {
                    let got = [p.c.x, p.c.y, p.s1, p.s2];
                    all_finite(&got, &what);
                    let r1 = Line::new([0.0, 0.0], [g1.dir.x, g1.dir.y]);
                    let r2 = Line::new([0.3, 1.0], [g2.dir.x, g2.dir.y]);
                    let (c, s1, s2) = rg::prp_position(&r1, 0.1, &r2, -0.2).unwrap();
                    let e = rel(&got[..2], &flat(&[c])).max(rel(&got[2..], &[s1, s2]));
                    let kappa = rg::cross(r1.dir, r2.dir).abs().to_f64();
                    worst.record(
                        [e, 0.0, 0.0],
                        kappa,
                        [1, 1, 1],
                        [16.0; 3],
                        f64::EPSILON,
                        &what,
                    );
                }
                Err(e) => {
                    assert!(matches!(e.fault, Fault::Singular { .. }), "{what}: {e:?}");
                    assert!(x < 64.0 * f64::EPSILON, "{what}: {e:?}");
                    worst.errs += 1;
                }
            }
        }
    }
    worst.print("f64 prp fixed guides to parallel");
}

/// RPP with the slot approaching parallel to the guide (`slot = delta`, and
/// `pi - delta`). `kappa = |sin slot|`. The determinant is `|dir|^2 sin
/// slot` (no cancellation: the slot's world direction is built from the
/// guide's), so the slides `~ 1 / kappa` carry only the rounding of their
/// data and of `sin`: `k = 1` is the bound's allowance for the rates'
/// right-hand sides, measured far below it; `c = 16`. `Singular` naming Q
/// only at `kappa <= 16 eps` (2x rounding).
fn rpp_parallel_run<T: Real + core::fmt::Debug>(name: &str, smallest: f64) {
    let eps = T::eps().as_f64();
    let mut cases = Vec::new();
    for x in decades().into_iter().filter(|&x| x >= smallest) {
        cases.push((format!("slot {x:e}"), x));
        cases.push((format!("slot pi - {x:e}"), std::f64::consts::PI - x));
    }
    approach_run::<T>(
        &cases,
        |x, w| {
            let m = RppSlot::<T> {
                slot: T::lit(x),
                ..RppSlot::<T>::default()
            };
            rpp_sample(&m, 0.9, w)
        },
        "Q",
        [1, 1, 1],
        [16.0; 3],
        |f, x| matches!(f, Fault::Singular { .. }) && x.sin().abs() < 64.0 * eps,
        name,
    );
}

#[test]
fn rpp_slot_approaching_parallel() {
    rpp_parallel_run::<f64>("f64 rpp slot to parallel", 0.0);
    rpp_parallel_run::<f32>("f32 rpp slot to parallel", 1e-7);
}

/// The linear actuator at full extension (`len = (b + r)(1 - delta)`) and
/// full retraction (`len = (b - r)(1 + delta)`): the RRR toggle, `kappa ~
/// sqrt(delta)`. Positions `c eps / kappa`, rates `/ kappa^2`,
/// accelerations `/ kappa^3` (the RRR's reasons, `TOGGLE_C` above),
/// `c = 8`. Errors (`Singular`, or `CannotAssemble` from the other side of
/// the rounding band) naming C only for `delta < 1e-13` (the band `4 eps`).
#[test]
fn actuator_dead_centres() {
    for (name, base, sign) in [("extension", 3.0, -1.0), ("retraction", 1.0, 1.0)] {
        let cases: Vec<(String, f64)> = decades()
            .into_iter()
            .map(|x| (format!("delta {x:e}"), base * (1.0 + sign * x)))
            .collect();
        let m = Ram::<f64>::default();
        approach_run::<f64>(
            &cases,
            |len, w| ram_sample(&m, len, 0.7, -3.0, w),
            "C",
            [1, 2, 3],
            [8.0; 3],
            |f, len| {
                matches!(f, Fault::Singular { .. } | Fault::CannotAssemble { .. })
                    && (len / base - 1.0).abs() < 1e-13
            },
            &format!("f64 actuator full {name}"),
        );
    }
}

/// RRP at its edge of assembly with a non-zero offset, both signs (the line
/// y = e below the crank tip A and above it), from inside and outside: `e`
/// puts A at `l (1 -+ rel)` from the line, rel 1e-1 .. 1e-15. `kappa =
/// |cos|` of link 1 against the guide `~ sqrt(2 rel)`: positions `c eps /
/// kappa`, rates `/ kappa^2`, accelerations `/ kappa^3`, `c = 8` (as the
/// RRR's edge). Outside by more than the band (`4 eps l`, `rel > 1e-13`):
/// `CannotAssemble` naming C; inside it must assemble unless within the
/// band.
#[test]
fn rrp_edge_with_offset() {
    let theta = 1.2f64;
    let ay = theta.sin();
    let l = 1.5;
    let mut refused = 0;
    for (side, dist_sign) in [("line below A", 1.0), ("line above A", -1.0)] {
        for (way, rel_sign) in [("inside", -1.0), ("outside", 1.0)] {
            let cases: Vec<(String, f64)> = decades()
                .into_iter()
                .map(|x| (format!("rel {x:e}"), x))
                .collect();
            let w = approach_run::<f64>(
                &cases,
                |x, what| {
                    let e = ay - dist_sign * l * (1.0 + rel_sign * x);
                    let m = RrpEdge::<f64> {
                        e,
                        l,
                        ..RrpEdge::<f64>::default()
                    };
                    let r = rrp_sample(&m, theta, what);
                    if r.is_ok() {
                        assert!(!(rel_sign > 0.0 && x > 1e-13), "{what}: assembled outside");
                    }
                    r
                },
                "C",
                [1, 2, 3],
                [8.0; 3],
                |f, x| {
                    if rel_sign > 0.0 && x > 1e-13 {
                        matches!(f, Fault::CannotAssemble { .. })
                    } else {
                        matches!(f, Fault::Singular { .. } | Fault::CannotAssemble { .. })
                            && x < 1e-13
                    }
                },
                &format!("f64 rrp edge, {side}, {way}"),
            );
            refused += w.errs;
        }
    }
    // 13 decades outside by more than the band, on two sides.
    assert!(refused >= 26, "only {refused} refused");
}
