//! The definition of `SliderCrank` in `examples/common/scenes.rs` (copied): it
//! passes the expansion-time checks and its generated code compiles.
use mechanism::mechanism;

mechanism! {
    /// Offset slider-crank (m): crank 0.1, connecting rod 0.4, slide line at
    /// y = 0.02 along +x.
    #[self_test]
    pub SliderCrank {
        params { crank = 0.1, rod = 0.4, offset = 0.02 }
        dof 1;
        let O = ground(0.0, 0.0);
        let line = guide((0.0, offset), 0 deg);
        let A = crank(O, crank, theta) as link2;
        let B = rrp(A, rod, line, plus) as (link3, slider) slide x;
        outputs { B, link3, x }
    }
}

fn main() {
    let report = SliderCrank::<f64>::default().check();
    assert!(report.assembles());
}
