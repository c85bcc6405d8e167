//! Stage 6, check: the declared input ranges, and the mechanism assembled over
//! them at expansion time.
//!
//! - [`inputs`] reads the `range` statements (and the default: a crank turns
//!   fully; sliders and actuators have no default range) and [`allowances`]
//!   the `allow singular` statements, with errors on the user's tokens.
//! - [`expansion_check`]: when every dimension the position analysis uses is
//!   known at expansion time (literals and `const`s, no `params`), the
//!   mechanism is solved in `f64` through the same `mechanism-core` primitives
//!   the generated code calls, in the plan's solve order, over the input range,
//!   by the sweep of `mechanism_core::sweep` (the one the generated `check()`
//!   runs). A group that cannot be assembled somewhere is a compile error on
//!   the group's name, with the input interval and a hint computed from the
//!   numbers; a singular position (toggle, dead centre) is a warning
//!   (`#[deprecated]` on a generated item used at the group's name: the only
//!   warning a stable proc macro can raise).
//! - [`emit_check`]: the generated `check()`, the same sweep at run time
//!   through the generated `position()`, for any parameters.
//!
//! Two inputs are checked only when both have declared ranges (a grid over the
//! box); three or more are not checked.

use crate::model::{did_you_mean, Errors, Kind, Local, Mode, Model, Origin};
use crate::parse::{Arg, RangeDecl};
use crate::plan::Plan;
use crate::value::{convert, Scope, Value};
use mechanism_core::guide::Line;
use mechanism_core::sweep::{self, Event, Outcome, Range, Tolerances};
use mechanism_core::{driver, dyad, geometry, link, Fault, Point2, Vector2};
use proc_macro2::{Span, TokenStream};
use quote::{format_ident, quote, quote_spanned};
use std::collections::BTreeMap;
use std::f64::consts::PI;
use syn::Ident;

/// What the definition declares for the checks.
#[derive(Default)]
pub struct Declared {
    /// `range INPUT = (lo, hi);` statements.
    pub ranges: Vec<RangeDecl>,
    /// `allow singular [groups];` statements: the keyword's span, the word
    /// after it, the groups (empty: every group).
    pub allow: Vec<(Span, Ident, Vec<Ident>)>,
    /// `#[self_test]`.
    pub self_test: Option<Span>,
}

/// One driver input, as the checks see it.
#[derive(Clone)]
pub struct Input {
    /// Its name (a field of the generated input struct).
    pub name: Ident,
    /// `true` for a crank angle (rad; shown in deg).
    pub angle: bool,
    /// The range to check; `None`: none declared and no default (a slider or
    /// an actuator).
    pub range: Option<Range>,
    /// `true` when the range was declared.
    pub declared: bool,
    /// Where the declared range is written: its input's name, its lower and
    /// its upper end (the spans of a failure the range is to blame for).
    pub spans: Option<RangeSpans>,
}

/// The tokens of a `range INPUT = (lo, hi);` statement.
#[derive(Clone, Copy)]
pub struct RangeSpans {
    /// `INPUT`.
    pub input: Span,
    /// The value of `lo`.
    pub lo: Span,
    /// The value of `hi`.
    pub hi: Span,
}

/// Most groups the expansion-time check handles (more: not checked).
const MAX_GROUPS: usize = 64;

struct ConstScope<'a>(&'a Model);

impl Scope for ConstScope<'_> {
    fn constant(&self, name: &Ident) -> Option<f64> {
        self.0.consts.get(&name.to_string()).map(|c| c.1)
    }
    fn is_param(&self, _: &Ident) -> bool {
        false
    }
    fn not_a_number(&self, name: &Ident) -> syn::Error {
        let s = name.to_string();
        if self.0.params.iter().any(|(p, _)| p == name) {
            return syn::Error::new(
                name.span(),
                format!("a range must be known at compile time: `{s}` is a run-time parameter; use a literal or a `const`"),
            );
        }
        let consts: Vec<&str> = self.0.consts.keys().map(String::as_str).collect();
        syn::Error::new(
            name.span(),
            format!(
                "cannot find constant `{s}`{}; a range bound is a literal or a `const`",
                did_you_mean(&s, consts)
            ),
        )
    }
}

/// One bound of a range, in rad (angles) or length units.
fn bound(model: &Model, arg: &Arg, input: &Ident, angle: bool, errors: &mut Errors) -> Option<f64> {
    let (expr, unit) = match arg {
        Arg::Value(e, u) => (e, u),
        Arg::From(i) => {
            errors.push(i.span(), "expected a number here, not `from`");
            return None;
        }
    };
    let value = match convert(expr, &ConstScope(model)) {
        Ok(v) => v,
        Err(e) => {
            errors.0.push(e);
            return None;
        }
    };
    let x = value.fold()?;
    match unit {
        None => Some(x),
        Some(u) if angle && u == "deg" => Some(x.to_radians()),
        Some(u) if angle && u == "rad" => Some(x),
        Some(u) if angle => {
            errors.push(
                u.span(),
                format!("unknown angle unit `{u}`; write `deg` or `rad`"),
            );
            None
        }
        Some(u) => {
            errors.push(
                u.span(),
                format!("`{input}` is a displacement (length units): its range takes no unit, remove `{u}`"),
            );
            None
        }
    }
}

