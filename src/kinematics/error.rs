//! Errors of the kinematics module and their AdaIR exceptions.

use std::fmt;

use nalgebra::Vector3;

use super::ik::{Arm, Elbow};

/// The AdaIR exception a [`KinError`] is raised as.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AdaException {
    /// `FrameInvalid`: not a rigid transform, or an orientation the arm
    /// cannot take.
    FrameInvalid,
    /// `OutOfReach`: a position outside the workspace or a joint limit.
    OutOfReach,
    /// `TimeInvalid`: a requested motion time shorter than the fastest.
    TimeInvalid,
    /// Ada's `Constraint_Error`: an argument outside its range (a velocity
    /// of 0 %, an interpolation width of 0 mm, a NaN joint value).
    ConstraintError,
}

impl AdaException {
    /// The exception's name as AdaIR spells it.
    pub fn name(self) -> &'static str {
        match self {
            AdaException::FrameInvalid => "FrameInvalid",
            AdaException::OutOfReach => "OutOfReach",
            AdaException::TimeInvalid => "TimeInvalid",
            AdaException::ConstraintError => "Constraint_Error",
        }
    }
}

impl fmt::Display for AdaException {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A joint value outside its limits (radians inside, degrees when shown).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LimitViolation {
    /// Joint number, 1-based as in AdaIR.
    pub joint: usize,
    /// The value that does not fit, rad.
    pub target: f64,
    /// Lower limit, rad.
    pub min: f64,
    /// Upper limit, rad.
    pub max: f64,
    /// For a joint target: the same angle reached the other way round
    /// (target -+ 2 pi), which does not fit either.
    pub other_way: Option<f64>,
}

impl LimitViolation {
    /// How far (rad) `value` lies outside `min .. max`.
    pub fn excess_of(value: f64, min: f64, max: f64) -> f64 {
        if value < min {
            min - value
        } else if value > max {
            value - max
        } else {
            0.0
        }
    }

    /// How far (rad) the target lies outside the limits.
    pub fn excess(&self) -> f64 {
        Self::excess_of(self.target, self.min, self.max)
    }
}

/// Decimals (1 ..= 9) needed to show an excess of `excess_deg` degrees as
/// a non-zero number, so that a target just past a limit does not read as
/// the limit itself ("110.0 .. by 0.0 deg").
pub(crate) fn decimals_for(excess_deg: f64) -> usize {
    let mut d = 1;
    while d < 9 && (excess_deg.abs() * 10f64.powi(d as i32)) < 1.0 {
        d += 1;
    }
    d
}

impl fmt::Display for LimitViolation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let excess = self.excess().to_degrees();
        let d = decimals_for(excess);
        write!(
            f,
            "joint {} target {:.d$} deg outside {:.1} .. {:.1} deg by {:.d$} deg",
            self.joint,
            self.target.to_degrees(),
            self.min.to_degrees(),
            self.max.to_degrees(),
            excess
        )?;
        if let Some(other) = self.other_way {
            let excess = Self::excess_of(other, self.min, self.max).to_degrees();
            let d = decimals_for(excess);
            write!(
                f,
                " (the other way round, {:.d$} deg, by {:.d$} deg)",
                other.to_degrees(),
                excess
            )?;
        }
        Ok(())
    }
}

