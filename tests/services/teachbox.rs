//! The TeachBox service with a scripted pendant (no terminal): its jogs are
//! recorded like motions, the trace is held while the pendant has the
//! screen, and another task that moves the arm while the box is open meets
//! `RobotBusy` (tasks.md "Robot services from several tasks").

use adair::golden::SharedBuf;
use adair::interp::Clock;
use adair::kinematics::{Joints, rad};
use adair::services::{Pendant, RobotState, jog};
use adair::session::{Outcome, Session};
use std::cell::RefCell;
use std::rc::Rc;

/// What each jog answered.
type Answers = Rc<RefCell<Vec<Result<(), String>>>>;

/// Jogs by each of `deltas` (degrees), as an operator would with the keys;
/// keeps what each jog answered, and how much of the trace had reached its
/// writer by the time the pendant closes.
struct Scripted {
    deltas: Vec<[f64; 5]>,
    answers: Answers,
    trace: Option<SharedBuf>,
    traced_while_open: Rc<RefCell<Option<usize>>>,
}

impl Pendant for Scripted {
    fn teach(
        &mut self,
        st: &mut RobotState,
        clock: &mut dyn Clock,
        _text: &str,
        _refresh: bool,
        _clear: bool,
    ) -> Result<(), String> {
        for d in &self.deltas {
            let mut q: Joints = st.robot.joints();
            for j in 0..5 {
                q[j] += rad(d[j]);
            }
            let r = jog(st, clock, q);
            self.answers.borrow_mut().push(r);
        }
        if let Some(t) = &self.trace {
            *self.traced_while_open.borrow_mut() = Some(t.0.borrow().len());
        }
        Ok(())
    }
}

fn scripted(deltas: &[[f64; 5]]) -> (Scripted, Answers) {
    let answers = Rc::new(RefCell::new(Vec::new()));
    (
        Scripted {
            deltas: deltas.to_vec(),
            answers: answers.clone(),
            trace: None,
            traced_while_open: Rc::new(RefCell::new(None)),
        },
        answers,
    )
}

fn run(s: &mut Session, text: &str) -> String {
    let buf = SharedBuf::default();
    s.machine.out = Box::new(buf.clone());
    let o = s.run_source("teach.air", text);
    assert!(matches!(o, Outcome::Ok), "{o:?}\n{}", buf.take());
    buf.take()
}

/// A TeachBox jog is a motion for `--record`, `--plot` and `:record`:
/// sampled from its start to its end (it was missing from recordings). A
/// jog beyond a limit is refused and records nothing.
#[test]
fn teachbox_jogs_are_recorded_like_motions() {
    let mut s = super::rv_m1_session();
    s.start_recording();
    let (p, answers) = scripted(&[[30.0, 0.0, 0.0, 0.0, 0.0], [0.0, 0.0, -5.0, 0.0, 0.0]]);
    s.install_pendant(Box::new(p));
    run(&mut s, "InitRobot;\nTeachBox (\"jog\");\n");
    let a = answers.borrow();
    assert!(a[0].is_ok(), "{a:?}");
    assert!(a[1].as_ref().is_err_and(|e| e.contains("joint 3")), "{a:?}");
    let rec = s.robot_state().unwrap().record.clone().unwrap();
    let j1: Vec<f64> = rec.iter().map(|x| x.joints[0].to_degrees()).collect();
    // The jog's end, and points on its way (sampled every 20 ms).
    assert!((j1.last().unwrap() - 30.0).abs() < 1e-9, "{j1:?}");
    let between = j1.iter().filter(|d| **d > 1.0 && **d < 29.0).count();
    assert!(between >= 3, "the jog is not sampled: {j1:?}");
    // Nothing of the refused jog: J3 stays at 0.
    assert!(rec.iter().all(|x| x.joints[2].abs() < 1e-12));
    // The hand keys are recorded as MoveTool is.
    let n = rec.len();
    let t = rec.last().unwrap().t;
    let st = s.robot_state_mut().unwrap();
    let mut clock = adair::interp::VirtualClock { t };
    let g = adair::services::jog_hand(st, &mut clock, false).expect("close");
    assert!(g.opening < 60.0);
    let rec = &s.robot_state().unwrap().record.as_ref().unwrap()[n..];
    assert_eq!(rec.len(), 1);
    assert!((rec[0].grip - g.opening).abs() < 1e-9 && rec[0].t > t);
}

