//! Stage 2, model: the parse tree lowered into typed statements. Arguments are
//! checked for arity, role (point, guide, link, number, mode) and literal
//! positivity here; names are resolved across statements in `validate`.

mod inputs;

pub use inputs::{Allowed, Input, RangeSpans};

use crate::diag::{did_you_mean, Diagnostics};
use crate::parse::vocabulary::{
    arity, input_position, links_created, unsupported_driver, usage, KINDS,
};
use crate::parse::{self, Arg, Definition, Item};
use crate::value::{Scope, Value, ValueKind};
use proc_macro2::Span;
use std::collections::BTreeMap;
use syn::spanned::Spanned;
use syn::{Attribute, Expr, Ident, LitInt, Visibility};

/// How far the generated code goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Level {
    /// `position` only.
    Position,
    /// `position` and `velocity`.
    Velocity,
    /// `position`, `velocity`, `acceleration` (the default without loads).
    Acceleration,
    /// Everything, and the force analysis (the default with loads).
    Forces,
}

/// Assembly mode as written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// `plus` / `left`: m = +1.
    Plus,
    /// `minus` / `right`: m = -1.
    Minus,
}

/// A whole mechanism.
pub struct Model {
    /// Doc comments of the definition.
    pub docs: Vec<Attribute>,
    /// Visibility of the generated items.
    pub vis: Visibility,
    /// Type name.
    pub name: Ident,
    /// Run-time parameters with their (folded) default values.
    pub params: Vec<(Ident, f64)>,
    /// Compile-time constants (folded).
    pub consts: BTreeMap<String, (Ident, f64)>,
    /// `let` statements, in the order written.
    pub stmts: Vec<Stmt>,
    /// Requested analysis level and the token that asked.
    pub level: Level,
    /// Span of the `analysis` statement's value.
    pub level_span: Option<Span>,
    /// Requested outputs (`None`: everything named).
    pub outputs: Option<Vec<Ident>>,
    /// Declared mobility.
    pub dof: Option<LitInt>,
    /// Statements whose arguments were rejected: their names stay defined.
    pub failed: Vec<Failed>,
    /// Masses, gravity and loads (the force analysis).
    pub kinetics: Kinetics,
    /// The driver inputs, in the order of the generated input struct, with
    /// the ranges the checks sweep.
    pub inputs: Vec<Input>,
    /// The groups whose singular positions are allowed (`allow singular`).
    pub allowed: Allowed,
    /// `#[self_test]`: the span of the attribute.
    pub self_test: Option<Span>,
    /// A statement's kind is unknown (reported): no other statement is
    /// blamed for what it would have defined (a missing driver, say).
    pub unknown_kinds: bool,
}

/// What the force analysis needs: masses, gravity and external loads.
#[derive(Default)]
pub struct Kinetics {
    /// `mass LINK { m, at, j }`.
    pub masses: Vec<MassSpec>,
    /// `gravity (gx, gy)`, with the span of the keyword.
    pub gravity: Option<(Span, Value, Value)>,
    /// `force at P ...`.
    pub forces: Vec<ForceSpec>,
    /// `torque on LINK = t`.
    pub torques: Vec<TorqueSpec>,
    /// `loads { name = default }`: values supplied per evaluation.
    pub loads: Vec<(Ident, f64)>,
    /// A load statement was written (even one that was rejected).
    pub declared: bool,
}

/// Mass properties of one link.
pub struct MassSpec {
    /// The link.
    pub link: Ident,
    /// Mass (M).
    pub mass: Value,
    /// Centre of mass: a point of the link.
    pub at: Ident,
    /// Moment of inertia about the centre of mass (M L^2); `None`: a point mass.
    pub inertia: Option<Value>,
}

/// An external force.
pub struct ForceSpec {
    /// Point of application.
    pub at: Ident,
    /// The link it acts on (`None`: the only link that has the point).
    pub on: Option<Ident>,
    /// The force.
    pub value: ForceSpecValue,
}

/// The value of an external force.
pub enum ForceSpecValue {
    /// Global components (force units).
    Components(Value, Value),
    /// Signed magnitude along a guide's unit direction.
    Along(Ident, Value),
}

/// An external couple on a link (force x length, counter-clockwise positive).
pub struct TorqueSpec {
    /// The link.
    pub on: Ident,
    /// The couple.
    pub value: Value,
}

impl Model {
    /// `true` when the definition asks for the force analysis.
    pub fn has_forces(&self) -> bool {
        self.level == Level::Forces
    }
}

/// A statement whose arguments were rejected (an error is already reported).
pub struct Failed {
    /// The name it defines.
    pub name: Ident,
    /// Its kind token.
    pub kind: Ident,
    /// Links it names.
    pub links: Vec<Ident>,
    /// Slides it names.
    pub slides: Vec<Ident>,
    /// Its input name, for a driver.
    pub input: Option<Ident>,
}

