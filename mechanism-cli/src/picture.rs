//! `mechanism draw`, `animate` and `chart`: SVG pictures of a run-time
//! mechanism. The drawing and the animation are `mechanism_plot::runtime`'s
//! (shared with the Python package); the chart (`Plot`/`Figure`: outputs
//! against the swept input) reads the command's table.

use crate::table::Table;
use mechanism_codegen::runtime::Mechanism;
pub use mechanism_plot::runtime::{caption, poses, sketch};
use mechanism_plot::{Figure, Plot};

/// The chart of `outputs` against the first input over the table's rows:
/// one panel per output (a point: its `x` and `y` together), angles in
/// degrees, gaps where a pose fails. An output is a column's name without
/// its unit (`link3`, `velocity.B.x`, `forces.drive_theta`) or a point's
/// (`B`: `B.x` and `B.y`).
pub fn chart(t: &Table, m: &Mechanism, title: &str, outputs: &[String]) -> Result<Figure, String> {
    let input = m
        .inputs()
        .into_iter()
        .next()
        .ok_or("the definition has no input")?;
    let to_x = |v: f64| if input.angle { v.to_degrees() } else { v };
    let xs: Vec<f64> = t.rows.iter().map(|(q, _)| to_x(q[0])).collect();
    let x_unit = if input.angle {
        "deg".to_string()
    } else {
        m.layout().length_unit
    };
    let columns: Vec<(String, String)> = t
        .header
        .iter()
        .map(|h| {
            let (n, u) = h.rsplit_once(" [").unwrap_or((h, "]"));
            (n.to_string(), u.trim_end_matches(']').to_string())
        })
        .collect();
    let mut fig = Figure::new(title);
    for out in outputs {
        let first = t.input_names.len();
        let outs = || columns.iter().enumerate().skip(first);
        let picked: Vec<usize> = match outs().find(|(_, (n, _))| n == out) {
            Some((k, _)) => vec![k],
            None => outs()
                .filter(|(_, (n, _))| *n == format!("{out}.x") || *n == format!("{out}.y"))
                .map(|(k, _)| k)
                .collect(),
        };
        if picked.is_empty() {
            let names: Vec<&str> = outs().map(|(_, (n, _))| n.as_str()).collect();
            return Err(format!(
                "--outputs: no output `{out}`; the outputs are: {}",
                names.join(", ")
            ));
        }
        let unit = &columns[picked[0]].1;
        let angle = unit.starts_with("rad");
        let (y_unit, scale) = if angle {
            (unit.replacen("rad", "deg", 1), 180.0 / std::f64::consts::PI)
        } else {
            (unit.clone(), 1.0)
        };
        let mut plot = Plot::new("")
            .x_axis(&input.name, &x_unit)
            .y_axis(out, &y_unit);
        for &k in &picked {
            let ys: Vec<Option<f64>> = t
                .rows
                .iter()
                .map(|(_, r)| r.as_ref().ok().map(|v| v[k - first] * scale))
                .collect();
            plot = plot.gapped(&columns[k].0, &xs, &ys);
        }
        fig = fig.panel(plot);
    }
    Ok(fig)
}

/// Requests for `table::build` that a chart needs: the analyses its
/// outputs name.
pub fn needs(outputs: &[String]) -> (bool, bool, bool) {
    let has = |p: &str| outputs.iter().any(|o| o.starts_with(p));
    (
        has("velocity.") || has("acceleration.") || has("forces."),
        has("acceleration.") || has("forces."),
        has("forces."),
    )
}
