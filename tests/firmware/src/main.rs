//! The four-bar and shaper sweeps of `rows.rs` and the shaper's force analysis
//! (crank torque, joint reactions), in `f32` and `f64`, on a Cortex-M under
//! QEMU, against the host's `f64` values in `expected.rs`.
//! Prints the worst difference per sweep and exits non-zero on a mismatch (a
//! panic exits non-zero too).
//!
//! `#![no_std]`, `#![no_main]` and no global allocator: if anything in the
//! dependency graph used `alloc`, this binary would not link.
//!
//! Run (from this directory): `timeout 120 cargo run --release` (Cortex-M4F,
//! mps2-an386) or add `--target thumbv7m-none-eabi` (Cortex-M3, lm3s6965evb).
#![no_std]
#![no_main]

use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use panic_semihosting as _;

#[path = "../../../examples/common/scenes.rs"]
mod scenes;

mod expected;
mod rows;

use mechanism::Error;

/// f64 against the host, relative to each column's largest value (pi for
/// angles). Both sides compute the same operations in the same order; they
/// differ only in the elementary functions (libm here, glibc on the host),
/// each within 1 ulp, so each input to the chain moves by at most an eps or
/// two, amplified by the sweeps' conditioning (below about 20, see
/// `tests/examples/kinematics.rs`): up to about 20 eps. 32 eps covers that (about 1 eps
/// observed) and would still catch any wrong operation, which moves values by
/// many orders more.
const TOL64: f64 = 32.0 * f64::EPSILON;

/// f32 against the host's f64, relative to each column's largest value. f32
/// rounds at 1.2e-7 and the chains of a few tens of operations are amplified
/// by the conditioning (transmission angle, rate ratios): `tests/examples/kinematics.rs`
/// observes up to 2.6e-6 for these two mechanisms over more poses and motions
/// (and justifies 2e-5 for all its scenes); here about 3.6e-7 is observed.
/// 5e-6 leaves a factor of 2 over the worst seen on the host. The f32 sine and
/// cosine are `mechanism::trig::sin_cos_f32` (2 ulp).
const TOL32: f64 = 5e-6;

/// f32 force analysis against the host's f64, relative to each column's
/// largest value: the kinematics' error (above) goes through the groups'
/// force systems, whose pivots stay above about 0.1 over the shaper's turn;
/// the report (`docs/report.md`, ShaperForces) measures the generated f32
/// forces at up to 2.4e-6 of a column's largest value against the
/// double-double reference over 3600 poses. 1e-5 is 4 times that; a wrong
/// term moves a reaction by a mass times an acceleration, orders more.
const TOL32_FORCES: f64 = 1e-5;

/// Worst difference of one sweep, relative to its column's scale, and where.
struct Worst {
    rel: f64,
    step: usize,
    column: usize,
}

fn wrap(mut d: f64) -> f64 {
    let two_pi = 2.0 * core::f64::consts::PI;
    while d > core::f64::consts::PI {
        d -= two_pi;
    }
    while d < -core::f64::consts::PI {
        d += two_pi;
    }
    d
}

fn abs(x: f64) -> f64 {
    if x < 0.0 {
        -x
    } else {
        x
    }
}

fn compare(
    table: &[[f64; 9]; rows::STEPS],
    angles: &[bool; 9],
    row: fn(f64) -> Result<[f64; 9], Error>,
) -> Result<Worst, (usize, Error)> {
    let mut scale = [0.0f64; 9];
    for (c, s) in scale.iter_mut().enumerate() {
        *s = if angles[c] {
            core::f64::consts::PI
        } else {
            table
                .iter()
                .fold(0.0, |m, r| if abs(r[c]) > m { abs(r[c]) } else { m })
        };
    }
    let mut worst = Worst {
        rel: 0.0,
        step: 0,
        column: 0,
    };
    for (i, want) in table.iter().enumerate() {
        let got = row(want[0]).map_err(|e| (i, e))?;
        for c in 0..9 {
            let d = got[c] - want[c];
            let d = if angles[c] { wrap(d) } else { d };
            let rel = abs(d) / scale[c];
            // A NaN is kept as the worst (and then fails the tolerance).
            if rel.is_nan() || rel > worst.rel {
                worst = Worst {
                    rel,
                    step: i,
                    column: c,
                };
            }
        }
    }
    Ok(worst)
}

