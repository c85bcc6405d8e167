//! Stage 1, parse: the token stream of `mechanism! { ... }` into a syntax tree
//! that keeps every user token (for spans). No meaning is given here.
//!
//! Grammar (see `docs/dsl.md` for the reference with examples):
//!
//! ```text
//! definition := outer-doc* vis? IDENT '{' item* '}'
//! item       := 'params' '{' (IDENT '=' expr),* '}'
//!             | 'const' IDENT '=' expr ';'
//!             | 'analysis' IDENT ';'
//!             | 'outputs' '{' IDENT,* '}'
//!             | 'dof' INT ';'
//!             | 'let' IDENT '=' IDENT '(' arg,* ')' ('as' links)? ('slide' names)? ';'
//!             | 'loads' '{' (IDENT '=' expr),* '}'
//!             | 'mass' IDENT '{' (IDENT '=' arg),* '}' ';'?
//!             | 'gravity' '(' expr ',' expr ')' ';'
//!             | 'force' 'at' IDENT ('on' IDENT)? '=' '(' expr ',' expr ')' ';'
//!             | 'force' 'at' IDENT ('on' IDENT)? 'along' IDENT '=' expr ';'
//!             | 'torque' 'on' IDENT '=' expr ';'
//!             | 'range' IDENT '=' '(' arg ',' arg ')' ';'
//!             | 'allow' 'singular' (IDENT,*)? ';'
//! arg        := 'from' IDENT | expr ('deg' | 'rad')?
//! links      := IDENT | '(' IDENT,* ')'
//! names      := IDENT | '(' IDENT,* ')'
//! ```

use proc_macro2::{Delimiter, Span, TokenTree};
use syn::buffer::Cursor;
use syn::parse::{Parse, ParseStream};
use syn::{braced, parenthesized, Attribute, Expr, ExprLit, Ident, Lit, LitInt, Token, Visibility};

/// A whole definition.
pub struct Definition {
    /// Outer doc comments, copied onto the generated type.
    pub docs: Vec<Attribute>,
    /// `#[self_test]`: the attribute's span, when given.
    pub self_test: Option<Span>,
    /// Visibility of the generated items.
    pub vis: Visibility,
    /// Name of the mechanism type.
    pub name: Ident,
    /// Statements in the order written.
    pub items: Vec<Item>,
}

/// One statement of the body.
pub enum Item {
    /// `params { a = 1.0, ... }`: run-time parameters with literal defaults.
    Params(Vec<Assign>),
    /// `const a = 1.0;`: a compile-time constant, folded into the code.
    Const(Assign),
    /// `analysis velocity;`, with the keyword's span.
    Analysis(Span, Ident),
    /// `outputs { B, link3 }`, with the keyword's span.
    Outputs(Span, Vec<Ident>),
    /// `dof 1;`: the mobility the author computed (checked), with the
    /// keyword's span.
    Dof(Span, LitInt),
    /// `let NAME = KIND(args) as (links) slide (names);`
    Let(Let),
    /// `mass link3 { m = 20.0, at = P, j = 1.2 }`
    Mass(Mass),
    /// `gravity (0.0, -9.81);`
    Gravity(Span, Expr, Expr),
    /// `loads { cut = 0.0 }`: load values the caller supplies per evaluation.
    Loads(Vec<Assign>),
    /// `force at E on LINK = (fx, fy);` or `force at E on LINK along GUIDE = f;`
    Force(Force),
    /// `torque on link3 = t;`
    Torque(Ident, Expr),
    /// `range theta2 = (-40 deg, 40 deg);`: the input range to check.
    Range(RangeDecl),
    /// `allow singular;` / `allow singular B, C;`: the `allow` keyword's
    /// span, what is allowed, and the groups (empty: all).
    Allow(Span, Ident, Vec<Ident>),
}

/// `range INPUT = (lo, hi);`
pub struct RangeDecl {
    /// The driver input.
    pub input: Ident,
    /// Lower end (with its unit).
    pub lo: Arg,
    /// Upper end (with its unit).
    pub hi: Arg,
}

/// `name = expr`.
pub struct Assign {
    /// The name.
    pub name: Ident,
    /// The value.
    pub value: Expr,
}

