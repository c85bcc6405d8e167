//! A double-double reference for the triad (the class III group of the
//! Stephenson III six-bar), written from its loop-closure equations in the
//! four link angles, not from `mechanism-core`'s formulation (which solves
//! for `A` and the ternary's angle from the legs' squared lengths and
//! searches along leg 1's angle).
//!
//! Unknowns `q = (theta1, theta2, theta3, theta4)`: the angles of leg 1
//! (`K1 -> A`), leg 2 (`K2 -> B`), leg 3 (`K3 -> P`) and the ternary link
//! (`A -> B`), with `e(x) = (cos x, sin x)`:
//!
//! ```text
//! K1 + l1 e(theta1) + ab e(theta4)            - l2 e(theta2) - K2 = 0   (B two ways)
//! K1 + l1 e(theta1) + u e(theta4) + v perp(e(theta4)) - l3 e(theta3) - K3 = 0   (P)
//! ```
//!
//! [`newton`] solves them in double-double from a start; [`assemblies`]
//! finds every assembly by a dense scan of the *ternary's* angle `theta4`:
//! for a fixed `theta4`, `A` lies on the circle about `K1` (radius `l1`) and
//! on the circle about `K2 - ab e(theta4)` (radius `l2`); each of the two
//! intersections gives `P` and the residual `|P - K3|^2 - l3^2`, whose sign
//! changes (bisected, then polished by [`newton`]) are the assemblies. Where
//! the circles stop intersecting between two samples, the end is found by
//! bisection and both branches' residuals are compared with the common
//! value there. Rates and accelerations: the same equations differentiated,
//! solved by [`crate::linear::solve`]. [`fold`] finds where an assembly
//! meets another as an input varies (the end of a swing): the equations plus
//! `det J = 0`, Newton with a central-difference Jacobian.

use crate::groups::{add, dot, perp, scale, sub, V};
use crate::linear;
use crate::Dd;

/// The triad's data, exact `f64` values taken as double-double.
#[derive(Clone, Copy, Debug)]
pub struct TriadRef {
    /// `K1`, `K2`, `K3` (L).
    pub k: [V; 3],
    /// Leg lengths `l1`, `l2`, `l3` (L).
    pub l: [Dd; 3],
    /// `|AB|` (L).
    pub ab: Dd,
    /// `P` in the ternary's frame (origin `A`, x along `A -> B`) (L).
    pub p_local: V,
}

/// One assembly.
#[derive(Clone, Copy, Debug)]
pub struct Pose {
    /// `theta1 .. theta4` (rad).
    pub q: [Dd; 4],
    /// Joints `A`, `B`, `P` (L).
    pub joints: [V; 3],
}

fn e(x: Dd) -> V {
    let (s, c) = x.sin_cos();
    [c, s]
}

impl TriadRef {
    /// From `f64` data (exact).
    pub fn new(k: [[f64; 2]; 3], l: [f64; 3], ab: f64, p_local: [f64; 2]) -> TriadRef {
        let v = |p: [f64; 2]| [Dd::from(p[0]), Dd::from(p[1])];
        TriadRef {
            k: k.map(v),
            l: l.map(Dd::from),
            ab: Dd::from(ab),
            p_local: v(p_local),
        }
    }

    /// `P - A` for the ternary's unit axis `e4`.
    fn ap(&self, e4: V) -> V {
        add(scale(self.p_local[0], e4), scale(self.p_local[1], perp(e4)))
    }

    /// The joints for the angles `q` (`A` and `B`, `P` from `A`).
    pub fn joints(&self, q: &[Dd; 4]) -> [V; 3] {
        let a = add(self.k[0], scale(self.l[0], e(q[0])));
        let e4 = e(q[3]);
        [a, add(a, scale(self.ab, e4)), add(a, self.ap(e4))]
    }

    /// The four loop-closure residuals and their Jacobian (rows: the two
    /// vector equations' components; columns: `theta1 .. theta4`).
    fn system(&self, q: &[Dd; 4]) -> ([Dd; 4], [[Dd; 4]; 4]) {
        let es = [e(q[0]), e(q[1]), e(q[2]), e(q[3])];
        let [l1, l2, l3] = self.l;
        let base = add(self.k[0], scale(l1, es[0]));
        let ap = self.ap(es[3]);
        let r1 = sub(
            sub(add(base, scale(self.ab, es[3])), scale(l2, es[1])),
            self.k[1],
        );
        let r2 = sub(sub(add(base, ap), scale(l3, es[2])), self.k[2]);
        let d1 = scale(l1, perp(es[0]));
        let d2 = scale(-l2, perp(es[1]));
        let d3 = scale(-l3, perp(es[2]));
        let d4b = scale(self.ab, perp(es[3]));
        let d4p = perp(ap);
        let z = Dd::ZERO;
        let jac = [
            [d1[0], d2[0], z, d4b[0]],
            [d1[1], d2[1], z, d4b[1]],
            [d1[0], z, d3[0], d4p[0]],
            [d1[1], z, d3[1], d4p[1]],
        ];
        ([r1[0], r1[1], r2[0], r2[1]], jac)
    }

