//! `guide(origin, angle)` and `guide(origin, angle) on LINK`: a line, fixed
//! or carried by a link (turning with the link's axis).

use super::closure::{f, Residuals, Scale};
use super::group::{GroupKind, Placed, Role, Solve};
use super::lane::{Lane, LaneGuide, Step, Vector};
use super::lane_shapes::{carried, OriginMotion};
use super::rates::RateCx;
use super::run::{Compile, ForceRunCx, LinkSlot, Me, PointSlot, RunCx, RunPose};
use super::tokens::{axis, local, unit_vector};
use crate::diag::Diagnostics;
use crate::keys::{LinkName, PointName};
use crate::model::{Origin, Stmt};
use crate::names::Family;
use crate::value::{lit, Value};
use mechanism_core::guide::Line;
use mechanism_core::{geometry, link, Point2};
use proc_macro2::TokenStream;
use quote::quote;
use syn::Ident;

/// How `guide` is written: its word, usage, arity and links.
pub(crate) const SPEC: super::word::Spec = super::word::Spec {
    word: super::word::KindWord::Guide,
    text: "guide",
    usage: "guide(POINT or (x, y), angle) or guide(POINT, LINK[, angle])",
    arity: super::word::Arity::Range(2, 3),
    links: "",
    inputs: &[],
    mode_at: None,
    mode_words: &[],
    group: None,
};

/// A `guide` statement.
pub(super) struct Guide<'a> {
    pub stmt: &'a Stmt,
    pub origin: &'a Origin,
    pub angle: &'a Value,
    pub carrier: Option<&'a Ident>,
}