/// `let` statement.
pub struct Let {
    /// The defined name (a point, a guide, or a slide variable).
    pub name: Ident,
    /// The statement kind (`ground`, `crank`, `rrr`, ...).
    pub kind: Ident,
    /// Arguments in order.
    pub args: Vec<Arg>,
    /// Span of the parenthesized argument list (for arity errors).
    pub args_span: Span,
    /// Names given to the links the statement creates (`as`).
    pub links: Vec<Ident>,
    /// Names given to slide displacements (`slide`).
    pub slides: Vec<Ident>,
}

/// A call argument.
// `syn::Expr` is larger with proc-macro2's `span-locations` (the codegen tests
// enable it to check error positions); these live only while the macro runs.
#[allow(clippy::large_enum_variant)]
pub enum Arg {
    /// `from X`: the point a link point is measured from.
    From(Ident),
    /// A value, with an optional angle unit.
    Value(Expr, Option<Ident>),
}

/// `mass link { m = .., at = .., j = .. }`.
pub struct Mass {
    /// The link.
    pub link: Ident,
    /// Its fields.
    pub fields: Vec<(Ident, Arg)>,
}

/// `force at POINT (on LINK)? (= (fx, fy) | along GUIDE = f);`
pub struct Force {
    /// The point of application.
    pub at: Ident,
    /// The link it acts on, when given.
    pub on: Option<Ident>,
    /// Its value.
    pub value: ForceValue,
}

/// The value of a `force` statement.
// `syn::Expr` is larger with proc-macro2's `span-locations` (the codegen tests
// enable it to check error positions); these live only while the macro runs.
#[allow(clippy::large_enum_variant)]
pub enum ForceValue {
    /// Components in the global frame.
    Components(Expr, Expr),
    /// A signed magnitude along a guide's direction.
    Along(Ident, Expr),
}

/// The words that begin a statement (besides `let` and `const`).
const STATEMENTS: &[&str] = &[
    "params", "analysis", "outputs", "dof", "loads", "mass", "gravity", "force", "torque", "range",
    "allow",
];

/// Unit words a user may write after a value where none is taken (in a
/// constant, a parameter, a load, a force, a torque): they get a message about
/// units rather than a bare "expected `;`". `deg` and `rad` are the only units
/// of the language (angles, in arguments and ranges).
const UNIT_WORDS: &[&str] = &[
    "deg", "rad", "degree", "degrees", "mm", "cm", "m", "km", "in", "ft", "kg", "g", "t", "N",
    "kN", "Nm", "Nmm", "s", "ms", "rpm", "Hz",
];

fn kw(input: ParseStream, word: &str) -> bool {
    input.peek(Ident) && input.fork().parse::<Ident>().is_ok_and(|i| i == word)
}

/// `true` when the next tokens begin a statement (so a `;` before them is
/// missing, rather than a stray token standing where the `;` goes).
fn starts_statement(input: ParseStream) -> bool {
    input.peek(Token![let])
        || input.peek(Token![const])
        || input
            .fork()
            .parse::<Ident>()
            .is_ok_and(|i| STATEMENTS.contains(&i.to_string().as_str()))
}

/// The next token, when it is a unit word (see [`UNIT_WORDS`]).
fn unit_word(input: ParseStream) -> Option<Ident> {
    let word = input.fork().parse::<Ident>().ok()?;
    UNIT_WORDS
        .contains(&word.to_string().as_str())
        .then_some(word)
}

/// The span of the last token from `from` up to (not including) `to`, two
/// cursors of one stream; for a group, its closing delimiter. `None` when
/// nothing lies between them.
fn last_token(from: Cursor, to: Cursor) -> Option<Span> {
    let mut cursor = from;
    let mut last = None;
    while cursor != to {
        let Some((tree, next)) = cursor.token_tree() else {
            break;
        };
        last = Some(match &tree {
            TokenTree::Group(g) => g.span_close(),
            other => other.span(),
        });
        cursor = next;
    }
    last
}

