//! Forward dynamics of any planar mechanism by the global formulation with
//! Lagrange multipliers, in double-double: the reference for the generated
//! `dynamics` (the input-coordinate equations of motion) at single states.
//!
//! Every moving body `k` has three coordinates, its centre of mass `c_k` and
//! its angle `th_k` (`z`, `3 B` of them). The joints give the constraints
//! `Phi(z) = 0`, the inputs the driving functions `q = Psi(z)`. At a state
//! `(q, q')` the positions solve `[Phi(z); Psi(z) - q] = 0` (Newton from a
//! guess), the velocities `[Phi_z; Psi_z] z' = [0; q']`, and the
//! accelerations with the multipliers `lam`
//!
//! ```text
//! [ M      Phi_z^T ] [ z'' ]   [ F + Psi_z^T tau ]
//! [ Phi_z  0       ] [ lam ] = [ -g_Phi          ]
//! ```
//!
//! with `M = diag(m_k, m_k, J_k)` (about the centre of mass), `F` the weights,
//! forces and couples as each body's force and moment about its centre,
//! `tau` the inputs' efforts (generalized forces dual to `q`: a crank's
//! torque, a slider's or cylinder's force along its input, a positioner's
//! force components) and `g_Phi = (d/dt Phi_z) z'` the constraints' velocity
//! terms. Then `q'' = Psi_z z'' + g_Psi`. The generalized mass matrix
//! `V^T M V` (the columns of `V` the body rates at a unit rate of each input)
//! is returned beside it.
//!
//! Body geometry is given in each body's own frame (any origin and axis the
//! caller picks); the masses of a body's parts are merged about their common
//! centre here. Every derivative is written by hand from the constraint's
//! definition (see [`Joint`], [`Input`]). Nothing is shared with
//! `mechanism-core` or the generated code; the guess of the positions only
//! selects the assembly (Newton converges to the double-double solution).

use crate::constraint::V2;
use crate::linear::{solve, SingularMatrix};
use crate::Dd;

/// A point of a body (coordinates in the body's frame, L) or of the ground
/// (global coordinates, L).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Anchor {
    /// The body (`None`: the ground).
    pub body: Option<usize>,
    /// Coordinates in the body's frame (the ground: global).
    pub at: V2,
}

impl Anchor {
    /// A ground point at `(x, y)` (exact).
    pub fn ground(x: f64, y: f64) -> Anchor {
        Anchor {
            body: None,
            at: V2::new(x, y),
        }
    }
    /// The point `(x, y)` of body `body`'s frame (exact).
    pub fn on(body: usize, x: f64, y: f64) -> Anchor {
        Anchor {
            body: Some(body),
            at: V2::new(x, y),
        }
    }
    /// The point at distance `r` and angle `deg` (degrees, counter-clockwise
    /// from the body's axis) from the body frame's origin.
    pub fn polar(body: usize, r: f64, deg: f64) -> Anchor {
        let (s, c) = radians(deg).sin_cos();
        Anchor {
            body: Some(body),
            at: V2 {
                x: c * Dd::from_f64(r),
                y: s * Dd::from_f64(r),
            },
        }
    }
}

/// `deg` degrees in radians (double-double).
pub fn radians(deg: f64) -> Dd {
    Dd::from_f64(deg) * Dd::PI / Dd::from_f64(180.0)
}

/// A mass part of a body: a mass at a point of its frame with its own moment
/// of inertia about that point's centre of mass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Part {
    /// Mass (M, >= 0).
    pub mass: f64,
    /// Its centre of mass in the body's frame (L).
    pub at: V2,
    /// Moment of inertia about its own centre of mass (M L^2, >= 0).
    pub inertia: f64,
}

/// A joint between two bodies (or a body and the ground).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Joint {
    /// A pin: the two anchors coincide (`r_a - r_b = 0`, two rows).
    Revolute(Anchor, Anchor),
    /// A sliding pair: anchor `a` stays on the line through anchor `b`
    /// along the direction at angle `dir` (rad) in `b`'s frame
    /// (`cross(u_b, r_a - r_b) = 0`), and the two frames keep the angle
    /// `lock` (`th_a - th_b - lock = 0`): two rows.
    Prismatic {
        /// The point sliding on the line.
        a: Anchor,
        /// A point of the line.
        b: Anchor,
        /// The line's angle in `b`'s frame (rad).
        dir: Dd,
        /// `th_a - th_b` (rad).
        lock: Dd,
    },
    /// The angle between two frames held (`th_a - th_b - angle = 0`, one
    /// row; `None`: the ground, angle 0): a body that only translates.
    Locked {
        /// The first body.
        a: Option<usize>,
        /// The second body.
        b: Option<usize>,
        /// `th_a - th_b` (rad).
        angle: Dd,
    },
}

