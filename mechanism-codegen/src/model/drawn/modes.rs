//! Run-time assembly modes in the drawn form: `mode elbow = assembly(C);`
//! makes `elbow` a mode parameter (a field of type `mechanism::Mode`) read
//! by the group the decomposition finds to place joint `C` (an RRR, an RRP,
//! a cylinder's rod end) or to slide block `C` in its slot (an RPR). Its
//! default is the assembly the drawing shows; the other value is the other
//! assembly of that group. The group's statement gets the parameter's name in
//! its mode's place, so it lowers as a group statement naming a
//! `params { elbow = .. }` entry would, and the expansion-time check runs
//! for every value (`check::modes`).

use super::super::modes::{mode_index, mode_word};
use super::super::Mode;
use crate::diag::{did_you_mean, Diagnostics};
use crate::parse::vocabulary::KindWord;
use crate::parse::{Arg, Let};
use syn::{Expr, Ident};

/// A `mode NAME = assembly(J);` of the drawing: the parameter's name and the
/// joint (or block) whose group it sets.
pub(super) struct DrawnMode {
    pub name: Ident,
    pub at: Ident,
}

/// The group statement among `lets` that `at` names: the one defining the
/// joint `at`, or the RPR whose block (its first link) is `at`.
fn group_of<'l>(lets: &'l mut [Let], at: &Ident) -> Option<&'l mut Let> {
    lets.iter_mut().find(|l| {
        &l.name == at
            || l.joints.contains(at)
            || (l.word == Some(KindWord::Rpr) && l.links.first() == Some(at))
    })
}

/// Puts each mode parameter of `modes` in its group's mode place in `lets`
/// (the statements the drawing decomposed into), and returns the parameters
/// with their defaults (the drawing's assemblies). A name that is no joint or
/// block of the drawing, or whose group has a single assembly, or that a
/// second `mode` names again, is an error on the user's token.
pub(super) fn attach(
    lets: &mut [Let],
    modes: &[DrawnMode],
    errors: &mut Diagnostics,
) -> Vec<(Ident, Mode)> {
    let mut out: Vec<(Ident, Mode)> = Vec::new();
    let mut taken: Vec<&Ident> = Vec::new();
    let groups = "an RRR, an RRP or a cylinder places (a dyad's free joint, a cylinder's rod end), or the block of an RPR";
    for m in modes {
        if taken.contains(&&m.at) {
            errors.push(
                m.at.span(),
                format!("the assembly of `{}` is already the mode parameter of another `mode` statement; one parameter per group: remove this statement, or use the other parameter's field", m.at),
            );
            continue;
        }
        let names: Vec<String> = lets
            .iter()
            .flat_map(|l| std::iter::once(&l.name).chain(&l.joints).chain(&l.links))
            .map(Ident::to_string)
            .collect();
        let Some(group) = group_of(lets, &m.at) else {
            errors.push(
                m.at.span(),
                format!(
                    "`{}` is no joint or block of the drawing; `assembly(..)` takes a joint that {groups}{}",
                    m.at,
                    did_you_mean(&m.at.to_string(), names.iter().map(String::as_str))
                ),
            );
            continue;
        };
        let kind = group.kind.to_string();
        let word = mode_index(group.word).and_then(|i| match group.args.get(i) {
            Some(Arg::Value(e @ Expr::Path(_), None)) => mode_word(e).map(|w| (i, w)),
            _ => None,
        });
        let Some((index, default)) = word else {
            errors.push(
                m.at.span(),
                format!(
                    "`{}` is placed by a `{kind}`, which has a single assembly, so there is no mode to choose at run time; `assembly(..)` takes a joint that {groups}",
                    m.at
                ),
            );
            continue;
        };
        let name = &m.name;
        group.args[index] = Arg::Value(syn::parse_quote!(#name), None);
        taken.push(&m.at);
        out.push((name.clone(), default));
    }
    out
}
