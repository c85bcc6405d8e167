//! The pictures of the five examples (`examples/common/plots.rs`), written to a
//! temporary directory and read back with an independent XML parser: well-formed,
//! every coordinate finite and inside the viewBox, tick values increasing, every series
//! in the legend, every joint drawn, links keeping their lengths across the animation,
//! exactly one pose visible at any time.

use crate::check::*;
use std::path::{Path, PathBuf};

/// What a scene's pictures must hold, counted from its definition in
/// `examples/common/scenes.rs` (not from the picture code).
struct Expect {
    name: &'static str,
    make: fn(&Path) -> Result<Vec<PathBuf>, mechanism_plot::PlotError>,
    /// Panels of the kinematics figure.
    panels: usize,
    /// Revolute joints on moving links (drawn in each frame), and ground pivots.
    moving_joints: usize,
    ground_joints: usize,
    /// Slider blocks.
    sliders: usize,
    /// Frames of the animation.
    frames: usize,
}

const SCENES: [Expect; 7] = [
    // O2, O4 ground; A, B moving; link3 a plate A-B-P.
    Expect {
        name: "fourbar",
        make: crate::example_fourbar::pictures,
        panels: 3,
        moving_joints: 2,
        ground_joints: 2,
        sliders: 0,
        frames: 90,
    },
    // A, E ground; K, B, F, D, C moving (B and D are points of one link where
    // another is pinned); block 5 on the crank line; angles and the slide af at
    // three levels; 31 poses there and 29 back.
    Expect {
        name: "sixbar",
        make: crate::example_sixbar::pictures,
        panels: 6,
        moving_joints: 5,
        ground_joints: 2,
        sliders: 1,
        frames: 60,
    },
    // A, C ground; B, D, E moving; the block on the rocker and the ram; E and two
    // angles at three levels.
    Expect {
        name: "shaper",
        make: crate::example_shaper::pictures,
        panels: 6,
        moving_joints: 3,
        ground_joints: 2,
        sliders: 2,
        frames: 90,
    },
    // O ground; A, B moving; the slider.
    Expect {
        name: "slider_crank",
        make: crate::example_slider_crank::pictures,
        panels: 6,
        moving_joints: 2,
        ground_joints: 1,
        sliders: 1,
        frames: 90,
    },
    // A ground; B, Q moving; block 2 and the yoke link 3 (the forces figure
    // comes first: driving torque, reactions, couples of the prismatic pairs).
    Expect {
        name: "sine_mechanism",
        make: crate::example_sine_mechanism::pictures,
        panels: 3,
        moving_joints: 2,
        ground_joints: 1,
        sliders: 2,
        frames: 90,
    },
    // O2, O5 ground; A, C, B moving; B and the gear's angle at three levels.
    Expect {
        name: "geared_five_bar",
        make: crate::example_geared_five_bar::pictures,
        panels: 6,
        moving_joints: 3,
        ground_joints: 2,
        sliders: 0,
        frames: 90,
    },
    // O1, O2 ground; A, C, P moving; P at three levels.
    Expect {
        name: "five_bar",
        make: crate::example_five_bar::pictures,
        panels: 3,
        moving_joints: 3,
        ground_joints: 2,
        sliders: 0,
        frames: 90,
    },
];

fn out_dir(name: &str) -> PathBuf {
    std::env::temp_dir()
        .join(format!("mechanism-plots-test-{}", std::process::id()))
        .join(name)
}

/// Pixel lengths of the two-joint links of a frame, by link name.
fn bar_lengths(frame: roxmltree::Node) -> Vec<(String, f64)> {
    with_class(frame, "link")
        .iter()
        .filter_map(|l| {
            let pts = path_points(l.attribute("d").unwrap());
            (pts.len() == 2).then(|| {
                let d = ((pts[1][0] - pts[0][0]).powi(2) + (pts[1][1] - pts[0][1]).powi(2)).sqrt();
                (l.attribute("data-name").unwrap().to_string(), d)
            })
        })
        .collect()
}

