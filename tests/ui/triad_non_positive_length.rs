use mechanism::mechanism;

mechanism! {
    /// A leg of length zero and a negative side of the ternary link.
    pub Stephenson {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.30, 0.0);
        let O6 = ground(0.05, 0.42);
        let C = crank(O6, 0.24, phi) as link6;
        let (A, B, P) = triad(O2, 0.0, O4, 0.20, C, 0.28, -0.26, 0.15, 40 deg,
                              phi = -49.48 deg, (-0.061, -0.052), (0.137, 0.116), (-0.036, 0.096))
            as (crank2, rocker, link5, coupler);
    }
}

fn main() {}
