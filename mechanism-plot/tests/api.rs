//! The public API of `mechanism-plot`: typed errors instead of panics, and SVG that an
//! independent XML parser reads back into the data it was given.

mod check;

use check::*;
use mechanism_core::structure::{
    Describe, Field, Fields, Input, Link, LinkKind, Point, PointKind, Quantity, Structure, Units,
    Value,
};
use mechanism_core::{Point2, Real};
use mechanism_plot::any;
use mechanism_plot::{Figure, Frame, Plot, PlotError, Sketch};

fn sine() -> (Vec<f64>, Vec<f64>) {
    let xs: Vec<f64> = (0..=72).map(|k| 5.0 * k as f64).collect();
    let ys = xs.iter().map(|d| 3.0 * d.to_radians().sin()).collect();
    (xs, ys)
}

#[test]
fn bad_data_is_a_typed_error() {
    let (xs, mut ys) = sine();
    assert!(matches!(
        Plot::new("t").to_svg(),
        Err(PlotError::NoSeries { .. })
    ));
    assert!(matches!(
        Plot::new("t").series("e", &[], &[]).to_svg(),
        Err(PlotError::EmptySeries { .. })
    ));
    assert!(matches!(
        Plot::new("t").series("m", &xs, &ys[1..]).to_svg(),
        Err(PlotError::LengthMismatch { xs: 73, ys: 72, .. })
    ));
    ys[7] = f64::NAN;
    match Plot::new("t").series("n", &xs, &ys).to_svg() {
        Err(PlotError::NonFinite { index, what }) => {
            assert_eq!(index, 7);
            assert!(what.contains('n'));
        }
        other => panic!("expected NonFinite, got {other:?}"),
    }
    ys[7] = f64::INFINITY;
    assert!(Plot::new("t").series("n", &xs, &ys).to_svg().is_err());
    let (xs, ys) = sine();
    for bad in [(1.0, 1.0), (2.0, 1.0), (f64::NAN, 1.0)] {
        assert!(matches!(
            Plot::new("t")
                .series("s", &xs, &ys)
                .y_range(bad.0, bad.1)
                .to_svg(),
            Err(PlotError::BadRange { axis: "y", .. })
        ));
    }
    assert!(matches!(
        Plot::new("t").series("s", &xs, &ys).x_step(-1.0).to_svg(),
        Err(PlotError::BadRange { axis: "x", .. })
    ));
    assert!(matches!(
        Figure::new("f").to_svg(),
        Err(PlotError::NoSeries { .. })
    ));
    // The error names the problem in words.
    let e = Plot::new("t")
        .series("m", &xs, &ys[1..])
        .to_svg()
        .unwrap_err();
    assert_eq!(e.to_string(), "series `m` has 73 x values but 72 y values");
}

#[test]
fn a_plot_reads_back_as_its_data() {
    let (xs, ys) = sine();
    let cos: Vec<f64> = xs.iter().map(|d| d.to_radians().cos()).collect();
    let svg = Plot::new("Sine & cosine <test>")
        .x_axis("crank angle", "deg")
        .y_axis("value", "rad/s^2")
        .series("3 sin", &xs, &ys)
        .series("cos", &xs, &cos)
        .to_svg()
        .unwrap();
    let (doc, vb) = parse(&svg);
    assert_inside(&doc, vb);
    let p = panels(&doc).remove(0);
    assert_eq!(p.series, ["3 sin", "cos"]);
    // x: a full turn in degrees reads 0, 45, ..., 360.
    let xv: Vec<f64> = p.x_ticks.iter().map(|t| t.0).collect();
    assert_eq!(
        xv,
        [0.0, 45.0, 90.0, 135.0, 180.0, 225.0, 270.0, 315.0, 360.0]
    );
    // y: the ticks bracket the data (-3..3).
    let (ylo, yhi) = (p.y_ticks[0].0, p.y_ticks.last().unwrap().0);
    assert!(ylo <= -3.0 && yhi >= 3.0, "y ticks {ylo}..{yhi}");
    // Each vertex sits where the ticks say: interpolate pixel position from the first
    // and last tick of each axis (tick labels are exact here: integers).
    let (x0, x1) = (p.x_ticks[0], *p.x_ticks.last().unwrap());
    let (y0, y1) = (p.y_ticks[0], *p.y_ticks.last().unwrap());
    let tick_px_x = |v: f64| x0.1 + (v - x0.0) / (x1.0 - x0.0) * (x1.1 - x0.1);
    let tick_px_y_label = |v: f64| y0.1 + (v - y0.0) / (y1.0 - y0.0) * (y1.1 - y0.1);
    // y tick labels are drawn 4 px below the tick line (baseline offset): compare
    // differences only, which the offset cancels.
    for (k, q) in p.paths[0].iter().enumerate() {
        assert!(
            (q[0] - tick_px_x(xs[k])).abs() <= 2.0 * ROUND,
            "x of vertex {k}"
        );
        let dy = q[1] - p.paths[0][0][1];
        let want = tick_px_y_label(ys[k]) - tick_px_y_label(ys[0]);
        assert!(
            (dy - want).abs() <= 3.0 * ROUND,
            "y of vertex {k}: {dy} vs {want}"
        );
    }
    // The axis label carries the unit with a superscript; the title is escaped text.
    assert!(svg.contains("value (rad/s²)"));
    assert!(svg.contains("Sine &amp; cosine &lt;test&gt;"));
}

