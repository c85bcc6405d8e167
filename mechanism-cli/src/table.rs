//! `mechanism table`: every output of a run-time mechanism over a sweep of
//! its inputs, as CSV (17 significant digits), JSON or an aligned table.

use crate::spec::Spec;
use mechanism_codegen::runtime::{Analysis, Mechanism};

/// Values of an input not given on the command line that has a range (a
/// crank's full turn, a declared `range`): every 5 degrees of a full turn.
const DEFAULT_COUNT: usize = 73;

/// What to tabulate.
pub struct Request {
    /// One spec per input (values to sweep).
    pub inputs: Vec<Spec>,
    /// `true`: the inputs' lists are paired (zipped), else a grid.
    pub paired: bool,
    /// Input rates (rad/s, L/s); unnamed inputs 0. `None`: no velocity.
    pub rates: Option<Vec<Spec>>,
    /// Input accelerations; unnamed inputs 0. `None`: no acceleration.
    pub accels: Option<Vec<Spec>>,
    /// `true`: the force analysis too (at the rates and accelerations
    /// given, 0 for the others).
    pub forces: bool,
}

/// One pose: its inputs, and its outputs or why it failed.
pub type Row = (Vec<f64>, Result<Vec<f64>, String>);

/// The table: its header (input columns, then outputs) and rows.
pub struct Table {
    /// `name [unit]` of every column.
    pub header: Vec<String>,
    /// The input names.
    pub input_names: Vec<String>,
    /// Per row: the inputs, and the outputs or the error.
    pub rows: Vec<Row>,
}

/// The value of each input for one spec list (`default` when not named).
fn values_by_input(m: &Mechanism, specs: &[Spec], default: f64) -> Result<Vec<f64>, String> {
    check_names(m, specs)?;
    Ok(m.inputs()
        .iter()
        .map(|i| {
            specs
                .iter()
                .find(|s| s.name == i.name)
                .and_then(|s| s.values.first().copied())
                .unwrap_or(default)
        })
        .collect())
}

/// Every spec names an input.
fn check_names(m: &Mechanism, specs: &[Spec]) -> Result<(), String> {
    let inputs = m.inputs();
    for s in specs {
        if !inputs.iter().any(|i| i.name == s.name) {
            let names: Vec<String> = inputs.iter().map(|i| format!("`{}`", i.name)).collect();
            return Err(format!(
                "no input `{}`; the inputs are: {}",
                s.name,
                names.join(", ")
            ));
        }
    }
    Ok(())
}

/// The input points of the sweep: a grid (the first input outermost) or
/// the paired lists.
pub fn points(m: &Mechanism, specs: &[Spec], paired: bool) -> Result<Vec<Vec<f64>>, String> {
    check_names(m, specs)?;
    let mut lists = Vec::new();
    for i in m.inputs() {
        let values = match (specs.iter().find(|s| s.name == i.name), i.range) {
            (Some(spec), _) => spec.values.clone(),
            (None, Some((lo, hi))) => crate::spec::linspace(lo, hi, DEFAULT_COUNT)?,
            (None, None) => {
                return Err(format!(
                    "no values for input `{}` (it has no range): add --input {}=LO:HI:N",
                    i.name, i.name
                ))
            }
        };
        lists.push(values);
    }
    if paired {
        let n = lists.first().map_or(0, Vec::len);
        if lists.iter().any(|l| l.len() != n) {
            return Err("--paired needs the same number of values for every input".into());
        }
        return Ok((0..n)
            .map(|k| lists.iter().map(|l| l[k]).collect())
            .collect());
    }
    let mut out: Vec<Vec<f64>> = vec![Vec::new()];
    for list in &lists {
        out = out
            .iter()
            .flat_map(|prefix| {
                list.iter().map(move |&x| {
                    let mut p = prefix.clone();
                    p.push(x);
                    p
                })
            })
            .collect();
    }
    Ok(out)
}

/// The analyses a request asks for.
fn analyses(req: &Request) -> Vec<Analysis> {
    let mut a = vec![Analysis::Position];
    if req.rates.is_some() || req.accels.is_some() {
        a.push(Analysis::Velocity);
    }
    if req.accels.is_some() {
        a.push(Analysis::Acceleration);
    }
    a
}

/// The header: inputs, then each analysis' columns (`velocity.` and
/// `acceleration.` before the names of those analyses, as the fields of the
/// generated `Solution`).
fn header(m: &Mechanism, req: &Request) -> Vec<String> {
    let mut h: Vec<String> = m
        .inputs()
        .iter()
        .map(|i| format!("{} [{}]", i.name, if i.angle { "rad" } else { "L" }))
        .collect();
    for a in analyses(req) {
        let prefix = match a {
            Analysis::Position => "",
            Analysis::Velocity => "velocity.",
            Analysis::Acceleration => "acceleration.",
        };
        for c in m.columns(a) {
            h.push(format!("{prefix}{} [{}]", c.name, c.unit));
        }
    }
    if req.forces {
        for c in m.force_columns() {
            h.push(format!("forces.{} [{}]", c.name, c.unit));
        }
    }
    h
}

