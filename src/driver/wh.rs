//! The `WH` pose (`x,y,z,p,r`: TCP in mm, tool elevation and roll in
//! degrees) to and from joints, shared by the serial driver and the
//! virtual controller. `p = 90 - (J2 + J3 + J4)`, `r = J5` (robots.md).

use crate::kinematics::{Arm, Elbow, Joints, KinError, Kinematics, Pose};

/// The tool of `TL length`: along the tool axis.
pub fn tool(length: f64) -> Pose {
    Pose::from_translation(0.0, 0.0, length)
}

/// The `WH` reply for joints `q` with tool length `tl`.
pub fn of_joints(kin: &Kinematics, q: &Joints, tl: f64) -> [f64; 5] {
    let p = kin.fk_tcp(q, &tool(tl));
    let c = kin.description().to_controller_deg(q);
    [
        p.translation[0],
        p.translation[1],
        p.translation[2],
        90.0 - (c[1] + c[2] + c[3]),
        c[4],
    ]
}

/// The joints of a `WH` pose: the inverse-kinematics branch nearest `near`.
pub fn to_joints(
    kin: &Kinematics,
    wh: &[f64; 5],
    tl: f64,
    near: &Joints,
) -> Result<Joints, KinError> {
    let [x, y, z, p, r] = *wh;
    let j1 = if x.hypot(y) < 1e-6 {
        near[0]
    } else {
        y.atan2(x)
    };
    let psi = (90.0 - p).to_radians();
    let rot = Pose::rot_z(j1) * Pose::rot_y(psi) * Pose::rot_z(r.to_radians());
    let goal = Pose::new(rot.rotation, nalgebra::Vector3::new(x, y, z));
    kin.ik_choose(&goal, &tool(tl), near, Arm::None, Elbow::None)
        .map(|s| s.joints)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::{RobotDescription, joints_from_deg};

    #[test]
    fn wh_round_trips_through_the_nearest_branch() {
        let kin = Kinematics::new(RobotDescription::builtin("rv-m1").unwrap());
        for q in [
            joints_from_deg([0.0, 0.0, 90.0, 90.0, 0.0]),
            joints_from_deg([10.0, 5.0, 90.0, 90.0, 0.0]),
            joints_from_deg([30.0, 20.0, 60.0, -10.0, 45.0]),
            joints_from_deg([-100.0, 50.0, 30.0, 40.0, -170.0]),
        ] {
            let wh = of_joints(&kin, &q, 107.0);
            let back = to_joints(&kin, &wh, 107.0, &q).unwrap();
            for (a, b) in q.iter().zip(back) {
                assert!((a - b).abs() < 1e-9, "{q:?} -> {wh:?} -> {back:?}");
            }
        }
    }
}
