//! Exact sensitivities: the generated `FourBarPath` code run on
//! `mechanism::dual::Dual` gives the derivatives of the coupler point with
//! respect to parameters and the input that (1) Richardson-extrapolated central
//! differences of the f64 code and (2) the four-bar's hand-derived velocity
//! equation give.

use mechanism::dual::Dual;
use mechanism::Mode;
use mechanism_synthesis::fourbar::{FourBarPath, FourBarPathInput};

type D = Dual<10>;

/// The test four-bar (a crank-rocker), each parameter seeded as its own
/// derivative direction (0..9 in field order), the input as direction 9.
fn seeded(phi: f64, mode: Mode) -> (FourBarPath<D>, FourBarPathInput<D>) {
    let p = [4.0, 1.2, 3.1, 3.4, 1.5, 0.8, 0.3, -0.7, 0.4];
    let fb = FourBarPath {
        r1: D::var(p[0], 0),
        r2: D::var(p[1], 1),
        r3: D::var(p[2], 2),
        r4: D::var(p[3], 3),
        rcx: D::var(p[4], 4),
        rcy: D::var(p[5], 5),
        theta0: D::var(p[6], 6),
        x0: D::var(p[7], 7),
        y0: D::var(p[8], 8),
        circuit: mode,
    };
    (
        fb,
        FourBarPathInput {
            phi: D::var(phi, 9),
        },
    )
}

/// The coupler point in f64 with seed direction `k` moved by `h`.
fn point_f64(phi: f64, mode: Mode, k: usize, h: f64) -> [f64; 2] {
    let (fb, input) = seeded(phi, mode);
    let v = |d: D, j: usize| d.re + if j == k { h } else { 0.0 };
    let f = FourBarPath {
        r1: v(fb.r1, 0),
        r2: v(fb.r2, 1),
        r3: v(fb.r3, 2),
        r4: v(fb.r4, 3),
        rcx: v(fb.rcx, 4),
        rcy: v(fb.rcy, 5),
        theta0: v(fb.theta0, 6),
        x0: v(fb.x0, 7),
        y0: v(fb.y0, 8),
        circuit: mode,
    };
    let p = f
        .position(&FourBarPathInput {
            phi: v(input.phi, 9),
        })
        .expect("the test four-bar assembles");
    [p.P.x, p.P.y]
}

/// Central difference with Richardson extrapolation (h and h/2): error
/// O(h^4) ~ 1e-10 relative at h = 1e-3 on this O(1) geometry, rounding
/// O(eps / h) ~ 1e-13.
fn richardson(phi: f64, mode: Mode, k: usize) -> [f64; 2] {
    let h = 1e-3;
    let cd = |h: f64| {
        let (a, b) = (point_f64(phi, mode, k, h), point_f64(phi, mode, k, -h));
        [(a[0] - b[0]) / (2.0 * h), (a[1] - b[1]) / (2.0 * h)]
    };
    let (d1, d2) = (cd(h), cd(h / 2.0));
    [(4.0 * d2[0] - d1[0]) / 3.0, (4.0 * d2[1] - d1[1]) / 3.0]
}

#[test]
fn dual_derivatives_of_every_parameter_and_the_input_match_finite_differences() {
    for mode in [Mode::Plus, Mode::Minus] {
        for step in 0..12 {
            let phi = 0.1 + step as f64 * 0.5;
            let (fb, input) = seeded(phi, mode);
            let p = fb.position(&input).expect("assembles");
            for k in 0..10 {
                let fd = richardson(phi, mode, k);
                let (dx, dy) = (p.P.x.eps[k], p.P.y.eps[k]);
                // Tolerance: the extrapolated difference's truncation
                // (~1e-10 relative, see `richardson`) on derivatives of size
                // up to ~10.
                assert!(
                    (dx - fd[0]).abs() <= 1e-8 * (1.0 + fd[0].abs())
                        && (dy - fd[1]).abs() <= 1e-8 * (1.0 + fd[1].abs()),
                    "mode {mode:?} phi {phi} seed {k}: dual ({dx}, {dy}) vs fd {fd:?}"
                );
            }
        }
    }
}

#[test]
fn dual_derivative_along_the_crank_matches_the_hand_derived_velocity_equation() {
    // Loop closure r2 e^{i phi} + r3 e^{i th3} = r1 e^{i th0} + r4 e^{i th4}:
    // d th3 / d phi = r2 sin(th4 - phi) / (r3 sin(th3 - th4)), and
    // P = A + R(th3) (rcx, rcy) gives
    // dP/dphi = r2 (-sin phi, cos phi) + d th3/d phi (-(rcx s3 + rcy c3), rcx c3 - rcy s3).
    for mode in [Mode::Plus, Mode::Minus] {
        for step in 0..12 {
            let phi = 0.2 + step as f64 * 0.5;
            let (fb, input) = seeded(phi, mode);
            let p = fb.position(&input).expect("assembles");
            let (a, b, o4) = (p.A, p.B, p.O4);
            let th3 = (b.y.re - a.y.re).atan2(b.x.re - a.x.re);
            let th4 = (b.y.re - o4.y.re).atan2(b.x.re - o4.x.re);
            let (r2, r3) = (fb.r2.re, fb.r3.re);
            let (rcx, rcy) = (fb.rcx.re, fb.rcy.re);
            let w3 = r2 * (th4 - phi).sin() / (r3 * (th3 - th4).sin());
            let (s3, c3) = th3.sin_cos();
            let hand = [
                -r2 * phi.sin() - w3 * (rcx * s3 + rcy * c3),
                r2 * phi.cos() + w3 * (rcx * c3 - rcy * s3),
            ];
            // Both are exact formulas evaluated in f64: a few ulps of the
            // O(1) terms, amplified by 1 / sin(th3 - th4) (>= 0.2 here).
            for (d, h) in [p.P.x.eps[9], p.P.y.eps[9]].iter().zip(hand) {
                assert!((d - h).abs() <= 1e-12 * (1.0 + h.abs()), "{d} vs {h}");
            }
        }
    }
}
