//! The pose the expansion-time evaluator builds statement by statement: what
//! each kind's `eval` reads and records, in `f64`.

use crate::model::{Mode, Stmt};
use crate::value::Value;
use mechanism_core::guide::Line;
use mechanism_core::{Point2, Vector2};
use std::any::Any;
use std::cell::RefCell;
use std::collections::BTreeMap;
use syn::Ident;

/// What the statements solved so far have found: points, guides and the
/// unit axes of links, by name. A name not (yet) known reads as NaN, which
/// the primitives reject with a typed error.
#[derive(Default)]
pub struct Pose {
    points: BTreeMap<String, Point2<f64>>,
    guides: BTreeMap<String, Line<f64>>,
    axes: BTreeMap<String, Vector2<f64>>,
    /// The core's position state of each group (`grp_NAME` of the generated
    /// code), kept only by the run-time evaluator ([`Pose::keeping`]): its
    /// rates, link angles and slides read them.
    kept: Option<BTreeMap<String, Box<dyn Any>>>,
}

impl Pose {
    /// An empty pose that keeps each group's position state (the run-time
    /// evaluator's; the expansion-time check keeps none).
    pub fn keeping() -> Self {
        Pose {
            kept: Some(BTreeMap::new()),
            ..Pose::default()
        }
    }

    /// Keeps `state`, the core's position state of `stmt`'s group, when
    /// this pose keeps states.
    pub fn keep<S: Any>(&mut self, stmt: &Stmt, state: S) {
        if let Some(kept) = &mut self.kept {
            kept.insert(stmt.name.to_string(), Box::new(state));
        }
    }

    /// The position state kept for the statement named `name`.
    pub fn kept<S: Any>(&self, name: &Ident) -> Option<&S> {
        self.kept.as_ref()?.get(&name.to_string())?.downcast_ref()
    }

    /// The point `n` (NaN when unknown).
    pub fn point(&self, n: &Ident) -> Point2<f64> {
        let nan = Point2::new(f64::NAN, f64::NAN);
        self.points.get(&n.to_string()).copied().unwrap_or(nan)
    }

    /// The guide line `n` (NaN when unknown).
    pub fn line(&self, n: &Ident) -> Line<f64> {
        let nan = Line {
            origin: Point2::new(f64::NAN, f64::NAN),
            dir: Vector2::new(f64::NAN, f64::NAN),
        };
        self.guides.get(&n.to_string()).copied().unwrap_or(nan)
    }

    /// The unit axis of link `n` (NaN when unknown).
    pub fn axis(&self, n: &Ident) -> Vector2<f64> {
        let nan = Vector2::new(f64::NAN, f64::NAN);
        self.axes.get(&n.to_string()).copied().unwrap_or(nan)
    }

    /// Records a statement's point and its links' axes.
    pub fn found(&mut self, stmt: &Stmt, point: Option<Point2<f64>>, axes: &[Vector2<f64>]) {
        if let Some(p) = point {
            self.points.insert(stmt.name.to_string(), p);
        }
        for (link, axis) in stmt.links.iter().zip(axes) {
            self.axes.insert(link.to_string(), *axis);
        }
    }

    /// Records a guide statement's line.
    pub fn found_line(&mut self, stmt: &Stmt, line: Line<f64>) {
        self.guides.insert(stmt.name.to_string(), line);
    }
}

thread_local! {
    /// The run-time parameters' values while the run-time evaluator walks
    /// the plan ([`with_params`]); empty otherwise, so that at expansion
    /// time a parameter reads as unknown.
    static PARAMS: RefCell<BTreeMap<String, f64>> = const { RefCell::new(BTreeMap::new()) };
}

/// Runs `f` with the run-time parameters valued as in `params` (what
/// [`num`] reads), then forgets them.
pub fn with_params<R>(params: &BTreeMap<String, f64>, f: impl FnOnce() -> R) -> R {
    PARAMS.with(|p| p.borrow_mut().clone_from(params));
    let r = f();
    PARAMS.with(|p| p.borrow_mut().clear());
    r
}

/// A dimension's value: folded, with the run-time parameters valued when
/// the run-time evaluator runs ([`with_params`]); NaN for one that does
/// not fold (the expansion-time check runs only when every value the
/// position analysis uses folds).
pub fn num(v: &Value) -> f64 {
    PARAMS
        .with(|p| {
            let p = p.borrow();
            if p.is_empty() {
                v.fold()
            } else {
                v.eval_with(&|n| p.get(&n.to_string()).copied())
            }
        })
        .unwrap_or(f64::NAN)
}

/// The core's assembly mode of a written one.
pub fn mode(m: Mode) -> mechanism_core::Mode {
    match m {
        Mode::Plus => mechanism_core::Mode::Plus,
        Mode::Minus => mechanism_core::Mode::Minus,
    }
}
