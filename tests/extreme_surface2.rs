//! Extreme surface, second round: the cases `extreme_surface.rs` did not
//! reach, against the double-double reference (`mechanism_reference::groups`,
//! about 106 bits, per group from exact inputs).
//!
//! Every case asserts: an `Ok` answer is finite and within `c eps / kappa^k`
//! of the reference (normwise relative per stage: positions, rates,
//! accelerations), `kappa` the exact condition of the pose and `k`, `c`
//! stated per case with the reason; an `Err` names the group and carries the
//! fault the geometry calls for; the velocity's `condition` indicator is
//! within a factor of the exact `kappa` (so it falls when the digits do);
//! nothing panics.
//!
//! `cargo test --release --test extreme_surface2 -- --nocapture` prints the
//! measured worst figures.

use mechanism::{mechanism, Error, Fault, Real};
use mechanism_reference::groups::{self as rg, Line, V};
use mechanism_reference::Dd;

#[path = "common/extreme.rs"]
mod extreme;
use extreme::{all_finite, decades, typed, Worst};

// ---------------------------------------------------------------------------
// Helpers.

fn d(x: f64) -> Dd {
    Dd::from_f64(x)
}

/// Normwise relative error of scalars `got` against `r`: `max |got - r| /
/// max |r|` (the absolute error when every `r` is 0).
fn rel(got: &[f64], r: &[Dd]) -> f64 {
    let mut e = 0.0f64;
    let mut s = 0.0f64;
    for (g, r) in got.iter().zip(r) {
        e = e.max((d(*g) - *r).abs().to_f64());
        s = s.max(r.abs().to_f64());
    }
    if s > 0.0 {
        e / s
    } else {
        e
    }
}

/// The components of reference vectors, flattened.
fn flat(vs: &[V]) -> Vec<Dd> {
    vs.iter().flat_map(|v| [v[0], v[1]]).collect()
}

// ---------------------------------------------------------------------------
// 1. The non-generated RRR rates (`dyad::rrr::velocity`, scale `|r1| |r2|`)
// at lengths far from 1.

/// `mechanism::dyad::rrr::velocity` takes the scale of its determinant from
/// the link vectors. Before the fix it was `sqrt(|r1|^2 |r2|^2)`, a fourth
/// power of the lengths: f32 lengths of 1e-12 gave a zero product and a
/// false `Singular`, 1e-11 a subnormal one (the indicator off), 1e10 an
/// infinite one (`Singular` again), while the position (which takes its
/// Heron roots apart there) was fine. A crank-rocker pose (condition 0.8)
/// at scales from 1e-12 to 1e12 (f32) and 1e-100 .. 1e100 (f64): rates
/// within `c eps / kappa^2` (`c = 16`: the position's error `eps / kappa`
/// carried through the 2x2 system, plus a few roundings; measured below 4)
/// and the indicator within a factor 2 of `kappa` (it is `|sin|` of the
/// transmission angle, computed from vectors good to a few eps).
fn rrr_velocity_run<T: Real + core::fmt::Debug>(scales: &[f64], eps: f64, name: &str) {
    use mechanism::dyad::rrr;
    use nalgebra::{Point2, Vector2};
    let mut worst = Worst::new();
    for &s in scales {
        // A = (0.3 s, 0.9 s) moving at (-0.9 s, 0.3 s) * 7 (a crank tip), B =
        // (3 s, 0) fixed, l1 = 2.5 s, l2 = 1.8 s.
        let t = |x: f64| T::lit(x * s);
        let (a, b) = (Point2::new(t(0.3), t(0.9)), Point2::new(t(3.0), t(0.0)));
        let va = Vector2::new(t(-6.3), t(2.1));
        let (l1, l2) = (t(2.5), t(1.8));
        let what = format!("{name} rrr::velocity at scale {s:e}");
        let p = rrr::position(&a, l1, &b, l2, mechanism::Mode::Plus)
            .unwrap_or_else(|e| panic!("{what}: position {e:?}"));
        let v =
            rrr::velocity(&p, Some(&va), None).unwrap_or_else(|e| panic!("{what}: velocity {e:?}"));
        let got = [v.omega1.as_f64(), v.omega2.as_f64(), v.condition.as_f64()];
        all_finite(&got, &what);
        let ra = rg::v(a.x.as_f64(), a.y.as_f64());
        let rb = rg::v(b.x.as_f64(), b.y.as_f64());
        let rc = rg::rrr_position(ra, l1.as_f64(), rb, l2.as_f64(), true).unwrap();
        let (w1, w2) = rg::rrr_rates(
            ra,
            rb,
            rc,
            rg::v(va.x.as_f64(), va.y.as_f64()),
            rg::v(0.0, 0.0),
        )
        .unwrap();
        let (r1, r2) = (rg::sub(rc, ra), rg::sub(rc, rb));
        let kappa = (rg::cross(r1, r2).abs() / (rg::norm(r1) * rg::norm(r2))).to_f64();
        let e = rel(&got[..2], &[w1, w2]);
        worst.record([0.0, e, 0.0], kappa, [1, 2, 3], [16.0; 3], eps, &what);
        worst.indicator(got[2], kappa, &what);
    }
    worst.print(&format!("{name} rrr::velocity far from 1"));
}

