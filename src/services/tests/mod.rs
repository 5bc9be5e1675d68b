//! Unit tests of the services that need no `Session` (the layer above:
//! tests/layering.rs): the path memory and the service core's pieces.
//! `cargo test --lib` runs them, with the kinematics' tests; the tests that
//! run whole programs are one integration test, tests/services/.

mod parts;
mod path_memory;
