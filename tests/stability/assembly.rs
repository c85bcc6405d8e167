//! Part 1: the edge of assembly.
//!
//! Each group is closed at relative distances `delta` = 1e-2 .. 1e-14 inside
//! its limit (RRR: `|B - A| -> l1 + l2` and `-> |l1 - l2|`; RRP: the circle
//! about `A` tangent to the slide line; RPR: `A` on the circle the slide line
//! is tangent to), against the double-double reference
//! (`mechanism_reference::groups`) evaluated on the same `f64` inputs.
//!
//! Why the bound is `c eps / sqrt(delta)`: the joint sits at height
//! `h ~ L sqrt(2 delta)` off the line of centres, and an input perturbation of
//! `eps` (relative) moves `delta` by `~eps`, hence `h` by
//! `~L eps / sqrt(delta)`: that is the conditioning of the problem, and no
//! `f64` algorithm fed rounded inputs can do better in general. We measure
//! `c = max err sqrt(delta) / eps` with `err = |C - C_ref| / L` (`L` the
//! group's size) and assert it below a stated constant. Since
//! `sqrt(delta) >= delta`, this implies the form `c eps / delta` with
//! the same `c`.

use crate::common::*;
use mechanism::driver::actuator;
use mechanism::dyad::{rpr, rrp, rrr};
use mechanism::guide::Line;
use mechanism::{Error, Fault, Mode, Point2, Primitive, Vector2};
use mechanism_reference::groups as refg;
use mechanism_reference::Dd;

/// The constant `c` of the position bound `|C - C_ref| / L <= c eps /
/// sqrt(delta)` (assertion); measured worst cases are printed and recorded in
/// `docs/stability.md` (RRR outer 0.25, inner 0.14, RRP 0.83, RPR 0.57).
/// 2 leaves room for other orientations without hiding a lost digit (a
/// cancelling formula would exceed it by orders of magnitude, see
/// `naive_formula_fails_at_the_edge`).
pub const C_POSITION: f64 = 2.0;

/// RRR `A`, lengths and directions used in the sweeps (none exact in binary).
const A: (f64, f64) = (0.31, -0.72);
const L1: f64 = 1.3;
const L2: f64 = 0.9;
const PHIS: [f64; 3] = [0.4, 2.2, -2.9];

/// `(B, realized delta)` for a relative distance `delta` inside the outer
/// (`outer = true`) or inner limit, direction `phi`.
fn rrr_case(delta: f64, phi: f64, outer: bool) -> (Point2<f64>, f64) {
    let sum = L1 + L2;
    let d = if outer {
        sum * (1.0 - delta)
    } else {
        (L1 - L2).abs() + sum * delta
    };
    let b = p(A.0 + d * phi.cos(), A.1 + d * phi.sin());
    // Realized distance to the limit, from the exact f64 inputs.
    let dist = refg::norm(refg::sub(dv(&b), refg::v(A.0, A.1)));
    let (l1, l2) = (Dd::from(L1), Dd::from(L2));
    let gap = if outer {
        l1 + l2 - dist
    } else {
        dist - (l1 - l2).abs()
    };
    (b, (gap / (l1 + l2)).to_f64())
}

/// Sweeps an RRR edge; returns the worst `err sqrt(delta) / eps`.
fn rrr_sweep(outer: bool) -> f64 {
    let a = p(A.0, A.1);
    let mut worst: f64 = 0.0;
    for delta in deltas() {
        for phi in PHIS {
            let (b, real) = rrr_case(delta, phi, outer);
            assert!(real > 0.0, "inside by construction: {real:e}");
            for (mode, left) in [(Mode::Plus, true), (Mode::Minus, false)] {
                let c = rrr::position(&a, L1, &b, L2, mode)
                    .unwrap_or_else(|e| panic!("delta {real:e}: {e}"))
                    .c;
                let r = refg::rrr_position(refg::v(A.0, A.1), L1, dv(&b), L2, left).unwrap();
                let err = dist(&c, r) / (L1 + L2);
                worst = worst.max(err * real.sqrt() / EPS);
            }
        }
    }
    worst
}

/// Proves: near `|B - A| = l1 + l2` (links almost stretched out) the RRR joint
/// is accurate to the problem's conditioning, `c eps / sqrt(delta)`, down to
/// `delta = 1e-14`, in every direction and both modes.
#[test]
fn rrr_outer_edge_accurate_to_conditioning() {
    let c = rrr_sweep(true);
    println!("RRR outer edge: max err sqrt(delta) / eps = {c:.3}");
    assert!(c <= C_POSITION, "c = {c}");
}

