//! Joint reactions and driving efforts in double-double from the Newton-Euler
//! equations of every link at once.
//!
//! Given the positions, velocities and accelerations of a mechanism's points
//! (from [`crate::loop_closure`] or written by hand), each moving body `k`
//! contributes three scalar equations (planar Newton-Euler, moments about its
//! centre of mass `G`):
//!
//! ```text
//! sum F           = m a_G
//! sum M_G         = J alpha
//! ```
//!
//! where the sums run over the joint reactions on the body, the driving
//! effort (if the body is driven), the external forces and couples, and the
//! weight `m g` at `G`. All joint reactions and driving efforts are unknowns
//! of one square linear system, solved by [`crate::linear::solve`] (partial
//! pivoting, double-double). The ground is not a body: its equations are
//! never written, its reactions are the negated ones of the bodies pinned to
//! it.
//!
//! Unknowns (the force of body `from` on body `to`; `to` receives it, `from`
//! the opposite):
//!
//! | pair | unknowns |
//! |---|---|
//! | [`Pair::Revolute`] at `P` | the force `(Rx, Ry)` acting at `P` |
//! | [`Pair::Prismatic`] along the unit `u`, about `P` | the signed normal force `N` (the force is `N perp(u)`, `perp(u) = (-u.y, u.x)`, acting at `P`) and the couple `M` (counter-clockwise positive) |
//! | [`Driver::Torque`] | the couple on the driven body (counter-clockwise positive) |
//! | [`Driver::Force`] along the unit `u` at `P` | the force `f u` acting at `P` |
//!
//! A body without mass still has its three equilibrium equations (a massless
//! crank or slider block); a body whose `inertia` is zero needs no rotation
//! reference.
//!
//! Consistency check: the residual `A x - b` of the assembled system is
//! recomputed in double-double after the solve; the largest residual of a
//! force equation is compared with the largest single term (`|A_ij x_j|` or
//! `|b_i|`) of all force equations, and likewise for the moment equations;
//! above [`RESIDUAL_TOLERANCE`] the answer is refused
//! ([`ForceError::Inconsistent`]).
//!
//! Nothing here shares code with `mechanism-core` or the generated code: this
//! is the textbook formulation a general multibody code would assemble.

use crate::constraint::{PointId, V2};
use crate::linear::{solve, SingularMatrix};
use crate::loop_closure::angular_acceleration;
use crate::Dd;

/// Largest accepted residual of a force (moment) equation relative to the
/// largest term of the force (moment) equations. Elimination with partial
/// pivoting is backward stable: the residual is a small multiple of the system's size times the
/// double-double rounding unit (2^-104 = 4.9e-32) when the pivots grow
/// little. Random Scotch yokes (`tests/random_designs/`), equilibrated,
/// still reached 1.5e-28 in 1 of 100 000 (a growth of about 3000) where
/// 1e-28 had been the limit; 1e-26 leaves room for that and stays 1e10
/// below what an `f64` answer can reach.
pub const RESIDUAL_TOLERANCE: f64 = 1e-26;

/// A link a joint connects: the frame or a moving body (an index into
/// [`System::bodies`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Link {
    /// The frame (its equations are not written).
    Ground,
    /// A moving body.
    Body(usize),
}

/// A moving body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    /// Mass (M, >= 0; zero for a massless link).
    pub mass: Dd,
    /// Centre of mass, a point of the body; the moment equation is written
    /// about it (for a massless body any point of the body).
    pub com: PointId,
    /// Moment of inertia about the centre of mass (M L^2, >= 0).
    pub inertia: Dd,
    /// Two points of the body whose segment gives its angular acceleration
    /// (`None`: the body does not turn, or `inertia` is zero).
    pub turn: Option<(PointId, PointId)>,
}

