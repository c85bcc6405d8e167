//! The f32 accuracy of the RRP group near tangency and of the generated
//! six-bar, against the double-double reference
//! (`mechanism-reference`). The analysis behind the bounds is in
//! `docs/stability.md`, section "f32 six-bar".

use crate::{reference, scenes};

use mechanism::dyad::{rrp, rrr};
use mechanism::guide::{Line, LineAcceleration, LineVelocity};
use mechanism::{geometry, link, Mode, Point2, Real, Vector2};
use mechanism_reference::groups as refg;
use mechanism_reference::Dd;

/// f32 machine epsilon (2^-23).
const EPS32: f64 = f32::EPSILON as f64;

/// Proves: in f32, with a guide direction rounded from `(cos, sin)` (so off
/// unit length by up to an ulp) and `A` at relative distance `delta` inside
/// tangency, the RRP joint is accurate to a few eps of `l`, not to
/// `eps / sqrt(delta)`: the reference takes the same `A`, `l` and the exact
/// direction of the rounded pair, so the only error left is the group's own
/// rounding. Without the compensation (`k` carried with its rounding error,
/// the direction divided by its length) the error grows like
/// `eps / sqrt(delta)`: 84 eps of `l` here (at `delta = 5.3e-5`); with it 1.1.
#[test]
fn rrp_f32_near_tangency_with_a_rounded_direction() {
    let l = 60.0f32;
    let mut worst: f64 = 0.0;
    for k in 0..40 {
        // Guide angles over a full turn, none a multiple of 90 degrees.
        let psi = 0.1 + 0.157 * k as f64;
        let dir = Vector2::new(psi.cos() as f32, psi.sin() as f32);
        let g = Line {
            origin: Point2::origin(),
            dir,
        };
        let gr = refg::Line::new([0.0, 0.0], [dir.x as f64, dir.y as f64]);
        for delta in [0.2, 0.05, 1.3e-2, 3.1e-3, 1.7e-4, 5.3e-5] {
            for side in [1.0f64, -1.0] {
                // A at distance l (1 - delta) from the line (to f32 rounding;
                // the reference takes A as rounded).
                let kk = side * 60.0 * (1.0 - delta);
                let along = 23.7;
                let a = Point2::new(
                    (psi.cos() * along - psi.sin() * kk) as f32,
                    (psi.sin() * along + psi.cos() * kk) as f32,
                );
                let ar = refg::v(a.x as f64, a.y as f64);
                for (mode, ahead) in [(Mode::Plus, true), (Mode::Minus, false)] {
                    let Ok(pos) = rrp::position(&a, l, &g, 0.0, mode) else {
                        panic!("psi {psi}, delta {delta}: no assembly");
                    };
                    let (cr, _) =
                        refg::rrp_position(ar, 60.0, &gr, 0.0, ahead).expect("reference assembles");
                    let dx = (Dd::from(pos.c.x as f64) - cr[0]).to_f64();
                    let dy = (Dd::from(pos.c.y as f64) - cr[1]).to_f64();
                    worst = worst.max(dx.hypot(dy) / 60.0 / EPS32);
                }
            }
        }
    }
    println!("RRP f32 near tangency: max |C - C_ref| / (l eps) = {worst:.2}");
    // The output's own rounding is 0.5 ulp per coordinate of |C| <= 84
    // (up to 1 eps of l per coordinate), plus the rounding of the half chord
    // and of r1; 4 eps of l bounds that sum with room (1.1 measured), and
    // lies far below the 84 eps of the uncompensated form.
    assert!(worst <= 4.0, "{worst} eps");
}

