//! The expansion-time evaluator: the position analysis in `f64`, walking the
//! plan's solve order and calling the same `mechanism-core` primitives, with
//! the same arguments, as the generated `position()`.

use crate::model::{Kind, Local, Mode, Model, Origin, Stmt};
use crate::plan::Checked;
use crate::value::Value;
use mechanism_core::guide::Line;
use mechanism_core::sweep::{self, Outcome};
use mechanism_core::{driver, dyad, geometry, link, Point2, Vector2};
use std::collections::BTreeMap;
use syn::Ident;

/// Most groups the expansion-time check handles (more: not checked).
pub const MAX_GROUPS: usize = 64;

/// Every value `position()` uses, for the statements in `order`.
pub fn position_values(model: &Model, order: &[usize]) -> Vec<Value> {
    let mut v = Vec::new();
    for &i in order {
        match &model.stmts[i].kind {
            Kind::Ground { x, y } => v.extend([x.clone(), y.clone()]),
            Kind::Guide { origin, angle, .. } => {
                if let Origin::Coords(x, y) = origin {
                    v.extend([x.clone(), y.clone()]);
                }
                v.push(angle.clone());
            }
            Kind::Crank { radius, .. } => v.push(radius.clone()),
            Kind::Slider { offset, .. } => v.push(offset.clone()),
            Kind::Actuator { l, .. } => v.push(l.clone()),
            Kind::Rrr { l1, l2, .. } => v.extend([l1.clone(), l2.clone()]),
            Kind::Rrp { l, offset, .. } => v.extend([l.clone(), offset.clone()]),
            Kind::Rpr { offset, .. } => v.push(offset.clone()),
            Kind::Prp {
                offset1, offset2, ..
            } => v.extend([offset1.clone(), offset2.clone()]),
            Kind::Rpp { slot, offset, .. } => v.extend([slot.clone(), offset.clone()]),
            Kind::Point { local, .. } => match local {
                Local::Polar(a, b) | Local::Cartesian(a, b) => v.extend([a.clone(), b.clone()]),
            },
        }
    }
    v
}

/// A dimension's folded value (NaN for one that does not fold: the check
/// runs only when every value the position analysis uses folds).
pub fn num(v: &Value) -> f64 {
    v.fold().unwrap_or(f64::NAN)
}

fn mode(m: Mode) -> mechanism_core::Mode {
    match m {
        Mode::Plus => mechanism_core::Mode::Plus,
        Mode::Minus => mechanism_core::Mode::Minus,
    }
}

/// What the statements solved so far have found: points, guides and the
/// unit axes of links, by name. A name not (yet) known reads as NaN, which
/// the primitives reject with a typed error.
#[derive(Default)]
struct Pose {
    points: BTreeMap<String, Point2<f64>>,
    guides: BTreeMap<String, Line<f64>>,
    axes: BTreeMap<String, Vector2<f64>>,
}

impl Pose {
    fn point(&self, n: &Ident) -> Point2<f64> {
        let nan = Point2::new(f64::NAN, f64::NAN);
        self.points.get(&n.to_string()).copied().unwrap_or(nan)
    }

    fn line(&self, n: &Ident) -> Line<f64> {
        let nan = Line {
            origin: Point2::new(f64::NAN, f64::NAN),
            dir: Vector2::new(f64::NAN, f64::NAN),
        };
        self.guides.get(&n.to_string()).copied().unwrap_or(nan)
    }

    fn axis(&self, n: &Ident) -> Vector2<f64> {
        let nan = Vector2::new(f64::NAN, f64::NAN);
        self.axes.get(&n.to_string()).copied().unwrap_or(nan)
    }

    /// Records a statement's point and its links' axes.
    fn found(&mut self, stmt: &Stmt, point: Option<Point2<f64>>, axes: &[Vector2<f64>]) {
        if let Some(p) = point {
            self.points.insert(stmt.name.to_string(), p);
        }
        for (link, axis) in stmt.links.iter().zip(axes) {
            self.axes.insert(link.to_string(), *axis);
        }
    }
}

/// The position analysis of the checked statements in `f64`.
pub struct Evaluator<'a> {
    model: &'a Model,
    order: &'a [usize],
    /// Group index of each checked statement.
    group: BTreeMap<usize, usize>,
    /// Input index by name.
    input: BTreeMap<String, usize>,
}

impl<'a> Evaluator<'a> {
    /// The evaluator of the statements `checked` solves, with the inputs in
    /// the order of the model's input struct.
    pub fn new(model: &'a Model, checked: &'a Checked) -> Self {
        Evaluator {
            model,
            order: &checked.order,
            group: checked
                .groups
                .iter()
                .enumerate()
                .map(|(k, &i)| (i, k))
                .collect(),
            input: model
                .inputs
                .iter()
                .enumerate()
                .map(|(k, i)| (i.name.to_string(), k))
                .collect(),
        }
    }

    /// Solves the position at inputs `q`: each checked group's scaled
    /// determinant, or the first failing group with its fault.
    pub fn solve(&self, q: &[f64]) -> Outcome<MAX_GROUPS> {
        let mut pose = Pose::default();
        let mut dets = [1.0; MAX_GROUPS];
        for &i in self.order {
            let stmt = &self.model.stmts[i];
            let g = self.group.get(&i).copied().unwrap_or(0);
            let input = |n: &Ident| {
                self.input
                    .get(&n.to_string())
                    .and_then(|&k| q.get(k))
                    .copied()
                    .unwrap_or(f64::NAN)
            };
            if let Some(det) = step(stmt, &mut pose, input).map_err(|e| (g, e.fault))? {
                dets[g] = det;
            }
        }
        Ok(dets)
    }
}