/// An input coordinate `q_i = Psi_i(z)`; its effort is the generalized
/// force dual to it (power `tau_i q_i'`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Input {
    /// `th_body - th_carrier - offset` (rad; carrier `None`: the ground): a
    /// crank, or a motor carried by a moving link.
    Angle {
        /// The driven body.
        body: usize,
        /// The body carrying the motor.
        carrier: Option<usize>,
        /// Angle of the driven body's frame at input 0 (rad).
        offset: Dd,
    },
    /// `dot(u, r - origin)` (L): a slider's displacement, or one coordinate
    /// of a point (`origin` 0, `u` an axis).
    Along {
        /// The moving point.
        at: Anchor,
        /// The origin of the displacement (global, L).
        origin: V2,
        /// The unit direction (global).
        dir: V2,
    },
    /// `|r_a - r_b|` (L): a cylinder's length.
    Distance(Anchor, Anchor),
}

/// A known load.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Load {
    /// A force (F, global) at a point of a body.
    Force {
        /// Its point of application.
        at: Anchor,
        /// The force.
        force: V2,
    },
    /// A couple (F L, counter-clockwise positive) on a body.
    Couple {
        /// The body.
        body: usize,
        /// The couple.
        couple: Dd,
    },
}

/// A mechanism: bodies (each a list of mass parts), joints, inputs, loads.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Model {
    /// Each body's mass parts (an empty list: a massless body).
    pub bodies: Vec<Vec<Part>>,
    /// The joints.
    pub joints: Vec<Joint>,
    /// The inputs, in the order of `q`.
    pub inputs: Vec<Input>,
    /// The known loads.
    pub loads: Vec<Load>,
    /// Gravitational acceleration (L/s^2).
    pub gravity: V2,
}

/// Why the reference could not answer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Error {
    /// Constraints and inputs do not make three rows per body.
    NotSquare {
        /// Constraint and input rows.
        rows: usize,
        /// Coordinates (three per body).
        coordinates: usize,
    },
    /// A body or input index out of range, or a slice of the wrong length.
    BadIndex,
    /// A singular system (a dead point, a body left free).
    Singular(SingularMatrix),
    /// Newton did not converge (largest final residual, L or rad).
    NotConverged {
        /// The largest residual.
        residual: f64,
    },
}

impl From<SingularMatrix> for Error {
    fn from(e: SingularMatrix) -> Self {
        Error::Singular(e)
    }
}

/// A solved state.
#[derive(Clone, Debug, PartialEq)]
pub struct Forward {
    /// The inputs' accelerations `q''`.
    pub accels: Vec<Dd>,
    /// The generalized mass matrix `V^T M V` (row-major, `n x n`).
    pub mass: Vec<Vec<Dd>>,
    /// Each body's `(c_x, c_y, th)`: centre of mass (L) and angle (rad).
    pub coordinates: Vec<[Dd; 3]>,
    /// Newton iterations of the position solve.
    pub iterations: usize,
}

/// Largest accepted constraint residual after Newton (L or rad, relative
/// to the geometry's scale 1): a few units of the double-double rounding
/// (2^-104 = 4.9e-32) times the coordinates' size.
pub const POSITION_TOLERANCE: f64 = 1e-28;

/// Newton iterations allowed (quadratic convergence from an `f64` guess
/// takes three or four).
pub const MAX_ITERATIONS: usize = 30;

/// One body's merged mass: total mass, centre in its frame, inertia about
/// the centre.
#[derive(Clone, Copy, Debug)]
struct Inertia {
    mass: Dd,
    centre: V2,
    inertia: Dd,
}

