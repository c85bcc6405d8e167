//! The force analysis `mechanism!` generates, through the example scenes and
//! two scenes of this file:
//!
//! - seed 000, problem 4-23 (sine mechanism): the document's whole table
//!   (36 angles, 4 decimals) and its three worked positions, in its own sign
//!   convention; and a closed form derived here from each link's equilibrium;
//! - the power balance (driver + loads + weights + inertia = 0) at every
//!   sample of every force example, recomputed here from the kinematics;
//! - every link of the shaper (crank, block, rocker, rod, ram) in equilibrium
//!   under the generated reactions, its loads and its inertia;
//! - a stiff four-bar (t, mm, s: forces in N; masses from 1e-6 to 1e6 kg):
//!   equilibrium and power balance hold to rounding, and the same group
//!   system defeats unscaled, unpivoted elimination.
//!
//! Seed 003 goes through the core primitive (`examples/assur_rrr.rs`); its
//! test is `mechanism-core/tests/primitives/kinetostatics.rs`, which shares the data.

use crate::scenes::*;
use mechanism::force::group::{assemble, Connection, Joint, Pair};
use mechanism::force::Wrench;
use mechanism::geometry::{cross, dot};
use mechanism::linsolve::solve;
use mechanism::{mechanism, Point2, Vector2};
use mechanism_reference::naive::solve_unpivoted_unscaled;
use std::f64::consts::PI;

const DOC_FR23: [f64; 36] = [
    400.0, 382.1443, 364.8625, 348.7101, 334.2061, 321.8169, 311.9404, 304.8943, 300.905, 300.1007,
    302.5072, 308.0472, 316.5427, 327.7205, 341.2215, 356.6116, 373.3963, 391.0361, 408.9639,
    426.6037, 443.3884, 458.7785, 472.2795, 483.4573, 491.9528, 497.4928, 499.8993, 499.095,
    495.1057, 488.0596, 478.1831, 465.7939, 451.2899, 435.1375, 417.8557, 400.0,
];
const DOC_FR4: [f64; 36] = [
    500.0, 470.0039, 426.9963, 374.1872, 314.6014, 250.8119, 184.7735, 117.7719, 50.4893, -16.83,
    -84.1427, -151.3378, -217.978, -283.0943, -345.0675, -401.62, -449.9252, -486.8273, -509.147,
    -514.0376, -499.3489, -463.9495, -407.9684, -332.919, -241.6872, -138.3782, -28.0349, 83.7439,
    191.2451, 289.0952, 372.6779, 438.4701, 484.2616, 509.2386, 513.9257, 500.0,
];
const DOC_FR12X: [f64; 36] = [
    40.0, 39.3572, 37.4494, 34.338, 30.1229, 24.9396, 18.9547, 12.3607, 5.3693, -1.7946, -8.9008,
    -15.721, -22.0359, -27.6425, -32.3607, -36.0388, -38.5585, -39.839, -39.839, -38.5585,
    -36.0388, -32.3607, -27.6425, -22.0359, -15.721, -8.9008, -1.7946, 5.3693, 12.3607, 18.9547,
    24.9396, 30.1229, 34.338, 37.4494, 39.3572, 40.0,
];
const DOC_FR12Y: [f64; 36] = [
    400.0, 375.002, 350.8075, 328.1941, 307.8886, 290.5436, 276.7166, 266.8521, 261.267, 260.141,
    263.5101, 271.2661, 283.1597, 298.8087, 317.7101, 339.2563, 362.7548, 387.4505, 412.5495,
    437.2452, 460.7437, 482.2899, 501.1913, 516.8403, 528.7339, 536.4899, 539.859, 538.733,
    533.1479, 523.2834, 509.4564, 492.1114, 471.8059, 449.1925, 424.998, 400.0,
];
const DOC_MB: [f64; 36] = [
    40.0, 37.6003, 34.1597, 29.935, 25.1681, 20.065, 14.7819, 9.4218, 4.0391, -1.3464, -6.7314,
    -12.107, -17.4382, -22.6475, -27.6054, -32.1296, -35.994, -38.9462, -40.7318, -41.123,
    -39.9479, -37.116, -32.6375, -26.6335, -19.335, -11.0703, -2.2428, 6.6995, 15.2996, 23.1276,
    29.8142, 35.0776, 38.7409, 40.7391, 41.1141, 40.0,
];