/// The driver inputs, in the order of the generated input struct, with their
/// ranges; reports bad `range` statements.
pub fn inputs(model: &Model, errors: &mut Errors) -> Vec<Input> {
    let mut inputs: Vec<Input> = model
        .stmts
        .iter()
        .filter_map(|s| {
            let angle = matches!(s.kind, Kind::Crank { .. });
            s.kind.input().map(|name| Input {
                name: name.clone(),
                angle,
                range: angle.then_some(Range {
                    lo: 0.0,
                    hi: 2.0 * PI,
                    periodic: true,
                }),
                declared: false,
                spans: None,
            })
        })
        .collect();
    for decl in &model.checks.ranges {
        let Some(k) = inputs.iter().position(|i| i.name == decl.input) else {
            let names: Vec<String> = inputs.iter().map(|i| i.name.to_string()).collect();
            let s = decl.input.to_string();
            errors.push(
                decl.input.span(),
                format!(
                    "`{s}` is not a driver input; a range is declared for the input of a `crank`, `slider` or `actuator`{}",
                    did_you_mean(&s, names.iter().map(String::as_str))
                ),
            );
            continue;
        };
        if inputs[k].declared {
            errors.push(
                decl.input.span(),
                format!("the range of `{}` is declared twice", decl.input),
            );
            continue;
        }
        let angle = inputs[k].angle;
        let lo = bound(model, &decl.lo, &decl.input, angle, errors);
        let hi = bound(model, &decl.hi, &decl.input, angle, errors);
        let (Some(lo), Some(hi)) = (lo, hi) else {
            inputs[k].declared = true;
            continue;
        };
        // A negative end is spanned on its number (a span cannot join `-`
        // and the number on stable Rust; the `-` alone reads as the fault).
        let arg_span = |a: &Arg| match a {
            Arg::Value(syn::Expr::Unary(u), _) => syn::spanned::Spanned::span(&*u.expr),
            Arg::Value(e, _) => syn::spanned::Spanned::span(e),
            Arg::From(i) => i.span(),
        };
        let span = arg_span(&decl.hi);
        inputs[k].spans = Some(RangeSpans {
            input: decl.input.span(),
            lo: arg_span(&decl.lo),
            hi: span,
        });
        let show = |x: f64| show_value(x, angle);
        if lo >= hi || !lo.is_finite() || !hi.is_finite() {
            errors.push(
                span,
                format!(
                    "the range of `{}` is empty: the upper end must be above the lower, got ({}, {})",
                    decl.input,
                    show(lo),
                    show(hi)
                ),
            );
        } else if !(hi - lo).is_finite() || (hi - lo) / sweep::SAMPLES_1D as f64 <= 0.0 {
            // The sweep steps by (hi - lo) / samples: a width that overflows
            // (or a step that underflows) would leave it nothing to sample.
            let sci = |x: f64| {
                if angle {
                    format!("{:e} deg", x.to_degrees())
                } else {
                    format!("{x:e}")
                }
            };
            let why = if (hi - lo).is_finite() {
                format!(
                    "its sample step (width / {}) underflows to 0; widen the range",
                    sweep::SAMPLES_1D
                )
            } else {
                "its width hi - lo overflows an f64; narrow the range".to_string()
            };
            errors.push(
                span,
                format!(
                    "the range of `{}`, ({}, {}), cannot be swept: {why}",
                    decl.input,
                    sci(lo),
                    sci(hi),
                ),
            );
        } else if angle && hi - lo > 2.0 * PI * (1.0 + 1e-12) {
            errors.push(
                span,
                format!(
                    "the range of `{}` spans {} : a crank's range spans at most a full turn (360 deg)",
                    decl.input,
                    show(hi - lo)
                ),
            );
        } else {
            let periodic = angle && hi - lo >= 2.0 * PI * (1.0 - 1e-12);
            inputs[k].range = Some(Range { lo, hi, periodic });
        }
        inputs[k].declared = true;
    }
    inputs
}

/// Groups whose singular positions are allowed: `None` = none, `Some(empty)`
/// = all. Reports bad `allow` statements.
pub fn allowances(model: &Model, errors: &mut Errors) -> Option<Vec<String>> {
    let mut allowed: Option<Vec<String>> = None;
    let groups: Vec<String> = model
        .stmts
        .iter()
        .filter(|s| group_kind(&s.kind).is_some())
        .map(|s| s.name.to_string())
        .collect();
    for (_, what, names) in &model.checks.allow {
        if what != "singular" {
            errors.push(
                what.span(),
                format!("`allow {what}` is unknown; write `allow singular;` (every group) or `allow singular B, C;` (those groups)"),
            );
            continue;
        }
        let list = allowed.get_or_insert_with(Vec::new);
        if names.is_empty() {
            list.clear();
            list.push(String::new());
        }
        for n in names {
            let s = n.to_string();
            if groups.contains(&s) {
                list.push(s);
            } else {
                errors.push(
                    n.span(),
                    format!(
                        "`{s}` is not a group or driver: `allow singular` names the point a group defines{}",
                        did_you_mean(&s, groups.iter().map(String::as_str))
                    ),
                );
            }
        }
    }
    allowed.map(|mut l| {
        if l.iter().any(String::is_empty) {
            l.clear();
        }
        l
    })
}

fn is_allowed(allowed: &Option<Vec<String>>, group: &str) -> bool {
    match allowed {
        None => false,
        Some(list) => list.is_empty() || list.iter().any(|g| g == group),
    }
}

/// The kind name of a statement that can fail (drivers, groups, link points).
fn group_kind(kind: &Kind) -> Option<&'static str> {
    Some(match kind {
        Kind::Crank { .. } => "crank",
        Kind::Slider { .. } => "slider",
        Kind::Actuator { .. } => "actuator",
        Kind::Rrr { .. } => "RRR",
        Kind::Rrp { .. } => "RRP",
        Kind::Rpr { .. } => "RPR",
        Kind::Prp { .. } => "PRP",
        Kind::Rpp { .. } => "RPP",
        Kind::Point { .. } => "link point",
        Kind::Ground { .. } | Kind::Guide { .. } => return None,
    })
}

/// The statements the generated `position()` solves (those the outputs
/// need), in solve order, and among them the checked groups.
pub struct Checked {
    /// Statement indices in solve order.
    pub order: Vec<usize>,
    /// Statement indices of the checked groups (drivers, groups, link points).
    pub groups: Vec<usize>,
}

/// The statements `position()` solves and the checked groups among them.
pub fn checked(model: &Model, plan: &Plan) -> Checked {
    let out = crate::emit::outputs(model, plan);
    let needed = crate::emit::needed_statements(model, plan, &out);
    let order: Vec<usize> = plan
        .order
        .iter()
        .copied()
        .filter(|i| needed.contains(i))
        .collect();
    let groups = order
        .iter()
        .copied()
        .filter(|&i| group_kind(&model.stmts[i].kind).is_some())
        .collect();
    Checked { order, groups }
}