#[test]
fn constant_and_large_series() {
    let xs = [0.0, 1.0, 2.0];
    let svg = Plot::new("c")
        .series("flat", &xs, &[4.0; 3])
        .to_svg()
        .unwrap();
    let (doc, vb) = parse(&svg);
    assert_inside(&doc, vb);
    let p = panels(&doc).remove(0);
    assert!(p.y_ticks[0].0 < 4.0 && p.y_ticks.last().unwrap().0 > 4.0);
    // Values of 10^5: the labels are scaled and the axis says by how much.
    let svg = Plot::new("big")
        .y_axis("acceleration", "rad/s^2")
        .series("a", &xs, &[-2.0e5, 1.0e5, 3.1e5])
        .to_svg()
        .unwrap();
    let (doc, _) = parse(&svg);
    let p = panels(&doc).remove(0);
    assert!(
        p.y_ticks.iter().all(|t| t.0.abs() <= 1000.0),
        "scaled labels"
    );
    assert!(svg.contains("acceleration (10³ rad/s²)"));
}

#[test]
fn figures_align_panels_and_many_series_stay_distinct() {
    let (xs, ys) = sine();
    let mut many = Plot::new("many").x_axis("x", "");
    for k in 0..12 {
        let shifted: Vec<f64> = ys.iter().map(|y| y + k as f64).collect();
        many = many.series(&format!("s{k}"), &xs, &shifted);
    }
    let svg = Figure::new("fig")
        .panel(Plot::new("one").series("a", &xs, &ys))
        .panel(many)
        .to_svg()
        .unwrap();
    let (doc, vb) = parse(&svg);
    assert_inside(&doc, vb);
    let ps = panels(&doc);
    assert_eq!(ps.len(), 2);
    assert_eq!(
        ps[0].area[0], ps[1].area[0],
        "plot areas start at the same x"
    );
    assert_eq!(ps[0].area[2], ps[1].area[2], "and have the same width");
    assert!(
        ps[1].area[1] > ps[0].area[1] + ps[0].area[3],
        "panel 2 below panel 1"
    );
    // 12 series: the 11th and 12th reuse colours, so they must be dashed.
    let styles: Vec<(String, String)> =
        elements(with_class(doc.root_element(), "series")[1], "path")
            .iter()
            .map(|p| {
                (
                    p.attribute("stroke").unwrap().to_string(),
                    p.attribute("stroke-dasharray").unwrap_or("").to_string(),
                )
            })
            .collect();
    for i in 0..styles.len() {
        for j in 0..i {
            assert_ne!(styles[i], styles[j], "series {i} and {j} look alike");
        }
    }
}

fn square_sketch() -> Sketch {
    let mut sk = Sketch::new("t", "m");
    sk.ground_pivot("O", [0.0, 0.0])
        .ground_guide([-1.0, -0.5], [2.0, -0.5]);
    for k in 0..8 {
        let a = std::f64::consts::TAU * k as f64 / 8.0;
        let tip = [a.cos(), a.sin()];
        sk.frame(
            Frame::new(&format!("{k}"))
                .link("crank", &[[0.0, 0.0], tip])
                .joint("A", tip)
                .slider("block", tip, 0.0),
        );
    }
    sk
}

