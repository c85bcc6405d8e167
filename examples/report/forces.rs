//! The forces section: the generated force analysis (`solve` of a definition
//! with masses or loads: position, velocity, acceleration and forces) of the
//! force scenes against the double-double Newton-Euler reference
//! (`mechanism_reference::newton_euler`), whose kinematics come from the
//! reference's loop closure at the same inputs.
//!
//! The scenes are described to the reference here from their definitions
//! (`examples/common/scenes.rs`, and the four-bar with masses of
//! `tests/firmware/src/bin/probe.rs`, repeated below): points and
//! constraints, bodies (mass, centre, inertia), joints, loads and driver. The
//! load that depends on the motion (the shaper's cutting force) is decided
//! once per grid point from the reference's motion and handed to both the
//! generated code and the reference, so both solve the same problem.

use crate::global_forces as gf;
use crate::scenes::{
    ShaperForces, ShaperForcesInput, ShaperForcesLoads, SineMechanism, SineMechanismInput,
};
use crate::timing::{self, Sweep};
use crate::{sci, MIN_SAMPLE_NS, ROUNDS};
use mechanism::{mechanism, Real, Vector2};
use mechanism_reference::constraint::{Constraint, Linkage, Point, Side, V2};
use mechanism_reference::loop_closure::{acceleration, position, velocity};
use mechanism_reference::newton_euler::{
    solve_forces, Body, Direction, Driver, Joint, Link, Load, Reaction, Solution, State, System,
};
use mechanism_reference::Dd;
use std::f64::consts::PI;
use std::fmt::Write as _;
use std::hint::black_box;
use std::path::Path;

mechanism! {
    /// The seed 002 four-bar in metres with masses (kg, kg m^2): coupler
    /// 1.2 kg at its midpoint, rocker 0.9 kg at its midpoint, gravity, and a
    /// 5 N m clockwise couple on the rocker (as the firmware probe's).
    pub FourBarForces {
        params { ground = 0.3048, crank = 0.1016, coupler = 0.254, rocker = 0.1778 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        let G3 = point(link3, from A, 0.127, 0 deg);
        let G4 = point(link4, from O4, 0.0889, 0 deg);
        mass link3 { m = 1.2, at = G3, j = 0.0065 };
        mass link4 { m = 0.9, at = G4, j = 0.0024 };
        gravity (0.0, -9.81);
        torque on link4 = -5.0;
    }
}

/// Unit of a compared column.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Unit {
    /// A force component (N).
    Force,
    /// A moment or torque (N m).
    Moment,
}

