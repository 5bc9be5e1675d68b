//! ValidFrame: nearest reachable orientation, degenerate cases.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

use crate::kinematics::{AdaException, KinError, Pose};
use nalgebra::{Matrix3, UnitQuaternion, Vector3};

use super::{Rng, angle, rv_m1};

impl Rng {
    fn rotation(&mut self) -> Matrix3<f64> {
        let axis = Vector3::new(self.next() - 0.5, self.next() - 0.5, self.next() - 0.5);
        UnitQuaternion::from_scaled_axis(axis.normalize() * (self.next() * PI))
            .to_rotation_matrix()
            .into_inner()
    }
}

fn plane_angle(pose: &Pose) -> f64 {
    let p = pose.translation;
    let m = Vector3::new(-p.y, p.x, 0.0).normalize();
    pose.approach().dot(&m).abs().asin()
}

#[test]
fn reachable_frame_unchanged() {
    let k = rv_m1();
    let tool = k.standard_tool();
    let goal = k.fk_tcp(&[0.3, 0.5, 0.9, -0.2, 1.0], &tool);
    let v = k.valid_frame(&goal, &tool).unwrap();
    assert!((v.rotation - goal.rotation).amax() < 1e-15);
    assert_eq!(v.translation, goal.translation);
}

#[test]
fn minimal_and_reachable() {
    let k = rv_m1();
    let tool = k.standard_tool();
    let mut rng = Rng(7);
    for _ in 0..500 {
        // Positions well inside the workspace.
        let angle = (rng.next() - 0.5) * 2.4;
        let r = 200.0 + 150.0 * rng.next();
        let z = 250.0 + 250.0 * rng.next();
        let goal = Pose::new(
            rng.rotation(),
            Vector3::new(r * angle.cos(), r * angle.sin(), z),
        );
        let v = k.valid_frame(&goal, &tool).unwrap();
        assert_eq!(v.translation, goal.translation);
        assert!(plane_angle(&v) < 1e-12);
        v.check_rigid("valid frame").unwrap();
        // The turn is exactly the approach's angle to the plane.
        let turned = goal.rotation_angle_to(&v);
        assert!(
            (turned - plane_angle(&goal)).abs() < 1e-9,
            "{turned} vs {}",
            plane_angle(&goal)
        );
        // The result is no longer FrameInvalid.
        if let Err(e) = k.classify(&v, &tool, &[0.0; 5]) {
            assert_ne!(e.exception(), AdaException::FrameInvalid, "{e}");
        }
        // No reachable orientation found by random search is closer.
        let theta = goal.translation.y.atan2(goal.translation.x);
        for _ in 0..200 {
            let flip = if rng.next() < 0.5 { 0.0 } else { PI };
            let candidate = Pose::rot_z(theta + flip)
                * Pose::rot_y((rng.next() - 0.5) * 2.0 * PI)
                * Pose::rot_z((rng.next() - 0.5) * 2.0 * PI);
            let other = Pose::new(candidate.rotation, goal.translation);
            assert!(plane_angle(&other) < 1e-12);
            assert!(goal.rotation_angle_to(&other) >= turned - 1e-12);
        }
        // Nor are small perturbations of the answer that stay reachable.
        for _ in 0..50 {
            let d =
                Pose::rot_z(theta) * Pose::rot_y((rng.next() - 0.5) * 1e-3) * Pose::rot_z(-theta);
            let other = Pose::new(d.rotation * v.rotation, goal.translation);
            if plane_angle(&other) < 1e-12 {
                assert!(goal.rotation_angle_to(&other) >= turned - 1e-12);
            }
        }
    }
}

#[test]
fn on_waist_axis_unchanged() {
    let k = rv_m1();
    let tool = k.standard_tool();
    // J2 = -20, J3 = 60 deg and the pitch chosen so that the TCP is on the
    // waist axis; then the frame turned about z (still on the axis).
    let (j2, j3) = ((-20.0f64).to_radians(), 60.0f64.to_radians());
    let r = 250.0 * j2.sin() + 160.0 * (j2 + j3).sin();
    let psi = (-r / 179.0).asin();
    let q = [0.0, j2, j3, psi - j2 - j3, 0.0];
    let mut goal = Pose::rot_z(1.0) * k.fk_tcp(&q, &tool);
    assert!(goal.translation.xy().norm() < 1e-9);
    goal.translation.x = 0.0;
    goal.translation.y = 0.0;
    let v = k.valid_frame(&goal, &tool).unwrap();
    assert!((v.rotation - goal.rotation).amax() < 1e-15);
    // And it is reachable: J1 turns to the approach's plane.
    let s = k.ik_all(&v, &tool, &[0.0; 5]).unwrap();
    assert!(s.iter().any(|s| (s.joints[0] - 1.0).abs() < 1e-9), "{s:?}");
}

