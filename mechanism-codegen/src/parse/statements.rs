//! The statements of a definition's body, one parser per statement keyword
//! (`let`, `const`, `params`, `analysis`, ...), and the pieces they share
//! (a name after a keyword, `=`, a `(x, y)` pair, `{ name = value, .. }`).
//!
//! Each statement parser gets `start`, the cursor at the statement's first
//! token, for the messages that quote what was written or point at its last
//! token (a missing `;`).

use super::{
    end, kw, last_token, list, next_text, starts_arg, starts_assign, starts_statement, text,
    unit_message, unit_word, vocabulary, Arg, Assign, DrawnCylinder, DrawnGear, DrawnSlider, Force,
    ForceValue, Item, Let, Mass, RangeDecl, Valued, STATEMENTS,
};
use crate::keys::GROUND;
use syn::buffer::Cursor;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{braced, parenthesized, Expr, ExprLit, Ident, Lit, Token};

/// Every word that begins a statement, for messages: `` `let`, `const`,
/// `params`, .. or `cylinder` `` (the vocabulary's list, so a new statement
/// is named in them).
fn statement_words() -> String {
    let words: Vec<String> = ["let", "const"]
        .iter()
        .chain(STATEMENTS)
        .map(|w| format!("`{w}`"))
        .collect();
    match words.split_last() {
        Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
        None => String::new(),
    }
}

impl Parse for Item {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let start = input.cursor();
        if input.peek(Token![let]) {
            return parse_let(input, start);
        }
        if input.peek(Token![const]) {
            return parse_const(input, start);
        }
        let word: Ident = input.parse().map_err(|e| {
            syn::Error::new(
                e.span(),
                format!("expected a statement: {}", statement_words()),
            )
        })?;
        match word.to_string().as_str() {
            "params" => Ok(Item::Params(assignments(input, "params", "a parameter")?)),
            "loads" => Ok(Item::Loads(assignments(input, "loads", "a load value")?)),
            "analysis" => parse_analysis(input, start, &word),
            "outputs" => parse_outputs(input, &word),
            "dof" => parse_dof(input, start, &word),
            "mass" => parse_mass(input),
            "gravity" => parse_gravity(input, start, &word),
            "force" => parse_force(input, start),
            "torque" => parse_torque(input, start),
            "motor" => parse_motor(input, start),
            "range" => parse_range(input, start),
            "allow" => parse_allow(input, start, &word),
            "joints" => Ok(Item::Joints(word.span(), drawn_list(input, "joints")?)),
            "links" => Ok(Item::Links(word.span(), drawn_list(input, "links")?)),
            "input" => parse_input(input, start),
            "slider" => parse_slider(input, start),
            "cylinder" => parse_cylinder(input, start),
            "gear" => parse_gear(input, start),
            "mode" => parse_mode(input, start),
            "units" => Ok(Item::Units(word.span(), units_list(input)?)),
            other => Err(syn::Error::new(
                word.span(),
                format!(
                    "unknown statement `{other}`; expected {}{}",
                    statement_words(),
                    crate::diag::did_you_mean(other, STATEMENTS.iter().copied())
                ),
            )),
        }
    }
}

/// `(A, B, P)`: the joints a `triad` defines, after `let`.
fn joint_names(input: ParseStream) -> syn::Result<Vec<Ident>> {
    let content;
    let paren = parenthesized!(content in input);
    let names = Punctuated::<Ident, Token![,]>::parse_terminated(&content).map_err(|e| {
        syn::Error::new(
            e.span(),
            "expected the three joints a triad defines: `let (A, B, P) = triad(..)`",
        )
    })?;
    if names.len() != 3 {
        return Err(syn::Error::new(
            paren.span.join(),
            format!(
                "a `let (..)` names the three joints of a triad, `(A, B, P)`, not {}: `let (A, B, P) = triad(..)`",
                names.len()
            ),
        ));
    }
    Ok(names.into_iter().collect())
}

