//! The reaction fields of a definition with errors, found from the statements
//! alone (no plan): what the stubs' forces struct holds, so the user's code
//! that reads a reaction reports no follow-on error.

use crate::keys::{GuideName, LinkName, PointName};
use crate::kinds::{
    self,
    forces::{ForceCx, Reaction},
    reads::Reads,
};
use crate::model::Model;
use proc_macro2::TokenStream;
use std::collections::BTreeMap;
use syn::Ident;

/// A [`ForceCx`] that keeps the fields only, the bodies found from the
/// statements alone (no plan): the forces struct of a definition with
/// errors, so the user's code that reads a reaction reports no follow-on
/// error.
pub struct FieldsOnly {
    owner: BTreeMap<PointName, Option<LinkName>>,
    carrier: BTreeMap<GuideName, Option<LinkName>>,
    /// The fields found, in the order found.
    pub reactions: Vec<Reaction>,
    /// The reads of the code the kinds write, which goes nowhere.
    reads: Reads,
}

impl FieldsOnly {
    /// The reaction fields of the statements of `model`, taken in the
    /// reverse of the order written (the force analysis takes the groups in
    /// the reverse of the solve order).
    pub fn of(model: &Model) -> Vec<Reaction> {
        let mut cx = FieldsOnly {
            owner: BTreeMap::new(),
            carrier: BTreeMap::new(),
            reactions: Vec::new(),
            reads: Reads::default(),
        };
        for stmt in &model.stmts {
            let kind = kinds::of(stmt);
            if let Some(body) = kind.point_owner() {
                cx.owner.insert(PointName::of(&stmt.name), body);
            }
            if let Some(carrier) = kinds::guide_carrier(stmt) {
                let carrier = carrier.map(LinkName::of);
                cx.carrier.insert(GuideName::of(&stmt.name), carrier);
            }
        }
        for stmt in model.stmts.iter().rev() {
            kinds::of(stmt).forces(&mut cx);
        }
        cx.reactions
    }
}

impl ForceCx for FieldsOnly {
    fn body_of_point(&self, point: &Ident) -> Option<LinkName> {
        self.owner.get(&PointName::of(point)).cloned().flatten()
    }
    fn body_of_guide(&self, guide: &Ident) -> Option<LinkName> {
        self.carrier.get(&GuideName::of(guide)).cloned().flatten()
    }
    fn reference(&self, link: &LinkName) -> Ident {
        link.ident()
    }
    fn load_about(&self, _link: &Ident, _point: &Ident) -> TokenStream {
        TokenStream::new()
    }
    fn add(&mut self, _link: &LinkName, _wrench: TokenStream) {}
    fn code(&mut self, _code: TokenStream) {}
    fn reaction(&mut self, reaction: Reaction) {
        self.reactions.push(reaction);
    }
    fn power(&mut self, _term: TokenStream) {}
    fn condition(&mut self, _term: TokenStream) {}
    fn reads(&self) -> &Reads {
        &self.reads
    }
}