/// One force scene as the reference sees it.
struct ForceScene {
    name: &'static str,
    /// Compared columns: reactions' components (of `from` on `to`, global
    /// frame), prismatic pairs' couples about the generated field's stated
    /// point, the driving effort.
    columns: Vec<(&'static str, Unit)>,
    /// Crank angles (rad): 3600 points over a full turn.
    grid: Vec<f64>,
    /// Crank rate (rad/s) and acceleration (rad/s^2).
    rate: f64,
    accel: f64,
    linkage: Linkage,
    /// A starting guess for the first grid point (one pair per point).
    first_guess: Vec<(f64, f64)>,
    /// The linkage's points followed by the derived points the force model
    /// names (centres of mass): linear in the points, so the same map gives
    /// the derived velocities and accelerations.
    extend: fn(&[V2]) -> Vec<V2>,
    /// The load value (N) at a point of the motion (positions, velocities).
    load_of: fn(&[V2], &[V2]) -> f64,
    /// The force model for a load value.
    system: fn(f64) -> System,
}

fn fixed(x: f64, y: f64) -> Point {
    Point::Fixed(V2::new(x, y))
}

fn d(x: f64) -> Dd {
    Dd::from_f64(x)
}

fn midpoint(p: &[V2], a: usize, b: usize) -> V2 {
    p[a].plus(p[b]).scale(d(0.5))
}

fn grid() -> Vec<f64> {
    (0..3600)
        .map(|k| (360.0 * k as f64 / 3600.0).to_radians())
        .collect()
}

use Link::{Body as Bd, Ground};

fn scenes() -> Vec<ForceScene> {
    vec![
        sine_mechanism_scene(),
        shaper_forces_scene(),
        four_bar_forces_scene(),
    ]
}

/// Sine mechanism: 0 A, 1 B (crank tip, block 2's pin); derived 2 Q =
/// (0, B.y), link 3's point on the frame's line x = 0. The slot of
/// link 3 is horizontal (the guide's 90 deg turned by -90 deg), the
/// guide vertical; both prismatic couples are stated about B.
fn sine_mechanism_scene() -> ForceScene {
    ForceScene {
        name: "SineMechanism",
        columns: vec![
            ("r_ground_link1.x", Unit::Force),
            ("r_ground_link1.y", Unit::Force),
            ("r_link1_block2.x", Unit::Force),
            ("r_link1_block2.y", Unit::Force),
            ("r_block2_link3.force.x", Unit::Force),
            ("r_block2_link3.force.y", Unit::Force),
            ("r_block2_link3.moment", Unit::Moment),
            ("r_ground_link3.force.x", Unit::Force),
            ("r_ground_link3.force.y", Unit::Force),
            ("r_ground_link3.moment", Unit::Moment),
            ("drive_phi1", Unit::Moment),
        ],
        grid: grid(),
        rate: 10.0,
        accel: 0.0,
        linkage: Linkage {
            points: vec![fixed(0.0, 0.0), Point::Unknown],
            constraints: vec![Constraint::Crank {
                p: 1,
                o: 0,
                r: 0.1,
                input: 0,
            }],
            sides: vec![],
            scale: 0.1,
        },
        first_guess: vec![(0.0, 0.0), (0.1, 0.0)],
        extend: |p| {
            let mut v = p.to_vec();
            v.push(V2 {
                x: Dd::ZERO,
                y: p[1].y,
            });
            v
        },
        load_of: |_, _| 0.0,
        system: |_| System {
            // 0 link1 (massless), 1 block2 (4 kg at B), 2 link3 (10 kg at Q).
            bodies: vec![
                Body::new(0.0, 0, 0.0, None),
                Body::new(4.0, 1, 0.0, None),
                Body::new(10.0, 2, 0.0, None),
            ],
            joints: vec![
                Joint::revolute(Ground, Bd(0), 0),
                Joint::revolute(Bd(0), Bd(1), 1),
                Joint::prismatic(Bd(1), Bd(2), Direction::Fixed(V2::new(1.0, 0.0)), 1),
                Joint::prismatic(Ground, Bd(2), Direction::Fixed(V2::new(0.0, 1.0)), 1),
            ],
            drivers: vec![Driver::Torque { body: 0 }],
            loads: vec![Load::Force {
                body: 2,
                at: 2,
                force: V2::new(0.0, -400.0),
            }],
            gravity: V2::default(),
        },
    }
}

/// Shaper: 0 A, 1 C, 2-3 the ram guide's points, 4 B, 5 D, 6 E;
/// derived 7 S3 (midpoint C-D), 8 S4 (midpoint D-E). The block slides
/// on the rocker along C -> B (couple about the pin B), the ram on the
/// frame along (-1, 0) (couple about E).
fn shaper_forces_scene() -> ForceScene {
    ForceScene {
        name: "ShaperForces",
        columns: vec![
            ("r_ground_link2.x", Unit::Force),
            ("r_ground_link2.y", Unit::Force),
            ("r_link2_block.x", Unit::Force),
            ("r_link2_block.y", Unit::Force),
            ("r_block_link3.force.x", Unit::Force),
            ("r_block_link3.force.y", Unit::Force),
            ("r_block_link3.moment", Unit::Moment),
            ("r_ground_link3.x", Unit::Force),
            ("r_ground_link3.y", Unit::Force),
            ("r_link3_link4.x", Unit::Force),
            ("r_link3_link4.y", Unit::Force),
            ("r_link4_ram_block.x", Unit::Force),
            ("r_link4_ram_block.y", Unit::Force),
            ("r_ground_ram_block.force.x", Unit::Force),
            ("r_ground_ram_block.force.y", Unit::Force),
            ("r_ground_ram_block.moment", Unit::Moment),
            ("drive_crank", Unit::Moment),
        ],
        grid: grid(),
        rate: 2.0 * PI,
        accel: 0.0,
        linkage: crate::reference::shaper_linkage(),
        first_guess: vec![
            (0.0, 0.0),
            (0.0, -0.275),
            (0.0, 0.3),
            (-1.0, 0.3),
            (0.125, 0.0),
            (0.25, 0.25),
            (0.1, 0.3),
        ],
        extend: |p| {
            let mut v = p.to_vec();
            v.push(midpoint(p, 1, 5));
            v.push(midpoint(p, 5, 6));
            v
        },
        // The cutting force on the forward stroke: the ram's slide rate
        // along the guide's (-1, 0) positive.
        load_of: |_, v| if -v[6].x.to_f64() > 0.0 { -5000.0 } else { 0.0 },
        system: |cut| System {
            // 0 link2, 1 block (massless), 2 link3, 3 link4, 4 ram_block.
            bodies: vec![
                Body::new(0.0, 0, 0.0, None),
                Body::new(0.0, 4, 0.0, None),
                Body::new(20.0, 7, 0.6, Some((1, 5))),
                Body::new(3.0, 8, 0.005625, Some((5, 6))),
                Body::new(60.0, 6, 0.0, None),
            ],
            joints: vec![
                Joint::revolute(Ground, Bd(0), 0),
                Joint::revolute(Bd(0), Bd(1), 4),
                Joint::prismatic(Bd(1), Bd(2), Direction::Segment(1, 4), 4),
                Joint::revolute(Ground, Bd(2), 1),
                Joint::revolute(Bd(2), Bd(3), 5),
                Joint::revolute(Bd(3), Bd(4), 6),
                Joint::prismatic(Ground, Bd(4), Direction::Fixed(V2::new(-1.0, 0.0)), 6),
            ],
            drivers: vec![Driver::Torque { body: 0 }],
            // `force at E on ram_block along ram = cut`: cut times the
            // guide's unit direction (-1, 0).
            loads: vec![Load::Force {
                body: 4,
                at: 6,
                force: V2::new(-cut, 0.0),
            }],
            gravity: V2::new(0.0, -9.81),
        },
    }
}

/// Four-bar (m): 0 O2, 1 O4, 2 A, 3 B; derived 4 G3 (midpoint A-B:
/// 0.127 of 0.254), 5 G4 (midpoint O4-B: 0.0889 of 0.1778).
fn four_bar_forces_scene() -> ForceScene {
    ForceScene {
        name: "FourBarForces",
        columns: vec![
            ("r_ground_link2.x", Unit::Force),
            ("r_ground_link2.y", Unit::Force),
            ("r_link2_link3.x", Unit::Force),
            ("r_link2_link3.y", Unit::Force),
            ("r_ground_link4.x", Unit::Force),
            ("r_ground_link4.y", Unit::Force),
            ("r_link3_link4.x", Unit::Force),
            ("r_link3_link4.y", Unit::Force),
            ("drive_theta2", Unit::Moment),
        ],
        grid: grid(),
        rate: 250.0,
        accel: 2.0e4,
        linkage: Linkage {
            points: vec![
                fixed(0.0, 0.0),
                fixed(0.3048, 0.0),
                Point::Unknown,
                Point::Unknown,
            ],
            constraints: vec![
                Constraint::Crank {
                    p: 2,
                    o: 0,
                    r: 0.1016,
                    input: 0,
                },
                Constraint::Distance {
                    p: 3,
                    q: 2,
                    len: 0.254,
                },
                Constraint::Distance {
                    p: 3,
                    q: 1,
                    len: 0.1778,
                },
            ],
            sides: vec![Side::Left {
                p: 3,
                a: 2,
                b: 1,
                sign: 1.0,
            }],
            scale: 0.3048,
        },
        first_guess: vec![(0.0, 0.0), (0.3048, 0.0), (0.1016, 0.0), (0.2, 0.17)],
        extend: |p| {
            let mut v = p.to_vec();
            v.push(midpoint(p, 2, 3));
            v.push(midpoint(p, 1, 3));
            v
        },
        load_of: |_, _| 0.0,
        system: |_| System {
            // 0 link2 (massless), 1 link3, 2 link4.
            bodies: vec![
                Body::new(0.0, 0, 0.0, None),
                Body::new(1.2, 4, 0.0065, Some((2, 3))),
                Body::new(0.9, 5, 0.0024, Some((1, 3))),
            ],
            joints: vec![
                Joint::revolute(Ground, Bd(0), 0),
                Joint::revolute(Bd(0), Bd(1), 2),
                Joint::revolute(Ground, Bd(2), 1),
                Joint::revolute(Bd(1), Bd(2), 3),
            ],
            drivers: vec![Driver::Torque { body: 0 }],
            loads: vec![Load::Couple {
                body: 2,
                couple: d(-5.0),
            }],
            gravity: V2::new(0.0, -9.81),
        },
    }
}

/// The reference's columns from its solution (the order of
/// [`ForceScene::columns`]: every joint's force components, and a prismatic
/// pair's couple after them; the driving efforts last).
fn ref_columns(sol: &Solution) -> Vec<Dd> {
    let mut out = Vec::new();
    for r in &sol.reactions {
        match *r {
            Reaction::Revolute(f) => out.extend([f.x, f.y]),
            Reaction::Prismatic { moment, force, .. } => out.extend([force.x, force.y, moment]),
        }
    }
    out.extend(sol.drives.iter().copied());
    out
}

/// The reference at one grid point: its extended positions (the next
/// point's starting guess), the load value, and the columns.
struct RefPoint {
    points: Vec<(f64, f64)>,
    load: f64,
    cols: Vec<Dd>,
    residual: f64,
}

/// The reference at crank angle `q` (with `load`: `None` decides it from the
/// motion).
fn reference(
    sc: &ForceScene,
    q: f64,
    rate: f64,
    accel: f64,
    load: Option<f64>,
    start: &[(f64, f64)],
) -> Result<RefPoint, String> {
    let q = [d(q)];
    let (w, al) = ([d(rate)], [d(accel)]);
    let pose = position(&sc.linkage, &q, start).map_err(|e| format!("{e:?}"))?;
    let v = velocity(&sc.linkage, &pose, &q, &w).map_err(|e| format!("{e:?}"))?;
    let a = acceleration(&sc.linkage, &pose, &v, &q, &w, &al).map_err(|e| format!("{e:?}"))?;
    let load = load.unwrap_or_else(|| (sc.load_of)(&pose.points, &v));
    let (p, v, a) = ((sc.extend)(&pose.points), (sc.extend)(&v), (sc.extend)(&a));
    let sol = solve_forces(
        &(sc.system)(load),
        &State {
            p: &p,
            v: &v,
            a: &a,
        },
    )
    .map_err(|e| format!("{e:?}"))?;
    Ok(RefPoint {
        points: pose
            .points
            .iter()
            .map(|v| (v.x.to_f64(), v.y.to_f64()))
            .collect(),
        load,
        cols: ref_columns(&sol),
        residual: sol.residual,
    })
}

/// The generated code's answer at one grid point: columns and its
/// `power_residual`.
type GenSample = Option<(Vec<f64>, f64)>;

fn v2<T: Real>(v: &Vector2<T>) -> [f64; 2] {
    [v.x.as_f64(), v.y.as_f64()]
}

fn sine<T: Real>(q: f64, w: f64, a: f64, _load: f64) -> GenSample {
    let m = SineMechanism::<T>::default();
    let i = |x: f64| SineMechanismInput { phi1: T::lit(x) };
    let f = m.solve(&i(q), &i(w), &i(a)).ok()?.forces;
    let mut c = Vec::new();
    c.extend(v2(&f.r_ground_link1));
    c.extend(v2(&f.r_link1_block2));
    c.extend(v2(&f.r_block2_link3.force));
    c.push(f.r_block2_link3.moment.as_f64());
    c.extend(v2(&f.r_ground_link3.force));
    c.push(f.r_ground_link3.moment.as_f64());
    c.push(f.drive_phi1.as_f64());
    Some((c, f.power_residual.as_f64()))
}

fn shaper<T: Real>(q: f64, w: f64, a: f64, load: f64) -> GenSample {
    let m = ShaperForces::<T>::default();
    let i = |x: f64| ShaperForcesInput { crank: T::lit(x) };
    let f = m
        .solve(
            &i(q),
            &i(w),
            &i(a),
            &ShaperForcesLoads { cut: T::lit(load) },
        )
        .ok()?
        .forces;
    let mut c = Vec::new();
    c.extend(v2(&f.r_ground_link2));
    c.extend(v2(&f.r_link2_block));
    c.extend(v2(&f.r_block_link3.force));
    c.push(f.r_block_link3.moment.as_f64());
    c.extend(v2(&f.r_ground_link3));
    c.extend(v2(&f.r_link3_link4));
    c.extend(v2(&f.r_link4_ram_block));
    c.extend(v2(&f.r_ground_ram_block.force));
    c.push(f.r_ground_ram_block.moment.as_f64());
    c.push(f.drive_crank.as_f64());
    Some((c, f.power_residual.as_f64()))
}

fn four_bar<T: Real>(q: f64, w: f64, a: f64, _load: f64) -> GenSample {
    let m = FourBarForces::<T>::default();
    let i = |x: f64| FourBarForcesInput { theta2: T::lit(x) };
    let f = m.solve(&i(q), &i(w), &i(a)).ok()?.forces;
    let mut c = Vec::new();
    c.extend(v2(&f.r_ground_link2));
    c.extend(v2(&f.r_link2_link3));
    c.extend(v2(&f.r_ground_link4));
    c.extend(v2(&f.r_link3_link4));
    c.push(f.drive_theta2.as_f64());
    Some((c, f.power_residual.as_f64()))
}

/// Timed sweep of one scene's generated `solve` (position, velocity,
/// acceleration and forces) over the grid, with the per-point loads; the
/// checksum sums the driving effort and one reaction component.
fn sweep<'a, T: Real + 'static>(
    name: &str,
    grid: &[f64],
    rate: f64,
    accel: f64,
    loads: &[f64],
) -> Sweep<'a> {
    let qs: Vec<T> = grid.iter().map(|&q| T::lit(q)).collect();
    let ls: Vec<T> = loads.iter().map(|&l| T::lit(l)).collect();
    let (w, a) = (T::lit(rate), T::lit(accel));
    match name {
        "SineMechanism" => {
            let m = SineMechanism::<T>::default();
            let (wi, ai) = (
                SineMechanismInput { phi1: w },
                SineMechanismInput { phi1: a },
            );
            Box::new(move || {
                let mut acc = 0.0;
                for &q in &qs {
                    if let Ok(s) = black_box(&m).solve(&SineMechanismInput { phi1: q }, &wi, &ai) {
                        acc += (s.forces.drive_phi1 + s.forces.r_ground_link1.x).as_f64();
                    }
                }
                acc
            })
        }
        "ShaperForces" => {
            let m = ShaperForces::<T>::default();
            let (wi, ai) = (
                ShaperForcesInput { crank: w },
                ShaperForcesInput { crank: a },
            );
            Box::new(move || {
                let mut acc = 0.0;
                for (&q, &cut) in qs.iter().zip(&ls) {
                    if let Ok(s) = black_box(&m).solve(
                        &ShaperForcesInput { crank: q },
                        &wi,
                        &ai,
                        &ShaperForcesLoads { cut },
                    ) {
                        acc += (s.forces.drive_crank + s.forces.r_ground_link2.x).as_f64();
                    }
                }
                acc
            })
        }
        _ => {
            let m = FourBarForces::<T>::default();
            let (wi, ai) = (
                FourBarForcesInput { theta2: w },
                FourBarForcesInput { theta2: a },
            );
            Box::new(move || {
                let mut acc = 0.0;
                for &q in &qs {
                    if let Ok(s) = black_box(&m).solve(&FourBarForcesInput { theta2: q }, &wi, &ai)
                    {
                        acc += (s.forces.drive_theta2 + s.forces.r_ground_link2.x).as_f64();
                    }
                }
                acc
            })
        }
    }
}

