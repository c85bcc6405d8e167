// A definition with one error (a negative mass) still gives its forces struct
// every reaction and effort field: main reads `r_ground_boom` (the RRR's pin
// on the ground), the crank's pivot reaction and its driving torque, and the
// only error reported is the mass.
use mechanism::mechanism;

mechanism! {
    pub Arm {
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.0, 0.0);
        let A = crank(O2, 1.0, theta) as crank;
        let B = rrr(A, 3.0, O4, 2.5, left) as (coupler, boom);
        mass boom { m = -2.0, at = B };
    }
}

fn main() {
    let arm = Arm::<f64>::default();
    let input = ArmInput { theta: 0.5 };
    let s = arm.solve(&input, &input, &input).unwrap();
    let f = s.forces;
    let _: mechanism::Vector2<f64> = f.r_ground_boom + f.r_ground_crank + f.r_crank_coupler;
    let _: f64 = f.drive_theta + f.condition;
}