/// Solves the sine mechanism at `phi` (rad), crank 10 rad/s, masses `G / g`.
fn sine(phi: f64, g: f64) -> SineMechanismSolution {
    let m = SineMechanism::<f64> {
        m2: 40.0 / g,
        m3: 100.0 / g,
        ..SineMechanism::default()
    };
    m.solve(
        &SineMechanismInput { phi1: phi },
        &SineMechanismInput { phi1: 10.0 },
        &SineMechanismInput { phi1: 0.0 },
    )
    .expect("the sine mechanism is regular everywhere")
}

/// The document's outputs `[FR23, FR4, FR12x, FR12y, Mb]` from ours: its
/// FR12x is the force of block 2 on crank 1 (our `r12x` negated) and its
/// guide forces are the couple `m43` as two forces h2 = 0.08 m apart,
/// FR4 = -m43 / h2.
fn document_convention(s: &SineMechanismSolution) -> [f64; 5] {
    let f = &s.forces;
    let m43 = f
        .r_ground_link3
        .wrench_about(&s.position.B, &s.position.Q)
        .moment;
    [
        f.r_block2_link3.force.y,
        -m43 / 0.08,
        -f.r_link1_block2.x,
        f.r_link1_block2.y,
        f.drive_phi1,
    ]
}

/// Seed 000's table: `th1 = linspace(0, 2 pi, 36)`, printed with 4 decimals,
/// so every value must agree to half a unit of its last place (5e-5 N); a
/// sign or convention slip is off by hundreds of N.
#[test]
fn sine_mechanism_reproduces_the_seed_000_table() {
    let printed = [DOC_FR23, DOC_FR4, DOC_FR12X, DOC_FR12Y, DOC_MB];
    let mut worst: f64 = 0.0;
    for k in 0..36 {
        let phi = 2.0 * PI * k as f64 / 35.0;
        let ours = document_convention(&sine(phi, 10.0));
        for (column, value) in printed.iter().zip(ours) {
            let err = (value - column[k]).abs();
            worst = worst.max(err);
            assert!(err <= 5.0e-5 + 1e-9, "sample {k}: {ours:?}");
        }
    }
    println!("worst difference from the printed table: {worst:.2e} N");
    // The worked positions, printed separately (same digits).
    let worked = [
        (60.0, [313.3975, 195.8734, 20.0000, 278.7564, 15.6699]),
        (150.0, [350.0000, -378.8861, -34.6410, 330.0000, -30.3109]),
        (220.0, [464.2788, -444.5727, -30.6418, 489.9903, -35.5658]),
    ];
    for (deg, want) in worked {
        let ours = document_convention(&sine(f64::to_radians(deg), 10.0));
        for (o, w) in ours.iter().zip(want) {
            assert!((o - w).abs() <= 5.0e-5 + 1e-9, "{deg} deg: {ours:?}");
        }
    }
}

