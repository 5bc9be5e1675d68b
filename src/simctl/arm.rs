//! The simulated arm behind a drive unit: joint position counters, limits,
//! the speed level and motion times, the `WH` pose and the unit's own
//! inverse kinematics for `MP`/`MO`. It takes link lengths, limits, speeds
//! and the nest pose from the robot file and nothing else from the rest of
//! adair: the pose formulas are written here from robots.md.

use crate::kinematics::{JOINTS, Joints, RobotDescription};

/// Joint counts per controller degree, as robots.md gives them.
pub const RV_M1_COUNTS: [f64; JOINTS] = [40.0; JOINTS];
/// The RM-501: 40 per degree for J1-J3, one per 0.075 degree for J4-J5.
pub const RM_501_COUNTS: [f64; JOINTS] = [40.0, 40.0, 40.0, 1.0 / 0.075, 1.0 / 0.075];

/// Joint position in counts of each joint's resolution, in the controller's
/// own frame (`controller_deg = direction * adair_deg + zero_offset`).
pub type Counts = [i64; JOINTS];

/// Speed level at power-on.
pub const POWER_ON_SPEED: u8 = 4;

/// The arm: where it stands and how fast it moves.
#[derive(Clone, Debug)]
pub struct Arm {
    desc: RobotDescription,
    per_deg: [f64; JOINTS],
    /// Allowed counts per joint, inclusive.
    limits: [(i64, i64); JOINTS],
    /// Where the arm stands.
    pub counts: Counts,
    /// `SP` level 0..9.
    pub speed: u8,
}

/// Why a target was refused: a joint beyond its limits (error mode II on
/// the RV-M1).
#[derive(Debug, PartialEq)]
pub struct OutOfRange;

impl Arm {
    /// The arm at power-on: standing at the nest (as if the operator had
    /// nested it), speed level 4.
    pub fn new(desc: RobotDescription, per_deg: [f64; JOINTS]) -> Arm {
        let mut limits = [(0, 0); JOINTS];
        let lo = desc.to_controller_deg(&desc.joints().clone().map(|j| j.min));
        let hi = desc.to_controller_deg(&desc.joints().clone().map(|j| j.max));
        for j in 0..JOINTS {
            let (a, b) = (lo[j].min(hi[j]) * per_deg[j], lo[j].max(hi[j]) * per_deg[j]);
            limits[j] = ((a - 1e-6).ceil() as i64, (b + 1e-6).floor() as i64);
        }
        let mut arm = Arm {
            desc,
            per_deg,
            limits,
            counts: [0; JOINTS],
            speed: POWER_ON_SPEED,
        };
        arm.counts = arm.nest();
        arm
    }

    /// The robot file.
    pub fn description(&self) -> &RobotDescription {
        &self.desc
    }

    /// Counts of controller angles (deg), rounded to the resolution.
    pub fn counts_of_deg(&self, deg: &[f64; JOINTS]) -> Counts {
        let mut c = [0; JOINTS];
        for j in 0..JOINTS {
            c[j] = (deg[j] * self.per_deg[j]).round() as i64;
        }
        c
    }

    /// Controller angles (deg) of counts.
    pub fn deg_of_counts(&self, c: &Counts) -> [f64; JOINTS] {
        let mut d = [0.0; JOINTS];
        for j in 0..JOINTS {
            d[j] = c[j] as f64 / self.per_deg[j];
        }
        d
    }

    /// Our joint angles (rad) of counts.
    pub fn joints_of(&self, c: &Counts) -> Joints {
        self.desc.from_controller_deg(&self.deg_of_counts(c))
    }

    /// Counts of our joint angles (rad).
    pub fn counts_of_joints(&self, q: &Joints) -> Counts {
        self.counts_of_deg(&self.desc.to_controller_deg(q))
    }

    /// The nest pose (robot file) in counts.
    pub fn nest(&self) -> Counts {
        self.counts_of_joints(&self.desc.nest())
    }

    /// Whether every joint of `c` lies within its limits.
    pub fn within_limits(&self, c: &Counts) -> bool {
        c.iter()
            .zip(&self.limits)
            .all(|(v, (lo, hi))| lo <= v && v <= hi)
    }

    /// Seconds from `from` to `to` at the current speed level: the slowest
    /// joint's travel over its speed, each joint at
    /// `max_speed * max(level, 1) / 9` (adair's model of the levels).
    pub fn travel_time(&self, from: &Counts, to: &Counts) -> f64 {
        let fraction = f64::from(self.speed.max(1)) / 9.0;
        let mut t: f64 = 0.0;
        for (j, spec) in self.desc.joints().iter().enumerate() {
            let deg = (to[j] - from[j]).abs() as f64 / self.per_deg[j];
            t = t.max(deg / (spec.max_speed.to_degrees() * fraction));
        }
        t
    }

