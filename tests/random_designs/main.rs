//! Random designs: the dimensions of a four-bar (RRR), of an offset
//! slider-crank on a tilted guide (RRP), of an inverted slider-crank whose
//! block slides on a rocker with an offset slide line (RPR), of two blocks
//! joined on a turning line and a fixed guide (PRP), of a Scotch yoke at
//! any angle (RPP), of a boom lifted by a linear actuator, and of a
//! Stephenson six-bar (two RRR groups chained through a coupler point) drawn
//! at random (run-time `params`, lengths
//! over six decades of scale), each at a random pose, speed and angular
//! acceleration of the crank, as a user sweeping or optimizing designs would
//! run them, in `f64` and in `f32`, against the double-double group
//! references of `mechanism-reference` (written from the circle and line
//! intersections, not from the generated code).
//!
//! Per sample, the error of the coupler joint `B`, its velocity and its
//! acceleration, and of the link angles, is divided by its first-order bound:
//! `eps L / s` for the position, `eps L / (l s)` for a link's angle, and
//! `eps (L_pos / l_min) L / s^k` for the velocity (`k = 2`) and the
//! acceleration (`k = 3`). `L` is the stage's largest reference vector in the
//! sample, `s` the group's condition (`|sin|` of the angle between the RRR's
//! links at `B`; `|cos|` of the rod's angle to the guide for the RRP;
//! `min(|s| / |A - P|, |A - P| / size)` for the RPR; `|sin|` of the angle
//! between the guides for the PRP; `|sin|` of the slot's angle to the guide
//! for the RPP, whose rates carry it once per stage), and
//! `L_pos / l_min` the largest coordinate over the group's shortest link: the
//! positions are known to eps of their coordinates, so a link's direction
//! only to `eps L_pos / l`, which the rates inherit (`docs/stability.md`,
//! "End to end"). The largest ratio over all samples is printed and must stay
//! below [`BOUND`]. Where that first-order relative error of the rates exceeds
//! [`NO_DIGITS`] (next to a toggle or tangency, or a link thousands of times
//! shorter than its coordinates in `f32`) the rates have no digit to promise
//! and are checked finite only. Where the reference cannot assemble, or the
//! generated code returns an error, the two must agree except within the
//! documented rounding band of an edge (a typed error naming the group, never
//! NaN).
//!
//! Two draws: every dimension at random (`Free`), and the group's lengths
//! fitted to the pose at a relative distance of 1e-17 .. 1e-2 from an edge of
//! assembly, on either side (`Edge`).
//!
//! Loaded designs (masses 1e-3 .. 1e3 kg with centres and inertias, forces,
//! couples, forces along guides, gravity) against the reference's
//! Newton-Euler: the four-bar and the slider-crank here
//! ([`run_quad_forces`], [`run_slide_forces`]), the inverted slider-crank,
//! the yoke, the crossing guides and the boom in the modules below, every
//! reaction and the driving effort within [`FORCE_BOUND`] of
//! `eps (L / l_min) F / kappa^3` ([`ForceVerdict`]).
//!
//! `cargo test --test random_designs -- --nocapture` prints the figures.

use mechanism::{mechanism, Error, Fault, Point2, Real, Vector2};
use mechanism_reference::constraint::V2 as CV2;
use mechanism_reference::groups::{self as refg, V};
use mechanism_reference::newton_euler::{
    solve_forces, Body, Direction, Driver, Joint, Link, Load, Reaction, Solution, State, System,
};
use mechanism_reference::Dd;

mechanism! {
    /// A four-bar with every dimension a run-time parameter: the crank `a`
    /// about the origin, the rocker `c` about `Q = (gx, gy)`, the coupler
    /// `b`; `B` on the left of `A -> Q`.
    pub Quad {
        params { gx = 1.0, gy = 0.0, a = 0.3, b = 1.0, c = 0.8 }
        let O = ground(0.0, 0.0);
        let Q = ground(gx, gy);
        let A = crank(O, a, theta) as crank_link;
        let B = rrr(A, b, Q, c, left) as (coupler, rocker);
    }
}

mechanism! {
    /// An offset slider-crank on a guide through `(0, e)` at angle `tilt`
    /// (rad): crank `a` about the origin, rod `l`, the block's pin `B` ahead
    /// of the foot of the perpendicular from `A` (`plus`).
    pub Slide {
        params { a = 0.1, l = 0.4, e = 0.02, tilt = 0.3 }
        let O = ground(0.0, 0.0);
        let line = guide((0.0, e), tilt);
        let A = crank(O, a, theta) as crank_link;
        let B = rrp(A, l, line, plus) as (rod, block) slide s;
    }
}

mechanism! {
    /// A crank `a` about the origin whose tip `A` carries a block sliding on
    /// a rocker pivoted at `P = (px, py)`, the slide line `e` to the left of
    /// the pivot (an inverted slider-crank, a quick-return's core).
    pub Swing {
        params { px = 0.0, py = -0.3, a = 0.1, e = 0.02 }
        let O = ground(0.0, 0.0);
        let P = ground(px, py);
        let A = crank(O, a, theta) as crank_link;
        let s = rpr(A, P, plus, e) as (block, rocker);
    }
}

mechanism! {
    /// The four-bar `Quad` loaded: masses on all three links at points
    /// given in each link's frame, gravity, a force at a coupler point `P`
    /// and a couple on the rocker (kg, m, s: N and N m).
    pub QuadLoaded {
        params {
            gx = 1.0, gy = 0.0, a = 0.3, b = 1.0, c = 0.8,
            m2 = 1.0, u2 = 0.1, j2 = 0.01,
            m3 = 1.0, u3 = 0.5, v3 = 0.1, j3 = 0.1,
            m4 = 1.0, u4 = 0.4, v4 = -0.05, j4 = 0.05,
            pu = 0.7, pv = 0.2, fx = 10.0, fy = -5.0, t4 = 2.0
        }
        let O = ground(0.0, 0.0);
        let Q = ground(gx, gy);
        let A = crank(O, a, theta) as crank_link;
        let B = rrr(A, b, Q, c, left) as (coupler, rocker);
        let G2 = point(crank_link, from O, (u2, 0.0));
        let G3 = point(coupler, from A, (u3, v3));
        let G4 = point(rocker, from Q, (u4, v4));
        let P = point(coupler, from A, (pu, pv));
        mass crank_link { m = m2, at = G2, j = j2 };
        mass coupler { m = m3, at = G3, j = j3 };
        mass rocker { m = m4, at = G4, j = j4 };
        gravity (0.0, -9.81);
        force at P = (fx, fy);
        torque on rocker = t4;
    }
}

mechanism! {
    /// Two blocks joined at `C`: one on a line through the crank's pivot
    /// turning with the crank (at `tilt` to it, `o1` to its left), one on a
    /// fixed guide through `(gx, gy)` at angle `gangle` (`o2` to its left).
    pub Cross {
        params { gx = 0.3, gy = 0.0, gangle = 1.5, tilt = 0.5, o1 = 0.0, o2 = 0.0 }
        let O = ground(0.0, 0.0);
        let G = ground(gx, gy);
        let fixed_line = guide(G, gangle);
        let A = crank(O, 0.1, theta) as crank_link;
        let rod_line = guide(O, crank_link, tilt);
        let C = prp(rod_line, fixed_line, o1, o2) as (block1, block2) slide (s1, s2);
    }
}

mechanism! {
    /// A Scotch yoke at any angle: the crank's pin `A` slides in a slot of
    /// the yoke at `slot` (rad) to the yoke's guide through `(gx, gy)` at
    /// `gangle`; the yoke's reference point `Q` runs `off` to the left of
    /// the guide.
    pub Yoke {
        params { a = 0.1, gx = 0.0, gy = 0.0, gangle = 1.5, slot = 0.7, off = 0.0 }
        let O = ground(0.0, 0.0);
        let G = ground(gx, gy);
        let line = guide(G, gangle);
        let A = crank(O, a, theta) as crank_link;
        let Q = rpp(A, line, slot, off) as (block, yoke) slide (s1, s2);
    }
}

mechanism! {
    /// A boom of length `r` about `A = (0, 0)` lifted by a cylinder from
    /// `B = (bx, by)` whose length `len` is the input; the joint `C` on the
    /// left of `A -> B`.
    pub Boom {
        params { r = 1.0, bx = 0.8, by = -0.3 }
        let A = ground(0.0, 0.0);
        let B = ground(bx, by);
        let C = actuator(A, r, B, len, left) as (boom, cylinder);
    }
}

mechanism! {
    /// A Stephenson six-bar: the four-bar `Quad` with a point `P` on its
    /// coupler (`(pu, pv)` in the coupler's frame from `A`) driving a second
    /// RRR group to the ground pivot `H = (hx, hy)`; `D` on the left of
    /// `P -> H`.
    pub Six {
        params {
            gx = 1.0, gy = 0.0, a = 0.3, b = 1.0, c = 0.8,
            pu = 0.5, pv = 0.3, hx = 0.5, hy = 1.5, d = 1.0, e = 1.0
        }
        let O = ground(0.0, 0.0);
        let Q = ground(gx, gy);
        let H = ground(hx, hy);
        let A = crank(O, a, theta) as crank_link;
        let B = rrr(A, b, Q, c, left) as (coupler, rocker);
        let P = point(coupler, from A, (pu, pv));
        let D = rrr(P, d, H, e, left) as (link5, link6);
    }
}

mechanism! {
    /// The slider-crank `Slide` loaded: masses on the crank, the rod and the
    /// block, gravity, a force at a rod point and a resistance along the
    /// guide on the block (kg, m, s: N).
    pub SlideLoaded {
        params {
            a = 0.1, l = 0.4, e = 0.02, tilt = 0.3,
            m2 = 1.0, u2 = 0.05, j2 = 0.001,
            m3 = 1.0, u3 = 0.2, v3 = 0.01, j3 = 0.01,
            m4 = 1.0, fx = 10.0, fy = -5.0, fs = 20.0
        }
        let O = ground(0.0, 0.0);
        let line = guide((0.0, e), tilt);
        let A = crank(O, a, theta) as crank_link;
        let B = rrp(A, l, line, plus) as (rod, block) slide s;
        let G2 = point(crank_link, from O, (u2, 0.0));
        let G3 = point(rod, from A, (u3, v3));
        mass crank_link { m = m2, at = G2, j = j2 };
        mass rod { m = m3, at = G3, j = j3 };
        mass block { m = m4, at = B };
        gravity (0.0, -9.81);
        force at G3 = (fx, fy);
        force at B on block along line = fs;
    }
}

