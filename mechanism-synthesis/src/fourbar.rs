//! Path generation by a four-bar, the benchmark problem of the literature:
//! ground pivot `O2 = (x0, y0)`, ground link `r1` at angle `theta0`, crank `r2`
//! at angle `th2` from the ground link, coupler `r3`, rocker `r4`, the coupler
//! point at `(rcx, rcy)` in the frame of `A -> B`; the objective is the sum over
//! the targets of the squared distance from the coupler point.
//!
//! The mechanism is the `mechanism!` definition [`FourBarPath`], evaluated on
//! `f64` for the objective and on dual numbers for the exact Jacobian, in the
//! assembly mode of the problem (a run-time parameter).
//!
//! Design variables (`x`): `r1, t, r3, r4, rcx, rcy`, then `theta0, x0, y0`
//! when the frame is free, then `v_0 .. v_n` when the timing is free.
//! Constraints hold by construction:
//! - Grashof crank-rocker with the crank shortest: `r2 <= r1, r3, r4` and
//!   `r2 + l <= p + q` are six linear bounds `r2 <= f_i(r1, r3, r4)` (each has
//!   `r2` with coefficient 1), so `r2 = lo + t (m - lo)` with
//!   `m = min(r1, r3, r4, r3 + r4 - r1, r1 + r4 - r3, r1 + r3 - r4)` and
//!   `t` in `[0, 1]` spans exactly the feasible crank lengths; `t = 1` is the
//!   change-point boundary `s + l = p + q` or `r2` equal to another link. One
//!   residual, `W (lo - m)` when `m < lo` (zero otherwise), keeps `r1, r3, r4`
//!   a triangle long enough for a crank of at least `lo`.
//! - Free crank angles ascending in `[0, 2 pi]`: the `n + 1` gaps before,
//!   between and after them are `2 pi v_j^2 / sum v^2`, so
//!   `th_k = 2 pi (v_0^2 + .. + v_(k-1)^2) / sum v^2`.
//!
//! A crank-rocker turns fully, so the whole sweep assembles on the chosen mode.

use std::f64::consts::TAU;

use mechanism::{mechanism, Mode, Real};

use crate::problem::Problem;
use crate::rng::Rng;

mechanism! {
    /// The path-generating four-bar of the synthesis benchmarks (lengths in the
    /// targets' units): `O2 = (x0, y0)`, `O4` at `r1` from it at angle
    /// `theta0`, crank `r2` at absolute angle `phi` (= `theta0 + th2`),
    /// coupler `r3`, rocker `r4`, coupler point `P` at `(rcx, rcy)` in the
    /// frame of `A -> B`; `circuit` the assembly mode.
    pub FourBarPath {
        params {
            r1 = 4.0, r2 = 1.0, r3 = 3.0, r4 = 3.5, rcx = 1.5, rcy = 1.0,
            theta0 = 0.0, x0 = 0.0, y0 = 0.0, circuit = left
        }
        analysis position;
        let O2 = ground(x0, y0);
        let O4 = ground(x0 + r1 * cos(theta0), y0 + r1 * sin(theta0));
        let A = crank(O2, r2, phi) as crank;
        let B = rrr(A, r3, O4, r4, circuit) as (coupler, rocker);
        let P = point(coupler, from A, (rcx, rcy));
    }
}

/// Gap between free crank angles (rad) below which [`Problem::snap`] tries
/// the gap closed: 1e-3 rad moves a coupler point of the benchmark cases by
/// a few hundredths of a percent of its path, well inside a local solve's
/// reach, and no optimum found on the cases has a gap between 1e-9 and 1e-3.
const SNAP_GAP: f64 = 1e-3;

/// Most small gaps whose closings [`Problem::faces`] combines (`2^3 - 1 = 7`
/// designs to polish at most).
const SNAP_MOST: usize = 3;

/// Weight of the triangle residual (per unit length of violation): large
/// against the path residuals, so a start that violates it is pulled back first.
const TRIANGLE_WEIGHT: f64 = 1e3;

/// Weight of the transmission angle residuals (per unit of cosine past the
/// bound): a violation of `1e-3` in the cosine costs as much as a path error
/// of one unit.
const TRANSMISSION_WEIGHT: f64 = 1e3;

