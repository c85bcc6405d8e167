use mechanism::mechanism;

mechanism! {
    /// The Stephenson III triad written as three RRR dyads: a dependency cycle that is a class III group.
    pub Stephenson {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.30, 0.0);
        let O6 = ground(0.05, 0.42);
        let C = crank(O6, 0.24, phi) as link6;
        let A = rrr(O2, 0.08, B, 0.26, left) as (crank2, coupler);
        let B = rrr(O4, 0.20, P, 0.15, right) as (rocker, side);
        let P = rrr(C, 0.28, A, 0.15, left) as (link5, side2);
    }
}

fn main() {}
