//! Stage 1, parse: the token stream of `mechanism! { ... }` into a syntax tree
//! that keeps every user token (for spans). No meaning is given here.
//!
//! Grammar (see `docs/dsl.md` for the reference with examples):
//!
//! ```text
//! definition := (outer-doc | '#[self_test]' | derive)* vis? IDENT '{' item* '}'
//! derive     := '#[derive(' PATH,* ')]' | '#[cfg_attr(' META ',' derive,* ')]'
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
//!             | 'units' '{' (IDENT '=' STRING),* '}'
//! arg        := 'from' IDENT | expr ('deg' | 'rad')?
//! links      := IDENT | '(' IDENT,* ')'
//! names      := IDENT | '(' IDENT,* ')'
//! ```

pub mod attrs;
mod lexical;
mod statements;
pub mod vocabulary;

pub use attrs::{Derive, DeriveKind};
use lexical::Lexical;
pub use lexical::MAX_PATH;

use proc_macro2::{Delimiter, Span, TokenTree};
use syn::buffer::Cursor;
use syn::parse::{Parse, ParseStream};
use syn::{braced, Attribute, Expr, Ident, LitInt, Token, Visibility};

/// A whole definition.
pub struct Definition {
    /// Outer doc comments, copied onto the generated type.
    pub docs: Vec<Attribute>,
    /// `#[self_test]`: the attribute's span, when given.
    pub self_test: Option<Span>,
    /// `#[derive(..)]`s (also inside `#[cfg_attr(..)]`), passed on to the
    /// generated types.
    pub derives: Vec<Derive>,
    /// `#[mechanism(crate = PATH)]`: the facade's path for a renamed
    /// dependency (`None`: `::mechanism`).
    pub krate: Option<syn::Path>,
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
    /// `motor q1 = angle(arm1);` or `motor knee = angle(shank, thigh);`: a
    /// motor of an inverse-kinematics definition (its torque is what holds
    /// the target): its name, its link and the link carrying it.
    Motor(Ident, Ident, Option<Ident>),
    /// `range theta2 = (-40 deg, 40 deg);`: the input range to check.
    Range(RangeDecl),
    /// `allow singular;` / `allow singular B, C;`: the `allow` keyword's
    /// span, what is allowed, and the groups (empty: all).
    Allow(Span, Ident, Vec<Ident>),
    /// The drawn form: `joints { A = (x, y), .. }`, the joints where the
    /// drawing (the reference pose) has them, with the keyword's span.
    Joints(Span, Vec<Assign>),
    /// The drawn form: `links { ground = [O2, O4], crank = [O2, A], .. }`,
    /// each link the set of joints it has, with the keyword's span.
    Links(Span, Vec<Assign>),
    /// The drawn form: `input theta = angle(crank);` (a link's angle from
    /// the ground) or `input knee = angle(shank, thigh);` (from another
    /// link): the input's name and what it measures.
    Input(Ident, Expr),
    /// The drawn form: `slider BLOCK at J on LINK along ANGLE;`, a block
    /// pinned at joint `J` sliding on the ground (or in a slot of `LINK`)
    /// along a line through `J`'s drawn place.
    Slider(DrawnSlider),
    /// The drawn form: `cylinder CYL from B to C;` (or `cylinder (BARREL,
    /// ROD) from B to C;`), a linear actuator pinned at joints `B` and `C`.
    Cylinder(DrawnCylinder),
    /// The drawn form: `gear LINK to MESH ratio R;` (optionally `on
    /// CARRIER`, `pressure ANGLE`), a gear pair between two links pivoted
    /// on a common link, its phase read from the drawing.
    Gear(DrawnGear),
    /// The drawn form: `mode elbow = assembly(C);`, a run-time assembly
    /// mode parameter (`elbow`) read by the group that places the joint (or
    /// slides the block) `C`, its default the drawing's assembly.
    Mode(Ident, Ident),
    /// `units { length = "mm", force = "N" }`: the names of the
    /// definition's units, for labels (read in `model::units`), with the
    /// keyword's span.
    Units(Span, Vec<Assign>),
}

/// `cylinder CYL from B to C;` of the drawn form.
pub struct DrawnCylinder {
    /// The cylinder as one link, or its barrel and its rod.
    pub names: Vec<Ident>,
    /// The joint its barrel is pinned at.
    pub from: Ident,
    /// The joint its rod is pinned at.
    pub to: Ident,
}

