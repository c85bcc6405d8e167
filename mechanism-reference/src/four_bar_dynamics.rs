//! Forward dynamics of a four-bar by the global formulation with Lagrange
//! multipliers, for checking the generated equations of motion and the
//! integrators of `mechanism` (its `run_up` example).
//!
//! Each moving link `k` (crank 2, coupler 3, rocker 4) has the coordinates of
//! its centre of mass `c_k` and its angle `th_k`: nine coordinates `x`. The
//! four revolute joints (O2, A, B, O4) give eight constraints `Phi(x) = 0`,
//! each `c_k + R(th_k) s_k - (c_j + R(th_j) s_j) = 0` (`s` the joint in the
//! link's frame). The accelerations and multipliers solve
//!
//! ```text
//! [ M   Phi_x^T ] [ x'' ]   [ F     ]
//! [ Phi_x   0   ] [ lam ] = [ gamma ]
//! ```
//!
//! with `M = diag(m, m, J_G)` per link, `F` the weights and the crank's
//! torque, `gamma = sum w_k^2 R(th_k) s_k - w_j^2 R(th_j) s_j` the
//! constraints' velocity terms. The crank's angle and speed are the state:
//! the positions come from this module's own circle intersection at every
//! evaluation and the velocities from `Phi_x x' = 0` with the crank's speed
//! given, so nothing drifts. Time integration: the classical fourth-order
//! Runge-Kutta method with a fixed step and Richardson extrapolation of two
//! step sizes (order 5), written here. `f64`; no code shared with
//! `mechanism-core` or the generated code.

/// A link of the four-bar: mass, centre of mass and moment of inertia.
#[derive(Clone, Copy, Debug)]
pub struct Body {
    /// Mass (kg).
    pub m: f64,
    /// Moment of inertia about the centre of mass (kg m^2).
    pub j: f64,
    /// Centre of mass from the link's first joint along its axis (m).
    pub g: f64,
}

/// The four-bar: ground pivots `O2 = (0, 0)`, `O4 = (ground, 0)`, crank
/// O2-A, coupler A-B, rocker O4-B, `B` on the side of `sign` (+1: left of
/// A -> O4), the links' axes O2 -> A, A -> B, O4 -> B.
#[derive(Clone, Copy, Debug)]
pub struct FourBar {
    /// |O2 O4| (m).
    pub ground: f64,
    /// |O2 A| (m).
    pub crank: f64,
    /// |A B| (m).
    pub coupler: f64,
    /// |O4 B| (m).
    pub rocker: f64,
    /// +1 or -1: which of the two assemblies.
    pub sign: f64,
    /// Crank, coupler, rocker.
    pub bodies: [Body; 3],
    /// Gravity (m/s^2).
    pub gravity: (f64, f64),
}

type V = (f64, f64);

/// A joint: (link, its joint's offset along the link from the centre),
/// and the other link's the same (`None`: the ground).
type Joint = (usize, f64, Option<(usize, f64)>);

fn rot(th: f64, s: f64) -> V {
    (s * th.cos(), s * th.sin())
}

/// The link angles `(th2, th3, th4)` at crank angle `phi` (rad).
impl FourBar {
    /// The four-bar of the `run_up` example (SI units): ground 0.30, crank
    /// 0.10, coupler 0.25, rocker 0.18, B on the left of A -> O4; the crank
    /// (0.5 kg at 0.05 m, 4e-4 kg m^2) and its flywheel (2.0 kg at O2,
    /// 0.02 kg m^2) merged: 2.5 kg at 0.01 m from O2, and
    /// J = 4e-4 + 0.5 * 0.04^2 + 0.02 + 2.0 * 0.01^2 = 0.0214 kg m^2 about
    /// the merged centre; coupler
    /// 1.2 kg, 6.5e-3 kg m^2 at its midpoint; rocker 0.9 kg, 2.5e-3 kg m^2 at
    /// its midpoint; gravity 9.81 m/s^2 along -y.
    pub fn run_up() -> Self {
        FourBar {
            ground: 0.30,
            crank: 0.10,
            coupler: 0.25,
            rocker: 0.18,
            sign: 1.0,
            bodies: [
                Body {
                    m: 2.5,
                    j: 0.0214,
                    g: 0.01,
                },
                Body {
                    m: 1.2,
                    j: 6.5e-3,
                    g: 0.125,
                },
                Body {
                    m: 0.9,
                    j: 2.5e-3,
                    g: 0.09,
                },
            ],
            gravity: (0.0, -9.81),
        }
    }

    /// The angles of the crank, coupler and rocker at crank angle `phi`.
    pub fn angles(&self, phi: f64) -> (f64, f64, f64) {
        let a = rot(phi, self.crank);
        let (dx, dy) = (self.ground - a.0, -a.1);
        let d = (dx * dx + dy * dy).sqrt();
        // Distance from A along A -> O4 to the foot of B, and the height.
        let along = (self.coupler * self.coupler - self.rocker * self.rocker + d * d) / (2.0 * d);
        let h = (self.coupler * self.coupler - along * along)
            .max(0.0)
            .sqrt();
        let (ux, uy) = (dx / d, dy / d);
        let b = (
            a.0 + along * ux - self.sign * h * uy,
            a.1 + along * uy + self.sign * h * ux,
        );
        let th3 = (b.1 - a.1).atan2(b.0 - a.0);
        let th4 = b.1.atan2(b.0 - self.ground);
        (phi, th3, th4)
    }

