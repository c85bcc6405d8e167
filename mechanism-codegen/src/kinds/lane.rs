//! The lane machinery of the batch kernel (`__lane_batch`): what the
//! statements solved so far have made known (points, links, guides, slides,
//! as locals of the kernel's loop body), one [`Step`] per statement that each
//! kind's `GroupKind::lane` fills (shapes shared by several kinds are in
//! `lane_shapes`), and the kernel around them (`emit::batch`).
//!
//! Every local of the loop body is named after the statement that makes it:
//! `p_A_x` / `v_A_x` / `a_A_x` a point's position, velocity and acceleration
//! components, `g_A` the group solution (a `mechanism::__private::lane` struct),
//! `w_link3` / `al_link3` a link's angular velocity and acceleration,
//! `s0_B` / `sd0_B` / `sdd0_B` a slide and its rates, `ln_line` a guide's
//! `mechanism::__private::lane::Line`. Values that do not depend on the element (a unit
//! vector at a run-time angle, `u_NAME`; the sign of a run-time assembly
//! mode, `m_NAME`) are computed once before the loop.

use crate::keys::{GuideName, LinkName, PointName, SlideName};
use crate::model::{Mode, Stmt};
use crate::names::Family;
use crate::value::{lit, Value};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use std::collections::{BTreeMap, BTreeSet};
use syn::Ident;

/// The x and y locals of one planar vector of the loop body.
#[derive(Clone)]
pub(crate) struct Pair {
    pub x: Ident,
    pub y: Ident,
}

/// Per-statement names of the lane code: `PREFIX_NAME_x` and `PREFIX_NAME_y`
/// (`p`, `v`, `a` for a point's position, velocity and acceleration, `o` for
/// a link point's offset from its reference point).
pub(crate) fn pv(family: Family, name: &Ident) -> Pair {
    Pair {
        x: family.coord(name, "x"),
        y: family.coord(name, "y"),
    }
}

/// A point's locals: position (`px`, `py`, in the definition's length unit),
/// velocity (`vx`, `vy`, length per second) and acceleration (`ax`, `ay`,
/// length per second squared). The velocity and acceleration locals exist
/// only when the kernel goes that far.
#[derive(Clone)]
pub(crate) struct PointLocals {
    pub px: Ident,
    pub py: Ident,
    pub vx: Ident,
    pub vy: Ident,
    pub ax: Ident,
    pub ay: Ident,
}

impl PointLocals {
    /// The locals of the point `name` (`p_NAME_x` ... `a_NAME_y`).
    pub fn of(name: &Ident) -> PointLocals {
        let (p, v, a) = (
            pv(Family::LanePos, name),
            pv(Family::LaneVel, name),
            pv(Family::LaneAcc, name),
        );
        PointLocals {
            px: p.x,
            py: p.y,
            vx: v.x,
            vy: v.y,
            ax: a.x,
            ay: a.y,
        }
    }
}

/// A planar vector as two expressions (literals, locals or field reads).
#[derive(Clone)]
pub(crate) struct Vector {
    pub x: TokenStream,
    pub y: TokenStream,
}

/// A link in the lane code: unit axis, angle expression (radians, wrapped
/// to `(-pi, pi]`), angular velocity (rad/s) and acceleration (rad/s^2)
/// (expressions: a link that turns with a guide's body uses that body's, a
/// link that never turns `zero`).
pub(crate) struct LaneLink {
    pub axis: Vector,
    pub angle: TokenStream,
    pub omega: TokenStream,
    pub alpha: TokenStream,
}

