//! Probe 3: mechanisms no other test defines, each against references the
//! generated code does not use (the double-double `mechanism_reference`:
//! `loop_closure` for kinematics, `newton_euler` for the reactions and the
//! drive; closed forms written here from the geometry; the power balance):
//!
//! 1. `KnucklePress`: a crank drives the knuckle of a toggle press through a
//!    rod (crank -> RRR -> RRP ram), 100 kN on the ram, swept geometrically
//!    to the knuckle's toggle (1e-1 .. 1e-12 rad of crank angle, both sides,
//!    both passes, f64 and f32). `SliderKnuckle`: the same knuckle driven by
//!    its ram with a side load on the knuckle, swept into its fold (where the
//!    RRR group is singular) and past it.
//! 2. `Whitworth`: the Whitworth quick return with a ram, masses on every
//!    link, gravity, a cutting force; forces over a full turn, the stroke and
//!    the time ratio of its strokes against their closed forms.
//! 3. The same Whitworth with masses from 1e-6 to 1e6 kg on its links, and
//!    with every length times 1e-6 and times 1e6.
//!
//! Every figure is printed with `cargo test --test zoo probe3 -- --nocapture`
//! as the measured worst error over its bound (1 = at the bound).

use mechanism::{mechanism, Error, Fault, Real};
use mechanism_reference::constraint::{Constraint, Linkage, Point, Side, V2};
use mechanism_reference::loop_closure;
use mechanism_reference::newton_euler::{
    solve_forces, Body, Direction, Driver, ForceError, Joint, Link, Load, Reaction, Solution,
    State, System,
};
use mechanism_reference::Dd;

use Link::{Body as Bd, Ground};

// ---------------------------------------------------------------------------
// Helpers.

fn d(x: f64) -> Dd {
    Dd::from_f64(x)
}

fn fixed(x: f64, y: f64) -> Point {
    Point::Fixed(V2::new(x, y))
}

/// The reference's reactions and drives for the points' positions `p`,
/// velocities `v` and accelerations `a`.
fn reference_forces(sys: &System, p: &[V2], v: &[V2], a: &[V2]) -> Result<Solution, ForceError> {
    solve_forces(sys, &State { p, v, a })
}

fn len(v: V2) -> f64 {
    v.dot(v).sqrt().to_f64()
}

/// Rounds to `f32` and back (`f32` runs: the reference is built from the
/// values the `f32` code actually holds).
fn r32(x: f64) -> f64 {
    x as f32 as f64
}

/// Positions, velocities and accelerations of every point.
type Motion = (Vec<V2>, Vec<V2>, Vec<V2>);

/// The reference's kinematics for one crank input.
fn kinematics(
    l: &Linkage,
    q: f64,
    w: f64,
    al: f64,
    start: &[(f64, f64)],
) -> Result<Motion, String> {
    let (q, w, al) = ([d(q)], [d(w)], [d(al)]);
    let pose = loop_closure::position(l, &q, start).map_err(|e| format!("{e:?}"))?;
    let v = loop_closure::velocity(l, &pose, &q, &w).map_err(|e| format!("{e:?}"))?;
    let a = loop_closure::acceleration(l, &pose, &v, &q, &w, &al).map_err(|e| format!("{e:?}"))?;
    Ok((pose.points, v, a))
}

/// The reference's columns: every joint's force components (a prismatic
/// pair's couple after them), the driving efforts last, as in the order of
/// [`System::joints`].
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

