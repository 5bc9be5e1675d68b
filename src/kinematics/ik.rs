//! Closed-form inverse kinematics with every branch, and branch choice.

use std::f64::consts::{PI, TAU};
use std::fmt;

use nalgebra::Vector3;

use super::error::{KinError, LimitViolation};
use super::{JOINTS, Joints, Kinematics, Pose, tolerance};

/// Arm configuration: which side of the waist axis the wrist is on.
/// `None` (AdaIR `NoArmConfig`) = no preference.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Arm {
    /// Wrist point in front of the waist axis (in the direction J1 points).
    Forward,
    /// Wrist point behind the waist axis: the arm leans back over the base.
    Backward,
    /// No preference.
    None,
}

/// Elbow configuration: the sign of J3. `None` (AdaIR `NoElbowConfig`) = no
/// preference.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Elbow {
    /// J3 >= 0 (J3 taken in -180 .. 180 deg).
    Above,
    /// J3 < 0.
    Below,
    /// No preference.
    None,
}

impl fmt::Display for Arm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Arm::Forward => "arm forward",
            Arm::Backward => "arm backward",
            Arm::None => "any arm",
        })
    }
}

impl fmt::Display for Elbow {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Elbow::Above => "elbow above",
            Elbow::Below => "elbow below",
            Elbow::None => "any elbow",
        })
    }
}

impl Arm {
    fn accepts(self, other: Arm) -> bool {
        self == Arm::None || self == other
    }
}

impl Elbow {
    fn accepts(self, other: Elbow) -> bool {
        self == Elbow::None || self == other
    }
}

/// One inverse-kinematics solution within the joint limits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solution {
    /// Joint vector, rad.
    pub joints: Joints,
    /// Its arm configuration.
    pub arm: Arm,
    /// Its elbow configuration.
    pub elbow: Elbow,
}

/// Up to four raw branches (joint values before limits and 2 pi
/// representations are chosen).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Branches {
    pub(crate) joints: [Joints; 4],
    /// The configuration of each branch (as [`Kinematics::config_of`] would
    /// compute it, without the trigonometry).
    pub(crate) configs: [(Arm, Elbow); 4],
    pub(crate) len: usize,
}

impl Branches {
    pub(crate) fn as_slice(&self) -> &[Joints] {
        &self.joints[..self.len]
    }
}

/// `x` wrapped into (-pi, pi].
pub(crate) fn wrap(x: f64) -> f64 {
    let y = x - TAU * (x / TAU).round();
    if y <= -PI { y + TAU } else { y }
}

impl Kinematics {
    /// Flange goal for a TCP goal: `goal * tool^-1`, after checking that
    /// both are rigid transforms.
    pub(crate) fn flange_goal(&self, goal: &Pose, tool: &Pose) -> Result<Pose, KinError> {
        goal.check_rigid("goal frame")?;
        tool.check_rigid("tool transform")?;
        Ok(*goal * tool.inverse())
    }

