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
    let mut st = s.machine.robot.take().unwrap();
    let st = st
        .downcast_mut::<adair::services::RobotState>()
        .expect("robot state");
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
    let s = Session::new(Box::new(std::io::sink()));
    for svc in adair::services::SERVICES {
        let n = s
            .checker
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
