//! Checks on the raw tokens before they are parsed: the longest path through
//! the input is bounded (so parsing cannot overflow the compiler's stack), and
//! in the body the keywords that cannot name anything and numbers written with
//! a suffix or in another base are errors on their tokens.

use proc_macro2::{Span, TokenTree};
use syn::{Ident, Lit};

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

/// The bound [`MAX_PATH`], checked on the whole input before it is parsed,
/// and, with `rules`, rules on single tokens of the body (every error
/// collected, each on its token; the head may hold `pub(crate)`).
#[derive(Default)]
pub(super) struct Lexical {
    pub(super) rules: bool,
    pub(super) errors: Option<syn::Error>,
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
    ///
    /// A raw identifier (`r#type`) is refused too: the generated code builds
    /// names from the user's (`r_<link>_<link>`, `vel_<point>`), and
    /// `r_r#type_link4` is no identifier (the macro panicked in `quote`;
    /// expand fuzzer, seed 1795706637983566365).
    fn ident(&mut self, i: &Ident) {
        let word = i.to_string();
        if let Some(plain) = word.strip_prefix("r#") {
            self.push(syn::Error::new(
                i.span(),
                format!("`{word}`: raw identifiers are not supported: the generated code builds its names from yours (`r_<link>_<link>`, `vel_<point>`), and `r#` cannot stand inside a name; choose another name, e.g. `{plain}_`"),
            ));
        } else if ["self", "Self", "super", "crate"].contains(&word.as_str()) {
            self.push(syn::Error::new(
                i.span(),
                format!("`{word}` is a Rust keyword and cannot name anything in a definition; choose another name, e.g. `{}_`", word.to_lowercase()),
            ));
        }
    }

    /// The longest path (see [`MAX_PATH`]) through `stream`, the content of
    /// a group opened at `open` at nesting `depth`.
    pub(super) fn walk(
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
