#[macro_use]
#[path = "common/cli.rs"]
mod cli;
mod common;
use common::stephenson::{Stephenson, StephensonInput};
fn main() {
    let m = Stephenson::<f64>::default();
    let p = m.position(&StephensonInput { phi: (-49.48f64).to_radians() }).unwrap();
    outln!("{:?} {:?} {:?}", p.A, p.B, p.P);
}
