// Error: a block's joint also listed as a pin of the link it slides on.
use mechanism::mechanism;

mechanism! {
    pub Shaper {
        joints { A = (0.0, 0.0), C = (0.0, -0.275), B = (0.07, 0.1), D = (0.1, 0.3) }
        links { ground = [A, C], link2 = [A, B], link3 = [C, B, D] }
        slider block at B on link3 along 1.39;
        input crank = angle(link2);
    }
}

fn main() {}
