//! What the kinds' force code needs from the force emitter ([`ForceCx`]),
//! and the reaction fields they add to the forces struct ([`Reaction`]).
//! The same per-kind code runs against the emitter (code and fields) and
//! against [`FieldsOnly`] (the fields alone, for the stubs emitted on error).

use super::reads::Reads;
use crate::keys::LinkName;
use crate::keys::GROUND;
use crate::model::Stmt;
use crate::names::Family;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

/// A reaction field of the generated forces struct.
pub struct Reaction {
    /// Field name (`r_FROM_TO`, `drive_INPUT`).
    pub name: Ident,
    /// Field type.
    pub ty: TokenStream,
    /// Its value in the `forces` code.
    pub value: TokenStream,
    /// Its doc comment.
    pub doc: String,
    /// What it holds.
    pub held: Held,
}

/// What a reaction field holds, as `mechanism::structure::Fields` reads it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Held {
    /// A revolute joint's force (`Vector2`).
    Force,
    /// A prismatic pair's `PrismaticReaction`: read as `NAME.force` (the
    /// normal force as a vector) and `NAME.moment` (its couple).
    Prismatic,
    /// A driver's torque (a moment).
    Torque,
    /// A slider's or an actuator's force along its line (a scalar).
    Push,
}

/// The force emitter as the kinds see it: the bodies around a group, the
/// loads of its links, and where its code, fields, power terms and
/// conditioning go.
pub trait ForceCx {
    /// The body owning a point (`None`: the ground or unknown).
    fn body_of_point(&self, point: &Ident) -> Option<LinkName>;
    /// The body carrying a guide (`None`: the ground).
    fn body_of_guide(&self, guide: &Ident) -> Option<LinkName>;
    /// The reference point a link's load is accumulated about.
    fn reference(&self, link: &LinkName) -> Ident;
    /// The load of `link` as a wrench about `point` (code).
    fn load_about(&self, link: &Ident, point: &Ident) -> TokenStream;
    /// Adds a wrench (code about the link's reference point) to a link's load.
    fn add(&mut self, link: &LinkName, wrench: TokenStream);
    /// Appends code to the `forces` method.
    fn code(&mut self, code: TokenStream);
    /// Adds a field to the forces struct.
    fn reaction(&mut self, reaction: Reaction);
    /// Adds a driver's power term to the balance.
    fn power(&mut self, term: TokenStream);
    /// Adds a group's conditioning (its relative pivot) to `condition`.
    fn condition(&mut self, term: TokenStream);
    /// The recorder of the code's reads of `pos`, `vel` and `acc`.
    fn reads(&self) -> &Reads;

    /// A force `force` (code) acting on `link` at point `at`, as a wrench
    /// about the link's reference point.
    fn force_on(&mut self, link: &LinkName, force: TokenStream, at: &Ident) {
        let r = self.reference(link);
        let wrench = if *at == r {
            quote!(::mechanism::force::Wrench::new(#force, <T as ::mechanism::Real>::lit(0.0)))
        } else {
            let (p_at, p_r) = (self.reads().pos(at), self.reads().pos(&r));
            quote!(::mechanism::force::Wrench::force_at(&(#force), &#p_at, &#p_r))
        };
        self.add(link, wrench);
    }

    /// A prismatic reaction `rx` (about point `about`) negated onto `body`.
    fn prismatic_on(&mut self, body: Option<LinkName>, rx: TokenStream, about: &Ident) {
        if let Some(body) = body {
            let r = self.reference(&body);
            let wrench = if *about == r {
                quote!(-(#rx).wrench())
            } else {
                let (p_about, p_r) = (self.reads().pos(about), self.reads().pos(&r));
                quote!(-(#rx).wrench_about(&#p_about, &#p_r))
            };
            self.add(&body, wrench);
        }
    }

    /// An outer revolute joint at `point` whose reaction on the group is
    /// `rx.field`: passes the reaction, negated, to the body that owns the
    /// point (nothing for the ground) and returns that body.
    fn pass_revolute(&mut self, point: &Ident, rx: &Ident, field: &str) -> Option<LinkName> {
        let body = self.body_of_point(point);
        if let Some(b) = &body {
            let field = format_ident!("{}", field);
            self.force_on(b, quote!(-#rx.#field), point);
        }
        body
    }

    /// `let rx_NAME = CALL.map_err(..)?;`
    fn solve(&mut self, stmt: &Stmt, call: TokenStream) {
        let (rx, t) = (rx(stmt), super::tokens::tag(stmt));
        self.code(quote!(let #rx = #call #t;));
    }

    /// The loads of the two links of a group about `point`.
    fn loads_about(&self, stmt: &Stmt, point: &Ident) -> (TokenStream, TokenStream) {
        (
            self.load_about(&stmt.links[0], point),
            self.load_about(&stmt.links[1], point),
        )
    }
}

/// `rx_NAME`: the local holding a statement's reactions.
pub fn rx(stmt: &Stmt) -> Ident {
    Family::Rx.of(&stmt.name)
}

/// The name of the body on the far side of a joint, for field names.
pub fn body_name(body: &Option<LinkName>) -> String {
    body.as_ref()
        .map_or_else(|| GROUND.into(), ToString::to_string)
}

/// The reaction of a revolute joint: the force of `from` (a body, or the
/// ground) on `to` at `at`, field `field` of `rx`.
pub fn revolute(
    rx: &Ident,
    from: &Option<LinkName>,
    to: &Ident,
    at: &Ident,
    field: &str,
) -> Reaction {
    let from = body_name(from);
    let field = format_ident!("{}", field);
    Reaction {
        name: Family::Reaction.pair(&from, to),
        ty: quote!(::mechanism::Vector2<T>),
        value: quote!(#rx.#field),
        doc: format!("Force of `{from}` on `{to}` at `{at}` (force units, global frame)."),
        held: Held::Force,
    }
}

/// The reaction of a prismatic pair of `from` on `to`, its couple taken
/// about `about`, field `field` of `rx`.
pub fn prismatic(
    rx: &Ident,
    from: &Option<LinkName>,
    to: &Ident,
    about: &Ident,
    field: &str,
) -> Reaction {
    let from = body_name(from);
    let field = format_ident!("{}", field);
    Reaction {
        name: Family::Reaction.pair(&from, to),
        ty: quote!(::mechanism::force::PrismaticReaction<T>),
        value: quote!(#rx.#field),
        doc: format!(
            "Reaction of the prismatic pair of `{from}` on `{to}`: normal force (signed, along the left normal of the sliding direction) and couple about `{about}` (counter-clockwise positive)."
        ),
        held: Held::Prismatic,
    }
}

/// The driving effort of `input`, field `field` of `rx` (a torque or a push
/// along the driver's line, as `held` says), documented by `doc`.
pub fn drive(rx: &Ident, input: &Ident, field: &str, held: Held, doc: String) -> Reaction {
    let field = format_ident!("{}", field);
    Reaction {
        name: Family::Drive.of(input),
        ty: quote!(T),
        value: quote!(#rx.#field),
        doc,
        held,
    }
}

/// The joint between the two links of a group, at `at`.
pub fn inner(
    rx: &Ident,
    links: &[Ident],
    at: &Ident,
    field: &str,
    prismatic_pair: bool,
) -> Reaction {
    let from = Some(LinkName::of(&links[0]));
    if prismatic_pair {
        prismatic(rx, &from, &links[1], at, field)
    } else {
        revolute(rx, &from, &links[1], at, field)
    }
}
