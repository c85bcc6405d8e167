//! An excavator-type boom lifted by a hydraulic cylinder with mass
//! (`actuator(..) as (boom, barrel, rod)`), against Newton-Euler written out
//! here: the 9 x 9 system of the boom, the rod and the barrel (unknowns: the
//! ground's force on the boom at `A`, the boom's force on the rod at `C`,
//! the ground's force on the barrel at `B`, the barrel's normal force and
//! couple on the rod, the axial force), solved by nalgebra's LU, with the
//! loads recomputed from the generated motion of the centres. The centres'
//! accelerations on the barrel and the rod are first checked against their
//! closed forms from the cylinder's axis (`G1 = B + 0.6 u`, `G2 = C - 0.5 u`).
//!
//! Tolerance. Both sides solve the same equations from the same motion by
//! different eliminations; each is within a few eps of the exact solution
//! times the conditioning of its system (the poses keep `condition` above
//! 0.05, so at most 20 x a few eps, 9e-15). `CLOSE` = 5e-15 of the pose's
//! largest force; the largest difference measured, printed by the test, is
//! 6.6e-16.

use crate::equilibrium::{cross, inertial, power_balances, G, TOL};
use mechanism::{mechanism, Point2, Vector2};
use nalgebra::{SMatrix, SVector};

/// Reactions and axial force agree to this, relative to the largest force
/// at the pose (see the module documentation).
const CLOSE: f64 = 5e-15;

mechanism! {
    /// Boom (m, kg, N) pivoted at A, lifted by a cylinder from the ground
    /// point B to the boom's pin C: a 1.8 t boom and a 0.6 t payload at its
    /// tip (two masses on one link), a 220 kg barrel and a 140 kg rod.
    pub Excavator {
        dof 1;
        let A = ground(0.0, 0.0);
        let B = ground(0.8, -0.9);
        let C = actuator(A, 2.2, B, len, left) as (boom, barrel, rod);
        let Gb = point(boom, from A, 2.5, 8 deg);
        let Tip = point(boom, from A, 5.0, 0 deg);
        let G1 = point(barrel, from B, 0.6, 0 deg);
        let G2 = point(rod, from C, 0.5, 180 deg);
        mass boom { m = 1800.0, at = Gb, j = 4500.0 };
        mass boom { m = 600.0, at = Tip };
        mass barrel { m = 220.0, at = G1, j = 30.0 };
        mass rod { m = 140.0, at = G2, j = 18.0 };
        gravity (0.0, -9.81);
        range len = (1.9, 3.0);
    }
}

/// Known load of a body: the weight and inertia force `m (g - a_g)` at `g`,
/// as (force, moment about `about`), with the inertia couple `-j alpha`.
fn load(
    m: f64,
    j: f64,
    g: Point2<f64>,
    a_g: Vector2<f64>,
    alpha: f64,
    about: Point2<f64>,
) -> (Vector2<f64>, f64) {
    let f = (G - a_g) * m;
    (f, cross(&(g - about), &f) - j * alpha)
}

/// The nine unknowns from Newton-Euler for the three bodies, in the order
/// `[R_A (2), R_C (2), R_B (2), N, M_p, F]`.
fn newton_euler(s: &ExcavatorSolution) -> SVector<f64, 9> {
    let (p, a) = (&s.position, &s.acceleration);
    let u = (p.C - p.B).normalize();
    let n = Vector2::new(-u.y, u.x);
    let (boom1, boom1_m) = load(1800.0, 4500.0, p.Gb, a.Gb, a.boom, p.A);
    let (boom2, boom2_m) = load(600.0, 0.0, p.Tip, a.Tip, a.boom, p.A);
    let (f_arm, m_arm) = (boom1 + boom2, boom1_m + boom2_m);
    let (f_b, m_b) = load(220.0, 30.0, p.G1, a.G1, a.barrel, p.B);
    let (f_r, m_r) = load(140.0, 18.0, p.G2, a.G2, a.barrel, p.C);
    let (ac, bc) = (p.C - p.A, p.C - p.B);
    let mut k = SMatrix::<f64, 9, 9>::zeros();
    let mut rhs = SVector::<f64, 9>::zeros();
    // Boom: R_A - R_C + f_arm = 0; about A: (C - A) x (-R_C) + m_arm = 0.
    k[(0, 0)] = 1.0;
    k[(0, 2)] = -1.0;
    k[(1, 1)] = 1.0;
    k[(1, 3)] = -1.0;
    k[(2, 2)] = ac.y;
    k[(2, 3)] = -ac.x;
    rhs[0] = -f_arm.x;
    rhs[1] = -f_arm.y;
    rhs[2] = -m_arm;
    // Rod: R_C + F u + N n + f_r = 0; about C: M_p + m_r = 0.
    k[(3, 2)] = 1.0;
    k[(3, 6)] = n.x;
    k[(3, 8)] = u.x;
    k[(4, 3)] = 1.0;
    k[(4, 6)] = n.y;
    k[(4, 8)] = u.y;
    k[(5, 7)] = 1.0;
    rhs[3] = -f_r.x;
    rhs[4] = -f_r.y;
    rhs[5] = -m_r;
    // Barrel: R_B - F u - N n + f_b = 0; about B: (C - B) x (-N n) - M_p + m_b = 0.
    k[(6, 4)] = 1.0;
    k[(6, 6)] = -n.x;
    k[(6, 8)] = -u.x;
    k[(7, 5)] = 1.0;
    k[(7, 6)] = -n.y;
    k[(7, 8)] = -u.y;
    k[(8, 6)] = -cross(&bc, &n);
    k[(8, 7)] = -1.0;
    rhs[6] = -f_b.x;
    rhs[7] = -f_b.y;
    rhs[8] = -m_b;
    k.lu().solve(&rhs).expect("the 9 x 9 system is regular")
}

