//! The rate tests: velocities and accelerations against central finite
//! differences of positions and velocities, with a Richardson error estimate
//! as the tolerance; and the output rows of the rate structs they compare.

use super::Context;
use crate::model::Level;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// `RateRow` for the velocity and acceleration structs the definition's
/// analysis level generates.
pub(super) fn row_impls(cx: &Context) -> TokenStream {
    let (name, k) = (cx.name, cx.rows.len());
    let rate_row = &cx.rows.rate;
    let mut rate_impls = TokenStream::new();
    for (level, ty) in [
        (Level::Velocity, "Velocity"),
        (Level::Acceleration, "Acceleration"),
    ] {
        if cx.model.level >= level {
            let ty = format_ident!("{}{}", name, ty);
            rate_impls.extend(quote! {
                impl<T: ::mechanism::Real> RateRow for #ty<T> {
                    fn row(&self) -> [f64; #k] { let v = self; [#(#rate_row),*] }
                }
            });
        }
    }
    rate_impls
}

/// The central difference of velocities along `q + W t + A t^2 / 2`; it
/// exists only where velocities do (`analysis position;` generates no
/// `velocity`).
pub(super) fn fd_vel(cx: &Context) -> TokenStream {
    if !cx.velocity {
        return quote!();
    }
    let (name, d, k) = (cx.name, cx.d, cx.rows.len());
    quote! {
        /// Central difference of velocities along `q + W t + A t^2 / 2`.
        fn fd_vel(m: &#name<f64>, q: [f64; #d], scale: f64) -> Option<[f64; #k]> {
            let at = |t: f64| -> Option<[f64; #k]> {
                let mut x = q;
                let mut w = W;
                for i in 0..#d { x[i] += W[i] * t + 0.5 * A[i] * t * t; w[i] += A[i] * t; }
                let p = m.position(&input(x)).ok()?;
                m.velocity(&p, &input(w)).ok().map(|v| rate_row(&v))
            };
            let h = scale * H_MIN;
            let (a, b) = (at(h)?, at(-h)?);
            let mut d = [0.0; #k];
            for j in 0..#k { d[j] = (a[j] - b[j]) / (2.0 * h); }
            Some(d)
        }
    }
}

/// The generated `velocity_vs_finite_differences` test (none below the
/// velocity level).
fn velocity(cx: &Context) -> TokenStream {
    if !cx.velocity {
        return quote!();
    }
    let name = cx.name;
    quote! {
        /// Velocities against central differences of positions along
        /// `q(t) = q0 + W t`: `D(h) = (p(t + h) - p(t - h)) / 2h` with
        /// `h` = 1e-4 (time; the rates `W` are 1 rad or 1 range width
        /// per unit of time, so an input moves by 1e-4 of it). Its error
        /// is `c h^2` (estimated by `|D(2h) - D(h)|`, three times it) plus
        /// rounding, `eps_p / h` with `eps_p` = 16 eps times the size of
        /// the column (the mechanism's size for lengths, size / shortest
        /// link for angles); the velocity's own rounding adds 16 eps
        /// times the largest velocity of its kind (it dominates where `h`
        /// is large: a displacement input far above unit scale). A wrong
        /// velocity is off by its own magnitude.
        #[test]
        fn velocity_vs_finite_differences() {
            let m = #name::<f64>::default();
            let mut checked = 0usize;
            for s in 0..samples() {
                let q = sample(s);
                let Ok(pos) = m.position(&input(q)) else { continue };
                let Ok(v) = m.velocity(&pos, &input(W)) else { continue };
                let Some(d1) = fd_pos(&m, q, 1.0) else { continue };
                let Some(d2) = fd_pos(&m, q, 2.0) else { continue };
                let got = rate_row(&v);
                let size = size_of(&pos);
                let (got_len, got_ang) = family_max(&got);
                for j in 0..K {
                    let eps_p = 16.0 * f64::EPSILON * if ANGLE[j] { size / L_MIN } else { size };
                    let own = 16.0 * f64::EPSILON * if ANGLE[j] { got_ang } else { got_len };
                    let tol = (d2[j] - d1[j]).abs() + 2.0 * eps_p / H_MIN + own;
                    assert!((got[j] - d1[j]).abs() <= tol, "sample {q:?}, column {j}: velocity {} vs finite difference {} (tolerance {tol:e})", got[j], d1[j]);
                }
                checked += 1;
            }
            assert!(checked > 0, "no sample could be checked");
        }
    }
}

/// The generated `acceleration_vs_finite_differences` test (none below the
/// acceleration level).
fn acceleration(cx: &Context) -> TokenStream {
    if !cx.acceleration {
        return quote!();
    }
    let name = cx.name;
    quote! {
        /// Accelerations against central differences of velocities along
        /// `q(t) = q0 + W t + A t^2 / 2`, rates `W + A t` (the input
        /// accelerations `A` nonzero, so their terms are exercised);
        /// tolerance as for the velocities, with the velocity columns'
        /// largest magnitude for the rounding term of the difference.
        #[test]
        fn acceleration_vs_finite_differences() {
            let m = #name::<f64>::default();
            let mut checked = 0usize;
            for s in 0..samples() {
                let q = sample(s);
                let Ok(pos) = m.position(&input(q)) else { continue };
                let Ok(vel) = m.velocity(&pos, &input(W)) else { continue };
                let Ok(a) = m.acceleration(&pos, &vel, &input(A)) else { continue };
                let Some(d1) = fd_vel(&m, q, 1.0) else { continue };
                let Some(d2) = fd_vel(&m, q, 2.0) else { continue };
                let v = rate_row(&vel);
                let got = rate_row(&a);
                let (v_len, v_ang) = family_max(&v);
                let (got_len, got_ang) = family_max(&got);
                for j in 0..K {
                    let eps_v = 16.0 * f64::EPSILON * if ANGLE[j] { v_ang } else { v_len };
                    let own = 16.0 * f64::EPSILON * if ANGLE[j] { got_ang } else { got_len };
                    let tol = (d2[j] - d1[j]).abs() + 2.0 * eps_v / H_MIN + own;
                    assert!((got[j] - d1[j]).abs() <= tol, "sample {q:?}, column {j}: acceleration {} vs finite difference {} (tolerance {tol:e})", got[j], d1[j]);
                }
                checked += 1;
            }
            assert!(checked > 0, "no sample could be checked");
        }
    }
}

/// The rate tests the analysis level allows: velocities, then accelerations.
pub(super) fn tests(cx: &Context) -> TokenStream {
    let mut out = velocity(cx);
    out.extend(acceleration(cx));
    out
}