/// A physical design: `[r1, r2, r3, r4, rcx, rcy, theta0, x0, y0, th2_1 ..]`
/// (lengths in the targets' units, angles in radians).
#[derive(Clone, Debug, PartialEq)]
pub struct Design(pub Vec<f64>);

/// The word of the definition's `circuit` for an assembly mode: `left` for
/// [`Mode::Plus`], `right` for [`Mode::Minus`].
pub fn circuit_word(mode: Mode) -> &'static str {
    match mode {
        Mode::Plus => "left",
        Mode::Minus => "right",
    }
}

impl Design {
    /// The names of a design's first nine numbers, in order.
    pub const NAMES: [&'static str; 9] =
        ["r1", "r2", "r3", "r4", "rcx", "rcy", "theta0", "x0", "y0"];

    /// The four-bar of this design in assembly mode `mode`.
    pub fn mechanism(&self, mode: Mode) -> FourBarPath<f64> {
        let d = &self.0;
        FourBarPath {
            r1: d[0],
            r2: d[1],
            r3: d[2],
            r4: d[3],
            rcx: d[4],
            rcy: d[5],
            theta0: d[6],
            x0: d[7],
            y0: d[8],
            circuit: mode,
        }
    }
    /// The crank angles from the ground link (rad).
    pub fn angles(&self) -> &[f64] {
        &self.0[9..]
    }

    /// The text of [`FourBarPath`] with this design's parameters and the
    /// circuit `mode` (`left` for [`Mode::Plus`]), for what reads a
    /// definition at run time (`mechanism table`, the Python package): the
    /// same statements as the macro's input above, each number written so
    /// that it reads back to the same `f64` (Rust's shortest round-trip
    /// form). Its input `phi` is the crank's absolute angle, `theta0` plus
    /// the angle from the ground link.
    pub fn definition(&self, mode: Mode) -> String {
        let d = &self.0;
        let circuit = circuit_word(mode);
        format!(
            "pub FourBarPath {{\n    \
             params {{\n        \
             r1 = {:?}, r2 = {:?}, r3 = {:?}, r4 = {:?}, rcx = {:?}, rcy = {:?},\n        \
             theta0 = {:?}, x0 = {:?}, y0 = {:?}, circuit = {circuit}\n    \
             }}\n    \
             let O2 = ground(x0, y0);\n    \
             let O4 = ground(x0 + r1 * cos(theta0), y0 + r1 * sin(theta0));\n    \
             let A = crank(O2, r2, phi) as crank;\n    \
             let B = rrr(A, r3, O4, r4, circuit) as (coupler, rocker);\n    \
             let P = point(coupler, from A, (rcx, rcy));\n\
             }}\n",
            d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7], d[8]
        )
    }
}

/// When the crank reaches the targets.
#[derive(Clone, Debug)]
pub enum Timing {
    /// Prescribed crank angles from the ground link (rad), one per target.
    Prescribed(Vec<f64>),
    /// Free: ascending in `[0, 2 pi]`, design variables.
    Free,
}

/// A path-generation problem for [`FourBarPath`].
#[derive(Clone, Debug)]
pub struct PathProblem {
    /// Target points `(x, y)`.
    pub targets: Vec<[f64; 2]>,
    /// Prescribed or free crank angles.
    pub timing: Timing,
    /// `Some((theta0, x0, y0))` when the frame placement is fixed.
    pub frame: Option<[f64; 3]>,
    /// Bounds of `r1 .. r4`.
    pub links: (f64, f64),
    /// Bounds of `rcx, rcy` (and `x0, y0` when free).
    pub coords: (f64, f64),
    /// The assembly mode.
    pub mode: Mode,
    /// Motion generation: the coupler's target angle at each target (rad,
    /// the direction of `A -> B` from +x) and the length that weighs an
    /// angle error against a distance (see [`PathProblem::with_orientations`]).
    pub orientations: Option<(Vec<f64>, f64)>,
    /// The least transmission angle allowed (rad, in `(0, pi/2)`; see
    /// [`PathProblem::with_transmission`]).
    pub transmission: Option<f64>,
    lo: Vec<f64>,
    hi: Vec<f64>,
}