/// The generated forces in the order of [`newton_euler`].
fn generated(f: &ExcavatorForces) -> SVector<f64, 9> {
    SVector::<f64, 9>::from_column_slice(&[
        f.r_ground_boom.x,
        f.r_ground_boom.y,
        f.r_boom_rod.x,
        f.r_boom_rod.y,
        f.r_ground_barrel.x,
        f.r_ground_barrel.y,
        f.r_barrel_rod.normal,
        f.r_barrel_rod.moment,
        f.drive_len,
    ])
}

/// Solves at input length `len` (m) with rate `v` (m/s), acceleration `acc`.
fn solve(len: f64, v: f64, acc: f64) -> ExcavatorSolution {
    Excavator::<f64>::default()
        .solve(
            &ExcavatorInput { len },
            &ExcavatorInput { len: v },
            &ExcavatorInput { len: acc },
        )
        .unwrap()
}

// Proves the barrel's and the rod's centres move with the cylinder's axis:
// `G1 = B + 0.6 u`, `G2 = C - 0.5 u`, their accelerations from the axis'
// rates (`u'' = alpha perp(u) - omega^2 u`), to rounding.
#[test]
fn barrel_and_rod_points_follow_the_cylinder_axis() {
    for k in 0..12 {
        let s = solve(1.95 + 0.09 * k as f64, 0.3, -0.4);
        let (p, v, a) = (&s.position, &s.velocity, &s.acceleration);
        let u = (p.C - p.B).normalize();
        let n = Vector2::new(-u.y, u.x);
        let (w, al) = (v.barrel, a.barrel);
        let u2 = n * al - u * (w * w);
        let close = |x: Vector2<f64>, y: Vector2<f64>| (x - y).norm() <= 1e-14 * y.norm().max(1.0);
        assert!(close(p.G1.coords, p.B.coords + u * 0.6));
        assert!(close(p.G2.coords, p.C.coords - u * 0.5));
        assert!(close(a.G1, u2 * 0.6), "{:?} {:?}", a.G1, u2 * 0.6);
        assert!(close(a.G2, a.C - u2 * 0.5), "{:?}", a.G2);
        assert_eq!((v.rod, a.rod), (v.barrel, a.barrel));
    }
}

// Proves the reactions at A, C and B, the barrel-rod pair's normal force and
// couple and the axial force equal the hand Newton-Euler solution of boom,
// rod and barrel, statically and in motion over the cylinder's stroke, and
// that the power balance (with the barrel's and the rod's inertia powers)
// closes.
#[test]
fn cylinder_with_mass_matches_newton_euler() {
    let mut worst = 0.0f64;
    let mut compared = 0;
    for (v, acc) in [(0.0, 0.0), (0.35, 0.0), (-0.25, 0.8), (0.4, -1.5)] {
        for k in 0..23 {
            let len = 1.92 + 0.05 * k as f64;
            let s = solve(len, v, acc);
            if s.forces.condition < 0.05 {
                continue;
            }
            compared += 1;
            let (ours, hand) = (generated(&s.forces), newton_euler(&s));
            let scale = hand.amax();
            let d = (ours - hand).amax() / scale;
            worst = worst.max(d);
            assert!(d <= CLOSE, "len {len}, v {v}: {d:e}\n{ours}\n{hand}");
            let (vv, a) = (&s.velocity, &s.acceleration);
            power_balances(
                &[
                    s.forces.drive_len * v,
                    inertial(1800.0, 4500.0, vv.Gb, a.Gb, vv.boom, a.boom, G),
                    inertial(600.0, 0.0, vv.Tip, a.Tip, vv.boom, a.boom, G),
                    inertial(220.0, 30.0, vv.G1, a.G1, vv.barrel, a.barrel, G),
                    inertial(140.0, 18.0, vv.G2, a.G2, vv.barrel, a.barrel, G),
                ],
                "Excavator",
            );
            assert!(
                s.forces.power_residual <= TOL,
                "{}",
                s.forces.power_residual
            );
        }
    }
    assert!(compared >= 80, "only {compared} poses compared");
    println!(
        "cylinder with mass vs Newton-Euler: largest difference {worst:e} of the largest force"
    );
}