impl Body {
    /// A body of `mass` (M) with its centre of mass at point `com`, moment of
    /// inertia `inertia` (M L^2) about it, and the two points `turn` whose
    /// segment gives its angular acceleration (`None`: it does not turn, or
    /// `inertia` is zero); the numbers as given (exact in double-double).
    pub fn new(mass: f64, com: PointId, inertia: f64, turn: Option<(PointId, PointId)>) -> Body {
        Body {
            mass: Dd::from_f64(mass),
            com,
            inertia: Dd::from_f64(inertia),
            turn,
        }
    }
}

/// A direction in the plane (normalized by the solver).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Direction {
    /// A fixed direction (any non-zero length).
    Fixed(V2),
    /// The direction of the segment from the first point to the second.
    Segment(PointId, PointId),
}

/// A lower pair between two links.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pair {
    /// Pin joint at a point (common to both links).
    Revolute {
        /// The pin.
        at: PointId,
    },
    /// Sliding joint: the links slide relative to each other along `dir`.
    Prismatic {
        /// The sliding direction.
        dir: Direction,
        /// The point the reaction's couple is stated about (and the normal
        /// force's point of application).
        about: PointId,
    },
}

/// A joint: the pair and the two links; the unknown reaction is the force
/// (and couple) of `from` on `to`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Joint {
    /// The link exerting the reaction.
    pub from: Link,
    /// The link receiving it.
    pub to: Link,
    /// The pair.
    pub pair: Pair,
}

impl Joint {
    /// A pin at point `at`; the reaction is the force of `from` on `to`.
    pub fn revolute(from: Link, to: Link, at: PointId) -> Joint {
        Joint {
            from,
            to,
            pair: Pair::Revolute { at },
        }
    }

    /// A sliding pair along `dir`, its couple stated about point `about`;
    /// the reaction is that of `from` on `to`.
    pub fn prismatic(from: Link, to: Link, dir: Direction, about: PointId) -> Joint {
        Joint {
            from,
            to,
            pair: Pair::Prismatic { dir, about },
        }
    }
}

/// A driving effort (one unknown each), applied by the frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Driver {
    /// A couple on `body` (counter-clockwise positive; the crank's torque).
    Torque {
        /// The driven body.
        body: usize,
    },
    /// A force of signed magnitude `f` along `dir` at `at` on `body` (a
    /// slider's driving force).
    Force {
        /// The driven body.
        body: usize,
        /// Point of application (on the body).
        at: PointId,
        /// Direction of the positive force.
        dir: Direction,
    },
}

/// A known external load.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Load {
    /// A force (F) at a point of a body.
    Force {
        /// The loaded body.
        body: usize,
        /// Point of application.
        at: PointId,
        /// The force vector.
        force: V2,
    },
    /// A couple (F L, counter-clockwise positive) on a body.
    Couple {
        /// The loaded body.
        body: usize,
        /// The couple.
        couple: Dd,
    },
}

/// A mechanism's force model.
#[derive(Clone, Debug, PartialEq)]
pub struct System {
    /// The moving bodies.
    pub bodies: Vec<Body>,
    /// The joints, in the order of [`Solution::reactions`].
    pub joints: Vec<Joint>,
    /// The drivers, in the order of [`Solution::drives`].
    pub drivers: Vec<Driver>,
    /// The external loads.
    pub loads: Vec<Load>,
    /// Gravitational acceleration (L/s^2); zero for no weights.
    pub gravity: V2,
}

/// The kinematic state: position (L), velocity (L/s) and acceleration
/// (L/s^2) of every point the [`System`] names.
#[derive(Clone, Copy, Debug)]
pub struct State<'a> {
    /// Positions.
    pub p: &'a [V2],
    /// Velocities.
    pub v: &'a [V2],
    /// Accelerations.
    pub a: &'a [V2],
}

/// A joint's reaction (of `from` on `to`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Reaction {
    /// A pin's force (F).
    Revolute(V2),
    /// A sliding pair's reaction.
    Prismatic {
        /// Signed normal force along `perp(u)` (F).
        normal: Dd,
        /// Couple about the pair's `about` point (F L, counter-clockwise
        /// positive).
        moment: Dd,
        /// The normal force as a vector, `normal perp(u)` (F).
        force: V2,
    },
}

