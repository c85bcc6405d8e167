//! The driver inputs as the checks see them: each input's range (declared by
//! `range INPUT = (lo, hi);`, or the default: a crank turns fully; sliders and
//! actuators have none) and the groups whose singular positions are allowed
//! (`allow singular ...;`), lowered from the definition with errors on the
//! user's tokens.

use super::{Kind, Model};
use crate::diag::{did_you_mean, show_value, Diagnostics};
use crate::parse::{Arg, RangeDecl};
use crate::value::{convert, Scope};
use mechanism_core::sweep::{self, Range};
use proc_macro2::Span;
use std::f64::consts::PI;
use syn::Ident;

/// What the definition declares for the checks, as written (lowered by
/// [`inputs`] and [`allowances`]).
#[derive(Default)]
pub(super) struct Declared {
    /// `range INPUT = (lo, hi);` statements.
    pub ranges: Vec<RangeDecl>,
    /// `allow singular [groups];` statements: the keyword's span, the word
    /// after it, the groups (empty: every group).
    pub allow: Vec<(Span, Ident, Vec<Ident>)>,
}

/// The groups whose singular positions (toggle, dead centre) the definition
/// allows: the expansion-time check does not report them.
#[derive(Clone, Debug, PartialEq)]
pub enum Allowed {
    /// No `allow singular`.
    Nothing,
    /// `allow singular;`: every group.
    Every,
    /// `allow singular B, C;`: the groups by the names of the points they define.
    Groups(Vec<String>),
}

impl Allowed {
    /// `true` when `group`'s singular positions are allowed.
    pub fn allows(&self, group: &str) -> bool {
        match self {
            Allowed::Nothing => false,
            Allowed::Every => true,
            Allowed::Groups(list) => list.iter().any(|g| g == group),
        }
    }
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
fn bound(
    model: &Model,
    arg: &Arg,
    input: &Ident,
    angle: bool,
    errors: &mut Diagnostics,
) -> Option<f64> {
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
            errors.error(e);
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
pub(super) fn inputs(model: &Model, ranges: &[RangeDecl], errors: &mut Diagnostics) -> Vec<Input> {
    let mut inputs: Vec<Input> = model
        .stmts
        .iter()
        .flat_map(|s| {
            let angle = matches!(s.kind, Kind::Crank { .. });
            s.kind.inputs().into_iter().map(move |name| Input {
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
    for decl in ranges {
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
pub(super) fn allowances(
    model: &Model,
    allow: &[(Span, Ident, Vec<Ident>)],
    errors: &mut Diagnostics,
) -> Allowed {
    let mut allowed: Option<Vec<String>> = None;
    let groups: Vec<String> = model
        .stmts
        .iter()
        .filter(|s| super::group_kind(&s.kind).is_some())
        .map(|s| s.name.to_string())
        .collect();
    for (_, what, names) in allow {
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
    match allowed {
        None => Allowed::Nothing,
        Some(l) if l.iter().any(String::is_empty) => Allowed::Every,
        Some(l) => Allowed::Groups(l),
    }
}