impl PathProblem {
    /// A problem; `links` bounds `r1 .. r4`, `coords` bounds `rcx, rcy, x0, y0`.
    pub fn new(
        targets: Vec<[f64; 2]>,
        timing: Timing,
        frame: Option<[f64; 3]>,
        links: (f64, f64),
        coords: (f64, f64),
        mode: Mode,
    ) -> Self {
        let mut lo = vec![links.0, 0.0, links.0, links.0, coords.0, coords.0];
        let mut hi = vec![links.1, 1.0, links.1, links.1, coords.1, coords.1];
        if frame.is_none() {
            lo.extend([f64::NEG_INFINITY, coords.0, coords.0]);
            hi.extend([f64::INFINITY, coords.1, coords.1]);
        }
        if matches!(timing, Timing::Free) {
            lo.extend(std::iter::repeat_n(f64::NEG_INFINITY, targets.len() + 1));
            hi.extend(std::iter::repeat_n(f64::INFINITY, targets.len() + 1));
        }
        PathProblem {
            targets,
            timing,
            frame,
            links,
            coords,
            mode,
            orientations: None,
            transmission: None,
            lo,
            hi,
        }
    }

    /// Motion generation: the coupler link also turns to `angles` (rad, the
    /// direction of `A -> B` from +x, one per target). Each target adds two
    /// residuals, `scale (cos a - cos a_t)` and `scale (sin a - sin a_t)`:
    /// the chord between the two directions on a circle of radius `scale`
    /// (a length in the targets' units), so an angle error `e` weighs as a
    /// distance of about `scale e`, with no jump at the wrap of the angle.
    pub fn with_orientations(mut self, angles: Vec<f64>, scale: f64) -> Self {
        self.orientations = Some((angles, scale));
        self
    }

    /// Transmission angle bounds: the angle between coupler and rocker stays
    /// in `[mu_min, pi - mu_min]` (rad) over the whole turn. For a
    /// crank-rocker its extremes are at crank angles 0 and pi (the diagonal
    /// `A -> O4` shortest and longest), where `cos mu = (r3^2 + r4^2 -
    /// (r1 -+ r2)^2) / (2 r3 r4)`; two residuals, each `W` times how far that
    /// cosine passes `+-cos mu_min` (zero inside), hold them: a penalty, so
    /// a design at the bound may pass it by a few `1e-6` in the cosine (the
    /// path residuals' pull over `W`'s weight).
    pub fn with_transmission(mut self, mu_min: f64) -> Self {
        self.transmission = Some(mu_min);
        self
    }

    /// The transmission angle's cosine at crank angles 0 and pi of the
    /// physical parameters `[r1, r2, r3, r4, ..]`.
    pub fn transmission_cosines<T: Real>(p: &[T]) -> [T; 2] {
        let (r1, r2, r3, r4) = (p[0], p[1], p[2], p[3]);
        let two = T::lit(2.0) * r3 * r4;
        let base = r3 * r3 + r4 * r4;
        let (d0, dpi) = (r1 - r2, r1 + r2);
        [(base - d0 * d0) / two, (base - dpi * dpi) / two]
    }

    /// Index of the first angle variable `v_0` (free timing).
    fn angle_base(&self) -> usize {
        if self.frame.is_none() {
            9
        } else {
            6
        }
    }

    /// `m`: the largest crank the Grashof crank-rocker bounds allow.
    fn crank_limit<T: Real>(r1: T, r3: T, r4: T) -> T {
        let m = r1.min(r3).min(r4);
        m.min(r3 + r4 - r1).min(r1 + r4 - r3).min(r1 + r3 - r4)
    }

