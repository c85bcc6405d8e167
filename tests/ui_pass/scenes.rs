//! Every example definition (`examples/common/scenes.rs`, included as is):
//! each passes the expansion-time assembly checks, its generated code
//! compiles, and its run-time `check()` agrees that it assembles over its
//! declared (or default) input range.
#[allow(dead_code)]
#[path = "../../examples/common/scenes.rs"]
mod scenes;

use scenes::*;

fn main() {
    assert!(FourBar::<f64>::default().check().assembles());
    assert!(SixBar::<f64>::default().check().assembles());
    assert!(Shaper::<f64>::default().check().assembles());
    assert!(SliderCrank::<f64>::default().check().assembles());
    assert!(FiveBar::<f64>::default().check().assembles());
    assert!(SineMechanism::<f64>::default().check().assembles());
    assert!(ShaperForces::<f64>::default().check().assembles());
}
