// Error: a crank of radius 0.0. (A second crank keeps the definition driven
// and nothing refers to `A`, so only this error is reported.)
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, 0.0, t) as link2;
        let C = crank(O4, 50.0, phi) as link5;
    }
}

fn main() {}
