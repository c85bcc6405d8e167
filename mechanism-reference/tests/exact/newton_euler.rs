//! The double-double Newton-Euler solver against answers derived by hand
//! (a driven compound pendulum; a static slider-crank with an offset load),
//! against the power balance of a moving slider-crank whose kinematics come
//! from the reference's loop closure, and its typed errors.
//!
//! Tolerances: the expected values are closed forms evaluated in
//! double-double (a few roundings of 2^-104 = 4.9e-32 each) and the solver
//! eliminates systems of at most 9 unknowns; 1e-29 of the problem's largest
//! force (or moment) is about 200 such roundings, while any wrong sign,
//! missing term or lever arm is off by 1e-3 or more.

use mechanism_reference::constraint::{Constraint, Linkage, Point, Side, V2};
use mechanism_reference::loop_closure::{
    acceleration, angular_acceleration, angular_velocity, position, velocity,
};
use mechanism_reference::newton_euler::{
    solve_forces, Body, Direction, Driver, ForceError, Joint, Link, Load, Pair, Reaction, State,
    System,
};
use mechanism_reference::Dd;

fn d(x: f64) -> Dd {
    Dd::from_f64(x)
}

/// |got - want| <= tol * scale.
fn close(got: Dd, want: Dd, scale: f64, tol: f64) -> bool {
    (got - want).abs().to_f64() <= tol * scale
}

/// A compound pendulum driven at its pivot O = (0, 0): mass m, centre at
/// distance l along the angle theta, inertia J about the centre, gravity
/// (0, -g). Textbook result (moments about the fixed pivot, J_O = J + m l^2
/// by the parallel-axis theorem):
/// T = (J + m l^2) alpha + m g l cos(theta);
/// R = m a_G + (0, m g) with a_G = l alpha (-s, c) - l omega^2 (c, s).
#[test]
fn driven_pendulum_matches_the_textbook() {
    let (m, l, j, g) = (d(2.5), d(0.3), d(0.04), d(9.81));
    for k in 0..24 {
        let theta = d(0.27 * k as f64 - 3.0);
        let (w, al) = (d(7.0) - d(0.5 * k as f64), d(-40.0) + d(3.0 * k as f64));
        let (s, c) = theta.sin_cos();
        let g_pos = V2 { x: l * c, y: l * s };
        let v_g = V2 {
            x: -(l * w * s),
            y: l * w * c,
        };
        let a_g = V2 {
            x: -(l * al * s) - l * w * w * c,
            y: l * al * c - l * w * w * s,
        };
        let p = [V2::default(), g_pos];
        let v = [V2::default(), v_g];
        let a = [V2::default(), a_g];
        let sys = System {
            bodies: vec![Body {
                mass: m,
                com: 1,
                inertia: j,
                turn: Some((0, 1)),
            }],
            joints: vec![Joint {
                from: Link::Ground,
                to: Link::Body(0),
                pair: Pair::Revolute { at: 0 },
            }],
            drivers: vec![Driver::Torque { body: 0 }],
            loads: vec![],
            gravity: V2 { x: Dd::ZERO, y: -g },
        };
        let sol = solve_forces(
            &sys,
            &State {
                p: &p,
                v: &v,
                a: &a,
            },
        )
        .expect("regular");
        let t_want = (j + m * l * l) * al + m * g * l * c;
        let r_want = V2 {
            x: m * a_g.x,
            y: m * a_g.y + m * g,
        };
        let r = sol.reactions[0].force();
        let scale = r_want.x.abs().to_f64().max(r_want.y.abs().to_f64());
        assert!(close(r.x, r_want.x, scale, 1e-29), "{k}: {r:?}");
        assert!(close(r.y, r_want.y, scale, 1e-29), "{k}: {r:?}");
        // Moments: scale by the largest force times the arm l.
        assert!(
            close(sol.drives[0], t_want, scale * 0.3, 1e-29),
            "{k}: {} vs {}",
            sol.drives[0],
            t_want
        );
        assert!(sol.residual <= 1e-28);
    }
}

