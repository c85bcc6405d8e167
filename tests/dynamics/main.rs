//! Forward dynamics of generated definitions (`analysis dynamics`): `q''`
//! against the double-double global formulation, the inverse dynamics round trip, the energy balance of simulated runs, and
//! the `run_up` four-bar against an independent reference.
mod defs;
mod energy;
mod global_reference;
#[path = "../../examples/common/leg_drop.rs"]
mod leg_drop_scene;
mod round_trip;
mod run_up;
#[path = "../../examples/common/run_up.rs"]
mod run_up_scene;