impl Reaction {
    /// The reaction's force vector (F).
    pub fn force(&self) -> V2 {
        match *self {
            Reaction::Revolute(f) => f,
            Reaction::Prismatic { force, .. } => force,
        }
    }
}

/// The solved force analysis.
#[derive(Clone, Debug, PartialEq)]
pub struct Solution {
    /// One reaction per joint, in the order of [`System::joints`].
    pub reactions: Vec<Reaction>,
    /// One driving effort per driver (F L for a torque, F for a force).
    pub drives: Vec<Dd>,
    /// The largest relative residual of the assembled equations.
    pub residual: f64,
}

/// Why the force analysis failed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ForceError {
    /// Unknowns and equations differ in number (three per body).
    NotSquare {
        /// Scalar equations.
        equations: usize,
        /// Unknowns (reactions and driving efforts).
        unknowns: usize,
    },
    /// A body, point or link index out of range.
    BadIndex,
    /// A direction of zero length.
    ZeroDirection,
    /// A negative or non-finite mass or inertia, or a body with inertia but no rotation
    /// reference.
    BadBody {
        /// Index into [`System::bodies`].
        body: usize,
    },
    /// The system is singular at double-double precision (a dead centre, or
    /// a description that leaves a body free).
    Singular(SingularMatrix),
    /// The consistency check failed.
    Inconsistent {
        /// The largest relative residual found.
        residual: f64,
    },
}

impl From<SingularMatrix> for ForceError {
    fn from(e: SingularMatrix) -> Self {
        ForceError::Singular(e)
    }
}

fn point(s: &State, i: PointId) -> Result<V2, ForceError> {
    s.p.get(i).copied().ok_or(ForceError::BadIndex)
}

fn unit(s: &State, d: Direction) -> Result<V2, ForceError> {
    let v = match d {
        Direction::Fixed(v) => v,
        Direction::Segment(a, b) => point(s, b)?.minus(point(s, a)?),
    };
    let n = v.dot(v).sqrt();
    if n.hi == 0.0 || !n.is_finite() {
        return Err(ForceError::ZeroDirection);
    }
    Ok(v.scale(Dd::ONE / n))
}

/// The assembled linear system: `matrix x = rhs`, three rows per body
/// (force x, force y, moment about the centre of mass).
struct Assembled {
    matrix: Vec<Vec<Dd>>,
    rhs: Vec<Dd>,
    /// Each body's centre of mass (the moment equations' point).
    com: Vec<V2>,
}

impl Assembled {
    /// Adds the force `f` acting at `at` (a coefficient per unit of the
    /// unknown `col`, or a known load when `col` is `None`) and the couple
    /// `c` to the equations of `link` (nothing for the ground).
    fn add(
        &mut self,
        link: Link,
        col: Option<usize>,
        f: V2,
        at: V2,
        c: Dd,
    ) -> Result<(), ForceError> {
        let Link::Body(k) = link else {
            return Ok(());
        };
        let g = *self.com.get(k).ok_or(ForceError::BadIndex)?;
        let m = at.minus(g).cross(f) + c;
        let terms = [f.x, f.y, m];
        for (r, t) in terms.into_iter().enumerate() {
            match col {
                Some(j) => self.matrix[3 * k + r][j] += t,
                // A known load moves to the right-hand side.
                None => self.rhs[3 * k + r] -= t,
            }
        }
        Ok(())
    }
}

