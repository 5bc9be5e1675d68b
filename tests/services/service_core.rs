//! The services as a typed core: no silent default robot, the TeachBox's
//! jogs through the service code (limits, clock, trace), `PlaceObject` only
//! on the simulator, and the service table as the source of the AdaIR
//! package's declarations.

use adair::golden::SharedBuf;
use adair::interp::{Clock, VirtualClock};
use adair::kinematics::{RobotDescription, joints_from_deg};
use adair::session::{Outcome, Session};

#[test]
fn a_session_without_a_robot_raises_instead_of_inventing_one() {
    let mut s = Session::new(Box::new(std::io::sink()));
    match s.run_source("t.air", "InitRobot;") {
        Outcome::Raised(d) => assert!(
            d.message.contains("PROGRAM_ERROR") && d.message.contains("no robot"),
            "{}",
            d.message
        ),
        o => panic!("{o:?}"),
    }
}

#[test]
fn a_teach_box_jog_is_limited_clocked_and_traced_like_a_motion() {
    let buf = SharedBuf::default();
    let mut s = Session::new(Box::new(std::io::sink()));
    s.set_robot(
        RobotDescription::builtin("rv-m1").unwrap(),
        Some(Box::new(buf.clone())),
        false,
    );
    let st = s.robot_state_mut().expect("robot state");
    let mut clock = VirtualClock::default();
    adair::services::jog(st, &mut clock, joints_from_deg([30.0, 0.0, 0.0, 0.0, 0.0])).unwrap();
    assert!(clock.now() > 0.0, "the jog took no time");
    assert!((st.robot.joints()[0] - 30f64.to_radians()).abs() < 1e-12);
    let e = adair::services::jog(st, &mut clock, joints_from_deg([0.0, 150.0, 0.0, 0.0, 0.0]))
        .unwrap_err();
    assert!(e.contains("joint 2"), "{e}");
    assert!((st.robot.joints()[1]).abs() < 1e-12, "a refused jog moved");
    let trace = buf.take();
    assert!(trace.contains("TeachBox jog"), "{trace}");
}

#[test]
fn the_adair_package_declares_every_service_of_the_table() {
    let mut s = Session::new(Box::new(std::io::sink()));
    s.need_package("AdaIR");
    for svc in adair::services::SERVICES {
        let n = s
            .front
            .checker
            .tables
            .funcs
            .iter()
            .filter(|f| f.name.eq_ignore_ascii_case(svc.name))
            .count();
        assert!(n >= 1, "{} is not declared", svc.name);
    }
    let spec = adair::services::table::spec_text();
    assert!(spec.contains(
        "procedure MoveAxesAbsolute (Axes : in AxesVector; Time : in Duration := 0.0; Control : in Boolean := False; RealTime : in Boolean := False) with Import, External_Name => \"MoveAxesAbsolute\";"
    ));
}

/// The services see a narrow context, never the whole run: no `Run`,
/// `Flow` or `Machine` of the interpreter in `src/services/`, and the robot
/// state is a typed value (no `Any`, no downcast) in the session too.
#[test]
fn services_take_a_narrow_context_and_a_typed_state() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    // Every `.rs` file under a folder, its subfolders included.
    fn rust_files(dir: &std::path::Path, into: &mut Vec<std::path::PathBuf>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                rust_files(&p, into);
            } else if p.extension().is_some_and(|x| x == "rs") {
                into.push(p);
            }
        }
    }
    // The services' own files (not these tests, which name what they ban).
    let mut files = Vec::new();
    rust_files(&root.join("src/services"), &mut files);
    assert!(files.len() >= 5, "{files:?}");
    // The session's files, and the engine's (`src/interp/vm/` included).
    rust_files(&root.join("src/session"), &mut files);
    let before = files.len();
    rust_files(&root.join("src/interp"), &mut files);
    assert!(
        files.iter().any(|f| f.ends_with("vm/exec.rs")) && files.len() - before >= 15,
        "{files:?}"
    );
    let words = |text: &str| -> Vec<String> {
        text.split(|c: char| !c.is_alphanumeric() && c != '_')
            .map(str::to_string)
            .collect()
    };
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap();
        let w = words(&text);
        for banned in ["std::any", "dyn Any", "downcast"] {
            assert!(!text.contains(banned), "{} uses {banned}", f.display());
        }
        if f.starts_with(root.join("src/interp")) {
            assert!(
                !w.iter().any(|x| x == "Checker"),
                "{} reads the checker, not the program",
                f.display()
            );
        }
        if f.starts_with(root.join("src/services")) {
            for banned in ["Run", "Flow", "Machine", "Native"] {
                assert!(
                    !w.iter().any(|x| x == banned),
                    "{} uses {banned}",
                    f.display()
                );
            }
        }
    }
}

