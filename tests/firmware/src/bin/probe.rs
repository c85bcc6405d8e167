//! Measurement probe for `scripts/embedded-measure.sh`: runs one scene (chosen
//! by a cargo feature; no feature is the empty baseline in `f64`, `base32`
//! the one in `f32`) over the 72 crank
//! angles of the sweeps, each evaluation between the calls `probe_start()` and
//! `probe_end()`, so that a QEMU single-step trace counts the instructions of
//! each evaluation, and the `.text` of this binary minus the baseline's is the
//! code the scene pulls in. The scene is called through a function pointer in
//! `black_box` and its inputs and result pass through `black_box`, so nothing
//! is folded at compile time.
//!
//! Scenes (f32 or f64): the seed 002 four-bar of `examples/common/scenes.rs`
//! (mm, run-time `params`), each defined here as a user of that scene would
//! define it: the outputs are the coupler joint `B` and the two link angles
//! (`outputs { B, link3, link4 }`: no coupler point `P`, no crank angle, which
//! is the input), and `analysis` stops where the scene stops. `pos*`
//! position only (`FourBarPos`, `analysis position`); `vel*` position and
//! velocity (`FourBarVel`, `analysis velocity`); `acc*` position, velocity
//! and acceleration (`FourBarAcc`, `solve`); `forces*` that plus the
//! generated `forces()` (the same four-bar in metres with masses,
//! `FourBarForces` below); `crank32` / `cossin32` the crank driver alone from
//! an angle or from `(cos, sin)`; `dyn32` one `q''` of the `run_up` four-bar
//! (`examples/common/run_up.rs`, `RunUp` below): `position` then `dynamics`
//! under the DC motor's torque; `dynkin32` the same definition's position,
//! velocity and acceleration (`solve`), for the ratio.
#![no_std]
#![no_main]
#![allow(dead_code, unused_imports)]

use core::hint::black_box;
use cortex_m_rt::entry;
use cortex_m_semihosting::debug;
use panic_semihosting as _;

#[path = "../../../../examples/common/scenes.rs"]
mod scenes;

use mechanism::{Point2, Real};
use scenes::FourBar;