/// Proves: the same near `|B - A| = |l1 - l2|` (links folded onto each other).
#[test]
fn rrr_inner_edge_accurate_to_conditioning() {
    let c = rrr_sweep(false);
    println!("RRR inner edge: max err sqrt(delta) / eps = {c:.3}");
    assert!(c <= C_POSITION, "c = {c}");
}

/// Proves: near tangency of the circle about `A` and the slide line, the RRP
/// joint is accurate to `c eps / sqrt(delta)` (`delta = (l - |k|) / l`, `k`
/// the distance of `A` from the offset line), for tilted guides and offsets.
#[test]
fn rrp_tangency_accurate_to_conditioning() {
    let (l, offset) = (0.37, 0.055);
    let origin = [0.2, -0.1];
    let mut worst: f64 = 0.0;
    for psi in [0.3f64, 1.9, -2.4] {
        let g = Line {
            origin: p(origin[0], origin[1]),
            dir: Vector2::new(psi.cos(), psi.sin()),
        };
        let gr = refg::Line::new(origin, [g.dir.x, g.dir.y]);
        for delta in deltas() {
            for side in [1.0, -1.0] {
                let k = offset + side * l * (1.0 - delta);
                let a = g.origin + g.dir * 0.123 + Vector2::new(-g.dir.y, g.dir.x) * k;
                // Realized delta from the exact inputs.
                let kr = refg::cross(gr.dir, refg::sub(dv(&a), gr.origin)) - Dd::from(offset);
                let real = ((Dd::from(l) - kr.abs()) / Dd::from(l)).to_f64();
                assert!(real > 0.0);
                for (mode, ahead) in [(Mode::Plus, true), (Mode::Minus, false)] {
                    let pos = rrp::position(&a, l, &g, offset, mode)
                        .unwrap_or_else(|e| panic!("delta {real:e}: {e}"));
                    let (cr, sr) = refg::rrp_position(dv(&a), l, &gr, offset, ahead).unwrap();
                    let err = (dist(&pos.c, cr) / l).max(rel(pos.s, sr) * sr.abs().to_f64() / l);
                    worst = worst.max(err * real.sqrt() / EPS);
                }
            }
        }
    }
    println!("RRP tangency: max err sqrt(delta) / eps = {worst:.3}");
    assert!(worst <= C_POSITION, "c = {worst}");
}

/// Proves: when `A` approaches the circle of radius `|offset|` about `B` (the
/// RPR's slide line through `A` becomes the tangent at `A`), the axis and the
/// block's place are accurate to `c eps / sqrt(delta)`,
/// `delta = (|A - B| - |offset|) / |offset|`.
#[test]
fn rpr_tangency_accurate_to_conditioning() {
    let b = p(0.4, 0.1);
    let mut worst: f64 = 0.0;
    for offset in [0.35, -0.35] {
        let e = f64::abs(offset);
        for phi in PHIS {
            for delta in deltas() {
                let r = e * (1.0 + delta);
                let a = p(b.x + r * phi.cos(), b.y + r * phi.sin());
                let dist_r = refg::norm(refg::sub(dv(&a), dv(&b)));
                let real = ((dist_r - Dd::from(e)) / Dd::from(e)).to_f64();
                assert!(real > 0.0);
                for (mode, pos_s) in [(Mode::Plus, true), (Mode::Minus, false)] {
                    let pos = rpr::position(&a, &b, offset, mode)
                        .unwrap_or_else(|err| panic!("delta {real:e}: {err}"));
                    let (u, s) = refg::rpr_position(dv(&a), dv(&b), offset, pos_s).unwrap();
                    let err_u = refg::norm(refg::sub(dvec(&pos.axis), u)).to_f64();
                    let err_s = (Dd::from(pos.s) - s).abs().to_f64() / e;
                    worst = worst.max(err_u.max(err_s) * real.sqrt() / EPS);
                }
            }
        }
    }
    println!("RPR tangency: max err sqrt(delta) / eps = {worst:.3}");
    assert!(worst <= C_POSITION, "c = {worst}");
}