    /// Every branch for a flange pose, before joint limits: up to 4 joint
    /// vectors (2 when the arm is stretched and the elbow branches
    /// coincide). `current` decides J1 when the flange is on the waist axis
    /// and the approach is vertical, and J2 when the wrist point sits on the
    /// shoulder (only possible when L2 = L3).
    pub(crate) fn branches(&self, flange: &Pose, current: &Joints) -> Result<Branches, KinError> {
        let l = self.desc.links();
        let p = flange.translation;
        let a = flange.approach();
        let rxy = (p.x * p.x + p.y * p.y).sqrt();
        let axy = (a.x * a.x + a.y * a.y).sqrt();
        // J1: from the position; on the waist axis from the approach vector;
        // with both on the axis, keep the current J1.
        let theta = if rxy > tolerance::AXIS {
            p.y.atan2(p.x)
        } else if axy > tolerance::VERTICAL {
            a.y.atan2(a.x)
        } else {
            current[0]
        };
        let (s1, c1) = theta.sin_cos();
        let out_of_plane = -s1 * a.x + c1 * a.y;
        if out_of_plane.is_nan() || out_of_plane.abs() > tolerance::PLANE {
            return Err(KinError::OrientationUnreachable {
                angle: out_of_plane.clamp(-1.0, 1.0).asin().abs(),
            });
        }
        let psi = (c1 * a.x + s1 * a.y).atan2(a.z);
        let (sp, cp) = psi.sin_cos();
        let r = c1 * p.x + s1 * p.y;
        let rw = r - l.l4 * sp;
        let zw = p.z - l.l1 - l.l4 * cp;
        let d = (rw * rw + zw * zw).sqrt();
        let reach = l.l2 + l.l3;
        let min_reach = (l.l2 - l.l3).abs();
        // The flange moved along shoulder -> wrist point until the wrist
        // point is `to` mm from the shoulder (same orientation), 0.05 mm
        // inside so that the stretched or folded arm is not on its J3 limit.
        // A wrist point on the shoulder has no direction: it moves up.
        let moved = |to: f64| {
            if d > 0.0 {
                let k = to / d - 1.0;
                p + Vector3::new(c1 * rw * k, s1 * rw * k, zw * k)
            } else {
                p + Vector3::new(0.0, 0.0, to)
            }
        };
        if d.is_nan() || d > reach + tolerance::REACH {
            return Err(KinError::WristTooFar {
                distance: d,
                reach,
                goal: p,
                nearest: moved(reach - 0.05),
            });
        }
        if d < min_reach - tolerance::REACH {
            return Err(KinError::WristTooClose {
                distance: d,
                min_reach,
                goal: p,
                nearest: moved(min_reach + 0.05),
            });
        }
        let c3 = ((d * d - l.l2 * l.l2 - l.l3 * l.l3) / (2.0 * l.l2 * l.l3)).clamp(-1.0, 1.0);
        let j3 = c3.acos();
        let (s3, c3) = j3.sin_cos();
        let beta = (l.l3 * s3).atan2(l.l2 + l.l3 * c3);
        // Wrist point on the shoulder (L2 = L3 folded): keep the current J2.
        let phi = if d > tolerance::REACH {
            rw.atan2(zw)
        } else {
            current[1] + beta
        };
        let n = flange.rotation.column(0);
        let o = flange.rotation.column(1);
        let m = Vector3::new(-s1, c1, 0.0);
        let j5 = n.dot(&m).atan2(o.dot(&m));

        // The second J1 (theta + pi) mirrors the arm plane: r, psi, phi and
        // the J5 reference change sign.
        let mut out = Branches {
            joints: [[0.0; JOINTS]; 4],
            configs: [(Arm::None, Elbow::None); 4],
            len: 0,
        };
        let elbows: &[f64] = if j3 == 0.0 || j3 == PI {
            &[1.0]
        } else {
            &[1.0, -1.0]
        };
        for (sigma, j1, j5) in [(1.0, theta, j5), (-1.0, theta + PI, j5 + PI)] {
            for &e in elbows {
                let j2 = sigma * phi - e * beta;
                let j3e = e * j3;
                let j4 = sigma * psi - j2 - j3e;
                out.joints[out.len] = [j1, j2, j3e, j4, j5];
                // The wrist point lies at sigma * rw along this J1.
                // Wrist point on the waist axis: the turned waist is the
                // backward arm (else both would read "forward").
                let arm = if sigma * rw > tolerance::AXIS
                    || (rw.abs() <= tolerance::AXIS && sigma > 0.0)
                {
                    Arm::Forward
                } else {
                    Arm::Backward
                };
                let elbow = if wrap(j3e) >= 0.0 {
                    Elbow::Above
                } else {
                    Elbow::Below
                };
                out.configs[out.len] = (arm, elbow);
                out.len += 1;
            }
        }
        Ok(out)
    }

