//! The one boundary between the services and a robot: the [`Robot`] trait.
//! The simulator implements it today; a serial driver for the real
//! controllers will implement it beside it. Drivers never do kinematics:
//! they receive joint vectors and report joint vectors.

pub mod sim;

use crate::kinematics::{Joints, RobotDescription};

/// Why a driver could not do what it was asked (a real link can fail).
#[derive(Debug, Clone, PartialEq)]
pub enum DriverError {
    /// The controller did not answer or the link dropped.
    NoConnection(String),
    /// The controller refused the command.
    Refused(String),
}

/// The gripper as the driver reports it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GripperState {
    /// Opening between the jaws, mm.
    pub opening: f64,
    /// Force the jaws apply, N.
    pub force: f64,
}

pub trait Robot {
    fn description(&self) -> &RobotDescription;
    /// The joints as commanded (the driver's own tracked state).
    fn joints(&self) -> Joints;
    /// The joints as the controller reads them back (quantised).
    fn read_joints(&self) -> Joints;
    /// Moves through the joint vectors in order, taking `duration` seconds in all.
    fn move_joints(&mut self, points: &[Joints], duration: f64) -> Result<(), DriverError>;
    /// Calibrates (the simulator has no drift to remove).
    fn calibrate(&mut self) -> Result<(), DriverError>;
    fn gripper(&self) -> GripperState;
    /// Moves the jaws towards `opening`; when `force_limit` is given, they stop
    /// at contact once that force is reached. Returns the final state.
    fn move_gripper(
        &mut self,
        opening: f64,
        force_limit: Option<f64>,
    ) -> Result<GripperState, DriverError>;
    /// Simulator only: an object of `width` mm between the jaws (0 = none).
    fn place_object(&mut self, width: f64) -> Result<(), DriverError>;
}
