//! The one boundary between the services and a robot: the [`Robot`] trait,
//! implemented by the simulator and by the serial driver for the real
//! controllers. Every operation that talks to a robot is fallible; the
//! services map a [`DriverError`] to the handbook's exceptions (appendix B)
//! per robots.md's fault table. The serial driver turns the unit's replies
//! into joints (`WH`); motion planning stays in the services.

pub mod protocol;
pub mod serial;
pub mod sim;
pub mod wh;

use crate::kinematics::{Joints, RobotDescription};

/// Why a driver could not do what it was asked.
#[derive(Debug, Clone, PartialEq)]
pub enum DriverError {
    /// The port does not open, or the link is down (`NoConnection`).
    NoConnection(String),
    /// The port opened but no unit answered (`NoRobotInstalled`).
    NoRobot(String),
    /// Another unit than the robot description names (`WrongRobotInstalled`).
    WrongRobot(String),
    /// No reply in time (`MessageLost`).
    Lost(String),
    /// A reply that does not parse (`MessageInvalid`).
    Invalid(String),
    /// End of file, EIO, the port vanished (`FatalCommunicationError`).
    Fatal(String),
    /// The unit refused a command: error mode I (`CommandNotSupported`).
    Refused(String),
    /// The unit found a target out of range: error mode II (`OutOfReach`).
    UnitOutOfRange(String),
    /// A joint vector outside the limits reached the driver (`OutOfReach`).
    Limit(String),
    /// The user stopped the motion (Ctrl-C).
    Interrupted,
}

impl std::fmt::Display for DriverError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            DriverError::NoConnection(m)
            | DriverError::NoRobot(m)
            | DriverError::WrongRobot(m)
            | DriverError::Lost(m)
            | DriverError::Invalid(m)
            | DriverError::Fatal(m)
            | DriverError::Refused(m)
            | DriverError::UnitOutOfRange(m)
            | DriverError::Limit(m) => f.write_str(m),
            DriverError::Interrupted => f.write_str("interrupted (Ctrl-C)"),
        }
    }
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
    /// True when motions take wall-clock time in the driver (a real arm):
    /// the services then do not advance a clock of their own.
    fn real_time(&self) -> bool {
        false
    }
    /// Connects and finds the arm's pose (`InitRobot`, before its motion).
    fn init(&mut self) -> Result<(), DriverError> {
        Ok(())
    }
    /// The speed for later motions, percent of the maximum.
    fn set_speed(&mut self, _percent: f64) -> Result<(), DriverError> {
        Ok(())
    }
    /// Starts a motion through the joint vectors in order, taking `duration`
    /// seconds in all, and returns as soon as the robot has it (a real arm:
    /// the lines are sent). The motion then runs until [`Robot::wait_motion`]
    /// sees its end or [`Robot::stop_motion`] stops it; a driver finishes a
    /// running motion before its next command.
    fn start_motion(&mut self, points: &[Joints], duration: f64) -> Result<(), DriverError>;
    /// As [`Robot::start_motion`] for a motion whose time the program
    /// states (`Time =>`): it must end at `duration`. A real unit picks the
    /// speed level that comes closest from below and waits out the rest.
    fn start_timed_motion(&mut self, points: &[Joints], duration: f64) -> Result<(), DriverError> {
        self.start_motion(points, duration)
    }
    /// The arm may have been moved outside the program (the unit's own
    /// teach box, by hand): a driver that can ask the arm reads its pose
    /// again, so that [`Robot::joints`] is where the arm is (robots.md "The
    /// arm moved outside the program"). Called by every read-back and every
    /// motion service before it plans.
    fn refresh(&mut self) -> Result<(), DriverError> {
        Ok(())
    }
    /// Waits until the running motion (if any) has ended. A user interrupt
    /// (Ctrl-C) ends the wait with [`DriverError::Interrupted`]; the caller
    /// then calls [`Robot::stop_motion`].
    fn wait_motion(&mut self) -> Result<(), DriverError> {
        Ok(())
    }
    /// True while a started motion may still run (not yet waited for).
    fn motion_pending(&self) -> bool {
        false
    }
    /// Stops the running motion: afterwards [`Robot::joints`] is where the
    /// arm stays. The serial units cannot abort a line (robots.md): the
    /// driver sends nothing more, and the arm ends at the line's target.
    fn stop_motion(&mut self) -> Result<(), DriverError> {
        Ok(())
    }
    /// Start, then wait: a whole motion.
    fn move_joints(&mut self, points: &[Joints], duration: f64) -> Result<(), DriverError> {
        self.start_motion(points, duration)?;
        self.wait_motion()
    }
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
    /// The simulator, for what only it can do (placing an object); `None`
    /// on a real arm and on a simulator that stands in for one (a
    /// rehearsal), so that such a service fails there as on the arm.
    fn as_simulator(&mut self) -> Option<&mut sim::Simulator> {
        None
    }
}