/// Proves: the generated f32 six-bar stays within the error the analysis
/// in `docs/stability.md` accounts for, on the part of its range where the
/// error is largest (54..55 deg, the crank line closest to tangency of the
/// RRP) and a coarse sample of the rest. Errors are relative to each
/// column's largest reference value over the sample, as in the report.
#[test]
fn generated_f32_six_bar_against_reference() {
    let scene = reference::scenes()
        .into_iter()
        .find(|s| s.name == "SixBar")
        .expect("the six-bar scene");
    let m32 = scenes::SixBar::<f32>::default();
    let mut degs: Vec<f64> = (0..15).map(|k| 40.0 + k as f64).collect();
    degs.extend((0..40).map(|k| 54.0 + 0.025 * k as f64));
    let (w, a) = (10.0f32, -60.0f32);
    let mut rows = Vec::new();
    for d in degs {
        let phi = d.to_radians() as f32;
        let i = |x: f32| scenes::SixBarInput { phi1: x };
        let s = m32
            .solve(&i(phi), &i(w), &i(a))
            .expect("f32 six-bar solves");
        let (p, v, ac) = (s.position, s.velocity, s.acceleration);
        let got: Vec<f64> = [
            p.C.x, p.C.y, p.F.x, p.F.y, p.link2, p.link3, p.link4, p.af, v.C.x, v.C.y, v.F.x,
            v.F.y, v.link2, v.link3, v.link4, v.af, ac.C.x, ac.C.y, ac.F.x, ac.F.y, ac.link2,
            ac.link3, ac.link4, ac.af,
        ]
        .iter()
        .map(|&x| x as f64)
        .collect();
        let (c, s) = (phi.cos() as f64, phi.sin() as f64);
        let l4 = p.link4 as f64;
        let start = [
            (0.0, 0.0),
            (70.0, 0.0),
            (40.0 * c, 40.0 * s),
            (-40.0 * c, -40.0 * s),
            (p.F.x as f64, p.F.y as f64),
            (70.0 - 35.0 * l4.cos(), -35.0 * l4.sin()),
            (p.C.x as f64, p.C.y as f64),
        ];
        let (r, _) = reference::solve(&scene, &[phi as f64], &[w as f64], &[a as f64], &start)
            .expect("reference solves");
        rows.push((got, r));
    }
    let n = scene.columns.len();
    let mut scale = vec![0.0f64; n];
    for (_, r) in &rows {
        for k in 0..n {
            scale[k] = scale[k].max(r[k].to_f64().abs());
        }
    }
    let (mut pos, mut rate) = (0.0f64, 0.0f64);
    for (g, r) in &rows {
        for k in 0..n {
            let e = (Dd::from(g[k]) - r[k]).to_f64().abs() / scale[k];
            if scene.columns[k].order == 0 {
                pos = pos.max(e);
            } else {
                rate = rate.max(e);
            }
        }
    }
    println!("f32 six-bar: position {pos:.2e}, rates {rate:.2e} (relative to column maxima)");
    // Bounds (docs/stability.md, "f32 six-bar"): what the f64 code makes of
    // the f32-rounded cos/sin alone is 3.5e-7 (positions) and 2.0e-6
    // (rates) over the whole grid; the f32 RRR position brings C.y to
    // 2.4e-6, the RRP rates and the output roundings F.x'' to 3.7e-6.
    // Measured on this sample: 1.49e-6 and 3.68e-6 (the RRR and RRP rates
    // formed from `r / det`, which keeps slow, small groups out of
    // subnormal products; 2.90e-6 with the products first: the same number
    // of roundings, landing elsewhere). The report's 3600-point grid finds
    // 2.2e-6 and 4.0e-6 between these angles, and the rates' floor is the
    // rounding of the f32 cos/sin (about 2e-6, docs/stability.md). 1.8e-6
    // and 4.4e-6 leave about a fifth for another platform's sine and still
    // catch the lost digits of the uncompensated RRP (5.15e-6 in rates on
    // this sample).
    assert!(pos <= 1.8e-6, "position {pos:e}");
    assert!(rate <= 4.4e-6, "rates {rate:e}");
}

