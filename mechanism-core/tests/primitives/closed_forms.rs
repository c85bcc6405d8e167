//! The closed forms of the five class II groups' kinetostatics
//! (`force::{rrr, rrp, rpr, rpp, prp}::reactions`, derived in each file)
//! against two solutions they share no code with:
//!
//! - the general elimination of the same six equations,
//!   `force::group::solve` (moments about the same joint, row-equilibrated
//!   pivoted Gaussian elimination), over random poses, loads and scales;
//! - near singular poses (the angle that makes each group's determinant
//!   vanish at `1e-1 .. 1e-14` rad from it), a double-double solution of the
//!   group's Newton-Euler equations written here with moments about another
//!   point (`mechanism_reference::linear::solve`), and each link's equilibrium
//!   residual evaluated in double-double.
//!
//! Also: the closed form refuses (`Singular`) only where the general solve's
//! relative pivot is as small, and its `min_pivot_ratio` is within a fixed
//! factor of the general solve's over the random poses (the indicator keeps
//! its meaning).
//!
//! Tolerances, and why:
//!
//! - both solutions are backward stable, so each has a forward error of a
//!   few `eps` times the condition of the group's equations, which
//!   `min_pivot_ratio` bounds (the reduced system's 2-norm condition is at
//!   most `2 / min_pivot_ratio`; the elimination of the rest multiplies by
//!   at most a small constant): errors are compared with
//!   `K eps / min_pivot_ratio` of the largest reaction of their unit (forces;
//!   couples together with the forces times the group's size), with
//!   `K = 64`. Observed: see each test's comment.
//! - residuals: each link equation of the reference formulation, evaluated
//!   in double-double at the closed form's reactions, against `64 eps` of its
//!   largest term (the bound `rrr_links_balance` and the others in
//!   `kinetostatics.rs` use), now also at the near-singular poses, where
//!   Cramer's rule would leave `eps / min_pivot_ratio`.

use mechanism_core::force::group::{self, Connection, Joint, Pair};
use mechanism_core::force::{self, Wrench};
use mechanism_core::{Error, Fault, Point2, Primitive, Vector2};
use mechanism_reference::{linear, Dd};

type V = Vector2<f64>;
type P = Point2<f64>;

const EPS: f64 = f64::EPSILON;

/// The tolerance factor `K` of the module documentation.
const K: f64 = 64.0;

/// A small deterministic generator (xorshift64*), so that every run sees the
/// same poses and a failure reproduces.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let x = self.0.wrapping_mul(0x2545_F491_4F6C_DD1D);
        (x >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in `[-1, 1)`.
    fn sym(&mut self) -> f64 {
        2.0 * self.next() - 1.0
    }
    fn point(&mut self, l: f64) -> P {
        P::new(self.sym() * l, self.sym() * l)
    }
    fn unit(&mut self) -> V {
        let t = self.next() * std::f64::consts::TAU;
        V::new(t.cos(), t.sin())
    }
    /// `10^u` with `u` uniform in `[-3, 3)`.
    fn decade(&mut self) -> f64 {
        10f64.powf(3.0 * self.sym())
    }
    fn wrench(&mut self, l: f64, f: f64) -> Wrench<f64> {
        Wrench::new(V::new(self.sym() * f, self.sym() * f), self.sym() * f * l)
    }
}

fn rotate(v: &V, angle: f64) -> V {
    let (s, c) = angle.sin_cos();
    V::new(c * v.x - s * v.y, s * v.x + c * v.y)
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Rrr,
    Rrp,
    Rpr,
    Rpp,
    Prp,
}

const KINDS: [Kind; 5] = [Kind::Rrr, Kind::Rrp, Kind::Rpr, Kind::Rpp, Kind::Prp];

/// One group's inputs: its three joints in the order of
/// `force::group::Joint` that the kind's file documents, the point moments
/// are taken about, and the known loads about it.
#[derive(Clone, Copy, Debug)]
struct Case {
    kind: Kind,
    joints: [Joint<f64>; 3],
    about: P,
    load1: Wrench<f64>,
    load2: Wrench<f64>,
}

fn rev(point: P, connection: Connection) -> Joint<f64> {
    Joint {
        pair: Pair::Revolute { point },
        connection,
    }
}

fn pri(point: P, dir: V, connection: Connection) -> Joint<f64> {
    Joint {
        pair: Pair::Prismatic {
            point,
            dir: group::unit_direction(&dir, Primitive::Rpp, "test").unwrap(),
        },
        connection,
    }
}

