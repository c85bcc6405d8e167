// Passes: a full-turn crank drawn below the x axis (at -120 deg, read in
// (-180, 180]) in front of a triad, with the crank's default range
// [0, 360] deg: the drawing's input counts as the same angle a turn away
// (240 deg), inside the range, and the triad is tracked from there.
use mechanism::mechanism;

mechanism! {
    pub CrankBelow {
        const phi0 = -28.402242220599071 * pi / 180.0;
        joints {
            O2 = (0.0, 0.0),
            O4 = (0.30, 0.0),
            O6 = (0.05 + 0.24 * cos(phi0) + 0.01, 0.42 + 0.24 * sin(phi0) + 0.01 * sqrt(3.0)),
            C = (0.05 + 0.24 * cos(phi0), 0.42 + 0.24 * sin(phi0)),
            A = (-5.9201362974731851e-2, 5.3807049927811955e-2),
            B = (1.7859606664268302e-1, 1.5893736176674175e-1),
            P = (6.9064856947974249e-3, 1.8845381871298039e-1),
        }
        links {
            ground = [O2, O4, O6],
            crank = [O6, C],
            crank2 = [O2, A],
            rocker = [O4, B],
            link5 = [C, P],
            coupler = [A, B, P],
        }
        input theta = angle(crank);
    }
}

fn main() {
    let m = CrankBelow::<f64>::default();
    let _ = m.position(&CrankBelowInput { theta: -2.0 });
}