    /// The physical parameters `[r1, r2, r3, r4, rcx, rcy, theta0, x0, y0]`
    /// and the crank angles of design `x`, and the triangle residual.
    fn physical<T: Real>(&self, x: &[T], th: &mut [T]) -> ([T; 9], T) {
        let lo = T::lit(self.links.0);
        let m = Self::crank_limit(x[0], x[2], x[3]);
        let r2 = lo + x[1] * (m - lo);
        let tri = if m < lo {
            T::lit(TRIANGLE_WEIGHT) * (lo - m)
        } else {
            T::zero()
        };
        let (t0, x0, y0) = match self.frame {
            Some(f) => (T::lit(f[0]), T::lit(f[1]), T::lit(f[2])),
            None => (x[6], x[7], x[8]),
        };
        match &self.timing {
            Timing::Prescribed(a) => {
                for (t, v) in th.iter_mut().zip(a) {
                    *t = T::lit(*v);
                }
            }
            Timing::Free => {
                let v = &x[self.angle_base()..];
                let total = v.iter().fold(T::zero(), |s, w| s + *w * *w);
                let mut acc = T::zero();
                for (k, t) in th.iter_mut().enumerate() {
                    acc += v[k] * v[k];
                    *t = T::lit(TAU) * acc / total;
                }
            }
        }
        ([x[0], r2, x[2], x[3], x[4], x[5], t0, x0, y0], tri)
    }

    /// The physical design of variables `x`.
    pub fn design(&self, x: &[f64]) -> Design {
        let mut th = vec![0.0; self.targets.len()];
        let (p, _) = self.physical(x, &mut th);
        let mut d = p.to_vec();
        d.extend(th);
        Design(d)
    }

    /// The coupler point at crank angle `th2` from the ground link.
    pub fn coupler<T: Real>(fb: &FourBarPath<T>, th2: T) -> Option<[T; 2]> {
        let pos = fb
            .position(&FourBarPathInput {
                phi: fb.theta0 + th2,
            })
            .ok()?;
        Some([pos.P.x, pos.P.y])
    }

    /// The coupler point and the unit direction of `A -> B` at crank angle
    /// `th2` from the ground link.
    pub fn coupler_pose<T: Real>(fb: &FourBarPath<T>, th2: T) -> Option<([T; 2], [T; 2])> {
        let pos = fb
            .position(&FourBarPathInput {
                phi: fb.theta0 + th2,
            })
            .ok()?;
        let (u, v) = ((pos.B.x - pos.A.x) / fb.r3, (pos.B.y - pos.A.y) / fb.r3);
        Some(([pos.P.x, pos.P.y], [u, v]))
    }

    /// A start: a random shape (links, coupler point), placed on the targets
    /// by the similarity (rotation, scale, translation) that best maps its
    /// points to them, with free crank angles from the ordered nearest
    /// assignment on the sampled coupler curve ([`assign`]); two rounds.
    pub fn sample(&self, rng: &mut Rng, x: &mut [f64]) {
        let (l0, l1) = self.links;
        let (c0, c1) = self.coords;
        for _ in 0..100 {
            x[0] = rng.range(l0, l1);
            x[2] = rng.range(l0, l1);
            x[3] = rng.range(l0, l1);
            if Self::crank_limit(x[0], x[2], x[3]) > l0 {
                break;
            }
        }
        // The optima of the benchmarks lie on faces of the box (a crank at its
        // Grashof limit, a coupler point at its bound): a fifth of the draws
        // start there.
        x[1] = if rng.unit() < 0.2 { 1.0 } else { rng.unit() };
        for j in [4, 5] {
            x[j] = match rng.index(10) {
                0 => c0,
                1 => c1,
                _ => rng.range(c0, c1),
            };
        }
        if self.frame.is_none() {
            x[6] = rng.range(0.0, TAU);
            x[7] = 0.0;
            x[8] = 0.0;
        }
        if matches!(self.timing, Timing::Free) {
            let b = self.angle_base();
            for v in &mut x[b..] {
                *v = 1.0;
            }
        }
        if self.frame.is_some() {
            return;
        }
        for _ in 0..2 {
            if matches!(self.timing, Timing::Free) && !self.assign_angles(x) {
                return;
            }
            if !self.place(x) {
                return;
            }
        }
        if matches!(self.timing, Timing::Free) {
            self.assign_angles(x);
        }
    }

    /// Sets the free angle variables of `x` from [`assign`] on 121 samples.
    fn assign_angles(&self, x: &mut [f64]) -> bool {
        self.assign_angles_on(x, 120)
    }