use Connection::{Link1ToLink2 as In, OutsideToLink1 as O1, OutsideToLink2 as O2};

impl Case {
    /// The kind's case from two points and two directions (each kind takes
    /// what it needs, in the order of its `reactions` arguments).
    fn new(kind: Kind, p: [P; 3], d: [V; 2], load1: Wrench<f64>, load2: Wrench<f64>) -> Case {
        let (joints, about) = match kind {
            Kind::Rrr => ([rev(p[0], O1), rev(p[1], O2), rev(p[2], In)], p[2]),
            Kind::Rrp => ([rev(p[0], O1), pri(p[1], d[0], O2), rev(p[1], In)], p[1]),
            Kind::Rpr => ([rev(p[0], O1), rev(p[1], O2), pri(p[0], d[0], In)], p[0]),
            Kind::Rpp => (
                [rev(p[0], O1), pri(p[0], d[0], In), pri(p[0], d[1], O2)],
                p[0],
            ),
            Kind::Prp => (
                [pri(p[0], d[0], O1), pri(p[0], d[1], O2), rev(p[0], In)],
                p[0],
            ),
        };
        Case {
            kind,
            joints,
            about,
            load1,
            load2,
        }
    }

    fn point(&self, k: usize) -> P {
        match self.joints[k].pair {
            Pair::Revolute { point } | Pair::Prismatic { point, .. } => point,
        }
    }

    fn dir(&self, k: usize) -> V {
        match self.joints[k].pair {
            Pair::Prismatic { dir, .. } => dir,
            Pair::Revolute { .. } => V::zeros(),
        }
    }

    /// The closed form's unknowns in the joints' order (`[Fx, Fy]` or
    /// `[N, M]` per joint) and its `min_pivot_ratio`.
    fn closed(&self) -> Result<([f64; 6], f64), Error<f64>> {
        let (w1, w2) = (&self.load1, &self.load2);
        Ok(match self.kind {
            Kind::Rrr => {
                let r = force::rrr::reactions(&self.point(0), &self.point(1), &self.about, w1, w2)?;
                (
                    [r.a.x, r.a.y, r.b.x, r.b.y, r.c.x, r.c.y],
                    r.min_pivot_ratio,
                )
            }
            Kind::Rrp => {
                let r = force::rrp::reactions(&self.point(0), &self.about, &self.dir(1), w1, w2)?;
                let g = r.guide;
                (
                    [r.a.x, r.a.y, g.normal, g.moment, r.c.x, r.c.y],
                    r.min_pivot_ratio,
                )
            }
            Kind::Rpr => {
                let r = force::rpr::reactions(&self.about, &self.point(1), &self.dir(2), w1, w2)?;
                let s = r.slide;
                (
                    [r.a.x, r.a.y, r.b.x, r.b.y, s.normal, s.moment],
                    r.min_pivot_ratio,
                )
            }
            Kind::Rpp => {
                let r = force::rpp::reactions(&self.about, &self.dir(1), &self.dir(2), w1, w2)?;
                let (s, g) = (r.slot, r.guide);
                (
                    [r.a.x, r.a.y, s.normal, s.moment, g.normal, g.moment],
                    r.min_pivot_ratio,
                )
            }
            Kind::Prp => {
                let r = force::prp::reactions(&self.about, &self.dir(0), &self.dir(1), w1, w2)?;
                let (g1, g2) = (r.guide1, r.guide2);
                (
                    [g1.normal, g1.moment, g2.normal, g2.moment, r.c.x, r.c.y],
                    r.min_pivot_ratio,
                )
            }
        })
    }

    /// The general elimination of the same equations.
    fn general(&self) -> Result<([f64; 6], f64), Error<f64>> {
        let kind = match self.kind {
            Kind::Rrr => Primitive::Rrr,
            Kind::Rrp => Primitive::Rrp,
            Kind::Rpr => Primitive::Rpr,
            Kind::Rpp => Primitive::Rpp,
            Kind::Prp => Primitive::Prp,
        };
        let s = group::solve(&self.joints, &self.about, &self.load1, &self.load2, kind)?;
        let [[a, b], [c, d], [e, f]] = s.unknowns;
        Ok(([a, b, c, d, e, f], s.min_pivot_ratio))
    }

    /// Which unknowns are couples (the second of a prismatic pair's two).
    fn is_couple(&self) -> [bool; 6] {
        let mut out = [false; 6];
        for (k, j) in self.joints.iter().enumerate() {
            out[2 * k + 1] = matches!(j.pair, Pair::Prismatic { .. });
        }
        out
    }