/// Each link's equilibrium by hand (crank r = 0.1 m, omega = 10 rad/s,
/// B = r (cos, sin), block acceleration -r omega^2 (cos, sin), link 3's
/// -r omega^2 sin along y): r23y = Fr + m3 a3y; r12 = (0, r23y) + m2 aB;
/// mb = cross(B, r12); m43 = -xB r23y. Values are at most ~600 N and the
/// generated path solves 6x6 systems: agreement to 1e-12 N (about 2000 ulp of
/// 600) leaves room for that, while any missing term is off by > 1 N.
#[test]
fn sine_mechanism_matches_the_closed_form() {
    for g in [10.0, 9.80665] {
        let (m2, m3, r, w, fr) = (40.0 / g, 100.0 / g, 0.1, 10.0, 400.0);
        for step in 0..72 {
            let phi = f64::to_radians(5.0 * step as f64);
            let s = sine(phi, g);
            let (c, sn) = (phi.cos(), phi.sin());
            let a_b = [-r * w * w * c, -r * w * w * sn];
            let r23y = fr + m3 * a_b[1];
            let r12 = [m2 * a_b[0], r23y + m2 * a_b[1]];
            let mb = r * c * r12[1] - r * sn * r12[0];
            let m43 = -r * c * r23y;
            let f = &s.forces;
            let m43_ours = f
                .r_ground_link3
                .wrench_about(&s.position.B, &s.position.Q)
                .moment;
            let pairs = [
                (f.r_block2_link3.force.y, r23y),
                (f.r_link1_block2.x, r12[0]),
                (f.r_link1_block2.y, r12[1]),
                (f.drive_phi1, mb),
                (m43_ours, m43),
                (f.r_block2_link3.force.x, 0.0),
                (f.r_ground_link3.normal, 0.0),
            ];
            for (ours, want) in pairs {
                assert!(
                    (ours - want).abs() < 1e-12,
                    "g {g}, {step}: {ours} vs {want}"
                );
            }
        }
    }
}

/// Power of every load on a moving body, computed from the kinematics only.
fn power(force: &Vector2<f64>, velocity: &Vector2<f64>) -> f64 {
    dot(force, velocity)
}

/// The power balance, recomputed here for the sine mechanism: driver + Fr +
/// inertia of both bodies; and the generated residual agrees. Powers are
/// up to ~400 W; 1e-12 relative is ~4500 ulp of slack over sums of a few
/// products, far below any missing term (>= 1e-3 relative here).
#[test]
fn power_balance_sine_mechanism() {
    for g in [10.0, 9.80665] {
        for step in 0..72 {
            let phi = f64::to_radians(5.0 * step as f64);
            let s = sine(phi, g);
            let (v, a, f) = (&s.velocity, &s.acceleration, &s.forces);
            let terms = [
                f.drive_phi1 * 10.0,
                power(&Vector2::new(0.0, -400.0), &v.Q),
                power(&(a.B * -(40.0 / g)), &v.B),
                power(&(a.Q * -(100.0 / g)), &v.Q),
            ];
            let scale = terms.iter().fold(0.0f64, |m, t| m.max(t.abs()));
            let sum: f64 = terms.iter().sum();
            assert!(sum.abs() <= 1e-12 * scale, "g {g} step {step}: {terms:?}");
            assert!(f.power_residual <= 1e-12, "{}", f.power_residual);
        }
    }
}

