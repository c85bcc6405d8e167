use mechanism::mechanism;

mechanism! {
    /// A pose far from every assembly at its input selects none.
    pub Stephenson {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.30, 0.0);
        let O6 = ground(0.05, 0.42);
        let C = crank(O6, 0.24, phi) as link6;
        let (A, B, P) = triad(O2, 0.08, O4, 0.20, C, 0.28, 0.26, 0.15, 40 deg,
                              phi = -49.48 deg, (1.0, 1.0), (1.2, 1.0), (1.0, 1.2))
            as (crank2, rocker, link5, coupler);
        range phi = (-50 deg, -3 deg);
    }
}

fn main() {}
