//! The tests' own closed-form four-bar (independent of the generated code):
//! the circle intersection of the coupler about `A` and the rocker about
//! `O4`, in the benchmark cases' parametrization.
#![allow(dead_code)]

/// One pose: crank pin `A`, coupler-rocker joint `B`, rocker pivot `O4`,
/// coupler point `P`.
pub struct Pose {
    pub a: [f64; 2],
    pub b: [f64; 2],
    pub o4: [f64; 2],
    pub p: [f64; 2],
}

/// The pose of design `d = [r1, r2, r3, r4, rcx, rcy, theta0, x0, y0, ..]` at
/// crank angle `th` (from the ground link) in mode `m` (+1: B left of
/// A -> O4), by intersecting the circles about A (radius r3) and O4 (radius
/// r4); `None` when they do not meet.
pub fn pose(d: &[f64], th: f64, m: f64) -> Option<Pose> {
    let (r1, r2, r3, r4, rcx, rcy, t0, x0, y0) =
        (d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]);
    let o4 = [x0 + r1 * t0.cos(), y0 + r1 * t0.sin()];
    let a = [x0 + r2 * (t0 + th).cos(), y0 + r2 * (t0 + th).sin()];
    let (dx, dy) = (o4[0] - a[0], o4[1] - a[1]);
    let l2 = dx * dx + dy * dy;
    let l = l2.sqrt();
    let along = (r3 * r3 - r4 * r4 + l2) / (2.0 * l);
    let h2 = r3 * r3 - along * along;
    if h2 < -1e-9 * r3 * r3 {
        return None;
    }
    let h = h2.max(0.0).sqrt();
    let (ux, uy) = (dx / l, dy / l);
    let b = [
        a[0] + along * ux - m * h * uy,
        a[1] + along * uy + m * h * ux,
    ];
    let (ex, ey) = ((b[0] - a[0]) / r3, (b[1] - a[1]) / r3);
    let p = [a[0] + rcx * ex - rcy * ey, a[1] + rcx * ey + rcy * ex];
    Some(Pose { a, b, o4, p })
}

/// The coupler point of [`pose`].
pub fn coupler(d: &[f64], th: f64, m: f64) -> Option<[f64; 2]> {
    pose(d, th, m).map(|q| q.p)
}