/// The shaper over a full turn at 60 rpm, with the cutting force on the
/// forward stroke, and the power balance recomputed here: crank torque,
/// weights and inertia of rocker, rod and ram (force and couple), cutting
/// force. 1e-12 relative as above; the generated residual agrees.
#[test]
fn power_balance_and_equilibrium_shaper() {
    let shaper = ShaperForces::<f64>::default();
    let (w, g) = (2.0 * PI, Vector2::new(0.0, -9.81));
    let mut worst_power: f64 = 0.0;
    let mut worst_balance: f64 = 0.0;
    for step in 0..72 {
        let deg = 5.0 * step as f64;
        let p = shaper
            .position(&ShaperForcesInput {
                crank: deg.to_radians(),
            })
            .unwrap();
        let v = shaper
            .velocity(&p, &ShaperForcesInput { crank: w })
            .unwrap();
        let a = shaper
            .acceleration(&p, &v, &ShaperForcesInput { crank: 0.0 })
            .unwrap();
        let cut = if v.s_ram > 0.0 { -5000.0 } else { 0.0 };
        let f = shaper
            .forces(&p, &v, &a, &ShaperForcesLoads { cut })
            .unwrap();
        // Kinematics of the mass centres and the links.
        let (w3, w4) = (v.link3, v.link4);
        let (al3, al4) = (a.link3, a.link4);
        // Mass centres at the midpoints (C is fixed), independent of S3, S4.
        let s3 = p.C + (p.D - p.C) * 0.5;
        let s4 = p.D + (p.E - p.D) * 0.5;
        assert!((s3 - p.S3).norm() < 1e-15 && (s4 - p.S4).norm() < 1e-15);
        let v_s3 = v.D * 0.5;
        let a_s3 = a.D * 0.5;
        let v_s4 = (v.D + v.E) * 0.5;
        let a_s4 = (a.D + a.E) * 0.5;
        let guide_dir = Vector2::new(-1.0, 0.0);
        let cutting = guide_dir * cut;
        let terms = [
            f.drive_crank * w,
            power(&(g * 20.0 - a_s3 * 20.0), &v_s3) - 0.6 * al3 * w3,
            power(&(g * 3.0 - a_s4 * 3.0), &v_s4) - 0.005625 * al4 * w4,
            power(&(g * 60.0 - a.E * 60.0), &v.E),
            power(&cutting, &v.E),
        ];
        let scale = terms.iter().fold(0.0f64, |m, t| m.max(t.abs()));
        let sum: f64 = terms.iter().sum();
        worst_power = worst_power.max(sum.abs() / scale);
        assert!(sum.abs() <= 1e-12 * scale, "{deg}: {terms:?}");
        assert!(f.power_residual <= 1e-12, "{deg}: {}", f.power_residual);

        // Equilibrium of each body: forces, and moments about the origin.
        // Each body's sum is compared with its largest single force (and
        // moment with largest force times the mechanism's size, 1 m).
        let moment = |force: &Vector2<f64>, at: &Point2<f64>| cross(&at.coords, force);
        let mut check = |forces: &[(Vector2<f64>, Point2<f64>)], couples: &[f64]| {
            let sum_f = forces.iter().fold(Vector2::zeros(), |s, (f, _)| s + f);
            let sum_m = forces.iter().map(|(f, at)| moment(f, at)).sum::<f64>()
                + couples.iter().sum::<f64>();
            let scale = forces.iter().fold(1.0f64, |m, (f, _)| m.max(f.norm()));
            let err = sum_f.norm().max(sum_m.abs()) / scale;
            worst_balance = worst_balance.max(err);
            assert!(err < 1e-13, "{deg}: body off balance by {err:e}");
        };
        // Crank: ground pivot at A, block on it at B (-(crank on block)), torque.
        check(
            &[(f.r_ground_link2, p.A), (-f.r_link2_block, p.B)],
            &[f.drive_crank],
        );
        // Block: crank on it at B, rocker's slide reaction on it (about B).
        check(
            &[(f.r_link2_block, p.B), (-f.r_block_link3.force, p.B)],
            &[-f.r_block_link3.moment],
        );
        // Rocker: ground at C, block's slide reaction (about B), rod at D
        // (-(rocker on rod)), weight and inertia at S3, inertia couple.
        check(
            &[
                (f.r_ground_link3, p.C),
                (f.r_block_link3.force, p.B),
                (-f.r_link3_link4, p.D),
                (g * 20.0 - a_s3 * 20.0, s3),
            ],
            &[f.r_block_link3.moment, -0.6 * al3],
        );
        // Rod: rocker at D, ram at E (-(rod on ram)), weight, inertia.
        check(
            &[
                (f.r_link3_link4, p.D),
                (-f.r_link4_ram_block, p.E),
                (g * 3.0 - a_s4 * 3.0, s4),
            ],
            &[-0.005625 * al4],
        );
        // Ram: rod at E, guide (about E), weight, inertia, cutting force.
        check(
            &[
                (f.r_link4_ram_block, p.E),
                (f.r_ground_ram_block.force, p.E),
                (g * 60.0 - a.E * 60.0, p.E),
                (cutting, p.E),
            ],
            &[f.r_ground_ram_block.moment],
        );
    }
    println!(
        "shaper: worst power balance {worst_power:.2e}, worst equilibrium {worst_balance:.2e}"
    );
}

