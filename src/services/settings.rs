//! The setting services: `InitRobot`, `EndRobot`, `CalibrateRobot`,
//! `SetVelocity`, `SetTool`, `SetBase`, ... and `PlaceObject`.

use super::*;

pub(super) fn init_robot(cx: &mut Cx, st: &mut RobotState, _a: &mut [Value]) -> R<Option<Value>> {
    // InitRobot moves (to the zero pose): like every motion it waits for a
    // `Control => True` motion still running.
    wait_for_control(cx, st, "InitRobot")?;
    let o = MotionOpts {
        time: None,
        time_arg: 0.0,
        control: false,
        realtime: false,
    };
    if let Err(e) = st.robot.init() {
        return Err(driver_fail(st, "InitRobot", e));
    }
    st.initialized = true;
    st.velocity = 50.0;
    st.straight = false;
    st.interpolation = 1.0;
    st.arm = Arm::None;
    st.elbow = Elbow::None;
    st.hand = 2;
    st.tool = standard_tool(&st.kin);
    st.base = Pose::identity();
    st.busy_until = cx.clock.now();
    if let Err(e) = st.robot.set_speed(st.velocity) {
        st.initialized = false;
        return Err(driver_fail(st, "InitRobot", e));
    }
    let zero = [0.0; 5];
    let d = plan(st, "InitRobot", &zero, &o)?;
    perform(cx, st, "InitRobot", &[zero], d, &o)?;
    let g = *st.kin.description().gripper();
    if let Err(e) = st.robot.move_gripper(g.opening_max, None) {
        return Err(driver_fail(st, "InitRobot", e));
    }
    st.force_setting = g.init_force;
    Ok(None)
}

pub(super) fn end_robot(cx: &mut Cx, st: &mut RobotState, _a: &mut [Value]) -> R<Option<Value>> {
    if !st.initialized {
        return Err(fail(
            st,
            "EndRobot",
            Exc::SystemNotInitialized,
            "EndRobot before InitRobot".into(),
        ));
    }
    let now = cx.clock.now();
    if st.busy_until > now + 1e-12 {
        return Err(fail(
            st,
            "EndRobot",
            Exc::ControlCommandActive,
            format!(
                "a Control => True motion runs until t = {:.3} s (now {now:.3} s)",
                st.busy_until
            ),
        ));
    }
    // The nest (rest) position of the robot description (robots.md).
    let o = MotionOpts {
        time: None,
        time_arg: 0.0,
        control: false,
        realtime: false,
    };
    let nest = st.kin.description().nest();
    let d = plan(st, "EndRobot", &nest, &o)?;
    perform(cx, st, "EndRobot", &[nest], d, &o)?;
    st.initialized = false;
    st.tool = standard_tool(&st.kin);
    st.base = Pose::identity();
    Ok(None)
}

pub(super) fn calibrate(cx: &mut Cx, st: &mut RobotState, _a: &mut [Value]) -> R<Option<Value>> {
    require_init(cx, st, "CalibrateRobot")?;
    if let Err(e) = st.robot.calibrate() {
        return Err(driver_fail(st, "CalibrateRobot", e));
    }
    Ok(None)
}

pub(super) fn set_velocity(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let v = a[0].real();
    require_init(cx, st, "SetVelocity")?;
    if v <= 0.0 {
        return Err(fail(
            st,
            "SetVelocity",
            Exc::ConstraintError,
            format!(
                "velocity {v:.1} % would never arrive: give a velocity above 0.0 %, up to 100.0 %"
            ),
        ));
    }
    if let Err(e) = st.robot.set_speed(v) {
        return Err(driver_fail(st, "SetVelocity", e));
    }
    st.velocity = v;
    Ok(None)
}

pub(super) fn set_move_mode(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let k = a[0].int();
    require_init(cx, st, "SetMoveMode")?;
    st.straight = k == 1;
    Ok(None)
}

pub(super) fn set_interpolation(
    cx: &mut Cx,
    st: &mut RobotState,
    a: &mut [Value],
) -> R<Option<Value>> {
    let w = a[0].real();
    require_init(cx, st, "SetInterpolation")?;
    st.interpolation = w;
    Ok(None)
}

pub(super) fn set_robot_config(
    cx: &mut Cx,
    st: &mut RobotState,
    a: &mut [Value],
) -> R<Option<Value>> {
    let (arm, elbow, hand) = (a[0].int(), a[1].int(), a[2].int());
    require_init(cx, st, "SetRobotConfig")?;
    st.arm = match arm {
        0 => Arm::Forward,
        1 => Arm::Backward,
        _ => Arm::None,
    };
    st.elbow = match elbow {
        0 => Elbow::Above,
        1 => Elbow::Below,
        _ => Elbow::None,
    };
    st.hand = hand;
    Ok(None)
}

pub(super) fn set_tool(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let Some(rec) = a[0].fields() else {
        return Ok(None);
    };
    let trans = Pose::from_rows(frame_rows(&rec[0]));
    let (fmin, fmax, dmin, dmax) = (rec[1].real(), rec[2].real(), rec[4].real(), rec[5].real());
    require_init(cx, st, "SetTool")?;
    if let Err(e) = trans.check_rigid("tool transform") {
        return Err(kin_fail(st, "SetTool", &e));
    }
    if fmin > fmax {
        return Err(fail(
            st,
            "SetTool",
            Exc::ForceInvalid,
            format!("ForceMin {fmin:.1} N is above ForceMax {fmax:.1} N"),
        ));
    }
    if dmin > dmax {
        return Err(fail(
            st,
            "SetTool",
            Exc::DistanceInvalid,
            format!("DistMin {dmin:.1} mm is above DistMax {dmax:.1} mm"),
        ));
    }
    st.tool = Tool {
        trans,
        force_min: fmin,
        force_max: fmax,
        dist_min: dmin,
        dist_max: dmax,
    };
    Ok(None)
}

pub(super) fn set_base(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let base = Pose::from_rows(frame_rows(&a[0]));
    require_init(cx, st, "SetBase")?;
    if let Err(e) = base.check_rigid("base frame") {
        return Err(kin_fail(st, "SetBase", &e));
    }
    st.base = base;
    Ok(None)
}

pub(super) fn place_object(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let w = a[0].real();
    // Like every service but `ValueErrorStatus`: not before `InitRobot`.
    require_init(cx, st, "PlaceObject")?;
    let result = match st.robot.as_simulator() {
        Some(sim) => sim.place_object(w).map_err(|m| (Exc::ConstraintError, m)),
        None => Err((
            Exc::CommandNotSupported,
            "PlaceObject exists only on the simulator: a real hand holds real objects (a rehearsal for a real arm refuses it as the arm would)".into(),
        )),
    };
    match result {
        Ok(()) => Ok(None),
        Err((exc, m)) => Err(fail(st, "PlaceObject", exc, m)),
    }
}
