//! FK -> IK -> FK round trips over random joint vectors inside the limits.

use crate::kinematics::{Joints, Kinematics, Pose, RobotDescription};
use proptest::prelude::*;

use super::Rng;

impl Rng {
    fn joints(&mut self, k: &Kinematics) -> Joints {
        let mut q = [0.0; 5];
        for (v, spec) in q.iter_mut().zip(k.description().joints()) {
            *v = spec.min + (spec.max - spec.min) * self.next();
        }
        q
    }
}

/// Checks one joint vector; returns whether the original joints were among
/// the solutions (they may not be within 1e-7 rad right at a singularity).
fn check(k: &Kinematics, q: &Joints, tool: &Pose) -> bool {
    let goal = k.fk_tcp(q, tool);
    let sols = match k.ik_all(&goal, tool, q) {
        Ok(s) => s,
        Err(e) => panic!("{q:?}: {e}"),
    };
    for s in &sols {
        let back = k.fk_tcp(&s.joints, tool);
        let dp = (back.translation - goal.translation).amax();
        let dr = (back.rotation - goal.rotation).amax();
        assert!(dp < 1e-9, "{q:?} -> {:?}: position error {dp}", s.joints);
        // Rounding in the trigonometric chain reaches ~2e-12 for some
        // random poses (seen in CI); 1e-10 is still far below anything a
        // joint encoder resolves.
        assert!(
            dr < 1e-10,
            "{q:?} -> {:?}: orientation error {dr}",
            s.joints
        );
        assert_eq!(k.config_of(&s.joints), (s.arm, s.elbow));
        assert!(k.description().check_limits(&s.joints).is_ok());
    }
    sols.iter()
        .any(|s| s.joints.iter().zip(q).all(|(a, b)| (a - b).abs() < 1e-7))
}

fn round_trips(name: &str, seed: u64) {
    let k = Kinematics::new(RobotDescription::builtin(name).unwrap());
    let tool = k.standard_tool();
    let mut rng = Rng(seed);
    let mut missed = 0;
    for _ in 0..100_000 {
        let q = rng.joints(&k);
        if !check(&k, &q, &tool) {
            missed += 1;
        }
    }
    assert_eq!(missed, 0, "{name}: original joints not recovered");
}

#[test]
fn round_trip_rv_m1_100k() {
    round_trips("rv-m1", 1);
}

#[test]
fn round_trip_rm_501_100k() {
    round_trips("rm-501", 2);
}

#[test]
fn round_trip_general_tools() {
    let k = Kinematics::new(RobotDescription::builtin("rv-m1").unwrap());
    let mut rng = Rng(3);
    let mut missed = Vec::new();
    for _ in 0..20_000 {
        let tool = Pose::rot_z(rng.next() * 6.0)
            * Pose::rot_x(rng.next() - 0.5)
            * Pose::from_translation(
                40.0 * rng.next() - 20.0,
                40.0 * rng.next() - 20.0,
                150.0 * rng.next(),
            );
        let q = rng.joints(&k);
        if !check(&k, &q, &tool) {
            missed.push(q);
        }
    }
    assert!(
        missed.is_empty(),
        "original joints not recovered: {missed:?}"
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn round_trip_proptest(a in 0.0..1.0f64, b in 0.0..1.0f64, c in 0.0..1.0f64, d in 0.0..1.0f64, e in 0.0..1.0f64, robot in 0..2usize) {
        let k = Kinematics::new(RobotDescription::builtin(["rv-m1", "rm-501"][robot]).unwrap());
        let mut q = [a, b, c, d, e];
        for (v, spec) in q.iter_mut().zip(k.description().joints()) {
            *v = spec.min + (spec.max - spec.min) * *v;
        }
        prop_assert!(check(&k, &q, &k.standard_tool()));
    }
}
