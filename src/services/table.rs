//! The one typed table of the AdaIR services: name, import name, command
//! code, parameter profile, `:help` group, doc text and Rust body. It is the
//! single source of the AdaIR package's service declarations (generated into
//! `stdlib/adair.air` at the `--  @services` marker), of the natives the
//! interpreter binds, of `:help`, and of the check of `with Import` bindings:
//! a declaration that imports a service with another profile is a check error.

use crate::check::ImportProfile;
use crate::syntax::ast::Mode;

/// The `:help` groups, in the order `:help` lists them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Group {
    Start,
    Settings,
    Motion,
    Gripper,
    Paths,
    Values,
    Teach,
    /// Not a service of the handbook: `SERIAL_IO` and stdlib helpers.
    Library,
}

impl Group {
    pub const ALL: [Group; 7] = [
        Group::Start,
        Group::Settings,
        Group::Motion,
        Group::Gripper,
        Group::Paths,
        Group::Values,
        Group::Teach,
    ];
    pub fn title(self) -> &'static str {
        match self {
            Group::Start => "start and stop",
            Group::Settings => "settings",
            Group::Motion => "motion",
            Group::Gripper => "gripper",
            Group::Paths => "paths",
            Group::Values => "values",
            Group::Teach => "teaching",
            Group::Library => "library",
        }
    }
}

/// One service (or native helper).
pub struct Service {
    /// The Ada name the program calls.
    pub name: &'static str,
    /// The `External_Name` the declaration imports.
    pub import: &'static str,
    /// Command code for `ValueErrorStatus` (0: not a handbook service).
    pub code: i64,
    pub group: Group,
    /// A function (the parameterless form of a `Value...` service).
    pub function: bool,
    /// The Ada parameter profile: `(A : in T; ...)`, `return T` for a
    /// function, empty for none.
    pub profile: &'static str,
    /// `:help` text (and the comment above the generated declaration).
    pub doc: &'static str,
    pub body: Body,
}

/// What runs when a program calls an entry.
#[derive(Clone, Copy)]
pub enum Body {
    /// A robot service: it gets the robot state and a narrow context.
    Robot(super::ServiceFn),
    /// A text helper the interpreter's builtins define under the same
    /// import name (`SERIAL_IO` maps terminals to standard output).
    Interp,
}

impl Service {
    /// The Ada declaration, as the AdaIR package spec holds it.
    pub fn declaration(&self) -> String {
        let kind = if self.function {
            "function"
        } else {
            "procedure"
        };
        let profile = if self.profile.is_empty() {
            String::new()
        } else {
            format!(" {}", self.profile)
        };
        format!(
            "{kind} {}{profile} with Import, External_Name => \"{}\";",
            self.name, self.import
        )
    }

    /// The profile as the checker compares it: (mode, type name) per
    /// parameter, and the result type.
    pub fn import_profile(&self) -> ImportProfile {
        let (params, ret) = parse_profile(self.profile);
        ImportProfile {
            params,
            ret,
            text: {
                let kind = if self.function {
                    "function"
                } else {
                    "procedure"
                };
                if self.profile.is_empty() {
                    format!("{kind} {}", self.name)
                } else {
                    format!("{kind} {} {}", self.name, self.profile)
                }
            },
        }
    }
}

/// Splits an Ada profile text into (mode, type) per parameter and the result.
fn parse_profile(p: &str) -> (Vec<(Mode, String)>, Option<String>) {
    let (params, ret) = match p.find("return ") {
        Some(i) => (&p[..i], Some(p[i + 7..].trim().to_string())),
        None => (p, None),
    };
    let inner = params.trim().trim_start_matches('(').trim_end_matches(')');
    let mut out = Vec::new();
    for group in inner.split(';').filter(|g| !g.trim().is_empty()) {
        let Some((names, rest)) = group.split_once(':') else {
            continue;
        };
        let rest = rest.split(":=").next().unwrap_or("").trim();
        let (mode, ty) = if let Some(t) = rest.strip_prefix("in out ") {
            (Mode::InOut, t)
        } else if let Some(t) = rest.strip_prefix("out ") {
            (Mode::Out, t)
        } else if let Some(t) = rest.strip_prefix("in ") {
            (Mode::In, t)
        } else {
            (Mode::In, rest)
        };
        for _ in names.split(',') {
            out.push((mode, ty.trim().to_string()));
        }
    }
    (out, ret)
}

