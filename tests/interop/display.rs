//! `Display` of the generated result structs, against strings worked out by
//! hand: each number below comes from the geometry stated beside it, not
//! from running the code.

use mechanism::mechanism;

mechanism! {
    /// A crank of radius 1 carrying a point mass of 2 at its tip, under
    /// gravity 10 downwards.
    pub Crank {
        outputs { A, link2 }
        let O = ground(0.0, 0.0);
        let A = crank(O, 1.0, th) as link2;
        mass link2 { m = 2.0, at = A };
        gravity (0.0, -10.0);
    }
}

mechanism! {
    /// A parallelogram four-bar: pivots O2 = (0, 0) and O4 = (3, 4), crank
    /// and rocker 1, coupler 5 (= |O4 - O2|), closed on the parallelogram
    /// side (B = A + (3, 4)): right of A -> O4 for crank angles from 0 to
    /// atan2(4, 3) = 53.1 deg, where cross(O4 - A, B - A) = 3 sin - 4 cos < 0.
    pub Parallelogram {
        outputs { B, link4 }
        let O2 = ground(0.0, 0.0);
        let O4 = ground(3.0, 4.0);
        let A = crank(O2, 1.0, th) as link2;
        let B = rrr(A, 5.0, O4, 1.0, right) as (link3, link4);
        range th = (0 deg, 50 deg);
    }
}

// Proves each struct's line (label, names, units, order) and the solution's
// four lines, for the crank at 60 deg turning at 1 rad/s: A = (cos 60,
// sin 60) = (0.500, 0.866), v_A = w k x A = (-0.866, 0.500), a_A = -w^2 A =
// (-0.500, -0.866); the ground holds the weight (0, -20) and the inertia
// force -m a_A = (1.000, 1.732): r = (-1.000, 20 - 1.732 = 18.268); the
// driving torque balances the weight's moment about O, -(0.5 * -20) =
// 10.000 (the inertia force passes through O); no group: condition 1; a
// consistent balance: residual 0.
#[test]
fn each_struct_one_line_and_the_solution_four() {
    let crank = Crank::<f64>::default();
    let th = 60f64.to_radians();
    let s = crank
        .solve(
            &CrankInput { th },
            &CrankInput { th: 1.0 },
            &CrankInput { th: 0.0 },
        )
        .unwrap();
    let lines = [
        "position: A = (0.500, 0.866) L, link2 = 1.047 rad",
        "velocity: A = (-0.866, 0.500) L/s, link2 = 1.000 rad/s, condition = 1.000",
        "acceleration: A = (-0.500, -0.866) L/s^2, link2 = 0.000 rad/s^2",
        "forces: r_ground_link2 = (-1.000, 18.268) F, drive_th = 10.000 F L, condition = 1.000, power_residual = 0.000",
    ];
    assert_eq!(format!("{:.3}", s.position), lines[0]);
    assert_eq!(format!("{:.3}", s.velocity), lines[1]);
    assert_eq!(format!("{:.3}", s.acceleration), lines[2]);
    assert_eq!(format!("{:.3}", s.forces), lines[3]);
    assert_eq!(format!("{s:.3}"), lines.join("\n"));
}

// Proves numbers print as `Display` prints them when no precision is given:
// the crank at 0 has its tip at exactly (1, 0) and its angle exactly 0.
#[test]
fn without_a_precision_numbers_print_as_display_does() {
    let p = Crank::<f64>::default()
        .position(&CrankInput { th: 0.0 })
        .unwrap();
    assert_eq!(p.to_string(), "position: A = (1, 0) L, link2 = 0 rad");
}

