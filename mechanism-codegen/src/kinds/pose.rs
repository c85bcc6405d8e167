//! The numbers a kind reads from its statement in `f64`: a dimension folded,
//! an assembly mode as the core's.

use crate::model::Mode;
use crate::value::Value;

/// A dimension's value, folded; NaN for one that does not fold (the
/// expansion-time check runs only when every value the position analysis
/// uses folds; the run-time mechanism values parameters when it compiles
/// its plan, `run::Compile::num`).
pub fn num(v: &Value) -> f64 {
    v.fold().unwrap_or(f64::NAN)
}

/// The core's assembly mode of a written one.
pub fn mode(m: Mode) -> mechanism_core::Mode {
    match m {
        Mode::Plus => mechanism_core::Mode::Plus,
        Mode::Minus => mechanism_core::Mode::Minus,
    }
}