#[test]
fn rrr_velocity_far_from_one() {
    rrr_velocity_run::<f32>(
        &[1e-12, 1e-11, 1e-10, 1e-9, 1.0, 1e9, 3e9, 1e10, 1e12],
        f32::EPSILON as f64,
        "f32",
    );
    rrr_velocity_run::<f64>(&[1e-100, 1e-80, 1.0, 1e80, 1e100], f64::EPSILON, "f64");
}

// ---------------------------------------------------------------------------
// 2. Definitions: every dimension a run-time parameter (scales), each with
// a sampler against the group-level reference from exact inputs.

mechanism! {
    /// PRP on a rod turning about O (guide 1, carried by the crank) and a
    /// fixed line through (0, h) at angle phi (guide 2): parallel when
    /// theta = phi (mod pi), where C runs off to infinity.
    pub PrpRod {
        params { h = 1.0, phi = 0.4 }
        let O = ground(0.0, 0.0);
        let A = crank(O, 1.0, theta) as link2;
        let rod = guide(O, link2);
        let line = guide((0.0, h), phi rad);
        let C = prp(rod, line) as (b1, b2) slide (s1, s2);
    }
}

mechanism! {
    /// RPP: the crank tip A (radius r) slides in a slot at `slot` rad to a
    /// fixed line (through (0, gy) at 0.4 rad) along which the yoke
    /// translates, its point Q `off` to the left of the line.
    pub RppSlot {
        params { r = 1.0, slot = 1.2, off = 0.3, gy = -0.2 }
        let O = ground(0.0, 0.0);
        let A = crank(O, r, theta) as link2;
        let line = guide((0.0, gy), 0.4 rad);
        let Q = rpp(A, line, slot rad, off) as (blk, yoke) slide (s1, s2);
    }
}

mechanism! {
    /// Linear actuator between the ground points A = (0, 0) and B = (b, 0):
    /// arm of length r about A, cylinder of length `len` (the input) from B.
    /// Full extension at len = b + r, full retraction at len = b - r.
    pub Ram {
        params { b = 2.0, r = 1.0 }
        let A = ground(0.0, 0.0);
        let B = ground(b, 0.0);
        let C = actuator(A, r, B, len, left) as (arm, cyl);
    }
}

mechanism! {
    /// RRP: crank tip A (radius r), rod of length l to C on the line y = e
    /// (the x axis offset by e).
    pub RrpEdge {
        params { r = 1.0, l = 1.5, e = 0.2 }
        let O = ground(0.0, 0.0);
        let A = crank(O, r, theta) as link2;
        let line = guide((0.0, 0.0), 0 deg);
        let C = rrp(A, l, line, plus, e) as (rod, blk) slide s;
    }
}

mechanism! {
    /// Inverted slider-crank with an offset: crank tip A (radius r), the
    /// block on A slides along the rocker pivoted at B = (b, 0), offset e.
    pub RprOff {
        params { r = 1.0, b = 3.5, e = 0.5 }
        let O = ground(0.0, 0.0);
        let B = ground(b, 0.0);
        let A = crank(O, r, theta) as link2;
        let s = rpr(A, B, plus, e) as (block, rocker);
    }
}

