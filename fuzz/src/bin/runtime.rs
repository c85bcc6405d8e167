//! Placeholder: the runtime fuzzer is being written.
fn main() {}
