//! The motion rules of docs/kinematics.md ("Motion rules"), as properties
//! over random reachable poses and random current joints on both robots
//! (and on a variant with joints of more than a turn, where the 2 pi
//! representation matters):
//!
//! 1. a frame move takes, of all branches and representations inside the
//!    limits, the one nearest the current joints by the documented metric
//!    (slowest joint's time, then summed squares), among those matching a
//!    `SetRobotConfig` preference when any does;
//! 2. no joint turns the long way round when the short way is within its
//!    limits;
//! 3. a straight line keeps every joint continuous between support points
//!    (no 2 pi jump, no branch flip), inside the limits, on the segment,
//!    ending at the goal, and is refused whole;
//! 4. a joint whose start value has another representation inside its limits
//!    (J5 at +-180 deg) does the line in that one rather than refusing;
//!
//! and ValidFrame keeps the position, gives a reachable orientation, and the
//! nearest one.

use std::f64::consts::{PI, TAU};

use crate::kinematics::{
    Arm, Elbow, Joints, KinError, Kinematics, Pose, RobotDescription, Solution, continuity,
    joints_from_deg,
};
use nalgebra::{UnitQuaternion, Vector3};
use proptest::prelude::*;

fn robot(i: usize) -> Kinematics {
    match i {
        0 => Kinematics::new(RobotDescription::builtin("rv-m1").unwrap()),
        1 => Kinematics::new(RobotDescription::builtin("rm-501").unwrap()),
        // RV-M1 with J1 over -200 .. 200 and J5 over -400 .. 400 deg.
        _ => {
            let text = RobotDescription::builtin_text("rv-m1")
                .unwrap()
                .replace("min_deg = -150.0", "min_deg = -200.0")
                .replace("max_deg = 150.0", "max_deg = 200.0")
                .replace("min_deg = -180.0", "min_deg = -400.0")
                .replace("max_deg = 180.0", "max_deg = 400.0");
            Kinematics::new(RobotDescription::from_toml_str(&text).unwrap())
        }
    }
}

/// Joints inside the limits from fractions 0..1.
fn within(k: &Kinematics, f: &[f64; 5]) -> Joints {
    let mut q = [0.0; 5];
    for ((v, spec), f) in q.iter_mut().zip(k.description().joints()).zip(f) {
        *v = spec.min + (spec.max - spec.min) * f;
    }
    q
}

fn metric(k: &Kinematics, a: &Joints, b: &Joints) -> (f64, f64) {
    let mut time = 0.0f64;
    let mut sq = 0.0;
    for ((x, y), spec) in a.iter().zip(b).zip(k.description().joints()) {
        time = time.max((x - y).abs() / spec.max_speed);
        sq += (x - y) * (x - y);
    }
    (time, sq)
}

/// Every representation (whole turns) of every solution's joints inside the
/// limits, enumerated here independently of the library's choice.
fn all_candidates(k: &Kinematics, sols: &[Solution]) -> Vec<(Joints, Arm, Elbow)> {
    let specs = k.description().joints();
    let mut out = Vec::new();
    for s in sols {
        let mut reps: Vec<Joints> = vec![s.joints];
        for (j, spec) in specs.iter().enumerate() {
            let mut next = Vec::new();
            for q in &reps {
                for turns in -3..=3 {
                    let v = q[j] + turns as f64 * TAU;
                    if v >= spec.min - 1e-9 && v <= spec.max + 1e-9 {
                        let mut r = *q;
                        r[j] = v;
                        next.push(r);
                    }
                }
            }
            reps = next;
        }
        out.extend(reps.into_iter().map(|r| (r, s.arm, s.elbow)));
    }
    out
}

fn lexi_le(a: (f64, f64), b: (f64, f64)) -> bool {
    a.0 < b.0 - 1e-12 || (a.0 <= b.0 + 1e-12 && a.1 <= b.1 + 1e-9)
}

fn arm_of(i: u8) -> Arm {
    [Arm::None, Arm::Forward, Arm::Backward][i as usize % 3]
}

fn elbow_of(i: u8) -> Elbow {
    [Elbow::None, Elbow::Above, Elbow::Below][i as usize % 3]
}

