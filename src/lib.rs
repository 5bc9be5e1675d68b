//! adair: an interpreter, checker and simulator for AdaIR, Ada for industrial robots.
#![forbid(unsafe_code)]
#![deny(clippy::print_stdout, clippy::print_stderr)]

pub mod diag;
pub mod check;
pub mod syntax;
