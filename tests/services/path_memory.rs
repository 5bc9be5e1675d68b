//! The path memory full in a program: `InsertPosition` raises
//! `PathMemOverflow` and nothing changes (handbook appendix B). The memory
//! itself is tested in `src/services/tests/path_memory.rs`.

use adair::golden::SharedBuf;
use adair::services::paths::{Frame, MAX_POSITIONS, MAX_TOTAL_POSITIONS, Positions};
use adair::session::{Outcome, Session};

fn frame(x: f64) -> Frame {
    [
        [1.0, 0.0, 0.0, x],
        [0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, 1.0, 0.0],
    ]
}

#[test]
fn insert_position_raises_path_mem_overflow_when_the_memory_is_full() {
    let out = SharedBuf::default();
    let mut s = Session::new(Box::new(out.clone()));
    s.set_robot(
        adair::kinematics::RobotDescription::builtin("rv-m1").unwrap(),
        None,
        false,
    );
    let st = s.robot_state_mut().unwrap();
    let mut p = 100;
    while st.paths.total() < MAX_TOTAL_POSITIONS {
        if st.paths.get(&p).map_or(0, Positions::len) == MAX_POSITIONS {
            p += 1;
        }
        st.paths.insert(p, usize::MAX, frame(0.0)).unwrap();
    }
    let prog = "InitRobot;\nCreatePath (1);\n\
        begin\n   InsertPosition (1, 1, Trans (300.0, 0.0, 200.0));\n   Put_Line (\"stored (wrong)\");\n\
        exception\n   when E : PathMemOverflow =>\n      \
        Put_Line (Ada.Exceptions.Exception_Name (E) & \": \" & Ada.Exceptions.Exception_Message (E));\n      \
        Put_Line (ErrorCode'Image (ValueErrorStatus));\nend;\n";
    assert!(matches!(s.run_source("t.air", prog), Outcome::Ok));
    assert_eq!(
        out.take(),
        "ADAIR.PATHMEMOVERFLOW: the path memory holds 1000000 position(s) over all paths, \
         its limit is 1000000\n 160\n"
    );
    let st = s.robot_state_mut().unwrap();
    assert_eq!(st.paths.get(&1).map(Positions::len), Some(0));
}
