//! Which fields of the position, velocity and acceleration structs later
//! code reads. The structs keep, besides the outputs, exactly those fields: a
//! group's solved state (`pos.grp_B`), a guide (`pos.g`), a link's axis, the
//! inputs; everything else stays a local of the analysis that computes it.
//!
//! The readers are the later analyses (velocity, acceleration, forces,
//! dynamics, `position_near`), `check()` and the self-tests. Each read is
//! recorded where its code is emitted: the code that reads field `grp_B` of
//! the position writes `r.pos(&grp_B)` ([`Reads::pos`], and [`Reads::vel`],
//! [`Reads::acc`]), which records `(Position, grp_B)` and returns the tokens
//! `pos.grp_B`. The set of recorded reads is then the set of kept fields
//! ([`Reads::reads`]), asked once every reader is emitted.
//!
//! The recorder is shared (`&Reads`, recording through a `RefCell`): the
//! readers are emitted by several emitters alive at the same time (the rate
//! and force emitters behind `RateCx` and `ForceCx`, the self-tests'
//! residuals, which read a link's axis through a `&dyn Fn` closure), and a
//! `&mut Reads` would have to be threaded through each of them and could
//! not be captured by those closures. The kinds reach it through the
//! context they already receive (`RateCx::reads`, `ForceCx::reads`,
//! `Residuals::reads`) or, for the methods that have none (`det_code`,
//! `closure_axis`, `position_tracking`), as an argument.
//!
//! In debug builds of the macro, `emit` checks the recorded reads against a
//! scan of the emitted readers' token trees ([`Reads::scan`]: an identifier
//! `pos`, `vel` or `acc`, a `.`, and the field): a read written directly into
//! tokens, bypassing the recorder, or a recorded read whose code was not
//! emitted, fails that assertion on every expansion the tests run.

use proc_macro2::{TokenStream, TokenTree};
use quote::{format_ident, quote};
use std::cell::{Cell, RefCell};
use std::collections::BTreeSet;
use syn::Ident;

/// The analysis struct a field belongs to, by the name the generated code
/// gives its value (`pos`, `vel`, `acc`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Analysis {
    /// `pos: &NamePosition<T>`.
    Position,
    /// `vel: &NameVelocity<T>`.
    Velocity,
    /// `acc: &NameAcceleration<T>`.
    Acceleration,
}

impl Analysis {
    fn of(binding: &str) -> Option<Self> {
        Some(match binding {
            "pos" => Analysis::Position,
            "vel" => Analysis::Velocity,
            "acc" => Analysis::Acceleration,
            _ => return None,
        })
    }
}

/// A read field: its analysis and its name.
pub type Read = (Analysis, String);

/// The fields read, recorded as their reads are emitted.
#[derive(Default, Debug)]
pub struct Reads {
    fields: RefCell<BTreeSet<Read>>,
    /// Set by the first [`Reads::reads`]: the structs' fields are being
    /// decided, and a read recorded after that would read a field the
    /// struct may lack.
    decided: Cell<bool>,
}

