//! Part 2: toggle and dead-centre poses, where the 2x2 rate systems become
//! singular.
//!
//! Each group's rate system is driven through poses whose exact condition
//! `kappa = |det| / scale` (computed in double-double from the same `f64`
//! data) runs from 1 down to 1e-15 and to 0. At every pose the result must be
//! either
//!
//! - `Ok`, with the rates' normwise relative error at most
//!   `C_RATE eps / kappa` against the double-double solution of the same
//!   system (the 2x2 system's condition number is about `1 / kappa`: the
//!   determinant's absolute rounding error is ~`eps scale`), and with the
//!   `condition` field equal to `kappa` within `4 eps` (absolute: the same
//!   rounding of the determinant); or
//! - `Err(Singular { det, scale })` with `|det| / scale <= 16 eps`, which then
//!   needs `kappa <= 18 eps` (16 eps plus the determinant's own rounding).
//!
//! The position structs are built from `f64` data directly (their fields are
//! public), so that these tests isolate the rate systems; the end-to-end
//! test at the bottom feeds positions computed from exact inputs.

use crate::common::*;
use mechanism::driver::actuator;
use mechanism::dyad::{prp, rpp, rpr, rrp, rrr};
use mechanism::guide::{Line, LineVelocity};
use mechanism::{Error, Fault, Mode, Vector2};
use mechanism_reference::groups::{self as refg, V};
use mechanism_reference::Dd;

/// Constant of the rate bound `err <= C_RATE eps / kappa`. Measured worst
/// cases are printed (about 1 for every group; `docs/stability.md`); 4 covers
/// the few roundings in each right-hand side and Cramer's two divisions.
pub const C_RATE: f64 = 4.0;

/// Conditions 1, 10^-0.5, ..., 1e-15, and 0.
pub fn kappas() -> Vec<f64> {
    let mut k: Vec<f64> = (0..=30).map(|i| 10f64.powf(-0.5 * i as f64)).collect();
    k.push(0.0);
    k
}

fn vec2(x: f64, y: f64) -> Vector2<f64> {
    Vector2::new(x, y)
}

fn dvv(v: &Vector2<f64>) -> V {
    refg::v(v.x, v.y)
}

/// Checks one pose; returns `err kappa / eps` (0 for a Singular result).
fn check(
    what: &str,
    got: Result<([f64; 2], f64), Error>,
    reference: Option<(Dd, Dd)>,
    kappa: Dd,
) -> f64 {
    let k = kappa.to_f64();
    match got {
        Ok((x, cond)) => {
            assert!(x.iter().all(|v| v.is_finite()) && cond.is_finite());
            let (r0, r1) =
                reference.unwrap_or_else(|| panic!("{what}: Ok at an exactly singular pose"));
            let size = r0.abs().to_f64().max(r1.abs().to_f64());
            let err = (Dd::from(x[0]) - r0)
                .abs()
                .to_f64()
                .max((Dd::from(x[1]) - r1).abs().to_f64())
                / size;
            assert!(
                err <= C_RATE * EPS / k,
                "{what}: kappa {k:e}: error {err:e} > {C_RATE} eps / kappa"
            );
            assert!(
                (cond - k).abs() <= 4.0 * EPS,
                "{what}: condition {cond:e} against {k:e}"
            );
            assert!(cond > 16.0 * EPS && cond <= 1.0);
            err * k / EPS
        }
        Err(Error {
            fault: Fault::Singular { det, scale },
            ..
        }) => {
            assert!(
                det.abs() <= 16.0 * EPS * scale,
                "{what}: Singular {det:e} / {scale:e}"
            );
            assert!(k <= 18.0 * EPS, "{what}: Singular at kappa {k:e}");
            0.0
        }
        Err(e) => panic!("{what}: unexpected error {e}"),
    }
}

