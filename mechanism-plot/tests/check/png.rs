//! Pictures looked at, not only parsed: an SVG rendered to pixels with resvg
//! (pure Rust; text laid out with the system's fonts) and checked as a person
//! would see it: the image is not blank, it has more than one colour, every
//! text element was laid out (a font was found for it) and every label's box
//! lies inside the canvas.
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
    assert!(
        !opt.fontdb.is_empty(),
        "no system font found: the labels cannot be laid out (install e.g. fonts-dejavu-core)"
    );
    opt
}

/// Every text node of `group` and below, with its box in canvas px.
fn text_boxes(group: &usvg::Group, out: &mut Vec<usvg::Rect>) {
    for node in group.children() {
        match node {
            Node::Group(g) => text_boxes(g, out),
            Node::Text(t) => out.push(t.abs_bounding_box()),
            _ => {}
        }
    }
}

/// Renders `svg` (named `what` in messages) and checks it: at least `min_ink`
/// of the pixels are not white, at least 3 colours, as many text nodes laid
/// out as the SVG has non-empty `<text>` elements, and every text box inside
/// the canvas (to 0.5 px: anti-aliasing of the box's edge).
pub fn look(svg: &str, what: &str, min_ink: f64) -> Look {
    let tree = Tree::from_str(svg, &options()).unwrap_or_else(|e| panic!("{what}: {e}"));
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
    let written = doc
        .descendants()
        .filter(|n| n.has_tag_name("text") && n.text().is_some_and(|t| !t.trim().is_empty()))
        .count();
    let mut boxes = Vec::new();
    text_boxes(tree.root(), &mut boxes);
    assert_eq!(
        boxes.len(),
        written,
        "{what}: every text element laid out with a font"
    );
    for b in &boxes {
        assert!(
            b.left() >= -0.5
                && b.top() >= -0.5
                && b.right() <= w as f32 + 0.5
                && b.bottom() <= h as f32 + 0.5,
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
