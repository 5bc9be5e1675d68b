//! Forward kinematics.

use nalgebra::{Matrix3, Vector3};

use super::ik::{Arm, Elbow};
use super::{Joints, Kinematics, Pose};

impl Kinematics {
    /// Pose of the flange for joint vector `q` (robots.md):
    /// `R = Rz(J1) Ry(psi) Rz(J5)`, `psi = J2 + J3 + J4`, position in the
    /// arm plane at `r = L2 sin J2 + L3 sin(J2+J3) + L4 sin psi`,
    /// `z = L1 + L2 cos J2 + L3 cos(J2+J3) + L4 cos psi`.
    pub fn fk_flange(&self, q: &Joints) -> Pose {
        let l = self.desc.links();
        let (s1, c1) = q[0].sin_cos();
        let (s2, c2) = q[1].sin_cos();
        let (s23, c23) = (q[1] + q[2]).sin_cos();
        let (sp, cp) = (q[1] + q[2] + q[3]).sin_cos();
        let (s5, c5) = q[4].sin_cos();
        let r = l.l2 * s2 + l.l3 * s23 + l.l4 * sp;
        let z = l.l1 + l.l2 * c2 + l.l3 * c23 + l.l4 * cp;
        // Ry(psi) Rz(J5), then rotated about z by J1.
        let (a11, a12, a13) = (cp * c5, -cp * s5, sp);
        let (a21, a22) = (s5, c5);
        let rotation = Matrix3::new(
            c1 * a11 - s1 * a21,
            c1 * a12 - s1 * a22,
            c1 * a13,
            s1 * a11 + c1 * a21,
            s1 * a12 + c1 * a22,
            s1 * a13,
            -sp * c5,
            sp * s5,
            cp,
        );
        Pose::new(rotation, Vector3::new(r * c1, r * s1, z))
    }

    /// Pose of the TCP: `fk_flange(q) * tool`.
    pub fn fk_tcp(&self, q: &Joints, tool: &Pose) -> Pose {
        self.fk_flange(q) * *tool
    }

    /// How far the wrist-pitch axis lies from the waist axis in the
    /// direction J1 points (negative behind it), mm.
    pub(crate) fn wrist_reach(&self, q: &Joints) -> f64 {
        let l = self.desc.links();
        l.l2 * q[1].sin() + l.l3 * (q[1] + q[2]).sin()
    }

    /// The configuration (branch) of a joint vector: arm forward when the
    /// wrist point lies in front of the waist axis in the direction J1 points
    /// (r >= 0, on the axis counts as forward); elbow above when J3 >= 0 (J3 taken in -180 .. 180 deg).
    pub fn config_of(&self, q: &Joints) -> (Arm, Elbow) {
        let r = self.wrist_reach(q);
        let arm = if r >= 0.0 {
            Arm::Forward
        } else {
            Arm::Backward
        };
        let elbow = if super::ik::wrap(q[2]) >= 0.0 {
            Elbow::Above
        } else {
            Elbow::Below
        };
        (arm, elbow)
    }
}