    /// `raw` with each joint moved by a multiple of 2 pi into its limits,
    /// nearest to `reference`; or the first joint that fits no way.
    pub fn fit_limits(&self, raw: &Joints, reference: &Joints) -> Result<Joints, LimitViolation> {
        let mut out = *raw;
        for (i, spec) in self.desc.joints().iter().enumerate() {
            let q = raw[i];
            // Fast path: a limit range narrower than a turn holds at most one
            // representation; the raw value usually is it.
            if spec.max - spec.min < TAU && spec.contains(q) {
                out[i] = q.clamp(spec.min, spec.max);
                continue;
            }
            let lo = ((spec.min - tolerance::LIMIT - q) / TAU).ceil();
            let hi = ((spec.max + tolerance::LIMIT - q) / TAU).floor();
            if lo.is_nan() || hi.is_nan() || lo > hi {
                // No representation fits, so the range is narrower than a
                // turn: the one nearest the range is the one nearest its
                // centre (within half a turn of it).
                let centre = 0.5 * (spec.min + spec.max);
                let best = q + ((centre - q) / TAU).round() * TAU;
                return Err(LimitViolation {
                    joint: i + 1,
                    target: best,
                    min: spec.min,
                    max: spec.max,
                    other_way: None,
                });
            }
            let k = ((reference[i] - q) / TAU).round().clamp(lo, hi);
            out[i] = (q + k * TAU).clamp(spec.min, spec.max);
        }
        Ok(out)
    }

    /// `raw` with each joint moved by a multiple of 2 pi next to
    /// `reference`, whatever the limits.
    pub(crate) fn nearest_representation(raw: &Joints, reference: &Joints) -> Joints {
        let mut out = *raw;
        for (q, r) in out.iter_mut().zip(reference) {
            // Most joints are already next to the reference: skip the
            // rounding then.
            if (r - *q).abs() > PI {
                *q += TAU * ((r - *q) / TAU).round();
            }
        }
        out
    }

    /// Distance between joint vectors for branch choice: the time the
    /// slowest joint needs at full speed, then the summed squares.
    pub(crate) fn joint_distance(&self, a: &Joints, b: &Joints) -> (f64, f64) {
        let mut time = 0.0f64;
        let mut sq = 0.0;
        for ((x, y), spec) in a.iter().zip(b).zip(self.desc.joints()) {
            let d = (x - y).abs();
            time = time.max(d / spec.max_speed);
            sq += d * d;
        }
        (time, sq)
    }

    /// Every inverse-kinematics solution within the joint limits for the TCP
    /// `goal` with tool transform `tool` (the flange goal `goal * tool^-1` is
    /// solved with D = L4). Each joint takes the 2 pi representation within
    /// its limits nearest `current`.
    ///
    /// Errors, in this order: `goal` or `tool` not rigid (`FrameInvalid`);
    /// position outside the workspace (`OutOfReach`, wrist distance in the
    /// message); orientation not reachable by a 5-axis arm (`FrameInvalid`);
    /// every branch beyond a joint limit (`OutOfReach`, each branch's first
    /// violation).
    pub fn ik_all(
        &self,
        goal: &Pose,
        tool: &Pose,
        current: &Joints,
    ) -> Result<Vec<Solution>, KinError> {
        super::joints::check_finite(current, "current joints")?;
        let flange = self.flange_goal(goal, tool)?;
        let to_tcp = goal.translation - flange.translation;
        let branches = match self.branches(&flange, current) {
            Ok(b) => b,
            Err(e @ KinError::OrientationUnreachable { .. }) => {
                return Err(self.orientation_or_reach(goal, tool, current, e));
            }
            Err(e) => return Err(e.shifted(to_tcp)),
        };
        let mut solutions = Vec::with_capacity(4);
        let mut violations = Vec::new();
        for (raw, &(arm, elbow)) in branches.as_slice().iter().zip(&branches.configs) {
            match self.fit_limits(raw, current) {
                Ok(q) => solutions.push(Solution {
                    joints: q,
                    arm,
                    elbow,
                }),
                Err(v) => violations.push((arm, elbow, v)),
            }
        }
        if solutions.is_empty() {
            return Err(KinError::NoBranchWithinLimits {
                branches: violations,
            });
        }
        Ok(solutions)
    }

