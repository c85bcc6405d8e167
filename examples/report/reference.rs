//! The example scenes described to the independent reference
//! (`mechanism_reference`): points, constraints and branch checks written from
//! the definitions in `examples/common/scenes.rs` (not from the generated
//! code), the input grids over each example's whole range, the motion, and the
//! columns the report compares.

use mechanism_reference::constraint::{Constraint, Linkage, Point, Side, V2};
use mechanism_reference::loop_closure::{
    acceleration, angle, angular_acceleration, angular_velocity, position, velocity, ReferenceError,
};
use mechanism_reference::Dd;

/// What a column holds: angles get absolute errors (rad), everything else
/// errors relative to the column's largest value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// A link angle (rad).
    Angle,
    /// Anything else (lengths, rates, accelerations).
    Value,
}

/// A compared column: name, kind, derivative order (0 position, 1 velocity,
/// 2 acceleration).
#[derive(Clone, Copy, Debug)]
pub struct Column {
    pub name: &'static str,
    pub kind: Kind,
    pub order: usize,
}

/// Columns from positions, velocities, accelerations of every point.
pub type ColumnsOf = fn(&[V2], &[V2], &[V2]) -> Vec<Dd>;

/// One example scene as the report sees it.
pub struct Scene {
    pub name: &'static str,
    pub columns: Vec<Column>,
    /// Driver inputs per grid point (rad).
    pub grid: Vec<Vec<f64>>,
    /// Input rates (rad/s) and accelerations (rad/s^2), the same at every point.
    pub rates: Vec<f64>,
    pub accels: Vec<f64>,
    pub linkage: Linkage,
    /// The compared columns from the reference's positions, velocities,
    /// accelerations of every point.
    pub columns_of: ColumnsOf,
}