#[test]
fn sketch_errors() {
    let sk = Sketch::new("t", "m");
    assert!(matches!(
        sk.animation(1.0),
        Err(PlotError::NoFrame { frames: 0, .. })
    ));
    assert!(matches!(sk.drawing(0), Err(PlotError::NoFrame { .. })));
    assert!(matches!(
        square_sketch().drawing(8),
        Err(PlotError::NoFrame {
            index: 8,
            frames: 8
        })
    ));
    let mut sk = Sketch::new("t", "m");
    sk.frame(Frame::new(""));
    assert!(matches!(sk.drawing(0), Err(PlotError::NothingToDraw)));
    let mut sk = square_sketch();
    sk.frame(Frame::new("").joint("bad", [f64::NAN, 0.0]));
    assert!(matches!(
        sk.animation(1.0),
        Err(PlotError::NonFinite { .. })
    ));
    let mut sk = square_sketch();
    sk.path("p", &[[0.0, 0.0], [1.0, f64::INFINITY]]);
    assert!(matches!(
        sk.drawing(0),
        Err(PlotError::NonFinite { index: 1, .. })
    ));
}

#[test]
fn a_drawing_has_its_elements_at_one_scale() {
    let sk = square_sketch();
    let svg = sk.drawing(1).unwrap();
    let (doc, vb) = parse(&svg);
    assert_inside(&doc, vb);
    let root = doc.root_element();
    assert_eq!(with_class(root, "joint").len(), 1);
    assert_eq!(with_class(root, "ground-joint").len(), 1);
    assert_eq!(with_class(root, "slider").len(), 1);
    assert_eq!(with_class(root, "ground-guide").len(), 1);
    assert_eq!(with_class(root, "ground-pivot").len(), 1);
    // Frame 1: the tip at 45 deg: on screen up and right of the pivot, equally.
    let o = &with_class(root, "ground-joint")[0];
    let a = &with_class(root, "joint")[0];
    let (dx, dy) = (num(a, "cx") - num(o, "cx"), num(a, "cy") - num(o, "cy"));
    assert!(dx > 0.0 && dy < 0.0, "y is up");
    assert!(
        (dx + dy).abs() <= 4.0 * ROUND,
        "uniform scale: {dx} vs {}",
        -dy
    );
}

#[test]
fn the_animation_shows_exactly_one_pose_at_a_time() {
    let svg = square_sketch().animation(2.0).unwrap();
    let (doc, vb) = parse(&svg);
    assert_inside(&doc, vb);
    let frames = with_class(doc.root_element(), "frame");
    assert_eq!(frames.len(), 8);
    // Without SMIL only the first pose shows.
    let statically: Vec<bool> = frames
        .iter()
        .map(|f| f.attribute("visibility") == Some("visible"))
        .collect();
    assert_eq!(statically.iter().filter(|v| **v).count(), 1);
    assert!(statically[0]);
    // With SMIL: at 1000 instants of the cycle, one pose, and pose k during slice k.
    for i in 0..1000 {
        let t = i as f64 / 1000.0;
        let shown: Vec<usize> = (0..8).filter(|&k| visible_at(&frames[k], t)).collect();
        assert_eq!(shown, [(t * 8.0).floor() as usize], "at t = {t}");
    }
    let a = elements(frames[3], "animate")[0];
    assert_eq!(a.attribute("dur"), Some("2s"));
    // Each pose carries its joint.
    for f in &frames {
        assert_eq!(with_class(*f, "joint").len(), 1);
    }
}

/// A result struct read by name, as the macro's are: an angle and a point,
/// in `f32` or `f64`, in mm and N (as a `units` statement names them).
#[derive(Clone)]
struct Out<T: Real> {
    a: T,
    p: Point2<T>,
}

const MM_N: Units = Units {
    length: "mm",
    force: "N",
    mass: "kg",
    time: "s",
};

impl<T: Real> Fields<T> for Out<T> {
    const UNITS: Units = MM_N;
    const FIELDS: &'static [Field] = &[
        Field {
            name: "a",
            quantity: Quantity::Angle,
            planar: false,
        },
        Field {
            name: "P",
            quantity: Quantity::Length,
            planar: true,
        },
    ];

    fn get(&self, name: &str) -> Option<Value<T>> {
        match name {
            "a" => Some(Value::Scalar(self.a)),
            "P" => Some(Value::Point(self.p)),
            _ => None,
        }
    }
}

/// The rows of [`a_generic_chart_has_gaps_where_rows_fail`] in `f64`.
fn out_rows() -> Vec<(f64, Option<Out<f64>>)> {
    (0..=40)
        .map(|k| {
            let x = 9.0 * k as f64;
            let t = (2.0 * x).to_radians();
            let out = Out {
                a: t.sin().atan2(t.cos()),
                p: Point2::new(x.to_radians().cos(), 2.0),
            };
            (x, (!(10..15).contains(&k)).then_some(out))
        })
        .collect()
}

