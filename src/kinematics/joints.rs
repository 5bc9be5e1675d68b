//! Joint targets of `MoveAxesAbsolute` / `MoveAxesRelative`: the 2 pi rule
//! and the other turning direction.

use std::f64::consts::TAU;

use super::error::{KinError, LimitViolation};
use super::{Joints, Kinematics};

/// `Ok` when every value is finite, else `Constraint_Error`.
pub(crate) fn check_finite(q: &Joints, name: &'static str) -> Result<(), KinError> {
    match q.iter().find(|v| !v.is_finite()) {
        Some(v) => Err(KinError::InvalidParameter {
            name,
            value: *v,
            expected: "finite joint values",
        }),
        None => Ok(()),
    }
}

impl Kinematics {
    /// The joint values a `MoveAxesAbsolute (commanded)` moves to, or why it
    /// cannot move (nothing moves then).
    ///
    /// Per joint (handbook 4.3.1, services.md): multiples of 2 pi are
    /// removed keeping the sign (`t % 2pi`, in (-2pi, 2pi)); the sign gives
    /// the turning direction, so that value is tried first; if it breaks the
    /// joint's limits the same angle the other way round (`t -+ 2pi`) is
    /// tried; if neither fits: `OutOfReach` naming the joint, its limits, and
    /// both values with their excess. Values within
    /// [`super::tolerance::LIMIT`] of a limit are clamped onto it.
    ///
    /// The rule is absolute: the current joint values do not change the
    /// result (any in-limit target is reachable from any in-limit pose by a
    /// monotonic move), so this takes no current pose; see
    /// [`Kinematics::relative_joint_target`] for `MoveAxesRelative`.
    pub fn joint_target(&self, commanded: &Joints) -> Result<Joints, KinError> {
        check_finite(commanded, "joint target")?;
        let mut out = *commanded;
        for (i, spec) in self.desc.joints().iter().enumerate() {
            let signed = commanded[i] % TAU;
            let other = if signed >= 0.0 {
                signed - TAU
            } else {
                signed + TAU
            };
            out[i] = if spec.contains(signed) {
                signed.clamp(spec.min, spec.max)
            } else if spec.contains(other) {
                other.clamp(spec.min, spec.max)
            } else {
                return Err(KinError::JointLimit(LimitViolation {
                    joint: i + 1,
                    target: signed,
                    min: spec.min,
                    max: spec.max,
                    other_way: Some(other),
                }));
            };
        }
        Ok(out)
    }

    /// The target of `MoveAxesRelative (delta)` from `current`:
    /// `joint_target(current + delta)`.
    pub fn relative_joint_target(
        &self,
        current: &Joints,
        delta: &Joints,
    ) -> Result<Joints, KinError> {
        check_finite(current, "current joints")?;
        let mut sum = *current;
        for (s, d) in sum.iter_mut().zip(delta) {
            *s += d;
        }
        self.joint_target(&sum)
    }
}
