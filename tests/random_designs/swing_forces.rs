//! Random loaded inverted slider-cranks (RPR) against `newton_euler`: the
//! kinematics of [`Swing`](super::Swing) (a crank whose tip `A` carries a
//! block sliding on a rocker pivoted at `P`, the slide line `e` to the left
//! of the pivot), loaded on all three links, as `run_quad_forces` does for
//! the four-bar.

use super::*;

mechanism! {
    /// The inverted slider-crank `Swing` loaded: masses on the crank, the
    /// block and the rocker at points in each link's frame (the block's and
    /// the rocker's axis is the slide direction, from `P` along the slide),
    /// gravity, a force at a rocker point `K`, a couple on the block and one
    /// on the rocker, and a force on the block along the slide line (kg, m,
    /// s: N and N m).
    pub SwingLoaded {
        params {
            px = 0.0, py = -0.3, a = 0.1, e = 0.02,
            m2 = 1.0, u2 = 0.05, j2 = 0.001,
            m3 = 1.0, u3 = 0.01, v3 = 0.0, j3 = 0.0001,
            m4 = 1.0, u4 = 0.1, v4 = 0.01, j4 = 0.01,
            ku = 0.2, kv = 0.0, fx = 10.0, fy = -5.0, t3 = 0.1, t4 = 1.0, fs = 3.0
        }
        let O = ground(0.0, 0.0);
        let P = ground(px, py);
        let A = crank(O, a, theta) as crank_link;
        let s = rpr(A, P, plus, e) as (block, rocker);
        let line = guide(P, rocker);
        let G2 = point(crank_link, from O, (u2, 0.0));
        let G3 = point(block, from A, (u3, v3));
        let G4 = point(rocker, from P, (u4, v4));
        let K = point(rocker, from P, (ku, kv));
        mass crank_link { m = m2, at = G2, j = j2 };
        mass block { m = m3, at = G3, j = j3 };
        mass rocker { m = m4, at = G4, j = j4 };
        gravity (0.0, -9.81);
        force at K = (fx, fy);
        force at A on block along line = fs;
        torque on block = t3;
        torque on rocker = t4;
    }
}

