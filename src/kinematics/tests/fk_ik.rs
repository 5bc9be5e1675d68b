//! Forward and inverse kinematics: spec test vectors, branches, error
//! classes, joint targets.

use crate::kinematics::{
    AdaException, Arm, Elbow, Joints, KinError, Kinematics, Pose, RobotDescription, Solution,
    joints_from_deg, tolerance,
};
use nalgebra::{Matrix3, Vector3};

use super::{down_at, rm_501, rv_m1, wide, wide_text};

fn assert_close(a: Vector3<f64>, b: Vector3<f64>, tol: f64) {
    assert!((a - b).amax() < tol, "{a:?} != {b:?}");
}

#[test]
fn spec_vectors_rv_m1() {
    let k = rv_m1();
    let tool = k.standard_tool();
    let zero = k.fk_tcp(&[0.0; 5], &tool);
    assert_eq!(zero.translation, Vector3::new(0.0, 0.0, 889.0));
    assert_eq!(zero.rotation, Matrix3::identity());
    let p = k.fk_tcp(&joints_from_deg([0.0, 0.0, 0.0, 90.0, 0.0]), &tool);
    assert_close(p.translation, Vector3::new(179.0, 0.0, 710.0), 1e-9);
    let p = k.fk_tcp(&joints_from_deg([90.0, 30.0, 60.0, 0.0, 0.0]), &tool);
    assert_close(p.translation, Vector3::new(0.0, 464.0, 516.506), 1e-3);
}

#[test]
fn spec_vectors_rm_501() {
    let k = rm_501();
    let tool = k.standard_tool();
    let zero = k.fk_tcp(&[0.0; 5], &tool);
    assert_close(zero.translation, Vector3::new(0.0, 0.0, 844.6), 1e-9);
    let p = k.fk_tcp(&joints_from_deg([0.0, 0.0, 90.0, 90.0, 0.0]), &tool);
    assert_close(p.translation, Vector3::new(160.0, 0.0, 255.4), 1e-9);
    assert_close(p.approach(), Vector3::new(0.0, 0.0, -1.0), 1e-12);
}

#[test]
fn flange_and_general_tool() {
    let k = rv_m1();
    let q = joints_from_deg([20.0, 30.0, 40.0, -10.0, 33.0]);
    let flange = k.fk_flange(&q);
    let tool = Pose::rot_x(0.3) * Pose::from_translation(10.0, -20.0, 50.0);
    let tcp = k.fk_tcp(&q, &tool);
    assert_eq!(tcp, flange * tool);
    // The standard tool is a shift along the approach.
    let std_tcp = k.fk_tcp(&q, &k.standard_tool());
    assert_close(
        std_tcp.translation,
        flange.translation + flange.approach() * 107.0,
        1e-9,
    );
}

#[test]
fn frame_conversions() {
    let rows = [
        [0.0, -1.0, 0.0, 10.0],
        [1.0, 0.0, 0.0, 20.0],
        [0.0, 0.0, 1.0, 30.0],
    ];
    let p = Pose::from_rows(rows);
    assert_eq!(p.to_rows(), rows);
    let expected =
        Pose::from_translation(10.0, 20.0, 30.0) * Pose::rot_z(std::f64::consts::FRAC_PI_2);
    assert!((p.rotation - expected.rotation).amax() < 1e-15);
    assert_eq!(p.translation, expected.translation);
    assert_eq!(Pose::from_matrix4(&p.to_matrix4()), p);
    let q = p * p.inverse();
    assert!((q.rotation - Matrix3::identity()).amax() < 1e-15);
    assert!(q.translation.amax() < 1e-12);
}

#[test]
fn ik_zero_pose_and_vectors() {
    let k = rv_m1();
    let tool = k.standard_tool();
    for deg in [
        [0.0, 0.0, 0.0, 90.0, 0.0],
        [90.0, 30.0, 60.0, 0.0, 0.0],
        [-45.0, 10.0, 80.0, 45.0, 120.0],
    ] {
        let q = joints_from_deg(deg);
        let goal = k.fk_tcp(&q, &tool);
        let sols = k.ik_all(&goal, &tool, &q).unwrap();
        assert!(
            sols.iter()
                .any(|s| s.joints.iter().zip(&q).all(|(a, b)| (a - b).abs() < 1e-9)),
            "{deg:?}: {sols:?}"
        );
        for s in &sols {
            let back = k.fk_tcp(&s.joints, &tool);
            assert_close(back.translation, goal.translation, 1e-9);
            assert!((back.rotation - goal.rotation).amax() < 1e-12);
        }
    }
}

