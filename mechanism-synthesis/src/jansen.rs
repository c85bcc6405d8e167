//! Synthesis of a definition other than the four-bar: Theo Jansen's leg (an
//! eight-link, one-input linkage of three RRR dyads on a crank), its foot
//! path at prescribed crank angles. The same [`Problem`], dual-number
//! Jacobian, bounded LM and multi-start serve it unchanged.
//!
//! The leg is [`JansenFoot`], with the thirteen "holy numbers" (Jansen's
//! published link lengths `a` .. `m`, in his units) as run-time parameters;
//! the two ternary links (triangles `b, d, e` on the upper rocker and
//! `g, h, i` on the foot) are placed by their sides, so every length is a
//! parameter. [`FootPath`] chooses some of the thirteen as design variables
//! (the others fixed at [`HOLY`]) and fits the foot point to target points
//! at the given crank angles, in the least-squares sense.

use mechanism::{mechanism, Real};

use crate::problem::Problem;

mechanism! {
    /// Jansen's leg (lengths in his units): crank `m` about `O`, second
    /// ground pivot `Z = (-a, -l)`; rods `j` and `k` from the crank pin to
    /// the upper rocker (`b`) and the lower rocker (`c`) about `Z`; `D` on
    /// the upper rocker's triangle (`b, d, e`) at `(dx, dy)` from `Z` in the
    /// frame of `Z -> B`; rod `f` from `D` and the foot's side `g` from `C`
    /// meet at `E`; the foot point `F` at `(ix, iy)` from `C` in the frame
    /// of `C -> E` (triangle `g, h, i`).
    pub JansenFoot {
        params {
            a = 38.0, l = 7.8, m = 15.0, j = 50.0, b = 41.5, k = 61.9, c = 39.3,
            f = 39.4, g = 36.7,
            dx = 2.6098795180722933, dy = 40.01497880670621,
            ix = -7.746594005449595, iy = 48.38378118041967
        }
        analysis position;
        let O = ground(0.0, 0.0);
        let Z = ground(-a, -l);
        let A = crank(O, m, theta) as crank;
        let B = rrr(A, j, Z, b, right) as (rodj, upper);
        let C = rrr(A, k, Z, c, left) as (rodk, lower);
        let D = point(upper, from Z, (dx, dy));
        let E = rrr(D, f, C, g, right) as (rodf, foot);
        let F = point(foot, from C, (ix, iy));
    }
}

/// Jansen's thirteen numbers `a, b, c, d, e, f, g, h, i, j, k, l, m`.
pub const HOLY: [f64; 13] = [
    38.0, 41.5, 39.3, 40.1, 55.8, 39.4, 36.7, 65.7, 49.0, 50.0, 61.9, 7.8, 15.0,
];

/// Names of the thirteen numbers, in [`HOLY`]'s order.
pub const NAMES: [&str; 13] = [
    "a", "b", "c", "d", "e", "f", "g", "h", "i", "j", "k", "l", "m",
];

/// The third vertex of a triangle with sides `base` (along the frame's
/// x axis from the vertex), `near` (from the vertex to the point) and `far`
/// (from the base's other end to the point), on the positive side:
/// `x = (base^2 + near^2 - far^2) / (2 base)`, `y = sqrt(near^2 - x^2)`;
/// `None` when the three lengths make no triangle.
pub fn apex<T: Real>(base: T, near: T, far: T) -> Option<(T, T)> {
    let x = (base * base + near * near - far * far) / (T::lit(2.0) * base);
    let y2 = near * near - x * x;
    (y2 > T::zero()).then(|| (x, y2.sqrt()))
}

/// The leg of the thirteen numbers `n` (in [`HOLY`]'s order); `None` when a
/// triangle does not close.
pub fn leg<T: Real>(n: &[T; 13]) -> Option<JansenFoot<T>> {
    let [a, b, c, d, e, f, g, h, i, j, k, l, m] = *n;
    let (dx, dy) = apex(b, d, e)?;
    let (ix, iy) = apex(g, i, h)?;
    Some(JansenFoot {
        a,
        l,
        m,
        j,
        b,
        k,
        c,
        f,
        g,
        dx,
        dy,
        ix,
        iy,
    })
}

/// The foot point of `leg` at crank angle `theta` (rad, from +x).
pub fn foot<T: Real>(leg: &JansenFoot<T>, theta: T) -> Option<[T; 2]> {
    let p = leg.position(&JansenFootInput { theta }).ok()?;
    Some([p.F.x, p.F.y])
}

/// Foot-path synthesis: the numbers at `vars` (indices into [`HOLY`]) are
/// the design variables, in `[lower, upper]`; the others stay at [`HOLY`];
/// the residuals are the foot point minus the target at each crank angle.
#[derive(Clone, Debug)]
pub struct FootPath {
    /// Indices into [`HOLY`] of the design variables.
    pub vars: Vec<usize>,
    /// Crank angles (rad), one per target.
    pub angles: Vec<f64>,
    /// Target foot points.
    pub targets: Vec<[f64; 2]>,
    lo: Vec<f64>,
    hi: Vec<f64>,
}

impl FootPath {
    /// A problem over the numbers `vars`, each in `[HOLY (1 - spread),
    /// HOLY (1 + spread)]`.
    pub fn new(vars: Vec<usize>, angles: Vec<f64>, targets: Vec<[f64; 2]>, spread: f64) -> Self {
        let lo = vars.iter().map(|&v| HOLY[v] * (1.0 - spread)).collect();
        let hi = vars.iter().map(|&v| HOLY[v] * (1.0 + spread)).collect();
        FootPath {
            vars,
            angles,
            targets,
            lo,
            hi,
        }
    }

    /// The thirteen numbers of design `x`.
    pub fn numbers<T: Real>(&self, x: &[T]) -> [T; 13] {
        let mut n = HOLY.map(T::lit);
        for (&v, &xv) in self.vars.iter().zip(x) {
            n[v] = xv;
        }
        n
    }
}

impl Problem for FootPath {
    fn dim(&self) -> usize {
        self.vars.len()
    }
    fn residual_count(&self) -> usize {
        2 * self.targets.len()
    }
    fn lower(&self) -> &[f64] {
        &self.lo
    }
    fn upper(&self) -> &[f64] {
        &self.hi
    }
    fn residuals<T: Real>(&self, x: &[T], out: &mut [T]) -> bool {
        let Some(leg) = leg(&self.numbers(x)) else {
            return false;
        };
        for (k, (&th, t)) in self.angles.iter().zip(&self.targets).enumerate() {
            let Some(p) = foot(&leg, T::lit(th)) else {
                return false;
            };
            out[2 * k] = p[0] - T::lit(t[0]);
            out[2 * k + 1] = p[1] - T::lit(t[1]);
        }
        true
    }
}

/// The multi-start budget that fits the leg from uniform starts in a
/// [`FootPath`]'s box (the example's Jansen line and `tests/jansen.rs`): 12
/// starts, each the best of 10 draws, 40 LM iterations each, 4 basin hops
/// at 0.2 of the box, a polish of at most 500 iterations; `seed` seeds the
/// draws.
pub fn settings(seed: u64) -> crate::multistart::Settings {
    use crate::lm::Options;
    crate::multistart::Settings {
        starts: 12,
        screen: 10,
        local: Options {
            max_iterations: 40,
            ..Options::default()
        },
        polish: Options {
            max_iterations: 500,
            ..Options::default()
        },
        hops: 4,
        hop_scale: 0.2,
        seed,
    }
}