/// One `let` statement.
pub struct Stmt {
    /// The defined name.
    pub name: Ident,
    /// The kind token (`rrr`, ...).
    pub kind_token: Ident,
    /// What the statement is.
    pub kind: Kind,
    /// Names of the links it creates (user-given or generated).
    pub links: Vec<Ident>,
    /// Which of `links` the user named (only those become outputs).
    pub links_named: Vec<bool>,
    /// Names of slide displacements (user-given) by slot.
    pub slides: Vec<Option<Ident>>,
}

/// Origin of a guide.
pub enum Origin {
    /// A named point.
    Point(Ident),
    /// Literal or parametric coordinates.
    Coords(Value, Value),
}

/// A point's local coordinates on a link.
pub enum Local {
    /// Distance and angle from the link's axis.
    Polar(Value, Value),
    /// `(x, y)` along the axis and its left normal.
    Cartesian(Value, Value),
}

/// The statement kinds.
pub enum Kind {
    /// A fixed point.
    Ground { x: Value, y: Value },
    /// A guide line, fixed (`carrier == None`) or carried by a link.
    Guide {
        origin: Origin,
        angle: Value,
        carrier: Option<Ident>,
    },
    /// Crank driver. `cos_sin`: the definition wrote `INPUT as cos_sin`, so a
    /// `position_cos_sin` entry point takes this input as `(cos, sin)`.
    Crank {
        pivot: Ident,
        radius: Value,
        input: Ident,
        cos_sin: bool,
    },
    /// Slider driver.
    Slider {
        guide: Ident,
        input: Ident,
        offset: Value,
    },
    /// Linear actuator driver.
    Actuator {
        a: Ident,
        l: Value,
        b: Ident,
        input: Ident,
        mode: Mode,
    },
    /// RRR group.
    Rrr {
        a: Ident,
        l1: Value,
        b: Ident,
        l2: Value,
        mode: Mode,
    },
    /// RRP group.
    Rrp {
        a: Ident,
        l: Value,
        guide: Ident,
        mode: Mode,
        offset: Value,
    },
    /// RPR group.
    Rpr {
        a: Ident,
        b: Ident,
        mode: Mode,
        offset: Value,
    },
    /// PRP group.
    Prp {
        g1: Ident,
        g2: Ident,
        offset1: Value,
        offset2: Value,
    },
    /// RPP group.
    Rpp {
        a: Ident,
        guide: Ident,
        slot: Value,
        offset: Value,
    },
    /// A point fixed on a link.
    Point {
        link: Ident,
        from: Ident,
        local: Local,
    },
}

impl Kind {
    /// Number of links the statement creates.
    pub fn link_count(&self) -> usize {
        match self {
            Kind::Ground { .. } | Kind::Guide { .. } | Kind::Point { .. } => 0,
            Kind::Crank { .. } | Kind::Slider { .. } => 1,
            _ => 2,
        }
    }

    /// Number of slide displacements the statement creates.
    pub fn slide_count(&self) -> usize {
        match self {
            Kind::Rrp { .. } => 1,
            Kind::Prp { .. } | Kind::Rpp { .. } => 2,
            _ => 0,
        }
    }

    /// `true` for drivers.
    pub fn is_driver(&self) -> bool {
        matches!(
            self,
            Kind::Crank { .. } | Kind::Slider { .. } | Kind::Actuator { .. }
        )
    }

    /// The input variable of a driver.
    pub fn input(&self) -> Option<&Ident> {
        match self {
            Kind::Crank { input, .. }
            | Kind::Slider { input, .. }
            | Kind::Actuator { input, .. } => Some(input),
            _ => None,
        }
    }
}

struct NumberScope<'a> {
    consts: &'a BTreeMap<String, (Ident, f64)>,
    params: &'a [(Ident, f64)],
    names: &'a [(String, &'static str)],
    /// Per-evaluation load values, and whether this place may use them.
    loads: &'a [(Ident, f64)],
    allow_loads: bool,
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
                "cannot find parameter or constant `{s}`{}",
                did_you_mean(&s, all.iter().map(String::as_str))
            ),
        )
    }
}

/// Converts a user expression ([`crate::value::convert`]) and rejects a value
/// that is not a finite number: a literal too large for `f64`, a division by
/// an expression that folds to zero, or a folded result that overflows. Such a
/// value would put infinities or NaN into the expansion-time check and the
/// generated literals, so it is an error on the user's tokens.
fn convert(expr: &Expr, scope: &dyn Scope) -> Result<Value, syn::Error> {
    let v = crate::value::convert(expr, scope)?;
    check_finite(&v)?;
    Ok(v)
}