#[test]
fn ik_zero_pose_on_axis_keeps_j1() {
    // TCP on the waist axis with a vertical approach: J1 and J5 are
    // redundant; the current J1 is kept.
    let k = rv_m1();
    let tool = k.standard_tool();
    let goal = k.fk_tcp(&[0.0; 5], &tool);
    let current = joints_from_deg([37.0, 0.0, 0.0, 0.0, 0.0]);
    let s = k
        .ik_choose(&goal, &tool, &current, Arm::None, Elbow::None)
        .unwrap();
    assert!((s.joints[0] - current[0]).abs() < 1e-12);
    assert!((s.joints[4] + current[0]).abs() < 1e-12, "{:?}", s.joints);
    let back = k.fk_tcp(&s.joints, &tool);
    assert!((back.rotation - goal.rotation).amax() < 1e-12);
    assert_close(back.translation, goal.translation, 1e-9);
}

#[test]
fn ik_on_axis_takes_j1_from_approach() {
    let k = wide();
    let tool = k.standard_tool();
    let tool_len = tool.translation.z;
    assert!(tool_len > 1.0);
    // The *flange* on the waist axis (the TCP is a tool length beside it),
    // approach horizontal towards -y: only the approach can give J1, which
    // is -90 or +90 deg. (A TCP on the axis would leave the flange off it,
    // and J1 would come from the position.)
    let mut goal =
        Pose::rot_z(-std::f64::consts::FRAC_PI_2) * Pose::rot_y(std::f64::consts::FRAC_PI_2);
    goal.translation = Vector3::new(0.0, -tool_len, 500.0);
    let flange = goal * tool.inverse();
    assert!(flange.translation.xy().norm() < 1e-9, "{flange:?}");
    for current in [[0.0; 5], joints_from_deg([40.0, 0.0, 0.0, 0.0, 0.0])] {
        let sols = k.ik_all(&goal, &tool, &current).unwrap();
        assert!(!sols.is_empty());
        for s in &sols {
            let j1 = s.joints[0].to_degrees();
            assert!((j1.abs() - 90.0).abs() < 1e-9, "{j1}");
            let back = k.fk_tcp(&s.joints, &tool);
            assert_close(back.translation, goal.translation, 1e-9);
            assert!((back.rotation - goal.rotation).amax() < 1e-12);
        }
    }
}

/// Every solution of `goal` (flange = goal: identity tool) reaches it.
fn all_reach(k: &Kinematics, goal: &Pose, current: &Joints) -> Vec<Solution> {
    let tool = Pose::identity();
    let sols = k
        .ik_all(goal, &tool, current)
        .unwrap_or_else(|e| panic!("{goal:?}: {e}"));
    assert!(!sols.is_empty());
    for s in &sols {
        let back = k.fk_tcp(&s.joints, &tool);
        assert_close(back.translation, goal.translation, 1e-9);
        assert!(
            (back.rotation - goal.rotation).amax() < 1e-12,
            "{:?} -> {:?}",
            goal.rotation,
            s.joints
        );
    }
    sols
}

#[test]
fn ik_behind_the_waist_axis_with_a_vertical_approach() {
    // Behind the base and close to the x axis, pointing down: J1 comes from
    // the position (about 178 deg or its mirror, -2 deg with the arm
    // leaning back), whatever the current J1.
    let k = wide();
    for (x, y) in [
        (-300.0, 10.0),
        (-300.0, -10.0),
        (-250.0, 0.5),
        (10.0, -300.0),
    ] {
        for current in [[0.0; 5], joints_from_deg([-120.0, 0.0, 0.0, 0.0, 0.0])] {
            let sols = all_reach(&k, &down_at(x, y, 300.0), &current);
            let theta = f64::atan2(y, x);
            for s in &sols {
                let d = (s.joints[0] - theta).rem_euclid(std::f64::consts::PI);
                assert!(!(1e-9..=std::f64::consts::PI - 1e-9).contains(&d), "{s:?}");
            }
        }
    }
}

