// Pass: the whole force language — masses with and without inertia, gravity
// from parameters, per-evaluation loads, a force along a guide on a named
// link, a force in components, a couple — and the generated API used.
use mechanism::mechanism;

mechanism! {
    pub Press {
        params { crank = 0.1, rod = 0.4, g = 9.81 }
        loads { press = 0.0, brake = 0.0 }
        dof 1;
        let O = ground(0.0, 0.0);
        let line = guide((0.0, 0.0), 0 deg);
        let A = crank(O, crank, theta) as link2;
        let B = rrp(A, rod, line, plus) as (link3, ram) slide x;
        let G3 = point(link3, from A, 0.2, 0 deg);
        mass link2 { m = 1.0, at = O, j = 0.01 }
        mass link3 { m = 2.0, at = G3, j = 0.03 }
        mass ram { m = 5.0, at = B }
        gravity (0.0, -g);
        force at B on ram along line = -press;
        force at G3 = (0.0, 1.0);
        torque on link2 = brake;
    }
}

fn main() {
    let press = Press::<f64>::default();
    let one = PressInput { theta: 0.3 };
    let rates = PressInput { theta: 10.0 };
    let accels = PressInput { theta: 0.0 };
    let loads = PressLoads { press: 100.0, ..PressLoads::default() };
    let s = press.solve(&one, &rates, &accels, &loads).unwrap();
    let f: PressForces = s.forces;
    let _: mechanism::Vector2<f64> = f.r_ground_link2;
    let _: mechanism::force::PrismaticReaction<f64> = f.r_ground_ram;
    let _: f64 = f.drive_theta + f.condition + f.power_residual;
}