    /// The group's size: the largest distance from `about` to a joint, or 1.
    fn size(&self) -> f64 {
        let l = (0..3).fold(0.0f64, |m, k| m.max((self.point(k) - self.about).norm()));
        if l > 0.0 {
            l
        } else {
            1.0
        }
    }

    /// The six Newton-Euler equations in double-double, with moments about
    /// `q` (not the core's point): rows link 1 `Fx`, `Fy`, moment, then link
    /// 2; each row as its terms `(coefficient of each unknown, known part)`.
    fn equations(&self, q: &P) -> (Vec<Vec<Dd>>, Vec<Dd>) {
        let d = Dd::from;
        let cross = |a: [Dd; 2], b: [Dd; 2]| a[0] * b[1] - a[1] * b[0];
        let qd = [d(q.x), d(q.y)];
        let mut a = vec![vec![Dd::ZERO; 6]; 6];
        for (k, joint) in self.joints.iter().enumerate() {
            let cols: [[Dd; 3]; 2] = match joint.pair {
                Pair::Revolute { point } => {
                    let r = [d(point.x) - qd[0], d(point.y) - qd[1]];
                    // (Fx, 0) has moment -r.y Fx about q; (0, Fy) r.x Fy.
                    [[Dd::ONE, Dd::ZERO, -r[1]], [Dd::ZERO, Dd::ONE, r[0]]]
                }
                Pair::Prismatic { point, dir } => {
                    let r = [d(point.x) - qd[0], d(point.y) - qd[1]];
                    let n = [-d(dir.y), d(dir.x)];
                    [[n[0], n[1], cross(r, n)], [Dd::ZERO, Dd::ZERO, Dd::ONE]]
                }
            };
            let signs: [f64; 2] = match joint.connection {
                Connection::OutsideToLink1 => [1.0, 0.0],
                Connection::OutsideToLink2 => [0.0, 1.0],
                Connection::Link1ToLink2 => [-1.0, 1.0],
            };
            for (link, s) in signs.iter().enumerate() {
                for row in 0..3 {
                    for (u, col) in cols.iter().enumerate() {
                        a[3 * link + row][2 * k + u] = d(*s) * col[row];
                    }
                }
            }
        }
        // Known loads about `about`, moved to `q`: M_q = M + cross(about - q, F).
        let r = [d(self.about.x) - qd[0], d(self.about.y) - qd[1]];
        let known = |w: &Wrench<f64>| {
            let f = [d(w.force.x), d(w.force.y)];
            [f[0], f[1], d(w.moment) + cross(r, f)]
        };
        let (k1, k2) = (known(&self.load1), known(&self.load2));
        let b = k1.iter().chain(k2.iter()).map(|&x| -x).collect();
        (a, b)
    }

    /// The double-double solution of [`Self::equations`].
    fn reference(&self) -> Option<[f64; 6]> {
        let (a, b) = self.equations(&P::new(0.3, -0.7));
        let x = linear::solve(a, b).ok()?;
        Some([0, 1, 2, 3, 4, 5].map(|i| x[i].to_f64()))
    }