/// The user's text from `from` up to `to`, for messages: groups shortened to
/// `(..)` when they hold more than one token.
fn text(from: Cursor, to: Cursor) -> String {
    let mut cursor = from;
    let mut out = String::new();
    let mut glue = true; // no space before the next token
    while cursor != to {
        let Some((tree, next)) = cursor.token_tree() else {
            break;
        };
        let piece = match &tree {
            TokenTree::Group(g) => {
                let inner = g.stream().to_string();
                let inner = if g.stream().into_iter().count() > 1 {
                    "..".to_string()
                } else {
                    inner
                };
                match g.delimiter() {
                    Delimiter::Parenthesis => format!("({inner})"),
                    Delimiter::Brace => format!("{{ {inner} }}"),
                    Delimiter::Bracket => format!("[{inner}]"),
                    Delimiter::None => inner,
                }
            }
            other => other.to_string(),
        };
        let is_group = matches!(tree, TokenTree::Group(_));
        let tight = matches!(&tree, TokenTree::Punct(p) if p.as_char() == ',');
        // A group right after a name is a call: `ground(..)`.
        let call = is_group && out.ends_with(char::is_alphanumeric);
        if !(out.is_empty() || glue || tight || call) {
            out.push(' ');
        }
        out.push_str(&piece);
        // A sign sticks to what follows it when it stands first or after `=`,
        // `(` or `,`.
        glue = matches!(&tree, TokenTree::Punct(p) if p.as_char() == '-')
            && (out.len() == 1 || out[..out.len() - 1].ends_with(['=', ' ', '(', ',']));
        cursor = next;
    }
    out
}

/// The text of the next token, for "found `x`".
fn next_text(input: ParseStream) -> String {
    let cursor = input.cursor();
    match cursor.token_tree() {
        Some((TokenTree::Group(g), _)) => match g.delimiter() {
            Delimiter::Parenthesis => "(".to_string(),
            Delimiter::Brace => "{".to_string(),
            Delimiter::Bracket => "[".to_string(),
            Delimiter::None => g.stream().to_string(),
        },
        Some((tree, _)) => tree.to_string(),
        None => "the end".to_string(),
    }
}

/// What a value just parsed is, for the message on a unit word written after
/// it.
#[derive(Clone, Copy)]
enum Valued<'a> {
    /// Nothing to say about units.
    Nothing,
    /// A plain number that is named (a constant or a parameter: "a constant",
    /// its name), whose angle unit goes where it is used.
    Number(&'a str, &'a Ident),
    /// A load or gravity value ("a torque"): a number in the definition's
    /// own units.
    Load(&'a str),
}

/// The message for the unit word `unit` written after a value, when there is
/// one to give.
fn unit_message(unit: &Ident, valued: Valued) -> Option<String> {
    let angle = unit == "deg" || unit == "rad";
    match valued {
        Valued::Nothing => None,
        Valued::Number(what, name) if angle => Some(format!(
            "unexpected `{unit}`: {what} takes no unit, it is a plain number; write the number alone, and the angle unit where `{name}` is used: `{name} {unit}` (e.g. `point(LINK, from A, d, {name} {unit})`)"
        )),
        Valued::Number(what, _) => Some(format!(
            "unexpected `{unit}`: {what} takes no unit, it is a plain number in the definition's own units (lengths, masses and forces carry none; only angles take `deg` or `rad`)"
        )),
        Valued::Load(what) => Some(format!(
            "unexpected `{unit}`: {what} takes no unit{}; loads are plain numbers in the definition's own consistent units (kg, m, s give N and N m; t, mm, s give N and N mm)",
            if angle { " (`deg` and `rad` are for angles)" } else { "" }
        )),
    }
}

/// The `;` that ends the statement begun at `start`. `what` names the
/// statement ("the `let B = rrr(..)` statement"). When the `;` is missing and
/// the next statement follows, the error is on the last token of this one;
/// when something else stands where the `;` goes, on that token; a unit word
/// after a value gets a message about units (`valued`).
fn end(input: ParseStream, start: Cursor, what: &str, valued: Valued) -> syn::Result<()> {
    if input.peek(Token![;]) {
        input.parse::<Token![;]>()?;
        return Ok(());
    }
    if input.is_empty() || starts_statement(input) {
        let span = last_token(start, input.cursor()).unwrap_or_else(|| input.span());
        return Err(syn::Error::new(
            span,
            format!("expected `;` after {what}: every statement ends with `;`"),
        ));
    }
    if let Some(message) = unit_word(input).and_then(|u| unit_message(&u, valued)) {
        return Err(input.error(message));
    }
    Err(input.error(format!(
        "expected `;` to end {what}, found `{}`",
        next_text(input)
    )))
}

