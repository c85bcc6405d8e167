//! What the command line says about the inputs: `NAME=VALUE[unit]` for one
//! value, `NAME=LO:HI[unit]:N` for `N` values from `LO` to `HI` inclusive,
//! `NAME=A,B,C[unit]` for a list. Units: `deg` (converted to rad) or `rad`
//! for angles; none for lengths (the definition's unit).

/// The values one `--input` (or `--rate`, `--accel`, `--at`) gives one input.
#[derive(Clone, Debug, PartialEq)]
pub struct Spec {
    /// The input's name.
    pub name: String,
    /// Its values (rad for angles, L for lengths; per second for rates).
    pub values: Vec<f64>,
}

/// One number with an optional `deg`/`rad` suffix, in rad (or as written).
pub fn number(text: &str) -> Result<f64, String> {
    let t = text.trim();
    let (t, scale) = if let Some(n) = t.strip_suffix("deg") {
        (n, std::f64::consts::PI / 180.0)
    } else if let Some(n) = t.strip_suffix("rad") {
        (n, 1.0)
    } else {
        (t, 1.0)
    };
    let x: f64 = t
        .trim()
        .parse()
        .map_err(|_| format!("`{text}` is not a number (e.g. `30`, `30deg`, `0.5rad`)"))?;
    if !x.is_finite() {
        return Err(format!("`{text}` is not finite"));
    }
    Ok(x * scale)
}

/// The unit suffix of a range or list, applied to every number of it
/// (`0:360deg:73` means 0 deg to 360 deg).
fn suffix(text: &str) -> &'static str {
    if text.contains("deg") {
        "deg"
    } else {
        ""
    }
}

impl Spec {
    /// Reads `NAME=...`.
    pub fn parse(text: &str) -> Result<Spec, String> {
        let (name, rest) = text
            .split_once('=')
            .ok_or_else(|| format!("`{text}`: expected NAME=VALUE, NAME=LO:HI:N or NAME=A,B,C"))?;
        let name = name.trim().to_string();
        let unit = suffix(rest);
        let with_unit = |t: &str| {
            let t = t.trim();
            if unit.is_empty() || t.ends_with("deg") || t.ends_with("rad") {
                number(t)
            } else {
                number(&format!("{t}{unit}"))
            }
        };
        let parts: Vec<&str> = rest.split(':').collect();
        let values = match parts.as_slice() {
            [one] if one.contains(',') => one
                .split(',')
                .map(with_unit)
                .collect::<Result<Vec<_>, _>>()?,
            [one] => vec![with_unit(one)?],
            [lo, hi, n] => {
                let (lo, hi) = (with_unit(lo)?, with_unit(hi)?);
                let n: usize = n
                    .trim()
                    .parse()
                    .map_err(|_| format!("`{n}`: the number of values must be a whole number"))?;
                linspace(lo, hi, n)?
            }
            _ => return Err(format!("`{text}`: expected NAME=LO:HI:N")),
        };
        Ok(Spec { name, values })
    }
}

/// `n` values from `lo` to `hi` inclusive, evenly spaced (`lo + (hi - lo) k
/// / (n - 1)`: both ends exact).
pub fn linspace(lo: f64, hi: f64, n: usize) -> Result<Vec<f64>, String> {
    match n {
        0 => Err("the number of values must be at least 1".into()),
        1 => Ok(vec![lo]),
        _ => Ok((0..n)
            .map(|k| {
                if k == n - 1 {
                    hi
                } else {
                    lo + (hi - lo) * k as f64 / (n - 1) as f64
                }
            })
            .collect()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_range_in_degrees_gives_radians_with_exact_ends() {
        // Proves `0:360deg:73` is 73 values, 0 and 2 pi at the ends, 5 deg apart.
        let s = Spec::parse("theta=0:360deg:73").unwrap();
        assert_eq!(s.name, "theta");
        assert_eq!(s.values.len(), 73);
        assert_eq!(s.values[0], 0.0);
        assert_eq!(s.values[72], 360.0 * std::f64::consts::PI / 180.0);
        assert!((s.values[1] - 5f64.to_radians()).abs() < 1e-15);
    }

    #[test]
    fn single_values_and_lists_read_their_units() {
        // Proves one value, a list with a shared suffix, and a length.
        assert_eq!(
            Spec::parse("t=30deg").unwrap().values,
            vec![30f64.to_radians()]
        );
        assert_eq!(
            Spec::parse("t=0,90deg").unwrap().values,
            vec![0.0, 90f64.to_radians()]
        );
        assert_eq!(Spec::parse("s=1.5").unwrap().values, vec![1.5]);
        assert!(Spec::parse("s=abc").is_err());
        assert!(Spec::parse("s=1:2:0").is_err());
        assert!(Spec::parse("nothing").is_err());
    }
}
