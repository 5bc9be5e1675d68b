//! The motion services' bodies and what they share: options, planning,
//! execution, trace.

use super::*;

/// Motion options common to every motion service.
pub(super) struct MotionOpts {
    pub(super) time: Option<f64>,
    /// `Time` as given (0.0 = as fast as the velocity allows).
    pub(super) time_arg: f64,
    pub(super) control: bool,
    pub(super) realtime: bool,
}

pub(super) fn opts(a: &[Value], first: usize) -> MotionOpts {
    let t = a.get(first).map(|v| v.real()).unwrap_or(0.0);
    MotionOpts {
        time: if t > 0.0 { Some(t) } else { None },
        time_arg: t,
        control: a.get(first + 1).is_some_and(|v| v.int() != 0),
        realtime: a.get(first + 2).is_some_and(|v| v.int() != 0),
    }
}

/// `require_init` for a motion service, and its `Time`: a NaN, an infinite
/// or a negative duration is `TimeInvalid` before anything moves.
pub(super) fn require_motion(
    cx: &mut Cx,
    st: &mut RobotState,
    service: &str,
    o: &MotionOpts,
) -> R<()> {
    require_fresh_pose(cx, st, service)?;
    let t = o.time_arg;
    if !t.is_finite() || t < 0.0 {
        return Err(fail(
            st,
            service,
            Exc::TimeInvalid,
            format!("Time => {t} s: a duration must be a finite number of seconds, 0.0 or more"),
        ));
    }
    Ok(())
}

/// Executes a planned joint motion: driver, clock, trace.
pub(super) fn perform(
    cx: &mut Cx,
    st: &mut RobotState,
    service: &str,
    points: &[Joints],
    duration: f64,
    o: &MotionOpts,
) -> R<()> {
    let before = st.robot.joints();
    let real = st.robot.real_time();
    if cx.interrupt_requested() {
        return Err(stop(cx, st, service, "before the motion started"));
    }
    st.refused = None;
    record::announce(st, cx.clock.now(), &before, points, duration);
    // Paced to the wall clock: the user can stop the motion (Ctrl-C); the
    // robot then stays where it had got to. A real arm takes its own time.
    if (o.realtime || st.realtime) && !o.control && !real {
        let done = cx.pace(duration);
        if done < 1.0 {
            let reached = interpolate(&before, points, done);
            let _ = st.robot.move_joints(&[reached], duration * done);
            // The recording holds the motion up to where the arm stopped.
            let start = cx.clock.now();
            record::motion(st, start, &before, points, duration);
            record::cut(st, start + duration * done, reached);
            cx.clock.sleep(duration * done);
            let what = format!("after {:.3} of {duration:.3} s", duration * done);
            return Err(stop(cx, st, service, &what));
        }
    }
    let start = cx.clock.now();
    let started = if o.time.is_some() {
        st.robot.start_timed_motion(points, duration)
    } else {
        st.robot.start_motion(points, duration)
    };
    if let Err(e) = started {
        return Err(driver_fail(st, service, e));
    }
    if real {
        // A real arm takes its own (wall-clock) time: wait for its end,
        // unless the program goes on computing (`Control => True`).
        if !o.control {
            match st.robot.wait_motion() {
                Ok(()) => {
                    // The unit reports the end (the RV-M1's `ER` reply)
                    // before the end adair planned: the motion ends there,
                    // at its target, for the recording and the live view.
                    let now = cx.clock.now();
                    if now < start + duration {
                        record::motion(st, start, &before, points, duration);
                        record::cut(st, now, st.robot.joints());
                        trace_motion(cx, st, service, start, &before, duration);
                        return Ok(());
                    }
                }
                Err(crate::driver::DriverError::Interrupted) => {
                    let _ = st.robot.stop_motion();
                    // Recorded up to the stop, ending at the target of the
                    // line the unit finishes.
                    let now = cx.clock.now();
                    record::motion(st, start, &before, points, duration);
                    record::cut(st, now, st.robot.joints());
                    let what = format!(
                        "{:.3} s into the motion; the unit finishes the line it has",
                        now - start
                    );
                    return Err(stop(cx, st, service, &what));
                }
                Err(e) => {
                    let fault = driver_fail(st, service, e);
                    // The motion ends where the driver reports the arm
                    // after the fault (it read `WH` again when it could).
                    record::motion(st, start, &before, points, duration);
                    record::cut(st, cx.clock.now(), st.robot.joints());
                    return Err(fault);
                }
            }
        }
    } else if o.control {
        // As the clock counts it: whole nanoseconds (value::whole_ns).
        st.busy_until = crate::interp::value::whole_ns(start + duration);
        st.busy_paced =
            (o.realtime || st.realtime).then(|| (start, duration, before, points.to_vec()));
    } else {
        cx.clock.sleep(duration);
    }
    record::motion(st, start, &before, points, duration);
    trace_motion(cx, st, service, start, &before, duration);
    Ok(())
}