/// `gear LINK to MESH ratio R [on CARRIER] [pressure ANGLE];` of the drawn
/// form.
pub struct DrawnGear {
    /// The gear's link, turning about its joint on the carrier.
    pub link: Ident,
    /// The link it meshes with (`ground`: a fixed gear).
    pub mesh: Ident,
    /// `MESH`'s pitch radius over `LINK`'s (negative: an internal pair).
    pub ratio: Expr,
    /// The common link both gears turn on (`None`: the ground).
    pub carrier: Option<Ident>,
    /// The pressure angle with its unit (`None`: the kind's default).
    pub pressure: Option<(Expr, Option<Ident>)>,
}

/// `slider BLOCK at J on CARRIER along angle;` of the drawn form.
pub struct DrawnSlider {
    /// The block (a link of its own).
    pub block: Ident,
    /// The joint it is pinned at.
    pub at: Ident,
    /// What it slides on (`ground`, a moving link, or another block).
    pub on: Ident,
    /// The direction of the line, with its unit (`deg`, `rad`, none: rad).
    pub angle: Expr,
    pub unit: Option<Ident>,
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
    /// The other joints a `let (A, B, P) = triad(..)` defines (`B`, `P`);
    /// empty for every other statement.
    pub joints: Vec<Ident>,
    /// The statement kind as written (`ground`, `crank`, `rrr`, ...).
    pub kind: Ident,
    /// The kind it names, `None` for a word the language does not know
    /// (reported when the statement is lowered).
    pub word: Option<vocabulary::KindWord>,
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
    "params", "analysis", "outputs", "dof", "loads", "mass", "gravity", "force", "torque", "motor",
    "range", "allow", "joints", "links", "input", "slider", "cylinder", "gear", "units", "mode",
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

impl Parse for Definition {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let all: proc_macro2::TokenStream = input.fork().parse()?;
        Lexical::default().walk(all, 0, input.span())?;
        let attrs::Attrs {
            docs,
            self_test,
            derives,
            krate,
        } = attrs::sort(input.call(Attribute::parse_outer)?)?;
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
            derives,
            krate,
            vis,
            name,
            items,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The definition `src` parsed.
    fn parse(src: &str) -> syn::Result<Definition> {
        syn::parse_str::<Definition>(src)
    }

    /// The error `src` gets: its message and where it starts (line, column
    /// from 0).
    fn error(src: &str) -> (String, usize, usize) {
        let Err(e) = parse(src) else {
            panic!("`{src}` parsed");
        };
        let start = e.span().start();
        (e.to_string(), start.line, start.column)
    }

    /// The text of a parsed expression.
    fn show(e: &Expr) -> String {
        quote::ToTokens::to_token_stream(e).to_string()
    }

    #[test]
    fn a_let_statement_becomes_its_syntax_node() {
        // Proves a `let` keeps its name, kind, arguments in order (a name, a
        // number, `from`, a value with its unit), and the names after `as` and
        // `slide`.
        let def = parse(
            "pub M {
                let B = rrp(A, 2.5, line, plus, -0.5) as (rod, ram) slide x;
                let P = point(link3, from A, 1.0, 30 deg);
            }",
        )
        .unwrap();
        assert_eq!(def.name, "M");
        assert_eq!(def.items.len(), 2);
        let Item::Let(l) = &def.items[0] else {
            panic!("not a let");
        };
        assert_eq!(
            (l.name.to_string(), l.kind.to_string()),
            ("B".into(), "rrp".into())
        );
        let args: Vec<String> = l
            .args
            .iter()
            .map(|a| match a {
                Arg::From(i) => format!("from {i}"),
                Arg::Value(e, None) => show(e),
                Arg::Value(e, Some(u)) => format!("{} {u}", show(e)),
            })
            .collect();
        assert_eq!(args, ["A", "2.5", "line", "plus", "- 0.5"]);
        assert_eq!(l.links, ["rod", "ram"]);
        assert_eq!(l.slides, ["x"]);
        let Item::Let(p) = &def.items[1] else {
            panic!("not a let");
        };
        assert!(matches!(&p.args[1], Arg::From(a) if a == "A"));
        assert!(matches!(&p.args[3], Arg::Value(e, Some(u)) if show(e) == "30" && u == "deg"));
        assert!(p.links.is_empty() && p.slides.is_empty());
    }

