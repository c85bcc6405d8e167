#![doc = include_str!("../README.md")]
//!
//! The modules: [`any`] (any generated mechanism, from its description),
//! [`Plot`] / [`Figure`] (line plots), [`Sketch`] / [`Frame`] (drawings),
//! with the feature `dxf` the module `dxf` (`Sketch::dxf`, `Sketch::write_dxf`),
//! and with the feature `runtime` the module `runtime` (drawings of a
//! mechanism read at run time).
#![forbid(unsafe_code)]
#![cfg_attr(docsrs, feature(doc_cfg))]

pub mod any;
#[cfg(feature = "dxf")]
#[cfg_attr(docsrs, doc(cfg(feature = "dxf")))]
pub mod dxf;
mod labels;
mod plot;
#[cfg(feature = "runtime")]
#[cfg_attr(docsrs, doc(cfg(feature = "runtime")))]
pub mod runtime;
mod sketch;
mod svg;
mod ticks;

pub use plot::{Figure, Plot};
pub use sketch::{Frame, Sketch};
pub use ticks::{nice_ticks, Ticks};

use std::fmt;

/// World coordinates of a point `[x, y]`, in the mechanism's length unit, y up.
pub type Xy = [f64; 2];

/// Everything that can go wrong when making a picture.
#[derive(Debug)]
pub enum PlotError {
    /// A plot (or every panel of a figure) has no series.
    NoSeries {
        /// The plot's title.
        plot: String,
    },
    /// A series has no points.
    EmptySeries {
        /// The series' name.
        series: String,
    },
    /// A series' x and y slices differ in length.
    LengthMismatch {
        /// The series' name.
        series: String,
        /// Length of the x values.
        xs: usize,
        /// Length of the y values.
        ys: usize,
    },
    /// A value is NaN or infinite.
    NonFinite {
        /// What holds the value: a series name, an axis, an element of a sketch.
        what: String,
        /// Index of the value in its series or frame.
        index: usize,
    },
    /// An axis range or step set by the caller is unusable (`lo >= hi`, step <= 0, ...).
    BadRange {
        /// Which axis.
        axis: &'static str,
        /// The offending lower bound (or step).
        lo: f64,
        /// The offending upper bound (or step).
        hi: f64,
    },
    /// A sketch has no frames, or the requested frame does not exist.
    NoFrame {
        /// The requested index.
        index: usize,
        /// The number of frames.
        frames: usize,
    },
    /// A sketch has no geometry at all (nothing to scale the drawing to).
    NothingToDraw,
    /// A chart asks for a field the result struct does not have.
    NoField {
        /// The name asked for.
        name: String,
        /// The struct's field names.
        known: Vec<&'static str>,
    },
    /// Writing the file failed.
    Io(std::io::Error),
}

impl fmt::Display for PlotError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PlotError::NoSeries { plot } => write!(f, "plot `{plot}` has no series"),
            PlotError::EmptySeries { series } => write!(f, "series `{series}` is empty"),
            PlotError::LengthMismatch { series, xs, ys } => {
                write!(f, "series `{series}` has {xs} x values but {ys} y values")
            }
            PlotError::NonFinite { what, index } => {
                write!(f, "{what}: value {index} is NaN or infinite")
            }
            PlotError::BadRange { axis, lo, hi } => {
                write!(f, "{axis} axis: unusable range or step ({lo}, {hi})")
            }
            PlotError::NoFrame { index, frames } => {
                write!(f, "sketch has {frames} frames, frame {index} requested")
            }
            PlotError::NothingToDraw => write!(f, "sketch has no geometry to draw"),
            PlotError::NoField { name, known } => {
                write!(f, "no field `{name}`; the fields are {}", known.join(", "))
            }
            PlotError::Io(e) => write!(f, "cannot write the SVG file: {e}"),
        }
    }
}

impl std::error::Error for PlotError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            PlotError::Io(e) => Some(e),
            _ => None,
        }
    }
}

impl From<std::io::Error> for PlotError {
    fn from(e: std::io::Error) -> Self {
        PlotError::Io(e)
    }
}

/// Writes `text` to `path`, creating the parent directories.
pub(crate) fn write_file(path: &std::path::Path, text: &str) -> Result<(), PlotError> {
    if let Some(dir) = path.parent() {
        if !dir.as_os_str().is_empty() {
            std::fs::create_dir_all(dir)?;
        }
    }
    std::fs::write(path, text)?;
    Ok(())
}
