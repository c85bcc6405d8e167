//! Each kind's descriptor by its word: the one table from [`KindWord`] to the
//! `SPEC` its file states (word, usage, arity, the links it creates). Apart
//! from `word.rs`, which the kinds' files import for the types, so that the
//! table that names every kind's file is imported by none of them.

use super::word::{KindWord, Spec};

impl KindWord {
    /// Its descriptor, stated in its kind's file.
    pub fn spec(self) -> &'static Spec {
        match self {
            KindWord::Ground => &super::ground::SPEC,
            KindWord::Guide => &super::guide::SPEC,
            KindWord::Crank => &super::crank::SPEC,
            KindWord::Slider => &super::slider::SPEC,
            KindWord::Actuator => &super::actuator::SPEC,
            KindWord::Target => &super::target::SPEC,
            KindWord::Rrr => &super::rrr::SPEC,
            KindWord::Rrp => &super::rrp::SPEC,
            KindWord::Rpr => &super::rpr::SPEC,
            KindWord::Prp => &super::prp::SPEC,
            KindWord::Rpp => &super::rpp::SPEC,
            KindWord::Point => &super::point::SPEC,
            KindWord::Triad => &super::triad::SPEC,
            KindWord::Gear => &super::gear::SPEC,
        }
    }
}