#[test]
fn perpendicular_approach_points_outward() {
    let k = rv_m1();
    let tool = k.standard_tool();
    // A reachable pose with a horizontal approach along +x ...
    let reachable = k.fk_tcp(&[0.0, 0.7, 0.9, FRAC_PI_2 - 1.6, 0.0], &tool);
    assert!((reachable.approach() - Vector3::x()).amax() < 1e-12);
    // ... asked for with the approach along +y, perpendicular to the plane;
    // then the whole scene turned about the waist axis, so that the TCP is
    // off the x axis (y != 0) and x and y play different parts.
    let at_x = Pose::new(Pose::rot_x(-FRAC_PI_2).rotation, reachable.translation);
    for turn in [0.0, 0.7, 2.0, -2.5, -0.3] {
        let goal = Pose::rot_z(turn) * at_x;
        let (s, c) = f64::sin_cos(turn);
        assert!((goal.approach() - Vector3::new(-s, c, 0.0)).amax() < 1e-15);
        let v = k.valid_frame(&goal, &tool).unwrap();
        // Horizontal, pointing away from the waist axis.
        assert!(
            (v.approach() - Vector3::new(c, s, 0.0)).amax() < 1e-15,
            "turn {turn}: {:?}",
            v.approach()
        );
        assert_eq!(v.translation, goal.translation);
        assert!((goal.rotation_angle_to(&v) - FRAC_PI_2).abs() < 1e-12);
        let current = [turn, 0.0, 0.0, 0.0, 0.0];
        if turn.abs() < 150f64.to_radians() {
            k.classify(&v, &tool, &current).unwrap();
        }
        let e = k.classify(&goal, &tool, &current).unwrap_err();
        assert_eq!(e.exception(), AdaException::FrameInvalid);
        assert!(e.to_string().contains("90.000 deg"), "{e}");
    }
}

/// The flange axis's angle to the vertical plane through the waist axis and
/// the flange: 0 for an orientation the arm can take.
fn flange_off_plane(pose: &Pose, tool: &Pose) -> f64 {
    let flange = *pose * tool.inverse();
    let p = flange.translation;
    let m = Vector3::new(-p.y, p.x, 0.0).normalize();
    flange.approach().dot(&m).abs().asin()
}

#[test]
fn off_axis_tool_converges() {
    let k = rv_m1();
    let tool = Pose::rot_x(0.3) * Pose::from_translation(25.0, -10.0, 90.0);
    let mut rng = Rng(11);
    for _ in 0..100 {
        let angle = (rng.next() - 0.5) * 2.0;
        let goal = Pose::new(
            rng.rotation(),
            Vector3::new(300.0 * angle.cos(), 300.0 * angle.sin(), 350.0),
        );
        let v = k.valid_frame(&goal, &tool).unwrap();
        // Position kept.
        assert_eq!(v.translation, goal.translation);
        // Reachable orientation: the flange axis lies in the arm plane.
        assert!(flange_off_plane(&v, &tool) < 1e-9, "{v:?}");
        // Nearest (locally): every reachable orientation made from a small
        // turn of the result is no closer to the goal.
        let best = goal.rotation_angle_to(&v);
        for _ in 0..20 {
            let nudge = Pose::new(
                UnitQuaternion::from_scaled_axis(
                    Vector3::new(rng.next() - 0.5, rng.next() - 0.5, rng.next() - 0.5) * 0.1,
                )
                .to_rotation_matrix()
                .into_inner(),
                Vector3::zeros(),
            );
            let mut turned = nudge * v;
            turned.translation = v.translation;
            let w = k.valid_frame(&turned, &tool).unwrap();
            assert!(flange_off_plane(&w, &tool) < 1e-9);
            assert!(
                goal.rotation_angle_to(&w) >= best - 1e-9,
                "{} < {best}",
                goal.rotation_angle_to(&w)
            );
        }
    }
    // An orientation the arm already takes comes back unchanged.
    for _ in 0..100 {
        let q: Vec<f64> = k
            .description()
            .joints()
            .iter()
            .map(|s| s.min + (s.max - s.min) * rng.next())
            .collect();
        let reachable = k.fk_tcp(&[q[0], q[1], q[2], q[3], q[4]], &tool);
        let v = k.valid_frame(&reachable, &tool).unwrap();
        assert_eq!(v.translation, reachable.translation);
        assert!(
            (v.rotation - reachable.rotation).amax() < 1e-9,
            "{q:?}: turned by {}",
            reachable.rotation_angle_to(&v)
        );
    }
}