    /// Sets the free angle variables of `x` from [`assign`] on `samples + 1`
    /// samples of the coupler curve (a crank step of `2 pi / samples`).
    fn assign_angles_on(&self, x: &mut [f64], samples: usize) -> bool {
        let d = self.design(x);
        let fb = d.mechanism(self.mode);
        let mut curve = Vec::with_capacity(samples + 1);
        for k in 0..=samples {
            match Self::coupler(&fb, TAU * k as f64 / samples as f64) {
                Some(p) => curve.push(p),
                None => return false,
            }
        }
        let idx = assign(&curve, &self.targets);
        let th: Vec<f64> = idx
            .iter()
            .map(|&i| TAU * i as f64 / samples as f64)
            .collect();
        let b = self.angle_base();
        let n = th.len();
        // Gaps floored at a degree: a zero gap has a zero derivative in v.
        let gap = |a: f64, b: f64| ((b - a) / TAU).max(1.0 / 360.0).sqrt();
        x[b] = gap(0.0, th[0]);
        for k in 1..n {
            x[b + k] = gap(th[k - 1], th[k]);
        }
        x[b + n] = gap(th[n - 1], TAU);
        true
    }

    /// Moves the frame and scales the lengths of `x` by the similarity that
    /// best maps the coupler points at the design's angles to the targets
    /// (Umeyama 1991, in the plane), the scale kept within the bounds.
    fn place(&self, x: &mut [f64]) -> bool {
        let d = self.design(x);
        let fb = d.mechanism(self.mode);
        let mut pts = Vec::with_capacity(self.targets.len());
        for &th in d.angles() {
            match Self::coupler(&fb, th) {
                Some(p) => pts.push(p),
                None => return false,
            }
        }
        let n = pts.len() as f64;
        let mean = |v: &[[f64; 2]]| {
            let s = v.iter().fold([0.0, 0.0], |a, p| [a[0] + p[0], a[1] + p[1]]);
            [s[0] / n, s[1] / n]
        };
        let (mp, mt) = (mean(&pts), mean(&self.targets));
        let (mut sxx, mut sxy, mut var) = (0.0, 0.0, 0.0);
        for (p, t) in pts.iter().zip(&self.targets) {
            let (px, py) = (p[0] - mp[0], p[1] - mp[1]);
            let (tx, ty) = (t[0] - mt[0], t[1] - mt[1]);
            sxx += px * tx + py * ty;
            sxy += px * ty - py * tx;
            var += px * px + py * py;
        }
        let alpha = sxy.atan2(sxx);
        let mut s = if var > 0.0 { sxx.hypot(sxy) / var } else { 1.0 };
        let longest = x[0].max(x[2]).max(x[3]).max(x[4].abs()).max(x[5].abs());
        let shortest = x[0].min(x[2]).min(x[3]);
        s = s.min(self.links.1 / longest.max(1e-300));
        if shortest > 0.0 {
            s = s.max(self.links.0 / shortest);
        }
        let lim = self.coords.1.min(-self.coords.0);
        s = s.min(lim / x[4].abs().max(x[5].abs()).max(1e-300));
        for j in [0, 2, 3, 4, 5] {
            x[j] *= s;
        }
        let (sa, ca) = alpha.sin_cos();
        // The origin maps to O2' = R s O2 + (mt - R s mp): with O2 scaled and
        // turned about the origin, its image is mt + R s (O2 - mp).
        let (ox, oy) = (d.0[7] - mp[0], d.0[8] - mp[1]);
        x[6] = (x[6] + alpha).rem_euclid(TAU);
        x[7] = (mt[0] + s * (ca * ox - sa * oy)).clamp(self.coords.0, self.coords.1);
        x[8] = (mt[1] + s * (sa * ox + ca * oy)).clamp(self.coords.0, self.coords.1);
        true
    }
}

