//! Straight-line (Cartesian) interpolation.

use std::f64::consts::TAU;

use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};

use super::error::{KinError, LimitViolation};
use super::valid::into_plane;
use super::{Joints, Kinematics, Pose, continuity};

/// Support points are capped so that a tiny width cannot exhaust memory.
const MAX_POINTS: f64 = 1_000_000.0;

/// The line being followed: TCP poses from `start` to `goal`.
struct Line {
    p0: Vector3<f64>,
    p1: Vector3<f64>,
    slerp: Slerp,
    goal: Pose,
    tool: Pose,
    tool_inv: Pose,
    /// Rt^T e3: the flange axis in TCP coordinates.
    flange_axis: Vector3<f64>,
    length: f64,
}

/// Spherical linear interpolation on the shorter arc, with the arc's
/// constants computed once per line.
struct Slerp {
    q0: Quaternion<f64>,
    q1: Quaternion<f64>,
    theta: f64,
    sin_theta: f64,
}

impl Slerp {
    fn new(q0: Quaternion<f64>, q1: Quaternion<f64>) -> Self {
        let d = q0.dot(&q1);
        let q1 = if d < 0.0 { -q1 } else { q1 };
        let theta = d.abs().min(1.0).acos();
        Slerp {
            q0,
            q1,
            theta,
            sin_theta: theta.sin(),
        }
    }

    fn at(&self, t: f64) -> Matrix3<f64> {
        let q = if self.theta > 1e-6 {
            self.q0 * (((1.0 - t) * self.theta).sin() / self.sin_theta)
                + self.q1 * ((t * self.theta).sin() / self.sin_theta)
        } else {
            self.q0 + (self.q1 - self.q0) * t
        };
        UnitQuaternion::from_quaternion(q)
            .to_rotation_matrix()
            .into_inner()
    }
}

impl Kinematics {
    /// Joint vectors of the support points of a straight TCP line from the
    /// pose at `from` to `goal` with `tool`, every support point checked
    /// before anything is returned (the start itself is not in the list; the
    /// last entry reaches `goal`).
    ///
    /// - Spacing: `n = max(ceil(length / width), ceil(rotation / 1 deg), 1)`
    ///   equal steps, so points are at most `width` mm and 1 degree apart.
    /// - Position by linear interpolation, orientation by slerp; a 5-axis arm
    ///   cannot hold every slerped orientation, so each is turned into the
    ///   nearest reachable one (the ValidFrame projection; exact at both
    ///   ends, which are reachable).
    /// - Each point is solved on the branch continuous with the previous one
    ///   (nearest solution, each joint's 2 pi representation next to the
    ///   previous value). Where a joint moves more than 2 degrees between
    ///   two points the piece is bisected, down to 0.01 mm
    ///   ([`continuity`]); a step still larger then is a jump.
    ///
    /// Errors: `goal` itself as [`Kinematics::ik_all`] reports it; then
    /// `LineBlocked { at, .. }` (a point outside the workspace or beyond a
    /// joint limit, at `at` mm from the start) or `JointJump { at, .. }` (a
    /// branch flip or a singularity on the line). `width` not > 0:
    /// `Constraint_Error`.
    pub fn straight_line(
        &self,
        from: &Joints,
        goal: &Pose,
        tool: &Pose,
        width: f64,
    ) -> Result<Vec<Joints>, KinError> {
        super::joints::check_finite(from, "start joints")?;
        if !width.is_finite() || width <= 0.0 {
            return Err(KinError::InvalidParameter {
                name: "interpolation width",
                value: width,
                expected: "a width > 0 mm",
            });
        }
        self.ik_all(goal, tool, from)?;
        if let Err(v) = self.desc.check_limits(from) {
            return Err(KinError::JointLimit(v));
        }
        let start = self.fk_tcp(from, tool);
        let tool_rot = super::valid::orthonormalize(&tool.rotation);
        let line = Line {
            p0: start.translation,
            p1: goal.translation,
            slerp: Slerp::new(
                *start.quaternion().quaternion(),
                *goal.quaternion().quaternion(),
            ),
            goal: *goal,
            tool: *tool,
            tool_inv: tool.inverse(),
            flange_axis: tool_rot.row(2).transpose(),
            length: (goal.translation - start.translation).norm(),
        };
        let angle = start.rotation_angle_to(goal);
        let n = (line.length / width)
            .ceil()
            .max((angle / continuity::MAX_ROTATION_STEP).ceil())
            .max(1.0);
        if n > MAX_POINTS {
            return Err(KinError::InvalidParameter {
                name: "interpolation width",
                value: width,
                expected: "at most 1000000 support points on the line",
            });
        }
        let n = n as usize;
        let first = self.walk(&line, from, n);
        let Err(refusal) = first else {
            return first;
        };
        if !matches!(&refusal, KinError::LineBlocked { cause, .. } if matches!(**cause, KinError::JointLimit(_)))
        {
            return Err(refusal);
        }
        // A joint whose start value has another 2 pi representation inside
        // its limits (J5 at +-180 deg on a range of exactly one turn) may do
        // the whole line in that one instead: the same pose, so try it
        // rather than refuse.
        for (j, spec) in self.desc.joints().iter().enumerate() {
            for other in [from[j] - TAU, from[j] + TAU] {
                if spec.contains(other) {
                    let mut alt = *from;
                    alt[j] = other.clamp(spec.min, spec.max);
                    if let Ok(points) = self.walk(&line, &alt, n) {
                        return Ok(points);
                    }
                }
            }
        }
        Err(refusal)
    }

