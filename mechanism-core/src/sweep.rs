//! Sweeps of a mechanism's input range: where each group cannot be assembled,
//! and where its rate system passes through a singular position.
//!
//! One algorithm serves two callers, so that they find the same things: the
//! `mechanism!` macro runs it at expansion time (in `f64`, through the same
//! position primitives the generated code calls) and turns its findings into
//! compile errors and warnings; the generated `check()` runs it at run time
//! through the generated `position()` and returns a fixed-size [`Report`].
//!
//! The caller supplies `eval`, which solves the position at one input and
//! returns either the *scaled determinant* of every checked group's rate
//! system (a number in [-1, 1], a sine: see [`det_rrr`] and its siblings; 1
//! for groups that have none) or the index of the group that failed and its
//! [`Fault`].
//!
//! One input (`sweep_1d`): `samples + 1` equally spaced inputs over the range
//! (3600 for a full turn: 0.1 deg); every change of outcome between two
//! neighbours (assembles / group `g` fails) is bisected to
//! `Tolerances::edge` times the range's width, so a reported interval's ends
//! are accurate to about 1e-10 of the range (3.6e-8 deg on a full turn),
//! within rounding. A failing interval narrower than a sample step can be
//! missed. A periodic range (a full turn) joins an interval that runs over its
//! end with one that starts at its beginning (`[a - 360 deg, b]`).
//!
//! Singular positions, between neighbours that both assemble: a change of
//! sign of a group's scaled determinant is bisected; a sample where its
//! magnitude is a local minimum (no sign change), and could reach zero if the
//! determinant is V-shaped there (`f1 - max(f0 - f1, f2 - f1)` below the
//! threshold), is refined by a golden-section search, and counts as singular
//! when the minimum is below `Tolerances::singular`; positions found within a
//! sample step of each other count once. (For the groups with an assembly mode the
//! determinant keeps its sign and touches zero at a toggle, so the minimum
//! test is the one that finds them.)
//!
//! Two inputs (`sweep_2d`): a `(samples + 1)^2` grid over the box, without
//! refinement; per group, the number of failing grid points and their bounding
//! box, and sign changes of the determinant between neighbours along the
//! second input.
//!
//! Input units are the inputs' own (rad for angles, length units for
//! displacements); `f64` throughout, whatever the scalar `eval` solves in.

use crate::dyad::{rpp::RppPosition, rpr::RprPosition, rrp::RrpPosition, rrr::RrrPosition};
use crate::error::Fault;
use crate::geometry::{cross, dot, length};
use crate::guide::Line;
use crate::scalar::Real;
use nalgebra::{Point2, Vector2};

/// Samples of a one-input sweep: 0.1 deg on a full turn.
pub const SAMPLES_1D: usize = 3600;
/// Samples per input of a two-input sweep (a 121 x 121 grid).
pub const SAMPLES_2D: usize = 120;

/// The range of one input.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Range {
    /// Lower end (rad or length units).
    pub lo: f64,
    /// Upper end, `> lo`.
    pub hi: f64,
    /// `true` for a full turn: the input at `hi` is the input at `lo`.
    pub periodic: bool,
}

/// How finely the sweep resolves what it finds.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct Tolerances {
    /// Bisection and golden-section searches stop at this fraction of the
    /// range's width.
    pub edge: f64,
    /// A scaled determinant (a sine) whose magnitude falls below this counts
    /// as singular.
    pub singular: f64,
}

impl Tolerances {
    /// The tolerances for a scalar with machine epsilon `eps`: edges bisected
    /// to `max(1e-10, eps)` of the range (the edge found is where the
    /// caller's position solve changes its verdict, which in `f32` can lie
    /// its rounding band beyond the exact limit: 3.3e-6 rad measured at a
    /// four-bar's, `tests/sweep_surface.rs`), singular below `sqrt(eps)` (1.5e-8 in
    /// `f64`, 3.5e-4 in `f32`). Why `sqrt(eps)`: near a toggle the scaled
    /// determinant grows like the distance to it (a V), and the searches place
    /// its minimum to about `eps` of the range at best, where rounding of the
    /// determinant itself is `eps`; a positive minimum above `sqrt(eps)` is
    /// a genuine, if poorly conditioned, pose (the rates lose at most half the
    /// digits there) and is not reported.
    pub fn for_eps(eps: f64) -> Self {
        Tolerances {
            edge: if eps > 1e-10 { eps } else { 1e-10 },
            singular: sqrt(eps),
        }
    }
}