/// The AdaIR services, in the order of the package spec.
pub const SERVICES: &[Service] = &[
    Service {
        name: "PlaceObject",
        import: "PlaceObject",
        code: 0,
        group: Group::Gripper,
        function: false,
        profile: "(Width : in Float)",
        doc: "Simulator only: an object of the given width (mm) between the jaws,\nso that force-limited closing can be tried (0.0 removes it).\nExample: PlaceObject (30.0);",
        body: Body::Robot(super::place_object),
    },
    Service {
        name: "InitRobot",
        import: "InitRobot",
        code: 150,
        group: Group::Start,
        function: false,
        profile: "",
        doc: "Must come first: calibrates, moves to the zero pose (arm straight up), opens\nthe gripper, velocity 50 %, JointInterpolated, standard tool, robot base.\nExample: InitRobot;",
        body: Body::Robot(super::init_robot),
    },
    Service {
        name: "EndRobot",
        import: "EndRobot",
        code: 110,
        group: Group::Start,
        function: false,
        profile: "",
        doc: "Moves to the nest position; all settings are lost; InitRobot is needed again.\nRaises ControlCommandActive while a Control => True motion runs.\nExample: EndRobot;",
        body: Body::Robot(super::end_robot),
    },
    Service {
        name: "CalibrateRobot",
        import: "CalibrateRobot",
        code: 40,
        group: Group::Start,
        function: false,
        profile: "",
        doc: "Recalibrates the joints (the simulator has no drift to remove).\nExample: CalibrateRobot;",
        body: Body::Robot(super::calibrate),
    },
    Service {
        name: "SetVelocity",
        import: "SetVelocity",
        code: 330,
        group: Group::Settings,
        function: false,
        profile: "(Velocity : in RobotVelocity)",
        doc: "Percent of the maximum joint speed for later motions (the leading joint runs\nat that percentage; the others are slowed to start and stop with it).\nExample: SetVelocity (25.0);",
        body: Body::Robot(super::set_velocity),
    },
    Service {
        name: "SetMoveMode",
        import: "SetMoveMode",
        code: 290,
        group: Group::Settings,
        function: false,
        profile: "(Kind : in Motion)",
        doc: "JointInterpolated or StraightLine for later frame and path moves.\nExample: SetMoveMode (StraightLine);",
        body: Body::Robot(super::set_move_mode),
    },
    Service {
        name: "SetInterpolation",
        import: "SetInterpolation",
        code: 300,
        group: Group::Settings,
        function: false,
        profile: "(Width : in Interpolation)",
        doc: "Spacing of the support points of straight-line moves, in mm.\nExample: SetInterpolation (5.0);",
        body: Body::Robot(super::set_interpolation),
    },
    Service {
        name: "SetRobotConfig",
        import: "SetRobotConfig",
        code: 310,
        group: Group::Settings,
        function: false,
        profile: "(ArmMode : in ArmConfig; ElbowMode : in ElbowConfig; HandMode : in HandConfig)",
        doc: "The preferred inverse-kinematics branch for frame moves; No...Config keeps\nthe branch nearest to the current pose.\nExample: SetRobotConfig (ArmForward, ElbowAbove, NoHandConfig);",
        body: Body::Robot(super::set_robot_config),
    },
    Service {
        name: "ValueRobotConfig",
        import: "ValueRobotConfig",
        code: 430,
        group: Group::Values,
        function: false,
        profile: "(ArmMode : out ArmConfig; ElbowMode : out ElbowConfig; HandMode : out HandConfig)",
        doc: "The branch of the current pose.\nExample:\n  A : ArmConfig;  E : ElbowConfig;  H : HandConfig;\n  ValueRobotConfig (A, E, H);",
        body: Body::Robot(super::value_robot_config),
    },
    Service {
        name: "SetTool",
        import: "SetTool",
        code: 320,
        group: Group::Settings,
        function: false,
        profile: "(Tool : in ToolDescriptor)",
        doc: "Tool transform (flange -> TCP) and sensor ranges; current values are ignored.\nRaises FrameInvalid, ForceInvalid, DistanceInvalid.\nExample:\n  T : ToolDescriptor := ValueTool;\n  T.Trans := Trans (0.0, 0.0, 120.0);  SetTool (T);",
        body: Body::Robot(super::set_tool),
    },
    Service {
        name: "ValueTool",
        import: "ValueTool",
        code: 440,
        group: Group::Values,
        function: false,
        profile: "(Tool : out ToolDescriptor)",
        doc: "The tool, with the current gripper opening and force.\nExample:\n  T : ToolDescriptor := ValueTool;",
        body: Body::Robot(super::value_tool),
    },
    Service {
        name: "ValueTool",
        import: "ValueTool_F",
        code: 440,
        group: Group::Values,
        function: true,
        profile: "return ToolDescriptor",
        doc: "",
        body: Body::Robot(super::value_tool_f),
    },
    Service {
        name: "MoveTool",
        import: "MoveTool",
        code: 230,
        group: Group::Gripper,
        function: false,
        profile: "(Distance : in ToolDistance; Force : in ToolForce)",
        doc: "Opens or closes the gripper to Distance (mm) or until Force (N) is reached;\nthe distance wins. Raises DistanceInvalid or ForceInvalid outside the tool's ranges.\nExample: MoveTool (Distance => 20.0, Force => 5.0);",
        body: Body::Robot(super::move_tool),
    },
    Service {
        name: "MoveAxesAbsolute",
        import: "MoveAxesAbsolute",
        code: 180,
        group: Group::Motion,
        function: false,
        profile: "(Axes : in AxesVector; Time : in Duration := 0.0; Control : in Boolean := False; RealTime : in Boolean := False)",
        doc: "Joint targets in radians; multiples of 2 pi are removed, the sign gives the\nturning direction (the other way if needed). Raises OutOfReach, TimeInvalid.\nExample: MoveAxesAbsolute ((0.0, 0.5, 0.5, 0.0, 0.0));",
        body: Body::Robot(super::move_axes_absolute),
    },
    Service {
        name: "MoveAxesRelative",
        import: "MoveAxesRelative",
        code: 190,
        group: Group::Motion,
        function: false,
        profile: "(Axes : in AxesVector; Time : in Duration := 0.0; Control : in Boolean := False; RealTime : in Boolean := False)",
        doc: "Moves every joint by the given angle from where it is. Raises OutOfReach.\nExample: MoveAxesRelative ((0.1, 0.0, 0.0, 0.0, 0.0));",
        body: Body::Robot(super::move_axes_relative),
    },
    Service {
        name: "MoveFrameAbsolute",
        import: "MoveFrameAbsolute",
        code: 200,
        group: Group::Motion,
        function: false,
        profile: "(Goal : in Frame; Time : in Duration := 0.0; Control : in Boolean := False; RealTime : in Boolean := False)",
        doc: "Moves the TCP to Goal (robot base coordinates) in the current move mode.\nRaises FrameInvalid (not rigid, or an orientation a 5-axis arm cannot take),\nOutOfReach, TimeInvalid. Example: MoveFrameAbsolute (Trans (300.0, 0.0, 250.0) * RotY (Rad (180.0)));",
        body: Body::Robot(super::move_frame_absolute),
    },
    Service {
        name: "MoveFrameRelative",
        import: "MoveFrameRelative",
        code: 210,
        group: Group::Motion,
        function: false,
        profile: "(Goal : in Frame; Time : in Duration := 0.0; Control : in Boolean := False; RealTime : in Boolean := False)",
        doc: "As MoveFrameAbsolute, with the goal in the base frame set by SetBase.\nExample:\n  SetBase (Trans (300.0, 0.0, 0.0));\n  MoveFrameRelative (Trans (0.0, 0.0, 250.0) * RotY (Rad (180.0)));",
        body: Body::Robot(super::move_frame_relative),
    },
    Service {
        name: "SetBase",
        import: "SetBase",
        code: 280,
        group: Group::Settings,
        function: false,
        profile: "(Base : in Frame)",
        doc: "The object frame for MoveFrameRelative and ValueFrameRelative.\nExample: SetBase (Trans (300.0, 0.0, 0.0));",
        body: Body::Robot(super::set_base),
    },
    Service {
        name: "ValidFrame",
        import: "ValidFrame",
        code: 370,
        group: Group::Motion,
        function: false,
        profile: "(VaryFrame : in out Frame)",
        doc: "Keeps the position and turns the orientation to the nearest one this arm\ncan reach. Example:\n  F : Frame := Trans (250.0, 150.0, 200.0) * RotY (Rad (180.0)) * RotX (Rad (15.0));\n  ValidFrame (F);  MoveFrameAbsolute (F);",
        body: Body::Robot(super::valid_frame),
    },
    Service {
        name: "ValueAxes",
        import: "ValueAxes",
        code: 380,
        group: Group::Values,
        function: false,
        profile: "(Axes : out AxesVector)",
        doc: "The joints as the controller reads them back (radians, quantised).\nExample:\n  A : AxesVector := ValueAxes;",
        body: Body::Robot(super::value_axes),
    },
    Service {
        name: "ValueAxes",
        import: "ValueAxes_F",
        code: 380,
        group: Group::Values,
        function: true,
        profile: "return AxesVector",
        doc: "",
        body: Body::Robot(super::value_axes_f),
    },
    Service {
        name: "ValueFrameAbsolute",
        import: "ValueFrameAbsolute",
        code: 400,
        group: Group::Values,
        function: false,
        profile: "(ReturnFrame : out Frame)",
        doc: "The TCP frame in robot base coordinates. Example:\n  F : Frame := ValueFrameAbsolute;",
        body: Body::Robot(super::value_frame_absolute),
    },
    Service {
        name: "ValueFrameAbsolute",
        import: "ValueFrameAbsolute_F",
        code: 400,
        group: Group::Values,
        function: true,
        profile: "return Frame",
        doc: "",
        body: Body::Robot(super::value_frame_absolute_f),
    },
    Service {
        name: "ValueFrameRelative",
        import: "ValueFrameRelative",
        code: 410,
        group: Group::Values,
        function: false,
        profile: "(ReturnFrame : out Frame)",
        doc: "The TCP frame in the base frame set by SetBase. Example:\n  F : Frame := ValueFrameRelative;",
        body: Body::Robot(super::value_frame_relative),
    },
    Service {
        name: "ValueFrameRelative",
        import: "ValueFrameRelative_F",
        code: 410,
        group: Group::Values,
        function: true,
        profile: "return Frame",
        doc: "",
        body: Body::Robot(super::value_frame_relative_f),
    },
    Service {
        name: "ValueErrorStatus",
        import: "ValueErrorStatus",
        code: 390,
        group: Group::Values,
        function: false,
        profile: "(Status : out ErrorCode)",
        doc: "The command code of the service where the last exception arose (0 if none).\nExample:\n  Code : ErrorCode := ValueErrorStatus;",
        body: Body::Robot(super::value_error_status),
    },
    Service {
        name: "ValueErrorStatus",
        import: "ValueErrorStatus_F",
        code: 390,
        group: Group::Values,
        function: true,
        profile: "return ErrorCode",
        doc: "",
        body: Body::Robot(super::value_error_status_f),
    },
    Service {
        name: "CreatePath",
        import: "CreatePath",
        code: 70,
        group: Group::Paths,
        function: false,
        profile: "(PathNumber : in PathNo)",
        doc: "Creates an empty path. Raises PathAlreadyDefined. Example: CreatePath (1);",
        body: Body::Robot(super::paths::create_path),
    },
    Service {
        name: "DeletePath",
        import: "DeletePath",
        code: 80,
        group: Group::Paths,
        function: false,
        profile: "(PathNumber : in PathNo)",
        doc: "Deletes a path. Raises PathNotDefined. Example:\n  CreatePath (1);  DeletePath (1);",
        body: Body::Robot(super::paths::delete_path),
    },
    Service {
        name: "InsertPosition",
        import: "InsertPosition",
        code: 160,
        group: Group::Paths,
        function: false,
        profile: "(PathNumber : in PathNo; PositionNumber : in PosNo; Position : in Frame)",
        doc: "Inserts F before position N (beyond the end: appends). Raises PathNotDefined,\nPathMemOverflow (a path holds 65000 positions, all paths 1000000). Example:\n  CreatePath (1);\n  InsertPosition (1, 1, Trans (300.0, 0.0, 250.0) * RotY (Rad (180.0)));",
        body: Body::Robot(super::paths::insert_position),
    },
    Service {
        name: "DeletePosition",
        import: "DeletePosition",
        code: 90,
        group: Group::Paths,
        function: false,
        profile: "(PathNumber : in PathNo; PositionNumber : in PosNo)",
        doc: "Removes position N. Raises PathElementNotDefined. Example:\n  CreatePath (1);  InsertPosition (1, 1, ValueFrameAbsolute);\n  DeletePosition (1, 1);",
        body: Body::Robot(super::paths::delete_position),
    },
    Service {
        name: "ValuePosition",
        import: "ValuePosition",
        code: 420,
        group: Group::Paths,
        function: false,
        profile: "(PathNumber : in PathNo; PositionNumber : in PosNo; Position : out Frame)",
        doc: "Reads position N. Raises PathElementNotDefined. Example:\n  F : Frame;  CreatePath (1);  InsertPosition (1, 1, ValueFrameAbsolute);\n  ValuePosition (1, 1, F);",
        body: Body::Robot(super::paths::value_position),
    },
    Service {
        name: "MovePath",
        import: "MovePath",
        code: 220,
        group: Group::Motion,
        function: false,
        profile: "(PathNumber : in PathNo; Time : in Duration := 0.0; Control : in Boolean := False; RealTime : in Boolean := False)",
        doc: "Moves through every position of a path; all are checked before the robot\nstarts. Raises PathNotDefined, PathElementNotDefined, OutOfReach. Example:\n  CreatePath (1);\n  InsertPosition (1, 1, Trans (300.0, 0.0, 250.0) * RotY (Rad (180.0)));\n  InsertPosition (1, 2, Trans (300.0, 100.0, 250.0) * RotY (Rad (180.0)));\n  MovePath (1);",
        body: Body::Robot(super::paths::move_path),
    },
    Service {
        name: "SavePathSystem",
        import: "SavePathSystem",
        code: 260,
        group: Group::Paths,
        function: false,
        profile: "(PathFileName : in String)",
        doc: "Writes all paths to a text file (atomically). Raises Name_Error, Use_Error.\nExample: SavePathSystem (\"paths.txt\");",
        body: Body::Robot(super::paths::save_path_system),
    },
    Service {
        name: "LoadPathSystem",
        import: "LoadPathSystem",
        code: 170,
        group: Group::Paths,
        function: false,
        profile: "(PathFileName : in String)",
        doc: "Reads paths from a file: all or nothing. Raises Name_Error, Data_Error,\nPathAlreadyDefined, PathMemOverflow. Example:\n  CreatePath (1);  SavePathSystem (\"paths.txt\");  DeletePath (1);\n  LoadPathSystem (\"paths.txt\");",
        body: Body::Robot(super::paths::load_path_system),
    },
    Service {
        name: "TeachBox",
        import: "TeachBox",
        code: 350,
        group: Group::Teach,
        function: false,
        profile: "(Text : in String := \" \"; Refresh : in Boolean := True; Clear : in Boolean := True)",
        doc: "The screen teach pendant; returns when the user leaves it. Raises\nUserInfoInvalid (text over 60 characters), CommandNotSupported without a terminal.\nExample: TeachBox (\"Jog to the part, store it with p\");",
        body: Body::Robot(super::teach_box),
    },
];

