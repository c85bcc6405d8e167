//! Random loaded PRP groups: the crossing guides of [`Cross`] (a block on a
//! line through the crank's pivot turning with the crank, a block on a fixed
//! guide, pinned together at `C`) with masses on the crank and on both
//! blocks, gravity, forces at a point of the turning block and at the pin on
//! the fixed guide's block, a couple on each block and a force along each
//! guide (the turning one's direction is the crank's), against the Newton-Euler reference of `mechanism-reference`
//! (see [`run_quad_forces`] for the draws and the bound).

use super::*;

mechanism! {
    /// [`Cross`] loaded (kg, m, s: N and N m): the crank of length `a` with
    /// its centre of mass `G2` in its frame; block 1 (on the turning line,
    /// so it turns with the crank) with its centre `G3` and the loaded point
    /// `P` in its frame from `C` (its axis is the turning line's direction);
    /// block 2 (on the fixed guide; it translates) with its centre `G4`,
    /// which also takes a force `fs` along the fixed guide; block 1 takes
    /// `fr` at `G3` along the turning line. Block 2's `j4` never acts (it
    /// does not turn).
    pub CrossLoaded {
        params {
            gx = 0.3, gy = 0.0, gangle = 1.5, tilt = 0.5, o1 = 0.0, o2 = 0.0, a = 0.1,
            m2 = 1.0, u2 = 0.05, v2 = 0.01, j2 = 0.001,
            m3 = 1.0, u3 = 0.02, v3 = 0.01, j3 = 0.001,
            m4 = 1.0, u4 = -0.01, v4 = 0.03, j4 = 0.002,
            pu = 0.03, pv = -0.01, fx = 10.0, fy = -5.0, hx = 2.0, hy = 1.0,
            t3 = 0.3, t4 = 0.7, fs = 20.0, fr = -8.0
        }
        let O = ground(0.0, 0.0);
        let G = ground(gx, gy);
        let fixed_line = guide(G, gangle);
        let A = crank(O, a, theta) as crank_link;
        let rod_line = guide(O, crank_link, tilt);
        let C = prp(rod_line, fixed_line, o1, o2) as (block1, block2) slide (s1, s2);
        let G2 = point(crank_link, from O, (u2, v2));
        let G3 = point(block1, from C, (u3, v3));
        let G4 = point(block2, from C, (u4, v4));
        let P = point(block1, from C, (pu, pv));
        mass crank_link { m = m2, at = G2, j = j2 };
        mass block1 { m = m3, at = G3, j = j3 };
        mass block2 { m = m4, at = G4, j = j4 };
        gravity (0.0, -9.81);
        force at P = (fx, fy);
        force at C on block2 = (hx, hy);
        torque on block1 = t3;
        torque on block2 = t4;
        force at G4 on block2 along fixed_line = fs;
        force at G3 on block1 along rod_line = fr;
    }
}

