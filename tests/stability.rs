//! Stability suite (issue 6): every answer is either accurate to what the
//! conditioning allows, or a typed error; never NaN, never silently wrong.
//!
//! - [`assembly`]: the edge of assembly of each group, approached from inside
//!   at relative distances 1e-2 .. 1e-14, and just outside;
//! - [`toggle`]: the rate systems near their singular poses, against
//!   double-double references, and the `condition` indicator;
//! - [`scale`]: extreme scales, ratios, speeds and masses; scale invariance in
//!   `f32` and `f64`;
//! - [`stiff`]: stiff kinetostatics, scaled pivoting against naive
//!   elimination;
//! - [`inputs`]: NaN, infinities, zero and negative run-time parameters, and
//!   property tests over absurd parameters.
//!
//! References come from `mechanism_reference::groups` (double-double, written
//! from the equations). Every test prints its measured worst case
//! (`cargo test --test stability -- --nocapture`); `docs/stability.md`
//! collects the numbers and the constants.

#[path = "../examples/common/scenes.rs"]
mod scenes;

#[path = "stability/common.rs"]
mod common;

#[path = "stability/assembly.rs"]
mod assembly;
#[path = "stability/inputs.rs"]
mod inputs;
#[path = "stability/scale.rs"]
mod scale;
#[path = "stability/stiff.rs"]
mod stiff;
#[path = "stability/toggle.rs"]
mod toggle;