/// The stage study of `docs/stability.md` ("f32 six-bar"): the generated
/// six-bar's sequence of primitive calls, replayed with each stage in f64, in
/// f32, or in f64 with its outputs rounded to f32, against the all-f64 chain
/// at the same f32-rounded crank angle (whose own error, about 1e-14, is far
/// below what is measured). Prints one line per variant; asserts that the
/// all-f32 replay is the generated f32 code (so that the study studies it).
/// `cargo test --release --test stability sixbar_f32 -- --ignored --nocapture`.
#[test]
#[ignore = "prints the stage study (seconds in release)"]
fn stage_study() {
    let (w, al) = (10.0, -60.0);
    let grid: Vec<f64> = (0..3600)
        .map(|k| r((40.0 + 15.0 * k as f64 / 3600.0).to_radians()))
        .collect();
    let refs: Vec<[f64; 24]> = grid
        .iter()
        .map(|&p| chain(p, w, al, &[M::D; NS], Ax::None))
        .collect();
    let mut scale = [0.0f64; 24];
    for rr in &refs {
        for k in 0..24 {
            scale[k] = scale[k].max(rr[k].abs());
        }
    }
    // The replay in f32 is the generated code.
    let m32 = scenes::SixBar::<f32>::default();
    for &phi in &grid {
        let o = chain(phi, w, al, &[M::S; NS], Ax::None);
        let i = |x: f64| scenes::SixBarInput { phi1: x as f32 };
        let s = m32.solve(&i(phi), &i(w), &i(al)).expect("solves");
        let (p, v) = (s.position, s.velocity);
        let g = [p.C.x, p.C.y, p.F.x, p.F.y, v.C.x, v.F.y, s.acceleration.F.x];
        let o = [o[0], o[1], o[2], o[3], o[8], o[11], o[18]];
        for (a, b) in g.iter().zip(o) {
            // Both are the same f32 operations: equal but for an operation
            // the compiler may order differently (a few ulp).
            assert!(
                (*a as f64 - b).abs() <= 4.0 * 1.2e-7 * b.abs().max(1.0),
                "{a} {b}"
            );
        }
    }
    let report = |label: &str, m: &[M; NS], ax: Ax, dphi: f64| {
        let mut worst = [0.0f64; 24];
        for (p, rr) in grid.iter().zip(&refs) {
            let o = chain(*p + dphi, w, al, m, ax);
            for k in 0..24 {
                worst[k] = worst[k].max((o[k] - rr[k]).abs() / scale[k]);
            }
        }
        let pos = worst[..8].iter().cloned().fold(0.0, f64::max);
        let rate = worst[8..].iter().cloned().fold(0.0, f64::max);
        // The worst rate column (the report's column names).
        let kr = 8 + (0..16).fold(0, |b, k| if worst[8 + k] > worst[8 + b] { k } else { b });
        println!(
            "{label:<42} positions {pos:.3e}  rates {rate:.3e}  C.y {:.2e}  d2/dt2 F.x {:.2e}  ({})",
            worst[1], worst[18], COLS[kr]
        );
    };
    report("all f32", &[M::S; NS], Ax::None, 0.0);
    report(
        "f64 inside each stage, f32 between",
        &[M::R; NS],
        Ax::None,
        0.0,
    );
    let mut axis_r = [M::D; NS];
    axis_r[0] = M::R;
    report("f64, cos/sin rounded to f32", &axis_r, Ax::None, 0.0);
    report(
        "f64, axis turned as the f32 pair",
        &[M::D; NS],
        Ax::Turned,
        0.0,
    );
    report(
        "f64, axis scaled as the f32 pair",
        &[M::D; NS],
        Ax::Scaled,
        0.0,
    );
    for (k, n) in ["B", "RRP position", "RRP rates"].iter().enumerate() {
        report(
            &format!("f64, axis scaled for {n} only"),
            &[M::D; NS],
            Ax::ScaledFor(k as u8),
            0.0,
        );
    }
    report(
        "f64, phi + 2^-25",
        &[M::D; NS],
        Ax::None,
        1.0 / 33_554_432.0,
    );
    // What a crank direction carried with a tail and compensated RRP rate
    // arithmetic could buy at best (docs/stability.md, "f32 six-bar", the
    // 2026-11-22 paragraph). First in f64 arithmetic: the consumers of the
    // axis (B, the RRP position, the RRP rates and accelerations) given the
    // exact direction (X) or the rounded pair's angle (U).
    use Src::{Exact as X, Stage as G, Turned as U};
    // Stages by their index in NAMES.
    let (rrp, rrr, rrpv, rrpa) = (2, 4, 7, 11);
    // Every stage in `base`, but the stages in `rounded` in f64 with their
    // outputs rounded to f32.
    let modes = |base: M, rounded: &[usize]| {
        let mut m = [base; NS];
        for &i in rounded {
            m[i] = M::R;
        }
        m
    };
    // Then the f32 code with the ideal of each idea: (1) the RRP position
    // from the exact direction in f64, its outputs rounded (a tail on the
    // direction entering `k`); (2) the RRP rates and accelerations in f64,
    // outputs rounded (compensated right-hand sides at their best); the
    // rates given the exact direction too (the tail entering the rate
    // systems); and the RRR position in f64, outputs rounded. Last, the
    // floor of f32 values between the primitives: every stage in f64 with
    // its outputs rounded and the exact direction; then with the RRP
    // group's state (position, rates) carried unrounded from its position
    // to its accelerations ("fused": what tails on `r1`, `s`, `omega1`,
    // `s_dot` would give), alone and in the f32 code.
    let variants = [
        (
            "f64, turned but the RRP position exact",
            modes(M::D, &[]),
            Ax::Per([U, X, U]),
        ),
        (
            "f64, turned for the RRP rates only",
            modes(M::D, &[]),
            Ax::Per([X, X, U]),
        ),
        (
            "f64, turned but the RRP exact",
            modes(M::D, &[]),
            Ax::Per([U, X, X]),
        ),
        (
            "f32, RRR pos. exact, rounded",
            modes(M::S, &[rrr]),
            Ax::None,
        ),
        (
            "f32, RRP pos. exact dir, rounded (1)",
            modes(M::S, &[rrp]),
            Ax::Per([G, X, G]),
        ),
        (
            "f32, RRP v, a exact, rounded (2)",
            modes(M::S, &[rrpv, rrpa]),
            Ax::None,
        ),
        (
            "f32, (1) and (2)",
            modes(M::S, &[rrp, rrpv, rrpa]),
            Ax::Per([G, X, G]),
        ),
        (
            "f32, (1) and (2), rates exact dir",
            modes(M::S, &[rrp, rrpv, rrpa]),
            Ax::Per([G, X, X]),
        ),
        (
            "f32, (1), (2) exact dir, RRR pos. rounded",
            modes(M::S, &[rrp, rrr, rrpv, rrpa]),
            Ax::Per([G, X, X]),
        ),
        (
            "f64 in each stage, f32 between, exact dir",
            modes(M::R, &[]),
            Ax::Per([X, X, X]),
        ),
        (
            "f64 in each stage, f32 between, RRP fused",
            modes(M::R, &[]),
            Ax::Fused([X, X, X]),
        ),
        (
            "f32, RRP fused in f64, exact dir",
            modes(M::S, &[]),
            Ax::Fused([X, X, X]),
        ),
        (
            "f32, RRP fused in f64, RRR pos. rounded",
            modes(M::S, &[rrr]),
            Ax::Fused([X, X, X]),
        ),
    ];
    for (label, m, ax) in variants {
        report(label, &m, ax, 0.0);
    }
    // Which stage's f32 storage costs what, with the exact direction.
    for i in 1..NS {
        let mut m = [M::D; NS];
        m[i] = M::R;
        report(
            &format!("f64, exact dir, only {} rounded", NAMES[i]),
            &m,
            Ax::Per([X, X, X]),
            0.0,
        );
    }
    for i in 1..NS {
        let mut m = axis_r;
        m[i] = M::S;
        report(
            &format!("cos/sin rounded, {} in f32", NAMES[i]),
            &m,
            Ax::None,
            0.0,
        );
        m[i] = M::R;
        report(
            &format!("cos/sin rounded, {} rounded", NAMES[i]),
            &m,
            Ax::None,
            0.0,
        );
    }
}

