//! `let (A, B, P) = triad(K1, l1, K2, l2, K3, l3, ab, d, angle, INPUT =
//! value, (ax, ay), (bx, by), (px, py)) as (LEG1, LEG2, LEG3, TERNARY)`: the
//! class III group of the Stephenson III six-bar (`mechanism::triad`). A
//! ternary link with joints `A`, `B`, `P` (`|AB| = ab`, `P` at distance `d`
//! from `A`, `angle` counter-clockwise from `A -> B`, or at `(x, y)` in that
//! frame) on three legs from the known points `K1`, `K2`, `K3`.
//!
//! The statement is the group's joint `A`; its joints `B` and `P` are
//! lowered as points on the ternary link (`model::lower`), so their rates
//! and the rest of the pipeline are the link point's.
//!
//! **Which assembly.** A triad has up to six. The statement gives an
//! approximate pose of `A`, `B`, `P` at one input value. With one input
//! and a declared (or default) range, and every dimension known at
//! expansion time, the check tracks that assembly over the range
//! ([`track`], the core's `position_near` in small steps) and stores the
//! tracked pose at up to [`ROWS`] `+ 2` inputs, crowded where linear
//! interpolation needs them ([`table_rows`]); the generated `position()`
//! takes the assembly nearest the pose interpolated from that table
//! (`triad::near_from_table`: Newton from it with a radius of isolation,
//! else the full search), a typed
//! `NotNear` when none is clearly nearest or the input lies outside the
//! tracked interval. Otherwise (parameters, several inputs) the stated pose
//! itself is the hint at every input.

use super::closure::{f, Residuals};
use super::forces::{revolute, rx, ForceCx};
use super::group::{links_text, GroupKind, LinkShape, Role, Solve, Tracked, Tracking, Turn};
use super::lane::{Lane, Step};
use super::rates::{states, vec_ty, RateCx};
use super::reads::Reads;
use super::run::{Compile, ForceRunCx, InputSlot, Me, NamedPose, PointSlot, RunCx, RunPose};
use super::tokens::{arm, grp, local, tag, unit_field};
use crate::diag::{show_num, Diagnostics};
use crate::keys::LinkName;
use crate::kinds::pose::num;
use crate::model::{Local, Stmt, Triad as Args};
use crate::value::Value;
use mechanism_core::triad::{self, Near, TriadPosition};
use mechanism_core::{geometry, Fault, Point2, Vector2};
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// How `triad` is written: its word, usage, arity and links.
pub(crate) const SPEC: super::word::Spec = super::word::Spec {
    word: super::word::KindWord::Triad,
    text: "triad",
    usage: "let (A, B, P) = triad(K1, l1, K2, l2, K3, l3, ab, distance, angle, INPUT = value, (ax, ay), (bx, by), (px, py)) as (LEG1, LEG2, LEG3, TERNARY), P's place also `(x, y)`",
    arity: super::word::Arity::TupleAt { index: 7, tuple: (12, 12), other: (13, 13) },
    links: "leg 1 from K1 to A, leg 2 from K2 to B, leg 3 from K3 to P, and the ternary link A-B-P",
    inputs: &[],
    mode_at: None,
    mode_words: &[],
    group: Some("triad"),
};

/// The tracked-pose table the generated `position()` reads holds at most
/// this many rows plus two ([`table_rows`]: the first and last input found,
/// the others where linear interpolation needs them).
pub const ROWS: usize = 49;

/// Tracking steps between two rows of the table.
const SUB: usize = 16;

/// A `triad` statement (the joint `A`).
pub(super) struct TriadKind<'a> {
    pub stmt: &'a Stmt,
    pub t: &'a Args,
    /// The assembly the check tracked over the input's range (its
    /// findings, `check::Findings::known`); `None` where the check did not
    /// track it: the stated pose is the hint at every input.
    pub tracked: Option<&'a Tracked>,
}

/// `P`'s offset in the ternary's frame (L), its dimensions valued by `num`.
fn p_local(t: &Args, num: &dyn Fn(&Value) -> f64) -> Vector2<f64> {
    match &t.p_local {
        Local::Cartesian(x, y) => Vector2::new(num(x), num(y)),
        Local::Polar(d, a) => geometry::unit(num(a)) * num(d),
    }
}

/// The core's dimensions, valued by `num` (folded: `pose::num`).
fn dims(t: &Args, num: &dyn Fn(&Value) -> f64) -> triad::Triad<f64> {
    triad::Triad {
        l1: num(&t.l[0]),
        l2: num(&t.l[1]),
        l3: num(&t.l[2]),
        ab: num(&t.ab),
        p_local: p_local(t, num),
    }
}

/// The stated pose, valued by `num`.
fn stated(t: &Args, num: &dyn Fn(&Value) -> f64) -> Near<f64> {
    let p = |k: usize| Point2::new(num(&t.near[k].0), num(&t.near[k].1));
    Near::new(p(0), p(1), p(2))
}

