//! The read-back services (`Value*`, `ValidFrame`).

use super::*;

pub(super) fn value_robot_config(
    cx: &mut Cx,
    st: &mut RobotState,
    a: &mut [Value],
) -> R<Option<Value>> {
    require_fresh_pose(cx, st, "ValueRobotConfig")?;
    let (arm, elbow) = st.kin.config_of(&st.robot.read_joints());
    a[0] = Value::Int(match arm {
        Arm::Forward => 0,
        Arm::Backward => 1,
        Arm::None => 2,
    });
    a[1] = Value::Int(match elbow {
        Elbow::Above => 0,
        Elbow::Below => 1,
        Elbow::None => 2,
    });
    // A 5-axis wrist never flips.
    a[2] = Value::Int(1);
    Ok(None)
}

/// The gripper as every reader reports it (`ValueTool`, the trace, the
/// TeachBox): the opening, and the grip force. The grip force is the
/// handbook's *Greifkraft*, a setting: `InitToolForce` after `InitRobot`,
/// the `Force` of the last `MoveTool`; while the jaws press on something it
/// is the force they press with. Without a force sensor it reads 0.0.
pub fn grip_reading(st: &RobotState) -> crate::driver::GripperState {
    let mut g = st.robot.gripper();
    let t = &st.tool;
    g.force = if t.force_min == 0.0 && t.force_max == 0.0 {
        0.0
    } else if g.force > 0.0 {
        g.force
    } else {
        st.force_setting
    };
    g
}

pub(super) fn tool_value(st: &RobotState) -> Value {
    let g = grip_reading(st);

    Value::record(smallvec::smallvec![
        frame_value(&st.tool.trans),
        Value::Real(st.tool.force_min),
        Value::Real(st.tool.force_max),
        Value::Real(g.force),
        Value::Real(st.tool.dist_min),
        Value::Real(st.tool.dist_max),
        Value::Real(g.opening),
    ])
}

pub(super) fn value_tool(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    require_init(cx, st, "ValueTool")?;
    a[0] = tool_value(st);
    Ok(None)
}

pub(super) fn value_tool_f(cx: &mut Cx, st: &mut RobotState, _a: &mut [Value]) -> R<Option<Value>> {
    require_init(cx, st, "ValueTool")?;
    Ok(Some(tool_value(st)))
}

pub(super) fn valid_frame(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let f = Pose::from_rows(frame_rows(&a[0]));
    require_init(cx, st, "ValidFrame")?;
    match st.kin.valid_frame(&f, &st.tool.trans) {
        Ok(v) => {
            a[0] = frame_value(&v);
            Ok(None)
        }
        Err(e) => Err(kin_fail(st, "ValidFrame", &e)),
    }
}

pub(super) fn value_axes(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let v = value_axes_f(cx, st, a)?;
    a[0] = v.unwrap_or_default();
    Ok(None)
}

pub(super) fn value_axes_f(cx: &mut Cx, st: &mut RobotState, _a: &mut [Value]) -> R<Option<Value>> {
    require_fresh_pose(cx, st, "ValueAxes")?;
    Ok(Some(axes_value(&st.robot.read_joints())))
}

/// The tool centre point at joints `q`, `(x, y, z)` in mm, for the trace.
pub(super) fn tcp_mm(st: &RobotState, q: &Joints) -> String {
    let p = st.kin.fk_tcp(q, &st.tool.trans).translation;
    format!("({:.1}, {:.1}, {:.1})", p.x, p.y, p.z)
}

pub(super) fn current_frame(st: &RobotState) -> Pose {
    st.kin.fk_tcp(&st.robot.read_joints(), &st.tool.trans)
}

pub(super) fn value_frame_absolute(
    cx: &mut Cx,
    st: &mut RobotState,
    a: &mut [Value],
) -> R<Option<Value>> {
    a[0] = value_frame_absolute_f(cx, st, a)?.unwrap_or_default();
    Ok(None)
}

pub(super) fn value_frame_absolute_f(
    cx: &mut Cx,
    st: &mut RobotState,
    _a: &mut [Value],
) -> R<Option<Value>> {
    require_fresh_pose(cx, st, "ValueFrameAbsolute")?;
    Ok(Some(frame_value(&current_frame(st))))
}

pub(super) fn value_frame_relative(
    cx: &mut Cx,
    st: &mut RobotState,
    a: &mut [Value],
) -> R<Option<Value>> {
    a[0] = value_frame_relative_f(cx, st, a)?.unwrap_or_default();
    Ok(None)
}

pub(super) fn value_frame_relative_f(
    cx: &mut Cx,
    st: &mut RobotState,
    _a: &mut [Value],
) -> R<Option<Value>> {
    require_fresh_pose(cx, st, "ValueFrameRelative")?;
    Ok(Some(frame_value(&(st.base.inverse() * current_frame(st)))))
}

pub(super) fn value_error_status(
    cx: &mut Cx,
    st: &mut RobotState,
    a: &mut [Value],
) -> R<Option<Value>> {
    a[0] = value_error_status_f(cx, st, a)?.unwrap_or_default();
    Ok(None)
}

pub(super) fn value_error_status_f(
    cx: &mut Cx,
    st: &mut RobotState,
    _a: &mut [Value],
) -> R<Option<Value>> {
    // Always answers, before InitRobot too: a handler must be able to ask
    // which service raised, SystemNotInitialized included.
    wait_for_control(cx, st, "ValueErrorStatus")?;
    Ok(Some(Value::Int(st.error_status)))
}