/// One sample's outcome: errors per stage, exact kappa, the code's
/// indicator; or the error.
type Sample<T> = Result<([f64; 3], f64, f64), Error<T>>;

/// The unit vector at angle `a` (rad, exact) in double-double.
fn unit(a: f64) -> V {
    rg::crank(rg::v(0.0, 0.0), 1.0, a, 0.0, 0.0).0
}

fn prp_sample<T: Real + core::fmt::Debug>(m: &PrpRod<T>, theta: f64, what: &str) -> Sample<T> {
    let (w, al) = (2.3, -7.0);
    let inp = |x: f64| PrpRodInput { theta: T::lit(x) };
    let s = m.solve(&inp(theta), &inp(w), &inp(al))?;
    let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
    let f = |x: T| x.as_f64();
    let gp = [f(p.C.x), f(p.C.y), f(p.s1), f(p.s2)];
    let gv = [f(v.C.x), f(v.C.y), f(v.s1), f(v.s2)];
    let ga = [f(a.C.x), f(a.C.y), f(a.s1), f(a.s2)];
    let all: Vec<f64> = gp.iter().chain(&gv).chain(&ga).copied().collect();
    all_finite(&all, what);
    let th = T::lit(theta).as_f64();
    let (u, uw, _) = rg::crank(rg::v(0.0, 0.0), 1.0, th, T::lit(w).as_f64(), 0.0);
    let pu = rg::perp(u);
    let (wd, ald) = (d(T::lit(w).as_f64()), d(T::lit(al).as_f64()));
    let g1 = Line {
        origin: rg::v(0.0, 0.0),
        dir: u,
    };
    let g2 = Line {
        origin: rg::v(0.0, f(m.h)),
        dir: unit(f(m.phi)),
    };
    let (c, s1, s2) = rg::prp_position(&g1, 0.0, &g2, 0.0).expect("reference: parallel");
    let neg = |x: V| rg::scale(-Dd::ONE, x);
    // C = s1 u on guide 2: s1' u - s2' d2 = -s1 w perp(u).
    let (s1d, s2d) = rg::solve2(u, neg(g2.dir), neg(rg::scale(s1, uw))).unwrap();
    // s1'' u - s2'' d2 = -(2 s1' w + s1 al) perp(u) + s1 w^2 u.
    let rhs = rg::add(
        rg::scale(-(d(2.0) * s1d * wd + s1 * ald), pu),
        rg::scale(s1 * wd * wd, u),
    );
    let (s1dd, s2dd) = rg::solve2(u, neg(g2.dir), rhs).unwrap();
    let (vc, ac) = (rg::scale(s2d, g2.dir), rg::scale(s2dd, g2.dir));
    let e = [
        rel(&gp[..2], &flat(&[c])).max(rel(&gp[2..], &[s1, s2])),
        rel(&gv[..2], &flat(&[vc])).max(rel(&gv[2..], &[s1d, s2d])),
        rel(&ga[..2], &flat(&[ac])).max(rel(&ga[2..], &[s1dd, s2dd])),
    ];
    let kappa = rg::cross(u, g2.dir).abs().to_f64();
    Ok((e, kappa, f(v.condition)))
}