fn merge(parts: &[Part]) -> Inertia {
    let mut mass = Dd::ZERO;
    let mut first = V2::default();
    for p in parts {
        let m = Dd::from_f64(p.mass);
        mass += m;
        first = first.plus(p.at.scale(m));
    }
    let centre = if mass.hi == 0.0 {
        V2::default()
    } else {
        first.scale(Dd::ONE / mass)
    };
    let mut inertia = Dd::ZERO;
    for p in parts {
        let d = p.at.minus(centre);
        inertia += Dd::from_f64(p.inertia) + Dd::from_f64(p.mass) * d.dot(d);
    }
    Inertia {
        mass,
        centre,
        inertia,
    }
}

/// The kinematics of the bodies at one state: coordinates, rates, and each
/// body's centre in its frame.
struct Frames<'a> {
    z: &'a [Dd],
    zd: &'a [Dd],
    centres: &'a [V2],
}

/// A point's position, its derivatives with respect to its body's
/// coordinates, its velocity and its acceleration at `z'' = 0`.
#[derive(Clone, Copy)]
struct Pt {
    r: V2,
    /// `d r / d th` (`perp(R s)`); the body's `(c_x, c_y)` enter with the
    /// identity.
    dth: V2,
    v: V2,
    /// `-w^2 R s`.
    quad: V2,
    body: Option<usize>,
}

impl Frames<'_> {
    fn angle(&self, body: Option<usize>) -> (Dd, Dd) {
        match body {
            Some(k) => (self.z[3 * k + 2], self.zd[3 * k + 2]),
            None => (Dd::ZERO, Dd::ZERO),
        }
    }

    fn point(&self, a: Anchor) -> Pt {
        let Some(k) = a.body else {
            return Pt {
                r: a.at,
                dth: V2::default(),
                v: V2::default(),
                quad: V2::default(),
                body: None,
            };
        };
        let s = a.at.minus(self.centres[k]);
        let (sn, cs) = self.z[3 * k + 2].sin_cos();
        let rs = V2 {
            x: cs * s.x - sn * s.y,
            y: sn * s.x + cs * s.y,
        };
        let w = self.zd[3 * k + 2];
        let c = V2 {
            x: self.z[3 * k],
            y: self.z[3 * k + 1],
        };
        let cd = V2 {
            x: self.zd[3 * k],
            y: self.zd[3 * k + 1],
        };
        Pt {
            r: c.plus(rs),
            dth: rs.perp(),
            v: cd.plus(rs.perp().scale(w)),
            quad: rs.scale(-(w * w)),
            body: Some(k),
        }
    }
}

/// One scalar constraint at a state: value, gradient over `z`, and its
/// second time derivative at `z'' = 0`.
struct Row {
    value: Dd,
    grad: Vec<Dd>,
    quad: Dd,
}

impl Row {
    fn new(n: usize) -> Row {
        Row {
            value: Dd::ZERO,
            grad: vec![Dd::ZERO; n],
            quad: Dd::ZERO,
        }
    }
    /// Adds `k . r_p` to the gradient (the point's coordinates' part).
    fn add_point(&mut self, p: &Pt, k: V2) {
        if let Some(b) = p.body {
            self.grad[3 * b] += k.x;
            self.grad[3 * b + 1] += k.y;
            self.grad[3 * b + 2] += k.dot(p.dth);
        }
    }
    fn add_angle(&mut self, body: Option<usize>, k: Dd) {
        if let Some(b) = body {
            self.grad[3 * b + 2] += k;
        }
    }
}

fn angle_row(f: &Frames, n: usize, a: Option<usize>, b: Option<usize>, angle: Dd) -> Row {
    let mut row = Row::new(n);
    row.value = f.angle(a).0 - f.angle(b).0 - angle;
    row.add_angle(a, Dd::ONE);
    row.add_angle(b, -Dd::ONE);
    row
}

