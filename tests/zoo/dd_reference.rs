//! What the zoo's double-double checks share: the reference's kinematics
//! (`mechanism_reference::loop_closure`) and reactions
//! (`mechanism_reference::newton_euler`) for one crank input, the worst
//! error of the generated reactions over their bound `eps S / kappa`
//! (`worst_ratio`), and the check that an error is typed.

use mechanism::{Error, Fault, Real};
use mechanism_reference::constraint::{Linkage, Point, V2};
use mechanism_reference::loop_closure;
use mechanism_reference::newton_euler::{
    solve_forces, ForceError, Reaction, Solution, State, System,
};
use mechanism_reference::Dd;

pub fn d(x: f64) -> Dd {
    Dd::from_f64(x)
}

pub fn fixed(x: f64, y: f64) -> Point {
    Point::Fixed(V2::new(x, y))
}

/// The reference's reactions and drives for the points' positions `p`,
/// velocities `v` and accelerations `a`.
pub fn reference_forces(
    sys: &System,
    p: &[V2],
    v: &[V2],
    a: &[V2],
) -> Result<Solution, ForceError> {
    solve_forces(sys, &State { p, v, a })
}

pub fn len(v: V2) -> f64 {
    v.dot(v).sqrt().to_f64()
}

/// Rounds to `f32` and back (`f32` runs: the reference is built from the
/// values the `f32` code actually holds).
pub fn r32(x: f64) -> f64 {
    x as f32 as f64
}

/// Positions, velocities and accelerations of every point.
pub type Motion = (Vec<V2>, Vec<V2>, Vec<V2>);

/// The reference's kinematics for one crank input.
pub fn kinematics(
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
pub fn ref_columns(sol: &Solution) -> Vec<Dd> {
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
pub type Col = (&'static str, usize, bool);

/// The worst of `|gen - ref|` over a bound: per column, the bound is
/// `eps * S_g / kappa` with `S_g` the largest reference reaction force of the
/// column's group `g` and of the groups solved before it, whose reactions
/// load it, or the scale of the inertia loads and weights on its bodies
/// (`loads[g]`: the kinematics are accurate to a few eps of the largest
/// acceleration, not of each body's), whichever is larger (times `length`
/// for moments) and `kappa` the pose's
/// condition. Returns the worst ratio and the column.
pub fn worst_ratio(
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
pub fn typed<T: Real>(e: &Error<T>, groups: &[&str], what: &str) {
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

/// `|sin|` of the angle between the segments `a -> b` and `c -> e`.
pub fn sin_between(p: &[V2], (a, b): (usize, usize), (c, e): (usize, usize)) -> f64 {
    let (u, v) = (p[b].minus(p[a]), p[e].minus(p[c]));
    (u.cross(v).abs() / (u.dot(u).sqrt() * v.dot(v).sqrt())).to_f64()
}

/// `|cos|` of the angle between the segments `a -> b` and `c -> e`.
pub fn cos_between(p: &[V2], (a, b): (usize, usize), (c, e): (usize, usize)) -> f64 {
    let (u, v) = (p[b].minus(p[a]), p[e].minus(p[c]));
    (u.dot(v).abs() / (u.dot(u).sqrt() * v.dot(v).sqrt())).to_f64()
}
