//! An independent reader of the SVG files `mechanism-plot` writes, shared by
//! `mechanism-plot/tests/api.rs` and the root `tests/examples/plots.rs`. It parses the XML with
//! `roxmltree` (a real parser: a malformed file fails here) and reads the geometry back
//! from the attributes, without using the crate's code.
#![allow(dead_code)]

use roxmltree::{Document, Node};

/// Coordinates are written with two decimals: any single coordinate is within 0.005 px
/// of its exact value.
pub const ROUND: f64 = 0.005;

/// Parses `svg`; panics (failing the test) on malformed XML or a root that is not an
/// `<svg>` with a four-number viewBox. Returns the document and the viewBox.
pub fn parse(svg: &str) -> (Document<'_>, [f64; 4]) {
    let doc = Document::parse(svg).unwrap_or_else(|e| panic!("malformed SVG: {e}"));
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "svg", "root element");
    let vb: Vec<f64> = root
        .attribute("viewBox")
        .expect("viewBox")
        .split_whitespace()
        .map(|t| t.parse().expect("viewBox number"))
        .collect();
    assert_eq!(vb.len(), 4, "viewBox has 4 numbers");
    assert!(vb.iter().all(|v| v.is_finite()) && vb[2] > 0.0 && vb[3] > 0.0);
    (doc, [vb[0], vb[1], vb[2], vb[3]])
}

pub fn class_is(n: &Node, class: &str) -> bool {
    n.attribute("class") == Some(class)
}

pub fn elements<'a, 'i>(node: Node<'a, 'i>, tag: &str) -> Vec<Node<'a, 'i>> {
    node.descendants()
        .filter(|n| n.is_element() && n.tag_name().name() == tag)
        .collect()
}

pub fn with_class<'a, 'i>(node: Node<'a, 'i>, class: &str) -> Vec<Node<'a, 'i>> {
    node.descendants()
        .filter(|n| n.is_element() && class_is(n, class))
        .collect()
}

pub fn num(n: &Node, attr: &str) -> f64 {
    let v: f64 = n
        .attribute(attr)
        .unwrap_or_else(|| panic!("<{}> lacks {attr}", n.tag_name().name()))
        .parse()
        .unwrap_or_else(|e| panic!("{attr}: {e}"));
    assert!(v.is_finite(), "{attr} is finite");
    v
}

/// The vertices of path data made of `M`, `L` and `Z` commands (all the crate writes);
/// panics on anything else, on an empty path and on a non-finite number.
pub fn path_points(d: &str) -> Vec<[f64; 2]> {
    let mut pts = Vec::new();
    let mut nums: Vec<f64> = Vec::new();
    let flush = |nums: &mut Vec<f64>, pts: &mut Vec<[f64; 2]>| {
        assert!(
            nums.len().is_multiple_of(2),
            "odd number count in path `{d}`"
        );
        for c in nums.chunks(2) {
            pts.push([c[0], c[1]]);
        }
        nums.clear();
    };
    let mut tok = String::new();
    for ch in d.chars().chain(std::iter::once(' ')) {
        match ch {
            'M' | 'L' | 'Z' | ' ' => {
                if !tok.is_empty() {
                    let v: f64 = tok.parse().unwrap_or_else(|e| panic!("`{tok}`: {e}"));
                    assert!(v.is_finite());
                    nums.push(v);
                    tok.clear();
                }
                if ch != ' ' {
                    flush(&mut nums, &mut pts);
                }
            }
            c if c.is_ascii_digit() || c == '.' || c == '-' || c == 'e' => tok.push(c),
            c => panic!("unexpected `{c}` in path data `{d}`"),
        }
    }
    flush(&mut nums, &mut pts);
    assert!(!pts.is_empty(), "empty path data");
    pts
}

/// Every coordinate of every path, line, circle, rect and text lies inside the viewBox
/// and every path is non-empty.
pub fn assert_inside(doc: &Document, vb: [f64; 4]) {
    let inside = |x: f64, y: f64, what: &str| {
        assert!(
            x >= vb[0] && x <= vb[0] + vb[2] && y >= vb[1] && y <= vb[1] + vb[3],
            "{what} at ({x}, {y}) outside the viewBox {vb:?}"
        );
    };
    let root = doc.root_element();
    for p in elements(root, "path") {
        for q in path_points(p.attribute("d").expect("d")) {
            inside(q[0], q[1], "path vertex");
        }
    }
    for l in elements(root, "line") {
        inside(num(&l, "x1"), num(&l, "y1"), "line end");
        inside(num(&l, "x2"), num(&l, "y2"), "line end");
    }
    for c in elements(root, "circle") {
        inside(num(&c, "cx"), num(&c, "cy"), "circle");
    }
    for r in elements(root, "rect")
        .into_iter()
        .filter(|r| r.parent().map(|p| p.tag_name().name()) != Some("clipPath"))
    {
        inside(num(&r, "x"), num(&r, "y"), "rect corner");
        inside(
            num(&r, "x") + num(&r, "width"),
            num(&r, "y") + num(&r, "height"),
            "rect corner",
        );
    }
    for t in elements(root, "text") {
        inside(num(&t, "x"), num(&t, "y"), "text");
    }
}

