//! The generated `f32_vs_f64` test: positions and velocities of the two
//! instantiations at inputs both represent exactly.

use super::Context;
use proc_macro2::TokenStream;
use quote::quote;

/// The velocity part of `f32_vs_f64` (none below the velocity level).
fn velocities(cx: &Context) -> TokenStream {
    if !cx.velocity {
        return quote!();
    }
    quote! {
        if let (Ok(v64), Ok(v32)) = (m64.velocity(&p64, &input::<f64>(W)), m32.velocity(&p32, &input::<f32>(W))) {
            let (a, b) = (rate_row(&v64), rate_row(&v32));
            let vmax = a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            for j in 0..K {
                let tol = 64.0 * f32::EPSILON as f64 * vmax / (sigma * sigma);
                assert!((a[j] - b[j]).abs() <= tol, "sample {q:?}, velocity column {j}: f64 {} vs f32 {} (tolerance {tol:e})", a[j], b[j]);
            }
        }
    }
}

/// The generated `f32_vs_f64` test.
pub(super) fn test(cx: &Context) -> TokenStream {
    let name = cx.name;
    let f32_vel = velocities(cx);
    quote! {
        /// f32 against f64 at inputs both represent exactly: positions
        /// within 64 eps_f32 times the size over sigma (the product of
        /// the groups' scaled determinants: how much a group amplifies
        /// errors of its inputs), velocities within 64 eps_f32 times the
        /// largest velocity over sigma^2.
        #[test]
        fn f32_vs_f64() {
            let (m64, m32) = (#name::<f64>::default(), #name::<f32>::default());
            let mut checked = 0usize;
            for s in 0..samples() {
                let mut q = sample(s);
                for x in q.iter_mut() { *x = *x as f32 as f64; }
                let (Ok(p64), Ok(p32)) = (m64.position(&input::<f64>(q)), m32.position(&input::<f32>(q))) else { continue };
                let sigma = sigma(&p64).max(f64::EPSILON);
                let size = size_of(&p64);
                let (a, b) = (pos_row(&p64), pos_row(&p32));
                for j in 0..K {
                    let scale = if ANGLE[j] { size / L_MIN } else { size };
                    let diff = if ANGLE[j] { wrap(a[j] - b[j]) } else { a[j] - b[j] };
                    let tol = 64.0 * f32::EPSILON as f64 * scale / sigma;
                    assert!(diff.abs() <= tol, "sample {q:?}, position column {j}: f64 {} vs f32 {} (tolerance {tol:e})", a[j], b[j]);
                }
                #f32_vel
                checked += 1;
            }
            assert!(checked > 0, "no sample assembles in both");
        }
    }
}
