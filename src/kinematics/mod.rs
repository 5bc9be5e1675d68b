//! Kinematics of 5-axis vertical articulated arms (Mitsubishi RV-M1, RM-501
//! and any robot of the same structure described by a TOML file).
//!
//! Pure math: no I/O (a description file is read above, by the services;
//! tests/layering.rs holds it), no printing, no clock. Every public
//! function returns a [`KinError`] instead of panicking, whatever its input
//! (NaN included).
//!
//! Conventions (see `docs/kinematics.md` for the decisions):
//! - joint angles in radians, lengths in millimetres, times in seconds;
//! - all joints 0 = arm straight up; base frame z up along the waist axis;
//! - a [`Pose`] is a homogeneous transform (rotation + translation), the
//!   AdaIR `Frame` is its 3x4 row-major form ([`Pose::from_rows`]);
//! - TCP = flange * tool; the standard tool is a shift along the tool z axis.

mod error;
mod fk;
mod ik;
mod joints;
mod line;
mod pose;
mod profile;
mod robot;
mod valid;

#[cfg(test)]
mod tests;
pub use error::{AdaException, KinError, LimitViolation};
pub use ik::{Arm, Elbow, Solution};
pub use pose::Pose;
pub use profile::MotionProfile;
pub use robot::{DescriptionError, Gripper, JointSpec, Links, RobotDescription};

/// Number of joints of the robots this module handles.
pub const JOINTS: usize = 5;

/// Joint vector J1..J5 in radians (waist, shoulder, elbow, wrist pitch,
/// wrist roll).
pub type Joints = [f64; JOINTS];

/// Tolerances used throughout the module. They are documented together in
/// `docs/kinematics.md`.
pub mod tolerance {
    /// Largest allowed entry of `R^T R - I` (and of `det R - 1`) for a
    /// rotation to count as orthonormal.
    pub const ORTHONORMAL: f64 = 1e-6;
    /// Largest allowed sine of the angle between the approach vector and the
    /// vertical plane through the waist axis and the flange.
    pub const PLANE: f64 = 1e-6;
    /// A point no farther than this (mm) from the waist axis is "on the
    /// axis".
    pub const AXIS: f64 = 1e-6;
    /// A unit vector whose horizontal component is no longer than this is
    /// "vertical".
    pub const VERTICAL: f64 = 1e-9;
    /// Slack (mm) on the arm's reach before a wrist point is out of reach.
    pub const REACH: f64 = 1e-9;
    /// Slack (rad) on joint limits; values within it are clamped onto the
    /// limit.
    pub const LIMIT: f64 = 1e-9;
    /// Slack (s) when comparing a requested motion time with the fastest.
    pub const TIME: f64 = 1e-9;
}

/// Straight-line continuity parameters (see [`Kinematics::straight_line`]).
pub mod continuity {
    /// Largest joint step (rad) accepted between two solved points without
    /// checking the middle: 2 degrees.
    pub const MAX_STEP: f64 = 2.0 * std::f64::consts::PI / 180.0;
    /// Shortest piece of line (mm) the continuity check bisects down to; a
    /// step above `MAX_STEP` over a shorter piece is a joint jump.
    pub const MIN_PIECE: f64 = 0.01;
    /// Largest orientation change (rad) between two support points: 1 degree.
    pub const MAX_ROTATION_STEP: f64 = std::f64::consts::PI / 180.0;
}

/// Radians to degrees.
pub fn deg(rad: f64) -> f64 {
    rad.to_degrees()
}

/// Degrees to radians.
pub fn rad(deg: f64) -> f64 {
    deg.to_radians()
}

/// Joint vector from degrees.
pub fn joints_from_deg(deg: [f64; JOINTS]) -> Joints {
    deg.map(f64::to_radians)
}

/// Joint vector in degrees.
pub fn joints_to_deg(joints: &Joints) -> [f64; JOINTS] {
    joints.map(f64::to_degrees)
}

/// The solver for one robot: forward and inverse kinematics, ValidFrame,
/// joint targets and straight lines. Cheap to clone.
#[derive(Debug, Clone, PartialEq)]
pub struct Kinematics {
    desc: RobotDescription,
}

impl Kinematics {
    /// A solver for the robot `desc` (already validated when it was loaded).
    pub fn new(desc: RobotDescription) -> Self {
        Kinematics { desc }
    }

    /// The robot description this solver works with.
    pub fn description(&self) -> &RobotDescription {
        &self.desc
    }

    /// The standard tool: a shift along the flange's z axis by the tool
    /// length of the description.
    pub fn standard_tool(&self) -> Pose {
        self.desc.standard_tool()
    }
}