fn joint_rows(f: &Frames, n: usize, j: &Joint) -> Vec<Row> {
    match *j {
        Joint::Revolute(a, b) => {
            let (pa, pb) = (f.point(a), f.point(b));
            let d = pa.r.minus(pb.r);
            let q = pa.quad.minus(pb.quad);
            [(V2::new(1.0, 0.0), d.x, q.x), (V2::new(0.0, 1.0), d.y, q.y)]
                .into_iter()
                .map(|(e, value, quad)| {
                    let mut row = Row::new(n);
                    row.value = value;
                    row.quad = quad;
                    row.add_point(&pa, e);
                    row.add_point(&pb, e.scale(-Dd::ONE));
                    row
                })
                .collect()
        }
        Joint::Prismatic { a, b, dir, lock } => {
            let (pa, pb) = (f.point(a), f.point(b));
            let (th, w) = f.angle(b.body);
            let (sn, cs) = (th + dir).sin_cos();
            let u = V2 { x: cs, y: sn };
            let d = pa.r.minus(pb.r);
            let dd = pa.v.minus(pb.v);
            let mut row = Row::new(n);
            // cross(u, v) = dot(perp(u), v).
            let k = u.perp();
            row.value = u.cross(d);
            row.add_point(&pa, k);
            row.add_point(&pb, k.scale(-Dd::ONE));
            // u turns with b: d u / d th_b = perp(u).
            row.add_angle(b.body, u.perp().cross(d));
            let ud = u.perp().scale(w);
            let udd = u.scale(-(w * w));
            row.quad =
                u.cross(pa.quad.minus(pb.quad)) + Dd::from_f64(2.0) * ud.cross(dd) + udd.cross(d);
            vec![row, angle_row(f, n, a.body, b.body, lock)]
        }
        Joint::Locked { a, b, angle } => vec![angle_row(f, n, a, b, angle)],
    }
}

fn input_row(f: &Frames, n: usize, i: &Input) -> Row {
    match *i {
        Input::Angle {
            body,
            carrier,
            offset,
        } => angle_row(f, n, Some(body), carrier, offset),
        Input::Along { at, origin, dir } => {
            let p = f.point(at);
            let mut row = Row::new(n);
            row.value = dir.dot(p.r.minus(origin));
            row.quad = dir.dot(p.quad);
            row.add_point(&p, dir);
            row
        }
        Input::Distance(a, b) => {
            let (pa, pb) = (f.point(a), f.point(b));
            let d = pa.r.minus(pb.r);
            let len = d.dot(d).sqrt();
            let e = d.scale(Dd::ONE / len);
            let dd = pa.v.minus(pb.v);
            let along = e.dot(dd);
            let mut row = Row::new(n);
            row.value = len;
            row.quad = (dd.dot(dd) - along * along) / len + e.dot(pa.quad.minus(pb.quad));
            row.add_point(&pa, e);
            row.add_point(&pb, e.scale(-Dd::ONE));
            row
        }
    }
}

/// The constraint rows, then the input rows.
fn rows(model: &Model, f: &Frames) -> (Vec<Row>, Vec<Row>) {
    let n = 3 * model.bodies.len();
    let c = model
        .joints
        .iter()
        .flat_map(|j| joint_rows(f, n, j))
        .collect();
    let i = model.inputs.iter().map(|i| input_row(f, n, i)).collect();
    (c, i)
}

/// Each body's force and moment about its centre (weights and loads).
fn applied(model: &Model, f: &Frames, inertia: &[Inertia]) -> Vec<Dd> {
    let mut out = vec![Dd::ZERO; 3 * model.bodies.len()];
    for (k, b) in inertia.iter().enumerate() {
        out[3 * k] += b.mass * model.gravity.x;
        out[3 * k + 1] += b.mass * model.gravity.y;
    }
    for load in &model.loads {
        match *load {
            Load::Force { at, force } => {
                let p = f.point(at);
                if let Some(k) = p.body {
                    out[3 * k] += force.x;
                    out[3 * k + 1] += force.y;
                    // Moment about the centre: cross(R s, F), R s = -perp(dth).
                    let rs = V2 {
                        x: p.dth.y,
                        y: -p.dth.x,
                    };
                    out[3 * k + 2] += rs.cross(force);
                }
            }
            Load::Couple { body, couple } => out[3 * body + 2] += couple,
        }
    }
    out
}

