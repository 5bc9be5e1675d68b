//! Homogeneous transforms.

use nalgebra::{Matrix3, Matrix4, Rotation3, UnitQuaternion, Vector3};

use super::error::KinError;
use super::tolerance;

/// A homogeneous transform: a 3x3 rotation and a translation (mm).
///
/// A `Pose` may hold any matrix (a user's `Frame` is not checked when it is
/// converted); [`Pose::check_rigid`] tells whether it is a rigid transform.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    /// Rotation part; columns are the frame's x (n), y (o) and z (approach)
    /// axes in base coordinates.
    pub rotation: Matrix3<f64>,
    /// Position of the frame's origin in base coordinates, mm.
    pub translation: Vector3<f64>,
}

impl Default for Pose {
    fn default() -> Self {
        Pose::identity()
    }
}

impl Pose {
    /// The identity transform.
    pub fn identity() -> Self {
        Pose {
            rotation: Matrix3::identity(),
            translation: Vector3::zeros(),
        }
    }

    /// A pose from its parts.
    pub fn new(rotation: Matrix3<f64>, translation: Vector3<f64>) -> Self {
        Pose {
            rotation,
            translation,
        }
    }

    /// A pure translation.
    pub fn from_translation(x: f64, y: f64, z: f64) -> Self {
        Pose::new(Matrix3::identity(), Vector3::new(x, y, z))
    }

    /// Rotation about the x axis by `angle` radians.
    pub fn rot_x(angle: f64) -> Self {
        let (s, c) = angle.sin_cos();
        Pose::new(
            Matrix3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c),
            Vector3::zeros(),
        )
    }

    /// Rotation about the y axis by `angle` radians.
    pub fn rot_y(angle: f64) -> Self {
        let (s, c) = angle.sin_cos();
        Pose::new(
            Matrix3::new(c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c),
            Vector3::zeros(),
        )
    }

    /// Rotation about the z axis by `angle` radians.
    pub fn rot_z(angle: f64) -> Self {
        let (s, c) = angle.sin_cos();
        Pose::new(
            Matrix3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0),
            Vector3::zeros(),
        )
    }

    /// From the AdaIR `Frame`: 3 rows of 4, rotation | position.
    pub fn from_rows(rows: [[f64; 4]; 3]) -> Self {
        let r = |i: usize, j: usize| rows[i][j];
        Pose::new(
            Matrix3::new(
                r(0, 0),
                r(0, 1),
                r(0, 2),
                r(1, 0),
                r(1, 1),
                r(1, 2),
                r(2, 0),
                r(2, 1),
                r(2, 2),
            ),
            Vector3::new(r(0, 3), r(1, 3), r(2, 3)),
        )
    }

    /// To the AdaIR `Frame`: 3 rows of 4, rotation | position.
    pub fn to_rows(&self) -> [[f64; 4]; 3] {
        let mut rows = [[0.0; 4]; 3];
        for (i, row) in rows.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().take(3).enumerate() {
                *v = self.rotation[(i, j)];
            }
            row[3] = self.translation[i];
        }
        rows
    }

    /// From a 4x4 homogeneous matrix (the bottom row is ignored).
    pub fn from_matrix4(m: &Matrix4<f64>) -> Self {
        Pose::new(
            m.fixed_view::<3, 3>(0, 0).into_owned(),
            m.fixed_view::<3, 1>(0, 3).into_owned(),
        )
    }

    /// The 4x4 homogeneous matrix.
    pub fn to_matrix4(&self) -> Matrix4<f64> {
        let mut m = Matrix4::identity();
        m.fixed_view_mut::<3, 3>(0, 0).copy_from(&self.rotation);
        m.fixed_view_mut::<3, 1>(0, 3).copy_from(&self.translation);
        m
    }

    /// Inverse of a rigid transform (`R^T`, `-R^T p`). For a matrix that is
    /// not rigid this is not the matrix inverse; check first.
    pub fn inverse(&self) -> Pose {
        let rt = self.rotation.transpose();
        Pose::new(rt, -(rt * self.translation))
    }

    /// Approach vector (third column of the rotation).
    pub fn approach(&self) -> Vector3<f64> {
        self.rotation.column(2).into_owned()
    }

    /// `Ok` when every entry is finite and the rotation is orthonormal with
    /// determinant +1 within [`tolerance::ORTHONORMAL`]; else
    /// [`KinError::NotFinite`], [`KinError::NotOrthonormal`] or
    /// [`KinError::NotRightHanded`] (all `FrameInvalid`).
    pub fn check_rigid(&self, what: &'static str) -> Result<(), KinError> {
        if self.rotation.iter().any(|v| !v.is_finite())
            || self.translation.iter().any(|v| !v.is_finite())
        {
            return Err(KinError::NotFinite { what });
        }
        let gram = self.rotation.transpose() * self.rotation - Matrix3::identity();
        let deviation = gram.amax();
        if deviation > tolerance::ORTHONORMAL {
            return Err(KinError::NotOrthonormal { what, deviation });
        }
        let det = self.rotation.determinant();
        if (det - 1.0).abs() > tolerance::ORTHONORMAL {
            return Err(KinError::NotRightHanded { what, det });
        }
        Ok(())
    }

    /// The rotation as a unit quaternion (of the orthonormalised rotation
    /// when the matrix is only nearly orthonormal).
    pub fn quaternion(&self) -> UnitQuaternion<f64> {
        let rot = Rotation3::from_matrix_unchecked(super::valid::orthonormalize(&self.rotation));
        UnitQuaternion::from_rotation_matrix(&rot)
    }

    /// Angle (rad) of the rotation that turns `self`'s orientation into
    /// `other`'s, for rigid poses.
    pub fn rotation_angle_to(&self, other: &Pose) -> f64 {
        let d = self.rotation.transpose() * other.rotation;
        // Via the antisymmetric part and the trace: accurate near 0 and pi.
        let s = Vector3::new(
            d[(2, 1)] - d[(1, 2)],
            d[(0, 2)] - d[(2, 0)],
            d[(1, 0)] - d[(0, 1)],
        )
        .norm()
            / 2.0;
        let c = (d.trace() - 1.0) / 2.0;
        s.atan2(c)
    }
}

impl std::ops::Mul for Pose {
    type Output = Pose;

    /// Homogeneous product.
    fn mul(self, other: Pose) -> Pose {
        Pose::new(
            self.rotation * other.rotation,
            self.rotation * other.translation + self.translation,
        )
    }
}