impl Reads {
    /// `pos.FIELD`, recorded: a read of the position struct's `field`.
    pub fn pos(&self, field: &Ident) -> TokenStream {
        self.record(Analysis::Position, field);
        quote!(pos.#field)
    }

    /// `vel.FIELD`, recorded: a read of the velocity struct's `field`.
    pub fn vel(&self, field: &Ident) -> TokenStream {
        self.record(Analysis::Velocity, field);
        quote!(vel.#field)
    }

    /// `acc.FIELD`, recorded: a read of the acceleration struct's `field`.
    pub fn acc(&self, field: &Ident) -> TokenStream {
        self.record(Analysis::Acceleration, field);
        quote!(acc.#field)
    }

    /// `pos.input`, recorded: the inputs the position struct then keeps
    /// (a driver's input value, in length units or rad).
    pub fn pos_input(&self) -> TokenStream {
        self.pos(&format_ident!("input"))
    }

    /// `vel.rates`, recorded: the input rates every velocity struct keeps.
    pub fn vel_rates(&self) -> TokenStream {
        self.vel(&format_ident!("rates"))
    }

    fn record(&self, analysis: Analysis, field: &Ident) {
        debug_assert!(
            !self.decided.get(),
            "`{field}` of {analysis:?} read after the structs' fields were decided"
        );
        self.fields
            .borrow_mut()
            .insert((analysis, field.to_string()));
    }

    /// `true` when some reader reads `field` of `analysis`. Asked once every
    /// reader is emitted.
    pub fn reads(&self, analysis: Analysis, field: &Ident) -> bool {
        self.decided.set(true);
        self.fields
            .borrow()
            .contains(&(analysis, field.to_string()))
    }

    /// The reads written in `readers` (found by [`Reads::scan`]) that were
    /// not recorded, and the recorded reads written in none of them: both
    /// empty when every read of the readers' code went through the
    /// recorder and every recorded read was emitted.
    pub fn mismatch<'t>(
        &self,
        readers: impl IntoIterator<Item = &'t TokenStream>,
    ) -> (Vec<Read>, Vec<Read>) {
        let written: BTreeSet<Read> = readers.into_iter().flat_map(Reads::scan).collect();
        let recorded = self.fields.borrow();
        (
            written.difference(&recorded).cloned().collect(),
            recorded.difference(&written).cloned().collect(),
        )
    }

    /// The reads written in `code`: each identifier `pos`, `vel` or `acc`
    /// (not itself after a `.`) followed by `.` and a field, at any depth of
    /// nesting. The debug cross-check of the recorded reads.
    pub fn scan(code: &TokenStream) -> BTreeSet<Read> {
        let mut found = BTreeSet::new();
        scan_into(code, &mut found);
        found
    }
}

fn scan_into(code: &TokenStream, found: &mut BTreeSet<Read>) {
    let tokens: Vec<TokenTree> = code.clone().into_iter().collect();
    for (k, token) in tokens.iter().enumerate() {
        match token {
            TokenTree::Group(g) => scan_into(&g.stream(), found),
            TokenTree::Ident(binding) => {
                let (Some(TokenTree::Punct(dot)), Some(TokenTree::Ident(field))) =
                    (tokens.get(k + 1), tokens.get(k + 2))
                else {
                    continue;
                };
                // `x.pos.y` is a field of something else.
                let after_dot =
                    k > 0 && matches!(&tokens[k - 1], TokenTree::Punct(p) if p.as_char() == '.');
                if let (Some(analysis), '.', false) =
                    (Analysis::of(&binding.to_string()), dot.as_char(), after_dot)
                {
                    found.insert((analysis, field.to_string()));
                }
            }
            _ => {}
        }
    }
}

#[cfg(test)]
mod tests {
    //! The recorder: a read is kept when its code is emitted through it, in
    //! the tokens a reader writes by hand; the scan finds the fields after
    //! `pos.`, `vel.`, `acc.` at any depth of nesting, and nothing else.
    use super::*;
    use quote::format_ident;

    fn id(s: &str) -> Ident {
        format_ident!("{}", s)
    }

    #[test]
    fn a_recorded_read_is_kept_with_the_tokens_it_replaces() {
        let r = Reads::default();
        assert_eq!(
            r.pos(&id("grp_B")).to_string(),
            quote!(pos.grp_B).to_string()
        );
        assert_eq!(
            r.vel(&id("omega_L")).to_string(),
            quote!(vel.omega_L).to_string()
        );
        assert_eq!(
            r.acc(&id("acc_P")).to_string(),
            quote!(acc.acc_P).to_string()
        );
        assert_eq!(r.pos_input().to_string(), quote!(pos.input).to_string());
        assert!(r.reads(Analysis::Position, &id("grp_B")));
        assert!(r.reads(Analysis::Velocity, &id("omega_L")));
        assert!(r.reads(Analysis::Acceleration, &id("acc_P")));
        assert!(r.reads(Analysis::Position, &id("input")));
        assert!(!r.reads(Analysis::Velocity, &id("grp_B")));
        assert!(!r.reads(Analysis::Position, &id("omega_L")));
    }

    #[test]
    fn a_read_bypassing_the_recorder_or_never_emitted_is_a_mismatch() {
        let r = Reads::default();
        let through = r.pos(&id("grp_B"));
        let _never_emitted = r.vel(&id("grp_v_B"));
        let code = quote!(f(&#through, &acc.by_hand));
        let (unrecorded, unwritten) = r.mismatch([&code]);
        assert_eq!(
            unrecorded,
            [(Analysis::Acceleration, "by_hand".to_string())]
        );
        assert_eq!(unwritten, [(Analysis::Velocity, "grp_v_B".to_string())]);
        let clean = quote!(f(&#through));
        let r2 = Reads::default();
        let _ = r2.pos(&id("grp_B"));
        assert_eq!(r2.mismatch([&clean]), (vec![], vec![]));
    }

    #[test]
    fn scan_finds_fields_at_any_depth_and_only_of_the_three_bindings() {
        let found = Reads::scan(&quote! {
            let x = f(&pos.grp_B, g(vel.grp_v_B.omega, [acc.a_P]));
            let y = other.pos.not_this + position.nor_this;
        });
        let expected: BTreeSet<Read> = [
            (Analysis::Position, "grp_B"),
            (Analysis::Velocity, "grp_v_B"),
            (Analysis::Acceleration, "a_P"),
        ]
        .into_iter()
        .map(|(a, f)| (a, f.to_string()))
        .collect();
        assert_eq!(found, expected);
    }
}