mechanism! {
    /// A stiff four-bar in t, mm, s (forces in N, moments in N mm): a
    /// 1000 t coupler (1e6 kg) and a 1e-9 t rocker (1e-6 kg), inertias
    /// in t mm^2, a 2 kN mm couple on the rocker.
    pub StiffFourBar {
        params { m3 = 1000.0, m4 = 1.0e-9 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(304.8, 0.0);
        let A = crank(O2, 101.6, theta2) as link2;
        let B = rrr(A, 254.0, O4, 177.8, left) as (link3, link4);
        let G3 = point(link3, from A, 127.0, 0 deg);
        let G4 = point(link4, from O4, 88.9, 0 deg);
        mass link3 { m = m3, at = G3, j = m3 * 5376.0 };
        mass link4 { m = m4, at = G4, j = m4 * 2634.0 };
        gravity (0.0, -9810.0);
        torque on link4 = 2000.0;
    }
}

/// The stiff four-bar at 10 rad/s over a turn: every link in equilibrium and
/// the power balance, to 1e-12 of the largest term (the loads span 15 orders
/// of magnitude: 1e7 N on the coupler, 1e-5 N on the rocker).
#[test]
fn stiff_four_bar_balances() {
    let fb = StiffFourBar::<f64>::default();
    for step in 0..36 {
        let theta = f64::to_radians(10.0 * step as f64);
        let s = fb
            .solve(
                &StiffFourBarInput { theta2: theta },
                &StiffFourBarInput { theta2: 10.0 },
                &StiffFourBarInput { theta2: 0.0 },
            )
            .unwrap();
        let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
        let g = Vector2::new(0.0, -9810.0);
        let load3 = g * 1000.0 - a.G3 * 1000.0;
        let load4 = g * 1e-9 - a.G4 * 1e-9;
        let terms = [
            f.drive_theta2 * 10.0,
            power(&load3, &v.G3) - 1000.0 * 5376.0 * a.link3 * v.link3,
            power(&load4, &v.G4) - 1e-9 * 2634.0 * a.link4 * v.link4,
            2000.0 * v.link4,
        ];
        let scale = terms.iter().fold(0.0f64, |m, t| m.max(t.abs()));
        assert!(
            terms.iter().sum::<f64>().abs() <= 1e-12 * scale,
            "{terms:?}"
        );
        // Coupler: crank on it at A, rocker on it at B (-(coupler on rocker)).
        let sum3 = f.r_link2_link3 - f.r_link3_link4 + load3;
        assert!(sum3.norm() <= 1e-12 * load3.norm(), "{sum3:?}");
        // Rocker: ground at O4, coupler at B, its load: the rocker's own
        // loads are 1e-5 N beside 1e7 N reactions, so its balance is checked
        // relative to the reactions it carries.
        let sum4 = f.r_ground_link4 + f.r_link3_link4 + load4;
        assert!(sum4.norm() <= 1e-12 * f.r_link3_link4.norm(), "{sum4:?}");
        let m4 = cross(&(p.B - p.O4), &f.r_link3_link4) + cross(&(p.G4 - p.O4), &load4)
            - 1e-9 * 2634.0 * a.link4
            + 2000.0;
        assert!(m4.abs() <= 1e-12 * 254.0 * f.r_link3_link4.norm(), "{m4}");
    }
}

/// The coupler-rocker group of the stiff four-bar as one 6x6 system (the
/// core's assembler, about B): the solver the generated code uses gets the
/// generated reactions back; elimination without row scaling and pivoting,
/// on the same system, does not (its first pivot is the rocker's 1e-5 N
/// scale beside 1e7 N rows, or zero).
#[test]
fn stiff_group_defeats_naive_elimination() {
    let fb = StiffFourBar::<f64>::default();
    let s = fb
        .solve(
            &StiffFourBarInput { theta2: 0.7 },
            &StiffFourBarInput { theta2: 10.0 },
            &StiffFourBarInput { theta2: 0.0 },
        )
        .unwrap();
    let (p, a, f) = (&s.position, &s.acceleration, &s.forces);
    let g = Vector2::new(0.0, -9810.0);
    let load3 = Wrench::force_at(&(g * 1000.0 - a.G3 * 1000.0), &p.G3, &p.B)
        .with_couple(-1000.0 * 5376.0 * a.link3);
    let load4 = Wrench::force_at(&(g * 1e-9 - a.G4 * 1e-9), &p.G4, &p.B)
        .with_couple(-1e-9 * 2634.0 * a.link4 + 2000.0);
    let joints = [
        Joint {
            pair: Pair::Revolute { point: p.A },
            connection: Connection::OutsideToLink1,
        },
        Joint {
            pair: Pair::Revolute { point: p.O4 },
            connection: Connection::OutsideToLink2,
        },
        Joint {
            pair: Pair::Revolute { point: p.B },
            connection: Connection::Link1ToLink2,
        },
    ];
    let system = assemble(&joints, &p.B, &load3, &load4);
    let want = [
        f.r_link2_link3.x,
        f.r_link2_link3.y,
        f.r_ground_link4.x,
        f.r_ground_link4.y,
        f.r_link3_link4.x,
        f.r_link3_link4.y,
    ];
    let scale = want.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let good = solve(system.matrix, system.rhs).unwrap().x;
    let good_err = good
        .iter()
        .zip(&want)
        .fold(0.0f64, |m, (g, w)| m.max((g - w).abs()))
        / scale;
    let naive_err = match solve_unpivoted_unscaled(system.matrix, system.rhs) {
        Ok(x) => {
            x.iter()
                .zip(&want)
                .fold(0.0f64, |m, (g, w)| m.max((g - w).abs()))
                / scale
        }
        Err(_) => f64::INFINITY,
    };
    println!("relative error: pivoting {good_err:.1e}, naive {naive_err:.1e}");
    assert!(good_err < 1e-14, "{good_err}");
    assert!(
        naive_err >= 1e-6 || naive_err.is_nan(),
        "naive elimination unexpectedly fine: {naive_err}"
    );
}

/// The shaper's force analysis in f32 against f64 over a turn, relative to
/// each quantity's largest magnitude over the turn. f32 rounds at 6e-8
/// relative; the kinematics (sin/cos, the RPR and RRP closures, the
/// accelerations) and two chained 6x6 solves amplify that by a few tens
/// (measured: 2.1e-6), so the bound is 1e-5, about 80 f32 ulps; a term
/// missing in one precision would be off by its full size, > 1e-2.
#[test]
fn shaper_forces_f32_against_f64() {
    let (s64, s32) = (
        ShaperForces::<f64>::default(),
        ShaperForces::<f32>::default(),
    );
    let mut rows64 = Vec::new();
    let mut rows32 = Vec::new();
    for step in 0..72 {
        let deg = 5.0 * step as f64;
        let cut = if (60.0..=250.0).contains(&deg) {
            -5000.0
        } else {
            0.0
        };
        let f64s = s64
            .solve(
                &ShaperForcesInput {
                    crank: deg.to_radians(),
                },
                &ShaperForcesInput { crank: 2.0 * PI },
                &ShaperForcesInput { crank: 0.0 },
                &ShaperForcesLoads { cut },
            )
            .unwrap()
            .forces;
        let f32s = s32
            .solve(
                &ShaperForcesInput {
                    crank: deg.to_radians() as f32,
                },
                &ShaperForcesInput {
                    crank: 2.0 * std::f32::consts::PI,
                },
                &ShaperForcesInput { crank: 0.0 },
                &ShaperForcesLoads { cut: cut as f32 },
            )
            .unwrap()
            .forces;
        rows64.push([
            f64s.drive_crank,
            f64s.r_ground_link3.x,
            f64s.r_ground_link3.y,
            f64s.r_link4_ram_block.x,
            f64s.r_ground_ram_block.normal,
        ]);
        rows32.push([
            f32s.drive_crank,
            f32s.r_ground_link3.x,
            f32s.r_ground_link3.y,
            f32s.r_link4_ram_block.x,
            f32s.r_ground_ram_block.normal,
        ]);
    }
    let mut worst: f64 = 0.0;
    for col in 0..5 {
        let scale = rows64.iter().fold(0.0f64, |m, r| m.max(r[col].abs()));
        for (a, b) in rows64.iter().zip(&rows32) {
            worst = worst.max((a[col] - f64::from(b[col])).abs() / scale);
        }
    }
    println!("shaper forces, f32 against f64: {worst:.2e} of each column's largest value");
    assert!(worst < 1e-5, "{worst}");
}