/// `sqrt` without `std`: Newton's iteration from a power-of-two guess, to
/// rounding (used for the tolerance only).
fn sqrt(x: f64) -> f64 {
    if x <= 0.0 || !x.is_finite() {
        return 0.0;
    }
    let mut y = if x > 1.0 { x } else { 1.0 };
    for _ in 0..200 {
        let next = 0.5 * (y + x / y);
        if next >= y {
            break;
        }
        y = next;
    }
    y
}

/// What one evaluation returns: every checked group's scaled determinant, or
/// the index of the group that failed and why (the fault widened to `f64`
/// with [`Fault::to_f64`] when the scene is `f32`).
pub type Outcome<const G: usize> = Result<[f64; G], (usize, Fault)>;

/// A finding.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub enum Event<const D: usize> {
    /// Group `group` cannot be assembled: for inputs in `[lo, hi]` (one
    /// input), or at `count` grid points whose bounding box is `[lo, hi]`
    /// (two inputs). `fault` is the one at the first failing sample.
    Fails {
        /// Index of the group.
        group: usize,
        /// Lower corner.
        #[cfg_attr(feature = "serde", serde(serialize_with = "crate::ser::array"))]
        lo: [f64; D],
        /// Upper corner.
        #[cfg_attr(feature = "serde", serde(serialize_with = "crate::ser::array"))]
        hi: [f64; D],
        /// The fault at the first failing sample.
        fault: Fault,
        /// 1 for an interval; the number of failing grid points in 2D.
        count: u32,
    },
    /// Group `group`'s rate system is singular at input `at` (one input), or
    /// changes sign `count` times between grid neighbours, first at `at`.
    Singular {
        /// Index of the group.
        group: usize,
        /// Where.
        #[cfg_attr(feature = "serde", serde(serialize_with = "crate::ser::array"))]
        at: [f64; D],
        /// The smallest scaled determinant found there.
        det: f64,
        /// 1 for one input; the number of grid sign changes in 2D.
        count: u32,
    },
}

fn class<const G: usize>(o: &Outcome<G>) -> Option<usize> {
    match o {
        Ok(_) => None,
        Err((g, _)) => Some(*g),
    }
}

fn abs(x: f64) -> f64 {
    if x < 0.0 {
        -x
    } else {
        x
    }
}

/// Whether a local minimum `f1` of `|det|` between neighbours `f0`, `f2`
/// (equal steps) may dip below the singular threshold: the steepest V through
/// the three samples, `f1 - max(f0 - f1, f2 - f1)`, is its lowest possible
/// value if the determinant is no steeper than its samples show. A smooth
/// minimum well above zero (or a constant determinant's rounding noise) is
/// not refined.
fn may_reach(f0: f64, f1: f64, f2: f64, tol: &Tolerances) -> bool {
    let rise = if f0 > f2 { f0 - f1 } else { f2 - f1 };
    f1 - rise < tol.singular
}

/// At most this many halvings (a width ratio of 2^-80 is below any tolerance).
const MAX_STEPS: usize = 80;

/// Whether a group's `|det|` at a sample, `here`, is a local minimum between
/// its neighbours `before` and `after` (equal steps) worth refining: no sign
/// change was found in the step before (`changed`), where the bisection
/// already searched, and the minimum may reach the threshold ([`may_reach`]).
fn dips(before: f64, here: f64, after: f64, changed: bool, tol: &Tolerances) -> bool {
    here <= before && here < after && !changed && may_reach(before, here, after, tol)
}

/// Sweeps one input over `range` at `samples + 1` points; see the module
/// documentation. `report` receives every finding, failing intervals in
/// increasing order of their end (a periodic interval joined across the
/// range's end comes last).
pub fn sweep_1d<const G: usize>(
    range: &Range,
    samples: usize,
    tol: &Tolerances,
    eval: impl FnMut(&[f64; 1]) -> Outcome<G>,
    report: impl FnMut(Event<1>),
) {
    if let Some(mut sweep) = Sweep1d::new(range, samples, tol, eval, report) {
        sweep.run();
    }
}

