//! Random loaded booms: the actuator driver of [`Boom`] (a boom about a
//! ground pivot lifted by a cylinder whose length is the input) with a mass
//! on the boom, gravity, a payload force at the boom's tip, a force at the
//! cylinder's joint and a couple on the boom, against the Newton-Euler
//! reference of `mechanism-reference` (see [`run_quad_forces`] for the draws
//! and the bound). The driving effort is the cylinder's axial force.
//!
//! The cylinder itself carries no mass: the generated force analysis takes
//! it as a massless two-force member, and a `mass` or load on it is a
//! compile error (`docs/dsl.md`, "Force analysis"). The reference models it
//! the same way, as the frame's driving force on the boom at `C` along
//! `B -> C`.

use super::*;

mechanism! {
    /// [`Boom`] loaded (kg, m, s: N and N m): the boom's centre of mass `G`
    /// and its tip `Tip` in its frame from `A` (axis `A -> C`), a payload
    /// force at `Tip`, a force on the boom at the cylinder's joint `C` and a
    /// couple on the boom.
    pub BoomLoaded {
        params {
            r = 1.0, bx = 0.8, by = -0.3,
            m1 = 100.0, gu = 0.6, gv = 0.05, j1 = 10.0,
            tu = 1.5, tv = 0.1, fx = 100.0, fy = -2000.0, cx = 10.0, cy = 5.0,
            t1 = 50.0
        }
        let A = ground(0.0, 0.0);
        let B = ground(bx, by);
        let C = actuator(A, r, B, len, left) as (boom, cylinder);
        let G = point(boom, from A, (gu, gv));
        let Tip = point(boom, from A, (tu, tv));
        mass boom { m = m1, at = G, j = j1 };
        gravity (0.0, -9.81);
        force at Tip = (fx, fy);
        force at C on boom = (cx, cy);
        torque on boom = t1;
    }
}