/// A massless slider-crank at rest (crank r at theta about O, rod L, slider
/// on y = 0), loaded by a force (-P, 0) on the slider applied at H = B +
/// (0, h). The rod is a two-force member: its force on the slider is S e
/// with e = (B - A) / L; the slider's x balance gives S = P / e_x, its y
/// balance the guide's normal force N = -S e_y, its moment balance about B
/// the guide's couple M = -h P; the crank's moment about O the driving
/// torque T = S cross(A, e); the ground's pin force on the crank is S e.
#[test]
fn static_slider_crank_matches_the_two_force_member_solution() {
    let (r, len, p_load, h) = (d(0.1), d(0.4), d(1000.0), d(0.05));
    for k in 0..36 {
        let theta = d(10.0 * k as f64 + 5.0) * Dd::PI / d(180.0);
        let (s, c) = theta.sin_cos();
        let a_pt = V2 { x: r * c, y: r * s };
        let xb = a_pt.x + (len * len - a_pt.y * a_pt.y).sqrt();
        let b_pt = V2 { x: xb, y: Dd::ZERO };
        let h_pt = V2 { x: xb, y: h };
        let p = [V2::default(), a_pt, b_pt, h_pt];
        let zeros = [V2::default(); 4];
        // Bodies: 0 crank, 1 rod, 2 slider (all massless).
        let massless = |com| Body {
            mass: Dd::ZERO,
            com,
            inertia: Dd::ZERO,
            turn: None,
        };
        let sys = System {
            bodies: vec![massless(0), massless(1), massless(2)],
            joints: vec![
                Joint {
                    from: Link::Ground,
                    to: Link::Body(0),
                    pair: Pair::Revolute { at: 0 },
                },
                Joint {
                    from: Link::Body(0),
                    to: Link::Body(1),
                    pair: Pair::Revolute { at: 1 },
                },
                Joint {
                    from: Link::Body(1),
                    to: Link::Body(2),
                    pair: Pair::Revolute { at: 2 },
                },
                Joint {
                    from: Link::Ground,
                    to: Link::Body(2),
                    pair: Pair::Prismatic {
                        dir: Direction::Fixed(V2::new(1.0, 0.0)),
                        about: 2,
                    },
                },
            ],
            drivers: vec![Driver::Torque { body: 0 }],
            loads: vec![Load::Force {
                body: 2,
                at: 3,
                force: V2 {
                    x: -p_load,
                    y: Dd::ZERO,
                },
            }],
            gravity: V2::default(),
        };
        let sol = solve_forces(
            &sys,
            &State {
                p: &p,
                v: &zeros,
                a: &zeros,
            },
        )
        .expect("regular away from the dead centres");
        let e = b_pt.minus(a_pt).scale(Dd::ONE / len);
        let s_rod = p_load / e.x;
        let f_rod = e.scale(s_rod);
        let scale = s_rod.abs().to_f64();
        for joint in 0..3 {
            let f = sol.reactions[joint].force();
            assert!(close(f.x, f_rod.x, scale, 1e-29), "{k} joint {joint}");
            assert!(close(f.y, f_rod.y, scale, 1e-29), "{k} joint {joint}");
        }
        let Reaction::Prismatic { normal, moment, .. } = sol.reactions[3] else {
            panic!("joint 3 is prismatic");
        };
        assert!(close(normal, -(s_rod * e.y), scale, 1e-29), "{k}");
        // Moments: the largest force times the mechanism's size, 0.5 m.
        assert!(close(moment, -(h * p_load), scale * 0.5, 1e-29), "{k}");
        let t_want = s_rod * a_pt.cross(e);
        assert!(close(sol.drives[0], t_want, scale * 0.5, 1e-29), "{k}");
    }
}

