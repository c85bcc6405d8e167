//! `#[self_test]`: a `#[cfg(test)]` module of tests for one mechanism, over
//! its input range, with the definition's default parameters:
//!
//! - `check`: the generated `check()` finds that every group assembles, and
//!   (when the macro checked at expansion time) the same singular positions;
//! - `loop_closure_f64`, `loop_closure_f32`: every constraint of every group
//!   the position analysis solves (distances, points on lines, assembly
//!   branches, points on links), recomputed from the solved points;
//! - `velocity_vs_finite_differences`, `acceleration_vs_finite_differences`:
//!   central differences of positions (velocities) along an input trajectory,
//!   with a Richardson error estimate as the tolerance;
//! - `power_balance` (with a force analysis): the generated residual;
//! - `f32_vs_f64`: positions and velocities of the two instantiations.
//!
//! The constraints are written here from the definition, not from the
//! generated position code: a wrong formula there fails them.

use crate::check::Findings;
use crate::model::{Allowed, Kind, Level, Local, Mode, Model, Origin, Stmt};
use crate::plan::checked;
use crate::plan::Plan;
use crate::value::{Value, ValueKind};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

/// A value with run-time parameters at their defaults.
fn with_defaults(model: &Model, v: &Value) -> Option<f64> {
    Some(match &v.kind {
        ValueKind::Lit(x) => *x,
        ValueKind::Param(p) => model.params.iter().find(|(n, _)| n == p)?.1,
        ValueKind::Load(_) => return None,
        ValueKind::Neg(a) => -with_defaults(model, a)?,
        ValueKind::Bin(a, op, b) => {
            let (a, b) = (with_defaults(model, a)?, with_defaults(model, b)?);
            match op {
                '+' => a + b,
                '-' => a - b,
                '*' => a * b,
                _ => a / b,
            }
        }
    })
}

