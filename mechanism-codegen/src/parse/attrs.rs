//! The attributes written on a definition: doc comments, `#[self_test]`, and
//! the derives that pass through to the generated types
//! (`#[derive(serde::Serialize)]`, `#[cfg_attr(feature = "x", derive(..))]`).
//! Anything else is an error on the attribute, naming what to write instead.

use proc_macro2::{Span, TokenStream};
use quote::{quote, ToTokens};
use syn::punctuated::Punctuated;
use syn::spanned::Spanned;
use syn::{Attribute, Meta, Path, Token};

/// What a derive written on a definition asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DeriveKind {
    /// `Serialize` (any path ending so): generated `Serialize` impls over the
    /// user's fields of every public data type.
    Serialize,
    /// `Deserialize`: generated `Deserialize` impls for the types that hold
    /// only the user's values (the mechanism's parameters, inputs, loads).
    Deserialize,
    /// Any other derive: passed through onto the mechanism's struct and its
    /// inputs struct (every field of those is the user's).
    Other,
}

/// One derive of a definition.
#[derive(Clone)]
pub struct Derive {
    /// The derive's path as written (its span is the user's token).
    pub path: Path,
    /// What it asks for.
    pub kind: DeriveKind,
    /// The `cfg` predicate of the `cfg_attr` it came in (nested ones joined
    /// with `all(..)`), `None` for a plain `#[derive(..)]`.
    pub cfg: Option<TokenStream>,
}

