//! Stability suite: every answer is either accurate to what the
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
//!   property tests over absurd parameters;
//! - [`scale_definitions`], [`singular_definitions`]: definitions the scenes
//!   do not have (a four-bar with every dimension a parameter, a five-bar,
//!   RPR, PRP, RPP, actuator and RRP definitions) at lengths far from 1 and
//!   near their singular poses, against the double-double references (the
//!   harness in [`bounds`], [`reference_errors`] and [`param_defs`]);
//! - [`sixbar_f32`]: the f32 accuracy of the RRP near tangency and of the
//!   generated six-bar.
//!
//! References come from `mechanism_reference::groups` (double-double, written
//! from the equations). Every test prints its measured worst case
//! (`cargo test --test stability -- --nocapture`); `docs/stability.md`
//! collects the numbers and the constants.

#[path = "../../examples/report/reference.rs"]
#[allow(dead_code)]
mod reference;
#[path = "../../examples/common/scenes.rs"]
mod scenes;

mod bounds;
mod common;
mod param_defs;
mod reference_errors;

mod assembly;
mod inputs;
mod scale;
mod scale_definitions;
mod singular_definitions;
mod sixbar_f32;
mod stiff;
mod toggle;
