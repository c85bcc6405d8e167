//! Diagnostics: the one collector of compile errors, and the nearest-name
//! suggestions every stage uses ("did you mean `link3`?").
//!
//! Every stage reports into a [`Diagnostics`]; `expand` turns what it holds
//! into `compile_error!`s once, sorted by source position, so independent
//! mistakes in one definition are all reported in one compile.

use proc_macro2::Span;

/// The compile errors of one expansion, collected by every stage.
///
/// Made by [`Diagnostics::new`] and ended by [`Diagnostics::finish`], which
/// hands the errors back sorted by source position (the order a reader meets
/// them). Dropping it unfinished is a bug of the macro (an error would be
/// lost), caught by a panic in debug builds, as serde's `Ctxt` does.
#[derive(Default)]
pub struct Diagnostics {
    errors: Vec<syn::Error>,
    finished: bool,
}

impl Diagnostics {
    /// An empty collector.
    pub fn new() -> Self {
        Self::default()
    }

    /// Records an error on `span`.
    pub fn push(&mut self, span: Span, message: impl std::fmt::Display) {
        self.errors.push(syn::Error::new(span, message));
    }

    /// Records an error made elsewhere (a `syn` parse error, say).
    pub fn error(&mut self, error: syn::Error) {
        self.errors.push(error);
    }

    /// Records every error of `errors`.
    pub fn extend(&mut self, errors: impl IntoIterator<Item = syn::Error>) {
        self.errors.extend(errors);
    }

    /// `true` while no error is recorded.
    pub fn is_empty(&self) -> bool {
        self.errors.is_empty()
    }

    /// The number of errors recorded.
    pub fn len(&self) -> usize {
        self.errors.len()
    }

    /// Ends the collection: the errors, sorted by where they start in the
    /// source (stable: errors at one token keep the order they were found).
    /// Without source positions (outside a compiler, where `proc_macro2`
    /// gives none) the order is the order found.
    pub fn finish(mut self) -> Vec<syn::Error> {
        self.finished = true;
        let mut errors = std::mem::take(&mut self.errors);
        errors.sort_by_key(|e| {
            let start = e.span().start();
            (start.line, start.column)
        });
        errors
    }
}

impl Drop for Diagnostics {
    fn drop(&mut self) {
        if !self.finished && !std::thread::panicking() {
            debug_assert!(
                self.errors.is_empty(),
                "Diagnostics dropped with {} unreported error(s)",
                self.errors.len()
            );
        }
    }
}

/// Levenshtein distance, for "did you mean" hints.
pub fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != *cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}

/// The nearest of `candidates` to `name`, if reasonably close.
/// Close means at most a third of the longer name differs (one letter in
/// names of 2 or 3, none in one-letter names: `Q` is no typo of `A`). Ties
/// prefer a candidate that keeps the last character (`O5` -> `O4`? no:
/// equal; `Q4` -> `O4` over `A`), then alphabetical order.
pub fn nearest<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    candidates
        .into_iter()
        .map(|c| (edit_distance(name, c), c))
        .filter(|(d, c)| {
            *d > 0
                && *d
                    <= name
                        .chars()
                        .count()
                        .max(c.chars().count())
                        .div_ceil(3)
                        .min(3)
                && name.chars().count() > 1
        })
        .min_by_key(|(d, c)| (*d, name.chars().last() != c.chars().last(), c.to_string()))
        .map(|(_, c)| c)
}

/// A " (did you mean `x`?)" hint, or "".
pub fn did_you_mean<'a>(name: &str, candidates: impl IntoIterator<Item = &'a str>) -> String {
    match nearest(name, candidates) {
        Some(c) => format!("; did you mean `{c}`?"),
        None => String::new(),
    }
}

/// `n` and the noun it counts, singular for 1: `1 input`, `2 inputs`.
pub fn counted(n: impl Into<i64>, singular: &str, plural: &str) -> String {
    let n = n.into();
    format!("{n} {}", if n == 1 { singular } else { plural })
}

/// The verb after a count of `n`: `is` for 1, else `are`.
pub fn is_are(n: impl Into<i64>) -> &'static str {
    if n.into() == 1 {
        "is"
    } else {
        "are"
    }
}

/// A number for a message: up to 6 decimals, trailing zeros removed.
pub fn show_num(x: f64) -> String {
    let s = format!("{x:.6}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    };
    if s == "-0" {
        "0".into()
    } else {
        s
    }
}

/// An input value for a message: degrees for angles.
pub fn show_value(x: f64, angle: bool) -> String {
    if angle {
        format!("{} deg", show_num(x.to_degrees()))
    } else {
        show_num(x)
    }
}

pub fn show_interval(lo: f64, hi: f64, angle: bool) -> String {
    let (lo, hi) = if angle {
        (lo.to_degrees(), hi.to_degrees())
    } else {
        (lo, hi)
    };
    format!(
        "[{}, {}]{}",
        show_num(lo),
        show_num(hi),
        if angle { " deg" } else { "" }
    )
}
