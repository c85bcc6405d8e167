//! Proves the generated `dynamics` gives the right `q''` and mass matrix:
//! at random states (inputs, rates, efforts) of seven definitions (a
//! four-bar with a couple and a force, a slider-crank with a mass on the
//! slider and a press load, the Stephenson III triad, a 2R leg with a
//! carried knee motor, an actuator whose barrel and rod carry mass, the
//! five-bar given its end point, the five-bar given its motors), against
//! `mechanism_reference::multibody`: every body's Newton-Euler equations with
//! the joint constraints and Lagrange multipliers, solved in double-double,
//! written from the bodies, joints and inputs described here (nothing from
//! the generated code but the `f64` pose that picks the assembly for the
//! reference's Newton).
//!
//! Tolerance 5e-14 relative to the scale of `q''` (and of the largest
//! `|M_ij|` for the mass matrix). The scale of `q''` is its largest
//! reference value or, where the right side of `M q'' = tau + Q - h`
//! cancels, the largest of `|tau_i|`, `|Q_i|`, `|h_i|` over `M_ii`: the
//! generated code reaches each term through the pose, the rates and the
//! accelerations (relative rounding a few eps each, amplified by the
//! velocity systems' condition) and a few dozen products, so its rounding
//! is relative to the terms, not to their difference. A Stephenson draw
//! with `Q = -6.95`, `h = -6.98` and `M q'' = 0.085` has an error of 9.8e-14
//! of `|q''|` and 1.1e-14 of the terms' scale. Worst of the 100 draws
//! (`--nocapture` prints them): triad 1.1e-14, four-bar 1.7e-15, the
//! others below 1.6e-15; `M` at most 1.4e-14 (triad, whose velocity
//! coefficients grow towards the swing's ends). The reference's own error
//! is about 1e-30.
use super::defs::*;
use super::round_trip::Rng;
use mechanism::Point2;
use mechanism_reference::constraint::V2;
use mechanism_reference::multibody::{forward, Anchor, Input, Joint, Load, Model, Part};
use mechanism_reference::Dd;

const TOLERANCE: f64 = 5e-14;

/// The largest errors of a definition's draws, printed with `--nocapture`.
#[derive(Default)]
struct Worst {
    name: &'static str,
    accel: f64,
    mass: f64,
}

impl Worst {
    fn add(&mut self, name: &'static str, (accel, mass): (f64, f64)) {
        self.name = name;
        self.accel = self.accel.max(accel);
        self.mass = self.mass.max(mass);
    }
    fn show(&self) {
        eprintln!(
            "{}: q'' {:.1e}, M {:.1e} (relative, worst of {DRAWS})",
            self.name, self.accel, self.mass
        );
    }
}
const DRAWS: usize = 100;

fn part(mass: f64, at: Anchor, inertia: f64) -> Part {
    Part {
        mass,
        at: at.at,
        inertia,
    }
}

fn angle(body: usize, carrier: Option<usize>) -> Input {
    Input::Angle {
        body,
        carrier,
        offset: Dd::ZERO,
    }
}

fn pin(a: Anchor, b: Anchor) -> Joint {
    Joint::Revolute(a, b)
}

fn on(body: usize, x: f64, y: f64) -> Anchor {
    Anchor::on(body, x, y)
}

/// A body frame's guess: origin `o`, axis towards `a`.
fn frame(o: Point2<f64>, a: Point2<f64>) -> [f64; 3] {
    [o.x, o.y, (a.y - o.y).atan2(a.x - o.x)]
}

