//! The rules on names: each defined once, none the generated code needs for
//! itself, and every reference naming something defined of the right
//! category; with the symbol table and the hints on a name that is not
//! found, which the other rules share.

use crate::diag::{did_you_mean, Diagnostics};
use crate::kinds::word::KindWord;
use crate::kinds::{self, Role};
use crate::model::{FailedKind, Model, StmtId};
use std::collections::BTreeMap;
use syn::Ident;

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
    pub(super) fn article(self) -> &'static str {
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
/// twice (an error of its own, from `unique_names`) keeps its first
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
    for (name, _) in model
        .params
        .iter()
        .map(|(n, _)| (n, ()))
        .chain(model.modes.iter().map(|(n, _)| (n, ())))
    {
        table.insert(name.to_string(), (Category::Param, name.clone()));
    }
    for (name, (ident, _)) in &model.consts {
        table.insert(name.clone(), (Category::Const, ident.clone()));
    }
    for stmt in &model.stmts {
        let kind = kinds::of(stmt);
        let cat = if kinds::guide_carrier(stmt).is_some() {
            Category::Guide
        } else if kind.names_slide() {
            Category::Slide
        } else {
            Category::Point
        };
        table.insert(stmt.name.to_string(), (cat, stmt.name.clone()));
        for link in &stmt.links {
            table.insert(link.to_string(), (Category::Link, link.clone()));
        }
        for slide in stmt.slides.iter().flatten() {
            table.insert(slide.to_string(), (Category::Slide, slide.clone()));
        }
        for input in stmt.kind.inputs() {
            table.insert(input.to_string(), (Category::Input, input.clone()));
        }
    }
    for f in &model.failed {
        let cat = match f.kind {
            FailedKind::Let(Some(KindWord::Guide)) => Some(Category::Guide),
            FailedKind::Let(Some(KindWord::Rpr)) => Some(Category::Slide),
            _ => f.names_point().then_some(Category::Point),
        };
        if let Some(cat) = cat {
            table.insert(f.name.to_string(), (cat, f.name.clone()));
        }
        for link in &f.links {
            table.insert(link.to_string(), (Category::Link, link.clone()));
        }
        for slide in &f.slides {
            table.insert(slide.to_string(), (Category::Slide, slide.clone()));
        }
        for input in &f.inputs {
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
    /// By statement `.0`, in the role `.1` ("as a link of"), written `.2`
    /// (`let B = rrr(..)`).
    Statement(StmtId, &'static str, String),
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
    for (name, _) in &model.modes {
        out.push((
            name.clone(),
            Place::Outside("as a run-time mode parameter (in `params { .. }`)".to_string()),
        ));
    }
    for (ident, _) in model.consts.values() {
        out.push((
            ident.clone(),
            Place::Outside(format!("as a constant (`const {ident} = ..;`)")),
        ));
    }
    for (i, stmt) in StmtId::all(&model.stmts).zip(&model.stmts) {
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
        for input in stmt.kind.inputs() {
            push(input, "as the input of");
        }
    }
    out
}

/// Rule: a name is defined once (points, links, slides, inputs, parameters and
/// constants share one namespace: they become fields side by side). The error
/// is on the later definition (parameters and constants count as first) and
/// says where the first one is (a `compile_error!` carries no second span).
pub(super) fn unique_names(model: &Model, errors: &mut Diagnostics) {
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
pub(super) fn another(name: &str) -> String {
    if name.ends_with(|c: char| c.is_ascii_digit()) {
        format!("{name}b")
    } else {
        format!("{name}2")
    }
}

/// The links the user named (after `as`): the names to suggest. A statement
/// written without `as` gets internal link names, which are never suggested.
pub(super) fn named_links(model: &Model) -> Vec<String> {
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
pub(super) fn is_named_link(model: &Model, name: &str) -> bool {
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
            let usage = KindWord::of(&s.kind_token).map_or("", |k| k.spec().usage);
            let names = usage
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
pub(super) fn link_hints(model: &Model, near: String) -> String {
    match (near.is_empty(), unnamed_links_hint(model)) {
        (_, unnamed) if unnamed.is_empty() => near,
        (true, unnamed) => format!("; {unnamed}"),
        (false, unnamed) => format!("{near} Or, for a link without a name: {unnamed}"),
    }
}

/// Where `name` is defined, in words, for messages about a second
/// definition outside the statements (a load value); `None` when it is not.
pub(super) fn defined_where(model: &Model, name: &Ident) -> Option<String> {
    definitions(model)
        .into_iter()
        .find(|(ident, _)| ident == name)
        .map(|(_, place)| match place {
            Place::Outside(words) => words,
            Place::Statement(_, role, written) => format!("{role} the {written} statement"),
        })
}

/// Rule: names the generated code needs for itself are not available.
pub(super) fn reserved_names(model: &Model, errors: &mut Diagnostics) {
    for (name, (_, ident)) in symbols(model) {
        // Raw identifiers (`r#type`) never get here: `parse::lexical`
        // refuses them on every token.
        if name == "T" {
            errors.push(
                ident.span(),
                "`T` is the generated types' scalar parameter (`f32` or `f64`); choose another name",
            );
        } else if RESERVED.contains(&name.as_str()) {
            errors.push(
                ident.span(),
                format!("`{name}` is reserved for the generated methods' arguments; choose another name"),
            );
        } else if let Some(p) =
            crate::names::reserved_prefixes().find(|p| name.starts_with(p.as_str()))
        {
            errors.push(
                ident.span(),
                format!("names starting with `{p}` are reserved for the generated code's locals; rename `{name}`"),
            );
        }
    }
}

/// Rule: every reference names something defined, of the right category, and
/// not the statement itself.
pub(super) fn references_resolve(model: &Model, errors: &mut Diagnostics) {
    let table = symbols(model);
    let every = every_symbol(model);
    for stmt in &model.stmts {
        let expected: Vec<(&Ident, Category)> = kinds::of(stmt)
            .references()
            .into_iter()
            .map(|(r, role)| {
                let want = match role {
                    Role::Point => Category::Point,
                    Role::Guide => Category::Guide,
                    Role::Link => Category::Link,
                };
                (r, want)
            })
            .collect();
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