/// The core's dimensions (code, in the mechanism's scalar `T`).
fn dims_code(t: &Args) -> TokenStream {
    let [l1, l2, l3] = [t.l[0].emit(), t.l[1].emit(), t.l[2].emit()];
    let ab = t.ab.emit();
    let p = match &t.p_local {
        Local::Cartesian(x, y) => {
            let (x, y) = (x.emit(), y.emit());
            quote!(::mechanism::Vector2::new(#x, #y))
        }
        Local::Polar(d, a) => {
            let (d, u) = (d.emit(), super::tokens::unit_vector(a));
            quote!(#u * #d)
        }
    };
    quote!(::mechanism::triad::Triad { l1: #l1, l2: #l2, l3: #l3, ab: #ab, p_local: #p })
}

/// Tracks the stated assembly of `t` over `[lo, hi]` (the input's unit):
/// solved at the stated input from the stated pose, then followed up and
/// down in steps of `(hi - lo) / ((ROWS - 1) SUB)` by `triad::position_near`.
/// `ks` gives the three known points at an input. `Err` when the stated
/// input is outside the range or the stated pose selects no assembly. An
/// angle input (`angle`, rad) is periodic: a stated input outside the range
/// counts at the same angle a whole number of turns away ([`stated_input`]).
pub fn track(
    t: &Args,
    (lo, hi): (f64, f64),
    angle: bool,
    ks: &dyn Fn(f64) -> Option<[Point2<f64>; 3]>,
) -> Result<Tracked, mechanism_core::Error<f64>> {
    let q0 = stated_input(t, (lo, hi), angle);
    let steps = (ROWS - 1) * SUB;
    let h = (hi - lo) / steps as f64;
    let not_near = mechanism_core::Error::new(
        mechanism_core::Primitive::Triad,
        Fault::NotNear {
            nearest: f64::INFINITY,
            next: 0.0,
        },
    );
    if !(q0 >= lo && q0 <= hi) || h.is_nan() || h <= 0.0 {
        return Err(not_near);
    }
    // The grid's ends are the range's, exactly.
    let grid = |i: usize| {
        if i == steps {
            hi
        } else {
            lo + h * i as f64
        }
    };
    let dims = dims(t, &num);
    let k0 = ks(q0).ok_or(not_near)?;
    let start = triad::position(&dims, &k0, &stated(t, &num))?;
    // The grid index at or below the stated input.
    let i0 = (((q0 - lo) / h).floor() as usize).min(steps);
    let mut poses: Vec<Option<TriadPosition<f64>>> = vec![None; steps + 1];
    let mut ends = Vec::new();
    for dir in [-1i64, 1] {
        let mut prev = start;
        let mut prev_q = q0;
        let mut i = if dir < 0 { i0 as i64 } else { i0 as i64 + 1 };
        while i >= 0 && i <= steps as i64 {
            let q = grid(i as usize);
            let next = ks(q).and_then(|k| triad::position_near(&dims, &k, &prev).ok());
            match next {
                Some(pos) => {
                    poses[i as usize] = Some(pos);
                    prev = pos;
                    prev_q = q;
                }
                None => {
                    ends.push((prev_q.min(q), prev_q.max(q)));
                    break;
                }
            }
            i += dir;
        }
    }
    // Every step the assembly was found at, as a row; then the table's.
    let found: Vec<[f64; 7]> = (0..=steps)
        .filter_map(|i| {
            let pos = poses[i]?;
            Some([
                grid(i),
                pos.a.x,
                pos.a.y,
                pos.b.x,
                pos.b.y,
                pos.p.x,
                pos.p.y,
            ])
        })
        .collect();
    let rows = table_rows(&found).into_iter().map(|k| found[k]).collect();
    Ok(Tracked {
        rows,
        ends,
        angle: false,
    })
}

/// The table's rows among the tracked steps `found` (rows `[q, ax, ay, bx,
/// by, px, py]`, consecutive steps, `q` increasing), as indices: the first
/// and the last always, at most [`ROWS`] `+ 2` in all, placed where linear
/// interpolation needs them. For a tolerance, each row is followed by the
/// farthest step (at most `4 SUB` steps on) whose segment interpolates
/// every tracked step between within the tolerance (root-sum-square over
/// the three joints); the tolerance is bisected (40 times, between 0 and
/// what rows every `SUB` steps achieve, which fit) to the smallest whose
/// rows fit. Near the ends of a swing, where the joints turn fastest with
/// the input and the other assembly comes closest, the rows crowd; where
/// the motion is nearly linear they spread.
fn table_rows(found: &[[f64; 7]]) -> Vec<usize> {
    let n = found.len();
    if n <= 2 {
        return (0..n).collect();
    }
    // The largest miss of the segment from `i` to `j` at the steps between.
    let miss = |i: usize, j: usize| {
        let (a, b) = (&found[i], &found[j]);
        (i + 1..j).fold(0.0f64, |m, k| {
            let w = (found[k][0] - a[0]) / (b[0] - a[0]);
            let d2: f64 = (1..7)
                .map(|c| (a[c] + (b[c] - a[c]) * w - found[k][c]).powi(2))
                .sum();
            m.max(d2.sqrt())
        })
    };
    let greedy = |tol: f64| {
        let mut rows = vec![0];
        let mut i = 0;
        while i + 1 < n {
            let mut j = i + 1;
            while j + 1 < n && j + 1 - i <= 4 * SUB && miss(i, j + 1) <= tol {
                j += 1;
            }
            rows.push(j);
            i = j;
        }
        rows
    };
    let even: Vec<usize> = (0..n).filter(|&k| k % SUB == 0 || k == n - 1).collect();
    let mut hi = even.windows(2).fold(0.0f64, |m, w| m.max(miss(w[0], w[1])));
    let mut best = greedy(hi);
    if best.len() > ROWS + 2 {
        return even;
    }
    let mut lo = 0.0;
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        let rows = greedy(mid);
        if rows.len() <= ROWS + 2 {
            (hi, best) = (mid, rows);
        } else {
            lo = mid;
        }
    }
    best
}

/// The input at which the pose is stated: as written, or for an angle
/// (rad) outside `[lo, hi]`, the same angle a whole number of turns away
/// when that lies inside (a drawing's angles read in `(-180, 180]` deg where
/// a crank's range is `[0, 360]`).
fn stated_input(t: &Args, (lo, hi): (f64, f64), angle: bool) -> f64 {
    let q = num(&t.at.1);
    let turned = triad::same_turn(q, lo);
    if angle && !(q >= lo && q <= hi) && turned <= hi {
        turned
    } else {
        q
    }
}

impl TriadKind<'_> {
    /// The hint's code: the table as `const` data, or the stated pose.
    fn hint_code(&self) -> TokenStream {
        let Some(rows) = self.tracked.filter(|t| !t.rows.is_empty()) else {
            let p = |k: usize| {
                let (x, y) = (self.t.near[k].0.emit(), self.t.near[k].1.emit());
                quote!(::mechanism::Point2::new(#x, #y))
            };
            let (a, b, p) = (p(0), p(1), p(2));
            return quote!(::mechanism::triad::Near::new(#a, #b, #p));
        };
        let n = rows.rows.len();
        let body = rows.rows.iter().map(|r| {
            let v = r.iter().map(|x| proc_macro2::Literal::f64_suffixed(*x));
            quote!([#(#v),*])
        });
        let (input, t) = (&self.t.at.0, tag(self.stmt));
        // An angle's pose repeats every turn: any input is read in the
        // table's turn.
        let lookup = if rows.angle {
            quote!(near_from_table_turning)
        } else {
            quote!(near_from_table)
        };
        quote!({
            const TRACKED: [[f64; 7]; #n] = [#(#body),*];
            ::mechanism::triad::#lookup(&TRACKED, input.#input) #t
        })
    }
}

impl<'a> GroupKind<'a> for TriadKind<'a> {
    fn references(&self) -> Vec<(&'a Ident, Role)> {
        self.t.k.iter().map(|k| (k, Role::Point)).collect()
    }

    fn link_shapes(&self) -> Vec<LinkShape> {
        let (n, t) = (&self.stmt.name, self.t);
        vec![
            LinkShape::new(&[&t.k[0], n], Turn::Own, None),
            LinkShape::new(&[&t.k[1], &t.b], Turn::Own, None),
            LinkShape::new(&[&t.k[2], &t.p], Turn::Own, None),
            LinkShape::new(&[n], Turn::Own, None),
        ]
    }

    fn point_owner(&self) -> Option<Option<LinkName>> {
        Some(Some(LinkName::of(&self.stmt.links[3])))
    }

    fn position_values(&self) -> Vec<Value> {
        let t = self.t;
        let mut v: Vec<Value> = t.l.to_vec();
        v.push(t.ab.clone());
        match &t.p_local {
            Local::Polar(a, b) | Local::Cartesian(a, b) => v.extend([a.clone(), b.clone()]),
        }
        v.push(t.at.1.clone());
        for (x, y) in &t.near {
            v.extend([x.clone(), y.clone()]);
        }
        v
    }

    fn position_type(&self) -> TokenStream {
        quote!(::mechanism::triad::TriadPosition<T>)
    }

    fn position(&self, _cos_sin: bool) -> Solve {
        let dims = dims_code(self.t);
        let k = self.t.k.each_ref().map(local);
        let [k1, k2, k3] = &k;
        let hint = self.hint_code();
        Solve::Group {
            call: quote!({
                let near = #hint;
                ::mechanism::triad::position(&#dims, &[#k1, #k2, #k3], &near)
            }),
            joint: Some("a"),
        }
    }

    fn position_tracking(&self, reads: &Reads) -> Option<Solve> {
        let dims = dims_code(self.t);
        let k = self.t.k.each_ref().map(local);
        let [k1, k2, k3] = &k;
        let g = reads.pos(&grp(self.stmt));
        Some(Solve::Group {
            call: quote!(::mechanism::triad::position_near(&#dims, &[#k1, #k2, #k3], &#g)),
            joint: Some("a"),
        })
    }

    fn link_direction(&self, index: usize) -> (TokenStream, TokenStream) {
        match index {
            0..=2 => {
                let field = ["r1", "r2", "r3"][index];
                arm(self.stmt, field, self.t.l[index].emit())
            }
            _ => unit_field(self.stmt, "axis"),
        }
    }

    fn rates(&self, cx: &mut dyn RateCx) {
        let (g, gv) = states(self.stmt);
        let dims = dims_code(self.t);
        let [m1, m2, m3] = self.t.k.each_ref().map(|k| cx.point_arg(k));
        let g = cx.reads().pos(&g);
        let call = if cx.accel() {
            let gv = cx.reads().vel(&gv);
            quote!(::mechanism::triad::acceleration(&#dims, &#g, &#gv, #m1, #m2, #m3))
        } else {
            quote!(::mechanism::triad::velocity(&#dims, &#g, #m1, #m2, #m3))
        };
        let gr = cx.group(self.stmt, call, quote!(triad), "Triad");
        let (pt, rates) = if cx.accel() {
            (
                quote!(aa),
                [
                    quote!(alpha1),
                    quote!(alpha2),
                    quote!(alpha3),
                    quote!(alpha),
                ],
            )
        } else {
            (
                quote!(va),
                [
                    quote!(omega1),
                    quote!(omega2),
                    quote!(omega3),
                    quote!(omega),
                ],
            )
        };
        cx.named(cx.motion(self.stmt), quote!(#gr.#pt), vec_ty());
        for (i, r) in rates.iter().enumerate() {
            cx.named(cx.own(self.stmt, i), quote!(#gr.#r), quote!(T));
        }
    }

    fn rate_system(&self) -> bool {
        true
    }

    /// The three legs' lengths (`B` and `P` on the ternary are the link
    /// points' residuals).
    fn residuals(&self, r: &mut Residuals<'_>, _link_axis: &dyn Fn(&Ident) -> TokenStream) {
        let t = self.t;
        r.at_length("|A - K1| = l1", &t.k[0], f(&t.l[0]));
        for (j, k, l, what) in [
            (&t.b, &t.k[1], &t.l[1], "|B - K2| = l2"),
            (&t.p, &t.k[2], &t.l[2], "|P - K3| = l3"),
        ] {
            let (j, k, l) = (r.pos(j), r.pos(k), f(l));
            r.push(what, quote!(norm(sub(pt(&#j), pt(&#k))) - #l));
        }
    }

    fn closure_axis(&self, index: usize, reads: &Reads) -> TokenStream {
        let t = self.t;
        let (from, to) = match index {
            0 => (&t.k[0], &self.stmt.name),
            1 => (&t.k[1], &t.b),
            2 => (&t.k[2], &t.p),
            _ => (&self.stmt.name, &t.b),
        };
        super::closure::axis_between(from, to, reads)
    }

    fn link_lengths(&self) -> Vec<&'a Value> {
        let t = self.t;
        vec![&t.l[0], &t.l[1], &t.l[2], &t.ab]
    }

    fn explain_fault(&self, fault: &Fault, at: &str) -> Option<String> {
        let input = &self.t.at.0;
        let none = Tracked::default();
        let tracked = self.tracked.unwrap_or(&none);
        let show = |x: f64| {
            if tracked.angle {
                format!("{} deg", show_num(x.to_degrees()))
            } else {
                show_num(x)
            }
        };
        let ends: Vec<String> = tracked
            .ends
            .iter()
            .map(|(a, b)| format!("between `{input}` = {} and {}", show(*a), show(*b)))
            .collect();
        let from = "the assembly given by the triad's approximate pose";
        Some(match fault {
            Fault::NotNear { nearest, .. } if nearest.is_infinite() && !ends.is_empty() => format!(
                "at {at}, {from} no longer exists: followed from the input it is given at, it meets another assembly (a branch point) or vanishes {}; narrow the range to where it exists",
                ends.join(" and ")
            ),
            Fault::NotNear { nearest, .. } if nearest.is_infinite() => format!(
                "at {at}, the input lies outside where {from} was followed"
            ),
            Fault::NotNear { nearest, next } => format!(
                "at {at}, no assembly of the triad is clearly {from} followed there (nearest {}, next {}); check the approximate pose (A, B, P) and the input it is given at",
                show_num(*nearest),
                show_num(*next)
            ),
            Fault::CannotAssemble { .. } => format!(
                "at {at}, the triad's legs cannot reach a common pose of the ternary link (no assembly)"
            ),
            _ => return None,
        })
    }

    /// The rule that the approximate pose is given at a value of one of
    /// the definition's inputs (`INPUT = value` names a driver's input).
    fn check_inputs(&self, inputs: &[crate::model::Input], errors: &mut Diagnostics) {
        let at = &self.t.at.0;
        let inputs: Vec<String> = inputs.iter().map(|i| i.name.to_string()).collect();
        let name = at.to_string();
        if inputs.contains(&name) {
            return;
        }
        errors.push(
            at.span(),
            format!(
                "`{name}` is not an input: the triad's pose is given at a value of a driver's input ({}){}",
                inputs
                    .iter()
                    .map(|i| format!("`{i}`"))
                    .collect::<Vec<_>>()
                    .join(", "),
                crate::diag::did_you_mean(&name, inputs.iter().map(String::as_str))
            ),
        );
    }

    fn singular_meaning(&self) -> Option<String> {
        Some("the triad is at a branch point (two of its assemblies meet)".into())
    }

    /// Follows the stated assembly over the input's range ([`track`]): the
    /// tracked poses, which the sweep and the generated `position()` then
    /// read. A stated input outside the range, or a stated pose that
    /// selects no assembly, is an error on the statement.
    fn track<'l>(
        &self,
        before: &dyn Fn(f64) -> Option<NamedPose<'l>>,
        (lo, hi): (f64, f64),
        angle: bool,
        errors: &mut Diagnostics,
    ) -> Tracking {
        let t = self.t;
        let ks = |q: f64| {
            let pose = before(q)?;
            Some(t.k.each_ref().map(|k| pose.point(k)))
        };
        let e = match track(t, (lo, hi), angle, &ks) {
            Ok(tracked) => return Tracking::Tracked(Tracked { angle, ..tracked }),
            Err(e) => e,
        };
        let q =
            t.at.1
                .fold()
                .map_or(f64::NAN, |_| stated_input(t, (lo, hi), angle));
        let shown = |x: f64| {
            if angle {
                format!("{} deg", show_num(x.to_degrees()))
            } else {
                show_num(x)
            }
        };
        let inside = q >= lo && q <= hi;
        if inside {
            // On the pose's first coordinate.
            errors.push(
                t.near[0].0.span,
                format!(
                    "the approximate pose of `{}`, `{}`, `{}` given at `{} = {}` selects no assembly of the triad there ({}); give the joints' positions at that input to within a fraction of the legs' lengths",
                    self.stmt.name, t.b, t.p, t.at.0, shown(q), why(&e.fault)
                ),
            );
        } else {
            // On the input's value.
            errors.push(
                t.at.1.span,
                format!(
                    "the pose is given at `{} = {}`, outside the range checked, {} .. {}: give it at an input inside the range, or widen the range",
                    t.at.0,
                    shown(q),
                    shown(lo),
                    shown(hi)
                ),
            );
        }
        Tracking::Failed
    }

    fn primitive(&self) -> &'static str {
        "Triad"
    }

    fn det_code(&self, reads: &Reads) -> TokenStream {
        let g = reads.pos(&grp(self.stmt));
        quote!(<T as ::mechanism::Real>::as_f64(#g.jacobian))
    }

    fn describe(&self) -> String {
        let (n, t) = (&self.stmt.name, self.t);
        format!(
            "triad `{}`: `{}`, `{}`, `{}` -> `{n}`, `{}`, `{}`, the assembly near the pose given at `{}`",
            links_text(self.stmt),
            t.k[0],
            t.k[1],
            t.k[2],
            t.b,
            t.p,
            t.at.0
        )
    }

    fn forces(&self, cx: &mut dyn ForceCx) {
        forces(self, cx);
    }

    fn bodies_and_pairs(&self) -> (i64, i64, i64) {
        (4, 6, 0)
    }

    fn lane(&self, _lane: &mut Lane, _s: &mut Step<'_>) -> Option<()> {
        None
    }

    fn slide_field(&self, _slot: usize) -> TokenStream {
        quote!(s)
    }

    moving_joint_facets!();
}

/// The triad's reactions: the 12x12 system of `triad::reactions` from the
/// loads on its four links, passed (negated) to the bodies carrying `K1`,
/// `K2`, `K3`.
fn forces(kind: &TriadKind<'_>, cx: &mut dyn ForceCx) {
    let (stmt, t) = (kind.stmt, kind.t);
    let (rx, links, a) = (rx(stmt), &stmt.links, &stmt.name);
    let l = [
        cx.load_about(&links[0], a),
        cx.load_about(&links[1], &t.b),
        cx.load_about(&links[2], &t.p),
        cx.load_about(&links[3], a),
    ];
    let [l1, l2, l3, l4] = &l;
    let g = cx.reads().pos(&grp(stmt));
    cx.solve(
        stmt,
        quote!(::mechanism::triad::reactions(&#g, &::mechanism::triad::TriadLoads {
            leg1: #l1, leg2: #l2, leg3: #l3, ternary: #l4
        })),
    );
    for (i, field) in ["k1", "k2", "k3"].into_iter().enumerate() {
        let body = cx.pass_revolute(&t.k[i], &rx, field);
        cx.reaction(revolute(&rx, &body, &links[i], &t.k[i], field));
    }
    let joints = [a, &t.b, &t.p];
    for (i, field) in ["a", "b", "p"].into_iter().enumerate() {
        let from = Some(LinkName::of(&links[i]));
        cx.reaction(revolute(&rx, &from, &links[3], joints[i], field));
    }
    cx.condition(quote!(#rx.min_pivot_ratio));
}

/// For a dependency cycle of three `rrr` statements each pinned to one
/// known point outside the cycle (a class III group written as three
/// dyads): what it is and the `triad` statement to write instead, with the
/// names and lengths the statements give. `None` for any other cycle.
pub(super) fn cycle_hint(cycle: &[&Stmt]) -> Option<String> {
    let [j1, j2, j3] = cycle else {
        return None;
    };
    let names: Vec<String> = cycle.iter().map(|s| s.name.to_string()).collect();
    let legs: Vec<(String, String)> = cycle
        .iter()
        .map(|s| {
            let crate::model::Kind::Rrr { a, l1, b, l2, .. } = &s.kind else {
                return None;
            };
            let inside = |n: &Ident| names.contains(&n.to_string());
            let shown = |v: &Value| match v.fold() {
                Some(x) => show_num(x),
                None => v.tokens.to_string(),
            };
            match (inside(a), inside(b)) {
                (false, true) => Some((a.to_string(), shown(l1))),
                (true, false) => Some((b.to_string(), shown(l2))),
                _ => None,
            }
        })
        .collect::<Option<_>>()?;
    let (a, b, p) = (&j1.name, &j2.name, &j3.name);
    let known: Vec<String> = legs.iter().map(|(k, _)| format!("`{k}`")).collect();
    let args: Vec<String> = legs.iter().map(|(k, l)| format!("{k}, {l}")).collect();
    Some(format!(
        "`{a}`, `{b}`, `{p}` are the joints of a ternary link on three legs from {}: a class III group (a triad), which no order of `rrr` statements can solve. Write the three as one statement: `let ({a}, {b}, {p}) = triad({}, |{a}{b}|, |{a}{p}|, angle of {p} from {a} -> {b}, INPUT = value, ({a}x, {a}y), ({b}x, {b}y), ({p}x, {p}y)) as (LEG1, LEG2, LEG3, TERNARY);` with the ternary link's shape and the joints' approximate positions at one input value (`docs/dsl.md`, \"triad\")",
        known.join(", "),
        args.join(", ")
    ))
}

/// Why a triad's stated pose selects no assembly, in numbers.
fn why(fault: &Fault) -> String {
    match fault {
        Fault::NotNear { nearest, next } => format!(
            "the nearest assembly is {} from it, more than {} (half the shortest link) or not half as far as the next",
            show_num(*nearest),
            show_num(*next)
        ),
        Fault::CannotAssemble { .. } => "it has no assembly at that input".into(),
        other => other.to_string(),
    }
}

impl super::run::RunKind for TriadKind<'_> {
    fn compile(&self, cx: &Compile<'_>) -> Box<dyn super::run::Step> {
        let t = self.t;
        let num = |v: &Value| cx.num(v);
        let none = Tracked::default();
        let table = self.tracked.unwrap_or(&none);
        Box::new(TriadRun {
            me: cx.me(self.stmt),
            k: t.k.each_ref().map(|k| cx.point(k)),
            b: cx.point(&t.b),
            p: cx.point(&t.p),
            at: cx.input(&t.at.0),
            dims: dims(t, &num),
            stated: stated(t, &num),
            rows: table.rows.clone(),
            turning: table.angle,
        })
    }
}

/// A triad, compiled: its legs' known points, its joints `B` and `P`, the
/// input its hint follows, its dimensions, the stated pose and the
/// tracked table (empty: the stated pose is the hint).
struct TriadRun {
    me: Me,
    k: [PointSlot; 3],
    b: PointSlot,
    p: PointSlot,
    at: InputSlot,
    dims: triad::Triad<f64>,
    stated: Near<f64>,
    rows: Vec<[f64; 7]>,
    turning: bool,
}

impl TriadRun {
    /// The hint the position uses at `q`, as `TriadKind::hint`.
    fn hint(&self, q: f64) -> Result<Near<f64>, mechanism_core::Error<f64>> {
        if self.rows.is_empty() {
            Ok(self.stated)
        } else if self.turning {
            triad::near_from_table_turning(&self.rows, q)
        } else {
            triad::near_from_table(&self.rows, q)
        }
    }
}

impl super::run::Step for TriadRun {
    fn group(&self) -> &'static str {
        self.me.group
    }

    fn walks(&self) -> super::run::Walks {
        super::run::Walks::ALL
    }

    fn position(&self, pose: &mut RunPose) -> Result<Option<f64>, mechanism_core::Error<f64>> {
        let k = self.k.map(|k| pose.point(k));
        let near = self.hint(pose.input(self.at))?;
        let d = &self.dims;
        let p = triad::position(d, &k, &near)?;
        let axes = [p.r1 / d.l1, p.r2 / d.l2, p.r3 / d.l3, p.axis];
        pose.found(&self.me, p.a, &axes);
        pose.keep(&self.me, p);
        Ok(Some(p.jacobian))
    }

    fn rates(&self, cx: &mut RunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let me = &self.me;
        let missing = || super::run::missing(mechanism_core::Primitive::Triad);
        let g = cx
            .pose
            .kept::<triad::TriadPosition<f64>>(me)
            .ok_or_else(missing)?;
        let d = &self.dims;
        let [m1, m2, m3] = self.k.map(|k| cx.point_arg(k));
        if cx.accel() {
            let gv = cx
                .vel_group::<triad::TriadVelocity<f64>>(me)
                .ok_or_else(missing)?;
            let r = triad::acceleration(d, g, gv, m1.as_ref(), m2.as_ref(), m3.as_ref())?;
            cx.set_motion(me, r.aa);
            for (i, w) in [r.alpha1, r.alpha2, r.alpha3, r.alpha]
                .into_iter()
                .enumerate()
            {
                cx.set_own(me, i, w);
            }
        } else {
            let r = triad::velocity(d, g, m1.as_ref(), m2.as_ref(), m3.as_ref())?;
            cx.set_motion(me, r.va);
            for (i, w) in [r.omega1, r.omega2, r.omega3, r.omega]
                .into_iter()
                .enumerate()
            {
                cx.set_own(me, i, w);
            }
            cx.keep(me, r, Some(r.condition));
        }
        Ok(())
    }

    /// `triad::reactions` on the loads of its four links; the legs'
    /// reactions at `K1`, `K2`, `K3` passed to their bodies.
    fn forces(&self, cx: &mut ForceRunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let (me, links) = (&self.me, self.me.links);
        let loads = triad::TriadLoads {
            leg1: cx.load_about(links[0], me.point),
            leg2: cx.load_about(links[1], self.b),
            leg3: cx.load_about(links[2], self.p),
            ternary: cx.load_about(links[3], me.point),
        };
        let g = cx
            .pose
            .kept::<TriadPosition<f64>>(me)
            .ok_or_else(|| super::run::missing(mechanism_core::Primitive::Triad))?;
        let rx = triad::reactions(g, &loads)?;
        for (i, force) in [rx.k1, rx.k2, rx.k3].into_iter().enumerate() {
            let body = cx.pass_revolute(self.k[i], force);
            cx.revolute(body, links[i], force);
        }
        for (i, force) in [rx.a, rx.b, rx.p].into_iter().enumerate() {
            cx.revolute(Some(links[i]), links[3], force);
        }
        cx.conditions.push(rx.min_pivot_ratio);
        Ok(())
    }

    fn link_dir(&self, index: usize, pose: &RunPose) -> Vector2<f64> {
        let nan = Vector2::new(f64::NAN, f64::NAN);
        pose.kept::<triad::TriadPosition<f64>>(&self.me)
            .map_or(nan, |p| match index {
                0 => p.r1,
                1 => p.r2,
                2 => p.r3,
                _ => p.axis,
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::Diagnostics;
    use crate::model::{Kind, Model};

    /// The definition `src` lowered (it must have no errors).
    fn lowered(src: &str) -> Model {
        let def = syn::parse_str::<crate::parse::Definition>(src).expect("parses");
        let mut diag = Diagnostics::new();
        let model = crate::model::lower(def, &mut diag);
        let errors: Vec<String> = diag.finish().iter().map(ToString::to_string).collect();
        assert!(errors.is_empty(), "{errors:?}");
        model
    }

    const STEPHENSON: &str = "pub S {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.30, 0.0);
        let O6 = ground(0.05, 0.42);
        let C = crank(O6, 0.24, phi) as link6;
        let (A, B, P) = triad(O2, 0.08, O4, 0.20, C, 0.28, 0.26, 0.15, 40 deg,
                              phi = -49.48 deg, (-0.061, -0.052), (0.137, 0.116), (-0.036, 0.096))
            as (crank2, rocker, link5, coupler);
    }";

    #[test]
    fn a_triad_is_lowered_as_its_joint_a_and_two_points_on_the_ternary() {
        // Proves `let (A, B, P) = triad(..)` becomes the group statement `A`
        // with four links and `B`, `P` as points of the ternary link from
        // `A`: `B` at (ab, 0), `P` at the polar place given (in rad).
        let model = lowered(STEPHENSON);
        let names: Vec<String> = model.stmts.iter().map(|s| s.name.to_string()).collect();
        assert_eq!(names, ["O2", "O4", "O6", "C", "A", "B", "P"]);
        let a = &model.stmts[4];
        assert!(matches!(a.kind, Kind::Triad(_)));
        assert_eq!(a.links.len(), 4);
        for (stmt, want) in [
            (&model.stmts[5], (0.26, 0.0)),
            (&model.stmts[6], (0.15, 40f64.to_radians())),
        ] {
            let Kind::Point { link, from, local } = &stmt.kind else {
                panic!("{} is not a link point", stmt.name);
            };
            assert_eq!(
                (link.to_string(), from.to_string()),
                ("coupler".into(), "A".into())
            );
            let (x, y) = match local {
                Local::Cartesian(x, y) | Local::Polar(x, y) => (num(x), num(y)),
            };
            assert!(
                (x - want.0).abs() < 1e-15 && (y - want.1).abs() < 1e-15,
                "{x} {y}"
            );
        }
    }

    /// The Stephenson's known points `O2`, `O4` and `C` at link 6's angle
    /// `q` (rad), as `track` asks for them.
    fn stephenson_known(q: f64) -> Option<[Point2<f64>; 3]> {
        let c = Point2::new(0.05 + 0.24 * q.cos(), 0.42 + 0.24 * q.sin());
        Some([Point2::new(0.0, 0.0), Point2::new(0.30, 0.0), c])
    }

    #[test]
    fn tracking_over_a_range_wider_than_the_swing_finds_its_ends() {
        // Proves the expansion-time tracking of the stated assembly over
        // -60..0 deg stops at link 6's swing, whose ends (-50.4365077489 and
        // -2.6333554164 deg, from the double-double reference's fold points
        // in mechanism-core/tests/triad.rs) each lie inside a reported
        // interval one step (60/768 deg) wide; the table's inputs increase
        // and stay inside the swing, and every row closes the three legs.
        let model = lowered(STEPHENSON);
        let Kind::Triad(t) = &model.stmts[4].kind else {
            unreachable!()
        };
        let ks = stephenson_known;
        let (lo, hi) = ((-60f64).to_radians(), 0.0);
        let tracked = track(t, (lo, hi), false, &ks).expect("the stated pose selects an assembly");
        let step = (hi - lo) / ((ROWS - 1) * SUB) as f64;
        let mut ends = tracked.ends.clone();
        ends.sort_by(|a, b| a.0.total_cmp(&b.0));
        assert_eq!(ends.len(), 2, "{ends:?}");
        for ((a, b), want) in ends.iter().zip([-50.4365077489f64, -2.6333554164]) {
            let want = want.to_radians();
            assert!(*a < want && want < *b, "{want} not in [{a}, {b}]");
            assert!((b - a - step).abs() < 1e-12, "{a} {b}");
        }
        let rows = &tracked.rows;
        assert!(rows.windows(2).all(|w| w[0][0] < w[1][0]));
        assert!(rows[0][0] > ends[0].0 && rows[rows.len() - 1][0] < ends[1].1);
        for r in rows {
            let [_, _, k3] = ks(r[0]).unwrap();
            let leg = |x: f64, y: f64, k: Point2<f64>| (x - k.x).hypot(y - k.y);
            assert!((leg(r[1], r[2], Point2::new(0.0, 0.0)) - 0.08).abs() < 1e-14);
            assert!((leg(r[3], r[4], Point2::new(0.30, 0.0)) - 0.20).abs() < 1e-14);
            assert!((leg(r[5], r[6], k3) - 0.28).abs() < 1e-14);
        }
    }

    #[test]
    fn the_table_crowds_its_rows_where_interpolation_needs_them() {
        // Proves the table's rows (`table_rows`) interpolate the tracked
        // assembly more closely than evenly spaced rows with as many rows
        // or more: over the Stephenson's declared range, the largest miss
        // of `triad::near_from_table` at every tracked step (root-sum-square
        // over A, B, P) against the one of rows every SUB steps, and that
        // the table keeps the first and last step and at most ROWS + 2 rows.
        let model = lowered(STEPHENSON);
        let Kind::Triad(t) = &model.stmts[4].kind else {
            unreachable!()
        };
        let ks = stephenson_known;
        let (lo, hi) = ((-50.43f64).to_radians(), (-2.64f64).to_radians());
        let tracked = track(t, (lo, hi), false, &ks).expect("tracks");
        // Every step again, from the first row's pose (the same steps the
        // check took, so the same poses).
        let steps = (ROWS - 1) * SUB;
        let h = (hi - lo) / steps as f64;
        let dims = dims(t, &num);
        let first = tracked.rows[0];
        let pt = |x: f64, y: f64| Point2::new(x, y);
        let mut prev = triad::position(
            &dims,
            &ks(first[0]).unwrap(),
            &Near::new(
                pt(first[1], first[2]),
                pt(first[3], first[4]),
                pt(first[5], first[6]),
            ),
        )
        .unwrap();
        let mut all = vec![first];
        for i in 1..=steps {
            let q = if i == steps { hi } else { lo + h * i as f64 };
            if q <= first[0] {
                continue;
            }
            let Ok(p) = triad::position_near(&dims, &ks(q).unwrap(), &prev) else {
                break;
            };
            all.push([q, p.a.x, p.a.y, p.b.x, p.b.y, p.p.x, p.p.y]);
            prev = p;
        }
        let worst = |table: &[[f64; 7]]| {
            all.iter().fold(0.0f64, |m, r| {
                let n = triad::near_from_table::<f64>(table, r[0]).unwrap();
                let d = [n.a.x, n.a.y, n.b.x, n.b.y, n.p.x, n.p.y];
                let d2: f64 = (0..6).map(|c| (d[c] - r[c + 1]).powi(2)).sum();
                m.max(d2.sqrt())
            })
        };
        let even: Vec<[f64; 7]> = all
            .iter()
            .enumerate()
            .filter(|(k, _)| k % SUB == 0 || *k == all.len() - 1)
            .map(|(_, r)| *r)
            .collect();
        let rows = &tracked.rows;
        assert!(rows.len() <= ROWS + 2 && rows.len() >= even.len() - 1);
        assert_eq!(rows[0], all[0]);
        assert_eq!(rows[rows.len() - 1], all[all.len() - 1]);
        let (adaptive, evenly) = (worst(rows), worst(&even));
        println!(
            "{} rows miss by at most {adaptive:.2e} m; {} evenly spaced by {evenly:.2e} m",
            rows.len(),
            even.len()
        );
        // Measured 1.08e-4 m against 6.72e-3 m.
        assert!(adaptive <= 0.05 * evenly, "{adaptive:e} vs {evenly:e}");
    }

    #[test]
    fn a_rejected_triad_still_defines_its_three_joints() {
        // Proves a triad whose arguments are rejected (a leg of length 0)
        // keeps `A`, `B` and `P` defined for the stubs, so the user's code
        // that reads them reports no follow-on error, and that the error is
        // the length's alone.
        let src = STEPHENSON.replace("O2, 0.08,", "O2, 0.0,");
        let def = syn::parse_str::<crate::parse::Definition>(&src).expect("parses");
        let mut diag = Diagnostics::new();
        let model = crate::model::lower(def, &mut diag);
        let errors: Vec<String> = diag.finish().iter().map(ToString::to_string).collect();
        assert_eq!(errors.len(), 1, "{errors:?}");
        assert!(
            errors[0].contains("first leg's length must be positive"),
            "{errors:?}"
        );
        let failed: Vec<String> = model.failed.iter().map(|f| f.name.to_string()).collect();
        assert_eq!(failed, ["A", "B", "P"]);
    }

    #[test]
    fn only_a_cycle_of_three_pinned_rrr_is_called_a_triad() {
        // Proves the cycle hint names the class III group, with the legs'
        // known points and lengths, for three RRR statements each pinned to
        // one point outside the cycle, and says nothing for a cycle of two.
        let model = lowered(
            "pub S {
                let O2 = ground(0.0, 0.0);
                let O4 = ground(0.30, 0.0);
                let C = ground(0.2, 0.4);
                let A = rrr(O2, 0.08, B, 0.26, left);
                let B = rrr(O4, 0.20, P, 0.15, right);
                let P = rrr(C, 0.28, A, 0.15, left);
            }",
        );
        let cycle: Vec<&Stmt> = model.stmts[3..].iter().collect();
        let hint = cycle_hint(&cycle).expect("a triad");
        assert!(hint.contains("class III"), "{hint}");
        assert!(hint.contains("triad(O2, 0.08, O4, 0.2, C, 0.28,"), "{hint}");
        assert!(cycle_hint(&cycle[..2]).is_none());
    }
}
