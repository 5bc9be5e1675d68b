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

/// Who sees each motion when it starts, before it is paced or driven: the
/// live 3D view (`--view`). It gets the same samples the recording keeps.
pub trait Watch {
    /// The samples of a motion that starts now, or a gripper's new pose.
    fn samples(&mut self, samples: &[Sample]);
    /// The motion announced last ended early (Ctrl-C) with the pose `s`.
    fn cut(&mut self, s: &Sample);
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

/// The most samples one motion adds, its ends included. A motion longer
/// than `MAX_PER_MOTION / 2` steps of 20 ms (20 s) is sampled at even
/// intervals of its duration instead (`Time => Duration'Last` was sampled
/// every 20 ms: hundreds of billions of samples); more support points than
/// half of it are thinned evenly, the first and the last kept.
pub const MAX_PER_MOTION: usize = 2_000;

/// The share of `--max-memory` a recording may take (an eighth): past it,
/// and whenever the program has used the memory up to its limit, the
/// recording keeps every other sample ([`thin`]), so it neither takes the
/// program's memory nor ends the run.
fn budget() -> usize {
    crate::interp::memory::limit() / 8
}

/// Halves a recording: every other sample, the first and the last kept;
/// the memory freed is given back.
fn thin(r: &mut Vec<Sample>) {
    let Some(&last) = r.last() else { return };
    let mut k = 0usize;
    r.retain(|_| {
        k += 1;
        k % 2 == 1
    });
    if r.last() != Some(&last) {
        r.push(last);
    }
    r.shrink_to_fit();
}

/// Appends `new` to the recording, thinned first when it would pass its
/// [`budget`] or the memory limit.
fn add(st: &mut RobotState, new: Vec<Sample>) {
    let Some(r) = &mut st.record else { return };
    let size = std::mem::size_of::<Sample>();
    loop {
        let after = (r.len() + new.len()).saturating_mul(size);
        // A vector may double when it grows.
        let grows = if r.capacity() - r.len() >= new.len() {
            0
        } else {
            after.saturating_mul(2)
        };
        let fits = after.saturating_mul(2) <= budget()
            && crate::interp::memory::room_for(grows.saturating_add(1 << 20));
        if fits || r.len() <= 2 {
            break;
        }
        thin(r);
    }
    r.extend(new);
}

/// The fractions of a motion to sample: its `n` support points (thinned
/// evenly when there are too many; the first and last kept) and every
/// 20 ms of `duration` (at even intervals when the motion is long).
fn fractions(n: usize, duration: f64) -> Vec<f64> {
    let half = MAX_PER_MOTION / 2;
    let mut fracs: Vec<f64> = if n < half {
        (0..=n).map(|i| i as f64 / n as f64).collect()
    } else {
        (0..half)
            .map(|k| (k * n / (half - 1)) as f64 / n as f64)
            .collect()
    };
    if duration > 0.0 && duration.is_finite() {
        let steps = (duration / STEP).floor();
        if steps < half as f64 {
            let steps = steps as usize;
            fracs.extend((1..=steps).map(|k| (k as f64 * STEP / duration).min(1.0)));
        } else {
            fracs.extend((1..=half).map(|k| k as f64 / half as f64));
        }
    }
    fracs.sort_by(f64::total_cmp);
    fracs.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    fracs
}

/// Records a motion from `before` through `points` that starts at `start`
/// and takes `duration`: sampled every 20 ms plus both ends, and at every
/// support point (at most [`MAX_PER_MOTION`] samples, evenly spread).
pub(super) fn motion(
    st: &mut RobotState,
    start: f64,
    before: &Joints,
    points: &[Joints],
    duration: f64,
) {
    if st.record.is_none() && st.watch.is_none() {
        return;
    }
    let new = samples_of(st, start, before, points, duration);
    if let Some(&s) = new.last() {
        st.last_sample = Some(s);
    }
    add(st, new);
}

/// The sample a new one must not repeat: the recording's last (none when
/// it has just started), or without a recording the last one shown.
fn previous(st: &RobotState) -> Option<Sample> {
    match &st.record {
        Some(r) => r.last().copied(),
        None => st.last_sample,
    }
}

/// Whether `b` repeats `a`: the same time, pose and gripper (to far less
/// than the four decimals a recording shows).
fn repeats(a: &Sample, b: &Sample) -> bool {
    let near = |x: f64, y: f64| (x - y).abs() <= 1e-9;
    near(a.t, b.t)
        && near(a.grip, b.grip)
        && a.joints.iter().zip(&b.joints).all(|(x, y)| near(*x, *y))
        && a.tcp.iter().zip(&b.tcp).all(|(x, y)| near(*x, *y))
}

/// The samples [`motion`] records for a motion, without the ones that
/// repeat the sample before them: a motion that takes no time (`InitRobot`
/// at the zero pose) has its two ends at one instant, and a motion that
/// starts when the one before it ended starts where it ended (the first
/// sample is compared with the recording's last). The recording and the
/// [`Watch`] get the same samples.
fn samples_of(
    st: &RobotState,
    start: f64,
    before: &Joints,
    points: &[Joints],
    duration: f64,
) -> Vec<Sample> {
    let mut last = previous(st);
    let mut out = Vec::new();
    for &f in &fractions(points.len().max(1), duration) {
        let s = sample(
            st,
            start + f * duration,
            super::interpolate(before, points, f),
        );
        if last.is_some_and(|l| repeats(&l, &s)) {
            continue;
        }
        last = Some(s);
        out.push(s);
    }
    out
}

/// Shows a motion that starts now to the [`Watch`], when there is one.
pub(super) fn announce(
    st: &mut RobotState,
    start: f64,
    before: &Joints,
    points: &[Joints],
    duration: f64,
) {
    if st.watch.is_none() {
        return;
    }
    let new = samples_of(st, start, before, points, duration);
    if let Some(w) = &mut st.watch
        && !new.is_empty()
    {
        w.samples(&new);
    }
}

/// Records the robot's pose now (e.g. after a gripper motion).
pub(super) fn point(st: &mut RobotState, t: f64) {
    if st.record.is_none() && st.watch.is_none() {
        return;
    }
    let s = sample(st, t, st.robot.joints());
    if previous(st).is_some_and(|l| repeats(&l, &s)) {
        return;
    }
    st.last_sample = Some(s);
    if let Some(w) = &mut st.watch {
        w.samples(&[s]);
    }
    add(st, vec![s]);
}

/// The driver reports the arm elsewhere than it was shown: a fresh read-back
/// (a real arm's `WH`) after the arm was moved by hand. The pose `before`
/// holds until `t`, and the reported one from `t` on: a jump at `t`, not a
/// motion, since no one knows when the hand moved it. The recording and
/// the live view get it as they get a motion (docs/view.md).
pub(super) fn reported(st: &mut RobotState, t: f64, before: Joints) {
    if st.record.is_none() && st.watch.is_none() {
        return;
    }
    let was = sample(st, t, before);
    let now = sample(st, t, st.robot.joints());
    let mut new = Vec::with_capacity(2);
    if !previous(st).is_some_and(|l| repeats(&l, &was)) {
        new.push(was);
    }
    new.push(now);
    st.last_sample = Some(now);
    if let Some(w) = &mut st.watch {
        w.samples(&new);
    }
    add(st, new);
}

/// Ends a motion that was recorded whole where the arm stopped (Ctrl-C):
/// the samples after `t` go, and the pose `q` at `t` is the last one.
pub(super) fn cut(st: &mut RobotState, t: f64, q: Joints) {
    if st.record.is_none() && st.watch.is_none() {
        return;
    }
    let s = sample(st, t, q);
    st.last_sample = Some(s);
    if let Some(w) = &mut st.watch {
        w.cut(&s);
    }
    if let Some(r) = &mut st.record {
        while r.last().is_some_and(|x| x.t >= t) {
            r.pop();
        }
        r.push(s);
    }
}

/// The JSON keys (the short names, whose units the CSV header spells).
const KEYS: [&str; 10] = ["t", "j1", "j2", "j3", "j4", "j5", "x", "y", "z", "grip"];

/// The CSV header row: each column with its unit (seconds, degrees, mm).
/// Readers of a recording also take the header of earlier versions,
/// [`OLD_CSV_HEADER`] (docs/record.md says which readers).
pub const CSV_HEADER: &str = "t_s,j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,x_mm,y_mm,z_mm,grip_mm";

/// The CSV header row without units that `--record` wrote before.
pub const OLD_CSV_HEADER: &str = "t,j1,j2,j3,j4,j5,x,y,z,grip";

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
    let mut out = CSV_HEADER.to_string();
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
    fn a_long_motion_has_at_most_max_per_motion_fractions_evenly_spread() {
        // A short motion: every 20 ms and each support point.
        let f = fractions(3, 0.1);
        assert_eq!(f.len(), 4 + 4, "{f:?}");
        for (n, d) in [(1, 1.0e12), (1, f64::MAX), (100_000, 5.0), (100_000, 1.0e9)] {
            let f = fractions(n, d);
            assert!(f.len() <= MAX_PER_MOTION, "{n} {d}: {}", f.len());
            assert!(f.len() >= MAX_PER_MOTION / 2, "{n} {d}: {}", f.len());
            assert_eq!((f[0], *f.last().unwrap()), (0.0, 1.0));
        }
        // Not a number of steps: the support points only.
        assert_eq!(fractions(2, f64::INFINITY), [0.0, 0.5, 1.0]);
    }

    #[test]
    fn thinning_keeps_every_other_sample_and_both_ends() {
        let s = |t: f64| Sample {
            t,
            joints: [0.0; 5],
            tcp: [0.0; 3],
            grip: 0.0,
        };
        let mut r: Vec<Sample> = (0..6).map(|k| s(k as f64)).collect();
        thin(&mut r);
        let ts: Vec<f64> = r.iter().map(|x| x.t).collect();
        assert_eq!(ts, [0.0, 2.0, 4.0, 5.0]);
        let mut r: Vec<Sample> = (0..5).map(|k| s(k as f64)).collect();
        thin(&mut r);
        let ts: Vec<f64> = r.iter().map(|x| x.t).collect();
        assert_eq!(ts, [0.0, 2.0, 4.0]);
    }

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
            "t_s,j1_deg,j2_deg,j3_deg,j4_deg,j5_deg,x_mm,y_mm,z_mm,grip_mm\n0.5000,0.0000,90.0000,0.0000,0.0000,0.0000,1.0000,2.0000,3.0000,40.0000\n"
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
