use mechanism::mechanism;

mechanism! {
    /// The PRP of `sweep_prp_full_turn.rs` with the line at 33.33 deg to the
    /// crank: the guides are parallel at 56.67 and 236.67 deg, between the
    /// sweep's 0.1 deg samples. The joint goes to infinity there, as at
    /// 30 deg, and the verdict is the same: the group cannot be assembled at
    /// those two inputs (it used to be a singular-position warning).
    pub Cross {
        let O = ground(0.0, 0.0);
        let V = ground(0.3, 0.0);
        let vertical = guide(V, 90 deg);
        let A = crank(O, 0.1, theta) as crank_link;
        let rod_line = guide(O, crank_link, 33.33 deg);
        let C = prp(rod_line, vertical) as (b1, b2) slide (s1, s2);
    }
}

fn main() {}