/// `let NAME = KIND(args) as (links) slide (names);` (or `let (A, B, P) =
/// triad(..) as (..);`), begun at `start`.
fn parse_let(input: ParseStream, start: Cursor) -> syn::Result<Item> {
    input.parse::<Token![let]>()?;
    let joints = if input.peek(syn::token::Paren) {
        joint_names(input)?
    } else {
        Vec::new()
    };
    let name: Ident = if let Some(first) = joints.first() {
        first.clone()
    } else {
        input.parse().map_err(|e| {
            syn::Error::new(
            e.span(),
            "expected the name this statement defines (a letter first): `let NAME = KIND(args);`",
        )
        })?
    };
    let joints = joints.into_iter().skip(1).collect();
    input.parse::<Token![=]>().map_err(|e| {
        syn::Error::new(
            e.span(),
            format!(
                "expected `=` after `let {name}`, found `{}`: `let {name} = KIND(args);`",
                next_text(input)
            ),
        )
    })?;
    let kind: Ident = input.parse().map_err(|e| {
        syn::Error::new(
            e.span(),
            format!(
                "expected the statement kind after `let {name} =`: one of {}",
                vocabulary::kinds_list()
            ),
        )
    })?;
    if !input.peek(syn::token::Paren) {
        let usage = match vocabulary::KindWord::of(&kind) {
            Some(word) => format!(": `{}`", word.spec().usage),
            None => String::new(),
        };
        return Err(input.error(format!(
            "expected `(`: the arguments of `{kind}` go in parentheses{usage}"
        )));
    }
    let what = format!("the `let {name} = {kind}(..)` statement");
    let content;
    let paren = parenthesized!(content in input);
    let args = list(
        &content,
        &format!("the arguments of `let {name} = {kind}(..)`"),
        Arg::parse,
        starts_arg,
        |_, _| None,
    )?;
    let mut links = Vec::new();
    if input.peek(Token![as]) {
        input.parse::<Token![as]>()?;
        links = names(input, "as", &what)?;
    }
    let mut slides = Vec::new();
    if kw(input, "slide") {
        let _: Ident = input.parse()?;
        slides = names(input, "slide", &what)?;
    }
    if links.is_empty() && input.peek(Ident) && !starts_statement(input) {
        let word = next_text(input);
        return Err(input.error(format!(
            "expected `;` to end {what}, found `{word}`; to name its link write `as {word}`"
        )));
    }
    end(input, start, &what, Valued::Nothing)?;
    Ok(Item::Let(Let {
        name,
        joints,
        word: vocabulary::KindWord::of(&kind),
        kind,
        args,
        args_span: paren.span.join(),
        links,
        slides,
    }))
}

/// `const NAME = value;`, begun at `start`.
fn parse_const(input: ParseStream, start: Cursor) -> syn::Result<Item> {
    input.parse::<Token![const]>()?;
    if input.peek(Ident) && input.peek2(Token![:]) {
        let name: Ident = input.parse()?;
        let colon = input.parse::<Token![:]>()?;
        return Err(syn::Error::new(
                colon.span,
                format!("a `const` takes no type (its value is a number, folded at compile time): write `const {name} = value;`"),
            ));
    }
    let assign: Assign = input.parse()?;
    let what = format!("the `const {} = ..` statement", assign.name);
    end(
        input,
        start,
        &what,
        Valued::Number("a constant", &assign.name),
    )?;
    Ok(Item::Const(assign))
}

/// `analysis LEVEL;`, after the keyword `word`.
fn parse_analysis(input: ParseStream, start: Cursor, word: &Ident) -> syn::Result<Item> {
    let what: Ident = name_after(
        input,
        "analysis",
        "the analysis",
        "`analysis position;`, `velocity`, `acceleration`, `forces` or `dynamics`",
    )?;
    end(
        input,
        start,
        &format!("the `analysis {what}` statement"),
        Valued::Nothing,
    )?;
    Ok(Item::Analysis(word.span(), what))
}

/// `outputs { NAME, .. }`, after the keyword `word`.
fn parse_outputs(input: ParseStream, word: &Ident) -> syn::Result<Item> {
    if !input.peek(syn::token::Brace) {
        return Err(
            input.error("expected `{`: the outputs are listed in braces, `outputs { B, link3 }`")
        );
    }
    let content;
    braced!(content in input);
    let list = list(
        &content,
        "`outputs { .. }`",
        |c| {
            c.parse::<Ident>().map_err(|e| {
                syn::Error::new(
                    e.span(),
                    format!(
                        "expected a point, link or slide name in `outputs {{ .. }}`, found `{}`",
                        next_text(c)
                    ),
                )
            })
        },
        |c| c.peek(Ident),
        |_, _| None,
    )?;
    Ok(Item::Outputs(word.span(), list))
}

