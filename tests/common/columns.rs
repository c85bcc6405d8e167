//! The drawn-versus-grouped comparisons of `tests/examples/drawn.rs` and
//! `tests/surface/drawn.rs` (included with `#[path]`): over a sweep, each
//! result column's largest difference against that column's scale, the
//! largest magnitude of its grouped values over the sweep. A column near
//! zero everywhere (a reaction that vanishes at one pose) is judged against
//! its largest value, not against each value, so a sign change or a zero
//! crossing does not make its relative error blow up.
#![allow(dead_code)]

use mechanism::{Point2, Vector2};

/// One column: its name, its largest difference and its scale so far.
struct Column {
    name: &'static str,
    diff: f64,
    scale: f64,
}

/// The columns of one sweep, in the order first added.
#[derive(Default)]
pub struct Columns(Vec<Column>);

impl Columns {
    fn add(&mut self, name: &'static str, diff: f64, magnitude: f64) {
        assert!(
            diff.is_finite() && magnitude.is_finite(),
            "{name}: not finite"
        );
        let k = match self.0.iter().position(|c| c.name == name) {
            Some(k) => k,
            None => {
                self.0.push(Column {
                    name,
                    diff: 0.0,
                    scale: 0.0,
                });
                self.0.len() - 1
            }
        };
        let c = &mut self.0[k];
        c.diff = c.diff.max(diff);
        c.scale = c.scale.max(magnitude);
    }

    /// One sample of a scalar column (an angle, a rate, a torque).
    pub fn scalar(&mut self, name: &'static str, drawn: f64, grouped: f64) {
        self.add(name, (drawn - grouped).abs(), grouped.abs());
    }

    /// One sample of a vector column (a velocity, a reaction): the norm of
    /// the difference, the grouped vector's norm.
    pub fn vector(&mut self, name: &'static str, drawn: Vector2<f64>, grouped: Vector2<f64>) {
        self.add(name, (drawn - grouped).norm(), grouped.norm());
    }

    /// One sample of a point column: the distance between the two, the
    /// grouped point's distance from the origin.
    pub fn point(&mut self, name: &'static str, drawn: Point2<f64>, grouped: Point2<f64>) {
        self.add(name, (drawn - grouped).norm(), grouped.coords.norm());
    }

    /// The worst column: its name and its largest difference in units of
    /// its scale (a column whose grouped values are all zero is judged
    /// against 1, its differences absolute).
    pub fn worst(&self) -> (&'static str, f64) {
        self.0
            .iter()
            .map(|c| {
                let scale = if c.scale > 0.0 { c.scale } else { 1.0 };
                (c.name, c.diff / scale)
            })
            .fold(("none", 0.0), |w, c| if c.1 > w.1 { c } else { w })
    }

    /// Prints every column (largest difference, scale, their ratio in ulps
    /// of 1) and returns the worst ratio in ulps.
    pub fn report(&self, what: &str) -> f64 {
        for c in &self.0 {
            let scale = if c.scale > 0.0 { c.scale } else { 1.0 };
            eprintln!(
                "{what}: {:>14} differs by {:.2e} of scale {:.3e} ({:.1} ulps)",
                c.name,
                c.diff,
                c.scale,
                c.diff / scale / f64::EPSILON
            );
        }
        let (name, w) = self.worst();
        eprintln!("{what}: worst column {name}, {:.1} ulps", w / f64::EPSILON);
        w / f64::EPSILON
    }
}
