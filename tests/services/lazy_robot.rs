//! `adair run`'s robot is built when the program names the AdaIR package
//! (`Session::set_robot_lazily`): a program that never moves the arm does
//! not read the robot's description (start-up, issue 32), and one that
//! does drives the robot as before, whether it names AdaIR in a `with`
//! clause, in a file it names, or is a script.

use adair::golden::SharedBuf;
use adair::kinematics::RobotDescription;
use adair::session::{Outcome, Session};
use std::cell::Cell;
use std::rc::Rc;

/// A session whose RV-M1 is chosen lazily, and how often its description
/// was read.
fn lazy_session(out: SharedBuf) -> (Session, Rc<Cell<u32>>) {
    let reads = Rc::new(Cell::new(0));
    let mut s = Session::new(Box::new(out));
    let r = reads.clone();
    s.set_robot_lazily(
        Box::new(move || {
            r.set(r.get() + 1);
            RobotDescription::builtin("rv-m1").unwrap()
        }),
        None,
        false,
    );
    (s, reads)
}

#[test]
fn a_program_without_adair_never_reads_the_robot() {
    let out = SharedBuf::default();
    let (mut s, reads) = lazy_session(out.clone());
    let hello = "with Ada.Text_IO; use Ada.Text_IO;\n\
                 procedure Hello is\nbegin\n   Put_Line (\"Hello\");\nend Hello;\n";
    assert!(matches!(s.run_source("hello.adb", hello), Outcome::Ok));
    assert_eq!(out.take(), "Hello\n");
    assert_eq!(
        reads.get(),
        0,
        "the robot was built for a program without AdaIR"
    );
    assert!(s.robot_state().is_none());
}

#[test]
fn a_program_with_adair_drives_the_robot_it_names() {
    let out = SharedBuf::default();
    let (mut s, reads) = lazy_session(out.clone());
    let prog = "with AdaIR; use AdaIR;\nwith Ada.Text_IO; use Ada.Text_IO;\n\
                procedure Cell is\nbegin\n   InitRobot;\n\
                   MoveAxesAbsolute ((0.5, 0.0, 0.0, 0.0, 0.0));\n\
                   Put_Line (\"moved\");\nend Cell;\n";
    let o = s.run_source("cell.adb", prog);
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    assert_eq!(out.take(), "moved\n");
    assert_eq!(reads.get(), 1);
    let st = s.robot_state().expect("the robot was built");
    assert!((st.robot.joints()[0] - 0.5).abs() < 1e-9);
}

#[test]
fn a_script_names_adair_without_with() {
    let out = SharedBuf::default();
    let (mut s, reads) = lazy_session(out);
    let o = s.run_source(
        "s.air",
        "InitRobot;\nMoveAxesAbsolute ((0.25, 0.0, 0.0, 0.0, 0.0));\n",
    );
    assert!(matches!(o, Outcome::Ok), "{o:?}");
    assert_eq!(reads.get(), 1);
    let st = s.robot_state().expect("the robot was built");
    assert!((st.robot.joints()[0] - 0.25).abs() < 1e-9);
}

#[test]
fn the_robot_faults_of_a_program_with_adair_are_still_warned() {
    // W0005 (a service before InitRobot) needs the robot's description.
    let (mut s, _) = lazy_session(SharedBuf::default());
    let prog = "with AdaIR; use AdaIR;\nprocedure Cell is\nbegin\n\
                   MoveAxesAbsolute ((0.5, 0.0, 0.0, 0.0, 0.0));\nend Cell;\n";
    let _ = s.check_source("cell.adb", prog, false);
    assert!(
        s.take_warnings()
            .iter()
            .any(|d| d.code == adair::diag::codes::W0005),
        "no W0005"
    );
}
