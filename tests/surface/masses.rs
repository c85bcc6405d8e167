//! Several `mass` statements on one link, each a part with its own centre and
//! moment of inertia, against the same mechanism with the parts merged by
//! hand into one mass: the combined mass `M = sum m_k`, centre
//! `G = sum m_k p_k / M` and `J_G = sum (j_k + m_k |p_k - G|^2)` (parallel-axis
//! theorem), computed here and written into the merged definition as a
//! `point` and a `mass`. The macro applies each part's loads at its own point
//! (see `emit::forces::loads`), so the two agree to rounding, never by
//! construction.
//!
//! Tolerance. The two definitions' loads on the coupler are the same sums
//! of products taken in a different order (per part vs the merged centre and
//! `J`), so they differ by a few eps of the largest load term; each reaction
//! is a solve of the group's and the crank's systems, which amplify that by
//! at most `1 / condition` (the poses compared keep `condition` above 0.05,
//! so at most 20): 20 x 4 eps = 9e-15. `CLOSE` = 1e-14 of the pose's largest
//! reaction; the largest difference measured over the sweeps is printed by
//! the test (1.1e-15).

use crate::equilibrium::{inertial, power_balances, G, TOL};
use mechanism::{mechanism, Point2, Vector2};

/// Reactions and driving torque agree to this, relative to the pose's
/// largest reaction (see the module documentation).
const CLOSE: f64 = 1e-14;

mechanism! {
    /// A crank-rocker four-bar (m, kg, N) whose coupler carries three parts
    /// (two literal ones, and one from `params`), with gravity and a load.
    pub Parts {
        dof 1;
        params { m3 = 3.0, j3 = 0.02 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.3048, 0.0);
        let A = crank(O2, 0.1016, theta) as crank;
        let B = rrr(A, 0.254, O4, 0.1778, left) as (coupler, rocker);
        let P1 = point(coupler, from A, (0.05, 0.02));
        let P2 = point(coupler, from A, (0.20, -0.03));
        let P3 = point(coupler, from A, (0.12, 0.06));
        let G4 = point(rocker, from O4, 0.09, 4 deg);
        mass coupler { m = 1.5, at = P1, j = 0.004 };
        mass coupler { m = 2.5, at = P2, j = 0.007 };
        mass coupler { m = m3, at = P3, j = j3 };
        mass rocker { m = 0.9, at = G4, j = 0.003 };
        gravity (0.0, -9.81);
        force at B on rocker = (-20.0, 5.0);
    }
}

mechanism! {
    /// [`Parts`] with the coupler's parts merged by hand, the `params` mass
    /// kept: the centre and `J_G` as arithmetic on `m3` and `j3` (`S` the
    /// first moments `sum m_k p_k`; `J_G = sum (j_k + m_k |p_k|^2) - |S|^2 / M`,
    /// the parallel-axis theorem about `A`).
    pub Merged {
        dof 1;
        params { m3 = 3.0, j3 = 0.02 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.3048, 0.0);
        let A = crank(O2, 0.1016, theta) as crank;
        let B = rrr(A, 0.254, O4, 0.1778, left) as (coupler, rocker);
        let Gc = point(coupler, from A, (
            (1.5 * 0.05 + 2.5 * 0.20 + m3 * 0.12) / (4.0 + m3),
            (1.5 * 0.02 - 2.5 * 0.03 + m3 * 0.06) / (4.0 + m3)
        ));
        let G4 = point(rocker, from O4, 0.09, 4 deg);
        mass coupler {
            m = 4.0 + m3,
            at = Gc,
            j = 0.004 + 0.007 + j3
                + 1.5 * (0.05 * 0.05 + 0.02 * 0.02)
                + 2.5 * (0.20 * 0.20 + 0.03 * 0.03)
                + m3 * (0.12 * 0.12 + 0.06 * 0.06)
                - ((1.5 * 0.05 + 2.5 * 0.20 + m3 * 0.12) * (1.5 * 0.05 + 2.5 * 0.20 + m3 * 0.12)
                    + (1.5 * 0.02 - 2.5 * 0.03 + m3 * 0.06) * (1.5 * 0.02 - 2.5 * 0.03 + m3 * 0.06))
                    / (4.0 + m3)
        };
        mass rocker { m = 0.9, at = G4, j = 0.003 };
        gravity (0.0, -9.81);
        force at B on rocker = (-20.0, 5.0);
    }
}

