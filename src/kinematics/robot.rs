//! Robot descriptions: geometry, limits and speeds as data (TOML files).
//!
//! The files use degrees and millimetres; in memory everything is radians.
//! Loading collects every missing or out-of-range field before it fails, so
//! a user fixing a file sees all problems at once. Type errors and unknown
//! keys come from the TOML parser (one at a time, with line and column).

use std::fmt;

use serde::Deserialize;

use super::error::LimitViolation;
use super::pose::Pose;
use super::{JOINTS, Joints};

const RV_M1: &str = include_str!("../../robots/rv-m1.toml");
const RM_501: &str = include_str!("../../robots/rm-501.toml");

/// Names accepted by [`RobotDescription::builtin`].
pub const BUILTIN_ROBOTS: [&str; 2] = ["rv-m1", "rm-501"];

/// Link lengths (mm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Links {
    /// Base mounting surface -> shoulder axis.
    pub l1: f64,
    /// Upper arm, shoulder -> elbow.
    pub l2: f64,
    /// Forearm, elbow -> wrist-pitch axis.
    pub l3: f64,
    /// Wrist-pitch axis -> flange.
    pub l4: f64,
    /// Standard tool, flange -> TCP along the tool axis.
    pub tool: f64,
}

/// One joint's data (radians, seconds).
#[derive(Debug, Clone, PartialEq)]
pub struct JointSpec {
    /// Name ("waist", ...).
    pub name: String,
    /// Lower limit, rad.
    pub min: f64,
    /// Upper limit, rad.
    pub max: f64,
    /// Maximum speed, rad/s.
    pub max_speed: f64,
    /// Acceleration of the speed ramp, rad/s^2.
    pub max_accel: f64,
    /// Smallest step the controller resolves, rad.
    pub resolution: f64,
    /// +1 or -1: the controller's direction relative to ours.
    pub direction: f64,
    /// The controller's reading (rad) when our angle is 0.
    pub zero_offset: f64,
}

impl JointSpec {
    /// Whether `value` lies within the limits (with [`super::tolerance::LIMIT`]).
    pub fn contains(&self, value: f64) -> bool {
        value >= self.min - super::tolerance::LIMIT && value <= self.max + super::tolerance::LIMIT
    }
}

/// The standard hand's sensor ranges.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gripper {
    /// Smallest opening, mm.
    pub opening_min: f64,
    /// Largest opening, mm.
    pub opening_max: f64,
    /// Smallest grip force, N.
    pub force_min: f64,
    /// Largest grip force, N.
    pub force_max: f64,
    /// Force set by `InitRobot`, N.
    pub init_force: f64,
}

/// A validated robot description.
#[derive(Debug, Clone, PartialEq)]
pub struct RobotDescription {
    name: String,
    links: Links,
    joints: [JointSpec; JOINTS],
    gripper: Gripper,
    /// Where the controller's `NT` (nest) leaves the arm, rad.
    nest: [f64; JOINTS],
}

/// Why a robot description could not be loaded: every problem found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DescriptionError {
    /// The file name, or `built-in NAME`, or `<string>`.
    pub source: String,
    /// One line per problem, naming the field (`joint[2].max_deg`).
    pub problems: Vec<String>,
}

impl fmt::Display for DescriptionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "robot description {}:", self.source)?;
        for p in &self.problems {
            write!(f, "\n  - {p}")?;
        }
        Ok(())
    }
}

