//! Planar linkage analysis generated per mechanism.
//!
//! The [`mechanism!`] macro reads a declarative definition of a planar
//! linkage (points, links, Assur groups, dimensions, masses, loads) and
//! generates specialized, allocation-free, `no_std` code for that one
//! mechanism: position, velocity and acceleration analysis, and the force
//! analysis (joint reactions and the driving torque or force) when the
//! definition gives masses and loads, generic over `f32` and `f64`. A
//! definition that does not make sense, or that cannot move over its input
//! range, is a compile error on the offending name.
//!
//! A crank-rocker four-bar at a crank angle of 60 deg, with
//! the path of its coupler point `P` over a turn, as
//! [`mechanism-plot`](https://docs.rs/mechanism-plot) draws any definition:
//!
#![doc = include_str!("../docs/fourbar-drawing.svg")]
//!
//! # Quick start
//!
//! In `Cargo.toml` (the package is `planar-mechanism`, the library
//! `mechanism`):
//!
//! ```toml
//! [dependencies]
//! planar-mechanism = "0.1"
//! mechanism-plot = "0.1"      # optional: pictures, charts and CSV tables
//! ```
//!
//! A crank-rocker four-bar with a coupler point, its position and velocity at
//! one crank angle:
//!
//! ```
//! use mechanism::mechanism;
//!
//! mechanism! {
//!     /// Crank-rocker four-bar with a coupler point P (mm).
//!     pub FourBar {
//!         params { ground = 304.8, crank = 101.6, coupler = 254.0, rocker = 177.8 }
//!         let O2 = ground(0.0, 0.0);
//!         let O4 = ground(ground, 0.0);
//!         let A = crank(O2, crank, theta2) as link2;
//!         let B = rrr(A, coupler, O4, rocker, left) as (link3, link4);
//!         let P = point(link3, from A, 120.0, 30 deg);
//!     }
//! }
//!
//! fn main() -> Result<(), mechanism::Error> {
//!     let fb = FourBar::<f64>::default();                     // parameters at their literal values
//!     let input = FourBarInput { theta2: 0.5 };
//!     let p = fb.position(&input)?;                           // p.B, p.P: Point2; p.link3: angle (rad)
//!     let v = fb.velocity(&p, &FourBarInput { theta2: 250.0 })?;   // v.link3: rad/s, v.P: mm/s
//!     println!("B = ({:.3}, {:.3}) mm, theta3 = {:.3} deg, omega3 = {:.3} rad/s",
//!         p.B.x, p.B.y, p.link3.to_degrees(), v.link3);
//!     # assert_eq!(format!("{:.3} {:.3} {:.3} {:.3}", p.B.x, p.B.y, p.link3.to_degrees(), v.link3),
//!     #     "307.929 177.772 30.539 -101.971");
//!     Ok(())
//! }
//! ```
//!
//! prints
//!
//! ```text
//! B = (307.929, 177.772) mm, theta3 = 30.539 deg, omega3 = -101.971 rad/s
//! ```
//!
//! The types this definition generates (`FourBar`, `FourBarInput`,
//! `FourBarPosition`, ...) are shown, with their documentation, in the
//! [`example`] module. The language (drivers, the five groups, points on
//! links, masses and loads, analyses, outputs, ranges) is described on the
//! page of the [`mechanism!`] macro.
//!
//! # As drawn, and inverse kinematics
//!
//! A definition may also say the mechanism as it is drawn: the joints at one
//! pose, the links as sets of joints, the inputs. The macro finds the groups
//! and reads every length and assembly from the drawing. Making a joint's
//! coordinates the inputs gives the inverse kinematics: a five-bar robot
//! given its end point, its motor angles, rates and the torques that hold a
//! 2 N payload:
//!
//! ```
//! use mechanism::mechanism;
//!
//! mechanism! {
//!     /// A five-bar robot given its end point (m, N).
//!     pub Robot {
//!         joints {
//!             O1 = (0.0, 0.0),
//!             O2 = (0.08, 0.0),
//!             A = (-0.017364817766693034885, 0.098480775301220805937),
//!             C = (0.15071067811865475244, 0.07071067811865475244),
//!             P = (0.088752052427120438854, 0.2182272151659171658),
//!         }
//!         links { ground = [O1, O2], arm1 = [O1, A], arm2 = [O2, C], fore1 = [A, P], fore2 = [C, P] }
//!         input x = P.x;                          // the end point is the input
//!         input y = P.y;
//!         motor q1 = angle(arm1);                 // the motors that hold it
//!         motor q2 = angle(arm2);
//!         force at P on P_effector = (0.0, -2.0); // a 2 N payload
//!     }
//! }
//!
//! fn main() -> Result<(), mechanism::Error> {
//!     let robot = Robot::<f64>::default();
//!     let (p, v, a) = (RobotInput { x: 0.04, y: 0.2 }, RobotInput { x: 0.1, y: 0.0 }, RobotInput { x: 0.0, y: 0.0 });
//!     let s = robot.solve(&p, &v, &a)?;
//!     let f = robot.forces(&s.position, &s.velocity, &s.acceleration)?;
//!     let (q1, q2) = (s.position.arm1, s.position.arm2);
//!     println!("q1 = {:.3} deg, q2 = {:.3} deg, rates {:.4} and {:.4} rad/s, torques {:.4} and {:.4} N m",
//!         q1.to_degrees(), q2.to_degrees(), s.velocity.arm1, s.velocity.arm2, f.drive_q1, f.drive_q2);
//!     // The end point is on the robot's axis of symmetry: the motors mirror each other.
//!     assert!((q1 + q2 - core::f64::consts::PI).abs() < 1e-14);
//!     assert!((f.drive_q1 + f.drive_q2).abs() < 1e-15);
//!     Ok(())
//! }
//! ```
//!
//! The [`mechanism!`] page ("Say it as drawn") has the whole drawn
//! language: blocks in slots, cylinders, motors on moving links.
//!
//! # Pictures
//!
//! [`mechanism-plot`](https://docs.rs/mechanism-plot) (a separate crate, std)
//! reads a definition's description of itself: `mechanism_plot::any::sketch`
//! draws it at one pose or animates it over its input, `chart` plots any
//! outputs against the input, `csv` tabulates them, with the definition's
//! units.
//!
//! # Conventions
//!
//! Lengths in the user's unit L throughout (results scale with it); angles in
//! radians from +x, counter-clockwise positive; rates per second. Every
//! generated function returns `Result<_, `[`Error`]`>`: an input at which a
//! group cannot be assembled, or a singular rate or force system, is a typed
//! error naming the group; no `Ok` holds NaN or infinity, and nothing panics.
//!
//! # Features
//!
//! - `rayon`: `par_solve`, a generated batch split over rayon's thread pool
//!   (needs `std`).
//! - `serde`: `Serialize` for the core's results, errors and check reports
//!   (and `Deserialize` where the type owns its data), `no_std` compatible;
//!   a definition written with `#[derive(serde::Serialize,
//!   serde::Deserialize)]` gets them for its generated types too (the
//!   mechanism's page, "Attributes").
//!
//! Without features the crate is `#![no_std]` and allocates nothing.
#![no_std]
#![forbid(unsafe_code)]
#![cfg_attr(docsrs, feature(doc_cfg))]

