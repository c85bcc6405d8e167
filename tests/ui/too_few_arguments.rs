// Error: an rrr written without its second length; the count is reported, not
// `left` read as a length.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.0, 0.0);
        let A = crank(O2, 1.0, th) as link2;
        let B = rrr(A, 3.5, O4, left) as (link3, link4);
    }
}

fn main() {}
