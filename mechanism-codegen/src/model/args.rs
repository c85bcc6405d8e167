//! Reading a statement's arguments: the scope numbers are read in (constants,
//! parameters, loads, and the other names for "not a number" messages),
//! conversion to [`Value`]s that rejects non-finite numbers, and [`Args`],
//! which reads one statement's arguments in order by role.

use crate::diag::{did_you_mean, Diagnostics};
use crate::parse::Arg;
use crate::value::{convert, Scope, Value};
use proc_macro2::Span;
use std::collections::BTreeMap;
use syn::spanned::Spanned;
use syn::{Expr, Ident};

use super::Mode;

/// What [`NumberScope::names`] calls a run-time mode parameter.
pub(super) const MODE_PARAM: &str = "an assembly mode parameter";

/// The names a number may use where it is read, and the other names (for
/// the message on a name that is no number).
pub(super) struct NumberScope<'a> {
    /// The compile-time constants (folded).
    pub(super) consts: &'a BTreeMap<String, (Ident, f64)>,
    /// The run-time parameters with their defaults.
    pub(super) params: &'a [(Ident, f64)],
    /// Every point, guide, link, slide and input name, with what it is ("a
    /// point").
    pub(super) names: &'a [(String, &'static str)],
    /// Per-evaluation load values, and whether this place may use them.
    pub(super) loads: &'a [(Ident, f64)],
    pub(super) allow_loads: bool,
    /// Appended to the message on a name that is nothing known: what this
    /// place may use (`""`: nothing more to say).
    pub(super) unknown_note: &'static str,
}

impl Scope for NumberScope<'_> {
    fn constant(&self, name: &Ident) -> Option<f64> {
        self.consts.get(&name.to_string()).map(|c| c.1)
    }
    fn is_param(&self, name: &Ident) -> bool {
        self.params.iter().any(|(p, _)| p == name)
    }
    fn is_load(&self, name: &Ident) -> bool {
        self.allow_loads && self.loads.iter().any(|(l, _)| l == name)
    }
    fn not_a_number(&self, name: &Ident) -> syn::Error {
        let s = name.to_string();
        if self.loads.iter().any(|(l, _)| l == name) {
            return syn::Error::new(
                name.span(),
                format!("`{s}` is a load value (from `loads`): it may appear in `force` and `torque` statements only; dimensions are `params` or `const`"),
            );
        }
        if let Some((_, what)) = self.names.iter().find(|(n, _)| *n == s) {
            let why = match *what {
                "a driver input" => " (its value is given at run time, in the input struct)",
                "a slide displacement" => " (the mechanism finds it)",
                _ => "",
            };
            return syn::Error::new(
                name.span(),
                format!("`{s}` is {what}{why}, not a dimension; dimensions are numbers, `params` or `const` names"),
            );
        }
        // Where loads may stand, a misspelled load value is suggested too.
        let loads = self.loads.iter().filter(|_| self.allow_loads);
        let all = self
            .params
            .iter()
            .chain(loads)
            .map(|(p, _)| p.to_string())
            .chain(self.consts.keys().cloned())
            .collect::<Vec<_>>();
        syn::Error::new(
            name.span(),
            format!(
                "cannot find parameter or constant `{s}`{}{}",
                did_you_mean(&s, all.iter().map(String::as_str)),
                self.unknown_note
            ),
        )
    }
}

/// Reads the arguments of one statement in order.
pub(super) struct Args<'a> {
    /// The arguments not read yet.
    pub(super) args: std::slice::Iter<'a, Arg>,
    /// The span of the parenthesized argument list.
    pub(super) span: Span,
    /// The statement kind (`rrr`).
    pub(super) kind: crate::kinds::word::KindWord,
    /// The statement's usage, for messages.
    pub(super) usage: &'static str,
    /// The names its numbers may use.
    pub(super) scope: &'a NumberScope<'a>,
    /// Where its errors go.
    pub(super) errors: &'a mut Diagnostics,
    /// An argument was rejected (reported): the statement is not lowered.
    pub(super) failed: bool,
}

