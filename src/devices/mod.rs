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

mod file;
mod world;

#[cfg(test)]
mod tests;

pub use file::{Device, DeviceFileError, DeviceKind, Devices, Event, KINDS, ObjectSpec, Role};
pub use world::{
    DeviceError, GRIP_TOLERANCE_MM, Happening, Interrupt, ObjectInfo, Place, TimedHappening, World,
};

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
