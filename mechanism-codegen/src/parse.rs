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

use proc_macro2::Span;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{braced, parenthesized, Attribute, Expr, Ident, LitInt, Token, Visibility};

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

fn kw(input: ParseStream, word: &str) -> bool {
    input.peek(Ident) && input.fork().parse::<Ident>().is_ok_and(|i| i == word)
}

impl Parse for Arg {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        if kw(input, "from") && input.peek2(Ident) {
            let _: Ident = input.parse()?;
            return Ok(Arg::From(input.parse()?));
        }
        let expr: Expr = input.parse()?;
        let unit = if input.peek(Ident) {
            Some(input.parse::<Ident>()?)
        } else {
            None
        };
        Ok(Arg::Value(expr, unit))
    }
}

fn names(input: ParseStream) -> syn::Result<Vec<Ident>> {
    if input.peek(syn::token::Paren) {
        let content;
        parenthesized!(content in input);
        let list = Punctuated::<Ident, Token![,]>::parse_terminated(&content)?;
        Ok(list.into_iter().collect())
    } else {
        Ok(vec![input.parse()?])
    }
}

fn input_eq(input: ParseStream) -> syn::Result<()> {
    input
        .parse::<Token![=]>()
        .map(|_| ())
        .map_err(|e| syn::Error::new(e.span(), "expected `=`: `range INPUT = (lo, hi);`"))
}

/// `(x, y)`: two components; `usage` shows the whole statement.
fn pair(input: ParseStream, usage: &str) -> syn::Result<(Expr, Expr)> {
    let two = |span| syn::Error::new(span, format!("expected two components: {usage}"));
    if !input.peek(syn::token::Paren) {
        return Err(two(input.span()));
    }
    let content;
    parenthesized!(content in input);
    let x: Expr = content.parse()?;
    content.parse::<Token![,]>().map_err(|e| two(e.span()))?;
    let y: Expr = content.parse()?;
    if !content.is_empty() {
        return Err(two(content.span()));
    }
    Ok((x, y))
}

