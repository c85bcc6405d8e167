// Error: a const divides by a zero const: the value is not a finite number (this made the macro panic).
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        const gap = 0.0;
        const scale = 304.8 / gap;
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
    }
}

fn main() {
    let fb = FourBar::<f64>::default();
    let _ = fb.position(&FourBarInput { theta2: 0.0 }).map(|p| p.B);
}