#[test]
fn ik_on_axis_with_an_approach_along_an_axis_of_the_base() {
    // The flange on the waist axis, the approach exactly along +y, -x or
    // +x (components exactly 0): J1 comes from the approach.
    let k = wide();
    let approaches = [
        (Vector3::y(), Vector3::x()),
        (-Vector3::x(), Vector3::y()),
        (Vector3::x(), Vector3::z()),
    ];
    for (a, n) in approaches {
        let o = a.cross(&n);
        let mut goal = Pose::new(Matrix3::from_columns(&[n, o, a]), Vector3::zeros());
        goal.translation = Vector3::new(0.0, 0.0, 400.0);
        for current in [[0.0; 5], joints_from_deg([40.0, 0.0, 0.0, 0.0, 0.0])] {
            let sols = all_reach(&k, &goal, &current);
            let theta = a.y.atan2(a.x);
            for s in &sols {
                let d = (s.joints[0] - theta).rem_euclid(std::f64::consts::PI);
                assert!(!(1e-9..=std::f64::consts::PI - 1e-9).contains(&d), "{s:?}");
            }
        }
    }
}

#[test]
fn folded_arm_with_equal_links_keeps_the_current_shoulder() {
    // L2 = L3 and the wrist point on the shoulder: the folded arm can point
    // the upper arm anywhere; J2 stays where it is (and J1, the flange
    // being on the waist axis with a vertical approach).
    let text = wide_text().replace("l3 = 160.0", "l3 = 250.0");
    let k = Kinematics::new(RobotDescription::from_toml_str(&text).unwrap());
    let l = *k.description().links();
    assert_eq!(l.l2, l.l3);
    let mut goal = Pose::identity();
    goal.translation = Vector3::new(0.0, 0.0, l.l1 + l.l4);
    for current in [
        joints_from_deg([20.0, 30.0, 0.0, 0.0, 0.0]),
        joints_from_deg([-70.0, -45.0, 0.0, 0.0, 0.0]),
    ] {
        let sols = all_reach(&k, &goal, &current);
        assert!(
            sols.iter().any(|s| (s.joints[0] - current[0]).abs() < 1e-9
                && (s.joints[1] - current[1]).abs() < 1e-9),
            "{sols:?}"
        );
    }
}

#[test]
fn on_axis_and_vertical_include_their_tolerance() {
    // A flange exactly `AXIS` from the waist axis is on it, and an approach
    // whose horizontal part is exactly `VERTICAL` is vertical: J1 stays.
    let k = wide();
    let current = joints_from_deg([30.0, 0.0, 0.0, 0.0, 0.0]);
    let keeps_j1 = |goal: &Pose| {
        let tool = Pose::identity();
        let sols = k.ik_all(goal, &tool, &current).unwrap();
        for s in &sols {
            // Within the tolerance: the flange is taken as on the axis.
            let back = k.fk_tcp(&s.joints, &tool);
            assert_close(back.translation, goal.translation, 2.0 * tolerance::AXIS);
        }
        assert!(
            sols.iter()
                .any(|s| (s.joints[0] - current[0]).abs() < 1e-12),
            "{sols:?}"
        );
    };
    assert_eq!((tolerance::AXIS * tolerance::AXIS).sqrt(), tolerance::AXIS);
    let mut goal = down_at(tolerance::AXIS, 0.0, 100.0);
    keeps_j1(&goal);
    // Approach (VERTICAL, 0, -1): n = o x a with o = y.
    let v = tolerance::VERTICAL;
    assert_eq!((v * v).sqrt(), v);
    let a = Vector3::new(v, 0.0, -1.0);
    let o = Vector3::y();
    goal = Pose::new(
        Matrix3::from_columns(&[o.cross(&a), o, a]),
        Vector3::new(0.0, 0.0, 100.0),
    );
    keeps_j1(&goal);
}

#[test]
fn wrist_on_the_waist_axis_the_turned_waist_is_backward() {
    // Arm straight up: the wrist point is on the waist axis. Of the two
    // waist angles, the one the current J1 (or the approach) gives is the
    // forward arm, the one turned by 180 deg the backward arm; a preference
    // chooses between them.
    let k = wide();
    let tool = k.standard_tool();
    // Also a wrist point a hair (within the axis tolerance) behind the axis.
    for (j1, behind) in [(0.0, 0.0), (50.0, 0.0), (-100.0, 0.0), (30.0, 5e-7)] {
        let current = joints_from_deg([j1, 0.0, 0.0, 0.0, 0.0]);
        let mut goal = k.fk_tcp(&current, &tool);
        let (s1, c1) = current[0].sin_cos();
        goal.translation -= Vector3::new(c1, s1, 0.0) * behind;
        let forward = k
            .ik_choose(&goal, &tool, &current, Arm::Forward, Elbow::None)
            .unwrap();
        assert_eq!(forward.arm, Arm::Forward);
        assert!((forward.joints[0] - current[0]).abs() < 1e-9, "{forward:?}");
        let backward = k
            .ik_choose(&goal, &tool, &current, Arm::Backward, Elbow::None)
            .unwrap();
        assert_eq!(backward.arm, Arm::Backward);
        let turned = (backward.joints[0] - current[0]).abs().to_degrees();
        assert!((turned - 180.0).abs() < 1e-6, "{backward:?}");
    }
}