/// Everything the kinematics module can refuse. Each variant maps to one
/// AdaIR exception ([`KinError::exception`]); `Display` gives the message,
/// with numbers, without the exception's name.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum KinError {
    /// A frame holds NaN or an infinity. `FrameInvalid`.
    NotFinite {
        /// Which frame ("goal frame", "tool").
        what: &'static str,
    },
    /// The rotation part is not orthonormal. `FrameInvalid`.
    NotOrthonormal {
        /// Which frame.
        what: &'static str,
        /// Largest entry of `R^T R - I`.
        deviation: f64,
    },
    /// The rotation part is a reflection or scaled (`det R != 1`).
    /// `FrameInvalid`.
    NotRightHanded {
        /// Which frame.
        what: &'static str,
        /// The determinant found.
        det: f64,
    },
    /// The approach vector leaves the vertical plane through the waist axis
    /// and the flange: a 5-axis arm cannot take this orientation here.
    /// `FrameInvalid`.
    OrientationUnreachable {
        /// Angle (rad) between the approach vector and that plane.
        angle: f64,
    },
    /// The wrist point is farther from the shoulder than the arm reaches.
    /// `OutOfReach`.
    WristTooFar {
        /// Distance shoulder -> wrist point, mm.
        distance: f64,
        /// `L2 + L3`, mm.
        reach: f64,
        /// The goal position (TCP, robot base coordinates), mm.
        goal: Vector3<f64>,
        /// The nearest position with the same orientation within the arm's
        /// length (joint limits may still refuse it), mm.
        nearest: Vector3<f64>,
    },
    /// The wrist point is closer to the shoulder than the folded arm.
    /// `OutOfReach`.
    WristTooClose {
        /// Distance shoulder -> wrist point, mm.
        distance: f64,
        /// `|L2 - L3|`, mm.
        min_reach: f64,
        /// The goal position (TCP, robot base coordinates), mm.
        goal: Vector3<f64>,
        /// The nearest position with the same orientation within the arm's
        /// length (joint limits may still refuse it), mm.
        nearest: Vector3<f64>,
    },
    /// One joint target outside its limits. `OutOfReach`.
    JointLimit(LimitViolation),
    /// Every inverse-kinematics branch breaks a joint limit (the first
    /// violation of each branch). `OutOfReach`.
    NoBranchWithinLimits {
        /// (arm, elbow, first violation) of each branch.
        branches: Vec<(Arm, Elbow, LimitViolation)>,
    },
    /// A straight line cannot be followed at `at` mm of `length` mm.
    /// Raised as its cause's exception.
    LineBlocked {
        /// Distance along the line from the start, mm.
        at: f64,
        /// Length of the line, mm.
        length: f64,
        /// Why the point at `at` cannot be reached.
        cause: Box<KinError>,
    },
    /// Following a straight line needs a joint to jump (a branch flip or a
    /// pass through a singularity). `OutOfReach`.
    JointJump {
        /// Distance along the line from the start, mm.
        at: f64,
        /// Length of the line, mm.
        length: f64,
        /// Joint number, 1-based.
        joint: usize,
        /// Size of the jump, rad.
        jump: f64,
    },
    /// The requested motion time is shorter than the fastest possible one,
    /// or not a time. `TimeInvalid`.
    TimeInvalid {
        /// Requested duration, s.
        requested: f64,
        /// Fastest possible duration, s.
        minimum: f64,
    },
    /// An argument outside its range. `Constraint_Error`.
    InvalidParameter {
        /// Which argument.
        name: &'static str,
        /// Its value.
        value: f64,
        /// What was expected.
        expected: &'static str,
    },
    /// ValidFrame found no reachable orientation for this tool (off-axis
    /// tool, flange on the waist axis). `FrameInvalid`.
    NoValidOrientation {
        /// Angle (rad) still missing when the search stopped.
        residual: f64,
    },
}

/// A position shown as `(x, y, z) mm` with one decimal.
struct Point<'a>(&'a Vector3<f64>);

impl fmt::Display for Point<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // `+ 0.0` turns -0.0 into 0.0.
        let r = |v: f64| (v * 10.0).round() / 10.0 + 0.0;
        write!(
            f,
            "({:.1}, {:.1}, {:.1}) mm",
            r(self.0.x),
            r(self.0.y),
            r(self.0.z)
        )
    }
}

impl KinError {
    /// The error with the positions it names moved by `by`: the inverse
    /// kinematics solve for the flange, the message names the TCP.
    pub(crate) fn shifted(mut self, by: Vector3<f64>) -> KinError {
        match &mut self {
            KinError::WristTooFar { goal, nearest, .. }
            | KinError::WristTooClose { goal, nearest, .. } => {
                *goal += by;
                *nearest += by;
            }
            KinError::LineBlocked { cause, .. } => {
                **cause = cause.as_ref().clone().shifted(by);
            }
            _ => {}
        }
        self
    }

