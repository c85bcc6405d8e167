//! The lowering of a whole definition, in phases: the names it defines (for
//! messages), its constants and parameter defaults (folded), then its
//! statements in the order written ([`Body`]), then the inputs with their
//! ranges and the allowances.

use super::args::{literal_scope_for, NumberScope, MODE_PARAM};
use super::kinds::lower_kind;
use super::{
    drawn, inputs, modes, Allowed, Failed, FailedKind, GearCrank, Kind, Kinetics, Level, Local,
    Mode, Model, MotorSpec, Stmt,
};
use crate::diag::{did_you_mean, Diagnostics};
use crate::keys::GROUND;
use crate::parse::vocabulary::KindWord;
use crate::parse::{self, Arg, Assign, Definition, Item, RangeDecl};
use crate::value::{convert, Value};
use proc_macro2::Span;
use std::collections::BTreeMap;
use syn::{Expr, Ident, LitInt};

/// Lowers a parsed definition. Returns the model (possibly partial) and errors.
pub fn lower(def: Definition, errors: &mut Diagnostics) -> Model {
    let unknown_kinds = def.items.iter().any(|item| match item {
        Item::Let(l) => l.word.is_none(),
        _ => false,
    });
    let names = defined_names(&def.items);
    let units = super::units::read(&def.items, errors);
    let Numbers {
        params,
        consts,
        loads,
        mut modes,
    } = numbers(&def.items, &names, errors);
    let scope = NumberScope {
        consts: &consts,
        params: &params,
        names: &names,
        loads: &loads,
        allow_loads: false,
        unknown_note: "",
    };
    let load_scope = NumberScope {
        allow_loads: true,
        ..scope
    };
    let (items, drawing_failed, drawn_modes) = drawn::expand(def.items, &scope, errors);
    modes.extend(drawn_modes);
    let mut body = Body::new(&scope, &load_scope, loads.clone());
    body.modes = modes.clone();
    body.failed = drawing_failed;
    for item in items {
        body.item(item, errors);
    }
    let Body {
        mut level,
        level_span,
        level_written,
        outputs,
        empty_outputs,
        dof,
        stmts,
        failed,
        kinetics,
        checks,
        ..
    } = body;
    if kinetics.declared && !level_written {
        level = Level::Forces;
    }
    if let (Some(span), false) = (empty_outputs, kinetics.declared) {
        errors.push(span, "`outputs { }` lists nothing, and without masses or loads there is no force analysis to return, so every analysis would return nothing; name the points, links and slides to return, or remove the line (the default is every named thing)");
    }
    let mut model = Model {
        docs: def.docs,
        derives: def.derives,
        vis: def.vis,
        name: def.name,
        params,
        modes,
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
        self_test: def.self_test,
        unknown_kinds,
        units,
    };
    model.inputs = inputs::inputs(&model, &checks.ranges, errors);
    model.allowed = inputs::allowances(&model, &checks.allow, errors);
    model
}