/// The index of the solution nearest `current` by the documented metric
/// (time of the slowest joint at full speed, then summed squares), computed
/// here independently of the library.
fn nearest_by_metric(k: &Kinematics, sols: &[Solution], current: &Joints) -> usize {
    let key = |q: &Joints| {
        let mut time = 0.0f64;
        let mut sq = 0.0;
        for ((a, b), spec) in q.iter().zip(current).zip(k.description().joints()) {
            time = time.max((a - b).abs() / spec.max_speed);
            sq += (a - b) * (a - b);
        }
        (time, sq)
    };
    (0..sols.len())
        .min_by(|&a, &b| {
            let (ta, sa) = key(&sols[a].joints);
            let (tb, sb) = key(&sols[b].joints);
            ta.total_cmp(&tb).then(sa.total_cmp(&sb))
        })
        .unwrap()
}

/// The index of the solution nearest by summed squares alone.
fn nearest_by_squares(sols: &[Solution], current: &Joints) -> usize {
    let sq = |q: &Joints| {
        q.iter()
            .zip(current)
            .map(|(a, b)| (a - b) * (a - b))
            .sum::<f64>()
    };
    (0..sols.len())
        .min_by(|&a, &b| sq(&sols[a].joints).total_cmp(&sq(&sols[b].joints)))
        .unwrap()
}