/// A failing interval whose other end is not known yet.
#[derive(Clone, Copy)]
struct Open {
    /// The group that fails.
    group: usize,
    /// The known end (input units): the start while the walk is inside the
    /// interval; its end for one held back to be joined across a periodic
    /// range's end.
    at: f64,
    /// The fault at its first failing sample.
    fault: Fault,
}

/// A one-input sweep: the range's sampling, the tolerances in input units,
/// the caller's `eval` and `report`, and the last singular position reported
/// per group (to report one per sample step).
struct Sweep1d<'a, const G: usize, E, R> {
    /// The range swept.
    range: &'a Range,
    /// The tolerances, `edge` as a fraction of the width.
    tol: &'a Tolerances,
    /// Sample steps, at least 2.
    n: usize,
    /// `range.hi - range.lo` (input units, > 0).
    width: f64,
    /// `width / n` (input units).
    step: f64,
    /// Searches stop at this width (input units): `tol.edge * width`.
    edge: f64,
    /// The caller's position solve: scaled determinants or the failing group.
    eval: E,
    /// The caller's receiver of findings.
    report: R,
    /// Per group, the input of the last singular position reported (NaN:
    /// none yet).
    last_singular: [f64; G],
}

/// Where the walk over the samples stands after sample `prev.0`.
struct Walk<const G: usize> {
    /// The last sample: input and outcome.
    prev: (f64, Outcome<G>),
    /// The sample before it, when both assemble and no change of outcome lies
    /// between them (the left neighbour of a candidate minimum).
    prev2: Option<(f64, [f64; G])>,
    /// The determinants at the second sample (`lo + step`), when it
    /// assembles: the right neighbour of `hi` on a periodic range.
    second: Option<[f64; G]>,
    /// Per group: the determinant changed sign between `prev2` and `prev`.
    changed: [bool; G],
    /// The failing interval the walk is in.
    open: Option<Open>,
    /// On a periodic range, the failing interval that starts at `lo`, held
    /// back to be joined with one that runs to `hi`.
    held: Option<Open>,
}

