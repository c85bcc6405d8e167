use mechanism::mechanism;

mechanism! {
    /// An inverted slider: the crank pin carries a block on a rocker pivoted
    /// at (0.12, 0), slide line 0.05 from the pivot. The pin comes within
    /// 0.05 of the pivot for |theta| < 24.15 deg; the range crosses it.
    pub Inverted {
        let O = ground(0.0, 0.0);
        let B = ground(0.12, 0.0);
        let A = crank(O, 0.1, theta) as link2;
        let s = rpr(A, B, plus, 0.05) as (block, rocker);
        range theta = (-60 deg, 180 deg);
    }
}

fn main() {}