    /// The Jacobian of the loop closure at `q`.
    pub fn jacobian(&self, q: &[Dd; 4]) -> [[Dd; 4]; 4] {
        self.system(q).1
    }
}

/// Newton's method on the loop closure from `q0`: `Some` when the last step
/// is below `1e-28` rad and every residual below `1e-28` of the scale.
pub fn newton(t: &TriadRef, q0: [Dd; 4]) -> Option<Pose> {
    let scale_len = t.l[0] + t.l[1] + t.l[2] + t.ab;
    let mut q = q0;
    for _ in 0..60 {
        let (r, jac) = t.system(&q);
        let rows = jac.iter().map(|row| row.to_vec()).collect();
        let step = linear::solve(rows, r.iter().map(|x| -*x).collect()).ok()?;
        let mut size = 0.0f64;
        for (qi, si) in q.iter_mut().zip(&step) {
            *qi += *si;
            size = size.max(si.hi.abs());
        }
        if !size.is_finite() {
            return None;
        }
        if size < 1e-28 {
            let (r, _) = t.system(&q);
            let worst = r.iter().map(|x| x.hi.abs()).fold(0.0, f64::max);
            return (worst < 1e-28 * scale_len.hi).then(|| Pose {
                q,
                joints: t.joints(&q),
            });
        }
    }
    None
}

/// `A` for the ternary axis `e4` on branch `left` (of `K1 -> Q`, `Q = K2 -
/// ab e4`), or `None` where the circles do not meet; and the squared height.
fn joint_a(t: &TriadRef, e4: V, left: bool) -> (Option<V>, Dd) {
    let q = sub(t.k[1], scale(t.ab, e4));
    let d = sub(q, t.k[0]);
    let dist2 = dot(d, d);
    let (l1, l2) = (t.l[0], t.l[1]);
    if dist2.hi == 0.0 {
        return (None, Dd::from(-1.0));
    }
    // Foot along d (times |d|) and height (times |d|): h2 = l1^2 |d|^2 - foot^2.
    let foot = (l1.sqr() - l2.sqr() + dist2) / Dd::from(2.0);
    let h2 = l1.sqr() * dist2 - foot.sqr();
    if h2.hi < 0.0 {
        return (None, h2);
    }
    let h = if left { h2.sqrt() } else { -h2.sqrt() };
    let a = add(
        t.k[0],
        scale(Dd::ONE / dist2, add(scale(foot, d), scale(h, perp(d)))),
    );
    (Some(a), h2)
}

/// The residual `|P - K3|^2 - l3^2` on a branch at the ternary axis `e4`.
fn residual(t: &TriadRef, e4: V, left: bool) -> Option<Dd> {
    let a = joint_a(t, e4, left).0?;
    let r = sub(add(a, t.ap(e4)), t.k[2]);
    Some(dot(r, r) - t.l[2].sqr())
}

