//! The sweeps the firmware checks, shared word for word with the host test
//! `tests/examples/firmware_table.rs` that writes and re-checks `expected.rs`: one row of
//! outputs per crank angle, generic over the scalar, widened to `f64` (the
//! values and the error's numbers).
//!
//! Expects the example scenes as `crate::scenes` (`examples/common/scenes.rs`).
#![allow(dead_code)]

use crate::scenes::{
    FourBar, FourBarInput, Shaper, ShaperForces, ShaperForcesInput, ShaperForcesLoads, ShaperInput,
};
use mechanism::{Error, Real};

/// Number of crank angles in each sweep: 0, 5, ..., 355 deg.
pub const STEPS: usize = 72;

/// Crank angle of step `i` (rad), rounded to `f32` so that the f32 and f64
/// evaluations see the same input.
pub fn angle(i: usize) -> f64 {
    ((5.0 * i as f64) * (core::f64::consts::PI / 180.0)) as f32 as f64
}

/// Four-bar (seed 002, mm) columns.
pub const FOURBAR_COLUMNS: [&str; 9] = [
    "theta2", "B.x", "B.y", "theta3", "theta4", "omega3", "omega4", "alpha3", "alpha4",
];
/// Which four-bar columns are angles (compared modulo 2 pi).
pub const FOURBAR_ANGLES: [bool; 9] = [true, false, false, true, true, false, false, false, false];
/// Crank speed (rad/s) and angular acceleration (rad/s^2) of the four-bar
/// sweep: the example's 250 rad/s and an acceleration whose term is comparable
/// to the omega^2 term (as in `tests/examples/kinematics.rs`).
pub const FOURBAR_MOTION: (f64, f64) = (250.0, 2.0e4);

/// One four-bar row at crank angle `theta` (rad).
pub fn fourbar_row<T: Real>(theta: f64) -> Result<[f64; 9], Error> {
    let m = FourBar::<T>::default();
    let (w, a) = FOURBAR_MOTION;
    let s = m
        .solve(
            &FourBarInput {
                theta2: T::lit(theta),
            },
            &FourBarInput { theta2: T::lit(w) },
            &FourBarInput { theta2: T::lit(a) },
        )
        .map_err(Error::to_f64)?;
    let (p, v, acc) = (&s.position, &s.velocity, &s.acceleration);
    Ok([
        theta,
        p.B.x.as_f64(),
        p.B.y.as_f64(),
        p.link3.as_f64(),
        p.link4.as_f64(),
        v.link3.as_f64(),
        v.link4.as_f64(),
        acc.link3.as_f64(),
        acc.link4.as_f64(),
    ])
}

/// Shaper (seed 001, m) columns.
pub const SHAPER_COLUMNS: [&str; 9] = [
    "crank", "E.x", "theta3", "theta4", "omega3", "omega4", "v_E", "alpha3", "a_E",
];
/// Which shaper columns are angles (compared modulo 2 pi).
pub const SHAPER_ANGLES: [bool; 9] = [true, false, true, true, false, false, false, false, false];
/// Crank speed and acceleration of the shaper sweep (as in `tests/examples/kinematics.rs`).
pub const SHAPER_MOTION: (f64, f64) = (1.0, 0.7);

/// One shaper row at crank angle `crank` (rad).
pub fn shaper_row<T: Real>(crank: f64) -> Result<[f64; 9], Error> {
    let m = Shaper::<T>::default();
    let (w, a) = SHAPER_MOTION;
    let s = m
        .solve(
            &ShaperInput {
                crank: T::lit(crank),
            },
            &ShaperInput { crank: T::lit(w) },
            &ShaperInput { crank: T::lit(a) },
        )
        .map_err(Error::to_f64)?;
    let (p, v, acc) = (&s.position, &s.velocity, &s.acceleration);
    Ok([
        crank,
        p.E.x.as_f64(),
        p.link3.as_f64(),
        p.link4.as_f64(),
        v.link3.as_f64(),
        v.link4.as_f64(),
        v.E.x.as_f64(),
        acc.link3.as_f64(),
        acc.E.x.as_f64(),
    ])
}

/// Shaper with masses (seed 001, m, kg, N) columns: the crank torque and the
/// joint reactions (N, N m).
pub const SHAPER_FORCES_COLUMNS: [&str; 9] = [
    "crank",
    "drive_crank",
    "r_ground_link2.x",
    "r_ground_link2.y",
    "r_ground_link3.x",
    "r_ground_link3.y",
    "r_link3_link4.x",
    "r_block_link3.normal",
    "r_ground_ram_block.normal",
];
/// Which force columns are angles (compared modulo 2 pi).
pub const SHAPER_FORCES_ANGLES: [bool; 9] =
    [true, false, false, false, false, false, false, false, false];
/// Crank speed (rad/s, the example's 60 rpm), angular acceleration (rad/s^2:
/// non-zero, so the crank's own term is in the torque) and the cutting load
/// (N, along the ram guide) of the force sweep.
pub const SHAPER_FORCES_MOTION: (f64, f64, f64) = (2.0 * core::f64::consts::PI, 3.0, 2000.0);

/// One row of the shaper's force analysis at crank angle `crank` (rad).
pub fn shaper_forces_row<T: Real>(crank: f64) -> Result<[f64; 9], Error> {
    let m = ShaperForces::<T>::default();
    let (w, a, cut) = SHAPER_FORCES_MOTION;
    let s = m
        .solve(
            &ShaperForcesInput {
                crank: T::lit(crank),
            },
            &ShaperForcesInput { crank: T::lit(w) },
            &ShaperForcesInput { crank: T::lit(a) },
            &ShaperForcesLoads { cut: T::lit(cut) },
        )
        .map_err(Error::to_f64)?;
    let f = &s.forces;
    Ok([
        crank,
        f.drive_crank.as_f64(),
        f.r_ground_link2.x.as_f64(),
        f.r_ground_link2.y.as_f64(),
        f.r_ground_link3.x.as_f64(),
        f.r_ground_link3.y.as_f64(),
        f.r_link3_link4.x.as_f64(),
        f.r_block_link3.normal.as_f64(),
        f.r_ground_ram_block.normal.as_f64(),
    ])
}