#[test]
fn invalid_input() {
    let k = rv_m1();
    let tool = k.standard_tool();
    let bad = Pose::new(Matrix3::from_element(0.5), Vector3::new(1.0, 2.0, 3.0));
    let e = k.valid_frame(&bad, &tool).unwrap_err();
    assert!(matches!(e, KinError::NotOrthonormal { .. }));
    assert_eq!(e.exception(), AdaException::FrameInvalid);
}

/// The flange orientations the arm can take with its TCP at `p` and a tool
/// offset `t`, written independently of the library: the flange turned by
/// Rz(theta) Ry(psi) Rz(phi) has its axis in the vertical plane at azimuth
/// theta; theta (two roots) puts the flange, at p - R t, in that plane.
fn reachable_flanges(p: &Vector3<f64>, t: &Vector3<f64>, psi: f64, phi: f64) -> Vec<Matrix3<f64>> {
    let inner = (Pose::rot_y(psi) * Pose::rot_z(phi)).rotation;
    let s = (inner * t).y / p.xy().norm();
    if s.abs() > 1.0 {
        return Vec::new();
    }
    let (alpha, d) = (p.y.atan2(p.x), s.asin());
    [alpha - d, alpha + PI + d]
        .iter()
        .map(|theta| Pose::rot_z(*theta).rotation * inner)
        .collect()
}

/// The least angle from `goal` to an orientation the arm can take with
/// `tool`: a grid over (psi, phi) in 2 degree steps, then a pattern search
/// in those two parameters from the best grid point down to 1e-11 rad.
fn brute_force_nearest(goal: &Pose, tool: &Pose) -> f64 {
    let p = goal.translation;
    let t = tool.translation;
    let eval = |psi: f64, phi: f64| {
        reachable_flanges(&p, &t, psi, phi)
            .iter()
            .map(|f| angle(&goal.rotation, &(f * tool.rotation)))
            .fold(f64::INFINITY, f64::min)
    };
    let n = 180;
    let mut best = (f64::INFINITY, 0.0, 0.0);
    for i in 0..n {
        for j in 0..n {
            let psi = -PI + TAU * i as f64 / n as f64;
            let phi = -PI + TAU * j as f64 / n as f64;
            let a = eval(psi, phi);
            if a < best.0 {
                best = (a, psi, phi);
            }
        }
    }
    let mut step = TAU / n as f64;
    while step > 1e-11 {
        let mut improved = false;
        for (dp, df) in [
            (1.0, 0.0),
            (-1.0, 0.0),
            (0.0, 1.0),
            (0.0, -1.0),
            (1.0, 1.0),
            (-1.0, -1.0),
            (1.0, -1.0),
            (-1.0, 1.0),
        ] {
            let (psi, phi) = (best.1 + dp * step, best.2 + df * step);
            let a = eval(psi, phi);
            if a < best.0 {
                best = (a, psi, phi);
                improved = true;
            }
        }
        if !improved {
            step *= 0.5;
        }
    }
    best.0
}

/// ZYZ angles (theta, psi, phi) of a flange orientation, as in
/// `reachable_flanges` (psi in 0 ..= pi).
fn zyz(r: &Matrix3<f64>) -> (f64, f64, f64) {
    let psi = r[(0, 2)].hypot(r[(1, 2)]).atan2(r[(2, 2)]);
    (r[(1, 2)].atan2(r[(0, 2)]), psi, r[(2, 1)].atan2(-r[(2, 0)]))
}