/// A compared column: its name, the group whose force system yields it
/// (an index into the per-group scales), and whether it is a moment (its
/// scale is the group's force scale times the length scale).
type Col = (&'static str, usize, bool);

/// The worst of `|gen - ref|` over a bound: per column, the bound is
/// `eps * S_g / kappa` with `S_g` the largest reference reaction force of the
/// column's group `g` and of the groups solved before it, whose reactions
/// load it, or the scale of the inertia loads and weights on its bodies
/// (`loads[g]`: the kinematics are accurate to a few eps of the largest
/// acceleration, not of each body's), whichever is larger (times `length`
/// for moments) and `kappa` the pose's
/// condition. Returns the worst ratio and the column.
fn worst_ratio(
    cols: &[Col],
    gen: &[f64],
    reference: &[Dd],
    (length, loads): (f64, &[f64]),
    eps: f64,
    kappa: f64,
) -> (f64, &'static str) {
    let groups = cols.iter().map(|c| c.1).max().unwrap_or(0) + 1;
    let mut scale = vec![0.0f64; groups];
    for (s, l) in scale.iter_mut().zip(loads) {
        *s = *l;
    }
    for (c, r) in cols.iter().zip(reference) {
        if !c.2 {
            scale[c.1] = scale[c.1].max(r.to_f64().abs());
        }
    }
    // A group's force system takes the reactions of the groups solved
    // before it (the later ones, numbered in solve order) as loads, with
    // their errors: its scale is the largest of its own and theirs.
    for g in (0..groups.saturating_sub(1)).rev() {
        scale[g] = scale[g].max(scale[g + 1]);
    }
    let mut worst = (0.0f64, "");
    for ((c, g), r) in cols.iter().zip(gen).zip(reference) {
        let s = scale[c.1] * if c.2 { length } else { 1.0 };
        let mut e = (d(*g) - *r).abs().to_f64() / (eps * s / kappa);
        if !e.is_finite() {
            e = f64::INFINITY;
        }
        if e > worst.0 {
            worst = (e, c.0);
        }
    }
    worst
}

/// Asserts an error is typed: it names one of `groups` and its numbers are
/// finite.
fn typed<T: Real>(e: &Error<T>, groups: &[&str], what: &str) {
    assert!(
        groups.contains(&e.group),
        "{what}: error names {:?}, expected one of {groups:?}: {e}",
        e.group
    );
    let e64 = e.to_f64();
    let ok = match e64.fault {
        Fault::Singular { det, scale } => det.is_finite() && scale.is_finite(),
        _ => true,
    };
    assert!(ok, "{what}: non-finite fault numbers: {e}");
}

// ---------------------------------------------------------------------------
// 1. Toggle press.

mechanism! {
    /// Knuckle-joint press (m, N): the crank O1-A (0.06 about O1 = (0.3,
    /// -0.1)) drives the knuckle B through the rod A-B (0.3); the upper
    /// knuckle link O2-B (0.2) turns about O2 = (0, 0); the lower link B-C
    /// (0.25) pushes the ram C down the vertical guide through O2. The press
    /// force (100 kN, up) resists the ram. Massless links: the drive torque
    /// is the press force times the ram's velocity ratio, which vanishes
    /// where the knuckle straightens (B below O2, the toggle).
    ///
    /// As a four-bar O1-A-B-O2 (ground |O1 O2| = 0.316): crank 0.06 shortest,
    /// 0.06 + 0.316 < 0.3 + 0.2 (Grashof), so the crank turns fully and the
    /// upper link rocks through the toggle twice per turn. `right`: B is
    /// right of O2 -> A (A stays at x >= 0.24 > 0 = B's x at the toggle).
    pub KnucklePress {
        params { r = 0.06, rod = 0.3, upper = 0.2, lower = 0.25, ox = 0.3, oy = -0.1, press = 1.0e5 }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O1 = ground(ox, oy);
        let ram_line = guide(O2, -90 deg);
        let A = crank(O1, r, theta) as crank;
        let B = rrr(O2, upper, A, rod, right) as (upper_link, rod_link);
        let C = rrp(B, lower, ram_line, plus) as (lower_link, ram) slide s;
        force at C on ram = (0.0, press);
    }
}

/// The press's dimensions as the reference uses them (rounded by `rnd`).
struct Press {
    r: f64,
    rod: f64,
    upper: f64,
    lower: f64,
    ox: f64,
    oy: f64,
    press: f64,
}

impl Press {
    fn new(rnd: fn(f64) -> f64) -> Press {
        Press {
            r: rnd(0.06),
            rod: rnd(0.3),
            upper: rnd(0.2),
            lower: rnd(0.25),
            ox: rnd(0.3),
            oy: rnd(-0.1),
            press: rnd(1.0e5),
        }
    }

    /// Points: 0 O2, 1 O1, 2 A, 3 B, 4 C, 5 (0, -1) on the ram's guide.
    fn linkage(&self) -> Linkage {
        Linkage {
            points: vec![
                fixed(0.0, 0.0),
                fixed(self.ox, self.oy),
                Point::Unknown,
                Point::Unknown,
                Point::Unknown,
                fixed(0.0, -1.0),
            ],
            constraints: vec![
                Constraint::Crank {
                    p: 2,
                    o: 1,
                    r: self.r,
                    input: 0,
                },
                Constraint::Distance {
                    p: 3,
                    q: 0,
                    len: self.upper,
                },
                Constraint::Distance {
                    p: 3,
                    q: 2,
                    len: self.rod,
                },
                Constraint::Distance {
                    p: 4,
                    q: 3,
                    len: self.lower,
                },
                Constraint::OnFixedLine {
                    p: 4,
                    origin: V2::new(0.0, 0.0),
                    dir: V2::new(0.0, -1.0),
                },
            ],
            sides: vec![
                Side::Left {
                    p: 3,
                    a: 0,
                    b: 2,
                    sign: -1.0,
                },
                Side::Ahead {
                    p: 4,
                    a: 3,
                    from: 0,
                    to: 5,
                },
            ],
            scale: 0.3,
        }
    }

    /// Bodies 0 crank, 1 upper_link, 2 rod_link, 3 lower_link, 4 ram (all
    /// massless); joints in the order of [`PRESS_COLS`]. The lower link is
    /// pinned at B to the upper link (the first link of B's statement, see
    /// docs/dsl.md).
    fn system(&self) -> System {
        System {
            bodies: vec![
                Body::new(0.0, 1, 0.0, None),
                Body::new(0.0, 0, 0.0, None),
                Body::new(0.0, 2, 0.0, None),
                Body::new(0.0, 3, 0.0, None),
                Body::new(0.0, 4, 0.0, None),
            ],
            joints: vec![
                Joint::revolute(Ground, Bd(0), 1),
                Joint::revolute(Bd(0), Bd(2), 2),
                Joint::revolute(Ground, Bd(1), 0),
                Joint::revolute(Bd(1), Bd(2), 3),
                Joint::revolute(Bd(1), Bd(3), 3),
                Joint::revolute(Bd(3), Bd(4), 4),
                Joint::prismatic(Ground, Bd(4), Direction::Fixed(V2::new(0.0, -1.0)), 4),
            ],
            drivers: vec![Driver::Torque { body: 0 }],
            loads: vec![Load::Force {
                body: 4,
                at: 4,
                force: V2::new(0.0, self.press),
            }],
            gravity: V2::default(),
        }
    }

    /// The two crank angles (rad) of the toggle, in double-double: B at
    /// `(0, -upper)` straight below O2, A on both the crank's circle about O1
    /// and the rod's circle about B (the two intersections).
    fn toggles(&self) -> [Dd; 2] {
        let (o1x, o1y) = (d(self.ox), d(self.oy));
        let (bx, by) = (Dd::ZERO, -d(self.upper));
        let (dx, dy) = (bx - o1x, by - o1y);
        let dist = (dx * dx + dy * dy).sqrt();
        let (ux, uy) = (dx / dist, dy / dist);
        let (r, l) = (d(self.r), d(self.rod));
        let along = (r * r - l * l + dist * dist) / (d(2.0) * dist);
        let h = (r * r - along * along).sqrt();
        [h, -h].map(|h| {
            let ax = ux * along - uy * h;
            let ay = uy * along + ux * h;
            Dd::atan2(ay, ax)
        })
    }
}

/// Group 0: the crank (its pivot and the drive), 1: the RRR at B, 2: the RRP
/// at C.
const PRESS_COLS: [Col; 15] = [
    ("r_ground_crank.x", 0, false),
    ("r_ground_crank.y", 0, false),
    ("r_crank_rod_link.x", 1, false),
    ("r_crank_rod_link.y", 1, false),
    ("r_ground_upper_link.x", 1, false),
    ("r_ground_upper_link.y", 1, false),
    ("r_upper_link_rod_link.x", 1, false),
    ("r_upper_link_rod_link.y", 1, false),
    ("r_upper_link_lower_link.x", 2, false),
    ("r_upper_link_lower_link.y", 2, false),
    ("r_lower_link_ram.x", 2, false),
    ("r_lower_link_ram.y", 2, false),
    ("r_ground_ram.force.x", 2, false),
    ("r_ground_ram.force.y", 2, false),
    ("r_ground_ram.moment", 2, true),
];

/// The generated press at crank angle `q` (rate 1 rad/s, no acceleration:
/// massless links, so the forces do not depend on them): columns in the
/// order of [`PRESS_COLS`] plus the drive, its `condition`, and the
/// positions of O2, O1, A, B, C, (0, -1) as a starting guess.
type PressSample = (Vec<f64>, f64, Vec<(f64, f64)>);

fn press_gen<T: Real>(q: f64) -> Result<PressSample, Error<T>> {
    let m = KnucklePress::<T>::default();
    let i = |x: f64| KnucklePressInput { theta: T::lit(x) };
    let s = m.solve(&i(q), &i(1.0), &i(0.0))?;
    let f = &s.forces;
    let v = |x: &mechanism::Vector2<T>| [x.x.as_f64(), x.y.as_f64()];
    let mut c = Vec::new();
    c.extend(v(&f.r_ground_crank));
    c.extend(v(&f.r_crank_rod_link));
    c.extend(v(&f.r_ground_upper_link));
    c.extend(v(&f.r_upper_link_rod_link));
    c.extend(v(&f.r_upper_link_lower_link));
    c.extend(v(&f.r_lower_link_ram));
    c.extend(v(&f.r_ground_ram.force));
    c.push(f.r_ground_ram.moment.as_f64());
    c.push(f.drive_theta.as_f64());
    let p = |x: &mechanism::Point2<T>| (x.x.as_f64(), x.y.as_f64());
    let pos = vec![
        (0.0, 0.0),
        (0.0, 0.0),
        p(&s.position.A),
        p(&s.position.B),
        p(&s.position.C),
        (0.0, -1.0),
    ];
    Ok((c, f.condition.as_f64(), pos))
}

/// `|sin|` of the angle between the segments `a -> b` and `c -> e`.
fn sin_between(p: &[V2], (a, b): (usize, usize), (c, e): (usize, usize)) -> f64 {
    let (u, v) = (p[b].minus(p[a]), p[e].minus(p[c]));
    (u.cross(v).abs() / (u.dot(u).sqrt() * v.dot(v).sqrt())).to_f64()
}

/// `|cos|` of the angle between the segments `a -> b` and `c -> e`.
fn cos_between(p: &[V2], (a, b): (usize, usize), (c, e): (usize, usize)) -> f64 {
    let (u, v) = (p[b].minus(p[a]), p[e].minus(p[c]));
    (u.dot(v).abs() / (u.dot(u).sqrt() * v.dot(v).sqrt())).to_f64()
}

/// One toggle sweep's figures.
#[derive(Debug, Default)]
struct PressFigures {
    /// Worst error over `eps S / kappa` (see [`worst_ratio`]) and its column.
    worst: (f64, &'static str),
    /// Smallest independent condition met.
    kappa: f64,
    /// Smallest crank offset from the toggle reached (rad).
    closest: f64,
    /// Samples.
    n: usize,
}

/// Sweeps the press to both toggles from both sides by decades (offsets
/// 1.37e-1 .. 1.37e-12 rad) in `T`, against the reference at the same
/// (rounded) input and dimensions. `mistake` adds a deliberate error of
/// `mistake eps F L` to the generated drive (`F` the press force, `L` the
/// rod) to show the check can fail.
fn press_sweep<T: Real>(rnd: fn(f64) -> f64, eps: f64, mistake: f64) -> PressFigures {
    let dims = Press::new(rnd);
    let (lk, sys) = (dims.linkage(), dims.system());
    let mut fig = PressFigures {
        kappa: 1.0,
        closest: 1.0,
        ..PressFigures::default()
    };
    for t in dims.toggles() {
        for side in [1.0, -1.0] {
            for k in 1..=12 {
                let off = side * 1.37 * 10f64.powi(-k);
                let q = rnd((t + d(off)).to_f64());
                let what = format!("KnucklePress<{}> at toggle {} {off:e}", eps, t.to_f64());
                // Nothing is singular at the toggle (the RRR's links meet at
                // a finite angle, the RRP's lower link runs along its guide):
                // an error here is a defect.
                let (mut gen, cond, start) =
                    press_gen::<T>(q).unwrap_or_else(|e| panic!("{what}: {e}"));
                assert!(gen.iter().all(|x| x.is_finite()), "{what}: {gen:?}");
                assert!(cond.is_finite() && cond > 0.0, "{what}: condition {cond}");
                let (p, v, a) = kinematics(&lk, q, 1.0, 0.0, &start).expect("reference");
                let sol = reference_forces(&sys, &p, &v, &a).expect("reference forces");
                let refc = ref_columns(&sol);
                // The reference's own power balance (massless links): drive
                // times 1 rad/s plus the press force's power is zero, to
                // double-double rounding of the largest power.
                let power = refc[15] + d(dims.press) * v[4].y;
                assert!(
                    power.abs().to_f64() <= 1e-25 * dims.press * dims.rod,
                    "{what}: reference power {power}"
                );
                *gen.last_mut().unwrap() += mistake * eps * dims.press * dims.rod;
                // Independent condition: the RRR's angle at B (rod against
                // upper link) and the RRP's lower link against the guide's
                // normal (singular when at right angles to the guide).
                let kappa = sin_between(&p, (0, 3), (2, 3)).min(cos_between(&p, (3, 4), (0, 5)));
                let mut cols = PRESS_COLS.to_vec();
                cols.push(("drive_theta", 0, true));
                let w = worst_ratio(&cols, &gen, &refc, (dims.rod, &[]), eps, kappa);
                if w.0 > fig.worst.0 {
                    fig.worst = w;
                }
                fig.kappa = fig.kappa.min(kappa);
                fig.closest = fig.closest.min((d(q) - t).abs().to_f64().max(1e-300));
                fig.n += 1;
            }
        }
    }
    fig
}

/// Bound of the press's columns, in `eps S / kappa` (see [`worst_ratio`]):
/// each reaction comes out of a 2- to 4-unknown pivoted elimination whose
/// inputs (positions, the reactions of the group before) carry a few eps of
/// their scale: a backward-stable answer is within a few units. 8 is four
/// times the worst measured (2.2 in f64 and f32); a drive 20 eps F L off is
/// caught (`press_check_fails_on_a_drive_off_by_20_eps`).
const PRESS_BOUND: f64 = 8.0;

#[test]
fn knuckle_press_to_the_toggle() {
    let f64s = press_sweep::<f64>(|x| x, f64::EPSILON, 0.0);
    let f32s = press_sweep::<f32>(r32, f32::EPSILON as f64, 0.0);
    println!("KnucklePress f64: {f64s:?}");
    println!("KnucklePress f32: {f32s:?}");
    for f in [&f64s, &f32s] {
        assert!(f.worst.0 <= PRESS_BOUND, "{f:?}");
    }
    // The f64 sweep reached the toggle to 1.4e-12 rad.
    assert!(f64s.closest < 2e-12 && f64s.n == 48, "{f64s:?}");
    for (t, q) in Press::new(|x| x).toggles().iter().zip(["first", "second"]) {
        // The drive torque vanishes linearly: T / offset tends to a constant.
        let mut line = format!(
            "KnucklePress {q} toggle {:.15} rad: drive/offset",
            t.to_f64()
        );
        for k in [2, 4, 6, 8, 10, 12] {
            let off = 1.37 * 10f64.powi(-k);
            let (c, _, _) = press_gen::<f64>((*t + d(off)).to_f64()).unwrap();
            line += &format!(" {:.6e}", c[15] / off);
        }
        println!("{line}");
    }
}

#[test]
fn press_check_fails_on_a_drive_off_by_20_eps() {
    let f = press_sweep::<f64>(|x| x, f64::EPSILON, 20.0);
    assert!(
        f.worst.0 > PRESS_BOUND && f.worst.1 == "drive_theta",
        "{f:?}"
    );
}

mechanism! {
    /// The press's knuckle driven by its ram (m, N): the ram C slides down
    /// the vertical guide through O2 by `s`; the upper link O2-B (0.2) and
    /// the lower link B-C (0.25) meet at the knuckle B (`left` of O2 -> C:
    /// to +x). 100 kN on the ram (up), 500 N on the knuckle (+x). At `s =
    /// 0.45` the knuckle is straight: the RRR group is singular there (its
    /// links aligned), its reactions grow as `H / (2 sin)` of the knuckle's
    /// half angle; beyond, it cannot close.
    pub SliderKnuckle {
        dof 1;
        let O2 = ground(0.0, 0.0);
        let line = guide(O2, -90 deg);
        let C = slider(line, s) as ram;
        let B = rrr(O2, 0.2, C, 0.25, left) as (upper_link, lower_link);
        force at C on ram = (0.0, 1.0e5);
        force at B on upper_link = (500.0, 0.0);
    }
}

/// `SliderKnuckle`'s columns: group 0 the slider (its guide and the drive),
/// group 1 the RRR.
const KNUCKLE_COLS: [Col; 10] = [
    ("r_ground_ram.force.x", 0, false),
    ("r_ground_ram.force.y", 0, false),
    ("r_ground_ram.moment", 0, true),
    ("drive_s", 0, false),
    ("r_ground_upper_link.x", 1, false),
    ("r_ground_upper_link.y", 1, false),
    ("r_ram_lower_link.x", 1, false),
    ("r_ram_lower_link.y", 1, false),
    ("r_upper_link_lower_link.x", 1, false),
    ("r_upper_link_lower_link.y", 1, false),
];

fn knuckle_gen<T: Real>(s: f64) -> Result<Vec<f64>, Error<T>> {
    let m = SliderKnuckle::<T>::default();
    let i = |x: f64| SliderKnuckleInput { s: T::lit(x) };
    let f = m.solve(&i(s), &i(1.0), &i(0.0))?.forces;
    let v = |x: &mechanism::Vector2<T>| [x.x.as_f64(), x.y.as_f64()];
    let mut c = Vec::new();
    c.extend(v(&f.r_ground_ram.force));
    c.push(f.r_ground_ram.moment.as_f64());
    c.push(f.drive_s.as_f64());
    c.extend(v(&f.r_ground_upper_link));
    c.extend(v(&f.r_ram_lower_link));
    c.extend(v(&f.r_upper_link_lower_link));
    Ok(c)
}

/// The reference for `SliderKnuckle` at ram displacement `s` (dimensions
/// rounded by `rnd`): the knuckle from the triangle O2-B-C in double-double,
/// `h^2 = ((l1 + l2)^2 - s^2) (s^2 - (l1 - l2)^2) / (4 s^2)` factored so that
/// `l1 + l2 - s` is formed exactly; `None` where it cannot close. Returns
/// the columns and `sin` of the angle at B.
fn knuckle_ref(s: f64, rnd: fn(f64) -> f64) -> Option<(Vec<Dd>, f64)> {
    let (l1, l2, sd) = (d(rnd(0.2)), d(rnd(0.25)), d(s));
    let far = (l1 + l2 - sd) * (l1 + l2 + sd);
    let near = (sd - (l2 - l1)) * (sd + (l2 - l1));
    if far.hi <= 0.0 || near.hi <= 0.0 {
        return None;
    }
    let h = (far * near).sqrt() / (d(2.0) * sd);
    let along = (l1 * l1 - l2 * l2 + sd * sd) / (d(2.0) * sd);
    // Points: 0 O2, 1 C = (0, -s), 2 B = (h, -along).
    let p = [
        V2::default(),
        V2 {
            x: Dd::ZERO,
            y: -sd,
        },
        V2 { x: h, y: -along },
    ];
    let zero = [V2::default(); 3];
    let dir = Direction::Fixed(V2::new(0.0, -1.0));
    let sys = System {
        bodies: vec![
            Body::new(0.0, 0, 0.0, None),
            Body::new(0.0, 1, 0.0, None),
            Body::new(0.0, 1, 0.0, None),
        ],
        joints: vec![
            Joint::prismatic(Ground, Bd(2), dir, 1),
            Joint::revolute(Ground, Bd(0), 0),
            Joint::revolute(Bd(2), Bd(1), 1),
            Joint::revolute(Bd(0), Bd(1), 2),
        ],
        drivers: vec![Driver::Force {
            body: 2,
            at: 1,
            dir,
        }],
        loads: vec![
            Load::Force {
                body: 2,
                at: 1,
                force: V2::new(0.0, rnd(1.0e5)),
            },
            Load::Force {
                body: 0,
                at: 2,
                force: V2::new(rnd(500.0), 0.0),
            },
        ],
        gravity: V2::default(),
    };
    let sol = reference_forces(&sys, &p, &zero, &zero).ok()?;
    let c = ref_columns(&sol);
    // The column order of KNUCKLE_COLS: the slide (3), the drive, then the
    // three pins.
    let mut out = c[..3].to_vec();
    out.push(c[9]);
    out.extend_from_slice(&c[3..9]);
    Some((out, sin_between(&p, (2, 0), (2, 1))))
}

/// Sweeps `SliderKnuckle` into its fold and past it by decades of `1 - s /
/// (l1 + l2)`; returns, per power `k` of the bound `eps S / sin^k`, the
/// worst ratio, the smallest `sin` met with an answer, and the numbers of
/// answers and typed errors. `mistake` as in [`press_sweep`] (on the drive).
fn knuckle_sweep<T: Real>(
    rnd: fn(f64) -> f64,
    eps: f64,
    mistake: f64,
) -> ([f64; 3], f64, usize, usize) {
    let reach = rnd(0.2) + rnd(0.25);
    let (mut worst, mut kappa_min, mut oks, mut errs) = ([0.0f64; 3], 1.0f64, 0, 0);
    for side in [1.0, -1.0] {
        for k in 1..=17 {
            let s = rnd(reach * (1.0 - side * 1.37 * 10f64.powi(-k)));
            let what = format!("SliderKnuckle<{eps:e}> s = {s:e}");
            let gen = knuckle_gen::<T>(s);
            let reference = knuckle_ref(s, rnd);
            match (gen, reference) {
                (Ok(mut g), Some((r, sin))) => {
                    assert!(g.iter().all(|x| x.is_finite()), "{what}: {g:?}");
                    g[3] += mistake * eps * rnd(1.0e5);
                    for (kk, w) in worst.iter_mut().enumerate() {
                        let kappa = sin.powi(kk as i32);
                        *w = w.max(worst_ratio(&KNUCKLE_COLS, &g, &r, (reach, &[]), eps, kappa).0);
                    }
                    kappa_min = kappa_min.min(sin);
                    oks += 1;
                }
                (Err(e), _) => {
                    typed(&e, &["B", "C"], &what);
                    errs += 1;
                }
                (Ok(g), None) => panic!("{what}: the knuckle cannot close, yet Ok {g:?}"),
            }
        }
    }
    (worst, kappa_min, oks, errs)
}

/// Bound of `SliderKnuckle`'s columns in `eps S / sin^2`, `sin` that of the
/// knuckle's angle at B, `S` the group's largest reaction (about `H / (2
/// sin)`): the knuckle's position is backward stable (its error is that of
/// lengths a few eps off), and the reactions' sensitivity to the lengths is
/// `1 / sin^2` relative near the fold (`sin` itself moves by `eps / sin^2`
/// relative). The measured constant is 0.72 (f64) and 2.5 (f32) with `sin`
/// down to 3.2e-8 (f64) and 1.2e-3 (f32); the bounds `eps S / sin^0` or
/// `/ sin` are exceeded by 2e14 and 7e6 (printed): the growth is real,
/// not a slack bound. 8 as for the press.
const KNUCKLE_BOUND: f64 = 8.0;

#[test]
fn slider_knuckle_into_its_fold() {
    let f64s = knuckle_sweep::<f64>(|x| x, f64::EPSILON, 0.0);
    let f32s = knuckle_sweep::<f32>(r32, f32::EPSILON as f64, 0.0);
    println!("SliderKnuckle f64 (worst for k = 0, 1, 2; min sin; ok; errors): {f64s:?}");
    println!("SliderKnuckle f32: {f32s:?}");
    for f in [&f64s, &f32s] {
        assert!(f.0[2] <= KNUCKLE_BOUND, "{f:?}");
        // Every sample past the fold was a typed error, every one short of
        // it an answer down to sin ~ sqrt(eps).
        assert!(f.2 >= 7 && f.3 >= 17, "{f:?}");
    }
    assert!(f64s.1 < 1e-7, "{f64s:?}");
    let bad = knuckle_sweep::<f64>(|x| x, f64::EPSILON, 100.0);
    assert!(
        bad.0[2] > KNUCKLE_BOUND,
        "a drive 100 eps F off passes: {bad:?}"
    );
}

// ---------------------------------------------------------------------------
// 3. Whitworth quick return, and 4. its extreme masses and scales.

mechanism! {
    /// Whitworth quick return (m, kg, N): the crank O2-B (`r`) turns about
    /// O2 = (0, 0); its block slides along the slotted link, which turns
    /// fully about O4 = (0, -dd) (`dd < r`, so O4 is inside the crank's
    /// circle); the slotted link's arm O4-D (`arm`, opposite the block)
    /// drives the ram E along the horizontal guide through O4 by the rod D-E
    /// (`rod > arm`). Masses on every link, gravity, a cutting force `cut`
    /// resisting the ram along -x.
    pub Whitworth {
        params {
            r = 0.2, dd = 0.07, arm = 0.25, rod = 0.6, g1 = 0.1, g3 = 0.05,
            m1 = 1.0, j1 = 0.004, m2 = 0.3, m3 = 4.0, j3 = 0.08, m4 = 1.5, j4 = 0.045,
            m5 = 20.0, cut = 2000.0
        }
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.0, -dd);
        let ram_line = guide(O4, 0 deg);
        let B = crank(O2, r, theta) as crank;
        let sb = rpr(B, O4, plus) as (block, slotted);
        let D = point(slotted, from O4, arm, 180 deg);
        let E = rrp(D, rod, ram_line, plus) as (link4, ram) slide x;
        let G1 = point(crank, from O2, g1, 0 deg);
        let G3 = point(slotted, from O4, g3, 0 deg);
        let G4 = point(link4, from D, rod * 0.5, 0 deg);
        mass crank { m = m1, at = G1, j = j1 };
        mass block { m = m2, at = B };
        mass slotted { m = m3, at = G3, j = j3 };
        mass link4 { m = m4, at = G4, j = j4 };
        mass ram { m = m5, at = E };
        gravity (0.0, -9.81);
        force at E on ram along ram_line = -cut;
    }
}

/// The Whitworth's parameters (f64), in the order of the definition.
#[derive(Clone, Copy, Debug)]
struct Ww {
    r: f64,
    dd: f64,
    arm: f64,
    rod: f64,
    g1: f64,
    g3: f64,
    m: [f64; 5],
    j: [f64; 3],
    cut: f64,
}

impl Ww {
    fn nominal() -> Ww {
        Ww {
            r: 0.2,
            dd: 0.07,
            arm: 0.25,
            rod: 0.6,
            g1: 0.1,
            g3: 0.05,
            m: [1.0, 0.3, 4.0, 1.5, 20.0],
            j: [0.004, 0.08, 0.045],
            cut: 2000.0,
        }
    }
    /// Every length times `k` (inertias times `k^2`).
    fn scaled(mut self, k: f64) -> Ww {
        for l in [
            &mut self.r,
            &mut self.dd,
            &mut self.arm,
            &mut self.rod,
            &mut self.g1,
            &mut self.g3,
        ] {
            *l *= k;
        }
        for j in &mut self.j {
            *j *= k * k;
        }
        self
    }
    /// Every number rounded by `rnd`.
    fn rounded(mut self, rnd: fn(f64) -> f64) -> Ww {
        for l in [
            &mut self.r,
            &mut self.dd,
            &mut self.arm,
            &mut self.rod,
            &mut self.g1,
            &mut self.g3,
            &mut self.cut,
        ] {
            *l = rnd(*l);
        }
        self.m = self.m.map(rnd);
        self.j = self.j.map(rnd);
        self
    }
    fn generated<T: Real>(&self) -> Whitworth<T> {
        let t = T::lit;
        Whitworth {
            r: t(self.r),
            dd: t(self.dd),
            arm: t(self.arm),
            rod: t(self.rod),
            g1: t(self.g1),
            g3: t(self.g3),
            m1: t(self.m[0]),
            j1: t(self.j[0]),
            m2: t(self.m[1]),
            m3: t(self.m[2]),
            j3: t(self.j[1]),
            m4: t(self.m[3]),
            j4: t(self.j[2]),
            m5: t(self.m[4]),
            cut: t(self.cut),
        }
    }
    /// Points: 0 O2, 1 O4, 2 (1, -dd) on the ram's guide, 3 B, 4 D, 5 E.
    fn linkage(&self) -> Linkage {
        Linkage {
            points: vec![
                fixed(0.0, 0.0),
                fixed(0.0, -self.dd),
                fixed(1.0, -self.dd),
                Point::Unknown,
                Point::Unknown,
                Point::Unknown,
            ],
            constraints: vec![
                Constraint::Crank {
                    p: 3,
                    o: 0,
                    r: self.r,
                    input: 0,
                },
                Constraint::OnLine { p: 4, q1: 1, q2: 3 },
                Constraint::Distance {
                    p: 4,
                    q: 1,
                    len: self.arm,
                },
                Constraint::Distance {
                    p: 5,
                    q: 4,
                    len: self.rod,
                },
                Constraint::OnFixedLine {
                    p: 5,
                    origin: V2::new(0.0, -self.dd),
                    dir: V2::new(1.0, 0.0),
                },
            ],
            sides: vec![
                // D behind O4 seen from B (the arm opposite the block).
                Side::Ahead {
                    p: 1,
                    a: 4,
                    from: 1,
                    to: 3,
                },
                // E ahead of D along +x.
                Side::Ahead {
                    p: 5,
                    a: 4,
                    from: 1,
                    to: 2,
                },
            ],
            scale: self.rod,
        }
    }
    /// The linkage's points and the centres of mass: 6 G1, 7 G3, 8 G4
    /// (linear in the points, so the same map gives their rates).
    fn extend(&self, p: &[V2]) -> Vec<V2> {
        let mut v = p.to_vec();
        v.push(p[0].plus(p[3].minus(p[0]).scale(d(self.g1) / d(self.r))));
        v.push(p[1].plus(p[1].minus(p[4]).scale(d(self.g3) / d(self.arm))));
        v.push(p[4].plus(p[5].minus(p[4]).scale(d(0.5))));
        v
    }
    /// Bodies 0 crank, 1 block, 2 slotted, 3 link4, 4 ram; joints in the
    /// order of [`WW_COLS`].
    fn system(&self) -> System {
        let (m, j) = (self.m, self.j);
        System {
            bodies: vec![
                Body::new(m[0], 6, j[0], Some((0, 3))),
                Body::new(m[1], 3, 0.0, None),
                Body::new(m[2], 7, j[1], Some((1, 3))),
                Body::new(m[3], 8, j[2], Some((4, 5))),
                Body::new(m[4], 5, 0.0, None),
            ],
            joints: vec![
                Joint::revolute(Ground, Bd(0), 0),
                Joint::revolute(Bd(0), Bd(1), 3),
                Joint::prismatic(Bd(1), Bd(2), Direction::Segment(1, 3), 3),
                Joint::revolute(Ground, Bd(2), 1),
                Joint::revolute(Bd(2), Bd(3), 4),
                Joint::revolute(Bd(3), Bd(4), 5),
                Joint::prismatic(Ground, Bd(4), Direction::Fixed(V2::new(1.0, 0.0)), 5),
            ],
            drivers: vec![Driver::Torque { body: 0 }],
            loads: vec![Load::Force {
                body: 4,
                at: 5,
                force: V2::new(-self.cut, 0.0),
            }],
            gravity: V2::new(0.0, -9.81),
        }
    }
}

/// Groups: 0 the crank (its pivot, the drive), 1 the RPR, 2 the RRP.
const WW_COLS: [Col; 18] = [
    ("r_ground_crank.x", 0, false),
    ("r_ground_crank.y", 0, false),
    ("r_crank_block.x", 1, false),
    ("r_crank_block.y", 1, false),
    ("r_block_slotted.force.x", 1, false),
    ("r_block_slotted.force.y", 1, false),
    ("r_block_slotted.moment", 1, true),
    ("r_ground_slotted.x", 1, false),
    ("r_ground_slotted.y", 1, false),
    ("r_slotted_link4.x", 2, false),
    ("r_slotted_link4.y", 2, false),
    ("r_link4_ram.x", 2, false),
    ("r_link4_ram.y", 2, false),
    ("r_ground_ram.force.x", 2, false),
    ("r_ground_ram.force.y", 2, false),
    ("r_ground_ram.moment", 2, true),
    ("drive_theta", 0, true),
    ("power_residual", 0, false),
];

/// Columns and starting guess (see [`ww_gen`]).
type WwSample = (Vec<f64>, Vec<(f64, f64)>);

/// The generated Whitworth's columns (the order of [`WW_COLS`], the last its
/// `power_residual`) and the positions of the linkage's points.
fn ww_gen<T: Real>(w: &Ww, q: f64, rate: f64, accel: f64) -> Result<WwSample, Error<T>> {
    let m = w.generated::<T>();
    let i = |x: f64| WhitworthInput { theta: T::lit(x) };
    let s = m.solve(&i(q), &i(rate), &i(accel))?;
    let f = &s.forces;
    let v = |x: &mechanism::Vector2<T>| [x.x.as_f64(), x.y.as_f64()];
    let mut c = Vec::new();
    c.extend(v(&f.r_ground_crank));
    c.extend(v(&f.r_crank_block));
    c.extend(v(&f.r_block_slotted.force));
    c.push(f.r_block_slotted.moment.as_f64());
    c.extend(v(&f.r_ground_slotted));
    c.extend(v(&f.r_slotted_link4));
    c.extend(v(&f.r_link4_ram));
    c.extend(v(&f.r_ground_ram.force));
    c.push(f.r_ground_ram.moment.as_f64());
    c.push(f.drive_theta.as_f64());
    c.push(f.power_residual.as_f64());
    let p = |x: &mechanism::Point2<T>| (x.x.as_f64(), x.y.as_f64());
    let pos = vec![
        (0.0, 0.0),
        (0.0, 0.0),
        (0.0, 0.0),
        p(&s.position.B),
        p(&s.position.D),
        p(&s.position.E),
    ];
    Ok((c, pos))
}

/// Worst error over `eps S / kappa` of the Whitworth over a full turn (720
/// steps) at crank rate 6 rad/s and acceleration 3 rad/s^2, in `T`, against
/// the reference built from `w` rounded by `rnd`; the worst
/// `power_residual`; `mistake` adds `mistake eps S_0 L` to the drive.
fn ww_sweep<T: Real>(
    w: &Ww,
    rnd: fn(f64) -> f64,
    eps: f64,
    mistake: f64,
) -> ((f64, &'static str), f64) {
    let wr = w.rounded(rnd);
    let (lk, sys) = (wr.linkage(), wr.system());
    let length = wr.r.max(wr.arm).max(wr.rod);
    let (rate, accel) = (6.0, 3.0);
    let mut worst = (0.0f64, "");
    let mut power = 0.0f64;
    for k in 0..720 {
        let q = rnd((k as f64 + 0.3) * core::f64::consts::PI / 360.0);
        let what = format!("Whitworth {w:?} at {q}");
        let (mut gen, start) =
            ww_gen::<T>(w, q, rate, accel).unwrap_or_else(|e| panic!("{what}: {e}"));
        assert!(gen.iter().all(|x| x.is_finite()), "{what}: {gen:?}");
        power = power.max(gen.pop().unwrap());
        let (p, v, a) = kinematics(&lk, q, rate, accel, &start).expect("reference");
        let (p, v, a) = (wr.extend(&p), wr.extend(&v), wr.extend(&a));
        let sol = reference_forces(&sys, &p, &v, &a).expect("reference forces");
        let refc = ref_columns(&sol);
        // Independent condition: the RRP's rod against the guide's normal,
        // the RPR's slide (the block's distance from O4) over its largest.
        let kappa = cos_between(&p, (4, 5), (1, 2)).min(len(p[3].minus(p[1])) / (wr.r + wr.dd));
        let s0 = refc[..2]
            .iter()
            .chain(&refc[2..16])
            .map(|x| x.to_f64().abs())
            .fold(0.0, f64::max);
        *gen.last_mut().unwrap() += mistake * eps * s0 * length;
        // Inertia and weight scales per group: each body's `m (a_max + g)`
        // and `j alpha_max / L` (a_max, alpha_max the largest point and link
        // accelerations, L the body's length).
        let a_max = a.iter().map(|x| len(*x)).fold(0.0, f64::max);
        let alpha = |i: usize, j: usize| {
            loop_closure::angular_acceleration(&p, &v, &a, i, j)
                .to_f64()
                .abs()
        };
        let al_max = alpha(0, 3).max(alpha(1, 3)).max(alpha(4, 5));
        let scale_of = |k: usize, j: f64, l: f64| wr.m[k] * (a_max + 9.81) + j * al_max / l;
        let loads = [
            scale_of(0, wr.j[0], wr.r),
            scale_of(1, 0.0, 1.0).max(scale_of(2, wr.j[1], wr.arm)),
            scale_of(3, wr.j[2], wr.rod).max(scale_of(4, 0.0, 1.0)),
        ];
        let wq = worst_ratio(&WW_COLS[..17], &gen, &refc, (length, &loads), eps, kappa);
        if std::env::var("WW_TRACE").is_ok() && wq.0 > 20.0 {
            println!("TRACE q {q} kappa {kappa} {wq:?}");
            for (c, (g, r)) in WW_COLS.iter().zip(gen.iter().zip(&refc)) {
                println!(
                    "   {:28} {g:+.17e} {:+.17e} {:e}",
                    c.0,
                    r.to_f64(),
                    (d(*g) - *r).to_f64()
                );
            }
        }
        if wq.0 > worst.0 {
            worst = wq;
        }
    }
    (worst, power)
}

/// Bound of the Whitworth's columns in `eps S / kappa`: as [`PRESS_BOUND`]
/// (inertia loads add the kinematics' few eps of the largest acceleration,
/// hence the inertia scales in `S`: without them the lengths times 1e3 gave
/// 131, the ram's `m a` being small against `m a_max`). Measured: 1.8 (f64
/// and f32) over a turn; 2.8 with masses 1e-6 .. 1e6 kg; 1.8 and 4.5 with
/// lengths times 1e-6 and 1e6 (printed). A drive 20 eps S L off is caught.
const WW_BOUND: f64 = 8.0;

/// `power_residual` bound: a few eps of the largest power when consistent
/// (docs/dsl.md); the crank's rate keeps the driving power well away from a
/// dead centre here, so 64 eps of `T` (measured 3.2e-15 = 14 eps in f64,
/// 8.3e-7 = 7 eps in f32).
const WW_POWER: f64 = 64.0;

#[test]
fn whitworth_forces_over_a_turn() {
    let f64s = ww_sweep::<f64>(&Ww::nominal(), |x| x, f64::EPSILON, 0.0);
    let f32s = ww_sweep::<f32>(&Ww::nominal(), r32, f32::EPSILON as f64, 0.0);
    println!("Whitworth f64 (worst, power_residual): {f64s:?}");
    println!("Whitworth f32: {f32s:?}");
    assert!(
        f64s.0 .0 <= WW_BOUND && f64s.1 <= WW_POWER * f64::EPSILON,
        "{f64s:?}"
    );
    assert!(
        f32s.0 .0 <= WW_BOUND && f32s.1 <= WW_POWER * f32::EPSILON as f64,
        "{f32s:?}"
    );
    let bad = ww_sweep::<f64>(&Ww::nominal(), |x| x, f64::EPSILON, 20.0);
    assert!(bad.0 .0 > WW_BOUND, "a drive 20 eps off passes: {bad:?}");
}

#[test]
fn whitworth_wild_masses_and_scales() {
    let mut cases = Vec::new();
    for m in [
        [1e6, 1e-6, 1e3, 1e-6, 1e6],
        [1e-6, 1e6, 1e-6, 1e6, 1e-6],
        [1e-6, 1e-6, 1e-6, 1e-6, 1e6],
        [1e6, 1e6, 1e6, 1e6, 1e-6],
    ] {
        let mut w = Ww::nominal();
        // Inertias follow the masses (the nominal radii of gyration).
        for (j, (k, m0)) in w.j.iter_mut().zip([(0, 1.0), (2, 4.0), (3, 1.5)]) {
            *j *= m[k] / m0;
        }
        w.m = m;
        cases.push(w);
    }
    for k in [1e-6, 1e6] {
        cases.push(Ww::nominal().scaled(k));
    }
    let mut worst = (0.0f64, "");
    for w in &cases {
        let (e, p) = ww_sweep::<f64>(w, |x| x, f64::EPSILON, 0.0);
        println!(
            "Whitworth masses {:?} r {:e}: worst {e:?}, power_residual {p:e}",
            w.m, w.r
        );
        if e.0 > worst.0 {
            worst = e;
        }
    }
    assert!(worst.0 <= WW_BOUND, "{worst:?}");
}

/// The ram's extremes (closed form): with the ram's guide through O4 and
/// `rod > arm`, E's abscissa `arm cos(phi) + sqrt(rod^2 - arm^2 sin^2)` (phi
/// the arm's angle) is stationary only where `sin(phi) = 0`, the slotted
/// link horizontal, i.e. the block at O4's height: `r sin(theta) = -dd`,
/// `theta_1 = -asin(dd / r)` and `theta_2 = pi + asin(dd / r)`. The crank
/// turns `pi + 2 asin(dd / r)` for one stroke and `pi - 2 asin(dd / r)` for
/// the other; at a uniform crank rate their times have that ratio. The
/// stroke is `2 arm`.
#[test]
fn whitworth_time_ratio() {
    let w = Ww::nominal();
    let m = w.generated::<f64>();
    let at = |q: f64| {
        let i = |x: f64| WhitworthInput { theta: x };
        let p = m.position(&i(q)).unwrap();
        let v = m.velocity(&p, &i(1.0)).unwrap();
        (p.E.x, v.x)
    };
    // The ram's rate changes sign twice a turn: bisect each change on the
    // generated rate.
    let n = 3600;
    let mut roots = Vec::new();
    let q0 = -0.5;
    for k in 0..n {
        let (mut lo, mut hi) = (
            q0 + k as f64 * std::f64::consts::TAU / n as f64,
            q0 + (k + 1) as f64 * std::f64::consts::TAU / n as f64,
        );
        if at(lo).1.signum() == at(hi).1.signum() {
            continue;
        }
        for _ in 0..80 {
            let mid = 0.5 * (lo + hi);
            if at(mid).1.signum() == at(lo).1.signum() {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        roots.push(0.5 * (lo + hi));
    }
    assert_eq!(roots.len(), 2, "{roots:?}");
    let a = (w.dd / w.r).asin();
    let exact = [-a, std::f64::consts::PI + a];
    let root_err = roots
        .iter()
        .zip(exact)
        .map(|(r, e)| (r - e).abs())
        .fold(0.0, f64::max);
    let slow = roots[1] - roots[0];
    let ratio = slow / (std::f64::consts::TAU - slow);
    let closed = (std::f64::consts::PI + 2.0 * a) / (std::f64::consts::PI - 2.0 * a);
    let stroke = (at(roots[0]).0 - at(roots[1]).0).abs();
    println!(
        "Whitworth strokes at {roots:?} (closed form {exact:?}, worst {root_err:e} rad); time ratio {ratio} vs {closed} (rel {:e}); stroke {stroke} vs {}",
        (ratio / closed - 1.0).abs(),
        2.0 * w.arm
    );
    // The rate's rounding (a few eps of its scale, about 0.3 m/s per rad/s)
    // over its slope at the roots (of that order) places each root to about
    // 1e-15 rad; 1e-13 leaves room and misses nothing a wrong geometry
    // would show (a 1e-3 change of dd moves the roots by 5e-3 rad).
    assert!(root_err <= 1e-13, "{roots:?} vs {exact:?}");
    assert!((ratio / closed - 1.0).abs() <= 1e-13, "{ratio} vs {closed}");
    // E's abscissa at the extremes is stationary: its error there is the
    // position's few eps of the rod, 1e-15; 1e-14 leaves room.
    assert!((stroke - 2.0 * w.arm).abs() <= 1e-14, "{stroke}");
}
