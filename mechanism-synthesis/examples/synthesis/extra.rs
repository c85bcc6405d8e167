//! The measurements of the report section beside the benchmark table.

/// What [`measure`] found: its markdown, and its lines for the targets.
pub struct Extra {
    pub markdown: String,
    pub targets: String,
}

/// Runs the measurements.
pub fn measure() -> Extra {
    Extra {
        markdown: String::new(),
        targets: String::new(),
    }
}