#[cfg(any(feature = "pos32", feature = "pos64"))]
mechanism::mechanism! {
    /// Position only: the coupler joint and the two link angles.
    pub FourBarPos {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        dof 1;
        analysis position;
        outputs { B, link3, link4 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
    }
}

#[cfg(any(feature = "vel32", feature = "vel64"))]
mechanism::mechanism! {
    /// Up to velocity: the coupler joint and the two links.
    pub FourBarVel {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        dof 1;
        analysis velocity;
        outputs { B, link3, link4 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
    }
}

#[cfg(any(feature = "acc32", feature = "acc64"))]
mechanism::mechanism! {
    /// Up to acceleration: the coupler joint and the two links.
    pub FourBarAcc {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        dof 1;
        analysis acceleration;
        outputs { B, link3, link4 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
    }
}

#[cfg(any(feature = "forces32", feature = "forces64"))]
mechanism::mechanism! {
    /// The seed 002 four-bar in metres with masses (kg, kg m^2): coupler
    /// 1.2 kg at its midpoint, rocker 0.9 kg at its midpoint, gravity, and a
    /// 5 N m clockwise couple on the rocker.
    pub FourBarForces {
        params { ground = 0.3048, crank = 0.1016, coupler = 0.254, rocker = 0.1778 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        let G3 = point(link3, from A, 0.127, 0 deg);
        let G4 = point(link4, from O4, 0.0889, 0 deg);
        mass link3 { m = 1.2, at = G3, j = 0.0065 };
        mass link4 { m = 0.9, at = G4, j = 0.0024 };
        gravity (0.0, -9.81);
        torque on link4 = -5.0;
    }
}

#[cfg(feature = "ik32")]
mechanism::mechanism! {
    /// The five-bar robot given its end point (m, kg, N): arms 0.12 kg and
    /// forearms 0.09 kg at their midpoints, a 0.05 kg effector, gravity,
    /// a 2 N payload, and its two motors' torques.
    pub FiveBarIk {
        let O1 = ground(0.0, 0.0);
        let O2 = ground(0.08, 0.0);
        let P = target(x, y) as effector;
        let A = rrr(O1, 0.1, P, 0.16, left) as (arm1, fore1);
        let C = rrr(O2, 0.1, P, 0.16, right) as (arm2, fore2);
        let G1 = point(arm1, from O1, 0.05, 0 deg);
        let G2 = point(arm2, from O2, 0.05, 0 deg);
        let H1 = point(fore1, from P, 0.08, 0 deg);
        let H2 = point(fore2, from P, 0.08, 0 deg);
        mass arm1 { m = 0.12, at = G1, j = 1.1e-4 };
        mass arm2 { m = 0.12, at = G2, j = 1.1e-4 };
        mass fore1 { m = 0.09, at = H1, j = 2.0e-4 };
        mass fore2 { m = 0.09, at = H2, j = 2.0e-4 };
        mass effector { m = 0.05, at = P };
        gravity (0.0, -9.81);
        force at P on effector = (0.0, -2.0);
        motor q1 = angle(arm1);
        motor q2 = angle(arm2);
        outputs { arm1, arm2 }
    }
}

#[cfg(any(feature = "dyn32", feature = "dynkin32"))]
mechanism::mechanism! {
    /// The `run_up` four-bar (m, kg, s) with its flywheel (0.02 kg m^2).
    pub RunUp {
        analysis dynamics;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.30, 0.0);
        let A = crank(O2, 0.10, phi) as crank;
        let B = rrr(A, 0.25, O4, 0.18, left) as (coupler, rocker);
        let G2 = point(crank, from O2, 0.05, 0 deg);
        let G3 = point(coupler, from A, 0.125, 0 deg);
        let G4 = point(rocker, from O4, 0.09, 0 deg);
        mass crank { m = 0.5, at = G2, j = 4.0e-4 };
        mass crank { m = 2.0, at = O2, j = 0.02 };
        mass coupler { m = 1.2, at = G3, j = 6.5e-3 };
        mass rocker { m = 0.9, at = G4, j = 2.5e-3 };
        gravity (0.0, -9.81);
    }
}

/// Marks the start of one evaluation (the trace counts from its entry).
#[no_mangle]
#[inline(never)]
pub extern "C" fn probe_start() {
    // An opaque use of a distinct constant: the call can be neither removed
    // nor merged with `probe_end`.
    black_box(1u32);
}

/// Marks the end of one evaluation (the trace stops counting at its entry).
#[no_mangle]
#[inline(never)]
pub extern "C" fn probe_end() {
    black_box(2u32);
}

#[cfg(any(
    feature = "base32",
    feature = "pos32",
    feature = "vel32",
    feature = "acc32",
    feature = "forces32",
    feature = "crank32",
    feature = "cossin32",
    feature = "ik32",
    feature = "dyn32",
    feature = "dynkin32"
))]
type T = f32;
#[cfg(not(any(
    feature = "base32",
    feature = "pos32",
    feature = "vel32",
    feature = "acc32",
    feature = "forces32",
    feature = "crank32",
    feature = "cossin32",
    feature = "ik32",
    feature = "dyn32",
    feature = "dynkin32"
)))]
type T = f64;

#[cfg(any(feature = "pos32", feature = "pos64"))]
fn scene(_m: &FourBar<T>, q: T) -> impl Sized {
    let m = black_box(FourBarPos::<T>::default());
    m.position(&FourBarPosInput { theta2: q })
}

#[cfg(any(feature = "vel32", feature = "vel64"))]
fn scene(_m: &FourBar<T>, q: T) -> impl Sized {
    let m = black_box(FourBarVel::<T>::default());
    let p = m.position(&FourBarVelInput { theta2: q })?;
    let v = m.velocity(
        &p,
        &FourBarVelInput {
            theta2: T::lit(250.0),
        },
    )?;
    Ok::<_, mechanism::Error<T>>((p, v))
}

#[cfg(any(feature = "acc32", feature = "acc64"))]
fn scene(_m: &FourBar<T>, q: T) -> impl Sized {
    let m = black_box(FourBarAcc::<T>::default());
    m.solve(
        &FourBarAccInput { theta2: q },
        &FourBarAccInput {
            theta2: T::lit(250.0),
        },
        &FourBarAccInput {
            theta2: T::lit(2.0e4),
        },
    )
}

/// Position, velocity, acceleration and forces (`solve` of a definition with
/// masses computes all four).
#[cfg(any(feature = "forces32", feature = "forces64"))]
fn scene(_m: &FourBar<T>, q: T) -> impl Sized {
    let m = black_box(FourBarForces::<T>::default());
    m.solve(
        &FourBarForcesInput { theta2: q },
        &FourBarForcesInput {
            theta2: T::lit(250.0),
        },
        &FourBarForcesInput {
            theta2: T::lit(2.0e4),
        },
    )
}

