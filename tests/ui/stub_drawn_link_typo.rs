// A drawn four-bar whose crank is misspelt `crnk` in `links`: the only error
// is the input naming `crank`; the stubs keep every name with its type, so
// main reading the rocker's angle (`p.rocker`, a number), a joint (`p.B`, a
// point) and the struct's run-time mode reports nothing more.
use mechanism::mechanism;

mechanism! {
    pub Drawn {
        params { elbow = left }
        joints { O2 = (0.0, 0.0), O4 = (4.0, 0.0), A = (0.5, 0.9), B = (3.2, 2.1) }
        links { ground = [O2, O4], crnk = [O2, A], coupler = [A, B], rocker = [O4, B] }
        input theta = angle(crank);
    }
}

fn main() {
    let mut d = Drawn::<f64>::default();
    d.elbow = mechanism::Mode::Minus;
    let p = d.position(&DrawnInput { theta: 0.5 }).unwrap();
    let _: f64 = p.rocker.to_degrees() + p.coupler + p.crnk;
    let _: mechanism::Point2<f64> = p.B;
}