/// `solve` of a generated mechanism `m` whose one input is `theta`, at the
/// angle, speed and angular acceleration `(q, w, al)` (f64, as `T`).
macro_rules! solve_at {
    ($m:expr, $input:ident, $t:ty, ($q:expr, $w:expr, $al:expr)) => {
        $m.solve(
            &$input {
                theta: <$t>::lit($q),
            },
            &$input {
                theta: <$t>::lit($w),
            },
            &$input {
                theta: <$t>::lit($al),
            },
        )
    };
}

/// The largest error allowed, in units of the sample's first-order bound.
/// The generated chain rounds about 8 times per stage at the stage's scale:
/// the crank's tip (sine and cosine within 2 ulp, a product and a sum), the
/// group's difference vector, its squared length, the square root and the
/// products forming the joint; the rates and accelerations repeat it through
/// the same `1 / s`. Measured: at most 6.7 over 400 000 samples per run (the
/// eight runs below with `SAMPLES = 400_000`, release build; 4.7 with the
/// 20 000 of CI).
const BOUND: f64 = 8.0;

/// SplitMix64: a small deterministic generator (fixed seeds, so a failure
/// reproduces).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in `[lo, hi)`.
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn vd(x: f64, y: f64) -> V {
    refg::v(x, y)
}

fn norm(a: V) -> f64 {
    refg::norm(a).to_f64()
}

/// `|got - r|` for a computed vector against a reference one.
fn dist(got: (f64, f64), r: V) -> f64 {
    norm(refg::sub(vd(got.0, got.1), r))
}

/// `|got - r|` for an angle (rad), the difference wrapped to `(-pi, pi]`.
fn angle_error(got: f64, r: Dd) -> f64 {
    let d = (Dd::from(got) - r).to_f64();
    let turn = 2.0 * std::f64::consts::PI;
    (d - turn * (d / turn).round()).abs()
}

/// Worst ratios and counts over a run.
#[derive(Default, Debug)]
struct Tally {
    /// Worst error over its bound: position, velocity, acceleration, angle.
    worst: [f64; 4],
    /// Samples compared.
    compared: usize,
    /// Typed errors where the reference assembles, within an edge's band.
    edge_errors: usize,
    /// Samples the reference cannot assemble (all typed errors here).
    outside: usize,
    /// Samples whose rates have no digits to promise (see [`NO_DIGITS`]).
    no_digits: usize,
}

/// A joint's position, velocity and acceleration, computed and reference,
/// with each stage's largest reference vector in the sample.
struct Stages {
    got: [(f64, f64); 3],
    reference: [V; 3],
    scales: [f64; 3],
    /// The power of the condition in each stage's bound: `[1, 2, 3]` where
    /// the rate system is built from the positions (it inherits their
    /// `1 / s`), `[1, 1, 1]` where its matrix is fixed by the guides (an
    /// RPP's slot and guide: the rates see the positions only through the
    /// right-hand side).
    powers: [i32; 3],
}

impl Stages {
    /// A joint's computed position, velocity and acceleration against the
    /// reference's, with the stages' scales.
    fn of_joint<T: Real>(
        (p, v, a): (&Point2<T>, &Vector2<T>, &Vector2<T>),
        reference: [V; 3],
        scales: [f64; 3],
    ) -> Stages {
        let pair = |x: T, y: T| (x.as_f64(), y.as_f64());
        Stages {
            got: [pair(p.x, p.y), pair(v.x, v.y), pair(a.x, a.y)],
            reference,
            scales,
            powers: [1, 2, 3],
        }
    }
}

/// Above this first-order relative error the rates promise no digits (the
/// first-order bound stops describing the error, which is no longer small):
/// they are then checked finite only.
const NO_DIGITS: f64 = 1e-2;

impl Tally {
    /// Adds a sample's three stages: position against `eps L / s`, the rates
    /// against `eps spread L / s^k` (stage `k`; the power as
    /// [`Stages::powers`] gives it), `spread` the largest
    /// coordinate over the group's shortest link (what the positions'
    /// rounding does to the links' directions).
    fn compare(&mut self, st: &Stages, eps: f64, s: f64, spread: f64, what: &str) {
        let err = |k: usize| dist(st.got[k], st.reference[k]);
        let unit = |k: usize| eps * st.scales[k] / s.powi(st.powers[k]);
        self.add(0, err(0) / unit(0), what);
        if eps * spread / s.powi(st.powers[1]) > NO_DIGITS {
            self.no_digits += 1;
            assert!(
                st.got.iter().all(|g| g.0.is_finite() && g.1.is_finite()),
                "{what}: non-finite rates"
            );
            return;
        }
        self.add(1, err(1) / (spread * unit(1)), what);
        self.add(2, err(2) / (spread * unit(2)), what);
    }

    /// A pose the reference cannot assemble: the generated code must return
    /// a typed error naming `group`, or (within an edge's rounding band,
    /// `near_edge`) a finite answer.
    fn outside<T: Real, S>(
        &mut self,
        got: &Result<S, Error<T>>,
        group: &str,
        near_edge: bool,
        what: &str,
    ) {
        self.outside += 1;
        match got {
            Err(e) => assert_eq!(e.group, group, "{what}: error in the wrong group: {e}"),
            Ok(_) => assert!(
                near_edge,
                "{what}: Ok where the reference does not assemble"
            ),
        }
    }

    /// A pose the reference assembles, with the group's condition `kappa`:
    /// the generated solution, or `None` after checking that its typed error
    /// names `group` and lies within an edge's band (`near_edge`) or is
    /// `Singular` where `kappa` is within rounding of zero.
    fn inside<T: Real, S>(
        &mut self,
        got: Result<S, Error<T>>,
        group: &str,
        (near_edge, kappa): (bool, f64),
        eps: f64,
        what: &str,
    ) -> Option<S> {
        match got {
            Ok(sol) => {
                self.compared += 1;
                Some(sol)
            }
            Err(e) => {
                assert_eq!(e.group, group, "{what}: {e}");
                let singular = kappa <= 1e3 * eps && matches!(e.fault, Fault::Singular { .. });
                assert!(
                    near_edge || singular,
                    "{what}: the reference assembles (condition {kappa:e}) but: {e}"
                );
                self.edge_errors += 1;
                None
            }
        }
    }

    /// Records the kinematic ratio `k` (position, velocity, acceleration,
    /// angle) against [`BOUND`].
    fn add(&mut self, k: usize, ratio: f64, what: &str) {
        let label = ["position", "velocity", "acceleration", "angle"][k];
        self.record(k, ratio, BOUND, label, what);
    }

    /// Records a ratio in slot `k`, asserting it is within `bound`.
    fn record(&mut self, k: usize, ratio: f64, bound: f64, label: &str, what: &str) {
        assert!(
            ratio <= bound,
            "{what}: {label} error {ratio:.2} times its first-order bound (allowed {bound})"
        );
        self.worst[k] = self.worst[k].max(ratio);
    }
}

/// A value as `T` (rounded once for `f32`) and back: the generated code and
/// the reference then see the same number.
fn through<T: Real>(x: f64) -> f64 {
    T::lit(x).as_f64()
}

/// A random applied load (N or N m, as `typical`): `typical` times a factor
/// log-uniform over 1e-2 .. 1e2 and a uniform sign and size in (-1, 1),
/// rounded through `T`.
fn random_load<T: Real>(rng: &mut Rng, typical: f64) -> f64 {
    through::<T>(typical * 10f64.powf(rng.uniform(-2.0, 2.0)) * rng.uniform(-1.0, 1.0))
}

/// A random length: a factor in [0.2, 5) times `scale`.
fn length(rng: &mut Rng, scale: f64) -> f64 {
    scale * rng.uniform(0.2, 5.0)
}

/// A random overall scale over six decades (1e-3 .. 1e3).
fn scale(rng: &mut Rng) -> f64 {
    10f64.powf(rng.uniform(-3.0, 3.0))
}

/// The crank's input: angle (rad), speed (rad/s), angular acceleration
/// (rad/s^2), each rounded to `T`.
fn drive<T: Real>(rng: &mut Rng) -> (f64, f64, f64) {
    (
        through::<T>(rng.uniform(-4.0, 4.0)),
        through::<T>(rng.uniform(-300.0, 300.0)),
        through::<T>(rng.uniform(-5e4, 5e4)),
    )
}

/// How a run draws its samples.
#[derive(Clone, Copy, PartialEq)]
enum Draw {
    /// Every dimension and the pose at random.
    Free,
    /// The pose at random and the group's lengths fitted to it, at a
    /// relative distance of 1e-17 .. 1e-2 inside or outside an edge of
    /// assembly (full extension, folding, tangency).
    Edge,
}

/// A relative distance to an edge, `+-10^U(-17, -2)` (the smallest below
/// `f64`'s rounding of the lengths: the band's both sides).
fn edge_distance(rng: &mut Rng) -> f64 {
    let d = 10f64.powf(rng.uniform(-17.0, -2.0));
    if rng.next() & 1 == 0 {
        d
    } else {
        -d
    }
}