// Proves a group's outputs in each line, for the parallelogram at 30 deg,
// crank rate 2 rad/s and acceleration 1 rad/s^2: the rocker stays parallel
// to the crank, so B = A + (3, 4) = (3.866, 4.500) and theta4 = 30 deg =
// 0.524 rad; omega4 = 2, v_B = 2 k x (cos 30, sin 30) = (-1.000, 1.732);
// alpha4 = 1, a_B = k x u - 4 u = (-0.5 - 3.464, 0.866 - 2) = (-3.964,
// -1.134); condition = |(3, 4) x (cos 30, sin 30)| / 5 = |1.5 - 3.464| / 5
// = 0.393.
#[test]
fn a_group_in_every_line() {
    let fb = Parallelogram::<f64>::default();
    let s = fb
        .solve(
            &ParallelogramInput {
                th: 30f64.to_radians(),
            },
            &ParallelogramInput { th: 2.0 },
            &ParallelogramInput { th: 1.0 },
        )
        .unwrap();
    assert_eq!(
        format!("{s:.3}"),
        "position: B = (3.866, 4.500) L, link4 = 0.524 rad\n\
         velocity: B = (-1.000, 1.732) L/s, link4 = 2.000 rad/s, condition = 0.393\n\
         acceleration: B = (-3.964, -1.134) L/s^2, link4 = 1.000 rad/s^2"
    );
}

mechanism! {
    /// A ram of mass 2 on a horizontal guide, pushed along it, under gravity
    /// 10 downwards.
    pub Ram {
        outputs { P }
        let line = guide((0.0, 0.0), 0 deg);
        let P = slider(line, s) as ram;
        mass ram { m = 2.0, at = P };
        gravity (0.0, -10.0);
    }
}

// Proves a prismatic reaction and a slider's force print with their units,
// and that zeros print unsigned: the ram at s = 1.5 accelerating at 3 L/s^2
// needs a push m a = 6.000 F along the guide; the guide holds the weight,
// a normal force of +20.000 F along the guide's left normal (0, 1), with no
// couple about P, where the weight acts; P has no y motion (0.000, not
// -0.000).
#[test]
fn a_prismatic_reaction_and_a_push() {
    let ram = Ram::<f64>::default();
    let s = ram
        .solve(
            &RamInput { s: 1.5 },
            &RamInput { s: 0.5 },
            &RamInput { s: 3.0 },
        )
        .unwrap();
    assert_eq!(
        format!("{s:.3}"),
        "position: P = (1.500, 0.000) L\n\
         velocity: P = (0.500, 0.000) L/s, condition = 1.000\n\
         acceleration: P = (3.000, 0.000) L/s^2\n\
         forces: r_ground_ram = (normal 20.000 F, moment 0.000 F L), drive_s = 6.000 F, condition = 1.000, power_residual = 0.000"
    );
}

mechanism! {
    /// The ram of `Ram` with its units named: mm, N, kg and ms (labels
    /// only; the numbers are the same).
    pub RamInUnits {
        units { length = "mm", force = "N", mass = "kg", time = "ms" }
        outputs { P }
        let line = guide((0.0, 0.0), 0 deg);
        let P = slider(line, s) as ram;
        mass ram { m = 2.0, at = P };
        gravity (0.0, -10.0);
    }
}

// Proves a `units` statement reaches every unit `Display` prints: the ram's
// lines of `a_prismatic_reaction_and_a_push`, the same numbers, with `mm`
// for `L`, `N` for `F` and `ms` for the time of the rates; and the
// description carries the same names.
#[test]
fn a_units_statement_names_every_unit() {
    use mechanism::structure::{Describe, Fields, Units};
    let s = RamInUnits::<f64>::default()
        .solve(
            &RamInUnitsInput { s: 1.5 },
            &RamInUnitsInput { s: 0.5 },
            &RamInUnitsInput { s: 3.0 },
        )
        .unwrap();
    assert_eq!(
        format!("{s:.3}"),
        "position: P = (1.500, 0.000) mm\n\
         velocity: P = (0.500, 0.000) mm/ms, condition = 1.000\n\
         acceleration: P = (3.000, 0.000) mm/ms^2\n\
         forces: r_ground_ram = (normal 20.000 N, moment 0.000 N mm), drive_s = 6.000 N, condition = 1.000, power_residual = 0.000"
    );
    let units = Units {
        length: "mm",
        force: "N",
        mass: "kg",
        time: "ms",
    };
    assert_eq!(RamInUnits::<f64>::STRUCTURE.units, units);
    assert_eq!(<RamInUnitsPosition<f64> as Fields<f64>>::UNITS, units);
    assert_eq!(<RamInUnitsForces<f32> as Fields<f32>>::UNITS, units);
    assert_eq!(Crank::<f64>::STRUCTURE.units, Units::SYMBOLS);
}
