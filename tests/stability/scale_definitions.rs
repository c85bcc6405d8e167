//! Definitions the stability suite's scenes do not have, at lengths far
//! from 1, against the double-double references: a four-bar with every
//! dimension a run-time parameter from 1e-9 to 1e9 (and far beyond in f64),
//! mixed scales (a small crank on a large frame), RRR lengths far from 1;
//! the non-generated RRR rates (`dyad::rrr::velocity`) from 1e-12 to 1e12
//! (f32) and 1e-100 to 1e100 (f64); the five definitions of `param_defs.rs`
//! with every length times `s`.
//!
//! Every case asserts: an `Ok` answer is finite and within a bound of the
//! form `c eps (1 / kappa)^k` of the reference (`kappa` the exact condition
//! of the pose, `k` and `c` stated per case with the reason), an `Err` is
//! typed (it names the group, its `Fault` is the one the geometry calls for),
//! nothing panics. Errors are normwise relative per stage: `max |x - ref| /
//! max |ref|` over the points (positions, velocities, accelerations
//! separately) and over the angular quantities.
//!
//! `cargo test --release --test stability scale_definitions -- --nocapture`
//! prints the measured worst figures.

use super::bounds::{all_finite, Worst};
use super::param_defs::*;
use super::reference_errors::*;
use mechanism::{mechanism, Real};
use mechanism_reference::constraint::{Constraint, Linkage, Point, Side};
use mechanism_reference::groups::{self as rg};
use mechanism_reference::loop_closure;
use mechanism_reference::Dd;

// ---------------------------------------------------------------------------
// A four-bar with every dimension a run-time parameter: 1e-9 .. 1e9, f64
// and f32; mixed scales.

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
pub const SWEEP_K: [i32; 3] = [1, 2, 3];
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
/// an ordinary number: f32 3e-12 .. 1e12 (a Heron product taken whole is
/// 5e5 eps wrong, silently, at 3e-12 from a subnormal product, and gives
/// `CannotAssemble`/`Singular` from 3e9 up from an infinite one), f64 1e-100
/// and 1e100 (a zero or infinite product). Same bound as the ordinary scales.
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
// The non-generated RRR rates (`dyad::rrr::velocity`, scale `|r1| |r2|`)
// at lengths far from 1.

/// `mechanism::dyad::rrr::velocity` takes the scale of its determinant from
/// the link vectors `|r1| |r2|`. Taken as `sqrt(|r1|^2 |r2|^2)`, a fourth
/// power of the lengths, f32 lengths of 1e-12 give a zero product and a
/// false `Singular`, 1e-11 a subnormal one (the indicator off), 1e10 an
/// infinite one (`Singular` again), while the position (which takes its
/// Heron roots apart there) is fine. A crank-rocker pose (condition 0.8)
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
// The five parameter definitions (`param_defs.rs`) with every dimension
// times `s`.

/// Ordinary poses (8 crank angles or cylinder lengths) of the five
/// definitions with every length times `s`: positions `c eps / kappa`,
/// rates `/ kappa^2`, accelerations `/ kappa^3` (the 2x2 systems' inverses
/// have norm `1 / kappa`), `c = 32` (the parameters round too; measured
/// constants printed), and no error anywhere. Products of two lengths
/// (squared lengths) stay normal in f32 from 1e-19 to 1e19; the scales
/// below reach 3e-12 and 1e12 in f32 and 1e-100 .. 1e100 in f64.
fn lengths_scaled_run<T: Real + core::fmt::Debug>(scales: &[f64], name: &str) {
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
    lengths_scaled_run::<f64>(&[1e-9, 1e-3, 1.0, 1e3, 1e9], "f64");
    lengths_scaled_run::<f32>(&[1e-9, 1e-3, 1.0, 1e3, 1e9], "f32");
}

#[test]
fn lengths_far_from_one() {
    lengths_scaled_run::<f64>(&[1e-100, 1e-80, 1e80, 1e100], "f64 far");
    lengths_scaled_run::<f32>(&[3e-12, 1e-11, 1e11, 1e12], "f32 far");
}
