//! The global Newton-Euler method as a user would write it, the timed baseline
//! of the forces section: after the kinematics (the generated `position`,
//! `velocity` and `acceleration` of the same definition, whose outputs name
//! every point and link), the Newton-Euler equations of every moving link
//! (sum F = m a_G, sum M_G = J alpha) with every joint reaction and the
//! driving torque as unknowns are assembled into one square linear system per
//! pose and solved by LU with partial pivoting, either fixed-size
//! (`nalgebra::SMatrix`, the size known at compile time) or heap-allocated
//! (`nalgebra::DMatrix`, the size known at run time).
//!
//! Unknowns, in the order of the joints: a revolute joint's force `(Rx, Ry)`
//! of `from` on `to`; a prismatic joint's force `N` along the slide's normal
//! and its couple `M` on `to`, the force acting through the joint's stated
//! point; the driving torque last. This code shares nothing with the
//! generated force analysis or with `mechanism_reference::newton_euler`.

use crate::forces::{FourBarForces, FourBarForcesInput};
use crate::scenes::{ShaperForces, ShaperForcesInput, SineMechanism, SineMechanismInput};
use nalgebra::{Const, DMatrix, DVector, DimMin, SMatrix, SVector};
use std::ops::IndexMut;

/// A moving link at one pose: mass (kg), moment of inertia about its centre
/// (kg m^2), centre `g` (m), the centre's acceleration (m/s^2), angular
/// acceleration (rad/s^2, counter-clockwise), the resultant of the applied
/// forces (gravity included, N) and their moment about `g` (N m).
#[derive(Clone, Copy, Default)]
pub struct Link {
    m: f64,
    j: f64,
    g: [f64; 2],
    a: [f64; 2],
    alpha: f64,
    f: [f64; 2],
    couple: f64,
}

/// A joint at one pose: the link it acts from (`None`: the frame), the link
/// it acts on, its point (m) and, for a prismatic pair, the slide's unit
/// normal.
#[derive(Clone, Copy)]
pub struct Joint {
    from: Option<usize>,
    to: usize,
    at: [f64; 2],
    normal: Option<[f64; 2]>,
}

fn rev(from: Option<usize>, to: usize, at: [f64; 2]) -> Joint {
    Joint {
        from,
        to,
        at,
        normal: None,
    }
}

fn pri(from: Option<usize>, to: usize, at: [f64; 2], dir: [f64; 2]) -> Joint {
    let l = dir[0].hypot(dir[1]);
    Joint {
        from,
        to,
        at,
        normal: Some([-dir[1] / l, dir[0] / l]),
    }
}

/// `(p - g) x f`.
fn cross(p: [f64; 2], g: [f64; 2], f: [f64; 2]) -> f64 {
    (p[0] - g[0]) * f[1] - (p[1] - g[1]) * f[0]
}

/// Writes the system `a x = b` (3 rows per link, 2 columns per joint and one
/// for the driving torque on link `driven`) into zeroed `a` and `b`.
fn assemble<A, B>(links: &[Link], joints: &[Joint], driven: usize, a: &mut A, b: &mut B)
where
    A: IndexMut<(usize, usize), Output = f64>,
    B: IndexMut<usize, Output = f64>,
{
    for (k, l) in links.iter().enumerate() {
        b[3 * k] = l.m * l.a[0] - l.f[0];
        b[3 * k + 1] = l.m * l.a[1] - l.f[1];
        b[3 * k + 2] = l.j * l.alpha - l.couple;
    }
    for (c, jt) in joints.iter().enumerate() {
        let (c0, c1) = (2 * c, 2 * c + 1);
        // (sign, link): the reaction acts on `to` and, reversed, on `from`.
        let sides = [(1.0, Some(jt.to)), (-1.0, jt.from)];
        for (s, link) in sides {
            let Some(k) = link else { continue };
            let g = links[k].g;
            match jt.normal {
                None => {
                    a[(3 * k, c0)] += s;
                    a[(3 * k + 1, c1)] += s;
                    a[(3 * k + 2, c0)] += s * cross(jt.at, g, [1.0, 0.0]);
                    a[(3 * k + 2, c1)] += s * cross(jt.at, g, [0.0, 1.0]);
                }
                Some(n) => {
                    a[(3 * k, c0)] += s * n[0];
                    a[(3 * k + 1, c0)] += s * n[1];
                    a[(3 * k + 2, c0)] += s * cross(jt.at, g, n);
                    a[(3 * k + 2, c1)] += s;
                }
            }
        }
    }
    a[(3 * driven + 2, 2 * joints.len())] += 1.0;
}

/// The report's columns from the solution: every joint's force components
/// (and a prismatic pair's couple after them), the driving torque last.
pub fn columns<X: std::ops::Index<usize, Output = f64>>(joints: &[Joint], x: &X) -> Vec<f64> {
    let mut out = Vec::new();
    for (c, jt) in joints.iter().enumerate() {
        match jt.normal {
            None => out.extend([x[2 * c], x[2 * c + 1]]),
            Some(n) => out.extend([x[2 * c] * n[0], x[2 * c] * n[1], x[2 * c + 1]]),
        }
    }
    out.push(x[2 * joints.len()]);
    out
}

/// Fixed-size LU of the `N x N` system; `None` when it is singular.
pub fn solve_fixed<const N: usize>(
    links: &[Link],
    joints: &[Joint],
    driven: usize,
) -> Option<SVector<f64, N>>
where
    Const<N>: DimMin<Const<N>, Output = Const<N>>,
{
    let mut a = SMatrix::<f64, N, N>::zeros();
    let mut b = SVector::<f64, N>::zeros();
    assemble(links, joints, driven, &mut a, &mut b);
    a.lu().solve(&b)
}

