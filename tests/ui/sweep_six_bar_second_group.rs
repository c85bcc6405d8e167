use mechanism::mechanism;

mechanism! {
    /// A Grashof crank-rocker (130, 40, 120, 100) that turns fully, then a
    /// second RRR from the rocker's tip B to O6 = (130, 180) with links 70
    /// and 50: B is more than 120 from O6 once the rocker swings past
    /// 128.9 deg. The second group, `D`, is the one that fails.
    pub Six {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(130.0, 0.0);
        let O6 = ground(130.0, 180.0);
        let A = crank(O2, 40.0, theta) as link2;
        let B = rrr(A, 120.0, O4, 100.0, left) as (link3, link4);
        let D = rrr(B, 70.0, O6, 50.0, left) as (link5, link6);
    }
}

fn main() {}