/// The global Newton-Euler method's answer at one grid point (f64; `heap`:
/// `DMatrix`, else `SMatrix`); its power residual is not computed (0).
fn global(name: &str, q: f64, w: f64, a: f64, load: f64, heap: bool) -> GenSample {
    macro_rules! solve {
        ($pose:expr, $n:literal) => {{
            let ps = $pose?;
            let cols = if heap {
                gf::columns(
                    &ps.joints,
                    &gf::solve_heap(&ps.links, &ps.joints, ps.driven)?,
                )
            } else {
                gf::columns(
                    &ps.joints,
                    &gf::solve_fixed::<$n>(&ps.links, &ps.joints, ps.driven)?,
                )
            };
            Some((cols, 0.0))
        }};
    }
    match name {
        "SineMechanism" => solve!(gf::sine(&SineMechanism::default(), q, w, a), 9),
        "ShaperForces" => solve!(gf::shaper(&ShaperForces::default(), q, w, a, load), 15),
        _ => solve!(gf::four_bar(&FourBarForces::default(), q, w, a), 9),
    }
}

/// Timed sweep of the generated kinematics alone (`position`, `velocity`,
/// `acceleration` of the same definition, f64); the checksum sums one
/// acceleration component.
fn kinematics_sweep<'a>(name: &str, grid: &[f64], rate: f64, accel: f64) -> Sweep<'a> {
    let qs = grid.to_vec();
    macro_rules! run {
        ($m:expr, $input:ident, $field:ident, $point:ident) => {{
            let m = $m;
            let (wi, ai) = ($input { $field: rate }, $input { $field: accel });
            Box::new(move || {
                let mut acc = 0.0;
                for &q in &qs {
                    let m = black_box(&m);
                    let Ok(pos) = m.position(&$input { $field: q }) else {
                        continue;
                    };
                    let Ok(vel) = m.velocity(&pos, &wi) else {
                        continue;
                    };
                    if let Ok(a) = m.acceleration(&pos, &vel, &ai) {
                        acc += a.$point.x;
                    }
                }
                acc
            })
        }};
    }
    match name {
        "SineMechanism" => run!(SineMechanism::<f64>::default(), SineMechanismInput, phi1, Q),
        "ShaperForces" => run!(ShaperForces::<f64>::default(), ShaperForcesInput, crank, E),
        _ => run!(
            FourBarForces::<f64>::default(),
            FourBarForcesInput,
            theta2,
            G3
        ),
    }
}