impl<'a, const G: usize, E, R> Sweep1d<'a, G, E, R>
where
    E: FnMut(&[f64; 1]) -> Outcome<G>,
    R: FnMut(Event<1>),
{
    /// The sweep of `range` at `samples` steps (at least 2), or `None` (nothing
    /// to sweep, nothing reported) when the range's width is not finite and
    /// positive.
    fn new(
        range: &'a Range,
        samples: usize,
        tol: &'a Tolerances,
        eval: E,
        report: R,
    ) -> Option<Self> {
        let n = if samples < 2 { 2 } else { samples };
        let width = range.hi - range.lo;
        if width.partial_cmp(&0.0) != Some(core::cmp::Ordering::Greater) || !width.is_finite() {
            return None;
        }
        Some(Sweep1d {
            range,
            tol,
            n,
            width,
            step: width / n as f64,
            edge: tol.edge * width,
            eval,
            report,
            last_singular: [f64::NAN; G],
        })
    }

    /// Sample `i` of `0..=n` (input units); sample `n` is exactly `hi`.
    fn at(&self, i: usize) -> f64 {
        if i == self.n {
            self.range.hi
        } else {
            self.range.lo + self.step * i as f64
        }
    }

    /// The caller's outcome at input `x`.
    fn eval(&mut self, x: f64) -> Outcome<G> {
        (self.eval)(&[x])
    }

    /// Passes a finding to the caller, except a singular position within a
    /// sample step of the last one reported for its group: where the scaled
    /// determinant is at rounding level (a clamped toggle) a sample can take
    /// either sign, and the sign-change bisection and the minimum search may
    /// then both find the same position.
    fn report(&mut self, e: Event<1>) {
        if let Event::Singular { group, at, .. } = &e {
            if abs(at[0] - self.last_singular[*group]) < self.step {
                return;
            }
            self.last_singular[*group] = at[0];
        }
        (self.report)(e)
    }

    /// Reports that group `group` fails over `[lo, hi]` (input units).
    fn report_fails(&mut self, group: usize, lo: f64, hi: f64, fault: Fault) {
        self.report(Event::Fails {
            group,
            lo: [lo],
            hi: [hi],
            fault,
            count: 1,
        });
    }

    /// Reports a singular position of group `group` at input `at`, `det` the
    /// smallest scaled determinant found there.
    fn report_singular(&mut self, group: usize, at: f64, det: f64) {
        self.report(Event::Singular {
            group,
            at: [at],
            det,
            count: 1,
        });
    }

    /// The walk: the first sample, every step to the next sample, the end of
    /// the range, then the failing intervals still open.
    fn run(&mut self) {
        let lo = self.at(0);
        let first = self.eval(lo);
        if let (Ok(d), false) = (&first, self.range.periodic) {
            self.singular_samples(d, self.range.lo);
        }
        let mut walk = Walk {
            prev: (lo, first),
            prev2: None,
            second: None,
            changed: [false; G],
            open: match first {
                Err((group, fault)) => Some(Open {
                    group,
                    at: self.range.lo,
                    fault,
                }),
                Ok(_) => None,
            },
            held: None,
        };
        for i in 1..=self.n {
            let x = self.at(i);
            let cur = self.eval(x);
            if i == 1 {
                walk.second = cur.as_ref().ok().copied();
            }
            self.advance(&mut walk, x, cur);
        }
        if self.range.periodic {
            self.wrap_minima(&walk);
        } else if let Ok(d) = &walk.prev.1 {
            self.singular_samples(d, self.range.hi);
        }
        self.close(walk.open, walk.held);
    }

    /// Reports every group whose scaled determinant `d` at the sample `at`
    /// (an end of a non-periodic range) is below the singular threshold.
    fn singular_samples(&mut self, d: &[f64; G], at: f64) {
        for (g, x) in d.iter().enumerate() {
            if abs(*x) < self.tol.singular {
                self.report_singular(g, at, *x);
            }
        }
    }

    /// One step, from `walk.prev` to the sample `x` with outcome `cur`: a
    /// change of outcome is bisected; between two assembling samples, sign
    /// changes and minima of the determinants are searched.
    fn advance(&mut self, walk: &mut Walk<G>, x: f64, cur: Outcome<G>) {
        let (cp, cc) = (class(&walk.prev.1), class(&cur));
        let mut now_changed = [false; G];
        if cp != cc {
            self.outcome_change(walk, x, &cur, cp);
            walk.prev2 = None;
        } else if let (Ok(dp), Ok(dc)) = (&walk.prev.1, &cur) {
            let dp = *dp;
            now_changed = self.signs_and_minima(walk, (x, dc), &dp);
            walk.prev2 = Some((walk.prev.0, dp));
        } else {
            walk.prev2 = None;
        }
        walk.changed = now_changed;
        walk.prev = (x, cur);
    }

    /// The outcome changes between `walk.prev` (class `cp`) and the sample `x`
    /// (outcome `cur`): bisects where, closes the open failing interval there
    /// (or holds it back when it starts at a periodic range's `lo`), and opens
    /// one when `cur` fails.
    fn outcome_change(&mut self, walk: &mut Walk<G>, x: f64, cur: &Outcome<G>, cp: Option<usize>) {
        let b = self.bisect_outcome(walk.prev.0, x, cp);
        if let Some(open) = walk.open.take() {
            if self.range.periodic && open.at == self.range.lo && walk.held.is_none() {
                walk.held = Some(Open { at: b, ..open });
            } else {
                self.report_fails(open.group, open.at, b, open.fault);
            }
        }
        if let Err((group, fault)) = *cur {
            walk.open = Some(Open {
                group,
                at: b,
                fault,
            });
        }
    }

    /// Between `walk.prev` (determinants `dp`) and the sample `x` (`dc`), both
    /// assembling: per group, a sign change is bisected and reported;
    /// otherwise the determinant at `walk.prev` is tested as a minimum between
    /// `walk.prev2` and `x` and refined. Returns the groups whose sign changed.
    fn signs_and_minima(
        &mut self,
        walk: &Walk<G>,
        (x, dc): (f64, &[f64; G]),
        dp: &[f64; G],
    ) -> [bool; G] {
        let mut changed = [false; G];
        for g in 0..G {
            if (dp[g] < 0.0) != (dc[g] < 0.0) && dp[g] != 0.0 && dc[g] != 0.0 {
                changed[g] = true;
                let (q, det) = self.bisect_sign(g, walk.prev.0, dp[g], x);
                self.report_singular(g, q, det);
            } else if let Some((x2, d2)) = walk.prev2 {
                if dips(
                    abs(d2[g]),
                    abs(dp[g]),
                    abs(dc[g]),
                    walk.changed[g],
                    self.tol,
                ) {
                    let (q, det) = self.golden(g, x2, x);
                    if det < self.tol.singular {
                        self.report_singular(g, q, det);
                    }
                }
            }
        }
        changed
    }

    /// Periodic range: the sample at `hi` is the one at `lo`; tests it as a
    /// minimum between the last step and the first, and reports a position
    /// found beyond `hi` at its equivalent in the range.
    fn wrap_minima(&mut self, walk: &Walk<G>) {
        let (Some((x2, d2)), Ok(dn), Some(d1)) = (walk.prev2, &walk.prev.1, walk.second) else {
            return;
        };
        for g in 0..G {
            if dips(
                abs(d2[g]),
                abs(dn[g]),
                abs(d1[g]),
                walk.changed[g],
                self.tol,
            ) {
                let (q, det) = self.golden(g, x2, self.range.hi + self.step);
                if det < self.tol.singular {
                    let q = if q >= self.range.hi {
                        q - self.width
                    } else {
                        q
                    };
                    self.report_singular(g, q, det);
                }
            }
        }
    }

    /// Reports the failing intervals left at the end of the walk: `open` runs
    /// to `hi`, `held` from `lo`; on a periodic range the two are one interval
    /// `[open - width, held]` when the same group fails in both.
    fn close(&mut self, open: Option<Open>, held: Option<Open>) {
        let (lo, hi) = (self.range.lo, self.range.hi);
        match (open, held) {
            (Some(o), Some(h)) if o.group == h.group => {
                self.report_fails(o.group, o.at - self.width, h.at, o.fault);
            }
            (Some(o), Some(h)) => {
                self.report_fails(h.group, lo, h.at, h.fault);
                self.report_fails(o.group, o.at, hi, o.fault);
            }
            (Some(o), None) => self.report_fails(o.group, o.at, hi, o.fault),
            (None, Some(h)) => self.report_fails(h.group, lo, h.at, h.fault),
            (None, None) => {}
        }
    }

    /// Bisects between `a` (outcome class `ca`) and `b` (another class) to
    /// `edge`; returns the midpoint of the last bracket (input units).
    fn bisect_outcome(&mut self, mut a: f64, mut b: f64, ca: Option<usize>) -> f64 {
        for _ in 0..MAX_STEPS {
            if abs(b - a) <= self.edge {
                break;
            }
            let m = 0.5 * (a + b);
            if class(&self.eval(m)) == ca {
                a = m;
            } else {
                b = m;
            }
        }
        0.5 * (a + b)
    }

    /// Bisects a sign change of group `g`'s determinant between `a` (where it
    /// is `da`) and `b`, to `edge`. Returns the midpoint of the last bracket
    /// and the smallest `|det|` met on the way (0 when no midpoint assembled
    /// or one failed: the position is then at the midpoint that failed).
    fn bisect_sign(&mut self, g: usize, mut a: f64, da: f64, mut b: f64) -> (f64, f64) {
        let mut best = (0.5 * (a + b), f64::INFINITY);
        for _ in 0..MAX_STEPS {
            if abs(b - a) <= self.edge {
                break;
            }
            let m = 0.5 * (a + b);
            match self.eval(m) {
                Ok(d) => {
                    if abs(d[g]) < best.1 {
                        best = (m, abs(d[g]));
                    }
                    if (d[g] < 0.0) == (da < 0.0) {
                        a = m;
                    } else {
                        b = m;
                    }
                }
                Err(_) => return (m, 0.0),
            }
        }
        (0.5 * (a + b), if best.1.is_finite() { best.1 } else { 0.0 })
    }

    /// `|det|` of group `g` at `x`; infinite where the mechanism fails.
    fn abs_det(&mut self, g: usize, x: f64) -> f64 {
        match self.eval(x) {
            Ok(d) => abs(d[g]),
            Err(_) => f64::INFINITY,
        }
    }

    /// Golden-section search for the smallest `|det|` of group `g` in
    /// `[a, b]`, to `edge`: the input and the `|det|` there.
    fn golden(&mut self, g: usize, mut a: f64, mut b: f64) -> (f64, f64) {
        const R: f64 = 0.618_033_988_749_894_8;
        let mut x1 = b - R * (b - a);
        let mut x2 = a + R * (b - a);
        let mut f1 = self.abs_det(g, x1);
        let mut f2 = self.abs_det(g, x2);
        for _ in 0..2 * MAX_STEPS {
            if abs(b - a) <= self.edge {
                break;
            }
            if f1 <= f2 {
                b = x2;
                x2 = x1;
                f2 = f1;
                x1 = b - R * (b - a);
                f1 = self.abs_det(g, x1);
            } else {
                a = x1;
                x1 = x2;
                f1 = f2;
                x2 = a + R * (b - a);
                f2 = self.abs_det(g, x2);
            }
        }
        if f1 <= f2 {
            (x1, f1)
        } else {
            (x2, f2)
        }
    }
}

