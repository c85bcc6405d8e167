//! The dense global formulation of the run-up four-bar, as a user writes it
//! with nalgebra: each link's centre of mass and angle (nine coordinates,
//! eighteen states with their rates), the four pins' eight constraints, and
//! the accelerations with the multipliers from one 17 x 17 `DMatrix` LU per
//! evaluation, without stabilisation. Read by the report's dynamics section
//! and `benches/dynamics.rs`.

use crate::run_up::{motor, RunUp, RunUpInput};
use mechanism::ode::System;
use nalgebra::{DMatrix, DVector};

/// Ground pivot O4 (m) and the link lengths (m).
pub const GROUND: f64 = 0.30;
pub const CRANK: f64 = 0.10;
pub const COUPLER: f64 = 0.25;
pub const ROCKER: f64 = 0.18;

/// One link of the dense formulation: mass (kg), inertia about the centre
/// (kg m^2), and its two joints' offsets from the centre along its axis (m).
struct Link {
    m: f64,
    j: f64,
    ends: (f64, f64),
}

/// A pin: `(link, offset)` on one side, the other link's or a ground point.
enum Side {
    Link(usize, f64),
    Ground(f64, f64),
}

/// The run-up four-bar in nine coordinates `(x, y, th)` of the crank (with
/// the flywheel: 2.5 kg at 0.01 m from O2, 0.0214 kg m^2 about it), the
/// coupler and the rocker.
pub struct Dense {
    links: [Link; 3],
    pins: [(Side, Side); 4],
}

impl Dense {
    /// The run-up four-bar's links and pins.
    #[allow(clippy::new_without_default)]
    pub fn new() -> Dense {
        let links = [
            Link {
                m: 2.5,
                j: 0.0214,
                ends: (-0.01, CRANK - 0.01),
            },
            Link {
                m: 1.2,
                j: 6.5e-3,
                ends: (-0.125, COUPLER - 0.125),
            },
            Link {
                m: 0.9,
                j: 2.5e-3,
                ends: (-0.09, ROCKER - 0.09),
            },
        ];
        let pins = [
            (Side::Link(0, links[0].ends.0), Side::Ground(0.0, 0.0)),
            (
                Side::Link(0, links[0].ends.1),
                Side::Link(1, links[1].ends.0),
            ),
            (
                Side::Link(1, links[1].ends.1),
                Side::Link(2, links[2].ends.1),
            ),
            (Side::Link(2, links[2].ends.0), Side::Ground(GROUND, 0.0)),
        ];
        Dense { links, pins }
    }

    /// The constraint Jacobian (8 x 9), the constraints' values and their
    /// velocity terms `-d/dt(Phi_z) z'`.
    fn constraints(&self, z: &[f64], zd: &[f64]) -> (DMatrix<f64>, DVector<f64>, DVector<f64>) {
        let mut jac = DMatrix::zeros(8, 9);
        let mut phi = DVector::zeros(8);
        let mut gamma = DVector::zeros(8);
        for (r, pin) in self.pins.iter().enumerate() {
            for (side, sign) in [(&pin.0, 1.0), (&pin.1, -1.0)] {
                match *side {
                    Side::Link(k, s) => {
                        let (sn, cs) = z[3 * k + 2].sin_cos();
                        let (rx, ry) = (s * cs, s * sn);
                        let w = zd[3 * k + 2];
                        jac[(2 * r, 3 * k)] += sign;
                        jac[(2 * r + 1, 3 * k + 1)] += sign;
                        jac[(2 * r, 3 * k + 2)] -= sign * ry;
                        jac[(2 * r + 1, 3 * k + 2)] += sign * rx;
                        phi[2 * r] += sign * (z[3 * k] + rx);
                        phi[2 * r + 1] += sign * (z[3 * k + 1] + ry);
                        gamma[2 * r] += sign * w * w * rx;
                        gamma[2 * r + 1] += sign * w * w * ry;
                    }
                    Side::Ground(x, y) => {
                        phi[2 * r] += sign * x;
                        phi[2 * r + 1] += sign * y;
                    }
                }
            }
        }
        (jac, phi, gamma)
    }

    /// `z''` from `(z, z')` and the crank's torque: one dense LU of the
    /// 17 x 17 system with the multipliers.
    pub fn accel(&self, z: &[f64], zd: &[f64], tau: f64) -> Option<DVector<f64>> {
        let (jac, _, gamma) = self.constraints(z, zd);
        let mut k = DMatrix::zeros(17, 17);
        let mut rhs = DVector::zeros(17);
        for (n, l) in self.links.iter().enumerate() {
            k[(3 * n, 3 * n)] = l.m;
            k[(3 * n + 1, 3 * n + 1)] = l.m;
            k[(3 * n + 2, 3 * n + 2)] = l.j;
            rhs[3 * n + 1] = -9.81 * l.m;
        }
        rhs[2] += tau;
        k.view_mut((9, 0), (8, 9)).copy_from(&jac);
        k.view_mut((0, 9), (9, 8)).copy_from(&jac.transpose());
        rhs.rows_mut(9, 8).copy_from(&gamma);
        let x = k.lu().solve(&rhs)?;
        Some(x.rows(0, 9).into_owned())
    }

    /// The full state `(z, z')` at crank angle `phi` and speed `omega`: the
    /// generated position for the assembly, the rates from the constraints.
    pub fn state(&self, phi: f64, omega: f64) -> [f64; 18] {
        let pos = RunUp::<f64>::default()
            .position(&RunUpInput { phi })
            .expect("the crank-rocker assembles at every angle");
        let th = [
            phi,
            (pos.B.y - pos.A.y).atan2(pos.B.x - pos.A.x),
            (pos.B.y - pos.O4.y).atan2(pos.B.x - pos.O4.x),
        ];
        let origin = [(0.0, 0.0), (pos.A.x, pos.A.y), (GROUND, 0.0)];
        let mut y = [0.0; 18];
        for n in 0..3 {
            let g = -self.links[n].ends.0;
            y[3 * n] = origin[n].0 + g * th[n].cos();
            y[3 * n + 1] = origin[n].1 + g * th[n].sin();
            y[3 * n + 2] = th[n];
        }
        let (jac, _, _) = self.constraints(&y[..9], &[0.0; 9]);
        let mut a = DMatrix::zeros(9, 9);
        a.view_mut((0, 0), (8, 9)).copy_from(&jac);
        a[(8, 2)] = 1.0;
        let mut b = DVector::zeros(9);
        b[8] = omega;
        let zd = a.lu().solve(&b).expect("not at a dead point");
        y[9..].copy_from_slice(zd.as_slice());
        y
    }

    /// The largest distance between the two sides of a pin (m).
    pub fn open(&self, y: &[f64; 18]) -> f64 {
        let (_, phi, _) = self.constraints(&y[..9], &y[9..]);
        (0..4)
            .map(|r| phi[2 * r].hypot(phi[2 * r + 1]))
            .fold(0.0, f64::max)
    }
}

impl System<f64, 18> for Dense {
    type Error = ();
    fn rate(&mut self, _t: f64, y: &[f64; 18]) -> Result<[f64; 18], ()> {
        let a = self.accel(&y[..9], &y[9..], motor(y[9 + 2])).ok_or(())?;
        let mut out = [0.0; 18];
        out[..9].copy_from_slice(&y[9..]);
        out[9..].copy_from_slice(a.as_slice());
        Ok(out)
    }
}