/// The `--trace` line of a motion that ran.
pub(super) fn trace_motion(
    cx: &mut Cx,
    st: &mut RobotState,
    service: &str,
    start: f64,
    before: &Joints,
    duration: f64,
) {
    if st.trace.is_some() {
        let after = st.robot.joints();
        let (from, to) = (tcp_mm(st, before), tcp_mm(st, &after));
        if let Some(t) = &mut st.trace {
            let _ = writeln!(
                t,
                "[t={start:9.3} s] {service} at {}: {} -> {} deg, TCP {from} -> {to} mm, {duration:.3} s",
                cx.here(),
                deg5(before),
                deg5(&after)
            );
        }
    }
}

/// The joints a fraction of the way along a motion through `points`.
pub(super) fn interpolate(from: &Joints, points: &[Joints], fraction: f64) -> Joints {
    let n = points.len();
    if n == 0 {
        return *from;
    }
    let x = fraction.clamp(0.0, 1.0) * n as f64;
    let i = (x.floor() as usize).min(n - 1);
    let a = if i == 0 { *from } else { points[i - 1] };
    let b = points[i];
    let t = x - i as f64;
    let mut q = a;
    for j in 0..q.len() {
        q[j] = a[j] + (b[j] - a[j]) * t;
    }
    q
}

/// Plans a point-to-point joint motion to `target`.
pub(super) fn plan(st: &mut RobotState, service: &str, target: &Joints, o: &MotionOpts) -> R<f64> {
    let from = st.robot.joints();
    // With `Time`, the motion may use the robot's full speed.
    let velocity = if o.time.is_some() { 100.0 } else { st.velocity };
    match MotionProfile::plan(&from, target, velocity, st.kin.description(), o.time) {
        Ok(p) => Ok(p.duration()),
        Err(e) => Err(kin_fail(st, service, &e)),
    }
}

/// The duration of a path through support points at the current velocity.
pub(super) fn path_duration(
    st: &RobotState,
    from: &Joints,
    points: &[Joints],
    velocity: f64,
) -> f64 {
    let desc = st.kin.description();
    let mut t = 0.0;
    let mut prev = *from;
    for p in points {
        let mut seg: f64 = 0.0;
        for (j, spec) in desc.joints().iter().enumerate() {
            let v = spec.max_speed * velocity / 100.0;
            if v > 0.0 {
                seg = seg.max((p[j] - prev[j]).abs() / v);
            }
        }
        t += seg;
        prev = *p;
    }
    t
}

/// Solves a frame goal in the current move mode: the support points to go through.
pub(super) fn frame_motion(
    st: &RobotState,
    from: &Joints,
    goal: &Pose,
) -> Result<Vec<Joints>, KinError> {
    if st.straight {
        st.kin
            .straight_line(from, goal, &st.tool.trans, st.interpolation)
    } else {
        st.kin
            .ik_choose(goal, &st.tool.trans, from, st.arm, st.elbow)
            .map(|s| vec![s.joints])
    }
}