impl<'a> GroupKind<'a> for Guide<'a> {
    fn references(&self) -> Vec<(&'a Ident, Role)> {
        let mut r = vec![];
        if let Origin::Point(p) = self.origin {
            r.push((p, Role::Point));
        }
        r.extend(self.carrier.map(|c| (c, Role::Link)));
        r
    }

    fn point_owner(&self) -> Option<Option<LinkName>> {
        None
    }

    fn position_values(&self) -> Vec<Value> {
        let mut v = Vec::new();
        if let Origin::Coords(x, y) = self.origin {
            v.extend([x.clone(), y.clone()]);
        }
        v.push(self.angle.clone());
        v
    }

    /// The line: its origin and its direction (a carried guide turns with
    /// its link's axis).
    fn position(&self, _cos_sin: bool) -> Solve {
        let origin = match self.origin {
            Origin::Point(p) => {
                let p = local(p);
                quote!(#p)
            }
            Origin::Coords(x, y) => {
                let (x, y) = (x.emit(), y.emit());
                quote!(::mechanism::Point2::new(#x, #y))
            }
        };
        let dir = match self.carrier {
            None => unit_vector(self.angle),
            Some(link) => {
                let axis = axis(link);
                if self.angle.fold() == Some(0.0) {
                    quote!(#axis)
                } else {
                    let u = unit_vector(self.angle);
                    quote!(::mechanism::link::local_offset(&#axis, &#u))
                }
            }
        };
        Solve::Own {
            expr: quote!(::mechanism::guide::Line { origin: #origin, dir: #dir }),
            ty: quote!(::mechanism::guide::Line<T>),
        }
    }

    /// A carried guide: the motion of its line (a fixed one has none).
    fn rates(&self, cx: &mut dyn RateCx) {
        let Some(link) = self.carrier else {
            return;
        };
        let accel = cx.accel();
        let n = if accel { Family::Gacc } else { Family::Gvel }.of(&self.stmt.name);
        let origin_motion = match self.origin {
            Origin::Point(p) if cx.moves(p) => {
                let v = cx.pfx().of(p);
                quote!(#v)
            }
            _ => quote!(::mechanism::Vector2::zeros()),
        };
        let w = cx
            .link_rate(link)
            .map(|w| quote!(#w))
            .unwrap_or_else(|| lit(0.0));
        let (body, ty) = if accel {
            (
                quote!(::mechanism::guide::LineAcceleration { a_origin: #origin_motion, alpha: #w }),
                quote!(::mechanism::guide::LineAcceleration<T>),
            )
        } else {
            (
                quote!(::mechanism::guide::LineVelocity { v_origin: #origin_motion, omega: #w }),
                quote!(::mechanism::guide::LineVelocity<T>),
            )
        };
        cx.code(quote!(let #n = #body;));
        cx.field(n, ty);
    }

    /// Its direction (fixed, or turned from its carrier link's axis) and,
    /// when carried through a point, its origin at that point.
    fn residuals(&self, r: &mut Residuals<'_>, link_axis: &dyn Fn(&Ident) -> TokenStream) {
        let n = r.pos(r.n);
        let a = f(self.angle);
        let Some(carrier) = self.carrier else {
            r.push_scaled(
                "fixed guide direction",
                quote!(norm(sub(vc(&#n.dir), turn([1.0, 0.0], #a)))),
                Scale::Direction,
            );
            return;
        };
        let ax = link_axis(carrier);
        if let Origin::Point(p) = self.origin {
            let p = r.pos(p);
            r.push(
                "carried guide origin",
                quote!(norm(sub(pt(&#n.origin), pt(&#p)))),
            );
        }
        r.push_scaled(
            "carried guide direction",
            quote!(norm(sub(vc(&#n.dir), turn(#ax, #a)))),
            Scale::CarriedDirection,
        );
    }

    fn reads_axis(&self) -> Option<&'a Ident> {
        self.carrier
    }

    fn describe(&self) -> String {
        let n = &self.stmt.name;
        match self.carrier {
            None => format!("fixed guide `{n}`"),
            Some(l) => format!("guide `{n}` carried by `{l}`"),
        }
    }

    fn point_kind(&self) -> Option<&'static str> {
        None
    }

    fn point_moves(
        &self,
        _link_turns: &dyn Fn(&Ident) -> bool,
        _moves: &dyn Fn(&Ident) -> bool,
    ) -> bool {
        false
    }

    /// Through a point of what carries it: a point of its link, or a
    /// ground point for a fixed guide.
    fn check_placed(&self, plan: &dyn Placed, errors: &mut Diagnostics) {
        let Origin::Point(p) = self.origin else {
            return;
        };
        match self.carrier {
            Some(link) => {
                if let Some(points) = plan.link_points(link) {
                    if !points.contains(&PointName::of(p)) {
                        errors.push(
                            p.span(),
                            format!("a guide carried by `{link}` must pass through one of its points, and `{p}` is not on it"),
                        );
                    }
                }
            }
            None => {
                let name = PointName::of(p);
                if plan.is_defined(p) && !plan.is_ground_point(&name) {
                    errors.push(
                        p.span(),
                        format!("a fixed guide must pass through a ground point, and `{name}` moves; to slide on a moving link write `guide({name}, LINK)`"),
                    );
                }
            }
        }
    }

    /// Its lane code in the batch kernel (`None`: an argument the kernel
    /// does not know; the batch then takes the scalar path).
    fn lane(&self, lane: &mut Lane, s: &mut Step<'_>) -> Option<()> {
        lane_steps(lane, s, self.origin, self.angle, self.carrier)
    }

    linkless_facets!('a);
}

/// A guide line through `origin` at `angle` (radians): fixed, a
/// `mechanism::__private::lane::Line` local `ln_NAME` whose motion is `None`; or
/// carried by the link `carrier`, its direction the link's axis turned by
/// `angle` (`lane::carried`), its motion `LineVelocity` / `LineAcceleration`
/// locals (`gv_NAME`, `ga_NAME`) from the origin's motion and the link's
/// rates. Defines no point. `None` when the origin point or the carrier is
/// not known yet.
fn lane_steps(
    lane: &Lane,
    s: &mut Step,
    origin: &Origin,
    angle: &Value,
    carrier: Option<&Ident>,
) -> Option<()> {
    s.defines_no_point();
    let line = Family::LaneLine.of(s.name);
    let origin = match origin {
        Origin::Point(p) => OriginMotion::point(lane.point(p)?),
        Origin::Coords(x, y) => OriginMotion::fixed(x, y),
    };
    let guide = match carrier {
        None => {
            let Vector { x: ox, y: oy } = &origin.p;
            let Vector { x: dx, y: dy } = s.unit(angle);
            s.emit(quote! {
                let #line = ::mechanism::__private::lane::Line { ox: #ox, oy: #oy, dx: #dx, dy: #dy };
            });
            let none = quote!(::core::option::Option::None);
            LaneGuide {
                line,
                gv: none.clone(),
                ga: none,
                omega: quote!(zero),
                alpha: quote!(zero),
            }
        }
        Some(link) => carried(lane, s, line, &origin, angle, link)?,
    };
    s.defines_guide(guide);
    Some(())
}

impl super::run::RunKind for Guide<'_> {
    fn compile(&self, cx: &Compile<'_>) -> Box<dyn super::run::Step> {
        let origin = match self.origin {
            Origin::Point(p) => GuideOrigin::Point(cx.point(p)),
            Origin::Coords(x, y) => GuideOrigin::At(Point2::new(cx.num(x), cx.num(y))),
        };
        Box::new(GuideRun {
            me: cx.me(self.stmt),
            origin,
            unit: geometry::unit(cx.num(self.angle)),
            carrier: self.carrier.map(|l| cx.link(l)),
        })
    }
}

/// Where a compiled guide's line passes.
enum GuideOrigin {
    /// A solved point.
    Point(PointSlot),
    /// Fixed coordinates (L).
    At(Point2<f64>),
}

/// A guide, compiled: its origin, its unit direction (in the carrier's
/// frame when carried) and its carrier.
struct GuideRun {
    me: Me,
    origin: GuideOrigin,
    unit: mechanism_core::Vector2<f64>,
    carrier: Option<LinkSlot>,
}

impl super::run::Step for GuideRun {
    fn group(&self) -> &'static str {
        self.me.group
    }

    fn walks(&self) -> super::run::Walks {
        super::run::Walks {
            rates: self.carrier.is_some(),
            forces: false,
        }
    }

    fn position(&self, pose: &mut RunPose) -> Result<Option<f64>, mechanism_core::Error<f64>> {
        let origin = match self.origin {
            GuideOrigin::Point(p) => pose.point(p),
            GuideOrigin::At(p) => p,
        };
        let dir = match self.carrier {
            None => self.unit,
            Some(l) => link::local_offset(&pose.axis(l), &self.unit),
        };
        pose.found_line(&self.me, Line { origin, dir });
        Ok(None)
    }

    /// A carried guide's motion: its origin's and its carrier's rate.
    fn rates(&self, cx: &mut RunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        let Some(link) = self.carrier else {
            return Ok(());
        };
        let origin_motion = match self.origin {
            GuideOrigin::Point(p) if cx.moves(p) => cx.motion_of(p),
            _ => mechanism_core::Vector2::zeros(),
        };
        let w = cx.link_rate(link).unwrap_or(0.0);
        if cx.accel() {
            let a = mechanism_core::guide::LineAcceleration {
                a_origin: origin_motion,
                alpha: w,
            };
            cx.set_guide_acc(&self.me, a);
        } else {
            let v = mechanism_core::guide::LineVelocity {
                v_origin: origin_motion,
                omega: w,
            };
            cx.set_guide_vel(&self.me, v);
        }
        Ok(())
    }

    fn forces(&self, _cx: &mut ForceRunCx<'_>) -> Result<(), mechanism_core::Error<f64>> {
        Ok(())
    }

    fn link_dir(&self, _index: usize, _pose: &RunPose) -> mechanism_core::Vector2<f64> {
        mechanism_core::Vector2::x()
    }
}
