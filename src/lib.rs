//! adair: an interpreter, checker and simulator for AdaIR, Ada for industrial robots.
//!
//! Layers (arrows point one way): `syntax` below `check` below `interp`
//! below `services` below `session`; `diag` at the bottom; the table is in
//! ARCHITECTURE.md ("Layers") and `tests/layering.rs` enforces it. Only the
//! binary prints.
#![forbid(unsafe_code)]
// AST and IR nodes are built once per program; boxing their big variants
// would cost more in code than it saves in memory.
#![allow(clippy::large_enum_variant)]

pub mod check;
pub mod devices;
pub mod diag;
pub mod driver;
pub mod golden;
pub mod interp;
pub mod kinematics;
pub mod lsp;
pub mod plot;
pub mod repl;
pub mod services;
pub mod session;
pub mod simctl;
pub mod syntax;
pub mod view;
pub mod work;