/// `dof N;`, after the keyword `word`.
fn parse_dof(input: ParseStream, start: Cursor, word: &Ident) -> syn::Result<Item> {
    let value_start = input.cursor();
    let value: Expr = input.parse().map_err(|e| {
        syn::Error::new(
            e.span(),
            "expected the number of degrees of freedom after `dof`, a positive integer: `dof 1;`",
        )
    })?;
    let n = match &value {
            Expr::Lit(ExprLit {
                lit: Lit::Int(n), ..
            }) if n.base10_parse::<u32>().is_ok_and(|n| n > 0) => n.clone(),
            _ => {
                return Err(syn::Error::new_spanned(
                    &value,
                    format!(
                        "`dof` takes a positive integer, the mechanism's degrees of freedom (one per driver input, e.g. `dof 1;`), not `{}`",
                        text(value_start, input.cursor())
                    ),
                ))
            }
        };
    end(
        input,
        start,
        &format!("the `dof {n}` statement"),
        Valued::Nothing,
    )?;
    Ok(Item::Dof(word.span(), n))
}

/// `mass LINK { m = .., at = .., j = .. }` (a `;` after it optional), after `mass`.
fn parse_mass(input: ParseStream) -> syn::Result<Item> {
    let usage = "`mass LINK { m = mass, at = POINT, j = inertia }`";
    let link: Ident = name_after(input, "mass", "the link's name", usage)?;
    if !input.peek(syn::token::Brace) {
        return Err(input.error(format!(
            "expected `{{` after `mass {link}`, found `{}`: {usage}",
            next_text(input)
        )));
    }
    let content;
    braced!(content in input);
    let list_name = format!("`mass {link} {{ .. }}`");
    let fields = list(
        &content,
        &list_name,
        |c| {
            let name: Ident = c.parse().map_err(|e| {
                syn::Error::new(
                    e.span(),
                    format!(
                        "expected a field, `m`, `at` or `j`, found `{}`: {usage}",
                        next_text(c)
                    ),
                )
            })?;
            c.parse::<Token![=]>().map_err(|e| {
                syn::Error::new(
                    e.span(),
                    format!("expected `=` and a value after `{name}`: {usage}"),
                )
            })?;
            Ok((name, c.parse::<Arg>()?))
        },
        starts_assign,
        |_, _| None,
    )?;
    if input.peek(Token![;]) {
        input.parse::<Token![;]>()?;
    }
    Ok(Item::Mass(Mass { link, fields }))
}

/// `gravity (gx, gy);`, after the keyword `word`.
fn parse_gravity(input: ParseStream, start: Cursor, word: &Ident) -> syn::Result<Item> {
    let (x, y) = pair(
        input,
        "`gravity (gx, gy);`",
        Valued::Load("a gravity component"),
    )?;
    end(
        input,
        start,
        "the `gravity (..)` statement",
        Valued::Nothing,
    )?;
    Ok(Item::Gravity(word.span(), x, y))
}

/// `force at POINT (on LINK)? = (fx, fy);` or `.. along GUIDE = f;`, after `force`.
fn parse_force(input: ParseStream, start: Cursor) -> syn::Result<Item> {
    let usage = "`force at POINT = (fx, fy);`";
    if !kw(input, "at") {
        return Err(input.error(format!("expected `at`: {usage}")));
    }
    let _: Ident = input.parse()?;
    let at: Ident = name_after(input, "at", "a point's name", usage)?;
    let mut on = None;
    if kw(input, "on") {
        let _: Ident = input.parse()?;
        on = Some(name_after(
            input,
            "on",
            "a link's name",
            "`force at POINT on LINK = (fx, fy);`",
        )?);
    }
    let what = format!("the `force at {at} ..` statement");
    let value = if kw(input, "along") {
        let _: Ident = input.parse()?;
        let along = "`force at POINT on LINK along GUIDE = f;`";
        let guide = name_after(input, "along", "a guide's name", along)?;
        equals(input, start, along)?;
        let f = input.parse()?;
        end(input, start, &what, Valued::Load("a force"))?;
        ForceValue::Along(guide, f)
    } else {
        input.parse::<Token![=]>().map_err(|e| {
            syn::Error::new(
                e.span(),
                "expected `= (fx, fy)`, `on LINK` or `along GUIDE = f`",
            )
        })?;
        let (x, y) = pair(input, usage, Valued::Load("a force component"))?;
        end(input, start, &what, Valued::Nothing)?;
        ForceValue::Components(x, y)
    };
    Ok(Item::Force(Force { at, on, value }))
}

