//! Every example's drawing and first chart rendered to pixels (resvg) and
//! looked at: not blank, more than one colour, every label laid out and
//! inside the canvas (`mechanism-plot/tests/check/png.rs`). With
//! `MECHANISM_DOC_PNGS=<dir>` set, the pictures shown in `docs/plots.md` are
//! written there.

use crate::common;
use crate::render::{look, save_for_docs};
use std::path::{Path, PathBuf};

type Make = fn(&Path) -> Result<Vec<PathBuf>, mechanism_plot::PlotError>;

/// An example's pictures: which of the files it writes is its first chart and
/// which its drawing, and the docs' names for them (if shown there).
struct Example {
    name: &'static str,
    make: Make,
    chart: usize,
    drawing: usize,
    docs: Option<(&'static str, &'static str)>,
}

const fn example(name: &'static str, make: Make) -> Example {
    Example {
        name,
        make,
        chart: 0,
        drawing: 1,
        docs: None,
    }
}

const EXAMPLES: [Example; 9] = [
    Example {
        docs: Some(("fourbar-kinematics.png", "fourbar-drawing.png")),
        ..example("fourbar", crate::example_fourbar::pictures)
    },
    example("sixbar", crate::example_sixbar::pictures),
    example("shaper", crate::example_shaper::pictures),
    example("slider_crank", crate::example_slider_crank::pictures),
    example("five_bar", crate::example_five_bar::pictures),
    example("sine_mechanism", crate::example_sine_mechanism::pictures),
    Example {
        docs: Some(("shaper-forces.png", "shaper-drawing.png")),
        ..example("shaper_forces", crate::example_shaper_forces::pictures)
    },
    Example {
        docs: Some(("stephenson-kinematics.png", "stephenson.png")),
        ..example("stephenson", common::stephenson::plots)
    },
    // Kinematics, forces, then the drawing.
    Example {
        drawing: 2,
        ..example("two_r_leg", common::leg::plots)
    },
];

/// Renders each example's first chart and its drawing; each must be at least
/// 1 % ink (the emptiest, the four-bar's drawing of three bars on 872 x 698
/// px, is about 2.5 %; a blank canvas is 0 %).
#[test]
fn every_example_picture_renders_with_its_labels_inside() {
    let dir = std::env::temp_dir().join(format!("mechanism-png-test-{}", std::process::id()));
    for Example {
        name,
        make,
        chart,
        drawing,
        docs,
    } in EXAMPLES
    {
        let files = make(&dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        let read = |k: usize| std::fs::read_to_string(&files[k]).unwrap();
        let c = look(&read(chart), &format!("{name} chart"), 0.01);
        let d = look(&read(drawing), &format!("{name} drawing"), 0.01);
        eprintln!(
            "{name}: chart {}x{} px, {:.1} % ink, {} colours, {} labels; drawing {}x{} px, {:.1} % ink, {} colours, {} labels",
            c.size.0, c.size.1, 100.0 * c.inked, c.colours, c.texts,
            d.size.0, d.size.1, 100.0 * d.inked, d.colours, d.texts
        );
        if let Some((chart_png, drawing_png)) = docs {
            save_for_docs(&c, chart_png);
            save_for_docs(&d, drawing_png);
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The check can fail: a picture with a label pushed off the canvas, one
/// with two labels over each other, and a blank one, are refused.
#[test]
fn the_look_refuses_labels_off_the_canvas_or_overlapping_and_blank_pictures() {
    let off = r##"<svg xmlns="http://www.w3.org/2000/svg" width="200" height="100" font-family="DejaVu Sans, sans-serif"><rect width="200" height="100" fill="white"/><path d="M10 10 L190 90" stroke="#0072B2" stroke-width="8"/><path d="M10 90 L190 10" stroke="#D55E00" stroke-width="8"/><text x="150" y="50" font-size="13">a long label</text></svg>"##;
    let r = std::panic::catch_unwind(|| look(off, "off", 0.02));
    assert!(r.is_err(), "a label beyond the right edge is refused");
    let inside = off.replace(r#"x="150""#, r#"x="20""#);
    assert!(look(&inside, "inside", 0.02).texts == 1);
    let twice = inside.replace(
        "</svg>",
        r#"<text x="24" y="54" font-size="13">again</text></svg>"#,
    );
    assert!(
        std::panic::catch_unwind(|| look(&twice, "twice", 0.02)).is_err(),
        "two labels over each other are refused"
    );
    let blank = r#"<svg xmlns="http://www.w3.org/2000/svg" width="200" height="100"><rect width="200" height="100" fill="white"/></svg>"#;
    assert!(std::panic::catch_unwind(|| look(blank, "blank", 0.02)).is_err());
}