/// The textbook RRR formula `h = sqrt(l1^2 - a^2)`, `a = (l1^2 - l2^2 + d^2)
/// / (2 d)`, for contrast. Returns `(C, h)`.
fn naive_rrr(a: Point2<f64>, l1: f64, b: Point2<f64>, l2: f64) -> (Point2<f64>, f64) {
    let d = b - a;
    let dist = (d.x * d.x + d.y * d.y).sqrt();
    let along = (l1 * l1 - l2 * l2 + dist * dist) / (2.0 * dist);
    let h = (l1 * l1 - along * along).sqrt();
    let e = d / dist;
    (a + e * along + Vector2::new(-e.y, e.x) * h, h)
}

/// Proves: the clamped Heron height on squared lengths keeps the height to
/// the problem's conditioning at every orientation (relative error at most
/// `c eps / delta`, the same law as the absolute bound `c eps / sqrt(delta)`
/// above, since `h ~ sqrt(delta)`) and never returns NaN where the group
/// assembles, while the textbook `sqrt(l1^2 - a^2)` returns NaN or a height
/// 3 % wrong one ulp inside the edge. (With exact axis-aligned inputs a form
/// using `l1 + l2 - |d|` can do better than `eps / delta`, because
/// `sqrt(fl(x^2)) = |x|`; in any other direction `|d|` carries a rounding
/// and both forms follow `eps / delta`: docs/stability.md.)
#[test]
fn naive_formula_fails_at_the_edge() {
    let (l1, l2) = (1.25, 0.75); // l1 + l2 = 2 exactly
    let a = p(0.0, 0.0);
    let mut ours: f64 = 0.0; // max relative error of the height x delta / eps
    let mut naive: f64 = 0.0; // the same for the textbook formula
    for phi in [0.0f64, 0.3, 1.0, 2.5] {
        for delta in deltas() {
            let r = 2.0 * (1.0 - delta);
            let b = p(r * phi.cos(), r * phi.sin());
            let real = (Dd::from(2.0) - refg::norm(dv(&b))).to_f64() / 2.0;
            let h_ref = {
                let c = refg::rrr_position(refg::v(0.0, 0.0), l1, dv(&b), l2, true).unwrap();
                // Distance of C from the line A B (through the origin).
                let (bx, by) = (Dd::from(b.x), Dd::from(b.y));
                ((bx * c[1] - by * c[0]) / refg::norm(dv(&b))).to_f64()
            };
            let c = rrr::position(&a, l1, &b, l2, Mode::Plus).unwrap().c;
            let h = (b.x * c.y - b.y * c.x) / (b.x * b.x + b.y * b.y).sqrt();
            assert!(h.is_finite() && h > 0.0, "phi {phi} delta {real:e}: {h}");
            ours = ours.max((h - h_ref).abs() / h_ref * real / EPS);
            let (c_naive, _) = naive_rrr(a, l1, b, l2);
            let h_naive = (b.x * c_naive.y - b.y * c_naive.x) / (b.x * b.x + b.y * b.y).sqrt();
            naive = naive.max((h_naive - h_ref).abs() / h_ref * real / EPS);
        }
    }
    println!("height: max rel err x delta / eps = {ours:.3}; textbook formula {naive:.3}");
    // The conditioning: D = |d|^2 carries about 1.5 ulp of 4, against a
    // factor (l1 + l2)^2 - D of about 8 delta, so the height (a square root)
    // is off by about (1.5 eps 4) / (2 8 delta) = 0.375 eps / delta at most;
    // 1 leaves room for the rounding of the other factor and the products
    // (measured 0.146; the textbook formula, which subtracts two rounded
    // squares of about l1^2 = 1.6, measures 0.805 and fails one ulp inside).
    assert!(ours <= 1.0, "height: {ours} eps / delta");

    // One ulp inside the edge: B = (2 - 2^-51, 0), delta = 2^-52. Measured:
    // naive 3% off (2.107e-8 against 2.040e-8); ours: D = 4 - 2^-49 rounds
    // exactly, so the height is correctly rounded.
    let b = p(2.0 - 2f64.powi(-51), 0.0);
    let h_ref = refg::rrr_position(refg::v(0.0, 0.0), l1, dv(&b), l2, true).unwrap()[1];
    let c = rrr::position(&a, l1, &b, l2, Mode::Plus).unwrap().c;
    let (_, h_naive) = naive_rrr(a, l1, b, l2);
    println!(
        "one ulp inside: reference h = {:.6e}, ours {:.6e}, naive {h_naive:e}",
        h_ref.to_f64(),
        c.y
    );
    assert!(rel(c.y, h_ref) <= 4.0 * EPS);
    assert!(
        h_naive.is_nan() || rel(h_naive, h_ref) > 0.01,
        "naive happened to be right: {h_naive}"
    );
}

