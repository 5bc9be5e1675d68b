//! The RV-M1's drive unit D/U-M1: the command list of robots.md with its
//! argument counts and ranges, error modes I and II, the replies.

use super::arm::{Arm, OutOfRange, RV_M1_COUNTS};
use super::line::{self, Line};
use super::{Error, Outcome};
use crate::kinematics::{JOINTS, RobotDescription};
use std::collections::HashMap;

/// Position numbers of `PD`, `HE`, `MO`, `MS`, `MC`.
const POSITIONS: std::ops::RangeInclusive<i64> = 1..=629;
/// What the input port reads (the unit's inputs are not wired here).
pub const INPUT_PORT: u32 = 0x5A;
/// Seconds the hand takes to open or close.
pub const HAND_TIME: f64 = 0.3;

/// The D/U-M1.
#[derive(Clone, Debug)]
pub struct DuM1 {
    /// The arm it drives.
    pub arm: Arm,
    /// The current error mode.
    pub error: Error,
    /// `TL`: flange to TCP along the tool axis, mm.
    pub tool: f64,
    /// Positions 1..629 as `WH`-style poses.
    positions: HashMap<i64, [f64; 5]>,
    /// Whether the hand is open.
    pub hand_open: bool,
    register: u32,
    output: u16,
}

impl DuM1 {
    /// The unit at power-on: the arm at the nest, speed 4, the robot file's
    /// tool length, no positions, the hand open, the register holding the
    /// input port, the output port 0.
    pub fn new(desc: RobotDescription) -> DuM1 {
        let tool = desc.links().tool;
        DuM1 {
            arm: Arm::new(desc, RV_M1_COUNTS),
            error: Error::None,
            tool,
            positions: HashMap::new(),
            hand_open: true,
            register: INPUT_PORT,
            output: 0,
        }
    }

    /// The `WH` reply of where the arm stands.
    pub fn where_reply(&self) -> String {
        let p = self.arm.pose(self.tool);
        let parts: Vec<String> = p.iter().map(|v| line::signed_tenth(*v)).collect();
        parts.join(",")
    }

    fn fail(&mut self, mode: Error) -> Outcome {
        self.error = mode;
        Outcome::default()
    }

    fn moved(&mut self, r: Result<f64, OutOfRange>) -> Outcome {
        match r {
            Ok(t) => Outcome::busy(t),
            Err(OutOfRange) => self.fail(Error::Position),
        }
    }

    fn go_pose(&mut self, pose: &[f64; 5]) -> Outcome {
        match self.arm.solve(pose, self.tool, &self.arm.counts) {
            Some(c) => {
                let r = self.arm.move_to(c);
                self.moved(r)
            }
            None => self.fail(Error::Position),
        }
    }

    /// A straight line from where the arm stands to `to` through `points`
    /// intermediate points, each solved; any of them unreachable: error
    /// mode II and nothing moves. The time is the sum of the joint moves
    /// between the points.
    fn line_to(&mut self, to: &[f64; 5], points: usize) -> Outcome {
        let from = self.arm.pose(self.tool);
        let mut at = self.arm.counts;
        let mut busy = 0.0;
        for i in 1..=points + 1 {
            let s = i as f64 / (points + 1) as f64;
            let mut p = [0.0; 5];
            for k in 0..5 {
                p[k] = from[k] + (to[k] - from[k]) * s;
            }
            let Some(c) = self.arm.solve(&p, self.tool, &at) else {
                return self.fail(Error::Position);
            };
            busy += self.arm.travel_time(&at, &c);
            at = c;
        }
        self.arm.counts = at;
        Outcome::busy(busy)
    }

    /// The position number argument, if it is one.
    fn position_no(arg: &str) -> Option<i64> {
        line::integer(arg, *POSITIONS.start(), *POSITIONS.end())
    }

    /// The optional hand argument of `MO`/`MS` (`O` open, `C` closed).
    fn hand_arg(arg: Option<&&str>) -> Option<Option<bool>> {
        match arg.copied() {
            None => Some(None),
            Some("O") => Some(Some(true)),
            Some("C") => Some(Some(false)),
            Some(_) => None,
        }
    }

