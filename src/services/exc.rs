//! The exceptions the services raise: an enum, bound to the program's
//! exception identities once when the robot is chosen (no look-up by name
//! when a service fails).

use crate::check::Checker;
use crate::check::ir::ExcId;
use crate::kinematics::AdaException;

macro_rules! excs {
    ($($v:ident = $full:literal,)*) => {
        /// An exception a service can raise: appendix B, and the Ada ones.
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub enum Exc { $($v,)* }
        impl Exc {
            pub const ALL: &'static [Exc] = &[$(Exc::$v,)*];
            /// The full name the checker gives the exception.
            pub fn full_name(self) -> &'static str {
                match self { $(Exc::$v => $full,)* }
            }
        }
    };
}

excs! {
    CommandNotImplemented = "ADAIR.COMMANDNOTIMPLEMENTED",
    CommandNotSupported = "ADAIR.COMMANDNOTSUPPORTED",
    ControlCommandActive = "ADAIR.CONTROLCOMMANDACTIVE",
    DistanceInvalid = "ADAIR.DISTANCEINVALID",
    FatalCommunicationError = "ADAIR.FATALCOMMUNICATIONERROR",
    ForceInvalid = "ADAIR.FORCEINVALID",
    FrameInvalid = "ADAIR.FRAMEINVALID",
    MessageInvalid = "ADAIR.MESSAGEINVALID",
    MessageLost = "ADAIR.MESSAGELOST",
    NoConnection = "ADAIR.NOCONNECTION",
    NoRobotInstalled = "ADAIR.NOROBOTINSTALLED",
    OutOfReach = "ADAIR.OUTOFREACH",
    PathAlreadyDefined = "ADAIR.PATHALREADYDEFINED",
    PathElementNotDefined = "ADAIR.PATHELEMENTNOTDEFINED",
    PathMemOverflow = "ADAIR.PATHMEMOVERFLOW",
    PathNotDefined = "ADAIR.PATHNOTDEFINED",
    RobotBusy = "ADAIR.ROBOTBUSY",
    SystemNotInitialized = "ADAIR.SYSTEMNOTINITIALIZED",
    TimeInvalid = "ADAIR.TIMEINVALID",
    UserInfoInvalid = "ADAIR.USERINFOINVALID",
    WrongRobotInstalled = "ADAIR.WRONGROBOTINSTALLED",
    ConstraintError = "CONSTRAINT_ERROR",
    ProgramError = "PROGRAM_ERROR",
    NameError = "ADA.IO_EXCEPTIONS.NAME_ERROR",
    UseError = "ADA.IO_EXCEPTIONS.USE_ERROR",
    DataError = "ADA.IO_EXCEPTIONS.DATA_ERROR",
}

impl From<AdaException> for Exc {
    fn from(e: AdaException) -> Exc {
        match e {
            AdaException::FrameInvalid => Exc::FrameInvalid,
            AdaException::OutOfReach => Exc::OutOfReach,
            AdaException::TimeInvalid => Exc::TimeInvalid,
            AdaException::ConstraintError => Exc::ConstraintError,
        }
    }
}

/// The exception identity of each [`Exc`] in one checked program.
#[derive(Clone, Debug)]
pub struct ExcIds(Vec<ExcId>);

impl ExcIds {
    /// Binds every [`Exc`] to its identity; `None` names the first one the
    /// program does not declare (the stdlib is broken).
    pub fn bind(chk: &Checker) -> Result<ExcIds, &'static str> {
        let mut ids = Vec::with_capacity(Exc::ALL.len());
        for e in Exc::ALL {
            match chk.tables.excs.iter().position(|x| x.name == e.full_name()) {
                Some(i) => ids.push(i as ExcId),
                None => return Err(e.full_name()),
            }
        }
        Ok(ExcIds(ids))
    }

    /// Before the AdaIR package is checked: every exception is
    /// Program_Error (no service can be called yet).
    pub fn unbound() -> ExcIds {
        ExcIds(vec![crate::check::PROGRAM_ERROR; Exc::ALL.len()])
    }

    pub fn id(&self, e: Exc) -> ExcId {
        self.0[e as usize]
    }
}

/// What the REPL's `:help` and the language server's hover say about an
/// AdaIR exception (handbook appendix B): when adair raises it.
pub fn exception_doc(name: &str) -> Option<String> {
    const EXCEPTIONS: &[(&str, &str)] = &[
        (
            "CommandNotImplemented",
            "the controller has no such command",
        ),
        (
            "CommandNotSupported",
            "the service cannot run here: TeachBox without a terminal, or the unit refused the command (ER 1; the message shows the line sent)",
        ),
        (
            "ControlCommandActive",
            "a motion started with Control => True is still running",
        ),
        (
            "DistanceInvalid",
            "a gripper distance outside the tool's DistMin .. DistMax",
        ),
        (
            "FatalCommunicationError",
            "the serial link broke (end of file, I/O error, the port vanished); later services raise NoConnection until InitRobot opens it again",
        ),
        (
            "FatalNetError",
            "a network failure (no adair driver uses a network)",
        ),
        (
            "ForceInvalid",
            "a gripper force outside the tool's ForceMin .. ForceMax",
        ),
        (
            "FrameInvalid",
            "a frame that is not a rigid transform, or an orientation this 5-axis arm cannot take (ValidFrame turns it into one it can)",
        ),
        (
            "MessageInvalid",
            "a reply from the unit that does not parse",
        ),
        (
            "MessageLost",
            "no reply from the unit within the motion's time plus --serial-timeout",
        ),
        ("MessageOverflow", "a message too long for the controller"),
        (
            "NoConnection",
            "the serial port does not open (the message names the port and the OS error)",
        ),
        ("NoRobotInstalled", "the port opened but no unit answers"),
        (
            "OutOfReach",
            "the goal is outside the arm's reach or a joint's limits (the message gives the goal and the nearest reachable point, or the joint)",
        ),
        (
            "PathAlreadyDefined",
            "CreatePath or LoadPathSystem of a path number that exists",
        ),
        (
            "PathElementNotDefined",
            "a position number the path does not have",
        ),
        ("PathMemOverflow", "the controller's path memory is full"),
        ("PathNotDefined", "a path number that was never created"),
        (
            "RobotBusy",
            "a task calls a motion service while the TeachBox is open (another task has it)",
        ),
        (
            "SystemNotInitialized",
            "a service called before InitRobot (or after EndRobot)",
        ),
        (
            "TimeInvalid",
            "a motion time that is negative, not a number, or shorter than the joints' speed allows",
        ),
        (
            "UserInfoInvalid",
            "a TeachBox text over 60 characters or with control characters",
        ),
        (
            "WrongRobotInstalled",
            "the unit answers as another robot than --robot says",
        ),
    ];
    EXCEPTIONS
        .iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(name))
        .map(|(n, d)| format!("exception AdaIR.{n} (handbook appendix B)\nraised when {d}\n"))
}