/// Names of every let, link, slide and driver input, with what each is ("a
/// point"), for "not a number" messages.
fn defined_names(items: &[Item]) -> Vec<(String, &'static str)> {
    let mut names: Vec<(String, &'static str)> = Vec::new();
    for item in items {
        if let Item::Params(list) = item {
            let modes = list.iter().filter(|p| modes::mode_word(&p.value).is_some());
            names.extend(modes.map(|p| (p.name.to_string(), MODE_PARAM)));
        }
        if let Item::Mode(name, _) = item {
            names.push((name.to_string(), MODE_PARAM));
        }
        if let Item::Let(l) = item {
            let what = match l.word {
                Some(KindWord::Guide) => "a guide",
                Some(KindWord::Rpr) => "a slide displacement",
                _ => "a point",
            };
            names.push((l.name.to_string(), what));
            names.extend(l.joints.iter().map(|n| (n.to_string(), "a point")));
            names.extend(l.links.iter().map(|n| (n.to_string(), "a link")));
            names.extend(
                l.slides
                    .iter()
                    .map(|n| (n.to_string(), "a slide displacement")),
            );
            let positions: &[usize] = l.word.map_or(&[], |k| k.spec().inputs);
            let inputs = positions
                .iter()
                .filter_map(|&i| l.args.get(i))
                .filter_map(|a| match a {
                    Arg::Value(Expr::Path(p), None) => p.path.get_ident(),
                    Arg::Value(Expr::Cast(c), None) => match &*c.expr {
                        Expr::Path(p) => p.path.get_ident(),
                        _ => None,
                    },
                    _ => None,
                });
            for input in inputs {
                names.push((input.to_string(), "a driver input"));
            }
        }
    }
    names
}

/// The folded numbers of a definition.
struct Numbers {
    /// Run-time parameters with their defaults.
    params: Vec<(Ident, f64)>,
    /// Compile-time constants.
    consts: BTreeMap<String, (Ident, f64)>,
    /// Load values with their defaults.
    loads: Vec<(Ident, f64)>,
    /// Run-time assembly modes with their defaults.
    modes: Vec<(Ident, Mode)>,
}

/// Constants and parameter (and load) defaults, first (they may appear
/// anywhere). A constant may use the constants written before it, a default
/// the constants written before it. A value that fails is reported and still
/// registered (as 0), so its uses raise no follow-on errors.
fn numbers(items: &[Item], names: &[(String, &'static str)], errors: &mut Diagnostics) -> Numbers {
    let mut params: Vec<(Ident, f64)> = Vec::new();
    let mut consts: BTreeMap<String, (Ident, f64)> = BTreeMap::new();
    let mut loads: Vec<(Ident, f64)> = Vec::new();
    let mut modes: Vec<(Ident, Mode)> = Vec::new();
    for item in items {
        match item {
            Item::Const(c) => {
                let x = constant(c, &consts, names, errors);
                consts.insert(c.name.to_string(), (c.name.clone(), x));
            }
            Item::Params(list) | Item::Loads(list) => {
                let is_loads = matches!(item, Item::Loads(_));
                for p in list {
                    if let (false, Some(mode)) = (is_loads, modes::mode_word(&p.value)) {
                        modes.push((p.name.clone(), mode));
                        continue;
                    }
                    let x = default_value(p, &consts, names, errors);
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
    Numbers {
        params,
        consts,
        loads,
        modes,
    }
}

/// The value of `const NAME = value;`, from the constants before it (`consts`);
/// 0 when it is rejected (reported).
fn constant(
    c: &Assign,
    consts: &BTreeMap<String, (Ident, f64)>,
    names: &[(String, &'static str)],
    errors: &mut Diagnostics,
) -> f64 {
    let earlier = literal_scope_for(
        consts,
        names,
        " (a `const` may use literals and constants defined before it)",
    );
    match convert(&c.value, &earlier).map(|v| (v.fold(), v.span)) {
        Ok((Some(x), _)) => x,
        Ok((None, span)) => {
            errors.push(span, "a `const` must be a number known at compile time: a literal, or arithmetic on literals and earlier constants");
            0.0
        }
        Err(e) => {
            errors.error(e);
            0.0
        }
    }
}

/// The default of a parameter or load value `p`, from the constants before
/// it; 0 when it is rejected (reported).
fn default_value(
    p: &Assign,
    consts: &BTreeMap<String, (Ident, f64)>,
    names: &[(String, &'static str)],
    errors: &mut Diagnostics,
) -> f64 {
    let scope = literal_scope_for(
        consts,
        names,
        " (a parameter's default may use literals and constants only)",
    );
    match convert(&p.value, &scope).map(|v| (v.fold(), v.span)) {
        Ok((Some(x), _)) => x,
        Ok((None, span)) => {
            errors.push(span, "a parameter's default must be a literal number (or arithmetic on literals and constants)");
            0.0
        }
        Err(e) => {
            errors.error(e);
            0.0
        }
    }
}

/// The statements of the body lowered in the order written: what each one
/// says, gathered for the [`Model`].
pub(super) struct Body<'a> {
    /// The scope of dimensions.
    pub(super) scope: &'a NumberScope<'a>,
    /// The scope of forces and torques (loads allowed).
    pub(super) load_scope: &'a NumberScope<'a>,
    /// Statements that may appear once, by keyword, as first written.
    pub(super) seen: BTreeMap<&'static str, String>,
    level: Level,
    level_span: Option<Span>,
    level_written: bool,
    outputs: Option<Vec<Ident>>,
    /// `outputs { }`: allowed only where the force analysis returns something.
    empty_outputs: Option<Span>,
    dof: Option<LitInt>,
    stmts: Vec<Stmt>,
    failed: Vec<Failed>,
    pub(super) kinetics: Kinetics,
    checks: inputs::Declared,
    /// The run-time assembly modes (`params { circuit = left }`).
    modes: Vec<(Ident, Mode)>,
}

impl<'a> Body<'a> {
    fn new(
        scope: &'a NumberScope<'a>,
        load_scope: &'a NumberScope<'a>,
        loads: Vec<(Ident, f64)>,
    ) -> Self {
        Body {
            scope,
            load_scope,
            seen: BTreeMap::new(),
            level: Level::Acceleration,
            level_span: None,
            level_written: false,
            outputs: None,
            empty_outputs: None,
            dof: None,
            stmts: Vec::new(),
            failed: Vec::new(),
            kinetics: Kinetics {
                loads,
                ..Kinetics::default()
            },
            checks: inputs::Declared::default(),
            modes: Vec::new(),
        }
    }

    /// Lowers one statement (constants, parameters and loads are lowered
    /// before, by [`numbers`]).
    fn item(&mut self, item: Item, errors: &mut Diagnostics) {
        match item {
            Item::Analysis(span, what) => self.analysis(span, what, errors),
            Item::Outputs(span, list) => self.outputs(span, list, errors),
            Item::Dof(span, n) => {
                if once(&mut self.seen, "dof", || format!("dof {n};"), span, errors) {
                    self.dof = Some(n);
                }
            }
            Item::Let(l) => self.let_statement(l, errors),
            Item::Mass(m) => self.mass(&m, errors),
            Item::Gravity(span, x, y) => self.gravity(span, x, y, errors),
            Item::Force(f) => self.force(f, errors),
            Item::Torque(on, value) => self.torque(on, value, errors),
            Item::Motor(name, link, carrier) => {
                self.kinetics.declared = true;
                self.kinetics.motors.push(MotorSpec {
                    name,
                    link,
                    carrier,
                });
            }
            Item::Range(r) => self.range(r),
            Item::Allow(span, what, groups) => self.checks.allow.push((span, what, groups)),
            Item::Loads(_) | Item::Units(..) => {}
            Item::Params(_) | Item::Const(_) => {}
            // Replaced by group statements before the body is lowered.
            Item::Joints(..)
            | Item::Links(..)
            | Item::Input(..)
            | Item::Slider(..)
            | Item::Cylinder(..)
            | Item::Gear(..)
            | Item::Mode(..) => {}
        }
    }

    /// `analysis LEVEL;`.
    fn analysis(&mut self, span: Span, what: Ident, errors: &mut Diagnostics) {
        let written = || format!("analysis {what};");
        if !once(&mut self.seen, "analysis", written, span, errors) {
            return;
        }
        self.level_span = Some(what.span());
        self.level_written = true;
        self.level = match what.to_string().as_str() {
            "position" => Level::Position,
            "velocity" => Level::Velocity,
            "acceleration" => Level::Acceleration,
            "forces" => Level::Forces,
            "dynamics" => Level::Dynamics,
            other => {
                let known = ["position", "velocity", "acceleration", "forces", "dynamics"];
                errors.push(
                    what.span(),
                    format!(
                        "this definition cannot give the analysis `{other}`; write `position`, `velocity`, `acceleration`, `forces` or `dynamics`{}",
                        did_you_mean(other, known)
                    ),
                );
                Level::Acceleration
            }
        };
    }

    /// `outputs { NAME, .. }`.
    fn outputs(&mut self, span: Span, list: Vec<Ident>, errors: &mut Diagnostics) {
        let written = || {
            let names: Vec<String> = list.iter().take(4).map(ToString::to_string).collect();
            let more = if list.len() > 4 { ", .." } else { "" };
            format!("outputs {{ {}{more} }}", names.join(", "))
        };
        if !once(&mut self.seen, "outputs", written, span, errors) {
            return;
        }
        if list.is_empty() {
            self.empty_outputs = Some(span);
        }
        self.outputs = Some(list);
    }

    /// `let NAME = KIND(args) as (links) slide (names);`: a statement, or,
    /// when its arguments are rejected, the names it meant to define.
    fn let_statement(&mut self, mut l: parse::Let, errors: &mut Diagnostics) {
        let mode_param = modes::take_mode_param(&mut l, &self.modes);
        let kind = lower_kind(&l, self.scope, errors);
        let kind = kind.and_then(|k| resolve_gear(k, &self.stmts, errors));
        let Some(kind) = kind else {
            // A triad's other joints stay defined as well.
            let joints = l.joints.iter().map(|j| Failed {
                name: j.clone(),
                kind: FailedKind::Let(l.word),
                links: Vec::new(),
                slides: Vec::new(),
                inputs: Vec::new(),
            });
            let joints: Vec<Failed> = joints.collect();
            self.failed.push(failed(l));
            self.failed.extend(joints);
            return;
        };
        // An actuator names two links (the arm; the cylinder, a massless
        // two-force member) or three (the arm, the barrel, the rod: a
        // cylinder with mass, `kinds::actuator`).
        let want_links = match kind {
            Kind::Actuator { .. } if l.links.len() == 3 => 3,
            _ => kind.link_count(),
        };
        let (links, links_named) = links(&l, want_links, errors);
        let want_slides = kind.slide_count();
        if l.slides.len() > want_slides {
            errors.push(
                l.slides[0].span(),
                format!(
                    "`{}` has {} to name, not {}",
                    l.kind,
                    crate::diag::counted(
                        want_slides as i64,
                        "slide displacement",
                        "slide displacements"
                    ),
                    l.slides.len()
                ),
            );
        }
        let slides = (0..want_slides).map(|i| l.slides.get(i).cloned()).collect();
        let joints = triad_joints(&l, &kind, &links);
        self.stmts.push(Stmt {
            name: l.name,
            kind_token: l.kind,
            kind,
            links,
            links_named,
            slides,
            mode_param,
        });
        self.stmts.extend(joints);
    }

    /// `range INPUT = (lo, hi);`: kept for [`inputs::inputs`], which reads
    /// the bounds and reports what is wrong with them (a non-finite number
    /// included, from [`crate::value::convert`]).
    fn range(&mut self, r: RangeDecl) {
        self.checks.ranges.push(r);
    }
}

/// A triad's joints `B` and `P` as points on its ternary link (its fourth
/// link) measured from `A`: `B` at `(ab, 0)`, `P` where the statement puts
/// it. Empty for every other kind.
fn triad_joints(l: &parse::Let, kind: &Kind, links: &[Ident]) -> Vec<Stmt> {
    let (Kind::Triad(t), Some(ternary)) = (kind, links.get(3)) else {
        return Vec::new();
    };
    let zero = Value::lit(0.0, t.ab.span);
    let p_local = match &t.p_local {
        Local::Polar(d, a) => Local::Polar(d.clone(), a.clone()),
        Local::Cartesian(x, y) => Local::Cartesian(x.clone(), y.clone()),
    };
    [
        (&t.b, Local::Cartesian(t.ab.clone(), zero)),
        (&t.p, p_local),
    ]
    .into_iter()
    .map(|(name, local)| Stmt {
        name: name.clone(),
        kind_token: l.kind.clone(),
        kind: Kind::Point {
            link: ternary.clone(),
            from: l.name.clone(),
            local,
        },
        links: Vec::new(),
        links_named: Vec::new(),
        slides: Vec::new(),
        mode_param: None,
    })
    .collect()
}

/// A gear's meshing link and carrier resolved to the cranks on the ground
/// that turn them (a gear reads their inputs: a link's angle over whole
/// turns); `None` with an error when one is not such a crank's link.
fn resolve_gear(kind: Kind, stmts: &[Stmt], errors: &mut Diagnostics) -> Option<Kind> {
    let Kind::Gear(mut g) = kind else {
        return Some(kind);
    };
    let crank_of = |link: &Ident, role: &str, errors: &mut Diagnostics| {
        let found = stmts.iter().find(|s| s.links.first() == Some(link));
        match found.map(|s| (&s.kind, s)) {
            Some((
                Kind::Crank {
                    input,
                    pivot,
                    carrier: None,
                    cos_sin: false,
                    ..
                },
                _,
            )) => Some(GearCrank {
                input: input.clone(),
                pivot: pivot.clone(),
            }),
            Some((
                Kind::Crank {
                    cos_sin: true,
                    input,
                    ..
                },
                _,
            )) => {
                errors.push(
                    link.span(),
                    format!("a gear reads the angle of `{link}` (its crank's input `{input}`), which is given as `(cos, sin)` here; drop `as cos_sin` from that crank"),
                );
                None
            }
            _ => {
                errors.push(
                    link.span(),
                    format!("a gear's {role} is a link turned by a crank on the ground (the gear reads its angle, that crank's input, over whole turns) or `ground`, and `{link}` is not one defined before this statement; write its `crank(O, r, theta) as {link}` first, or gear to `ground`"),
                );
                None
            }
        }
    };
    if let Some(m) = &g.mesh {
        g.mesh_crank = Some(crank_of(m, "meshing link", errors)?);
    }
    if let Some(c) = &g.carrier {
        g.carrier_crank = Some(crank_of(c, "carrier", errors)?);
    }
    if g.mesh == g.carrier {
        let span = g.mesh_span;
        let on = g
            .mesh
            .as_ref()
            .map_or(GROUND.to_string(), ToString::to_string);
        errors.push(
            span,
            format!("a gear meshing with `{on}` while turning on `{on}` never turns; mesh it with a crank's link, e.g. `gear({}, r, link2, 2.0)`, or carry it on one (its sixth argument)", g.pivot),
        );
        return None;
    }
    Some(Kind::Gear(g))
}

/// A `let` statement whose arguments were rejected: the names it meant to
/// define are kept, so that the rest of the definition and the user's code
/// see no cascade.
fn failed(l: parse::Let) -> Failed {
    let positions: &[usize] = l.word.map_or(&[], |k| k.spec().inputs);
    let inputs = positions
        .iter()
        .filter_map(|&i| l.args.get(i))
        .filter_map(|a| match a {
            Arg::Value(Expr::Path(p), None) => p.path.get_ident().cloned(),
            _ => None,
        })
        .collect();
    Failed {
        name: l.name,
        kind: FailedKind::Let(l.word),
        links: l.links,
        slides: l.slides,
        inputs,
    }
}

/// The `want_links` links of the statement `l`: the names after `as`, the
/// rest generated (`B_link1`), and which of them the user named. An `as`
/// naming more or fewer links than the statement creates is reported.
fn links(l: &parse::Let, want_links: usize, errors: &mut Diagnostics) -> (Vec<Ident>, Vec<bool>) {
    if want_links == 0 && !l.links.is_empty() {
        errors.push(
            l.links[0].span(),
            format!(
                "`{}` creates no link, so there is nothing to name after `as`; remove `as {}`",
                l.kind,
                l.links
                    .iter()
                    .map(Ident::to_string)
                    .collect::<Vec<_>>()
                    .join(", ")
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
        errors.push(l.links[at].span(), link_count_message(l, want_links));
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
    (links, links_named)
}

/// Reports the second `word` statement of a definition (`outputs`, `dof`,
/// `analysis`, `gravity`: each says one thing, so a second one would silently
/// replace the first). `written` shows the statement (named in the error on
/// a second one). Returns `true` for the first, which is the one kept (so
/// the second's content raises no further errors).
pub(super) fn once(
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
        // A triad's links by role (a number after the last given name may
        // be a link of the crank that drives it).
        let next = match (l.word == Some(KindWord::Triad), names.len()) {
            (true, 3) => "ternary".to_string(),
            (true, k) => format!("leg{}", k + 1),
            _ => next_name(names.last().map_or("link", String::as_str)),
        };
        names.push(next);
    }
    let kind = &l.kind;
    let what = l.word.map_or("", |k| k.spec().links);
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
    } else if want > 2 {
        format!(
            "`{kind}` creates {want} links ({what}), and {} names are given: name the {want}, `as ({})`",
            given.len(),
            names.join(", ")
        )
    } else if given.len() > want && l.word == Some(KindWord::Actuator) {
        format!(
            "`actuator` creates two links ({what}) or, for a cylinder with mass, three (the link, the barrel pivoted at B and the rod pinned at the joint), and {} names are given: `as ({})` or `as ({}, barrel, rod)`",
            given.len(),
            names.join(", "),
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
