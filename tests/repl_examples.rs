//! Service-table examples run as printed in a fresh REPL (after `InitRobot;`).

use adair::repl::Repl;
use adair::services::table::SERVICES;

/// MoveFrameAbsolute's `:help` example used to raise OutOfReach.
#[test]
fn move_frame_absolute_example_runs() {
    let s = SERVICES
        .iter()
        .find(|s| s.name == "MoveFrameAbsolute")
        .expect("MoveFrameAbsolute");
    let (_, example) = s.doc.split_once("Example: ").expect("an example");
    let mut repl = Repl::new(Box::new(|| Box::new(std::io::sink())), false);
    assert!(!repl.entry("InitRobot;").failed);
    let reply = repl.entry(&example.replace('\n', " "));
    assert!(!reply.failed, "`{example}`: {}", reply.text);
}
