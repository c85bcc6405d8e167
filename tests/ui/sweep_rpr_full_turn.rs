use mechanism::mechanism;

mechanism! {
    /// The inverted slider of `sweep_rpr_range.rs` over the default full
    /// turn: the failing interval runs over 0 deg.
    pub Inverted {
        let O = ground(0.0, 0.0);
        let B = ground(0.12, 0.0);
        let A = crank(O, 0.1, theta) as link2;
        let s = rpr(A, B, plus, 0.05) as (block, rocker);
    }
}

fn main() {}