impl LaneLink {
    /// A link along the vector `direction`, divided by `length` when given
    /// (a unit vector otherwise): its axis, its angle (`lane::angle` of the
    /// vector: a positive factor does not change it), its rates.
    pub fn along(
        direction: Vector,
        length: Option<&TokenStream>,
        omega: TokenStream,
        alpha: TokenStream,
    ) -> LaneLink {
        let Vector { x, y } = direction;
        let axis = match length {
            Some(l) => Vector {
                x: quote!((#x / #l)),
                y: quote!((#y / #l)),
            },
            None => Vector {
                x: x.clone(),
                y: y.clone(),
            },
        };
        LaneLink {
            axis,
            angle: quote!(::mechanism::__private::lane::angle(#y, #x)),
            omega,
            alpha,
        }
    }

    /// The link's angle, angular velocity or angular acceleration for level
    /// 0, 1 or 2.
    fn at(&self, level: usize) -> &TokenStream {
        match level {
            0 => &self.angle,
            1 => &self.omega,
            _ => &self.alpha,
        }
    }
}

/// A guide in the lane code: the `mechanism::__private::lane::Line` local, the body's
/// motion as `Option<&LineVelocity>` / `Option<&LineAcceleration>`
/// expressions (`None` for a fixed guide, so its terms fold away), and the
/// body's angular velocity and acceleration (for the blocks sliding on it).
pub(crate) struct LaneGuide {
    pub line: Ident,
    pub gv: TokenStream,
    pub ga: TokenStream,
    pub omega: TokenStream,
    pub alpha: TokenStream,
}

/// A link's own rate locals, made by the statement that creates the link:
/// `w_LINK` (rad/s) and `al_LINK` (rad/s^2).
pub(crate) struct Rates {
    pub omega: Ident,
    pub alpha: Ident,
}

/// The locals of one slide slot of a statement: displacement `sK_NAME`
/// (length), its rate `sdK_NAME` and its second rate `sddK_NAME`.
pub(crate) struct SlideLocals {
    pub s: Ident,
    pub sd: Ident,
    pub sdd: Ident,
}

/// A slide's displacement and rates as expressions, by level.
struct Slide([TokenStream; 3]);

/// What the statements solved so far have made known, and the kernel's code
/// so far: `pre` (before the loop) and `body` (per element).
pub(crate) struct Lane {
    /// The kernel computes velocities.
    pub vel: bool,
    /// The kernel computes accelerations.
    pub acc: bool,
    pub(crate) pre: TokenStream,
    pub(crate) body: TokenStream,
    points: BTreeSet<PointName>,
    links: BTreeMap<LinkName, LaneLink>,
    guides: BTreeMap<GuideName, LaneGuide>,
    slides: BTreeMap<SlideName, Slide>,
}

impl Lane {
    /// An empty kernel computing `levels` levels (1 position, 2 velocity, 3
    /// acceleration).
    pub(crate) fn new(levels: usize) -> Lane {
        Lane {
            vel: levels > 1,
            acc: levels > 2,
            pre: TokenStream::new(),
            body: TokenStream::new(),
            points: BTreeSet::new(),
            links: BTreeMap::new(),
            guides: BTreeMap::new(),
            slides: BTreeMap::new(),
        }
    }

    /// Point `p`'s locals, `None` while no statement solved so far defines
    /// it.
    pub fn point(&self, p: &Ident) -> Option<PointLocals> {
        self.points
            .contains(&PointName::of(p))
            .then(|| PointLocals::of(p))
    }

    /// Link `l` as solved so far.
    pub fn link(&self, l: &Ident) -> Option<&LaneLink> {
        self.links.get(&LinkName::of(l))
    }

    /// Guide `g` as solved so far.
    pub fn guide(&self, g: &Ident) -> Option<&LaneGuide> {
        self.guides.get(&GuideName::of(g))
    }

    /// Appends a statement's code and makes what it defines known.
    ///
    /// Every value the scalar path checks is checked here too (finite),
    /// outputs or not, so that an element the kernel accepts is one the
    /// scalar path accepts: summed into `chk` (one add each, as a balanced
    /// tree), the sum is finite unless one of them is not (or, harmlessly,
    /// the sum overflows: the element then goes to the scalar path).
    pub(crate) fn commit(&mut self, step: Step) {
        let Step {
            name,
            own,
            pre,
            body,
            defines_point,
            mut checked,
            links,
            slides,
            guide,
            ..
        } = step;
        self.pre.extend(pre);
        self.body.extend(body);
        if defines_point {
            let PointLocals {
                px,
                py,
                vx,
                vy,
                ax,
                ay,
            } = own;
            checked.extend([quote!(#px), quote!(#py)]);
            if self.vel {
                checked.extend([quote!(#vx), quote!(#vy)]);
            }
            if self.acc {
                checked.extend([quote!(#ax), quote!(#ay)]);
            }
            self.points.insert(PointName::of(name));
        }
        if let Some(sum) = tree_sum(&checked) {
            self.body.extend(quote!(chk += #sum;));
        }
        if let Some(g) = guide {
            self.guides.insert(GuideName::of(name), g);
        }
        self.links.extend(links);
        self.slides.extend(slides);
    }

    /// The writes of the outputs into their slices, per level: `None` when
    /// an output is not known to the kernel.
    pub(crate) fn writes(&self, outputs: &[(Ident, OutputShape)], levels: usize) -> Option<Writes> {
        let mut w = Writes {
            slices: Vec::new(),
            code: TokenStream::new(),
        };
        let prefixes = [Family::Pos, Family::Vel, Family::Acc];
        let lanes = [Family::LanePos, Family::LaneVel, Family::LaneAcc];
        for li in 0..levels {
            for (o, shape) in outputs {
                if *shape == OutputShape::Point {
                    if !self.points.contains(&PointName::of(o)) {
                        return None;
                    }
                    let Pair { x, y } = pv(lanes[li], o);
                    w.push(prefixes[li].coord(o, "x"), quote!(#x));
                    w.push(prefixes[li].coord(o, "y"), quote!(#y));
                } else {
                    let (link, slide) = (LinkName::of(o), SlideName::of(o));
                    let v = match (self.links.get(&link), self.slides.get(&slide)) {
                        (Some(l), _) => l.at(li).clone(),
                        (None, Some(Slide(s))) => s[li].clone(),
                        (None, None) => return None,
                    };
                    w.push(prefixes[li].of(o), v);
                }
            }
        }
        Some(w)
    }
}

/// What an output of the position struct is (the velocity and
/// acceleration structs' outputs have the same names and shapes).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputShape {
    /// A point: two coordinates (`Point2<T>`, L).
    Point,
    /// A link angle (rad) or a slide displacement (L): one scalar `T`.
    Scalar,
}

impl OutputShape {
    /// The output's type in the generated structs.
    pub fn ty(self) -> TokenStream {
        match self {
            OutputShape::Point => quote!(::mechanism::Point2<T>),
            OutputShape::Scalar => quote!(T),
        }
    }
}

/// The output slices the kernel writes (its `&mut [T]` arguments, in
/// order) and the code writing element `k` of each.
pub(crate) struct Writes {
    pub(crate) slices: Vec<Ident>,
    pub(crate) code: TokenStream,
}

impl Writes {
    /// `slice[k] = value;` (angles are finite where their arguments are,
    /// which the kernel checks).
    fn push(&mut self, slice: Ident, value: TokenStream) {
        self.code.extend(quote! {
            #slice[k] = #value;
        });
        self.slices.push(slice);
    }
}

/// One statement's lane code while the per-kind function writes it: its
/// code, the values to check, and what it will make known (see
/// [`Lane::commit`]).
pub(crate) struct Step<'s> {
    stmt: &'s Stmt,
    /// The statement's name.
    pub name: &'s Ident,
    /// The locals of the point it defines (if it defines one).
    pub own: PointLocals,
    /// The local holding its `mechanism::__private::lane` group solution (`g_NAME`).
    pub g: Ident,
    pre: TokenStream,
    body: TokenStream,
    defines_point: bool,
    checked: Vec<TokenStream>,
    links: BTreeMap<LinkName, LaneLink>,
    slides: BTreeMap<SlideName, Slide>,
    guide: Option<LaneGuide>,
    /// An unnamed slide goes by the statement's name (`GroupKind::names_slide`).
    names_slide: bool,
}

impl<'s> Step<'s> {
    /// The sign of the statement's assembly mode `mode` (see [`sign`]), or
    /// of its run-time mode parameter: the local `m_NAME`, set once before
    /// the loop from `self.PARAM`.
    pub(crate) fn sign(&mut self, mode: &Mode) -> TokenStream {
        match &self.stmt.mode_param {
            Some(param) => {
                let local = Family::LaneSign.of(self.name);
                self.pre
                    .extend(quote!(let #local: T = ::mechanism::Mode::sign::<T>(self.#param);));
                quote!(#local)
            }
            None => sign(mode),
        }
    }

    /// The step of `stmt`, whose unnamed slide goes by the statement's
    /// name when `names_slide` (its kind's `GroupKind::names_slide`).
    pub(crate) fn new(stmt: &'s Stmt, names_slide: bool) -> Step<'s> {
        Step {
            stmt,
            name: &stmt.name,
            own: PointLocals::of(&stmt.name),
            g: Family::LaneGroup.of(&stmt.name),
            pre: TokenStream::new(),
            body: TokenStream::new(),
            defines_point: true,
            checked: Vec::new(),
            links: BTreeMap::new(),
            slides: BTreeMap::new(),
            guide: None,
            names_slide,
        }
    }

    /// Appends per-element code.
    pub fn emit(&mut self, code: TokenStream) {
        self.body.extend(code);
    }

    /// Values the kernel checks for finiteness (see [`Lane::commit`]).
    pub fn check(&mut self, values: impl IntoIterator<Item = TokenStream>) {
        self.checked.extend(values);
    }

    /// The statement defines no point (a guide, an RPR's slide).
    pub fn defines_no_point(&mut self) {
        self.defines_point = false;
    }

    /// How many links the statement creates.
    pub fn link_count(&self) -> usize {
        self.stmt.links.len()
    }

    /// The rate locals of the statement's `k`th link, `None` when it has
    /// fewer links.
    pub fn rates(&self, k: usize) -> Option<Rates> {
        let l = self.stmt.links.get(k)?;
        Some(Rates {
            omega: Family::LaneOmega.of(l),
            alpha: Family::LaneAlpha.of(l),
        })
    }

    /// The locals of slide slot `k`.
    pub fn slide_locals(&self, k: usize) -> SlideLocals {
        SlideLocals {
            s: format_ident!("s{}_{}", k, self.name),
            sd: format_ident!("sd{}_{}", k, self.name),
            sdd: format_ident!("sdd{}_{}", k, self.name),
        }
    }

    /// Makes the statement's `k`th link known as `link` (`None` when it has
    /// fewer links).
    pub fn defines_link(&mut self, k: usize, link: LaneLink) -> Option<()> {
        let name = LinkName::of(self.stmt.links.get(k)?);
        self.links.insert(name, link);
        Some(())
    }

    /// Makes slide slot `slot` known, under the name the definition gave it
    /// (an RPR's slide without one under the statement's name; other
    /// unnamed slides are no output and stay unknown).
    pub fn defines_slide(&mut self, slot: usize, l: &SlideLocals) {
        let slide = match self.stmt.slides.get(slot) {
            Some(Some(s)) => Some(SlideName::of(s)),
            _ if self.names_slide => Some(SlideName::of(self.name)),
            _ => None,
        };
        if let Some(name) = slide {
            let SlideLocals { s, sd, sdd } = l;
            self.slides
                .insert(name, Slide([quote!(#s), quote!(#sd), quote!(#sdd)]));
        }
    }

    /// Makes the statement's guide known.
    pub fn defines_guide(&mut self, guide: LaneGuide) {
        self.guide = Some(guide);
    }

    /// A unit vector at `angle` (radians): literals when the angle is
    /// literal, else the local `u_NAME` computed once before the loop with
    /// the scalar `geometry::unit`, as the scalar path does.
    pub fn unit(&mut self, angle: &Value) -> Vector {
        unit(angle, Family::LaneUnit.of(self.name), &mut self.pre)
    }

    /// Appends code run once before the loop.
    pub fn before_loop(&mut self, code: TokenStream) {
        self.pre.extend(code);
    }
}

/// A unit vector at `angle` as two expressions: literals when the angle is
/// literal, else a local computed once before the loop (named `id`) with the
/// scalar `geometry::unit`, as the scalar path does.
fn unit(angle: &Value, id: Ident, pre: &mut TokenStream) -> Vector {
    match angle.fold() {
        Some(a) => {
            let (s, c) = a.sin_cos();
            Vector {
                x: lit(c),
                y: lit(s),
            }
        }
        None => {
            let a = angle.emit();
            pre.extend(quote!(let #id = ::mechanism::geometry::unit(#a);));
            Vector {
                x: quote!(#id.x),
                y: quote!(#id.y),
            }
        }
    }
}

/// The sum of `terms` as a balanced tree of additions (`(a + b) + (c + d)`):
/// the same check as adding them one by one, with a dependency chain of
/// `log2(n)` additions instead of `n`, which a long loop body waits on.
pub(crate) fn tree_sum(terms: &[TokenStream]) -> Option<TokenStream> {
    match terms {
        [] => None,
        [t] => Some(t.clone()),
        _ => {
            let (lo, hi) = terms.split_at(terms.len() / 2);
            let (a, b) = (tree_sum(lo)?, tree_sum(hi)?);
            Some(quote!((#a + #b)))
        }
    }
}

/// The assembly mode as the sign literal the `mechanism::__private::lane` group
/// functions take: `1.0` for `plus`, `-1.0` for `minus`.
pub(crate) fn sign(mode: &Mode) -> TokenStream {
    lit(match mode {
        Mode::Plus => 1.0,
        Mode::Minus => -1.0,
    })
}