fn run_quad<T: Real>(samples: usize, seed: u64, draw: Draw) -> Tally {
    let eps = T::eps().as_f64();
    draws(samples, seed, |rng, n, tally, sc| {
        let mut dims = [
            length(rng, sc),
            length(rng, sc) * rng.uniform(-1.0, 1.0),
            length(rng, sc),
            length(rng, sc),
            length(rng, sc),
        ];
        let (q, w, al) = drive::<T>(rng);
        if draw == Draw::Edge {
            // |A - Q| at this pose (f64: the edge is approached to about
            // 1e-16, the f32 runs' band is far wider), then b and c that
            // reach it to the drawn relative distance: b + c (stretched)
            // or |b - c| (folded).
            let [gx, gy, a, _, _] = dims.map(through::<T>);
            let span = ((gx - a * q.cos()).powi(2) + (gy - a * q.sin()).powi(2)).sqrt();
            let f = rng.uniform(0.2, 0.8);
            let at = span * (1.0 + edge_distance(rng));
            if rng.next() & 1 == 0 {
                dims[3] = f * at;
                dims[4] = (1.0 - f) * at;
            } else {
                dims[3] = at / (1.0 - f);
                dims[4] = dims[3] - at;
            }
        }
        let [gx, gy, a, b, c] = dims.map(through::<T>);
        let m = Quad::<T> {
            gx: T::lit(gx),
            gy: T::lit(gy),
            a: T::lit(a),
            b: T::lit(b),
            c: T::lit(c),
        };
        let got = solve_at!(m, QuadInput, T, (q, w, al));
        // The reference, in double-double at the same (rounded) numbers.
        let o = vd(0.0, 0.0);
        let qq = vd(gx, gy);
        let (pa, va, aa) = refg::crank(o, a, q, w, al);
        let what = format!("Quad {n}: gx {gx:e} gy {gy:e} a {a:e} b {b:e} c {c:e} theta {q}");
        let size = [gx.abs(), gy.abs(), a, b, c]
            .into_iter()
            .fold(0.0, f64::max);
        let Some((sol, pb, s)) = rrr_verdict(tally, got, "B", (pa, b, qq, c), size, eps, &what)
        else {
            return;
        };
        let (r1, r2) = (refg::sub(pb, pa), refg::sub(pb, qq));
        let s = s.max(f64::MIN_POSITIVE);
        let (w1, w2) = refg::rrr_rates(pa, qq, pb, va, vd(0.0, 0.0)).expect("rates");
        let vb = refg::add(va, refg::scale(w1, refg::perp(r1)));
        let (a1, _) =
            refg::rrr_accelerations(pa, qq, pb, aa, vd(0.0, 0.0), w1, w2).expect("accelerations");
        let ab = refg::sub(
            refg::add(aa, refg::scale(a1, refg::perp(r1))),
            refg::scale(w1.sqr(), r1),
        );
        let l_pos = [norm(pa), norm(qq), norm(pb), a, b, c]
            .into_iter()
            .fold(0.0, f64::max);
        let l_vel = norm(va).max(norm(vb));
        let l_acc = [
            norm(aa),
            norm(ab),
            w1.sqr().to_f64() * b,
            w2.sqr().to_f64() * c,
        ]
        .into_iter()
        .fold(0.0, f64::max);
        // The rates see the links' directions, known to the positions'
        // rounding (eps l_pos) over the shorter link's length.
        let spread = l_pos / b.min(c);
        let p = &sol.position;
        let (v, ac) = (&sol.velocity.B, &sol.acceleration.B);
        let stages = Stages::of_joint((&p.B, v, ac), [pb, vb, ab], [l_pos, l_vel, l_acc]);
        tally.compare(&stages, eps, s, spread, &what);
        // A link's angle moves by the error of its vector over its length.
        let t3 = Dd::atan2(r1[1], r1[0]);
        let t4 = Dd::atan2(r2[1], r2[0]);
        let e3 = angle_error(p.coupler.as_f64(), t3) / (eps * l_pos / (b * s));
        let e4 = angle_error(p.rocker.as_f64(), t4) / (eps * l_pos / (c * s));
        tally.add(3, e3.max(e4), &what);
    })
}

fn run_slide<T: Real>(samples: usize, seed: u64, draw: Draw) -> Tally {
    let eps = T::eps().as_f64();
    draws(samples, seed, |rng, n, tally, sc| {
        let a = through::<T>(length(rng, sc));
        let mut l = through::<T>(length(rng, sc));
        let e = coordinate::<T>(rng, sc);
        let tilt = through::<T>(rng.uniform(-3.2, 3.2));
        let (q, w, al) = drive::<T>(rng);
        if draw == Draw::Edge {
            // The rod as long as A's distance from the line, to the drawn
            // relative distance (tangency).
            let k = (e - a * q.sin()) * tilt.cos() + a * q.cos() * tilt.sin();
            l = through::<T>(k.abs() * (1.0 + edge_distance(rng)));
        }
        let m = Slide::<T> {
            a: T::lit(a),
            l: T::lit(l),
            e: T::lit(e),
            tilt: T::lit(tilt),
        };
        let got = solve_at!(m, SlideInput, T, (q, w, al));
        // The guide's direction as the generated code has it (cos, sin of
        // the rounded tilt, rounded to T): the reference takes that exact
        // line, so the comparison is of the group, not of the guide's
        // trigonometry (whose own rounding is the input's).
        let (st, ct) = T::lit(tilt).sin_cos_kernel();
        let line = refg::Line::new([0.0, e], [ct.as_f64(), st.as_f64()]);
        let o = vd(0.0, 0.0);
        let (pa, va, aa) = refg::crank(o, a, q, w, al);
        let what = format!("Slide {n}: a {a:e} l {l:e} e {e:e} tilt {tilt} theta {q}");
        let p_rel = refg::sub(pa, line.origin);
        let k = refg::dot(p_rel, refg::perp(line.dir)).to_f64().abs();
        let size = [a, l, e.abs()].into_iter().fold(0.0, f64::max);
        // The band of `rrp::position` on the distance of A from the line
        // (a few eps of l), widened by A's and the guide's rounding.
        let near_edge = (k - l).abs() <= 8.0 * eps * l + 8.0 * eps * size;
        let Some((pb, _)) = refg::rrp_position(pa, l, &line, 0.0, true) else {
            tally.outside(&got, "B", near_edge, &what);
            return;
        };
        let r1 = refg::sub(pb, pa);
        let s = (refg::dot(r1, line.dir).to_f64() / l).abs();
        let Some(sol) = tally.inside(got, "B", (near_edge, s), eps, &what) else {
            return;
        };
        let s = s.max(f64::MIN_POSITIVE);
        let (w1, sd) = refg::rrp_rates(pa, pb, &line, va).expect("rates");
        let vb = refg::scale(sd, line.dir);
        let (_, sdd) = refg::rrp_accelerations(pa, pb, &line, aa, w1).expect("accelerations");
        let ab = refg::scale(sdd, line.dir);
        let l_pos = [norm(pa), norm(pb), a, l, e.abs()]
            .into_iter()
            .fold(0.0, f64::max);
        let l_vel = norm(va).max(norm(vb));
        let l_acc = [norm(aa), norm(ab), w1.sqr().to_f64() * l]
            .into_iter()
            .fold(0.0, f64::max);
        // The rod's direction is known to the positions' rounding over its
        // length (the guide's direction is exact for the reference).
        let spread = l_pos / l;
        let p = &sol.position;
        let (v, ac) = (&sol.velocity.B, &sol.acceleration.B);
        let stages = Stages::of_joint((&p.B, v, ac), [pb, vb, ab], [l_pos, l_vel, l_acc]);
        tally.compare(&stages, eps, s, spread, &what);
        let t = Dd::atan2(r1[1], r1[0]);
        tally.add(
            3,
            angle_error(p.rod.as_f64(), t) / (eps * l_pos / (l * s)),
            &what,
        );
    })
}

fn run_swing<T: Real>(samples: usize, seed: u64, draw: Draw) -> Tally {
    let eps = T::eps().as_f64();
    draws(samples, seed, |rng, n, tally, sc| {
        let a = through::<T>(length(rng, sc));
        let px = coordinate::<T>(rng, sc);
        let py = coordinate::<T>(rng, sc);
        let mut e = through::<T>(length(rng, sc) * rng.uniform(-0.5, 0.5));
        let (q, w, al) = drive::<T>(rng);
        if draw == Draw::Edge {
            // The offset as large as |A - P|, to the drawn relative distance
            // (the slide line tangent to the circle through A about P).
            let span = (a * q.cos() - px).hypot(a * q.sin() - py);
            e = through::<T>(span * (1.0 + edge_distance(rng)) * e.signum());
        }
        let m = Swing::<T> {
            px: T::lit(px),
            py: T::lit(py),
            a: T::lit(a),
            e: T::lit(e),
        };
        let got = solve_at!(m, SwingInput, T, (q, w, al));
        let (pa, va, aa) = refg::crank(vd(0.0, 0.0), a, q, w, al);
        let pp = vd(px, py);
        let pv = refg::sub(pa, pp);
        let span = norm(pv);
        let what = format!("Swing {n}: px {px:e} py {py:e} a {a:e} e {e:e} theta {q}");
        let size = [px.abs(), py.abs(), a, e.abs()]
            .into_iter()
            .fold(0.0, f64::max);
        let near_edge = (span - e.abs()).abs() <= 8.0 * eps * size;
        let Some((u, sl)) = refg::rpr_position(pa, pp, e, true) else {
            tally.outside(&got, "s", near_edge, &what);
            return;
        };
        // The condition of `docs/stability.md`: |s| / |A - P|, and at most
        // |A - P| / size (the axis is known to eps size / |A - P|).
        let kappa = (sl.to_f64().abs() / span).min(span / size);
        let Some(sol) = tally.inside(got, "s", (near_edge, kappa), eps, &what) else {
            return;
        };
        // Rates: s_dot u + omega perp(A - P) = vA; accelerations from its
        // derivative, s_ddot u + alpha perp(A - P) = aA - s_dot omega
        // perp(u) - omega perp(vA) (u turns at omega).
        let (om, sd) = refg::rpr_rates(pa, pp, u, va, vd(0.0, 0.0)).expect("rates");
        let rhs = refg::sub(
            aa,
            refg::add(
                refg::scale(sd * om, refg::perp(u)),
                refg::scale(om, refg::perp(va)),
            ),
        );
        let (alpha, sdd) = refg::solve2(refg::perp(pv), u, rhs).expect("accelerations");
        // Each stage as a vector of its two unknowns in one unit: the slide
        // and the rocker's turn times |A - P| (position: the block's place
        // along the rocker and across it).
        let l_pos = [norm(pa), span, a, size].into_iter().fold(0.0, f64::max);
        let turn = |x: Dd| (x * Dd::from(span)).to_f64();
        let l_vel = [norm(va), sd.to_f64().abs(), turn(om).abs()]
            .into_iter()
            .fold(0.0, f64::max);
        let l_acc = [
            norm(aa),
            (sd * om).to_f64().abs(),
            turn(om * om).abs(),
            sdd.to_f64().abs(),
            turn(alpha).abs(),
        ]
        .into_iter()
        .fold(0.0, f64::max);
        let (p, v, ac) = (&sol.position, &sol.velocity, &sol.acceleration);
        let t = Dd::atan2(u[1], u[0]);
        let angle = angle_error(p.rocker.as_f64(), t);
        let stages = Stages {
            got: [
                (p.s.as_f64(), 0.0),
                (v.s.as_f64(), v.rocker.as_f64() * span),
                (ac.s.as_f64(), ac.rocker.as_f64() * span),
            ],
            reference: [
                [sl, Dd::from(angle * span)],
                [sd, om * Dd::from(span)],
                [sdd, alpha * Dd::from(span)],
            ],
            scales: [l_pos, l_vel, l_acc],
            powers: [1, 2, 3],
        };
        tally.compare(&stages, eps, kappa, l_pos / span, &what);
        tally.add(3, angle / (eps * l_pos / (span * kappa)), &what);
    })
}

