// Error: `T` is reserved; the user's code calling the force analysis (with
// its loads) gets no follow-on errors from the stub.
use mechanism::mechanism;

mechanism! {
    pub FourBar {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.0, 0.0);
        let A = crank(O2, 1.0, th) as link2;
        let T = rrr(A, 3.5, O4, 2.0, left) as (link3, link4);
        loads { cut = 1.0 }
        mass link3 { m = 1.0, at = T };
        force at T on link3 = (cut, 0.0);
    }
}

fn main() {
    let m = FourBar::<f64>::default();
    let input = FourBarInput { th: 0.0 };
    let rates = FourBarInput { th: 1.0 };
    let accels = FourBarInput { th: 0.0 };
    let loads = FourBarLoads::default();
    let s = m.solve(&input, &rates, &accels, &loads).unwrap();
    let _ = s.forces.condition;
    let f = m.forces(&s.position, &s.velocity, &s.acceleration, &loads).unwrap();
    let _ = f.condition;
}
