//! Pictures looked at, not only parsed: an SVG rendered to pixels with resvg
//! (pure Rust; text laid out with the system's fonts) and checked as a person
//! would see it: the image is not blank, it has more than one colour, every
//! text element was laid out (a font was found for it), no two texts overlap
//! and every label's box lies inside the canvas.
//!
//! Shared by the tests that render pictures (`#[path]`-included; a
//! dev-dependency only, the library stays free of it).
#![allow(dead_code)]

use resvg::tiny_skia::{Pixmap, Transform};
use resvg::usvg::{self, Node, Options, Tree};
use std::collections::HashSet;

/// What a rendered picture shows.
pub struct Look {
    /// The PNG file's bytes.
    pub png: Vec<u8>,
    /// Canvas size in px.
    pub size: (u32, u32),
    /// Share of the pixels that are not the white background.
    pub inked: f64,
    /// Distinct colours among those pixels (each channel to 4 bits).
    pub colours: usize,
    /// Text elements laid out (each with its box inside the canvas).
    pub texts: usize,
}

/// Fonts: the system's, with DejaVu Sans for the generic `sans-serif` (the
/// font stack of `mechanism-plot` names it first).
fn options() -> Options<'static> {
    let mut opt = Options::default();
    opt.fontdb_mut().load_system_fonts();
    opt.fontdb_mut().set_sans_serif_family("DejaVu Sans");
    opt
}

/// Text boxes estimated from the SVG's attributes alone, for a system with no
/// font (nothing to lay text out with): from `x`, `y`, `font-size`,
/// `text-anchor` and a `rotate(a cx cy)` transform, 0.62 em per character
/// (DejaVu Sans' mean advance on these labels), 0.8 em above the baseline and
/// 0.25 em below.
fn estimated_boxes(doc: &roxmltree::Document) -> Vec<[f32; 4]> {
    let num = |n: &roxmltree::Node, a: &str| -> f32 {
        n.attribute(a).and_then(|v| v.parse().ok()).unwrap_or(0.0)
    };
    let mut out = Vec::new();
    for t in doc.descendants().filter(|n| n.has_tag_name("text")) {
        let Some(text) = t.text().filter(|s| !s.trim().is_empty()) else {
            continue;
        };
        let (x, y, size) = (num(&t, "x"), num(&t, "y"), num(&t, "font-size"));
        let w = 0.62 * size * text.chars().count() as f32;
        let x0 = match t.attribute("text-anchor") {
            Some("middle") => x - w / 2.0,
            Some("end") => x - w,
            _ => x,
        };
        let mut b = [x0, y - 0.8 * size, x0 + w, y + 0.25 * size];
        if let Some(r) = t
            .attribute("transform")
            .and_then(|v| v.strip_prefix("rotate("))
        {
            let v: Vec<f32> = r
                .trim_end_matches(')')
                .split([' ', ','])
                .filter_map(|p| p.parse().ok())
                .collect();
            if let [a, cx, cy] = v[..] {
                let (sin, cos) = a.to_radians().sin_cos();
                let turn = |px: f32, py: f32| {
                    let (dx, dy) = (px - cx, py - cy);
                    (cx + dx * cos - dy * sin, cy + dx * sin + dy * cos)
                };
                let c = [
                    turn(b[0], b[1]),
                    turn(b[2], b[1]),
                    turn(b[0], b[3]),
                    turn(b[2], b[3]),
                ];
                b = [
                    c.iter().map(|p| p.0).fold(f32::MAX, f32::min),
                    c.iter().map(|p| p.1).fold(f32::MAX, f32::min),
                    c.iter().map(|p| p.0).fold(f32::MIN, f32::max),
                    c.iter().map(|p| p.1).fold(f32::MIN, f32::max),
                ];
            }
        }
        out.push(b);
    }
    out
}

