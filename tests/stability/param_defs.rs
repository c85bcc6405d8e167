//! Five definitions with every dimension a run-time parameter (a PRP on a
//! turning rod, an RPP slot, a linear actuator, an RRP with an offset, an
//! RPR with an offset), each with a sampler that returns the normwise
//! relative errors per stage against the group-level double-double
//! reference (`mechanism_reference::groups`, from exact inputs), the exact
//! condition `kappa` and the code's indicator. Shared by
//! `scale_definitions.rs` (every length times `s`) and
//! `singular_definitions.rs` (the singular approaches).

use super::bounds::all_finite;
use super::reference_errors::*;
use mechanism::{mechanism, Error, Real};
use mechanism_reference::groups::{self as rg, Line, V};
use mechanism_reference::Dd;

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
pub type Sample<T> = Result<([f64; 3], f64, f64), Error<T>>;

/// The unit vector at angle `a` (rad, exact) in double-double.
pub fn unit(a: f64) -> V {
    rg::crank(rg::v(0.0, 0.0), 1.0, a, 0.0, 0.0).0
}

pub fn prp_sample<T: Real + core::fmt::Debug>(m: &PrpRod<T>, theta: f64, what: &str) -> Sample<T> {
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

pub fn rpp_sample<T: Real + core::fmt::Debug>(m: &RppSlot<T>, theta: f64, what: &str) -> Sample<T> {
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
pub fn ram_sample<T: Real + core::fmt::Debug>(
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

pub fn rrp_sample<T: Real + core::fmt::Debug>(m: &RrpEdge<T>, theta: f64, what: &str) -> Sample<T> {
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

pub fn rpr_sample<T: Real + core::fmt::Debug>(m: &RprOff<T>, theta: f64, what: &str) -> Sample<T> {
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