/// Compares one state's `q''` and `M` with the reference's; returns the
/// relative errors.
fn compare(
    name: &str,
    model: &Model,
    state: [&[f64]; 3],
    got: (&[f64], &[&[f64]]),
    terms: [&[f64]; 2],
    start: &[[f64; 3]],
) -> (f64, f64) {
    let [q, qd, tau] = state;
    let r = forward(model, q, qd, tau, start).unwrap_or_else(|e| panic!("{name}: {e:?}"));
    let want: Vec<f64> = r.accels.iter().map(|a| a.to_f64()).collect();
    // The scale of q'': its largest reference value, or the largest term
    // of a row of `M q'' = tau + Q - h` over that row's diagonal mass where
    // the terms cancel (a term wrong by d moves q'' by about d / M_ii, so a
    // wrong h or Q cannot hide behind the scale it sets).
    let [h, gen] = terms;
    let term_scale = (0..want.len()).fold(0.0f64, |s, i| {
        let largest = tau[i].abs().max(gen[i].abs()).max(h[i].abs());
        s.max(largest / r.mass[i][i].to_f64().abs())
    });
    let scale = want
        .iter()
        .fold(0.0f64, |s, a| s.max(a.abs()))
        .max(term_scale);
    let acc = got
        .0
        .iter()
        .zip(&want)
        .map(|(g, w)| (g - w).abs())
        .fold(0.0, f64::max)
        / scale;
    let mscale = r
        .mass
        .iter()
        .flatten()
        .fold(0.0f64, |s, m| s.max(m.to_f64().abs()));
    let mut mass: f64 = 0.0;
    for (row, rrow) in got.1.iter().zip(&r.mass) {
        for (g, w) in row.iter().zip(rrow) {
            mass = mass.max((g - w.to_f64()).abs() / mscale);
        }
    }
    assert!(
        acc <= TOLERANCE && mass <= TOLERANCE,
        "{name} at q {q:?} q' {qd:?} tau {tau:?}: q'' {:?} want {want:?} (rel {acc:e}), mass rel {mass:e}",
        got.0
    );
    (acc, mass)
}

fn four_bar() -> Model {
    let (crank, coupler, rocker) = (0, 1, 2);
    Model {
        bodies: vec![
            vec![
                part(0.5, on(crank, 0.05, 0.0), 4.0e-4),
                part(2.0, on(crank, 0.0, 0.0), 0.02),
            ],
            vec![part(1.2, on(coupler, 0.125, 0.0), 6.5e-3)],
            vec![part(0.9, on(rocker, 0.09, 0.0), 2.5e-3)],
        ],
        joints: vec![
            pin(on(crank, 0.0, 0.0), Anchor::ground(0.0, 0.0)),
            pin(on(crank, 0.10, 0.0), on(coupler, 0.0, 0.0)),
            pin(on(coupler, 0.25, 0.0), on(rocker, 0.18, 0.0)),
            pin(on(rocker, 0.0, 0.0), Anchor::ground(0.30, 0.0)),
        ],
        inputs: vec![angle(crank, None)],
        loads: vec![
            Load::Couple {
                body: rocker,
                couple: Dd::from_f64(-0.3),
            },
            Load::Force {
                at: on(coupler, 0.125, 0.0),
                force: V2::new(2.0, 1.0),
            },
        ],
        gravity: V2::new(0.0, -9.81),
    }
}

// The four-bar with a couple on the rocker and a force on the coupler.
#[test]
fn four_bar_matches_the_global_formulation() {
    let (m, model) = (FourBar::<f64>::default(), four_bar());
    let mut rng = Rng(0x5eed_0001);
    let mut worst = Worst::default();
    for _ in 0..DRAWS {
        let (q, w, t) = (
            rng.range(-4.0, 4.0),
            rng.range(-40.0, 40.0),
            rng.range(-2.0, 2.0),
        );
        let pos = m.position(&FourBarInput { phi: q }).unwrap();
        let d = m
            .dynamics(&pos, &FourBarInput { phi: w }, &FourBarInput { phi: t })
            .unwrap();
        let start = [[0.0, 0.0, q], frame(pos.A, pos.B), frame(pos.O4, pos.B)];
        worst.add(
            "FourBar",
            compare(
                "FourBar",
                &model,
                [&[q], &[w], &[t]],
                (&[d.accels.phi], &[&d.mass[0]]),
                [&d.velocity_terms, &d.generalized_forces],
                &start,
            ),
        );
    }
    worst.show();
}