// Generated code names this crate `::mechanism`; inside the crate itself
// (the `example` module) that path needs this alias.
extern crate self as mechanism;

pub use mechanism_core as core_api;
// Everything the core exports, for the generated code (which names the
// core's modules through `::mechanism::`), including the kernels and
// machinery (`lane`, `scalar`, `sincos64`, `sweep`, `trig64`) that are public
// so that it can call them but are not part of the documented API ...
#[doc(hidden)]
pub use mechanism_core::*;
// ... and, shadowing those, the documented API.
#[cfg(feature = "dual")]
#[cfg_attr(docsrs, doc(cfg(feature = "dual")))]
pub use mechanism_core::dual;
pub use mechanism_core::{
    driver, dyad, error, force, geometry, guide, link, linsolve, mode, structure, triad, trig,
};
pub use mechanism_core::{Error, Fault, Mode, Point2, Primitive, Real, Vector2};
// What the generated `check()` returns (from the core's sweep).
pub use mechanism_core::sweep::{Event, GroupReport, Range, Report};

/// The [`mechanism!`] macro (see its page for the language).
pub use mechanism_macros::mechanism;

pub mod batch;
#[cfg(feature = "rayon")]
mod par;
pub use batch::{BatchError, BatchSplit};
#[cfg(feature = "rayon")]
#[cfg_attr(docsrs, doc(cfg(feature = "rayon")))]
pub use par::{
    par_solve, par_task_ns, PAR_PIECES_PER_THREAD, PAR_PROBE, PAR_TASK_NS, PAR_TASK_NS_RANGE,
};

pub mod example;

#[doc(hidden)]
#[path = "interop.rs"]
pub mod __interop;

#[cfg(feature = "alloc")]
extern crate alloc;

/// `alloc` for the owned batch form of the generated code (inside
/// `__with_alloc!`, feature `alloc`; see [`batch`]). Not public API.
#[cfg(feature = "alloc")]
#[doc(hidden)]
pub mod __alloc {
    pub use alloc::vec::Vec;
}