/// `torque on LINK = value;`, after `torque`.
fn parse_torque(input: ParseStream, start: Cursor) -> syn::Result<Item> {
    let usage = "`torque on LINK = value;`";
    if !kw(input, "on") {
        return Err(input.error(format!("expected `on`: {usage}")));
    }
    let _: Ident = input.parse()?;
    let on: Ident = name_after(input, "on", "a link's name", usage)?;
    equals(input, start, usage)?;
    let value = input.parse()?;
    end(
        input,
        start,
        &format!("the `torque on {on} = ..` statement"),
        Valued::Load("a torque"),
    )?;
    Ok(Item::Torque(on, value))
}

/// `mode NAME = assembly(J);`, after `mode`.
fn parse_mode(input: ParseStream, start: Cursor) -> syn::Result<Item> {
    let usage = "`mode elbow = assembly(C);` (the group placing joint `C` takes its assembly from the run-time field `elbow`)";
    let name: Ident = name_after(input, "mode", "the mode parameter's name", usage)?;
    equals(input, start, usage)?;
    let word: Ident = name_after(input, "=", "`assembly`", usage)?;
    if word != "assembly" {
        return Err(syn::Error::new(
            word.span(),
            format!("a mode parameter is the assembly of the group placing a joint, `assembly(..)`: {usage}"),
        ));
    }
    let content;
    parenthesized!(content in input);
    let joint: Ident = content
        .parse()
        .map_err(|e| syn::Error::new(e.span(), format!("expected a joint's name: {usage}")))?;
    if !content.is_empty() {
        return Err(content.error(format!("`assembly` takes one joint: {usage}")));
    }
    end(
        input,
        start,
        &format!("the `mode {name} = ..` statement"),
        Valued::Nothing,
    )?;
    Ok(Item::Mode(name, joint))
}

/// `motor NAME = angle(LINK);` or `motor NAME = angle(LINK, CARRIER);`,
/// after `motor`.
fn parse_motor(input: ParseStream, start: Cursor) -> syn::Result<Item> {
    let usage = "`motor q1 = angle(arm1);` or `motor knee = angle(shank, thigh);`";
    let name: Ident = name_after(input, "motor", "the motor's name", usage)?;
    equals(input, start, usage)?;
    let word: Ident = name_after(input, "=", "`angle`", usage)?;
    if word != "angle" {
        return Err(syn::Error::new(
            word.span(),
            format!("a motor is a link's angle, `angle(..)`: {usage}"),
        ));
    }
    let content;
    parenthesized!(content in input);
    let links: Punctuated<Ident, Token![,]> = Punctuated::parse_terminated(&content)
        .map_err(|e| syn::Error::new(e.span(), format!("expected a link's name: {usage}")))?;
    let mut links = links.into_iter();
    let (Some(link), carrier, None) = (links.next(), links.next(), links.next()) else {
        return Err(syn::Error::new(
            word.span(),
            format!("`angle` takes the motor's link, and the link carrying it if that is not the ground: {usage}"),
        ));
    };
    end(
        input,
        start,
        &format!("the `motor {name} = ..` statement"),
        Valued::Load("a motor"),
    )?;
    let carrier = carrier.filter(|c| c != GROUND);
    Ok(Item::Motor(name, link, carrier))
}

/// `range INPUT = (lo, hi);`, after `range`.
fn parse_range(input: ParseStream, start: Cursor) -> syn::Result<Item> {
    let usage = "`range INPUT = (lo, hi);`";
    let name: Ident = name_after(input, "range", "the driver input", usage)?;
    input_eq(input)?;
    if !input.peek(syn::token::Paren) {
        return Err(input.error(format!(
                "expected `(`, found `{}`: the two ends of a range go in parentheses, each with its unit: `range {name} = (-40 deg, 40 deg);`",
                next_text(input)
            )));
    }
    let content;
    parenthesized!(content in input);
    let lo_start = content.cursor();
    let lo = content.parse()?;
    if !content.peek(Token![,]) && starts_arg(&content) {
        let span = last_token(lo_start, content.cursor()).unwrap_or_else(|| content.span());
        return Err(syn::Error::new(
                span,
                format!(
                    "expected `,` after `{}`: the two ends are separated by a comma, `range {name} = (lo, hi);`",
                    text(lo_start, content.cursor())
                ),
            ));
    }
    content.parse::<Token![,]>().map_err(|e| {
        syn::Error::new(
            e.span(),
            format!(
                "expected `,` after the lower end, found `{}`: `range {name} = (lo, hi);`",
                next_text(&content)
            ),
        )
    })?;
    let hi = content.parse()?;
    if !content.is_empty() {
        return Err(content.error("a range is `(lo, hi)`: two values"));
    }
    let what = format!("the `range {name} = (..)` statement");
    if unit_word(input).is_some() {
        return Err(input.error(format!(
                "unexpected `{}` after the parentheses: in {what} each end takes its own unit, `(-40 deg, 40 deg)`",
                next_text(input)
            )));
    }
    end(input, start, &what, Valued::Nothing)?;
    Ok(Item::Range(RangeDecl {
        input: name,
        lo,
        hi,
    }))
}