/// One statement's position: what it finds goes into `pose`; returns the
/// group's scaled determinant (`None` for statements without a rate system).
fn step(
    stmt: &Stmt,
    pose: &mut Pose,
    input: impl Fn(&Ident) -> f64,
) -> Result<Option<f64>, mechanism_core::Error<f64>> {
    match &stmt.kind {
        Kind::Ground { .. } | Kind::Guide { .. } | Kind::Point { .. } => {
            fixed(stmt, pose).map(|()| None)
        }
        Kind::Crank { .. } | Kind::Slider { .. } | Kind::Actuator { .. } => {
            driver_step(stmt, pose, input)
        }
        _ => group_step(stmt, pose).map(Some),
    }
}

/// Ground points, guides and points on links.
fn fixed(stmt: &Stmt, pose: &mut Pose) -> Result<(), mechanism_core::Error<f64>> {
    match &stmt.kind {
        Kind::Ground { x, y } => pose.found(stmt, Some(Point2::new(num(x), num(y))), &[]),
        Kind::Guide {
            origin,
            angle,
            carrier,
        } => {
            let origin = match origin {
                Origin::Point(p) => pose.point(p),
                Origin::Coords(x, y) => Point2::new(num(x), num(y)),
            };
            let u = geometry::unit(num(angle));
            let dir = match carrier {
                None => u,
                Some(l) => link::local_offset(&pose.axis(l), &u),
            };
            pose.guides
                .insert(stmt.name.to_string(), Line { origin, dir });
        }
        Kind::Point {
            link: on,
            from,
            local,
        } => {
            let local = match local {
                Local::Cartesian(x, y) => Vector2::new(num(x), num(y)),
                Local::Polar(d, a) => geometry::unit(num(a)) * num(d),
            };
            let p = link::point_position(&pose.point(from), &pose.axis(on), &local)?;
            pose.found(stmt, Some(p), &[]);
        }
        _ => {}
    }
    Ok(())
}

/// Cranks, sliders and actuators at their inputs.
fn driver_step(
    stmt: &Stmt,
    pose: &mut Pose,
    input: impl Fn(&Ident) -> f64,
) -> Result<Option<f64>, mechanism_core::Error<f64>> {
    Ok(match &stmt.kind {
        Kind::Crank {
            pivot,
            radius,
            input: q,
            ..
        } => {
            let c = driver::crank::position(&pose.point(pivot), num(radius), input(q))?;
            pose.found(stmt, Some(c.tip), &[c.axis]);
            None
        }
        Kind::Slider {
            guide,
            input: q,
            offset,
        } => {
            let g = pose.line(guide);
            let s = driver::slider::position(&g, num(offset), input(q))?;
            pose.found(stmt, Some(s.p), &[g.dir]);
            None
        }
        Kind::Actuator {
            a,
            l,
            b,
            input: q,
            mode: m,
        } => {
            let len = input(q);
            let (pa, pb) = (pose.point(a), pose.point(b));
            let p = driver::actuator::position(&pa, num(l), &pb, len, mode(*m))?;
            pose.found(stmt, Some(p.c), &[p.r1 / num(l), p.r2 / len]);
            Some(sweep::det_rrr(&p))
        }
        _ => None,
    })
}

/// The five dyads; returns the scaled determinant.
fn group_step(stmt: &Stmt, pose: &mut Pose) -> Result<f64, mechanism_core::Error<f64>> {
    Ok(match &stmt.kind {
        Kind::Rrr {
            a,
            l1,
            b,
            l2,
            mode: m,
        } => {
            let (pa, pb) = (pose.point(a), pose.point(b));
            let p = dyad::rrr::position(&pa, num(l1), &pb, num(l2), mode(*m))?;
            pose.found(stmt, Some(p.c), &[p.r1 / num(l1), p.r2 / num(l2)]);
            sweep::det_rrr(&p)
        }
        Kind::Rrp {
            a,
            l,
            guide,
            mode: m,
            offset,
        } => {
            let gl = pose.line(guide);
            let p = dyad::rrp::position(&pose.point(a), num(l), &gl, num(offset), mode(*m))?;
            pose.found(stmt, Some(p.c), &[p.r1 / num(l), gl.dir]);
            sweep::det_rrp(&p, &gl)
        }
        Kind::Rpr {
            a,
            b,
            mode: m,
            offset,
        } => {
            let (pa, pb) = (pose.point(a), pose.point(b));
            let p = dyad::rpr::position(&pa, &pb, num(offset), mode(*m))?;
            pose.found(stmt, None, &[p.axis, p.axis]);
            sweep::det_rpr(&p, &pa, &pb)
        }
        Kind::Prp {
            g1,
            g2,
            offset1,
            offset2,
        } => {
            let (l1, l2) = (pose.line(g1), pose.line(g2));
            let p = dyad::prp::position(&l1, num(offset1), &l2, num(offset2))?;
            pose.found(stmt, Some(p.c), &[l1.dir, l2.dir]);
            sweep::det_prp(&l1, &l2)
        }
        Kind::Rpp {
            a,
            guide,
            slot,
            offset,
        } => {
            let gl = pose.line(guide);
            let u = geometry::unit(num(slot));
            let p = dyad::rpp::position(&pose.point(a), &gl, num(offset), &u)?;
            pose.found(stmt, Some(p.q), &[p.slot, gl.dir]);
            sweep::det_rpp(&p, &gl)
        }
        // Not a group: no rate system to be singular.
        _ => 1.0,
    })
}
