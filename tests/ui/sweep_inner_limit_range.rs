use mechanism::mechanism;

mechanism! {
    /// A four-bar whose crank pin comes closer to O4 than the coupler and
    /// rocker can fold (|200 - 100| = 100 > 130 - 40): it fails for
    /// |theta| < 35.2 deg, and the declared range crosses 35.2 deg.
    pub Folded {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(130.0, 0.0);
        let A = crank(O2, 40.0, theta) as link2;
        let B = rrr(A, 200.0, O4, 100.0, left) as (link3, link4);
        range theta = (-20 deg, 90 deg);
    }
}

fn main() {}