/// Failing grid points of one group: bounding box, first fault, count.
type Box2 = ([f64; 2], [f64; 2], Fault, u32);

/// Sweeps two inputs over the grid `(samples + 1)^2` of the box `ranges`; see
/// the module documentation. At most one `Fails` and one `Singular` event per
/// group, in group order.
pub fn sweep_2d<const G: usize>(
    ranges: &[Range; 2],
    samples: usize,
    mut eval: impl FnMut(&[f64; 2]) -> Outcome<G>,
    mut report: impl FnMut(Event<2>),
) {
    let n = if samples < 1 { 1 } else { samples };
    let at = |r: &Range, i: usize| {
        if i == n {
            r.hi
        } else {
            r.lo + (r.hi - r.lo) / n as f64 * i as f64
        }
    };
    let mut fails: [Option<Box2>; G] = [None; G];
    let mut sing: [Option<([f64; 2], f64, u32)>; G] = [None; G];
    for i in 0..=n {
        let x = at(&ranges[0], i);
        let mut prev: Option<(f64, [f64; G])> = None;
        for j in 0..=n {
            let y = at(&ranges[1], j);
            match eval(&[x, y]) {
                Err((g, fault)) => {
                    if g < G {
                        let e = fails[g].get_or_insert(([x, y], [x, y], fault, 0));
                        e.0 = [e.0[0].min(x), e.0[1].min(y)];
                        e.1 = [e.1[0].max(x), e.1[1].max(y)];
                        e.3 += 1;
                    }
                    prev = None;
                }
                Ok(d) => {
                    if let Some((py, pd)) = prev {
                        for g in 0..G {
                            if (pd[g] < 0.0) != (d[g] < 0.0) || d[g] == 0.0 {
                                let det = if abs(d[g]) < abs(pd[g]) { d[g] } else { pd[g] };
                                let q = if abs(d[g]) < abs(pd[g]) { y } else { py };
                                let e = sing[g].get_or_insert(([x, q], det, 0));
                                e.2 += 1;
                            }
                        }
                    }
                    prev = Some((y, d));
                }
            }
        }
    }
    for g in 0..G {
        if let Some((lo, hi, fault, count)) = fails[g] {
            report(Event::Fails {
                group: g,
                lo,
                hi,
                fault,
                count,
            });
        }
        if let Some((at, det, count)) = sing[g] {
            report(Event::Singular {
                group: g,
                at,
                det,
                count,
            });
        }
    }
}