/// Bisection on `x` in `[lo, hi]` for a predicate true at `lo`, false at
/// `hi` (or the opposite), 90 halvings: returns the last `lo` side.
fn bisect(mut lo: Dd, mut hi: Dd, side: impl Fn(Dd) -> bool) -> Dd {
    let at_lo = side(lo);
    for _ in 0..90 {
        let mid = (lo + hi) * Dd::from(0.5);
        if side(mid) == at_lo {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// Polishes a root of branch `left` at ternary angle `x` and adds it to
/// `out` unless already there (joints within `1e-20`).
fn polish(t: &TriadRef, x: Dd, left: bool, out: &mut Vec<Pose>) {
    let e4 = e(x);
    let Some(a) = joint_a(t, e4, left).0 else {
        return;
    };
    let b = add(a, scale(t.ab, e4));
    let p = add(a, t.ap(e4));
    let ang = |from: V, to: V| {
        let d = sub(to, from);
        Dd::atan2(d[1], d[0])
    };
    let q0 = [ang(t.k[0], a), ang(t.k[1], b), ang(t.k[2], p), x];
    let Some(pose) = newton(t, q0) else { return };
    let dist = |u: &Pose| {
        (0..3)
            .map(|i| {
                let d = sub(u.joints[i], pose.joints[i]);
                dot(d, d).hi
            })
            .sum::<f64>()
            .sqrt()
    };
    if out.iter().all(|u| dist(u) > 1e-20) {
        out.push(pose);
    }
}

/// Every assembly, by a scan of the ternary's angle at `samples` points
/// (see the module documentation).
pub fn assemblies(t: &TriadRef, samples: usize) -> Vec<Pose> {
    let mut out = Vec::new();
    let step = Dd::TAU / Dd::from(samples as f64);
    let x_at = |j: usize| step * Dd::from(j as f64);
    // The sample directions by rotation (exact sine and cosine every 64).
    let turn = e(step);
    let mut dirs: Vec<V> = Vec::with_capacity(samples + 1);
    for j in 0..=samples {
        let d = match dirs.last() {
            Some(&[c, s]) if j % 64 != 0 => [c * turn[0] - s * turn[1], s * turn[0] + c * turn[1]],
            _ => e(x_at(j)),
        };
        dirs.push(d);
    }
    for j in 0..samples {
        let (x0, x1) = (x_at(j), x_at(j + 1));
        let (e0, e1) = (dirs[j], dirs[j + 1]);
        let exists = |ee: V| joint_a(t, ee, true).0.is_some();
        let (in0, in1) = (exists(e0), exists(e1));
        for left in [true, false] {
            match (in0, in1) {
                (true, true) => {
                    let (Some(r0), Some(r1)) = (residual(t, e0, left), residual(t, e1, left))
                    else {
                        continue;
                    };
                    if (r0.hi > 0.0) != (r1.hi > 0.0) {
                        let s0 = r0.hi > 0.0;
                        let x = bisect(x0, x1, |x| {
                            residual(t, e(x), left).is_some_and(|r| (r.hi > 0.0) == s0)
                        });
                        polish(t, x, left, &mut out);
                    }
                }
                (true, false) | (false, true) => {
                    // A branch end between the samples: both branches meet there.
                    let (inside, outside) = if in0 { (x0, x1) } else { (x1, x0) };
                    // The last point where the branches exist.
                    let end_x = bisect(inside, outside, |x| exists(e(x)));
                    let end_r = residual(t, e(end_x), true);
                    let (Some(r0), Some(re)) = (residual(t, e(inside), left), end_r) else {
                        continue;
                    };
                    if (r0.hi > 0.0) != (re.hi > 0.0) {
                        let s0 = r0.hi > 0.0;
                        let x = bisect(inside, end_x, |x| {
                            residual(t, e(x), left).is_some_and(|r| (r.hi > 0.0) == s0)
                        });
                        polish(t, x, left, &mut out);
                    }
                }
                (false, false) => {}
            }
        }
    }
    out
}

/// The angular rates `(omega1 .. omega4)` (rad/s) and the joints'
/// velocities (`A`, `B`, `P`; L/s) from the known points' velocities:
/// `J qdot = (vK2 - vK1, vK3 - vK1)`. `None` when `J` is singular.
pub fn rates(t: &TriadRef, pose: &Pose, vk: [V; 3]) -> Option<([Dd; 4], [V; 3])> {
    let jac = t.jacobian(&pose.q);
    let r1 = sub(vk[1], vk[0]);
    let r2 = sub(vk[2], vk[0]);
    let w = solve4(&jac, [r1[0], r1[1], r2[0], r2[1]])?;
    Some((w, joint_rates(t, pose, vk[0], &w, None)))
}

/// Joint velocities (or accelerations, with `alpha` and the centripetal
/// terms) from leg 1 and the ternary.
fn joint_rates(t: &TriadRef, pose: &Pose, base: V, w: &[Dd; 4], alpha: Option<&[Dd; 4]>) -> [V; 3] {
    let [a, b, p] = pose.joints;
    let rel = |r: V, i: usize| match alpha {
        None => scale(w[i], perp(r)),
        Some(al) => sub(scale(al[i], perp(r)), scale(w[i].sqr(), r)),
    };
    let va = add(base, rel(sub(a, t.k[0]), 0));
    [va, add(va, rel(sub(b, a), 3)), add(va, rel(sub(p, a), 3))]
}

/// The angular accelerations (rad/s^2) and the joints' accelerations
/// (L/s^2): `J qddot = (aK2 - aK1, aK3 - aK1) + centripetal terms`.
pub fn accelerations(
    t: &TriadRef,
    pose: &Pose,
    w: &[Dd; 4],
    ak: [V; 3],
) -> Option<([Dd; 4], [V; 3])> {
    let es: Vec<V> = pose.q.iter().map(|x| e(*x)).collect();
    let [l1, l2, l3] = t.l;
    let c1 = scale(l1 * w[0].sqr(), es[0]);
    let ap = t.ap(es[3]);
    let rb = sub(
        add(add(sub(ak[1], ak[0]), c1), scale(t.ab * w[3].sqr(), es[3])),
        scale(l2 * w[1].sqr(), es[1]),
    );
    let rp = sub(
        add(add(sub(ak[2], ak[0]), c1), scale(w[3].sqr(), ap)),
        scale(l3 * w[2].sqr(), es[2]),
    );
    let al = solve4(&t.jacobian(&pose.q), [rb[0], rb[1], rp[0], rp[1]])?;
    Some((al, joint_rates(t, pose, ak[0], w, Some(&al))))
}

fn solve4(jac: &[[Dd; 4]; 4], rhs: [Dd; 4]) -> Option<[Dd; 4]> {
    let rows = jac.iter().map(|row| row.to_vec()).collect();
    let x = linear::solve(rows, rhs.to_vec()).ok()?;
    Some([x[0], x[1], x[2], x[3]])
}

/// `det` of a 4x4 matrix by elimination with partial pivoting.
pub fn det4(m: &[[Dd; 4]; 4]) -> Dd {
    let mut a = *m;
    let mut det = Dd::ONE;
    for k in 0..4 {
        let p = (k..4)
            .max_by(|&i, &j| {
                a[i][k]
                    .abs()
                    .partial_cmp(&a[j][k].abs())
                    .unwrap_or(core::cmp::Ordering::Equal)
            })
            .unwrap_or(k);
        if a[p][k].hi == 0.0 {
            return Dd::ZERO;
        }
        if p != k {
            a.swap(p, k);
            det = -det;
        }
        det *= a[k][k];
        let pivot = a[k];
        for row in a.iter_mut().skip(k + 1) {
            let f = row[k] / pivot[k];
            for (x, &p) in row.iter_mut().zip(&pivot).skip(k) {
                *x -= f * p;
            }
        }
    }
    det
}

/// Where the assembly near `start` meets another as the input `x` varies
/// (a fold: the end of a swing): solves the loop closure with `K` =
/// `known(x)` together with `det J(q) = 0` for `(q, x)`, by Newton's method
/// with a central-difference Jacobian (step `2^-30`: truncation `~1e-18`
/// relative, so each step gains about 18 digits), from `(start.q, x0)`.
/// Returns `x` and the pose; `None` when Newton does not converge.
pub fn fold(
    t: &TriadRef,
    known: impl Fn(Dd) -> [V; 3],
    start: &Pose,
    x0: Dd,
) -> Option<(Dd, Pose)> {
    let eval = |z: &[Dd; 5]| -> [Dd; 5] {
        let tk = TriadRef {
            k: known(z[4]),
            ..*t
        };
        let q = [z[0], z[1], z[2], z[3]];
        let (r, jac) = tk.system(&q);
        [r[0], r[1], r[2], r[3], det4(&jac)]
    };
    let mut z = [start.q[0], start.q[1], start.q[2], start.q[3], x0];
    let h = Dd::from(2f64.powi(-30));
    for _ in 0..40 {
        let f0 = eval(&z);
        let mut cols = vec![vec![Dd::ZERO; 5]; 5];
        for j in 0..5 {
            let (mut zp, mut zm) = (z, z);
            zp[j] += h;
            zm[j] -= h;
            let (fp, fm) = (eval(&zp), eval(&zm));
            for i in 0..5 {
                cols[i][j] = (fp[i] - fm[i]) / (h + h);
            }
        }
        let step = linear::solve(cols, f0.iter().map(|x| -*x).collect()).ok()?;
        let mut size = 0.0f64;
        for (zi, si) in z.iter_mut().zip(&step) {
            *zi += *si;
            size = size.max(si.hi.abs());
        }
        if size < 1e-27 {
            let tk = TriadRef {
                k: known(z[4]),
                ..*t
            };
            let q = [z[0], z[1], z[2], z[3]];
            return Some((
                z[4],
                Pose {
                    q,
                    joints: tk.joints(&q),
                },
            ));
        }
    }
    None
}