/// Every text node of `group` and below, with its box in canvas px (left,
/// top, right, bottom).
fn text_boxes(group: &usvg::Group, out: &mut Vec<[f32; 4]>) {
    for node in group.children() {
        match node {
            Node::Group(g) => text_boxes(g, out),
            Node::Text(t) => {
                let b = t.abs_bounding_box();
                out.push([b.left(), b.top(), b.right(), b.bottom()]);
            }
            _ => {}
        }
    }
}

/// Renders `svg` (named `what` in messages) and checks it: at least `min_ink`
/// of the pixels are not white, at least 3 colours, as many text nodes laid
/// out as the SVG has non-empty `<text>` elements, no two text boxes
/// overlapping, and every text box inside the canvas (to 0.5 px:
/// anti-aliasing of the box's edge). On a system with
/// no font the text cannot be laid out: the boxes are then estimated
/// ([`estimated_boxes`]) and a note says so on stderr.
pub fn look(svg: &str, what: &str, min_ink: f64) -> Look {
    let opt = options();
    let tree = Tree::from_str(svg, &opt).unwrap_or_else(|e| panic!("{what}: {e}"));
    let size = tree.size().to_int_size();
    let (w, h) = (size.width(), size.height());
    let mut pixmap = Pixmap::new(w, h).unwrap_or_else(|| panic!("{what}: {w} x {h} px"));
    resvg::render(&tree, Transform::default(), &mut pixmap.as_mut());
    let mut colours = HashSet::new();
    let mut inked = 0usize;
    for p in pixmap.pixels() {
        let c = p.demultiply();
        let rgba = (c.red(), c.green(), c.blue(), c.alpha());
        if rgba != (255, 255, 255, 255) {
            inked += 1;
            colours.insert((rgba.0 >> 4, rgba.1 >> 4, rgba.2 >> 4));
        }
    }
    let inked = inked as f64 / (w as f64 * h as f64);
    assert!(
        inked >= min_ink,
        "{what}: only {:.2} % of the pixels are drawn",
        100.0 * inked
    );
    assert!(
        colours.len() >= 3,
        "{what}: {} colours besides the background",
        colours.len()
    );
    let doc = roxmltree::Document::parse(svg).unwrap_or_else(|e| panic!("{what}: {e}"));
    let boxes = if opt.fontdb.is_empty() {
        eprintln!("{what}: no system font, label boxes estimated from the SVG");
        estimated_boxes(&doc)
    } else {
        let mut boxes = Vec::new();
        text_boxes(tree.root(), &mut boxes);
        assert_eq!(
            boxes.len(),
            estimated_boxes(&doc).len(),
            "{what}: every text element laid out with a font"
        );
        boxes
    };
    // No two texts overlap (by more than 1 px each way: glyph boxes touch at
    // their anti-aliased edges).
    for (i, a) in boxes.iter().enumerate() {
        for b in &boxes[..i] {
            let (dx, dy) = (
                a[2].min(b[2]) - a[0].max(b[0]),
                a[3].min(b[3]) - a[1].max(b[1]),
            );
            assert!(
                dx <= 1.0 || dy <= 1.0,
                "{what}: texts at {a:?} and {b:?} overlap"
            );
        }
    }
    for b in &boxes {
        assert!(
            b[0] >= -0.5 && b[1] >= -0.5 && b[2] <= w as f32 + 0.5 && b[3] <= h as f32 + 0.5,
            "{what}: a label's box {b:?} leaves the {w} x {h} px canvas"
        );
    }
    let png = pixmap
        .encode_png()
        .unwrap_or_else(|e| panic!("{what}: {e}"));
    Look {
        png,
        size: (w, h),
        inked,
        colours: colours.len(),
        texts: boxes.len(),
    }
}

/// Writes `look`'s PNG as `name` into the directory named by the environment
/// variable `MECHANISM_DOC_PNGS`, when it is set (how `docs/*.png` are made).
pub fn save_for_docs(look: &Look, name: &str) {
    if let Some(dir) = std::env::var_os("MECHANISM_DOC_PNGS") {
        let path = std::path::Path::new(&dir).join(name);
        std::fs::write(&path, &look.png).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    }
}
