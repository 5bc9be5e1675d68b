//! A count of the work the front end does: one tick per token the parser
//! reads and per expression, name and statement the checker visits. Tests
//! and benchmarks compare counts at 1x, 2x and 4x input to show that the
//! parser and the checker stay linear on any text (issue 35); a count, not
//! a clock, so the comparison is exact on a loaded machine.
//!
//! The counter is per thread and costs one add per tick.

use std::cell::Cell;

thread_local! {
    static TICKS: Cell<u64> = const { Cell::new(0) };
    static TEXTS: Cell<u64> = const { Cell::new(0) };
}

/// Counts a text lexed and parsed (a file, a stdlib file, a REPL entry; a
/// long text, whose lazy parse may fall back to a whole one, may count twice).
pub fn text_parsed() {
    TEXTS.with(|t| t.set(t.get().wrapping_add(1)));
}

/// The texts parsed on this thread since it started: the predefined
/// library's are read in a parsed form, never parsed (`tests/startup.rs`).
pub fn texts_parsed() -> u64 {
    TEXTS.with(Cell::get)
}

/// Counts one step of work.
#[inline]
pub fn tick() {
    TICKS.with(|t| t.set(t.get().wrapping_add(1)));
}

/// The steps counted on this thread since it started.
pub fn count() -> u64 {
    TICKS.with(Cell::get)
}