/// Random loaded inverted slider-cranks: the dimensions as `run_swing`'s
/// free draw; masses 1e-3 .. 1e3 kg per link, inertias `m l^2 / 100 ..
/// m l^2 / 5` (`l` the crank, a random block size `lb`, the span
/// `|A - P|` for the rocker), centres of mass and the loaded point anywhere
/// near their links; the applied force, the slide force and the couples
/// (over a length) of the size of the weights and crank-driven inertia
/// loads times 1e-2 .. 1e2.
///
/// Bound as `run_quad_forces`: `c eps (L / l_min) F / kappa^3`, `kappa` the
/// RPR's condition of `run_swing` (`min(|s| / |A - P|, |A - P| / size)`:
/// the force system is singular where the rate system is, at `s = 0` and
/// at `A = P`), `l_min` the shorter of the crank and `|A - P|`. The slide's
/// couple (about `A`) is compared over `l_min`. Measured: at most 9.2 over
/// 100 000 draws per run (release, f64; 5.3 in f32); with `kappa^2` in
/// place of `kappa^3`, 2.8 and 4.5 over 4 000 (free draws rarely come near
/// `s = 0`), with `kappa` alone 21.5.
pub(crate) fn run_swing_forces<T: Real>(samples: usize, seed: u64) -> Tally {
    let eps = T::eps().as_f64();
    let g = 9.81;
    draws(samples, seed, |rng, n, tally, sc| {
        let a = through::<T>(length(rng, sc));
        let px = coordinate::<T>(rng, sc);
        let py = coordinate::<T>(rng, sc);
        let e = through::<T>(length(rng, sc) * rng.uniform(-0.5, 0.5));
        let lb = length(rng, sc) * 0.2;
        let lr = length(rng, sc);
        let mass = |rng: &mut Rng| through::<T>(10f64.powf(rng.uniform(-3.0, 3.0)));
        let (m2, m3, m4) = (mass(rng), mass(rng), mass(rng));
        let frac = |rng: &mut Rng, l: f64, lo: f64, hi: f64| through::<T>(l * rng.uniform(lo, hi));
        let u2 = frac(rng, a, -0.5, 1.5);
        let (u3, v3) = (frac(rng, lb, -0.5, 0.5), frac(rng, lb, -0.5, 0.5));
        let (u4, v4) = (frac(rng, lr, -0.5, 1.5), frac(rng, lr, -0.25, 0.25));
        let (ku, kv) = (frac(rng, lr, -0.5, 1.5), frac(rng, lr, -0.25, 0.25));
        let inertia =
            |rng: &mut Rng, m: f64, l: f64| through::<T>(m * l * l * rng.uniform(0.01, 0.2));
        let (j2, j3, j4) = (
            inertia(rng, m2, a),
            inertia(rng, m3, lb),
            inertia(rng, m4, lr),
        );
        let (q, w, al) = drive::<T>(rng);
        let typical = (m2 + m3 + m4) * (g + a * (w * w + al.abs()));
        let load = |rng: &mut Rng| random_load::<T>(rng, typical);
        let (fx, fy, fs) = (load(rng), load(rng), load(rng));
        let (t3, t4) = (through::<T>(load(rng) * lb), through::<T>(load(rng) * lr));
        let lit = |x: f64| T::lit(x);
        let m = SwingLoaded::<T> {
            px: lit(px),
            py: lit(py),
            a: lit(a),
            e: lit(e),
            m2: lit(m2),
            u2: lit(u2),
            j2: lit(j2),
            m3: lit(m3),
            u3: lit(u3),
            v3: lit(v3),
            j3: lit(j3),
            m4: lit(m4),
            u4: lit(u4),
            v4: lit(v4),
            j4: lit(j4),
            ku: lit(ku),
            kv: lit(kv),
            fx: lit(fx),
            fy: lit(fy),
            t3: lit(t3),
            t4: lit(t4),
            fs: lit(fs),
        };
        let got = solve_at!(m, SwingLoadedInput, T, (q, w, al));
        let what = format!(
            "SwingLoaded {n}: px {px:e} py {py:e} a {a:e} e {e:e} masses {m2:e} {m3:e} {m4:e} theta {q}"
        );
        let o = vd(0.0, 0.0);
        let (pa, va, aa) = refg::crank(o, a, q, w, al);
        let pp = vd(px, py);
        let pv = refg::sub(pa, pp);
        let span = norm(pv);
        let size = [px.abs(), py.abs(), a, e.abs()]
            .into_iter()
            .fold(0.0, f64::max);
        // The generated `|A - P|` against `|e|` is rounded at the size's
        // scale (as `run_swing`).
        let near_edge = (span - e.abs()).abs() <= 8.0 * eps * size;
        let Some((u, sl)) = refg::rpr_position(pa, pp, e, true) else {
            tally.outside(&got, "s", near_edge, &what);
            return;
        };
        let kappa = (sl.to_f64().abs() / span).min(span / size);
        let l_min = a.min(span);
        let l_pos = [norm(pa), span, a, size].into_iter().fold(0.0, f64::max);
        let spread = l_pos / l_min;
        let sol = match got {
            Ok(sol) => sol,
            Err(err) => {
                assert_eq!(err.group, "s", "{what}: {err}");
                assert!(
                    near_edge || eps * spread / kappa.powi(3) > NO_DIGITS,
                    "{what}: the reference assembles (condition {kappa:e}) but: {err}"
                );
                tally.edge_errors += 1;
                return;
            }
        };
        tally.compared += 1;
        // Rates and accelerations as `run_swing`: s_dot u + omega perp(A - P)
        // = vA; s_ddot u + alpha perp(A - P) = aA - s_dot omega perp(u) -
        // omega perp(vA).
        let (om, sd) = refg::rpr_rates(pa, pp, u, va, o).expect("rates");
        let rhs = refg::sub(
            aa,
            refg::add(
                refg::scale(sd * om, refg::perp(u)),
                refg::scale(om, refg::perp(va)),
            ),
        );
        let (alpha, _) = refg::solve2(refg::perp(pv), u, rhs).expect("accelerations");
        let zero = vd(0.0, 0.0);
        let unit = |x: V| refg::scale(Dd::ONE / refg::norm(x), x);
        let e2 = unit(refg::sub(pa, o));
        let g2 = on_link((o, zero, zero), e2, (u2, 0.0), Dd::from(w), Dd::from(al));
        // The block turns with the rocker: both frames along `u`.
        let g3 = on_link((pa, va, aa), u, (u3, v3), om, alpha);
        let b1 = on_link((pa, va, aa), u, (span, 0.0), om, alpha);
        let g4 = on_link((pp, zero, zero), u, (u4, v4), om, alpha);
        let pk = on_link((pp, zero, zero), u, (ku, kv), om, alpha);
        let r1 = on_link((pp, zero, zero), u, (span, 0.0), om, alpha);
        // Points: 0 O, 1 P, 2 A, 3 G2, 4 G3, 5 B1 (block), 6 G4, 7 K,
        // 8 R1 (rocker).
        let ps: Vec<CV2> = [o, pp, pa, g2.0, g3.0, b1.0, g4.0, pk.0, r1.0]
            .map(cv)
            .to_vec();
        let vs: Vec<CV2> = [zero, zero, va, g2.1, g3.1, b1.1, g4.1, pk.1, r1.1]
            .map(cv)
            .to_vec();
        let accs: Vec<CV2> = [zero, zero, aa, g2.2, g3.2, b1.2, g4.2, pk.2, r1.2]
            .map(cv)
            .to_vec();
        let system = System {
            bodies: vec![
                Body::new(m2, 3, j2, Some((0, 2))),
                Body::new(m3, 4, j3, Some((2, 5))),
                Body::new(m4, 6, j4, Some((1, 8))),
            ],
            joints: vec![
                Joint::revolute(Link::Ground, Link::Body(0), 0),
                Joint::revolute(Link::Body(0), Link::Body(1), 2),
                Joint::revolute(Link::Ground, Link::Body(2), 1),
                // The slide along the rocker's axis (the segment P -> R1 of
                // the rocker), its couple about the block's pin.
                Joint::prismatic(Link::Body(1), Link::Body(2), Direction::Segment(1, 8), 2),
            ],
            drivers: vec![Driver::Torque { body: 0 }],
            loads: vec![
                Load::Force {
                    body: 2,
                    at: 7,
                    force: CV2::new(fx, fy),
                },
                Load::Force {
                    body: 1,
                    at: 2,
                    force: cv(refg::scale(Dd::from(fs), u)),
                },
                Load::Couple {
                    body: 1,
                    couple: Dd::from(t3),
                },
                Load::Couple {
                    body: 2,
                    couple: Dd::from(t4),
                },
            ],
            gravity: CV2::new(0.0, -g),
        };
        let reference = reference_forces(&system, (&ps, &vs, &accs));
        let f = &sol.forces;
        let pins = [
            f.r_ground_crank_link,
            f.r_crank_link_block,
            f.r_ground_rocker,
        ];
        // Each body's inertia scale as in `run_quad_forces`: the largest
        // acceleration of the mechanism.
        let a_max = [
            norm(aa),
            norm(g2.2),
            norm(g3.2),
            norm(b1.2),
            norm(g4.2),
            norm(pk.2),
            norm(r1.2),
        ]
        .into_iter()
        .fold(0.0, f64::max);
        let alpha_max = al.abs().max(alpha.to_f64().abs());
        let loads = [
            m2 * (a_max + g),
            m3 * (a_max + g),
            m4 * (a_max + g),
            j2 * alpha_max / a,
            j3 * alpha_max / lb,
            j4 * alpha_max / lr,
            fx.hypot(fy),
            fs.abs(),
            t3.abs() / l_min,
            t4.abs() / l_min,
            reference.drives[0].to_f64().abs() / l_min,
        ];
        let drive = (f.drive_theta.as_f64() - reference.drives[0].to_f64()).abs() / a;
        let extra = prismatic_errors(&f.r_block_rocker, &reference.reactions[3], l_min, &what);
        let verdict = ForceVerdict {
            eps,
            spread,
            condition: kappa,
        };
        verdict.record(tally, (&reference, &pins), drive, &loads, &extra, &what);
    })
}

#[test]
fn random_loaded_swinging_blocks_f64() {
    forces_report(
        "SwingLoaded f64",
        &run_swing_forces::<f64>(FORCE_SAMPLES, 101),
    );
}

#[test]
fn random_loaded_swinging_blocks_f32() {
    forces_report(
        "SwingLoaded f32",
        &run_swing_forces::<f32>(FORCE_SAMPLES, 102),
    );
}