/// Proves: the RRR rate system (determinant `cross(r1, r2)`, zero at toggle)
/// gives rates accurate to `C_RATE eps / kappa` or `Singular` with its
/// determinant, and `condition` equals `|sin|` of the angle between the
/// links, both for stretched (`beta -> 0`) and folded (`beta -> pi`) links.
#[test]
fn rrr_rates_near_toggle() {
    let (l1, l2, phi) = (1.3, 0.9, 0.7f64);
    let (va, vb) = (vec2(0.3, -1.1), vec2(-0.8, 0.45));
    let mut worst: f64 = 0.0;
    for kappa in kappas() {
        for folded in [false, true] {
            let beta = if folded {
                std::f64::consts::PI - kappa.asin()
            } else {
                kappa.asin()
            };
            let r1 = vec2(l1 * phi.cos(), l1 * phi.sin());
            let r2 = vec2(l2 * (phi + beta).cos(), l2 * (phi + beta).sin());
            let a = p(0.2, 0.1);
            let pos = rrr::RrrPosition::new(a + r1, r1, r2);
            let got = rrr::velocity(&pos, Some(&va), Some(&vb))
                .map(|v| ([v.omega1, v.omega2], v.condition));
            let (r1d, r2d) = (dvv(&r1), dvv(&r2));
            let kd = refg::cross(r1d, r2d).abs() / (refg::norm(r1d) * refg::norm(r2d));
            let c = r1d;
            let b = refg::sub(r1d, r2d);
            let reference = refg::rrr_rates(refg::v(0.0, 0.0), b, c, dvv(&va), dvv(&vb));
            worst = worst.max(check("RRR", got, reference, kd));
        }
    }
    println!("RRR rates: max err kappa / eps = {worst:.3}");
}

/// Proves: the same for the RRP (determinant `dot(r1, dir)`, zero when link 1
/// is perpendicular to the guide: the slider-crank's rod at tangency).
#[test]
fn rrp_rates_near_tangency() {
    let (l, psi) = (0.4, -0.35f64);
    let dir = vec2(psi.cos(), psi.sin());
    let g = Line {
        origin: p(0.0, 0.0),
        dir,
    };
    let gr = refg::Line {
        origin: refg::v(0.0, 0.0),
        dir: dvv(&dir),
    };
    let va = vec2(-0.7, 0.25);
    let mut worst: f64 = 0.0;
    for kappa in kappas() {
        for sign in [1.0, -1.0] {
            // Angle of link 1 to the guide: pi/2 - asin(kappa).
            let gamma = psi + sign * (std::f64::consts::FRAC_PI_2 - kappa.asin());
            let r1 = vec2(l * gamma.cos(), l * gamma.sin());
            let a = p(0.05, 0.3);
            let pos = rrp::RrpPosition {
                c: a + r1,
                r1,
                s: 0.0,
                l,
            };
            let got = rrp::velocity(&pos, &g, Some(&va), None)
                .map(|v| ([v.omega1, v.s_dot], v.condition));
            let r1d = dvv(&r1);
            let kd = refg::dot(r1d, gr.dir).abs() / (refg::norm(r1d) * refg::norm(gr.dir));
            let reference = refg::rrp_rates(refg::v(0.0, 0.0), r1d, &gr, dvv(&va));
            worst = worst.max(check("RRP", got, reference, kd));
        }
    }
    println!("RRP rates: max err kappa / eps = {worst:.3}");
}

/// Proves: the same for the RPR (determinant `s = dot(u, A - B)`, zero when
/// `A` is the foot of the perpendicular from `B` on the slide line).
#[test]
fn rpr_rates_near_foot() {
    let (rho, phi) = (0.6, 2.1f64);
    let (va, vb) = (vec2(0.2, 0.9), vec2(-0.1, 0.3));
    let b = p(0.4, -0.2);
    let a = b + vec2(rho * phi.cos(), rho * phi.sin());
    let mut worst: f64 = 0.0;
    for kappa in kappas() {
        for sign in [1.0, -1.0] {
            let gamma = phi + sign * kappa.acos();
            let u = vec2(gamma.cos(), gamma.sin());
            let pos = rpr::RprPosition {
                axis: u,
                s: 0.0,
                dist: (a - b).norm(),
            };
            let got = rpr::velocity(&pos, &a, &b, Some(&va), Some(&vb))
                .map(|v| ([v.omega, v.s_dot], v.condition));
            let pd = refg::sub(dv(&a), dv(&b));
            let ud = dvv(&u);
            let kd = refg::dot(ud, pd).abs() / (refg::norm(ud) * refg::norm(pd));
            let reference = refg::rpr_rates(dv(&a), dv(&b), ud, dvv(&va), dvv(&vb));
            worst = worst.max(check("RPR", got, reference, kd));
        }
    }
    println!("RPR rates: max err kappa / eps = {worst:.3}");
}

