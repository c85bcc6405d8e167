//! The known loads of the force analysis: inertia forces and couples and
//! weights of the links with mass, external forces and couples, each added
//! to its link's load (about the link's reference point) with its power for
//! the balance. Masses and moments of inertia not known at expansion are
//! checked at run time.

use super::ForceEmitter;
use crate::emit::tag;
use crate::keys::{LinkName, PointName};
use crate::kinds::{self, forces::ForceCx};
use crate::model::{ForceSpec, ForceSpecValue, Kind, Local, MassSpec, Model, Stmt, TorqueSpec};
use crate::names::Family;
use crate::value::Value;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

impl ForceEmitter<'_> {
    /// Known loads: inertia and weight of every link with mass, external
    /// forces and couples.
    pub(super) fn known_loads(&mut self) {
        let k = &self.model.kinetics;
        if let Some((_, gx, gy)) = &k.gravity {
            let (gx, gy) = (gx.emit(), gy.emit());
            self.code
                .extend(quote!(let gravity = ::mechanism::Vector2::new(#gx, #gy);));
        }
        for (link, parts) in masses_by_link(&k.masses) {
            match parts.as_slice() {
                [m] => self.mass(m),
                _ => self.mass_parts(&link, &parts),
            }
        }
        for (n, f) in k.forces.iter().enumerate() {
            self.external_force(n, f);
        }
        for (n, t) in k.torques.iter().enumerate() {
            self.torque(n, t);
        }
    }

    /// The inertia force, weight and inertia couple of a link with mass, and
    /// their powers.
    fn mass(&mut self, m: &MassSpec) {
        let link = LinkName::of(&m.link);
        let forces = self.part_forces(m, Part::whole(&link));
        let couple = match (&m.inertia, self.rate_fields(&m.link)) {
            (Some(j), Some((w, alpha))) if j.fold() != Some(0.0) => {
                let (w, alpha) = (self.reads.vel(&w), self.reads.acc(&alpha));
                let j = self.checked(j, &link, Quantity::Inertia);
                let c = Family::PwInertiaCouple.of(&link);
                self.code.extend(quote!(let #c = -(#j * #alpha);));
                self.power.push(quote!(#c * #w));
                Some(quote!(#c))
            }
            _ => None,
        };
        self.place_part(&link, m, forces);
        if let Some(c) = couple {
            self.add(&link, quote!(::mechanism::force::Wrench::couple(#c)));
        }
    }

    /// The loads of a link with several `mass` statements (parts): each
    /// part's inertia force and weight at its own point (the d'Alembert
    /// loads are linear in the mass distribution, so this is exactly the
    /// combined body's `-M a_G`, `M g` through the combined centre and the
    /// couple `-J_G alpha` by the parallel-axis theorem, with no point at the
    /// combined centre to compute), and one inertia couple `-(sum j_k)
    /// alpha`, the sum folded when every `j` is literal. Locals are numbered
    /// by part from 1 in the order written (`pw_inertia_force_LINK_1`).
    fn mass_parts(&mut self, link: &LinkName, parts: &[&MassSpec]) {
        let mut inertias = Vec::new();
        for (k, m) in parts.iter().enumerate() {
            let part = Part {
                link,
                number: Some(k + 1),
            };
            let forces = self.part_forces(m, part);
            self.place_part(link, m, forces);
            if let Some(j) = m.inertia.as_ref().filter(|j| j.fold() != Some(0.0)) {
                inertias.push((part, j));
            }
        }
        let Some((w, alpha)) = self.rate_fields(&parts[0].link) else {
            return;
        };
        if inertias.is_empty() {
            return;
        }
        let (w, alpha) = (self.reads.vel(&w), self.reads.acc(&alpha));
        let folded: Option<f64> = inertias.iter().map(|(_, j)| j.fold()).sum();
        let j = match folded {
            Some(sum) => crate::value::lit(sum),
            None => {
                let terms: Vec<TokenStream> = inertias
                    .iter()
                    .map(|(part, j)| self.checked_as(j, *part, Quantity::Inertia))
                    .collect();
                sum(&terms).expect("at least one part has a moment of inertia")
            }
        };
        let c = Family::PwInertiaCouple.of(link);
        self.code.extend(quote!(let #c = -((#j) * #alpha);));
        self.power.push(quote!(#c * #w));
        self.add(link, quote!(::mechanism::force::Wrench::couple(#c)));
    }

    /// A mass part's inertia force (`pw_inertia_force_PART = -m a_G`, when
    /// its centre moves) and weight (`pw_weight_PART = m g`, with gravity):
    /// their code emitted (the mass checked first when not literal), the
    /// forces and their powers returned for [`Self::place_part`].
    fn part_forces(&mut self, m: &MassSpec, part: Part<'_>) -> PartForces {
        let gravity = self.model.kinetics.gravity.is_some();
        let mass = self.checked_as(&m.mass, part, Quantity::Mass);
        let v_g = self.velocity(&m.at);
        let mut out = PartForces::default();
        if v_g.is_some() {
            let (f, a) = (
                Family::PwInertiaForce.of(part.suffix()),
                self.reads.acc(&Family::Acc.of(&m.at)),
            );
            self.code.extend(quote!(let #f = #a * (-#mass);));
            out.terms.push(quote!(#f));
        }
        if gravity {
            let w = Family::PwWeight.of(part.suffix());
            self.code.extend(quote!(let #w = gravity * #mass;));
            out.terms.push(quote!(#w));
        }
        if let Some(v) = v_g {
            out.powers = out
                .terms
                .iter()
                .map(|t| quote!(::mechanism::geometry::dot(&#t, &#v)))
                .collect();
        }
        out
    }

    /// A part's forces and powers added: the powers to the balance, the sum
    /// of the forces to `link`'s load at the part's centre.
    fn place_part(&mut self, link: &LinkName, m: &MassSpec, forces: PartForces) {
        self.power.extend(forces.powers);
        if let Some(total) = sum(&forces.terms) {
            self.force_on(link, total, &m.at);
        }
    }

    /// External force number `n` and its power.
    fn external_force(&mut self, n: usize, f: &ForceSpec) {
        let link = match &f.on {
            Some(l) => LinkName::of(l),
            None => self.plan.links_with_point(&PointName::of(&f.at))[0].clone(),
        };
        let local = Family::PwForce.of(n);
        let value = match &f.value {
            ForceSpecValue::Components(x, y) => {
                let (x, y) = (x.emit(), y.emit());
                quote!(::mechanism::Vector2::new(#x, #y))
            }
            ForceSpecValue::Along(guide, v) => {
                let (guide, v) = (self.reads.pos(guide), v.emit());
                quote!(#guide.dir * #v)
            }
        };
        self.code.extend(quote!(let #local = #value;));
        if let Some(v) = self.velocity(&f.at) {
            self.power
                .push(quote!(::mechanism::geometry::dot(&#local, &#v)));
        }
        self.force_on(&link, quote!(#local), &f.at);
    }

    /// External couple number `n` and its power.
    fn torque(&mut self, n: usize, t: &TorqueSpec) {
        let local = Family::PwTorque.of(n);
        let value = t.value.emit();
        self.code.extend(quote!(let #local = #value;));
        if let Some((w, _)) = self.rate_fields(&t.on) {
            let w = self.reads.vel(&w);
            self.power.push(quote!(#local * #w));
        }
        self.add(
            &LinkName::of(&t.on),
            quote!(::mechanism::force::Wrench::couple(#local)),
        );
    }

    /// A mass or moment of inertia of `link` as the force analysis uses it. A
    /// literal one was checked at expansion (`model`); one that depends on
    /// `params` or `loads` is checked here, at run time, into a local: a mass
    /// must be finite and positive, a moment of inertia finite and not
    /// negative, else a typed error naming the group that creates the link
    /// (a negative mass would give finite, consistent and wrong reactions).
    fn checked(&mut self, value: &Value, link: &LinkName, quantity: Quantity) -> TokenStream {
        self.checked_as(value, Part::whole(link), quantity)
    }

    /// [`Self::checked`] into the local named after `part`.
    fn checked_as(&mut self, value: &Value, part: Part<'_>, quantity: Quantity) -> TokenStream {
        let link = part.link;
        if value.fold().is_some() {
            return value.emit();
        }
        let Some(stmt) = self
            .model
            .stmts
            .iter()
            .find(|s| s.links.iter().any(|l| *link == *l))
        else {
            return value.emit();
        };
        let v = value.emit();
        let primitive = primitive(stmt);
        let t = tag(stmt);
        let (local, check, what) = match quantity {
            Quantity::Mass => (
                Family::PwMass.of(part.suffix()),
                quote!(positive),
                format!("mass of `{link}`{}", part.text()),
            ),
            Quantity::Inertia => (
                Family::PwInertia.of(part.suffix()),
                quote!(non_negative),
                format!("moment of inertia of `{link}`{}", part.text()),
            ),
        };
        self.code.extend(quote!(
            let #local = ::mechanism::geometry::#check(#v, #primitive, #what) #t;
        ));
        quote!(#local)
    }
}

/// The masses grouped by link, links in the order of their first `mass`,
/// parts in the order written.
pub(crate) fn masses_by_link(masses: &[MassSpec]) -> Vec<(LinkName, Vec<&MassSpec>)> {
    let mut out: Vec<(LinkName, Vec<&MassSpec>)> = Vec::new();
    for m in masses {
        let link = LinkName::of(&m.link);
        match out.iter_mut().find(|(l, _)| *l == link) {
            Some((_, parts)) => parts.push(m),
            None => out.push((link, vec![m])),
        }
    }
    out
}

/// A mass of a link as the force code names its locals: the link's only
/// mass (locals named after `LINK`) or its part `k` (from 1, in the order
/// written; locals named after `LINK_k`).
#[derive(Clone, Copy)]
struct Part<'a> {
    link: &'a LinkName,
    number: Option<usize>,
}

impl<'a> Part<'a> {
    /// The link's only mass.
    fn whole(link: &'a LinkName) -> Self {
        Part { link, number: None }
    }

    /// What the locals are named after: `LINK` or `LINK_k`.
    fn suffix(self) -> String {
        match self.number {
            Some(k) => format!("{}_{k}", self.link),
            None => self.link.to_string(),
        }
    }

    /// ` (part k)` in messages, empty for a link's only mass.
    fn text(self) -> String {
        match self.number {
            Some(k) => format!(" (part {k})"),
            None => String::new(),
        }
    }
}

/// A mass part's inertia force and weight terms, and their powers.
#[derive(Default)]
struct PartForces {
    terms: Vec<TokenStream>,
    powers: Vec<TokenStream>,
}

/// `a + b + ..` of `terms`, `None` for none.
fn sum(terms: &[TokenStream]) -> Option<TokenStream> {
    let (first, rest) = terms.split_first()?;
    Some(rest.iter().fold(first.clone(), |acc, t| quote!(#acc + #t)))
}

/// What [`ForceEmitter::checked`] checks.
#[derive(Clone, Copy)]
enum Quantity {
    /// A link's mass: finite and positive.
    Mass,
    /// A link's moment of inertia about its centre of mass: finite, `>= 0`.
    Inertia,
}

/// The core's tag of the primitive a statement calls (for run-time errors).
fn primitive(stmt: &Stmt) -> TokenStream {
    let name = format_ident!("{}", kinds::of(stmt).primitive());
    quote!(::mechanism::Primitive::#name)
}

/// The doc comment's sentence on the links with several masses: each such
/// link's combined mass `M = sum m_k`, centre `G = sum m_k p_k / M` (from
/// the parts' common base point, in the link's frame: along its axis and
/// its left normal) and `J_G = sum (j_k + m_k |p_k - G|^2)`, folded at
/// expansion when every part's `m` and `j` is literal and its centre is the
/// base point or a `point(LINK, from BASE, ..)` with literal offsets, the same
/// base for every part; else the parts' count alone. Empty when every link
/// has at most one mass (their expansions are unchanged).
pub(super) fn parts_doc(model: &Model) -> String {
    let mut out = String::new();
    for (link, parts) in masses_by_link(&model.kinetics.masses) {
        if parts.len() < 2 {
            continue;
        }
        out.push_str(&format!(" `{link}` carries {} masses", parts.len()));
        match combined(model, &link, &parts) {
            Some((m, base, g, j)) => out.push_str(&format!(
                ", combined: mass {m}, centre ({}, {}) from `{base}` in `{link}`'s frame (along its axis, along its left normal), moment of inertia {j} about it.",
                g.x, g.y
            )),
            None => out.push('.'),
        }
    }
    if out.is_empty() {
        return out;
    }
    format!(" Several masses on one link are parts of it, each loading it at its own centre:{out}")
}

/// [`parts_doc`]'s folded merge of the parts of `link`: mass, base point,
/// centre from it in the link's frame, moment of inertia about the centre.
fn combined(
    model: &Model,
    link: &LinkName,
    parts: &[&MassSpec],
) -> Option<(f64, String, mechanism_core::Vector2<f64>, f64)> {
    use mechanism_core::Vector2;
    let mut base: Option<String> = None;
    let mut located = Vec::new();
    for m in parts {
        let mass = m.mass.fold()?;
        let j = match &m.inertia {
            Some(j) => j.fold()?,
            None => 0.0,
        };
        let at = m.at.to_string();
        let point = model
            .stmts
            .iter()
            .find(|s| s.name == at)
            .and_then(|s| match &s.kind {
                Kind::Point {
                    link: l,
                    from,
                    local,
                } if *link == *l => Some((from.to_string(), local)),
                _ => None,
            });
        let (from, offset) = match point {
            Some((from, Local::Cartesian(x, y))) => (from, Vector2::new(x.fold()?, y.fold()?)),
            Some((from, Local::Polar(d, a))) => {
                let (d, a) = (d.fold()?, a.fold()?);
                (from, Vector2::new(d * a.cos(), d * a.sin()))
            }
            None => (at, Vector2::zeros()),
        };
        if base.get_or_insert_with(|| from.clone()) != &from {
            return None;
        }
        located.push((mass, j, offset));
    }
    let total: f64 = located.iter().map(|p| p.0).sum();
    let g = located.iter().map(|p| p.2 * p.0).sum::<Vector2<f64>>() / total;
    let j = located
        .iter()
        .map(|p| p.1 + p.0 * (p.2 - g).norm_squared())
        .sum();
    Some((total, base?, g, j))
}