/// Random loaded booms against `newton_euler`, as [`run_quad_forces`]: the
/// pivot's reaction and the cylinder's force, within
/// `c eps (L / l) F / s^3`: `s` the sine of the angle between the boom and
/// the cylinder at `C`, `L / l` the largest coordinate over the shorter of
/// the boom's radius and the cylinder's length, `F` the largest load counted
/// as in [`run_quad_forces`] (the cylinder's force itself among them: it is
/// a force, compared as one).
fn run_boom_forces<T: Real>(samples: usize, seed: u64) -> Tally {
    let eps = T::eps().as_f64();
    let g = 9.81;
    draws(samples, seed, |rng, n, tally, sc| {
        let r = through::<T>(length(rng, sc));
        let bx = coordinate::<T>(rng, sc);
        let by = coordinate::<T>(rng, sc);
        let span = bx.hypot(by);
        // Mostly where the boom assembles: from 5 % below folding to 5 %
        // beyond full extension.
        let (lo, hi) = ((r - span).abs(), r + span);
        let len = through::<T>(lo + (hi - lo) * rng.uniform(-0.05, 1.05));
        // The cylinder's rate and acceleration as in `run_boom`.
        let len_dot = through::<T>(len * rng.uniform(-100.0, 100.0));
        let len_ddot = through::<T>(len * rng.uniform(-1e4, 1e4));
        let m1 = through::<T>(10f64.powf(rng.uniform(-3.0, 3.0)));
        let frac = |rng: &mut Rng, lo: f64, hi: f64| through::<T>(r * rng.uniform(lo, hi));
        let (gu, gv) = (frac(rng, -0.5, 1.5), frac(rng, -0.25, 0.25));
        let (tu, tv) = (frac(rng, -0.5, 3.0), frac(rng, -0.5, 0.5));
        let j1 = through::<T>(m1 * r * r * rng.uniform(0.01, 0.2));
        // The applied loads' size: the weight and an inertia load of the
        // cylinder's scale, times 1e-2 .. 1e2.
        let typical = m1 * (g + len_ddot.abs() + len_dot * len_dot / r.min(len.max(lo)));
        let load = |rng: &mut Rng| random_load::<T>(rng, typical);
        let (fx, fy, cx, cy) = (load(rng), load(rng), load(rng), load(rng));
        let t1 = load(rng) * r;
        let lit = |x: f64| T::lit(x);
        let m = BoomLoaded::<T> {
            r: lit(r),
            bx: lit(bx),
            by: lit(by),
            m1: lit(m1),
            gu: lit(gu),
            gv: lit(gv),
            j1: lit(j1),
            tu: lit(tu),
            tv: lit(tv),
            fx: lit(fx),
            fy: lit(fy),
            cx: lit(cx),
            cy: lit(cy),
            t1: lit(t1),
        };
        let got = m.solve(
            &BoomLoadedInput { len: lit(len) },
            &BoomLoadedInput { len: lit(len_dot) },
            &BoomLoadedInput { len: lit(len_ddot) },
        );
        let what = format!(
            "BoomLoaded {n}: r {r:e} B ({bx:e}, {by:e}) len {len:e} rate {len_dot:e} accel {len_ddot:e} mass {m1:e}"
        );
        let (pa, pb) = (vd(0.0, 0.0), vd(bx, by));
        // (A cylinder of no or negative length, drawn where the boom nearly
        // folds onto B, does not assemble either.)
        let assembled = Some(len).filter(|&l| l > 0.0);
        let Some(pc) = assembled.and_then(|l| refg::rrr_position(pa, r, pb, l, true)) else {
            tally.outside += 1;
            assert!(
                got.is_err(),
                "{what}: Ok where the reference does not assemble"
            );
            return;
        };
        let (r1, r2) = (refg::sub(pc, pa), refg::sub(pc, pb));
        let s = (refg::cross(r1, r2).to_f64() / (r * len)).abs();
        let size = [r, bx.abs(), by.abs(), len].into_iter().fold(0.0, f64::max);
        let l_pos = norm(pc).max(size);
        let spread = l_pos / r.min(len);
        let Ok(sol) = got else {
            tally.edge_errors += 1;
            assert!(
                eps * spread / s.powi(3) > NO_DIGITS,
                "{what}: the reference assembles (sine {s:e}) but the solve failed"
            );
            return;
        };
        tally.compared += 1;
        // The rates as `run_boom` has them: |C - A| = r and |C - B| = len
        // differentiated once and twice.
        let (c0, c1) = ([r1[0], r2[0]], [r1[1], r2[1]]);
        let (ld, ldd, l) = (Dd::from(len_dot), Dd::from(len_ddot), Dd::from(len));
        let (vx, vy) = refg::solve2(c0, c1, [Dd::ZERO, l * ld]).expect("rates");
        let vc = [vx, vy];
        let v2 = refg::dot(vc, vc);
        let (ax, ay) = refg::solve2(c0, c1, [-v2, ld.sqr() + l * ldd - v2]).expect("accelerations");
        let ac = [ax, ay];
        // The boom turns about A: vC = omega perp(r1), aC = alpha perp(r1) -
        // omega^2 r1, so omega and alpha are the cross products over r^2.
        let rr = refg::dot(r1, r1);
        let (omega, alpha) = (refg::cross(r1, vc) / rr, refg::cross(r1, ac) / rr);
        let e1 = refg::scale(Dd::ONE / rr.sqrt(), r1);
        let zero = vd(0.0, 0.0);
        let boom_pt = |xy: (f64, f64)| on_link((pa, zero, zero), e1, xy, omega, alpha);
        let (gg, tt) = (boom_pt((gu, gv)), boom_pt((tu, tv)));
        // Points: 0 A, 1 B, 2 C, 3 G, 4 Tip.
        let pts = [(pa, zero, zero), (pb, zero, zero), (pc, vc, ac), gg, tt];
        let ps: Vec<CV2> = pts.iter().map(|x| cv(x.0)).collect();
        let vs: Vec<CV2> = pts.iter().map(|x| cv(x.1)).collect();
        let accs: Vec<CV2> = pts.iter().map(|x| cv(x.2)).collect();
        let system = System {
            bodies: vec![Body::new(m1, 3, j1, Some((0, 2)))],
            joints: vec![Joint::revolute(Link::Ground, Link::Body(0), 0)],
            // The cylinder pushes the boom at C along B -> C.
            drivers: vec![Driver::Force {
                body: 0,
                at: 2,
                dir: Direction::Segment(1, 2),
            }],
            loads: vec![
                Load::Force {
                    body: 0,
                    at: 4,
                    force: CV2::new(fx, fy),
                },
                Load::Force {
                    body: 0,
                    at: 2,
                    force: CV2::new(cx, cy),
                },
                Load::Couple {
                    body: 0,
                    couple: Dd::from(t1),
                },
            ],
            gravity: CV2::new(0.0, -g),
        };
        let reference = reference_forces(&system, (&ps, &vs, &accs));
        let f = &sol.forces;
        let pins = [f.r_ground_boom];
        // The largest acceleration in the mechanism (see `run_quad_forces`).
        let a_max = [
            norm(ac),
            norm(gg.2),
            norm(tt.2),
            len_ddot.abs(),
            v2.to_f64() / r.min(len),
        ]
        .into_iter()
        .fold(0.0, f64::max);
        let alpha_max = alpha.to_f64().abs();
        let drive_ref = reference.drives[0].to_f64();
        let loads = [
            m1 * (a_max + g),
            j1 * alpha_max / r,
            fx.hypot(fy),
            cx.hypot(cy),
            t1.abs() / r,
            drive_ref.abs(),
        ];
        let drive = (f.drive_len.as_f64() - drive_ref).abs();
        let verdict = ForceVerdict {
            eps,
            spread,
            condition: s,
        };
        verdict.record(tally, (&reference, &pins), drive, &loads, &[], &what);
    })
}

#[test]
fn random_loaded_booms_f64() {
    forces_report("BoomLoaded f64", &run_boom_forces::<f64>(FORCE_SAMPLES, 53));
}

#[test]
fn random_loaded_booms_f32() {
    forces_report("BoomLoaded f32", &run_boom_forces::<f32>(FORCE_SAMPLES, 54));
}