/// Proves: the same for the PRP (determinant `cross(dir1, dir2)`, zero for
/// parallel guides), with guide 2 translating.
#[test]
fn prp_rates_near_parallel_guides() {
    let psi = 0.9f64;
    let g1 = Line {
        origin: p(0.0, 0.0),
        dir: vec2(psi.cos(), psi.sin()),
    };
    let w = vec2(0.35, -0.6);
    let gv2 = LineVelocity {
        v_origin: w,
        omega: 0.0,
    };
    let mut worst: f64 = 0.0;
    for kappa in kappas() {
        for sign in [1.0, -1.0] {
            let a2 = psi + sign * kappa.asin();
            let g2 = Line {
                origin: p(1.0, 0.5),
                dir: vec2(a2.cos(), a2.sin()),
            };
            let pos = prp::PrpPosition {
                c: p(0.3, 0.4),
                s1: 0.0,
                s2: 0.0,
            };
            let got = prp::velocity(&pos, &g1, &g2, None, Some(&gv2))
                .map(|v| ([v.s1_dot, v.s2_dot], v.condition));
            let (d1, d2) = (dvv(&g1.dir), dvv(&g2.dir));
            let kd = refg::cross(d1, d2).abs() / (refg::norm(d1) * refg::norm(d2));
            let l1 = refg::Line {
                origin: dv(&g1.origin),
                dir: d1,
            };
            let l2 = refg::Line {
                origin: dv(&g2.origin),
                dir: d2,
            };
            let reference = refg::prp_rates(&l1, &l2, dvv(&w));
            worst = worst.max(check("PRP", got, reference, kd));
        }
    }
    println!("PRP rates: max err kappa / eps = {worst:.3}");
}

/// Proves: the same for the RPP (determinant `sin beta`, zero when the slot
/// is parallel to the guide).
#[test]
fn rpp_rates_near_parallel_slot() {
    let psi = -1.2f64;
    let g = Line {
        origin: p(0.0, 0.0),
        dir: vec2(psi.cos(), psi.sin()),
    };
    let va = vec2(0.4, 0.75);
    let mut worst: f64 = 0.0;
    for kappa in kappas() {
        for sign in [1.0, -1.0] {
            let w = psi + sign * kappa.asin();
            let slot = vec2(w.cos(), w.sin());
            let a = p(0.3, 0.2);
            let pos = rpp::RppPosition {
                q: p(0.1, 0.1),
                slot,
                s1: 0.0,
                s2: 0.0,
            };
            let got = rpp::velocity(&pos, &a, &g, Some(&va), None)
                .map(|v| ([v.s1_dot, v.s2_dot], v.condition));
            let (dd, sd) = (dvv(&g.dir), dvv(&slot));
            let kd = refg::cross(dd, sd).abs() / (refg::norm(dd) * refg::norm(sd));
            let reference = refg::solve2(sd, dd, dvv(&va));
            worst = worst.max(check("RPP", got, reference, kd));
        }
    }
    println!("RPP rates: max err kappa / eps = {worst:.3}");
}