/// Every value `position()` uses, for the statements in `order`.
fn position_values(model: &Model, order: &[usize]) -> Vec<Value> {
    let mut v = Vec::new();
    for &i in order {
        match &model.stmts[i].kind {
            Kind::Ground { x, y } => v.extend([x.clone(), y.clone()]),
            Kind::Guide { origin, angle, .. } => {
                if let Origin::Coords(x, y) = origin {
                    v.extend([x.clone(), y.clone()]);
                }
                v.push(angle.clone());
            }
            Kind::Crank { radius, .. } => v.push(radius.clone()),
            Kind::Slider { offset, .. } => v.push(offset.clone()),
            Kind::Actuator { l, .. } => v.push(l.clone()),
            Kind::Rrr { l1, l2, .. } => v.extend([l1.clone(), l2.clone()]),
            Kind::Rrp { l, offset, .. } => v.extend([l.clone(), offset.clone()]),
            Kind::Rpr { offset, .. } => v.push(offset.clone()),
            Kind::Prp {
                offset1, offset2, ..
            } => v.extend([offset1.clone(), offset2.clone()]),
            Kind::Rpp { slot, offset, .. } => v.extend([slot.clone(), offset.clone()]),
            Kind::Point { local, .. } => match local {
                Local::Polar(a, b) | Local::Cartesian(a, b) => v.extend([a.clone(), b.clone()]),
            },
        }
    }
    v
}

fn num(v: &Value) -> f64 {
    v.fold().unwrap_or(f64::NAN)
}

fn mode(m: Mode) -> mechanism_core::Mode {
    match m {
        Mode::Plus => mechanism_core::Mode::Plus,
        Mode::Minus => mechanism_core::Mode::Minus,
    }
}

/// The expansion-time evaluator: the position analysis in `f64`.
struct Evaluator<'a> {
    model: &'a Model,
    order: &'a [usize],
    /// Group index of each checked statement.
    group: BTreeMap<usize, usize>,
    /// Input index by name.
    input: BTreeMap<String, usize>,
}

impl Evaluator<'_> {
    fn solve(&self, q: &[f64]) -> Outcome<MAX_GROUPS> {
        let nan = Point2::new(f64::NAN, f64::NAN);
        let mut points: BTreeMap<String, Point2<f64>> = BTreeMap::new();
        let mut guides: BTreeMap<String, Line<f64>> = BTreeMap::new();
        let mut axes: BTreeMap<String, Vector2<f64>> = BTreeMap::new();
        let mut dets = [1.0; MAX_GROUPS];
        for &i in self.order {
            let stmt = &self.model.stmts[i];
            let g = self.group.get(&i).copied().unwrap_or(0);
            let fail = |e: mechanism_core::Error| (g, e.fault);
            let pt = |n: &Ident| points.get(&n.to_string()).copied().unwrap_or(nan);
            let line = |n: &Ident| {
                guides.get(&n.to_string()).copied().unwrap_or(Line {
                    origin: nan,
                    dir: Vector2::new(f64::NAN, f64::NAN),
                })
            };
            let inp = |n: &Ident| {
                self.input
                    .get(&n.to_string())
                    .and_then(|&k| q.get(k))
                    .copied()
                    .unwrap_or(f64::NAN)
            };
            let name = stmt.name.to_string();
            let link = |k: usize| stmt.links[k].to_string();
            match &stmt.kind {
                Kind::Ground { x, y } => {
                    points.insert(name, Point2::new(num(x), num(y)));
                }
                Kind::Guide {
                    origin,
                    angle,
                    carrier,
                } => {
                    let origin = match origin {
                        Origin::Point(p) => pt(p),
                        Origin::Coords(x, y) => Point2::new(num(x), num(y)),
                    };
                    let u = geometry::unit(num(angle));
                    let dir = match carrier {
                        None => u,
                        Some(l) => {
                            let axis = axes
                                .get(&l.to_string())
                                .copied()
                                .unwrap_or(Vector2::new(f64::NAN, f64::NAN));
                            link::local_offset(&axis, &u)
                        }
                    };
                    guides.insert(name, Line { origin, dir });
                }
                Kind::Crank {
                    pivot,
                    radius,
                    input,
                    ..
                } => {
                    let c = driver::crank::position(&pt(pivot), num(radius), inp(input))
                        .map_err(fail)?;
                    points.insert(name, c.tip);
                    axes.insert(link(0), c.axis);
                }
                Kind::Slider {
                    guide,
                    input,
                    offset,
                } => {
                    let g = line(guide);
                    let s = driver::slider::position(&g, num(offset), inp(input)).map_err(fail)?;
                    points.insert(name, s.p);
                    axes.insert(link(0), g.dir);
                }
                Kind::Actuator {
                    a,
                    l,
                    b,
                    input,
                    mode: m,
                } => {
                    let len = inp(input);
                    let p = driver::actuator::position(&pt(a), num(l), &pt(b), len, mode(*m))
                        .map_err(fail)?;
                    dets[g] = sweep::det_rrr(&p);
                    points.insert(name, p.c);
                    axes.insert(link(0), p.r1 / num(l));
                    axes.insert(link(1), p.r2 / len);
                }
                Kind::Rrr {
                    a,
                    l1,
                    b,
                    l2,
                    mode: m,
                } => {
                    let p = dyad::rrr::position(&pt(a), num(l1), &pt(b), num(l2), mode(*m))
                        .map_err(fail)?;
                    dets[g] = sweep::det_rrr(&p);
                    points.insert(name, p.c);
                    axes.insert(link(0), p.r1 / num(l1));
                    axes.insert(link(1), p.r2 / num(l2));
                }
                Kind::Rrp {
                    a,
                    l,
                    guide,
                    mode: m,
                    offset,
                } => {
                    let gl = line(guide);
                    let p = dyad::rrp::position(&pt(a), num(l), &gl, num(offset), mode(*m))
                        .map_err(fail)?;
                    dets[g] = sweep::det_rrp(&p, &gl);
                    points.insert(name, p.c);
                    axes.insert(link(0), p.r1 / num(l));
                    axes.insert(link(1), gl.dir);
                }
                Kind::Rpr {
                    a,
                    b,
                    mode: m,
                    offset,
                } => {
                    let (pa, pb) = (pt(a), pt(b));
                    let p = dyad::rpr::position(&pa, &pb, num(offset), mode(*m)).map_err(fail)?;
                    dets[g] = sweep::det_rpr(&p, &pa, &pb);
                    axes.insert(link(0), p.axis);
                    axes.insert(link(1), p.axis);
                }
                Kind::Prp {
                    g1,
                    g2,
                    offset1,
                    offset2,
                } => {
                    let (l1, l2) = (line(g1), line(g2));
                    let p =
                        dyad::prp::position(&l1, num(offset1), &l2, num(offset2)).map_err(fail)?;
                    dets[g] = sweep::det_prp(&l1, &l2);
                    points.insert(name, p.c);
                    axes.insert(link(0), l1.dir);
                    axes.insert(link(1), l2.dir);
                }
                Kind::Rpp {
                    a,
                    guide,
                    slot,
                    offset,
                } => {
                    let gl = line(guide);
                    let u = geometry::unit(num(slot));
                    let p = dyad::rpp::position(&pt(a), &gl, num(offset), &u).map_err(fail)?;
                    dets[g] = sweep::det_rpp(&p, &gl);
                    points.insert(name, p.q);
                    axes.insert(link(0), p.slot);
                    axes.insert(link(1), gl.dir);
                }
                Kind::Point {
                    link: on,
                    from,
                    local,
                } => {
                    let local = match local {
                        Local::Cartesian(x, y) => Vector2::new(num(x), num(y)),
                        Local::Polar(d, a) => geometry::unit(num(a)) * num(d),
                    };
                    let axis = axes
                        .get(&on.to_string())
                        .copied()
                        .unwrap_or(Vector2::new(f64::NAN, f64::NAN));
                    let p = link::point_position(&pt(from), &axis, &local).map_err(fail)?;
                    points.insert(name, p);
                }
            }
        }
        Ok(dets)
    }
}