fn rpp_sample<T: Real + core::fmt::Debug>(m: &RppSlot<T>, theta: f64, what: &str) -> Sample<T> {
    let (w, al) = (2.3, -7.0);
    let inp = |x: f64| RppSlotInput { theta: T::lit(x) };
    let s = m.solve(&inp(theta), &inp(w), &inp(al))?;
    let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
    let f = |x: T| x.as_f64();
    let gp = [f(p.Q.x), f(p.Q.y), f(p.s1), f(p.s2)];
    let gv = [f(v.Q.x), f(v.Q.y), f(v.s1), f(v.s2)];
    let ga = [f(a.Q.x), f(a.Q.y), f(a.s1), f(a.s2)];
    let all: Vec<f64> = gp.iter().chain(&gv).chain(&ga).copied().collect();
    all_finite(&all, what);
    let th = T::lit(theta).as_f64();
    let (pa, va, aa) = rg::crank(
        rg::v(0.0, 0.0),
        f(m.r),
        th,
        T::lit(w).as_f64(),
        T::lit(al).as_f64(),
    );
    let dir = unit(T::lit(0.4).as_f64());
    let g = Line {
        origin: rg::v(0.0, f(m.gy)),
        dir,
    };
    let sl = unit(f(m.slot));
    let ws = rg::add(rg::scale(sl[0], dir), rg::scale(sl[1], rg::perp(dir)));
    let q = rg::sub(rg::sub(pa, g.origin), rg::scale(d(f(m.off)), rg::perp(dir)));
    let (s1, s2) = rg::solve2(ws, dir, q).expect("reference: parallel");
    let (s1d, s2d) = rg::solve2(ws, dir, va).unwrap();
    let (s1dd, s2dd) = rg::solve2(ws, dir, aa).unwrap();
    let qp = g.at(s2, d(f(m.off)));
    let e = [
        rel(&gp[..2], &flat(&[qp])).max(rel(&gp[2..], &[s1, s2])),
        rel(&gv[..2], &flat(&[rg::scale(s2d, dir)])).max(rel(&gv[2..], &[s1d, s2d])),
        rel(&ga[..2], &flat(&[rg::scale(s2dd, dir)])).max(rel(&ga[2..], &[s1dd, s2dd])),
    ];
    let kappa = rg::cross(dir, ws).abs().to_f64();
    Ok((e, kappa, f(v.condition)))
}

/// The actuator at cylinder length `len` (L), rate `ld` (L/s), acceleration
/// `ldd` (L/s^2).
fn ram_sample<T: Real + core::fmt::Debug>(
    m: &Ram<T>,
    len: f64,
    ld: f64,
    ldd: f64,
    what: &str,
) -> Sample<T> {
    let inp = |x: f64| RamInput { len: T::lit(x) };
    let s = m.solve(&inp(len), &inp(ld), &inp(ldd))?;
    let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
    let f = |x: T| x.as_f64();
    let gp = [f(p.C.x), f(p.C.y)];
    let gv = [f(v.C.x), f(v.C.y)];
    let ga = [f(a.C.x), f(a.C.y)];
    let (wv, wa) = ([f(v.arm), f(v.cyl)], [f(a.arm), f(a.cyl)]);
    let all: Vec<f64> = gp
        .iter()
        .chain(&gv)
        .chain(&ga)
        .chain(&wv)
        .chain(&wa)
        .copied()
        .collect();
    all_finite(&all, what);
    let (len, ld, ldd) = (
        T::lit(len).as_f64(),
        T::lit(ld).as_f64(),
        T::lit(ldd).as_f64(),
    );
    let (ra, rb) = (rg::v(0.0, 0.0), rg::v(f(m.b), 0.0));
    let c = rg::rrr_position(ra, f(m.r), rb, len, true).expect("reference: no assembly");
    let (r1, r2) = (rg::sub(c, ra), rg::sub(c, rb));
    let e2 = rg::scale(Dd::ONE / d(len), r2);
    let (p1, p2) = (rg::perp(r1), rg::scale(-Dd::ONE, rg::perp(r2)));
    // w1 perp(r1) - w2 perp(r2) = L' e2.
    let (w1, w2) = rg::solve2(p1, p2, rg::scale(d(ld), e2)).unwrap();
    // a1 perp(r1) - a2 perp(r2) = w1^2 r1 - w2^2 r2 + L'' e2 + 2 L' w2 perp(e2).
    let rhs = rg::add(
        rg::sub(rg::scale(w1 * w1, r1), rg::scale(w2 * w2, r2)),
        rg::add(
            rg::scale(d(ldd), e2),
            rg::scale(d(2.0 * ld) * w2, rg::perp(e2)),
        ),
    );
    let (a1, a2) = rg::solve2(p1, p2, rhs).unwrap();
    let vc = rg::scale(w1, p1);
    let ac = rg::sub(rg::scale(a1, p1), rg::scale(w1 * w1, r1));
    let e = [
        rel(&gp, &flat(&[c])),
        rel(&gv, &flat(&[vc])).max(rel(&wv, &[w1, w2])),
        rel(&ga, &flat(&[ac])).max(rel(&wa, &[a1, a2])),
    ];
    let kappa = (rg::cross(r1, r2).abs() / (rg::norm(r1) * rg::norm(r2))).to_f64();
    Ok((e, kappa, f(v.condition)))
}

