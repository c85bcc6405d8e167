//! The expansion-time check of a definition whose groups read run-time
//! assembly modes (`params { circuit = left }`): the check of
//! [`super::expansion_check`] runs with the modes' defaults (the findings the
//! generated docs and self-tests use), and once more here for every other
//! combination of their values, so a circuit that cannot be assembled over
//! the input range is a compile error whichever value the program picks.

use super::check_assuming;
use crate::diag::Diagnostics;
use crate::model::modes::flipped;
use crate::model::{Mode, Model};
use crate::plan::Plan;
use std::collections::BTreeMap;

/// Most mode parameters whose combinations are all checked (2^6 - 1 more
/// sweeps); beyond, each one is checked flipped alone.
const MAX_COMBINED: usize = 6;

/// Checks the combinations of the mode parameters' values other than the
/// defaults, each passed to the evaluator (the model keeps its defaults);
/// errors get the combination appended.
pub fn other_modes(model: &Model, plan: &Plan, errors: &mut Diagnostics) {
    // The mode parameters some group reads, in the order declared.
    let used: Vec<(String, Mode)> = model
        .modes
        .iter()
        .filter(|(m, _)| model.stmts.iter().any(|s| s.mode_param.as_ref() == Some(m)))
        .map(|(m, d)| (m.to_string(), *d))
        .collect();
    let masks: Vec<u64> = if used.len() <= MAX_COMBINED {
        (1..(1u64 << used.len())).collect()
    } else {
        (0..used.len()).map(|j| 1u64 << j).collect()
    };
    for mask in masks {
        let value = |j: usize| {
            let d = used[j].1;
            if mask & (1 << j) != 0 {
                flipped(d)
            } else {
                d
            }
        };
        let modes: BTreeMap<String, Mode> = (0..used.len())
            .map(|j| (used[j].0.clone(), value(j)))
            .collect();
        let mut sub = Diagnostics::new();
        check_assuming(model, plan, modes, &mut sub);
        let with: Vec<String> = (0..used.len())
            .map(|j| format!("`{} = {}`", used[j].0, word(value(j))))
            .collect();
        for e in sub.finish().into_iter().flat_map(syn::Error::into_iter) {
            errors.push(
                e.span(),
                format!("with the run-time mode {}: {e}", with.join(", ")),
            );
        }
    }
}

/// The word of a mode in messages.
fn word(mode: Mode) -> &'static str {
    match mode {
        Mode::Plus => "left (plus)",
        Mode::Minus => "right (minus)",
    }
}