pub(super) fn move_frame(
    cx: &mut Cx,
    st: &mut RobotState,
    service: &str,
    goal: Pose,
    o: MotionOpts,
) -> R<Option<Value>> {
    let from = st.robot.joints();
    let points = match frame_motion(st, &from, &goal) {
        Ok(p) => p,
        Err(e) => {
            st.refused = Some((cx.clock.now(), goal));
            return Err(kin_fail(st, service, &e));
        }
    };
    let duration = if st.straight {
        let d = path_duration(
            st,
            &from,
            &points,
            if o.time.is_some() { 100.0 } else { st.velocity },
        );
        match o.time {
            Some(t) if t + 1e-9 < d => {
                return Err(fail(
                    st,
                    service,
                    Exc::TimeInvalid,
                    format!("Time => {t:.3} s is shorter than the fastest straight line, {d:.3} s"),
                ));
            }
            Some(t) => t,
            None => d,
        }
    } else {
        let target = points[points.len() - 1];
        plan(st, service, &target, &o)?
    };
    perform(cx, st, service, &points, duration, &o)?;
    Ok(None)
}

/// Gripper motion, with the handbook's fallbacks for missing sensors: without
/// a distance sensor (DistMin = DistMax = 0) any distance above 0.0 opens
/// fully and 0.0 closes; without a force sensor (ForceMin = ForceMax = 0)
/// only the distance counts. The distance wins over the force.
pub(super) fn move_tool(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let (dist, force) = (a[0].real(), a[1].real());
    require_init(cx, st, "MoveTool")?;
    let t = st.tool;
    let has_dist = !(t.dist_min == 0.0 && t.dist_max == 0.0);
    let has_force = !(t.force_min == 0.0 && t.force_max == 0.0);
    if has_dist && (dist < t.dist_min || dist > t.dist_max) {
        return Err(fail(
            st,
            "MoveTool",
            Exc::DistanceInvalid,
            format!(
                "distance {dist:.1} mm outside {:.1} .. {:.1} mm",
                t.dist_min, t.dist_max
            ),
        ));
    }
    if has_force && (force < t.force_min || force > t.force_max) {
        return Err(fail(
            st,
            "MoveTool",
            Exc::ForceInvalid,
            format!(
                "force {force:.1} N outside {:.1} .. {:.1} N",
                t.force_min, t.force_max
            ),
        ));
    }
    let g = *st.kin.description().gripper();
    let target = if has_dist {
        dist
    } else if dist > 0.0 {
        g.opening_max
    } else {
        g.opening_min
    };
    let limit = if has_force { Some(force) } else { None };
    if has_force {
        st.force_setting = force;
    }
    let before = st.robot.gripper();
    // The simulated devices' objects (tasks.md): closing on one whose
    // centre is at the TCP picks it, opening puts it down there.
    let tcp = current_frame(st).translation;
    let at = [tcp.x, tcp.y, tcp.z];
    let closing = target < before.opening;
    let mut grasp = None;
    if closing
        && st.held.is_none()
        && let Some(w) = cx.world.as_deref()
        && let Some(o) = w.object_at(at, crate::devices::GRIP_TOLERANCE_MM)
        && o.width <= before.opening
        && let Some(sim) = st.robot.as_simulator()
        && sim.place_object(o.width).is_ok()
    {
        grasp = Some(o.name);
    }
    let moved = st.robot.move_gripper(target, limit);
    // The jaws move at 100 mm/s at full velocity.
    let jaw_time = |g: &crate::driver::GripperState| {
        (before.opening - g.opening).abs() / (100.0 * st.velocity / 100.0).max(1e-6)
    };
    if let (Some(name), Ok(g)) = (&grasp, &moved)
        && let Some(w) = cx.world.as_deref_mut()
    {
        let width = w
            .objects()
            .iter()
            .find(|o| &o.name == name)
            .map(|o| o.width);
        // The moment the clock reaches after the jaws' motion (it keeps
        // whole nanoseconds), so that the pick happens with that motion.
        let closed_at = crate::interp::value::whole_ns(cx.clock.now() + jaw_time(g));
        if width.is_some_and(|x| (g.opening - x).abs() < 1e-6) && w.pick_at(name, closed_at).is_ok()
        {
            st.held = Some(name.clone());
        }
    }
    if !closing
        && let Ok(g) = &moved
        && let Some(name) = st.held.clone()
        && g.opening > before.opening
        && let Some(w) = cx.world.as_deref_mut()
    {
        let _ = w.put_down(&name, at);
        st.held = None;
        if let Some(sim) = st.robot.as_simulator() {
            let _ = sim.place_object(0.0);
        }
    }
    match moved {
        Ok(g2) => {
            let d = jaw_time(&g2);
            if !st.robot.real_time() {
                cx.clock.sleep(d);
            }
            record::point(st, cx.clock.now());
            let g2 = grip_reading(st);
            if let Some(tr) = &mut st.trace {
                let _ = writeln!(
                    tr,
                    "[t={:9.3} s] MoveTool at {}: opening {:.1} -> {:.1} mm, force {:.1} N",
                    cx.clock.now() - d,
                    cx.here(),
                    before.opening,
                    g2.opening,
                    g2.force
                );
            }
            Ok(None)
        }
        Err(e) => Err(driver_fail(st, "MoveTool", e)),
    }
}