/// `allow WHAT (GROUP, ..)?;`, after the keyword `word`.
fn parse_allow(input: ParseStream, start: Cursor, word: &Ident) -> syn::Result<Item> {
    let what: Ident = name_after(
        input,
        "allow",
        "what is allowed",
        "`allow singular;` or `allow singular B, C;`",
    )?;
    let mut groups = Vec::new();
    while !input.peek(Token![;]) {
        // A group may be named like a statement keyword
        // (`allow singular range;`): only a keyword that does not
        // end the list begins the next statement.
        let keyword_next =
            starts_statement(input) && !(input.peek2(Token![;]) || input.peek2(Token![,]));
        if input.is_empty() || keyword_next || !input.peek(Ident) {
            break;
        }
        groups.push(input.parse()?);
        if input.peek(Token![,]) {
            input.parse::<Token![,]>()?;
        }
    }
    end(
        input,
        start,
        &format!("the `allow {what} ..` statement"),
        Valued::Nothing,
    )?;
    Ok(Item::Allow(word.span(), what, groups))
}

/// `IDENT` or `(IDENT, ...)` after `as` or `slide` (`word`) of the `let`
/// statement `what`.
fn names(input: ParseStream, word: &str, what: &str) -> syn::Result<Vec<Ident>> {
    if input.peek(syn::token::Paren) {
        let content;
        parenthesized!(content in input);
        let list_name = format!("the names after `{word}` in {what}");
        list(
            &content,
            &list_name,
            |c| {
                c.parse::<Ident>().map_err(|e| {
                    syn::Error::new(
                        e.span(),
                        format!("expected a name after `{word}` in {what}: `{word} (a, b)`"),
                    )
                })
            },
            |c| c.peek(Ident),
            |_, _| None,
        )
    } else {
        let name = input.parse::<Ident>().map_err(|e| {
            syn::Error::new(
                e.span(),
                format!("expected a name or `(a, b)` after `{word}` in {what}"),
            )
        })?;
        Ok(vec![name])
    }
}

fn input_eq(input: ParseStream) -> syn::Result<()> {
    input
        .parse::<Token![=]>()
        .map(|_| ())
        .map_err(|e| syn::Error::new(e.span(), "expected `=`: `range INPUT = (lo, hi);`"))
}

/// `(x, y)`: two components; `usage` shows the whole statement, `valued`
/// what a component is (for a unit word after one).
fn pair(input: ParseStream, usage: &str, valued: Valued) -> syn::Result<(Expr, Expr)> {
    let two = |span| syn::Error::new(span, format!("expected two components: {usage}"));
    if !input.peek(syn::token::Paren) {
        return Err(two(input.span()));
    }
    let content;
    parenthesized!(content in input);
    let unit = |content: ParseStream| -> Option<syn::Error> {
        let message = unit_word(content).and_then(|u| unit_message(&u, valued))?;
        Some(content.error(message))
    };
    let start = content.cursor();
    let x: Expr = content.parse()?;
    if let Some(e) = unit(&content) {
        return Err(e);
    }
    if !content.peek(Token![,]) && starts_arg(&content) {
        let span = last_token(start, content.cursor()).unwrap_or_else(|| content.span());
        return Err(syn::Error::new(
            span,
            format!(
                "expected `,` after `{}`: the two components are separated by a comma, {usage}",
                text(start, content.cursor())
            ),
        ));
    }
    content.parse::<Token![,]>().map_err(|e| two(e.span()))?;
    let y: Expr = content.parse()?;
    if let Some(e) = unit(&content) {
        return Err(e);
    }
    if !content.is_empty() {
        return Err(two(content.span()));
    }
    Ok((x, y))
}

