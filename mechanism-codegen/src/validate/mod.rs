//! Stage 3, validate: rules across statements, one function per rule, each
//! pushing errors with the span of the user's offending token and a hint.
//! All rules run, so several errors are reported at once.

use crate::diag::{did_you_mean, Diagnostics};
use crate::model::{ForceSpecValue, Input, Kind, Level, Model, Origin};
use crate::plan::{references, Plan};
use proc_macro2::Span;
use std::collections::BTreeMap;
use syn::Ident;

/// The rules on the statements as written: names, references, drivers,
/// mobility, outputs, `#[self_test]`'s ranges.
pub fn model(model: &Model, errors: &mut Diagnostics) {
    unique_names(model, errors);
    reserved_names(model, errors);
    references_resolve(model, errors);
    has_driver(model, errors);
    dof_matches(model, errors);
    outputs_exist(model, errors);
    rpp_slot_crosses_guide(model, errors);
    self_test_sweepable(model, errors);
}

/// The rules that need the solve order and the owner of every point: the
/// geometry of carried guides and link points, and the force analysis'
/// masses and loads.
pub fn planned(model: &Model, plan: &Plan, errors: &mut Diagnostics) {
    geometry_consistent(model, plan, errors);
    kinetics_consistent(model, plan, errors);
}

/// What a name stands for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Category {
    /// A point.
    Point,
    /// A guide line.
    Guide,
    /// A link.
    Link,
    /// A slide displacement.
    Slide,
    /// A driver input.
    Input,
    /// A run-time parameter.
    Param,
    /// A compile-time constant.
    Const,
}

impl Category {
    fn article(self) -> &'static str {
        match self {
            Category::Point => "a point",
            Category::Guide => "a guide",
            Category::Link => "a link",
            Category::Slide => "a slide displacement",
            Category::Input => "a driver input",
            Category::Param => "a parameter",
            Category::Const => "a constant",
        }
    }
}

/// Prefixes of names the generated code uses for its own locals.
pub const RESERVED_PREFIXES: &[&str] = &[
    "vel_", "acc_", "grp_", "axis_", "omega_", "alpha_", "gvel_", "gacc_", "load_", "rx_", "pw_",
];
/// Names the generated methods use for their arguments.
pub const RESERVED: &[&str] = &[
    "input",
    "rates",
    "accels",
    "pos",
    "vel",
    "acc",
    "loads",
    "gravity",
    "condition",
    "T",
];

/// Every defined name with its category and defining token. A name defined
/// twice (an error of its own, from [`unique_names`]) keeps its first
/// meaning, so its uses raise no second error.
pub fn symbols(model: &Model) -> BTreeMap<String, (Category, Ident)> {
    let mut table = Table(BTreeMap::new());
    for (name, cat, ident) in every_symbol(model) {
        table.insert(name, (cat, ident));
    }
    table.0
}

/// Every definition of a name with its category, a name defined twice
/// appearing twice (parameters, constants, then the statements in order).
fn every_symbol(model: &Model) -> Vec<(String, Category, Ident)> {
    let mut table = All(Vec::new());
    for (name, _) in &model.params {
        table.insert(name.to_string(), (Category::Param, name.clone()));
    }
    for (name, (ident, _)) in &model.consts {
        table.insert(name.clone(), (Category::Const, ident.clone()));
    }
    for stmt in &model.stmts {
        let cat = match stmt.kind {
            Kind::Guide { .. } => Category::Guide,
            Kind::Rpr { .. } => Category::Slide,
            _ => Category::Point,
        };
        table.insert(stmt.name.to_string(), (cat, stmt.name.clone()));
        for link in &stmt.links {
            table.insert(link.to_string(), (Category::Link, link.clone()));
        }
        for slide in stmt.slides.iter().flatten() {
            table.insert(slide.to_string(), (Category::Slide, slide.clone()));
        }
        if let Some(input) = stmt.kind.input() {
            table.insert(input.to_string(), (Category::Input, input.clone()));
        }
    }
    for f in &model.failed {
        let cat = match f.kind.to_string().as_str() {
            "guide" => Category::Guide,
            "rpr" => Category::Slide,
            _ => Category::Point,
        };
        table.insert(f.name.to_string(), (cat, f.name.clone()));
        for link in &f.links {
            table.insert(link.to_string(), (Category::Link, link.clone()));
        }
        for slide in &f.slides {
            table.insert(slide.to_string(), (Category::Slide, slide.clone()));
        }
        if let Some(input) = &f.input {
            table.insert(input.to_string(), (Category::Input, input.clone()));
        }
    }
    table.0
}

