//! Which fields of the position, velocity and acceleration structs later code
//! reads. The structs keep, besides the outputs, exactly those fields: a
//! group's solved state (`pos.grp_B`), a guide (`pos.g`), a link's axis, the
//! inputs; everything else stays a local of the analysis that computes it.
//!
//! The readers are the later analyses, `check()` and the self-tests. Their
//! reads are collected from the token trees they emit (an identifier `pos`,
//! `vel` or `acc`, a `.`, and the field), so a reader can never use a field
//! the struct does not keep, and the struct keeps no field nobody reads.

use proc_macro2::{TokenStream, TokenTree};
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

/// The set of fields read, by analysis and field name.
#[derive(Default, Debug)]
pub struct Reads {
    fields: BTreeSet<(Analysis, String)>,
}

impl Reads {
    /// Adds the reads of `code`.
    pub fn scan(&mut self, code: &TokenStream) {
        let tokens: Vec<TokenTree> = code.clone().into_iter().collect();
        for (k, token) in tokens.iter().enumerate() {
            match token {
                TokenTree::Group(g) => self.scan(&g.stream()),
                TokenTree::Ident(binding) => {
                    let (Some(TokenTree::Punct(dot)), Some(TokenTree::Ident(field))) =
                        (tokens.get(k + 1), tokens.get(k + 2))
                    else {
                        continue;
                    };
                    // `x.pos.y` is a field of something else.
                    let after_dot = k > 0
                        && matches!(&tokens[k - 1], TokenTree::Punct(p) if p.as_char() == '.');
                    if let (Some(analysis), '.', false) =
                        (Analysis::of(&binding.to_string()), dot.as_char(), after_dot)
                    {
                        self.fields.insert((analysis, field.to_string()));
                    }
                }
                _ => {}
            }
        }
    }

    /// `true` when some reader reads `field` of `analysis`.
    pub fn reads(&self, analysis: Analysis, field: &Ident) -> bool {
        self.fields.contains(&(analysis, field.to_string()))
    }
}

#[cfg(test)]
mod tests {
    //! The reads found in emitted code: fields after `pos.`, `vel.`,
    //! `acc.`, at any depth of nesting, and nothing else.
    use super::*;
    use quote::{format_ident, quote};

    #[test]
    fn finds_fields_at_any_depth_and_only_of_the_three_bindings() {
        let mut r = Reads::default();
        r.scan(&quote! {
            let x = f(&pos.grp_B, g(vel.grp_v_B.omega, [acc.a_P]));
            let y = other.pos.not_this + position.nor_this;
        });
        for (a, f) in [
            (Analysis::Position, "grp_B"),
            (Analysis::Velocity, "grp_v_B"),
            (Analysis::Acceleration, "a_P"),
        ] {
            assert!(r.reads(a, &format_ident!("{}", f)), "{f}");
        }
        let no = |a, f: &str| assert!(!r.reads(a, &format_ident!("{}", f)), "{f}");
        no(Analysis::Position, "not_this");
        no(Analysis::Position, "nor_this");
        no(Analysis::Velocity, "omega");
        no(Analysis::Velocity, "grp_B");
    }
}