/// Timed sweep of the global method (f64): the generated kinematics, the
/// system assembled, then solved by fixed-size (`heap`: heap) LU; the
/// checksum sums the driving torque and one reaction component.
fn global_sweep<'a>(
    name: &str,
    grid: &[f64],
    rate: f64,
    accel: f64,
    loads: &[f64],
    heap: bool,
) -> Sweep<'a> {
    let qs = grid.to_vec();
    let ls = loads.to_vec();
    macro_rules! run {
        ($m:expr, $pose:expr, $n:literal) => {{
            let m = $m;
            Box::new(move || {
                let mut acc = 0.0;
                for (&q, &l) in qs.iter().zip(&ls) {
                    let Some(ps) = $pose(black_box(&m), q, rate, accel, l) else {
                        continue;
                    };
                    acc += if heap {
                        gf::solve_heap(&ps.links, &ps.joints, ps.driven)
                            .map_or(0.0, |x| x[$n - 1] + x[0])
                    } else {
                        gf::solve_fixed::<$n>(&ps.links, &ps.joints, ps.driven)
                            .map_or(0.0, |x| x[$n - 1] + x[0])
                    };
                }
                acc
            })
        }};
    }
    match name {
        "SineMechanism" => run!(
            SineMechanism::<f64>::default(),
            |m, q, w, a, _| gf::sine(m, q, w, a),
            9
        ),
        "ShaperForces" => run!(ShaperForces::<f64>::default(), gf::shaper, 15),
        _ => run!(
            FourBarForces::<f64>::default(),
            |m, q, w, a, _| gf::four_bar(m, q, w, a),
            9
        ),
    }
}

