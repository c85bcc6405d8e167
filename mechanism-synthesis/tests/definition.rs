//! `Design::definition`, the text of a synthesized four-bar for what reads a
//! definition at run time, is the generated `FourBarPath` of the same
//! design: read by `mechanism_codegen::runtime::Mechanism`, its coupler
//! point at the design's crank angles is the generated code's, in both
//! circuits, for designs with negative coordinates and numbers that need
//! all 17 digits.

use mechanism::Mode;
use mechanism_codegen::runtime::{Analysis, Mechanism};
use mechanism_synthesis::fourbar::{Design, PathProblem};

#[test]
fn the_text_of_a_design_is_the_generated_four_bar() {
    // r1, r2, r3, r4, rcx, rcy, theta0, x0, y0, then crank angles.
    let designs = [
        vec![4.0, 1.0, 3.0, 3.5, 1.5, 1.0, 0.0, 0.0, 0.0, 0.5, 2.0, 4.0],
        vec![
            33.123456789012345,
            f64::from_bits(7f64.to_bits() + 1),
            29.5,
            31.25,
            -12.345678901234567,
            4.0e-7,
            5.9,
            -41.0,
            17.25,
            0.1,
            3.3,
            6.0,
        ],
    ];
    for d in designs {
        let design = Design(d);
        for mode in [Mode::Plus, Mode::Minus] {
            let text = design.definition(mode);
            let rt = Mechanism::new(&text).unwrap_or_else(|e| panic!("{e}\n{text}"));
            let cols = rt.columns(Analysis::Position);
            let at = |name: &str| cols.iter().position(|c| c.name == name).expect(name);
            let (px, py) = (at("P.x"), at("P.y"));
            let fb = design.mechanism(mode);
            for &th in design.angles() {
                let want = PathProblem::coupler(&fb, th).expect("assembles");
                let got = rt.position(&[design.0[6] + th]).expect("assembles");
                // The same primitives with the same arguments: to rounding
                // of coordinates of size 50.
                for (g, w) in [(got.values[px], want[0]), (got.values[py], want[1])] {
                    assert!(
                        (g - w).abs() <= 1e-13 * (1.0 + w.abs()),
                        "{mode:?} {th}: {g} vs {w}"
                    );
                }
            }
        }
    }
}