fn run_cross<T: Real>(samples: usize, seed: u64, draw: Draw) -> Tally {
    let eps = T::eps().as_f64();
    draws(samples, seed, |rng, n, tally, sc| {
        let gx = coordinate::<T>(rng, sc);
        let gy = coordinate::<T>(rng, sc);
        let gangle = through::<T>(rng.uniform(-3.2, 3.2));
        let o1 = through::<T>(length(rng, sc) * rng.uniform(-0.5, 0.5));
        let o2 = through::<T>(length(rng, sc) * rng.uniform(-0.5, 0.5));
        let (q, w, al) = drive::<T>(rng);
        let mut tilt = through::<T>(rng.uniform(-3.2, 3.2));
        if draw == Draw::Edge {
            // The turning line within 1e-17 .. 1e-2 rad of parallel to the
            // fixed guide (the joint runs off towards infinity).
            tilt = through::<T>(gangle - q + edge_distance(rng));
        }
        let m = Cross::<T> {
            gx: T::lit(gx),
            gy: T::lit(gy),
            gangle: T::lit(gangle),
            tilt: T::lit(tilt),
            o1: T::lit(o1),
            o2: T::lit(o2),
        };
        let got = solve_at!(m, CrossInput, T, (q, w, al));
        let what = format!("Cross {n}: guide ({gx:e}, {gy:e}) at {gangle}, tilt {tilt}, offsets {o1:e} {o2:e}, theta {q}");
        // The two lines exactly at the rounded angles (the generated code's
        // own sines and cosines round within eps: first order, in the bound).
        let (s1t, c1t) = (Dd::from(q) + Dd::from(tilt)).sin_cos();
        let (s2t, c2t) = Dd::from(gangle).sin_cos();
        let u1 = [c1t, s1t];
        let u2 = [c2t, s2t];
        let g1 = refg::Line {
            origin: vd(0.0, 0.0),
            dir: u1,
        };
        let g2 = refg::Line {
            origin: vd(gx, gy),
            dir: u2,
        };
        let kappa = refg::cross(u1, u2).to_f64().abs();
        let size = [gx.abs(), gy.abs(), o1.abs(), o2.abs()]
            .into_iter()
            .fold(0.0, f64::max);
        // Parallel to rounding: the reference's determinant is exact, the
        // generated lines' directions are eps off.
        let near_edge = kappa <= 8.0 * eps;
        let Some((pc, _, _)) = refg::prp_position(&g1, o1, &g2, o2) else {
            tally.outside(&got, "C", near_edge, &what);
            return;
        };
        let Some(sol) = tally.inside(got, "C", (near_edge, kappa), eps, &what) else {
            return;
        };
        // Rates: C - O = s1 u1 + o1 perp(u1) turns at w, so
        // s1' u1 - s2' u2 = -w perp(C - O); once more:
        // s1'' u1 - s2'' u2 = -s1' w perp(u1) - al perp(C - O) - w perp(vC).
        let (wd, ald) = (Dd::from(w), Dd::from(al));
        let (sd1, sd2) = refg::solve2(
            u1,
            refg::scale(-Dd::ONE, u2),
            refg::scale(-wd, refg::perp(pc)),
        )
        .expect("rates");
        let vc = refg::scale(sd2, u2);
        let rhs = refg::sub(
            refg::scale(-(sd1 * wd), refg::perp(u1)),
            refg::add(
                refg::scale(ald, refg::perp(pc)),
                refg::scale(wd, refg::perp(vc)),
            ),
        );
        let (_, sdd2) = refg::solve2(u1, refg::scale(-Dd::ONE, u2), rhs).expect("accelerations");
        let ac = refg::scale(sdd2, u2);
        let l_pos = norm(pc).max(size);
        // The turning line moves its points at w times their distance.
        let l_vel = norm(vc).max(w.abs() * l_pos);
        let l_acc = [
            norm(ac),
            (w * w + al.abs()) * l_pos,
            (sd1 * wd).to_f64().abs(),
        ]
        .into_iter()
        .fold(0.0, f64::max);
        let stages = Stages::of_joint(
            (&sol.position.C, &sol.velocity.C, &sol.acceleration.C),
            [pc, vc, ac],
            [l_pos, l_vel, l_acc],
        );
        // The guides' directions come from angles (eps each), not from
        // rounded points: no spread.
        tally.compare(&stages, eps, kappa.max(f64::MIN_POSITIVE), 1.0, &what);
    })
}

fn run_yoke<T: Real>(samples: usize, seed: u64, draw: Draw) -> Tally {
    let eps = T::eps().as_f64();
    draws(samples, seed, |rng, n, tally, sc| {
        let a = through::<T>(length(rng, sc));
        let gx = coordinate::<T>(rng, sc);
        let gy = coordinate::<T>(rng, sc);
        let off = through::<T>(length(rng, sc) * rng.uniform(-0.5, 0.5));
        let gangle = through::<T>(rng.uniform(-3.2, 3.2));
        let slot = through::<T>(match draw {
            Draw::Free => rng.uniform(-3.2, 3.2),
            // The slot within 1e-17 .. 1e-2 rad of the guide's direction.
            Draw::Edge => edge_distance(rng),
        });
        let (q, w, al) = drive::<T>(rng);
        let m = Yoke::<T> {
            a: T::lit(a),
            gx: T::lit(gx),
            gy: T::lit(gy),
            gangle: T::lit(gangle),
            slot: T::lit(slot),
            off: T::lit(off),
        };
        let got = solve_at!(m, YokeInput, T, (q, w, al));
        let what = format!("Yoke {n}: a {a:e} guide ({gx:e}, {gy:e}) at {gangle}, slot {slot}, off {off:e}, theta {q}");
        // A = G + s2 u + off perp(u) + s1 w, w the slot's direction
        // (cos slot, sin slot) in the guide's frame; the yoke translates, so
        // the same 2x2 system gives the rates and accelerations.
        let (sg, cg) = Dd::from(gangle).sin_cos();
        let u = [cg, sg];
        let nu = refg::perp(u);
        let (ss, cs) = Dd::from(slot).sin_cos();
        let slot_dir = refg::add(refg::scale(cs, u), refg::scale(ss, nu));
        let kappa = ss.to_f64().abs();
        let (pa, va, aa) = refg::crank(vd(0.0, 0.0), a, q, w, al);
        let base = refg::add(vd(gx, gy), refg::scale(Dd::from(off), nu));
        let near_edge = kappa <= 8.0 * eps;
        let Some((_, s2)) = refg::solve2(slot_dir, u, refg::sub(pa, base)) else {
            tally.outside(&got, "Q", near_edge, &what);
            return;
        };
        let Some(sol) = tally.inside(got, "Q", (near_edge, kappa), eps, &what) else {
            return;
        };
        let (_, sd2) = refg::solve2(slot_dir, u, va).expect("rates");
        let (_, sdd2) = refg::solve2(slot_dir, u, aa).expect("accelerations");
        let pq = refg::add(base, refg::scale(s2, u));
        let (vq, aq) = (refg::scale(sd2, u), refg::scale(sdd2, u));
        let l_pos = [norm(pa), norm(pq), a, gx.abs(), gy.abs(), off.abs()]
            .into_iter()
            .fold(0.0, f64::max);
        let stages = Stages {
            powers: [1, 1, 1],
            ..Stages::of_joint(
                (&sol.position.Q, &sol.velocity.Q, &sol.acceleration.Q),
                [pq, vq, aq],
                [l_pos, norm(va).max(norm(vq)), norm(aa).max(norm(aq))],
            )
        };
        // The slot and the guide keep their directions: the rates see the
        // positions only through the crank's pin (no spread, and the
        // condition once per stage).
        tally.compare(&stages, eps, kappa.max(f64::MIN_POSITIVE), 1.0, &what);
    })
}