/// Offset slider-crank (crank 0.1, rod 0.4, slide line y = 0.02) with
/// masses, inertias, gravity, a resisting force and a couple on the rod,
/// moving at 3000 rpm and accelerating: the kinematics come from the loop
/// closure; the power balance (driver + loads + weights + inertia forces and
/// couples = 0), which the solver never forms, holds to 1e-29 of the
/// largest power at 72 crank angles (each power is a sum of a few products
/// of double-double values; the accelerations carry the loop closure's
/// rounding, ~1e-31 relative).
#[test]
fn moving_slider_crank_balances_power() {
    let linkage = Linkage {
        points: vec![
            Point::Fixed(V2::new(0.0, 0.0)),
            Point::Fixed(V2::new(0.0, 0.02)),
            Point::Fixed(V2::new(1.0, 0.02)),
            Point::Unknown,
            Point::Unknown,
        ],
        constraints: vec![
            Constraint::Crank {
                p: 3,
                o: 0,
                r: 0.1,
                input: 0,
            },
            Constraint::Distance {
                p: 4,
                q: 3,
                len: 0.4,
            },
            Constraint::OnFixedLine {
                p: 4,
                origin: V2::new(0.0, 0.02),
                dir: V2::new(1.0, 0.0),
            },
        ],
        sides: vec![Side::Ahead {
            p: 4,
            a: 3,
            from: 1,
            to: 2,
        }],
        scale: 0.4,
    };
    let omega = d(3000.0) * Dd::TAU / d(60.0);
    let alpha = d(5.0e4);
    let (m2, j2, m3, j3, m4) = (d(1.0), d(0.002), d(2.0), d(0.03), d(5.0));
    let grav = V2::new(0.0, -9.81);
    let f_load = V2::new(-1500.0, 0.0);
    let couple = d(12.0);
    let mut worst = 0.0f64;
    for k in 0..72 {
        let q = d(5.0 * k as f64 + 2.5) * Dd::PI / d(180.0);
        let guess = [
            (0.0, 0.0),
            (0.0, 0.02),
            (1.0, 0.02),
            (0.1 * q.to_f64().cos(), 0.1 * q.to_f64().sin()),
            (0.1 * q.to_f64().cos() + 0.39, 0.02),
        ];
        let pose = position(&linkage, &[q], &guess).expect("assembles");
        let v = velocity(&linkage, &pose, &[q], &[omega]).expect("regular");
        let a = acceleration(&linkage, &pose, &v, &[q], &[omega], &[alpha]).expect("regular");
        // Centres: crank at its middle (5), rod at 0.15 from A (6); linear in
        // the points, so their rates follow the same combination.
        let mid = |x: &[V2]| x[3].scale(d(0.5));
        let rod = |x: &[V2]| x[3].plus(x[4].minus(x[3]).scale(d(0.375)));
        let mut p = pose.points.clone();
        let (mut vv, mut aa) = (v.clone(), a.clone());
        p.extend([mid(&pose.points), rod(&pose.points)]);
        vv.extend([mid(&v), rod(&v)]);
        aa.extend([mid(&a), rod(&a)]);
        let sys = System {
            bodies: vec![
                Body {
                    mass: m2,
                    com: 5,
                    inertia: j2,
                    turn: Some((0, 3)),
                },
                Body {
                    mass: m3,
                    com: 6,
                    inertia: j3,
                    turn: Some((3, 4)),
                },
                Body {
                    mass: m4,
                    com: 4,
                    inertia: Dd::ZERO,
                    turn: None,
                },
            ],
            joints: vec![
                Joint {
                    from: Link::Ground,
                    to: Link::Body(0),
                    pair: Pair::Revolute { at: 0 },
                },
                Joint {
                    from: Link::Body(0),
                    to: Link::Body(1),
                    pair: Pair::Revolute { at: 3 },
                },
                Joint {
                    from: Link::Body(1),
                    to: Link::Body(2),
                    pair: Pair::Revolute { at: 4 },
                },
                Joint {
                    from: Link::Ground,
                    to: Link::Body(2),
                    pair: Pair::Prismatic {
                        dir: Direction::Segment(1, 2),
                        about: 4,
                    },
                },
            ],
            drivers: vec![Driver::Torque { body: 0 }],
            loads: vec![
                Load::Force {
                    body: 2,
                    at: 4,
                    force: f_load,
                },
                Load::Couple { body: 1, couple },
            ],
            gravity: grav,
        };
        let sol = solve_forces(
            &sys,
            &State {
                p: &p,
                v: &vv,
                a: &aa,
            },
        )
        .expect("regular");
        let w3 = angular_velocity(&p, &vv, 3, 4);
        let al3 = angular_acceleration(&p, &vv, &aa, 3, 4);
        // Inertia force -m a_G and weight m g at each centre, inertia couple
        // -J alpha on each turning body; loads at their points.
        let body_power = |m: Dd, g_i: usize| grav.scale(m).minus(aa[g_i].scale(m)).dot(vv[g_i]);
        let terms = [
            sol.drives[0] * omega,
            body_power(m2, 5) - j2 * alpha * omega,
            body_power(m3, 6) - j3 * al3 * w3,
            body_power(m4, 4),
            f_load.dot(vv[4]),
            couple * w3,
        ];
        let scale = terms.iter().fold(0.0f64, |s, t| s.max(t.abs().to_f64()));
        let sum = terms.iter().fold(Dd::ZERO, |s, &t| s + t);
        let rel = sum.abs().to_f64() / scale;
        worst = worst.max(rel);
        assert!(rel <= 1e-29, "{k}: power balance off by {rel:e}");
        assert!(sol.residual <= 1e-28, "{k}: {}", sol.residual);
    }
    println!("worst relative power balance: {worst:.1e}");
}

fn one_body(joints: Vec<Joint>, drivers: Vec<Driver>) -> System {
    System {
        bodies: vec![Body {
            mass: d(1.0),
            com: 1,
            inertia: Dd::ZERO,
            turn: None,
        }],
        joints,
        drivers,
        loads: vec![],
        gravity: V2::new(0.0, -9.81),
    }
}

