//! Placeholder: the expand fuzzer is being written.
fn main() {}