/// Proves: the same for the linear actuator (determinant `cross(r1, r2)`,
/// zero when the cylinder pushes through link 1's pivot), with an extension
/// rate.
#[test]
fn actuator_rates_near_dead_centre() {
    let (l, len, phi, ldot) = (0.5, 0.8, -0.4f64, 0.37);
    let va = vec2(0.0, 0.0);
    let vb = vec2(0.1, -0.2);
    let mut worst: f64 = 0.0;
    for kappa in kappas() {
        for folded in [false, true] {
            let beta = if folded {
                std::f64::consts::PI - kappa.asin()
            } else {
                kappa.asin()
            };
            let r1 = vec2(l * phi.cos(), l * phi.sin());
            let r2 = vec2(len * (phi + beta).cos(), len * (phi + beta).sin());
            let pos = rrr::RrrPosition::new(p(0.0, 0.0) + r1, r1, r2);
            let got = actuator::velocity(&pos, Some(&va), Some(&vb), ldot)
                .map(|v| ([v.omega1, v.omega2], v.condition));
            let (r1d, r2d) = (dvv(&r1), dvv(&r2));
            let n2 = refg::norm(r2d);
            let kd = refg::cross(r1d, r2d).abs() / (refg::norm(r1d) * n2);
            let rhs = refg::add(
                refg::sub(dvv(&vb), dvv(&va)),
                refg::scale(Dd::from(ldot) / n2, r2d),
            );
            let reference =
                refg::solve2(refg::perp(r1d), refg::scale(-Dd::ONE, refg::perp(r2d)), rhs);
            worst = worst.max(check("actuator", got, reference, kd));
        }
    }
    println!("actuator rates: max err kappa / eps = {worst:.3}");
}

/// Proves: end to end (position from exact inputs, then rates), an RRR near
/// toggle gives rates whose relative error stays within the *problem's*
/// condition: the input rounding moves the height `h` by `~eps L /
/// sqrt(delta)`, a relative `eps / delta = eps / kappa^2`-order change in the
/// determinant. Bound: `8 eps / kappa^2` with `kappa` the exact condition,
/// equivalently `1 eps / delta` with `delta` the relative distance to the
/// edge of assembly (measured 2.9 and 0.36, `docs/stability.md`). Exactly at
/// the edge, `Singular` with `det = 0`.
#[test]
fn rrr_end_to_end_rates_near_toggle() {
    let a = p(0.31, -0.72);
    let (l1, l2) = (1.3, 0.9);
    let (va, vb) = (vec2(0.3, -1.1), vec2(-0.8, 0.45));
    let (mut worst, mut worst_delta): (f64, f64) = (0.0, 0.0);
    for delta in deltas() {
        for phi in [0.4f64, 2.2] {
            let d = (l1 + l2) * (1.0 - delta);
            let b = p(a.x + d * phi.cos(), a.y + d * phi.sin());
            let pos = rrr::position(&a, l1, &b, l2, Mode::Plus).unwrap();
            let v = rrr::velocity(&pos, Some(&va), Some(&vb)).unwrap();
            let c = refg::rrr_position(dv(&a), l1, dv(&b), l2, true).unwrap();
            let (r1, r2) = (refg::sub(c, dv(&a)), refg::sub(c, dv(&b)));
            let kd = (refg::cross(r1, r2).abs() / (refg::norm(r1) * refg::norm(r2))).to_f64();
            let (w1, w2) = refg::rrr_rates(dv(&a), dv(&b), c, dvv(&va), dvv(&vb)).unwrap();
            let size = w1.abs().to_f64().max(w2.abs().to_f64());
            let err = (Dd::from(v.omega1) - w1)
                .abs()
                .to_f64()
                .max((Dd::from(v.omega2) - w2).abs().to_f64())
                / size;
            // Near the outer edge kappa^2 ~ 8 delta for these lengths, so the
            // two forms of the bound are the same statement; measured worst
            // err kappa^2 / eps = 2.9, err delta / eps = 0.36.
            assert!(err <= 8.0 * EPS / (kd * kd), "delta {delta:e}: {err:e}");
            assert!(err <= EPS / delta, "delta {delta:e}: {err:e}");
            worst = worst.max(err * kd * kd / EPS);
            worst_delta = worst_delta.max(err * delta / EPS);
        }
    }
    println!(
        "RRR end to end: max err kappa^2 / eps = {worst:.3}, err delta / eps = {worst_delta:.3}"
    );
    // At the edge exactly (B = (2, 0) from the origin, l1 + l2 = 2): Singular.
    let pos = rrr::position(&p(0.0, 0.0), 1.25, &p(2.0, 0.0), 0.75, Mode::Plus).unwrap();
    match rrr::velocity(&pos, Some(&va), None) {
        Err(Error {
            fault: Fault::Singular { det, scale },
            ..
        }) => assert!(det == 0.0 && scale > 0.0, "{det} {scale}"),
        other => panic!("expected Singular, got {other:?}"),
    }
}
