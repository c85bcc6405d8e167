//! The loop-closure tests: every constraint of every group the position
//! analysis solves, written here from the definition (not from the generated
//! position code) as a residual recomputed from the solved points.

use super::Context;
use crate::model::{Kind, Local, Mode, Model, Origin, Stmt};
use crate::plan::Plan;
use crate::value::{Value, ValueKind};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

/// A value with run-time parameters at their defaults (`None` for a load).
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

/// Code of a definition value as an `f64` (`T` is the mechanism's scalar).
fn f(v: &Value) -> TokenStream {
    let e = v.emit();
    quote!(<T as ::mechanism::Real>::as_f64(#e))
}

/// The sign of an assembly mode: +1 for `Plus`, -1 for `Minus`.
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

impl Scale {
    /// The scale as code of the generated `loop_closure` (`size`, the
    /// mechanism's size at the pose, and `L_MIN` in scope).
    fn emit(self) -> TokenStream {
        match self {
            Scale::Length => quote!(size),
            Scale::Direction => quote!(1.0),
            Scale::CarriedDirection => quote!(size / L_MIN),
        }
    }
}

/// One constraint of one statement.
struct Residual {
    /// `"<statement>: <constraint>"`, for the failure message.
    label: String,
    /// Code of an `f64` residual, zero when the constraint holds (lengths in
    /// the definition's unit; reads `pos`).
    code: TokenStream,
    /// What its rounding scales with.
    scale: Scale,
}

/// Residuals of one statement, labelled with its name.
struct Residuals<'a> {
    /// The statement's (point's) name.
    n: &'a Ident,
    /// Its constraints, in the generated order.
    list: Vec<Residual>,
}

impl<'a> Residuals<'a> {
    /// No residuals yet for statement `n`.
    fn new(n: &'a Ident) -> Self {
        Residuals {
            n,
            list: Vec::new(),
        }
    }

    /// Adds the constraint `what` with residual `code` and its scale.
    fn push_scaled(&mut self, what: &str, code: TokenStream, scale: Scale) {
        let label = format!("{}: {what}", self.n);
        self.list.push(Residual { label, code, scale });
    }

    /// Adds a length constraint (its rounding scales with the size).
    fn push(&mut self, what: &str, code: TokenStream) {
        self.push_scaled(what, code, Scale::Length);
    }
}

/// The unit axis of `link` from the solved points (code).
fn link_axis(model: &Model, plan: &Plan, link: &Ident) -> TokenStream {
    let info = &plan.links[&link.to_string()];
    axis(&model.stmts[info.stmt], info.index)
}

/// A guide: its direction (fixed, or turned from its carrier link's axis)
/// and, when carried through a point, its origin at that point.
fn guide(r: &mut Residuals, axis: Option<TokenStream>, angle: &Value, origin: &Origin) {
    let n = r.n;
    let a = f(angle);
    let Some(ax) = axis else {
        r.push_scaled(
            "fixed guide direction",
            quote!(norm(sub(vc(&pos.#n.dir), turn([1.0, 0.0], #a)))),
            Scale::Direction,
        );
        return;
    };
    if let Origin::Point(p) = origin {
        r.push(
            "carried guide origin",
            quote!(norm(sub(pt(&pos.#n.origin), pt(&pos.#p)))),
        );
    }
    r.push_scaled(
        "carried guide direction",
        quote!(norm(sub(vc(&pos.#n.dir), turn(#ax, #a)))),
        Scale::CarriedDirection,
    );
}

/// A crank: the tip at its radius from the pivot.
fn crank(r: &mut Residuals, pivot: &Ident, radius: &Value) {
    let (n, l) = (r.n, f(radius));
    r.push(
        "|tip - pivot| = radius",
        quote!(norm(sub(pt(&pos.#n), pt(&pos.#pivot))) - #l),
    );
}

/// A slider: the pin on the guide's offset line, at the input displacement.
fn slider(r: &mut Residuals, guide: &Ident, input: &Ident, offset: &Value) {
    let (n, o) = (r.n, f(offset));
    r.push(
        "pin on the offset line",
        quote!(cross(vc(&pos.#guide.dir), sub(pt(&pos.#n), pt(&pos.#guide.origin))) - #o),
    );
    r.push(
        "pin at the input displacement",
        quote!(dot(vc(&pos.#guide.dir), sub(pt(&pos.#n), pt(&pos.#guide.origin))) - <T as ::mechanism::Real>::as_f64(pos.input.#input)),
    );
}

/// The assembly branch of a dyad on the two points `a`, `b`: `n` on the
/// side of `a -> b` that `mode` names.
fn dyad_branch(r: &mut Residuals, a: &Ident, b: &Ident, mode: Mode) {
    let (n, m) = (r.n, sign(mode));
    r.push(
        "assembly branch",
        quote!(wrong_side(#m * cross(sub(pt(&pos.#b), pt(&pos.#a)), sub(pt(&pos.#n), pt(&pos.#a))) / norm(sub(pt(&pos.#b), pt(&pos.#a))))),
    );
}

/// A linear actuator: `C` at `l` from `A`, at the input length from `B`, on
/// its branch.
fn actuator(r: &mut Residuals, a: &Ident, l: &Value, b: &Ident, input: &Ident, mode: Mode) {
    let (n, l) = (r.n, f(l));
    r.push(
        "|C - A| = l",
        quote!(norm(sub(pt(&pos.#n), pt(&pos.#a))) - #l),
    );
    r.push(
        "|C - B| = input length",
        quote!(norm(sub(pt(&pos.#n), pt(&pos.#b))) - <T as ::mechanism::Real>::as_f64(pos.input.#input)),
    );
    dyad_branch(r, a, b, mode);
}

/// An RRR dyad: `C` at `l1` from `A` and `l2` from `B`, on its branch.
fn rrr(r: &mut Residuals, a: &Ident, l1: &Value, b: &Ident, l2: &Value, mode: Mode) {
    let (n, l1, l2) = (r.n, f(l1), f(l2));
    r.push(
        "|C - A| = l1",
        quote!(norm(sub(pt(&pos.#n), pt(&pos.#a))) - #l1),
    );
    r.push(
        "|C - B| = l2",
        quote!(norm(sub(pt(&pos.#n), pt(&pos.#b))) - #l2),
    );
    dyad_branch(r, a, b, mode);
}

/// An RRP dyad: `C` at `l` from `A`, on the guide's offset line, on its
/// branch (along the guide from `A`).
fn rrp(r: &mut Residuals, a: &Ident, l: &Value, guide: &Ident, mode: Mode, offset: &Value) {
    let (n, l, m, o) = (r.n, f(l), sign(mode), f(offset));
    r.push(
        "|C - A| = l",
        quote!(norm(sub(pt(&pos.#n), pt(&pos.#a))) - #l),
    );
    r.push(
        "C on the offset line",
        quote!(cross(vc(&pos.#guide.dir), sub(pt(&pos.#n), pt(&pos.#guide.origin))) - #o),
    );
    r.push(
        "assembly branch",
        quote!(wrong_side(#m * dot(sub(pt(&pos.#n), pt(&pos.#a)), vc(&pos.#guide.dir)))),
    );
}

/// An RPR dyad: its slide line at its offset from `B`, the slide along it,
/// a unit axis, and the branch (the sign of the slide).
fn rpr(r: &mut Residuals, a: &Ident, b: &Ident, mode: Mode, offset: &Value) {
    let g = format_ident!("grp_{}", r.n);
    let (m, o) = (sign(mode), f(offset));
    r.push(
        "slide line at its offset from B",
        quote!(cross(vc(&pos.#g.axis), sub(pt(&pos.#a), pt(&pos.#b))) - #o),
    );
    r.push(
        "slide = dot(A - B, u)",
        quote!(dot(vc(&pos.#g.axis), sub(pt(&pos.#a), pt(&pos.#b))) - <T as ::mechanism::Real>::as_f64(pos.#g.s)),
    );
    r.push(
        "unit axis (times |A - B|)",
        quote!((norm(vc(&pos.#g.axis)) - 1.0) * norm(sub(pt(&pos.#a), pt(&pos.#b)))),
    );
    r.push(
        "assembly branch",
        quote!(wrong_side(#m * <T as ::mechanism::Real>::as_f64(pos.#g.s))),
    );
}

/// A PRP dyad: `C` on both guides' offset lines.
fn prp(r: &mut Residuals, g1: &Ident, g2: &Ident, offset1: &Value, offset2: &Value) {
    let (n, o1, o2) = (r.n, f(offset1), f(offset2));
    r.push(
        "C on offset line 1",
        quote!(cross(vc(&pos.#g1.dir), sub(pt(&pos.#n), pt(&pos.#g1.origin))) - #o1),
    );
    r.push(
        "C on offset line 2",
        quote!(cross(vc(&pos.#g2.dir), sub(pt(&pos.#n), pt(&pos.#g2.origin))) - #o2),
    );
}

/// An RPP dyad: `Q` on the guide's offset line, `A` in the slot through `Q`.
fn rpp(r: &mut Residuals, a: &Ident, guide: &Ident, slot: &Value, offset: &Value) {
    let (n, o, s) = (r.n, f(offset), f(slot));
    r.push(
        "Q on the offset line",
        quote!(cross(vc(&pos.#guide.dir), sub(pt(&pos.#n), pt(&pos.#guide.origin))) - #o),
    );
    r.push(
        "A in the slot through Q",
        quote!(cross(turn(unit_of(vc(&pos.#guide.dir)), #s), sub(pt(&pos.#a), pt(&pos.#n)))),
    );
}

/// A point on a link: `from` plus the link's axes times the local offset.
fn point(r: &mut Residuals, axis: TokenStream, from: &Ident, local: &Local) {
    let n = r.n;
    let (x, y) = match local {
        Local::Cartesian(x, y) => (f(x), f(y)),
        Local::Polar(d, a) => {
            let (d, a) = (f(d), f(a));
            (quote!(#d * (#a).cos()), quote!(#d * (#a).sin()))
        }
    };
    r.push(
        "P = from + the link's axes times the local offset",
        quote!({
            let u = #axis;
            let (x, y) = (#x, #y);
            norm(sub(sub(pt(&pos.#n), pt(&pos.#from)), [u[0] * x - u[1] * y, u[1] * x + u[0] * y]))
        }),
    );
}

/// Residuals of one statement's constraints (lengths in the definition's
/// unit); a carried guide's direction comes after its origin.
fn residuals(model: &Model, plan: &Plan, stmt: &Stmt) -> Vec<Residual> {
    let mut r = Residuals::new(&stmt.name);
    match &stmt.kind {
        Kind::Ground { .. } => {}
        Kind::Guide {
            carrier,
            angle,
            origin,
        } => {
            let axis = carrier.as_ref().map(|l| link_axis(model, plan, l));
            guide(&mut r, axis, angle, origin);
        }
        Kind::Crank { pivot, radius, .. } => crank(&mut r, pivot, radius),
        Kind::Slider {
            guide,
            input,
            offset,
        } => slider(&mut r, guide, input, offset),
        Kind::Actuator {
            a,
            l,
            b,
            input,
            mode,
        } => actuator(&mut r, a, l, b, input, *mode),
        Kind::Rrr { a, l1, b, l2, mode } => rrr(&mut r, a, l1, b, l2, *mode),
        Kind::Rrp {
            a,
            l,
            guide,
            mode,
            offset,
        } => rrp(&mut r, a, l, guide, *mode, offset),
        Kind::Rpr { a, b, mode, offset } => rpr(&mut r, a, b, *mode, offset),
        Kind::Prp {
            g1,
            g2,
            offset1,
            offset2,
        } => prp(&mut r, g1, g2, offset1, offset2),
        Kind::Rpp {
            a,
            guide,
            slot,
            offset,
        } => rpp(&mut r, a, guide, slot, offset),
        Kind::Point { link, from, local } => {
            point(&mut r, link_axis(model, plan, link), from, local)
        }
    }
    r.list
}

/// Every constraint of every solved statement, in solve order, as the
/// generated module uses them.
pub(super) struct Constraints {
    /// Failure-message labels (`LABELS`).
    pub labels: Vec<String>,
    /// Residual codes (`self_test_residuals`).
    pub codes: Vec<TokenStream>,
    /// Tolerance scales (code, in `loop_closure`).
    pub scales: Vec<TokenStream>,
}

impl Constraints {
    /// The constraints of the statements `position()` solves.
    pub fn new(cx: &Context) -> Self {
        let mut c = Constraints {
            labels: Vec::new(),
            codes: Vec::new(),
            scales: Vec::new(),
        };
        for &i in &cx.checked.order {
            for r in residuals(cx.model, cx.plan, &cx.model.stmts[i]) {
                c.labels.push(r.label);
                c.codes.push(r.code);
                c.scales.push(r.scale.emit());
            }
        }
        c
    }

    /// How many constraints (residuals) there are.
    pub fn len(&self) -> usize {
        self.codes.len()
    }
}

/// The shortest link length with the default parameters (positive lengths
/// only; 1 when there is none), for the rounding of link angles.
pub(super) fn shortest_link(cx: &Context) -> f64 {
    let model = cx.model;
    let mut lengths: Vec<f64> = Vec::new();
    for &i in &cx.checked.order {
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
    if l_min.is_finite() {
        l_min
    } else {
        1.0
    }
}

/// The generated `loop_closure` tests (f64 and f32).
pub(super) fn tests(cx: &Context, constraints: &Constraints) -> TokenStream {
    let name = cx.name;
    let nres = constraints.len();
    let scales = &constraints.scales;
    quote! {
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
    }
}