/// Solves the reactions and driving efforts of `sys` in the state `s`.
///
/// # Errors
/// See [`ForceError`]; in particular [`ForceError::Inconsistent`] when the
/// residual check fails.
pub fn solve_forces(sys: &System, s: &State) -> Result<Solution, ForceError> {
    let n_eq = 3 * sys.bodies.len();
    let n_unknowns = 2 * sys.joints.len() + sys.drivers.len();
    if n_eq != n_unknowns {
        return Err(ForceError::NotSquare {
            equations: n_eq,
            unknowns: n_unknowns,
        });
    }
    if s.v.len() != s.p.len() || s.a.len() != s.p.len() {
        return Err(ForceError::BadIndex);
    }
    let com = sys
        .bodies
        .iter()
        .map(|b| point(s, b.com))
        .collect::<Result<Vec<V2>, ForceError>>()?;
    let mut sysm = Assembled {
        matrix: vec![vec![Dd::ZERO; n_unknowns]; n_eq],
        rhs: vec![Dd::ZERO; n_eq],
        com,
    };
    // Inertia: m a_G on the right of the force rows, J alpha on the right of
    // the moment row; the weight m g is a known load at G.
    for (k, b) in sys.bodies.iter().enumerate() {
        let finite = b.mass.is_finite() && b.inertia.is_finite();
        if !finite || b.mass < Dd::ZERO || b.inertia < Dd::ZERO {
            return Err(ForceError::BadBody { body: k });
        }
        let a_g = *s.a.get(b.com).ok_or(ForceError::BadIndex)?;
        sysm.rhs[3 * k] += b.mass * a_g.x;
        sysm.rhs[3 * k + 1] += b.mass * a_g.y;
        if b.inertia.hi != 0.0 {
            let Some((p, q)) = b.turn else {
                return Err(ForceError::BadBody { body: k });
            };
            if p.max(q) >= s.p.len() {
                return Err(ForceError::BadIndex);
            }
            sysm.rhs[3 * k + 2] += b.inertia * angular_acceleration(s.p, s.v, s.a, p, q);
        }
        let g = point(s, b.com)?;
        let w = sys.gravity.scale(b.mass);
        sysm.add(Link::Body(k), None, w, g, Dd::ZERO)?;
    }
    let zero = V2::default();
    let ex = V2::new(1.0, 0.0);
    let ey = V2::new(0.0, 1.0);
    let mut dirs = Vec::with_capacity(sys.joints.len());
    for (i, j) in sys.joints.iter().enumerate() {
        let (c0, c1) = (2 * i, 2 * i + 1);
        let (f0, f1, c_second, at, dir) = match j.pair {
            Pair::Revolute { at } => (ex, ey, Dd::ZERO, point(s, at)?, None),
            Pair::Prismatic { dir, about } => {
                let u = unit(s, dir)?;
                (u.perp(), zero, Dd::ONE, point(s, about)?, Some(u))
            }
        };
        dirs.push(dir);
        let neg = |v: V2| v.scale(-Dd::ONE);
        sysm.add(j.to, Some(c0), f0, at, Dd::ZERO)?;
        sysm.add(j.from, Some(c0), neg(f0), at, Dd::ZERO)?;
        sysm.add(j.to, Some(c1), f1, at, c_second)?;
        sysm.add(j.from, Some(c1), neg(f1), at, -c_second)?;
    }
    let base = 2 * sys.joints.len();
    for (i, d) in sys.drivers.iter().enumerate() {
        match *d {
            Driver::Torque { body } => {
                // A couple's moment does not depend on its point.
                sysm.add(Link::Body(body), Some(base + i), zero, zero, Dd::ONE)?;
            }
            Driver::Force { body, at, dir } => {
                let u = unit(s, dir)?;
                let at = point(s, at)?;
                sysm.add(Link::Body(body), Some(base + i), u, at, Dd::ZERO)?;
            }
        }
    }
    for l in &sys.loads {
        match *l {
            Load::Force { body, at, force } => {
                let at = point(s, at)?;
                sysm.add(Link::Body(body), None, force, at, Dd::ZERO)?;
            }
            Load::Couple { body, couple } => {
                sysm.add(Link::Body(body), None, zero, zero, couple)?;
            }
        }
    }
    let x = equilibrated_solve(&sysm.matrix, &sysm.rhs)?;
    let residual = relative_residual(&sysm.matrix, &sysm.rhs, &x);
    if residual.is_nan() || residual > RESIDUAL_TOLERANCE {
        return Err(ForceError::Inconsistent { residual });
    }
    let reactions = sys
        .joints
        .iter()
        .zip(&dirs)
        .enumerate()
        .map(|(i, (_, dir))| match dir {
            None => Reaction::Revolute(V2 {
                x: x[2 * i],
                y: x[2 * i + 1],
            }),
            Some(u) => Reaction::Prismatic {
                normal: x[2 * i],
                moment: x[2 * i + 1],
                force: u.perp().scale(x[2 * i]),
            },
        })
        .collect();
    Ok(Solution {
        reactions,
        drives: x[base..].to_vec(),
        residual,
    })
}