// Proves the cylinder's weight loads the reactions: at rest with gravity
// only, the ground's forces at A and B hold up the whole weight, boom,
// payload, barrel and rod (2760 kg), not the boom and payload alone.
#[test]
fn cylinder_weight_shows_in_the_ground_reactions() {
    for len in [2.0, 2.4, 2.9] {
        let f = solve(len, 0.0, 0.0).forces;
        let ground = f.r_ground_boom + f.r_ground_barrel;
        let weight = G * (1800.0 + 600.0 + 220.0 + 140.0);
        assert!(
            (ground + weight).norm() <= 1e-14 * weight.norm(),
            "{ground:?}"
        );
        assert!((ground.y - 2400.0 * 9.81).abs() > 3000.0);
    }
}

mechanism! {
    /// The boom with a link pair hung from a point of the barrel (an RRR
    /// from the barrel's point K to the ground point O6), a force on the
    /// rod and a couple on the barrel (m, kg, N).
    pub LoadedCylinder {
        dof 1;
        let A = ground(0.0, 0.0);
        let B = ground(0.8, -0.9);
        let O6 = ground(1.5, -1.1);
        let C = actuator(A, 2.2, B, len, left) as (boom, barrel, rod);
        let Gb = point(boom, from A, 2.5, 8 deg);
        let G1 = point(barrel, from B, 0.6, 0 deg);
        let K = point(barrel, from B, 0.3, 0 deg);
        let G2 = point(rod, from C, 0.5, 180 deg);
        let P = point(rod, from C, (-0.2, 0.05));
        let D = rrr(K, 0.5, O6, 0.55, left) as (link5, link6);
        let G5 = point(link5, from K, 0.25, 0 deg);
        mass boom { m = 1800.0, at = Gb, j = 4500.0 };
        mass barrel { m = 220.0, at = G1, j = 30.0 };
        mass rod { m = 140.0, at = G2, j = 18.0 };
        mass link5 { m = 40.0, at = G5, j = 0.9 };
        mass link6 { m = 35.0, at = D };
        gravity (0.0, -9.81);
        force at P = (300.0, -800.0);
        torque on barrel = 250.0;
        range len = (1.9, 3.0);
    }
}

