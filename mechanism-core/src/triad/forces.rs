//! The triad's joint reactions (see the module documentation of [`super`]).

use super::{TriadPosition, PRIM};
use crate::error::{Error, Fault};
use crate::force::body::Wrench;
use crate::linsolve;
use crate::scalar::Real;
use nalgebra::Vector2;

/// The known loads on the four bodies (inertia, weight, external loads, the
/// reactions of later groups negated), each about a stated point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriadLoads<T: Real> {
    /// On leg 1, about `A`.
    pub leg1: Wrench<T>,
    /// On leg 2, about `B`.
    pub leg2: Wrench<T>,
    /// On leg 3, about `P`.
    pub leg3: Wrench<T>,
    /// On the ternary link, about `A`.
    pub ternary: Wrench<T>,
}

/// The joint reactions (force units; global frame).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriadReactions<T: Real> {
    /// Force of the body carrying `K1` on leg 1, at `K1`.
    pub k1: Vector2<T>,
    /// Force of the body carrying `K2` on leg 2, at `K2`.
    pub k2: Vector2<T>,
    /// Force of the body carrying `K3` on leg 3, at `K3`.
    pub k3: Vector2<T>,
    /// Force of leg 1 on the ternary link at `A` (leg 1 receives `-a`).
    pub a: Vector2<T>,
    /// Force of leg 2 on the ternary link at `B`.
    pub b: Vector2<T>,
    /// Force of leg 3 on the ternary link at `P`.
    pub p: Vector2<T>,
    /// [`linsolve::Solution::min_pivot_ratio`] of the 12x12 solve.
    pub min_pivot_ratio: T,
}

/// [`super::reactions`], generic: instantiated in this crate for `f32` and
/// `f64` only (through [`super::Kernels`]).
pub(super) fn reactions_in<T: Real>(
    pos: &TriadPosition<T>,
    loads: &TriadLoads<T>,
) -> Result<TriadReactions<T>, Error<T>> {
    let w = [loads.leg1, loads.leg2, loads.leg3, loads.ternary];
    if !w.iter().all(Wrench::is_finite) {
        return Err(Error::new(PRIM, Fault::NonFinite { what: "triad load" }));
    }
    let (o, i) = (T::one(), T::zero());
    let mut m = [[i; 12]; 12];
    let legs = [pos.r1, pos.r2, pos.r3];
    for (k, r) in legs.iter().enumerate() {
        let (row, col) = (3 * k, 2 * k);
        // Outer force on the leg at K = joint - r; the inner joint's force
        // on the ternary, received by the leg with the opposite sign.
        m[row][col] = o;
        m[row + 1][col + 1] = o;
        m[row][6 + col] = -o;
        m[row + 1][7 + col] = -o;
        // Moment about the inner joint of a force at K: cross(-r, F).
        m[row + 2][col] = r.y;
        m[row + 2][col + 1] = -r.x;
        // The ternary's force rows hold the three inner forces.
        m[9][6 + col] = o;
        m[10][7 + col] = o;
    }
    for (col, arm) in [(8, pos.ab), (10, pos.ap)] {
        m[11][col] = -arm.y;
        m[11][col + 1] = arm.x;
    }
    let mut rhs = [i; 12];
    for (k, load) in w.iter().enumerate() {
        rhs[3 * k] = -load.force.x;
        rhs[3 * k + 1] = -load.force.y;
        rhs[3 * k + 2] = -load.moment;
    }
    let s = linsolve::solve(m, rhs).map_err(|e| Error::new(PRIM, e.fault))?;
    if !s.x.iter().all(|x| x.finite()) {
        return Err(Error::new(
            PRIM,
            Fault::NonFinite {
                what: "triad reaction",
            },
        ));
    }
    let v = |j: usize| Vector2::new(s.x[j], s.x[j + 1]);
    Ok(TriadReactions {
        k1: v(0),
        k2: v(2),
        k3: v(4),
        a: v(6),
        b: v(8),
        p: v(10),
        min_pivot_ratio: s.min_pivot_ratio,
    })
}