/// A tick label as a number (the crate prints a true minus sign, U+2212).
pub fn label_value(t: &Node) -> f64 {
    let s = t.text().unwrap_or("").replace('\u{2212}', "-");
    s.parse()
        .unwrap_or_else(|e| panic!("tick label `{s}`: {e}"))
}

/// One plot panel read back.
pub struct Panel {
    /// Series names in drawing order (from the series paths).
    pub series: Vec<String>,
    /// Legend entries in order.
    pub legend: Vec<String>,
    /// (value, pixel x) of the x ticks, (value, pixel y) of the y ticks.
    pub x_ticks: Vec<(f64, f64)>,
    pub y_ticks: Vec<(f64, f64)>,
    /// Vertex lists of the series paths.
    pub paths: Vec<Vec<[f64; 2]>>,
    /// The plot area: x, y, width, height.
    pub area: [f64; 4],
}

/// Reads every `<g class="panel">`, checking on the way that tick values increase
/// left to right and bottom to top and that the legend names every series once.
pub fn panels(doc: &Document) -> Vec<Panel> {
    let out: Vec<Panel> = with_class(doc.root_element(), "panel")
        .into_iter()
        .map(|g| {
            let group = |c: &str| {
                with_class(g, c)
                    .into_iter()
                    .next()
                    .unwrap_or_else(|| panic!("no {c}"))
            };
            let ticks = |c: &str, coord: &str| -> Vec<(f64, f64)> {
                elements(group(c), "text")
                    .iter()
                    .map(|t| (label_value(t), num(t, coord)))
                    .collect()
            };
            let x_ticks = ticks("x-tick-labels", "x");
            let y_ticks = ticks("y-tick-labels", "y");
            assert!(
                x_ticks.len() >= 2 && y_ticks.len() >= 2,
                "at least two ticks per axis"
            );
            for w in x_ticks.windows(2) {
                assert!(
                    w[1].0 > w[0].0 && w[1].1 > w[0].1,
                    "x ticks increase: {x_ticks:?}"
                );
            }
            for w in y_ticks.windows(2) {
                assert!(
                    w[1].0 > w[0].0 && w[1].1 < w[0].1,
                    "y ticks increase upwards: {y_ticks:?}"
                );
            }
            let series_paths: Vec<Node> = elements(group("series"), "path");
            let series: Vec<String> = series_paths
                .iter()
                .map(|p| p.attribute("data-series").expect("data-series").to_string())
                .collect();
            let paths = series_paths
                .iter()
                .map(|p| path_points(p.attribute("d").unwrap()))
                .collect();
            let legend: Vec<String> = elements(group("legend"), "text")
                .iter()
                .map(|t| t.text().unwrap_or("").to_string())
                .collect();
            assert_eq!(legend, series, "the legend lists every series, in order");
            let frame = elements(g, "rect")
                .into_iter()
                .find(|r| r.attribute("fill") == Some("none"))
                .expect("plot area frame");
            Panel {
                series,
                legend,
                x_ticks,
                y_ticks,
                paths,
                area: [
                    num(&frame, "x"),
                    num(&frame, "y"),
                    num(&frame, "width"),
                    num(&frame, "height"),
                ],
            }
        })
        .collect();
    assert!(!out.is_empty(), "a plot has at least one panel");
    out
}

/// The frames of an animation: for each, the visibility it has at cycle fraction `t`
/// under its discrete `<animate>` (values hold from their key time to the next).
pub fn visible_at(frame: &Node, t: f64) -> bool {
    let a = elements(*frame, "animate")
        .into_iter()
        .next()
        .expect("<animate> in frame");
    assert_eq!(a.attribute("attributeName"), Some("visibility"));
    assert_eq!(a.attribute("calcMode"), Some("discrete"));
    assert_eq!(a.attribute("repeatCount"), Some("indefinite"));
    let values: Vec<&str> = a.attribute("values").unwrap().split(';').collect();
    let times: Vec<f64> = a
        .attribute("keyTimes")
        .unwrap()
        .split(';')
        .map(|k| k.parse().unwrap())
        .collect();
    assert_eq!(values.len(), times.len(), "one key time per value");
    assert_eq!(times[0], 0.0, "key times start at 0");
    assert!(times.windows(2).all(|w| w[1] > w[0]) && times.iter().all(|k| *k < 1.0));
    let k = times.iter().rposition(|&k| k <= t).unwrap();
    values[k] == "visible"
}
