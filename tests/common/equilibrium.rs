//! What the zoo (`tests/zoo`) and the loaded definitions of
//! `tests/surface/forces.rs` are checked with: Newton-Euler per body, the
//! power balance, constraint lengths and finite differences.

use mechanism::{force::PrismaticReaction, Point2, Vector2};

/// Gravity (m/s^2).
pub const G: Vector2<f64> = Vector2::new(0.0, -9.81);
/// Equilibrium and power residuals, relative to the largest term (see
/// `tests/zoo/main.rs`).
pub const TOL: f64 = 1e-13;
/// Finite-difference step (see `tests/zoo/main.rs`).
pub const H: f64 = 1e-5;

pub fn cross(a: &Vector2<f64>, b: &Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// One body's loads: forces applied at points (reactions, weights, external
/// forces, inertia forces `-m a_G`) and couples (external, `-J alpha`,
/// prismatic reactions' couples).
#[derive(Default)]
pub struct Body {
    forces: Vec<(Point2<f64>, Vector2<f64>)>,
    couples: Vec<f64>,
}

impl Body {
    pub fn force(mut self, at: Point2<f64>, f: Vector2<f64>) -> Self {
        self.forces.push((at, f));
        self
    }
    pub fn couple(mut self, c: f64) -> Self {
        self.couples.push(c);
        self
    }
    /// A prismatic reaction on this body (`sign` +1) or its opposite (-1):
    /// its normal force at its stated reference point `at`, and its couple.
    pub fn prismatic(self, r: &PrismaticReaction<f64>, at: Point2<f64>, sign: f64) -> Self {
        self.force(at, r.force * sign).couple(r.moment * sign)
    }
    /// Inertia and weight of a link of mass `m`, inertia `j` about its centre
    /// `g` (acceleration `a_g`, angular acceleration `alpha`), gravity `grav`.
    pub fn inertia(
        self,
        m: f64,
        j: f64,
        g: Point2<f64>,
        a_g: Vector2<f64>,
        alpha: f64,
        grav: Vector2<f64>,
    ) -> Self {
        self.force(g, grav * m - a_g * m).couple(-j * alpha)
    }
    /// Asserts zero net force and zero net moment (about the origin), each
    /// relative to the largest single term ([`Body::residual`]); `what` names
    /// the body.
    pub fn balances(&self, what: &str) {
        let (force, moment) = self.residual();
        assert!(
            force <= TOL,
            "{what}: net force {force:e} of the largest force"
        );
        assert!(
            moment <= TOL,
            "{what}: net moment {moment:e} of the largest moment"
        );
    }
    /// The net force's and the net moment's size (about the origin), each
    /// relative to the largest single term (also used by `classic.rs`, whose
    /// checks are shown to fail on a deliberate mistake).
    pub fn residual(&self) -> (f64, f64) {
        let mut sum = Vector2::zeros();
        let mut moment = 0.0;
        let (mut fscale, mut mscale) = (0.0f64, 0.0f64);
        for (p, f) in &self.forces {
            sum += f;
            moment += cross(&p.coords, f);
            fscale = fscale.max(f.norm());
            mscale = mscale.max(p.coords.norm() * f.norm());
        }
        for c in &self.couples {
            moment += c;
            mscale = mscale.max(c.abs());
        }
        // A body with no force (or no moment arm) at all has nothing to
        // balance: its residual is the absolute one, 0.
        let rel = |x: f64, scale: f64| if scale > 0.0 { x / scale } else { x };
        (rel(sum.norm(), fscale), rel(moment.abs(), mscale))
    }
}

/// Asserts that the powers in `terms` sum to zero, relative to the largest.
pub fn power_balances(terms: &[f64], what: &str) {
    let scale = terms.iter().fold(0.0f64, |m, t| m.max(t.abs()));
    let sum: f64 = terms.iter().sum();
    assert!(
        sum.abs() <= TOL * scale,
        "{what}: power residual {sum:e} of {scale:e}: {terms:?}"
    );
}

/// Power of the weight and the inertia loads of one body: mass `m`, inertia
/// `j`, centre velocity `vg` and acceleration `ag`, angular rate `omega` and
/// acceleration `alpha`, gravity `grav`.
pub fn inertial(
    m: f64,
    j: f64,
    vg: Vector2<f64>,
    ag: Vector2<f64>,
    omega: f64,
    alpha: f64,
    grav: Vector2<f64>,
) -> f64 {
    (grav * m - ag * m).dot(&vg) - j * alpha * omega
}

/// Asserts `|a - b| = l` to a few eps of the length (the groups close to
/// rounding).
pub fn assert_len(a: Point2<f64>, b: Point2<f64>, l: f64, what: &str) {
    assert!(
        ((a - b).norm() - l).abs() <= 1e-14 * l.max(1.0),
        "{what}: {} vs {l}",
        (a - b).norm()
    );
}

/// Asserts a generated rate against its central difference, to 1e-7 of
/// `max(1, scale)` (see `tests/zoo/main.rs`).
pub fn close_fd(got: Vector2<f64>, fd: Vector2<f64>, scale: f64, what: &str) {
    assert!(
        (got - fd).norm() <= 1e-7 * scale.max(1.0),
        "{what}: {got:?} vs {fd:?}"
    );
}
