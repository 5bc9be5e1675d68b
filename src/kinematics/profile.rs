//! Synchronous point-to-point joint motion with a trapezoidal speed profile.

use super::error::KinError;
use super::{JOINTS, Joints, RobotDescription, tolerance};

/// A planned joint motion: all joints start and stop together.
///
/// Every joint follows `q(t) = from + (to - from) * s(t)` with one common
/// normalised profile `s` (0 -> 1): constant acceleration, cruise,
/// constant deceleration (a triangle when the cruise speed is never
/// reached). The cruise speed is the largest that keeps every joint within
/// `velocity %` of its maximum speed, so the leading joint (largest travel
/// relative to its maximum speed) runs at exactly that; the acceleration is
/// the largest that keeps every joint within its `accel_deg_s2` (the
/// description's value, not scaled by the velocity percentage).
#[derive(Debug, Clone, PartialEq)]
pub struct MotionProfile {
    from: Joints,
    to: Joints,
    duration: f64,
    min_duration: f64,
    /// Normalised acceleration (1/s^2) and cruise speed (1/s).
    accel: f64,
    cruise: f64,
    ramp: f64,
    leading: Option<usize>,
}

impl MotionProfile {
    /// Plan a motion from `from` to `to` (final joint values, rad) at
    /// `velocity_percent` (0 < v <= 100) of the maximum speeds of `desc`.
    ///
    /// `requested_time`: `None` = as fast as the velocity allows; `Some(t)`
    /// = exactly `t` seconds (the acceleration stays, the cruise speed
    /// drops), `TimeInvalid` when `t` is shorter than the fastest duration
    /// (AdaIR's `Time => 0.0` means `None`). A motion without travel lasts
    /// `t` (or 0 s).
    pub fn plan(
        from: &Joints,
        to: &Joints,
        velocity_percent: f64,
        desc: &RobotDescription,
        requested_time: Option<f64>,
    ) -> Result<Self, KinError> {
        super::joints::check_finite(from, "start joints")?;
        super::joints::check_finite(to, "target joints")?;
        if velocity_percent.is_nan() || velocity_percent <= 0.0 || velocity_percent > 100.0 {
            return Err(KinError::InvalidParameter {
                name: "velocity",
                value: velocity_percent,
                expected: "0 < velocity <= 100 %",
            });
        }
        let fraction = velocity_percent / 100.0;
        let mut cruise = f64::INFINITY;
        let mut accel = f64::INFINITY;
        let mut leading = None;
        for (i, spec) in desc.joints().iter().enumerate() {
            let travel = (to[i] - from[i]).abs();
            if travel > 0.0 {
                let v = fraction * spec.max_speed / travel;
                if v < cruise {
                    cruise = v;
                    leading = Some(i);
                }
                accel = accel.min(spec.max_accel / travel);
            }
        }
        let (min_duration, ramp_min) = if leading.is_none() {
            (0.0, 0.0)
        } else if cruise * cruise >= accel {
            // Triangle: half the way accelerating, half decelerating.
            cruise = accel.sqrt();
            let ramp = (1.0 / accel).sqrt();
            (2.0 * ramp, ramp)
        } else {
            (1.0 / cruise + cruise / accel, cruise / accel)
        };
        let mut profile = MotionProfile {
            from: *from,
            to: *to,
            duration: min_duration,
            min_duration,
            accel,
            cruise,
            ramp: ramp_min,
            leading,
        };
        if let Some(t) = requested_time {
            if !t.is_finite() || t < min_duration - tolerance::TIME {
                return Err(KinError::TimeInvalid {
                    requested: t,
                    minimum: min_duration,
                });
            }
            if t > min_duration {
                profile.duration = t;
                if leading.is_some() {
                    // Cruise speed v with t = 1/v + v/a (smaller root, in a
                    // cancellation-free form).
                    let at = accel * t;
                    let disc = (at * at - 4.0 * accel).max(0.0);
                    let v = 2.0 * accel / (at + disc.sqrt());
                    profile.cruise = v;
                    profile.ramp = v / accel;
                }
            }
        }
        Ok(profile)
    }

    /// Duration of the motion, s.
    pub fn duration(&self) -> f64 {
        self.duration
    }

    /// Fastest duration at the planned velocity, s.
    pub fn min_duration(&self) -> f64 {
        self.min_duration
    }

    /// Index (0-based) of the leading joint, `None` without travel; of
    /// joints that need equally long, the lowest-numbered.
    pub fn leading_joint(&self) -> Option<usize> {
        self.leading
    }

    /// Fraction of the way done at time `t` (clamped to 0 .. duration).
    pub fn fraction_at(&self, t: f64) -> f64 {
        if self.leading.is_none() || t.is_nan() || t <= 0.0 {
            return 0.0;
        }
        if t >= self.duration {
            return 1.0;
        }
        let (a, v, ta, total) = (self.accel, self.cruise, self.ramp, self.duration);
        let s = if t < ta {
            0.5 * a * t * t
        } else if t <= total - ta {
            0.5 * a * ta * ta + v * (t - ta)
        } else {
            let rest = total - t;
            1.0 - 0.5 * a * rest * rest
        };
        s.clamp(0.0, 1.0)
    }

    /// Joint vector at time `t` s after the start (clamped to the motion;
    /// exactly `to` from `duration` on).
    pub fn at(&self, t: f64) -> Joints {
        let s = self.fraction_at(t);
        if s >= 1.0 {
            return self.to;
        }
        let mut q = self.from;
        for (q, to) in q.iter_mut().zip(&self.to) {
            *q += (to - *q) * s;
        }
        q
    }

    /// Joint speeds (rad/s) at time `t`.
    pub fn velocity_at(&self, t: f64) -> Joints {
        let ds = if self.leading.is_none() || t.is_nan() || t <= 0.0 || t >= self.duration {
            0.0
        } else if t < self.ramp {
            self.accel * t
        } else if t <= self.duration - self.ramp {
            self.cruise
        } else {
            self.accel * (self.duration - t)
        };
        let mut v = [0.0; JOINTS];
        for ((v, to), from) in v.iter_mut().zip(&self.to).zip(&self.from) {
            *v = (to - from) * ds;
        }
        v
    }
}