/// Inverse kinematics: the motor angles, rates, accelerations and torques
/// for an end point on a line through the workspace (x 0.02..0.082 m,
/// y 0.18..0.211 m as the angle runs over a turn: no sine or cosine is
/// linked for it), moving and accelerating.
#[cfg(feature = "ik32")]
fn scene(_m: &FourBar<T>, q: T) -> impl Sized {
    let m = black_box(FiveBarIk::<T>::default());
    let p = FiveBarIkInput {
        x: T::lit(0.02) + T::lit(0.01) * q,
        y: T::lit(0.18) + T::lit(0.005) * q,
    };
    let v = FiveBarIkInput {
        x: T::lit(0.3),
        y: T::lit(-0.2),
    };
    let a = FiveBarIkInput {
        x: T::lit(1.5),
        y: T::lit(2.5),
    };
    let s = m.solve(&p, &v, &a)?;
    let f = m.forces(&s.position, &s.velocity, &s.acceleration)?;
    Ok::<_, mechanism::Error<T>>((s.position.arm1, s.position.arm2, f.drive_q1, f.drive_q2))
}

/// One `q''` of the run-up: the pose at the crank angle, then the
/// equations of motion at 20 rad/s under the motor's torque
/// `1.2 (1 - omega / 40)` N m.
#[cfg(feature = "dyn32")]
fn scene(_m: &FourBar<T>, q: T) -> impl Sized {
    let m = black_box(RunUp::<T>::default());
    let omega = T::lit(20.0);
    let tau = mechanism::ode::drive::DcMotor::new(T::lit(1.2), T::lit(40.0)).torque(omega);
    let p = m.position(&RunUpInput { phi: q })?;
    let d = m.dynamics(&p, &RunUpInput { phi: omega }, &RunUpInput { phi: tau })?;
    Ok::<_, mechanism::Error<T>>(d.accels.phi)
}

/// The run-up four-bar's position, velocity and acceleration at 20 rad/s
/// and 10 rad/s^2 (the kinematics `q''` is compared with; `solve` would add
/// the forces of this definition with masses).
#[cfg(feature = "dynkin32")]
fn scene(_m: &FourBar<T>, q: T) -> impl Sized {
    let m = black_box(RunUp::<T>::default());
    let p = m.position(&RunUpInput { phi: q })?;
    let v = m.velocity(&p, &RunUpInput { phi: T::lit(20.0) })?;
    let a = m.acceleration(&p, &v, &RunUpInput { phi: T::lit(10.0) })?;
    Ok::<_, mechanism::Error<T>>((p, v, a))
}

#[cfg(feature = "crank32")]
fn scene(m: &FourBar<T>, q: T) -> impl Sized {
    mechanism::driver::crank::position(&Point2::origin(), m.crank, q)
}

/// The crank from `(cos, sin)`, as from an encoder's reading.
#[cfg(feature = "cossin32")]
fn scene(m: &FourBar<T>, cs: (T, T)) -> impl Sized {
    mechanism::driver::crank::position_cos_sin(&Point2::origin(), m.crank, cs.0, cs.1)
}

/// Baseline: the same calls around a function that does nothing.
#[cfg(not(any(
    feature = "pos32",
    feature = "vel32",
    feature = "acc32",
    feature = "forces32",
    feature = "crank32",
    feature = "cossin32",
    feature = "ik32",
    feature = "dyn32",
    feature = "dynkin32",
    feature = "pos64",
    feature = "vel64",
    feature = "acc64",
    feature = "forces64"
)))]
fn scene(_m: &FourBar<T>, q: T) -> impl Sized {
    q
}

/// The 72 crank angles 0, 5, ..., 355 deg in rad, computed at compile time:
/// converting at run time would link software-double routines (`f64`
/// products, `f64` to `f32`) into the probe and count them as the scene's.
static ANGLES: [T; 72] = {
    let mut a = [0.0; 72];
    let mut i = 0;
    while i < 72 {
        a[i] = (5.0 * i as f64 * (core::f64::consts::PI / 180.0)) as T;
        i += 1;
    }
    a
};

#[entry]
fn main() -> ! {
    let m = black_box(FourBar::<T>::default());
    for &q in ANGLES.iter() {
        // An arbitrary non-zero, non-unit pair: the driver normalizes it, and
        // its cost does not depend on the values (no sine or cosine is linked
        // into this probe, so its size is the (cos, sin) path alone).
        #[cfg(feature = "cossin32")]
        let q = (q, T::lit(1.0) - q);
        let f = black_box(scene as fn(&_, _) -> _);
        let q = black_box(q);
        probe_start();
        let r = f(&m, q);
        probe_end();
        // By reference: passing the result by value would copy it (a
        // `memcpy` of the solution struct, linked and counted as the scene's).
        black_box(&r);
    }
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}
