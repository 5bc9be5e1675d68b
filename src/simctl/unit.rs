//! The drive unit of the virtual controller, without I/O: it takes one
//! command line and says what to answer and how long the arm is busy. It
//! implements the units as robots.md describes them (not as our driver
//! happens to use them): error modes I and II, `RS`, positions (`PD`, `HE`,
//! `MO`, `MC`), limits, the `WH` format; the RM-501 never answers.

use crate::driver::protocol::{self, Unit};
use crate::driver::wh;
use crate::kinematics::{Joints, Kinematics, RobotDescription};
use std::collections::HashMap;

/// What the unit does with one line.
#[derive(Debug, Default, PartialEq)]
pub struct Outcome {
    /// The reply line (without its CR LF), if the command has one.
    pub reply: Option<String>,
    /// Seconds the arm moves (or dwells) for this line.
    pub busy: f64,
}

pub struct DriveUnit {
    pub kind: Unit,
    kin: Kinematics,
    /// The arm's joints (our convention, rad).
    pub joints: Joints,
    tool: f64,
    speed: u8,
    /// 0 none, 1 error mode I (command error), 2 error mode II (position).
    pub error: u8,
    positions: HashMap<u32, [f64; 5]>,
    pub hand_open: bool,
    input: u32,
    output: u32,
}

impl DriveUnit {
    pub fn new(desc: RobotDescription) -> DriveUnit {
        let kind = Unit::of_robot(desc.name());
        // Power-on: the arm stands where it was left; we take the nest.
        let joints = desc.nest();
        let tool = desc.links().tool;
        DriveUnit {
            kind,
            kin: Kinematics::new(desc),
            joints,
            tool,
            speed: 4,
            error: 0,
            positions: HashMap::new(),
            hand_open: true,
            input: 0x5a,
            output: 0,
        }
    }

    fn reply(&self, text: String) -> Outcome {
        Outcome {
            // The RM-501 never answers.
            reply: (self.kind == Unit::RvM1).then_some(text),
            busy: 0.0,
        }
    }

    fn fail(&mut self, mode: u8) -> Outcome {
        self.error = mode;
        Outcome::default()
    }

    /// Moves to `target` (rad) at the current speed level; error mode II
    /// when a joint leaves its limits (nothing moves).
    fn go(&mut self, target: Joints) -> Outcome {
        let desc = self.kin.description();
        if desc.check_limits(&target).is_err() {
            return self.fail(2);
        }
        let fraction = (f64::from(self.speed.max(1)) / 9.0).min(1.0);
        let mut t: f64 = 0.0;
        for (j, spec) in desc.joints().iter().enumerate() {
            t = t.max((target[j] - self.joints[j]).abs() / (spec.max_speed * fraction));
        }
        self.joints = target;
        Outcome {
            reply: None,
            busy: t,
        }
    }

    fn go_pose(&mut self, pose: [f64; 5]) -> Outcome {
        match wh::to_joints(&self.kin, &pose, self.tool, &self.joints) {
            Ok(q) => self.go(q),
            Err(_) => self.fail(2),
        }
    }

    pub fn where_is(&self) -> [f64; 5] {
        wh::of_joints(&self.kin, &self.joints, self.tool)
    }

