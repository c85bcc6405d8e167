//! The generated module's constants and helper functions: the input
//! samples, 2-D vector arithmetic on `[f64; 2]`, the residuals of every
//! constraint, output rows and the central difference of positions.

use super::closure::{shortest_link, Constraints};
use super::Context;
use crate::kinds::reads::Reads;
use crate::model::Model;
use crate::plan::Outputs;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

/// The output columns of the generated tests: each point's x and y, each
/// link angle, each slide.
pub(super) struct OutputRows {
    /// Code of each column from a position (`pos`), as `f64`.
    pub pos: Vec<TokenStream>,
    /// Code of each column from a velocity or acceleration (`v`), as `f64`.
    pub rate: Vec<TokenStream>,
    /// `true` for an angle column (rad; differences wrap), `false` for a
    /// length.
    pub angle: Vec<bool>,
}

impl OutputRows {
    /// The columns of the definition's outputs: points, link angles,
    /// slides; `reads` records the reads of the position struct.
    pub fn new(out: &Outputs, reads: &Reads) -> Self {
        let (mut pos, mut rate, mut angle) = (Vec::new(), Vec::new(), Vec::new());
        for p in &out.points {
            let at = reads.pos(p);
            pos.push(quote!(<T as ::mechanism::Real>::as_f64(#at.x)));
            pos.push(quote!(<T as ::mechanism::Real>::as_f64(#at.y)));
            rate.push(quote!(<T as ::mechanism::Real>::as_f64(v.#p.x)));
            rate.push(quote!(<T as ::mechanism::Real>::as_f64(v.#p.y)));
            angle.extend([false, false]);
        }
        for l in &out.links {
            let at = reads.pos(l);
            pos.push(quote!(<T as ::mechanism::Real>::as_f64(#at)));
            rate.push(quote!(<T as ::mechanism::Real>::as_f64(v.#l)));
            angle.push(true);
        }
        for s in out.slides.iter().map(|s| &s.name) {
            let at = reads.pos(s);
            pos.push(quote!(<T as ::mechanism::Real>::as_f64(#at)));
            rate.push(quote!(<T as ::mechanism::Real>::as_f64(v.#s)));
            angle.push(false);
        }
        OutputRows { pos, rate, angle }
    }

    /// The number of columns (`K`).
    pub fn len(&self) -> usize {
        self.pos.len()
    }
}

/// The inputs' ranges and the scales of their trajectories.
struct InputRanges {
    /// Lower ends (rad or the definition's length unit).
    lo: Vec<f64>,
    /// Upper ends.
    hi: Vec<f64>,
    /// Each input's scale: 1 rad for an angle, the range's width for a
    /// displacement.
    unit: Vec<f64>,
}

impl InputRanges {
    /// The ranges of `model`'s inputs (`#[self_test]` requires them all).
    fn new(model: &Model) -> Self {
        let (mut lo, mut hi, mut unit) = (Vec::new(), Vec::new(), Vec::new());
        for i in &model.inputs {
            let r = i.range.expect("self_test requires ranges");
            lo.push(r.lo);
            hi.push(r.hi);
            // The trajectories' input rates are in units of the input's scale
            // (1 rad for an angle, the range's width for a displacement) per
            // unit of time, and the finite differences step time by 1e-4: an
            // input moves by 1e-4 of its scale, and the acceleration term
            // (A h^2 / 2) stays 1e-4 below the rate term at every scale.
            unit.push(if i.angle { 1.0 } else { r.hi - r.lo });
        }
        InputRanges { lo, hi, unit }
    }
}

/// The constants: ranges, trajectory rates, columns, `L_MIN`, labels.
fn constants(cx: &Context, constraints: &Constraints) -> TokenStream {
    let InputRanges { lo, hi, unit } = InputRanges::new(cx.model);
    let (d, k, nres) = (cx.d, cx.rows.len(), constraints.len());
    let angle_col = &cx.rows.angle;
    let l_min = shortest_link(cx);
    let doc_w: Vec<f64> = (0..d).map(|i| [1.0, -0.7][i] * unit[i]).collect();
    let doc_a: Vec<f64> = (0..d).map(|i| [0.5, 0.3][i] * unit[i]).collect();
    let labels_arr = &constraints.labels;
    quote! {
        const LO: [f64; #d] = [#(#lo),*];
        const HI: [f64; #d] = [#(#hi),*];
        /// Finite-difference step in time (every input moves by 1e-4
        /// of its scale per step, see `W`).
        const H_MIN: f64 = 1e-4;
        /// Input rates and accelerations of the trajectories, per unit of
        /// time: 1 rad or one range width (a displacement) times a factor.
        const W: [f64; #d] = [#(#doc_w),*];
        const A: [f64; #d] = [#(#doc_a),*];
        const K: usize = #k;
        const ANGLE: [bool; #k] = [#(#angle_col),*];
        /// Shortest link (defaults): link angles' rounding is the
        /// mechanism's size over it.
        const L_MIN: f64 = #l_min;
        const LABELS: [&str; #nres] = [#(#labels_arr),*];
    }
}

/// The samples of the input range and the input struct built from one.
fn sampling(cx: &Context) -> TokenStream {
    let d = cx.d;
    let input_ty = format_ident!("{}Input", cx.name);
    let input_names: Vec<&Ident> = cx.model.inputs.iter().map(|i| &i.name).collect();
    let ks: Vec<usize> = (0..d).collect();
    let samples_n: usize = if d == 1 { 90 } else { 100 };
    let sample_code = if d == 1 {
        quote!([LO[0] + (HI[0] - LO[0]) * (k as f64 + 0.5) / 90.0])
    } else {
        quote!([
            LO[0] + (HI[0] - LO[0]) * ((k / 10) as f64 + 0.5) / 10.0,
            LO[1] + (HI[1] - LO[1]) * ((k % 10) as f64 + 0.5) / 10.0
        ])
    };
    quote! {
        fn ranges_width() -> f64 { HI[0] - LO[0] }
        fn samples() -> usize { #samples_n }
        /// Interior samples of the range (grid of 10 x 10 for two inputs).
        fn sample(k: usize) -> [f64; #d] { #sample_code }
        fn input<T: ::mechanism::Real>(q: [f64; #d]) -> #input_ty<T> {
            #input_ty { #(#input_names: T::lit(q[#ks]),)* }
        }
    }
}

/// 2-D vector arithmetic on `[f64; 2]`, the assembly-branch measure and
/// angle wrapping.
fn geometry() -> TokenStream {
    quote! {
        fn pt<T: ::mechanism::Real>(p: &::mechanism::Point2<T>) -> [f64; 2] { [p.x.as_f64(), p.y.as_f64()] }
        fn vc<T: ::mechanism::Real>(p: &::mechanism::Vector2<T>) -> [f64; 2] { [p.x.as_f64(), p.y.as_f64()] }
        fn sub(a: [f64; 2], b: [f64; 2]) -> [f64; 2] { [a[0] - b[0], a[1] - b[1]] }
        fn norm(a: [f64; 2]) -> f64 { a[0].hypot(a[1]) }
        fn dot(a: [f64; 2], b: [f64; 2]) -> f64 { a[0] * b[0] + a[1] * b[1] }
        fn cross(a: [f64; 2], b: [f64; 2]) -> f64 { a[0] * b[1] - a[1] * b[0] }
        fn unit_of(a: [f64; 2]) -> [f64; 2] { let n = norm(a); [a[0] / n, a[1] / n] }
        /// `u` turned counter-clockwise by `angle` (rad).
        fn turn(u: [f64; 2], angle: f64) -> [f64; 2] { let (s, c) = angle.sin_cos(); [u[0] * c - u[1] * s, u[1] * c + u[0] * s] }
        /// How far a point lies on the wrong side of its assembly branch (0 on the right one).
        fn wrong_side(signed: f64) -> f64 { if signed < 0.0 { -signed } else { 0.0 } }
        fn wrap(x: f64) -> f64 { let y = x.rem_euclid(2.0 * ::core::f64::consts::PI); if y > ::core::f64::consts::PI { y - 2.0 * ::core::f64::consts::PI } else { y } }
    }
}

/// Measures of a pose: the constraints' residuals, the mechanism's size,
/// output rows, and the groups' conditioning (`sigma`).
fn measures(cx: &Context, constraints: &Constraints) -> TokenStream {
    let (name, k, nres) = (cx.name, cx.rows.len(), constraints.len());
    let position_ty = format_ident!("{}Position", name);
    let codes = &constraints.codes;
    let pos_row = &cx.rows.pos;
    let points: Vec<TokenStream> = cx.points().into_iter().map(|p| cx.reads.pos(p)).collect();
    let dets: Vec<TokenStream> = cx
        .checked
        .groups
        .iter()
        .map(|&i| crate::emit::check_fn::det_code(cx.model, i, cx.reads))
        .collect();
    let ng = dets.len();
    let rate_impls = super::rates::row_impls(cx);
    quote! {
        impl<T: ::mechanism::Real> super::#name<T> {
            /// Residuals of every constraint (length units).
            fn self_test_residuals(&self, pos: &#position_ty<T>) -> [f64; #nres] {
                [#(#codes),*]
            }
        }
        /// The mechanism's size at a pose: the largest point coordinate.
        fn size_of<T: ::mechanism::Real>(pos: &#position_ty<T>) -> f64 {
            let mut s = 0.0f64;
            #( s = s.max(pt(&#points)[0].abs()).max(pt(&#points)[1].abs()); )*
            s
        }
        fn pos_row<T: ::mechanism::Real>(pos: &#position_ty<T>) -> [f64; #k] { [#(#pos_row),*] }
        fn rate_row<V: RateRow>(v: &V) -> [f64; #k] { v.row() }
        /// The largest magnitude among the length columns of `row` and
        /// among its angle columns.
        fn family_max(row: &[f64; #k]) -> (f64, f64) {
            let (mut len, mut ang) = (0.0f64, 0.0f64);
            for j in 0..K {
                if ANGLE[j] { ang = ang.max(row[j].abs()) } else { len = len.max(row[j].abs()) }
            }
            (len, ang)
        }
        /// Output rows of the velocity and acceleration structs.
        trait RateRow { fn row(&self) -> [f64; #k]; }
        #rate_impls
        /// Product of the groups' scaled determinants (each at most 1):
        /// errors of the inputs of a group are amplified by about its
        /// inverse.
        fn sigma<T: ::mechanism::Real>(pos: &#position_ty<T>) -> f64 {
            let d: [f64; #ng] = [#(#dets),*];
            d.iter().fold(1.0, |p, x| p * x.abs().min(1.0))
        }
    }
}

/// The central difference of positions along `q + W t`.
fn fd_pos(cx: &Context) -> TokenStream {
    let (name, d, k) = (cx.name, cx.d, cx.rows.len());
    quote! {
        /// Central difference of positions along `q + W t`, step `scale` h.
        fn fd_pos(m: &#name<f64>, q: [f64; #d], scale: f64) -> Option<[f64; #k]> {
            let at = |t: f64| -> Option<[f64; #k]> {
                let mut x = q;
                for i in 0..#d { x[i] += W[i] * t; }
                m.position(&input(x)).ok().map(|p| pos_row(&p))
            };
            let h = scale * H_MIN;
            let (a, b) = (at(h)?, at(-h)?);
            let mut d = [0.0; #k];
            for j in 0..#k {
                let diff = if ANGLE[j] { wrap(a[j] - b[j]) } else { a[j] - b[j] };
                d[j] = diff / (2.0 * h);
            }
            Some(d)
        }
    }
}

/// Everything the tests share, in the generated order: constants, samples,
/// geometry, pose measures, finite differences.
pub(super) fn emit(cx: &Context, constraints: &Constraints) -> TokenStream {
    let mut out = constants(cx, constraints);
    out.extend(sampling(cx));
    out.extend(geometry());
    out.extend(measures(cx, constraints));
    out.extend(fd_pos(cx));
    out.extend(super::rates::fd_vel(cx));
    out
}
