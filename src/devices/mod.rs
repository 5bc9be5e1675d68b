//! Simulated peripherals (tasks.md "Devices", handbook appendix C): the
//! parallel port, light barriers and conveyors with objects, described by a
//! device file and run on a virtual clock that the caller owns.
//!
//! Two halves:
//! - [`Devices`] is the description: which device sits at which address and
//!   the scripted events (`[[device]]` and `[[event]]` of the TOML device
//!   file, or [`Devices::default_set`]). It never changes; the checker asks
//!   it what an address is ([`Devices::lookup`]).
//! - [`World`] is one run of it: registers, belts, objects, interrupt
//!   counts, at the time [`World::now`]. The scheduler drives it: when every
//!   task is blocked it takes the earliest of its own wake-ups and
//!   [`World::next_wakeup`], calls [`World::advance_to`] and queues the
//!   [`Interrupt`]s it returns on their entries. Register reads and writes
//!   happen at `now`, so the scheduler advances the world to its clock
//!   before it lets a task touch a register.
//!
//! Nothing here reads a clock, prints or knows the robot: times are seconds
//! given by the caller, positions are plain millimetres.
//!
//! Where tasks.md is silent, this module decides:
//! - A device file replaces the default set (the spec's cell file has no
//!   parallel port). An empty file is allowed: no devices.
//! - Every register starts at 0, so the parallel port's interrupts are
//!   disabled until the program sets bit 0 of its control register. Only
//!   bit 0 of control (enable) and of motor (run) mean anything; every bit
//!   is kept and read back.
//! - Writing an input register (or an interrupt address) is refused with a
//!   [`DeviceError`] and changes nothing; the engine chooses what the
//!   program sees.
//! - Events at one instant apply in file order; within an event: input,
//!   then object, then interrupt. An object reaching a belt's end comes
//!   before the scripted events of the same instant.
//! - Objects on a belt never overlap: each one stops behind the one ahead,
//!   centre to centre at the sum of their half widths, and one put on a
//!   belt whose start is taken waits behind the last one (at a negative
//!   position). Only the front object can reach the end and break the beam;
//!   picking it lets the next one move up and interrupt again.
//! - The gripper reaches objects at rest: at a belt's end or where they
//!   were put down (a belt has no coordinates but its end). An object put
//!   down is off every belt, even at a belt's end. Object names are unique
//!   in the file.
//! - A light barrier without `on` is set by `input = 0|1` events and
//!   `:set`; one with `on` follows its belt and refuses both. Its interrupt
//!   is optional (a barrier may only be polled). An event's `interrupt =
//!   true` raises any device's interrupt, whatever its beam.
//! - Interrupts carry no data; the counts of delivered and dropped ones are
//!   kept per address. The trace log is off until `set_logging(true)`, so a
//!   long run without `--trace` keeps nothing.
//! - Addresses are `u32`; written in the file as TOML integers (`0o340`,
//!   `0xE0`, `224`); Ada's `"8#340#"` as a string is refused with a hint.

mod file;
mod report;
mod timeline;
mod world;

#[cfg(test)]
mod tests;

pub use file::{Device, DeviceFileError, DeviceKind, Devices, Event, KINDS, ObjectSpec, Role};
pub use report::{DeviceError, Happening, TimedHappening};
pub use timeline::{Course, Moment, ObjectCourse, Sink};
pub use world::{GRIP_TOLERANCE_MM, Interrupt, ObjectInfo, Place, World};

/// A device address (`for X use at 8#342#;`), as written in the device file
/// (`0o342`).
pub type Address = u32;

/// An address as Ada writes it, `8#340#`: the handbook and the programs
/// give addresses in octal, so `:devices` and `--trace` do too.
pub fn ada_address(a: Address) -> String {
    format!("8#{a:o}#")
}

/// A register value as Ada writes it, `16#00FF#`.
pub fn ada_word(v: u16) -> String {
    format!("16#{v:04X}#")
}