pub(super) fn move_axes_absolute(
    cx: &mut Cx,
    st: &mut RobotState,
    a: &mut [Value],
) -> R<Option<Value>> {
    let axes = axes_of(&a[0]);
    let o = opts(a, 1);
    require_motion(cx, st, "MoveAxesAbsolute", &o)?;
    let target = match st.kin.joint_target(&axes) {
        Ok(t) => t,
        Err(e) => {
            st.refused = Some((cx.clock.now(), st.kin.fk_tcp(&axes, &st.tool.trans)));
            return Err(kin_fail(st, "MoveAxesAbsolute", &e));
        }
    };
    let d = plan(st, "MoveAxesAbsolute", &target, &o)?;
    perform(cx, st, "MoveAxesAbsolute", &[target], d, &o)?;
    Ok(None)
}

pub(super) fn move_axes_relative(
    cx: &mut Cx,
    st: &mut RobotState,
    a: &mut [Value],
) -> R<Option<Value>> {
    let delta = axes_of(&a[0]);
    let o = opts(a, 1);
    require_motion(cx, st, "MoveAxesRelative", &o)?;
    let current = st.robot.joints();
    let target = match st.kin.relative_joint_target(&current, &delta) {
        Ok(t) => t,
        Err(e) => {
            let mut goal = current;
            for (g, d) in goal.iter_mut().zip(delta) {
                *g += d;
            }
            st.refused = Some((cx.clock.now(), st.kin.fk_tcp(&goal, &st.tool.trans)));
            return Err(kin_fail(st, "MoveAxesRelative", &e));
        }
    };
    let d = plan(st, "MoveAxesRelative", &target, &o)?;
    perform(cx, st, "MoveAxesRelative", &[target], d, &o)?;
    Ok(None)
}

pub(super) fn move_frame_absolute(
    cx: &mut Cx,
    st: &mut RobotState,
    a: &mut [Value],
) -> R<Option<Value>> {
    let goal = Pose::from_rows(frame_rows(&a[0]));
    let o = opts(a, 1);
    require_motion(cx, st, "MoveFrameAbsolute", &o)?;
    move_frame(cx, st, "MoveFrameAbsolute", goal, o)
}

pub(super) fn move_frame_relative(
    cx: &mut Cx,
    st: &mut RobotState,
    a: &mut [Value],
) -> R<Option<Value>> {
    let goal = Pose::from_rows(frame_rows(&a[0]));
    let o = opts(a, 1);
    require_motion(cx, st, "MoveFrameRelative", &o)?;
    let g = st.base * goal;
    move_frame(cx, st, "MoveFrameRelative", g, o)
}