fn slider_crank(press: f64) -> Model {
    let (crank, rod, ram) = (0, 1, 2);
    Model {
        bodies: vec![
            vec![part(0.8, on(crank, 0.02, 0.0), 1.0e-3)],
            vec![part(0.6, on(rod, 0.06, 0.0), 2.5e-3)],
            vec![part(1.5, on(ram, 0.0, 0.0), 0.0)],
        ],
        joints: vec![
            pin(on(crank, 0.0, 0.0), Anchor::ground(0.0, 0.0)),
            pin(on(crank, 0.05, 0.0), on(rod, 0.0, 0.0)),
            pin(on(rod, 0.2, 0.0), on(ram, 0.0, 0.0)),
            Joint::Prismatic {
                a: on(ram, 0.0, 0.0),
                b: Anchor::ground(0.0, 0.0),
                dir: Dd::ZERO,
                lock: Dd::ZERO,
            },
        ],
        inputs: vec![angle(crank, None)],
        loads: vec![Load::Force {
            at: on(ram, 0.0, 0.0),
            force: V2::new(-press, 0.0),
        }],
        gravity: V2::new(0.0, -9.81),
    }
}

// The slider-crank: a mass on the block, a press load along the guide.
#[test]
fn slider_crank_matches_the_global_formulation() {
    let (m, model) = (SliderCrank::<f64>::default(), slider_crank(300.0));
    let loads = SliderCrankLoads { press: 300.0 };
    let mut rng = Rng(0x5eed_0002);
    let mut worst = Worst::default();
    for _ in 0..DRAWS {
        let (q, w, t) = (
            rng.range(-4.0, 4.0),
            rng.range(-100.0, 100.0),
            rng.range(-5.0, 5.0),
        );
        let pos = m.position(&SliderCrankInput { theta: q }).unwrap();
        let d = m
            .dynamics(
                &pos,
                &SliderCrankInput { theta: w },
                &SliderCrankInput { theta: t },
                &loads,
            )
            .unwrap();
        let start = [[0.0, 0.0, q], frame(pos.A, pos.B), [pos.B.x, pos.B.y, 0.0]];
        worst.add(
            "SliderCrank",
            compare(
                "SliderCrank",
                &model,
                [&[q], &[w], &[t]],
                (&[d.accels.theta], &[&d.mass[0]]),
                [&d.velocity_terms, &d.generalized_forces],
                &start,
            ),
        );
    }
    worst.show();
}

fn stephenson() -> Model {
    let (link6, crank2, rocker, link5, coupler) = (0, 1, 2, 3, 4);
    Model {
        bodies: vec![
            vec![part(0.9, on(link6, 0.12, 0.0), 4.3e-3)],
            vec![part(0.4, on(crank2, 0.04, 0.0), 2.2e-4)],
            vec![part(0.8, on(rocker, 0.10, 0.0), 2.7e-3)],
            vec![part(1.0, on(link5, 0.14, 0.0), 6.5e-3)],
            vec![part(1.2, on(coupler, 0.13, 0.03), 7.5e-3)],
        ],
        joints: vec![
            pin(on(link6, 0.0, 0.0), Anchor::ground(0.05, 0.42)),
            pin(on(crank2, 0.0, 0.0), Anchor::ground(0.0, 0.0)),
            pin(on(rocker, 0.0, 0.0), Anchor::ground(0.30, 0.0)),
            pin(on(link6, 0.24, 0.0), on(link5, 0.0, 0.0)),
            pin(on(crank2, 0.08, 0.0), on(coupler, 0.0, 0.0)),
            pin(on(rocker, 0.20, 0.0), on(coupler, 0.26, 0.0)),
            pin(on(link5, 0.28, 0.0), Anchor::polar(coupler, 0.15, 40.0)),
        ],
        inputs: vec![angle(link6, None)],
        loads: vec![],
        gravity: V2::new(0.0, -9.81),
    }
}