/// The starting coordinates: each body's centre from its frame's guessed
/// origin and angle; an [`Input::Angle`]'s body at the input's value (in
/// the order of the inputs, so a carried motor adds to its carrier).
fn guess(model: &Model, q: &[f64], start: &[[f64; 3]], centres: &[V2]) -> Result<Vec<Dd>, Error> {
    let mut z = vec![Dd::ZERO; 3 * start.len()];
    for (k, s) in start.iter().enumerate() {
        z[3 * k + 2] = Dd::from_f64(s[2]);
    }
    for (input, &value) in model.inputs.iter().zip(q) {
        if let Input::Angle {
            body,
            carrier,
            offset,
        } = *input
        {
            let base = match carrier {
                Some(c) => *z.get(3 * c + 2).ok_or(Error::BadIndex)?,
                None => Dd::ZERO,
            };
            *z.get_mut(3 * body + 2).ok_or(Error::BadIndex)? = base + offset + Dd::from_f64(value);
        }
    }
    for (k, (s, c)) in start.iter().zip(centres).enumerate() {
        let (sn, cs) = z[3 * k + 2].sin_cos();
        z[3 * k] = Dd::from_f64(s[0]) + cs * c.x - sn * c.y;
        z[3 * k + 1] = Dd::from_f64(s[1]) + sn * c.x + cs * c.y;
    }
    Ok(z)
}

/// Newton on `[Phi(z); Psi(z) - q] = 0` from `z`; the iterations used.
fn assemble(model: &Model, q: &[f64], z: &mut [Dd], centres: &[V2]) -> Result<usize, Error> {
    let n = z.len();
    let zero = vec![Dd::ZERO; n];
    let mut iterations = 0;
    loop {
        let f = Frames {
            z,
            zd: &zero,
            centres,
        };
        let (c, i) = rows(model, &f);
        if c.len() + i.len() != n {
            return Err(Error::NotSquare {
                rows: c.len() + i.len(),
                coordinates: n,
            });
        }
        let residual: Vec<Dd> = c
            .iter()
            .map(|r| r.value)
            .chain(i.iter().zip(q).map(|(r, &q)| r.value - Dd::from_f64(q)))
            .collect();
        let worst = residual.iter().map(|r| r.hi.abs()).fold(0.0, f64::max);
        if worst <= POSITION_TOLERANCE {
            return Ok(iterations);
        }
        if iterations == MAX_ITERATIONS {
            return Err(Error::NotConverged { residual: worst });
        }
        let a = c.into_iter().chain(i).map(|r| r.grad).collect();
        let step = solve(a, residual.iter().map(|&r| -r).collect())?;
        for (zi, s) in z.iter_mut().zip(step) {
            *zi += s;
        }
        iterations += 1;
    }
}

/// The body rates `z'` at the input rates `qd`, and the generalized mass
/// matrix `V^T M V` (`V`'s columns: the rates at a unit rate of each input).
fn rates(jac: &[Vec<Dd>], qd: &[f64], diag: &[Dd]) -> Result<(Vec<Dd>, Vec<Vec<Dd>>), Error> {
    let (n, ni) = (jac.len(), qd.len());
    let mut rhs = vec![Dd::ZERO; n];
    for (r, &v) in rhs[n - ni..].iter_mut().zip(qd) {
        *r = Dd::from_f64(v);
    }
    let zd = solve(jac.to_vec(), rhs)?;
    let mut columns = Vec::with_capacity(ni);
    for k in 0..ni {
        let mut e = vec![Dd::ZERO; n];
        e[n - ni + k] = Dd::ONE;
        columns.push(solve(jac.to_vec(), e)?);
    }
    let product = |a: &[Dd], b: &[Dd]| {
        diag.iter()
            .zip(a.iter().zip(b))
            .fold(Dd::ZERO, |s, (&d, (&x, &y))| s + d * x * y)
    };
    let mass = columns
        .iter()
        .map(|a| columns.iter().map(|b| product(a, b)).collect())
        .collect();
    Ok((zd, mass))
}

/// The accelerations with the multipliers (the dense KKT system), then
/// `q'' = Psi_z z'' + g_Psi`.
fn accelerations(
    constraints: &[Row],
    inputs: &[Row],
    diag: &[Dd],
    applied: Vec<Dd>,
    tau: &[f64],
) -> Result<Vec<Dd>, Error> {
    let (n, nc) = (diag.len(), constraints.len());
    let mut kkt = vec![vec![Dd::ZERO; n + nc]; n + nc];
    let mut b = applied;
    b.resize(n + nc, Dd::ZERO);
    for (k, &d) in diag.iter().enumerate() {
        kkt[k][k] = d;
    }
    for (r, row) in constraints.iter().enumerate() {
        for (k, &g) in row.grad.iter().enumerate() {
            kkt[n + r][k] = g;
            kkt[k][n + r] = g;
        }
        b[n + r] = -row.quad;
    }
    for (row, &t) in inputs.iter().zip(tau) {
        for (bk, &g) in b.iter_mut().zip(&row.grad) {
            *bk += g * Dd::from_f64(t);
        }
    }
    let x = solve(kkt, b)?;
    Ok(inputs
        .iter()
        .map(|row| {
            row.grad
                .iter()
                .zip(&x)
                .fold(row.quad, |s, (&g, &a)| s + g * a)
        })
        .collect())
}

