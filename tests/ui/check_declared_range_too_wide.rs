use mechanism::mechanism;

mechanism! {
    /// The non-Grashof four-bar with a declared range that still goes past
    /// the limit position near 133 deg.
    pub TooWide {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(130.0, 0.0);
        let A = crank(O2, 40.0, theta2) as link2;
        let B = rrr(A, 90.0, O4, 70.0, left) as (link3, link4);
        range theta2 = (90 deg, 150 deg);
    }
}

fn main() {}