/// Error figures of one method on one scene.
#[derive(Default)]
struct ForceErrors {
    /// Largest absolute error of a force column (N).
    force_abs: f64,
    /// Largest absolute error of a moment column (N m).
    moment_abs: f64,
    /// Largest error relative to its column's largest |reference| value.
    rel: f64,
    /// The column of `rel`.
    worst: &'static str,
    /// Largest generated `power_residual`.
    power: f64,
    /// Grid points where the generated code returned an error.
    failures: usize,
}

fn compare(
    sc: &ForceScene,
    refs: &[Option<RefPoint>],
    scale: &[f64],
    samples: &[GenSample],
) -> ForceErrors {
    let mut e = ForceErrors::default();
    for (r, s) in refs.iter().zip(samples) {
        let Some(r) = r else { continue };
        let Some((cols, power)) = s else {
            e.failures += 1;
            continue;
        };
        e.power = e.power.max(*power);
        for (k, (&(name, unit), &m)) in sc.columns.iter().zip(cols).enumerate() {
            let mut diff = (d(m) - r.cols[k]).abs().to_f64();
            if !diff.is_finite() {
                diff = f64::INFINITY;
            }
            match unit {
                Unit::Force => e.force_abs = e.force_abs.max(diff),
                Unit::Moment => e.moment_abs = e.moment_abs.max(diff),
            }
            let rel = diff / scale[k];
            if rel > e.rel || (rel.is_nan() && !e.rel.is_nan()) {
                e.rel = rel;
                e.worst = name;
            }
        }
    }
    e
}