impl Derive {
    /// The `#[cfg(..)]` attribute that gates what this derive generates
    /// (empty without a predicate).
    pub fn cfg_attr(&self) -> TokenStream {
        match &self.cfg {
            Some(pred) => quote!(#[cfg(#pred)]),
            None => TokenStream::new(),
        }
    }

    /// The derive as an attribute on a generated struct: `#[derive(PATH)]`,
    /// or `#[cfg_attr(PRED, derive(PATH))]`.
    pub fn attribute(&self) -> TokenStream {
        let path = &self.path;
        match &self.cfg {
            Some(pred) => quote!(#[cfg_attr(#pred, derive(#path))]),
            None => quote!(#[derive(#path)]),
        }
    }
}

/// The attributes of a definition, sorted out.
pub struct Attrs {
    /// Doc comments, in order.
    pub docs: Vec<Attribute>,
    /// The span of `#[self_test]`, when given.
    pub self_test: Option<Span>,
    /// The derives, in order.
    pub derives: Vec<Derive>,
    /// `#[mechanism(crate = PATH)]`: the path the generated code names the
    /// facade by, for a dependency renamed in Cargo.toml (`None`:
    /// `::mechanism`).
    pub krate: Option<Path>,
}

/// What a definition accepts, for the messages.
const ACCEPTED: &str = "a definition takes doc comments (`///`), `#[self_test]`, `#[derive(..)]`, `#[cfg_attr(PREDICATE, derive(..))]` and `#[mechanism(crate = PATH)]`";

/// A doc attribute as `///` writes it: `#[doc = "text"]`. Anything else
/// (`#[doc = - "text"]`, `#[doc(hidden)]`) would be copied onto the
/// generated items and fail there; it is an error on its tokens here.
fn doc_is_text(attr: &Attribute) -> syn::Result<()> {
    match &attr.meta {
        Meta::NameValue(nv)
            if matches!(
                &nv.value,
                syn::Expr::Lit(syn::ExprLit {
                    lit: syn::Lit::Str(_),
                    ..
                })
            ) =>
        {
            Ok(())
        }
        _ => Err(syn::Error::new_spanned(
            &attr.meta,
            "a doc comment on a definition is text: write `/// text` (or `#[doc = \"text\"]`)",
        )),
    }
}

/// Sorts the outer attributes of a definition; the first bad one is an error
/// on its tokens.
pub fn sort(attrs: Vec<Attribute>) -> syn::Result<Attrs> {
    let mut out = Attrs {
        docs: Vec::new(),
        self_test: None,
        derives: Vec::new(),
        krate: None,
    };
    for attr in attrs {
        let path = attr.path();
        if path.is_ident("doc") {
            doc_is_text(&attr)?;
            out.docs.push(attr);
        } else if path.is_ident("self_test") {
            if out.self_test.is_some() {
                return Err(syn::Error::new_spanned(
                    attr,
                    "`#[self_test]` may appear once; remove this one",
                ));
            }
            if !matches!(attr.meta, Meta::Path(_)) {
                return Err(syn::Error::new_spanned(
                    &attr.meta,
                    "`#[self_test]` takes no arguments; write `#[self_test]`",
                ));
            }
            out.self_test = Some(attr.span());
        } else if path.is_ident("derive") || path.is_ident("cfg_attr") {
            meta(&attr.meta, None, &mut out.derives)?;
        } else if path.is_ident("mechanism") {
            crate_path(&attr, &mut out.krate)?;
        } else {
            return Err(unknown(&attr));
        }
    }
    for kind in [DeriveKind::Serialize, DeriveKind::Deserialize] {
        if let Some(second) = out.derives.iter().filter(|d| d.kind == kind).nth(1) {
            return Err(syn::Error::new_spanned(
                &second.path,
                format!("`{kind:?}` is derived twice on this definition (its impls would conflict); keep one"),
            ));
        }
    }
    Ok(out)
}

/// One attribute's meta (`derive(..)`, else `cfg_attr(..)`, under the
/// predicate `cfg` of the `cfg_attr`s around it), its derives added to
/// `derives`.
fn meta(meta: &Meta, cfg: Option<&TokenStream>, derives: &mut Vec<Derive>) -> syn::Result<()> {
    let path = meta.path();
    if path.is_ident("derive") {
        let list = meta.require_list().map_err(|_| {
            syn::Error::new_spanned(
                meta,
                "`derive` lists the traits to derive: `#[derive(serde::Serialize, serde::Deserialize)]`",
            )
        })?;
        let paths = list
            .parse_args_with(Punctuated::<Path, Token![,]>::parse_terminated)
            .map_err(|e| {
                syn::Error::new(
                    e.span(),
                    "`derive` takes trait paths separated by commas: `#[derive(serde::Serialize, serde::Deserialize)]`",
                )
            })?;
        if paths.is_empty() {
            return Err(syn::Error::new_spanned(
                meta,
                "`#[derive()]` lists nothing; name the traits (`#[derive(serde::Serialize)]`) or remove it",
            ));
        }
        for p in paths {
            derives.push(derive(p, cfg.cloned())?);
        }
        return Ok(());
    }
    cfg_attr(meta, cfg, derives)
}

/// `#[mechanism(crate = PATH)]` (or `crate = "PATH"`, as serde writes it):
/// the facade's path in the user's crate, once.
fn crate_path(attr: &Attribute, krate: &mut Option<Path>) -> syn::Result<()> {
    let usage = "write `#[mechanism(crate = pm)]` with the name your Cargo.toml gives the `planar-mechanism` dependency (`pm = { package = \"planar-mechanism\", .. }`)";
    attr.parse_nested_meta(|m| {
        if !m.path.is_ident("crate") {
            return Err(m.error(format!("`#[mechanism(..)]` takes `crate = PATH`; {usage}")));
        }
        let value = m.value()?;
        let path: Path = if value.peek(syn::LitStr) {
            value.parse::<syn::LitStr>()?.parse()?
        } else {
            value.parse()?
        };
        if krate.replace(path).is_some() {
            return Err(m.error("`crate = ..` is given twice; keep one"));
        }
        Ok(())
    })
    .map_err(|e| {
        if e.to_string().contains("crate") {
            e
        } else {
            syn::Error::new(e.span(), format!("{e}; {usage}"))
        }
    })
}

/// The error on an attribute a definition does not take (`attr`: its tokens).
fn unknown(attr: &Attribute) -> syn::Error {
    let word = attr.path().to_token_stream().to_string().replace(' ', "");
    let why = match word.as_str() {
        "serde" => "; serde's options do not apply: the generated impls use the definition's names as the keys and have no other form. Remove it".to_string(),
        "cfg" => "; a definition is not compiled conditionally: put `#[cfg(..)]` on a module holding it, or gate a derive with `#[cfg_attr(PREDICATE, derive(..))]`".to_string(),
        "repr" | "non_exhaustive" | "allow" | "warn" | "deny" | "must_use" => {
            "; the layout, lints and attributes of the generated types are fixed: remove it".to_string()
        }
        _ => crate::diag::did_you_mean(&word, ["self_test", "derive", "cfg_attr", "mechanism"]),
    };
    syn::Error::new_spanned(
        attr,
        format!("unknown attribute `#[{word}]`; {ACCEPTED}{why}"),
    )
}

/// `cfg_attr(PRED, attr, ..)`: each `attr` under `PRED` (and `outer`).
fn cfg_attr(
    meta: &Meta,
    outer: Option<&TokenStream>,
    derives: &mut Vec<Derive>,
) -> syn::Result<()> {
    let usage = "`cfg_attr` takes a predicate and the derives it gates: `#[cfg_attr(feature = \"serde\", derive(serde::Serialize))]`";
    let list = meta
        .require_list()
        .map_err(|_| syn::Error::new_spanned(meta, usage))?;
    let parts = list
        .parse_args_with(Punctuated::<Meta, Token![,]>::parse_terminated)
        .map_err(|e| syn::Error::new(e.span(), usage))?;
    let mut parts = parts.into_iter();
    let Some(pred) = parts.next() else {
        return Err(syn::Error::new_spanned(meta, usage));
    };
    let pred = pred.to_token_stream();
    let joined = match outer {
        Some(o) => quote!(all(#o, #pred)),
        None => pred,
    };
    let mut any = false;
    for part in parts {
        meta_under(&part, &joined, derives)?;
        any = true;
    }
    if !any {
        return Err(syn::Error::new_spanned(
            meta,
            format!("{usage}; this one gates nothing"),
        ));
    }
    Ok(())
}

/// One attribute inside a `cfg_attr`: a derive or a nested `cfg_attr`.
fn meta_under(part: &Meta, pred: &TokenStream, derives: &mut Vec<Derive>) -> syn::Result<()> {
    if part.path().is_ident("derive") || part.path().is_ident("cfg_attr") {
        meta(part, Some(pred), derives)
    } else {
        let word = part.path().to_token_stream().to_string().replace(' ', "");
        Err(syn::Error::new_spanned(
            part,
            format!("`#[cfg_attr(..)]` on a definition gates derives only, not `{word}`; write `#[cfg_attr(PREDICATE, derive(..))]`"),
        ))
    }
}

/// One derived trait: `Serialize` and `Deserialize` (by their last path
/// segment) are generated by the macro; traits every generated type already
/// implements, and traits floating-point fields cannot have, are errors.
fn derive(path: Path, cfg: Option<TokenStream>) -> syn::Result<Derive> {
    let last = path
        .segments
        .last()
        .map(|s| s.ident.to_string())
        .unwrap_or_default();
    let kind = match last.as_str() {
        "Serialize" => DeriveKind::Serialize,
        "Deserialize" => DeriveKind::Deserialize,
        "Clone" | "Copy" | "Debug" | "PartialEq" => {
            return Err(syn::Error::new_spanned(
                &path,
                format!("every type `mechanism!` generates already implements `{last}`; remove it from the list"),
            ))
        }
        "Eq" | "Ord" | "PartialOrd" | "Hash" => {
            return Err(syn::Error::new_spanned(
                &path,
                format!("`{last}` cannot be derived: the generated types hold floating-point numbers (`f32`, `f64`), which have no `{last}`; remove it from the list"),
            ))
        }
        "Default" => {
            return Err(syn::Error::new_spanned(
                &path,
                "`Default` is generated: the mechanism's `Default` holds the parameters' values from `params { .. }`; remove it from the list",
            ))
        }
        _ => DeriveKind::Other,
    };
    Ok(Derive { path, kind, cfg })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The attributes of `src` (a definition's head) sorted.
    fn sorted(src: &str) -> syn::Result<Attrs> {
        let attrs = syn::parse_str::<syn::DeriveInput>(&format!("{src} struct S;"))
            .expect("attributes parse")
            .attrs;
        sort(attrs)
    }

    // Proves a doc attribute that is not text (found by the expand fuzzer:
    // `#[doc = - "x"]` expanded, then failed to compile in the generated
    // code) is an error on the attribute, and text passes.
    #[test]
    fn doc_attributes_are_text() {
        assert!(sorted("#[doc = \"text\"]").is_ok());
        for bad in ["#[doc = - \"x\"]", "#[doc(hidden)]", "#[doc = 1.0]"] {
            let e = sorted(bad)
                .err()
                .unwrap_or_else(|| panic!("{bad} accepted"));
            assert!(e.to_string().contains("doc comment"), "{bad}: {e}");
        }
    }

    // Proves plain and gated derives are read with their kind and predicate,
    // nested `cfg_attr`s joined with `all`, and doc comments kept apart.
    #[test]
    fn derives_with_their_predicates() {
        let a = sorted(
            "/// Doc.\n#[derive(serde::Serialize)] #[cfg_attr(feature = \"x\", derive(Deserialize, my::Thing))] #[cfg_attr(unix, cfg_attr(test, derive(Thing)))]",
        )
        .unwrap();
        assert_eq!(a.docs.len(), 1);
        let got: Vec<(DeriveKind, String)> = a
            .derives
            .iter()
            .map(|d| {
                let cfg = d.cfg.as_ref().map(|c| c.to_string()).unwrap_or_default();
                (d.kind, cfg)
            })
            .collect();
        assert_eq!(
            got,
            [
                (DeriveKind::Serialize, String::new()),
                (DeriveKind::Deserialize, "feature = \"x\"".to_string()),
                (DeriveKind::Other, "feature = \"x\"".to_string()),
                (DeriveKind::Other, "all (unix , test)".to_string()),
            ]
        );
    }

    // Proves each bad form is rejected with a message that says what to write.
    #[test]
    fn bad_forms_say_what_to_write() {
        let cases = [
            ("#[derive]", "`derive` lists the traits"),
            ("#[derive()]", "lists nothing"),
            ("#[derive(Debug)]", "already implements `Debug`"),
            ("#[derive(Hash)]", "floating-point"),
            ("#[derive(Default)]", "`Default` is generated"),
            (
                "#[serde(rename_all = \"camelCase\")]",
                "serde's options do not apply",
            ),
            ("#[cfg_attr(feature = \"x\")]", "gates nothing"),
            (
                "#[cfg_attr(feature = \"x\", repr(C))]",
                "gates derives only",
            ),
            ("#[repr(C)]", "fixed: remove it"),
            ("#[drive(Serialize)]", "did you mean `derive`?"),
            ("#[self_test(x)]", "takes no arguments"),
            (
                "#[derive(Serialize)] #[cfg_attr(test, derive(serde::Serialize))]",
                "derived twice",
            ),
        ];
        for (src, says) in cases {
            let e = sorted(src)
                .err()
                .unwrap_or_else(|| panic!("{src} accepted"));
            assert!(e.to_string().contains(says), "{src}: {e}");
        }
    }
}
