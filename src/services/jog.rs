//! The teach pendant: the `TeachBox` service, and the jogs it (and the
//! REPL's `:jog`) drives.

use super::*;

/// The trace lines written while the teach pendant is open.
#[derive(Clone, Default)]
pub(super) struct Held(pub(super) Rc<std::cell::RefCell<Vec<u8>>>);

impl Write for Held {
    fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
        self.0.borrow_mut().extend_from_slice(b);
        Ok(b.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// The arm's pose as it is now, before the teach pendant computes a jog:
/// on a real arm that may have been moved by hand, a fresh `WH` (as every
/// motion service reads it, robots.md "The arm moved outside the program").
pub fn fresh_pose(st: &mut RobotState) -> Result<(), String> {
    st.robot.refresh().map_err(|e| e.to_string())
}

/// A jog of the teach pendant to `target`: checked against the limits
/// before anything is sent (on a real arm each jog is one motion, checked
/// on its own), timed at the current velocity, driven, clocked, recorded
/// (`--record`, `--plot`, the REPL's `:record`) and traced like a
/// program's joint motion.
pub fn jog(st: &mut RobotState, clock: &mut dyn Clock, target: Joints) -> Result<(), String> {
    let from = st.robot.joints();
    let desc = st.kin.description();
    desc.check_limits(&target).map_err(|v| v.to_string())?;
    let d = MotionProfile::plan(&from, &target, st.velocity, desc, None)
        .map_err(|e| e.to_string())?
        .duration();
    let start = clock.now();
    record::announce(st, start, &from, &[target], d);
    st.robot
        .move_joints(&[target], d)
        .map_err(|e| e.to_string())?;
    if !st.robot.real_time() {
        clock.sleep(d);
    }
    record::motion(st, start, &from, &[target], d);
    if st.trace.is_some() {
        let to = st.robot.joints();
        let (p, q) = (tcp_mm(st, &from), tcp_mm(st, &to));
        if let Some(t) = &mut st.trace {
            let _ = writeln!(
                t,
                "[t={start:9.3} s] TeachBox jog: {} -> {} deg, TCP {p} -> {q} mm, {d:.3} s",
                deg5(&from),
                deg5(&to)
            );
        }
    }
    Ok(())
}

/// The teach pendant's hand key: open fully, or close with the force
/// setting; clocked, recorded and traced as `MoveTool` is. Returns the
/// hand's reading.
pub fn jog_hand(
    st: &mut RobotState,
    clock: &mut dyn Clock,
    open: bool,
) -> Result<crate::driver::GripperState, String> {
    let g = *st.kin.description().gripper();
    let before = st.robot.gripper();
    let moved = if open {
        st.robot.move_gripper(g.opening_max, None)
    } else {
        st.robot.move_gripper(g.opening_min, Some(st.force_setting))
    }
    .map_err(|e| e.to_string())?;
    // The jaws move at 100 mm/s at full velocity (as `MoveTool`).
    let d = (before.opening - moved.opening).abs() / (100.0 * st.velocity / 100.0).max(1e-6);
    let start = clock.now();
    if !st.robot.real_time() {
        clock.sleep(d);
    }
    record::point(st, clock.now());
    let reading = grip_reading(st);
    if let Some(tr) = &mut st.trace {
        let _ = writeln!(
            tr,
            "[t={start:9.3} s] TeachBox hand: opening {:.1} -> {:.1} mm, force {:.1} N",
            before.opening, reading.opening, reading.force
        );
    }
    Ok(reading)
}

pub(super) fn teach_box(cx: &mut Cx, st: &mut RobotState, a: &mut [Value]) -> R<Option<Value>> {
    let text = a[0].text();
    let (refresh, clear) = (a[1].int() != 0, a[2].int() != 0);
    // The pendant shows the arm where it is (a real one may have been
    // moved by hand).
    require_fresh_pose(cx, st, "TeachBox")?;
    if text.chars().count() > 60 || text.chars().any(|c| c.is_control()) {
        let msg = match text.chars().position(|c| c.is_control()) {
            Some(i) => format!(
                "the text has a control character at position {} (none allowed)",
                i + 1
            ),
            None => format!(
                "the text has {} characters (at most 60)",
                text.chars().count()
            ),
        };
        return Err(fail(st, "TeachBox", Exc::UserInfoInvalid, msg));
    }
    if st.rehearsal {
        return Err(fail(
            st,
            "TeachBox",
            Exc::CommandNotSupported,
            "the TeachBox cannot be rehearsed: its jogs are the operator's (the REPL's :teach runs on the arm without a rehearsal, each jog checked against the limits before it is sent)".into(),
        ));
    }
    let Some(mut p) = st.pendant.take() else {
        return Err(fail(
            st,
            "TeachBox",
            Exc::CommandNotSupported,
            "the TeachBox needs an interactive terminal (run the program from a terminal, or use the REPL's :teach)".into(),
        ));
    };
    // Trace lines are held while the pendant has the screen, and written
    // when it has closed: written over the pendant they would corrupt what
    // it shows (a joint's value among them).
    let held = Held::default();
    let trace = st.trace.take();
    if trace.is_some() {
        st.trace = Some(Box::new(held.clone()));
    }
    let opened = cx.clock.now();
    let wall = std::time::Instant::now();
    let result = p.teach(st, &mut *cx.clock, &text, refresh, clear);
    st.pendant = Some(p);
    st.trace = trace;
    if let Some(t) = &mut st.trace {
        let _ = t.write_all(&held.0.borrow());
        let _ = t.flush();
    }
    // The box was open, on the program's clock, for as long as the
    // operator kept it open (and at least as long as its jogs take): with
    // tasks, another task that moves the arm meanwhile meets `RobotBusy`.
    let rest = wall.elapsed().as_secs_f64() - (cx.clock.now() - opened);
    if rest > 0.0 {
        cx.clock.sleep(rest);
    }
    st.teach_until = cx.clock.now();
    match result {
        Ok(()) => Ok(None),
        Err(msg) => Err(fail(st, "TeachBox", Exc::CommandNotSupported, msg)),
    }
}