/// Column scales: the largest |reference| of each column; a column below
/// 1e-6 of the largest column of the same unit (zero in exact arithmetic,
/// like the horizontal force across a vertical guide) is measured against
/// that largest column instead, the magnitude its rounding comes from (as
/// the kinematic tables do).
fn scales(sc: &ForceScene, refs: &[Option<RefPoint>]) -> Vec<f64> {
    let mut s = vec![0.0f64; sc.columns.len()];
    for r in refs.iter().flatten() {
        for (k, x) in r.cols.iter().enumerate() {
            s[k] = s[k].max(x.to_f64().abs());
        }
    }
    let largest = |u: Unit| {
        sc.columns
            .iter()
            .zip(&s)
            .filter(|((_, cu), _)| *cu == u)
            .fold(0.0f64, |m, (_, &x)| m.max(x))
    };
    let (lf, lm) = (largest(Unit::Force), largest(Unit::Moment));
    for ((_, u), x) in sc.columns.iter().zip(s.iter_mut()) {
        let largest = if *u == Unit::Force { lf } else { lm };
        if *x < 1e-6 * largest {
            *x = largest;
        }
    }
    s
}

/// The reference over a grid (continuation: each point starts from the
/// previous one's solution), with the loads given or decided from the motion.
fn references(
    sc: &ForceScene,
    grid: &[f64],
    rate: f64,
    accel: f64,
    loads: Option<&[f64]>,
    problems: &mut Vec<String>,
) -> Vec<Option<RefPoint>> {
    let mut start = sc.first_guess.clone();
    let mut out = Vec::with_capacity(grid.len());
    for (k, &q) in grid.iter().enumerate() {
        let load = loads.map(|l| l[k]);
        match reference(sc, q, rate, accel, load, &start) {
            Ok(r) => {
                start = r.points.clone();
                out.push(Some(r));
            }
            Err(e) => {
                problems.push(format!("{} at {q}: {e}", sc.name));
                out.push(None);
            }
        }
    }
    out
}

/// The target lines of one scene from its medians (rows in the order of the
/// table: generated f64 `solve`, f32, kinematics alone, global fixed, global
/// heap). The force analysis alone is a row's time less the kinematics'.
fn force_targets(name: &str, ns: &[Vec<f64>]) -> Vec<String> {
    let med = |k: usize| timing::stats(&ns[k]).0;
    let (solve, kin, fixed) = (med(0), med(2), med(3));
    let (gen_f, fixed_f) = (solve - kin, fixed - kin);
    let met = |b: bool| if b { "**met**" } else { "**not met**" };
    let speedup = fixed_f / gen_f;
    let ratio = solve / kin;
    vec![
        format!(
            "{name}: generated force analysis {gen_f:.1} ns (`solve` {solve:.1} less kinematics \
             {kin:.1}) vs the fixed-size global solve {fixed_f:.1} ns ({fixed:.1} less the same \
             kinematics): {speedup:.2}x faster (target >= 3): {}",
            met(speedup >= 3.0)
        ),
        format!(
            "{name}: whole `solve` with forces {solve:.1} ns = {ratio:.2}x its kinematics alone \
             {kin:.1} ns (target <= 2): {}",
            met(ratio <= 2.0)
        ),
    ]
}

