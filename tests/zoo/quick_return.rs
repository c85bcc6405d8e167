//! The Whitworth quick return against the double-double reference
//! (`loop_closure`, `newton_euler`) and closed forms written here: a ram,
//! masses on every link, gravity, a cutting force; forces over a full turn,
//! the stroke and the time ratio of its strokes against their closed forms;
//! the same mechanism with masses from 1e-6 to 1e6 kg on its links, and with
//! every length times 1e-6 and times 1e6.
//!
//! Every figure is printed with `cargo test --test zoo quick_return --
//! --nocapture` as the measured worst error over its bound (1 = at the
//! bound).

use super::dd_reference::*;
use mechanism::{mechanism, Error, Real};
use mechanism_reference::constraint::{Constraint, Linkage, Point, Side, V2};
use mechanism_reference::loop_closure;
use mechanism_reference::newton_euler::{Body, Direction, Driver, Joint, Link, Load, System};

use Link::{Body as Bd, Ground};

// ---------------------------------------------------------------------------
// The Whitworth quick return; its extreme masses and scales.

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