    /// Handles one line.
    pub fn handle(&mut self, text: &str) -> Outcome {
        let Some(Line { code, args }) = line::split(text) else {
            return self.command_error();
        };
        let none = args.is_empty();
        // Status and reset are taken in every mode; in an error mode all
        // other lines are ignored until `RS`.
        match code {
            "ER" if none => return Outcome::reply(self.error.digit().to_string()),
            "RS" if none => {
                self.error = Error::None;
                return Outcome::default();
            }
            _ => {}
        }
        if self.error != Error::None {
            return Outcome::default();
        }
        match (code, args.len()) {
            ("NT" | "OG", 0) => {
                // The origin is the pose `NT` leaves the arm in.
                let nest = self.arm.nest();
                let r = self.arm.move_to(nest);
                self.moved(r)
            }
            ("MJ", 5) => {
                let Some(deg) = line::decimals::<JOINTS>(&args) else {
                    return self.command_error();
                };
                let delta = self.arm.counts_of_deg(&deg);
                let r = self.arm.move_by(&delta);
                self.moved(r)
            }
            ("MP", 5) => match line::decimals::<5>(&args) {
                Some(p) => self.go_pose(&p),
                None => self.command_error(),
            },
            ("PD", 6) => {
                let (Some(n), Some(p)) = (Self::position_no(args[0]), line::decimals(&args[1..]))
                else {
                    return self.command_error();
                };
                self.positions.insert(n, p);
                Outcome::default()
            }
            ("HE", 1) => {
                let Some(n) = Self::position_no(args[0]) else {
                    return self.command_error();
                };
                self.positions.insert(n, self.arm.pose(self.tool));
                Outcome::default()
            }
            ("MO", 1 | 2) => {
                let (Some(n), Some(hand)) =
                    (Self::position_no(args[0]), Self::hand_arg(args.get(1)))
                else {
                    return self.command_error();
                };
                let Some(p) = self.positions.get(&n).copied() else {
                    return self.fail(Error::Position);
                };
                let mut o = self.go_pose(&p);
                self.set_hand(hand, &mut o);
                o
            }
            ("MS", 2 | 3) => {
                let (Some(n), Some(k), Some(hand)) = (
                    Self::position_no(args[0]),
                    line::integer(args[1], 1, 99),
                    Self::hand_arg(args.get(2)),
                ) else {
                    return self.command_error();
                };
                let Some(p) = self.positions.get(&n).copied() else {
                    return self.fail(Error::Position);
                };
                let mut o = self.line_to(&p, k as usize);
                self.set_hand(hand, &mut o);
                o
            }
            ("MC", 2) => {
                let (Some(a), Some(b)) = (Self::position_no(args[0]), Self::position_no(args[1]))
                else {
                    return self.command_error();
                };
                let order: Vec<i64> = if a <= b {
                    (a..=b).collect()
                } else {
                    (b..=a).rev().collect()
                };
                // Every position must be defined and reachable before the
                // arm starts.
                let mut at = self.arm.counts;
                let mut busy = 0.0;
                for k in order {
                    let Some(p) = self.positions.get(&k) else {
                        return self.fail(Error::Position);
                    };
                    let Some(c) = self.arm.solve(p, self.tool, &at) else {
                        return self.fail(Error::Position);
                    };
                    busy += self.arm.travel_time(&at, &c);
                    at = c;
                }
                self.arm.counts = at;
                Outcome::busy(busy)
            }
            ("DW", 3) => {
                let Some(d) = line::decimals::<3>(&args) else {
                    return self.command_error();
                };
                let mut p = self.arm.pose(self.tool);
                for k in 0..3 {
                    p[k] += d[k];
                }
                // A straight line, checked every 10 mm.
                let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                self.line_to(&p, (len / 10.0).ceil() as usize)
            }
            ("SP", 1 | 2) => {
                let level = line::integer(args[0], 0, 9);
                let accel_ok = args.get(1).is_none_or(|a| matches!(*a, "H" | "L"));
                match level {
                    Some(l) if accel_ok => {
                        self.arm.speed = l as u8;
                        Outcome::default()
                    }
                    _ => self.command_error(),
                }
            }
            ("TL", 1) => match line::decimal(args[0]) {
                Some(t) if (0.0..=300.0).contains(&t) => {
                    self.tool = t;
                    Outcome::default()
                }
                _ => self.command_error(),
            },
            ("GO", 0) => self.hand(true),
            ("GC", 0) => self.hand(false),
            ("GP", 3) => {
                let ok = line::integer(args[0], 0, 15).is_some()
                    && line::integer(args[1], 0, 15).is_some()
                    && line::integer(args[2], 0, 99).is_some();
                if ok {
                    Outcome::default()
                } else {
                    self.command_error()
                }
            }
            ("TI", 1) => match line::integer(args[0], 0, 32767) {
                Some(n) => Outcome::busy(n as f64 * 0.1),
                None => self.command_error(),
            },
            ("WH", 0) => Outcome::reply(self.where_reply()),
            ("ID", 0) => {
                self.register = INPUT_PORT;
                Outcome::default()
            }
            ("DR", 0) => Outcome::reply(format!("&H{:05X},&H{:04X}", self.register, self.output)),
            ("OD", 1) => match line::port_value(args[0]) {
                Some(v) => {
                    self.output = v;
                    Outcome::default()
                }
                None => self.command_error(),
            },
            _ => self.command_error(),
        }
    }

    fn command_error(&mut self) -> Outcome {
        self.fail(Error::Command)
    }

    fn hand(&mut self, open: bool) -> Outcome {
        self.hand_open = open;
        Outcome::busy(HAND_TIME)
    }

    /// `MO n,O|C`: the hand ends open or closed (after the motion).
    fn set_hand(&mut self, hand: Option<bool>, o: &mut Outcome) {
        if let Some(open) = hand
            && self.error == Error::None
            && open != self.hand_open
        {
            self.hand_open = open;
            o.busy += HAND_TIME;
        }
    }
}
