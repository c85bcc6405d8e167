// Error: numbers with a type suffix or in hex (they were accepted by value);
// each error shows the decimal to write.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, 1u8, theta2) as link2;
        let B = rrr(A, 0x10, O4, 1.5f32, left) as (link3, link4);
    }
}

fn main() {}
