// Error: a constant sub-expression that overflows beside a parameter (this made
// the macro panic in proc-macro2's `Literal::f64_suffixed`): the error is on it.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank + 1e308 * 10.0, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
    }
}

fn main() {}