/// ValidFrame with a tool whose TCP is off the flange axis searches for the
/// nearest reachable orientation (valid.rs, a pattern search over turns
/// about +-x, +-y, +-z from the settled projection). Checked against an
/// independent parametrisation of the reachable orientations: never nearer
/// than the brute-force minimum, equal to it (to 1e-10 rad) in all but a
/// few cases, and in those few (the search is local, as documented) a local
/// minimum in the independent parameters. A search that cannot turn one
/// way (a lost minus sign on -x or -y) stops short of the minimum by 1e-8
/// to 1e-3 rad in several of these cases.
#[test]
fn off_axis_tool_matches_brute_force() {
    let k = rv_m1();
    let tools = [
        Pose::rot_x(0.3) * Pose::from_translation(25.0, -10.0, 90.0),
        Pose::from_translation(40.0, 0.0, 60.0),
        Pose::rot_y(-0.5) * Pose::from_translation(0.0, 30.0, 80.0),
    ];
    let mut rng = Rng(23);
    let mut local_only = Vec::new();
    for case in 0..60 {
        let tool = tools[case % tools.len()];
        let azimuth = (rng.next() - 0.5) * 2.0 * PI;
        let r = 200.0 + 150.0 * rng.next();
        let goal = Pose::new(
            rng.rotation(),
            Vector3::new(
                r * azimuth.cos(),
                r * azimuth.sin(),
                250.0 + 200.0 * rng.next(),
            ),
        );
        let v = k.valid_frame(&goal, &tool).unwrap();
        assert_eq!(v.translation, goal.translation);
        assert!(flange_off_plane(&v, &tool) < 1e-9, "case {case}");
        let got = angle(&goal.rotation, &v.rotation);
        let nearest = brute_force_nearest(&goal, &tool);
        assert!(got >= nearest - 1e-12, "case {case}: {got} below {nearest}");
        if got <= nearest + 1e-10 {
            continue;
        }
        local_only.push(case);
        // A local minimum: no neighbour in (psi, phi) is nearer.
        let (_, psi, phi) = zyz(&(v.rotation * tool.rotation.transpose()));
        let h = 1e-4;
        for (dp, df) in [
            (h, 0.0),
            (-h, 0.0),
            (0.0, h),
            (0.0, -h),
            (h, h),
            (-h, -h),
            (h, -h),
            (-h, h),
        ] {
            for f in reachable_flanges(&goal.translation, &tool.translation, psi + dp, phi + df) {
                let a = angle(&goal.rotation, &(f * tool.rotation));
                assert!(
                    a >= got - 1e-12,
                    "case {case}: {a} nearer than {got} (global {nearest})"
                );
            }
        }
    }
    assert!(
        local_only.len() <= 2,
        "only locally nearest: {local_only:?}"
    );
}

/// The search is capped at 2000 rounds (a bound on the work of one
/// ValidFrame). Found in `off_axis_tool_converges`: for this goal the
/// search zigzags down a narrow valley and reaches the cap with its step
/// still at 3e-3 rad, 1.7e-6 rad short of the nearest orientation (which an
/// uncapped search reaches after about 4750 rounds). If the search is made
/// to converge faster, lower the first bound.
#[test]
fn off_axis_search_stops_after_2000_rounds() {
    let k = rv_m1();
    let tool = Pose::rot_x(0.3) * Pose::from_translation(25.0, -10.0, 90.0);
    let goal = Pose::new(
        Matrix3::new(
            -0.23140395565059607,
            0.15265803683386264,
            0.9608057728278323,
            0.8397194820325828,
            0.5300388074528779,
            0.11802565013107119,
            -0.49124678197845517,
            0.8341189282014658,
            -0.25084300431116263,
        ),
        Vector3::new(298.7126902456351, -27.76200076030652, 350.0),
    );
    let v = k.valid_frame(&goal, &tool).unwrap();
    assert!(flange_off_plane(&v, &tool) < 1e-9);
    let short = angle(&goal.rotation, &v.rotation) - brute_force_nearest(&goal, &tool);
    assert!(short > 1e-6 && short < 1e-5, "{short:e}");
}