// The stage study's replay of the generated code, one function per stage.

/// How a stage runs: in f64, in f32 (inputs rounded to f32), or in f64 with
/// its outputs rounded to f32.
#[derive(Clone, Copy, PartialEq, Debug)]
enum M {
    D,
    S,
    R,
}

fn c<A: Real, B: Real>(x: A) -> B {
    B::lit(x.as_f64())
}
fn cv<A: Real, B: Real>(v: &Vector2<A>) -> Vector2<B> {
    Vector2::new(c(v.x), c(v.y))
}
fn cp<A: Real, B: Real>(v: &Point2<A>) -> Point2<B> {
    Point2::new(c(v.x), c(v.y))
}
fn r(x: f64) -> f64 {
    x as f32 as f64
}
fn rv(v: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(r(v.x), r(v.y))
}
fn rp(v: Point2<f64>) -> Point2<f64> {
    Point2::new(r(v.x), r(v.y))
}

fn crp<A: Real, B: Real>(p: &rrp::RrpPosition<A>) -> rrp::RrpPosition<B> {
    rrp::RrpPosition {
        c: cp(&p.c),
        r1: cv(&p.r1),
        s: c(p.s),
        l: c(p.l),
    }
}
fn crv<A: Real, B: Real>(p: &rrp::RrpVelocity<A>) -> rrp::RrpVelocity<B> {
    rrp::RrpVelocity {
        omega1: c(p.omega1),
        s_dot: c(p.s_dot),
        vc: cv(&p.vc),
        condition: c(p.condition),
    }
}
fn ccp<A: Real, B: Real>(p: &rrr::RrrPosition<A>) -> rrr::RrrPosition<B> {
    rrr::RrrPosition::new(cp(&p.c), cv(&p.r1), cv(&p.r2))
}
fn ccv<A: Real, B: Real>(p: &rrr::RrrVelocity<A>) -> rrr::RrrVelocity<B> {
    rrr::RrrVelocity {
        omega1: c(p.omega1),
        omega2: c(p.omega2),
        vc: cv(&p.vc),
        condition: c(p.condition),
        inv_det: c(p.inv_det),
    }
}