#[test]
fn every_example_picture_is_sound() {
    for e in &SCENES {
        let dir = out_dir(e.name);
        let files = (e.make)(&dir).unwrap_or_else(|err| panic!("{}: {err}", e.name));
        assert_eq!(files.len(), 3, "{}: kinematics, drawing, animation", e.name);
        let read = |f: &PathBuf| {
            std::fs::read_to_string(f).unwrap_or_else(|err| panic!("{}: {err}", f.display()))
        };

        // The kinematics figure.
        let text = read(&files[0]);
        let (doc, vb) = parse(&text);
        assert_inside(&doc, vb);
        let ps = panels(&doc);
        assert_eq!(ps.len(), e.panels, "{}: panels", e.name);
        for p in &ps {
            assert!(!p.series.is_empty());
            for path in &p.paths {
                assert!(path.len() >= 10, "{}: a curve has points", e.name);
                // Curves stay in their plot area (y axes are widened to whole ticks).
                for q in path {
                    assert!(
                        q[0] >= p.area[0] - ROUND
                            && q[0] <= p.area[0] + p.area[2] + ROUND
                            && q[1] >= p.area[1] - ROUND
                            && q[1] <= p.area[1] + p.area[3] + ROUND,
                        "{}: vertex {q:?} outside its plot area {:?}",
                        e.name,
                        p.area
                    );
                }
            }
        }
        // Every panel has an axis label with a unit in parentheses.
        for t in with_class(doc.root_element(), "y-label")
            .iter()
            .chain(&with_class(doc.root_element(), "x-label"))
        {
            let s = t.text().unwrap();
            assert!(
                s.contains('(') && s.ends_with(')'),
                "{}: axis label `{s}` has a unit",
                e.name
            );
        }

        // The drawing of one pose.
        let text = read(&files[1]);
        let (doc, vb) = parse(&text);
        assert_inside(&doc, vb);
        let root = doc.root_element();
        assert_eq!(with_class(root, "frame").len(), 1);
        assert_eq!(
            with_class(root, "joint").len(),
            e.moving_joints,
            "{}: joints",
            e.name
        );
        assert_eq!(
            with_class(root, "ground-joint").len(),
            e.ground_joints,
            "{}: ground joints",
            e.name
        );
        assert_eq!(
            with_class(root, "ground-pivot").len(),
            e.ground_joints,
            "{}: supports",
            e.name
        );
        assert_eq!(
            with_class(root, "slider").len(),
            e.sliders,
            "{}: sliders",
            e.name
        );
        // Every named joint is labelled.
        let labels = with_class(root, "label").len();
        assert_eq!(
            labels,
            e.moving_joints + e.ground_joints + with_class(root, "point").len(),
            "{}: labels",
            e.name
        );

        // The animation.
        let text = read(&files[2]);
        let (doc, vb) = parse(&text);
        assert_inside(&doc, vb);
        let frames = with_class(doc.root_element(), "frame");
        if e.frames > 0 {
            assert_eq!(frames.len(), e.frames, "{}: frames", e.name);
        } else {
            assert!(frames.len() >= 8, "{}: frames", e.name);
        }
        for f in &frames {
            assert_eq!(
                with_class(*f, "joint").len(),
                e.moving_joints,
                "{}: joints per frame",
                e.name
            );
            assert_eq!(
                with_class(*f, "slider").len(),
                e.sliders,
                "{}: sliders per frame",
                e.name
            );
        }
        let n = frames.len();
        for i in 0..(4 * n) {
            let t = (i as f64 + 0.5) / (4 * n) as f64;
            let shown = frames.iter().filter(|f| visible_at(f, t)).count();
            assert_eq!(shown, 1, "{}: poses visible at t = {t}", e.name);
        }
        // One scale for all frames and rigid links: every bar keeps its pixel length.
        // Each end is rounded to 0.01 px (ROUND = 0.005 per coordinate), so a length is
        // within sqrt(2) * 2 * ROUND of its exact value and two lengths differ by at most
        // twice that.
        let tol = 4.0 * 2f64.sqrt() * ROUND;
        let first = bar_lengths(frames[0]);
        assert!(!first.is_empty());
        for (k, f) in frames.iter().enumerate() {
            let these = bar_lengths(*f);
            assert_eq!(these.len(), first.len());
            for ((name, l0), (name_k, lk)) in first.iter().zip(&these) {
                assert_eq!(name, name_k);
                assert!(
                    (l0 - lk).abs() <= tol,
                    "{}: link {name} is {l0} px in frame 0, {lk} px in frame {k}",
                    e.name
                );
            }
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}

/// The traced joint B of the four-bar lies on its drawn path in every frame of
/// the animation (the path and the frames come from the same poses).
#[test]
fn the_traced_point_rides_its_path() {
    let dir = out_dir("traced");
    let files = crate::example_fourbar::pictures(&dir).unwrap();
    let text = std::fs::read_to_string(&files[2]).unwrap();
    let (doc, _) = parse(&text);
    let root = doc.root_element();
    let path = with_class(root, "path")
        .into_iter()
        .find(|p| p.attribute("data-name") == Some("B"))
        .expect("the path of B");
    let verts = path_points(path.attribute("d").unwrap());
    let frames = with_class(root, "frame");
    assert_eq!(verts.len(), frames.len(), "one path vertex per frame");
    // B of frame k is vertex k, both rounded from the same exact point (<= 2 *
    // ROUND apart per coordinate).
    for (k, f) in frames.iter().enumerate() {
        let b = with_class(*f, "joint")
            .into_iter()
            .find(|j| j.attribute("data-name") == Some("B"))
            .expect("joint B");
        let v = verts[k];
        assert!(
            (num(&b, "cx") - v[0]).abs() <= 2.0 * ROUND
                && (num(&b, "cy") - v[1]).abs() <= 2.0 * ROUND,
            "frame {k}: B at ({}, {}), path vertex {v:?}",
            num(&b, "cx"),
            num(&b, "cy")
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The shaper's force figure (the first of its pictures, before its drawing
/// and animation): well-formed, inside its view, three panels: the driving torque; the
/// magnitudes of the 7 reactions of its definition (revolutes at A, B, C, D, E
/// and the prismatic pairs block-rocker and guide-ram); the 2 prismatic
/// couples.
#[test]
fn the_shaper_force_figure_is_sound() {
    let dir = out_dir("shaper_forces");
    let files = crate::example_shaper_forces::pictures(&dir).unwrap();
    assert_eq!(files.len(), 3, "forces.svg, a drawing and an animation");
    let text = std::fs::read_to_string(&files[0]).unwrap();
    let (doc, vb) = parse(&text);
    assert_inside(&doc, vb);
    let ps = panels(&doc);
    assert_eq!(ps.len(), 3);
    assert_eq!(ps[0].series.len(), 1);
    assert_eq!(ps[1].series.len(), 7);
    assert_eq!(ps[2].series.len(), 2);
    for p in &ps {
        for path in &p.paths {
            assert!(path.len() >= 100, "a curve over the turn");
        }
    }
}