    /// The solution to move to: among the solutions matching the preferred
    /// configuration (`Arm::None` / `Elbow::None` match all) the one nearest
    /// `current` (shortest time at full speed); when none matches, the
    /// nearest of all. The preference is a preference (handbook:
    /// "Vorzugskonfiguration"), not a demand; callers that need a given
    /// branch check [`Solution::arm`] / [`Solution::elbow`].
    pub fn ik_choose(
        &self,
        goal: &Pose,
        tool: &Pose,
        current: &Joints,
        arm: Arm,
        elbow: Elbow,
    ) -> Result<Solution, KinError> {
        let solutions = self.ik_all(goal, tool, current)?;
        let nearest = |list: &mut dyn Iterator<Item = &Solution>| {
            list.min_by(|a, b| {
                let (ta, sa) = self.joint_distance(&a.joints, current);
                let (tb, sb) = self.joint_distance(&b.joints, current);
                ta.total_cmp(&tb).then(sa.total_cmp(&sb))
            })
            .copied()
        };
        let preferred = nearest(
            &mut solutions
                .iter()
                .filter(|s| arm.accepts(s.arm) && elbow.accepts(s.elbow)),
        );
        match preferred.or_else(|| nearest(&mut solutions.iter())) {
            Some(s) => Ok(s),
            // ik_all never returns an empty list; keep the signature total.
            None => Err(KinError::NoBranchWithinLimits {
                branches: Vec::new(),
            }),
        }
    }

    /// Whether the arm can reach `goal` with `tool`: `Ok` or the error
    /// [`Kinematics::ik_all`] would give (its exception is `FrameInvalid` or
    /// `OutOfReach`).
    pub fn classify(&self, goal: &Pose, tool: &Pose, current: &Joints) -> Result<(), KinError> {
        self.ik_all(goal, tool, current).map(|_| ())
    }

    /// The goal's orientation is unreachable; decide whether its position is
    /// outside the workspace (then `OutOfReach` wins) or not (`orientation`
    /// error). The position counts as reachable when the ValidFrame
    /// projection of the goal is reachable or, for tools whose TCP lies on
    /// the flange axis, when any pitch angle (sampled every degree) reaches
    /// it.
    fn orientation_or_reach(
        &self,
        goal: &Pose,
        tool: &Pose,
        current: &Joints,
        orientation: KinError,
    ) -> KinError {
        let projected = match self.valid_frame(goal, tool) {
            Ok(p) => p,
            Err(_) => return orientation,
        };
        // Report the angle ValidFrame would turn the frame by (measured at
        // the TCP, which is what the user wrote).
        let orientation = KinError::OrientationUnreachable {
            angle: goal.rotation_angle_to(&projected),
        };
        let projected_error = match self.ik_all_no_projection(&projected, tool, current) {
            Ok(()) => return orientation,
            Err(e) => e,
        };
        if Self::tool_on_axis(tool) {
            let p = goal.translation;
            let theta = p.y.atan2(p.x);
            let base = Pose::rot_z(theta);
            for step in 0..360 {
                let pitch = Pose::rot_y((step as f64).to_radians());
                let mut candidate = base * pitch * Pose::new(tool.rotation, Vector3::zeros());
                candidate.translation = p;
                if self.ik_all_no_projection(&candidate, tool, current).is_ok() {
                    return orientation;
                }
            }
        }
        projected_error
    }

    /// `ik_all` reduced to reachable / the error, without the orientation
    /// fallback (which would recurse).
    fn ik_all_no_projection(
        &self,
        goal: &Pose,
        tool: &Pose,
        current: &Joints,
    ) -> Result<(), KinError> {
        let flange = self.flange_goal(goal, tool)?;
        let branches = self
            .branches(&flange, current)
            .map_err(|e| e.shifted(goal.translation - flange.translation))?;
        let mut violations = Vec::new();
        for (raw, &(arm, elbow)) in branches.as_slice().iter().zip(&branches.configs) {
            match self.fit_limits(raw, current) {
                Ok(_) => return Ok(()),
                Err(v) => violations.push((arm, elbow, v)),
            }
        }
        Err(KinError::NoBranchWithinLimits {
            branches: violations,
        })
    }

    /// Whether the tool's TCP lies on the flange axis (its translation has
    /// no x or y part), so the TCP stays in the arm plane.
    pub(crate) fn tool_on_axis(tool: &Pose) -> bool {
        tool.translation.x.abs() <= tolerance::AXIS && tool.translation.y.abs() <= tolerance::AXIS
    }
}