/// Evaluates one row.
fn row(
    m: &Mechanism,
    q: &[f64],
    rates: &[f64],
    accels: &[f64],
    req: &Request,
) -> Result<Vec<f64>, String> {
    let pos = m.position(q).map_err(|e| e.to_string())?;
    let mut values = pos.values.clone();
    let want = analyses(req);
    if want.contains(&Analysis::Velocity) || req.forces {
        let vel = m.velocity(&pos, rates).map_err(|e| e.to_string())?;
        if want.contains(&Analysis::Velocity) {
            values.extend(&vel.values);
        }
        if want.contains(&Analysis::Acceleration) || req.forces {
            let acc = m
                .acceleration(&pos, &vel, accels)
                .map_err(|e| e.to_string())?;
            if want.contains(&Analysis::Acceleration) {
                values.extend(&acc.values);
            }
            if req.forces {
                let f = m.forces(&pos, &vel, &acc).map_err(|e| e.to_string())?;
                values.extend(&f.values);
            }
        }
    }
    Ok(values)
}

/// Evaluates the whole sweep; `progress` is ticked once per row.
pub fn build(m: &Mechanism, req: &Request, progress: &dyn Fn()) -> Result<Table, String> {
    let pts = points(m, &req.inputs, req.paired)?;
    let rates = values_by_input(m, req.rates.as_deref().unwrap_or(&[]), 0.0)?;
    let accels = values_by_input(m, req.accels.as_deref().unwrap_or(&[]), 0.0)?;
    let mut rows = Vec::with_capacity(pts.len());
    for q in pts {
        let r = row(m, &q, &rates, &accels, req);
        rows.push((q, r));
        progress();
    }
    Ok(Table {
        header: header(m, req),
        input_names: m.inputs().into_iter().map(|i| i.name).collect(),
        rows,
    })
}

/// One number with 17 significant digits (round-trip exact).
fn num(x: f64) -> String {
    format!("{x:.16e}")
}

impl Table {
    /// CSV: the header, then one row per pose; a pose that fails is a
    /// comment line `# NAME=VALUE ...: ERROR` followed by its row with the
    /// inputs and empty outputs.
    pub fn csv(&self) -> String {
        let mut s = self.header.join(",");
        s.push('\n');
        let width = self.header.len();
        for (q, r) in &self.rows {
            let mut cells: Vec<String> = q.iter().map(|&x| num(x)).collect();
            match r {
                Ok(v) => cells.extend(v.iter().map(|&x| num(x))),
                Err(e) => {
                    s.push_str(&format!("# {}: {e}\n", self.at(q)));
                    cells.resize(width, String::new());
                }
            }
            s.push_str(&cells.join(","));
            s.push('\n');
        }
        s
    }

    /// `theta=1.2 s=3`: where a row is, for messages.
    fn at(&self, q: &[f64]) -> String {
        let parts: Vec<String> = self
            .input_names
            .iter()
            .zip(q)
            .map(|(n, x)| format!("{n}={}", num(*x)))
            .collect();
        parts.join(" ")
    }

    /// JSON: `{"columns": [{"name", "unit"}], "rows": [{"inputs": [..],
    /// "outputs": [..] | null, "error": null | ".."}]}`.
    pub fn json(&self) -> String {
        let columns: Vec<serde_json::Value> = self
            .header
            .iter()
            .map(|h| {
                let (name, unit) = h.rsplit_once(" [").unwrap_or((h, "]"));
                serde_json::json!({ "name": name, "unit": unit.trim_end_matches(']') })
            })
            .collect();
        let rows: Vec<serde_json::Value> = self
            .rows
            .iter()
            .map(|(q, r)| match r {
                Ok(v) => serde_json::json!({ "inputs": q, "outputs": v, "error": null }),
                Err(e) => serde_json::json!({ "inputs": q, "outputs": null, "error": e }),
            })
            .collect();
        let doc = serde_json::json!({ "columns": columns, "rows": rows });
        serde_json::to_string_pretty(&doc).unwrap_or_default()
    }

    /// An aligned table for reading (6 significant digits).
    pub fn text(&self) -> String {
        let w = self
            .header
            .iter()
            .map(String::len)
            .max()
            .unwrap_or(8)
            .clamp(12, 24);
        let mut s: String = self.header.iter().map(|h| format!("{h:>w$} ")).collect();
        s.push('\n');
        for (q, r) in &self.rows {
            let mut line: String = q.iter().map(|x| format!("{x:>w$.6} ")).collect();
            match r {
                Ok(v) => line.extend(v.iter().map(|x| format!("{x:>w$.6} "))),
                Err(e) => line.push_str(&format!("  # {e}")),
            }
            s.push_str(line.trim_end());
            s.push('\n');
        }
        s
    }
}
