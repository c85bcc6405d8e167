// Passes: the drawn Stephenson III with each triad leg's mass centre drawn
// as a third joint on the leg (as docs/dsl.md recommends): a joint that
// nothing else uses is a point on the leg, which stays a binary leg of the
// triad for the decomposition.
use mechanism::mechanism;

mechanism! {
    pub LegMasses {
        const phi0 = -28.402242220599071 * pi / 180.0;
        joints {
            O2 = (0.0, 0.0),
            O4 = (0.30, 0.0),
            O6 = (0.05, 0.42),
            C = (0.05 + 0.24 * cos(phi0), 0.42 + 0.24 * sin(phi0)),
            A = (-5.9201362974731851e-2, 5.3807049927811955e-2),
            B = (1.7859606664268302e-1, 1.5893736176674175e-1),
            P = (6.9064856947974249e-3, 1.8845381871298039e-1),
            G2 = (-0.03, 0.027),
            G4 = (0.24, 0.08),
            G5 = (0.09, 0.25),
        }
        links {
            ground = [O2, O4, O6],
            link6 = [O6, C],
            crank2 = [O2, A, G2],
            rocker = [O4, B, G4],
            link5 = [C, P, G5],
            coupler = [A, B, P],
        }
        input phi = angle(link6);
        range phi = (-50.43 deg, -2.64 deg);
        mass crank2 { m = 0.4, at = G2, j = 2.2e-4 };
        mass rocker { m = 0.8, at = G4, j = 2.7e-3 };
        mass link5 { m = 1.0, at = G5, j = 6.5e-3 };
        gravity (0.0, -9.81);
    }
}

fn main() {
    let m = LegMasses::<f64>::default();
    let _ = m.position(&LegMassesInput { phi: -0.5 });
}