/// Solves `A x = b` after scaling every row, then every column, by the power
/// of two nearest its largest entry (exact in binary). Force rows hold unit
/// vectors and moment rows lever arms (length units) and the couples' 1s, so
/// with coordinates of 1e5 the unscaled system mixes entries 1e5 apart and
/// partial pivoting on it grew the residual past [`RESIDUAL_TOLERANCE`] (about
/// 1 in 10 000 random yokes and crossing guides with arms of 1e2 .. 1e5);
/// equilibrated, the pivots compare like with like. `x = D_c y` where
/// `(D_r A D_c) y = D_r b`.
fn equilibrated_solve(a: &[Vec<Dd>], b: &[Dd]) -> Result<Vec<Dd>, SingularMatrix> {
    // The exponent `k` with `2^k` nearest `max |entry|` (0 for an empty line:
    // the solve reports the singular column).
    let exponent = |largest: f64| {
        if largest > 0.0 && largest.is_finite() {
            largest.log2().round() as i32
        } else {
            0
        }
    };
    let largest =
        |xs: &mut dyn Iterator<Item = Dd>| xs.map(|x| x.abs().to_f64()).fold(0.0, f64::max);
    let mut m: Vec<Vec<Dd>> = a.to_vec();
    let mut rhs: Vec<Dd> = b.to_vec();
    for (row, r) in m.iter_mut().zip(rhs.iter_mut()) {
        let k = exponent(largest(&mut row.iter().copied()));
        for x in row.iter_mut() {
            *x = x.scale_pow2(-k);
        }
        *r = r.scale_pow2(-k);
    }
    let n = b.len();
    let columns: Vec<i32> = (0..n)
        .map(|j| exponent(largest(&mut m.iter().map(|row| row[j]))))
        .collect();
    for row in m.iter_mut() {
        for (x, &k) in row.iter_mut().zip(&columns) {
            *x = x.scale_pow2(-k);
        }
    }
    let y = solve(m, rhs)?;
    Ok(y.into_iter()
        .zip(&columns)
        .map(|(y, &k)| y.scale_pow2(-k))
        .collect())
}

/// Largest `|(A x - b)_i|` of a force equation over the largest single term
/// (`|A_ij x_j|` or `|b_i|`) of all force equations, and likewise for the
/// moment equations (every third row): a normwise backward error per unit,
/// which pivoted elimination keeps at the rounding level. (Row by row it
/// is not: an equation whose only term is exactly zero, like a massless
/// slider block's moment balance, gets a rounding-sized value from the
/// elimination of the others, relatively 100% of itself.)
fn relative_residual(a: &[Vec<Dd>], b: &[Dd], x: &[Dd]) -> f64 {
    let mut worst = [0.0f64; 2];
    let mut scale = [0.0f64; 2];
    for (i, (row, &bi)) in a.iter().zip(b).enumerate() {
        let kind = usize::from(i % 3 == 2);
        let mut r = -bi;
        scale[kind] = scale[kind].max(bi.abs().to_f64());
        for (&aij, &xj) in row.iter().zip(x) {
            let t = aij * xj;
            r += t;
            scale[kind] = scale[kind].max(t.abs().to_f64());
        }
        let r = r.abs().to_f64();
        worst[kind] = if r.is_nan() {
            f64::INFINITY
        } else {
            worst[kind].max(r)
        };
    }
    let rel = |k: usize| {
        if scale[k] > 0.0 {
            worst[k] / scale[k]
        } else {
            worst[k]
        }
    };
    rel(0).max(rel(1))
}