fn rrp_sample<T: Real + core::fmt::Debug>(m: &RrpEdge<T>, theta: f64, what: &str) -> Sample<T> {
    let (w, al) = (2.3, -7.0);
    let inp = |x: f64| RrpEdgeInput { theta: T::lit(x) };
    let s = m.solve(&inp(theta), &inp(w), &inp(al))?;
    let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
    let f = |x: T| x.as_f64();
    let gp = [f(p.C.x), f(p.C.y), f(p.s)];
    let gv = [f(v.C.x), f(v.C.y), f(v.s)];
    let ga = [f(a.C.x), f(a.C.y), f(a.s)];
    let (wv, wa) = ([f(v.rod)], [f(a.rod)]);
    let all: Vec<f64> = gp
        .iter()
        .chain(&gv)
        .chain(&ga)
        .chain(&wv)
        .chain(&wa)
        .copied()
        .collect();
    all_finite(&all, what);
    let th = T::lit(theta).as_f64();
    let (pa, va, aa) = rg::crank(
        rg::v(0.0, 0.0),
        f(m.r),
        th,
        T::lit(w).as_f64(),
        T::lit(al).as_f64(),
    );
    let g = Line::new([0.0, 0.0], [1.0, 0.0]);
    // The reference misses only inside the code's rounding band (4 eps l):
    // no figures there (NaN errors, counted by the caller).
    let Some((c, sr)) = rg::rrp_position(pa, f(m.l), &g, f(m.e), true) else {
        return Ok(([f64::NAN; 3], 0.0, f(v.condition)));
    };
    let (w1, sd) = rg::rrp_rates(pa, c, &g, va).unwrap();
    let (a1, sdd) = rg::rrp_accelerations(pa, c, &g, aa, w1).unwrap();
    let e = [
        rel(&gp[..2], &flat(&[c])).max(rel(&gp[2..], &[sr])),
        rel(&gv[..2], &flat(&[rg::scale(sd, g.dir)]))
            .max(rel(&gv[2..], &[sd]).max(rel(&wv, &[w1]))),
        rel(&ga[..2], &flat(&[rg::scale(sdd, g.dir)]))
            .max(rel(&ga[2..], &[sdd]).max(rel(&wa, &[a1]))),
    ];
    let r1 = rg::sub(c, pa);
    let kappa = (rg::dot(r1, g.dir).abs() / rg::norm(r1)).to_f64();
    Ok((e, kappa, f(v.condition)))
}

fn rpr_sample<T: Real + core::fmt::Debug>(m: &RprOff<T>, theta: f64, what: &str) -> Sample<T> {
    let (w, al) = (2.3, -7.0);
    let inp = |x: f64| RprOffInput { theta: T::lit(x) };
    let s = m.solve(&inp(theta), &inp(w), &inp(al))?;
    let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
    let f = |x: T| x.as_f64();
    let (gp, gv, ga) = (
        [f(p.s), f(p.rocker)],
        [f(v.s), f(v.rocker)],
        [f(a.s), f(a.rocker)],
    );
    let all: Vec<f64> = gp.iter().chain(&gv).chain(&ga).copied().collect();
    all_finite(&all, what);
    let th = T::lit(theta).as_f64();
    let (pa, va, aa) = rg::crank(
        rg::v(0.0, 0.0),
        f(m.r),
        th,
        T::lit(w).as_f64(),
        T::lit(al).as_f64(),
    );
    let pb = rg::v(f(m.b), 0.0);
    let (u, sr) = rg::rpr_position(pa, pb, f(m.e), true).expect("reference: no assembly");
    let (om, sd) = rg::rpr_rates(pa, pb, u, va, rg::v(0.0, 0.0)).unwrap();
    let ab = rg::sub(pa, pb);
    // alpha perp(A - B) + s'' u = aA - 2 s' omega perp(u) + omega^2 (A - B).
    let rhs = rg::add(
        rg::sub(aa, rg::scale(d(2.0) * sd * om, rg::perp(u))),
        rg::scale(om * om, ab),
    );
    let (alp, sdd) = rg::solve2(rg::perp(ab), u, rhs).unwrap();
    // The rocker's angle: scales relative to pi (the angles' natural size).
    let ang = Dd::atan2(u[1], u[0]);
    let e = [
        rel(&gp[..1], &[sr]).max((d(gp[1]) - ang).abs().to_f64() / std::f64::consts::PI),
        rel(&gv, &[sd, om]),
        rel(&ga, &[sdd, alp]),
    ];
    let kappa = (sr.abs() / rg::norm(ab)).to_f64();
    Ok((e, kappa, f(v.condition)))
}

