// Error: a gear on the ground turns about a ground point, and `A` moves;
// the fix carries it on the crank's link that holds `A`.
use mechanism::mechanism;

mechanism! {
    pub Geared {
        let O2 = ground(0.0, 0.0);
        let A = crank(O2, 1.0, theta) as link2;
        let P = gear(A, 0.3, link2, 1.5) as planet;
    }
}

fn main() {}
