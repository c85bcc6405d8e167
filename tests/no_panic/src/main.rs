//! No panics, proved at link time: with the `no-panic` feature every function
//! below carries `#[no_panic]`, which makes the link fail if the optimizer
//! cannot remove every path to a panic from it (the `no-panic` crate's
//! method: a guard whose destructor, run only while unwinding, calls an
//! undefined symbol).
//!
//! Run: `cargo run --release --features no-panic` (from this directory; fat
//! LTO is set in `Cargo.toml`, the `.ci/run` also sets
//! `CARGO_PROFILE_RELEASE_LTO=fat`). Each function is called through a
//! function pointer passed through `black_box`, with inputs from
//! `black_box`: with known arguments the optimizer could fold a panic path
//! away at the call site and the check would pass for the wrong reason.
//!
//! Checked: `position`, `velocity`, `acceleration` and `solve` of every
//! example mechanism (`examples/common/scenes.rs`) in f32 and f64, `solve`
//! (with the generated `forces()`) of the definitions with masses, and the
//! f32 kernels `sin_cos_f32`, `sqrt_f32` and `atan2_f32`, and the f64 kernel
//! `trig64::atan2_f64`.

#[path = "../../../examples/common/scenes.rs"]
mod scenes;

use mechanism::trig::{atan2_f32, sin_cos_f32, sqrt_f32};
use mechanism::Error;
#[cfg(feature = "no-panic")]
use no_panic::no_panic;
use scenes::*;
use std::hint::black_box;

/// One checked wrapper per generated function and scalar: `$name` calls
/// `$m::<$t>::$f` on its inputs.
macro_rules! checked {
    ($($name:ident: $m:ident, $input:ident, $t:ty;)*) => {
        $(
            #[allow(non_snake_case)]
            mod $name {
                use super::*;
                #[cfg_attr(feature = "no-panic", no_panic)]
                #[inline(never)]
                pub fn position(m: &$m<$t>, q: &$input<$t>) -> Result<(), Error<$t>> {
                    black_box(m.position(q)?);
                    Ok(())
                }
                #[cfg_attr(feature = "no-panic", no_panic)]
                #[inline(never)]
                pub fn velocity(m: &$m<$t>, q: &$input<$t>, w: &$input<$t>) -> Result<(), Error<$t>> {
                    let p = m.position(q)?;
                    black_box(m.velocity(&p, w)?);
                    Ok(())
                }
                #[cfg_attr(feature = "no-panic", no_panic)]
                #[inline(never)]
                pub fn acceleration(
                    m: &$m<$t>,
                    q: &$input<$t>,
                    w: &$input<$t>,
                    a: &$input<$t>,
                ) -> Result<(), Error<$t>> {
                    let p = m.position(q)?;
                    let v = m.velocity(&p, w)?;
                    black_box(m.acceleration(&p, &v, a)?);
                    Ok(())
                }
                #[cfg_attr(feature = "no-panic", no_panic)]
                #[inline(never)]
                pub fn solve(
                    m: &$m<$t>,
                    q: &$input<$t>,
                    w: &$input<$t>,
                    a: &$input<$t>,
                ) -> Result<(), Error<$t>> {
                    black_box(m.solve(q, w, a)?);
                    Ok(())
                }
            }
        )*
    };
}

checked! {
    fourbar32: FourBar, FourBarInput, f32;
    fourbar64: FourBar, FourBarInput, f64;
    sixbar32: SixBar, SixBarInput, f32;
    sixbar64: SixBar, SixBarInput, f64;
    shaper32: Shaper, ShaperInput, f32;
    shaper64: Shaper, ShaperInput, f64;
    slider32: SliderCrank, SliderCrankInput, f32;
    slider64: SliderCrank, SliderCrankInput, f64;
    fivebar32: FiveBar, FiveBarInput, f32;
    fivebar64: FiveBar, FiveBarInput, f64;
}

/// The definitions with masses: `solve` there also runs the generated
/// `forces()` (kinetostatics).
macro_rules! checked_forces {
    ($($name:ident: $m:ident, $input:ident, $t:ty $(, $loads:ident)?;)*) => {
        $(
            #[cfg_attr(feature = "no-panic", no_panic)]
            #[inline(never)]
            fn $name(m: &$m<$t>, q: &$input<$t>, w: &$input<$t>, a: &$input<$t> $(, l: &$loads<$t>)?) -> Result<(), Error<$t>> {
                black_box(m.solve(q, w, a $(, l as &$loads<$t>)?)?);
                Ok(())
            }
        )*
    };
}

checked_forces! {
    sine32: SineMechanism, SineMechanismInput, f32;
    sine64: SineMechanism, SineMechanismInput, f64;
    shaper_forces32: ShaperForces, ShaperForcesInput, f32, ShaperForcesLoads;
    shaper_forces64: ShaperForces, ShaperForcesInput, f64, ShaperForcesLoads;
}

#[cfg_attr(feature = "no-panic", no_panic)]
#[inline(never)]
fn kernels(x: f32) -> (f32, f32, f32, f32) {
    let (s, c) = sin_cos_f32(x);
    (s, c, sqrt_f32(x), atan2_f32(s, x))
}