/// What a sweep found for one group (the fixed-size summary `check()` returns).
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct GroupReport<const D: usize> {
    /// The user's name of the group (the point it defines).
    pub group: &'static str,
    /// Failing intervals (one input) or grid points (two inputs); 0 when the
    /// group assembles over the whole range.
    pub failures: u32,
    /// The failing interval with the lowest start (one input), or the
    /// bounding box of the failing grid points (two inputs).
    #[cfg_attr(feature = "serde", serde(serialize_with = "crate::ser::opt_corners"))]
    pub failure: Option<([f64; D], [f64; D])>,
    /// The fault at the first failing sample.
    pub fault: Option<Fault>,
    /// Singular positions found (one input), or grid sign changes (two).
    pub singular: u32,
    /// The lowest singular input found.
    #[cfg_attr(feature = "serde", serde(serialize_with = "crate::ser::opt_array"))]
    pub first_singular: Option<[f64; D]>,
}

/// What a sweep found, per checked group in solve order; no heap.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Report<const G: usize, const D: usize> {
    /// The inputs' names.
    #[cfg_attr(feature = "serde", serde(serialize_with = "crate::ser::array"))]
    pub inputs: [&'static str; D],
    /// The ranges swept.
    #[cfg_attr(feature = "serde", serde(serialize_with = "crate::ser::array"))]
    pub ranges: [Range; D],
    /// Per group.
    #[cfg_attr(feature = "serde", serde(serialize_with = "crate::ser::array"))]
    pub groups: [GroupReport<D>; G],
    /// Per group: `true` where a vanishing determinant puts the joint at
    /// infinity (a PRP's parallel guides, an RPP's slot parallel to its
    /// guide), so that a sign change found between two samples is a failure
    /// at that input, as a sample on it would be, not a singular position.
    #[cfg_attr(feature = "serde", serde(skip))]
    at_infinity: [bool; G],
}