    /// Joint positions in each link's frame relative to its centre: crank
    /// (O2, A), coupler (A, B), rocker (O4, B).
    fn local(&self) -> [(f64, f64); 3] {
        let [c, k, r] = self.bodies;
        [
            (-c.g, self.crank - c.g),
            (-k.g, self.coupler - k.g),
            (-r.g, self.rocker - r.g),
        ]
    }

    /// `phi''` at crank angle `phi`, speed `omega` and crank torque `tau`,
    /// with the multipliers' system; also `(th3, th4, w3, w4)`.
    pub fn accel(&self, phi: f64, omega: f64, tau: f64) -> (f64, [f64; 4]) {
        let (_, th3, th4) = self.angles(phi);
        let th = [phi, th3, th4];
        let s = self.local();
        // Constraint rows act on 9 coordinates (x_k, y_k, th_k).
        // Joint list: (body i, local s_i) - (body j, local s_j); j = None: ground.
        let joints: [Joint; 4] = [
            (0, s[0].0, None),
            (0, s[0].1, Some((1, s[1].0))),
            (1, s[1].1, Some((2, s[2].1))),
            (2, s[2].0, None),
        ];
        let mut jac = [[0.0; 9]; 8];
        for (r, &(i, si, other)) in joints.iter().enumerate() {
            let ri = rot(th[i], si);
            jac[2 * r][3 * i] = 1.0;
            jac[2 * r + 1][3 * i + 1] = 1.0;
            jac[2 * r][3 * i + 2] = -ri.1;
            jac[2 * r + 1][3 * i + 2] = ri.0;
            if let Some((j, sj)) = other {
                let rj = rot(th[j], sj);
                jac[2 * r][3 * j] = -1.0;
                jac[2 * r + 1][3 * j + 1] = -1.0;
                jac[2 * r][3 * j + 2] = rj.1;
                jac[2 * r + 1][3 * j + 2] = -rj.0;
            }
        }
        // Velocities: Phi_x x' = 0 with th2' = omega (9 equations).
        let mut a = [[0.0; 9]; 9];
        let mut b = [0.0; 9];
        a[..8].copy_from_slice(&jac);
        a[8][2] = 1.0;
        b[8] = omega;
        let xd = solve(a, b);
        let w = [xd[2], xd[5], xd[8]];
        // Accelerations and multipliers (17 x 17).
        let mut k = [[0.0; 17]; 17];
        let mut rhs = [0.0; 17];
        for (n, body) in self.bodies.iter().enumerate() {
            k[3 * n][3 * n] = body.m;
            k[3 * n + 1][3 * n + 1] = body.m;
            k[3 * n + 2][3 * n + 2] = body.j;
            rhs[3 * n] = body.m * self.gravity.0;
            rhs[3 * n + 1] = body.m * self.gravity.1;
        }
        rhs[2] += tau;
        for r in 0..8 {
            for c in 0..9 {
                k[9 + r][c] = jac[r][c];
                k[c][9 + r] = jac[r][c];
            }
        }
        for (r, &(i, si, other)) in joints.iter().enumerate() {
            let ri = rot(th[i], si);
            let mut g = (w[i] * w[i] * ri.0, w[i] * w[i] * ri.1);
            if let Some((j, sj)) = other {
                let rj = rot(th[j], sj);
                g.0 -= w[j] * w[j] * rj.0;
                g.1 -= w[j] * w[j] * rj.1;
            }
            rhs[9 + 2 * r] = g.0;
            rhs[9 + 2 * r + 1] = g.1;
        }
        let x = solve(k, rhs);
        (x[2], [th3, th4, w[1], w[2]])
    }

    /// The kinetic and potential energy at `(phi, omega)` (J; potential
    /// from the weights, zero at height 0).
    pub fn energy(&self, phi: f64, omega: f64) -> (f64, f64) {
        let (_, th3, th4) = self.angles(phi);
        let th = [phi, th3, th4];
        let origins = [(0.0, 0.0), rot(phi, self.crank), (self.ground, 0.0)];
        let mut pot = 0.0;
        for n in 0..3 {
            let c = rot(th[n], self.bodies[n].g);
            let (x, y) = (origins[n].0 + c.0, origins[n].1 + c.1);
            pot -= self.bodies[n].m * (self.gravity.0 * x + self.gravity.1 * y);
        }
        // Velocities by a central difference are not independent enough: use
        // the velocity solve through `accel`'s rates.
        let (_, r) = self.accel(phi, omega, 0.0);
        let w = [omega, r[2], r[3]];
        let va = {
            let a = rot(phi, self.crank);
            (-omega * a.1, omega * a.0)
        };
        let vel = [
            rot(phi, self.bodies[0].g),
            rot(th3, self.bodies[1].g),
            rot(th4, self.bodies[2].g),
        ];
        let base = [(0.0, 0.0), va, (0.0, 0.0)];
        let mut kin = 0.0;
        for n in 0..3 {
            let v = (base[n].0 - w[n] * vel[n].1, base[n].1 + w[n] * vel[n].0);
            kin +=
                0.5 * (self.bodies[n].m * (v.0 * v.0 + v.1 * v.1) + self.bodies[n].j * w[n] * w[n]);
        }
        (kin, pot)
    }