// Stage functions, generic.
fn s_axis<T: Real>(phi: f64) -> Vector2<f64> {
    let (s, co) = T::lit(phi).sin_cos_kernel();
    Vector2::new(co.as_f64(), s.as_f64())
}
fn s_b<T: Real>(axis: &Vector2<f64>) -> Point2<f64> {
    cp(&link::point_position(
        &Point2::<T>::origin(),
        &cv(axis),
        &Vector2::new(T::lit(-40.0), T::lit(0.000000000000004898587196589413)),
    )
    .unwrap())
}
fn s_rrp<T: Real>(axis: &Vector2<f64>) -> rrp::RrpPosition<f64> {
    let g = Line {
        origin: Point2::<T>::origin(),
        dir: cv(axis),
    };
    crp(&rrp::position(
        &Point2::new(T::lit(70.0), T::zero()),
        T::lit(60.0),
        &g,
        T::zero(),
        Mode::Plus,
    )
    .unwrap())
}
fn s_d<T: Real>(r1: &Vector2<f64>) -> Point2<f64> {
    let ax: Vector2<T> = cv::<f64, T>(r1) / T::lit(60.0);
    cp(&link::point_position(
        &Point2::new(T::lit(70.0), T::zero()),
        &ax,
        &Vector2::new(T::lit(-35.0), T::lit(0.0000000000000042862637970157365)),
    )
    .unwrap())
}
fn s_rrr<T: Real>(b: &Point2<f64>, d: &Point2<f64>) -> rrr::RrrPosition<f64> {
    ccp(&rrr::position(
        &cp::<f64, T>(b),
        T::lit(50.0),
        &cp(d),
        T::lit(75.0),
        Mode::Plus,
    )
    .unwrap())
}
fn s_ang<T: Real>(v: &Vector2<f64>) -> f64 {
    geometry::angle(&cv::<f64, T>(v)).as_f64()
}
fn s_bv<T: Real>(b: &Point2<f64>, w: f64) -> Vector2<f64> {
    cv(&link::point_velocity(&cv::<f64, T>(&b.coords), c(w)).unwrap())
}
fn s_rrpv<T: Real>(
    f: &rrp::RrpPosition<f64>,
    axis: &Vector2<f64>,
    w: f64,
) -> rrp::RrpVelocity<f64> {
    let g = Line {
        origin: Point2::<T>::origin(),
        dir: cv(axis),
    };
    let gv = LineVelocity {
        v_origin: Vector2::zeros(),
        omega: c(w),
    };
    crv(&rrp::velocity(&crp::<f64, T>(f), &g, None, Some(&gv)).unwrap())
}
fn s_dv<T: Real>(d: &Point2<f64>, w4: f64) -> Vector2<f64> {
    let e = Point2::new(T::lit(70.0), T::zero());
    cv(&link::point_velocity(&(cp::<f64, T>(d) - e), c(w4)).unwrap())
}
fn s_rrrv<T: Real>(
    p: &rrr::RrrPosition<f64>,
    vb: &Vector2<f64>,
    vd: &Vector2<f64>,
) -> rrr::RrrVelocity<f64> {
    ccv(&rrr::velocity_lengths(
        &ccp::<f64, T>(p),
        T::lit(50.0),
        T::lit(75.0),
        Some(&cv(vb)),
        Some(&cv(vd)),
    )
    .unwrap())
}
fn s_ba<T: Real>(b: &Point2<f64>, w: f64, al: f64) -> Vector2<f64> {
    cv(&link::point_acceleration(&cv::<f64, T>(&b.coords), c(w), c(al)).unwrap())
}
fn s_rrpa<T: Real>(
    f: &rrp::RrpPosition<f64>,
    axis: &Vector2<f64>,
    fv: &rrp::RrpVelocity<f64>,
    w: f64,
    al: f64,
) -> (f64, f64, Vector2<f64>) {
    let g = Line {
        origin: Point2::<T>::origin(),
        dir: cv(axis),
    };
    let gv = LineVelocity {
        v_origin: Vector2::zeros(),
        omega: c(w),
    };
    let ga = LineAcceleration {
        a_origin: Vector2::zeros(),
        alpha: c(al),
    };
    let a = rrp::acceleration(&crp::<f64, T>(f), &g, &crv(fv), None, Some(&gv), Some(&ga)).unwrap();
    (a.alpha1.as_f64(), a.s_ddot.as_f64(), cv(&a.ac))
}
fn s_da<T: Real>(d: &Point2<f64>, w4: f64, a4: f64) -> Vector2<f64> {
    let e = Point2::new(T::lit(70.0), T::zero());
    cv(&link::point_acceleration(&(cp::<f64, T>(d) - e), c(w4), c(a4)).unwrap())
}
fn s_rrra<T: Real>(
    p: &rrr::RrrPosition<f64>,
    v: &rrr::RrrVelocity<f64>,
    ab: &Vector2<f64>,
    ad: &Vector2<f64>,
) -> (f64, f64, Vector2<f64>) {
    let a = rrr::acceleration(&ccp::<f64, T>(p), &ccv(v), Some(&cv(ab)), Some(&cv(ad))).unwrap();
    (a.alpha1.as_f64(), a.alpha2.as_f64(), cv(&a.ac))
}

