//! Run-time assembly modes: `params { circuit = left }` makes `circuit` a
//! field of type `mechanism::Mode` (default `Mode::Plus`), and a group that
//! names it in its mode's place (`rrr(A, l1, B, l2, circuit)`) reads it at
//! run time. The group's kind keeps the default as its mode, so everything
//! that evaluates the definition at expansion time sees the default, and
//! `expand` runs the expansion-time check once more per other value.

use super::Mode;
use crate::parse::vocabulary::KindWord;
use crate::parse::{self, Arg};
use syn::{Expr, Ident};

/// The words of an assembly mode, with the mode each names.
const WORDS: [(&str, Mode); 4] = [
    ("left", Mode::Plus),
    ("plus", Mode::Plus),
    ("right", Mode::Minus),
    ("minus", Mode::Minus),
];

/// The mode a parameter's default names, when it is a mode word (`left`,
/// `right`, `plus`, `minus`), `None` for anything else (a number).
pub(in crate::model) fn mode_word(value: &Expr) -> Option<Mode> {
    let Expr::Path(p) = value else { return None };
    let word = p.path.get_ident()?.to_string();
    WORDS.iter().find(|(w, _)| *w == word).map(|(_, m)| *m)
}

/// The position of the mode among a statement kind's arguments (`None`
/// for a word the language does not know, or a kind without a mode).
pub(in crate::model) fn mode_index(kind: Option<KindWord>) -> Option<usize> {
    kind?.spec().mode_at
}

/// When the statement `l` names a mode parameter of `modes` in its mode's
/// place, that parameter; the argument is replaced by the word of its
/// default (on the parameter's span), so the statement lowers as with a
/// literal mode.
pub(super) fn take_mode_param(l: &mut parse::Let, modes: &[(Ident, Mode)]) -> Option<Ident> {
    let at = mode_index(l.word)?;
    let Some(Arg::Value(Expr::Path(p), None)) = l.args.get(at) else {
        return None;
    };
    let name = p.path.get_ident()?.clone();
    let (_, mode) = modes.iter().find(|(m, _)| *m == name)?;
    let word = match mode {
        Mode::Plus => "plus",
        Mode::Minus => "minus",
    };
    let word = Ident::new(word, name.span());
    l.args[at] = Arg::Value(syn::parse_quote!(#word), None);
    Some(name)
}

/// The other mode.
pub fn flipped(mode: Mode) -> Mode {
    match mode {
        Mode::Plus => Mode::Minus,
        Mode::Minus => Mode::Plus,
    }
}

#[cfg(test)]
mod tests {
    use crate::diag::Diagnostics;
    use crate::model::{Kind, Mode};

    // Proves a mode word as a parameter's default makes a mode parameter (not
    // a number), that a group naming it in its mode's place reads it with the
    // default as its mode, and that the position code passes `self.PARAM`.
    #[test]
    fn a_mode_parameter_is_read_by_the_group_that_names_it() {
        let src = "pub F {
            params { crank = 1.0, circuit = right }
            let O2 = ground(0.0, 0.0);
            let O4 = ground(3.0, 0.0);
            let A = crank(O2, crank, t) as link2;
            let B = rrr(A, 3.0, O4, 2.0, circuit) as (link3, link4);
        }";
        let mut diag = Diagnostics::new();
        let model = crate::model::lower(syn::parse_str(src).unwrap(), &mut diag);
        assert!(diag.finish().is_empty());
        assert_eq!(model.params.len(), 1);
        assert_eq!(model.modes.len(), 1);
        assert_eq!(
            (model.modes[0].0.to_string(), model.modes[0].1),
            ("circuit".into(), Mode::Minus)
        );
        let b = model.stmts.iter().find(|s| s.name == "B").unwrap();
        assert_eq!(b.mode_param.as_ref().unwrap().to_string(), "circuit");
        assert!(matches!(
            b.kind,
            Kind::Rrr {
                mode: Mode::Minus,
                ..
            }
        ));
        let code = crate::expand(src.parse().unwrap())
            .to_string()
            .replace(' ', "");
        assert!(code.contains("pubcircuit:::mechanism::Mode,"), "{code}");
        assert!(code.contains("circuit:::mechanism::Mode::Minus,"), "{code}");
        assert!(code.contains(",self.circuit)"), "{code}");
        assert!(
            code.contains("::mechanism::Mode::sign::<T>(self.circuit)"),
            "{code}"
        );
    }

    // Proves a mode parameter shares the parameters' namespace: a second
    // definition of its name, or a reserved name, is an error.
    #[test]
    fn a_mode_parameter_name_is_checked_like_a_parameter() {
        for (params, says) in [
            ("a = 1.0, a = left", "`a` is already defined"),
            ("input = left", "reserved"),
        ] {
            let src = format!(
                "pub F {{ params {{ {params} }} let O = ground(0.0, 0.0); let A = crank(O, 1.0, t) as l; }}"
            );
            let code = crate::expand(src.parse().unwrap()).to_string();
            assert!(code.contains(says), "{params}: {code}");
        }
    }
}