/// The ordered nearest assignment: for targets `t_1 .. t_n` and curve samples
/// `c_0 .. c_M` (in crank order), the indices `i_1 <= .. <= i_n` minimizing
/// `sum |c_(i_k) - t_k|^2`, by dynamic programming in `O(n M)`.
pub fn assign(curve: &[[f64; 2]], targets: &[[f64; 2]]) -> Vec<usize> {
    let m = curve.len();
    let n = targets.len();
    let mut cost = vec![0.0; m];
    let mut from = vec![vec![0usize; m]; n];
    for (k, t) in targets.iter().enumerate() {
        // best[i] = min over i' <= i of the previous row, and where.
        let (mut run, mut arg) = (f64::INFINITY, 0);
        let mut next = vec![0.0; m];
        for (i, c) in curve.iter().enumerate() {
            let prev = if k == 0 { 0.0 } else { cost[i] };
            if prev < run {
                run = prev;
                arg = i;
            }
            next[i] = run + (c[0] - t[0]).powi(2) + (c[1] - t[1]).powi(2);
            from[k][i] = arg;
        }
        cost = next;
    }
    let mut i = (0..m)
        .min_by(|&a, &b| cost[a].total_cmp(&cost[b]))
        .unwrap_or(0);
    let mut idx = vec![0; n];
    for k in (0..n).rev() {
        idx[k] = i;
        i = from[k][i];
    }
    idx
}