/// Natives that the stdlib declares by hand (`SERIAL_IO`, a `Put` helper):
/// their profiles are checked at the Import like the services'.
pub const LIBRARY: &[Service] = &[
    Service {
        name: "PutS",
        import: "PutS_String",
        code: 0,
        group: Group::Library,
        function: false,
        profile: "(Term : in Term_T; Text : in String)",
        doc: "",
        body: Body::Interp,
    },
    Service {
        name: "PutS",
        import: "PutS_Integer",
        code: 0,
        group: Group::Library,
        function: false,
        profile: "(Term : in Term_T; Value : in Integer)",
        doc: "",
        body: Body::Interp,
    },
    Service {
        name: "New_LineS",
        import: "New_LineS",
        code: 0,
        group: Group::Library,
        function: false,
        profile: "(Term : in Term_T)",
        doc: "",
        body: Body::Interp,
    },
    Service {
        name: "Get_LineS",
        import: "Get_LineS",
        code: 0,
        group: Group::Library,
        function: false,
        profile: "",
        doc: "",
        body: Body::Interp,
    },
    Service {
        name: "Get_LineS",
        import: "Get_LineS_Text",
        code: 0,
        group: Group::Library,
        function: false,
        profile: "(Term : in Term_T; Text : out String; Last : out Natural)",
        doc: "",
        body: Body::Interp,
    },
    Service {
        name: "Put_Fixed",
        import: "put_fixed",
        code: 0,
        group: Group::Library,
        function: false,
        profile: "(X : in Float)",
        doc: "",
        body: Body::Interp,
    },
];

