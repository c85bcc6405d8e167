//! Small SVG text helpers shared by plots and sketches.

use std::fmt::Write;

/// Font stack of every text element: the viewer's own sans-serif font.
pub const FONT: &str = "DejaVu Sans, Helvetica, Arial, sans-serif";

/// Series and link colours: the Okabe-Ito palette (distinguishable with the common colour
/// vision deficiencies) without its yellow, which is too pale on white, then brown, grey
/// and a dark yellow.
pub const PALETTE: [&str; 10] = [
    "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#8C564B",
    "#7F7F7F", "#B59F00",
];

/// Dash patterns paired with the palette's second cycle, so that series 11.. still differ.
pub const DASHES: [&str; 3] = ["", "6 3", "2 3"];

/// A pixel coordinate with at most two decimals, trailing zeros dropped (`12.5`, `3`,
/// never `-0`). Callers pass finite values only (checked upstream).
pub fn num(v: f64) -> String {
    let r = (v * 100.0).round() / 100.0;
    let r = if r == 0.0 { 0.0 } else { r };
    let mut s = format!("{r:.2}");
    while s.ends_with('0') {
        s.pop();
    }
    if s.ends_with('.') {
        s.pop();
    }
    s
}

/// Escapes text for SVG character data and attribute values.
pub fn esc(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            _ => out.push(c),
        }
    }
    out
}

/// Unit text for display: `^` followed by an optional minus and digits becomes
/// superscript characters (`rad/s^2` -> `rad/s²`, `m^-1` -> `m⁻¹`).
pub fn pretty_unit(unit: &str) -> String {
    let mut out = String::new();
    let mut chars = unit.chars().peekable();
    while let Some(c) = chars.next() {
        if c == '^' {
            let mut sup = String::new();
            while let Some(&d) = chars.peek() {
                let s = superscript(d);
                if s.is_none() || (d == '-' && !sup.is_empty()) {
                    break;
                }
                sup.push(s.unwrap_or(d));
                chars.next();
            }
            if sup.is_empty() {
                out.push('^');
            } else {
                out.push_str(&sup);
            }
        } else {
            out.push(c);
        }
    }
    out
}

/// The superscript form of a digit or minus sign.
pub fn superscript(c: char) -> Option<char> {
    Some(match c {
        '0' => '⁰',
        '1' => '¹',
        '2' => '²',
        '3' => '³',
        '4' => '⁴',
        '5' => '⁵',
        '6' => '⁶',
        '7' => '⁷',
        '8' => '⁸',
        '9' => '⁹',
        '-' => '⁻',
        _ => return None,
    })
}

/// `10` followed by the exponent in superscript characters (`10³`, `10⁻³`).
pub fn pow10_text(exp: i32) -> String {
    let mut s = String::from("10");
    for c in exp.to_string().chars() {
        s.push(superscript(c).unwrap_or(c));
    }
    s
}

/// A polyline's path data `M x y L x y ...` from pixel coordinates.
pub fn path_data(points: &[[f64; 2]]) -> String {
    let mut d = String::with_capacity(points.len() * 14);
    for (k, p) in points.iter().enumerate() {
        let _ = write!(
            d,
            "{}{} {}",
            if k == 0 { "M" } else { " L" },
            num(p[0]),
            num(p[1])
        );
    }
    d
}

/// Opening tag of a standalone SVG document of `w` x `h` pixels.
pub fn open_svg(out: &mut String, w: f64, h: f64) {
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" version="1.1" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="{FONT}">"#,
        w = num(w),
        h = num(h)
    );
    let _ = writeln!(
        out,
        r#"<rect x="0" y="0" width="{}" height="{}" fill="white"/>"#,
        num(w),
        num(h)
    );
}

/// A text element; `anchor` is `start`, `middle` or `end`.
#[allow(clippy::too_many_arguments)]
pub fn text(out: &mut String, x: f64, y: f64, size: f64, anchor: &str, extra: &str, t: &str) {
    let _ = writeln!(
        out,
        r#"<text x="{}" y="{}" font-size="{}" text-anchor="{anchor}"{extra}>{}</text>"#,
        num(x),
        num(y),
        num(size),
        esc(t)
    );
}

/// Approximate advance width of `t` in pixels at font size `size` (sans-serif averages
/// about 0.6 em per character); used only to reserve margins.
pub fn text_width(t: &str, size: f64) -> f64 {
    t.chars().count() as f64 * 0.6 * size
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short_and_never_negative_zero() {
        assert_eq!(num(12.5), "12.5");
        assert_eq!(num(3.0), "3");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(-1.239), "-1.24");
    }

    #[test]
    fn units_get_superscripts() {
        assert_eq!(pretty_unit("rad/s^2"), "rad/s²");
        assert_eq!(pretty_unit("m^-1"), "m⁻¹");
        assert_eq!(pretty_unit("a^b"), "a^b");
        assert_eq!(pow10_text(-3), "10⁻³");
    }

    #[test]
    fn escaping() {
        assert_eq!(esc("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
    }
}
