//! A definition read from text: the tokens of what goes between the braces
//! of `mechanism! { ... }` (or the whole `pub Name { ... }` item), and its
//! diagnostics with line and column in that text, shown as rustc shows them.

use proc_macro2::{Delimiter, Group, Span, TokenStream, TokenTree};
use quote::quote;
use std::fmt;

/// One error of a definition, where the text says it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    /// The message, as the macro reports it.
    pub message: String,
    /// Line of the first character it blames (1-based; 0: the definition
    /// as a whole, no place in the text).
    pub line: usize,
    /// Column of that character (0-based, in characters).
    pub column: usize,
    /// Line of the last character it blames (1-based).
    pub end_line: usize,
    /// Column just after the last character it blames (0-based).
    pub end_column: usize,
}

impl Diagnostic {
    /// The diagnostic of one `syn` error.
    fn of(e: &syn::Error) -> Self {
        let span = e.span();
        let (start, end) = (span.start(), span.end());
        Diagnostic {
            message: e.to_string(),
            line: start.line,
            column: start.column,
            end_line: end.line,
            end_column: end.column,
        }
    }
}

/// Every error of a definition read from text, with the text, so that
/// they can be shown as rustc shows them ([`fmt::Display`], under the file
/// name `file`).
#[derive(Clone, Debug)]
pub struct Errors {
    /// The definition's text.
    pub source: String,
    /// The file it came from, for the ` --> FILE:LINE:COL` lines.
    pub file: String,
    /// The errors, in the order of the text.
    pub diagnostics: Vec<Diagnostic>,
}

impl Errors {
    /// The errors `errors` (from the stages) of `source`.
    pub(crate) fn new(source: &str, errors: Vec<syn::Error>) -> Self {
        Errors {
            source: source.to_string(),
            file: "<definition>".into(),
            diagnostics: errors
                .iter()
                .flat_map(|e| e.clone().into_iter())
                .map(|e| Diagnostic::of(&e))
                .collect(),
        }
    }

    /// The same errors shown under the file name `file`.
    #[must_use]
    pub fn in_file(mut self, file: &str) -> Self {
        self.file = file.to_string();
        self
    }
}

impl fmt::Display for Errors {
    /// rustc's layout: `error: MESSAGE`, ` --> FILE:LINE:COL`, the line of
    /// the text with the blamed characters underlined by `^`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let lines: Vec<&str> = self.source.lines().collect();
        for d in &self.diagnostics {
            writeln!(f, "error: {}", d.message)?;
            let Some(text) = d.line.checked_sub(1).and_then(|l| lines.get(l)) else {
                writeln!(f, " --> {}", self.file)?;
                writeln!(f)?;
                continue;
            };
            let number = d.line.to_string();
            let pad = " ".repeat(number.len());
            writeln!(f, "{pad}--> {}:{}:{}", self.file, d.line, d.column + 1)?;
            writeln!(f, "{pad} |")?;
            writeln!(f, "{number} | {text}")?;
            let width = text.chars().count();
            let end = if d.end_line == d.line {
                d.end_column.min(width)
            } else {
                width
            };
            let carets = end.saturating_sub(d.column).max(1);
            let lead: String = text
                .chars()
                .take(d.column)
                .map(|c| if c == '\t' { '\t' } else { ' ' })
                .collect();
            writeln!(f, "{pad} | {lead}{}", "^".repeat(carets))?;
            writeln!(f)?;
        }
        let n = self.diagnostics.len();
        write!(
            f,
            "error: could not read the definition due to {n} previous error{}",
            if n == 1 { "" } else { "s" }
        )
    }
}

/// The tokens of `text` as the macro's input: the `pub Name { ... }` item
/// when the text is one (attributes, an optional visibility, a name and a
/// braced body, nothing after), else the text as the body of `pub
/// Mechanism { ... }`. Spans keep their line and column in `text`.
pub(crate) fn tokens(text: &str) -> Result<TokenStream, syn::Error> {
    let body: TokenStream = text.parse().map_err(|e: proc_macro2::LexError| {
        syn::Error::new(e.span(), format!("cannot read the text: {e}"))
    })?;
    if is_item(&body) {
        return Ok(body);
    }
    let trees: Vec<TokenTree> = body.clone().into_iter().collect();
    let span = match (trees.first(), trees.last()) {
        (Some(a), Some(b)) => a.span().join(b.span()).unwrap_or_else(|| b.span()),
        _ => Span::call_site(),
    };
    let mut group = Group::new(Delimiter::Brace, body);
    group.set_span(span);
    let name = syn::Ident::new("Mechanism", span);
    Ok(quote!(pub #name #group))
}

/// `true` when `text` is a whole item (`pub Name { ... }`), `false` for a
/// body (or text that does not read as tokens).
pub fn is_item_text(text: &str) -> bool {
    text.parse::<TokenStream>().is_ok_and(|t| is_item(&t))
}

/// Statement words of a body that are followed by a braced block: a body
/// of one such statement is not an item.
const BLOCK_WORDS: [&str; 6] = ["let", "params", "joints", "links", "loads", "masses"];

/// `true` for `#[..]* [pub [(..)]] NAME { .. }`.
fn is_item(tokens: &TokenStream) -> bool {
    let trees: Vec<TokenTree> = tokens.clone().into_iter().collect();
    let mut i = 0;
    // Attributes (doc comments included): `#` then `[..]`.
    while matches!(trees.get(i), Some(TokenTree::Punct(p)) if p.as_char() == '#') {
        if !matches!(trees.get(i + 1), Some(TokenTree::Group(g)) if g.delimiter() == Delimiter::Bracket)
        {
            return false;
        }
        i += 2;
    }
    if matches!(trees.get(i), Some(TokenTree::Ident(id)) if id == "pub") {
        i += 1;
        if matches!(trees.get(i), Some(TokenTree::Group(g)) if g.delimiter() == Delimiter::Parenthesis)
        {
            i += 1;
        }
    }
    let named =
        matches!(trees.get(i), Some(TokenTree::Ident(id)) if !BLOCK_WORDS.iter().any(|w| id == w));
    let braced =
        matches!(trees.get(i + 1), Some(TokenTree::Group(g)) if g.delimiter() == Delimiter::Brace);
    named && braced && trees.len() == i + 2
}
