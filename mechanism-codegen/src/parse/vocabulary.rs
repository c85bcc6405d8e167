//! The language's vocabulary: the statement kinds, how each is written, and
//! how many arguments each takes. Each kind states these in its own file
//! (`kinds::X::SPEC`, typed by [`KindWord`]); this module lists them for
//! parsing, lowering and the messages of every stage.

pub use crate::kinds::word::{KindWord, Spec};

/// Every statement kind the language knows, as written, for suggestions.
pub fn kinds() -> impl Iterator<Item = &'static str> + Clone {
    KindWord::ALL.into_iter().map(KindWord::text)
}

/// Every statement kind as a list for messages (`ground, guide, ...`).
pub fn kinds_list() -> String {
    kinds().collect::<Vec<_>>().join(", ")
}

/// Drivers other tools call differently, with the word to use here.
pub fn unsupported_driver(kind: &str) -> Option<&'static str> {
    match kind {
        "motor" | "rotary" | "revolute" | "input" | "rocker" => {
            Some("a rotary input is a `crank(PIVOT, radius, INPUT) as LINK`")
        }
        "linear" | "cylinder" | "piston" => {
            Some("a length input is an `actuator(...)`, a translation input a `slider(...)`")
        }
        _ => None,
    }
}