/// Every definition, in order.
struct All(Vec<(String, Category, Ident)>);

impl All {
    fn insert(&mut self, name: String, (cat, ident): (Category, Ident)) {
        self.0.push((name, cat, ident));
    }
}

/// A symbol table where the first definition of a name stays.
struct Table(BTreeMap<String, (Category, Ident)>);

impl Table {
    fn insert(&mut self, name: String, entry: (Category, Ident)) {
        self.0.entry(name).or_insert(entry);
    }
}

/// Where a name is defined, for the message on a second definition.
enum Place {
    /// Outside the statements (a parameter or a constant, gathered from
    /// wherever they stand): the words.
    Outside(String),
    /// By statement `.0` (an index into the model's statements, which are in
    /// the order written), in the role `.1` ("as a link of"), written `.2`
    /// (`let B = rrr(..)`).
    Statement(usize, &'static str, String),
}

/// Every definition of a name with its place, in the order [`unique_names`]
/// checks them: parameters, constants, then each statement's point (or
/// guide, or slide), links, slides and input.
fn definitions(model: &Model) -> Vec<(Ident, Place)> {
    let mut out = Vec::new();
    for (name, _) in &model.params {
        out.push((
            name.clone(),
            Place::Outside("as a parameter (in `params { .. }`)".to_string()),
        ));
    }
    for (ident, _) in model.consts.values() {
        out.push((
            ident.clone(),
            Place::Outside(format!("as a constant (`const {ident} = ..;`)")),
        ));
    }
    for (i, stmt) in model.stmts.iter().enumerate() {
        let written = format!("`let {} = {}(..)`", stmt.name, stmt.kind_token);
        let mut push = |ident: &Ident, role| {
            out.push((ident.clone(), Place::Statement(i, role, written.clone())));
        };
        push(&stmt.name, "by");
        for (link, named) in stmt.links.iter().zip(&stmt.links_named) {
            if *named {
                push(link, "as a link of");
            }
        }
        for slide in stmt.slides.iter().flatten() {
            push(slide, "as a slide displacement of");
        }
        if let Some(input) = stmt.kind.input() {
            push(input, "as the input of");
        }
    }
    out
}

/// Rule: a name is defined once (points, links, slides, inputs, parameters and
/// constants share one namespace: they become fields side by side). The error
/// is on the later definition (parameters and constants count as first) and
/// says where the first one is (a `compile_error!` carries no second span).
pub fn unique_names(model: &Model, errors: &mut Diagnostics) {
    let mut seen: BTreeMap<String, Place> = BTreeMap::new();
    for (ident, place) in definitions(model) {
        let key = ident.to_string();
        let Some(first) = seen.get(&key) else {
            seen.insert(key, place);
            continue;
        };
        let whence = match (first, &place) {
            (Place::Statement(a, role, _), Place::Statement(b, _, _)) if a == b => {
                format!("{role} this statement")
            }
            (Place::Statement(_, role, written), Place::Statement(..)) => {
                format!("{role} the {written} statement above")
            }
            (Place::Statement(_, role, written), Place::Outside(_)) => {
                format!("{role} the {written} statement")
            }
            (Place::Outside(words), _) => words.clone(),
        };
        errors.push(
            ident.span(),
            format!(
                "`{key}` is already defined {whence}; every point, link, guide, slide, input, parameter and constant needs its own name: rename this one, e.g. `{}`",
                another(&key)
            ),
        );
    }
}

/// A name to suggest instead of `name`: `B2` for `B`, `link3b` for `link3`
/// (not `link32`, which reads as another number).
fn another(name: &str) -> String {
    if name.ends_with(|c: char| c.is_ascii_digit()) {
        format!("{name}b")
    } else {
        format!("{name}2")
    }
}

/// The links the user named (after `as`): the names to suggest. A statement
/// written without `as` gets internal link names, which are never suggested.
fn named_links(model: &Model) -> Vec<String> {
    model
        .stmts
        .iter()
        .flat_map(|s| s.links.iter().zip(&s.links_named))
        .filter(|(_, named)| **named)
        .map(|(l, _)| l.to_string())
        .chain(
            model
                .failed
                .iter()
                .flat_map(|f| f.links.iter().map(Ident::to_string)),
        )
        .collect()
}

/// `true` for a link name the user wrote (not an internal one).
fn is_named_link(model: &Model, name: &str) -> bool {
    named_links(model).iter().any(|l| l == name)
}

/// For a link name that does not exist: the statements whose links have no
/// names (written without `as`), and how to name them; "" when every link is
/// named.
fn unnamed_links_hint(model: &Model) -> String {
    let unnamed: Vec<(String, String)> = model
        .stmts
        .iter()
        .filter(|s| s.links_named.iter().any(|named| !named))
        .map(|s| {
            let kind = s.kind_token.to_string();
            let names = crate::parse::vocabulary::usage(&kind)
                .split_once(" as ")
                .map(|(_, after)| after.split(" slide").next().unwrap_or(after))
                .unwrap_or("LINK");
            let written = format!("`let {} = {kind}(..)`", s.name);
            let named = format!("`let {} = {kind}(..) as {names}`", s.name);
            (written, named)
        })
        .collect();
    let (written, named): (Vec<String>, Vec<String>) = unnamed.into_iter().unzip();
    match written.len() {
        0 => String::new(),
        1 => format!(
            "{} has no `as`, so its links have no names: name them, {}",
            written[0], named[0]
        ),
        _ => format!(
            "{} have no `as`, so their links have no names: name them, {}",
            written.join(" and "),
            named.join(", ")
        ),
    }
}

/// The hints for a link name that does not exist: the nearest named link
/// (`near`, a [`did_you_mean`] clause) and the statements whose links have
/// no names ([`unnamed_links_hint`]).
fn link_hints(model: &Model, near: String) -> String {
    match (near.is_empty(), unnamed_links_hint(model)) {
        (_, unnamed) if unnamed.is_empty() => near,
        (true, unnamed) => format!("; {unnamed}"),
        (false, unnamed) => format!("{near} Or, for a link without a name: {unnamed}"),
    }
}

/// Where `name` is defined, in words, for messages about a second
/// definition outside the statements (a load value); `None` when it is not.
fn defined_where(model: &Model, name: &Ident) -> Option<String> {
    definitions(model)
        .into_iter()
        .find(|(ident, _)| ident == name)
        .map(|(_, place)| match place {
            Place::Outside(words) => words,
            Place::Statement(_, role, written) => format!("{role} the {written} statement"),
        })
}

/// Rule: names the generated code needs for itself are not available.
pub fn reserved_names(model: &Model, errors: &mut Diagnostics) {
    for (name, (_, ident)) in symbols(model) {
        if let Some(bare) = name.strip_prefix("r#") {
            errors.push(
                ident.span(),
                format!("raw identifiers are not supported: the generated code builds its names from yours (`pos_{bare}`, `vel_{bare}`), and `r#` cannot stand inside a name; choose a name that is not a Rust keyword, e.g. `{bare}_`"),
            );
        } else if name == "T" {
            errors.push(
                ident.span(),
                "`T` is the generated types' scalar parameter (`f32` or `f64`); choose another name",
            );
        } else if RESERVED.contains(&name.as_str()) {
            errors.push(
                ident.span(),
                format!("`{name}` is reserved for the generated methods' arguments; choose another name"),
            );
        } else if let Some(p) = RESERVED_PREFIXES.iter().find(|p| name.starts_with(*p)) {
            errors.push(
                ident.span(),
                format!("names starting with `{p}` are reserved for the generated code's locals; rename `{name}`"),
            );
        }
    }
}

/// Rule: every reference names something defined, of the right category, and
/// not the statement itself (and, [`distinct_joints`], a group's two known
/// joints are two places).
pub fn references_resolve(model: &Model, errors: &mut Diagnostics) {
    distinct_joints(model, errors);
    let table = symbols(model);
    let every = every_symbol(model);
    for stmt in &model.stmts {
        let expected: Vec<(&Ident, Category)> = match &stmt.kind {
            Kind::Guide {
                origin, carrier, ..
            } => {
                let mut v = Vec::new();
                if let Origin::Point(p) = origin {
                    v.push((p, Category::Point));
                }
                if let Some(c) = carrier {
                    v.push((c, Category::Link));
                }
                v
            }
            Kind::Slider { guide, .. } => vec![(guide, Category::Guide)],
            Kind::Rrp { a, guide, .. } | Kind::Rpp { a, guide, .. } => {
                vec![(a, Category::Point), (guide, Category::Guide)]
            }
            Kind::Prp { g1, g2, .. } => vec![(g1, Category::Guide), (g2, Category::Guide)],
            Kind::Point { link, from, .. } => vec![(link, Category::Link), (from, Category::Point)],
            _ => references(stmt)
                .into_iter()
                .map(|r| (r, Category::Point))
                .collect(),
        };
        for (r, want) in expected {
            let name = r.to_string();
            let own_link = stmt.links.iter().any(|l| *l == name);
            // A link of this statement named like another statement's point
            // or link is a duplicate name (reported by `unique_names`), and
            // the reference means the other one: no second error.
            let defined_elsewhere = model.stmts.iter().any(|s| {
                !std::ptr::eq(s, stmt) && (s.name == name || s.links.iter().any(|l| *l == name))
            });
            if own_link && stmt.name != name && defined_elsewhere {
                continue;
            }
            if stmt.name == name || own_link {
                errors.push(
                    r.span(),
                    format!(
                        "`{}` refers to itself: `{name}` is what this statement defines; use a point or guide defined elsewhere",
                        stmt.name
                    ),
                );
                continue;
            }
            // A name defined twice, once as what is expected here: the
            // duplicate is reported (by `unique_names`), and this use means
            // the definition of the right kind: no second error.
            let also_wanted = every.iter().any(|(n, cat, _)| *n == name && *cat == want);
            match table.get(&name) {
                Some((cat, _)) if *cat == want || also_wanted => {}
                Some((cat, _)) => errors.push(
                    r.span(),
                    format!(
                        "`{name}` is {}, but {} is expected here",
                        cat.article(),
                        want.article()
                    ),
                ),
                None => {
                    let candidates: Vec<&str> = table
                        .iter()
                        .filter(|(n, (c, _))| {
                            *c == want && (want != Category::Link || is_named_link(model, n))
                        })
                        .map(|(n, _)| n.as_str())
                        .collect();
                    let near = did_you_mean(&name, candidates);
                    let (what, hint) = match want {
                        Category::Link => ("no link named", link_hints(model, near)),
                        Category::Guide => ("no guide named", near),
                        _ => ("cannot find point", near),
                    };
                    errors.push(r.span(), format!("{what} `{name}`{hint}"));
                }
            }
        }
    }
}

/// Rule: an RPP's slot crosses its guide. The slotted link translates along
/// the guide without turning relative to it (a carried guide turns the slot
/// with it), so the slot keeps its angle to the guide at every pose: a slot
/// parallel to the guide is parallel at every input, and the joint is at
/// infinity everywhere. Known at compile time for a slot angle that folds to
/// a number; "parallel" is the test the run-time solve applies
/// (`mechanism_core::dyad::rpp`: `|sin(slot)| <= 16 eps`, in f64 here).
pub fn rpp_slot_crosses_guide(model: &Model, errors: &mut Diagnostics) {
    for stmt in &model.stmts {
        let Kind::Rpp { guide, slot, .. } = &stmt.kind else {
            continue;
        };
        let Some(angle) = slot.fold() else {
            continue;
        };
        if angle.sin().abs() <= 16.0 * f64::EPSILON {
            // Rounded to 1e-9 deg, so that `180 deg` (rounded once to
            // radians and back) shows as 180.
            let deg = (angle.to_degrees() * 1e9).round() / 1e9;
            errors.push(
                slot.span,
                format!(
                    "the slot of `{}` is at {deg} deg to guide `{guide}`, parallel to it; the slotted link slides along `{guide}` without turning, so the slot stays parallel at every pose and the block's pin is at infinity for every input: give the slot an angle across the guide (e.g. `90 deg`, a slot perpendicular to it)",
                    stmt.name
                ),
            );
        }
    }
}

/// The literal coordinates of a ground point, when it is one.
fn literal_ground(model: &Model, name: &Ident) -> Option<(f64, f64)> {
    model.stmts.iter().find_map(|s| match &s.kind {
        Kind::Ground { x, y } if s.name == *name => Some((x.fold()?, y.fold()?)),
        _ => None,
    })
}

/// Rule: the two known joints of a group (or the two guides of a PRP) are two
/// different points (guides), and not two ground points at the same place.
pub fn distinct_joints(model: &Model, errors: &mut Diagnostics) {
    for stmt in &model.stmts {
        let (a, b, what) = match &stmt.kind {
            Kind::Rrr { a, b, .. } => (a, b, "known joints"),
            Kind::Rpr { a, b, .. } => (a, b, "points (the block's pin and the link's pivot)"),
            Kind::Actuator { a, b, .. } => {
                (a, b, "points (the link's pivot and the cylinder's base)")
            }
            Kind::Prp { g1, g2, .. } => (g1, g2, "guides"),
            _ => continue,
        };
        let kind = &stmt.kind_token;
        if a == b {
            errors.push(
                b.span(),
                format!("`{b}` is given twice: the two {what} of this `{kind}` must be different"),
            );
            continue;
        }
        if let (Some(pa), Some(pb)) = (literal_ground(model, a), literal_ground(model, b)) {
            if pa == pb {
                errors.push(
                    b.span(),
                    format!(
                        "`{a}` and `{b}` are both the ground point ({}, {}): the two {what} of this `{kind}` must be at different places; move one",
                        pa.0, pa.1
                    ),
                );
            }
        }
    }
}

/// Rule: at least one driver, unless a statement's kind was already rejected
/// (it may have been meant as the driver: no cascade).
pub fn has_driver(model: &Model, errors: &mut Diagnostics) {
    if model.unknown_kinds
        || !model.failed.is_empty()
        || model.stmts.iter().any(|s| s.kind.is_driver())
    {
        return;
    }
    errors.push(
        model.name.span(),
        format!(
            "`{}` has no driver, so nothing moves; add one, e.g. `let A = crank(O, radius, theta) as link2;`, a `slider(...)` or an `actuator(...)`",
            model.name
        ),
    );
}

/// Rule: a declared `dof N` matches Gruebler's count of the links and joints the
/// statements create (each driver adds one degree of freedom, each class II
/// group none), i.e. the number of inputs.
pub fn dof_matches(model: &Model, errors: &mut Diagnostics) {
    let Some(declared) = &model.dof else { return };
    if !model.failed.is_empty() {
        return; // a rejected statement would make the count meaningless
    }
    let Ok(n) = declared.base10_parse::<i64>() else {
        errors.push(declared.span(), "`dof` takes a whole number");
        return;
    };
    let (mut links, mut joints) = (1i64, 0i64);
    let mut inputs = Vec::new();
    for stmt in &model.stmts {
        match stmt.kind {
            Kind::Crank { .. } | Kind::Slider { .. } => {
                links += 1;
                joints += 1;
            }
            // Cylinder = barrel + rod: three bodies, four lower pairs.
            Kind::Actuator { .. } => {
                links += 3;
                joints += 4;
            }
            Kind::Rrr { .. }
            | Kind::Rrp { .. }
            | Kind::Rpr { .. }
            | Kind::Prp { .. }
            | Kind::Rpp { .. } => {
                links += 2;
                joints += 3;
            }
            _ => {}
        }
        if let Some(i) = stmt.kind.input() {
            inputs.push(i.to_string());
        }
    }
    let mobility = 3 * (links - 1) - 2 * joints;
    if mobility != n {
        errors.push(
            declared.span(),
            format!(
                "the mechanism has {mobility} degree(s) of freedom (Gruebler: 3*({links}-1) - 2*{joints} = {mobility}) for {} input(s) [{}], but `dof {n}` is declared; add or remove a driver, or correct `dof`",
                inputs.len(),
                inputs.join(", ")
            ),
        );
    }
}

/// Rule: every requested output is a point, a named link or a slide.
pub fn outputs_exist(model: &Model, errors: &mut Diagnostics) {
    let Some(outputs) = &model.outputs else {
        return;
    };
    let table = symbols(model);
    let mut listed: Vec<String> = Vec::new();
    for o in outputs {
        let name = o.to_string();
        if listed.contains(&name) {
            errors.push(
                o.span(),
                format!("`{name}` is listed twice in `outputs`; remove this one"),
            );
            continue;
        }
        listed.push(name.clone());
        match table.get(&name) {
            Some((Category::Point | Category::Link | Category::Slide, _)) => {}
            Some((cat, _)) => errors.push(
                o.span(),
                format!(
                    "this definition cannot give `{name}` as an output: it is {}; outputs are points, links (their angles and rates) and slide displacements",
                    cat.article()
                ),
            ),
            None => {
                let candidates = table
                    .iter()
                    .filter(|(n, (c, _))| match c {
                        Category::Point | Category::Slide => true,
                        Category::Link => is_named_link(model, n),
                        _ => false,
                    })
                    .map(|(n, _)| n.as_str());
                errors.push(
                    o.span(),
                    format!(
                        "this definition cannot give `{name}`: no point, link or slide has that name{}",
                        link_hints(model, did_you_mean(&name, candidates))
                    ),
                );
            }
        }
    }
}

/// Rule (after planning): a link point is measured from a point of that link,
/// and a crank turns about a ground point.
pub fn geometry_consistent(model: &Model, plan: &Plan, errors: &mut Diagnostics) {
    for stmt in &model.stmts {
        match &stmt.kind {
            Kind::Point { link, from, .. } => {
                if let Some(info) = plan.links.get(&link.to_string()) {
                    let f = from.to_string();
                    if !info.points.contains(&f) && plan.defined.contains_key(&f) {
                        errors.push(
                            from.span(),
                            format!(
                                "`{f}` is not a point of `{link}`; measure from one of its points: {}",
                                info.points
                                    .iter()
                                    .filter(|p| stmt.name != p.as_str())
                                    .map(|p| format!("`{p}`"))
                                    .collect::<Vec<_>>()
                                    .join(", ")
                            ),
                        );
                    }
                }
            }
            Kind::Crank { pivot, .. } => {
                let p = pivot.to_string();
                if plan.defined.contains_key(&p) && !plan.is_ground(&p) {
                    errors.push(
                        pivot.span(),
                        format!("a crank turns about a ground point, and `{p}` moves; define the pivot with `ground(x, y)`"),
                    );
                }
            }
            Kind::Guide {
                origin: Origin::Point(p),
                carrier: Some(link),
                ..
            } => {
                if let Some(info) = plan.links.get(&link.to_string()) {
                    if !info.points.contains(&p.to_string()) {
                        errors.push(
                            p.span(),
                            format!("a guide carried by `{link}` must pass through one of its points, and `{p}` is not on it"),
                        );
                    }
                }
            }
            Kind::Guide {
                origin: Origin::Point(p),
                carrier: None,
                ..
            } => {
                let name = p.to_string();
                if plan.defined.contains_key(&name) && !plan.is_ground(&name) {
                    errors.push(
                        p.span(),
                        format!("a fixed guide must pass through a ground point, and `{name}` moves; to slide on a moving link write `guide({name}, LINK)`"),
                    );
                }
            }
            _ => {}
        }
    }
}

/// `true` for the cylinder of an actuator (a massless two-force member).
fn is_cylinder(model: &Model, link: &str) -> bool {
    model.stmts.iter().any(|s| {
        matches!(s.kind, Kind::Actuator { .. }) && s.links.get(1).is_some_and(|l| l == link)
    })
}

/// Checks that `link` names a link that can carry loads; pushes an error otherwise.
fn loadable_link(
    model: &Model,
    plan: &Plan,
    link: &Ident,
    what: &str,
    errors: &mut Diagnostics,
) -> bool {
    let name = link.to_string();
    if !plan.links.contains_key(&name) {
        let named = named_links(model);
        let hint = did_you_mean(&name, named.iter().map(String::as_str));
        if name == "ground" || name == "frame" {
            errors.push(
                link.span(),
                format!("`{name}` is the frame, which is fixed: {what} on it moves nothing; put it on a moving link (the names after `as`){hint}"),
            );
            return false;
        }
        let (kind, hint) = if plan.defined.contains_key(&name) || plan.guides.contains_key(&name) {
            (format!("`{name}` is not a link"), hint)
        } else {
            (
                format!("cannot find link `{name}`"),
                link_hints(model, hint),
            )
        };
        errors.push(
            link.span(),
            format!("{kind}; {what} belongs to a link (the names after `as`){hint}"),
        );
        return false;
    }
    if is_cylinder(model, &name) {
        errors.push(
            link.span(),
            format!("`{name}` is an actuator's cylinder, a massless two-force member here; put the load on the link it drives"),
        );
        return false;
    }
    true
}

/// The error for a load's point `at` that is no point: what it is instead,
/// or that nothing has that name, with the nearest point's name (among
/// `first`, the points of the link named, when one is near; else among every
/// point). `what` says what the point is for ("a force acts at a point").
/// `None` when `at` is defined by a statement whose arguments were rejected
/// (that error is reported; this one would follow from it).
fn unknown_point(
    model: &Model,
    plan: &Plan,
    at: &str,
    first: &[String],
    what: &str,
) -> Option<String> {
    if model.failed.iter().any(|f| f.name == at) {
        return None;
    }
    let mut hint = did_you_mean(at, first.iter().map(String::as_str));
    if hint.is_empty() {
        hint = did_you_mean(at, plan.owner.keys().map(String::as_str));
    }
    Some(match symbols(model).get(at) {
        Some((cat, _)) => format!("`{at}` is {}, not a point; {what}{hint}", cat.article()),
        None => format!("cannot find point `{at}`{hint}"),
    })
}

/// Rule (after planning): the force analysis is asked for consistently, masses
/// sit on links at points of those links, forces act at points of one link
/// (or name it), guides and links named by loads exist.
pub fn kinetics_consistent(model: &Model, plan: &Plan, errors: &mut Diagnostics) {
    if model.level == Level::Forces {
        nothing_on_a_cylinder(model, plan, errors);
    }
    let k = &model.kinetics;
    let loaded = !k.masses.is_empty() || !k.forces.is_empty() || !k.torques.is_empty();
    if model.level == Level::Forces && !loaded && !k.declared {
        if let Some(span) = model.level_span {
            errors.push(span, "`analysis forces` needs something to carry: add `mass LINK { m = .., at = POINT }`, `force at POINT = (fx, fy);` or `torque on LINK = t;`");
        }
    }
    if k.declared && model.level < Level::Forces {
        if let Some(span) = model.level_span {
            errors.push(span, "this `analysis` leaves out the force analysis that the `mass`, `force` and `torque` statements ask for; write `analysis forces;` or remove the line");
        }
    }
    if k.gravity.is_some() && k.masses.is_empty() {
        if let Some((span, _, _)) = &k.gravity {
            errors.push(*span, "`gravity` acts through masses, and no link has one: add `mass LINK { m = .., at = POINT }`");
        }
    }
    let mut with_mass: BTreeMap<String, Ident> = BTreeMap::new();
    for m in &k.masses {
        if !loadable_link(model, plan, &m.link, "a mass", errors) {
            continue;
        }
        let link = m.link.to_string();
        if with_mass.contains_key(&link) {
            errors.push(
                m.link.span(),
                format!("`{link}` already has a mass (its first `mass` statement comes earlier); give each link one `mass` statement: merge the two"),
            );
            continue;
        }
        with_mass.insert(link.clone(), m.link.clone());
        let points = &plan.links[&link].points;
        let at = m.at.to_string();
        if !plan.owner.contains_key(&at) {
            let message = unknown_point(
                model,
                plan,
                &at,
                points,
                "the centre of mass is a point of the link",
            );
            if let Some(message) = message {
                errors.push(m.at.span(), message);
            }
            continue;
        }
        if !points.contains(&at) {
            errors.push(
                m.at.span(),
                format!(
                    "the centre of mass must be a point of `{link}`, and `{at}` is not; its points are {}; or define one: `let G = point({link}, from {}, distance, angle);`",
                    points.iter().map(|p| format!("`{p}`")).collect::<Vec<_>>().join(", "),
                    points.first().map(String::as_str).unwrap_or("A"),
                ),
            );
        }
    }
    for f in &k.forces {
        let at = f.at.to_string();
        if !plan.owner.contains_key(&at) {
            let on =
                f.on.as_ref()
                    .and_then(|l| plan.links.get(&l.to_string()))
                    .map_or(&[][..], |info| &info.points[..]);
            if let Some(message) = unknown_point(model, plan, &at, on, "a force acts at a point") {
                errors.push(f.at.span(), message);
            }
            continue;
        }
        match &f.on {
            Some(link) => {
                if loadable_link(model, plan, link, "a force", errors) {
                    let l = link.to_string();
                    if !plan.links[&l].points.contains(&at) {
                        errors.push(
                            f.at.span(),
                            format!(
                                "`{at}` is not a point of `{l}`; its points are {}",
                                plan.links[&l]
                                    .points
                                    .iter()
                                    .map(|p| format!("`{p}`"))
                                    .collect::<Vec<_>>()
                                    .join(", ")
                            ),
                        );
                    }
                }
            }
            None => {
                let links = plan.links_with_point(&at);
                match links.len() {
                    0 => errors.push(
                        f.at.span(),
                        format!("`{at}` is on no moving link (a force on the ground needs no analysis); apply the force at a point of a link"),
                    ),
                    1 => {
                        if is_cylinder(model, &links[0]) {
                            errors.push(f.at.span(), format!("`{at}` is on an actuator's cylinder only, a massless two-force member here"));
                        }
                    }
                    _ => errors.push(
                        f.at.span(),
                        format!(
                            "`{at}` joins {}: say which link the force acts on, e.g. `force at {at} on {} = (fx, fy);`",
                            links.iter().map(|l| format!("`{l}`")).collect::<Vec<_>>().join(" and "),
                            links[0]
                        ),
                    ),
                }
            }
        }
        if let ForceSpecValue::Along(guide, _) = &f.value {
            let g = guide.to_string();
            if !plan.guides.contains_key(&g) {
                let what = match symbols(model).get(&g) {
                    Some((cat, _)) => format!("`{g}` is {}, not a guide", cat.article()),
                    None => format!("cannot find guide `{g}`"),
                };
                errors.push(
                    guide.span(),
                    format!(
                        "{what}; `along` takes a guide, whose direction the force follows{}",
                        did_you_mean(&g, plan.guides.keys().map(String::as_str))
                    ),
                );
            }
        }
    }
    for t in &k.torques {
        loadable_link(model, plan, &t.on, "a torque", errors);
    }
    for (load, _) in &k.loads {
        let name = load.to_string();
        if model.params.iter().any(|(p, _)| p == load)
            || model.consts.contains_key(&name)
            || plan.defined.contains_key(&name)
        {
            let whence = defined_where(model, load)
                .map(|w| format!(" {w}"))
                .unwrap_or_default();
            errors.push(
                load.span(),
                format!("`{name}` is already defined{whence}; a load value needs a name of its own: rename it, e.g. `{}`, here and where it is used", another(&name)),
            );
        }
    }
}

/// Rule (with a force analysis): no group or driver is joined to an
/// actuator's cylinder (at a point of it or on a guide it carries). The force
/// analysis treats the cylinder as a massless two-force member (its force
/// along its axis is the drive) and solves no equations for it, so a
/// reaction passed to it would be lost and every effort behind it wrong; the
/// kinematics are fine, so this is an error of the force analysis only.
fn nothing_on_a_cylinder(model: &Model, plan: &Plan, errors: &mut Diagnostics) {
    let cylinders: Vec<String> = model
        .stmts
        .iter()
        .filter(|s| matches!(s.kind, Kind::Actuator { .. }))
        .filter_map(|s| s.links.get(1).map(Ident::to_string))
        .collect();
    for stmt in &model.stmts {
        if matches!(
            stmt.kind,
            Kind::Ground { .. } | Kind::Guide { .. } | Kind::Point { .. }
        ) {
            continue;
        }
        for r in references(stmt) {
            let name = r.to_string();
            let (body, what) = match (plan.body_of_point(&name), plan.body_of_guide(&name)) {
                (Some(b), _) => (b, "a point of"),
                (None, Some(b)) => (b, "a guide carried by"),
                (None, None) => continue,
            };
            if cylinders.contains(&body) {
                errors.push(
                    r.span(),
                    format!(
                        "`{name}` is {what} the actuator's cylinder `{body}`, which the force analysis takes as a massless two-force member (it carries only its axial force): `{}` cannot be joined to it there; join it to the link the actuator drives or to the ground, or leave out the force analysis (no `mass`, `force`, `torque`)",
                        stmt.name
                    ),
                );
            }
        }
    }
}

/// `#[self_test]` sweeps the input range: every input needs one, and there
/// are at most two inputs.
pub fn self_test_sweepable(model: &Model, errors: &mut Diagnostics) {
    if let Some(span) = model.self_test {
        errors.extend(self_test_requirements(&model.inputs, span));
    }
}

/// The error when `#[self_test]` cannot run (an input without a range).
fn self_test_requirements(inputs: &[Input], span: Span) -> Option<syn::Error> {
    // A declared range that was rejected is reported already.
    let missing: Vec<String> = inputs
        .iter()
        .filter(|i| i.range.is_none() && !i.declared)
        .map(|i| format!("`{}`", i.name))
        .collect();
    if !missing.is_empty() {
        return Some(syn::Error::new(
            span,
            format!(
                "`#[self_test]` tests the mechanism over its input range, and {} has none: declare it, e.g. `range {} = (0.0, 0.1);` (sliders and actuators have no default range)",
                missing.join(", "),
                inputs.iter().find(|i| i.range.is_none() && !i.declared).map(|i| i.name.to_string()).unwrap_or_default()
            ),
        ));
    }
    if inputs.len() > 2 {
        return Some(syn::Error::new(
            span,
            "`#[self_test]` sweeps one or two inputs; this mechanism has more",
        ));
    }
    // Two inputs are swept (and `check()` generated) over a declared box
    // only: a crank's default full turn does not count (`check::emit_check`).
    if inputs.len() == 2 {
        if let Some(i) = inputs.iter().find(|i| !i.declared) {
            return Some(syn::Error::new(
                span,
                format!(
                    "`#[self_test]` sweeps the box of a two-input mechanism's declared ranges, and `{0}` has none (a crank's default full turn is used only when it is the only input): declare it, e.g. `range {0} = (0 deg, 360 deg);`",
                    i.name
                ),
            ));
        }
    }
    None
}