    /// The residual of each link's equilibrium at `x` (the force balance, and
    /// the moments about `q`), evaluated in double-double, relative to the
    /// largest term of its equation: the largest force for the balance; the
    /// largest `|lever arm| |force|` or couple for the moments (as
    /// `kinetostatics.rs` measures it; a term's cross product can vanish
    /// while its rounding does not).
    fn residual(&self, x: &[f64; 6], q: &P) -> f64 {
        let d = Dd::from;
        // Each link's loads: (force, point) pairs and couples, receivers `+`.
        let mut forces: [Vec<(V, P)>; 2] = [Vec::new(), Vec::new()];
        let mut couples: [Vec<f64>; 2] = [Vec::new(), Vec::new()];
        for (k, joint) in self.joints.iter().enumerate() {
            let (f, m) = match joint.pair {
                Pair::Revolute { .. } => (V::new(x[2 * k], x[2 * k + 1]), 0.0),
                Pair::Prismatic { dir, .. } => (V::new(-dir.y, dir.x) * x[2 * k], x[2 * k + 1]),
            };
            let signs: [f64; 2] = match joint.connection {
                Connection::OutsideToLink1 => [1.0, 0.0],
                Connection::OutsideToLink2 => [0.0, 1.0],
                Connection::Link1ToLink2 => [-1.0, 1.0],
            };
            for link in 0..2 {
                if signs[link] != 0.0 {
                    forces[link].push((f * signs[link], self.point(k)));
                    couples[link].push(m * signs[link]);
                }
            }
        }
        for (link, w) in [self.load1, self.load2].iter().enumerate() {
            forces[link].push((w.force, self.about));
            couples[link].push(w.moment);
        }
        let mut worst = 0.0f64;
        for link in 0..2 {
            let (mut fx, mut fy, mut m) = (Dd::ZERO, Dd::ZERO, Dd::ZERO);
            let (mut f_scale, mut m_scale) = (0.0f64, 0.0f64);
            for (f, p) in &forces[link] {
                let (rx, ry) = (d(p.x) - d(q.x), d(p.y) - d(q.y));
                fx += d(f.x);
                fy += d(f.y);
                m += rx * d(f.y) - ry * d(f.x);
                f_scale = f_scale.max(f.norm());
                m_scale = m_scale.max((p - q).norm() * f.norm());
            }
            for &c in &couples[link] {
                m += d(c);
                m_scale = m_scale.max(c.abs());
            }
            let rel = |r: Dd, s: f64| {
                if s > 0.0 {
                    r.abs().to_f64() / s
                } else {
                    r.abs().to_f64()
                }
            };
            worst = worst
                .max(rel(fx, f_scale))
                .max(rel(fy, f_scale))
                .max(rel(m, m_scale));
        }
        worst
    }

    /// The largest difference between `x` and `y`, forces relative to the
    /// largest force of `y`, couples to the largest of its couples and of its
    /// forces times the group's size.
    fn difference(&self, x: &[f64; 6], y: &[f64; 6]) -> f64 {
        let couple = self.is_couple();
        let forces = (0..6)
            .filter(|&i| !couple[i])
            .fold(0.0f64, |m, i| m.max(y[i].abs()));
        let couples = (0..6)
            .filter(|&i| couple[i])
            .fold(forces * self.size(), |m, i| m.max(y[i].abs()));
        (0..6)
            .map(|i| {
                let scale = if couple[i] { couples } else { forces };
                if scale > 0.0 {
                    (x[i] - y[i]).abs() / scale
                } else {
                    (x[i] - y[i]).abs()
                }
            })
            .fold(0.0, f64::max)
    }
}

/// A random case of `kind`: points in a box of size `10^[-3, 3)`, loads of
/// force `10^[-3, 3)` and moment up to force times size.
fn random_case(kind: Kind, rng: &mut Rng) -> Case {
    let (l, f) = (rng.decade(), rng.decade());
    let p = [rng.point(l), rng.point(l), rng.point(l)];
    let d = [rng.unit() * (0.1 + 10.0 * rng.next()), rng.unit()];
    Case::new(kind, p, d, rng.wrench(l, f), rng.wrench(l, f))
}

/// A case of `kind` whose determinant vanishes at `angle = 0`: the line that
/// makes it turned by `angle` (rad) from the singular position. With
/// `consistent`, the loads are ones the singular pose itself could carry
/// (the right-hand side in the range of the singular system), so the
/// reactions stay of the loads' size while the pose nears singularity: the
/// case where Cramer's rule leaves residuals of `eps / angle`.
fn near_singular_case(kind: Kind, angle: f64, consistent: bool, rng: &mut Rng) -> Case {
    let (l, f) = (rng.decade(), rng.decade());
    let p0 = rng.point(l);
    let u = rng.unit();
    let (mut w1, mut w2) = (rng.wrench(l, f), rng.wrench(l, f));
    let len = |rng: &mut Rng| l * (0.2 + rng.next());
    let cross = |a: &V, b: &V| a.x * b.y - a.y * b.x;
    let normal = V::new(-u.y, u.x);
    if consistent {
        match kind {
            // Each link's load through its outer joint (set below for RRR).
            Kind::Rrr => {}
            // The whole group's load through A: N = 0.
            Kind::Rrp => w1.moment = cross(&(u * l), &(w1.force + w2.force)),
            // The rocker's load and both couples balanced about A: N = 0.
            Kind::Rpr => w1.moment = cross(&(u * l), &w2.force) - w2.moment,
            // Link 2's load across the (nearly parallel) slot and guide.
            Kind::Rpp => w2.force = normal * (f * rng.sym()),
            // The group's load across both guides.
            Kind::Prp => w2.force = normal * (f * rng.sym()) - w1.force,
        }
    }
    match kind {
        // C = p0; A along u; B along -u turned by `angle` (toggle at 0).
        Kind::Rrr => {
            let a = p0 + u * len(rng);
            let b = p0 + rotate(&-u, angle) * len(rng);
            if consistent {
                w1.moment = cross(&(a - p0), &w1.force);
                w2.moment = cross(&(b - p0), &w2.force);
            }
            Case::new(kind, [a, b, p0], [V::x(), V::x()], w1, w2)
        }
        // C = p0, A along u at distance l: the guide perpendicular to link
        // 1, turned.
        Kind::Rrp => {
            let d = rotate(&normal, angle);
            Case::new(kind, [p0 + u * l, p0, p0], [d, V::x()], w1, w2)
        }
        // A = p0, B along u at distance l: the slide perpendicular to AB,
        // turned.
        Kind::Rpr => {
            let d = rotate(&normal, angle);
            Case::new(kind, [p0, p0 + u * l, p0], [d, V::x()], w1, w2)
        }
        // Slot and guide (guides 1 and 2) parallel, turned.
        Kind::Rpp | Kind::Prp => Case::new(kind, [p0, p0, p0], [u, rotate(&u, angle)], w1, w2),
    }
}