/// A number for a message: up to 6 decimals, trailing zeros removed.
fn show_num(x: f64) -> String {
    let s = format!("{x:.6}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

/// An input value for a message: degrees for angles.
fn show_value(x: f64, angle: bool) -> String {
    if angle {
        format!("{} deg", show_num(x.to_degrees()))
    } else {
        show_num(x)
    }
}

fn show_interval(lo: f64, hi: f64, angle: bool) -> String {
    let (lo, hi) = if angle {
        (lo.to_degrees(), hi.to_degrees())
    } else {
        (lo, hi)
    };
    format!(
        "[{}, {}]{}",
        show_num(lo),
        show_num(hi),
        if angle { " deg" } else { "" }
    )
}

/// A range statement for a hint: the interval shrunk inward to whole tenths
/// (deg for angles), strictly inside; `None` when nothing is left.
fn suggest(input: &Input, lo: f64, hi: f64) -> Option<String> {
    let (lo, hi, unit) = if input.angle {
        (lo.to_degrees(), hi.to_degrees(), " deg")
    } else {
        (lo, hi, "")
    };
    let scale = if input.angle {
        10.0
    } else {
        // Two significant digits of the width below its leading digit.
        let w = hi - lo;
        if w <= 0.0 {
            return None;
        }
        10f64.powi(2 - w.log10().ceil() as i32)
    };
    let a = (lo * scale).floor() / scale + 1.0 / scale;
    let b = (hi * scale).ceil() / scale - 1.0 / scale;
    (a < b).then(|| {
        format!(
            "`range {} = ({}{unit}, {}{unit});`",
            input.name,
            show_num(a),
            show_num(b)
        )
    })
}

/// What the failing group's fault means, in the user's words.
fn explain(model: &Model, stmt_index: usize, fault: &Fault, at: &str) -> String {
    let stmt = &model.stmts[stmt_index];
    match (&stmt.kind, fault) {
        (Kind::Actuator { a, b, .. }, Fault::CannotAssemble { miss, reach }) => format!(
            "at {at}, `{a}` and `{b}` are {} outside the distances the link and the cylinder can span (bound {})",
            show_num(*miss),
            show_num(*reach)
        ),
        (Kind::Rrr { a, l1, b, l2, .. }, Fault::CannotAssemble { miss, reach }) => {
            let (l1, l2) = (num(l1), num(l2));
            if (reach - (l1 + l2)).abs() <= 1e-9 * reach.abs().max(1.0) {
                format!(
                    "at {at}, `{a}` and `{b}` are {} apart, {} more than the links reach ({} + {} = {})",
                    show_num(reach + miss),
                    show_num(*miss),
                    show_num(l1),
                    show_num(l2),
                    show_num(*reach)
                )
            } else {
                format!(
                    "at {at}, `{a}` and `{b}` are {} apart, {} less than the links' difference (|{} - {}| = {})",
                    show_num(reach - miss),
                    show_num(*miss),
                    show_num(l1),
                    show_num(l2),
                    show_num(*reach)
                )
            }
        }
        (Kind::Rrp { a, guide, .. }, Fault::CannotAssemble { miss, reach }) => format!(
            "at {at}, `{a}` is {} from the line of guide `{guide}`, {} more than the link's length {} reaches",
            show_num(reach + miss),
            show_num(*miss),
            show_num(*reach)
        ),
        (Kind::Rpr { a, b, .. }, Fault::CannotAssemble { miss, reach }) => format!(
            "at {at}, `{a}` is {} from `{b}`, {} inside the offset {} of the slide line",
            show_num(reach - miss),
            show_num(*miss),
            show_num(*reach)
        ),
        (Kind::Prp { g1, g2, .. }, Fault::Singular { .. }) => format!(
            "at {at}, guides `{g1}` and `{g2}` are parallel: the joint is at infinity"
        ),
        (Kind::Rpp { guide, .. }, Fault::Singular { .. }) => format!(
            "at {at}, the slot is parallel to guide `{guide}`: the joint is at infinity"
        ),
        (_, fault) => format!("at {at}: {fault}"),
    }
}

/// Why a group is singular, in the user's words.
fn singular_meaning(model: &Model, stmt_index: usize) -> String {
    let stmt = &model.stmts[stmt_index];
    let l = |k: usize| stmt.links[k].to_string();
    match &stmt.kind {
        Kind::Rrr { .. } => format!("links `{}` and `{}` are aligned (toggle)", l(0), l(1)),
        Kind::Actuator { .. } => format!(
            "the cylinder `{}` is aligned with link `{}` (dead centre)",
            l(1),
            l(0)
        ),
        Kind::Rrp { guide, .. } => format!(
            "link `{}` is perpendicular to guide `{guide}` (the block cannot be pushed along it)",
            l(0)
        ),
        Kind::Rpr { a, b, .. } => {
            format!("`{a}` is at the foot of the perpendicular from `{b}` on the slide line")
        }
        Kind::Prp { g1, g2, .. } => format!("guides `{g1}` and `{g2}` are parallel"),
        Kind::Rpp { guide, .. } => format!("the slot is parallel to guide `{guide}`"),
        _ => "its rate system is singular".into(),
    }
}

/// For a crank driving an RRR group onto a ground point: the four-bar's
/// Grashof condition, in numbers.
fn grashof(model: &Model, plan: &Plan, stmt_index: usize) -> Option<String> {
    let stmt = &model.stmts[stmt_index];
    let Kind::Rrr { a, l1, b, l2, .. } = &stmt.kind else {
        return None;
    };
    let find = |n: &Ident| plan.defined.get(&n.to_string()).map(|&i| &model.stmts[i]);
    let ground = |n: &Ident| match find(n).map(|s| &s.kind) {
        Some(Kind::Ground { x, y }) => Some((num(x), num(y))),
        _ => None,
    };
    let (crank, other) = match (find(a).map(|s| &s.kind), find(b).map(|s| &s.kind)) {
        (Some(Kind::Crank { .. }), _) => (find(a)?, b),
        (_, Some(Kind::Crank { .. })) => (find(b)?, a),
        _ => return None,
    };
    let Kind::Crank { pivot, radius, .. } = &crank.kind else {
        return None;
    };
    let (o, g) = (ground(pivot)?, ground(other)?);
    let base = (o.0 - g.0).hypot(o.1 - g.1);
    let r = num(radius);
    let mut links = [
        (r, format!("crank {}", show_num(r))),
        (num(l1), show_num(num(l1))),
        (num(l2), show_num(num(l2))),
        (base, format!("ground {}", show_num(base))),
    ];
    links.sort_by(|x, y| x.0.total_cmp(&y.0));
    let (s, p, q, l) = (&links[0], &links[1], &links[2], &links[3]);
    let text = format!(
        "s + l = {} + {} = {}, p + q = {} + {} = {}",
        s.1,
        l.1,
        show_num(s.0 + l.0),
        p.1,
        q.1,
        show_num(p.0 + q.0)
    );
    Some(if s.0 + l.0 > p.0 + q.0 {
        format!("the four-bar `{pivot}`-`{}`-`{}`-`{other}` is not Grashof ({text}): no link turns fully", crank.name, stmt.name)
    } else if s.0 < r {
        format!("the four-bar `{pivot}`-`{}`-`{}`-`{other}` is Grashof ({text}), but the crank is not its shortest link: only the shortest link turns fully", crank.name, stmt.name)
    } else {
        return None;
    })
}

/// One sweep event: group, lower corner (or the singular input), upper
/// corner, fault, count, `true` for a singular position.
type Found = (usize, Vec<f64>, Vec<f64>, Fault, u32, bool);

/// The expansion-time check's findings.
pub struct Findings {
    /// Compile errors.
    pub errors: Vec<syn::Error>,
    /// Warning items (`#[deprecated]` uses).
    pub warnings: TokenStream,
    /// What was checked, for the generated doc comment.
    pub summary: String,
    /// Singular inputs found (allowed or not): (group index, input).
    pub singular: Vec<(usize, Vec<f64>)>,
    /// `true` when the check ran at expansion time.
    pub ran: bool,
}

/// Per checked group: `true` for a group whose joint runs off to infinity
/// where its determinant vanishes (PRP: parallel guides; RPP: the slot
/// parallel to the guide): there the position itself fails, whether or not a
/// sample lands on it.
fn joints_at_infinity(model: &Model, checked: &Checked) -> Vec<bool> {
    checked
        .groups
        .iter()
        .map(|&i| matches!(model.stmts[i].kind, Kind::Prp { .. } | Kind::Rpp { .. }))
        .collect()
}

/// A singular position found by the sweep, as a finding: a failure at that
/// one input for a group whose joint is at infinity there (so the verdict does
/// not depend on whether a sample lands on the point), a singular position
/// otherwise.
fn singular_event(at_infinity: &[bool], group: usize, at: &[f64], det: f64, count: u32) -> Found {
    if at_infinity[group] {
        let fault = Fault::Singular { det, scale: 1.0 };
        (group, at.to_vec(), at.to_vec(), fault, count, false)
    } else {
        let fault = Fault::NonFinite { what: "" };
        (group, at.to_vec(), at.to_vec(), fault, count, true)
    }
}

/// Runs the expansion-time check (see the module documentation).
pub fn expansion_check(
    model: &Model,
    plan: &Plan,
    inputs: &[Input],
    allowed: &Option<Vec<String>>,
) -> Findings {
    let mut findings = Findings {
        errors: Vec::new(),
        warnings: TokenStream::new(),
        summary: String::new(),
        singular: Vec::new(),
        ran: false,
    };
    let checked = checked(model, plan);
    let ranges: Vec<Range> = inputs.iter().filter_map(|i| i.range).collect();
    if ranges.len() != inputs.len() || inputs.is_empty() {
        let missing: Vec<String> = inputs
            .iter()
            .filter(|i| i.range.is_none())
            .map(|i| format!("`{}`", i.name))
            .collect();
        findings.summary = format!(
            "Not checked: no range is declared for {} (declare one with `range INPUT = (lo, hi);`).",
            missing.join(", ")
        );
        return findings;
    }
    if inputs.len() > 2 {
        findings.summary =
            "Not checked: the checks sweep one or two inputs, this mechanism has more.".into();
        return findings;
    }
    if inputs.len() == 2 && inputs.iter().any(|i| !i.declared) {
        findings.summary = "Not checked: a mechanism with two inputs is checked over a box of declared ranges; declare `range` for both inputs.".into();
        return findings;
    }
    let show_ranges = inputs
        .iter()
        .map(|i| {
            let r = i.range.expect("checked above");
            format!(
                "`{}` in {}{}",
                i.name,
                show_interval(r.lo, r.hi, i.angle),
                if i.declared {
                    ""
                } else {
                    " (a crank's full turn, the default)"
                }
            )
        })
        .collect::<Vec<_>>()
        .join(", ");
    if checked.groups.len() > MAX_GROUPS {
        findings.summary = format!("Not checked at expansion time: more than {MAX_GROUPS} groups; `check()` sweeps {show_ranges} at run time.");
        return findings;
    }
    if position_values(model, &checked.order)
        .iter()
        .any(|v| v.fold().is_none())
    {
        findings.summary = format!("Not checked at expansion time (the dimensions include run-time `params`): `check()` sweeps {show_ranges} for the parameters it is called on.");
        return findings;
    }
    findings.ran = true;
    let ev = Evaluator {
        model,
        order: &checked.order,
        group: checked
            .groups
            .iter()
            .enumerate()
            .map(|(k, &i)| (i, k))
            .collect(),
        input: inputs
            .iter()
            .enumerate()
            .map(|(k, i)| (i.name.to_string(), k))
            .collect(),
    };
    let mut events: Vec<Found> = Vec::new();
    let at_infinity = joints_at_infinity(model, &checked);
    let tol = Tolerances::for_eps(f64::EPSILON);
    if inputs.len() == 1 {
        sweep::sweep_1d(
            &ranges[0],
            sweep::SAMPLES_1D,
            &tol,
            |q| ev.solve(q),
            |e| match e {
                Event::Fails {
                    group,
                    lo,
                    hi,
                    fault,
                    count,
                } => events.push((group, lo.to_vec(), hi.to_vec(), fault, count, false)),
                Event::Singular {
                    group,
                    at,
                    count,
                    det,
                } => events.push(singular_event(&at_infinity, group, &at, det, count)),
            },
        );
    } else {
        sweep::sweep_2d(
            &[ranges[0], ranges[1]],
            sweep::SAMPLES_2D,
            |q| ev.solve(q),
            |e| match e {
                Event::Fails {
                    group,
                    lo,
                    hi,
                    fault,
                    count,
                } => events.push((group, lo.to_vec(), hi.to_vec(), fault, count, false)),
                Event::Singular {
                    group,
                    at,
                    count,
                    det,
                } => events.push(singular_event(&at_infinity, group, &at, det, count)),
            },
        );
    }
    findings.summary = format!(
        "Checked at expansion time over {show_ranges} ({}): every group assembles.",
        if inputs.len() == 1 {
            format!("{} samples, edges bisected", sweep::SAMPLES_1D + 1)
        } else {
            format!("a {0} x {0} grid", sweep::SAMPLES_2D + 1)
        }
    );
    // Errors, one per failing group (all its intervals in one message).
    let mut by_group: BTreeMap<usize, Vec<&Found>> = BTreeMap::new();
    for e in events.iter().filter(|e| !e.5) {
        by_group.entry(e.0).or_default().push(e);
    }
    for (g, list) in &by_group {
        let stmt_index = checked.groups[*g];
        let stmt = &model.stmts[stmt_index];
        let kind = group_kind(&stmt.kind).unwrap_or("group");
        // The span: the group's name, unless a declared range is to blame
        // (the group assembles somewhere in it): then the end of the range
        // it fails at, or the range's input when it fails inside.
        let mut span = stmt.name.span();
        let message = if inputs.len() == 1 {
            let input = &inputs[0];
            let name = &input.name;
            let intervals: Vec<String> = list
                .iter()
                .map(|e| {
                    if e.2[0] - e.1[0] <= 1e-9 * (ranges[0].hi - ranges[0].lo) {
                        format!("at {}", show_value(0.5 * (e.1[0] + e.2[0]), input.angle))
                    } else {
                        format!("in {}", show_interval(e.1[0], e.2[0], input.angle))
                    }
                })
                .collect();
            let worst = list
                .iter()
                .max_by(|x, y| (x.2[0] - x.1[0]).total_cmp(&(y.2[0] - y.1[0])))
                .expect("non-empty");
            let mid = 0.5 * (worst.1[0] + worst.2[0]);
            let mid_show = format!("{name} = {}", show_value(mid, input.angle));
            let why = match ev.solve(&[mid]) {
                Err((_, fault)) => explain(model, stmt_index, &fault, &mid_show),
                // A failure at one input (a joint at infinity between two
                // samples) is explained where it was found.
                Ok(_) if worst.2[0] == worst.1[0] => {
                    explain(model, stmt_index, &worst.3, &mid_show)
                }
                Ok(_) => explain(model, stmt_index, &worst.3, "the first failing sample"),
            };
            // Where it assembles: the complement of the failing intervals.
            let r = ranges[0];
            let mut fails: Vec<(f64, f64)> = events
                .iter()
                .filter(|e| !e.5)
                .map(|e| (e.1[0], e.2[0]))
                .collect();
            fails.sort_by(|x, y| x.0.total_cmp(&y.0));
            let mut free: Vec<(f64, f64)> = Vec::new();
            let (start, end) = if r.periodic && fails.first().is_some_and(|f| f.0 < r.lo) {
                let first = fails.remove(0);
                (first.1, first.0 + (r.hi - r.lo))
            } else {
                (r.lo, r.hi)
            };
            let mut at = start;
            for (a, b) in fails.iter().chain(std::iter::once(&(end, end))) {
                if *a > at {
                    free.push((at, *a));
                }
                at = at.max(*b);
            }
            // A turn: what assembles at its end continues at its start.
            if r.periodic && free.len() > 1 {
                let (first, last) = (free[0], free[free.len() - 1]);
                if first.0 <= r.lo && last.1 >= r.hi {
                    free.pop();
                    free[0] = (last.0 - (r.hi - r.lo), first.1);
                }
            }
            let best = free
                .iter()
                .max_by(|x, y| (x.1 - x.0).total_cmp(&(y.1 - y.0)))
                .map(|&(a, b)| {
                    // A turn's interval shown with its middle in (-180, 180] deg;
                    // a middle at 180 deg to rounding (an interval symmetric
                    // about 180 deg, whose ends were bisected to 1e-10 of the
                    // turn) stays at 180, not -180.
                    if input.angle && r.periodic {
                        let k = ((0.5 * (a + b) - PI) / (2.0 * PI) - 1e-9).ceil();
                        (a - 2.0 * PI * k, b - 2.0 * PI * k)
                    } else {
                        (a, b)
                    }
                });
            let where_ok = match best {
                Some((a, b)) => {
                    // An end where the group fails at a single input (a PRP's
                    // parallel guides) is not part of where it assembles:
                    // shown open, `(60, 240) deg`, not `[60, 240] deg`.
                    let width = r.hi - r.lo;
                    let point_failure = |x: f64| {
                        events.iter().filter(|e| !e.5).any(|e| {
                            let (lo, hi) = (e.1[0], e.2[0]);
                            let mut d = (0.5 * (lo + hi) - x).abs();
                            if r.periodic {
                                d = d.rem_euclid(width);
                                d = d.min(width - d);
                            }
                            hi - lo <= 1e-9 * width && d <= 1e-9 * width
                        })
                    };
                    let mut s = show_interval(a, b, input.angle);
                    if point_failure(a) {
                        s.replace_range(..1, "(");
                    }
                    if point_failure(b) {
                        if let Some(k) = s.find(']') {
                            s.replace_range(k..k + 1, ")");
                        }
                    }
                    let verb = if input.declared {
                        "narrow the declared range to it"
                    } else {
                        "declare a range inside it"
                    };
                    if let (true, Some(at)) = (input.declared, input.spans) {
                        let tiny = 1e-9 * width;
                        let at_lo = list.iter().all(|e| e.1[0] <= r.lo + tiny);
                        let at_hi = list.iter().all(|e| e.2[0] >= r.hi - tiny);
                        span = match (at_lo && !r.periodic, at_hi && !r.periodic) {
                            (true, false) => at.lo,
                            (false, true) => at.hi,
                            _ => at.input,
                        };
                    }
                    match suggest(input, a, b) {
                        Some(range) => {
                            format!("it assembles for {name} in {s}: {verb}, e.g. {range}")
                        }
                        None => {
                            format!("it assembles only for {name} in {s}; change the dimensions")
                        }
                    }
                }
                None => "it assembles nowhere in the range: check the dimensions".into(),
            };
            // Guides parallel at every pose checked (a PRP whose guides turn
            // together, or keep their directions): said directly, not as a
            // failure at one input.
            let parallel_everywhere = best.is_none()
                && matches!(stmt.kind, Kind::Prp { .. })
                && matches!(ev.solve(&[mid]), Err((_, Fault::Singular { .. })));
            if let (true, Kind::Prp { g1, g2, .. }) = (parallel_everywhere, &stmt.kind) {
                findings.errors.push(syn::Error::new(
                    span,
                    format!(
                        "group `{}` (PRP) cannot assemble: guides `{g1}` and `{g2}` are parallel at every pose checked ({name} in {}), so the joint is at infinity for every input\n  = help: make the guides cross: change the angle of one of them",
                        stmt.name,
                        show_interval(r.lo, r.hi, input.angle)
                    ),
                ));
                continue;
            }
            let grashof = if !input.declared {
                grashof(model, plan, stmt_index)
                    .map(|g| format!("{g}; "))
                    .unwrap_or_default()
            } else {
                String::new()
            };
            let over = if input.declared {
                format!(
                    "the declared range {}",
                    show_interval(r.lo, r.hi, input.angle)
                )
            } else {
                format!(
                    "a full turn {}, the default for a crank",
                    show_interval(r.lo, r.hi, true)
                )
            };
            format!(
                "cannot assemble group `{}` ({kind}) for {name} {} (checked over {over})\n  = note: {why}\n  = help: {grashof}{where_ok}",
                stmt.name,
                intervals.join(" and "),
            )
        } else {
            let e = list[0];
            let unit = |i: usize| if inputs[i].angle { " deg" } else { "" };
            let v = |i: usize, x: f64| show_num(if inputs[i].angle { x.to_degrees() } else { x });
            let total = (sweep::SAMPLES_2D + 1) * (sweep::SAMPLES_2D + 1);
            format!(
                "cannot assemble group `{}` ({kind}) at {} of the {total} grid points of the declared box {} x {}: they span {} in [{}, {}]{}, {} in [{}, {}]{}\n  = note: {}\n  = help: narrow the declared ranges or change the dimensions",
                stmt.name,
                e.4,
                show_interval(ranges[0].lo, ranges[0].hi, inputs[0].angle),
                show_interval(ranges[1].lo, ranges[1].hi, inputs[1].angle),
                inputs[0].name, v(0, e.1[0]), v(0, e.2[0]), unit(0),
                inputs[1].name, v(1, e.1[1]), v(1, e.2[1]), unit(1),
                explain(model, stmt_index, &e.3, "the first failing grid point"),
            )
        };
        findings.errors.push(syn::Error::new(span, message));
    }
    if !findings.errors.is_empty() {
        return findings;
    }
    // Warnings, one per singular group.
    let mut sing: BTreeMap<usize, Vec<(Vec<f64>, u32)>> = BTreeMap::new();
    for e in events.iter().filter(|e| e.5) {
        sing.entry(e.0).or_default().push((e.1.clone(), e.4));
    }
    for (g, list) in &sing {
        let stmt_index = checked.groups[*g];
        let stmt = &model.stmts[stmt_index];
        findings
            .singular
            .push((*g, list.iter().map(|(at, _)| at[0]).collect()));
        if is_allowed(allowed, &stmt.name.to_string()) {
            continue;
        }
        let kind = group_kind(&stmt.kind).unwrap_or("group");
        let mut at1: Vec<f64> = list
            .iter()
            .map(|(at, _)| {
                // To 1e-4 (deg): the determinant is exactly zero over a
                // rounding band about a fold, where the search may stop.
                let r = ranges[0];
                let unit = if inputs[0].angle { 180.0 / PI } else { 1.0 };
                let x = (at[0] * unit * 1e4).round() / 1e4;
                if r.periodic && x >= r.hi * unit {
                    x - (r.hi - r.lo) * unit
                } else {
                    x
                }
            })
            .collect();
        at1.sort_by(f64::total_cmp);
        let at: Vec<String> = if inputs.len() == 1 {
            at1.iter()
                .map(|x| {
                    format!(
                        "{} = {}{}",
                        inputs[0].name,
                        show_num(*x),
                        if inputs[0].angle { " deg" } else { "" }
                    )
                })
                .collect()
        } else {
            list.iter()
                .map(|(at, _)| {
                    format!(
                        "({}, {}) = ({}, {})",
                        inputs[0].name,
                        inputs[1].name,
                        show_value(at[0], inputs[0].angle),
                        show_value(at[1], inputs[1].angle)
                    )
                })
                .collect()
        };
        let count = if inputs.len() == 2 {
            format!(" ({} sign changes on the grid)", list[0].1)
        } else {
            String::new()
        };
        let note = format!(
            "group `{}` ({kind}) passes through a singular position at {}{count}: {}; `velocity()` and `acceleration()` return `Singular` there and lose accuracy near it. If the motion is meant to pass there, write `allow singular {};` in the definition",
            stmt.name,
            at.join(" and "),
            singular_meaning(model, stmt_index),
            stmt.name
        );
        let span = stmt.name.span();
        let use_it = quote_spanned!(span=> singular_position);
        findings.warnings.extend(quote! {
            const _: () = {
                #[deprecated(note = #note)]
                #[allow(non_upper_case_globals)]
                const singular_position: () = ();
                #use_it
            };
        });
    }
    let n_sing: usize = findings.singular.iter().map(|(_, v)| v.len()).sum();
    if n_sing > 0 {
        findings
            .summary
            .push_str(&format!(" Singular positions found: {n_sing}."));
    } else {
        findings.summary.push_str(" No singular position found.");
    }
    findings
}

/// The scaled determinant of a checked group, from the generated position
/// struct `pos` (code).
pub(crate) fn det_code(model: &Model, stmt_index: usize) -> TokenStream {
    let stmt = &model.stmts[stmt_index];
    let g = format_ident!("grp_{}", stmt.name);
    match &stmt.kind {
        Kind::Rrr { .. } | Kind::Actuator { .. } => quote!(::mechanism::sweep::det_rrr(&pos.#g)),
        Kind::Rrp { guide, .. } => quote!(::mechanism::sweep::det_rrp(&pos.#g, &pos.#guide)),
        Kind::Rpr { a, b, .. } => quote!(::mechanism::sweep::det_rpr(&pos.#g, &pos.#a, &pos.#b)),
        Kind::Prp { g1, g2, .. } => quote!(::mechanism::sweep::det_prp(&pos.#g1, &pos.#g2)),
        Kind::Rpp { guide, .. } => quote!(::mechanism::sweep::det_rpp(&pos.#g, &pos.#guide)),
        _ => quote!(1.0),
    }
}

/// The generated `check()` method (empty when an input has no range).
pub fn emit_check(model: &Model, plan: &Plan, inputs: &[Input], summary: &str) -> TokenStream {
    let checked = checked(model, plan);
    if inputs.is_empty()
        || inputs.len() > 2
        || inputs.iter().any(|i| i.range.is_none())
        || (inputs.len() == 2 && inputs.iter().any(|i| !i.declared))
    {
        return TokenStream::new();
    }
    let name = &model.name;
    let input_ty = format_ident!("{}Input", name);
    let g = checked.groups.len();
    let d = inputs.len();
    let group_names: Vec<String> = checked
        .groups
        .iter()
        .map(|&i| model.stmts[i].name.to_string())
        .collect();
    let indices: Vec<usize> = (0..g).collect();
    let dets: Vec<TokenStream> = checked.groups.iter().map(|&i| det_code(model, i)).collect();
    let input_names: Vec<&Ident> = inputs.iter().map(|i| &i.name).collect();
    let input_strs: Vec<String> = input_names.iter().map(|i| i.to_string()).collect();
    let ks: Vec<usize> = (0..d).collect();
    let ranges: Vec<TokenStream> = inputs
        .iter()
        .map(|i| {
            let r = i.range.expect("checked above");
            let (lo, hi, p) = (r.lo, r.hi, r.periodic);
            quote!(::mechanism::sweep::Range { lo: #lo, hi: #hi, periodic: #p })
        })
        .collect();
    // A PRP's or an RPP's joint at infinity is a failure, as at expansion
    // time; the call only where the mechanism has one.
    let at_infinity = joints_at_infinity(model, &checked);
    let mark_infinity = if at_infinity.contains(&true) {
        quote!(.with_joints_at_infinity([#(#at_infinity),*]))
    } else {
        TokenStream::new()
    };
    let sweep_call = if d == 1 {
        quote!(::mechanism::sweep::sweep_1d(&ranges[0], ::mechanism::sweep::SAMPLES_1D, &tol, eval, |e| report.record(&e));)
    } else {
        quote!(let _ = tol; ::mechanism::sweep::sweep_2d(&ranges, ::mechanism::sweep::SAMPLES_2D, eval, |e| report.record(&e));)
    };
    let doc = format!(
        "Sweeps the input range with these parameters, through [`{name}::position`]: per group (in solve order: {}), where it cannot be assembled and where its rate system is singular. The sweep is the one the macro runs at expansion time (`mechanism::sweep`), in the scalar `T` (edges bisected to `max(1e-10, eps)` of the range, singular below `sqrt(eps)`; an edge lies where `position()` in `T` stops assembling, which can be the group's rounding band beyond the exact limit: in `f32` a few 1e-6 rad at an RRR's limit); about {} position solves. No heap.\n\n{summary}",
        group_names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", "),
        if d == 1 { "4000" } else { "15000" }
    );
    quote! {
        #[doc = #doc]
        #[allow(clippy::all)]
        pub fn check(&self) -> ::mechanism::sweep::Report<#g, #d> {
            let ranges = [#(#ranges),*];
            let mut report = ::mechanism::sweep::Report::new([#(#input_strs),*], ranges, [#(#group_names),*])#mark_infinity;
            let tol = ::mechanism::sweep::Tolerances::for_eps(<T as ::mechanism::Real>::as_f64(<T as ::mechanism::Real>::eps()));
            let eval = |q: &[::core::primitive::f64; #d]| -> ::mechanism::sweep::Outcome<#g> {
                let input = #input_ty { #(#input_names: <T as ::mechanism::Real>::lit(q[#ks]),)* };
                match self.position(&input) {
                    ::core::result::Result::Ok(pos) => ::core::result::Result::Ok([#(#dets),*]),
                    ::core::result::Result::Err(e) => ::core::result::Result::Err((
                        match e.group { #(#group_names => #indices,)* _ => 0 },
                        e.fault.to_f64(),
                    )),
                }
            };
            #sweep_call
            report
        }
    }
}