fn run_boom<T: Real>(samples: usize, seed: u64, draw: Draw) -> Tally {
    let eps = T::eps().as_f64();
    draws(samples, seed, |rng, n, tally, sc| {
        let r = through::<T>(length(rng, sc));
        let bx = coordinate::<T>(rng, sc);
        let by = coordinate::<T>(rng, sc);
        let span = bx.hypot(by);
        let len = through::<T>(match draw {
            Draw::Free => rng.uniform(0.0, 1.2) * (r + span),
            // Within 1e-17 .. 1e-2 of full extension or of folding.
            Draw::Edge => {
                let edge = if rng.next() & 1 == 0 {
                    r + span
                } else {
                    (r - span).abs()
                };
                edge * (1.0 + edge_distance(rng))
            }
        });
        // The cylinder's rate and acceleration, of the size the length
        // changes by in 10 ms and 0.1 ms^2.
        let len_dot = through::<T>(len * rng.uniform(-100.0, 100.0));
        let len_ddot = through::<T>(len * rng.uniform(-1e4, 1e4));
        let m = Boom::<T> {
            r: T::lit(r),
            bx: T::lit(bx),
            by: T::lit(by),
        };
        let got = m.solve(
            &BoomInput { len: T::lit(len) },
            &BoomInput {
                len: T::lit(len_dot),
            },
            &BoomInput {
                len: T::lit(len_ddot),
            },
        );
        let what = format!("Boom {n}: r {r:e} B ({bx:e}, {by:e}) len {len:e}");
        let (pa, pb) = (vd(0.0, 0.0), vd(bx, by));
        let size = [r, bx.abs(), by.abs(), len].into_iter().fold(0.0, f64::max);
        let Some((sol, pc, s)) = rrr_verdict(tally, got, "C", (pa, r, pb, len), size, eps, &what)
        else {
            return;
        };
        let (r1, r2) = (refg::sub(pc, pa), refg::sub(pc, pb));
        // |C - A| = r and |C - B| = len, differentiated: r1 . vC = 0,
        // r2 . vC = len len'; once more: r1 . aC = -|vC|^2,
        // r2 . aC = len'^2 + len len'' - |vC|^2. As columns for `solve2`:
        // x (r1.x, r2.x) + y (r1.y, r2.y) = rhs.
        let (c0, c1) = ([r1[0], r2[0]], [r1[1], r2[1]]);
        let (ld, ldd, l) = (Dd::from(len_dot), Dd::from(len_ddot), Dd::from(len));
        let (vx, vy) = refg::solve2(c0, c1, [Dd::ZERO, l * ld]).expect("rates");
        let vc = [vx, vy];
        let v2 = refg::dot(vc, vc);
        let (ax, ay) = refg::solve2(c0, c1, [-v2, ld.sqr() + l * ldd - v2]).expect("accelerations");
        let ac = [ax, ay];
        let l_pos = [norm(pc), size].into_iter().fold(0.0, f64::max);
        let stages = Stages::of_joint(
            (&sol.position.C, &sol.velocity.C, &sol.acceleration.C),
            [pc, vc, ac],
            [
                l_pos,
                norm(vc).max(len_dot.abs()),
                [norm(ac), len_ddot.abs(), v2.to_f64() / r.min(len)]
                    .into_iter()
                    .fold(0.0, f64::max),
            ],
        );
        tally.compare(
            &stages,
            eps,
            s.max(f64::MIN_POSITIVE),
            l_pos / r.min(len),
            &what,
        );
    })
}

/// Runs `sample` on `samples` draws from the generator seeded with `seed`:
/// each call gets the generator, the draw's index, the tally and the draw's
/// overall scale (see [`scale`]).
fn draws(
    samples: usize,
    seed: u64,
    mut sample: impl FnMut(&mut Rng, usize, &mut Tally, f64),
) -> Tally {
    let mut rng = Rng(seed);
    let mut tally = Tally::default();
    for n in 0..samples {
        let sc = scale(&mut rng);
        sample(&mut rng, n, &mut tally, sc);
    }
    tally
}

/// A random coordinate: `length` times a sign and factor in [-1, 1), rounded
/// to `T`.
fn coordinate<T: Real>(rng: &mut Rng, sc: f64) -> f64 {
    through::<T>(length(rng, sc) * rng.uniform(-1.0, 1.0))
}

/// Random six-bars: the second group's joint `D` against the chained group
/// references. Its inputs are `P`, which carries the first group's error
/// (`eps L / s1`, and the coupler's direction error `eps L / (b s1)` times
/// the lever `|P - A|`), and the ground pivot `H`: first order, `D`'s error
/// is `eps L (1 + |P - A| / b) / (s1 s2)` in position, and stage `k` of the
/// rates carries both groups' spreads and `1 / (s1 s2)^k` (each group's own
/// first-order bound, the second seeing the first's error in its inputs).
fn run_six<T: Real>(samples: usize, seed: u64) -> Tally {
    let eps = T::eps().as_f64();
    draws(samples, seed, |rng, n, tally, sc| {
        let [gx, gy, hx, hy] = [0; 4].map(|_| coordinate::<T>(rng, sc));
        let [a, b, c, d, e] = [0; 5].map(|_| through::<T>(length(rng, sc)));
        let (pu, pv) = (coordinate::<T>(rng, sc), coordinate::<T>(rng, sc));
        let (q, w, al) = drive::<T>(rng);
        let lit = |x: f64| T::lit(x);
        let m = Six::<T> {
            gx: lit(gx),
            gy: lit(gy),
            a: lit(a),
            b: lit(b),
            c: lit(c),
            pu: lit(pu),
            pv: lit(pv),
            hx: lit(hx),
            hy: lit(hy),
            d: lit(d),
            e: lit(e),
        };
        let got = solve_at!(m, SixInput, T, (q, w, al));
        let what = format!("Six {n}: Q ({gx:e}, {gy:e}) H ({hx:e}, {hy:e}) a {a:e} b {b:e} c {c:e} P ({pu:e}, {pv:e}) d {d:e} e {e:e} theta {q}");
        let (qq, hh, zero) = (vd(gx, gy), vd(hx, hy), vd(0.0, 0.0));
        let (pa, va, aa) = refg::crank(zero, a, q, w, al);
        let first = refg::rrr_position(pa, b, qq, c, true);
        let second = first.and_then(|pb| {
            let e3 = refg::scale(Dd::ONE / Dd::from(b), refg::sub(pb, pa));
            let rp = refg::add(
                refg::scale(Dd::from(pu), e3),
                refg::scale(Dd::from(pv), refg::perp(e3)),
            );
            let pp = refg::add(pa, rp);
            refg::rrr_position(pp, d, hh, e, true).map(|pd| (pb, rp, pd))
        });
        let Some((pb, rp, pd)) = second else {
            // Either group may fail; the generated error names one of them.
            tally.outside += 1;
            if let Ok(sol) = got {
                panic!(
                    "{what}: Ok where the reference does not assemble: {:?}",
                    sol.position.D
                );
            }
            return;
        };
        let pp = refg::add(pa, rp);
        let (r1, r2) = (refg::sub(pb, pa), refg::sub(pb, qq));
        let (r5, r6) = (refg::sub(pd, pp), refg::sub(pd, hh));
        let s1 = (refg::cross(r1, r2).to_f64() / (b * c)).abs();
        let s2 = (refg::cross(r5, r6).to_f64() / (d * e)).abs();
        let sol = match got {
            Ok(sol) => sol,
            Err(err) => {
                // Only where a group is at its edge or toggle to rounding:
                // the edge's band, 8 eps of the lengths and of the
                // coordinates on |d|, is a sine of about its square root.
                let size = [
                    gx.abs(),
                    gy.abs(),
                    hx.abs(),
                    hy.abs(),
                    pu.abs(),
                    pv.abs(),
                    a,
                    b,
                    c,
                    d,
                    e,
                ]
                .into_iter()
                .fold(0.0, f64::max);
                let band = (64.0 * eps * size / b.min(c).min(d).min(e)).sqrt();
                assert!(
                    s1.min(s2) <= band,
                    "{what}: the reference assembles (sines {s1:e}, {s2:e}) but: {err}"
                );
                tally.edge_errors += 1;
                return;
            }
        };
        tally.compared += 1;
        let (w3, w4) = refg::rrr_rates(pa, qq, pb, va, zero).expect("rates");
        let (a3, _) = refg::rrr_accelerations(pa, qq, pb, aa, zero, w3, w4).expect("accelerations");
        let vp = refg::add(va, refg::scale(w3, refg::perp(rp)));
        let ap = refg::sub(
            refg::add(aa, refg::scale(a3, refg::perp(rp))),
            refg::scale(w3.sqr(), rp),
        );
        let (w5, w6) = refg::rrr_rates(pp, hh, pd, vp, zero).expect("rates");
        let (a5, _) = refg::rrr_accelerations(pp, hh, pd, ap, zero, w5, w6).expect("accelerations");
        let vdd = refg::add(vp, refg::scale(w5, refg::perp(r5)));
        let add_ = refg::sub(
            refg::add(ap, refg::scale(a5, refg::perp(r5))),
            refg::scale(w5.sqr(), r5),
        );
        let l_pos = [
            norm(pa),
            norm(qq),
            norm(hh),
            norm(pb),
            norm(pp),
            norm(pd),
            a,
            b,
            c,
            d,
            e,
        ]
        .into_iter()
        .fold(0.0, f64::max);
        let l_vel = [
            norm(va),
            norm(vp),
            norm(vdd),
            w4.to_f64().abs() * c,
            w6.to_f64().abs() * e,
        ]
        .into_iter()
        .fold(0.0, f64::max);
        let l_acc = [
            norm(aa),
            norm(ap),
            norm(add_),
            w3.sqr().to_f64() * b,
            w4.sqr().to_f64() * c,
            w5.sqr().to_f64() * d,
            w6.sqr().to_f64() * e,
        ]
        .into_iter()
        .fold(0.0, f64::max);
        let lever = 1.0 + norm(rp) / b;
        let spread = (l_pos / b.min(c)) * (l_pos / d.min(e));
        let stages = Stages::of_joint(
            (&sol.position.D, &sol.velocity.D, &sol.acceleration.D),
            [pd, vdd, add_],
            [
                lever * l_pos / s1,
                lever * l_vel / (s1 * s1),
                lever * l_acc / (s1 * s1 * s1),
            ],
        );
        if std::env::var("RD_DEBUG").is_ok() {
            let _ = spread;
        }
        tally.compare(&stages, eps, s2.max(f64::MIN_POSITIVE), spread, &what);
    })
}