// Proves a group joined to a point of the barrel passes its reaction into
// the barrel's load, and a force on the rod and a couple on the barrel load
// them: Newton-Euler holds for each of the five bodies with the generated
// reactions (the axial force acting along the axis through C, `F u` on the
// rod and `-F u` on the barrel), and the power balance closes.
#[test]
fn loads_and_a_group_on_the_cylinder_balance_every_body() {
    use crate::equilibrium::Body;
    let m = LoadedCylinder::<f64>::default();
    let mut checked = 0;
    for (v, acc) in [(0.0, 0.0), (0.3, -0.7)] {
        for k in 0..23 {
            let len = 1.92 + 0.05 * k as f64;
            let s = m
                .solve(
                    &LoadedCylinderInput { len },
                    &LoadedCylinderInput { len: v },
                    &LoadedCylinderInput { len: acc },
                )
                .unwrap();
            let (p, vv, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
            if f.condition < 0.05 {
                continue;
            }
            checked += 1;
            let u = (p.C - p.B).normalize();
            let push = u * f.drive_len;
            let fp = Vector2::new(300.0, -800.0);
            Body::default()
                .force(p.A, f.r_ground_boom)
                .force(p.C, -f.r_boom_rod)
                .inertia(1800.0, 4500.0, p.Gb, a.Gb, a.boom, G)
                .balances("boom");
            Body::default()
                .force(p.C, f.r_boom_rod)
                .prismatic(&f.r_barrel_rod, p.C, 1.0)
                .force(p.C, push)
                .force(p.P, fp)
                .inertia(140.0, 18.0, p.G2, a.G2, a.rod, G)
                .balances("rod");
            Body::default()
                .force(p.B, f.r_ground_barrel)
                .prismatic(&f.r_barrel_rod, p.C, -1.0)
                .force(p.C, -push)
                .force(p.K, -f.r_barrel_link5)
                .couple(250.0)
                .inertia(220.0, 30.0, p.G1, a.G1, a.barrel, G)
                .balances("barrel");
            // The same balance without the group's reaction must fail (the
            // check can see a reaction that is not passed to the barrel).
            let (fr, mr) = Body::default()
                .force(p.B, f.r_ground_barrel)
                .prismatic(&f.r_barrel_rod, p.C, -1.0)
                .force(p.C, -push)
                .couple(250.0)
                .inertia(220.0, 30.0, p.G1, a.G1, a.barrel, G)
                .residual();
            assert!(fr.max(mr) > 1e-3, "{fr:e} {mr:e}");
            Body::default()
                .force(p.K, f.r_barrel_link5)
                .force(p.D, -f.r_link5_link6)
                .inertia(40.0, 0.9, p.G5, a.G5, a.link5, G)
                .balances("link5");
            Body::default()
                .force(p.O6, f.r_ground_link6)
                .force(p.D, f.r_link5_link6)
                .inertia(35.0, 0.0, p.D, a.D, a.link6, G)
                .balances("link6");
            power_balances(
                &[
                    f.drive_len * v,
                    fp.dot(&vv.P),
                    250.0 * vv.barrel,
                    inertial(1800.0, 4500.0, vv.Gb, a.Gb, vv.boom, a.boom, G),
                    inertial(220.0, 30.0, vv.G1, a.G1, vv.barrel, a.barrel, G),
                    inertial(140.0, 18.0, vv.G2, a.G2, vv.rod, a.rod, G),
                    inertial(40.0, 0.9, vv.G5, a.G5, vv.link5, a.link5, G),
                    inertial(35.0, 0.0, vv.D, a.D, vv.link6, a.link6, G),
                ],
                "LoadedCylinder",
            );
            assert!(f.power_residual <= TOL, "{}", f.power_residual);
        }
    }
    assert!(checked >= 40, "only {checked} poses checked");
}

// Proves the description lists the barrel and the rod as cylinder links
// with their own points (the barrel from B, the rod from C) and every mass
// part, the boom's two included.
#[test]
fn structure_lists_barrel_and_rod() {
    use mechanism::structure::{Describe, LinkKind};
    let s = Excavator::<f64>::STRUCTURE;
    let links: Vec<(&str, LinkKind, &[&str])> =
        s.links.iter().map(|l| (l.name, l.kind, l.points)).collect();
    assert_eq!(
        links,
        [
            ("boom", LinkKind::Bar, &["A", "C", "Gb", "Tip"][..]),
            ("barrel", LinkKind::Cylinder, &["B", "G1"][..]),
            ("rod", LinkKind::Cylinder, &["C", "G2"][..]),
        ]
    );
    let masses: Vec<(&str, &str)> = s.masses.iter().map(|m| (m.link, m.at)).collect();
    assert_eq!(
        masses,
        [
            ("boom", "Gb"),
            ("boom", "Tip"),
            ("barrel", "G1"),
            ("rod", "G2")
        ]
    );
}

// Proves the cylinder with mass runs in f32: every force within `F32_CLOSE`
// of the f64 one, relative to the pose's largest force. f32's eps is 1.2e-7;
// the positions, rates and loads each carry a few eps of their scale, and
// the solves amplify that by at most 1 / condition (20 here): 20 eps is
// 2.4e-6, taken as the bound; the largest measured, printed, is 3.7e-7.
#[test]
fn f32_agrees_with_f64() {
    const F32_CLOSE: f64 = 2.5e-6;
    let single = Excavator::<f32>::default();
    let mut worst = 0.0f64;
    for k in 0..12 {
        let len = 1.95 + 0.09 * k as f64;
        let double = solve(len, 0.3, -0.4);
        if double.forces.condition < 0.05 {
            continue;
        }
        let s = single
            .solve(
                &ExcavatorInput { len: len as f32 },
                &ExcavatorInput { len: 0.3 },
                &ExcavatorInput { len: -0.4 },
            )
            .unwrap();
        let f = &s.forces;
        let ours = SVector::<f64, 9>::from_column_slice(&[
            f.r_ground_boom.x as f64,
            f.r_ground_boom.y as f64,
            f.r_boom_rod.x as f64,
            f.r_boom_rod.y as f64,
            f.r_ground_barrel.x as f64,
            f.r_ground_barrel.y as f64,
            f.r_barrel_rod.normal as f64,
            f.r_barrel_rod.moment as f64,
            f.drive_len as f64,
        ]);
        let reference = generated(&double.forces);
        let d = (ours - reference).amax() / reference.amax();
        worst = worst.max(d);
        assert!(d <= F32_CLOSE, "len {len}: {d:e}");
    }
    println!("f32 vs f64: largest difference {worst:e} of the largest force");
}
