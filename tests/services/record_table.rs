//! What `--record` samples of a motion (the service table's lookups are
//! tested in `src/services/tests/parts.rs`).

use adair::kinematics::RobotDescription;
use adair::session::{Outcome, Session};

#[test]
fn a_recorded_motion_is_sampled_every_20_ms_and_at_both_ends() {
    let mut s = super::rv_m1_session();
    let o = s.run_source("rec.air", "InitRobot;\n");
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    s.start_recording();
    let o = s.run_source(
        "rec.air",
        "MoveAxesRelative ((0.05, 0.0, 0.0, 0.0, 0.0), Time => 0.2);\n",
    );
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    let rec = s.robot_state().unwrap().record.clone().unwrap();
    let t0 = rec[0].t;
    let times: Vec<f64> = rec.iter().map(|x| x.t - t0).collect();
    let want: Vec<f64> = (0..=10).map(|k| k as f64 * 0.02).collect();
    assert_eq!(times.len(), want.len(), "{times:?}");
    for (i, (t, w)) in times.iter().zip(want.iter().copied()).enumerate() {
        assert!(
            (t - w).abs() < 1e-9,
            "sample {i}: {t} s, want {w} s ({times:?})"
        );
        // The joint goes evenly from 0 to 0.05 rad over the motion.
        let j1 = rec[i].joints[0];
        assert!((j1 - 0.05 * w / 0.2).abs() < 1e-9, "sample {i}: J1 {j1}");
    }
    // The TCP follows the joints (J1 turns the arm about the base axis).
    let last = rec.last().unwrap();
    let fk = s.robot_state().unwrap().robot.joints();
    assert_eq!(last.joints, fk);
}

#[test]
fn a_recorded_straight_line_has_every_support_point_inside_the_motion() {
    // Support points lie at even fractions of the line: each is recorded,
    // in time order, none after the motion's end.
    let mut s = super::rv_m1_session();
    let setup = "InitRobot;\nMoveFrameAbsolute (((-1.0, 0.0, 0.0, 250.0), (0.0, 1.0, 0.0, 0.0), (0.0, 0.0, -1.0, 200.0)));\nSetMoveMode (StraightLine);\nSetInterpolation (10.0);\n";
    let o = s.run_source("line.air", setup);
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    s.start_recording();
    let o = s.run_source(
        "line.air",
        "MoveFrameAbsolute (((-1.0, 0.0, 0.0, 250.0), (0.0, 1.0, 0.0, 50.0), (0.0, 0.0, -1.0, 200.0)));\n",
    );
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    let rec = s.robot_state().unwrap().record.clone().unwrap();
    let (t0, t1) = (rec[0].t, rec.last().unwrap().t);
    assert!(rec.len() >= 6, "50 mm at 10 mm: {} samples", rec.len());
    assert!(rec.windows(2).all(|w| w[0].t < w[1].t), "in time order");
    // Every 10 mm support point is among the samples (y = 0, 10, ..., 50).
    for k in 0..=5 {
        let y = 10.0 * k as f64;
        assert!(
            rec.iter()
                .any(|x| (x.tcp[1] - y).abs() < 1e-6 && (x.tcp[0] - 250.0).abs() < 1e-6),
            "no sample at y = {y}: {:?}",
            rec.iter().map(|x| x.tcp[1]).collect::<Vec<_>>()
        );
    }
    assert!(t1 > t0);
}

#[test]
fn a_recorded_gripper_motion_adds_the_pose_with_the_new_opening() {
    let mut s = super::rv_m1_session();
    let o = s.run_source("grip.air", "InitRobot;\n");
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    s.start_recording();
    let o = s.run_source("grip.air", "MoveTool (Distance => 30.0, Force => 0.0);\n");
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    let rec = s.robot_state().unwrap().record.clone().unwrap();
    let last = rec.last().expect("the gripper motion is recorded");
    assert!((last.grip - 30.0).abs() < 1e-9, "{last:?}");
    assert!(last.t > 0.0, "at the end of the jaws' motion: {last:?}");
}

#[test]
fn set_robot_config_chooses_the_elbow_on_a_robot_whose_limits_allow_both() {
    // The built-in arms limit J3 to 0 .. 110 deg, so ElbowBelow is never
    // reachable there (robot_config_rm501.air); with J3 free, both elbows
    // reach the same frame and the preference chooses.
    let text = RobotDescription::builtin_text("rv-m1")
        .unwrap()
        .replace("min_deg = 0.0", "min_deg = -180.0")
        .replace("max_deg = 110.0", "max_deg = 180.0");
    let desc = RobotDescription::from_toml_str(&text).unwrap();
    let mut s = Session::new(Box::new(std::io::sink()));
    s.set_robot(desc, None, false);
    let out = adair::golden::SharedBuf::default();
    s.machine.out = Box::new(out.clone());
    let script = "\
Arm : ArmConfig; Elbow : ElbowConfig; Hand : HandConfig;
F : Frame;
InitRobot;
MoveAxesAbsolute ((Rad (10.0), Rad (10.0), Rad (60.0), Rad (-20.0), 0.0));
F := ValueFrameAbsolute;
SetRobotConfig (NoArmConfig, ElbowBelow, NoHandConfig);
MoveFrameAbsolute (F);
ValueRobotConfig (Arm, Elbow, Hand);
Put_Line (ElbowConfig'Image (Elbow));
SetRobotConfig (NoArmConfig, NoElbowConfig, NoHandConfig);
MoveFrameAbsolute (F);
ValueRobotConfig (Arm, Elbow, Hand);
Put_Line (ElbowConfig'Image (Elbow));
SetRobotConfig (NoArmConfig, ElbowAbove, NoHandConfig);
MoveFrameAbsolute (F);
ValueRobotConfig (Arm, Elbow, Hand);
Put_Line (ElbowConfig'Image (Elbow));
";
    let o = s.run_source("elbow.air", script);
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    // Below when asked; no preference stays on the nearest (below); Above
    // when asked.
    assert_eq!(out.take(), "ELBOWBELOW\nELBOWBELOW\nELBOWABOVE\n");
}