/// An RRR group's reference joint `C` from `A` (link `l1`) and `B` (link
/// `l2`), and the verdict where either side fails (see [`Tally::outside`]
/// and [`Tally::inside`]): the solution, `C` and the group's condition
/// (`|sin|` of the links' angle) where both assemble. The edge's band is
/// that of `rrr::position` on `|A - B|` (8 eps `(l1 + l2)`), widened by the
/// rounding of the coordinates (8 eps of `size`).
fn rrr_verdict<T: Real, S>(
    tally: &mut Tally,
    got: Result<S, Error<T>>,
    group: &str,
    (a, l1, b, l2): (V, f64, V, f64),
    size: f64,
    eps: f64,
    what: &str,
) -> Option<(S, V, f64)> {
    let span = norm(refg::sub(b, a));
    let band = 8.0 * eps * (l1 + l2) + 8.0 * eps * size;
    let near_edge = (span - (l1 + l2)).abs() <= band || (span - (l1 - l2).abs()).abs() <= band;
    let Some(c) = refg::rrr_position(a, l1, b, l2, true) else {
        tally.outside(&got, group, near_edge, what);
        return None;
    };
    let s = (refg::cross(refg::sub(c, a), refg::sub(c, b)).to_f64() / (l1 * l2)).abs();
    let sol = tally.inside(got, group, (near_edge, s), eps, what)?;
    Some((sol, c, s))
}

/// The point `from + x e + y perp(e)` of a link whose axis is the unit `e`,
/// with its velocity and acceleration for the link's `omega`, `alpha` (all
/// double-double).
fn on_link((p, v, acc): (V, V, V), e: V, (x, y): (f64, f64), omega: Dd, alpha: Dd) -> (V, V, V) {
    let r = refg::add(
        refg::scale(Dd::from(x), e),
        refg::scale(Dd::from(y), refg::perp(e)),
    );
    (
        refg::add(p, r),
        refg::add(v, refg::scale(omega, refg::perp(r))),
        refg::sub(
            refg::add(acc, refg::scale(alpha, refg::perp(r))),
            refg::scale(omega.sqr(), r),
        ),
    )
}

fn cv(v: V) -> CV2 {
    CV2 { x: v[0], y: v[1] }
}

/// Random loaded four-bars against `newton_euler` (the Newton-Euler
/// equations of the three bodies at once, in double-double, from the group
/// references' kinematics). Masses over six decades (1e-3 .. 1e3 kg, each
/// link its own), inertias `m l^2 / 100 .. m l^2 / 5`, centres of mass and
/// the loaded point anywhere near their links, the force and couple of the
/// size of the weights and inertia loads times 1e-2 .. 1e2.
///
/// Bound: the force solve is backward stable for the loads acting on each
/// group, and the inertia loads carry the accelerations' error, so each
/// reaction (and the drive torque over the crank's length) is within
/// `c eps (L / l_min) F / s^3`, `F` the largest force in the sample
/// (reactions, `m (a_max + g)`, `j alpha_max / l`, the applied force, the
/// couple and the drive over the shortest link), `s` the RRR's sine, with
/// `c` = [`FORCE_BOUND`].
fn run_quad_forces<T: Real>(samples: usize, seed: u64) -> Tally {
    let eps = T::eps().as_f64();
    let g = 9.81;
    draws(samples, seed, |rng, n, tally, sc| {
        let [gx, gy, a, b, c] = [
            length(rng, sc),
            length(rng, sc) * rng.uniform(-1.0, 1.0),
            length(rng, sc),
            length(rng, sc),
            length(rng, sc),
        ]
        .map(through::<T>);
        let mass = |rng: &mut Rng| through::<T>(10f64.powf(rng.uniform(-3.0, 3.0)));
        let frac = |rng: &mut Rng, l: f64| through::<T>(l * rng.uniform(-0.5, 1.5));
        let (m2, m3, m4) = (mass(rng), mass(rng), mass(rng));
        let (u2, u3, v3, u4, v4) = (
            frac(rng, a),
            frac(rng, b),
            frac(rng, b) * 0.5,
            frac(rng, c),
            frac(rng, c) * 0.5,
        );
        let inertia =
            |rng: &mut Rng, m: f64, l: f64| through::<T>(m * l * l * rng.uniform(0.01, 0.2));
        let (j2, j3, j4) = (
            inertia(rng, m2, a),
            inertia(rng, m3, b),
            inertia(rng, m4, c),
        );
        let (pu, pv) = (frac(rng, b), frac(rng, b) * 0.5);
        let (q, w, al) = drive::<T>(rng);
        // The applied loads' size: the weights and a crank-driven inertia
        // load (m |a_A|), times 1e-2 .. 1e2.
        let typical = (m2 + m3 + m4) * (g + a * (w * w + al.abs()));
        let load = |rng: &mut Rng| random_load::<T>(rng, typical);
        let (fx, fy, t4) = (load(rng), load(rng), load(rng) * c);
        let lit = |x: f64| T::lit(x);
        let m = QuadLoaded::<T> {
            gx: lit(gx),
            gy: lit(gy),
            a: lit(a),
            b: lit(b),
            c: lit(c),
            m2: lit(m2),
            u2: lit(u2),
            j2: lit(j2),
            m3: lit(m3),
            u3: lit(u3),
            v3: lit(v3),
            j3: lit(j3),
            m4: lit(m4),
            u4: lit(u4),
            v4: lit(v4),
            j4: lit(j4),
            pu: lit(pu),
            pv: lit(pv),
            fx: lit(fx),
            fy: lit(fy),
            t4: lit(t4),
        };
        let got = solve_at!(m, QuadLoadedInput, T, (q, w, al));
        let what = format!(
            "QuadLoaded {n}: a {a:e} b {b:e} c {c:e} masses {m2:e} {m3:e} {m4:e} theta {q}"
        );
        // The kinematics from the group references.
        let (o, qq) = (vd(0.0, 0.0), vd(gx, gy));
        let (pa, va, aa) = refg::crank(o, a, q, w, al);
        let Some(pb) = refg::rrr_position(pa, b, qq, c, true) else {
            tally.outside += 1;
            assert!(
                got.is_err(),
                "{what}: Ok where the reference does not assemble"
            );
            return;
        };
        let (r1, r2) = (refg::sub(pb, pa), refg::sub(pb, qq));
        let s = (refg::cross(r1, r2).to_f64() / (b * c)).abs();
        let Some((w3, w4)) = refg::rrr_rates(pa, qq, pb, va, vd(0.0, 0.0)) else {
            return;
        };
        let (a3, a4) =
            refg::rrr_accelerations(pa, qq, pb, aa, vd(0.0, 0.0), w3, w4).expect("accelerations");
        let size = [gx.abs(), gy.abs(), a, b, c]
            .into_iter()
            .fold(0.0, f64::max);
        let spread = size.max(norm(pa)).max(norm(pb)) / a.min(b).min(c);
        let sol = match got {
            Ok(sol) => sol,
            Err(e) => {
                // Only within the edges' band or at a toggle (as `run_quad`).
                assert!(
                    s <= 1e3 * eps || eps * spread / (s * s) > NO_DIGITS,
                    "{what}: the reference assembles (sine {s:e}) but: {e}"
                );
                tally.edge_errors += 1;
                return;
            }
        };
        tally.compared += 1;
        let unit = |x: V| refg::scale(Dd::ONE / refg::norm(x), x);
        let e2 = unit(refg::sub(pa, o));
        let (e3, e4) = (unit(r1), unit(r2));
        let w2 = Dd::from(w);
        let al2 = Dd::from(al);
        let g2 = on_link((o, vd(0.0, 0.0), vd(0.0, 0.0)), e2, (u2, 0.0), w2, al2);
        let g3 = on_link((pa, va, aa), e3, (u3, v3), w3, a3);
        let g4 = on_link((qq, vd(0.0, 0.0), vd(0.0, 0.0)), e4, (u4, v4), w4, a4);
        let pp = on_link((pa, va, aa), e3, (pu, pv), w3, a3);
        let vb = refg::add(va, refg::scale(w3, refg::perp(r1)));
        let ab = refg::sub(
            refg::add(aa, refg::scale(a3, refg::perp(r1))),
            refg::scale(w3.sqr(), r1),
        );
        // Points: 0 O, 1 Q, 2 A, 3 B, 4 G2, 5 G3, 6 G4, 7 P.
        let zero = vd(0.0, 0.0);
        let ps: Vec<CV2> = [o, qq, pa, pb, g2.0, g3.0, g4.0, pp.0].map(cv).to_vec();
        let vs: Vec<CV2> = [zero, zero, va, vb, g2.1, g3.1, g4.1, pp.1]
            .map(cv)
            .to_vec();
        let accs: Vec<CV2> = [zero, zero, aa, ab, g2.2, g3.2, g4.2, pp.2]
            .map(cv)
            .to_vec();
        let system = System {
            bodies: vec![
                Body::new(m2, 4, j2, Some((0, 2))),
                Body::new(m3, 5, j3, Some((2, 3))),
                Body::new(m4, 6, j4, Some((1, 3))),
            ],
            joints: vec![
                Joint::revolute(Link::Ground, Link::Body(0), 0),
                Joint::revolute(Link::Body(0), Link::Body(1), 2),
                Joint::revolute(Link::Ground, Link::Body(2), 1),
                Joint::revolute(Link::Body(1), Link::Body(2), 3),
            ],
            drivers: vec![Driver::Torque { body: 0 }],
            loads: vec![
                Load::Force {
                    body: 1,
                    at: 7,
                    force: CV2::new(fx, fy),
                },
                Load::Couple {
                    body: 2,
                    couple: Dd::from(t4),
                },
            ],
            gravity: CV2::new(0.0, -g),
        };
        let reference = reference_forces(&system, (&ps, &vs, &accs));
        let f = &sol.forces;
        let got_r = [
            f.r_ground_crank_link,
            f.r_crank_link_coupler,
            f.r_ground_rocker,
            f.r_coupler_rocker,
        ];
        let l_min = a.min(b).min(c);
        // An inertia load carries its acceleration's error, which is eps of
        // the largest acceleration in the mechanism (not of its own): each
        // body's scale is `m (a_max + g)` and `j alpha_max / l`.
        let a_max = [
            norm(aa),
            norm(ab),
            norm(g2.2),
            norm(g3.2),
            norm(g4.2),
            w3.sqr().to_f64() * b,
            w4.sqr().to_f64() * c,
        ]
        .into_iter()
        .fold(0.0, f64::max);
        let alpha_max = al.abs().max(a3.to_f64().abs()).max(a4.to_f64().abs());
        let loads = [
            m2 * (a_max + g),
            m3 * (a_max + g),
            m4 * (a_max + g),
            j2 * alpha_max / a,
            j3 * alpha_max / b,
            j4 * alpha_max / c,
            fx.hypot(fy),
            t4.abs() / l_min,
            reference.drives[0].to_f64().abs() / l_min,
        ];
        let drive = (f.drive_theta.as_f64() - reference.drives[0].to_f64()).abs() / a;
        let verdict = ForceVerdict {
            eps,
            spread,
            condition: s,
        };
        verdict.record(tally, (&reference, &got_r), drive, &loads, &[], &what);
    })
}

