//! A work-precision plot (error against run time, log-log) as a hand-written
//! SVG: one marker per method, methods of one family joined by a line
//! (Newton at tolerances 1e-3 .. 1e-14).

/// One plotted point: family (legend and colour), label, ns per evaluation,
/// error.
pub struct Pt {
    pub family: String,
    pub label: String,
    pub ns: f64,
    pub err: f64,
}

const COLOURS: [&str; 8] = [
    "#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf",
];

fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// Renders the plot; errors below `floor` are drawn at `floor` (exact results).
pub fn plot(title: &str, points: &[Pt], floor: f64) -> String {
    let (w, h, ml, mr, mt, mb) = (760.0, 480.0, 70.0, 230.0, 40.0, 50.0);
    let lx = |v: f64| v.max(1e-300).log10();
    let ns_min = points.iter().map(|p| p.ns).fold(f64::INFINITY, f64::min);
    let ns_max = points.iter().map(|p| p.ns).fold(0.0, f64::max);
    let x0 = lx(ns_min).floor();
    let x1 = lx(ns_max).ceil().max(x0 + 1.0);
    let e = |p: &Pt| p.err.max(floor);
    let y0 = lx(points.iter().map(e).fold(f64::INFINITY, f64::min)).floor();
    let y1 = lx(points.iter().map(e).fold(0.0, f64::max))
        .ceil()
        .max(y0 + 1.0);
    let px = |v: f64| ml + (lx(v) - x0) / (x1 - x0) * (w - ml - mr);
    let py = |v: f64| mt + (y1 - lx(v.max(floor))) / (y1 - y0) * (h - mt - mb);
    let mut s = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="11">
<rect width="100%" height="100%" fill="white"/>
<text x="{}" y="20" font-size="14" text-anchor="middle">{}</text>
"#,
        (w - mr + ml) / 2.0,
        esc(title)
    );
    // Grid and axes labels (decades).
    let mut d = x0;
    while d <= x1 + 1e-9 {
        let x = ml + (d - x0) / (x1 - x0) * (w - ml - mr);
        s += &format!(
            "<line x1=\"{x}\" y1=\"{mt}\" x2=\"{x}\" y2=\"{}\" stroke=\"#ddd\"/><text x=\"{x}\" y=\"{}\" text-anchor=\"middle\">1e{d}</text>\n",
            h - mb,
            h - mb + 15.0
        );
        d += 1.0;
    }
    let mut d = y0;
    while d <= y1 + 1e-9 {
        let y = mt + (y1 - d) / (y1 - y0) * (h - mt - mb);
        s += &format!(
            "<line x1=\"{ml}\" y1=\"{y}\" x2=\"{}\" y2=\"{y}\" stroke=\"#ddd\"/><text x=\"{}\" y=\"{}\" text-anchor=\"end\">1e{d}</text>\n",
            w - mr,
            ml - 5.0,
            y + 4.0
        );
        d += 1.0;
    }
    s += &format!(
        "<rect x=\"{ml}\" y=\"{mt}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"black\"/>\n",
        w - ml - mr,
        h - mt - mb
    );
    s += &format!(
        "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">ns per evaluation (median)</text>\n",
        (w - mr + ml) / 2.0,
        h - 12.0
    );
    s += &format!(
        "<text transform=\"translate(16,{}) rotate(-90)\" text-anchor=\"middle\">max error / column scale</text>\n",
        (h - mb + mt) / 2.0
    );
    // Families in order of appearance.
    let mut families: Vec<&str> = Vec::new();
    for p in points {
        if !families.contains(&p.family.as_str()) {
            families.push(&p.family);
        }
    }
    for (k, fam) in families.iter().enumerate() {
        let c = COLOURS[k % COLOURS.len()];
        let pts: Vec<&Pt> = points.iter().filter(|p| p.family == *fam).collect();
        if pts.len() > 1 {
            let path: Vec<String> = pts
                .iter()
                .map(|p| format!("{:.1},{:.1}", px(p.ns), py(p.err)))
                .collect();
            s += &format!(
                "<polyline points=\"{}\" fill=\"none\" stroke=\"{c}\" stroke-width=\"1.2\"/>\n",
                path.join(" ")
            );
        }
        for p in &pts {
            s += &format!(
                "<circle cx=\"{:.1}\" cy=\"{:.1}\" r=\"3.5\" fill=\"{c}\"><title>{}: {:.1} ns, {:.2e}</title></circle>\n",
                px(p.ns),
                py(p.err),
                esc(&p.label),
                p.ns,
                p.err
            );
        }
        let ly = mt + 14.0 * k as f64 + 8.0;
        s += &format!(
            "<circle cx=\"{}\" cy=\"{ly}\" r=\"3.5\" fill=\"{c}\"/><text x=\"{}\" y=\"{}\">{}</text>\n",
            w - mr + 12.0,
            w - mr + 20.0,
            ly + 4.0,
            esc(fam)
        );
    }
    s += &format!(
        "<text x=\"{}\" y=\"{}\" fill=\"#555\">errors below {floor:.0e} drawn at {floor:.0e}</text>\n",
        w - mr + 12.0,
        h - mb
    );
    s += "</svg>\n";
    s
}