fn expect_cannot_assemble(r: Result<impl core::fmt::Debug, Error>, prim: Primitive) -> (f64, f64) {
    match r {
        Err(Error {
            primitive,
            fault: Fault::CannotAssemble { miss, reach },
            ..
        }) if primitive == prim => (miss, reach),
        other => panic!("expected CannotAssemble from {prim:?}, got {other:?}"),
    }
}

/// Proves: just outside every limit (relative 1e-2 .. 1e-14, all beyond the
/// documented `4 eps` rounding band) each group and the actuator return
/// `CannotAssemble` (never NaN, never a point), with `miss` equal to the
/// exact distance outside the range within `4 eps L` (the rounding of `l1 +
/// l2` and of `|B - A|`, one each, plus the subtraction) and `reach` the bound
/// missed; and that inside the band the result is `Ok` and finite.
#[test]
fn just_outside_is_cannot_assemble_with_the_exact_miss() {
    let a = p(A.0, A.1);
    let (l1, l2) = (Dd::from(L1), Dd::from(L2));
    let mut worst: f64 = 0.0;
    for delta in deltas() {
        for phi in PHIS {
            for outer in [true, false] {
                let (b, real) = rrr_case(-delta, phi, outer);
                assert!(real < 0.0);
                let b_d = dv(&b);
                let dist_r = refg::norm(refg::sub(b_d, refg::v(A.0, A.1)));
                let miss_r = if outer {
                    dist_r - (l1 + l2)
                } else {
                    (l1 - l2).abs() - dist_r
                };
                for (prim, r) in [
                    (Primitive::Rrr, rrr::position(&a, L1, &b, L2, Mode::Plus)),
                    (
                        Primitive::Actuator,
                        actuator::position(&a, L1, &b, L2, Mode::Minus),
                    ),
                ] {
                    let (miss, reach) = expect_cannot_assemble(r, prim);
                    let e = (Dd::from(miss) - miss_r).abs().to_f64() / (L1 + L2);
                    worst = worst.max(e / EPS);
                    let want = if outer { L1 + L2 } else { (L1 - L2).abs() };
                    assert!((reach - want).abs() <= EPS * want, "reach {reach}");
                }
            }
        }
        // RRP: A farther than l from the line.
        let (l, offset) = (0.37, 0.055);
        let g = Line {
            origin: p(0.2, -0.1),
            dir: Vector2::new(1.0, 0.0),
        };
        let a_far = p(0.5, -0.1 + offset + l * (1.0 + delta));
        let (miss, _) = expect_cannot_assemble(
            rrp::position(&a_far, l, &g, offset, Mode::Plus),
            Primitive::Rrp,
        );
        let miss_r = Dd::from(a_far.y) - Dd::from(-0.1) - Dd::from(offset) - Dd::from(l);
        worst = worst.max((Dd::from(miss) - miss_r).abs().to_f64() / l / EPS);
        // RPR: A inside the circle of radius |offset|.
        let e = 0.35;
        let a_in = p(0.4 + e * (1.0 - delta), 0.1);
        let (miss, reach) = expect_cannot_assemble(
            rpr::position(&a_in, &p(0.4, 0.1), -e, Mode::Plus),
            Primitive::Rpr,
        );
        let miss_r = Dd::from(e) - (Dd::from(a_in.x) - Dd::from(0.4));
        worst = worst.max((Dd::from(miss) - miss_r).abs().to_f64() / e / EPS);
        assert_eq!(reach, e);
    }
    println!("just outside: max |miss - exact| = {worst:.3} eps L");
    assert!(worst <= 4.0, "{worst} eps");

    // Inside the band (|delta| <= 2 eps here, the band is 4 eps): Ok, finite,
    // within 2 sqrt(4 eps) L of the limit pose (the band's own conditioning).
    for k in -2..=2 {
        let b = p(A.0 + (L1 + L2) * (1.0 + k as f64 * EPS), A.1);
        let c = rrr::position(&a, L1, &b, L2, Mode::Plus).expect("in the band");
        assert!(c.c.x.is_finite() && c.c.y.is_finite());
        let limit = p(A.0 + L1, A.1);
        assert!((c.c - limit).norm() <= 2.0 * (4.0 * EPS).sqrt() * (L1 + L2));
    }
}
