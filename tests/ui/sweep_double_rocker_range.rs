use mechanism::mechanism;

mechanism! {
    /// A non-Grashof double rocker (s + l = 40 + 130 > p + q = 90 + 70) with
    /// a declared range that crosses both limit positions (133.05 and
    /// 226.95 deg, the law of cosines).
    pub Rocker {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(130.0, 0.0);
        let A = crank(O2, 40.0, theta) as link2;
        let B = rrr(A, 90.0, O4, 70.0, left) as (link3, link4);
        range theta = (90 deg, 250 deg);
    }
}

fn main() {}
