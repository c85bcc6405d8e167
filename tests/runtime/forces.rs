//! The run-time force analysis (`Mechanism::forces`) against the generated
//! `forces()`: every reaction, driving effort, `condition` and
//! `power_residual`, by the name the generated struct's `Fields` gives it,
//! is the same `f64`, bit for bit, at random inputs, rates, accelerations
//! and load values; a failing pose fails with the same typed error. Both
//! accumulate the same loads with the same operations in the same order and
//! call the same `mechanism::force` primitive per group, so nothing looser
//! is expected. Covered: masses given by params and literals, several
//! masses per link, gravity, external forces and couples from `loads`, a
//! carried crank, a triad, an RPR, an RRP, an RPP, and (`force_kinds`) a
//! slider, a PRP on a carried guide, both forms of the actuator, the gear
//! pair on the ground and on a carrier; the motors of an inverse kinematics
//! (the rate map from two velocity evaluations).

use super::agreement::{field, Rng};
use super::text::definition;
use mechanism::structure::Fields;
use mechanism_codegen::runtime::Mechanism;

/// Poses tried per definition.
const POSES: usize = 300;

/// Asserts the run-time forces `got` equal the generated struct's, by name.
fn same<S: Fields<f64>>(what: &str, m: &Mechanism, got: &[f64], s: &S) {
    let cols = m.force_columns();
    assert_eq!(cols.len(), got.len(), "{what}");
    for (c, &g) in cols.iter().zip(got) {
        let want = field(s, &c.name);
        assert_eq!(
            g.to_bits(),
            want.to_bits(),
            "{what}: forces `{}`: run time {g:e}, generated {want:e}",
            c.name
        );
    }
}

