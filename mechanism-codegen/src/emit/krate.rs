//! `#[mechanism(crate = PATH)]`: the generated code names the facade as
//! `::mechanism` everywhere; for a dependency renamed in Cargo.toml (`pm =
//! { package = "planar-mechanism" }`) the last step of the expansion turns
//! every leading `::mechanism` of a path into `PATH`, and the path strings
//! of serde's `crate = ".."` with it. One place, after every emitter, so
//! that no emitter needs to know.

use proc_macro2::{Group, Literal, Spacing, TokenStream, TokenTree};
use quote::ToTokens;

/// `code` with every path beginning `::mechanism` beginning `krate`
/// instead: the tokens `:: mechanism` where the `::` does not follow a name
/// (`a::mechanism` is left alone), and string literals that begin with
/// `::mechanism::`.
pub fn rename(code: TokenStream, krate: &syn::Path) -> TokenStream {
    let with = krate.to_token_stream();
    let text = with.to_string().replace(' ', "");
    walk(code, &with, &text)
}

fn walk(code: TokenStream, with: &TokenStream, text: &str) -> TokenStream {
    let tokens: Vec<TokenTree> = code.into_iter().collect();
    let mut out: Vec<TokenTree> = Vec::with_capacity(tokens.len());
    let mut i = 0;
    while i < tokens.len() {
        if starts_facade_path(&tokens, i) {
            out.extend(with.clone());
            i += 3;
            continue;
        }
        match &tokens[i] {
            TokenTree::Group(g) => {
                let mut inner = Group::new(g.delimiter(), walk(g.stream(), with, text));
                inner.set_span(g.span());
                out.push(TokenTree::Group(inner));
            }
            TokenTree::Literal(l) => out.push(TokenTree::Literal(literal(l, text))),
            t => out.push(t.clone()),
        }
        i += 1;
    }
    out.into_iter().collect()
}

/// Whether `tokens[i..]` is `:: mechanism` beginning a path: not after a
/// name or a `>` (the end of a path segment or of generic arguments).
fn starts_facade_path(tokens: &[TokenTree], i: usize) -> bool {
    let colon = |t: Option<&TokenTree>, spacing: Spacing| matches!(t, Some(TokenTree::Punct(p)) if p.as_char() == ':' && p.spacing() == spacing);
    let named = matches!(tokens.get(i + 2), Some(TokenTree::Ident(n)) if n == "mechanism");
    let after_segment = i > 0
        && match &tokens[i - 1] {
            TokenTree::Ident(_) => true,
            // `>` closing generic arguments, not the end of `->` or `=>`.
            TokenTree::Punct(p) => {
                p.as_char() == '>'
                    && !matches!(tokens.get(i.wrapping_sub(2)), Some(TokenTree::Punct(q))
                        if (q.as_char() == '-' || q.as_char() == '=') && q.spacing() == Spacing::Joint)
            }
            TokenTree::Group(_) | TokenTree::Literal(_) => false,
        };
    colon(tokens.get(i), Spacing::Joint)
        && colon(tokens.get(i + 1), Spacing::Alone)
        && named
        && !after_segment
}

/// A string literal naming a path under `::mechanism::` (serde's `crate =
/// ".."`), renamed; any other literal as it is.
fn literal(l: &Literal, text: &str) -> Literal {
    let written = l.to_string();
    let Some(rest) = written.strip_prefix("\"::mechanism::") else {
        return l.clone();
    };
    let mut renamed = Literal::string(&format!("{text}::{}", rest.trim_end_matches('"')));
    renamed.set_span(l.span());
    renamed
}

#[cfg(test)]
mod tests {
    use proc_macro2::TokenStream;
    use std::str::FromStr;

    // Proves the renaming turns each leading `::mechanism` (in nested
    // groups, in serde's path string) into the given path, and leaves
    // `a::mechanism` and other names alone.
    #[test]
    fn leading_facade_paths_take_the_given_path() {
        let code = TokenStream::from_str(
            r#"fn f() -> ::mechanism::Mode { let x: Vec<::mechanism::Real> = a::mechanism::b(::core::f64::MAX); match x { _ => ::mechanism::f() }; #[serde(crate = "::mechanism::__interop::serde")] struct S; }"#,
        )
        .unwrap();
        let path: syn::Path = syn::parse_str("pm").unwrap();
        let out = super::rename(code, &path).to_string().replace(' ', "");
        assert_eq!(
            out,
            r#"fnf()->pm::Mode{letx:Vec<pm::Real>=a::mechanism::b(::core::f64::MAX);matchx{_=>pm::f()};#[serde(crate="pm::__interop::serde")]structS;}"#
        );
    }
}
