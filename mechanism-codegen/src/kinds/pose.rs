//! The pose the expansion-time evaluator builds statement by statement: what
//! each kind's `eval` reads and records, in `f64`.

use crate::keys::{GuideName, LinkName, PointName};
use crate::model::{Mode, Stmt};
use crate::value::Value;
use mechanism_core::guide::Line;
use mechanism_core::{Point2, Vector2};
use std::collections::BTreeMap;
use syn::Ident;

/// What the statements solved so far have found: points, guides and the
/// unit axes of links, by name. A name not (yet) known reads as NaN, which
/// the primitives reject with a typed error.
#[derive(Default)]
pub struct Pose {
    points: BTreeMap<PointName, Point2<f64>>,
    guides: BTreeMap<GuideName, Line<f64>>,
    axes: BTreeMap<LinkName, Vector2<f64>>,
}

impl Pose {
    /// The point `n` (NaN when unknown).
    pub fn point(&self, n: &Ident) -> Point2<f64> {
        let nan = Point2::new(f64::NAN, f64::NAN);
        self.points.get(&PointName::of(n)).copied().unwrap_or(nan)
    }

    /// The guide line `n` (NaN when unknown).
    pub fn line(&self, n: &Ident) -> Line<f64> {
        let nan = Line {
            origin: Point2::new(f64::NAN, f64::NAN),
            dir: Vector2::new(f64::NAN, f64::NAN),
        };
        self.guides.get(&GuideName::of(n)).copied().unwrap_or(nan)
    }

    /// The unit axis of link `n` (NaN when unknown).
    pub fn axis(&self, n: &Ident) -> Vector2<f64> {
        let nan = Vector2::new(f64::NAN, f64::NAN);
        self.axes.get(&LinkName::of(n)).copied().unwrap_or(nan)
    }

    /// Records a statement's point and its links' axes.
    pub fn found(&mut self, stmt: &Stmt, point: Option<Point2<f64>>, axes: &[Vector2<f64>]) {
        if let Some(p) = point {
            self.points.insert(PointName::of(&stmt.name), p);
        }
        for (link, axis) in stmt.links.iter().zip(axes) {
            self.axes.insert(LinkName::of(link), *axis);
        }
    }

    /// Records a guide statement's line.
    pub fn found_line(&mut self, stmt: &Stmt, line: Line<f64>) {
        self.guides.insert(GuideName::of(&stmt.name), line);
    }
}

/// A dimension's value, folded; NaN for one that does not fold (the
/// expansion-time check runs only when every value the position analysis
/// uses folds; the run-time mechanism values parameters when it compiles
/// its plan, `run::Compile::num`).
pub fn num(v: &Value) -> f64 {
    v.fold().unwrap_or(f64::NAN)
}

/// The core's assembly mode of a written one.
pub fn mode(m: Mode) -> mechanism_core::Mode {
    match m {
        Mode::Plus => mechanism_core::Mode::Plus,
        Mode::Minus => mechanism_core::Mode::Minus,
    }
}