/// Proves: over 20 000 random cases per group (lengths and forces each over
/// six decades), the closed form and the general elimination agree to
/// `64 eps / min_pivot_ratio` (forces to the largest force, couples to the
/// largest couple or force times size), and they fail together (`Singular`)
/// on the same cases. The closed form's `min_pivot_ratio` (a relative
/// determinant) is never above twice the elimination's (the smallest
/// relative pivot of the 6x6), and can be far below it where the
/// elimination's row scaling hides a near-singular pose (nearly parallel
/// slot and guide: the equilibrated rows keep a pivot near 1 while the
/// normal forces grow as `1 / sin`). Observed: differences up to 4.9 eps /
/// ratio; the closed form's indicator over the elimination's 0.07 .. 1.96
/// (RRR), 0.06 .. 1.98 (RRP), 1 (RPR), 0.0018 .. 1.00 (RPP), 0.03 .. 1.99
/// (PRP).
#[test]
fn closed_forms_agree_with_the_general_elimination() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for kind in KINDS {
        let (mut worst, mut lo, mut hi) = (0.0f64, f64::INFINITY, 0.0f64);
        for _ in 0..20_000 {
            let case = random_case(kind, &mut rng);
            match (case.closed(), case.general()) {
                (Ok((x, ratio)), Ok((y, general))) => {
                    let diff = case.difference(&x, &y);
                    assert!(
                        diff <= K * EPS / ratio,
                        "{kind:?}: difference {diff:e} at ratio {ratio:e}: {case:?}"
                    );
                    worst = worst.max(diff * ratio / EPS);
                    lo = lo.min(ratio / general);
                    hi = hi.max(ratio / general);
                }
                (Err(e), Err(g)) => {
                    assert!(matches!(e.fault, Fault::Singular { .. }), "{e}");
                    assert!(matches!(g.fault, Fault::Singular { .. }), "{g}");
                }
                (x, y) => panic!("{kind:?}: closed {x:?}, general {y:?}: {case:?}"),
            }
        }
        println!("{kind:?}: difference <= {worst:.2} eps / ratio; ratio / general in {lo:.2e} .. {hi:.2}");
        assert!(hi <= 2.0, "{kind:?}: {lo} .. {hi}");
    }
}

/// Proves: near each group's singular pose (the determinant's line turned by
/// `1e-1 .. 1e-14` rad from it), the closed form's reactions are within
/// `64 eps / min_pivot_ratio` of the double-double solution, as accurate as
/// the conditioning allows, and satisfy every link equation (evaluated in
/// double-double, moments about a third point) to `64 eps` of its largest
/// term: backward stable, where Cramer's rule leaves up to
/// `eps / min_pivot_ratio`. Where the closed form refuses (`Singular`), the
/// general elimination's relative pivot is below `1e-8` or it refuses too.
/// Half the cases carry loads the singular pose itself could hold, so that
/// the reactions stay of the loads' size. Observed: errors up to 1.6 eps /
/// ratio, residuals up to 1.8 eps.
#[test]
fn closed_forms_near_singular_poses() {
    let mut rng = Rng(0xD1B5_4A32_D192_ED03);
    for kind in KINDS {
        let (mut worst, mut residual) = (0.0f64, 0.0f64);
        for decade in 2..=28 {
            let angle = 10f64.powf(-0.5 * decade as f64);
            for i in 0..200 {
                let case = near_singular_case(kind, angle, i % 2 == 0, &mut rng);
                let Ok((x, ratio)) = case.closed() else {
                    if let Ok((_, general)) = case.general() {
                        assert!(general < 1e-8, "{kind:?}: general ratio {general:e}");
                    }
                    continue;
                };
                let reference = case.reference().expect("a regular double-double system");
                let err = case.difference(&x, &reference);
                assert!(
                    err <= K * EPS / ratio,
                    "{kind:?} at {angle:e}: error {err:e}, ratio {ratio:e}: {case:?}"
                );
                let r = case.residual(&x, &P::new(-1.1, 0.4));
                assert!(
                    r <= K * EPS,
                    "{kind:?} at {angle:e}: residual {r:e}: {case:?}"
                );
                worst = worst.max(err * ratio / EPS);
                residual = residual.max(r / EPS);
            }
        }
        println!("{kind:?}: error <= {worst:.2} eps / ratio, residual <= {residual:.2} eps");
    }
}