/// A comma-separated list (a trailing comma allowed) filling `content`, whose
/// elements are parsed by `element`. `starts` tells whether the next tokens
/// begin an element (so a `,` before them is missing: the error is on the
/// last token of the previous element); otherwise a token other than `,`
/// stands there and the error is on it. `list` names the list ("the
/// arguments of `rrr(..)`"); `unit` gives the message for a unit word
/// written after an element, when there is one (see [`unit_message`]).
fn list<T>(
    content: ParseStream,
    list: &str,
    element: impl Fn(ParseStream) -> syn::Result<T>,
    starts: impl Fn(ParseStream) -> bool,
    unit: impl Fn(&T, &Ident) -> Option<String>,
) -> syn::Result<Vec<T>> {
    let mut out = Vec::new();
    while !content.is_empty() {
        let start = content.cursor();
        let item = element(content)?;
        let finish = content.cursor();
        if content.is_empty() {
            out.push(item);
            break;
        }
        if content.peek(Token![,]) {
            content.parse::<Token![,]>()?;
            out.push(item);
            continue;
        }
        let written = text(start, finish);
        if let Some(message) = unit_word(content).and_then(|u| unit(&item, &u)) {
            return Err(content.error(message));
        }
        if starts(content) {
            let span = last_token(start, finish).unwrap_or_else(|| content.span());
            return Err(syn::Error::new(
                span,
                format!(
                    "expected `,` after `{written}` in {list}: its entries are separated by commas"
                ),
            ));
        }
        return Err(content.error(format!(
            "expected `,` after `{written}` in {list}, found `{}`",
            next_text(content)
        )));
    }
    Ok(out)
}

/// `true` when the next token may begin an argument (a name, a number, a
/// sign or a parenthesis).
fn starts_arg(input: ParseStream) -> bool {
    input.peek(Ident)
        || input.peek(syn::Lit)
        || input.peek(Token![-])
        || input.peek(syn::token::Paren)
}

/// `true` when the next tokens begin `name = value`.
fn starts_assign(input: ParseStream) -> bool {
    input.peek(Ident) && input.peek2(Token![=])
}

impl Parse for Arg {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        if kw(input, "from") && input.peek2(Ident) {
            let _: Ident = input.parse()?;
            return Ok(Arg::From(input.parse()?));
        }
        let expr: Expr = input.parse()?;
        // A word after the value is its unit, unless it begins the next
        // `name = value` (a mass field whose `,` is missing) or is `from`.
        let unit = if input.peek(Ident) && !input.peek2(Token![=]) && !kw(input, "from") {
            Some(input.parse::<Ident>()?)
        } else {
            None
        };
        Ok(Arg::Value(expr, unit))
    }
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
    if !input.peek(syn::token::Brace) {
        return Err(input.error(format!(
            "expected `{{` after `{word}`: the entries go in braces, `{word} {{ a = 1.0, b = 2.0 }}`"
        )));
    }
    let content;
    braced!(content in input);
    let list_name = format!("`{word} {{ .. }}`");
    list(
        &content,
        &list_name,
        Assign::parse,
        starts_assign,
        |a: &Assign, u| {
            if word == "loads" {
                unit_message(u, Valued::Load(what))
            } else {
                unit_message(u, Valued::Number(what, &a.name))
            }
        },
    )
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

