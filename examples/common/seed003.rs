//! Seed 003's data (an RRR group of a four-bar with inertia, weight and an
//! external force, m, kg, N), shared by `examples/assur_rrr.rs` and the core's
//! kinetostatics tests. Everything goes through `mechanism_core` directly.
#![allow(dead_code)]

use mechanism_core::force::{self, inertia_and_gravity, Wrench};
use mechanism_core::{Point2, Vector2};

/// Seed 003's RRR group, in its notation: link 2 from `A` (pinned to the crank,
/// link 1) to `B`, link 3 from `B` to `C` (pinned to the ground, 0); our group's
/// `A`, `B`, `C` are its `A`, `C`, `B`. Inputs as printed in its results
/// (`xB = 0.503`, `yD = 0.197`; the input list's `xB0.053` and `yD = 0.97` are
/// typos: with them the program would print F12 = (4911.38, 1026.74)).
/// `mu3_sign` is the sign of link 3's inertia couple `Mu3 = mu3_sign J3 e3`:
/// -1 is d'Alembert's (and the program's), +1 the text's formula. Link 2's is
/// always `Mu2 = -J2 e2` (text and code agree).
pub fn group<T: mechanism_core::Real>(mu3_sign: f64) -> Out<T> {
    let p = |x: f64, y: f64| Point2::new(T::lit(x), T::lit(y));
    let v = |x: f64, y: f64| Vector2::new(T::lit(x), T::lit(y));
    let a = p(0.075, 0.13);
    let b_seed = p(0.503, 0.348); // inner joint: our C
    let c_seed = p(0.7, 0.0); // ground pivot of link 3: our B
    let d = p(1.048, 0.197);
    let s2 = p(0.289, 0.239);
    let s3 = p(0.7, 0.15);
    let g = v(0.0, -9.81);
    // `inertia_and_gravity` applies `-J alpha`; the text's `+J3 e3` is
    // obtained by flipping alpha.
    let e2 = T::lit(0.12);
    let e3 = T::lit(-mu3_sign * 0.404);
    let load2 = inertia_and_gravity(
        T::lit(480.0),
        T::lit(1.0),
        &s2,
        &v(-0.104, -0.112),
        e2,
        Some(&g),
        &b_seed,
    );
    let load3 = inertia_and_gravity(
        T::lit(200.0),
        T::lit(2.0),
        &s3,
        &v(0.061, -0.006),
        e3,
        Some(&g),
        &b_seed,
    ) + Wrench::force_at(&v(1000.0, 1000.0), &d, &b_seed);
    let r = force::rrr::reactions(&a, &c_seed, &b_seed, &load2, &load3).unwrap();
    Out {
        f12: r.a,
        f03: r.b,
        f23: r.c,
        ratio: r.min_pivot_ratio,
    }
}

/// The reactions of seed 003's group (N, global frame), in its names.
pub struct Out<T: mechanism_core::Real> {
    /// Force of the crank (link 1) on link 2 at `A`.
    pub f12: Vector2<T>,
    /// Force of the ground (0) on link 3 at `C`.
    pub f03: Vector2<T>,
    /// Force of link 2 on link 3 at `B` (not printed by the seed).
    pub f23: Vector2<T>,
    /// Conditioning indicator of the group's system.
    pub ratio: T,
}