// The Stephenson III six-bar: the ternary link on three legs (a triad).
#[test]
fn triad_matches_the_global_formulation() {
    let (m, model) = (Stephenson::<f64>::default(), stephenson());
    let mut rng = Rng(0x5eed_0003);
    let mut worst = Worst::default();
    for _ in 0..DRAWS {
        let q = rng.range(-50.0f64.to_radians(), -3.0f64.to_radians());
        let (w, t) = (rng.range(-5.0, 5.0), rng.range(-1.0, 1.0));
        let pos = m.position(&StephensonInput { phi: q }).unwrap();
        let d = m
            .dynamics(
                &pos,
                &StephensonInput { phi: w },
                &StephensonInput { phi: t },
            )
            .unwrap();
        let start = [
            [0.05, 0.42, q],
            frame(pos.O2, pos.A),
            frame(pos.O4, pos.B),
            frame(pos.C, pos.P),
            frame(pos.A, pos.B),
        ];
        worst.add(
            "Stephenson",
            compare(
                "Stephenson",
                &model,
                [&[q], &[w], &[t]],
                (&[d.accels.phi], &[&d.mass[0]]),
                [&d.velocity_terms, &d.generalized_forces],
                &start,
            ),
        );
    }
    worst.show();
}

fn leg() -> Model {
    let (thigh, shank) = (0, 1);
    Model {
        bodies: vec![
            vec![part(2.0, on(thigh, 0.18, 0.0), 0.03)],
            vec![
                part(1.2, on(shank, 0.16, 0.0), 0.015),
                part(0.3, on(shank, 0.38, 0.0), 0.0),
            ],
        ],
        joints: vec![
            pin(on(thigh, 0.0, 0.0), Anchor::ground(0.0, 0.0)),
            pin(on(thigh, 0.40, 0.0), on(shank, 0.0, 0.0)),
        ],
        inputs: vec![angle(thigh, None), angle(shank, Some(thigh))],
        loads: vec![],
        gravity: V2::new(0.0, -9.81),
    }
}

// The 2R leg: the knee motor is carried by the thigh (its torque reacts on it).
#[test]
fn carried_motor_matches_the_global_formulation() {
    let (m, model) = (Leg::<f64>::default(), leg());
    let mut rng = Rng(0x5eed_0004);
    let mut worst = Worst::default();
    for _ in 0..DRAWS {
        let q = [rng.range(-2.5, -0.5), rng.range(0.2, 2.5)];
        let w = [rng.range(-6.0, 6.0), rng.range(-6.0, 6.0)];
        let t = [rng.range(-30.0, 30.0), rng.range(-30.0, 30.0)];
        let pos = m
            .position(&LegInput {
                hip: q[0],
                knee: q[1],
            })
            .unwrap();
        let d = m
            .dynamics(
                &pos,
                &LegInput {
                    hip: w[0],
                    knee: w[1],
                },
                &LegInput {
                    hip: t[0],
                    knee: t[1],
                },
            )
            .unwrap();
        let start = [[0.0, 0.0, q[0]], [pos.K.x, pos.K.y, q[0] + q[1]]];
        let got = [d.accels.hip, d.accels.knee];
        worst.add(
            "Leg",
            compare(
                "Leg",
                &model,
                [&q, &w, &t],
                (&got, &[&d.mass[0], &d.mass[1]]),
                [&d.velocity_terms, &d.generalized_forces],
                &start,
            ),
        );
    }
    worst.show();
}

fn boom() -> Model {
    let (boom, barrel, rod) = (0, 1, 2);
    Model {
        bodies: vec![
            vec![
                part(1800.0, Anchor::polar(boom, 2.5, 8.0), 4500.0),
                part(600.0, on(boom, 5.0, 0.0), 0.0),
            ],
            vec![part(220.0, on(barrel, 0.6, 0.0), 30.0)],
            vec![part(140.0, on(rod, -0.5, 0.0), 18.0)],
        ],
        joints: vec![
            pin(on(boom, 0.0, 0.0), Anchor::ground(0.0, 0.0)),
            pin(on(barrel, 0.0, 0.0), Anchor::ground(0.8, -0.9)),
            pin(on(rod, 0.0, 0.0), on(boom, 2.2, 0.0)),
            Joint::Prismatic {
                a: on(rod, 0.0, 0.0),
                b: on(barrel, 0.0, 0.0),
                dir: Dd::ZERO,
                lock: Dd::ZERO,
            },
        ],
        inputs: vec![Input::Distance(on(rod, 0.0, 0.0), on(barrel, 0.0, 0.0))],
        loads: vec![],
        gravity: V2::new(0.0, -9.81),
    }
}