    /// The support points of `line` in `n` steps from the joints `from`
    /// (see [`Kinematics::straight_line`]).
    fn walk(&self, line: &Line, from: &Joints, n: usize) -> Result<Vec<Joints>, KinError> {
        let min_piece = if line.length > 0.0 {
            (continuity::MIN_PIECE / line.length).max(1e-12)
        } else {
            1e-6
        };
        let mut points = Vec::with_capacity(n);
        let mut q = *from;
        let mut s0 = 0.0;
        for i in 1..=n {
            let s_end = if i == n { 1.0 } else { i as f64 / n as f64 };
            let mut s1 = s_end;
            // Walk from s0 to s_end, halving the step while a joint moves too
            // far, doubling it again after each accepted step.
            loop {
                let q1 = self.track(line, s1, &q)?;
                let (joint, step) = q1
                    .iter()
                    .zip(&q)
                    .map(|(a, b)| (a - b).abs())
                    .enumerate()
                    .fold(
                        (0, 0.0f64),
                        |best, (j, d)| if d > best.1 { (j, d) } else { best },
                    );
                if step <= continuity::MAX_STEP {
                    let h = s1 - s0;
                    q = q1;
                    s0 = s1;
                    if s0 >= s_end {
                        break;
                    }
                    s1 = (s0 + 2.0 * h).min(s_end);
                } else if s1 - s0 <= min_piece {
                    return Err(KinError::JointJump {
                        at: s0 * line.length,
                        length: line.length,
                        joint: joint + 1,
                        jump: step,
                    });
                } else {
                    s1 = 0.5 * (s0 + s1);
                }
            }
            points.push(q);
        }
        Ok(points)
    }

    /// TCP pose at `s` (0..1) along the line, turned into a reachable
    /// orientation.
    fn line_pose(&self, line: &Line, s: f64) -> Result<Pose, KinError> {
        if s >= 1.0 {
            return Ok(line.goal);
        }
        let p = line.p0 + (line.p1 - line.p0) * s;
        let rot = line.slerp.at(s);
        if Self::tool_on_axis(&line.tool) {
            let turn = into_plane(&(rot * line.flange_axis), &p);
            Ok(Pose::new(turn * rot, p))
        } else {
            self.valid_frame(&Pose::new(rot, p), &line.tool)
        }
    }

    /// The solution at `s` nearest `previous` (each joint next to its
    /// previous value), checked against the limits.
    fn track(&self, line: &Line, s: f64, previous: &Joints) -> Result<Joints, KinError> {
        let blocked = |cause: KinError| KinError::LineBlocked {
            at: s * line.length,
            length: line.length,
            cause: Box::new(cause),
        };
        let pose = self.line_pose(line, s).map_err(blocked)?;
        let flange = pose * line.tool_inv;
        let to_tcp = pose.translation - flange.translation;
        let branches = self
            .branches(&flange, previous)
            .map_err(|e| blocked(e.shifted(to_tcp)))?;
        let mut best: Option<(Joints, (f64, f64))> = None;
        for raw in branches.as_slice() {
            let q = Self::nearest_representation(raw, previous);
            let d = self.joint_distance(&q, previous);
            if best.is_none_or(|(_, bd)| d.0.total_cmp(&bd.0).then(d.1.total_cmp(&bd.1)).is_lt()) {
                best = Some((q, d));
            }
        }
        let Some((q, _)) = best else {
            return Err(blocked(KinError::NoBranchWithinLimits {
                branches: Vec::new(),
            }));
        };
        let mut out = q;
        for (i, spec) in self.desc.joints().iter().enumerate() {
            if !spec.contains(q[i]) {
                return Err(blocked(KinError::JointLimit(LimitViolation {
                    joint: i + 1,
                    target: q[i],
                    min: spec.min,
                    max: spec.max,
                    other_way: None,
                })));
            }
            out[i] = q[i].clamp(spec.min, spec.max);
        }
        Ok(out)
    }
}
