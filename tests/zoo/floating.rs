//! Groups whose outer joints all move: an RPR between two moving links (a
//! floating cylinder) and an RRP whose pinned end and guide are both carried.

use crate::equilibrium::*;
use mechanism::{mechanism, Point2, Vector2};

mechanism! {
    /// A floating cylinder (m, kg, N): a crank-rocker four-bar whose coupler
    /// point P and rocker point E hold an RPR group (a sleeve pinned at P
    /// slides on a rod pinned at E), so both of the group's pins move; a slot
    /// on the rod at right angles through E takes the block of an RRP whose
    /// link is pinned to the crank at K. Masses on every moving body (the
    /// sleeve's and the block's centres off their pins, so their prismatic
    /// couples do not vanish), gravity, a force along the rod on the sleeve
    /// (the cylinder's pull), a force along the slot on the block and a
    /// couple on the rocker.
    pub FloatingCylinder {
        dof 1;
        let O2 = ground(0.0, 0.0);
        let O4 = ground(0.4, 0.0);
        let A = crank(O2, 0.1, theta) as crank;
        let B = rrr(A, 0.35, O4, 0.25, left) as (coupler, rocker);
        let P = point(coupler, from A, 0.2, 25 deg);
        let E = point(rocker, from O4, 0.12, -40 deg);
        let s = rpr(P, E, plus) as (sleeve, rod);
        let rod_line = guide(E, rod);
        let slot = guide(E, rod, 90 deg);
        let K = point(crank, from O2, 0.06, 90 deg);
        let F = rrp(K, 0.5, slot, plus) as (link7, slider7) slide u;
        let Gc = point(crank, from O2, 0.04, 0 deg);
        let G3 = point(coupler, from A, 0.15, 10 deg);
        let G4 = point(rocker, from O4, 0.1, -10 deg);
        let Gr = point(rod, from E, 0.05, 0 deg);
        let G7 = point(link7, from K, 0.12, 0 deg);
        let Gs = point(sleeve, from P, (0.02, 0.01));
        let G8 = point(slider7, from F, (0.0, 0.03));
        mass crank { m = 0.5, at = Gc, j = 0.001 };
        mass coupler { m = 1.1, at = G3, j = 0.012 };
        mass rocker { m = 0.7, at = G4, j = 0.004 };
        mass sleeve { m = 0.2, at = Gs, j = 0.0004 };
        mass rod { m = 0.35, at = Gr, j = 0.002 };
        mass link7 { m = 0.3, at = G7, j = 0.003 };
        mass slider7 { m = 0.15, at = G8, j = 0.0002 };
        gravity (0.0, -9.81);
        force at P on sleeve along rod_line = -25.0;
        force at F on slider7 along slot = 12.0;
        torque on rocker = 1.5;
    }
}

/// The unit vector along `b - a`.
fn unit(a: Point2<f64>, b: Point2<f64>) -> Vector2<f64> {
    (b - a) / (b - a).norm()
}