/// Random loaded crossing guides against `newton_euler`, as
/// [`run_quad_forces`]: the two pins' reactions, both guides' prismatic
/// reactions (the normal force, and the couple about `C` over the crank's
/// length `a`) and the drive torque over `a`, within
/// `c eps (L / a) F / s^3`: `s` the PRP's condition (`|sin|` of the angle
/// between the guides), `L` the largest coordinate or offset (the joint's
/// distance from the pivot, `|C| ~ size / s`, is the moment arm of every
/// load on the blocks about the crank's pivot, so a couple's error over `a`
/// is `eps |C| / a` of the forces), `F` the largest load counted as in
/// [`run_quad_forces`].
fn run_cross_forces<T: Real>(samples: usize, seed: u64) -> Tally {
    let eps = T::eps().as_f64();
    let g = 9.81;
    draws(samples, seed, |rng, n, tally, sc| {
        let gx = coordinate::<T>(rng, sc);
        let gy = coordinate::<T>(rng, sc);
        let gangle = through::<T>(rng.uniform(-3.2, 3.2));
        let tilt = through::<T>(rng.uniform(-3.2, 3.2));
        let o1 = through::<T>(length(rng, sc) * rng.uniform(-0.5, 0.5));
        let o2 = through::<T>(length(rng, sc) * rng.uniform(-0.5, 0.5));
        let a = through::<T>(length(rng, sc));
        // Each block's size, for its centre, loaded point and inertia.
        let (b3, b4) = (length(rng, sc), length(rng, sc));
        let mass = |rng: &mut Rng| through::<T>(10f64.powf(rng.uniform(-3.0, 3.0)));
        let off = |rng: &mut Rng, l: f64| through::<T>(l * rng.uniform(-1.0, 1.0));
        let (m2, m3, m4) = (mass(rng), mass(rng), mass(rng));
        let (u2, v2) = (through::<T>(a * rng.uniform(-0.5, 1.5)), off(rng, a * 0.5));
        let (u3, v3, u4, v4) = (off(rng, b3), off(rng, b3), off(rng, b4), off(rng, b4));
        let (pu, pv) = (off(rng, b3), off(rng, b3));
        let inertia =
            |rng: &mut Rng, m: f64, l: f64| through::<T>(m * l * l * rng.uniform(0.01, 0.2));
        let (j2, j3, j4) = (
            inertia(rng, m2, a),
            inertia(rng, m3, b3),
            inertia(rng, m4, b4),
        );
        let (q, w, al) = drive::<T>(rng);
        // The applied loads' size: the weights and an inertia load of the
        // crank's scale, times 1e-2 .. 1e2.
        let typical = (m2 + m3 + m4) * (g + sc * (w * w + al.abs()));
        let load = |rng: &mut Rng| random_load::<T>(rng, typical);
        let (fx, fy, hx, hy, fs) = (load(rng), load(rng), load(rng), load(rng), load(rng));
        let (t3, t4) = (load(rng) * b3, load(rng) * b4);
        let fr = load(rng);
        let lit = |x: f64| T::lit(x);
        let m = CrossLoaded::<T> {
            gx: lit(gx),
            gy: lit(gy),
            gangle: lit(gangle),
            tilt: lit(tilt),
            o1: lit(o1),
            o2: lit(o2),
            a: lit(a),
            m2: lit(m2),
            u2: lit(u2),
            v2: lit(v2),
            j2: lit(j2),
            m3: lit(m3),
            u3: lit(u3),
            v3: lit(v3),
            j3: lit(j3),
            m4: lit(m4),
            u4: lit(u4),
            v4: lit(v4),
            j4: lit(j4),
            pu: lit(pu),
            pv: lit(pv),
            fx: lit(fx),
            fy: lit(fy),
            hx: lit(hx),
            hy: lit(hy),
            t3: lit(t3),
            t4: lit(t4),
            fs: lit(fs),
            fr: lit(fr),
        };
        let got = solve_at!(m, CrossLoadedInput, T, (q, w, al));
        let what = format!(
            "CrossLoaded {n}: guide ({gx:e}, {gy:e}) at {gangle}, tilt {tilt}, offsets {o1:e} {o2:e}, a {a:e}, masses {m2:e} {m3:e} {m4:e}, theta {q}"
        );
        // The kinematics as `run_cross` has them: the lines exactly at the
        // rounded angles.
        let (s1t, c1t) = (Dd::from(q) + Dd::from(tilt)).sin_cos();
        let (s2t, c2t) = Dd::from(gangle).sin_cos();
        let (u1, ug) = ([c1t, s1t], [c2t, s2t]);
        let o = vd(0.0, 0.0);
        let g1 = refg::Line { origin: o, dir: u1 };
        let g2 = refg::Line {
            origin: vd(gx, gy),
            dir: ug,
        };
        let kappa = refg::cross(u1, ug).to_f64().abs();
        let Some((pc, _, _)) = refg::prp_position(&g1, o1, &g2, o2) else {
            tally.outside += 1;
            assert!(
                got.is_err(),
                "{what}: Ok where the reference does not assemble"
            );
            return;
        };
        let (wd, ald) = (Dd::from(w), Dd::from(al));
        let Some((sd1, sd2)) = refg::solve2(
            u1,
            refg::scale(-Dd::ONE, ug),
            refg::scale(-wd, refg::perp(pc)),
        ) else {
            tally.outside += 1;
            assert!(got.is_err(), "{what}: Ok where the rates are singular");
            return;
        };
        let vc = refg::scale(sd2, ug);
        let rhs = refg::sub(
            refg::scale(-(sd1 * wd), refg::perp(u1)),
            refg::add(
                refg::scale(ald, refg::perp(pc)),
                refg::scale(wd, refg::perp(vc)),
            ),
        );
        let (_, sdd2) = refg::solve2(u1, refg::scale(-Dd::ONE, ug), rhs).expect("accelerations");
        let ac = refg::scale(sdd2, ug);
        let size = [gx.abs(), gy.abs(), o1.abs(), o2.abs(), a, b3, b4]
            .into_iter()
            .fold(0.0, f64::max);
        let l_pos = norm(pc).max(size);
        let spread = l_pos / a;
        let Ok(sol) = got else {
            tally.edge_errors += 1;
            assert!(
                eps * spread / kappa.powi(3) > NO_DIGITS,
                "{what}: the reference assembles (condition {kappa:e}) but the solve failed"
            );
            return;
        };
        tally.compared += 1;
        // Points on the bodies: the crank turns about O, block 1 with the
        // crank about C's motion, block 2 translates with C.
        let zero = vd(0.0, 0.0);
        let (sq, cq) = Dd::from(q).sin_cos();
        let e2 = [cq, sq];
        let crank_pt = |xy: (f64, f64)| on_link((o, zero, zero), e2, xy, wd, ald);
        let block1_pt = |xy: (f64, f64)| on_link((pc, vc, ac), u1, xy, wd, ald);
        let block2_pt = |xy: (f64, f64)| on_link((pc, vc, ac), ug, xy, Dd::ZERO, Dd::ZERO);
        let pa = crank_pt((a, 0.0));
        let gc = crank_pt((u2, v2));
        // A second point of the turning line (its direction for the
        // reference's guide carried by the crank).
        let pu1 = on_link((o, zero, zero), u1, (a, 0.0), wd, ald);
        let g3 = block1_pt((u3, v3));
        let pp = block1_pt((pu, pv));
        // A second point of block 1 (its turn).
        let k1 = block1_pt((b3, 0.0));
        let g4 = block2_pt((u4, v4));
        // Points: 0 O, 1 A, 2 C, 3 G2, 4 G3, 5 G4, 6 P, 7 U (on the turning
        // line), 8 K (on block 1).
        let pts = [(o, zero, zero), pa, (pc, vc, ac), gc, g3, g4, pp, pu1, k1];
        let ps: Vec<CV2> = pts.iter().map(|x| cv(x.0)).collect();
        let vs: Vec<CV2> = pts.iter().map(|x| cv(x.1)).collect();
        let accs: Vec<CV2> = pts.iter().map(|x| cv(x.2)).collect();
        let along = |u: V, f: f64| CV2 {
            x: u[0] * Dd::from(f),
            y: u[1] * Dd::from(f),
        };
        let system = System {
            bodies: vec![
                Body::new(m2, 3, j2, Some((0, 1))),
                Body::new(m3, 4, j3, Some((2, 8))),
                // Block 2 translates: its inertia never acts.
                Body::new(m4, 5, 0.0, None),
            ],
            // The pins first (`ForceVerdict::record` takes them in order).
            joints: vec![
                Joint::revolute(Link::Ground, Link::Body(0), 0),
                Joint::revolute(Link::Body(1), Link::Body(2), 2),
                Joint::prismatic(Link::Body(0), Link::Body(1), Direction::Segment(0, 7), 2),
                Joint::prismatic(Link::Ground, Link::Body(2), Direction::Fixed(cv(ug)), 2),
            ],
            drivers: vec![Driver::Torque { body: 0 }],
            loads: vec![
                Load::Force {
                    body: 1,
                    at: 6,
                    force: CV2::new(fx, fy),
                },
                Load::Force {
                    body: 2,
                    at: 2,
                    force: CV2::new(hx, hy),
                },
                Load::Couple {
                    body: 1,
                    couple: Dd::from(t3),
                },
                Load::Couple {
                    body: 2,
                    couple: Dd::from(t4),
                },
                Load::Force {
                    body: 2,
                    at: 5,
                    force: along(ug, fs),
                },
                Load::Force {
                    body: 1,
                    at: 4,
                    force: along(u1, fr),
                },
            ],
            gravity: CV2::new(0.0, -g),
        };
        let reference = reference_forces(&system, (&ps, &vs, &accs));
        let f = &sol.forces;
        let pins = [f.r_ground_crank_link, f.r_block1_block2];
        let prismatic = |got, r| prismatic_errors(got, r, a, &what);
        let [n1, m1] = prismatic(&f.r_crank_link_block1, &reference.reactions[2]);
        let [n2, m2r] = prismatic(&f.r_ground_block2, &reference.reactions[3]);
        // The largest acceleration in the mechanism (see `run_quad_forces`):
        // every point's, and the turning line's (w^2 + |al|) at the largest
        // coordinate and its Coriolis term 2 s1' w.
        let a_max = [
            norm(ac),
            norm(pa.2),
            norm(gc.2),
            norm(g3.2),
            norm(g4.2),
            norm(pp.2),
            (w * w + al.abs()) * l_pos,
            2.0 * (sd1 * wd).to_f64().abs(),
        ]
        .into_iter()
        .fold(0.0, f64::max);
        let alpha_max = al.abs();
        let loads = [
            m2 * (a_max + g),
            m3 * (a_max + g),
            m4 * (a_max + g),
            j2 * alpha_max / a,
            j3 * alpha_max / a,
            fx.hypot(fy),
            hx.hypot(hy),
            fs.abs(),
            fr.abs(),
            t3.abs() / a,
            t4.abs() / a,
            reference.drives[0].to_f64().abs() / a,
        ];
        let drive = (f.drive_theta.as_f64() - reference.drives[0].to_f64()).abs() / a;
        let verdict = ForceVerdict {
            eps,
            spread,
            condition: kappa,
        };
        verdict.record(
            tally,
            (&reference, &pins),
            drive,
            &loads,
            &[n1, m1, n2, m2r],
            &what,
        );
    })
}

#[test]
fn random_loaded_crossing_guides_f64() {
    forces_report(
        "CrossLoaded f64",
        &run_cross_forces::<f64>(FORCE_SAMPLES, 51),
    );
}

#[test]
fn random_loaded_crossing_guides_f32() {
    forces_report(
        "CrossLoaded f32",
        &run_cross_forces::<f32>(FORCE_SAMPLES, 52),
    );
}