/// Forward dynamics at inputs `q`, rates `qd` and efforts `tau` (one per
/// input), from `start`: each body's frame origin (L) and angle (rad), the
/// guess that selects the assembly. An [`Input::Angle`] sets its body's
/// angle to the input's value before Newton (in the order of the inputs),
/// so that an input beyond one turn is not a 2 pi jump for Newton.
///
/// # Errors
/// See [`Error`].
pub fn forward(
    model: &Model,
    q: &[f64],
    qd: &[f64],
    tau: &[f64],
    start: &[[f64; 3]],
) -> Result<Forward, Error> {
    let nb = model.bodies.len();
    let ni = model.inputs.len();
    if q.len() != ni || qd.len() != ni || tau.len() != ni || start.len() != nb {
        return Err(Error::BadIndex);
    }
    let inertia: Vec<Inertia> = model.bodies.iter().map(|p| merge(p)).collect();
    let centres: Vec<V2> = inertia.iter().map(|b| b.centre).collect();
    let diag: Vec<Dd> = inertia
        .iter()
        .flat_map(|b| [b.mass, b.mass, b.inertia])
        .collect();
    let mut z = guess(model, q, start, &centres)?;
    let iterations = assemble(model, q, &mut z, &centres)?;
    let zero = vec![Dd::ZERO; z.len()];
    let f = Frames {
        z: &z,
        zd: &zero,
        centres: &centres,
    };
    let (c, i) = rows(model, &f);
    let jac: Vec<Vec<Dd>> = c.iter().chain(&i).map(|r| r.grad.clone()).collect();
    let (zd, mass) = rates(&jac, qd, &diag)?;
    let f = Frames {
        z: &z,
        zd: &zd,
        centres: &centres,
    };
    let (c, i) = rows(model, &f);
    let accels = accelerations(&c, &i, &diag, applied(model, &f, &inertia), tau)?;
    Ok(Forward {
        accels,
        mass,
        coordinates: (0..nb)
            .map(|k| [z[3 * k], z[3 * k + 1], z[3 * k + 2]])
            .collect(),
        iterations,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A pendulum: one body, a mass `m` at distance `l` from the ground
    /// pivot, no inertia of its own, driven by a torque.
    fn pendulum() -> Model {
        Model {
            bodies: vec![vec![Part {
                mass: 2.0,
                at: V2::new(0.5, 0.0),
                inertia: 0.0,
            }]],
            joints: vec![Joint::Revolute(
                Anchor::on(0, 0.0, 0.0),
                Anchor::ground(0.0, 0.0),
            )],
            inputs: vec![Input::Angle {
                body: 0,
                carrier: None,
                offset: Dd::ZERO,
            }],
            loads: vec![],
            gravity: V2::new(0.0, -9.81),
        }
    }

    // Proves the formulation on the textbook pendulum:
    // `m l^2 q'' = tau - m g l cos q`, and the generalized mass `m l^2`.
    #[test]
    fn pendulum_follows_its_equation() {
        let (m, l, g) = (2.0, 0.5, 9.81);
        for &(q, w, tau) in &[(0.3, 1.0, 0.5), (-2.0, 4.0, -1.0), (7.0, -3.0, 0.0)] {
            let out = forward(&pendulum(), &[q], &[w], &[tau], &[[0.0, 0.0, 0.0]]).unwrap();
            let expect = (tau - m * g * l * f64::cos(q)) / (m * l * l);
            let got = out.accels[0].to_f64();
            assert!(
                (got - expect).abs() <= 1e-14 * expect.abs().max(1.0),
                "{got} {expect}"
            );
            assert!((out.mass[0][0].to_f64() - m * l * l).abs() <= 1e-15);
        }
    }

    // Proves the slider's and the distance input's rows: a block of mass m
    // on a line at 30 degrees driven by a force along it (gravity along the
    // line's downhill component), and the same block driven through its
    // distance from a ground point on the line.
    #[test]
    fn block_on_an_incline() {
        let (m, g, f) = (3.0, 9.81, 20.0);
        let th = radians(30.0);
        let (s, c) = th.sin_cos();
        let dir = V2 { x: c, y: s };
        let mut model = Model {
            bodies: vec![vec![Part {
                mass: m,
                at: V2::new(0.0, 0.0),
                inertia: 0.0,
            }]],
            joints: vec![Joint::Prismatic {
                a: Anchor::on(0, 0.0, 0.0),
                b: Anchor::ground(0.0, 0.0),
                dir: th,
                lock: th,
            }],
            inputs: vec![Input::Along {
                at: Anchor::on(0, 0.0, 0.0),
                origin: V2::default(),
                dir,
            }],
            loads: vec![],
            gravity: V2::new(0.0, -g),
        };
        let expect = f / m - g * 0.5;
        let start = [[0.8, 0.4, th.to_f64()]];
        let out = forward(&model, &[0.9], &[2.0], &[f], &start).unwrap();
        assert!((out.accels[0].to_f64() - expect).abs() < 1e-14);
        model.inputs = vec![Input::Distance(
            Anchor::on(0, 0.0, 0.0),
            Anchor::ground(-0.1 * c.to_f64(), -0.1 * s.to_f64()),
        )];
        let out = forward(&model, &[1.0], &[2.0], &[f], &start).unwrap();
        assert!((out.accels[0].to_f64() - expect).abs() < 1e-14);
    }

    // Proves the general formulation against the four-bar's own (the f64
    // global formulation of `four_bar_dynamics`, written separately with
    // hand-merged bodies): the run-up four-bar at five states agrees to
    // 1e-12 relative to the largest q'' (that module's f64 solve carries
    // about 1e-14).
    #[test]
    fn agrees_with_the_four_bar_module() {
        use crate::four_bar_dynamics::FourBar;
        let fb = FourBar::run_up();
        let part = |mass, x, inertia| Part {
            mass,
            at: V2::new(x, 0.0),
            inertia,
        };
        let model = Model {
            bodies: vec![
                vec![part(0.5, 0.05, 4.0e-4), part(2.0, 0.0, 0.02)],
                vec![part(1.2, 0.125, 6.5e-3)],
                vec![part(0.9, 0.09, 2.5e-3)],
            ],
            joints: vec![
                Joint::Revolute(Anchor::on(0, 0.0, 0.0), Anchor::ground(0.0, 0.0)),
                Joint::Revolute(Anchor::on(0, 0.10, 0.0), Anchor::on(1, 0.0, 0.0)),
                Joint::Revolute(Anchor::on(1, 0.25, 0.0), Anchor::on(2, 0.18, 0.0)),
                Joint::Revolute(Anchor::on(2, 0.0, 0.0), Anchor::ground(0.30, 0.0)),
            ],
            inputs: vec![Input::Angle {
                body: 0,
                carrier: None,
                offset: Dd::ZERO,
            }],
            loads: vec![],
            gravity: V2::new(0.0, -9.81),
        };
        let states = [
            (0.0, 0.0, 1.2),
            (0.7, 12.0, 0.84),
            (2.0, 30.0, 0.3),
            (-1.3, 35.0, 0.15),
            (4.0, 20.0, 0.6),
        ];
        let mut got = Vec::new();
        let mut want = Vec::new();
        for &(phi, w, tau) in &states {
            let (_, th3, th4) = fb.angles(phi);
            let start = [
                [0.0, 0.0, phi],
                [0.1 * phi.cos(), 0.1 * phi.sin(), th3],
                [0.30, 0.0, th4],
            ];
            let r = forward(&model, &[phi], &[w], &[tau], &start).unwrap();
            got.push(r.accels[0].to_f64());
            want.push(fb.accel(phi, w, tau).0);
        }
        let scale = want.iter().fold(0.0f64, |s, a| s.max(a.abs()));
        for (g, w) in got.iter().zip(&want) {
            assert!((g - w).abs() <= 1e-12 * scale, "{got:?} {want:?}");
        }
    }
}
