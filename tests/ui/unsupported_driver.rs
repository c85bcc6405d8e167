// Error: `motor` is not a driver of this language; `crank` is suggested. (Kept
// to the driver alone so that nothing else refers to `A`.)
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = motor(O2, crank, theta2) as link2;
    }
}

fn main() {}