/// The forces section of the report (markdown), and one CSV per scene in
/// `out_dir`.
pub fn section(out_dir: &Path) -> String {
    let mut md = intro();
    let mut problems = Vec::new();
    let mut targets = Vec::new();
    for sc in scenes() {
        eprintln!("forces {}", sc.name);
        let m = measure(&sc, &mut problems);
        md += &scene_table(&sc, &m, out_dir);
        targets.push(force_targets(sc.name, &m.ns));
    }
    let _ = writeln!(md, "### Targets (forces, issue 35)\n");
    for t in targets.iter().flatten() {
        let _ = writeln!(md, "- {t}");
    }
    let _ = writeln!(md);
    if !problems.is_empty() {
        let _ = writeln!(md, "Reference failures (forces):\n");
        for p in problems.iter().take(20) {
            let _ = writeln!(md, "- {p}");
        }
        let _ = writeln!(md, "- ({} in all)\n", problems.len());
    }
    md
}

/// The section's heading and what it measures.
fn intro() -> String {
    let mut md = String::new();
    let _ = writeln!(md, "## Forces\n");
    let _ = writeln!(
        md,
        "The generated force analysis (`solve` of a definition with masses or loads: position, \
         velocity, acceleration and joint reactions with the driving effort) against an \
         independent double-double reference: the loop-closure kinematics above, then the \
         Newton-Euler equations of every link (sum F = m a_G, sum M_G = J alpha) with all joint \
         reactions and the driving effort as unknowns of one system, equilibrated (rows and \
         columns by powers of two) and solved by pivoted elimination in double-double, and \
         accepted only when every equation's residual is below {:e} of the largest term of the force (moment) equations \
         (`mechanism_reference::newton_euler`). Times: ns per evaluation of the whole `solve` (median, min - max over {ROUNDS} interleaved rounds). \
         Errors: largest absolute error of a force (N) and of a moment or torque (N m) over all \
         reactions (global components of `r_<from>_<to>`, prismatic couples about the field's \
         stated point) and the driving effort; relative: each column's error over that \
         column's largest value (columns that are zero in exact arithmetic: over the largest \
         column of their unit). f32 methods are compared with the reference at their \
         f32-rounded inputs (the loads are decided once per grid point from the f64 \
         reference's motion). `power_residual`: the largest the generated code reports. \
         Beside it, timed in the same rounds: the same definition's kinematics alone \
         (`position`, `velocity`, `acceleration`), and the global method a user would write \
         (`examples/report/global_forces.rs`): after those kinematics, all links' Newton-Euler \
         equations with every reaction and the driving torque as unknowns, assembled per pose \
         into one square system (3 rows per moving link) and solved by nalgebra's LU with \
         partial pivoting, fixed-size (`SMatrix`) or heap (`DMatrix`); its errors are against \
         the same reference. The force analysis alone is a row's time less the kinematics'.\n",
        mechanism_reference::newton_euler::RESIDUAL_TOLERANCE
    );
    md
}

/// One scene's measurements: the references' largest residual and the
/// columns' scales, each method's errors (f64, f32, the global method
/// fixed-size and heap) and the timed rounds (in the order of
/// [`scene_table`]'s rows).
struct Measured {
    max_res: f64,
    scale: Vec<f64>,
    errors: [ForceErrors; 4],
    ns: Vec<Vec<f64>>,
}

