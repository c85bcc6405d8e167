//! Every output of the run-time mechanism is the generated code's, bit for
//! bit, at random inputs; a failing pose fails with the same typed error.

#[path = "../../examples/common/leg.rs"]
pub(super) mod leg;
#[path = "../../examples/common/scenes.rs"]
pub(super) mod scenes;
#[path = "../../examples/common/stephenson.rs"]
pub(super) mod stephenson;

use super::text::definition;
use mechanism::structure::{Fields, Value};
use mechanism_codegen::runtime::{Analysis, Mechanism};

/// Poses tried per definition.
const POSES: usize = 400;

/// A small deterministic generator (SplitMix64), so a failure replays.
pub(super) struct Rng(pub(super) u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in `[lo, hi]`.
    pub(super) fn within(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}

/// The number of column `name` (`B.x`, `link3`) of a generated struct.
pub(super) fn field<S: Fields<f64>>(s: &S, name: &str) -> f64 {
    if let Some(Value::Scalar(x)) = s.get(name) {
        return x;
    }
    let (base, part) = match name.rsplit_once('.') {
        Some((b, p)) => (b, Some(p)),
        None => (name, None),
    };
    let v = s
        .get(base)
        .unwrap_or_else(|| panic!("the generated struct has no field `{base}`"));
    match (v, part) {
        (Value::Point(p), Some("x")) => p.x,
        (Value::Point(p), Some(_)) => p.y,
        (Value::Vector(p), Some("x")) => p.x,
        (Value::Vector(p), Some(_)) => p.y,
        (Value::Scalar(x), None) => x,
        (v, _) => panic!("field `{name}`: unexpected {v:?}"),
    }
}

/// Asserts the run-time values `got` equal the generated struct's, by name.
fn same<S: Fields<f64>>(what: &str, m: &Mechanism, a: Analysis, got: &[f64], s: &S) {
    let cols = m.columns(a);
    assert_eq!(cols.len(), got.len(), "{what}");
    for (c, &g) in cols.iter().zip(got) {
        let want = field(s, &c.name);
        assert_eq!(
            g.to_bits(),
            want.to_bits(),
            "{what}: {a:?} `{}`: run time {g:e}, generated {want:e}",
            c.name
        );
    }
}

/// What one definition's comparison covered.
#[derive(Default, Debug)]
struct Tally {
    /// Poses where every analysis succeeded in both.
    solved: usize,
    /// Poses where both failed with the same error.
    failed: usize,
}

/// Compares the run-time reading of definition `$name` of `$file` with the
/// compiled `$ty` at random inputs in their ranges (`$lo..$hi` for inputs
/// without one), rates and accelerations in [-10, 10].
macro_rules! compare {
    ($file:literal, $ty:path, $input:ident { $($i:ident),* }, $lo:expr, $hi:expr) => {{
        let source = include_str!($file);
        let name = stringify!($ty).rsplit("::").next().unwrap().trim();
        let text = definition(source, name);
        let m = Mechanism::new(&text).unwrap_or_else(|e| panic!("{name}: {e}"));
        let names: Vec<String> = m.inputs().into_iter().map(|i| i.name).collect();
        assert_eq!(names, [$(stringify!($i)),*], "{name}: inputs");
        let ranges: Vec<(f64, f64)> = m
            .inputs()
            .iter()
            .map(|i| i.range.unwrap_or(($lo, $hi)))
            .collect();
        let g = <$ty>::default();
        let mut rng = Rng(0x5EED ^ name.len() as u64);
        let mut tally = Tally::default();
        let make = |v: &[f64]| {
            let mut it = v.iter().copied();
            $input { $($i: it.next().unwrap()),* }
        };
        for _ in 0..POSES {
            let q: Vec<f64> = ranges.iter().map(|&(lo, hi)| rng.within(lo, hi)).collect();
            let qd: Vec<f64> = q.iter().map(|_| rng.within(-10.0, 10.0)).collect();
            let qdd: Vec<f64> = q.iter().map(|_| rng.within(-10.0, 10.0)).collect();
            let what = format!("{name} at {q:?}, rates {qd:?}, accels {qdd:?}");
            let (rp, gp) = (m.position(&q), g.position(&make(&q)));
            let (rp, gp) = match (rp, gp) {
                (Ok(r), Ok(p)) => (r, p),
                (Err(a), Err(b)) => {
                    assert_eq!(a, b, "{what}: position errors");
                    tally.failed += 1;
                    continue;
                }
                (r, p) => panic!("{what}: position: run time {:?}, generated {:?}", r.err(), p.err()),
            };
            same(&what, &m, Analysis::Position, &rp.values, &gp);
            let (rv, gv) = match (m.velocity(&rp, &qd), g.velocity(&gp, &make(&qd))) {
                (Ok(r), Ok(v)) => (r, v),
                (Err(a), Err(b)) => {
                    assert_eq!(a, b, "{what}: velocity errors");
                    tally.failed += 1;
                    continue;
                }
                (r, v) => panic!("{what}: velocity: run time {:?}, generated {:?}", r.err(), v.err()),
            };
            same(&what, &m, Analysis::Velocity, &rv.values, &gv);
            assert_eq!(rv.condition.to_bits(), gv.condition.to_bits(), "{what}: condition");
            match (m.acceleration(&rp, &rv, &qdd), g.acceleration(&gp, &gv, &make(&qdd))) {
                (Ok(r), Ok(a)) => {
                    same(&what, &m, Analysis::Acceleration, &r.values, &a);
                    tally.solved += 1;
                }
                (Err(a), Err(b)) => {
                    assert_eq!(a, b, "{what}: acceleration errors");
                    tally.failed += 1;
                }
                (r, a) => panic!("{what}: acceleration: run time {:?}, generated {:?}", r.err(), a.err()),
            }
        }
        eprintln!("{name}: {tally:?}");
        tally
    }};
}

#[test]
fn four_bar() {
    use scenes::{FourBar, FourBarInput};
    let t = compare!(
        "../../examples/common/scenes.rs",
        FourBar,
        FourBarInput { theta2 },
        0.0,
        1.0
    );
    assert_eq!(t.solved, POSES, "the crank-rocker assembles at every angle");
}

#[test]
fn six_bar() {
    use scenes::{SixBar, SixBarInput};
    let t = compare!(
        "../../examples/common/scenes.rs",
        SixBar,
        SixBarInput { phi1 },
        0.0,
        1.0
    );
    assert!(t.solved > POSES / 2, "{t:?}");
}

#[test]
fn shaper() {
    use scenes::{Shaper, ShaperInput};
    let t = compare!(
        "../../examples/common/scenes.rs",
        Shaper,
        ShaperInput { crank },
        0.0,
        1.0
    );
    assert!(t.solved > POSES / 2, "{t:?}");
}

#[test]
fn slider_crank() {
    use scenes::{SliderCrank, SliderCrankInput};
    let t = compare!(
        "../../examples/common/scenes.rs",
        SliderCrank,
        SliderCrankInput { theta },
        0.0,
        1.0
    );
    assert!(t.solved > POSES / 2, "{t:?}");
}

#[test]
fn five_bar_two_inputs() {
    use scenes::{FiveBar, FiveBarInput};
    let t = compare!(
        "../../examples/common/scenes.rs",
        FiveBar,
        FiveBarInput { q1, q2 },
        0.0,
        1.0
    );
    assert!(t.solved > POSES / 2, "{t:?}");
}

#[test]
fn sine_mechanism() {
    use scenes::{SineMechanism, SineMechanismInput};
    let t = compare!(
        "../../examples/common/scenes.rs",
        SineMechanism,
        SineMechanismInput { phi1 },
        0.0,
        1.0
    );
    assert!(t.solved > POSES / 2, "{t:?}");
}

#[test]
fn shaper_with_loads() {
    use scenes::{ShaperForces, ShaperForcesInput};
    let t = compare!(
        "../../examples/common/scenes.rs",
        ShaperForces,
        ShaperForcesInput { crank },
        0.0,
        1.0
    );
    assert!(t.solved > POSES / 2, "{t:?}");
}

#[test]
fn five_bar_inverse_kinematics_drawn() {
    use scenes::{FiveBarIk, FiveBarIkInput};
    // The end point over a box around the drawn pose (m).
    let t = compare!(
        "../../examples/common/scenes.rs",
        FiveBarIk,
        FiveBarIkInput { x, y },
        0.0,
        0.25
    );
    assert!(t.solved > 0, "{t:?}");
}

#[test]
fn stephenson_triad() {
    use stephenson::{Stephenson, StephensonInput};
    let t = compare!(
        "../../examples/common/stephenson.rs",
        Stephenson,
        StephensonInput { phi },
        0.0,
        1.0
    );
    assert!(t.solved > 0, "{t:?}");
}

#[test]
fn two_r_leg_carried_crank() {
    use leg::{Leg, LegInput};
    let t = compare!(
        "../../examples/common/leg.rs",
        Leg,
        LegInput { hip, knee },
        -3.0,
        3.0
    );
    assert_eq!(t.solved, POSES, "an open chain always assembles");
}
