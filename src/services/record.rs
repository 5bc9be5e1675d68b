//! `--record`: the support points of every motion with the virtual time,
//! written as CSV or JSON when the run ends (tools.md).

use super::RobotState;
use crate::kinematics::Joints;

/// One recorded support point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Virtual time, s.
    pub t: f64,
    /// Joint angles, rad.
    pub joints: Joints,
    /// TCP position in base coordinates, mm.
    pub tcp: [f64; 3],
    /// Gripper opening, mm.
    pub grip: f64,
}

/// Seconds between the samples of a joint motion.
const STEP: f64 = 0.02;

fn sample(st: &RobotState, t: f64, q: Joints) -> Sample {
    let p = st.kin.fk_tcp(&q, &st.tool.trans).translation;
    Sample {
        t,
        joints: q,
        tcp: [p.x, p.y, p.z],
        grip: st.robot.gripper().opening,
    }
}

/// Records a motion from `before` through `points` that starts at `start`
/// and takes `duration`: sampled every 20 ms plus both ends, and at every
/// support point.
pub(super) fn motion(
    st: &mut RobotState,
    start: f64,
    before: &Joints,
    points: &[Joints],
    duration: f64,
) {
    if st.record.is_none() {
        return;
    }
    let n = points.len().max(1);
    let mut fracs: Vec<f64> = (0..=n).map(|i| i as f64 / n as f64).collect();
    if duration > 0.0 {
        let steps = (duration / STEP).floor() as usize;
        fracs.extend((1..=steps).map(|k| (k as f64 * STEP / duration).min(1.0)));
    }
    fracs.sort_by(f64::total_cmp);
    fracs.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    let new: Vec<Sample> = fracs
        .iter()
        .map(|&f| {
            sample(
                st,
                start + f * duration,
                super::interpolate(before, points, f),
            )
        })
        .collect();
    if let Some(r) = &mut st.record {
        r.extend(new);
    }
}

/// Records the robot's pose now (e.g. after a gripper motion).
pub(super) fn point(st: &mut RobotState, t: f64) {
    if st.record.is_none() {
        return;
    }
    let s = sample(st, t, st.robot.joints());
    if let Some(r) = &mut st.record {
        r.push(s);
    }
}

const KEYS: [&str; 10] = ["t", "j1", "j2", "j3", "j4", "j5", "x", "y", "z", "grip"];

fn values(s: &Sample) -> [f64; 10] {
    let d = |i: usize| s.joints[i].to_degrees() + 0.0;
    [
        s.t,
        d(0),
        d(1),
        d(2),
        d(3),
        d(4),
        s.tcp[0] + 0.0,
        s.tcp[1] + 0.0,
        s.tcp[2] + 0.0,
        s.grip,
    ]
}

/// The samples as CSV with a header row.
pub fn to_csv(samples: &[Sample]) -> String {
    let mut out = KEYS.join(",");
    out.push('\n');
    for s in samples {
        let v: Vec<String> = values(s).iter().map(|x| format!("{x:.4}")).collect();
        out.push_str(&v.join(","));
        out.push('\n');
    }
    out
}

/// The samples as a JSON array of objects.
pub fn to_json(samples: &[Sample]) -> String {
    let rows: Vec<String> = samples
        .iter()
        .map(|s| {
            let fields: Vec<String> = KEYS
                .iter()
                .zip(values(s))
                .map(|(k, x)| format!("\"{k}\": {x:.4}"))
                .collect();
            format!("  {{{}}}", fields.join(", "))
        })
        .collect();
    format!("[\n{}\n]\n", rows.join(",\n"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_and_json_have_the_keys_in_order() {
        let s = Sample {
            t: 0.5,
            joints: [0.0, std::f64::consts::FRAC_PI_2, 0.0, 0.0, 0.0],
            tcp: [1.0, 2.0, 3.0],
            grip: 40.0,
        };
        let c = to_csv(&[s]);
        assert_eq!(
            c,
            "t,j1,j2,j3,j4,j5,x,y,z,grip\n0.5000,0.0000,90.0000,0.0000,0.0000,0.0000,1.0000,2.0000,3.0000,40.0000\n"
        );
        let j = to_json(&[s]);
        assert!(j.contains("\"j2\": 90.0000"), "{j}");
        assert!(j.starts_with("[\n  {\"t\": 0.5000,"), "{j}");
    }

    #[test]
    fn a_negative_zero_is_written_as_zero() {
        // -0.0 from a computation is written 0.0000, never -0.0000.
        let s = Sample {
            t: 0.0,
            joints: [-0.0; 5],
            tcp: [-0.0, -0.0, -0.0],
            grip: 0.0,
        };
        let c = to_csv(&[s]);
        assert!(!c.contains('-'), "{c}");
        assert!(!to_json(&[s]).contains('-'));
    }
}