fn fractions() -> impl Strategy<Value = [f64; 5]> {
    proptest::array::uniform5(0.0..1.0f64)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(600))]

    /// Rules 1 and 2 for frame moves.
    #[test]
    fn frame_move_takes_the_nearest_branch_and_representation(
        robot_i in 0..3usize,
        target in fractions(),
        current in fractions(),
        arm in 0..3u8,
        elbow in 0..3u8,
    ) {
        let k = robot(robot_i);
        let tool = k.standard_tool();
        let goal = k.fk_tcp(&within(&k, &target), &tool);
        let current = within(&k, &current);
        let (arm, elbow) = (arm_of(arm), elbow_of(elbow));
        let sols = k.ik_all(&goal, &tool, &current).unwrap();
        let chosen = k.ik_choose(&goal, &tool, &current, arm, elbow).unwrap();
        prop_assert!(sols.contains(&chosen));
        let back = k.fk_tcp(&chosen.joints, &tool);
        prop_assert!((back.translation - goal.translation).amax() < 1e-6);
        prop_assert!((back.rotation - goal.rotation).amax() < 1e-9);
        // Rule 1: nearest of the candidates that match the preference, or of
        // all when none matches.
        let cands = all_candidates(&k, &sols);
        let matching: Vec<_> = cands
            .iter()
            .filter(|(_, a, e)| (arm == Arm::None || arm == *a) && (elbow == Elbow::None || elbow == *e))
            .collect();
        let pool: Vec<_> = if matching.is_empty() { cands.iter().collect() } else { matching };
        let d = metric(&k, &chosen.joints, &current);
        prop_assert!(pool.iter().any(|(q, a, e)| *q == chosen.joints && *a == chosen.arm && *e == chosen.elbow));
        for (q, _, _) in &pool {
            prop_assert!(lexi_le(d, metric(&k, q, &current)), "{:?} nearer than {:?}", q, chosen.joints);
        }
        // Rule 2: per joint, the short way when it is inside the limits.
        for (j, spec) in k.description().joints().iter().enumerate() {
            let delta = chosen.joints[j] - current[j];
            let short = current[j] + (delta - TAU * (delta / TAU).round());
            if short >= spec.min && short <= spec.max {
                prop_assert!(delta.abs() <= PI + 1e-9, "joint {} turns {} rad", j + 1, delta);
            }
        }
    }

    /// Rule 3: continuity, limits and the goal on straight lines; a refused
    /// line is refused before anything moves (no points at all).
    #[test]
    fn straight_line_is_continuous_and_checked_whole(
        robot_i in 0..3usize,
        start in fractions(),
        target in fractions(),
        width in 5.0..60.0f64,
    ) {
        let k = robot(robot_i);
        let tool = k.standard_tool();
        let from = within(&k, &start);
        // A goal near the start (a mix of the two joint vectors), so that
        // many lines get through.
        let mut mixed = within(&k, &target);
        for (m, f) in mixed.iter_mut().zip(&from) {
            *m = f + 0.3 * (*m - f);
        }
        let goal = k.fk_tcp(&mixed, &tool);
        match k.straight_line(&from, &goal, &tool, width) {
            Ok(points) => {
                prop_assert!(!points.is_empty());
                let start_pose = k.fk_tcp(&from, &tool);
                let length = (goal.translation - start_pose.translation).norm();
                let mut prev = from;
                for (i, q) in points.iter().enumerate() {
                    prop_assert!(k.description().check_limits(q).is_ok());
                    // Continuous: no joint half a turn or more from its previous
                    // value (a 2 pi jump or a J1 branch flip would be; the
                    // library bisects to 2 deg between points internally, and
                    // the arm label may change continuously as the wrist
                    // crosses the waist axis). The first point may take a
                    // start value in its other representation (rule 4).
                    for (a, b) in q.iter().zip(&prev) {
                        let d = if i == 0 { (a - b + PI).rem_euclid(TAU) - PI } else { a - b };
                        prop_assert!(d.abs() < PI, "jump {} at {}", d, i);
                    }
                    // On the segment.
                    let p = k.fk_tcp(q, &tool).translation;
                    let along = (p - start_pose.translation).dot(&(goal.translation - start_pose.translation));
                    let off = if length > 1e-9 {
                        ((p - start_pose.translation) - (goal.translation - start_pose.translation) * (along / (length * length))).norm()
                    } else {
                        (p - start_pose.translation).norm()
                    };
                    prop_assert!(off < 1e-6, "point {} is {} mm off the line", i, off);
                    prev = *q;
                }
                let end = k.fk_tcp(points.last().unwrap(), &tool);
                prop_assert!((end.translation - goal.translation).amax() < 1e-6);
                prop_assert!((end.rotation - goal.rotation).amax() < 1e-9);
            }
            Err(e) => {
                prop_assert!(
                    matches!(e, KinError::LineBlocked { .. } | KinError::JointJump { .. }),
                    "{e:?}"
                );
            }
        }
    }

    /// Rule 4: from J5 at +-180 deg (one representation per end of the
    /// RV-M1's and RM-501's wrist roll range), a line that turns the roll on
    /// past the limit uses the other representation rather than refusing.
    #[test]
    fn wrist_roll_at_half_turn_uses_the_other_representation(
        robot_i in 0..2usize,
        start in fractions(),
        roll in 1.0..20.0f64,
        sign in prop::bool::ANY,
    ) {
        let k = robot(robot_i);
        let tool = k.standard_tool();
        let mut from = within(&k, &start);
        // Keep the arm well inside the limits and away from the waist axis.
        from[0] *= 0.5;
        from[1] = 0.5 * (from[1] + 40f64.to_radians());
        from[2] = 0.5 * (from[2] + 60f64.to_radians());
        from[3] *= 0.5;
        from[4] = if sign { PI } else { -PI };
        let mut turned = from;
        // Past the limit: beyond +180 from +180, beyond -180 from -180.
        turned[4] += if sign { roll.to_radians() } else { -roll.to_radians() };
        let goal = k.fk_tcp(&turned, &tool);
        let points = k.straight_line(&from, &goal, &tool, 20.0);
        prop_assert!(points.is_ok(), "{:?}", points);
        let points = points.unwrap();
        let last = points.last().unwrap();
        let want = turned[4] - if sign { TAU } else { -TAU };
        prop_assert!((last[4] - want).abs() < 1e-6, "{} vs {}", last[4], want);
        for w in points.windows(2) {
            prop_assert!((w[1][4] - w[0][4]).abs() <= continuity::MAX_STEP + 1e-9);
        }
    }

    /// ValidFrame: position kept, reachable result, the nearest reachable
    /// orientation (the turn equals the approach's angle to the arm plane,
    /// the least any rotation can achieve), unchanged when reachable.
    #[test]
    fn valid_frame_keeps_position_and_turns_least(
        robot_i in 0..2usize,
        target in fractions(),
        axis in proptest::array::uniform3(-1.0..1.0f64),
        angle in 0.0..3.1f64,
    ) {
        let k = robot(robot_i);
        let tool = k.standard_tool();
        let reachable = k.fk_tcp(&within(&k, &target), &tool);
        let v = k.valid_frame(&reachable, &tool).unwrap();
        prop_assert!((v.rotation - reachable.rotation).amax() < 1e-9);
        prop_assert_eq!(v.translation, reachable.translation);
        let axis = Vector3::new(axis[0], axis[1], axis[2]);
        prop_assume!(axis.norm() > 1e-3);
        let r = UnitQuaternion::from_scaled_axis(axis.normalize() * angle).to_rotation_matrix().into_inner();
        let goal = Pose::new(r * reachable.rotation, reachable.translation);
        let v = k.valid_frame(&goal, &tool).unwrap();
        prop_assert_eq!(v.translation, goal.translation);
        let p = goal.translation;
        prop_assume!(p.xy().norm() > 1e-3);
        let m = Vector3::new(-p.y, p.x, 0.0).normalize();
        // Reachable: in the plane, and solvable when the goal's position is
        // (the same position as a reachable pose).
        prop_assert!(v.approach().dot(&m).abs() < 1e-9);
        prop_assert!(k.classify(&v, &tool, &[0.0; 5]).map_err(|e| e.exception()) != Err(crate::kinematics::AdaException::FrameInvalid));
        // Nearest: turned by exactly the approach's angle to the plane.
        let plane_angle = goal.approach().dot(&m).abs().clamp(0.0, 1.0).asin();
        prop_assert!((goal.rotation_angle_to(&v) - plane_angle).abs() < 1e-9, "{} vs {}", goal.rotation_angle_to(&v), plane_angle);
        // Idempotent.
        let again = k.valid_frame(&v, &tool).unwrap();
        prop_assert!((again.rotation - v.rotation).amax() < 1e-12);
    }
}