impl<'a> Args<'a> {
    /// The next argument, in the role `role`; reports a missing one.
    pub(super) fn next(&mut self, role: &str) -> Option<&'a Arg> {
        let arg = self.args.next();
        if arg.is_none() && !self.failed {
            self.failed = true;
            self.errors.push(
                self.span,
                format!(
                    "missing argument for `{}`: its {role}; usage: `{}`",
                    self.kind, self.usage
                ),
            );
        }
        arg
    }

    /// Reports `message` on `span` and marks the statement rejected.
    pub(super) fn fail(&mut self, span: Span, message: String) {
        self.failed = true;
        self.errors.push(span, message);
    }

    /// A name (point, guide, link or new input name).
    pub(super) fn name(&mut self, role: &str) -> Option<Ident> {
        match self.next(role)? {
            Arg::Value(Expr::Path(p), None) if p.path.get_ident().is_some() => {
                p.path.get_ident().cloned()
            }
            Arg::Value(Expr::Cast(c), None) if role == "input name" => {
                self.fail(
                    c.ty.span(),
                    "only a crank's angle can be given as `(cos, sin)`: `crank(O, r, INPUT as cos_sin)`; other inputs are plain names".into(),
                );
                None
            }
            Arg::Value(e, _) => {
                self.fail(e.span(), format!("expected the {role} (a name) here"));
                None
            }
            Arg::From(i) => {
                self.fail(i.span(), format!("expected the {role} here, not `from`"));
                None
            }
        }
    }

    /// A crank's input: `NAME` (an angle) or `NAME as cos_sin`.
    pub(super) fn crank_input(&mut self) -> Option<(Ident, bool)> {
        if let Some(Arg::Value(Expr::Cast(c), None)) = self.args.clone().next() {
            self.args.next();
            let name = match &*c.expr {
                Expr::Path(p) => p.path.get_ident().cloned(),
                _ => None,
            };
            let form = match &*c.ty {
                syn::Type::Path(t) => t.path.get_ident().map(Ident::to_string),
                _ => None,
            };
            return match (name, form.as_deref()) {
                (Some(name), Some("cos_sin")) => Some((name, true)),
                (None, _) => {
                    self.fail(c.expr.span(), "expected the input name here".into());
                    None
                }
                (_, other) => {
                    self.fail(
                        c.ty.span(),
                        format!(
                            "unknown input form `{}`; a crank's angle may be given as `INPUT as cos_sin` (its cosine and sine)",
                            other.unwrap_or("?")
                        ),
                    );
                    None
                }
            };
        }
        Some((self.name("input name")?, false))
    }

    /// A number (angle units allowed when `angle`).
    pub(super) fn number(&mut self, role: &str, angle: bool) -> Option<Value> {
        let arg = self.next(role)?;
        let Arg::Value(expr, unit) = arg else {
            if let Arg::From(i) = arg {
                self.fail(i.span(), format!("expected the {role} (a number) here"));
            }
            return None;
        };
        let value = match convert(expr, self.scope) {
            Ok(v) => v,
            Err(e) => {
                self.failed = true;
                self.errors.error(e);
                return None;
            }
        };
        match unit {
            None => Some(value),
            Some(u) if angle && u == "deg" => Some(value.degrees()),
            Some(u) if angle && u == "rad" => Some(value),
            Some(u) => {
                let hint = if angle {
                    format!("unknown angle unit `{u}`; write `deg` or `rad`")
                } else {
                    format!("unexpected `{u}`: the {role} is a length, it takes no unit")
                };
                self.fail(u.span(), hint);
                None
            }
        }
    }

    /// A number that must be positive when it is known at compile time.
    pub(super) fn length(&mut self, role: &str) -> Option<Value> {
        let v = self.number(role, false)?;
        if let Some(x) = v.fold() {
            if x <= 0.0 || !x.is_finite() {
                self.failed = true;
                self.errors.error(syn::Error::new_spanned(
                    &v.tokens,
                    format!(
                        "the {role} must be positive, got {x:?}; a link length is a distance > 0"
                    ),
                ));
            }
        }
        Some(v)
    }

    /// A number that may be left out (0 then).
    pub(super) fn optional_number(&mut self, role: &str) -> Value {
        if self.args.len() == 0 {
            return Value::lit(0.0, self.span);
        }
        self.number(role, false)
            .unwrap_or_else(|| Value::lit(0.0, self.span))
    }

    /// The assembly mode of the statement's group (the words its kind's
    /// descriptor accepts).
    pub(super) fn mode(&mut self) -> Option<Mode> {
        let name = self.name("assembly mode")?;
        let accepted: &[&str] = self.kind.spec().mode_words;
        match name.to_string().as_str() {
            s if !accepted.contains(&s) => {
                // Run-time mode parameters are candidates too (`params { circuit = left }`).
                let modes = self
                    .scope
                    .names
                    .iter()
                    .filter(|(_, what)| *what == MODE_PARAM);
                let candidates = accepted
                    .iter()
                    .copied()
                    .chain(modes.map(|(n, _)| n.as_str()));
                let hint = if self.scope.is_param(&name) {
                    format!("; `{s}` is a number parameter: a run-time mode is a parameter whose default is a mode word, `params {{ {s} = left }}`")
                } else {
                    did_you_mean(s, candidates)
                };
                self.fail(
                    name.span(),
                    format!(
                        "unknown assembly mode `{s}` for `{}`; write {}, or the name of a run-time mode parameter{hint}",
                        self.kind,
                        accepted
                            .iter()
                            .map(|m| format!("`{m}`"))
                            .collect::<Vec<_>>()
                            .join(" or "),
                    ),
                );
                None
            }
            "left" | "plus" => Some(Mode::Plus),
            _ => Some(Mode::Minus),
        }
    }

    /// `from POINT`.
    pub(super) fn from(&mut self) -> Option<Ident> {
        match self.next("`from POINT`")? {
            Arg::From(i) => Some(i.clone()),
            Arg::Value(e, _) => {
                self.fail(
                    e.span(),
                    "expected `from POINT`: the point on the link the offset is measured from"
                        .into(),
                );
                None
            }
        }
    }

    /// Reports an argument left over after the last role.
    pub(super) fn finish(&mut self) {
        if let Some(extra) = self.args.next() {
            let span = match extra {
                Arg::From(i) => i.span(),
                Arg::Value(e, _) => e.span(),
            };
            if !self.failed {
                self.fail(
                    span,
                    format!(
                        "too many arguments for `{}`; usage: `{}`",
                        self.kind, self.usage
                    ),
                );
            }
        }
    }
}

/// The scope of a value known at expansion time: the constants (and the
/// other names, for messages); `unknown_note` says, on a name that is
/// nothing known, what the place may use.
pub(super) fn literal_scope_for<'a>(
    consts: &'a BTreeMap<String, (Ident, f64)>,
    names: &'a [(String, &'static str)],
    unknown_note: &'static str,
) -> NumberScope<'a> {
    NumberScope {
        consts,
        params: &[],
        names,
        loads: &[],
        allow_loads: false,
        unknown_note,
    }
}
