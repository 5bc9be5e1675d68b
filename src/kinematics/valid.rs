//! ValidFrame: the nearest orientation a 5-axis arm can reach.

use nalgebra::{Matrix3, Vector3};

use super::error::KinError;
use super::{Kinematics, Pose, tolerance};

/// Rotation (smallest angle, Rodrigues) that turns the unit vector `v` into
/// the vertical plane through the waist axis and the point `c`.
///
/// - `c` on the waist axis: every vertical plane contains `c`, so `v` is
///   already in one: identity.
/// - `v` exactly perpendicular to the plane: every direction in the plane is
///   90 degrees away; we turn `v` about the vertical onto the horizontal
///   direction pointing away from the waist axis (the arm reaching out).
pub(crate) fn into_plane(v: &Vector3<f64>, c: &Vector3<f64>) -> Matrix3<f64> {
    let cxy = (c.x * c.x + c.y * c.y).sqrt();
    if cxy <= tolerance::AXIS {
        return Matrix3::identity();
    }
    let m = Vector3::new(-c.y / cxy, c.x / cxy, 0.0);
    let projected = v - m * v.dot(&m);
    let norm = projected.norm();
    let target = if norm > 1e-12 {
        projected / norm
    } else {
        Vector3::new(c.x / cxy, c.y / cxy, 0.0)
    };
    let axis = v.cross(&target);
    let s = axis.norm();
    let cos = v.dot(&target);
    if s <= f64::MIN_POSITIVE {
        return Matrix3::identity();
    }
    // Rodrigues: R = cos I + sin [k]x + (1 - cos) k k^T.
    let k = axis / s;
    let t = 1.0 - cos;
    Matrix3::new(
        cos + t * k.x * k.x,
        t * k.x * k.y - s * k.z,
        t * k.x * k.z + s * k.y,
        t * k.x * k.y + s * k.z,
        cos + t * k.y * k.y,
        t * k.y * k.z - s * k.x,
        t * k.x * k.z - s * k.y,
        t * k.y * k.z + s * k.x,
        cos + t * k.z * k.z,
    )
}

/// A rotation matrix from a nearly orthonormal one (Gram-Schmidt keeping
/// the approach vector, then y, then x = y cross z). Exact rotations come
/// back unchanged up to rounding.
pub(crate) fn orthonormalize(m: &Matrix3<f64>) -> Matrix3<f64> {
    let z = m.column(2).normalize();
    let y0 = m.column(1).into_owned();
    let y = (y0 - z * z.dot(&y0)).normalize();
    let x = y.cross(&z);
    Matrix3::from_columns(&[x, y, z])
}