impl Parse for Assign {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let name: Ident = input.parse().map_err(|e| {
            syn::Error::new(
                e.span(),
                format!(
                    "expected a name, found `{}`: `name = 1.0`",
                    next_text(input)
                ),
            )
        })?;
        input.parse::<Token![=]>().map_err(|e| {
            syn::Error::new(
                e.span(),
                format!("expected `=` and a value after `{name}`: `{name} = 1.0` (every parameter, constant and load has a default)"),
            )
        })?;
        Ok(Assign {
            name,
            value: input.parse()?,
        })
    }
}

/// `{ name = value, .. }` of `params` or `loads` (`word`); `what` is one
/// entry ("a parameter").
fn assignments(input: ParseStream, word: &str, what: &str) -> syn::Result<Vec<Assign>> {
    let example = format!("{word} {{ a = 1.0, b = 2.0 }}");
    braced_assignments(input, word, &example, &|a: &Assign, u| {
        if word == "loads" {
            unit_message(u, Valued::Load(what))
        } else {
            unit_message(u, Valued::Number(what, &a.name))
        }
    })
}

/// `{ NAME = value, .. }` of the drawn form's `joints` (`(x, y)` values) or
/// `links` (`[J1, J2, ..]` values); the values are read in `model::drawn`.
fn drawn_list(input: ParseStream, word: &str) -> syn::Result<Vec<Assign>> {
    let example = if word == "joints" {
        "joints { O2 = (0.0, 0.0), A = (0.0, 0.1) }"
    } else {
        "links { ground = [O2, O4], crank = [O2, A] }"
    };
    braced_assignments(input, word, example, &|_, u| {
        Some(format!("`{u}` has no place in `{word}`: `{example}`"))
    })
}

/// `{ length = "mm", .. }` of `units`; the names and values are read in
/// `model::units`.
fn units_list(input: ParseStream) -> syn::Result<Vec<Assign>> {
    let example = r#"units { length = "mm", force = "N", mass = "kg", time = "s" }"#;
    braced_assignments(input, "units", example, &|a, u| {
        Some(format!(
            "`{u}` has no place here: a unit is named by a string, `{} = \"{u}\"`",
            a.name
        ))
    })
}

/// `{ NAME = value, .. }` after `word`, `example` shown when the brace is
/// missing; `unit` gives the message for a unit word after a value.
fn braced_assignments(
    input: ParseStream,
    word: &str,
    example: &str,
    unit: &dyn Fn(&Assign, &Ident) -> Option<String>,
) -> syn::Result<Vec<Assign>> {
    if !input.peek(syn::token::Brace) {
        return Err(input.error(format!(
            "expected `{{` after `{word}`: the entries go in braces, `{example}`"
        )));
    }
    let content;
    braced!(content in input);
    let list_name = format!("`{word} {{ .. }}`");
    list(&content, &list_name, Assign::parse, starts_assign, unit)
}

/// `slider BLOCK at J on CARRIER along angle;`, after `slider`.
fn parse_slider(input: ParseStream, start: Cursor) -> syn::Result<Item> {
    let usage = "`slider block at B on ground along 0 deg;`";
    let block = name_after(input, "slider", "the block's name", usage)?;
    let word = |w: &str, what: &str| -> syn::Result<Ident> {
        if !kw(input, w) {
            return Err(input.error(format!("expected `{w}`: {usage}")));
        }
        let _: Ident = input.parse()?;
        name_after(input, w, what, usage)
    };
    let at = word("at", "the joint it is pinned at")?;
    let on = word("on", "what it slides on")?;
    if !kw(input, "along") {
        return Err(input.error(format!(
            "expected `along` and the line's direction: {usage}"
        )));
    }
    let _: Ident = input.parse()?;
    let angle: Expr = input.parse()?;
    let unit = unit_word(input);
    if unit.is_some() {
        let _: Ident = input.parse()?;
    }
    end(
        input,
        start,
        &format!("the `slider {block} ..` statement"),
        Valued::Load("an angle"),
    )?;
    Ok(Item::Slider(DrawnSlider {
        block,
        at,
        on,
        angle,
        unit,
    }))
}