/// Proves: at an exactly singular pose each closed form returns `Singular`
/// with the determinant and scale it documents, tagged with its group.
#[test]
fn exactly_singular_poses_name_det_and_scale() {
    let o = P::origin();
    let w = Wrench::new(V::new(1.0, 2.0), 3.0);
    let singular = |e: Error<f64>, primitive: Primitive, det: f64, scale: f64| {
        assert_eq!(e.primitive, primitive);
        assert_eq!(e.fault, Fault::Singular { det, scale }, "{e}");
    };
    // RRR: C on the line AB, |A - C| = 1, |B - C| = 2.
    let e = force::rrr::reactions(&P::new(-1.0, 0.0), &P::new(2.0, 0.0), &o, &w, &w).unwrap_err();
    singular(e, Primitive::Rrr, 0.0, 2.0);
    // RRP: link 1 (length 3) perpendicular to the guide.
    let e = force::rrp::reactions(&P::new(0.0, 3.0), &o, &V::x(), &w, &w).unwrap_err();
    singular(e, Primitive::Rrp, 0.0, 3.0);
    // RPR: the slide perpendicular to AB (length 2).
    let e = force::rpr::reactions(&o, &P::new(2.0, 0.0), &V::y(), &w, &w).unwrap_err();
    singular(e, Primitive::Rpr, 0.0, 2.0);
    // RPP and PRP: parallel directions.
    let e = force::rpp::reactions(&o, &V::y(), &(V::y() * 3.0), &w, &w).unwrap_err();
    singular(e, Primitive::Rpp, 0.0, 1.0);
    let e = force::prp::reactions(&o, &V::x(), &(-V::x()), &w, &w).unwrap_err();
    singular(e, Primitive::Prp, -0.0, 1.0);
}

/// Proves the residual check of `closed_forms_near_singular_poses` can fail:
/// Cramer's rule on the RPP's 2x2 system (the adjugate over the determinant,
/// `Ns = -dot(F2, dg) / cross(ds, dg)`, `Ng = dot(F2, ds) / cross(ds, dg)`)
/// on the same consistent near-parallel cases leaves residuals far above
/// `64 eps` (observed: about `eps / angle`), where the closed form's stay
/// within a few `eps`.
#[test]
fn cramers_rule_fails_the_residual_check() {
    let mut rng = Rng(0x2545_F491_4F6C_DD1D);
    let angle = 1e-10;
    let mut worst = 0.0f64;
    for _ in 0..50 {
        let case = near_singular_case(Kind::Rpp, angle, true, &mut rng);
        let (ds, dg) = (case.dir(1), case.dir(2));
        let (w1, w2) = (case.load1, case.load2);
        let det = ds.x * dg.y - ds.y * dg.x;
        let slot = -(w2.force.dot(&dg)) / det;
        let guide = w2.force.dot(&ds) / det;
        let fa = V::new(-ds.y, ds.x) * slot - w1.force;
        let cramer = [fa.x, fa.y, slot, w1.moment, guide, -(w1.moment + w2.moment)];
        worst = worst.max(case.residual(&cramer, &P::new(-1.1, 0.4)));
        let (x, _) = case.closed().expect("regular");
        assert!(case.residual(&x, &P::new(-1.1, 0.4)) <= K * EPS);
    }
    println!("Cramer's rule: residual up to {:.2e} eps", worst / EPS);
    assert!(worst > 1e3 * K * EPS, "{worst:e}");
}
