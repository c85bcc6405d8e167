use mechanism::mechanism;

mechanism! {
    /// A four-bar that is not Grashof (s + l = 40 + 130 > p + q = 90 + 70),
    /// driven by a crank over a full turn (the default).
    pub NonGrashof {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(130.0, 0.0);
        let A = crank(O2, 40.0, theta2) as link2;
        let B = rrr(A, 90.0, O4, 70.0, left) as (link3, link4);
    }
}

fn main() {}
