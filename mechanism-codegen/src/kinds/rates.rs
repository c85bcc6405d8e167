//! What the kinds' velocity and acceleration code needs from the rate
//! emitter ([`RateCx`]): the motion of the points and guides a statement
//! uses, the rates of links, and where its code, stored values and slide
//! rates go. One `rates` method per kind writes either derivative.

use super::reads::Reads;
use super::tokens::{grp, tag};
use crate::model::Stmt;
use crate::names::Family;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::Ident;

/// The rate emitter as the kinds see it.
pub trait RateCx {
    /// `true` in `acceleration`, `false` in `velocity`.
    fn accel(&self) -> bool;
    /// `true` when point `p` moves.
    fn moves(&self, p: &Ident) -> bool;
    /// Motion of a known point as an optional argument of a core call.
    fn point_arg(&self, p: &Ident) -> TokenStream;
    /// A guide's velocity argument (`None` for a fixed guide).
    fn guide_vel(&self, g: &Ident) -> TokenStream;
    /// A guide's acceleration argument (`None` for a fixed guide).
    fn guide_acc(&self, g: &Ident) -> TokenStream;
    /// Angular rate of a link at this level (`None`: it does not turn).
    fn link_rate(&self, link: &Ident) -> Option<Ident>;
    /// A link's angular velocity read in `acceleration` (`None`: it does not turn).
    fn link_omega_in_accel(&self, link: &Ident) -> Option<TokenStream>;
    /// Appends code.
    fn code(&mut self, code: TokenStream);
    /// A value the struct may store, with its type.
    fn field(&mut self, name: Ident, ty: TokenStream);
    /// The rate of the current statement's slide `slot`.
    fn slide(&mut self, slot: usize, value: TokenStream);
    /// The recorder of the code's reads of `pos` and `vel` (`pos.grp_B`).
    fn reads(&self) -> &Reads;

    /// `vel_` or `acc_`: the family of point motions.
    fn pfx(&self) -> Family {
        Family::motion(self.accel())
    }

    /// `let LOCAL = VALUE;`, and LOCAL may be stored with type `ty`.
    fn named(&mut self, local: Ident, value: TokenStream, ty: TokenStream) {
        self.code(quote!(let #local = #value;));
        self.field(local, ty);
    }

    /// The rate of link `k` of `stmt` (`omega_LINK` or `alpha_LINK`).
    fn own(&self, stmt: &Stmt, k: usize) -> Ident {
        Family::link_rate(self.accel()).of(&stmt.links[k])
    }

    /// The motion of point `stmt` (`vel_NAME` or `acc_NAME`).
    fn motion(&self, stmt: &Stmt) -> Ident {
        self.pfx().of(&stmt.name)
    }

    /// A group's (or the actuator's) rate call: `let grp_v_NAME = CALL TAG;`
    /// (`grp_a_` in `acceleration`), stored with the core type `ty`
    /// (`VelocityNAME`/`AccelerationNAME` appended to `ty`, in `module`).
    /// Returns the local.
    fn group(&mut self, stmt: &Stmt, call: TokenStream, module: TokenStream, ty: &str) -> Ident {
        let accel = self.accel();
        let gr = if accel {
            Family::GrpAcc
        } else {
            Family::GrpVel
        }
        .of(&stmt.name);
        let t = tag(stmt);
        self.code(quote!(let #gr = #call #t;));
        let ty = format_ident!("{}{}", ty, if accel { "Acceleration" } else { "Velocity" });
        self.field(gr.clone(), quote!(::mechanism::#module::#ty<T>));
        gr
    }
}

/// `::mechanism::Vector2<T>`.
pub fn vec_ty() -> TokenStream {
    quote!(::mechanism::Vector2<T>)
}

/// The fields of a group's rates: its point's motion (`vc`/`ac`), its
/// links' rates (`omega1`/`alpha1`, ...), its slides' rates (`s_dot`/`s_ddot`, ...).
pub struct Pieces {
    /// The point's motion.
    pub point: TokenStream,
    /// The first link's rate.
    pub r1: TokenStream,
    /// The second link's rate.
    pub r2: TokenStream,
    /// The slide's rate.
    pub s: TokenStream,
    /// The first slide's rate.
    pub s1: TokenStream,
    /// The second slide's rate.
    pub s2: TokenStream,
}

impl Pieces {
    /// The names at this level.
    pub fn of(accel: bool) -> Self {
        if accel {
            Pieces {
                point: quote!(ac),
                r1: quote!(alpha1),
                r2: quote!(alpha2),
                s: quote!(s_ddot),
                s1: quote!(s1_ddot),
                s2: quote!(s2_ddot),
            }
        } else {
            Pieces {
                point: quote!(vc),
                r1: quote!(omega1),
                r2: quote!(omega2),
                s: quote!(s_dot),
                s1: quote!(s1_dot),
                s2: quote!(s2_dot),
            }
        }
    }
}

/// `(grp_NAME, grp_v_NAME)`: the position state and the velocity state a
/// group's rate calls read.
pub fn states(stmt: &Stmt) -> (Ident, Ident) {
    (grp(stmt), Family::GrpVel.of(&stmt.name))
}

/// The point motion and two link rates of a group shaped like the RRR (the
/// RRR and the actuator).
pub fn two_links(cx: &mut dyn RateCx, stmt: &Stmt, gr: &Ident) {
    let p = Pieces::of(cx.accel());
    let (pt, r1, r2) = (p.point, p.r1, p.r2);
    cx.named(cx.motion(stmt), quote!(#gr.#pt), vec_ty());
    cx.named(cx.own(stmt, 0), quote!(#gr.#r1), quote!(T));
    cx.named(cx.own(stmt, 1), quote!(#gr.#r2), quote!(T));
}