#[test]
fn wrist_roll_line_example() {
    // RV-M1 from J5 = 180 deg, a line that turns the roll 10 deg further.
    let k = robot(0);
    let tool = k.standard_tool();
    let from = joints_from_deg([0.0, 30.0, 60.0, 40.0, 180.0]);
    let goal = k.fk_tcp(&joints_from_deg([0.0, 30.0, 60.0, 40.0, 190.0]), &tool);
    let points = k.straight_line(&from, &goal, &tool, 10.0).unwrap();
    let last = points.last().unwrap();
    assert!((last[4].to_degrees() + 170.0).abs() < 1e-6, "{last:?}");
    assert!(
        (points[0][4].to_degrees() + 179.0).abs() < 0.5,
        "{:?}",
        points[0]
    );
    // The other way round from +180 needs no other representation.
    let goal = k.fk_tcp(&joints_from_deg([0.0, 30.0, 60.0, 40.0, 170.0]), &tool);
    let points = k.straight_line(&from, &goal, &tool, 10.0).unwrap();
    assert!((points.last().unwrap()[4].to_degrees() - 170.0).abs() < 1e-6);
    // And from 170 deg the joint cannot pass 180: refused, naming joint 5.
    let from = joints_from_deg([0.0, 30.0, 60.0, 40.0, 170.0]);
    let goal = k.fk_tcp(&joints_from_deg([0.0, 30.0, 60.0, 40.0, 200.0]), &tool);
    let e = k.straight_line(&from, &goal, &tool, 10.0).unwrap_err();
    assert!(e.to_string().contains("joint 5"), "{e}");
}