/// `cylinder CYL from B to C;` or `cylinder (BARREL, ROD) from B to C;`,
/// after `cylinder`.
fn parse_cylinder(input: ParseStream, start: Cursor) -> syn::Result<Item> {
    let usage = "`cylinder lift from B to C;` or `cylinder (barrel, rod) from B to C;`";
    let names = if input.peek(syn::token::Paren) {
        let content;
        parenthesized!(content in input);
        let list = content.parse_terminated(Ident::parse, Token![,])?;
        if list.len() != 2 {
            return Err(syn::Error::new(
                content.span(),
                format!("a cylinder is one link or two (its barrel and its rod): {usage}"),
            ));
        }
        list.into_iter().collect()
    } else {
        vec![name_after(input, "cylinder", "the cylinder's name", usage)?]
    };
    let word = |w: &str, what: &str| -> syn::Result<Ident> {
        if !kw(input, w) {
            return Err(input.error(format!("expected `{w}`: {usage}")));
        }
        let _: Ident = input.parse()?;
        name_after(input, w, what, usage)
    };
    let from = word("from", "the joint its barrel is pinned at")?;
    let to = word("to", "the joint its rod is pinned at")?;
    end(
        input,
        start,
        &format!("the `cylinder {} ..` statement", names[0]),
        Valued::Nothing,
    )?;
    Ok(Item::Cylinder(DrawnCylinder { names, from, to }))
}

/// `gear LINK to MESH ratio R [on CARRIER] [pressure ANGLE];`, after `gear`.
fn parse_gear(input: ParseStream, start: Cursor) -> syn::Result<Item> {
    let usage = "`gear link5 to link2 ratio 2.0;` or `gear planet to ground ratio 1.5 on arm pressure 20 deg;`";
    let link = name_after(input, "gear", "the gear's link", usage)?;
    if !kw(input, "to") {
        return Err(input.error(format!(
            "expected `to` and the link it meshes with: {usage}"
        )));
    }
    let _: Ident = input.parse()?;
    let mesh = name_after(input, "to", "the link it meshes with", usage)?;
    if !kw(input, "ratio") {
        return Err(input.error(format!(
            "expected `ratio` and the pitch radius of `{mesh}`'s gear over `{link}`'s: {usage}"
        )));
    }
    let _: Ident = input.parse()?;
    let ratio: Expr = input.parse()?;
    let carrier = if kw(input, "on") {
        let _: Ident = input.parse()?;
        Some(name_after(
            input,
            "on",
            "the link both gears turn on",
            usage,
        )?)
    } else {
        None
    };
    let pressure = if kw(input, "pressure") {
        let _: Ident = input.parse()?;
        let angle: Expr = input.parse()?;
        let unit = unit_word(input);
        if unit.is_some() {
            let _: Ident = input.parse()?;
        }
        Some((angle, unit))
    } else {
        None
    };
    end(
        input,
        start,
        &format!("the `gear {link} ..` statement"),
        Valued::Nothing,
    )?;
    Ok(Item::Gear(DrawnGear {
        link,
        mesh,
        ratio,
        carrier,
        pressure,
    }))
}

/// `input NAME = angle(LINK);` or `input NAME = angle(LINK, FROM_LINK);`,
/// after `input`.
fn parse_input(input: ParseStream, start: Cursor) -> syn::Result<Item> {
    let usage = "`input theta = angle(crank);` or `input knee = angle(shank, thigh);`";
    let name: Ident = name_after(input, "input", "the input's name", usage)?;
    equals(input, start, usage)?;
    let value: Expr = input.parse()?;
    end(
        input,
        start,
        &format!("the `input {name} = ..` statement"),
        Valued::Load("an input"),
    )?;
    Ok(Item::Input(name, value))
}

/// A name after `word` in the statement `usage`.
fn name_after(input: ParseStream, word: &str, what: &str, usage: &str) -> syn::Result<Ident> {
    input.parse::<Ident>().map_err(|e| {
        syn::Error::new(
            e.span(),
            format!(
                "expected {what} after `{word}`, found `{}`: {usage}",
                next_text(input)
            ),
        )
    })
}

/// `=` after the statement begun at `start`, with `usage` in the message.
fn equals(input: ParseStream, start: Cursor, usage: &str) -> syn::Result<()> {
    input.parse::<Token![=]>().map(|_| ()).map_err(|e| {
        syn::Error::new(
            e.span(),
            format!(
                "expected `=` after `{}`, found `{}`: {usage}",
                text(start, input.cursor()),
                next_text(input)
            ),
        )
    })
}