mechanism! {
    /// [`Parts`] with every part literal (the macro folds the sum of the
    /// parts' `j` into one inertia couple).
    pub LiteralParts {
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.3048, 0.0);
        let A = crank(O2, 0.1016, theta) as crank;
        let B = rrr(A, 0.254, O4, 0.1778, left) as (coupler, rocker);
        let P1 = point(coupler, from A, (0.05, 0.02));
        let P2 = point(coupler, from A, (0.20, -0.03));
        let P3 = point(coupler, from A, (0.12, 0.06));
        mass coupler { m = 1.5, at = P1, j = 0.004 };
        mass coupler { m = 2.5, at = P2, j = 0.007 };
        mass coupler { m = 3.0, at = P3, j = 0.02 };
        gravity (0.0, -9.81);
        force at B on rocker = (-20.0, 5.0);
    }
}

/// The combined centre (from `A`, in the coupler's frame) and `J_G` of
/// [`LiteralParts`], written out to 17 digits (computed exactly in rational
/// arithmetic; [`literal_merge_matches_the_parts`] recomputes them).
const G_MERGED: (f64, f64) = (0.13357142857142856, 0.019285714285714285);
const J_MERGED: f64 = 0.06410714285714286;

mechanism! {
    /// [`LiteralParts`] merged by hand: `M = 7`, the centre and `J_G` above.
    pub LiteralMerged {
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.3048, 0.0);
        let A = crank(O2, 0.1016, theta) as crank;
        let B = rrr(A, 0.254, O4, 0.1778, left) as (coupler, rocker);
        let Gc = point(coupler, from A, (0.13357142857142856, 0.019285714285714285));
        mass coupler { m = 7.0, at = Gc, j = 0.06410714285714286 };
        gravity (0.0, -9.81);
        force at B on rocker = (-20.0, 5.0);
    }
}

/// The four reactions and the driving torque of a four-bar's forces, in one
/// order.
fn effort(f: [Vector2<f64>; 4], drive: f64) -> [f64; 9] {
    [
        f[0].x, f[0].y, f[1].x, f[1].y, f[2].x, f[2].y, f[3].x, f[3].y, drive,
    ]
}

/// The largest difference of `a` and `b`, relative to the largest entry of `b`.
fn relative_difference(a: &[f64; 9], b: &[f64; 9]) -> f64 {
    let scale = b.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let diff = a
        .iter()
        .zip(b)
        .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    diff / scale
}

// Proves the hand merge written into `LiteralMerged` is the parts' combined
// mass, centre and parallel-axis `J_G` (recomputed here in f64), so that the
// comparisons below compare against an independent merge.
#[test]
fn literal_merge_matches_the_parts() {
    let parts = [
        (1.5, 0.004, Vector2::new(0.05, 0.02)),
        (2.5, 0.007, Vector2::new(0.20, -0.03)),
        (3.0, 0.02, Vector2::new(0.12, 0.06)),
    ];
    let m: f64 = parts.iter().map(|p| p.0).sum();
    let g = parts.iter().map(|p| p.2 * p.0).sum::<Vector2<f64>>() / m;
    let j: f64 = parts
        .iter()
        .map(|p| p.1 + p.0 * (p.2 - g).norm_squared())
        .sum();
    assert_eq!(m, 7.0);
    assert!((g.x - G_MERGED.0).abs() <= 2e-16 * g.norm(), "{g:?}");
    assert!((g.y - G_MERGED.1).abs() <= 2e-16 * g.norm(), "{g:?}");
    assert!((j - J_MERGED).abs() <= 4e-16 * j, "{j}");
}

