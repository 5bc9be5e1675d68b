//! The RM-501's drive unit (Movemaster II): joint space only, it never
//! answers, and its whole command set is `MI`, `PS`, `MO`, `NT`, `HO`,
//! `OG`, `SP`, `GO`, `GC`, `RS` (robots.md). Anything else, or a target
//! beyond a limit, puts it in error mode, in which it ignores every line
//! but `RS` without a sign.
//!
//! What robots.md leaves open, decided here: the unit counts joint
//! positions from an origin (home). At power-on and after `NT` the origin
//! is the nest pose; `HO` makes the current pose the origin (nothing
//! moves); `OG` moves to the origin; `PS n` (n = 1..629) stores the current
//! pose as position n, in counts from the origin; `MO n` moves to position
//! n (an undefined one is an error). `MI`'s sixth field is the hand axis of
//! units with one and must be 0. `SP n` takes n = 0..9 only (no `,H|L`).

use super::arm::{Arm, Counts, RM_501_COUNTS};
use super::line::{self, Line};
use super::rv_m1::HAND_TIME;
use super::{Error, Outcome};
use crate::kinematics::{JOINTS, RobotDescription};
use std::collections::HashMap;

/// Largest magnitude of an `MI` count (a 16-bit field).
pub const MI_MAX: i64 = 32767;

/// The Movemaster II drive unit.
#[derive(Clone, Debug)]
pub struct Movemaster2 {
    /// The arm it drives.
    pub arm: Arm,
    /// Whether the unit is in its error mode.
    pub error: Error,
    /// The origin (home), counts.
    pub origin: Counts,
    /// Positions, in counts from the origin.
    positions: HashMap<i64, Counts>,
    /// Whether the hand is open.
    pub hand_open: bool,
}

impl Movemaster2 {
    /// The unit at power-on: the arm at the nest, which is the origin.
    pub fn new(desc: RobotDescription) -> Movemaster2 {
        let arm = Arm::new(desc, RM_501_COUNTS);
        let origin = arm.nest();
        Movemaster2 {
            arm,
            error: Error::None,
            origin,
            positions: HashMap::new(),
            hand_open: true,
        }
    }

    fn fail(&mut self) -> Outcome {
        // One error mode: which kind it was cannot be asked.
        self.error = Error::Command;
        Outcome::default()
    }

    fn go(&mut self, target: Counts) -> Outcome {
        match self.arm.move_to(target) {
            Ok(t) => Outcome::busy(t),
            Err(_) => {
                self.error = Error::Position;
                Outcome::default()
            }
        }
    }

    /// Handles one line; the outcome never has a reply.
    pub fn handle(&mut self, text: &str) -> Outcome {
        let Some(Line { code, args }) = line::split(text) else {
            return self.fail();
        };
        if code == "RS" && args.is_empty() {
            self.error = Error::None;
            return Outcome::default();
        }
        if self.error != Error::None {
            return Outcome::default();
        }
        match (code, args.len()) {
            ("MI", 6) => {
                let mut delta = [0; JOINTS];
                for (d, a) in delta.iter_mut().zip(&args) {
                    match line::integer(a, -MI_MAX, MI_MAX) {
                        Some(v) => *d = v,
                        None => return self.fail(),
                    }
                }
                if line::integer(args[5], 0, 0).is_none() {
                    return self.fail();
                }
                let mut target = self.arm.counts;
                for (t, d) in target.iter_mut().zip(delta) {
                    *t += d;
                }
                self.go(target)
            }
            ("NT", 0) => {
                let nest = self.arm.nest();
                let o = self.go(nest);
                self.origin = nest;
                o
            }
            ("HO", 0) => {
                self.origin = self.arm.counts;
                Outcome::default()
            }
            ("OG", 0) => self.go(self.origin),
            ("PS", 1) => match line::integer(args[0], 1, 629) {
                Some(n) => {
                    let mut rel = self.arm.counts;
                    for (r, o) in rel.iter_mut().zip(self.origin) {
                        *r -= o;
                    }
                    self.positions.insert(n, rel);
                    Outcome::default()
                }
                None => self.fail(),
            },
            ("MO", 1) => {
                let Some(n) = line::integer(args[0], 1, 629) else {
                    return self.fail();
                };
                let Some(rel) = self.positions.get(&n).copied() else {
                    return self.fail();
                };
                let mut target = self.origin;
                for (t, r) in target.iter_mut().zip(rel) {
                    *t += r;
                }
                self.go(target)
            }
            ("SP", 1) => match line::integer(args[0], 0, 9) {
                Some(l) => {
                    self.arm.speed = l as u8;
                    Outcome::default()
                }
                None => self.fail(),
            },
            ("GO", 0) => {
                self.hand_open = true;
                Outcome::busy(HAND_TIME)
            }
            ("GC", 0) => {
                self.hand_open = false;
                Outcome::busy(HAND_TIME)
            }
            _ => self.fail(),
        }
    }
}
