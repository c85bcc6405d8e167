use mechanism::mechanism;

mechanism! {
    /// An offset slider-crank whose crank (0.1) is longer than the rod minus
    /// the offset (0.12 - 0.05): the rod cannot reach the line y = 0.05 for
    /// sin(theta) < -0.7, from 224.43 deg; the declared range crosses it.
    pub Slider {
        let O = ground(0.0, 0.0);
        let line = guide((0.0, 0.0), 0 deg);
        let A = crank(O, 0.1, theta) as link2;
        let B = rrp(A, 0.12, line, plus, 0.05) as (link3, slider) slide x;
        range theta = (0 deg, 270 deg);
    }
}

fn main() {}