/// Descriptions that cannot be solved give typed errors, not panics.
#[test]
fn bad_descriptions_are_errors() {
    let p = [V2::default(), V2::new(1.0, 0.0)];
    let z = [V2::default(); 2];
    let st = State {
        p: &p,
        v: &z,
        a: &z,
    };
    let pin = Joint {
        from: Link::Ground,
        to: Link::Body(0),
        pair: Pair::Revolute { at: 0 },
    };
    // Two unknowns, three equations.
    assert_eq!(
        solve_forces(&one_body(vec![pin], vec![]), &st),
        Err(ForceError::NotSquare {
            equations: 3,
            unknowns: 2
        })
    );
    // A pin at O and a driving force through O: nothing can take a moment
    // about O, the moment row of the system is zero.
    let through_o = Driver::Force {
        body: 0,
        at: 0,
        dir: Direction::Fixed(V2::new(1.0, 0.0)),
    };
    assert!(matches!(
        solve_forces(&one_body(vec![pin], vec![through_o]), &st),
        Err(ForceError::Singular(_))
    ));
    // A point index out of range.
    let far = Joint {
        pair: Pair::Revolute { at: 7 },
        ..pin
    };
    assert_eq!(
        solve_forces(&one_body(vec![far], vec![Driver::Torque { body: 0 }]), &st),
        Err(ForceError::BadIndex)
    );
    // Inertia without a rotation reference.
    let mut sys = one_body(vec![pin], vec![Driver::Torque { body: 0 }]);
    sys.bodies[0].inertia = d(0.1);
    assert_eq!(
        solve_forces(&sys, &st),
        Err(ForceError::BadBody { body: 0 })
    );
}

/// A slotted lever at rest (the shaper's crank-block-rocker loop, massless):
/// crank A-B (r at theta about A = (0, 0)), block pinned at B sliding on the
/// lever pivoted at C = (0, -c) along C -> B, a couple `ml` on the lever.
/// The block passes only a force normal to the lever through B: the lever's
/// moment about C gives the normal force of block on lever N = -ml / |B - C|
/// (along perp(u), u = (B - C) / |B - C|), the slide couple is zero, the
/// ground's pin force on the lever is -N perp(u), and the crank's torque is
/// T = N cross(B - A, perp(u)). Exercises a sliding pair between two moving
/// bodies along a direction given by two moving points.
#[test]
fn static_slotted_lever_matches_the_hand_solution() {
    let (r, c, ml) = (d(0.125), d(0.275), d(300.0));
    for k in 0..36 {
        let theta = d(10.0 * k as f64 + 3.0) * Dd::PI / d(180.0);
        let (s, co) = theta.sin_cos();
        let b_pt = V2 {
            x: r * co,
            y: r * s,
        };
        let c_pt = V2 { x: Dd::ZERO, y: -c };
        let p = [V2::default(), c_pt, b_pt];
        let zeros = [V2::default(); 3];
        let massless = |com| Body {
            mass: Dd::ZERO,
            com,
            inertia: Dd::ZERO,
            turn: None,
        };
        // Bodies: 0 crank, 1 block, 2 lever.
        let sys = System {
            bodies: vec![massless(0), massless(2), massless(1)],
            joints: vec![
                Joint {
                    from: Link::Ground,
                    to: Link::Body(0),
                    pair: Pair::Revolute { at: 0 },
                },
                Joint {
                    from: Link::Body(0),
                    to: Link::Body(1),
                    pair: Pair::Revolute { at: 2 },
                },
                Joint {
                    from: Link::Body(1),
                    to: Link::Body(2),
                    pair: Pair::Prismatic {
                        dir: Direction::Segment(1, 2),
                        about: 2,
                    },
                },
                Joint {
                    from: Link::Ground,
                    to: Link::Body(2),
                    pair: Pair::Revolute { at: 1 },
                },
            ],
            drivers: vec![Driver::Torque { body: 0 }],
            loads: vec![Load::Couple {
                body: 2,
                couple: ml,
            }],
            gravity: V2::default(),
        };
        let sol = solve_forces(
            &sys,
            &State {
                p: &p,
                v: &zeros,
                a: &zeros,
            },
        )
        .expect("regular");
        let bc = b_pt.minus(c_pt);
        let len = bc.dot(bc).sqrt();
        let n = bc.scale(Dd::ONE / len).perp();
        let normal = -(ml / len);
        let scale = normal.abs().to_f64();
        let Reaction::Prismatic {
            normal: got,
            moment,
            force,
        } = sol.reactions[2]
        else {
            panic!("joint 2 is prismatic");
        };
        assert!(close(got, normal, scale, 1e-29), "{k}: {got}");
        assert!(close(force.x, n.x * normal, scale, 1e-29), "{k}");
        // Couples: the largest force times the lever's size, 0.5 m.
        assert!(close(moment, Dd::ZERO, scale * 0.5, 1e-29), "{k}: {moment}");
        let rc = sol.reactions[3].force();
        assert!(close(rc.x, -(n.x * normal), scale, 1e-29), "{k}");
        assert!(close(rc.y, -(n.y * normal), scale, 1e-29), "{k}");
        let t_want = normal * b_pt.cross(n);
        assert!(close(sol.drives[0], t_want, scale * 0.5, 1e-29), "{k}");
    }
}