fn check(
    name: &str,
    table: &[[f64; 9]; rows::STEPS],
    angles: &[bool; 9],
    columns: &[&str; 9],
    row: fn(f64) -> Result<[f64; 9], Error>,
    tol: f64,
    scalar: &str,
) -> bool {
    match compare(table, angles, row) {
        Ok(w) => {
            let ok = w.rel <= tol;
            hprintln!(
                "{} {} {}: worst difference {:e} of the column's scale ({} at step {}), tolerance {:e}",
                if ok { "ok  " } else { "FAIL" },
                name,
                scalar,
                w.rel,
                columns[w.column],
                w.step,
                tol
            );
            ok
        }
        Err((i, e)) => {
            hprintln!("FAIL {} {}: error at step {}: {:?}", name, scalar, i, e);
            false
        }
    }
}

/// `mechanism::trig::sqrt_f32` on this core against the exact square root,
/// for 20 000 positive `f32` spread over the whole range (subnormals to
/// `f32::MAX`): correctly rounded on the Cortex-M4F (the FPU's `vsqrt.f32`),
/// at most one representable step away on the Cortex-M3 (the software
/// kernel, as documented). Exact test, no tolerance: `y` is within `k` steps
/// of the correctly rounded root when `x` lies strictly between the squares
/// of the midpoints just outside `y - k steps` and `y + k steps`; those
/// midpoints have 25 significant bits, so their squares (50 bits) and the
/// comparison are exact in `f64`.
fn check_sqrt() -> bool {
    let k = if cfg!(target_abi = "eabihf") { 0 } else { 1 };
    let mut worst_bad = None;
    for i in 1..=20_000u32 {
        let bits = i * (0x7F80_0000 / 20_001);
        let x = f32::from_bits(bits);
        let y = mechanism::trig::sqrt_f32(x);
        let at = |b: u32| f32::from_bits(b) as f64;
        let yb = y.to_bits();
        let (lo, hi) = (yb - k, yb + k);
        let mid_lo = (at(lo - 1) + at(lo)) / 2.0;
        let mid_hi = (at(hi) + at(hi + 1)) / 2.0;
        let xd = x as f64;
        if !(mid_lo * mid_lo < xd && xd < mid_hi * mid_hi) {
            worst_bad = Some((x, y));
            break;
        }
    }
    let what = if k == 0 {
        "correctly rounded"
    } else {
        "within one step"
    };
    match worst_bad {
        None => {
            hprintln!("ok   sqrt_f32: 20000 arguments, each {}", what);
            true
        }
        Some((x, y)) => {
            hprintln!("FAIL sqrt_f32({:e}) = {:e}: not {}", x, y, what);
            false
        }
    }
}

#[entry]
fn main() -> ! {
    let mut ok = check_sqrt();
    ok &= check(
        "fourbar",
        &expected::FOURBAR,
        &rows::FOURBAR_ANGLES,
        &rows::FOURBAR_COLUMNS,
        rows::fourbar_row::<f64>,
        TOL64,
        "f64",
    );
    ok &= check(
        "fourbar",
        &expected::FOURBAR,
        &rows::FOURBAR_ANGLES,
        &rows::FOURBAR_COLUMNS,
        rows::fourbar_row::<f32>,
        TOL32,
        "f32",
    );
    ok &= check(
        "shaper ",
        &expected::SHAPER,
        &rows::SHAPER_ANGLES,
        &rows::SHAPER_COLUMNS,
        rows::shaper_row::<f64>,
        TOL64,
        "f64",
    );
    ok &= check(
        "shaper ",
        &expected::SHAPER,
        &rows::SHAPER_ANGLES,
        &rows::SHAPER_COLUMNS,
        rows::shaper_row::<f32>,
        TOL32,
        "f32",
    );
    ok &= check(
        "forces ",
        &expected::SHAPER_FORCES,
        &rows::SHAPER_FORCES_ANGLES,
        &rows::SHAPER_FORCES_COLUMNS,
        rows::shaper_forces_row::<f64>,
        TOL64,
        "f64",
    );
    ok &= check(
        "forces ",
        &expected::SHAPER_FORCES,
        &rows::SHAPER_FORCES_ANGLES,
        &rows::SHAPER_FORCES_COLUMNS,
        rows::shaper_forces_row::<f32>,
        TOL32_FORCES,
        "f32",
    );
    hprintln!(
        "{}",
        if ok {
            "firmware: all sweeps match the host"
        } else {
            "firmware: MISMATCH"
        }
    );
    debug::exit(if ok {
        debug::EXIT_SUCCESS
    } else {
        debug::EXIT_FAILURE
    });
    loop {
        cortex_m::asm::wfi();
    }
}