fn cols(names: &[(&'static str, Kind)]) -> Vec<Column> {
    let mut v = Vec::new();
    for order in 0..3 {
        let prefix = ["", "d/dt ", "d2/dt2 "][order];
        for &(name, kind) in names {
            let name: &'static str = Box::leak(format!("{prefix}{name}").into_boxed_str());
            v.push(Column { name, kind, order });
        }
    }
    v
}

fn fixed(x: f64, y: f64) -> Point {
    Point::Fixed(V2::new(x, y))
}

fn deg_grid(from: f64, to_exclusive: f64, n: usize) -> Vec<Vec<f64>> {
    (0..n)
        .map(|k| vec![(from + (to_exclusive - from) * k as f64 / n as f64).to_radians()])
        .collect()
}

/// Point `i` x / y, segment angle, and their derivatives in one place.
fn xy(p: &[V2], i: usize) -> [Dd; 2] {
    [p[i].x, p[i].y]
}

/// Columns of an angle `a -> b` at each order.
fn ang(p: &[V2], v: &[V2], acc: &[V2], a: usize, b: usize) -> [Dd; 3] {
    [
        angle(p, a, b),
        angular_velocity(p, v, a, b),
        angular_acceleration(p, v, acc, a, b),
    ]
}

/// Assembles columns ordered [pos..., vel..., acc...] from per-quantity triples.
fn by_order(items: Vec<[Dd; 3]>) -> Vec<Dd> {
    (0..3)
        .flat_map(|o| items.iter().map(move |t| t[o]))
        .collect()
}

fn point_items(p: &[V2], v: &[V2], a: &[V2], i: usize) -> [[Dd; 3]; 2] {
    let (pp, vv, aa) = (xy(p, i), xy(v, i), xy(a, i));
    [[pp[0], vv[0], aa[0]], [pp[1], vv[1], aa[1]]]
}

use Kind::{Angle as An, Value as Va};

pub const RPM_3000: f64 = 3000.0 * 2.0 * std::f64::consts::PI / 60.0;

/// The six example scenes. Grid sizes: 3600 points each (0.1 deg steps over
/// a full turn; 3600 steps over the six-bar's 40-55 deg; 60 x 60 over the
/// five-bar's q1 in [60, 150) deg, q2 in [0, 90) deg).
pub fn scenes() -> Vec<Scene> {
    vec![
        four_bar(),
        six_bar(),
        shaper(),
        slider_crank(),
        five_bar(),
        geared_five_bar(),
    ]
}

/// The five-bar's grid: q1 in [60, 150) deg by 1.5, q2 in [0, 90) deg by 1.5.
fn five_grid() -> Vec<Vec<f64>> {
    let mut five = Vec::new();
    for i in 0..60 {
        for j in 0..60 {
            five.push(vec![
                (60.0 + 1.5 * i as f64).to_radians(),
                (1.5 * j as f64).to_radians(),
            ]);
        }
    }
    five
}

/// The report scene `FourBar`.
fn four_bar() -> Scene {
    Scene {
        name: "FourBar",
        columns: cols(&[("B.x", Va), ("B.y", Va), ("link3", An), ("link4", An)]),
        grid: deg_grid(0.0, 360.0, 3600),
        rates: vec![250.0],
        accels: vec![2.0e4],
        // 0 O2, 1 O4, 2 A, 3 B
        linkage: Linkage {
            points: vec![
                fixed(0.0, 0.0),
                fixed(304.8, 0.0),
                Point::Unknown,
                Point::Unknown,
            ],
            constraints: vec![
                Constraint::Crank {
                    p: 2,
                    o: 0,
                    r: 101.6,
                    input: 0,
                },
                Constraint::Distance {
                    p: 3,
                    q: 2,
                    len: 254.0,
                },
                Constraint::Distance {
                    p: 3,
                    q: 1,
                    len: 177.8,
                },
            ],
            sides: vec![Side::Left {
                p: 3,
                a: 2,
                b: 1,
                sign: 1.0,
            }],
            scale: 304.8,
        },
        columns_of: |p, v, a| {
            let [bx, by] = point_items(p, v, a, 3);
            by_order(vec![bx, by, ang(p, v, a, 2, 3), ang(p, v, a, 1, 3)])
        },
    }
}

/// The report scene `SixBar`.
fn six_bar() -> Scene {
    Scene {
        name: "SixBar",
        columns: cols(&[
            ("C.x", Va),
            ("C.y", Va),
            ("F.x", Va),
            ("F.y", Va),
            ("link2", An),
            ("link3", An),
            ("link4", An),
            ("af", Va),
        ]),
        grid: deg_grid(40.0, 55.0, 3600),
        rates: vec![10.0],
        accels: vec![-60.0],
        // 0 A, 1 E, 2 K, 3 B, 4 F, 5 D, 6 C
        linkage: Linkage {
            points: vec![
                fixed(0.0, 0.0),
                fixed(70.0, 0.0),
                Point::Unknown,
                Point::Unknown,
                Point::Unknown,
                Point::Unknown,
                Point::Unknown,
            ],
            constraints: vec![
                Constraint::Crank {
                    p: 2,
                    o: 0,
                    r: 40.0,
                    input: 0,
                },
                // B on the crank opposite K: B = A - (K - A).
                Constraint::Affine {
                    p: 3,
                    o: 0,
                    q: 2,
                    a: Dd::from_f64(-1.0),
                    b: Dd::ZERO,
                },
                Constraint::Distance {
                    p: 4,
                    q: 1,
                    len: 60.0,
                },
                Constraint::OnLine { p: 4, q1: 0, q2: 2 },
                // D on link4 (E -> F) at 35 behind E: D = E - 35/60 (F - E).
                Constraint::Affine {
                    p: 5,
                    o: 1,
                    q: 4,
                    a: Dd::from_f64(-35.0) / Dd::from_f64(60.0),
                    b: Dd::ZERO,
                },
                Constraint::Distance {
                    p: 6,
                    q: 3,
                    len: 50.0,
                },
                Constraint::Distance {
                    p: 6,
                    q: 5,
                    len: 75.0,
                },
            ],
            sides: vec![
                // rrp plus: F ahead of E's foot on the crank line, along A -> K.
                Side::Ahead {
                    p: 4,
                    a: 1,
                    from: 0,
                    to: 2,
                },
                Side::Left {
                    p: 6,
                    a: 3,
                    b: 5,
                    sign: 1.0,
                },
            ],
            scale: 75.0,
        },
        columns_of: |p, v, a| {
            let [cx, cy] = point_items(p, v, a, 6);
            let [fx, fy] = point_items(p, v, a, 4);
            // af = dot(F - A, K - A) / 40 (A fixed at the origin).
            let k = Dd::from_f64(40.0);
            let s = p[4].dot(p[2]) / k;
            let sd = (v[4].dot(p[2]) + p[4].dot(v[2])) / k;
            let sdd = (a[4].dot(p[2]) + Dd::from_f64(2.0) * v[4].dot(v[2]) + p[4].dot(a[2])) / k;
            by_order(vec![
                cx,
                cy,
                fx,
                fy,
                ang(p, v, a, 3, 6),
                ang(p, v, a, 5, 6),
                ang(p, v, a, 1, 4),
                [s, sd, sdd],
            ])
        },
    }
}

/// The report scene `Shaper`.
fn shaper() -> Scene {
    Scene {
        name: "Shaper",
        columns: cols(&[("E.x", Va), ("E.y", Va), ("link3", An), ("link4", An)]),
        grid: deg_grid(0.0, 360.0, 3600),
        rates: vec![1.0],
        accels: vec![0.7],
        linkage: shaper_linkage(),
        columns_of: |p, v, a| {
            let [ex, ey] = point_items(p, v, a, 6);
            by_order(vec![ex, ey, ang(p, v, a, 1, 4), ang(p, v, a, 5, 6)])
        },
    }
}

/// The report scene `SliderCrank`.
fn slider_crank() -> Scene {
    Scene {
        name: "SliderCrank",
        columns: cols(&[("B.x", Va), ("B.y", Va), ("link3", An)]),
        grid: deg_grid(0.0, 360.0, 3600),
        rates: vec![RPM_3000],
        accels: vec![5.0e4],
        // 0 O, 1 G0, 2 G1, 3 A, 4 B
        linkage: Linkage {
            points: vec![
                fixed(0.0, 0.0),
                fixed(0.0, 0.02),
                fixed(1.0, 0.02),
                Point::Unknown,
                Point::Unknown,
            ],
            constraints: vec![
                Constraint::Crank {
                    p: 3,
                    o: 0,
                    r: 0.1,
                    input: 0,
                },
                Constraint::Distance {
                    p: 4,
                    q: 3,
                    len: 0.4,
                },
                Constraint::OnFixedLine {
                    p: 4,
                    origin: V2::new(0.0, 0.02),
                    dir: V2::new(1.0, 0.0),
                },
            ],
            sides: vec![Side::Ahead {
                p: 4,
                a: 3,
                from: 1,
                to: 2,
            }],
            scale: 0.4,
        },
        columns_of: |p, v, a| {
            let [bx, by] = point_items(p, v, a, 4);
            by_order(vec![bx, by, ang(p, v, a, 3, 4)])
        },
    }
}

/// The report scene `FiveBar`.
fn five_bar() -> Scene {
    Scene {
        name: "FiveBar",
        columns: cols(&[("P.x", Va), ("P.y", Va)]),
        grid: five_grid(),
        rates: vec![0.8, -1.3],
        accels: vec![2.0, -0.5],
        // 0 O1, 1 O2, 2 A, 3 C, 4 P
        linkage: Linkage {
            points: vec![
                fixed(0.0, 0.0),
                fixed(0.08, 0.0),
                Point::Unknown,
                Point::Unknown,
                Point::Unknown,
            ],
            constraints: vec![
                Constraint::Crank {
                    p: 2,
                    o: 0,
                    r: 0.1,
                    input: 0,
                },
                Constraint::Crank {
                    p: 3,
                    o: 1,
                    r: 0.1,
                    input: 1,
                },
                Constraint::Distance {
                    p: 4,
                    q: 2,
                    len: 0.16,
                },
                Constraint::Distance {
                    p: 4,
                    q: 3,
                    len: 0.16,
                },
            ],
            sides: vec![Side::Left {
                p: 4,
                a: 2,
                b: 3,
                sign: 1.0,
            }],
            scale: 0.16,
        },
        columns_of: |p, v, a| {
            let [px, py] = point_items(p, v, a, 4);
            by_order(vec![px, py])
        },
    }
}

/// The report scene `GearedFiveBar`.
fn geared_five_bar() -> Scene {
    Scene {
        name: "GearedFiveBar",
        columns: cols(&[
            ("B.x", Va),
            ("B.y", Va),
            ("link3", An),
            ("link4", An),
            ("link5", An),
        ]),
        grid: deg_grid(0.0, 360.0, 3600),
        rates: vec![10.0],
        accels: vec![-50.0],
        // 0 O2, 1 O5, 2 A, 3 C, 4 B. The gear as its law (docs/dsl.md,
        // "Gear pairs"): an external gear of ratio 2 meshing with the
        // crank turns at `phase - 2 theta`.
        linkage: Linkage {
            points: vec![
                fixed(0.0, 0.0),
                fixed(0.3, 0.0),
                Point::Unknown,
                Point::Unknown,
                Point::Unknown,
            ],
            constraints: vec![
                Constraint::Crank {
                    p: 2,
                    o: 0,
                    r: 0.1,
                    input: 0,
                },
                Constraint::Geared {
                    p: 3,
                    o: 1,
                    r: 0.08,
                    input: 0,
                    phase: 30f64.to_radians(),
                    factor: -2.0,
                },
                Constraint::Distance {
                    p: 4,
                    q: 2,
                    len: 0.32,
                },
                Constraint::Distance {
                    p: 4,
                    q: 3,
                    len: 0.26,
                },
            ],
            sides: vec![Side::Left {
                p: 4,
                a: 2,
                b: 3,
                sign: 1.0,
            }],
            scale: 0.32,
        },
        columns_of: |p, v, a| {
            let [bx, by] = point_items(p, v, a, 4);
            by_order(vec![
                bx,
                by,
                ang(p, v, a, 2, 4),
                ang(p, v, a, 3, 4),
                ang(p, v, a, 1, 3),
            ])
        },
    }
}

/// The reference columns at one grid point, from a starting guess (one pair
/// per point), with the relative loop-closure residual reached.
pub fn solve(
    scene: &Scene,
    inputs: &[f64],
    rates: &[f64],
    accels: &[f64],
    start: &[(f64, f64)],
) -> Result<(Vec<Dd>, f64), ReferenceError> {
    let q: Vec<Dd> = inputs.iter().map(|&x| Dd::from_f64(x)).collect();
    let w: Vec<Dd> = rates.iter().map(|&x| Dd::from_f64(x)).collect();
    let al: Vec<Dd> = accels.iter().map(|&x| Dd::from_f64(x)).collect();
    let pose = position(&scene.linkage, &q, start)?;
    let v = velocity(&scene.linkage, &pose, &q, &w)?;
    let a = acceleration(&scene.linkage, &pose, &v, &q, &w, &al)?;
    Ok(((scene.columns_of)(&pose.points, &v, &a), pose.residual))
}

/// Relative loop-closure residual of a method's points (one pair per point of
/// the description) at its inputs, evaluated in double-double.
pub fn residual(scene: &Scene, inputs: &[f64], points: &[(f64, f64)]) -> f64 {
    use mechanism_reference::equations;
    let q: Vec<Dd> = inputs.iter().map(|&x| Dd::from_f64(x)).collect();
    let p: Vec<V2> = scene
        .linkage
        .points
        .iter()
        .zip(points)
        .map(|(pt, s)| match pt {
            Point::Fixed(v) => *v,
            Point::Unknown => V2::new(s.0, s.1),
        })
        .collect();
    let f = equations::residual(&scene.linkage, &p, &q);
    equations::relative_residual(&scene.linkage, &f)
}

/// The shaper of seed 001 as points and constraints (m): 0 A, 1 C, 2 and 3
/// the ram guide's points, 4 B, 5 D, 6 E. Shared with the forces section.
pub fn shaper_linkage() -> Linkage {
    Linkage {
        points: vec![
            fixed(0.0, 0.0),
            fixed(0.0, -0.275),
            fixed(0.0, 0.3),
            fixed(-1.0, 0.3),
            Point::Unknown,
            Point::Unknown,
            Point::Unknown,
        ],
        constraints: vec![
            Constraint::Crank {
                p: 4,
                o: 0,
                r: 0.125,
                input: 0,
            },
            Constraint::OnLine { p: 5, q1: 1, q2: 4 },
            Constraint::Distance {
                p: 5,
                q: 1,
                len: 0.6,
            },
            Constraint::Distance {
                p: 6,
                q: 5,
                len: 0.15,
            },
            Constraint::OnFixedLine {
                p: 6,
                origin: V2::new(0.0, 0.3),
                dir: V2::new(-1.0, 0.0),
            },
        ],
        sides: vec![
            Side::Ahead {
                p: 5,
                a: 1,
                from: 1,
                to: 4,
            },
            Side::Ahead {
                p: 6,
                a: 5,
                from: 2,
                to: 3,
            },
        ],
        scale: 0.6,
    }
}