/// A generic chart of outputs named by the caller: one panel per quantity with
/// the result's units (`mm`, angles in deg), a row that failed breaks every
/// series into two runs (two `M` commands, no vertex for the five failed rows,
/// no segment across them), an angle that wraps at +-180 deg is drawn
/// continuous (its vertices rise monotonically on screen), and an unknown field
/// name is a typed error.
#[test]
fn a_generic_chart_has_gaps_where_rows_fail() {
    let rows = out_rows();
    let svg = any::chart("t", ("x", "deg"), &rows, &["a", "P"])
        .unwrap()
        .to_svg()
        .unwrap();
    let (doc, vb) = parse(&svg);
    assert_inside(&doc, vb);
    let ps = panels(&doc);
    assert_eq!(ps.len(), 2);
    assert_eq!(ps[0].series, ["a"]);
    assert_eq!(ps[1].series, ["P.x", "P.y"]);
    let labels: Vec<&str> = with_class(doc.root_element(), "y-label")
        .iter()
        .map(|t| t.text().unwrap())
        .collect();
    assert_eq!(labels, ["angle (deg)", "position (mm)"]);
    for path in elements(doc.root_element(), "path")
        .iter()
        .filter(|p| p.attribute("data-series").is_some())
    {
        let d = path.attribute("d").unwrap();
        assert_eq!(d.matches('M').count(), 2, "two runs: {d}");
        assert_eq!(path_points(d).len(), 36, "41 rows, 5 failed");
    }
    for w in ps[0].paths[0].windows(2) {
        assert!(w[1][1] < w[0][1], "the angle rises continuously: {w:?}");
    }
    assert!(matches!(
        any::chart("t", ("x", "deg"), &rows, &["nope"]),
        Err(PlotError::NoField { ref name, .. }) if name == "nope"
    ));
}

/// A panel with more series than its height shows grows to hold its legend:
/// with 30 series (600 px of legend rows in a 340 px panel) every legend entry
/// lies inside the panel's part of the canvas, above the next panel.
#[test]
fn a_long_legend_stays_inside_its_panel() {
    let (xs, ys) = sine();
    let mut many = Plot::new("many").x_axis("x", "");
    for k in 0..30 {
        let shifted: Vec<f64> = ys.iter().map(|y| y + k as f64).collect();
        many = many.series(&format!("s{k}"), &xs, &shifted);
    }
    let svg = Figure::new("fig")
        .panel(many)
        .panel(Plot::new("below").series("a", &xs, &ys))
        .to_svg()
        .unwrap();
    let (doc, vb) = parse(&svg);
    assert_inside(&doc, vb);
    let ps = panels(&doc);
    let legend = with_class(doc.root_element(), "legend");
    let last = elements(legend[0], "text")
        .iter()
        .map(|t| num(t, "y"))
        .fold(f64::MIN, f64::max);
    assert!(
        last < ps[1].area[1] - 30.0,
        "the last legend row ({last} px) above the next panel's plot area ({} px)",
        ps[1].area[1]
    );
}

/// `f32` results chart and tabulate as their `f64` counterparts do: the same
/// panels, series and labels, every vertex within a pixel's rounding of the
/// `f64` chart's (the values differ by f32's rounding, 6e-8 relative, far below
/// the 0.01 px the SVG writes), and the CSV's numbers are the `f32` values
/// widened exactly.
#[test]
fn f32_results_chart_and_tabulate_like_f64() {
    let rows64 = out_rows();
    let rows32: Vec<(f64, Option<Out<f32>>)> = rows64
        .iter()
        .map(|(x, o)| {
            let o = o.as_ref().map(|o| Out {
                a: o.a as f32,
                p: Point2::new(o.p.x as f32, o.p.y as f32),
            });
            (*x, o)
        })
        .collect();
    let svg64 = any::chart("t", ("x", "deg"), &rows64, &["a", "P"])
        .unwrap()
        .to_svg()
        .unwrap();
    let svg32 = any::chart("t", ("x", "deg"), &rows32, &["a", "P"])
        .unwrap()
        .to_svg()
        .unwrap();
    let ((d64, _), (d32, _)) = (parse(&svg64), parse(&svg32));
    let (p64, p32) = (panels(&d64), panels(&d32));
    assert_eq!(p64.len(), p32.len());
    for (a, b) in p64.iter().zip(&p32) {
        assert_eq!(a.series, b.series);
        for (pa, pb) in a.paths.iter().zip(&b.paths) {
            assert_eq!(pa.len(), pb.len());
            for (u, v) in pa.iter().zip(pb) {
                assert!(
                    (u[0] - v[0]).abs() <= 0.011 && (u[1] - v[1]).abs() <= 0.011,
                    "{u:?} {v:?}"
                );
            }
        }
    }
    let csv = any::csv("x", "deg", &rows32);
    let header = csv.lines().next().unwrap();
    assert_eq!(header, "x [deg],a [rad],P.x [mm],P.y [mm]");
    let row: Vec<f64> = csv
        .lines()
        .nth(2)
        .unwrap()
        .split(',')
        .map(|c| c.parse().unwrap())
        .collect();
    let o = rows32[1].1.as_ref().unwrap();
    assert_eq!(
        row[1..],
        [f64::from(o.a), f64::from(o.p.x), f64::from(o.p.y)]
    );
}