    /// Moves to `target`: the seconds it takes, or `OutOfRange` (nothing
    /// moves) when a joint would leave its limits.
    pub fn move_to(&mut self, target: Counts) -> Result<f64, OutOfRange> {
        if !self.within_limits(&target) {
            return Err(OutOfRange);
        }
        let t = self.travel_time(&self.counts, &target);
        self.counts = target;
        Ok(t)
    }

    /// Moves by `delta` counts (see [`Arm::move_to`]).
    pub fn move_by(&mut self, delta: &Counts) -> Result<f64, OutOfRange> {
        let mut target = self.counts;
        for (t, d) in target.iter_mut().zip(delta) {
            *t = t.saturating_add(*d);
        }
        self.move_to(target)
    }

    /// Moves the arm by hand (a teach box jog) by `deg` controller degrees
    /// per joint, each joint stopping at its limit as the teach box stops
    /// it. Returns the degrees it really moved.
    pub fn jog(&mut self, deg: &[f64; JOINTS]) -> [f64; JOINTS] {
        let delta = self.counts_of_deg(deg);
        let before = self.counts;
        for ((c, d), (lo, hi)) in self.counts.iter_mut().zip(delta).zip(self.limits) {
            *c = c.saturating_add(d).clamp(lo, hi);
        }
        let mut moved = [0.0; JOINTS];
        for j in 0..JOINTS {
            moved[j] = (self.counts[j] - before[j]) as f64 / self.per_deg[j];
        }
        moved
    }

    /// The `WH` pose of `c` with tool length `tool`: x, y, z (mm) of the
    /// TCP, p = 90 - (J2 + J3 + J4) wrapped into -180 .. 180, r = J5 (deg).
    pub fn pose_of(&self, c: &Counts, tool: f64) -> [f64; 5] {
        let q = self.joints_of(c);
        let l = self.desc.links();
        let d = l.l4 + tool;
        let psi = q[1] + q[2] + q[3];
        let radial = l.l2 * q[1].sin() + l.l3 * (q[1] + q[2]).sin() + d * psi.sin();
        let z = l.l1 + l.l2 * q[1].cos() + l.l3 * (q[1] + q[2]).cos() + d * psi.cos();
        [
            radial * q[0].cos(),
            radial * q[0].sin(),
            z,
            wrap_deg(90.0 - psi.to_degrees()),
            q[4].to_degrees(),
        ]
    }

    /// The `WH` pose of where the arm stands.
    pub fn pose(&self, tool: f64) -> [f64; 5] {
        self.pose_of(&self.counts, tool)
    }

    /// Joint counts reaching the `WH`-style pose `[x, y, z, p, r]` with tool
    /// length `tool`, as the unit solves it: J1 points at the target (or
    /// away from it, arm leaning back), p is read in that arm plane, J5 = r;
    /// of the solutions within the limits the one reached soonest from
    /// `near`. `None`: out of reach or beyond a limit (error mode II).
    pub fn solve(&self, pose: &[f64; 5], tool: f64, near: &Counts) -> Option<Counts> {
        let l = self.desc.links();
        let d = l.l4 + tool;
        let [x, y, z, p, r] = *pose;
        let q_near = self.joints_of(near);
        let horizontal = x.hypot(y);
        let toward = if horizontal < 1e-6 {
            q_near[0]
        } else {
            y.atan2(x)
        };
        let psi = (90.0 - p).to_radians();
        let mut best: Option<(f64, Counts)> = None;
        for j1 in [toward, toward + std::f64::consts::PI] {
            let j1 = wrap_rad(j1);
            let radial = x * j1.cos() + y * j1.sin();
            let (wr, wz) = (radial - d * psi.sin(), z - l.l1 - d * psi.cos());
            let cos3 = (wr * wr + wz * wz - l.l2 * l.l2 - l.l3 * l.l3) / (2.0 * l.l2 * l.l3);
            if !(-1.0 - 1e-9..=1.0 + 1e-9).contains(&cos3) {
                continue;
            }
            let a3 = cos3.clamp(-1.0, 1.0).acos();
            for j3 in [a3, -a3] {
                let j2 = wr.atan2(wz) - (l.l3 * j3.sin()).atan2(l.l2 + l.l3 * j3.cos());
                let j4 = psi - j2 - j3;
                let q = [j1, wrap_rad(j2), j3, wrap_rad(j4), r.to_radians()];
                let c = self.counts_of_joints(&q);
                if !self.within_limits(&c) {
                    continue;
                }
                let t = self.travel_time(near, &c);
                if best.as_ref().is_none_or(|(bt, _)| t < *bt - 1e-12) {
                    best = Some((t, c));
                }
            }
        }
        best.map(|(_, c)| c)
    }
}

/// Degrees wrapped into -180 .. 180.
fn wrap_deg(v: f64) -> f64 {
    let w = (v + 180.0).rem_euclid(360.0) - 180.0;
    if w == -180.0 && v > 0.0 { 180.0 } else { w }
}

/// Radians wrapped into -pi .. pi.
fn wrap_rad(v: f64) -> f64 {
    wrap_deg(v.to_degrees()).to_radians()
}