/// Enough samples that each run meets its edges (about a tenth of the poses
/// do not assemble) in a few seconds of a debug build.
const SAMPLES: usize = 20_000;

/// Prints a run at the edges; it must have met typed errors inside the
/// rounding band as well as poses on both sides of it.
fn edge_report(name: &str, t: &Tally) {
    println!(
        "{name}: {} compared ({} with rates of no digits), {} outside the assembly, {} typed errors at an edge; worst error / bound: position {:.2}, velocity {:.2}, acceleration {:.2}, angles {:.2}",
        t.compared, t.no_digits, t.outside, t.edge_errors, t.worst[0], t.worst[1], t.worst[2], t.worst[3]
    );
    // (In f32 most edge draws land within the rounding band.)
    assert!(t.compared > SAMPLES / 5, "{name}: {t:?}");
    assert!(
        t.edge_errors > 0,
        "{name}: no typed error at an edge: {t:?}"
    );
    assert!(
        t.outside + t.edge_errors > SAMPLES / 20,
        "{name}: few poses beyond the edge: {t:?}"
    );
}

/// Prints a run of random designs; it must have compared many samples and,
/// where the group has an edge of assembly (`meets_edges`: all but the PRP,
/// whose joint only runs off to infinity), met poses beyond it.
fn report(name: &str, t: &Tally) {
    report_run(name, t, true);
}

fn report_run(name: &str, t: &Tally, meets_edges: bool) {
    println!(
        "{name}: {} compared ({} with rates of no digits), {} outside the assembly, {} typed errors at an edge; worst error / bound: position {:.2}, velocity {:.2}, acceleration {:.2}, angles {:.2}",
        t.compared, t.no_digits, t.outside, t.edge_errors, t.worst[0], t.worst[1], t.worst[2], t.worst[3]
    );
    // (About 70 % of random six-bars do not assemble.)
    assert!(t.compared > SAMPLES / 4, "{name}: {t:?}");
    if meets_edges {
        assert!(t.outside > 0, "{name}: no pose outside the assembly: {t:?}");
    }
}

#[test]
fn random_four_bars_f64() {
    report("Quad f64", &run_quad::<f64>(SAMPLES, 1, Draw::Free));
}

#[test]
fn random_four_bars_f32() {
    report("Quad f32", &run_quad::<f32>(SAMPLES, 2, Draw::Free));
}

#[test]
fn random_slider_cranks_f64() {
    report("Slide f64", &run_slide::<f64>(SAMPLES, 3, Draw::Free));
}

#[test]
fn random_slider_cranks_f32() {
    report("Slide f32", &run_slide::<f32>(SAMPLES, 4, Draw::Free));
}

#[test]
fn four_bars_at_the_edges_f64() {
    edge_report("Quad edge f64", &run_quad::<f64>(SAMPLES, 5, Draw::Edge));
}

#[test]
fn four_bars_at_the_edges_f32() {
    edge_report("Quad edge f32", &run_quad::<f32>(SAMPLES, 6, Draw::Edge));
}

#[test]
fn slider_cranks_at_tangency_f64() {
    edge_report("Slide edge f64", &run_slide::<f64>(SAMPLES, 7, Draw::Edge));
}

#[test]
fn slider_cranks_at_tangency_f32() {
    edge_report("Slide edge f32", &run_slide::<f32>(SAMPLES, 8, Draw::Edge));
}

#[test]
fn random_swinging_blocks_f64() {
    report("Swing f64", &run_swing::<f64>(SAMPLES, 9, Draw::Free));
}

#[test]
fn random_swinging_blocks_f32() {
    report("Swing f32", &run_swing::<f32>(SAMPLES, 10, Draw::Free));
}

#[test]
fn swinging_blocks_at_the_edge_f64() {
    edge_report("Swing edge f64", &run_swing::<f64>(SAMPLES, 11, Draw::Edge));
}

#[test]
fn swinging_blocks_at_the_edge_f32() {
    edge_report("Swing edge f32", &run_swing::<f32>(SAMPLES, 12, Draw::Edge));
}

/// Prints a forces run (its worst ratio is in the position slot).
fn forces_report(name: &str, t: &Tally) {
    println!(
        "{name}: {} compared ({} with no digits), {} outside the assembly, {} typed errors; worst reaction or drive error / bound {:.2}",
        t.compared, t.no_digits, t.outside, t.edge_errors, t.worst[0]
    );
    assert!(t.compared > FORCE_SAMPLES / 3, "{name}: {t:?}");
}

/// The force bound's constant: the accelerations within [`BOUND`] (8) feed
/// the inertia loads, each at most `m` times eps of the largest acceleration
/// `a_max` (hence the scale `m (a_max + g)`), and the groups' force systems
/// round once more (the solve's `4 eps / condition` of `docs/stability.md`):
/// 12. Measured: at most 7.7 over 100 000 assembled samples per run
/// (`FORCE_SAMPLES = 200_000`, release; four-bars and slider-cranks, f64 and
/// f32). With each inertia load scaled by its own acceleration instead of
/// `a_max`, a heavy block on a light rod measured 58.
const FORCE_BOUND: f64 = 12.0;

#[test]
fn random_crossing_guides_f64() {
    report_run(
        "Cross f64",
        &run_cross::<f64>(SAMPLES, 15, Draw::Free),
        false,
    );
}

#[test]
fn random_crossing_guides_f32() {
    report_run(
        "Cross f32",
        &run_cross::<f32>(SAMPLES, 16, Draw::Free),
        false,
    );
}

#[test]
fn crossing_guides_near_parallel_f64() {
    edge_report("Cross edge f64", &run_cross::<f64>(SAMPLES, 17, Draw::Edge));
}

#[test]
fn crossing_guides_near_parallel_f32() {
    edge_report("Cross edge f32", &run_cross::<f32>(SAMPLES, 18, Draw::Edge));
}

#[test]
fn random_yokes_f64() {
    report_run("Yoke f64", &run_yoke::<f64>(SAMPLES, 19, Draw::Free), false);
}

#[test]
fn random_yokes_f32() {
    report_run("Yoke f32", &run_yoke::<f32>(SAMPLES, 20, Draw::Free), false);
}

#[test]
fn yokes_with_the_slot_near_the_guide_f64() {
    edge_report("Yoke edge f64", &run_yoke::<f64>(SAMPLES, 21, Draw::Edge));
}

#[test]
fn yokes_with_the_slot_near_the_guide_f32() {
    edge_report("Yoke edge f32", &run_yoke::<f32>(SAMPLES, 22, Draw::Edge));
}

#[test]
fn random_booms_f64() {
    report("Boom f64", &run_boom::<f64>(SAMPLES, 23, Draw::Free));
}

#[test]
fn random_booms_f32() {
    report("Boom f32", &run_boom::<f32>(SAMPLES, 24, Draw::Free));
}

#[test]
fn booms_at_the_edges_f64() {
    edge_report("Boom edge f64", &run_boom::<f64>(SAMPLES, 25, Draw::Edge));
}

#[test]
fn booms_at_the_edges_f32() {
    edge_report("Boom edge f32", &run_boom::<f32>(SAMPLES, 26, Draw::Edge));
}

#[test]
fn random_six_bars_f64() {
    report_run("Six f64", &run_six::<f64>(SAMPLES, 27), true);
}

#[test]
fn random_six_bars_f32() {
    report_run("Six f32", &run_six::<f32>(SAMPLES, 28), true);
}

