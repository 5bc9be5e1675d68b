//! Straight-line interpolation: continuity, refusals with a distance.

use crate::kinematics::{AdaException, KinError, Pose, continuity, joints_from_deg};

use nalgebra::Vector3;

use super::{angle, down_at, rv_m1, wide};

#[test]
fn continuous_line_on_the_line() {
    let k = rv_m1();
    let tool = k.standard_tool();
    let from = joints_from_deg([-30.0, 40.0, 70.0, 40.0, 10.0]);
    let start = k.fk_tcp(&from, &tool);
    let goal = k.fk_tcp(&joints_from_deg([40.0, 20.0, 90.0, 50.0, -60.0]), &tool);
    let width = 1.0;
    let points = k.straight_line(&from, &goal, &tool, width).unwrap();
    let length = (goal.translation - start.translation).norm();
    assert!(points.len() as f64 >= length / width);
    let mut prev = from;
    let mut prev_pos = start.translation;
    for q in &points {
        let step = q
            .iter()
            .zip(&prev)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        assert!(step <= continuity::MAX_STEP, "step {step}");
        let p = k.fk_tcp(q, &tool).translation;
        // On the line: distance to the infinite line through start and goal.
        let dir = (goal.translation - start.translation).normalize();
        let off = (p - start.translation) - dir * (p - start.translation).dot(&dir);
        assert!(off.norm() < 1e-6, "{off:?}");
        assert!((p - prev_pos).norm() <= width + 1e-9);
        assert!(k.description().check_limits(q).is_ok());
        prev = *q;
        prev_pos = p;
    }
    let end = k.fk_tcp(points.last().unwrap(), &tool);
    assert!((end.translation - goal.translation).norm() < 1e-9);
    assert!((end.rotation - goal.rotation).amax() < 1e-12);
}

#[test]
fn pure_rotation_and_zero_length() {
    let k = rv_m1();
    let tool = k.standard_tool();
    let from = joints_from_deg([0.0, 30.0, 60.0, 30.0, 0.0]);
    let goal = k.fk_tcp(&joints_from_deg([0.0, 30.0, 60.0, 30.0, 90.0]), &tool);
    let points = k.straight_line(&from, &goal, &tool, 10.0).unwrap();
    assert_eq!(points.len(), 90);
    let same = k
        .straight_line(&from, &k.fk_tcp(&from, &tool), &tool, 10.0)
        .unwrap();
    assert_eq!(same.len(), 1);
}

#[test]
fn orientation_turns_evenly_along_the_line() {
    // A pure turn of 80 deg about the tool axis: slerp turns it by the same
    // angle at every support point (a normalised linear blend would turn
    // faster in the middle).
    let k = rv_m1();
    let tool = k.standard_tool();
    let from = joints_from_deg([0.0, 20.0, 60.0, 10.0, -40.0]);
    let start = k.fk_tcp(&from, &tool);
    let mut goal = start * Pose::rot_z(80f64.to_radians());
    goal.translation = start.translation;
    let points = k.straight_line(&from, &goal, &tool, 1.0).unwrap();
    assert!(points.len() >= 80, "{}", points.len());
    let mut previous = start;
    let step = 80f64.to_radians() / points.len() as f64;
    for q in &points {
        let pose = k.fk_tcp(q, &tool);
        let turned = previous.rotation_angle_to(&pose);
        assert!((turned - step).abs() < 1e-9, "{} vs {}", turned, step);
        previous = pose;
    }
}

#[test]
fn a_hair_of_rotation_ends_on_the_goal() {
    // 20 mm with a turn of 5e-7 rad (under slerp's 1e-6 rad threshold,
    // where it blends linearly): the last point is the goal, and the turn
    // grows evenly along the way.
    let k = rv_m1();
    let tool = k.standard_tool();
    let from = joints_from_deg([0.0, 20.0, 60.0, 10.0, -40.0]);
    let start = k.fk_tcp(&from, &tool);
    let tiny = 5e-7;
    let mut goal = start * Pose::rot_z(tiny);
    goal.translation = start.translation + Vector3::new(0.0, 0.0, 20.0);
    let points = k.straight_line(&from, &goal, &tool, 1.0).unwrap();
    let end = k.fk_tcp(points.last().unwrap(), &tool);
    assert!((end.rotation - goal.rotation).amax() < 1e-12);
    let n = points.len() as f64;
    for (i, q) in points.iter().enumerate() {
        let pose = k.fk_tcp(q, &tool);
        let expected = tiny * (i + 1) as f64 / n;
        assert!(
            (angle(&start.rotation, &pose.rotation) - expected).abs() < 1e-10,
            "point {i}"
        );
    }
}