/// Without a `units` statement the symbols stay: the CSV header and the
/// chart's y labels say `L` (and the x axis what the caller says).
#[test]
fn a_definition_without_units_is_labelled_with_the_symbols() {
    #[derive(Clone)]
    struct Bare(f64);
    impl Fields<f64> for Bare {
        const FIELDS: &'static [Field] = &[Field {
            name: "s",
            quantity: Quantity::Velocity,
            planar: false,
        }];
        const UNITS: Units = Units::SYMBOLS;
        fn get(&self, name: &str) -> Option<Value<f64>> {
            (name == "s").then_some(Value::Scalar(self.0))
        }
    }
    let rows = vec![(0.0, Some(Bare(1.0))), (1.0, Some(Bare(2.0)))];
    assert!(any::csv("x", "s", &rows).starts_with("x [s],s [L/s]\n"));
    let svg = any::chart("t", ("x", "s"), &rows, &[])
        .unwrap()
        .to_svg()
        .unwrap();
    let (doc, _) = parse(&svg);
    let labels: Vec<&str> = with_class(doc.root_element(), "y-label")
        .iter()
        .map(|t| t.text().unwrap())
        .collect();
    assert_eq!(labels, ["velocity (L/s)"]);
}

/// A crank O-A about the ground pivot O, as the macro describes one, in mm.
struct Crank;

impl Describe for Crank {
    const STRUCTURE: Structure = Structure {
        name: "Crank",
        points: &[
            Point {
                name: "O",
                kind: PointKind::Ground,
            },
            Point {
                name: "A",
                kind: PointKind::Joint,
            },
        ],
        links: &[Link {
            name: "link2",
            named: true,
            kind: LinkKind::Crank,
            points: &["O", "A"],
            guide: None,
        }],
        guides: &[],
        inputs: &[Input {
            name: "theta",
            quantity: Quantity::Angle,
            driver: "A",
        }],
        masses: &[],
        units: MM_N,
    };
}

/// The crank's position: O and A.
#[derive(Clone)]
struct CrankAt<T: Real> {
    o: Point2<T>,
    a: Point2<T>,
}

impl<T: Real> Fields<T> for CrankAt<T> {
    const FIELDS: &'static [Field] = &[
        Field {
            name: "O",
            quantity: Quantity::Length,
            planar: true,
        },
        Field {
            name: "A",
            quantity: Quantity::Length,
            planar: true,
        },
    ];
    const UNITS: Units = MM_N;
    fn get(&self, name: &str) -> Option<Value<T>> {
        match name {
            "O" => Some(Value::Point(self.o)),
            "A" => Some(Value::Point(self.a)),
            _ => None,
        }
    }
}

/// An animation's captions give a crank's angle in degrees (the poses hold
/// radians: 0.5236 rad is `theta = 30 deg`), its scale bar the definition's
/// length unit; `f32` poses draw as `f64` ones do.
#[test]
fn captions_are_in_degrees_and_the_scale_in_the_units() {
    let poses: Vec<(f64, Option<CrankAt<f32>>)> = (0..4)
        .map(|k| {
            let t = (30.0 * k as f64).to_radians();
            let a = Point2::new(50.0 * t.cos() as f32, 50.0 * t.sin() as f32);
            (
                t,
                Some(CrankAt {
                    o: Point2::origin(),
                    a,
                }),
            )
        })
        .collect();
    let svg = any::sketch::<Crank, _>("crank", &poses, &[])
        .unwrap()
        .animation(2.0)
        .unwrap();
    let (doc, _) = parse(&svg);
    let captions: Vec<&str> = with_class(doc.root_element(), "caption")
        .iter()
        .map(|t| t.text().unwrap())
        .collect();
    assert_eq!(
        captions,
        [
            "theta = 0 deg",
            "theta = 30 deg",
            "theta = 60 deg",
            "theta = 90 deg"
        ]
    );
    let scale = with_class(doc.root_element(), "scale-label");
    assert!(
        scale[0].text().unwrap().ends_with(" mm"),
        "the scale bar is in mm"
    );
}