/// Random loaded slider-cranks against `newton_euler`, as
/// [`run_quad_forces`]: the pin reactions, the guide's prismatic reaction
/// (its normal force, and its couple about the pin `B` over the rod's
/// length) and the drive torque over the crank's length, within
/// `c eps (L / l) F / s^3` (`s` the RRP's condition, `l` the rod).
fn run_slide_forces<T: Real>(samples: usize, seed: u64) -> Tally {
    let eps = T::eps().as_f64();
    let g = 9.81;
    draws(samples, seed, |rng, n, tally, sc| {
        let a = through::<T>(length(rng, sc));
        let l = through::<T>(length(rng, sc));
        let e = coordinate::<T>(rng, sc);
        let tilt = through::<T>(rng.uniform(-3.2, 3.2));
        let mass = |rng: &mut Rng| through::<T>(10f64.powf(rng.uniform(-3.0, 3.0)));
        let (m2, m3, m4) = (mass(rng), mass(rng), mass(rng));
        let (u2, u3) = (
            through::<T>(a * rng.uniform(-0.5, 1.5)),
            through::<T>(l * rng.uniform(-0.5, 1.5)),
        );
        let v3 = through::<T>(l * rng.uniform(-0.25, 0.25));
        let j2 = through::<T>(m2 * a * a * rng.uniform(0.01, 0.2));
        let j3 = through::<T>(m3 * l * l * rng.uniform(0.01, 0.2));
        let (q, w, al) = drive::<T>(rng);
        let typical = (m2 + m3 + m4) * (g + a * (w * w + al.abs()));
        let load = |rng: &mut Rng| random_load::<T>(rng, typical);
        let (fx, fy, fs) = (load(rng), load(rng), load(rng));
        let lit = |x: f64| T::lit(x);
        let m = SlideLoaded::<T> {
            a: lit(a),
            l: lit(l),
            e: lit(e),
            tilt: lit(tilt),
            m2: lit(m2),
            u2: lit(u2),
            j2: lit(j2),
            m3: lit(m3),
            u3: lit(u3),
            v3: lit(v3),
            j3: lit(j3),
            m4: lit(m4),
            fx: lit(fx),
            fy: lit(fy),
            fs: lit(fs),
        };
        let got = solve_at!(m, SlideLoadedInput, T, (q, w, al));
        let what = format!("SlideLoaded {n}: a {a:e} l {l:e} e {e:e} tilt {tilt} masses {m2:e} {m3:e} {m4:e} theta {q}");
        // The guide exactly at the direction the generated code rounds to
        // (as `run_slide`).
        let (st, ct) = T::lit(tilt).sin_cos_kernel();
        let line = refg::Line::new([0.0, e], [ct.as_f64(), st.as_f64()]);
        let o = vd(0.0, 0.0);
        let (pa, va, aa) = refg::crank(o, a, q, w, al);
        let Some((pb, _)) = refg::rrp_position(pa, l, &line, 0.0, true) else {
            tally.outside += 1;
            assert!(
                got.is_err(),
                "{what}: Ok where the reference does not assemble"
            );
            return;
        };
        let r1 = refg::sub(pb, pa);
        let s = (refg::dot(r1, line.dir).to_f64() / l).abs();
        let size = [a, l, e.abs()].into_iter().fold(0.0, f64::max);
        let spread = size.max(norm(pa)).max(norm(pb)) / a.min(l);
        let Ok(sol) = got else {
            tally.edge_errors += 1;
            assert!(
                eps * spread / (s * s * s) > NO_DIGITS,
                "{what}: the reference assembles (condition {s:e}) but the solve failed"
            );
            return;
        };
        tally.compared += 1;
        let (w3, sd) = refg::rrp_rates(pa, pb, &line, va).expect("rates");
        let (a3, sdd) = refg::rrp_accelerations(pa, pb, &line, aa, w3).expect("accelerations");
        let unit = |x: V| refg::scale(Dd::ONE / refg::norm(x), x);
        let (e2, e3) = (unit(refg::sub(pa, o)), unit(r1));
        let zero = vd(0.0, 0.0);
        let g2 = on_link((o, zero, zero), e2, (u2, 0.0), Dd::from(w), Dd::from(al));
        let g3 = on_link((pa, va, aa), e3, (u3, v3), w3, a3);
        let (vb, ab) = (refg::scale(sd, line.dir), refg::scale(sdd, line.dir));
        // Points: 0 O, 1 A, 2 B, 3 G2, 4 G3.
        let ps: Vec<CV2> = [o, pa, pb, g2.0, g3.0].map(cv).to_vec();
        let vs: Vec<CV2> = [zero, va, vb, g2.1, g3.1].map(cv).to_vec();
        let accs: Vec<CV2> = [zero, aa, ab, g2.2, g3.2].map(cv).to_vec();
        let dir = cv(line.dir);
        let system = System {
            bodies: vec![
                Body::new(m2, 3, j2, Some((0, 1))),
                Body::new(m3, 4, j3, Some((1, 2))),
                Body::new(m4, 2, 0.0, None),
            ],
            joints: vec![
                Joint::revolute(Link::Ground, Link::Body(0), 0),
                Joint::revolute(Link::Body(0), Link::Body(1), 1),
                Joint::revolute(Link::Body(1), Link::Body(2), 2),
                Joint::prismatic(Link::Ground, Link::Body(2), Direction::Fixed(dir), 2),
            ],
            drivers: vec![Driver::Torque { body: 0 }],
            loads: vec![
                Load::Force {
                    body: 1,
                    at: 4,
                    force: CV2::new(fx, fy),
                },
                Load::Force {
                    body: 2,
                    at: 2,
                    force: CV2 {
                        x: line.dir[0] * Dd::from(fs),
                        y: line.dir[1] * Dd::from(fs),
                    },
                },
            ],
            gravity: CV2::new(0.0, -g),
        };
        let reference = reference_forces(&system, (&ps, &vs, &accs));
        let f = &sol.forces;
        let pins = [f.r_ground_crank_link, f.r_crank_link_rod, f.r_rod_block];
        let guide = &f.r_ground_block;
        // Each body's inertia scale as in `run_quad_forces`.
        let a_max = [
            norm(aa),
            norm(ab),
            norm(g2.2),
            norm(g3.2),
            w3.sqr().to_f64() * l,
        ]
        .into_iter()
        .fold(0.0, f64::max);
        let alpha_max = al.abs().max(a3.to_f64().abs());
        let loads = [
            m2 * (a_max + g),
            m3 * (a_max + g),
            m4 * (a_max + g),
            j2 * alpha_max / a,
            j3 * alpha_max / l,
            fx.hypot(fy),
            fs.abs(),
            reference.drives[0].to_f64().abs() / a.min(l),
        ];
        let drive = (f.drive_theta.as_f64() - reference.drives[0].to_f64()).abs() / a;
        // The guide's normal force and its couple over the rod's length.
        let guide = prismatic_errors(guide, &reference.reactions[3], l, &what);
        let verdict = ForceVerdict {
            eps,
            spread,
            condition: s,
        };
        verdict.record(tally, (&reference, &pins), drive, &loads, &guide, &what);
    })
}

/// A generated prismatic reaction against the reference's: the errors and
/// sizes `(|error|, |reference|)` of the normal force (N) and of the couple
/// over `length` (N m / m: a force, so that both compare with the force
/// bound), as `ForceVerdict::record` takes them. Panics (naming `what`) if
/// the reference's reaction at that joint is not prismatic.
fn prismatic_errors<T: Real>(
    got: &mechanism::force::PrismaticReaction<T>,
    reference: &Reaction,
    length: f64,
    what: &str,
) -> [(f64, f64); 2] {
    let Reaction::Prismatic { normal, moment, .. } = *reference else {
        panic!("{what}: a guide's reaction is prismatic");
    };
    [
        (
            (got.normal.as_f64() - normal.to_f64()).abs(),
            normal.to_f64().abs(),
        ),
        (
            (got.moment.as_f64() - moment.to_f64()).abs() / length,
            moment.to_f64().abs() / length,
        ),
    ]
}

/// The reference's reactions and driving efforts of `system` at the points'
/// positions, velocities and accelerations `(p, v, a)` (indices as the
/// system's `PointId`s); panics if the reference refuses (its own
/// consistency check), which no draw may make it do.
fn reference_forces(system: &System, (p, v, a): (&[CV2], &[CV2], &[CV2])) -> Solution {
    solve_forces(system, &State { p, v, a }).expect("reference forces")
}

/// What a loaded run's errors are measured against: `eps`, the sample's
/// spread (largest coordinate over the shortest link) and the group's
/// condition.
struct ForceVerdict {
    eps: f64,
    spread: f64,
    condition: f64,
}

impl ForceVerdict {
    /// Records the worst of the pin reactions (the reference's first
    /// `pins.len()`, as forces), the drive's error `drive` (already over the
    /// crank's length) and the `extra` (error, scale) pairs against
    /// [`FORCE_BOUND`] `eps spread F / condition^3`, `F` the largest of
    /// `loads`, the reference's pin forces and the extra scales.
    fn record<T: Real>(
        &self,
        tally: &mut Tally,
        (reference, pins): (&Solution, &[Vector2<T>]),
        drive: f64,
        loads: &[f64],
        extra: &[(f64, f64)],
        what: &str,
    ) {
        let k3 = self.condition.powi(3);
        if self.eps * self.spread / k3 > NO_DIGITS {
            tally.no_digits += 1;
            return;
        }
        let mut scale = loads.iter().fold(0.0f64, |m, x| m.max(*x));
        let mut err = drive;
        for (r, got) in reference.reactions.iter().zip(pins) {
            let rf = r.force();
            scale = scale.max(norm([rf.x, rf.y]));
            err = err.max(dist((got.x.as_f64(), got.y.as_f64()), [rf.x, rf.y]));
        }
        for &(e, sc) in extra {
            err = err.max(e);
            scale = scale.max(sc);
        }
        tally.record(
            0,
            err / (self.eps * self.spread * scale / k3),
            FORCE_BOUND,
            "reaction or drive",
            &format!(
                "{what} condition {:e} spread {:e}",
                self.condition, self.spread
            ),
        );
    }
}

/// Fewer samples than the kinematics: each reference force solve assembles
/// and eliminates a 9 x 9 double-double system.
const FORCE_SAMPLES: usize = 4_000;

#[test]
fn random_loaded_four_bars_f64() {
    forces_report("QuadLoaded f64", &run_quad_forces::<f64>(FORCE_SAMPLES, 13));
}

#[test]
fn random_loaded_four_bars_f32() {
    forces_report("QuadLoaded f32", &run_quad_forces::<f32>(FORCE_SAMPLES, 14));
}

#[test]
fn random_loaded_slider_cranks_f64() {
    forces_report(
        "SlideLoaded f64",
        &run_slide_forces::<f64>(FORCE_SAMPLES, 29),
    );
}

#[test]
fn random_loaded_slider_cranks_f32() {
    forces_report(
        "SlideLoaded f32",
        &run_slide_forces::<f32>(FORCE_SAMPLES, 30),
    );
}

// The loaded designs of the other groups (after `solve_at!`, which they use).
mod boom_forces;
mod cross_forces;
mod swing_forces;
mod yoke_forces;