    /// Handles one command line.
    pub fn handle(&mut self, line: &str) -> Outcome {
        let (code, args) = protocol::split(line);
        // Status and reset always answer; in an error mode the unit ignores
        // every other command until `RS`.
        match code.as_str() {
            "RS" if args.is_empty() => {
                self.error = 0;
                return Outcome::default();
            }
            "ER" if args.is_empty() && self.kind == Unit::RvM1 => {
                return self.reply(self.error.to_string());
            }
            "WH" if args.is_empty() && self.kind == Unit::RvM1 => {
                let p = self.where_is();
                let parts: Vec<String> = p.iter().map(|v| protocol::num(*v)).collect();
                return self.reply(parts.join(","));
            }
            _ => {}
        }
        if self.error != 0 {
            return Outcome::default();
        }
        let Some(nums) = protocol::numbers(&args) else {
            // `SP n,H` has a letter argument.
            if code == "SP" && args.len() == 2 && matches!(args[1], "H" | "L") {
                return self.set_speed(&args[..1]);
            }
            return self.fail(1);
        };
        let n = nums.len();
        match (self.kind, code.as_str(), n) {
            (_, "NT", 0) | (_, "OG", 0) | (Unit::Rm501, "HO", 0) => {
                let nest = self.kin.description().nest();
                self.go(nest)
            }
            (_, "SP", 1) => self.set_speed(&args),
            (_, "GO", 0) => {
                self.hand_open = true;
                Outcome {
                    reply: None,
                    busy: 0.3,
                }
            }
            (_, "GC", 0) => {
                self.hand_open = false;
                Outcome {
                    reply: None,
                    busy: 0.3,
                }
            }
            (Unit::RvM1, "MJ", 5) => {
                let mut c = self.kin.description().to_controller_deg(&self.joints);
                for (c, n) in c.iter_mut().zip(&nums) {
                    *c += n;
                }
                let q = self.kin.description().from_controller_deg(&c);
                self.go(q)
            }
            (Unit::Rm501, "MI", 6) => {
                let cpd = self.kind.counts_per_deg();
                let mut c = self.kin.description().to_controller_deg(&self.joints);
                if nums.iter().any(|n| n.fract() != 0.0) {
                    return self.fail(1);
                }
                for ((c, n), k) in c.iter_mut().zip(&nums).zip(cpd) {
                    *c += n / k;
                }
                let q = self.kin.description().from_controller_deg(&c);
                self.go(q)
            }
            (Unit::RvM1, "MP", 5) => self.go_pose([nums[0], nums[1], nums[2], nums[3], nums[4]]),
            (Unit::RvM1, "PD", 6) => match position_no(nums[0]) {
                Some(k) => {
                    self.positions
                        .insert(k, [nums[1], nums[2], nums[3], nums[4], nums[5]]);
                    Outcome::default()
                }
                None => self.fail(1),
            },
            (Unit::RvM1, "HE", 1) => match position_no(nums[0]) {
                Some(k) => {
                    let p = self.where_is();
                    self.positions.insert(k, p);
                    Outcome::default()
                }
                None => self.fail(1),
            },
            (_, "MO", 1) | (Unit::RvM1, "MS", 2) => match position_no(nums[0]) {
                Some(k) => match self.positions.get(&k).copied() {
                    Some(p) => self.go_pose(p),
                    None => self.fail(2),
                },
                None => self.fail(1),
            },
            (Unit::RvM1, "MC", 2) => {
                let (Some(a), Some(b)) = (position_no(nums[0]), position_no(nums[1])) else {
                    return self.fail(1);
                };
                let mut busy = 0.0;
                for k in a.min(b)..=a.max(b) {
                    let Some(p) = self.positions.get(&k).copied() else {
                        return self.fail(2);
                    };
                    let o = self.go_pose(p);
                    if self.error != 0 {
                        return o;
                    }
                    busy += o.busy;
                }
                Outcome { reply: None, busy }
            }
            (Unit::RvM1, "DW", 3) => {
                let mut p = self.where_is();
                for (p, n) in p.iter_mut().zip(&nums) {
                    *p += n;
                }
                self.go_pose(p)
            }
            (Unit::RvM1, "TL", 1) if (0.0..=300.0).contains(&nums[0]) => {
                self.tool = nums[0];
                Outcome::default()
            }
            (Unit::RvM1, "GP", 3)
                if (0.0..=15.0).contains(&nums[0])
                    && (0.0..=15.0).contains(&nums[1])
                    && (0.0..=99.0).contains(&nums[2]) =>
            {
                Outcome::default()
            }
            (Unit::RvM1, "TI", 1) if (0.0..=32767.0).contains(&nums[0]) => Outcome {
                reply: None,
                busy: nums[0] * 0.1,
            },
            (Unit::RvM1, "ID", 0) => Outcome::default(),
            (Unit::RvM1, "DR", 0) => {
                self.reply(format!("&H{:05X},&H{:04X}", self.input, self.output))
            }
            (_, "OD", 1) if (0.0..=255.0).contains(&nums[0]) => {
                self.output = nums[0] as u32;
                Outcome::default()
            }
            (Unit::Rm501, "PS", _) => Outcome::default(),
            _ => self.fail(1),
        }
    }

    fn set_speed(&mut self, args: &[&str]) -> Outcome {
        match args.first().and_then(|a| a.parse::<u8>().ok()) {
            Some(n) if n <= 9 => {
                self.speed = n;
                Outcome::default()
            }
            _ => self.fail(1),
        }
    }
}

fn position_no(v: f64) -> Option<u32> {
    (v.fract() == 0.0 && (1.0..=629.0).contains(&v)).then_some(v as u32)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rv() -> DriveUnit {
        DriveUnit::new(RobotDescription::builtin("rv-m1").unwrap())
    }

    #[test]
    fn error_modes_and_reset() {
        let mut u = rv();
        assert_eq!(u.handle("ER").reply.as_deref(), Some("0"));
        u.handle("XX 1,2");
        assert_eq!(u.handle("ER").reply.as_deref(), Some("1"));
        // Ignored while in an error mode.
        let before = u.joints;
        u.handle("MJ +10.0,+0.0,+0.0,+0.0,+0.0");
        assert_eq!(u.joints, before);
        u.handle("RS");
        assert_eq!(u.handle("ER").reply.as_deref(), Some("0"));
        // J2 beyond +100 deg: error mode II, nothing moves.
        u.handle("MJ +0.0,+150.0,+0.0,+0.0,+0.0");
        assert_eq!(u.handle("ER").reply.as_deref(), Some("2"));
        assert_eq!(u.joints, before);
        u.handle("RS");
        let o = u.handle("MJ +10.0,+0.0,+0.0,+0.0,+0.0");
        assert!(o.busy > 0.0 && o.reply.is_none());
        assert!((u.joints[0] - 10f64.to_radians()).abs() < 1e-12);
    }

    #[test]
    fn positions_where_and_the_silent_rm501() {
        let mut u = rv();
        u.handle("NT");
        let wh = u.handle("WH").reply.unwrap();
        assert_eq!(wh.split(',').count(), 5);
        u.handle(&format!("PD 5,{wh}"));
        u.handle("MJ +20.0,+10.0,+0.0,+0.0,+0.0");
        u.handle("MO 5");
        assert_eq!(u.handle("WH").reply.unwrap(), wh);
        u.handle("MO 6");
        assert_eq!(u.handle("ER").reply.as_deref(), Some("2"));
        u.handle("RS");
        u.handle("PD 700,+0.0,+0.0,+0.0,+0.0,+0.0");
        assert_eq!(u.handle("ER").reply.as_deref(), Some("1"));
        let mut m = DriveUnit::new(RobotDescription::builtin("rm-501").unwrap());
        assert_eq!(m.handle("ER"), Outcome::default());
        assert_eq!(m.error, 1);
        m.handle("RS");
        let o = m.handle("MI +400,+0,+0,+0,+0,+0");
        assert!(o.reply.is_none() && o.busy > 0.0);
        assert!((m.joints[0] - 10f64.to_radians()).abs() < 1e-12);
    }
}