impl Kinematics {
    /// ValidFrame: `goal` with its position kept and its orientation turned
    /// by the smallest angle (Rodrigues) into one this 5-axis arm can take
    /// with `tool` (Schweikard & Hommel 1988; robots.md).
    ///
    /// The arm reaches an orientation when the flange axis (the TCP frame's
    /// `tool^-1` z axis; the approach vector for the standard tool) lies in
    /// the vertical plane through the waist axis and the TCP. That vector is
    /// projected into the plane and the whole frame turned by the angle
    /// between them. No other reachable orientation is closer: any rotation
    /// moves the vector by at most its own angle.
    ///
    /// Degenerate cases (documented in `docs/kinematics.md`):
    /// - TCP on the waist axis (within [`tolerance::AXIS`]): every
    ///   orientation is reachable there (J1 turns to the approach's plane);
    ///   the frame comes back unchanged (only orthonormalised).
    /// - Approach exactly perpendicular to the plane: all in-plane directions
    ///   are 90 degrees away; the frame turns about the vertical so that the
    ///   approach points horizontally away from the waist axis.
    /// - A tool whose TCP is off the flange axis: the plane runs through the
    ///   flange, which moves when the orientation changes; the projection is
    ///   repeated until it settles, then a local search over reachable
    ///   orientations turns it nearer the goal while it can (the settled
    ///   point alone can be off by a fraction of a degree): locally nearest,
    ///   not proven globally; `NoValidOrientation` if the projection does not
    ///   settle (flange crossing the waist axis).
    ///
    /// Errors: `goal` or `tool` not a rigid transform (`FrameInvalid`).
    pub fn valid_frame(&self, goal: &Pose, tool: &Pose) -> Result<Pose, KinError> {
        goal.check_rigid("frame")?;
        tool.check_rigid("tool transform")?;
        let rotation = orthonormalize(&goal.rotation);
        let tool_rot = orthonormalize(&tool.rotation);
        let p = goal.translation;
        if Self::tool_on_axis(tool) {
            // The flange axis in base coordinates: R * Rt^T * e3.
            let axis = rotation * tool_rot.row(2).transpose();
            let turn = into_plane(&axis, &p);
            return Ok(Pose::new(turn * rotation, p));
        }
        let t = tool.translation;
        // The fixed point of the projection is reachable but not always the
        // nearest: descend from it over reachable orientations (a pattern
        // search, each trial turned back into reachability by the same
        // projection) while the angle to the goal shrinks.
        let mut best = settle(&(rotation * tool_rot.transpose()), &t, &p)?;
        // The Frobenius distance between two rotations is 2 sqrt 2 sin(a / 2)
        // for the angle a between them: it orders candidates as the angle
        // does, exactly for small angles too (where the trace's acos is not).
        let distance_of = |flange: &Matrix3<f64>| (rotation - flange * tool_rot).norm();
        let mut best_distance = distance_of(&best);
        let mut step = 0.05;
        let mut rounds = 0;
        while step > 1e-9 && rounds < 2000 {
            rounds += 1;
            let mut improved = false;
            for axis in [
                Vector3::x(),
                -Vector3::x(),
                Vector3::y(),
                -Vector3::y(),
                Vector3::z(),
                -Vector3::z(),
            ] {
                let nudge = nalgebra::Rotation3::from_scaled_axis(axis * step).into_inner();
                if let Ok(candidate) = settle(&(nudge * best), &t, &p) {
                    let a = distance_of(&candidate);
                    if a < best_distance {
                        best = candidate;
                        best_distance = a;
                        improved = true;
                    }
                }
            }
            if !improved {
                step *= 0.5;
            }
        }
        Ok(Pose::new(best * tool_rot, p))
    }
}

/// The flange orientation nearest `flange_rot` whose axis lies in the
/// vertical plane through the waist axis and the flange (at `p - R t` for
/// the TCP `p` and the tool offset `t`): the projection repeated until it
/// settles (up to 200 rounds), or `NoValidOrientation`.
fn settle(
    flange_rot: &Matrix3<f64>,
    t: &Vector3<f64>,
    p: &Vector3<f64>,
) -> Result<Matrix3<f64>, KinError> {
    let mut flange_rot = *flange_rot;
    let mut residual = f64::INFINITY;
    for _ in 0..200 {
        let flange_pos = p - flange_rot * t;
        let axis: Vector3<f64> = flange_rot.column(2).into_owned();
        let turn = into_plane(&axis, &flange_pos);
        flange_rot = orthonormalize(&(turn * flange_rot));
        let new_pos = p - flange_rot * t;
        residual = out_of_plane(&flange_rot.column(2).into_owned(), &new_pos);
        if residual <= 1e-14 {
            break;
        }
    }
    if residual <= tolerance::PLANE {
        Ok(flange_rot)
    } else {
        Err(KinError::NoValidOrientation { residual })
    }
}

/// Angle (rad) between `v` and the vertical plane through the waist axis and
/// `c`; 0 when `c` is on the axis.
pub(crate) fn out_of_plane(v: &Vector3<f64>, c: &Vector3<f64>) -> f64 {
    let cxy = (c.x * c.x + c.y * c.y).sqrt();
    if cxy <= tolerance::AXIS {
        return 0.0;
    }
    let m = Vector3::new(-c.y / cxy, c.x / cxy, 0.0);
    (v.dot(&m) / v.norm()).clamp(-1.0, 1.0).asin().abs()
}