impl<const G: usize, const D: usize> Report<G, D> {
    /// An empty report for the named groups.
    pub fn new(inputs: [&'static str; D], ranges: [Range; D], names: [&'static str; G]) -> Self {
        Report {
            inputs,
            ranges,
            groups: names.map(|group| GroupReport {
                group,
                failures: 0,
                failure: None,
                fault: None,
                singular: 0,
                first_singular: None,
            }),
            at_infinity: [false; G],
        }
    }

    /// Marks the groups whose joint is at infinity where their determinant
    /// vanishes (see the field `at_infinity`); the generated `check()` of a
    /// mechanism with a PRP or an RPP calls it.
    #[must_use]
    pub fn with_joints_at_infinity(mut self, at_infinity: [bool; G]) -> Self {
        self.at_infinity = at_infinity;
        self
    }

    /// Adds a finding.
    pub fn record(&mut self, event: &Event<D>) {
        match *event {
            Event::Fails {
                group,
                lo,
                hi,
                fault,
                count,
            } => {
                if let Some(r) = self.groups.get_mut(group) {
                    r.failures += count;
                    if r.failure.is_none_or(|(l, _)| lo[0] < l[0]) {
                        r.failure = Some((lo, hi));
                        r.fault = Some(fault);
                    }
                }
            }
            Event::Singular {
                group,
                at,
                det,
                count,
            } if self.at_infinity.get(group) == Some(&true) => self.record(&Event::Fails {
                group,
                lo: at,
                hi: at,
                fault: Fault::Singular { det, scale: 1.0 },
                count,
            }),
            Event::Singular {
                group, at, count, ..
            } => {
                if let Some(r) = self.groups.get_mut(group) {
                    r.singular += count;
                    if r.first_singular.is_none_or(|f| at[0] < f[0]) {
                        r.first_singular = Some(at);
                    }
                }
            }
        }
    }

    /// `true` when every group assembles over the whole range.
    pub fn assembles(&self) -> bool {
        self.groups.iter().all(|g| g.failures == 0)
    }

    /// `true` when every group assembles and no singular position was found.
    pub fn is_clean(&self) -> bool {
        self.assembles() && self.groups.iter().all(|g| g.singular == 0)
    }
}