#[cfg_attr(feature = "no-panic", no_panic)]
#[inline(never)]
fn kernel64(y: f64, x: f64) -> f64 {
    mechanism::trig64::atan2_f64(y, x)
}

/// Calls all four analyses of one mechanism through function pointers hidden
/// from the optimizer; returns how many succeeded.
macro_rules! run {
    ($module:ident, $m:ident, $input:ident, $t:ty, { $($field:ident),* }, $q:expr) => {{
        let m = black_box($m::<$t>::default());
        let input = |x: f64| $input { $($field: black_box(x as $t)),* };
        let (q, w, a) = (input($q), input(1.5), input(-0.5));
        let p: fn(&$m<$t>, &$input<$t>) -> Result<(), Error<$t>> = black_box($module::position);
        let v: fn(&$m<$t>, &$input<$t>, &$input<$t>) -> Result<(), Error<$t>> =
            black_box($module::velocity);
        type Full = fn(&$m<$t>, &$input<$t>, &$input<$t>, &$input<$t>) -> Result<(), Error<$t>>;
        let acc: Full = black_box($module::acceleration);
        let s: Full = black_box($module::solve);
        [p(&m, &q), v(&m, &q, &w), acc(&m, &q, &w, &a), s(&m, &q, &w, &a)]
            .iter()
            .filter(|r| r.is_ok())
            .count()
    }};
}

/// Calls one checked force function through a hidden function pointer;
/// 1 if it succeeded.
macro_rules! forces {
    ($f:ident, $m:ident, $input:ident, $t:ty, $field:ident, $q:expr) => {{
        let m = black_box($m::<$t>::default());
        let input = |x: f64| $input {
            $field: black_box(x as $t),
        };
        type F = fn(&$m<$t>, &$input<$t>, &$input<$t>, &$input<$t>) -> Result<(), Error<$t>>;
        let f: F = black_box($f);
        usize::from(f(&m, &input($q), &input(1.5), &input(-0.5)).is_ok())
    }};
    ($f:ident, $m:ident, $input:ident, $t:ty, $field:ident, $q:expr, $loads:ident { $lf:ident: $lv:expr }) => {{
        let m = black_box($m::<$t>::default());
        let input = |x: f64| $input {
            $field: black_box(x as $t),
        };
        let loads = $loads {
            $lf: black_box($lv as $t),
        };
        type F = fn(
            &$m<$t>,
            &$input<$t>,
            &$input<$t>,
            &$input<$t>,
            &$loads<$t>,
        ) -> Result<(), Error<$t>>;
        let f: F = black_box($f);
        usize::from(f(&m, &input($q), &input(1.5), &input(-0.5), &loads).is_ok())
    }};
}

fn main() {
    let mut ok = 0;
    for step in 0..8 {
        let q = 0.8 * step as f64;
        ok += run!(fourbar32, FourBar, FourBarInput, f32, { theta2 }, q);
        ok += run!(fourbar64, FourBar, FourBarInput, f64, { theta2 }, q);
        ok += run!(sixbar32, SixBar, SixBarInput, f32, { phi1 }, q);
        ok += run!(sixbar64, SixBar, SixBarInput, f64, { phi1 }, q);
        ok += run!(shaper32, Shaper, ShaperInput, f32, { crank }, q);
        ok += run!(shaper64, Shaper, ShaperInput, f64, { crank }, q);
        ok += run!(slider32, SliderCrank, SliderCrankInput, f32, { theta }, q);
        ok += run!(slider64, SliderCrank, SliderCrankInput, f64, { theta }, q);
        ok += run!(fivebar32, FiveBar, FiveBarInput, f32, { q1, q2 }, q);
        ok += run!(fivebar64, FiveBar, FiveBarInput, f64, { q1, q2 }, q);
        ok += forces!(sine32, SineMechanism, SineMechanismInput, f32, phi1, q);
        ok += forces!(sine64, SineMechanism, SineMechanismInput, f64, phi1, q);
        ok += forces!(
            shaper_forces32,
            ShaperForces,
            ShaperForcesInput,
            f32,
            crank,
            q,
            ShaperForcesLoads { cut: -5000.0 }
        );
        ok += forces!(
            shaper_forces64,
            ShaperForces,
            ShaperForcesInput,
            f64,
            crank,
            q,
            ShaperForcesLoads { cut: -5000.0 }
        );
        let k: fn(f32) -> (f32, f32, f32, f32) = black_box(kernels);
        black_box(k(black_box(q as f32 * 1.0e3)));
        let k64: fn(f64, f64) -> f64 = black_box(kernel64);
        black_box(k64(black_box(q - 2.0), black_box(1.0 - q)));
    }
    println!(
        "no-panic: {} analyses run ({ok} succeeded); checks {}",
        8 * (10 * 4 + 4),
        if cfg!(feature = "no-panic") {
            "on (the link proved them)"
        } else {
            "off"
        }
    );
}
