#![deny(deprecated)]
use mechanism::mechanism;

mechanism! {
    /// A parallelogram four-bar (ground = coupler, crank = rocker): at
    /// theta2 = 0 and 180 deg all four joints are collinear and the RRR group
    /// folds (a change point). The warning is made an error here
    /// (`deny(deprecated)`) so that the test records its text.
    pub Parallelogram {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(100.0, 0.0);
        let A = crank(O2, 40.0, theta2) as link2;
        let B = rrr(A, 100.0, O4, 40.0, left) as (link3, link4);
    }
}

fn main() {}