    /// One classical Runge-Kutta step of `(phi, omega)` over `h` with the
    /// torque `tau(omega)`.
    fn rk4(&self, y: [f64; 2], h: f64, tau: &dyn Fn(f64) -> f64) -> [f64; 2] {
        let f = |y: [f64; 2]| [y[1], self.accel(y[0], y[1], tau(y[1])).0];
        let k1 = f(y);
        let k2 = f([y[0] + 0.5 * h * k1[0], y[1] + 0.5 * h * k1[1]]);
        let k3 = f([y[0] + 0.5 * h * k2[0], y[1] + 0.5 * h * k2[1]]);
        let k4 = f([y[0] + h * k3[0], y[1] + h * k3[1]]);
        [
            y[0] + h / 6.0 * (k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + k4[0]),
            y[1] + h / 6.0 * (k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + k4[1]),
        ]
    }

    /// `(phi, omega)` at each of `times` (increasing, from `t0`), starting
    /// from `y0` at `t0`: RK4 with `steps` steps per unit time and with twice
    /// as many, extrapolated (`(16 y_fine - y_coarse) / 15`). Also returns
    /// the largest difference between the two runs, a bound on the coarse
    /// run's error (the extrapolated value is far better).
    pub fn run(
        &self,
        t0: f64,
        y0: [f64; 2],
        times: &[f64],
        steps: f64,
        tau: &dyn Fn(f64) -> f64,
    ) -> (Vec<[f64; 2]>, f64) {
        let go = |per: f64| {
            let mut out = Vec::new();
            let (mut t, mut y) = (t0, y0);
            for &t1 in times {
                let n = ((t1 - t) * per).ceil().max(1.0) as usize;
                let h = (t1 - t) / n as f64;
                for _ in 0..n {
                    y = self.rk4(y, h, tau);
                }
                t = t1;
                out.push(y);
            }
            out
        };
        let (coarse, fine) = (go(steps), go(2.0 * steps));
        let mut spread: f64 = 0.0;
        let out = coarse
            .iter()
            .zip(&fine)
            .map(|(c, f)| {
                spread = spread.max((c[0] - f[0]).abs()).max((c[1] - f[1]).abs());
                [(16.0 * f[0] - c[0]) / 15.0, (16.0 * f[1] - c[1]) / 15.0]
            })
            .collect();
        (out, spread)
    }
}

/// Gaussian elimination with partial pivoting (the reference's own, `f64`).
#[allow(clippy::needless_range_loop)]
fn solve<const N: usize>(mut a: [[f64; N]; N], mut b: [f64; N]) -> [f64; N] {
    for k in 0..N {
        let p = (k..N)
            .max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs()))
            .unwrap_or(k);
        a.swap(k, p);
        b.swap(k, p);
        for i in k + 1..N {
            let f = a[i][k] / a[k][k];
            if f != 0.0 {
                for j in k..N {
                    a[i][j] -= f * a[k][j];
                }
                b[i] -= f * b[k];
            }
        }
    }
    let mut x = [0.0; N];
    for k in (0..N).rev() {
        let mut s = b[k];
        for j in k + 1..N {
            s -= a[k][j] * x[j];
        }
        x[k] = s / a[k][k];
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bar() -> FourBar {
        let body = |m, j, g| Body { m, j, g };
        FourBar {
            ground: 0.3,
            crank: 0.1,
            coupler: 0.25,
            rocker: 0.18,
            sign: 1.0,
            bodies: [
                body(1.0, 1e-3, 0.05),
                body(1.2, 6.5e-3, 0.125),
                body(0.9, 2.5e-3, 0.09),
            ],
            gravity: (0.0, -9.81),
        }
    }

    // Proves the closure and the energy balance of the formulation: with no
    // torque the total energy of a run stays constant (to the RK4 run's own
    // error, 1e-9 relative at 20 000 steps a second over 1 s), which needs
    // the multipliers' system, the velocity solve and the positions right.
    #[test]
    fn energy_is_conserved_without_torque() {
        let fb = bar();
        let e = |y: [f64; 2]| {
            let (k, p) = fb.energy(y[0], y[1]);
            k + p
        };
        let y0 = [0.3, 12.0];
        let (out, _) = fb.run(0.0, y0, &[1.0], 20_000.0, &|_| 0.0);
        let (e0, e1) = (e(y0), e(out[0]));
        assert!((e1 - e0).abs() <= 1e-9 * e0.abs(), "{e0} {e1}");
    }
}