impl Parse for Assign {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let name: Ident = input.parse()?;
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

impl Parse for Item {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        if input.peek(Token![let]) {
            input.parse::<Token![let]>()?;
            let name: Ident = input.parse().map_err(|e| {
                syn::Error::new(
                    e.span(),
                    "expected the name this statement defines (a letter first): `let NAME = KIND(args);`",
                )
            })?;
            input.parse::<Token![=]>()?;
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
            let content;
            let paren = parenthesized!(content in input);
            let args = Punctuated::<Arg, Token![,]>::parse_terminated(&content)?
                .into_iter()
                .collect();
            let mut links = Vec::new();
            if input.peek(Token![as]) {
                input.parse::<Token![as]>()?;
                links = names(input)?;
            }
            let mut slides = Vec::new();
            if kw(input, "slide") {
                let _: Ident = input.parse()?;
                slides = names(input)?;
            }
            input.parse::<Token![;]>().map_err(|e| {
                syn::Error::new(
                    e.span(),
                    format!(
                        "expected `;` to end the statement `let {name} = {kind}(..)`{}",
                        if links.is_empty() {
                            " (or `as LINK` to name its link)"
                        } else {
                            ""
                        }
                    ),
                )
            })?;
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
            let assign = input.parse()?;
            input.parse::<Token![;]>()?;
            return Ok(Item::Const(assign));
        }
        let word: Ident = input.parse().map_err(|e| {
            syn::Error::new(
                e.span(),
                "expected a statement: `let`, `params`, `const`, `analysis`, `outputs`, `dof`, `loads`, `mass`, `gravity`, `force`, `torque`, `range` or `allow`",
            )
        })?;
        match word.to_string().as_str() {
            "params" => {
                let content;
                braced!(content in input);
                let list = Punctuated::<Assign, Token![,]>::parse_terminated(&content)?;
                Ok(Item::Params(list.into_iter().collect()))
            }
            "loads" => {
                let content;
                braced!(content in input);
                let list = Punctuated::<Assign, Token![,]>::parse_terminated(&content)?;
                Ok(Item::Loads(list.into_iter().collect()))
            }
            "analysis" => {
                let what = input.parse()?;
                input.parse::<Token![;]>()?;
                Ok(Item::Analysis(word.span(), what))
            }
            "outputs" => {
                if !input.peek(syn::token::Brace) {
                    return Err(input.error("expected `{`: the outputs are listed in braces, `outputs { B, link3 }`"));
                }
                let content;
                braced!(content in input);
                let list = Punctuated::<Ident, Token![,]>::parse_terminated(&content)?;
                Ok(Item::Outputs(word.span(), list.into_iter().collect()))
            }
            "dof" => {
                let n = input.parse()?;
                input.parse::<Token![;]>()?;
                Ok(Item::Dof(word.span(), n))
            }
            "mass" => {
                let link = input.parse()?;
                let content;
                braced!(content in input);
                let mut fields = Vec::new();
                while !content.is_empty() {
                    let name: Ident = content.parse()?;
                    content.parse::<Token![=]>()?;
                    fields.push((name, content.parse()?));
                    if content.is_empty() {
                        break;
                    }
                    content.parse::<Token![,]>()?;
                }
                if input.peek(Token![;]) {
                    input.parse::<Token![;]>()?;
                }
                Ok(Item::Mass(Mass { link, fields }))
            }
            "gravity" => {
                let (x, y) = pair(input, "`gravity (gx, gy);`")?;
                input.parse::<Token![;]>()?;
                Ok(Item::Gravity(word.span(), x, y))
            }
            "force" => {
                if !kw(input, "at") {
                    return Err(input.error("expected `at`: `force at POINT = (fx, fy);`"));
                }
                let _: Ident = input.parse()?;
                let at = input.parse()?;
                let mut on = None;
                if kw(input, "on") {
                    let _: Ident = input.parse()?;
                    on = Some(input.parse()?);
                }
                let value = if kw(input, "along") {
                    let _: Ident = input.parse()?;
                    let guide = input.parse()?;
                    input.parse::<Token![=]>()?;
                    ForceValue::Along(guide, input.parse()?)
                } else {
                    input.parse::<Token![=]>().map_err(|e| {
                        syn::Error::new(
                            e.span(),
                            "expected `= (fx, fy)`, `on LINK` or `along GUIDE = f`",
                        )
                    })?;
                    let (x, y) = pair(input, "`force at POINT = (fx, fy);`")?;
                    ForceValue::Components(x, y)
                };
                input.parse::<Token![;]>()?;
                Ok(Item::Force(Force { at, on, value }))
            }
            "torque" => {
                if !kw(input, "on") {
                    return Err(input.error("expected `on`: `torque on LINK = value;`"));
                }
                let _: Ident = input.parse()?;
                let on = input.parse()?;
                input.parse::<Token![=]>()?;
                let value = input.parse()?;
                input.parse::<Token![;]>()?;
                Ok(Item::Torque(on, value))
            }
            "range" => {
                let name = input.parse()?;
                input_eq(input)?;
                let content;
                parenthesized!(content in input);
                let lo = content.parse()?;
                content.parse::<Token![,]>()?;
                let hi = content.parse()?;
                if !content.is_empty() {
                    return Err(content.error("a range is `(lo, hi)`: two values"));
                }
                input.parse::<Token![;]>()?;
                Ok(Item::Range(RangeDecl {
                    input: name,
                    lo,
                    hi,
                }))
            }
            "allow" => {
                let what = input.parse()?;
                let mut groups = Vec::new();
                while !input.peek(Token![;]) {
                    groups.push(input.parse()?);
                    if input.peek(Token![,]) {
                        input.parse::<Token![,]>()?;
                    }
                }
                input.parse::<Token![;]>()?;
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

impl Parse for Definition {
    fn parse(input: ParseStream) -> syn::Result<Self> {
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
        let name = input.parse().map_err(|e| {
            syn::Error::new(
                e.span(),
                "expected the mechanism's type name: `pub FourBar { ... }`",
            )
        })?;
        let content;
        braced!(content in input);
        let mut items = Vec::new();
        while !content.is_empty() {
            items.push(content.parse()?);
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
