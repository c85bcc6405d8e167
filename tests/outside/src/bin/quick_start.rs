use mechanism::mechanism;

mechanism! {
    /// Crank-rocker four-bar with a coupler point P (mm).
    pub FourBar {
        params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(ground, 0.0);
        let A = crank(O2, crank, theta2) as link2;
        let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
        let P = point(link3, from A, 120.0, 30 deg);
    }
}

fn main() -> Result<(), mechanism::Error> {
    let fb = FourBar::<f64>::default();                     // parameters at their literal values
    let input = FourBarInput { theta2: 0.5 };
    let p = fb.position(&input)?;                           // p.B, p.P: Point2; p.link3: angle (rad)
    let v = fb.velocity(&p, &FourBarInput { theta2: 250.0 })?;   // v.link3: rad/s, v.P: mm/s
    println!("B = ({:.3}, {:.3}) mm, theta3 = {:.3} deg, omega3 = {:.3} rad/s",
        p.B.x, p.B.y, p.link3.to_degrees(), v.link3);
    Ok(())
}
