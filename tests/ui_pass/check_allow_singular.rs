//! A parallelogram four-bar passes through its change point at theta2 = 0
//! and 180 deg; `allow singular B;` says the motion is meant to, and the
//! warning goes (`deny(warnings)` proves it). `check()` still reports them.
#![deny(warnings)]
use mechanism::mechanism;

mechanism! {
    pub Parallelogram {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(100.0, 0.0);
        let A = crank(O2, 40.0, theta2) as link2;
        let B = rrr(A, 100.0, O4, 40.0, left) as (link3, link4);
        allow singular B;
    }
}

mechanism! {
    /// The non-Grashof four-bar with the range the error suggests.
    pub Rocker {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(130.0, 0.0);
        let A = crank(O2, 40.0, theta2) as link2;
        let B = rrr(A, 90.0, O4, 70.0, left) as (link3, link4);
        range theta2 = (-133 deg, 133 deg);
    }
}

fn main() {
    let report = Parallelogram::<f64>::default().check();
    assert!(report.assembles());
    assert_eq!(report.groups[1].group, "B");
    assert_eq!(report.groups[1].singular, 2);
    assert!(Rocker::<f64>::default().check().is_clean());
}