impl Problem for PathProblem {
    fn dim(&self) -> usize {
        self.lo.len()
    }
    fn residual_count(&self) -> usize {
        let n = self.targets.len();
        2 * n
            + 1
            + 2 * usize::from(self.transmission.is_some())
            + 2 * self.orientations.as_ref().map_or(0, |_| n)
    }
    fn lower(&self) -> &[f64] {
        &self.lo
    }
    fn upper(&self) -> &[f64] {
        &self.hi
    }
    /// The bounds, with `theta0` in `[0, 2 pi]` and the angle variables `v`
    /// in `[0, 1]` (scale-free: every gap ratio is reachable there).
    fn search_box(&self) -> (Vec<f64>, Vec<f64>) {
        let (mut lo, mut hi) = (self.lo.clone(), self.hi.clone());
        if self.frame.is_none() {
            (lo[6], hi[6]) = (0.0, TAU);
        }
        if matches!(self.timing, Timing::Free) {
            for j in self.angle_base()..lo.len() {
                (lo[j], hi[j]) = (0.0, 1.0);
            }
        }
        (lo, hi)
    }
    fn residuals<T: Real>(&self, x: &[T], out: &mut [T]) -> bool {
        let n = self.targets.len();
        let mut th = [T::zero(); 64];
        if n > th.len() {
            return false;
        }
        let (p, tri) = self.physical(x, &mut th[..n]);
        let fb = FourBarPath {
            r1: p[0],
            r2: p[1],
            r3: p[2],
            r4: p[3],
            rcx: p[4],
            rcy: p[5],
            theta0: p[6],
            x0: p[7],
            y0: p[8],
            circuit: self.mode,
        };
        for (k, t) in self.targets.iter().enumerate() {
            let Some((c, u)) = Self::coupler_pose(&fb, th[k]) else {
                return false;
            };
            out[2 * k] = c[0] - T::lit(t[0]);
            out[2 * k + 1] = c[1] - T::lit(t[1]);
            if let Some((angles, scale)) = &self.orientations {
                let (sa, ca) = angles[k].sin_cos();
                let at = 2 * n + 1 + 2 * k;
                out[at] = T::lit(*scale) * (u[0] - T::lit(ca));
                out[at + 1] = T::lit(*scale) * (u[1] - T::lit(sa));
            }
        }
        out[2 * n] = tri;
        if let Some(mu) = self.transmission {
            let at = out.len() - 2;
            let lim = T::lit(mu.cos());
            let [c0, cpi] = Self::transmission_cosines(&p);
            let w = T::lit(TRANSMISSION_WEIGHT);
            out[at] = if c0 > lim { w * (c0 - lim) } else { T::zero() };
            out[at + 1] = if cpi < -lim {
                w * (-lim - cpi)
            } else {
                T::zero()
            };
        }
        true
    }
    /// `theta0` into `[0, 2 pi)`, the angle variables `|v|` with `sum v^2 = 1`.
    /// Free timing: the ordered nearest assignment on 361 samples of the
    /// coupler curve (a crank step of one degree, which the local solve then
    /// refines); the crank angles are the variables a dimension change moves
    /// furthest. Prescribed timing: nothing.
    fn reseat(&self, x: &mut [f64]) {
        if matches!(self.timing, Timing::Free) {
            let mut y = x.to_vec();
            if self.assign_angles_on(&mut y, 360) {
                x.copy_from_slice(&y);
            }
        }
    }
    /// Free timing: the gaps before the first, between two, or after the
    /// last crank angle that are below [`SNAP_GAP`] rad (the angles' order
    /// bound nearly active: two targets at one crank angle, or an end angle
    /// near 0 or `2 pi`), closed in every combination (the smallest
    /// [`SNAP_MOST`] of them: an optimum may close one and keep its neighbour
    /// small but open). Prescribed timing: none.
    fn faces(&self, x: &[f64]) -> Vec<Vec<f64>> {
        if !matches!(self.timing, Timing::Free) {
            return Vec::new();
        }
        let b = self.angle_base();
        let total: f64 = x[b..].iter().map(|v| v * v).sum();
        let mut small: Vec<usize> = (b..x.len())
            .filter(|&j| x[j] != 0.0 && TAU * x[j] * x[j] <= SNAP_GAP * total)
            .collect();
        small.sort_by(|&i, &j| x[i].abs().total_cmp(&x[j].abs()));
        small.truncate(SNAP_MOST);
        (1..1usize << small.len())
            .map(|set| {
                let mut y = x.to_vec();
                for (k, &j) in small.iter().enumerate() {
                    if set & (1 << k) != 0 {
                        y[j] = 0.0;
                    }
                }
                y
            })
            .collect()
    }
    fn canonical(&self, x: &mut [f64]) {
        if self.frame.is_none() {
            x[6] = x[6].rem_euclid(TAU);
        }
        if matches!(self.timing, Timing::Free) {
            let b = self.angle_base();
            let s: f64 = x[b..].iter().map(|v| v * v).sum::<f64>().sqrt();
            if s > 0.0 {
                for v in &mut x[b..] {
                    *v = v.abs() / s;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    //! What `faces` offers: the small gaps of a free-timing design closed in
    //! every combination, everything else unchanged; nothing for prescribed
    //! timing or a design with no small gap.
    use super::*;
    use crate::cases;

    fn case(id: &str) -> PathProblem {
        let c = cases::all().into_iter().find(|c| c.id == id);
        c.map(|c| c.problem(Mode::Plus))
            .unwrap_or_else(|| panic!("{id}"))
    }

    #[test]
    fn faces_close_the_small_gaps_in_every_combination() {
        let p = case("ellipse10_free");
        let b = p.angle_base();
        // Eleven gap variables: two small (gaps of about 7e-7 and 6e-6
        // rad), the rest equal.
        let mut x = vec![30.0, 0.5, 30.0, 30.0, 1.0, 1.0, 0.5, 1.0, 1.0];
        x.extend(std::iter::repeat_n(1.0, p.dim() - b));
        x[b] = 1e-3;
        x[p.dim() - 1] = 3e-3;
        let faces = p.faces(&x);
        assert_eq!(faces.len(), 3);
        let closed: Vec<(bool, bool)> = faces
            .iter()
            .map(|y| (y[b] == 0.0, y[p.dim() - 1] == 0.0))
            .collect();
        assert!(closed.contains(&(true, false)));
        assert!(closed.contains(&(false, true)));
        assert!(closed.contains(&(true, true)));
        for y in &faces {
            for j in (0..p.dim()).filter(|&j| j != b && j != p.dim() - 1) {
                assert_eq!(y[j], x[j], "variable {j} moved");
            }
        }
        // No small gap: no face.
        x[b] = 1.0;
        x[p.dim() - 1] = 1.0;
        assert!(p.faces(&x).is_empty());
    }

    #[test]
    fn prescribed_timing_has_no_faces() {
        let p = case("arc5_timed");
        let x: Vec<f64> = (0..p.dim()).map(|_| 1e-9).collect();
        assert!(p.faces(&x).is_empty());
    }
}