/// The entry bound to an import name.
pub fn by_import(import: &str) -> Option<&'static Service> {
    SERVICES.iter().chain(LIBRARY).find(|s| s.import == import)
}

/// The index in [`SERVICES`] of the service bound to an import name.
pub fn index_of(import: &str) -> Option<u32> {
    SERVICES
        .iter()
        .position(|s| s.import == import)
        .map(|i| i as u32)
}

/// The service (not a helper) of an Ada name, for `:help`.
pub fn by_name(name: &str) -> Option<&'static Service> {
    SERVICES
        .iter()
        .find(|s| !s.function && s.name.eq_ignore_ascii_case(name))
}

/// The command code of a service by its Ada name (0 for none).
pub fn code_of(name: &str) -> i64 {
    by_name(name).map(|s| s.code).unwrap_or(0)
}

/// The service declarations of the AdaIR package spec, with their doc text
/// as comments, generated from the table.
pub fn spec_text() -> String {
    let mut s = String::new();
    for svc in SERVICES {
        for line in svc.doc.lines() {
            s.push_str("   --  ");
            s.push_str(line);
            s.push('\n');
        }
        s.push_str("   ");
        s.push_str(&svc.declaration());
        s.push('\n');
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn profiles_parse_modes_types_and_defaults() {
        let (p, r) = parse_profile(
            "(Axes : in AxesVector; Time : in Duration := 0.0; F : in out Frame; A, B : out Float)",
        );
        assert_eq!(
            p,
            vec![
                (Mode::In, "AxesVector".to_string()),
                (Mode::In, "Duration".to_string()),
                (Mode::InOut, "Frame".to_string()),
                (Mode::Out, "Float".to_string()),
                (Mode::Out, "Float".to_string()),
            ]
        );
        assert_eq!(r, None);
        assert_eq!(parse_profile("return Frame").1.as_deref(), Some("Frame"));
    }

    #[test]
    fn every_import_name_and_code_is_unique() {
        let all: Vec<&Service> = SERVICES.iter().chain(LIBRARY).collect();
        for (i, a) in all.iter().enumerate() {
            for b in &all[i + 1..] {
                assert_ne!(a.import, b.import);
            }
        }
        for (i, a) in SERVICES.iter().enumerate() {
            for b in &SERVICES[i + 1..] {
                if a.code != 0 && a.name != b.name {
                    assert_ne!(a.code, b.code, "{} and {}", a.name, b.name);
                }
            }
        }
    }
}