#[test]
fn floating_cylinder_balances() {
    let m = FloatingCylinder::<f64>::default();
    let (w, al) = (5.0, 2.0);
    let mut checked = 0;
    for k in 0..72 {
        let q = f64::to_radians(5.0 * k as f64 + 0.5);
        let at = |t: f64| FloatingCylinderInput {
            theta: q + w * t + 0.5 * al * t * t,
        };
        let rate = |t: f64| FloatingCylinderInput { theta: w + al * t };
        let s = m
            .solve(&at(0.0), &rate(0.0), &FloatingCylinderInput { theta: al })
            .unwrap();
        let (p, v, a, f) = (&s.position, &s.velocity, &s.acceleration, &s.forces);
        if f.condition < 0.05 || v.condition < 0.05 {
            continue;
        }
        checked += 1;

        // Geometry: the sleeve's pin on the rod's line at `s` from E, the
        // block on the slot (through E, at right angles to the rod), the
        // RRP's link closed. Coordinates are below 0.6 here, so 1e-15 is
        // about 8 eps of them: room for the few roundings of each group.
        let rod = unit(p.E, p.P);
        let slot = Vector2::new(-rod.y, rod.x);
        assert!(((p.P - p.E).dot(&rod) - p.s).abs() <= 1e-15, "s");
        assert!((p.F - p.E).dot(&rod).abs() <= 1e-15, "F off the slot");
        assert_len(p.F, p.K, 0.5, "link7");
        assert!((p.rod - rod.y.atan2(rod.x)).abs() <= 1e-15, "rod angle");

        // Central differences of the generated position and velocity.
        let pos = |t: f64| m.position(&at(t)).unwrap();
        let vel = |t: f64| m.velocity(&pos(t), &rate(t)).unwrap();
        let (p1, p0) = (pos(H), pos(-H));
        let (v1, v0) = (vel(H), vel(-H));
        close_fd(v.F, (p1.F - p0.F) / (2.0 * H), 10.0, "vF");
        close_fd(a.F, (v1.F - v0.F) / (2.0 * H), 100.0, "aF");
        let slide = Vector2::new(v.s, a.s);
        let slide_fd = Vector2::new((p1.s - p0.s) / (2.0 * H), (v1.s - v0.s) / (2.0 * H));
        close_fd(slide, slide_fd, 100.0, "s rate, acceleration");
        let turn = Vector2::new(v.rod, a.rod);
        let turn_fd = Vector2::new((p1.rod - p0.rod) / (2.0 * H), (v1.rod - v0.rod) / (2.0 * H));
        close_fd(turn, turn_fd, 100.0, "rod rate, acceleration");

        // Newton-Euler for every body.
        let pull = rod * -25.0;
        let push = slot * 12.0;
        Body::default()
            .force(p.O2, f.r_ground_crank)
            .force(p.A, -f.r_crank_coupler)
            .force(p.K, -f.r_crank_link7)
            .couple(f.drive_theta)
            .inertia(0.5, 0.001, p.Gc, a.Gc, a.crank, G)
            .balances("crank");
        Body::default()
            .force(p.A, f.r_crank_coupler)
            .force(p.B, -f.r_coupler_rocker)
            .force(p.P, -f.r_coupler_sleeve)
            .inertia(1.1, 0.012, p.G3, a.G3, a.coupler, G)
            .balances("coupler");
        Body::default()
            .force(p.O4, f.r_ground_rocker)
            .force(p.B, f.r_coupler_rocker)
            .force(p.E, -f.r_rocker_rod)
            .couple(1.5)
            .inertia(0.7, 0.004, p.G4, a.G4, a.rocker, G)
            .balances("rocker");
        Body::default()
            .force(p.P, f.r_coupler_sleeve)
            .prismatic(&f.r_sleeve_rod, p.P, -1.0)
            .force(p.P, pull)
            .inertia(0.2, 0.0004, p.Gs, a.Gs, a.sleeve, G)
            .balances("sleeve");
        Body::default()
            .force(p.E, f.r_rocker_rod)
            .prismatic(&f.r_sleeve_rod, p.P, 1.0)
            .prismatic(&f.r_rod_slider7, p.F, -1.0)
            .inertia(0.35, 0.002, p.Gr, a.Gr, a.rod, G)
            .balances("rod (carries the slot)");
        Body::default()
            .force(p.K, f.r_crank_link7)
            .force(p.F, -f.r_link7_slider7)
            .inertia(0.3, 0.003, p.G7, a.G7, a.link7, G)
            .balances("link7");
        Body::default()
            .force(p.F, f.r_link7_slider7)
            .prismatic(&f.r_rod_slider7, p.F, 1.0)
            .force(p.F, push)
            .inertia(0.15, 0.0002, p.G8, a.G8, a.slider7, G)
            .balances("slider7");
        power_balances(
            &[
                f.drive_theta * w,
                1.5 * v.rocker,
                pull.dot(&v.P),
                push.dot(&v.F),
                inertial(0.5, 0.001, v.Gc, a.Gc, v.crank, a.crank, G),
                inertial(1.1, 0.012, v.G3, a.G3, v.coupler, a.coupler, G),
                inertial(0.7, 0.004, v.G4, a.G4, v.rocker, a.rocker, G),
                inertial(0.2, 0.0004, v.Gs, a.Gs, v.sleeve, a.sleeve, G),
                inertial(0.35, 0.002, v.Gr, a.Gr, v.rod, a.rod, G),
                inertial(0.3, 0.003, v.G7, a.G7, v.link7, a.link7, G),
                inertial(0.15, 0.0002, v.G8, a.G8, v.slider7, a.slider7, G),
            ],
            "FloatingCylinder",
        );
    }
    assert!(checked >= 60, "only {checked} of 72 poses checked");
}
