//! The `units` statement: the names of the definition's units, for the
//! labels of what it generates (`Display`, `structure::Units`). Labels only:
//! the numbers are in whatever consistent units the definition is written
//! in, and nothing is converted.

use crate::diag::{did_you_mean, Diagnostics};
use crate::parse::{Assign, Item};
use syn::spanned::Spanned;
use syn::{Expr, Lit};

/// The quantities a `units` statement names, in the order the messages list
/// them.
const NAMES: [&str; 4] = ["length", "force", "mass", "time"];

/// The names of a definition's units.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnitNames {
    /// Lengths (`"mm"`), `L` when not named.
    pub length: String,
    /// Forces (`"N"`), `F` when not named.
    pub force: String,
    /// Masses (`"kg"`), `M` when not named.
    pub mass: String,
    /// Time, the denominator of rates (`"s"`), `s` when not named.
    pub time: String,
}

impl UnitNames {
    /// The units of a definition without a `units` statement: the symbols
    /// `L`, `F`, `M` and `s` (`mechanism::structure::Units::SYMBOLS`).
    pub fn symbols() -> Self {
        UnitNames {
            length: "L".into(),
            force: "F".into(),
            mass: "M".into(),
            time: "s".into(),
        }
    }

    /// The unit of a length (`"mm"`).
    pub fn length(&self) -> &str {
        &self.length
    }

    /// The unit of a rate of `of` (`"mm/s"` for a length, `"rad/s"` for an
    /// angle).
    pub fn per_time(&self, of: &str) -> String {
        format!("{of}/{}", self.time)
    }

    /// The unit of a second derivative of `of` (`"mm/s^2"`).
    pub fn per_time_squared(&self, of: &str) -> String {
        format!("{of}/{}^2", self.time)
    }

    /// The unit of a moment (`"N mm"`).
    pub fn moment(&self) -> String {
        format!("{} {}", self.force, self.length)
    }
}

/// Reads the `units` statements of `items` (one at most; each quantity
/// once, named by a non-empty string); errors on the offending token.
pub fn read(items: &[Item], errors: &mut Diagnostics) -> UnitNames {
    let mut units = UnitNames::symbols();
    let mut first: Option<proc_macro2::Span> = None;
    for item in items {
        let Item::Units(span, list) = item else {
            continue;
        };
        if first.is_some() {
            errors.push(
                *span,
                "`units` may appear once in a definition, and this is the second; name every unit in the first and remove this one",
            );
            continue;
        }
        first = Some(*span);
        let mut named: Vec<String> = Vec::new();
        for a in list {
            if let Some((key, value)) = entry(a, &named, errors) {
                let slot = match key.as_str() {
                    "length" => &mut units.length,
                    "force" => &mut units.force,
                    "mass" => &mut units.mass,
                    _ => &mut units.time,
                };
                *slot = value;
                named.push(key);
            }
        }
    }
    units
}

/// One `NAME = "unit"` of the statement: the quantity and its unit, or an
/// error (unknown quantity, named twice, not a string, an empty string).
fn entry(a: &Assign, named: &[String], errors: &mut Diagnostics) -> Option<(String, String)> {
    let key = a.name.to_string();
    if !NAMES.contains(&key.as_str()) {
        errors.push(
            a.name.span(),
            format!(
                "unknown quantity `{key}` in `units`; it names `length`, `force`, `mass` and `time`{}",
                did_you_mean(&key, NAMES)
            ),
        );
        return None;
    }
    if named.contains(&key) {
        errors.push(
            a.name.span(),
            format!("`{key}` is named twice in `units`; keep one"),
        );
        return None;
    }
    match &a.value {
        Expr::Lit(lit) => match &lit.lit {
            Lit::Str(s) if !s.value().trim().is_empty() => Some((key, s.value())),
            Lit::Str(s) => {
                errors.push(
                    s.span(),
                    format!("the unit of `{key}` is empty; name it, `{key} = \"mm\"`, or leave `{key}` out"),
                );
                None
            }
            other => {
                errors.push(other.span(), not_a_string(&key));
                None
            }
        },
        other => {
            errors.push(other.span(), not_a_string(&key));
            None
        }
    }
}

fn not_a_string(key: &str) -> String {
    let example = match key {
        "length" => "mm",
        "force" => "N",
        "mass" => "kg",
        _ => "s",
    };
    format!("a unit is named by a string: `{key} = \"{example}\"`")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse::Definition;

    fn read_src(src: &str) -> (UnitNames, Vec<String>) {
        let def: Definition = syn::parse_str(src).expect("parses");
        let mut errors = Diagnostics::new();
        let units = read(&def.items, &mut errors);
        let messages = errors.finish().iter().map(|e| e.to_string()).collect();
        (units, messages)
    }

    const BODY: &str = "let O = ground(0.0, 0.0); let A = crank(O, 1.0, t) as link2;";

    /// What the statement names replaces the symbols; what it leaves out
    /// keeps them.
    #[test]
    fn named_units_replace_the_symbols() {
        let (u, e) = read_src(&format!(
            r#"M {{ units {{ length = "mm", force = "N" }} {BODY} }}"#
        ));
        assert!(e.is_empty(), "{e:?}");
        assert_eq!((u.length(), u.force.as_str()), ("mm", "N"));
        assert_eq!((u.mass.as_str(), u.time.as_str()), ("M", "s"));
        assert_eq!(u.per_time_squared("mm"), "mm/s^2");
        assert_eq!(u.moment(), "N mm");
        let (u, e) = read_src(&format!("M {{ {BODY} }}"));
        assert!(e.is_empty());
        assert_eq!(u, UnitNames::symbols());
    }

    /// Each mistake is one error naming the fix.
    #[test]
    fn mistakes_are_errors() {
        for (units, wanted) in [
            (r#"lenght = "mm""#, "did you mean `length`?"),
            (r#"length = "mm", length = "m""#, "named twice"),
            (
                "length = mm",
                "a unit is named by a string: `length = \"mm\"`",
            ),
            ("force = 1.0", "`force = \"N\"`"),
            (r#"time = """#, "the unit of `time` is empty"),
        ] {
            let (_, e) = read_src(&format!("M {{ units {{ {units} }} {BODY} }}"));
            assert_eq!(e.len(), 1, "{units}: {e:?}");
            assert!(e[0].contains(wanted), "{units}: {e:?}");
        }
        let (_, e) = read_src(&format!(
            r#"M {{ units {{ length = "mm" }} units {{ force = "N" }} {BODY} }}"#
        ));
        assert_eq!(e.len(), 1);
        assert!(e[0].contains("may appear once"), "{e:?}");
    }
}