// The boom lifted by a cylinder whose barrel and rod carry mass.
#[test]
fn actuator_with_masses_matches_the_global_formulation() {
    let (m, model) = (Boom::<f64>::default(), boom());
    let mut rng = Rng(0x5eed_0005);
    let mut worst = Worst::default();
    for _ in 0..DRAWS {
        let (q, w, t) = (
            rng.range(2.0, 2.9),
            rng.range(-0.5, 0.5),
            rng.range(-1.0e5, 1.0e5),
        );
        let pos = m.position(&BoomInput { len: q }).unwrap();
        let d = m
            .dynamics(&pos, &BoomInput { len: w }, &BoomInput { len: t })
            .unwrap();
        let b_to_c = frame(pos.B, pos.C);
        let start = [frame(pos.A, pos.C), b_to_c, [pos.C.x, pos.C.y, b_to_c[2]]];
        worst.add(
            "Boom",
            compare(
                "Boom",
                &model,
                [&[q], &[w], &[t]],
                (&[d.accels.len], &[&d.mass[0]]),
                [&d.velocity_terms, &d.generalized_forces],
                &start,
            ),
        );
    }
    worst.show();
}

fn five_bar_ik() -> Model {
    let (arm1, forearm1, arm2, forearm2, effector) = (0, 1, 2, 3, 4);
    Model {
        bodies: vec![
            vec![part(0.12, on(arm1, 0.05, 0.0), 1.1e-4)],
            vec![part(0.09, on(forearm1, 0.08, 0.0), 2.0e-4)],
            vec![part(0.12, on(arm2, 0.05, 0.0), 1.1e-4)],
            vec![part(0.09, on(forearm2, 0.08, 0.0), 2.0e-4)],
            vec![part(0.05, on(effector, 0.0, 0.0), 0.0)],
        ],
        joints: vec![
            pin(on(arm1, 0.0, 0.0), Anchor::ground(0.0, 0.0)),
            pin(on(arm1, 0.1, 0.0), on(forearm1, 0.0, 0.0)),
            pin(on(forearm1, 0.16, 0.0), on(effector, 0.0, 0.0)),
            pin(on(arm2, 0.0, 0.0), Anchor::ground(0.08, 0.0)),
            pin(on(arm2, 0.1, 0.0), on(forearm2, 0.0, 0.0)),
            pin(on(forearm2, 0.16, 0.0), on(effector, 0.0, 0.0)),
            Joint::Locked {
                a: Some(effector),
                b: None,
                angle: Dd::ZERO,
            },
        ],
        inputs: vec![
            Input::Along {
                at: on(effector, 0.0, 0.0),
                origin: V2::default(),
                dir: V2::new(1.0, 0.0),
            },
            Input::Along {
                at: on(effector, 0.0, 0.0),
                origin: V2::default(),
                dir: V2::new(0.0, 1.0),
            },
        ],
        loads: vec![Load::Force {
            at: on(effector, 0.0, 0.0),
            force: V2::new(1.5, -4.0),
        }],
        gravity: V2::new(0.0, -9.81),
    }
}

// The five-bar given its end point: the effector translates with the
// target, the motors' links follow (inverse kinematics inside the dynamics).
#[test]
fn five_bar_given_its_end_point_matches_the_global_formulation() {
    let (m, model) = (FiveBarIk::<f64>::default(), five_bar_ik());
    let mut rng = Rng(0x5eed_0006);
    let mut worst = Worst::default();
    for _ in 0..DRAWS {
        let q = [rng.range(0.0, 0.08), rng.range(0.16, 0.22)];
        let w = [rng.range(-0.5, 0.5), rng.range(-0.5, 0.5)];
        let t = [rng.range(-10.0, 10.0), rng.range(-10.0, 10.0)];
        let pos = m.position(&FiveBarIkInput { x: q[0], y: q[1] }).unwrap();
        let d = m
            .dynamics(
                &pos,
                &FiveBarIkInput { x: w[0], y: w[1] },
                &FiveBarIkInput { x: t[0], y: t[1] },
            )
            .unwrap();
        let start = [
            frame(pos.O1, pos.A),
            frame(pos.A, pos.P),
            frame(pos.O2, pos.C),
            frame(pos.C, pos.P),
            [pos.P.x, pos.P.y, 0.0],
        ];
        let got = [d.accels.x, d.accels.y];
        worst.add(
            "FiveBarIk",
            compare(
                "FiveBarIk",
                &model,
                [&q, &w, &t],
                (&got, &[&d.mass[0], &d.mass[1]]),
                [&d.velocity_terms, &d.generalized_forces],
                &start,
            ),
        );
    }
    worst.show();
}