/// An error when `v` is, or contains, a value that is not a finite number.
fn check_finite(v: &Value) -> Result<(), syn::Error> {
    finite(v)?;
    match v.fold() {
        Some(x) if !x.is_finite() => Err(syn::Error::new_spanned(
            &v.tokens,
            format!("this evaluates to {x}, not a finite number; dimensions must be finite"),
        )),
        _ => Ok(()),
    }
}

/// The first non-finite literal or division by zero inside `v`.
fn finite(v: &Value) -> Result<(), syn::Error> {
    match &v.kind {
        ValueKind::Lit(x) if !x.is_finite() => Err(syn::Error::new_spanned(
            &v.tokens,
            format!("`{}` is not a finite number (too large for an f64, it rounds to {x}); dimensions must be finite", v.tokens),
        )),
        ValueKind::Neg(a) => finite(a),
        ValueKind::Bin(a, op, b) => {
            finite(a)?;
            finite(b)?;
            if *op == '/' && b.fold() == Some(0.0) {
                return Err(syn::Error::new_spanned(
                    &v.tokens,
                    format!("division by zero: `{}` is 0, so this is not a finite number; dimensions must be finite", b.tokens),
                ));
            }
            Ok(())
        }
        _ => Ok(()),
    }
}

/// Reads the arguments of one statement in order.
struct Args<'a> {
    args: std::slice::Iter<'a, Arg>,
    span: Span,
    kind: String,
    usage: &'static str,
    scope: &'a NumberScope<'a>,
    errors: &'a mut Diagnostics,
    failed: bool,
}

impl<'a> Args<'a> {
    fn next(&mut self, role: &str) -> Option<&'a Arg> {
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

    fn fail(&mut self, span: Span, message: String) {
        self.failed = true;
        self.errors.push(span, message);
    }