/// The columns of [`chain`]'s output (the report's order).
const COLS: [&str; 24] = [
    "C.x", "C.y", "F.x", "F.y", "link2", "link3", "link4", "af", "C.x'", "C.y'", "F.x'", "F.y'",
    "link2'", "link3'", "link4'", "af'", "C.x''", "C.y''", "F.x''", "F.y''", "link2''", "link3''",
    "link4''", "af''",
];

const NS: usize = 14;
const NAMES: [&str; NS] = [
    "axis", "B", "rrp", "D", "rrr", "angles", "Bv", "rrpv", "Dv", "rrrv", "Ba", "rrpa", "Da",
    "rrra",
];

macro_rules! st {
    ($m:expr, $f:ident ( $($a:expr),* ), $round:expr) => {{
        match $m { M::D => $f::<f64>($($a),*), M::S => $f::<f32>($($a),*), M::R => { let v = $f::<f64>($($a),*); ($round)(v) } }
    }};
}

/// How the crank's axis is perturbed: as computed by the stage (`None`), or
/// the exact axis turned to the angle of the f32-rounded pair (`Turned`), or
/// scaled to its length (`Scaled`, for every consumer or for one of `B`, the
/// RRP position, the RRP rates).
#[derive(Clone, Copy, PartialEq)]
enum Ax {
    None,
    Turned,
    Scaled,
    ScaledFor(u8),
    /// Per consumer (`B`, the RRP position, the RRP rates and
    /// accelerations): which axis it sees.
    Per([Src; 3]),
    /// As `Per`, and the RRP's rates and accelerations computed in f64
    /// from its unrounded position and rates (with the exact direction):
    /// what carrying the RRP group's state with tails from its position to
    /// its accelerations would give. The other stages see the rounded
    /// outputs as before.
    Fused([Src; 3]),
}

/// The axis one consumer sees under [`Ax::Per`]: the axis stage's output
/// (`Stage`: in f32 or rounded to f32 as the stage runs), the exact `(cos,
/// sin)` of the (f32-rounded) crank angle in f64 (`Exact`: what a direction
/// carried with a tail would give), or the exact unit vector at the rounded
/// f32 pair's angle (`Turned`).
#[derive(Clone, Copy, PartialEq)]
enum Src {
    Stage,
    Exact,
    Turned,
}

