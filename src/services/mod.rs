//! The AdaIR services: each is one table entry (import name, command code,
//! native body). A service validates its arguments, asks the kinematics,
//! and only then commands the driver, so a refused motion moves nothing and
//! every raised exception leaves the state as it was.

pub mod lint;
pub mod paths;
pub mod record;
pub mod table;

mod exc;
mod jog;
mod motion;
mod plumbing;
mod settings;
mod state;
#[cfg(test)]
mod tests;
mod values;

use crate::driver::{Robot, sim::Simulator};
pub use crate::interp::STOP_LABEL;
use crate::interp::{Clock, ServiceCx as Cx, ServiceFault, Services, Value, value::Array};
use crate::kinematics::{
    Arm, Elbow, Joints, KinError, Kinematics, MotionProfile, Pose, RobotDescription,
};
pub use exc::{Exc, ExcIds, exception_doc};
use std::collections::BTreeMap;
use std::io::Write;
use std::rc::Rc;

// The map: `state.rs` the robot state; `plumbing.rs` what every service
// shares; `motion.rs`, `settings.rs` and `values.rs` the services' bodies by
// group; `jog.rs` the teach pendant's jogs and `TeachBox`.
use jog::*;
pub use jog::{fresh_pose, jog, jog_hand};
use motion::*;
use plumbing::*;
pub use plumbing::{WallClock, frame_rows, frame_value};
pub(crate) use plumbing::{driver_fail, fail};
use settings::*;
use state::standard_tool;
pub use state::{RobotState, Tool};
pub use values::grip_reading;
use values::*;

/// How a service ends early: an exception, or the user's stop.
type R<T> = Result<T, ServiceFault>;

/// A service body: the call's narrow context, the robot state lent to it,
/// the arguments (`out` parameters written back in place).
pub type ServiceFn = fn(&mut Cx, &mut RobotState, &mut [Value]) -> R<Option<Value>>;

/// The motion services (import names): the ones that move the arm or the
/// hand. While the TeachBox is open, another task's call of one raises
/// `RobotBusy` (tasks.md); any other service waits for the box to close.
pub const MOVES_THE_ARM: &[&str] = &[
    "InitRobot",
    "EndRobot",
    "CalibrateRobot",
    "MoveTool",
    "MoveAxesAbsolute",
    "MoveAxesRelative",
    "MoveFrameAbsolute",
    "MoveFrameRelative",
    "MovePath",
    "TeachBox",
];

/// The screen teach pendant behind the `TeachBox` service. The terminal
/// code lives in `repl::teach`; the services only call this trait.
pub trait Pendant {
    /// Shows the teach box until the user leaves it; jogs move `st.robot`.
    fn teach(
        &mut self,
        st: &mut RobotState,
        clock: &mut dyn Clock,
        text: &str,
        refresh: bool,
        clear: bool,
    ) -> Result<(), String>;
}

pub use table::{Group, SERVICES, Service};

/// The import names of the services only the simulator has: on a real arm,
/// and in the rehearsal that stands in for it, they raise
/// `CommandNotSupported` (`adair check` warns of them).
pub const SIMULATOR_ONLY: &[&str] = &["PlaceObject"];

/// The service bound to an import name, as the interpreter binds it.
pub fn lookup(name: &str) -> Option<crate::interp::Binding> {
    table::index_of(name).map(crate::interp::Binding::Service)
}

/// Reads and parses a robot description file (`--robot-file`). The
/// kinematics parse the text and do no I/O; the file is read here.
pub fn read_robot_file(
    path: impl AsRef<std::path::Path>,
) -> Result<RobotDescription, crate::kinematics::DescriptionError> {
    let path = path.as_ref();
    let source = path.display().to_string();
    match std::fs::read_to_string(path) {
        Ok(text) => RobotDescription::from_file_text(&text, source),
        Err(e) => Err(crate::kinematics::DescriptionError {
            source,
            problems: vec![format!("cannot read the file: {e}")],
        }),
    }
}

/// The profile an import name expects, for the checker.
pub fn import_profile(name: &str) -> Option<crate::check::ImportProfile> {
    table::by_import(name).map(|s| s.import_profile())
}

fn code_of(name: &str) -> i64 {
    table::code_of(name)
}
