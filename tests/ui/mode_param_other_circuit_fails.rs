// Error: a run-time circuit is checked for both values: the second group
// reaches from B in the left circuit only (B above the x axis, within 222 to
// 373 of O6), not in the right one (B below it, 491 to 578 away, beyond 200 +
// 250).
use mechanism::mechanism;

mechanism! {
    pub SixBar {
        params { circuit = left }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(304.8, 0.0);
        let O6 = ground(300.0, 400.0);
        let A = crank(O2, 101.6, theta2) as link2;
        let B = rrr(A, 254.0, O4, 177.8, circuit) as (link3, link4);
        let C = rrr(B, 200.0, O6, 250.0, left) as (link5, link6);
    }
}

fn main() {}
