//! A small description of a planar linkage as points and constraints, generic
//! enough for every example scene: points are either fixed (ground) or
//! unknown; each constraint is a scalar or a 2-vector equation `phi = 0` in
//! the points' coordinates and the driver inputs.
//!
//! Equations (all at most quadratic in the coordinates, so their first and
//! second time derivatives are written here by hand):
//!
//! | constraint | equations `phi` | rows |
//! |---|---|---|
//! | [`Constraint::Crank`] | `P - O - r (cos q_k, sin q_k)` | 2 |
//! | [`Constraint::Geared`] | `P - O - r (cos a, sin a)`, `a = phase + factor q_k` | 2 |
//! | [`Constraint::Distance`] | `\|P - Q\|^2 - L^2` | 1 |
//! | [`Constraint::OnFixedLine`] | `cross(u, P - origin)` | 1 |
//! | [`Constraint::OnLine`] | `cross(Q2 - Q1, P - Q1)` | 1 |
//! | [`Constraint::Affine`] | `P - O - a (Q - O) - b perp(Q - O)` | 2 |
//!
//! Nothing here is shared with `mechanism-core`: this is the textbook
//! "natural coordinates" formulation a general multibody code would use.

use crate::Dd;

/// A 2-vector in double-double.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct V2 {
    /// x component.
    pub x: Dd,
    /// y component.
    pub y: Dd,
}

impl V2 {
    /// From two `f64` (exact).
    pub fn new(x: f64, y: f64) -> V2 {
        V2 {
            x: Dd::from_f64(x),
            y: Dd::from_f64(y),
        }
    }
    /// Difference `self - o`.
    pub fn minus(self, o: V2) -> V2 {
        V2 {
            x: self.x - o.x,
            y: self.y - o.y,
        }
    }
    /// Sum `self + o`.
    pub fn plus(self, o: V2) -> V2 {
        V2 {
            x: self.x + o.x,
            y: self.y + o.y,
        }
    }
    /// `self * k`.
    pub fn scale(self, k: Dd) -> V2 {
        V2 {
            x: self.x * k,
            y: self.y * k,
        }
    }
    /// Turned +90 degrees: `(-y, x)`.
    pub fn perp(self) -> V2 {
        V2 {
            x: -self.y,
            y: self.x,
        }
    }
    /// Dot product.
    pub fn dot(self, o: V2) -> Dd {
        self.x * o.x + self.y * o.y
    }
    /// z component of the cross product.
    pub fn cross(self, o: V2) -> Dd {
        self.x * o.y - self.y * o.x
    }
}

/// Index of a point in [`Linkage::points`].
pub type PointId = usize;

/// A point of the linkage.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Point {
    /// A ground point at fixed coordinates.
    Fixed(V2),
    /// A moving point whose coordinates the solver finds.
    Unknown,
}

/// One constraint equation (or pair) between points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Constraint {
    /// `P = O + r (cos q, sin q)` with `q` the driver input number `input`.
    Crank {
        /// The crank's tip.
        p: PointId,
        /// The pivot.
        o: PointId,
        /// Length (L).
        r: f64,
        /// Index of the input angle (rad).
        input: usize,
    },
    /// `P = O + r (cos a, sin a)` with `a = phase + factor q`, `q` the
    /// driver input number `input`: a link turned in proportion to an input
    /// (a gear meshing with a crank on the ground: `factor` minus the
    /// ratio of the pitch radii for external gears).
    Geared {
        /// The point on the turned link.
        p: PointId,
        /// Its pivot.
        o: PointId,
        /// Length (L).
        r: f64,
        /// Index of the input angle (rad).
        input: usize,
        /// The link's angle at input 0 (rad).
        phase: f64,
        /// Its angle per unit of the input (dimensionless).
        factor: f64,
    },
    /// `|P - Q| = len`.
    Distance {
        /// One end.
        p: PointId,
        /// The other end.
        q: PointId,
        /// Length (L).
        len: f64,
    },
    /// `P` on the fixed line through `origin` along the unit `dir`.
    OnFixedLine {
        /// The point.
        p: PointId,
        /// A point of the line.
        origin: V2,
        /// Its direction (need not be unit).
        dir: V2,
    },
    /// `P` on the moving line through `Q1` and `Q2`.
    OnLine {
        /// The point.
        p: PointId,
        /// First point of the line.
        q1: PointId,
        /// Second point of the line.
        q2: PointId,
    },
    /// `P = O + a (Q - O) + b perp(Q - O)`: a point rigidly attached to the
    /// segment `O -> Q` (dimensionless coefficients).
    Affine {
        /// The attached point.
        p: PointId,
        /// Origin of the segment.
        o: PointId,
        /// End of the segment.
        q: PointId,
        /// Coefficient along `Q - O`.
        a: Dd,
        /// Coefficient along `perp(Q - O)`.
        b: Dd,
    },
}

impl Constraint {
    /// Number of scalar equations.
    pub fn rows(&self) -> usize {
        match self {
            Constraint::Crank { .. } | Constraint::Geared { .. } | Constraint::Affine { .. } => 2,
            _ => 1,
        }
    }
    /// Polynomial degree in lengths (1: equation in L, 2: in L^2), for scaling
    /// residuals.
    pub fn degree(&self) -> i32 {
        match self {
            Constraint::Crank { .. }
            | Constraint::Geared { .. }
            | Constraint::Affine { .. }
            | Constraint::OnFixedLine { .. } => 1,
            _ => 2,
        }
    }
}

/// A check that the solution is on the intended assembly branch.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Side {
    /// `sign * cross(B - A, P - A) > 0` (`sign = +1`: `P` left of `A -> B`).
    Left {
        /// The point.
        p: PointId,
        /// Start of the directed line.
        a: PointId,
        /// End of the directed line.
        b: PointId,
        /// +1 for left, -1 for right.
        sign: f64,
    },
    /// `dot(P - A, to - from) > 0`: `P` ahead of `A` along `from -> to`.
    Ahead {
        /// The point.
        p: PointId,
        /// The point it is compared with.
        a: PointId,
        /// Start of the direction.
        from: PointId,
        /// End of the direction.
        to: PointId,
    },
}

/// A linkage: points, constraints, branch checks, and its length scale.
#[derive(Clone, Debug, PartialEq)]
pub struct Linkage {
    /// The points (fixed or unknown).
    pub points: Vec<Point>,
    /// The constraints; the number of rows must equal twice the number of
    /// unknown points.
    pub constraints: Vec<Constraint>,
    /// Branch checks.
    pub sides: Vec<Side>,
    /// A characteristic length (L) for relative residuals and steps.
    pub scale: f64,
}

impl Linkage {
    /// Column of the x coordinate of each point among the unknowns (`None`
    /// for a fixed point).
    pub fn columns(&self) -> Vec<Option<usize>> {
        let mut next = 0;
        self.points
            .iter()
            .map(|p| match p {
                Point::Fixed(_) => None,
                Point::Unknown => {
                    next += 2;
                    Some(next - 2)
                }
            })
            .collect()
    }
    /// Number of unknown coordinates.
    pub fn unknowns(&self) -> usize {
        2 * self
            .points
            .iter()
            .filter(|p| matches!(p, Point::Unknown))
            .count()
    }
    /// Number of scalar equations.
    pub fn equations(&self) -> usize {
        self.constraints.iter().map(Constraint::rows).sum()
    }
}