fn f(v: &Value) -> TokenStream {
    let e = v.emit();
    quote!(<T as ::mechanism::Real>::as_f64(#e))
}

fn sign(m: Mode) -> f64 {
    match m {
        Mode::Plus => 1.0,
        Mode::Minus => -1.0,
    }
}

/// The unit axis of link `k` of `stmt`, from the solved points (code, `V`).
fn axis(stmt: &Stmt, k: usize) -> TokenStream {
    let n = &stmt.name;
    let g = format_ident!("grp_{}", stmt.name);
    match (&stmt.kind, k) {
        (Kind::Crank { pivot, .. }, _) => quote!(unit_of(sub(pt(&pos.#n), pt(&pos.#pivot)))),
        (Kind::Slider { guide, .. }, _)
        | (Kind::Rrp { guide, .. }, 1)
        | (Kind::Rpp { guide, .. }, 1) => quote!(unit_of(vc(&pos.#guide.dir))),
        (Kind::Actuator { a, .. }, 0) | (Kind::Rrr { a, .. }, 0) | (Kind::Rrp { a, .. }, 0) => {
            quote!(unit_of(sub(pt(&pos.#n), pt(&pos.#a))))
        }
        (Kind::Actuator { b, .. }, _) | (Kind::Rrr { b, .. }, _) => {
            quote!(unit_of(sub(pt(&pos.#n), pt(&pos.#b))))
        }
        (Kind::Rpr { .. }, _) => quote!(unit_of(vc(&pos.#g.axis))),
        (Kind::Prp { g1, .. }, 0) => quote!(unit_of(vc(&pos.#g1.dir))),
        (Kind::Prp { g2, .. }, _) => quote!(unit_of(vc(&pos.#g2.dir))),
        (Kind::Rpp { guide, slot, .. }, _) => {
            let s = f(slot);
            quote!(turn(unit_of(vc(&pos.#guide.dir)), #s))
        }
        _ => quote!([1.0, 0.0]),
    }
}

/// What a residual's rounding scales with (its tolerance is 64 eps times
/// this): a length residual with the mechanism's size; a guide direction
/// (the difference of two unit vectors, dimensionless) computed from an
/// angle with 1; one turned from a link's axis, recomputed from two solved
/// points, with the size over the shortest link (the axis's rounding).
#[derive(Clone, Copy)]
enum Scale {
    Length,
    Direction,
    CarriedDirection,
}

/// Residuals of one statement's constraints (code: `(label, residual,
/// scale)`, lengths in the definition's unit).
fn residuals(model: &Model, plan: &Plan, stmt: &Stmt) -> Vec<(String, TokenStream, Scale)> {
    let n = &stmt.name;
    let name = n.to_string();
    let g = format_ident!("grp_{}", stmt.name);
    let mut r = Vec::new();
    let mut directions = Vec::new();
    let mut push =
        |what: &str, code: TokenStream| r.push((format!("{name}: {what}"), code, Scale::Length));
    let link_axis = |link: &Ident| {
        let info = &plan.links[&link.to_string()];
        axis(&model.stmts[info.stmt], info.index)
    };
    match &stmt.kind {
        Kind::Ground { .. } => {}
        Kind::Guide {
            carrier: None,
            angle,
            ..
        } => {
            let a = f(angle);
            directions.push((
                format!("{name}: fixed guide direction"),
                quote!(norm(sub(vc(&pos.#n.dir), turn([1.0, 0.0], #a)))),
                Scale::Direction,
            ));
        }
        Kind::Guide {
            carrier: Some(l),
            angle,
            origin,
        } => {
            let (ax, a) = (link_axis(l), f(angle));
            directions.push((
                format!("{name}: carried guide direction"),
                quote!(norm(sub(vc(&pos.#n.dir), turn(#ax, #a)))),
                Scale::CarriedDirection,
            ));
            if let Origin::Point(p) = origin {
                push(
                    "carried guide origin",
                    quote!(norm(sub(pt(&pos.#n.origin), pt(&pos.#p)))),
                );
            }
        }
        Kind::Crank { pivot, radius, .. } => {
            let r = f(radius);
            push(
                "|tip - pivot| = radius",
                quote!(norm(sub(pt(&pos.#n), pt(&pos.#pivot))) - #r),
            );
        }
        Kind::Slider {
            guide,
            input,
            offset,
        } => {
            let o = f(offset);
            push(
                "pin on the offset line",
                quote!(cross(vc(&pos.#guide.dir), sub(pt(&pos.#n), pt(&pos.#guide.origin))) - #o),
            );
            push(
                "pin at the input displacement",
                quote!(dot(vc(&pos.#guide.dir), sub(pt(&pos.#n), pt(&pos.#guide.origin))) - <T as ::mechanism::Real>::as_f64(pos.input.#input)),
            );
        }
        Kind::Actuator {
            a,
            l,
            b,
            input,
            mode,
        } => {
            let (l, m) = (f(l), sign(*mode));
            push(
                "|C - A| = l",
                quote!(norm(sub(pt(&pos.#n), pt(&pos.#a))) - #l),
            );
            push(
                "|C - B| = input length",
                quote!(norm(sub(pt(&pos.#n), pt(&pos.#b))) - <T as ::mechanism::Real>::as_f64(pos.input.#input)),
            );
            push(
                "assembly branch",
                quote!(wrong_side(#m * cross(sub(pt(&pos.#b), pt(&pos.#a)), sub(pt(&pos.#n), pt(&pos.#a))) / norm(sub(pt(&pos.#b), pt(&pos.#a))))),
            );
        }
        Kind::Rrr { a, l1, b, l2, mode } => {
            let (l1, l2, m) = (f(l1), f(l2), sign(*mode));
            push(
                "|C - A| = l1",
                quote!(norm(sub(pt(&pos.#n), pt(&pos.#a))) - #l1),
            );
            push(
                "|C - B| = l2",
                quote!(norm(sub(pt(&pos.#n), pt(&pos.#b))) - #l2),
            );
            push(
                "assembly branch",
                quote!(wrong_side(#m * cross(sub(pt(&pos.#b), pt(&pos.#a)), sub(pt(&pos.#n), pt(&pos.#a))) / norm(sub(pt(&pos.#b), pt(&pos.#a))))),
            );
        }
        Kind::Rrp {
            a,
            l,
            guide,
            mode,
            offset,
        } => {
            let (l, m, o) = (f(l), sign(*mode), f(offset));
            push(
                "|C - A| = l",
                quote!(norm(sub(pt(&pos.#n), pt(&pos.#a))) - #l),
            );
            push(
                "C on the offset line",
                quote!(cross(vc(&pos.#guide.dir), sub(pt(&pos.#n), pt(&pos.#guide.origin))) - #o),
            );
            push(
                "assembly branch",
                quote!(wrong_side(#m * dot(sub(pt(&pos.#n), pt(&pos.#a)), vc(&pos.#guide.dir)))),
            );
        }
        Kind::Rpr { a, b, mode, offset } => {
            let (m, o) = (sign(*mode), f(offset));
            push(
                "slide line at its offset from B",
                quote!(cross(vc(&pos.#g.axis), sub(pt(&pos.#a), pt(&pos.#b))) - #o),
            );
            push(
                "slide = dot(A - B, u)",
                quote!(dot(vc(&pos.#g.axis), sub(pt(&pos.#a), pt(&pos.#b))) - <T as ::mechanism::Real>::as_f64(pos.#g.s)),
            );
            push(
                "unit axis (times |A - B|)",
                quote!((norm(vc(&pos.#g.axis)) - 1.0) * norm(sub(pt(&pos.#a), pt(&pos.#b)))),
            );
            push(
                "assembly branch",
                quote!(wrong_side(#m * <T as ::mechanism::Real>::as_f64(pos.#g.s))),
            );
        }
        Kind::Prp {
            g1,
            g2,
            offset1,
            offset2,
        } => {
            let (o1, o2) = (f(offset1), f(offset2));
            push(
                "C on offset line 1",
                quote!(cross(vc(&pos.#g1.dir), sub(pt(&pos.#n), pt(&pos.#g1.origin))) - #o1),
            );
            push(
                "C on offset line 2",
                quote!(cross(vc(&pos.#g2.dir), sub(pt(&pos.#n), pt(&pos.#g2.origin))) - #o2),
            );
        }
        Kind::Rpp {
            a,
            guide,
            slot,
            offset,
        } => {
            let (o, s) = (f(offset), f(slot));
            push(
                "Q on the offset line",
                quote!(cross(vc(&pos.#guide.dir), sub(pt(&pos.#n), pt(&pos.#guide.origin))) - #o),
            );
            push(
                "A in the slot through Q",
                quote!(cross(turn(unit_of(vc(&pos.#guide.dir)), #s), sub(pt(&pos.#a), pt(&pos.#n)))),
            );
        }
        Kind::Point { link, from, local } => {
            let ax = link_axis(link);
            let (x, y) = match local {
                Local::Cartesian(x, y) => (f(x), f(y)),
                Local::Polar(d, a) => {
                    let (d, a) = (f(d), f(a));
                    (quote!(#d * (#a).cos()), quote!(#d * (#a).sin()))
                }
            };
            push(
                "P = from + the link's axes times the local offset",
                quote!({
                    let u = #ax;
                    let (x, y) = (#x, #y);
                    norm(sub(sub(pt(&pos.#n), pt(&pos.#from)), [u[0] * x - u[1] * y, u[1] * x + u[0] * y]))
                }),
            );
        }
    }
    r.extend(directions);
    r
}

/// The `#[cfg(test)]` module.
pub fn emit(model: &Model, plan: &Plan, findings: &Findings) -> TokenStream {
    let inputs = &model.inputs;
    let name = &model.name;
    let snake = snake(&name.to_string());
    let module = format_ident!("{}_self_test", snake);
    let input_ty = format_ident!("{}Input", name);
    let position_ty = format_ident!("{}Position", name);
    let checked = checked(model, plan);
    let out = &plan.outputs;
    let d = inputs.len();
    let ks: Vec<usize> = (0..d).collect();
    let input_names: Vec<&Ident> = inputs.iter().map(|i| &i.name).collect();
    let (mut lo, mut hi, mut unit) = (Vec::new(), Vec::new(), Vec::new());
    for i in inputs {
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

    // Residuals.
    let mut labels = Vec::new();
    let mut codes = Vec::new();
    let mut scales = Vec::new();
    for &i in &checked.order {
        for (label, code, scale) in residuals(model, plan, &model.stmts[i]) {
            labels.push(label);
            codes.push(code);
            scales.push(match scale {
                Scale::Length => quote!(size),
                Scale::Direction => quote!(1.0),
                Scale::CarriedDirection => quote!(size / L_MIN),
            });
        }
    }
    let nres = codes.len();
    // Points for the size.
    let points: Vec<&Ident> = checked
        .order
        .iter()
        .map(|&i| &model.stmts[i])
        .filter(|s| !matches!(s.kind, Kind::Guide { .. } | Kind::Rpr { .. }))
        .map(|s| &s.name)
        .collect();
    // Smallest link length (defaults), for the rounding of link angles.
    let mut lengths: Vec<f64> = Vec::new();
    for &i in &checked.order {
        match &model.stmts[i].kind {
            Kind::Crank { radius: l, .. } | Kind::Rrp { l, .. } | Kind::Actuator { l, .. } => {
                lengths.extend(with_defaults(model, l))
            }
            Kind::Rrr { l1, l2, .. } => {
                lengths.extend(with_defaults(model, l1));
                lengths.extend(with_defaults(model, l2));
            }
            _ => {}
        }
    }
    let l_min = lengths
        .iter()
        .copied()
        .filter(|x| *x > 0.0)
        .fold(f64::INFINITY, f64::min);
    let l_min = if l_min.is_finite() { l_min } else { 1.0 };

    // Output rows: points (x, y), link angles, slides.
    let mut pos_row = Vec::new();
    let mut rate_row = Vec::new();
    let mut angle_col = Vec::new();
    for p in &out.points {
        pos_row.push(quote!(<T as ::mechanism::Real>::as_f64(pos.#p.x)));
        pos_row.push(quote!(<T as ::mechanism::Real>::as_f64(pos.#p.y)));
        rate_row.push(quote!(<T as ::mechanism::Real>::as_f64(v.#p.x)));
        rate_row.push(quote!(<T as ::mechanism::Real>::as_f64(v.#p.y)));
        angle_col.extend([false, false]);
    }
    for l in &out.links {
        pos_row.push(quote!(<T as ::mechanism::Real>::as_f64(pos.#l)));
        rate_row.push(quote!(<T as ::mechanism::Real>::as_f64(v.#l)));
        angle_col.push(true);
    }
    for s in out.slides.iter().map(|s| &s.name) {
        pos_row.push(quote!(<T as ::mechanism::Real>::as_f64(pos.#s)));
        rate_row.push(quote!(<T as ::mechanism::Real>::as_f64(v.#s)));
        angle_col.push(false);
    }
    let k = pos_row.len();
    let dets: Vec<TokenStream> = checked
        .groups
        .iter()
        .map(|&i| super::check_fn::det_code(model, i))
        .collect();
    let ng = dets.len();

    // Expected singular positions from the expansion-time check.
    let singular_check = if findings.ran {
        let mut rows = Vec::new();
        for (g, list) in &findings.singular {
            let at: Vec<f64> = list.clone();
            let n = at.len() as u32;
            rows.push(quote! {
                assert_eq!(report.groups[#g].singular, #n, "group `{}`: singular positions found at run time {:?}, at expansion time {:?}", report.groups[#g].group, report.groups[#g], [#(#at),*]);
                let first = report.groups[#g].first_singular.map(|a| a[0]).unwrap_or(f64::NAN);
                let expected = [#(#at),*].iter().copied().fold(f64::INFINITY, f64::min);
                assert!(((first - expected).abs() <= 1e-6 * width) || ((first - expected).abs() - width).abs() <= 1e-6 * width, "group `{}`: first singular input {first} at run time, {expected} at expansion time", report.groups[#g].group);
            });
        }
        let found: Vec<usize> = findings.singular.iter().map(|(g, _)| *g).collect();
        quote! {
            let width = ranges_width();
            #(#rows)*
            for (g, r) in report.groups.iter().enumerate() {
                if ![#(#found),*].contains(&g) {
                    assert_eq!(r.singular, 0, "group `{}`: singular at run time, not at expansion time: {:?}", r.group, r);
                }
            }
        }
    } else {
        let allowed_names: Vec<String> = match &model.allowed {
            Allowed::Nothing => vec![],
            Allowed::Every => checked
                .groups
                .iter()
                .map(|&i| model.stmts[i].name.to_string())
                .collect(),
            Allowed::Groups(l) => l.clone(),
        };
        quote! {
            for r in report.groups.iter() {
                assert!(r.singular == 0 || [#(#allowed_names),*].contains(&r.group), "group `{}` passes through a singular position (not allowed by `allow singular`): {:?}", r.group, r);
            }
        }
    };
    let velocity = model.level >= Level::Velocity;
    let acceleration = model.level >= Level::Acceleration;
    let forces = model.has_forces();
    let loads_arg = if model.kinetics.loads.is_empty() {
        quote!()
    } else {
        let loads_ty = format_ident!("{}Loads", name);
        quote!(, &#loads_ty::default())
    };
    let vel_tests = if velocity {
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
    } else {
        quote!()
    };
    let acc_tests = if acceleration {
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
    } else {
        quote!()
    };
    let force_tests = if forces {
        quote! {
            /// The power balance of the generated force analysis (driving
            /// efforts + loads + weights + inertia = 0), relative to its
            /// largest term: rounding of the reactions is about
            /// `eps / condition` relative (the force systems' conditioning
            /// indicator), summed over a few terms: 256 eps / condition.
            #[test]
            fn power_balance() {
                let m = #name::<f64>::default();
                let mut checked = 0usize;
                for s in 0..samples() {
                    let q = sample(s);
                    let Ok(sol) = m.solve(&input(q), &input(W), &input(A) #loads_arg) else { continue };
                    let f = sol.forces;
                    let tol = 256.0 * f64::EPSILON / f.condition.max(f64::EPSILON);
                    assert!(f.power_residual <= tol, "sample {q:?}: power residual {:e} (tolerance {tol:e}, condition {:e})", f.power_residual, f.condition);
                    checked += 1;
                }
                assert!(checked > 0, "no sample could be checked");
            }
        }
    } else {
        quote!()
    };
    let f32_vel = if velocity {
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
    } else {
        quote!()
    };
    // The finite difference of velocities exists only where velocities do
    // (`analysis position;` generates no `velocity`).
    let fd_vel = if velocity {
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
    } else {
        quote!()
    };
    let mut rate_impls = TokenStream::new();
    for (level, ty) in [
        (Level::Velocity, "Velocity"),
        (Level::Acceleration, "Acceleration"),
    ] {
        if model.level >= level {
            let ty = format_ident!("{}{}", name, ty);
            rate_impls.extend(quote! {
                impl<T: ::mechanism::Real> RateRow for #ty<T> {
                    fn row(&self) -> [f64; #k] { let v = self; [#(#rate_row),*] }
                }
            });
        }
    }
    let doc_w: Vec<f64> = (0..d).map(|i| [1.0, -0.7][i] * unit[i]).collect();
    let doc_a: Vec<f64> = (0..d).map(|i| [0.5, 0.3][i] * unit[i]).collect();
    let labels_arr = labels.clone();
    let samples_n: usize = if d == 1 { 90 } else { 100 };
    let sample_code = if d == 1 {
        quote!([LO[0] + (HI[0] - LO[0]) * (k as f64 + 0.5) / 90.0])
    } else {
        quote!([
            LO[0] + (HI[0] - LO[0]) * ((k / 10) as f64 + 0.5) / 10.0,
            LO[1] + (HI[1] - LO[1]) * ((k % 10) as f64 + 0.5) / 10.0
        ])
    };
    let doc = format!("Tests of [`{name}`] generated by `#[self_test]`, over its input range with the default parameters.");
    quote! {
        #[doc = #doc]
        #[cfg(test)]
        #[allow(non_snake_case, unused_variables, unused_imports, dead_code, clippy::all)]
        mod #module {
            use super::*;
            // Explicit imports win over the glob: the tests work where the
            // user's module shadows prelude names.
            use ::core::option::Option::{self, None, Some};
            use ::core::primitive::{f32, f64};
            use ::core::result::Result::{self, Err, Ok};
            use ::mechanism::Real as _;

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

            fn ranges_width() -> f64 { HI[0] - LO[0] }
            fn samples() -> usize { #samples_n }
            /// Interior samples of the range (grid of 10 x 10 for two inputs).
            fn sample(k: usize) -> [f64; #d] { #sample_code }
            fn input<T: ::mechanism::Real>(q: [f64; #d]) -> #input_ty<T> {
                #input_ty { #(#input_names: T::lit(q[#ks]),)* }
            }
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

            impl<T: ::mechanism::Real> super::#name<T> {
                /// Residuals of every constraint (length units).
                fn self_test_residuals(&self, pos: &#position_ty<T>) -> [f64; #nres] {
                    [#(#codes),*]
                }
            }
            /// The mechanism's size at a pose: the largest point coordinate.
            fn size_of<T: ::mechanism::Real>(pos: &#position_ty<T>) -> f64 {
                let mut s = 0.0f64;
                #( s = s.max(pt(&pos.#points)[0].abs()).max(pt(&pos.#points)[1].abs()); )*
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
            #fd_vel
            /// `check()` with the default parameters: every group assembles
            /// over the range, and the singular positions are those the macro
            /// found at expansion time (same sweep; to 1e-6 of the range: at a
            /// fold the determinant is exactly zero over a rounding band of
            /// about sqrt(4 eps) of the range, where the searches may stop).
            #[test]
            fn check() {
                let report = #name::<f64>::default().check();
                assert!(report.assembles(), "a group cannot be assembled: {report:?}");
                #singular_check
            }

            /// Every constraint of every group, recomputed from the solved
            /// points, within 64 eps times its scale: the mechanism's size
            /// for a length (each is a few roundings of numbers of that
            /// size), 1 for a guide direction from an angle (a difference of
            /// unit vectors), the size over the shortest link for a direction
            /// turned from a link's axis (recomputed from two solved points).
            /// A group's constraints hold to rounding whatever its
            /// conditioning; errors of its inputs do not enter, its residuals
            /// are measured from them.
            fn loop_closure<T: ::mechanism::Real>() {
                let m = #name::<T>::default();
                let eps = T::eps().as_f64();
                let mut checked = 0usize;
                for s in 0..samples() {
                    let q = sample(s);
                    let Ok(pos) = m.position(&input(q)) else { continue };
                    let r = m.self_test_residuals(&pos);
                    let size = size_of(&pos);
                    let scale: [f64; #nres] = [#(#scales),*];
                    for (j, x) in r.iter().enumerate() {
                        let tol = 64.0 * eps * scale[j];
                        assert!(x.abs() <= tol, "sample {q:?}: {} off by {x:e} (tolerance {tol:e})", LABELS[j]);
                    }
                    checked += 1;
                }
                assert!(checked > 0, "no sample assembles");
            }
            #[test]
            fn loop_closure_f64() { loop_closure::<f64>(); }
            #[test]
            fn loop_closure_f32() { loop_closure::<f32>(); }

            #vel_tests
            #acc_tests
            #force_tests

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
}

/// `FourBar` -> `four_bar`.
fn snake(s: &str) -> String {
    let mut out = String::new();
    for (i, c) in s.chars().enumerate() {
        if c.is_uppercase() {
            if i > 0 {
                out.push('_');
            }
            out.extend(c.to_lowercase());
        } else {
            out.push(c);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    /// A two-input mechanism whose crank keeps its default full turn has no
    /// `check()` (two inputs are swept over a declared box only), so
    /// `#[self_test]` must say so instead of generating a call to it.
    #[test]
    fn two_inputs_need_both_ranges() {
        let out = crate::expand(quote::quote! {
            #[self_test]
            pub SliderOnCarried {
                let O = ground(0.0, 0.0);
                let A = crank(O, 0.1, theta) as link2;
                let g = guide(O, link2, 20 deg);
                let P = slider(g, s, 0.01) as block;
                range s = (0.0, 0.2);
            }
        })
        .to_string();
        assert!(
            out.contains("compile_error") && out.contains("and `theta` has none"),
            "{out}"
        );
    }
}
