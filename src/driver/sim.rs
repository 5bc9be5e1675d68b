//! The exact robot simulator: joint state, read-back quantised to the
//! joint resolution, and a gripper with an optional object between the jaws.
//! Timing is the services' business (they advance the machine's clock).

use super::{DriverError, GripperState, Robot};
use crate::kinematics::{Joints, RobotDescription};

pub struct Simulator {
    desc: RobotDescription,
    joints: Joints,
    gripper: GripperState,
    /// Width of an object between the jaws, mm (0 = none).
    object: f64,
    /// Stands in for a real arm (a rehearsal): what only the simulator can
    /// do is refused, as on the arm.
    stand_in: bool,
}

impl Simulator {
    pub fn new(desc: RobotDescription) -> Simulator {
        let opening = desc.gripper().opening_max;
        Simulator {
            desc,
            joints: [0.0; 5],
            gripper: GripperState {
                opening,
                force: 0.0,
            },
            object: 0.0,
            stand_in: false,
        }
    }
}

impl Simulator {
    /// Makes this simulator stand in for a real arm (`--rehearse` with
    /// `--port`): simulator-only services raise `CommandNotSupported`.
    pub fn stand_in_for_real_arm(&mut self) {
        self.stand_in = true;
    }

    /// Starts from `joints` (a rehearsal starts where the real arm is).
    pub fn set_joints(&mut self, joints: Joints) {
        self.joints = joints;
    }

    /// An object of `width` mm between the jaws (0 = none).
    pub fn place_object(&mut self, width: f64) -> Result<(), String> {
        if !width.is_finite() || width < 0.0 {
            return Err(format!(
                "an object {width} mm wide: give a width of 0.0 mm or more (0.0 removes the object)"
            ));
        }
        if width > self.gripper.opening + 1e-9 && width > 0.0 {
            return Err(format!(
                "an object of {width:.1} mm does not fit between jaws open {:.1} mm",
                self.gripper.opening
            ));
        }
        self.object = width.max(0.0);
        Ok(())
    }
}

impl Robot for Simulator {
    fn description(&self) -> &RobotDescription {
        &self.desc
    }
    fn joints(&self) -> Joints {
        self.joints
    }
    fn read_joints(&self) -> Joints {
        self.desc.quantize(&self.joints)
    }
    /// The simulator's motion is its joint state at the end; the services
    /// keep the virtual time it takes (and stop it part-way by `set_joints`).
    fn start_motion(&mut self, points: &[Joints], _duration: f64) -> Result<(), DriverError> {
        for p in points {
            // The services check limits before anything moves; a driver
            // still refuses to leave them.
            if let Err(v) = self.desc.check_limits(p) {
                return Err(DriverError::Limit(v.to_string()));
            }
        }
        if let Some(last) = points.last() {
            self.joints = *last;
        }
        Ok(())
    }
    fn calibrate(&mut self) -> Result<(), DriverError> {
        Ok(())
    }
    fn gripper(&self) -> GripperState {
        self.gripper
    }
    fn move_gripper(
        &mut self,
        opening: f64,
        force_limit: Option<f64>,
    ) -> Result<GripperState, DriverError> {
        let g = *self.desc.gripper();
        let target = opening.clamp(g.opening_min, g.opening_max);
        let closing = target < self.gripper.opening;
        // Closing onto an object: the jaws stop at its width and press.
        if closing
            && self.object > 0.0
            && target < self.object
            && self.gripper.opening >= self.object
        {
            let force = force_limit.unwrap_or(g.force_max).min(g.force_max);
            self.gripper = GripperState {
                opening: self.object,
                force,
            };
        } else if closing && target <= g.opening_min {
            // Closed on nothing: the jaws press on each other.
            self.gripper = GripperState {
                opening: g.opening_min,
                force: force_limit.unwrap_or(g.force_max).min(g.force_max),
            };
        } else {
            self.gripper = GripperState {
                opening: target,
                force: 0.0,
            };
        }
        Ok(self.gripper)
    }
    fn as_simulator(&mut self) -> Option<&mut Simulator> {
        (!self.stand_in).then_some(self)
    }
}
