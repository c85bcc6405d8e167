//! What [`mechanism!`](crate::mechanism!) generates, shown on a real
//! definition: the crank-rocker four-bar of the [quick start](crate) (lengths
//! in mm) with its coupler's mass, so that the force analysis appears too.
//! Compiled in every build (it costs one macro expansion and nothing at run
//! time), so its types can be used, and are checked, like any other.
//!
//! The definition:
//!
//! ```text
//! mechanism! {
//!     pub FourBar {
//!         params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
//!         let O2 = ground(0.0, 0.0);
//!         let O4 = ground(ground, 0.0);
//!         let A = crank(O2, crank, theta2) as link2;
//!         let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
//!         let P = point(link3, from A, 120.0, 30 deg);
//!         mass link3 { m = 2.0, at = P, j = 0.01 };
//!     }
//! }
//! ```
//!
//! Everything below is generated from it: [`FourBar`] holds the parameters,
//! [`FourBarInput`] the crank angle (and, in the same struct, its rates),
//! [`FourBarPosition`], [`FourBarVelocity`], [`FourBarAcceleration`] and
//! [`FourBarForces`] the results, [`FourBarSolution`] all of them, and
//! [`FourBarBatch`] a structure of arrays for many inputs at once.
//!
//! ```
//! use mechanism::example::{FourBar, FourBarInput};
//!
//! let fb = FourBar::<f64>::default();
//! let p = fb.position(&FourBarInput { theta2: 0.5 })?;
//! // The coupler keeps its length (mm), to rounding.
//! assert!(((p.B - p.A).norm() - 254.0).abs() < 1e-9);
//! # Ok::<(), mechanism::Error>(())
//! ```

use crate::mechanism;

mechanism! {
    /// Crank-rocker four-bar (mm), with the coupler's mass (kg,
    /// kg mm^2) at the coupler point `P`.
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        let P = point(link3, from A, 120.0, 30 deg);
        mass link3 { m = 2.0, at = P, j = 0.01 };
    }
}