/// One line for the ranges swept, then one per group: where it fails first
/// (the interval, or the grid points' bounding box, with the fault) and its
/// first singular position. Inputs print in their own units (rad for an
/// angle, the definition's length for a slide), as the report holds them.
impl<const G: usize, const D: usize> core::fmt::Display for Report<G, D> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "checked over")?;
        for (k, (name, r)) in self.inputs.iter().zip(&self.ranges).enumerate() {
            let sep = if k == 0 { " " } else { ", " };
            write!(f, "{sep}{name} in [{}, {}]", r.lo, r.hi)?;
        }
        if self.is_clean() {
            return write!(f, ": every group assembles, no singular position");
        }
        for g in &self.groups {
            write!(f, "\n  {}: ", g.group)?;
            match (g.failure, g.fault) {
                (Some((lo, hi)), fault) => {
                    write!(f, "fails ({} found), first over", g.failures)?;
                    for (k, name) in self.inputs.iter().enumerate() {
                        let sep = if k == 0 { " " } else { ", " };
                        write!(f, "{sep}{name} in [{}, {}]", lo[k], hi[k])?;
                    }
                    if let Some(fault) = fault {
                        write!(f, ": {fault}")?;
                    }
                }
                (None, _) => write!(f, "assembles")?,
            }
            if let Some(at) = g.first_singular {
                write!(f, "; {} singular, the first at", g.singular)?;
                for (k, name) in self.inputs.iter().enumerate() {
                    let sep = if k == 0 { " " } else { ", " };
                    write!(f, "{sep}{name} = {}", at[k])?;
                }
            }
        }
        Ok(())
    }
}

/// `num / scale`, or 0 (singular) when the scale is zero or either is not finite.
fn scaled<T: Real>(num: T, scale: T) -> f64 {
    let (n, s) = (num.as_f64(), scale.as_f64());
    if s > 0.0 && n.is_finite() && s.is_finite() {
        let r = n / s;
        if r.is_finite() {
            return r;
        }
    }
    0.0
}

/// RRR group (and linear actuator): `cross(r1, r2) / (|r1| |r2|)`, the sine
/// of the angle between the two links; zero at a toggle.
pub fn det_rrr<T: Real>(pos: &RrrPosition<T>) -> f64 {
    scaled(cross(&pos.r1, &pos.r2), length(&pos.r1) * length(&pos.r2))
}

/// RRP group: `dot(r1, dir) / |r1|`: zero when link 1 is perpendicular to
/// the guide.
pub fn det_rrp<T: Real>(pos: &RrpPosition<T>, g: &Line<T>) -> f64 {
    scaled(dot(&pos.r1, &g.dir), length(&pos.r1) * length(&g.dir))
}

/// RPR group: `dot(u, A - B) / |A - B|`, zero when `A` is at the foot of the
/// perpendicular from `B` on the slide line, and no larger in magnitude than
/// `|A - B| / size` (`size` the largest coordinate of `A` and `B`), the
/// second term of the velocity's `condition` (`dyad::rpr`): it falls to zero
/// where `A` passes through `B`. With offset 0 the first term is 1 on both
/// sides of that pass (the slide line turns with `A - B`, its direction
/// flipping by half a turn), so without the second the sweep would miss a
/// point where the rates are unbounded.
pub fn det_rpr<T: Real>(pos: &RprPosition<T>, a: &Point2<T>, b: &Point2<T>) -> f64 {
    let p: Vector2<T> = a - b;
    let sine = scaled(dot(&pos.axis, &p), length(&pos.axis) * length(&p));
    let size = [a.x, a.y, b.x, b.y]
        .iter()
        .fold(0.0f64, |m, c| m.max(abs(c.as_f64())));
    let spread = scaled(length(&p), T::lit(size));
    if spread < abs(sine) {
        if sine < 0.0 {
            -spread
        } else {
            spread
        }
    } else {
        sine
    }
}

/// PRP group: `cross(dir1, dir2)`: zero when the guides are parallel.
pub fn det_prp<T: Real>(g1: &Line<T>, g2: &Line<T>) -> f64 {
    scaled(cross(&g1.dir, &g2.dir), length(&g1.dir) * length(&g2.dir))
}

/// RPP group: `cross(dir, w)`: zero when the slot is parallel to the guide.
pub fn det_rpp<T: Real>(pos: &RppPosition<T>, g: &Line<T>) -> f64 {
    scaled(cross(&g.dir, &pos.slot), length(&g.dir) * length(&pos.slot))
}
