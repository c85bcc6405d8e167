// Error: Serialize derived twice (the impls would conflict).
use mechanism::mechanism;

mechanism! {
    #[derive(serde::Serialize)] #[cfg_attr(feature = "x", derive(serde::Serialize))]
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
    }
}

fn main() {}