// ---------------------------------------------------------------------------
// 3. Singular approaches.

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
/// accelerations `/ kappa^3` (the RRR's reasons, `extreme_surface.rs`),
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

// ---------------------------------------------------------------------------
// 4. Lengths far from 1: every dimension times `s`.

/// Ordinary poses (8 crank angles or cylinder lengths) of the five
/// definitions with every length times `s`: positions `c eps / kappa`,
/// rates `/ kappa^2`, accelerations `/ kappa^3` (the 2x2 systems' inverses
/// have norm `1 / kappa`), `c = 32` (the parameters round too; measured
/// constants printed), and no error anywhere. Products of two lengths
/// (squared lengths) stay normal in f32 from 1e-19 to 1e19; the scales
/// below reach 3e-12 and 1e12 in f32 and 1e-100 .. 1e100 in f64.
fn scales_run<T: Real + core::fmt::Debug>(scales: &[f64], name: &str) {
    let eps = T::eps().as_f64();
    let k = [1, 2, 3];
    let c = [32.0; 3];
    let t = |x: f64| T::lit(x);
    for &s in scales {
        let mut w = [
            Worst::new(),
            Worst::new(),
            Worst::new(),
            Worst::new(),
            Worst::new(),
        ];
        for i in 0..8 {
            let theta = -2.9 + 0.77 * i as f64;
            let what = format!("{name} scale {s:e} theta {theta}");
            let prp = PrpRod::<T> {
                h: t(s),
                ..PrpRod::<T>::default()
            };
            let rpp = RppSlot::<T> {
                r: t(s),
                off: t(0.3 * s),
                gy: t(-0.2 * s),
                ..RppSlot::<T>::default()
            };
            let rrp = RrpEdge::<T> {
                r: t(s),
                l: t(1.5 * s),
                e: t(0.2 * s),
            };
            let rpr = RprOff::<T> {
                r: t(s),
                b: t(3.5 * s),
                e: t(0.5 * s),
            };
            let ram = Ram::<T> {
                b: t(2.0 * s),
                r: t(s),
            };
            // PRP: keep clear of the parallel poses (theta = 0.4 mod pi).
            let samples = [
                prp_sample(&prp, theta + 0.1, &format!("prp {what}")),
                rpp_sample(&rpp, theta, &format!("rpp {what}")),
                rrp_sample(&rrp, theta, &format!("rrp {what}")),
                rpr_sample(&rpr, theta, &format!("rpr {what}")),
                ram_sample(
                    &ram,
                    s * (1.2 + 0.2 * i as f64),
                    0.7 * s,
                    -3.0 * s,
                    &format!("actuator {what}"),
                ),
            ];
            for (j, r) in samples.into_iter().enumerate() {
                let (e, kappa, cond) =
                    r.unwrap_or_else(|e| panic!("{what} (definition {j}): {e:?}"));
                assert!(!e[0].is_nan(), "{what} ({j}): reference missed");
                w[j].record(e, kappa, k, c, eps, &format!("{what} ({j})"));
                w[j].indicator(cond, kappa, &format!("{what} ({j})"));
            }
        }
        for (j, n) in ["prp", "rpp", "rrp", "rpr", "actuator"].iter().enumerate() {
            w[j].print(&format!("{name} {n} at scale {s:e}"));
        }
    }
}

#[test]
fn lengths_1e_minus9_to_1e9() {
    scales_run::<f64>(&[1e-9, 1e-3, 1.0, 1e3, 1e9], "f64");
    scales_run::<f32>(&[1e-9, 1e-3, 1.0, 1e3, 1e9], "f32");
}

#[test]
fn lengths_far_from_one() {
    scales_run::<f64>(&[1e-100, 1e-80, 1e80, 1e100], "f64 far");
    scales_run::<f32>(&[3e-12, 1e-11, 1e11, 1e12], "f32 far");
}