/// A service raises through the narrow context: the exception is the
/// program's, at the call, and the state is the session's own.
#[test]
fn a_service_exception_is_raised_at_the_call_and_the_state_stays_with_the_session() {
    let mut s = Session::new(Box::new(std::io::sink()));
    s.set_robot(RobotDescription::builtin("rv-m1").unwrap(), None, false);
    match s.run_source(
        "t.air",
        "InitRobot;\nSetVelocity (0.5);\nMoveAxesAbsolute ((Rad (200.0), 0.0, 0.0, 0.0, 0.0));\n",
    ) {
        Outcome::Raised(d) => {
            assert!(
                d.message.contains("OUTOFREACH") || d.message.contains("OutOfReach"),
                "{}",
                d.message
            );
            assert_eq!(
                s.front
                    .sources
                    .line_col(d.span.context, d.span.start as usize)
                    .0,
                3,
                "{}",
                d.message
            );
        }
        o => panic!("{o:?}"),
    }
    let st = s.robot_state().expect("the session keeps its robot");
    assert!(st.initialized);
    assert!((st.velocity - 0.5).abs() < 1e-12);
    assert_eq!(
        st.error_status,
        adair::services::table::code_of("MoveAxesAbsolute")
    );
}

/// A rehearsal (`--rehearse`) runs on a simulated copy: afterwards the
/// robot's pose, the clock, the output and the program's data are as before.
#[test]
fn a_rehearsal_leaves_robot_clock_output_and_data_as_they_were() {
    let buf = SharedBuf::default();
    let mut s = Session::new(Box::new(buf.clone()));
    s.set_robot(RobotDescription::builtin("rv-m1").unwrap(), None, false);
    assert!(matches!(
        s.run_source("a.air", "N : Integer := 1;\nInitRobot;\n"),
        Outcome::Ok
    ));
    let before = s.robot_state().unwrap().robot.joints();
    let t = s.machine.clock.now();
    let (stmts, _) = s
        .check_source(
            "b.air",
            "N := 2;\nPut_Line (\"moved\");\nMoveAxesRelative ((Rad (10.0), 0.0, 0.0, 0.0, 0.0));\n",
            true,
        )
        .unwrap();
    let r = s.rehearsing(|s| {
        let r = s.run_checked(&stmts, None);
        (r.is_ok(), s.robot_state().unwrap().robot.joints()[0])
    });
    assert!(r.0);
    assert!(
        (r.1 - 10f64.to_radians()).abs() < 1e-9,
        "the stand-in moved"
    );
    assert_eq!(s.robot_state().unwrap().robot.joints(), before);
    assert_eq!(s.machine.clock.now(), t);
    assert_eq!(buf.take(), "");
    match s.run_source("c.air", "Put_Line (Integer'Image (N));\n") {
        Outcome::Ok => assert_eq!(buf.take(), " 1\n"),
        o => panic!("{o:?}"),
    }
}

/// The `TeachBox` service hands its text and both flags to the pendant, as
/// the program gave them, and the pendant's refusal is `CommandNotSupported`.
#[test]
fn the_teach_box_service_passes_text_and_flags_to_the_pendant() {
    use std::cell::RefCell;
    use std::rc::Rc;
    type Seen = Rc<RefCell<Vec<(String, bool, bool)>>>;
    struct Fake(Seen);
    impl adair::services::Pendant for Fake {
        fn teach(
            &mut self,
            _: &mut adair::services::RobotState,
            _: &mut dyn Clock,
            text: &str,
            refresh: bool,
            clear: bool,
        ) -> Result<(), String> {
            self.0.borrow_mut().push((text.to_string(), refresh, clear));
            if text == "no" {
                Err("refused".into())
            } else {
                Ok(())
            }
        }
    }
    let seen: Seen = Rc::default();
    let mut s = Session::new(Box::new(std::io::sink()));
    s.set_robot(RobotDescription::builtin("rv-m1").unwrap(), None, false);
    s.robot_state_mut().unwrap().pendant = Some(Box::new(Fake(seen.clone())));
    let src = "InitRobot;\nTeachBox (\"one\", True, False);\nTeachBox (\"two\", False, True);\n\
               TeachBox (\"no\", False, False);\n";
    match s.run_source("t.air", src) {
        Outcome::Raised(d) => assert!(d.message.contains("COMMANDNOTSUPPORTED"), "{}", d.message),
        o => panic!("{o:?}"),
    }
    assert_eq!(
        *seen.borrow(),
        [
            ("one".to_string(), true, false),
            ("two".to_string(), false, true),
            ("no".to_string(), false, false)
        ]
    );
}
