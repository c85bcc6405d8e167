//! The statement kinds' words as a type: [`KindWord`] names each kind the
//! language knows, and [`Spec`] is how one is written (its word, usage,
//! arity, the links it creates, where its inputs sit). Each kind's file
//! states its own `SPEC`; [`KindWord::spec`] is the one table from word to
//! descriptor. The parse stage reads these constants (data only, no
//! dependency on the model), so the vocabulary and every message about a
//! kind are built from the kind's own file.

use syn::Ident;

/// A statement kind, by its word (`rrr`, `crank`, ...).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum KindWord {
    /// `ground(x, y)`: a fixed point.
    Ground,
    /// `guide(..)`: a line, fixed or carried.
    Guide,
    /// `crank(..)`: a rotary driver.
    Crank,
    /// `slider(..)`: a translation driver.
    Slider,
    /// `actuator(..)`: a linear actuator driver.
    Actuator,
    /// `target(..)`: a point placed by two inputs.
    Target,
    /// `rrr(..)`: the RRR group.
    Rrr,
    /// `rrp(..)`: the RRP group.
    Rrp,
    /// `rpr(..)`: the RPR group.
    Rpr,
    /// `prp(..)`: the PRP group.
    Prp,
    /// `rpp(..)`: the RPP group.
    Rpp,
    /// `point(..)`: a point fixed on a link.
    Point,
    /// `triad(..)`: the class III group.
    Triad,
    /// `gear(..)`: a link geared to another.
    Gear,
}

/// How many arguments a kind takes: the fewest (every optional argument
/// left out) and the most, possibly depending on whether one argument is a
/// tuple (`point`'s `(x, y)` form, `triad`'s `(x, y)` place of `P`).
#[derive(Clone, Copy, Debug)]
pub enum Arity {
    /// Always between the two.
    Range(usize, usize),
    /// `tuple` when the argument at `index` is a tuple, else `other`.
    TupleAt {
        /// The argument that decides.
        index: usize,
        /// The arity when it is a tuple.
        tuple: (usize, usize),
        /// The arity otherwise.
        other: (usize, usize),
    },
}

/// One statement kind as the language writes it.
#[derive(Debug)]
pub struct Spec {
    /// Its typed word.
    pub word: KindWord,
    /// The word as written.
    pub text: &'static str,
    /// How it is written, for messages.
    pub usage: &'static str,
    /// How many arguments it takes.
    pub arity: Arity,
    /// The links it creates, in the order `as` names them, in words (""
    /// when it creates none).
    pub links: &'static str,
    /// Where its input names sit among its arguments (a driver's).
    pub inputs: &'static [usize],
    /// The place of its assembly mode among its arguments, when it has one.
    pub mode_at: Option<usize>,
    /// The words its assembly mode accepts (empty without a mode).
    pub mode_words: &'static [&'static str],
    /// What messages call a statement of this kind that fails to assemble
    /// or is singular (`None`: it cannot fail, a ground point or a guide).
    pub group: Option<&'static str>,
}

/// The mode words of the groups whose mode is a side (RRR, actuator).
pub const SIDE_MODES: &[&str] = &["left", "right", "plus", "minus"];
/// The mode words of the groups whose mode is a sign (RRP, RPR).
pub const SIGN_MODES: &[&str] = &["plus", "minus"];

impl KindWord {
    /// Every kind, in the order the vocabulary lists them.
    pub const ALL: [KindWord; 14] = [
        KindWord::Ground,
        KindWord::Guide,
        KindWord::Crank,
        KindWord::Slider,
        KindWord::Actuator,
        KindWord::Target,
        KindWord::Rrr,
        KindWord::Rrp,
        KindWord::Rpr,
        KindWord::Prp,
        KindWord::Rpp,
        KindWord::Point,
        KindWord::Triad,
        KindWord::Gear,
    ];

    /// The kind a written word names, `None` for a word the language does
    /// not know (the one place a kind's text is compared).
    pub fn of(word: &Ident) -> Option<KindWord> {
        KindWord::ALL.into_iter().find(|k| word == k.spec().text)
    }

    /// The word as written.
    pub fn text(self) -> &'static str {
        self.spec().text
    }

    /// The word as an identifier on `span` (for the statements the drawn
    /// form writes).
    pub fn ident(self, span: proc_macro2::Span) -> Ident {
        Ident::new(self.text(), span)
    }

    /// The fewest and the most arguments it takes, `tuple_at(k)` saying
    /// whether its argument `k` is written as a tuple (`(x, y)`).
    pub fn arity(self, tuple_at: impl Fn(usize) -> bool) -> (usize, usize) {
        match self.spec().arity {
            Arity::Range(lo, hi) => (lo, hi),
            Arity::TupleAt {
                index,
                tuple,
                other,
            } => {
                if tuple_at(index) {
                    tuple
                } else {
                    other
                }
            }
        }
    }
}

impl std::fmt::Display for KindWord {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.text())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_word_names_its_own_descriptor_once() {
        // Proves each kind's file states the descriptor of its own word
        // (the table cannot send a word to another kind's `SPEC`), and no
        // two kinds share a written word.
        for k in KindWord::ALL {
            assert_eq!(k.spec().word, k, "{k:?}");
            let span = proc_macro2::Span::call_site();
            assert_eq!(KindWord::of(&k.ident(span)), Some(k));
            assert!(k.spec().usage.contains(k.text()), "{k:?}");
        }
    }
}