/// While the pendant has the screen, the trace lines are held (written over
/// the pendant they corrupted what it showed); they are written when it
/// closes, in order.
#[test]
fn the_trace_is_held_while_the_pendant_is_open() {
    let mut s = super::rv_m1_session();
    let trace = SharedBuf::default();
    s.robot_state_mut().unwrap().trace = Some(Box::new(trace.clone()));
    let (mut p, _) = scripted(&[[5.0, 0.0, 0.0, 0.0, 0.0], [5.0, 0.0, 0.0, 0.0, 0.0]]);
    p.trace = Some(trace.clone());
    let seen = p.traced_while_open.clone();
    s.install_pendant(Box::new(p));
    run(&mut s, "InitRobot;\n");
    let before = trace.take();
    assert!(before.contains("InitRobot"), "{before}");
    run(
        &mut s,
        "TeachBox (\"jog\");\nMoveAxesRelative ((Rad (1.0), 0.0, 0.0, 0.0, 0.0));\n",
    );
    assert_eq!(
        *seen.borrow(),
        Some(0),
        "trace written while the pendant was open"
    );
    let after = trace.take();
    let lines: Vec<&str> = after.lines().collect();
    assert_eq!(lines.len(), 3, "{after}");
    assert!(lines[0].contains("TeachBox jog: (0.00,"), "{after}");
    assert!(lines[1].contains("TeachBox jog: (5.00,"), "{after}");
    assert!(lines[2].contains("MoveAxesRelative"), "{after}");
}

/// tasks.md: `RobotBusy` is raised while the TeachBox is open and another
/// task calls a motion service. On the program's clock the box is open
/// from its call for as long as the operator keeps it (at least as long as
/// its jogs take: here a 30 degree jog, about 0.5 s); a read-back waits for
/// it to close (the services are a monitor) and a motion after it works.
#[test]
fn another_tasks_motion_while_the_teachbox_is_open_is_robot_busy() {
    let mut s = super::rv_m1_session();
    let (p, answers) = scripted(&[[30.0, 0.0, 0.0, 0.0, 0.0]]);
    s.install_pendant(Box::new(p));
    let out = run(
        &mut s,
        r#"
with Ada.Calendar; use Ada.Calendar;
Start : Time := Clock;

function Now return Duration is
begin
   return Clock - Start;
end Now;

task Other is
   entry Go;
end Other;

task body Other is
begin
   accept Go;
   delay 0.1;
   begin
      MoveAxesRelative ((Rad (1.0), 0.0, 0.0, 0.0, 0.0));
      Put_Line ("Other moved");
   exception
      when E : RobotBusy =>
         Put_Line ("Other: RobotBusy: " & Ada.Exceptions.Exception_Message (E));
         Put_Line ("error status" & Integer'Image (ValueErrorStatus));
   end;
   Put_Line ("Other reads J1 =" & Integer'Image (Integer (Deg (ValueAxes (1)))));
   Put_Line ("read after the box closed: " & Boolean'Image (Now >= 0.4));
   delay 1.0;
   MoveAxesRelative ((Rad (1.0), 0.0, 0.0, 0.0, 0.0));
   Put_Line ("Other moved later, J1 =" & Integer'Image (Integer (Deg (ValueAxes (1)))));
end Other;

InitRobot;
Start := Clock;
Other.Go;
TeachBox ("jog J1");
Put_Line ("box closed");
"#,
    );
    assert!(answers.borrow()[0].is_ok(), "{:?}", answers.borrow());
    assert!(
        out.contains("Other: RobotBusy: MoveAxesRelative while the TeachBox is open"),
        "{out}"
    );
    assert!(!out.contains("Other moved\n"), "{out}");
    // The command code of the service that raised it.
    assert!(out.contains("error status 190"), "{out}");
    assert!(out.contains("Other reads J1 = 30"), "{out}");
    assert!(out.contains("read after the box closed: TRUE"), "{out}");
    assert!(out.contains("Other moved later, J1 = 31"), "{out}");
}