impl Parse for Item {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let start = input.cursor();
        if input.peek(Token![let]) {
            input.parse::<Token![let]>()?;
            let name: Ident = input.parse().map_err(|e| {
                syn::Error::new(
                    e.span(),
                    "expected the name this statement defines (a letter first): `let NAME = KIND(args);`",
                )
            })?;
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
                        crate::model::KINDS.join(", ")
                    ),
                )
            })?;
            if !input.peek(syn::token::Paren) {
                let usage = crate::model::usage(&kind.to_string());
                let usage = if usage.is_empty() {
                    String::new()
                } else {
                    format!(": `{usage}`")
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
            return Ok(Item::Let(Let {
                name,
                kind,
                args,
                args_span: paren.span.join(),
                links,
                slides,
            }));
        }
        if input.peek(Token![const]) {
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
            return Ok(Item::Const(assign));
        }
        let word: Ident = input.parse().map_err(|e| {
            syn::Error::new(
                e.span(),
                "expected a statement: `let`, `params`, `const`, `analysis`, `outputs`, `dof`, `loads`, `mass`, `gravity`, `force`, `torque`, `range` or `allow`",
            )
        })?;
        match word.to_string().as_str() {
            "params" => Ok(Item::Params(assignments(input, "params", "a parameter")?)),
            "loads" => Ok(Item::Loads(assignments(input, "loads", "a load value")?)),
            "analysis" => {
                let what: Ident = name_after(
                    input,
                    "analysis",
                    "the analysis",
                    "`analysis position;`, `velocity`, `acceleration` or `forces`",
                )?;
                end(
                    input,
                    start,
                    &format!("the `analysis {what}` statement"),
                    Valued::Nothing,
                )?;
                Ok(Item::Analysis(word.span(), what))
            }
            "outputs" => {
                if !input.peek(syn::token::Brace) {
                    return Err(input.error("expected `{`: the outputs are listed in braces, `outputs { B, link3 }`"));
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
            "dof" => {
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
            "mass" => {
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
                                format!("expected a field, `m`, `at` or `j`, found `{}`: {usage}", next_text(c)),
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
            "gravity" => {
                let (x, y) = pair(
                    input,
                    "`gravity (gx, gy);`",
                    Valued::Load("a gravity component"),
                )?;
                end(input, start, "the `gravity (..)` statement", Valued::Nothing)?;
                Ok(Item::Gravity(word.span(), x, y))
            }
            "force" => {
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
            "torque" => {
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
            "range" => {
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
            "allow" => {
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
                    let keyword_next = starts_statement(input)
                        && !(input.peek2(Token![;]) || input.peek2(Token![,]));
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
            other => Err(syn::Error::new(
                word.span(),
                format!(
                    "unknown statement `{other}`; expected `let`, `params`, `const`, `analysis`, `outputs`, `dof`, `loads`, `mass`, `gravity`, `force`, `torque`, `range` or `allow`{}",
                    crate::model::did_you_mean(other, STATEMENTS.iter().copied())
                ),
            )),
        }
    }
}

/// The most tokens one path through the input may hold: a run of tokens
/// between two `,` or `;` (a group counting as one token) plus the longest
/// such path inside any group of the run; and so also the deepest nesting of
/// brackets. Parsing an expression recurses at most once per token of such
/// a path (syn's parser, then the conversion, folding and emission of the
/// value), so this bounds the stack the macro uses. Measured in a debug build
/// (how rustc builds a proc macro) without the bound: parentheses nested 600
/// deep in one dimension expand in an 8 MiB thread (what rustc gives the
/// macro) and 700 overflow it (about 12 KiB a level); at this bound, every
/// kind of path expands in 2 MiB (`tests/front_edges.rs`). A real
/// definition's longest path is about 20 tokens.
pub const MAX_PATH: usize = 128;

/// Parses a whole definition. An error at the end of the input points at
/// its last token (rather than at the whole invocation).
pub fn definition(input: proc_macro2::TokenStream) -> syn::Result<Definition> {
    let last = input.clone().into_iter().last().map(|t| match t {
        TokenTree::Group(g) => g.span_close(),
        other => other.span(),
    });
    let Some(last) = last else {
        return syn::parse2(input);
    };
    // The content of a group reports its end at the closing delimiter.
    let mut group = proc_macro2::Group::new(Delimiter::Brace, input);
    group.set_span(last);
    syn::parse::Parser::parse2(
        |outer: ParseStream| {
            let content;
            braced!(content in outer);
            Definition::parse(&content)
        },
        TokenTree::Group(group).into(),
    )
}

/// The bound [`MAX_PATH`], checked on the whole input before it is parsed,
/// and, with `rules`, rules on single tokens of the body (every error
/// collected, each on its token; the head may hold `pub(crate)`).
#[derive(Default)]
struct Lexical {
    rules: bool,
    errors: Option<syn::Error>,
}

impl Lexical {
    fn push(&mut self, e: syn::Error) {
        match &mut self.errors {
            Some(all) => all.combine(e),
            None => self.errors = Some(e),
        }
    }

    /// `self`, `Self`, `super` and `crate` are the keywords that syn takes as
    /// a path where a name stands (`crank(O, r, self)`); none names anything
    /// in a definition, and the generated code could not use them as names.
    fn ident(&mut self, i: &Ident) {
        let word = i.to_string();
        if ["self", "Self", "super", "crate"].contains(&word.as_str()) {
            self.push(syn::Error::new(
                i.span(),
                format!("`{word}` is a Rust keyword and cannot name anything in a definition; choose another name, e.g. `{}_`", word.to_lowercase()),
            ));
        }
    }

    /// The longest path (see [`MAX_PATH`]) through `stream`, the content of
    /// a group opened at `open` at nesting `depth`.
    fn walk(
        &mut self,
        stream: proc_macro2::TokenStream,
        depth: usize,
        open: Span,
    ) -> syn::Result<usize> {
        let too_long = |what: &str| {
            format!("{what}: a definition allows paths of at most {MAX_PATH} tokens (a path is the tokens between two `,` or `;` plus the longest path inside their brackets); split the expression with `const` entries")
        };
        if depth > MAX_PATH {
            return Err(syn::Error::new(
                open,
                too_long(&format!("brackets nested more than {MAX_PATH} deep")),
            ));
        }
        let (mut longest, mut run, mut inner) = (0, 0, 0);
        let mut first: Option<TokenTree> = None;
        for tree in stream {
            match &tree {
                TokenTree::Punct(p) if matches!(p.as_char(), ',' | ';') => {
                    longest = longest.max(run + inner);
                    (run, inner, first) = (0, 0, None);
                    continue;
                }
                TokenTree::Group(g) => {
                    inner = inner.max(self.walk(g.stream(), depth + 1, g.span_open())?)
                }
                TokenTree::Ident(i) if self.rules => self.ident(i),
                TokenTree::Literal(l) if self.rules => {
                    if let Some(e) = crate::value::literal_form(&Lit::new(l.clone())) {
                        self.push(e);
                    }
                }
                _ => {}
            }
            run += 1;
            let first = first.get_or_insert_with(|| tree.clone()).clone();
            if run + inner > MAX_PATH {
                let tokens: proc_macro2::TokenStream = [first, tree].into_iter().collect();
                return Err(syn::Error::new_spanned(
                    tokens,
                    too_long("this is nested or chained too deep"),
                ));
            }
        }
        Ok(longest.max(run + inner))
    }
}

impl Parse for Definition {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let all: proc_macro2::TokenStream = input.fork().parse()?;
        Lexical::default().walk(all, 0, input.span())?;
        let mut docs = input.call(Attribute::parse_outer)?;
        let self_test = docs
            .iter()
            .find(|a| a.path().is_ident("self_test"))
            .map(syn::spanned::Spanned::span);
        if let Some(second) = docs
            .iter()
            .filter(|a| a.path().is_ident("self_test"))
            .nth(1)
        {
            return Err(syn::Error::new_spanned(
                second,
                "`#[self_test]` may appear once; remove this one",
            ));
        }
        docs.retain(|a| !a.path().is_ident("self_test"));
        if let Some(other) = docs.iter().find(|a| !a.path().is_ident("doc")) {
            let path = other.path();
            let word = quote::ToTokens::to_token_stream(path)
                .to_string()
                .replace(' ', "");
            return Err(syn::Error::new_spanned(
                other,
                format!(
                    "unknown attribute `#[{word}]`; a definition takes doc comments (`///`) and `#[self_test]`{}",
                    crate::model::did_you_mean(&word, ["self_test"])
                ),
            ));
        }
        let vis = input.parse()?;
        let name: Ident = input.parse().map_err(|e| {
            syn::Error::new(
                e.span(),
                "expected the mechanism's type name: `pub FourBar { ... }`",
            )
        })?;
        if !input.peek(syn::token::Brace) {
            return Err(input.error(format!(
                "expected `{{` after `{name}`, found `{}`: the statements go in braces, `{name} {{ let O = ground(0.0, 0.0); .. }}`",
                next_text(input)
            )));
        }
        let content;
        braced!(content in input);
        let mut lexical = Lexical {
            rules: true,
            errors: None,
        };
        lexical.walk(content.fork().parse()?, 1, content.span())?;
        if let Some(e) = lexical.errors {
            return Err(e);
        }
        let mut items = Vec::new();
        while !content.is_empty() {
            items.push(content.parse()?);
        }
        if !input.is_empty() {
            return Err(input.error(format!(
                "unexpected `{}` after the definition of `{name}`: a `mechanism!` holds one definition, and its statements go inside its braces",
                next_text(input)
            )));
        }
        Ok(Definition {
            docs,
            self_test,
            vis,
            name,
            items,
        })
    }
}