    /// A name (point, guide, link or new input name).
    fn name(&mut self, role: &str) -> Option<Ident> {
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
    fn crank_input(&mut self) -> Option<(Ident, bool)> {
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
    fn number(&mut self, role: &str, angle: bool) -> Option<Value> {
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
    fn length(&mut self, role: &str) -> Option<Value> {
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

    fn optional_number(&mut self, role: &str) -> Value {
        if self.args.len() == 0 {
            return Value::lit(0.0, self.span);
        }
        self.number(role, false)
            .unwrap_or_else(|| Value::lit(0.0, self.span))
    }

    fn mode(&mut self, group: &str) -> Option<Mode> {
        let name = self.name("assembly mode")?;
        let accepted: &[&str] = if group == "rrr" || group == "actuator" {
            &["left", "right", "plus", "minus"]
        } else {
            &["plus", "minus"]
        };
        match name.to_string().as_str() {
            s if !accepted.contains(&s) => {
                self.fail(
                    name.span(),
                    format!(
                        "unknown assembly mode `{s}` for `{group}`; write {}{}",
                        accepted
                            .iter()
                            .map(|m| format!("`{m}`"))
                            .collect::<Vec<_>>()
                            .join(" or "),
                        did_you_mean(s, accepted.iter().copied())
                    ),
                );
                None
            }
            "left" | "plus" => Some(Mode::Plus),
            _ => Some(Mode::Minus),
        }
    }

    fn from(&mut self) -> Option<Ident> {
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

    fn finish(&mut self) {
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

/// The error for a statement written with fewer arguments than its kind
/// takes, before any argument is read: read in order, the arguments would
/// fill the wrong roles (`rrr(A, 3.5, O4, left)` would read `left` as the
/// second length), and the message would be about a name instead of the
/// count.
fn too_few_arguments(stmt: &parse::Let, kind: &str) -> Option<String> {
    let (least, most) = arity(kind, &stmt.args)?;
    let given = stmt.args.len();
    if given >= least {
        return None;
    }
    let takes = if kind == "point" {
        "it takes 4 (3 in the `(x, y)` form)".to_string()
    } else if least == most {
        format!("it takes {least}")
    } else {
        format!("it takes at least {least}")
    };
    Some(format!(
        "missing argument(s) for `{kind}`: {given} given, {takes}; usage: `{}`",
        usage(kind)
    ))
}

fn lower_kind(
    stmt: &parse::Let,
    scope: &NumberScope<'_>,
    errors: &mut Diagnostics,
) -> Option<Kind> {
    let kind = stmt.kind.to_string();
    if !KINDS.contains(&kind.as_str()) {
        let hint = match unsupported_driver(&kind) {
            Some(h) => format!("unsupported driver `{kind}`: {h}"),
            None => format!(
                "unknown statement kind `{kind}`; expected one of {}{}",
                KINDS.join(", "),
                did_you_mean(&kind, KINDS.iter().copied())
            ),
        };
        errors.push(stmt.kind.span(), hint);
        return None;
    }
    if let Some(message) = too_few_arguments(stmt, &kind) {
        errors.push(stmt.args_span, message);
        return None;
    }
    let mut a = Args {
        args: stmt.args.iter(),
        span: stmt.args_span,
        usage: usage(&kind),
        kind: kind.clone(),
        scope,
        errors,
        failed: false,
    };
    let k = match kind.as_str() {
        "ground" => Kind::Ground {
            x: a.number("x coordinate", false)?,
            y: a.number("y coordinate", false)?,
        },
        "guide" => {
            let origin = match a.next("origin")? {
                Arg::Value(Expr::Tuple(t), None) if t.elems.len() == 2 => {
                    let x = convert(&t.elems[0], scope)
                        .map_err(|e| a.errors.error(e))
                        .ok()?;
                    let y = convert(&t.elems[1], scope)
                        .map_err(|e| a.errors.error(e))
                        .ok()?;
                    Origin::Coords(x, y)
                }
                Arg::Value(Expr::Path(p), None) if p.path.get_ident().is_some() => {
                    Origin::Point(p.path.get_ident()?.clone())
                }
                other => {
                    let span = match other {
                        Arg::From(i) => i.span(),
                        Arg::Value(e, _) => e.span(),
                    };
                    a.fail(
                        span,
                        "expected the guide's origin: a point name or `(x, y)`".into(),
                    );
                    return None;
                }
            };
            // Second argument: a link (carried guide) or an angle (fixed guide).
            let carrier = match stmt.args.get(1) {
                Some(Arg::Value(Expr::Path(p), None))
                    if p.path.get_ident().is_some()
                        && scope.constant(p.path.get_ident()?).is_none()
                        && !scope.is_param(p.path.get_ident()?) =>
                {
                    a.name("carrying link")
                }
                _ => None,
            };
            let angle = if carrier.is_some() && a.args.len() == 0 {
                Value::lit(0.0, stmt.args_span)
            } else {
                a.number("direction angle", true)?
            };
            Kind::Guide {
                origin,
                angle,
                carrier,
            }
        }
        "crank" => {
            let pivot = a.name("pivot point")?;
            let radius = a.length("crank radius")?;
            let (input, cos_sin) = a.crank_input()?;
            Kind::Crank {
                pivot,
                radius,
                input,
                cos_sin,
            }
        }
        "slider" => Kind::Slider {
            guide: a.name("guide")?,
            input: a.name("input name")?,
            offset: a.optional_number("offset"),
        },
        "actuator" => Kind::Actuator {
            a: a.name("pivot-side point A")?,
            l: a.length("radius |C - A|")?,
            b: a.name("cylinder base point B")?,
            input: a.name("input name")?,
            mode: a.mode("actuator")?,
        },
        "rrr" => Kind::Rrr {
            a: a.name("first known joint")?,
            l1: a.length("first link length")?,
            b: a.name("second known joint")?,
            l2: a.length("second link length")?,
            mode: a.mode("rrr")?,
        },
        "rrp" => Kind::Rrp {
            a: a.name("known joint")?,
            l: a.length("link length")?,
            guide: a.name("guide")?,
            mode: a.mode("rrp")?,
            offset: a.optional_number("offset"),
        },
        "rpr" => Kind::Rpr {
            a: a.name("block pin")?,
            b: a.name("rocker pivot")?,
            mode: a.mode("rpr")?,
            offset: a.optional_number("offset"),
        },
        "prp" => {
            let g1 = a.name("first guide")?;
            let g2 = a.name("second guide")?;
            let offset1 = a.optional_number("first offset");
            let offset2 = a.optional_number("second offset");
            Kind::Prp {
                g1,
                g2,
                offset1,
                offset2,
            }
        }
        "rpp" => Kind::Rpp {
            a: a.name("block pin")?,
            guide: a.name("guide")?,
            slot: a.number("slot angle", true)?,
            offset: a.optional_number("offset"),
        },
        "point" => {
            let link = a.name("link")?;
            let from = a.from()?;
            let local = match stmt.args.get(2) {
                Some(Arg::Value(Expr::Tuple(t), None)) if t.elems.len() == 2 => {
                    a.args.next();
                    let x = convert(&t.elems[0], scope)
                        .map_err(|e| a.errors.error(e))
                        .ok()?;
                    let y = convert(&t.elems[1], scope)
                        .map_err(|e| a.errors.error(e))
                        .ok()?;
                    Local::Cartesian(x, y)
                }
                Some(Arg::Value(Expr::Tuple(t), _)) => {
                    a.fail(
                        t.span(),
                        format!(
                            "a point's local coordinates are `(x, y)`, two numbers, not {}; usage: `{}`",
                            t.elems.len(),
                            a.usage
                        ),
                    );
                    return None;
                }
                _ => Local::Polar(a.number("distance", false)?, a.number("angle", true)?),
            };
            Kind::Point { link, from, local }
        }
        _ => return None,
    };
    a.finish();
    if a.failed {
        None
    } else {
        Some(k)
    }
}

fn literal_scope_for<'a>(
    consts: &'a BTreeMap<String, (Ident, f64)>,
    names: &'a [(String, &'static str)],
) -> NumberScope<'a> {
    NumberScope {
        consts,
        params: &[],
        names,
        loads: &[],
        allow_loads: false,
    }
}

/// Reports the second `word` statement of a definition (`outputs`, `dof`,
/// `analysis`, `gravity`: each says one thing, so a second one would silently
/// replace the first). `written` shows the statement (named in the error on
/// a second one). Returns `true` for the first, which is the one kept (so
/// the second's content raises no further errors).
fn once(
    seen: &mut BTreeMap<&'static str, String>,
    word: &'static str,
    written: impl FnOnce() -> String,
    span: Span,
    errors: &mut Diagnostics,
) -> bool {
    if let Some(first) = seen.get(word) {
        let hint = match word {
            "outputs" => "list every output in the first and remove this one",
            "gravity" => "keep one `gravity (gx, gy);`",
            _ => "remove one of them",
        };
        errors.push(
            span,
            format!("`{word}` may appear once in a definition, and this is the second (the first is `{first}`); {hint}"),
        );
        return false;
    }
    seen.insert(word, written());
    true
}

/// Lowers a parsed definition. Returns the model (possibly partial) and errors.
pub fn lower(def: Definition, errors: &mut Diagnostics) -> Model {
    let unknown_kinds = def.items.iter().any(|item| match item {
        Item::Let(l) => !KINDS.contains(&l.kind.to_string().as_str()),
        _ => false,
    });
    let mut params: Vec<(Ident, f64)> = Vec::new();
    let mut consts: BTreeMap<String, (Ident, f64)> = BTreeMap::new();
    let mut level = Level::Acceleration;
    let mut level_span = None;
    let mut outputs = None;
    // `outputs { }`: allowed only where the force analysis returns something.
    let mut empty_outputs = None;
    let mut dof = None;
    let mut loads: Vec<(Ident, f64)> = Vec::new();
    let mut level_written = false;
    // Names of every let, link and slide, for "not a number" messages.
    let mut names: Vec<(String, &'static str)> = Vec::new();
    for item in &def.items {
        if let Item::Let(l) = item {
            let kind = l.kind.to_string();
            let what = match kind.as_str() {
                "guide" => "a guide",
                "rpr" => "a slide displacement",
                _ => "a point",
            };
            names.push((l.name.to_string(), what));
            names.extend(l.links.iter().map(|n| (n.to_string(), "a link")));
            names.extend(
                l.slides
                    .iter()
                    .map(|n| (n.to_string(), "a slide displacement")),
            );
            let input = input_position(&kind)
                .and_then(|i| l.args.get(i))
                .and_then(|a| match a {
                    Arg::Value(Expr::Path(p), None) => p.path.get_ident(),
                    Arg::Value(Expr::Cast(c), None) => match &*c.expr {
                        Expr::Path(p) => p.path.get_ident(),
                        _ => None,
                    },
                    _ => None,
                });
            if let Some(input) = input {
                names.push((input.to_string(), "a driver input"));
            }
        }
    }
    // Constants and parameter defaults first (they may appear anywhere). A
    // constant may use the constants written before it. A value that fails is
    // reported and still registered (as 0), so its uses raise no follow-on errors.
    for item in &def.items {
        match item {
            Item::Const(c) => {
                let earlier = NumberScope {
                    consts: &consts,
                    params: &[],
                    names: &names,
                    loads: &[],
                    allow_loads: false,
                };
                let x = match convert(&c.value, &earlier).map(|v| (v.fold(), v.span)) {
                    Ok((Some(x), _)) => x,
                    Ok((None, span)) => {
                        errors.push(span, "a `const` must be a number known at compile time: a literal, or arithmetic on literals and earlier constants");
                        0.0
                    }
                    Err(e) if e.to_string().starts_with("cannot find") => {
                        errors.error(syn::Error::new(
                            e.span(),
                            format!(
                                "{e} (a `const` may use literals and constants defined before it)"
                            ),
                        ));
                        0.0
                    }
                    Err(e) => {
                        errors.error(e);
                        0.0
                    }
                };
                consts.insert(c.name.to_string(), (c.name.clone(), x));
            }
            Item::Params(list) | Item::Loads(list) => {
                let is_loads = matches!(item, Item::Loads(_));
                for p in list {
                    let x = match convert(&p.value, &literal_scope_for(&consts, &names))
                        .map(|v| (v.fold(), v.span))
                    {
                        Ok((Some(x), _)) => x,
                        Ok((None, span)) => {
                            errors.push(span, "a parameter's default must be a literal number (or arithmetic on literals and constants)");
                            0.0
                        }
                        Err(e) if e.to_string().starts_with("cannot find") => {
                            errors.error(syn::Error::new(e.span(), format!("{e} (a parameter's default may use literals and constants only)")));
                            0.0
                        }
                        Err(e) => {
                            errors.error(e);
                            0.0
                        }
                    };
                    if is_loads {
                        loads.push((p.name.clone(), x));
                    } else {
                        params.push((p.name.clone(), x));
                    }
                }
            }
            _ => {}
        }
    }
    let scope = NumberScope {
        consts: &consts,
        params: &params,
        names: &names,
        loads: &loads,
        allow_loads: false,
    };
    let load_scope = NumberScope {
        allow_loads: true,
        ..scope
    };
    let mut kinetics = Kinetics {
        loads: loads.clone(),
        ..Kinetics::default()
    };
    let mut stmts = Vec::new();
    let mut failed = Vec::new();
    let self_test = def.self_test;
    let mut checks = inputs::Declared::default();
    // Statements that may appear once, by keyword.
    let mut seen = BTreeMap::new();
    for item in def.items {
        match item {
            Item::Analysis(span, what) => {
                let written = || format!("analysis {what};");
                if !once(&mut seen, "analysis", written, span, errors) {
                    continue;
                }
                level_span = Some(what.span());
                level_written = true;
                level = match what.to_string().as_str() {
                    "position" => Level::Position,
                    "velocity" => Level::Velocity,
                    "acceleration" => Level::Acceleration,
                    "forces" => Level::Forces,
                    other => {
                        let known = ["position", "velocity", "acceleration", "forces"];
                        errors.push(
                            what.span(),
                            format!(
                                "this definition cannot give the analysis `{other}`; write `position`, `velocity`, `acceleration` or `forces`{}",
                                did_you_mean(other, known)
                            ),
                        );
                        Level::Acceleration
                    }
                };
            }
            Item::Outputs(span, list) => {
                let written = || {
                    let names: Vec<String> = list.iter().take(4).map(ToString::to_string).collect();
                    let more = if list.len() > 4 { ", .." } else { "" };
                    format!("outputs {{ {}{more} }}", names.join(", "))
                };
                if !once(&mut seen, "outputs", written, span, errors) {
                    continue;
                }
                if list.is_empty() {
                    empty_outputs = Some(span);
                }
                outputs = Some(list);
            }
            Item::Dof(span, n) => {
                if !once(&mut seen, "dof", || format!("dof {n};"), span, errors) {
                    continue;
                }
                dof = Some(n);
            }
            Item::Let(l) => {
                let Some(kind) = lower_kind(&l, &scope, errors) else {
                    // Keep the names the statement meant to define, so that the
                    // rest of the definition and the user's code see no cascade.
                    let input = input_position(&l.kind.to_string())
                        .and_then(|i| l.args.get(i))
                        .and_then(|a| match a {
                            Arg::Value(Expr::Path(p), None) => p.path.get_ident().cloned(),
                            _ => None,
                        });
                    failed.push(Failed {
                        name: l.name,
                        kind: l.kind,
                        links: l.links,
                        slides: l.slides,
                        input,
                    });
                    continue;
                };
                let want_links = kind.link_count();
                if want_links == 0 && !l.links.is_empty() {
                    errors.push(
                        l.links[0].span(),
                        format!(
                            "`{}` creates no link, so there is nothing to name after `as`; remove `as {}`",
                            l.kind,
                            l.links.iter().map(Ident::to_string).collect::<Vec<_>>().join(", ")
                        ),
                    );
                } else if !l.links.is_empty() && l.links.len() != want_links {
                    // Too many: on the first extra name; too few: on the last
                    // name given, after which the missing ones go.
                    let at = if l.links.len() > want_links {
                        want_links
                    } else {
                        l.links.len() - 1
                    };
                    errors.push(l.links[at].span(), link_count_message(&l, want_links));
                }
                let mut links = Vec::new();
                let mut links_named = Vec::new();
                for i in 0..want_links {
                    match l.links.get(i) {
                        Some(n) => {
                            links.push(n.clone());
                            links_named.push(true);
                        }
                        None => {
                            links.push(syn::Ident::new(
                                &format!("{}_link{}", l.name, i + 1),
                                l.name.span(),
                            ));
                            links_named.push(false);
                        }
                    }
                }
                let want_slides = kind.slide_count();
                if l.slides.len() > want_slides {
                    errors.push(
                        l.slides[0].span(),
                        format!(
                            "`{}` has {want_slides} slide displacement(s) to name, not {}",
                            l.kind,
                            l.slides.len()
                        ),
                    );
                }
                let slides = (0..want_slides).map(|i| l.slides.get(i).cloned()).collect();
                stmts.push(Stmt {
                    name: l.name,
                    kind_token: l.kind,
                    kind,
                    links,
                    links_named,
                    slides,
                });
            }
            Item::Mass(m) => {
                kinetics.declared = true;
                if let Some(spec) = lower_mass(&m, &scope, errors) {
                    kinetics.masses.push(spec);
                }
            }
            Item::Gravity(span, x, y) => {
                kinetics.declared = true;
                let written = || {
                    // Tokens print `- 9.81`: close up a leading minus.
                    let show = |e: &syn::Expr| {
                        let t = quote::ToTokens::to_token_stream(e).to_string();
                        match t.strip_prefix("- ") {
                            Some(rest) => format!("-{rest}"),
                            None => t,
                        }
                    };
                    format!("gravity ({}, {});", show(&x), show(&y))
                };
                if !once(&mut seen, "gravity", written, span, errors) {
                    continue;
                }
                match (convert(&x, &scope), convert(&y, &scope)) {
                    (Ok(x), Ok(y)) => kinetics.gravity = Some((span, x, y)),
                    (Err(e), _) | (_, Err(e)) => errors.error(e),
                }
            }
            Item::Force(f) => {
                kinetics.declared = true;
                let value = match f.value {
                    parse::ForceValue::Components(x, y) => {
                        match (convert(&x, &load_scope), convert(&y, &load_scope)) {
                            (Ok(x), Ok(y)) => Some(ForceSpecValue::Components(x, y)),
                            (Err(e), _) | (_, Err(e)) => {
                                errors.error(e);
                                None
                            }
                        }
                    }
                    parse::ForceValue::Along(guide, v) => match convert(&v, &load_scope) {
                        Ok(v) => Some(ForceSpecValue::Along(guide, v)),
                        Err(e) => {
                            errors.error(e);
                            None
                        }
                    },
                };
                if let Some(value) = value {
                    kinetics.forces.push(ForceSpec {
                        at: f.at,
                        on: f.on,
                        value,
                    });
                }
            }
            Item::Torque(on, value) => {
                kinetics.declared = true;
                match convert(&value, &load_scope) {
                    Ok(value) => kinetics.torques.push(TorqueSpec { on, value }),
                    Err(e) => errors.error(e),
                }
            }
            Item::Range(r) => {
                // The checks read the bounds; a bound that is no finite number
                // is reported here, the rest (units, names) there.
                let infinite = [&r.lo, &r.hi].into_iter().find_map(|bound| match bound {
                    Arg::Value(e, _) => crate::value::convert(e, &scope)
                        .ok()
                        .and_then(|v| check_finite(&v).err()),
                    Arg::From(_) => None,
                });
                match infinite {
                    Some(e) => errors.error(e),
                    None => checks.ranges.push(r),
                }
            }
            Item::Allow(span, what, groups) => checks.allow.push((span, what, groups)),
            Item::Loads(_) => {}
            Item::Params(_) | Item::Const(_) => {}
        }
    }
    if kinetics.declared && !level_written {
        level = Level::Forces;
    }
    if let (Some(span), false) = (empty_outputs, kinetics.declared) {
        errors.push(span, "`outputs { }` lists nothing, and without masses or loads there is no force analysis to return, so every analysis would return nothing; name the points, links and slides to return, or remove the line (the default is every named thing)");
    }
    let mut model = Model {
        docs: def.docs,
        vis: def.vis,
        name: def.name,
        params,
        consts,
        stmts,
        level,
        level_span,
        outputs,
        dof,
        failed,
        kinetics,
        inputs: Vec::new(),
        allowed: Allowed::Nothing,
        self_test,
        unknown_kinds,
    };
    model.inputs = inputs::inputs(&model, &checks.ranges, errors);
    model.allowed = inputs::allowances(&model, &checks.allow, errors);
    model
}

/// A name for the link after `name` in a suggested `as (..)`: `link4` after
/// `link3`, `rod2` after `rod`.
fn next_name(name: &str) -> String {
    let stem = name.trim_end_matches(|c: char| c.is_ascii_digit());
    match name[stem.len()..].parse::<u64>() {
        Ok(n) if n < u64::MAX => format!("{stem}{}", n + 1),
        _ => format!("{name}2"),
    }
}

/// The error for an `as` that names more or fewer links than the statement
/// creates (`want`, one or two): says which links it creates and shows the
/// `as` that names them all, from the names given.
fn link_count_message(l: &parse::Let, want: usize) -> String {
    let given: Vec<String> = l.links.iter().map(Ident::to_string).collect();
    let mut names: Vec<String> = given.iter().take(want).cloned().collect();
    while names.len() < want {
        let next = next_name(names.last().map_or("link", String::as_str));
        names.push(next);
    }
    let kind = &l.kind;
    let what = links_created(&kind.to_string());
    if want == 1 {
        let extra = given[1..]
            .iter()
            .map(|n| format!("`{n}`"))
            .collect::<Vec<_>>()
            .join(", ");
        format!(
            "`{kind}` creates one link ({what}): name it alone, `as {}`, and remove {extra}",
            names[0]
        )
    } else if given.len() > want {
        format!(
            "`{kind}` creates two links ({what}), and {} names are given: name the two, `as ({})`",
            given.len(),
            names.join(", ")
        )
    } else {
        format!(
            "`{kind}` creates two links ({what}): name both, `as ({})`",
            names.join(", ")
        )
    }
}

/// Lowers `mass LINK { m = .., at = POINT, j = .. }`: `m` and `at` required,
/// `j` optional; literal values must be positive (`j` may be zero).
fn lower_mass(
    m: &parse::Mass,
    scope: &NumberScope<'_>,
    errors: &mut Diagnostics,
) -> Option<MassSpec> {
    const FIELDS: [&str; 3] = ["m", "at", "j"];
    let usage = "`mass LINK { m = mass, at = CENTRE_POINT, j = inertia_about_centre }`";
    let mut mass = None;
    let mut at = None;
    let mut inertia = None;
    let mut ok = true;
    let mut given: Vec<String> = Vec::new();
    for (name, arg) in &m.fields {
        let field = name.to_string();
        if FIELDS.contains(&field.as_str()) && given.contains(&field) {
            ok = false;
            errors.push(
                name.span(),
                format!("`{field}` is given twice in this `mass`; keep one"),
            );
            continue;
        }
        given.push(field.clone());
        match (field.as_str(), arg) {
            ("at", Arg::Value(Expr::Path(p), None)) if p.path.get_ident().is_some() => {
                at = p.path.get_ident().cloned();
            }
            ("at", _) => {
                ok = false;
                errors.push(name.span(), format!("`at` names the centre of mass, a point of the link (write `let G = point(LINK, from A, d, angle);` and `at = G`); usage: {usage}"));
            }
            ("m" | "j", Arg::Value(expr, None)) => match convert(expr, scope) {
                Ok(v) => {
                    let literal = v.fold();
                    let bad = match literal {
                        Some(x) if field == "m" => !(x > 0.0 && x.is_finite()),
                        Some(x) => !(x >= 0.0 && x.is_finite()),
                        None => false,
                    };
                    if bad {
                        ok = false;
                        errors.error(syn::Error::new_spanned(
                            &v.tokens,
                            if field == "m" {
                                format!("a mass must be positive, got {:?}; leave out the `mass` statement for a massless link", literal.unwrap_or_default())
                            } else {
                                format!("a moment of inertia must be zero or positive, got {:?}", literal.unwrap_or_default())
                            },
                        ));
                    } else if field == "m" {
                        mass = Some(v);
                    } else {
                        inertia = Some(v);
                    }
                }
                Err(e) => {
                    ok = false;
                    errors.error(e);
                }
            },
            ("m" | "j", _) => {
                ok = false;
                errors.push(
                    name.span(),
                    format!("`{field}` takes a number; usage: {usage}"),
                );
            }
            (other, _) => {
                ok = false;
                errors.push(
                    name.span(),
                    format!(
                        "unknown mass property `{other}`; write `m` (mass), `at` (centre of mass) or `j` (moment of inertia about it){}",
                        did_you_mean(other, FIELDS)
                    ),
                );
            }
        }
    }
    if ok && (mass.is_none() || at.is_none()) {
        let missing = if mass.is_none() { "`m`" } else { "`at`" };
        errors.push(
            m.link.span(),
            format!("`mass` is missing {missing}; usage: {usage}"),
        );
        return None;
    }
    Some(MassSpec {
        link: m.link.clone(),
        mass: mass?,
        at: at?,
        inertia: if ok { inertia } else { None },
    })
}

/// The kind name of a statement that can fail (drivers, groups, link points).
pub fn group_kind(kind: &Kind) -> Option<&'static str> {
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