/// Heap LU of the same system (its size from the links).
pub fn solve_heap(links: &[Link], joints: &[Joint], driven: usize) -> Option<DVector<f64>> {
    let n = 3 * links.len();
    let mut a = DMatrix::<f64>::zeros(n, n);
    let mut b = DVector::<f64>::zeros(n);
    assemble(links, joints, driven, &mut a, &mut b);
    a.lu().solve(&b)
}

fn p(v: mechanism::Point2<f64>) -> [f64; 2] {
    [v.x, v.y]
}

fn v(v: mechanism::Vector2<f64>) -> [f64; 2] {
    [v.x, v.y]
}

const G: f64 = -9.81;

/// A scene's links and joints at one pose.
pub struct Pose<const L: usize, const J: usize> {
    pub links: [Link; L],
    pub joints: [Joint; J],
    /// The link the driving torque acts on.
    pub driven: usize,
}

/// The sine mechanism: links 0 link1 (massless), 1 block2 (4 kg at B),
/// 2 link3 (10 kg at Q, 400 N down at Q); both prismatic couples about B.
pub fn sine(m: &SineMechanism<f64>, q: f64, w: f64, al: f64) -> Option<Pose<3, 4>> {
    let i = |x| SineMechanismInput { phi1: x };
    let pos = m.position(&i(q)).ok()?;
    let vel = m.velocity(&pos, &i(w)).ok()?;
    let acc = m.acceleration(&pos, &vel, &i(al)).ok()?;
    let (a, b, qq) = (p(pos.A), p(pos.B), p(pos.Q));
    let links = [
        Link {
            g: a,
            ..Link::default()
        },
        Link {
            m: 4.0,
            g: b,
            a: v(acc.B),
            ..Link::default()
        },
        Link {
            m: 10.0,
            g: qq,
            a: v(acc.Q),
            f: [0.0, -400.0],
            ..Link::default()
        },
    ];
    let joints = [
        rev(None, 0, a),
        rev(Some(0), 1, b),
        pri(Some(1), 2, b, [1.0, 0.0]),
        pri(None, 2, b, [0.0, 1.0]),
    ];
    Some(Pose {
        links,
        joints,
        driven: 0,
    })
}

/// The shaper: links 0 link2, 1 block (both massless), 2 link3 (20 kg at S3),
/// 3 link4 (3 kg at S4), 4 ram_block (60 kg at E, the cut along (-1, 0));
/// gravity; the block's couple about B, the ram's about E.
pub fn shaper(m: &ShaperForces<f64>, q: f64, w: f64, al: f64, cut: f64) -> Option<Pose<5, 7>> {
    let i = |x| ShaperForcesInput { crank: x };
    let pos = m.position(&i(q)).ok()?;
    let vel = m.velocity(&pos, &i(w)).ok()?;
    let acc = m.acceleration(&pos, &vel, &i(al)).ok()?;
    let (a, b, c, d, e) = (p(pos.A), p(pos.B), p(pos.C), p(pos.D), p(pos.E));
    let body = |m: f64, j: f64, g, a, alpha| Link {
        m,
        j,
        g,
        a,
        alpha,
        f: [0.0, m * G],
        couple: 0.0,
    };
    let mut ram = body(60.0, 0.0, e, v(acc.E), 0.0);
    ram.f[0] -= cut;
    let links = [
        body(0.0, 0.0, a, [0.0; 2], 0.0),
        body(0.0, 0.0, b, [0.0; 2], 0.0),
        body(20.0, 0.6, p(pos.S3), v(acc.S3), acc.link3),
        body(3.0, 0.005625, p(pos.S4), v(acc.S4), acc.link4),
        ram,
    ];
    let joints = [
        rev(None, 0, a),
        rev(Some(0), 1, b),
        pri(Some(1), 2, b, [b[0] - c[0], b[1] - c[1]]),
        rev(None, 2, c),
        rev(Some(2), 3, d),
        rev(Some(3), 4, e),
        pri(None, 4, e, [-1.0, 0.0]),
    ];
    Some(Pose {
        links,
        joints,
        driven: 0,
    })
}

/// The four-bar: links 0 link2 (massless), 1 link3 (1.2 kg at G3), 2 link4
/// (0.9 kg at G4, a 5 N m clockwise couple); gravity.
pub fn four_bar(m: &FourBarForces<f64>, q: f64, w: f64, al: f64) -> Option<Pose<3, 4>> {
    let i = |x| FourBarForcesInput { theta2: x };
    let pos = m.position(&i(q)).ok()?;
    let vel = m.velocity(&pos, &i(w)).ok()?;
    let acc = m.acceleration(&pos, &vel, &i(al)).ok()?;
    let (o2, o4, a, b) = (p(pos.O2), p(pos.O4), p(pos.A), p(pos.B));
    let links = [
        Link {
            g: o2,
            ..Link::default()
        },
        Link {
            m: 1.2,
            j: 0.0065,
            g: p(pos.G3),
            a: v(acc.G3),
            alpha: acc.link3,
            f: [0.0, 1.2 * G],
            couple: 0.0,
        },
        Link {
            m: 0.9,
            j: 0.0024,
            g: p(pos.G4),
            a: v(acc.G4),
            alpha: acc.link4,
            f: [0.0, 0.9 * G],
            couple: -5.0,
        },
    ];
    let joints = [
        rev(None, 0, o2),
        rev(Some(0), 1, a),
        rev(None, 2, o4),
        rev(Some(1), 2, b),
    ];
    Some(Pose {
        links,
        joints,
        driven: 0,
    })
}