    #[test]
    fn load_statements_become_their_syntax_nodes() {
        // Proves the load statements keep their parts: a force's point, link and
        // guide with its value, a torque's link, a mass's fields (its `;` left
        // out), and gravity's two components.
        let def = parse(
            "pub M {
                force at E on link4 along ram = -cut;
                force at C = (1.0, 2.0);
                torque on link2 = 3.0;
                mass link3 { m = 2.0, at = G, j = 0.5 }
                gravity (0.0, -9.81);
            }",
        )
        .unwrap();
        let [Item::Force(along), Item::Force(xy), Item::Torque(on, t), Item::Mass(m), Item::Gravity(_, gx, gy)] =
            def.items.as_slice()
        else {
            panic!("statements of other kinds");
        };
        assert_eq!(along.at, "E");
        assert_eq!(along.on.as_ref().unwrap(), "link4");
        assert!(
            matches!(&along.value, ForceValue::Along(g, f) if g == "ram" && show(f) == "- cut")
        );
        assert!(xy.on.is_none());
        assert!(
            matches!(&xy.value, ForceValue::Components(x, y) if show(x) == "1.0" && show(y) == "2.0")
        );
        assert_eq!((on.to_string(), show(t)), ("link2".into(), "3.0".into()));
        assert_eq!(m.link, "link3");
        let fields: Vec<String> = m.fields.iter().map(|(n, _)| n.to_string()).collect();
        assert_eq!(fields, ["m", "at", "j"]);
        assert_eq!((show(gx), show(gy)), ("0.0".into(), "- 9.81".into()));
    }

    #[test]
    fn declarations_become_their_syntax_nodes() {
        // Proves the one-line statements: a range's two ends with their units,
        // `allow` with its groups (one named like a keyword), `dof`, `analysis`,
        // `outputs`, `params` and `const`, and `#[self_test]` taken out of the docs.
        let def = parse(
            "/// A doc.
            #[self_test]
            pub M {
                params { a = 1.0, b = 2.0 }
                const c = 3.0;
                range theta = (-40 deg, 40 deg);
                allow singular B, range;
                dof 1;
                analysis velocity;
                outputs { B, link3 }
            }",
        )
        .unwrap();
        assert!(def.self_test.is_some());
        assert_eq!(def.docs.len(), 1);
        let [Item::Params(params), Item::Const(c), Item::Range(r), Item::Allow(_, what, groups), Item::Dof(_, n), Item::Analysis(_, level), Item::Outputs(_, outputs)] =
            def.items.as_slice()
        else {
            panic!("statements of other kinds");
        };
        let params: Vec<String> = params
            .iter()
            .map(|a| format!("{} = {}", a.name, show(&a.value)))
            .collect();
        assert_eq!(params, ["a = 1.0", "b = 2.0"]);
        assert_eq!(
            (c.name.to_string(), show(&c.value)),
            ("c".into(), "3.0".into())
        );
        assert_eq!(r.input, "theta");
        assert!(matches!(&r.lo, Arg::Value(e, Some(u)) if show(e) == "- 40" && u == "deg"));
        assert!(matches!(&r.hi, Arg::Value(e, Some(u)) if show(e) == "40" && u == "deg"));
        assert_eq!(what, "singular");
        assert_eq!(groups, &["B", "range"]);
        assert_eq!(n.base10_digits(), "1");
        assert_eq!(level, "velocity");
        assert_eq!(outputs, &["B", "link3"]);
    }

    #[test]
    fn a_missing_semicolon_is_reported_after_the_statement() {
        // Proves a missing `;` is reported on the last token of the statement
        // that lacks it (the `)` of `ground(..)`, line 2), not on the next one.
        let (message, line, column) = error(
            "pub M {
                let O = ground(0.0, 0.0)
                let A = crank(O, 1.0, theta) as link2;
            }",
        );
        assert_eq!(
            message,
            "expected `;` after the `let O = ground(..)` statement: every statement ends with `;`"
        );
        assert_eq!((line, column), (2, 39));
    }

    #[test]
    fn malformed_statements_get_their_messages() {
        // Proves a unit written after a constant gets the message about units,
        // on the unit word, and a misspelt keyword the nearest statement.
        let (message, line, column) = error("pub M { const d = 2.0 mm; }");
        assert_eq!(
            message,
            "unexpected `mm`: a constant takes no unit, it is a plain number in the definition's own units (lengths, masses and forces carry none; only angles take `deg` or `rad`)"
        );
        assert_eq!((line, column), (1, 22));
        let (message, _, column) = error("pub M { forse at E = (1.0, 0.0); }");
        assert_eq!(
            message,
            "unknown statement `forse`; expected `let`, `const`, `params`, `analysis`, `outputs`, `dof`, `loads`, `mass`, `gravity`, `force`, `torque`, `motor`, `range`, `allow`, `joints`, `links`, `input`, `slider`, `cylinder`, `gear`, `units` or `mode`; did you mean `force`?"
        );
        assert_eq!(column, 8);
        // A drawn gear without `ratio`: the message names both links.
        let (message, _, column) = error("pub M { gear link5 to link2 2.0; }");
        assert_eq!(
            message,
            "expected `ratio` and the pitch radius of `link2`'s gear over `link5`'s: `gear link5 to link2 ratio 2.0;` or `gear planet to ground ratio 1.5 on arm pressure 20 deg;`"
        );
        assert_eq!(column, 28);
    }
}