// Proves several masses on one link load it as the merged body: the
// reactions and the driving torque of `Parts` equal those of `Merged` over a
// sweep of the crank, at two values of the `params` mass and inertia, with
// gravity; and the power balance, computed here from the merged body's
// inertia and weight, closes for `Parts`.
#[test]
fn parts_load_a_link_as_their_merged_body() {
    let mut worst = 0.0f64;
    let mut compared = 0;
    for (m3, j3) in [(3.0, 0.02), (0.4, 0.0), (12.0, 0.5)] {
        let parts = Parts::<f64> { m3, j3 };
        let merged = Merged::<f64> { m3, j3 };
        let (w, al) = (9.0, -35.0);
        for k in 0..72 {
            let q = f64::to_radians(5.0 * k as f64 + 2.0);
            let (qi, wi, ai) = (
                PartsInput { theta: q },
                PartsInput { theta: w },
                PartsInput { theta: al },
            );
            let s = parts.solve(&qi, &wi, &ai).unwrap();
            let t = merged
                .solve(
                    &MergedInput { theta: q },
                    &MergedInput { theta: w },
                    &MergedInput { theta: al },
                )
                .unwrap();
            if t.forces.condition < 0.05 {
                continue;
            }
            compared += 1;
            let (f, g) = (&s.forces, &t.forces);
            let a = effort(
                [
                    f.r_ground_crank,
                    f.r_crank_coupler,
                    f.r_coupler_rocker,
                    f.r_ground_rocker,
                ],
                f.drive_theta,
            );
            let b = effort(
                [
                    g.r_ground_crank,
                    g.r_crank_coupler,
                    g.r_coupler_rocker,
                    g.r_ground_rocker,
                ],
                g.drive_theta,
            );
            let d = relative_difference(&a, &b);
            worst = worst.max(d);
            assert!(d <= CLOSE, "m3 = {m3}, theta = {q}: {d:e}\n{a:?}\n{b:?}");
            // Power, from the merged body (its centre's motion from `Merged`).
            let (tv, ta) = (&t.velocity, &t.acceleration);
            let jg = merged_j(m3, j3);
            power_balances(
                &[
                    f.drive_theta * w,
                    inertial(4.0 + m3, jg, tv.Gc, ta.Gc, tv.coupler, ta.coupler, G),
                    inertial(
                        0.9,
                        0.003,
                        s.velocity.G4,
                        s.acceleration.G4,
                        s.velocity.rocker,
                        s.acceleration.rocker,
                        G,
                    ),
                    Vector2::new(-20.0, 5.0).dot(&s.velocity.B),
                ],
                "Parts",
            );
            assert!(f.power_residual <= TOL, "{}", f.power_residual);
        }
    }
    assert!(compared >= 180, "only {compared} poses compared");
    println!("parts vs merged: largest difference {worst:e} of the largest reaction");
}

/// `J_G` of the coupler's three parts with `m3`, `j3` (parallel-axis theorem).
fn merged_j(m3: f64, j3: f64) -> f64 {
    let parts = [
        (1.5, 0.004, Point2::new(0.05, 0.02)),
        (2.5, 0.007, Point2::new(0.20, -0.03)),
        (m3, j3, Point2::new(0.12, 0.06)),
    ];
    let m: f64 = parts.iter().map(|p| p.0).sum();
    let g = parts.iter().map(|p| p.2.coords * p.0).sum::<Vector2<f64>>() / m;
    parts
        .iter()
        .map(|p| p.1 + p.0 * (p.2.coords - g).norm_squared())
        .sum()
}

// Proves the all-literal parts (one folded inertia couple) give the hand
// merge's reactions and torque over a sweep.
#[test]
fn literal_parts_load_a_link_as_their_merged_body() {
    let (parts, merged) = (
        LiteralParts::<f64>::default(),
        LiteralMerged::<f64>::default(),
    );
    let (w, al) = (-6.0, 40.0);
    let mut compared = 0;
    for k in 0..72 {
        let q = f64::to_radians(5.0 * k as f64 + 1.0);
        let s = parts
            .solve(
                &LiteralPartsInput { theta: q },
                &LiteralPartsInput { theta: w },
                &LiteralPartsInput { theta: al },
            )
            .unwrap();
        let t = merged
            .solve(
                &LiteralMergedInput { theta: q },
                &LiteralMergedInput { theta: w },
                &LiteralMergedInput { theta: al },
            )
            .unwrap();
        if t.forces.condition < 0.05 {
            continue;
        }
        compared += 1;
        let (f, g) = (&s.forces, &t.forces);
        let a = effort(
            [
                f.r_ground_crank,
                f.r_crank_coupler,
                f.r_coupler_rocker,
                f.r_ground_rocker,
            ],
            f.drive_theta,
        );
        let b = effort(
            [
                g.r_ground_crank,
                g.r_crank_coupler,
                g.r_coupler_rocker,
                g.r_ground_rocker,
            ],
            g.drive_theta,
        );
        let d = relative_difference(&a, &b);
        assert!(d <= CLOSE, "theta = {q}: {d:e}\n{a:?}\n{b:?}");
        assert!(f.power_residual <= TOL, "{}", f.power_residual);
    }
    assert!(compared >= 60, "only {compared} poses compared");
}

// Proves a non-literal part is checked at run time on its own: a negative
// `params` mass of the third part is a typed error, not finite wrong forces.
#[test]
fn a_negative_params_part_is_an_error() {
    let parts = Parts::<f64> { m3: -1.0, j3: 0.02 };
    let i = PartsInput { theta: 0.3 };
    let s = parts.position(&i).unwrap();
    let v = parts.velocity(&s, &PartsInput { theta: 1.0 }).unwrap();
    let a = parts
        .acceleration(&s, &v, &PartsInput { theta: 0.0 })
        .unwrap();
    let e = parts.forces(&s, &v, &a).unwrap_err();
    assert!(format!("{e}").contains("mass of `coupler` (part 3)"), "{e}");
}
