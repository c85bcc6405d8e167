use mechanism::mechanism;

mechanism! {
    /// A PRP: a block on a line through the crank's pivot at 30 deg to the
    /// crank, a block on a fixed vertical guide. The guides are parallel at
    /// theta = 60 and 240 deg only.
    pub Cross {
        let O = ground(0.0, 0.0);
        let V = ground(0.3, 0.0);
        let vertical = guide(V, 90 deg);
        let A = crank(O, 0.1, theta) as crank_link;
        let rod_line = guide(O, crank_link, 30 deg);
        let C = prp(rod_line, vertical) as (b1, b2) slide (s1, s2);
    }
}

fn main() {}