/// References at the scene's grid (and at the grid rounded to f32, with
/// the same loads), the generated and global methods' errors against them,
/// and all five methods timed in the same interleaved rounds.
fn measure(sc: &ForceScene, problems: &mut Vec<String>) -> Measured {
    let ref64 = references(sc, &sc.grid, sc.rate, sc.accel, None, problems);
    let loads: Vec<f64> = ref64
        .iter()
        .map(|r| r.as_ref().map_or(0.0, |r| r.load))
        .collect();
    let r32 = |x: f64| x as f32 as f64;
    let grid32: Vec<f64> = sc.grid.iter().map(|&q| r32(q)).collect();
    let (rate32, accel32) = (r32(sc.rate), r32(sc.accel));
    let ref32 = references(sc, &grid32, rate32, accel32, Some(&loads), problems);
    let scale = scales(sc, &ref64);
    let max_res = ref64
        .iter()
        .chain(&ref32)
        .flatten()
        .map(|r| r.residual)
        .fold(0.0f64, f64::max);
    let gen: fn(f64, f64, f64, f64) -> GenSample;
    let gen32: fn(f64, f64, f64, f64) -> GenSample;
    match sc.name {
        "SineMechanism" => (gen, gen32) = (sine::<f64>, sine::<f32>),
        "ShaperForces" => (gen, gen32) = (shaper::<f64>, shaper::<f32>),
        _ => (gen, gen32) = (four_bar::<f64>, four_bar::<f32>),
    }
    let samples = |f: &dyn Fn(f64, f64) -> GenSample| -> Vec<GenSample> {
        sc.grid.iter().zip(&loads).map(|(&q, &l)| f(q, l)).collect()
    };
    let s64 = samples(&|q, l| gen(q, sc.rate, sc.accel, l));
    let s32 = samples(&|q, l| gen32(q, sc.rate, sc.accel, l));
    let global_of = |heap| {
        compare(
            sc,
            &ref64,
            &scale,
            &samples(&|q, l| global(sc.name, q, sc.rate, sc.accel, l, heap)),
        )
    };
    let errors = [
        compare(sc, &ref64, &scale, &s64),
        compare(sc, &ref32, &scale, &s32),
        global_of(false),
        global_of(true),
    ];
    let sw64 = sweep::<f64>(sc.name, &sc.grid, sc.rate, sc.accel, &loads);
    let sw32 = sweep::<f32>(sc.name, &sc.grid, sc.rate, sc.accel, &loads);
    let sw_kin = kinematics_sweep(sc.name, &sc.grid, sc.rate, sc.accel);
    let sw_fixed = global_sweep(sc.name, &sc.grid, sc.rate, sc.accel, &loads, false);
    let sw_heap = global_sweep(sc.name, &sc.grid, sc.rate, sc.accel, &loads, true);
    let n = sc.grid.len();
    let ns = timing::interleaved(
        &[
            (&sw64, n),
            (&sw32, n),
            (&sw_kin, n),
            (&sw_fixed, n),
            (&sw_heap, n),
        ],
        ROUNDS,
        MIN_SAMPLE_NS,
    );
    Measured {
        max_res,
        scale,
        errors,
        ns,
    }
}

/// One scene's subsection: its description and table (markdown), and its
/// CSV written to `out_dir`.
fn scene_table(sc: &ForceScene, m: &Measured, out_dir: &Path) -> String {
    let mut md = String::new();
    let n = sc.grid.len();
    let _ = writeln!(md, "### {}\n", sc.name);
    let largest = |unit: Unit| {
        sc.columns
            .iter()
            .zip(&m.scale)
            .filter(|((_, u), _)| *u == unit)
            .fold(0.0f64, |acc, (_, &x)| acc.max(x))
    };
    let _ = writeln!(
        md,
        "{n} grid points (a full turn in 0.1 deg steps); crank rate {} rad/s, acceleration {} \
         rad/s^2; {} reactions and driving-effort columns; largest force {:.4e} N, largest \
         moment {:.4e} N m; reference residual at most {:.1e}.\n",
        sc.rate,
        sc.accel,
        sc.columns.len(),
        largest(Unit::Force),
        largest(Unit::Moment),
        m.max_res
    );
    let _ = writeln!(
        md,
        "| method | ns/eval median | min - max | force abs err (N) | moment abs err (N m) | rel err | worst column | power_residual max | failed |"
    );
    let _ = writeln!(md, "|---|---:|---:|---:|---:|---:|---|---:|---:|");
    let mut csv = String::from(
        "method,ns_median,ns_min,ns_max,force_abs,moment_abs,rel,worst,power_residual,failures\n",
    );
    let none = ForceErrors::default();
    let [e64, e32, e_fixed, e_heap] = &m.errors;
    let rows = [
        ("generated f64 `solve` (kinematics and forces)", e64),
        ("generated f32 `solve` (kinematics and forces)", e32),
        ("generated f64 kinematics alone", &none),
        ("global Newton-Euler, nalgebra SMatrix LU f64", e_fixed),
        ("global Newton-Euler, heap DMatrix LU f64", e_heap),
    ];
    for (k, (&(name, e), ns)) in rows.iter().zip(&m.ns).enumerate() {
        let (med, lo, hi) = timing::stats(ns);
        let errs = if k == 2 {
            "- | - | - | - | - | -".to_string()
        } else {
            format!(
                "{} | {} | {} | {} | {} | {}",
                sci(e.force_abs),
                sci(e.moment_abs),
                sci(e.rel),
                e.worst,
                if k >= 3 { "-".into() } else { sci(e.power) },
                e.failures
            )
        };
        let _ = writeln!(md, "| {name} | {med:.1} | {lo:.1} - {hi:.1} | {errs} |");
        let _ = writeln!(
            csv,
            "{name},{med},{lo},{hi},{},{},{},{},{},{}",
            e.force_abs, e.moment_abs, e.rel, e.worst, e.power, e.failures
        );
    }
    let _ = writeln!(md);
    std::fs::write(
        out_dir.join(format!("forces_{}.csv", sc.name.to_lowercase())),
        csv,
    )
    .expect("write forces csv");
    md
}
