//! DXF of a drawing at a pose (feature `dxf`), read back with the `dxf`
//! crate's reader: the unit, a hole at every link point, slider pin and
//! ground pivot, and outlines that are closed (every end of a line or an arc
//! meets another), at half the link width from the link's points.
#![cfg(feature = "dxf")]

use dxf::entities::EntityType;
use dxf::enums::Units;
use mechanism_plot::dxf::{Cut, HOLES, OUTLINE};
use mechanism_plot::{Frame, PlotError, Sketch};

/// A bar O-A (10 long along +x), a plate A-B-C, a slider at D on a guide at
/// 30 deg, the ground pivot O; in mm.
fn sketch() -> Sketch {
    let mut s = Sketch::new("cut", "mm");
    s.ground_pivot("O", [0.0, 0.0]);
    s.frame(
        Frame::new("")
            .link("crank", &[[0.0, 0.0], [10.0, 0.0]])
            .link("plate", &[[10.0, 0.0], [30.0, 5.0], [20.0, 20.0]])
            .slider("block", [40.0, 10.0], 30f64.to_radians()),
    );
    s
}

const CUT: Cut = Cut {
    width: 4.0,
    hole: 1.5,
};

/// Written, read back: what came back, by kind.
struct Back {
    units: Units,
    holes: Vec<([f64; 2], f64)>,
    lines: Vec<[[f64; 2]; 2]>,
    /// Centre, radius, start and end angle (deg).
    arcs: Vec<([f64; 2], f64, f64, f64)>,
}

fn written_and_read() -> Back {
    // One file per call: the tests run on several threads of one process.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let path =
        std::env::temp_dir().join(format!("mechanism_plot_{}_{call}.dxf", std::process::id()));
    sketch().write_dxf(0, CUT, &path).unwrap();
    let d = dxf::Drawing::load_file(&path).unwrap();
    std::fs::remove_file(&path).unwrap();
    let mut back = Back {
        units: d.header.default_drawing_units,
        holes: Vec::new(),
        lines: Vec::new(),
        arcs: Vec::new(),
    };
    for e in d.entities() {
        let layer = e.common.layer.as_str();
        match &e.specific {
            EntityType::Circle(c) if layer == HOLES => {
                back.holes.push(([c.center.x, c.center.y], c.radius))
            }
            EntityType::Line(l) if layer == OUTLINE => {
                back.lines.push([[l.p1.x, l.p1.y], [l.p2.x, l.p2.y]])
            }
            EntityType::Arc(a) if layer == OUTLINE => back.arcs.push((
                [a.center.x, a.center.y],
                a.radius,
                a.start_angle,
                a.end_angle,
            )),
            other => panic!("unexpected entity on {layer}: {other:?}"),
        }
    }
    back
}

// Coordinates go through the DXF text with 12 or more significant digits
// (the writer's format); the drawing's values are up to 45 mm: 1e-9 mm is
// a thousand times the rounding and far below any cutting tolerance.
const TOL: f64 = 1e-9;

fn close(a: [f64; 2], b: [f64; 2]) -> bool {
    (a[0] - b[0]).abs() <= TOL && (a[1] - b[1]).abs() <= TOL
}

/// The unit and the holes: one per point of each link (O and A of the bar,
/// A, B, C of the plate), the slider's pin and the ground pivot O, each of
/// the hole's radius.
#[test]
fn the_unit_and_a_hole_at_every_pin() {
    let back = written_and_read();
    assert_eq!(back.units, Units::Millimeters);
    let want = [
        [0.0, 0.0],
        [10.0, 0.0],
        [10.0, 0.0],
        [30.0, 5.0],
        [20.0, 20.0],
        [40.0, 10.0],
        [0.0, 0.0],
    ];
    assert_eq!(back.holes.len(), want.len());
    for (w, (c, r)) in want.iter().zip(&back.holes) {
        assert!(close(*w, *c), "{w:?} {c:?}");
        assert_eq!(*r, 0.75);
    }
}

/// The bar is the slot shape: its two sides 2 mm either side of O-A, half
/// circles about O and A; the plate's three sides are 2 mm outside its
/// triangle, with an arc about each corner; the block a 8 x 4 rectangle
/// along 30 deg. Every end of every line and arc meets the end of another:
/// the outlines are closed, as a cutter needs.
#[test]
fn outlines_are_closed_at_half_the_width() {
    let back = written_and_read();
    // 2 + 3 sides, 4 block sides; 2 + 3 arcs.
    assert_eq!(back.lines.len(), 9);
    assert_eq!(back.arcs.len(), 5);
    assert!(back
        .lines
        .iter()
        .any(|l| close(l[0], [0.0, -2.0]) && close(l[1], [10.0, -2.0])));
    assert!(back
        .lines
        .iter()
        .any(|l| close(l[0], [10.0, 2.0]) && close(l[1], [0.0, 2.0])));
    // Each arc is about a link point, of half the width.
    let points = [[0.0, 0.0], [10.0, 0.0], [30.0, 5.0], [20.0, 20.0]];
    for (c, r, _, _) in &back.arcs {
        assert_eq!(*r, 2.0);
        assert!(points.iter().any(|p| close(*p, *c)), "{c:?}");
    }
    // The half circles of the bar sweep 180 deg, counter-clockwise.
    let sweep = |s: f64, e: f64| (e - s).rem_euclid(360.0);
    let bar: Vec<_> = back.arcs.iter().take(2).collect();
    for (_, _, s, e) in bar {
        assert!((sweep(*s, *e) - 180.0).abs() < 1e-9, "{s} {e}");
    }
    // Every end meets another end.
    let mut ends: Vec<[f64; 2]> = back.lines.iter().flat_map(|l| [l[0], l[1]]).collect();
    for (c, r, s, e) in &back.arcs {
        for a in [s, e] {
            let a = a.to_radians();
            ends.push([c[0] + r * a.cos(), c[1] + r * a.sin()]);
        }
    }
    for (i, p) in ends.iter().enumerate() {
        let met = ends
            .iter()
            .enumerate()
            .any(|(j, q)| j != i && close(*p, *q));
        assert!(met, "an open end at {p:?}");
    }
    // The plate's sides: every point of each is 2 mm from the nearest corner
    // line, none inside the triangle (a side moved outward, not inward).
    let tri = [[10.0, 0.0], [30.0, 5.0], [20.0, 20.0]];
    let inside = |p: [f64; 2]| {
        (0..3).all(|i| {
            let (a, b) = (tri[i], tri[(i + 1) % 3]);
            (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]) > 0.0
        })
    };
    for l in &back.lines {
        let mid = [0.5 * (l[0][0] + l[1][0]), 0.5 * (l[0][1] + l[1][1])];
        assert!(!inside(mid), "a side inside the plate: {l:?}");
    }
}

/// Bad sizes and a missing pose are typed errors.
#[test]
fn bad_cuts_are_errors() {
    let s = sketch();
    for cut in [
        Cut {
            width: 0.0,
            hole: 1.0,
        },
        Cut {
            width: 4.0,
            hole: 4.0,
        },
        Cut {
            width: f64::NAN,
            hole: 1.0,
        },
    ] {
        assert!(
            matches!(s.dxf(0, cut), Err(PlotError::BadRange { .. })),
            "{cut:?}"
        );
    }
    assert!(matches!(
        s.dxf(1, CUT),
        Err(PlotError::NoFrame {
            index: 1,
            frames: 1
        })
    ));
}