fn chain(phi: f64, w: f64, al: f64, m: &[M; NS], ax: Ax) -> [f64; 24] {
    let mut axis = st!(m[0], s_axis(phi), rv);
    let a32 = rv(Vector2::new(phi.cos(), phi.sin()));
    let scaled = Vector2::new(phi.cos(), phi.sin()) * a32.norm();
    match ax {
        Ax::Turned => {
            let d = a32.y.atan2(a32.x);
            axis = Vector2::new(d.cos(), d.sin());
        }
        Ax::Scaled => axis = scaled,
        _ => {}
    }
    let exact = Vector2::new(phi.cos(), phi.sin());
    let turned = {
        let d = a32.y.atan2(a32.x);
        Vector2::new(d.cos(), d.sin())
    };
    let pick = |k: u8| match ax {
        Ax::ScaledFor(j) if j == k => scaled,
        Ax::Per(src) | Ax::Fused(src) => match src[k as usize] {
            Src::Stage => axis,
            Src::Exact => exact,
            Src::Turned => turned,
        },
        _ => axis,
    };
    let (axis_b, axis_p, axis_v) = (pick(0), pick(1), pick(2));
    let b = st!(m[1], s_b(&axis_b), rp);
    let f = st!(m[2], s_rrp(&axis_p), |p: rrp::RrpPosition<f64>| {
        rrp::RrpPosition {
            c: rp(p.c),
            r1: rv(p.r1),
            s: r(p.s),
            l: r(p.l),
        }
    });
    let d = st!(m[3], s_d(&f.r1), rp);
    let cc = st!(m[4], s_rrr(&b, &d), |p: rrr::RrrPosition<f64>| {
        rrr::RrrPosition::new(rp(p.c), rv(p.r1), rv(p.r2))
    });
    let l2 = st!(m[5], s_ang(&cc.r1), r);
    let l3 = st!(m[5], s_ang(&cc.r2), r);
    let l4 = st!(m[5], s_ang(&f.r1), r);
    let bv = st!(m[6], s_bv(&b, w), rv);
    let fv = st!(m[7], s_rrpv(&f, &axis_v, w), |p: rrp::RrpVelocity<f64>| {
        rrp::RrpVelocity {
            omega1: r(p.omega1),
            s_dot: r(p.s_dot),
            vc: rv(p.vc),
            condition: p.condition,
        }
    });
    let dv = st!(m[8], s_dv(&d, fv.omega1), rv);
    let cvv = st!(m[9], s_rrrv(&cc, &bv, &dv), |p: rrr::RrrVelocity<f64>| {
        rrr::RrrVelocity {
            omega1: r(p.omega1),
            omega2: r(p.omega2),
            vc: rv(p.vc),
            condition: p.condition,
            // Internal state of the group (like `condition`), not an output.
            inv_det: p.inv_det,
        }
    });
    let ba = st!(m[10], s_ba(&b, w, al), rv);
    let fa = if let Ax::Fused(_) = ax {
        let f = s_rrp::<f64>(&exact);
        let fv = s_rrpv::<f64>(&f, &exact, w);
        let a = s_rrpa::<f64>(&f, &exact, &fv, w, al);
        (r(a.0), r(a.1), rv(a.2))
    } else {
        st!(m[11], s_rrpa(&f, &axis_v, &fv, w, al), |(a, b, v): (
            f64,
            f64,
            Vector2<f64>
        )| (
            r(a),
            r(b),
            rv(v)
        ))
    };
    let da = st!(m[12], s_da(&d, fv.omega1, fa.0), rv);
    let ca = st!(m[13], s_rrra(&cc, &cvv, &ba, &da), |(a, b, v): (
        f64,
        f64,
        Vector2<f64>
    )| (
        r(a),
        r(b),
        rv(v)
    ));
    [
        cc.c.x, cc.c.y, f.c.x, f.c.y, l2, l3, l4, f.s, cvv.vc.x, cvv.vc.y, fv.vc.x, fv.vc.y,
        cvv.omega1, cvv.omega2, fv.omega1, fv.s_dot, ca.2.x, ca.2.y, fa.2.x, fa.2.y, ca.0, ca.1,
        fa.0, fa.1,
    ]
}