    /// The AdaIR exception this error is raised as.
    pub fn exception(&self) -> AdaException {
        match self {
            KinError::NotFinite { .. }
            | KinError::NotOrthonormal { .. }
            | KinError::NotRightHanded { .. }
            | KinError::OrientationUnreachable { .. }
            | KinError::NoValidOrientation { .. } => AdaException::FrameInvalid,
            KinError::WristTooFar { .. }
            | KinError::WristTooClose { .. }
            | KinError::JointLimit(_)
            | KinError::NoBranchWithinLimits { .. }
            | KinError::JointJump { .. } => AdaException::OutOfReach,
            KinError::LineBlocked { cause, .. } => cause.exception(),
            KinError::TimeInvalid { .. } => AdaException::TimeInvalid,
            KinError::InvalidParameter { .. } => AdaException::ConstraintError,
        }
    }
}

impl fmt::Display for KinError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            KinError::NotFinite { what } => write!(f, "{what} holds a value that is not a number"),
            KinError::NotOrthonormal { what, deviation } => write!(
                f,
                "{what} is not a rigid transform: rotation not orthonormal (R^T R - I up to {deviation:.3e})"
            ),
            KinError::NotRightHanded { what, det } => write!(
                f,
                "{what} is not a rigid transform: rotation determinant {det:.6}, not +1"
            ),
            KinError::OrientationUnreachable { angle } => write!(
                f,
                "orientation not reachable by a 5-axis arm: approach vector {:.3} deg out of the arm plane (ValidFrame gives the nearest reachable one)",
                angle.to_degrees()
            ),
            KinError::WristTooFar {
                distance,
                reach,
                goal,
                nearest,
            } => write!(
                f,
                "goal {} out of reach: wrist point {distance:.1} mm from shoulder, reach {reach:.1} mm; nearest within the arm's length with this orientation {}",
                Point(goal),
                Point(nearest)
            ),
            KinError::WristTooClose {
                distance,
                min_reach,
                goal,
                nearest,
            } => write!(
                f,
                "goal {} too close to the base: wrist point {distance:.1} mm from shoulder, closer than the folded arm's {min_reach:.1} mm; nearest within the arm's length with this orientation {}",
                Point(goal),
                Point(nearest)
            ),
            KinError::JointLimit(v) => write!(f, "{v}"),
            KinError::NoBranchWithinLimits { branches } => {
                f.write_str("every arm configuration breaks a joint limit")?;
                for (i, (arm, elbow, v)) in branches.iter().enumerate() {
                    let sep = if i == 0 { ": " } else { "; " };
                    write!(f, "{sep}{arm}/{elbow}: {v}")?;
                }
                Ok(())
            }
            KinError::LineBlocked { at, length, cause } => write!(
                f,
                "straight line blocked at {at:.1} mm of {length:.1} mm: {cause}"
            ),
            KinError::JointJump {
                at,
                length,
                joint,
                jump,
            } => write!(
                f,
                "straight line needs joint {joint} to jump {:.1} deg at {at:.1} mm of {length:.1} mm (configuration change or singularity)",
                jump.to_degrees()
            ),
            KinError::TimeInvalid { requested, minimum } => write!(
                f,
                "motion time {requested:.3} s shorter than the fastest possible {minimum:.3} s"
            ),
            KinError::InvalidParameter {
                name,
                value,
                expected,
            } => write!(f, "{name} {value} invalid: expected {expected}"),
            KinError::NoValidOrientation { residual } => write!(
                f,
                "no reachable orientation found for this tool ({:.3} deg still off the arm plane)",
                residual.to_degrees()
            ),
        }
    }
}

impl std::error::Error for KinError {}