/// Compares the forces of definition `$ty` of `$file` at random poses in
/// the inputs' ranges (`$lo..$hi` without one), rates and accelerations in
/// [-10, 10] and each load `$load` uniform in `[-$span, $span]`. Returns
/// (poses compared with forces, poses whose forces failed alike).
macro_rules! compare_forces {
    ($file:literal, $ty:ident, $input:ident { $($i:ident),* }, $lo:expr, $hi:expr,
     $loads:ident { $($load:ident),* }, $span:expr) => {{
        let source = include_str!($file);
        let name = stringify!($ty);
        let text = definition(source, name);
        #[allow(unused_mut)] // set_load needs it where the definition has loads
        let mut m = Mechanism::new(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(m.has_forces(), "{name}");
        let ranges: Vec<(f64, f64)> = m
            .inputs()
            .iter()
            .map(|i| i.range.unwrap_or(($lo, $hi)))
            .collect();
        let g = <$ty>::default();
        let mut rng = Rng(0xF0C5 ^ name.len() as u64);
        let make = |v: &[f64]| {
            let mut it = v.iter().copied();
            $input { $($i: it.next().unwrap()),* }
        };
        let (mut solved, mut failed) = (0, 0);
        for _ in 0..POSES {
            let q: Vec<f64> = ranges.iter().map(|&(lo, hi)| rng.within(lo, hi)).collect();
            let qd: Vec<f64> = q.iter().map(|_| rng.within(-10.0, 10.0)).collect();
            let qdd: Vec<f64> = q.iter().map(|_| rng.within(-10.0, 10.0)).collect();
            let loads = $loads { $($load: rng.within(-$span, $span)),* };
            $(m.set_load(stringify!($load), loads.$load).unwrap();)*
            let what = format!("{name} at {q:?}, rates {qd:?}, accels {qdd:?}, loads {loads:?}");
            let (Ok(rp), Ok(gp)) = (m.position(&q), g.position(&make(&q))) else {
                continue;
            };
            let (Ok(rv), Ok(gv)) = (m.velocity(&rp, &qd), g.velocity(&gp, &make(&qd))) else {
                continue;
            };
            let (Ok(ra), Ok(ga)) = (
                m.acceleration(&rp, &rv, &qdd),
                g.acceleration(&gp, &gv, &make(&qdd)),
            ) else {
                continue;
            };
            match (m.forces(&rp, &rv, &ra), compare_forces!(@call g, gp, gv, ga, loads, $loads)) {
                (Ok(r), Ok(f)) => {
                    same(&what, &m, &r.values, &f);
                    assert_eq!(r.condition.to_bits(), f.condition.to_bits(), "{what}");
                    assert_eq!(r.power_residual.to_bits(), f.power_residual.to_bits(), "{what}");
                    solved += 1;
                }
                (Err(a), Err(b)) => {
                    assert_eq!(a, b, "{what}: force errors");
                    failed += 1;
                }
                (r, f) => panic!("{what}: forces: run time {:?}, generated {:?}", r.err(), f.err()),
            }
        }
        eprintln!("{name}: forces compared at {solved} poses, failed alike at {failed}");
        (solved, failed)
    }};
    (@call $g:ident, $p:ident, $v:ident, $a:ident, $l:ident, NoLoads) => {
        $g.forces(&$p, &$v, &$a)
    };
    (@call $g:ident, $p:ident, $v:ident, $a:ident, $l:ident, $loads:ident) => {
        $g.forces(&$p, &$v, &$a, &$l)
    };
}

/// The load values of a definition without a `loads` block.
#[derive(Debug)]
struct NoLoads {}

#[test]
fn sine_mechanism_params_masses() {
    use super::agreement::scenes::{SineMechanism, SineMechanismInput};
    let (solved, _) = compare_forces!(
        "../../examples/common/scenes.rs",
        SineMechanism,
        SineMechanismInput { phi1 },
        0.0,
        1.0,
        NoLoads {},
        0.0
    );
    assert!(solved > POSES / 2, "{solved}");
}

#[test]
fn shaper_with_gravity_inertia_and_cutting_load() {
    use super::agreement::scenes::{ShaperForces, ShaperForcesInput, ShaperForcesLoads};
    let (solved, _) = compare_forces!(
        "../../examples/common/scenes.rs",
        ShaperForces,
        ShaperForcesInput { crank },
        0.0,
        1.0,
        ShaperForcesLoads { cut },
        2000.0
    );
    assert!(solved > POSES / 2, "{solved}");
}

#[test]
fn five_bar_inverse_kinematics_motors() {
    use super::agreement::scenes::{FiveBarIk, FiveBarIkInput};
    let (solved, _) = compare_forces!(
        "../../examples/common/scenes.rs",
        FiveBarIk,
        FiveBarIkInput { x, y },
        0.0,
        0.25,
        NoLoads {},
        0.0
    );
    assert!(solved > 0, "{solved}");
}

#[test]
fn stephenson_triad_with_a_load_at_p() {
    use super::agreement::stephenson::{Stephenson, StephensonInput, StephensonLoads};
    let (solved, _) = compare_forces!(
        "../../examples/common/stephenson.rs",
        Stephenson,
        StephensonInput { phi },
        0.0,
        1.0,
        StephensonLoads { fp },
        50.0
    );
    assert!(solved > 0, "{solved}");
}

#[test]
fn two_r_leg_carried_crank_with_a_foot_force() {
    use super::agreement::leg::{Leg, LegInput, LegLoads};
    let (solved, _) = compare_forces!(
        "../../examples/common/leg.rs",
        Leg,
        LegInput { hip, knee },
        -3.0,
        3.0,
        LegLoads { fx, fy },
        500.0
    );
    assert_eq!(solved, POSES, "an open chain always assembles");
}

/// A definition without a force analysis: no force columns, and `forces`
/// is a typed error rather than numbers.
#[test]
fn without_masses_there_is_no_force_analysis() {
    let m = Mechanism::new(
        "let O2 = ground(0.0, 0.0);
         let O4 = ground(3.0, 0.0);
         let A = crank(O2, 1.0, theta) as link2;
         let B = rrr(A, 3.0, O4, 2.5, left) as (link3, link4);",
    )
    .unwrap();
    assert!(!m.has_forces());
    assert!(m.force_columns().is_empty());
    let p = m.position(&[0.3]).unwrap();
    let v = m.velocity(&p, &[1.0]).unwrap();
    let a = m.acceleration(&p, &v, &[0.0]).unwrap();
    assert!(m.forces(&p, &v, &a).is_err());
}

#[test]
fn slider_driver_and_an_external_couple() {
    use super::force_kinds::{SliderRocker, SliderRockerInput};
    let (solved, _) = compare_forces!(
        "force_kinds.rs",
        SliderRocker,
        SliderRockerInput { s },
        0.0,
        1.0,
        NoLoads {},
        0.0
    );
    assert!(solved > POSES / 2, "{solved}");
}

#[test]
fn prp_on_a_carried_guide() {
    use super::force_kinds::{CrossForces, CrossForcesInput};
    let (solved, _) = compare_forces!(
        "force_kinds.rs",
        CrossForces,
        CrossForcesInput { theta },
        0.0,
        1.0,
        NoLoads {},
        0.0
    );
    assert!(solved > POSES / 2, "{solved}");
}

#[test]
fn two_name_actuator() {
    use super::force_kinds::{ArmForces, ArmForcesInput};
    let (solved, _) = compare_forces!(
        "force_kinds.rs",
        ArmForces,
        ArmForcesInput { len },
        0.0,
        1.0,
        NoLoads {},
        0.0
    );
    assert!(solved > POSES / 2, "{solved}");
}

#[test]
fn cylinder_with_barrel_and_rod_masses() {
    use super::force_kinds::{BoomForces, BoomForcesInput};
    let (solved, _) = compare_forces!(
        "force_kinds.rs",
        BoomForces,
        BoomForcesInput { len },
        0.0,
        1.0,
        NoLoads {},
        0.0
    );
    assert!(solved > POSES / 2, "{solved}");
}

#[test]
fn gear_pair_on_the_ground_and_on_a_carrier() {
    // The gear's run-time forces (its tooth force passed to the crank, the
    // pivot force to the ground or to the carrying arm) against the
    // generated ones, bit for bit.
    use super::force_kinds::{GearForces, GearForcesInput, PlanetForces, PlanetForcesInput};
    let (solved, _) = compare_forces!(
        "force_kinds.rs",
        GearForces,
        GearForcesInput { theta },
        0.0,
        1.0,
        NoLoads {},
        0.0
    );
    assert!(solved > POSES / 4, "{solved}");
    let (solved, failed) = compare_forces!(
        "force_kinds.rs",
        PlanetForces,
        PlanetForcesInput { theta },
        0.0,
        1.0,
        NoLoads {},
        0.0
    );
    assert_eq!((solved, failed), (POSES, 0));
}

/// Proves a mass or moment of inertia given by a parameter and set out of
/// range at run time fails the run-time forces with the generated code's
/// typed error (same group, same fault, same quantity named), the first
/// one its checks meet when several are bad, and that the analysis works
/// again once the parameter is valid.
#[test]
fn masses_set_out_of_range_fail_as_the_generated_checks() {
    use super::agreement::scenes::{ShaperForces, ShaperForcesInput, ShaperForcesLoads};
    let text = definition(
        include_str!("../../examples/common/scenes.rs"),
        "ShaperForces",
    );
    let mut m = Mechanism::new(&text).unwrap();
    let input = |x| ShaperForcesInput { crank: x };
    let loads = ShaperForcesLoads { cut: 0.0 };
    let bad: [&[(&str, f64)]; 6] = [
        &[("m3", -1.0)],
        &[("j3", -0.5)],
        &[("m4", 0.0)],
        &[("m5", -2.0), ("j4", -1.0)],
        &[("j4", -1.0), ("m3", -3.0)],
        &[("m3", 0.0), ("j3", -1.0)],
    ];
    for set in bad {
        let mut g = ShaperForces::<f64>::default();
        for &(name, value) in set {
            m.set_param(name, value).unwrap();
            match name {
                "m3" => g.m3 = value,
                "j3" => g.j3 = value,
                "m4" => g.m4 = value,
                "j4" => g.j4 = value,
                _ => g.m5 = value,
            }
        }
        let (gp, rp) = (
            g.position(&input(0.7)).unwrap(),
            m.position(&[0.7]).unwrap(),
        );
        let gv = g.velocity(&gp, &input(3.0)).unwrap();
        let rv = m.velocity(&rp, &[3.0]).unwrap();
        let ga = g.acceleration(&gp, &gv, &input(1.0)).unwrap();
        let ra = m.acceleration(&rp, &rv, &[1.0]).unwrap();
        let want = g.forces(&gp, &gv, &ga, &loads).expect_err("a bad mass");
        let got = m.forces(&rp, &rv, &ra).expect_err("a bad mass");
        assert_eq!(got, want, "{set:?}");
        for &(name, _) in set {
            let valid = ShaperForces::<f64>::default();
            let value = match name {
                "m3" => valid.m3,
                "j3" => valid.j3,
                "m4" => valid.m4,
                "j4" => valid.j4,
                _ => valid.m5,
            };
            m.set_param(name, value).unwrap();
        }
        assert!(m.forces(&rp, &rv, &ra).is_ok(), "{set:?} restored");
    }
}