/// A seeded search for a current pose (not itself a solution) from which
/// the slowest-joint time and the summed squares pick different solutions
/// among `allowed`: only there does the metric's order show.
fn discriminating_current(
    k: &Kinematics,
    goal: &Pose,
    tool: &Pose,
    base: &Joints,
    allowed: impl Fn(&Solution) -> bool,
) -> Joints {
    let mut state = 7u64;
    let mut next = || {
        state = state
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    for _ in 0..20_000 {
        let mut c = *base;
        for (v, spec) in c.iter_mut().zip(k.description().joints()) {
            *v = (*v + (next() - 0.5) * 4.0).clamp(spec.min, spec.max);
        }
        let sols: Vec<Solution> = k
            .ik_all(goal, tool, &c)
            .unwrap()
            .into_iter()
            .filter(|s| allowed(s))
            .collect();
        if sols.len() > 1 && nearest_by_metric(k, &sols, &c) != nearest_by_squares(&sols, &c) {
            return c;
        }
    }
    panic!("no discriminating current pose found");
}

#[test]
fn all_four_branches() {
    let k = wide();
    let tool = k.standard_tool();
    let q = joints_from_deg([30.0, 20.0, 50.0, 30.0, 10.0]);
    let goal = k.fk_tcp(&q, &tool);
    let sols = k.ik_all(&goal, &tool, &q).unwrap();
    assert_eq!(sols.len(), 4, "{sols:?}");
    let mut configs: Vec<_> = sols.iter().map(|s| (s.arm, s.elbow)).collect();
    configs.sort_by_key(|c| format!("{c:?}"));
    configs.dedup();
    assert_eq!(configs.len(), 4);
    for s in &sols {
        assert_eq!(k.config_of(&s.joints), (s.arm, s.elbow));
        let back = k.fk_tcp(&s.joints, &tool);
        assert_close(back.translation, goal.translation, 1e-9);
        assert!((back.rotation - goal.rotation).amax() < 1e-12);
    }
    // Preferences pick each branch; no preference picks the nearest.
    for arm in [Arm::Forward, Arm::Backward] {
        for elbow in [Elbow::Above, Elbow::Below] {
            let s = k.ik_choose(&goal, &tool, &q, arm, elbow).unwrap();
            assert_eq!((s.arm, s.elbow), (arm, elbow));
        }
    }
    let s = k
        .ik_choose(&goal, &tool, &q, Arm::None, Elbow::None)
        .unwrap();
    assert!(s.joints.iter().zip(&q).all(|(a, b)| (a - b).abs() < 1e-9));
    let s = k
        .ik_choose(&goal, &tool, &q, Arm::Backward, Elbow::None)
        .unwrap();
    assert_eq!(s.arm, Arm::Backward);
    // From a current pose that is no solution, where the slowest-joint time
    // and the summed squares disagree: the time decides, with and without a
    // preference that leaves two branches.
    let c = discriminating_current(&k, &goal, &tool, &q, |_| true);
    let all = k.ik_all(&goal, &tool, &c).unwrap();
    let s = k
        .ik_choose(&goal, &tool, &c, Arm::None, Elbow::None)
        .unwrap();
    assert_eq!(s, all[nearest_by_metric(&k, &all, &c)], "from {c:?}");
    assert_ne!(s, all[nearest_by_squares(&all, &c)]);
    let backward = |s: &Solution| s.arm == Arm::Backward;
    let c = discriminating_current(&k, &goal, &tool, &q, backward);
    let two: Vec<Solution> = k
        .ik_all(&goal, &tool, &c)
        .unwrap()
        .into_iter()
        .filter(backward)
        .collect();
    let s = k
        .ik_choose(&goal, &tool, &c, Arm::Backward, Elbow::None)
        .unwrap();
    assert_eq!(s, two[nearest_by_metric(&k, &two, &c)], "from {c:?}");
}

#[test]
fn preference_falls_back_to_nearest() {
    // RV-M1: J3 >= 0, so ElbowBelow never exists; the nearest is taken.
    let k = rv_m1();
    let tool = k.standard_tool();
    // A pose with both arm branches within the RV-M1's limits
    // (J1 -60 deg backward, 120 deg forward).
    let q = joints_from_deg([-60.0, -25.0, 20.0, -60.0, 0.0]);
    let goal = k.fk_tcp(&q, &tool);
    let s = k
        .ik_choose(&goal, &tool, &q, Arm::Forward, Elbow::Below)
        .unwrap();
    assert_eq!(s.elbow, Elbow::Above);
    assert!(s.joints.iter().zip(&q).all(|(a, b)| (a - b).abs() < 1e-9));
    // The fallback is the nearest of all by the metric, also from a current
    // pose that is no solution and where summed squares would pick another.
    let c = discriminating_current(&k, &goal, &tool, &q, |_| true);
    let all = k.ik_all(&goal, &tool, &c).unwrap();
    assert!(all.iter().all(|s| s.elbow == Elbow::Above));
    let s = k
        .ik_choose(&goal, &tool, &c, Arm::Forward, Elbow::Below)
        .unwrap();
    assert_eq!(s, all[nearest_by_metric(&k, &all, &c)], "from {c:?}");
    assert_ne!(s, all[nearest_by_squares(&all, &c)]);
}

#[test]
fn stretched_arm_has_one_elbow() {
    let k = wide();
    let tool = k.standard_tool();
    let q = joints_from_deg([0.0, 30.0, 0.0, 20.0, 0.0]);
    let goal = k.fk_tcp(&q, &tool);
    let sols = k.ik_all(&goal, &tool, &q).unwrap();
    assert_eq!(sols.len(), 2, "{sols:?}");
    for s in &sols {
        assert!(s.joints[2].abs() < 1e-6);
        assert!(s.joints.iter().all(|v| v.is_finite()));
    }
}

#[test]
fn general_tool_ik() {
    let k = rv_m1();
    let tool = Pose::rot_x(0.4) * Pose::rot_z(0.2) * Pose::from_translation(15.0, -30.0, 80.0);
    let q = joints_from_deg([-30.0, 40.0, 60.0, -20.0, 75.0]);
    let goal = k.fk_tcp(&q, &tool);
    let sols = k.ik_all(&goal, &tool, &q).unwrap();
    assert!(
        sols.iter()
            .any(|s| s.joints.iter().zip(&q).all(|(a, b)| (a - b).abs() < 1e-9))
    );
    for s in &sols {
        let back = k.fk_tcp(&s.joints, &tool);
        assert_close(back.translation, goal.translation, 1e-9);
    }
}

fn err(k: &Kinematics, goal: &Pose) -> KinError {
    k.ik_all(goal, &k.standard_tool(), &[0.0; 5]).unwrap_err()
}

#[test]
fn error_not_finite() {
    let k = rv_m1();
    let mut goal = down_at(300.0, 0.0, 200.0);
    goal.translation.x = f64::NAN;
    let e = err(&k, &goal);
    assert!(matches!(e, KinError::NotFinite { .. }), "{e}");
    assert_eq!(e.exception(), AdaException::FrameInvalid);
    // NaN current joints are refused too.
    let e = k
        .ik_all(
            &down_at(300.0, 0.0, 200.0),
            &k.standard_tool(),
            &[f64::NAN; 5],
        )
        .unwrap_err();
    assert_eq!(e.exception(), AdaException::ConstraintError);
}

#[test]
fn error_not_orthonormal() {
    let k = rv_m1();
    let mut goal = down_at(300.0, 0.0, 200.0);
    goal.rotation *= 1.01;
    let e = err(&k, &goal);
    assert!(matches!(e, KinError::NotOrthonormal { .. }), "{e}");
    assert_eq!(e.exception(), AdaException::FrameInvalid);
    assert!(e.to_string().contains("not a rigid transform"), "{e}");
}

#[test]
fn error_reflection() {
    let k = rv_m1();
    let mut goal = down_at(300.0, 0.0, 200.0);
    goal.rotation.set_column(0, &(-goal.rotation.column(0)));
    let e = err(&k, &goal);
    assert!(matches!(e, KinError::NotRightHanded { .. }), "{e}");
    assert_eq!(e.exception(), AdaException::FrameInvalid);
    assert!(e.to_string().contains("determinant -1.0"), "{e}");
}

#[test]
fn error_orientation_unreachable() {
    let k = rv_m1();
    let tool = k.standard_tool();
    // Reachable with a horizontal approach along +x; asked for along +y,
    // perpendicular to the arm plane y = 0.
    let reachable = k.fk_tcp(
        &[0.0, 0.7, 0.9, std::f64::consts::FRAC_PI_2 - 1.6, 0.0],
        &tool,
    );
    let goal = Pose::new(
        Pose::rot_x(-std::f64::consts::FRAC_PI_2).rotation,
        reachable.translation,
    );
    let e = err(&k, &goal);
    assert!(matches!(e, KinError::OrientationUnreachable { .. }), "{e}");
    assert_eq!(e.exception(), AdaException::FrameInvalid);
    assert!(e.to_string().contains("90.000 deg"), "{e}");
    // Slightly off the plane is FrameInvalid too; within 1e-6 it is accepted.
    let tilt = |a: f64| Pose::new((Pose::rot_z(a) * reachable).rotation, reachable.translation);
    assert!(matches!(
        err(&k, &tilt(1e-4)),
        KinError::OrientationUnreachable { .. }
    ));
    k.classify(&tilt(1e-8), &tool, &[0.0; 5]).unwrap();
}

#[test]
fn error_out_of_reach_beats_orientation() {
    let k = rv_m1();
    let mut goal = Pose::rot_x(-std::f64::consts::FRAC_PI_2);
    goal.translation = Vector3::new(2000.0, 0.0, 300.0);
    let e = err(&k, &goal);
    assert_eq!(e.exception(), AdaException::OutOfReach, "{e}");
}

#[test]
fn error_wrist_too_far() {
    let k = rv_m1();
    let e = err(&k, &down_at(800.0, 0.0, 200.0));
    match &e {
        KinError::WristTooFar {
            distance, reach, ..
        } => {
            assert!(*reach == 410.0 && *distance > 410.0);
        }
        _ => panic!("{e:?}"),
    }
    assert_eq!(e.exception(), AdaException::OutOfReach);
    assert!(
        e.to_string().contains("goal (800.0, 0.0, 200.0) mm out of reach: wrist point") && e.to_string().contains("mm from shoulder, reach 410.0 mm; nearest within the arm's length with this orientation ("),
        "{e}"
    );
}

#[test]
fn error_wrist_too_close() {
    let k = rv_m1();
    // Pointing down, wrist point 30 mm out and 30 mm above the shoulder.
    let e = err(&k, &down_at(30.0, 0.0, 300.0 + 30.0 - 179.0));
    assert!(matches!(e, KinError::WristTooClose { .. }), "{e}");
    assert_eq!(e.exception(), AdaException::OutOfReach);
    assert!(e.to_string().contains("42.4 mm"), "{e}");
}

#[test]
fn error_every_branch_beyond_limits() {
    let k = rv_m1();
    let tool = k.standard_tool();
    // Leaning back 60 deg: J2 below -30 deg; the mirrored branches need
    // J1 = 180 deg or J3 < 0.
    let goal = k.fk_tcp(&joints_from_deg([0.0, -60.0, 30.0, 0.0, 0.0]), &tool);
    let e = err(&k, &goal);
    match &e {
        KinError::NoBranchWithinLimits { branches } => assert_eq!(branches.len(), 4),
        _ => panic!("{e:?}"),
    }
    assert_eq!(e.exception(), AdaException::OutOfReach);
    let msg = e.to_string();
    assert!(
        msg.contains("joint 2 target -60.0 deg outside -30.0 .. 100.0 deg"),
        "{msg}"
    );
    assert!(k.classify(&goal, &tool, &[0.0; 5]).is_err());
    assert!(
        k.classify(&down_at(300.0, 0.0, 200.0), &tool, &[0.0; 5])
            .is_ok()
    );
}

#[test]
fn config_of_labels() {
    let k = rv_m1();
    assert_eq!(
        k.config_of(&joints_from_deg([0.0, 30.0, 40.0, 0.0, 0.0])),
        (Arm::Forward, Elbow::Above)
    );
    assert_eq!(
        k.config_of(&joints_from_deg([0.0, -30.0, 10.0, 0.0, 0.0])),
        (Arm::Backward, Elbow::Above)
    );
    assert_eq!(
        k.config_of(&joints_from_deg([0.0, 30.0, -40.0, 0.0, 0.0])),
        (Arm::Forward, Elbow::Below)
    );
}

#[test]
fn joint_target_two_pi_rule() {
    let k = rv_m1();
    let deg = |d: f64| d.to_radians();
    // Multiples of 2 pi are removed, the sign kept.
    let t = k
        .joint_target(&[7.0, 0.0, 0.0, 0.0, deg(720.0 + 30.0)])
        .unwrap();
    assert!((t[0] - (7.0 - std::f64::consts::TAU)).abs() < 1e-12);
    assert!((t[4] - deg(30.0)).abs() < 1e-12);
    // The other way round when the signed way breaks a limit.
    let t = k
        .joint_target(&[0.0, 0.0, 0.0, deg(-270.0), deg(350.0)])
        .unwrap();
    assert!((t[3] - deg(90.0)).abs() < 1e-12);
    assert!((t[4] - deg(-10.0)).abs() < 1e-12);
    // Neither way.
    let e = k
        .joint_target(&[deg(-200.0), 0.0, 0.0, 0.0, 0.0])
        .unwrap_err();
    assert_eq!(e.exception(), AdaException::OutOfReach);
    assert_eq!(
        e.to_string(),
        "joint 1 target -200.0 deg outside -150.0 .. 150.0 deg by 50.0 deg (the other way round, 160.0 deg, by 10.0 deg)"
    );
    let e = k
        .joint_target(&[0.0, deg(142.0), 0.0, 0.0, 0.0])
        .unwrap_err();
    assert!(
        e.to_string()
            .starts_with("joint 2 target 142.0 deg outside -30.0 .. 100.0 deg by 42.0 deg"),
        "{e}"
    );
    // Values a hair beyond a limit are clamped onto it.
    let t = k
        .joint_target(&[deg(150.0) + 1e-12, 0.0, 0.0, 0.0, 0.0])
        .unwrap();
    assert_eq!(t[0], deg(150.0));
    // Relative: current + delta.
    let t = k
        .relative_joint_target(
            &[0.0, deg(90.0), 0.0, 0.0, 0.0],
            &[0.0, deg(20.0), 0.0, 0.0, 0.0],
        )
        .unwrap_err();
    assert_eq!(t.exception(), AdaException::OutOfReach);
    let e = k.joint_target(&[f64::NAN, 0.0, 0.0, 0.0, 0.0]).unwrap_err();
    assert_eq!(e.exception(), AdaException::ConstraintError);
}

#[test]
fn no_panic_on_garbage() {
    let k = rv_m1();
    let tool = k.standard_tool();
    let values = [
        0.0,
        -0.0,
        1.0,
        -1.0,
        1e300,
        -1e300,
        f64::INFINITY,
        f64::NAN,
        1e-300,
    ];
    for (i, v) in values.iter().enumerate() {
        let mut goal = Pose::identity();
        goal.translation = Vector3::new(*v, values[(i + 3) % values.len()], *v);
        let _ = k.ik_all(&goal, &tool, &[0.0; 5]);
        goal.rotation = Matrix3::from_element(*v);
        let _ = k.ik_all(&goal, &tool, &[*v; 5]);
        let _ = k.valid_frame(&goal, &tool);
        let _ = k.joint_target(&[*v; 5]);
        let _ = k.straight_line(&[0.0; 5], &goal, &tool, *v);
        let _ = k.fk_tcp(&[*v; 5], &goal);
    }
}

#[test]
fn two_pi_representation_nearest_current() {
    // A wrist roll with more than two turns of range (-500 .. 500 deg): the
    // goal's J5 has three representations (100, -260, 460 deg), so the
    // nearest one is found by rounding, not by the limits cutting all but
    // one or two.
    let text = RobotDescription::builtin_text("rv-m1")
        .unwrap()
        .replace("min_deg = -180.0", "min_deg = -500.0")
        .replace("max_deg = 180.0", "max_deg = 500.0");
    let k = Kinematics::new(RobotDescription::from_toml_str(&text).unwrap());
    let tool = k.standard_tool();
    let q = joints_from_deg([10.0, 20.0, 50.0, 30.0, 100.0]);
    let goal = k.fk_tcp(&q, &tool);
    for (current_j5, expected_j5) in [
        (200.0, 100.0),
        (300.0, 460.0),
        (390.0, 460.0),
        (-100.0, -260.0),
        (-75.0, 100.0),
        (-390.0, -260.0),
        (0.0, 100.0),
    ] {
        let current = joints_from_deg([10.0, 20.0, 50.0, 30.0, current_j5]);
        let s = k
            .ik_choose(&goal, &tool, &current, Arm::None, Elbow::None)
            .unwrap();
        assert!(
            (s.joints[4] - f64::to_radians(expected_j5)).abs() < 1e-9,
            "from J5 = {current_j5} deg: {:?}",
            s.joints
        );
    }
}

/// Too far and too close: the message names the goal (TCP, not flange) and
/// the nearest point with the same orientation, which is within the arm's
/// length.
#[test]
fn out_of_reach_names_goal_and_a_reachable_nearest_point() {
    let k = rv_m1();
    let l = *k.description().links();
    let tool = k.standard_tool();
    // Tool up, the flange a wrist length above the shoulder: the wrist
    // point is on the shoulder, where it has no direction to move in.
    let mut up = Pose::identity();
    up.translation = Vector3::new(0.0, 0.0, l.l1 + l.l4 + tool.translation.z);
    for goal in [
        down_at(800.0, 100.0, 200.0),
        down_at(-300.0, -500.0, 600.0),
        down_at(30.0, 0.0, 300.0 + 30.0 - 179.0),
        down_at(20.0, 25.0, 300.0 + 30.0 - 179.0),
        up,
    ] {
        let e = err(&k, &goal);
        let (g, nearest, distance, to) = match &e {
            KinError::WristTooFar {
                goal,
                nearest,
                distance,
                reach,
            } => (*goal, *nearest, *distance, reach - 0.05),
            KinError::WristTooClose {
                goal,
                nearest,
                distance,
                min_reach,
            } => (*goal, *nearest, *distance, min_reach + 0.05),
            _ => panic!("{e:?}"),
        };
        assert!((g - goal.translation).norm() < 1e-9, "{e}");
        if distance == 0.0 {
            // On the shoulder: up, away from the base.
            assert!(nearest.z > g.z, "{e}");
        }
        // The nearest point is the goal moved straight towards (or away
        // from) the shoulder until the wrist point is inside the reach.
        assert!(
            ((nearest - g).norm() - (distance - to).abs()).abs() < 1e-9,
            "{e}: moved {} mm",
            (nearest - g).norm()
        );
        let mut near = goal;
        near.translation = nearest;
        if let Err(e2) = k.ik_all(&near, &k.standard_tool(), &[0.0; 5]) {
            assert!(
                !matches!(
                    e2,
                    KinError::WristTooFar { .. } | KinError::WristTooClose { .. }
                ),
                "nearest point of `{e}` out of the arm's length: {e2}"
            );
        }
        let msg = e.to_string();
        assert!(
            msg.starts_with(&format!("goal ({:.1}, {:.1}, {:.1}) mm", g.x, g.y, g.z)),
            "{msg}"
        );
        assert!(
            msg.contains(&format!(
                "nearest within the arm's length with this orientation ({:.1}, ",
                nearest.x
            )),
            "{msg}"
        );
    }
}

/// The handbook demo's F1 (tool up on the waist axis) on the RM-501: every
/// branch is refused and the message names all four, forward and backward.
#[test]
fn rm501_names_each_refused_branch() {
    let k = rm_501();
    let mut goal = Pose::rot_z(0.0);
    goal.translation = Vector3::new(0.0, 0.0, 830.6);
    let msg = err(&k, &goal).to_string();
    for b in [
        "arm forward/elbow above",
        "arm forward/elbow below",
        "arm backward/elbow above",
        "arm backward/elbow below",
    ] {
        assert!(msg.contains(b), "{b} missing: {msg}");
    }
}