impl std::error::Error for DescriptionError {}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    name: Option<String>,
    links: Option<RawLinks>,
    gripper: Option<RawGripper>,
    joint: Option<Vec<RawJoint>>,
    /// The nest pose, degrees J1..J5 (unpublished: see robots.md).
    nest_deg: Option<[f64; JOINTS]>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawLinks {
    l1: Option<f64>,
    l2: Option<f64>,
    l3: Option<f64>,
    l4: Option<f64>,
    tool: Option<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawGripper {
    opening_mm: Option<[f64; 2]>,
    force_n: Option<[f64; 2]>,
    init_force_n: Option<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawJoint {
    name: Option<String>,
    min_deg: Option<f64>,
    max_deg: Option<f64>,
    speed_deg_s: Option<f64>,
    accel_deg_s2: Option<f64>,
    resolution_deg: Option<f64>,
    direction: Option<f64>,
    zero_offset_deg: Option<f64>,
}

/// Collects problems while a raw file is checked.
struct Checker {
    problems: Vec<String>,
}

impl Checker {
    fn required<T: Clone>(&mut self, value: &Option<T>, field: &str) -> Option<T> {
        if value.is_none() {
            self.problems.push(format!("missing field `{field}`"));
        }
        value.clone()
    }

    /// A required finite number satisfying `ok`, described by `expected`.
    fn number(
        &mut self,
        value: Option<f64>,
        field: &str,
        ok: impl Fn(f64) -> bool,
        expected: &str,
    ) -> f64 {
        match value {
            None => {
                self.problems.push(format!("missing field `{field}`"));
                f64::NAN
            }
            Some(v) if !v.is_finite() || !ok(v) => {
                self.problems
                    .push(format!("field `{field}` = {v}: expected {expected}"));
                f64::NAN
            }
            Some(v) => v,
        }
    }

    fn range(&mut self, value: Option<[f64; 2]>, field: &str) -> (f64, f64) {
        match value {
            None => {
                self.problems.push(format!("missing field `{field}`"));
                (f64::NAN, f64::NAN)
            }
            Some([lo, hi]) if !(lo.is_finite() && hi.is_finite() && lo >= 0.0 && lo <= hi) => {
                self.problems.push(format!(
                    "field `{field}` = [{lo}, {hi}]: expected [min, max] with 0 <= min <= max"
                ));
                (f64::NAN, f64::NAN)
            }
            Some([lo, hi]) => (lo, hi),
        }
    }
}

fn positive(v: f64) -> bool {
    v > 0.0
}

impl RobotDescription {
    /// A description shipped with adair: `"rv-m1"` or `"rm-501"`
    /// (case-insensitive).
    pub fn builtin(name: &str) -> Result<Self, DescriptionError> {
        let text = match name.to_ascii_lowercase().as_str() {
            "rv-m1" => RV_M1,
            "rm-501" => RM_501,
            _ => {
                return Err(DescriptionError {
                    source: format!("built-in {name}"),
                    problems: vec![format!(
                        "no built-in robot `{name}`; built-in robots: {}",
                        BUILTIN_ROBOTS.join(", ")
                    )],
                });
            }
        };
        Self::parse(text, format!("built-in {name}"))
    }

    /// The text of a built-in description file (for `--robot-file` users who
    /// want a template).
    pub fn builtin_text(name: &str) -> Option<&'static str> {
        match name.to_ascii_lowercase().as_str() {
            "rv-m1" => Some(RV_M1),
            "rm-501" => Some(RM_501),
            _ => None,
        }
    }

    /// Parse a description from TOML text.
    pub fn from_toml_str(text: &str) -> Result<Self, DescriptionError> {
        Self::parse(text, "<string>".to_string())
    }

    /// Parse a description from the TOML text of the file `source` names
    /// (in its errors). The kinematics do no I/O: the file is read above
    /// them (`services::read_robot_file`).
    pub fn from_file_text(text: &str, source: impl Into<String>) -> Result<Self, DescriptionError> {
        Self::parse(text, source.into())
    }

    fn parse(text: &str, source: String) -> Result<Self, DescriptionError> {
        let raw: RawFile = match toml::from_str(text) {
            Ok(raw) => raw,
            Err(e) => {
                return Err(DescriptionError {
                    source,
                    problems: vec![e.to_string().trim_end().to_string()],
                });
            }
        };
        let mut c = Checker {
            problems: Vec::new(),
        };

        let name = c.required(&raw.name, "name").unwrap_or_default();
        if raw.name.as_deref().is_some_and(|n| n.trim().is_empty()) {
            c.problems.push("field `name` is empty".to_string());
        }

        let links = match &raw.links {
            None => {
                c.problems.push("missing table `[links]`".to_string());
                None
            }
            Some(l) => Some(Links {
                l1: c.number(l.l1, "links.l1", positive, "a length > 0 mm"),
                l2: c.number(l.l2, "links.l2", positive, "a length > 0 mm"),
                l3: c.number(l.l3, "links.l3", positive, "a length > 0 mm"),
                l4: c.number(l.l4, "links.l4", positive, "a length > 0 mm"),
                tool: c.number(l.tool, "links.tool", |v| v >= 0.0, "a length >= 0 mm"),
            }),
        };

        let gripper = match &raw.gripper {
            None => {
                c.problems.push("missing table `[gripper]`".to_string());
                None
            }
            Some(g) => {
                let (opening_min, opening_max) = c.range(g.opening_mm, "gripper.opening_mm");
                let (force_min, force_max) = c.range(g.force_n, "gripper.force_n");
                let init_force = c.number(
                    g.init_force_n,
                    "gripper.init_force_n",
                    |v| v >= 0.0,
                    "a force >= 0 N",
                );
                if init_force.is_finite()
                    && force_min.is_finite()
                    && !(force_min..=force_max).contains(&init_force)
                {
                    c.problems.push(format!(
                        "field `gripper.init_force_n` = {init_force}: outside gripper.force_n {force_min} .. {force_max}"
                    ));
                }
                Some(Gripper {
                    opening_min,
                    opening_max,
                    force_min,
                    force_max,
                    init_force,
                })
            }
        };

        let mut joints = Vec::new();
        match &raw.joint {
            None => c
                .problems
                .push(format!("missing `[[joint]]` tables (expected {JOINTS})")),
            Some(list) => {
                if list.len() != JOINTS {
                    c.problems.push(format!(
                        "{} `[[joint]]` tables, expected {JOINTS} (J1 waist .. J5 wrist roll)",
                        list.len()
                    ));
                }
                for (i, j) in list.iter().enumerate() {
                    let at = |f: &str| format!("joint[{}].{f}", i + 1);
                    let name = c.required(&j.name, &at("name")).unwrap_or_default();
                    let min = c.number(j.min_deg, &at("min_deg"), |_| true, "degrees");
                    let max = c.number(j.max_deg, &at("max_deg"), |_| true, "degrees");
                    if min.is_finite() && max.is_finite() && min >= max {
                        c.problems.push(format!(
                            "joint[{}]: min_deg {min} not below max_deg {max}",
                            i + 1
                        ));
                    }
                    let speed = c.number(j.speed_deg_s, &at("speed_deg_s"), positive, "> 0 deg/s");
                    let accel =
                        c.number(j.accel_deg_s2, &at("accel_deg_s2"), positive, "> 0 deg/s^2");
                    let resolution =
                        c.number(j.resolution_deg, &at("resolution_deg"), positive, "> 0 deg");
                    let direction = c.number(
                        j.direction,
                        &at("direction"),
                        |v| v == 1.0 || v == -1.0,
                        "1 or -1",
                    );
                    let zero = c.number(
                        j.zero_offset_deg,
                        &at("zero_offset_deg"),
                        |_| true,
                        "degrees",
                    );
                    joints.push(JointSpec {
                        name,
                        min: min.to_radians(),
                        max: max.to_radians(),
                        max_speed: speed.to_radians(),
                        max_accel: accel.to_radians(),
                        resolution: resolution.to_radians(),
                        direction,
                        zero_offset: zero.to_radians(),
                    });
                }
            }
        }

        // Optional: robots.md's reading (upper arm up, forearm level, hand
        // down) when a user's file has none.
        let nest_deg = raw.nest_deg.unwrap_or([0.0, 0.0, 90.0, 90.0, 0.0]);
        let nest = nest_deg.map(f64::to_radians);
        if c.problems.is_empty() {
            for (i, (q, spec)) in nest.iter().zip(&joints).enumerate() {
                if !spec.contains(*q) {
                    c.problems.push(format!(
                        "field `nest_deg[{}]` = {}: outside the joint's limits",
                        i + 1,
                        nest_deg[i]
                    ));
                }
            }
        }
        let joints: Result<[JointSpec; JOINTS], _> = joints.try_into();
        match (links, gripper, joints) {
            (Some(links), Some(gripper), Ok(joints)) if c.problems.is_empty() => {
                Ok(RobotDescription {
                    name,
                    links,
                    joints,
                    gripper,
                    nest,
                })
            }
            _ => Err(DescriptionError {
                source,
                problems: c.problems,
            }),
        }
    }

    /// The robot's name ("RV-M1").
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Where the controller's `NT` leaves the arm (our joint angles, rad).
    pub fn nest(&self) -> [f64; JOINTS] {
        self.nest
    }

    /// Link lengths.
    pub fn links(&self) -> &Links {
        &self.links
    }

    /// The five joints, J1 first.
    pub fn joints(&self) -> &[JointSpec; JOINTS] {
        &self.joints
    }

    /// The same robot with every joint's limits widened by `by` radians:
    /// for reading a pose the controller reports rounded (`WH`), where an
    /// arm standing at a limit may come out a rounding past it.
    pub fn with_limits_widened(&self, by: f64) -> RobotDescription {
        let mut d = self.clone();
        for j in d.joints.iter_mut() {
            j.min -= by;
            j.max += by;
        }
        d
    }

    /// The standard hand's ranges.
    pub fn gripper(&self) -> &Gripper {
        &self.gripper
    }

    /// The standard tool transform: a shift by the tool length along the
    /// flange's z axis.
    pub fn standard_tool(&self) -> Pose {
        Pose::from_translation(0.0, 0.0, self.links.tool)
    }

    /// The first joint of `joints` outside its limits, if any.
    pub fn check_limits(&self, joints: &Joints) -> Result<(), LimitViolation> {
        for (i, (q, spec)) in joints.iter().zip(&self.joints).enumerate() {
            if !spec.contains(*q) {
                return Err(LimitViolation {
                    joint: i + 1,
                    target: *q,
                    min: spec.min,
                    max: spec.max,
                    other_way: None,
                });
            }
        }
        Ok(())
    }

    /// Joint values as the controller reads them back: rounded to the joint
    /// resolution (in the controller's own zero).
    pub fn quantize(&self, joints: &Joints) -> Joints {
        let mut out = *joints;
        for (q, spec) in out.iter_mut().zip(&self.joints) {
            let controller = spec.direction * *q + spec.zero_offset;
            let steps = (controller / spec.resolution).round();
            *q = (steps * spec.resolution - spec.zero_offset) * spec.direction;
        }
        out
    }

    /// Our joint angles (rad) to the controller's (deg):
    /// `direction * deg + zero_offset_deg`.
    pub fn to_controller_deg(&self, joints: &Joints) -> [f64; JOINTS] {
        let mut out = [0.0; JOINTS];
        for ((o, q), spec) in out.iter_mut().zip(joints).zip(&self.joints) {
            *o = (spec.direction * *q + spec.zero_offset).to_degrees();
        }
        out
    }

    /// The controller's angles (deg) to ours (rad).
    pub fn from_controller_deg(&self, controller: &[f64; JOINTS]) -> Joints {
        let mut out = [0.0; JOINTS];
        for ((o, c), spec) in out.iter_mut().zip(controller).zip(&self.joints) {
            *o = (c.to_radians() - spec.zero_offset) * spec.direction;
        }
        out
    }
}