fn five_bar_fk() -> Model {
    let (arm1, arm2, forearm1, forearm2) = (0, 1, 2, 3);
    Model {
        bodies: vec![
            vec![part(0.12, on(arm1, 0.05, 0.0), 1.1e-4)],
            vec![part(0.12, on(arm2, 0.05, 0.0), 1.1e-4)],
            vec![
                part(0.09, on(forearm1, 0.08, 0.0), 2.0e-4),
                part(0.05, on(forearm1, 0.16, 0.0), 0.0),
            ],
            vec![part(0.09, on(forearm2, 0.08, 0.0), 2.0e-4)],
        ],
        joints: vec![
            pin(on(arm1, 0.0, 0.0), Anchor::ground(0.0, 0.0)),
            pin(on(arm2, 0.0, 0.0), Anchor::ground(0.08, 0.0)),
            pin(on(arm1, 0.1, 0.0), on(forearm1, 0.0, 0.0)),
            pin(on(arm2, 0.1, 0.0), on(forearm2, 0.0, 0.0)),
            pin(on(forearm1, 0.16, 0.0), on(forearm2, 0.16, 0.0)),
        ],
        inputs: vec![angle(arm1, None), angle(arm2, None)],
        loads: vec![],
        gravity: V2::new(0.0, -9.81),
    }
}

// The five-bar given its motors (two ground cranks closing one loop).
#[test]
fn five_bar_given_its_motors_matches_the_global_formulation() {
    let (m, model) = (FiveBarFk::<f64>::default(), five_bar_fk());
    let mut rng = Rng(0x5eed_0007);
    let mut worst = Worst::default();
    for _ in 0..DRAWS {
        let q = [rng.range(1.6, 2.0), rng.range(1.1, 1.5)];
        let w = [rng.range(-5.0, 5.0), rng.range(-5.0, 5.0)];
        let t = [rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)];
        let pos = m.position(&FiveBarFkInput { q1: q[0], q2: q[1] }).unwrap();
        let d = m
            .dynamics(
                &pos,
                &FiveBarFkInput { q1: w[0], q2: w[1] },
                &FiveBarFkInput { q1: t[0], q2: t[1] },
            )
            .unwrap();
        let start = [
            [0.0, 0.0, q[0]],
            [0.08, 0.0, q[1]],
            frame(pos.A, pos.P),
            frame(pos.C, pos.P),
        ];
        let got = [d.accels.q1, d.accels.q2];
        worst.add(
            "FiveBarFk",
            compare(
                "FiveBarFk",
                &model,
                [&q, &w, &t],
                (&got, &[&d.mass[0], &d.mass[1]]),
                [&d.velocity_terms, &d.generalized_forces],
                &start,
            ),
        );
    }
    worst.show();
}

// Proves the comparison can fail: the reference with the four-bar's rocker
// 1 % heavier disagrees with the generated `q''` far beyond the tolerance.
#[test]
fn a_wrong_mass_is_seen() {
    let m = FourBar::<f64>::default();
    let mut model = four_bar();
    model.bodies[2][0].mass *= 1.01;
    let (q, w, t) = (0.7, 12.0, 0.5);
    let pos = m.position(&FourBarInput { phi: q }).unwrap();
    let d = m
        .dynamics(&pos, &FourBarInput { phi: w }, &FourBarInput { phi: t })
        .unwrap();
    let start = [[0.0, 0.0, q], frame(pos.A, pos.B), frame(pos.O4, pos.B)];
    let r = forward(&model, &[q], &[w], &[t], &start).unwrap();
    let rel = (d.accels.phi - r.accels[0].to_f64()).abs() / d.accels.phi.abs();
    assert!(rel > 1e-4, "{rel:e}");
}