#[test]
fn blocked_where_it_leaves_the_workspace() {
    // Wide limits, so that the reach, not a limit, stops the line.
    let k = wide();
    let tool = k.standard_tool();
    // Pointing down, low, through the waist axis: the arm cannot reach
    // near its own base.
    let a = down_at(250.0, -250.0, 100.0);
    let b = down_at(-250.0, 250.0, 100.0);
    let from = k.ik_all(&a, &tool, &[0.0; 5]).unwrap()[0].joints;
    let e = k.straight_line(&from, &b, &tool, 1.0).unwrap_err();
    match &e {
        KinError::LineBlocked { at, length, cause } => {
            assert!((*length - 707.1).abs() < 0.1);
            assert!(*at > 200.0 && *at < 353.6, "{at} {cause}");
            // The cause names the TCP's point on the line there, in base
            // coordinates (not the flange's).
            let KinError::WristTooClose { goal, .. } = &**cause else {
                panic!("{cause}")
            };
            let s = *at / *length;
            let want = a.translation + (b.translation - a.translation) * s;
            assert!((goal - want).norm() < 1e-6, "{goal:?} {want:?}");
        }
        _ => panic!("{e:?}"),
    }
    assert_eq!(e.exception(), AdaException::OutOfReach);
    assert!(
        e.to_string().starts_with("straight line blocked at "),
        "{e}"
    );
}

#[test]
fn blocked_at_a_joint_limit() {
    let k = rv_m1();
    let tool = k.standard_tool();
    // Through the waist axis, pointing down: the arm stays in its plane and
    // folds the elbow until J3 reaches 110 deg.
    let from = k
        .ik_all(&down_at(200.0, 0.0, 350.0), &tool, &[0.0; 5])
        .unwrap()[0]
        .joints;
    let goal = Pose::rot_z(2.5) * down_at(200.0, 0.0, 350.0);
    let e = k.straight_line(&from, &goal, &tool, 1.0).unwrap_err();
    match &e {
        KinError::LineBlocked { cause, at, .. } => {
            assert!(*at > 100.0 && *at < 150.0, "{at} {cause}");
            match &**cause {
                KinError::JointLimit(v) => assert_eq!(v.joint, 3),
                other => panic!("{other:?}"),
            }
        }
        _ => panic!("{e:?}"),
    }
    assert_eq!(e.exception(), AdaException::OutOfReach);
}

#[test]
fn through_the_axis_in_one_plane_is_continuous() {
    let k = wide();
    let tool = k.standard_tool();
    let from = k
        .ik_all(&down_at(100.0, 0.0, 400.0), &tool, &[0.0; 5])
        .unwrap()[0]
        .joints;
    let points = k
        .straight_line(&from, &down_at(-100.0, 0.0, 400.0), &tool, 0.5)
        .unwrap();
    // J1 never moves: the arm leans back in its plane.
    assert!(points.iter().all(|q| (q[0] - from[0]).abs() < 1e-9));
}

#[test]
fn near_the_axis_is_a_joint_jump() {
    let k = wide();
    let tool = k.standard_tool();
    let from = k
        .ik_all(&down_at(100.0, 1e-4, 400.0), &tool, &[0.0; 5])
        .unwrap()[0]
        .joints;
    let e = k
        .straight_line(&from, &down_at(-100.0, 1e-4, 400.0), &tool, 0.5)
        .unwrap_err();
    match &e {
        KinError::JointJump {
            at, joint, jump, ..
        } => {
            assert_eq!(*joint, 1);
            assert!((*at - 100.0).abs() < 0.02, "{at}");
            assert!(*jump > continuity::MAX_STEP);
        }
        _ => panic!("{e:?}"),
    }
    assert_eq!(e.exception(), AdaException::OutOfReach);
}

#[test]
fn goal_errors_and_parameters() {
    let k = rv_m1();
    let tool = k.standard_tool();
    let from = joints_from_deg([0.0, 30.0, 60.0, 30.0, 0.0]);
    let e = k
        .straight_line(&from, &down_at(900.0, 0.0, 0.0), &tool, 1.0)
        .unwrap_err();
    assert!(matches!(e, KinError::WristTooFar { .. }), "{e}");
    let mut bad = k.fk_tcp(&[0.1; 5], &tool);
    bad.rotation *= 2.0;
    let e = k.straight_line(&from, &bad, &tool, 1.0).unwrap_err();
    assert_eq!(e.exception(), AdaException::FrameInvalid);
    for w in [0.0, -1.0, f64::NAN, 1e-9] {
        let e = k
            .straight_line(&from, &k.fk_tcp(&[0.1; 5], &tool), &tool, w)
            .unwrap_err();
        assert_eq!(e.exception(), AdaException::ConstraintError, "{w}: {e}");
    }
}
