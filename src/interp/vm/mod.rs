//! The compiled engine. Each subprogram body (and the level-0 statements of
//! a run) is compiled, once per run and on first call, into a flat list of
//! instructions over the slots of its frame: the frame's own variables
//! (`Var { level, slot }`, as the checker numbered them) followed by
//! temporaries. A loop runs the instructions with explicit frames: a call
//! pushes a [`Frame`] and jumps, a return pops it, an exception unwinds
//! through handler regions and frames, with no Rust recursion, so that a
//! task can be suspended between two instructions.
//!
//! Every construct has instructions of its own; code that runs inside an
//! instruction (a barrier, a default or a dynamic bound of the type table,
//! a REPL expression) runs in a nested run of the same loop (`nested.rs`).
//! It is the only engine: nothing runs the checked tree. Its meaning is
//! checked against GNAT-recorded programs (`tests/ada/`), the goldens and
//! generated programs whose output the generator knows (`tests/run_props.rs`).
//!
//! The parts:
//! - `ops.rs`: the instruction set ([`Op`]) and its metadata (jump targets);
//! - `compile/`: the compiler, by concern (`expr.rs`, `stmt.rs`,
//!   `calls.rs`, `rendezvous.rs`; `mod.rs` holds the [`Compiler`] itself);
//! - `code.rs`: a compiled body ([`Code`], its handler regions) and the
//!   parts of a long body compiled as they are checked;
//! - `frames.rs`: call frames and the saved registers of a waiting thread;
//! - `nested.rs`: runs nested in an instruction (barriers, the type
//!   table's expressions);
//! - `run.rs`: compiling on first call and starting a run;
//! - `exec.rs`: the execution loop and its slot helpers;
//! - `fast.rs`: its inner loop, for runs of instructions over the running
//!   frame's scalars and arrays of scalars;
//! - `blocking.rs`: the instructions that block or switch threads;
//! - `tests.rs`: unit tests of the compiler (whole runs are in tests/engine.rs).

use super::*;
use crate::check::types::Variant;

mod blocking;
mod code;
mod compile;
mod exec;
mod fast;
mod frames;
mod nested;
mod ops;
mod run;
#[cfg(test)]
mod tests;

use blocking::*;
use code::*;
pub(crate) use code::{Code, Part, compile_part};
pub(crate) use compile::effects_unless;
use compile::*;
use frames::*;
pub(crate) use frames::{Codes, Frame, Regs};
use ops::*;

/// The label by which the end of a body is signalled inside the engine.
const FALL_OFF: u32 = u32::MAX - 1;
