// `#[mechanism(crate = pm)]`: the generated code names the facade by the
// path given, as a crate that renames the dependency
// (`pm = { package = "planar-mechanism" }`) needs; here the rename is
// `extern crate .. as pm`, and `check()` and `Mode` come through it.
extern crate mechanism as pm;

pm::mechanism! {
    #[mechanism(crate = pm)]
    pub Renamed {
        params { circuit = left }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(4.0, 0.0);
        let A = crank(O2, 1.0, theta) as crank;
        let B = rrr(A, 3.5, O4, 3.0, circuit) as (coupler, rocker);
    }
}

fn main() {
    let mut r = Renamed::<f64>::default();
    r.circuit = pm::Mode::Minus;
    let p = r.position(&RenamedInput { theta: 0.5 }).unwrap();
    let _: f64 = p.rocker;
    assert!(r.check().assembles());
}
