//! Every service's `:help` example runs as printed in a fresh REPL after
//! `InitRobot;` (each line of the example is typed as one entry). The
//! examples write `paths.txt`: this test binary works in a temporary
//! directory.

use adair::repl::Repl;
use adair::services::table::SERVICES;

#[test]
fn every_help_example_runs_as_printed() {
    let dir = std::env::temp_dir().join(format!("adair-help-examples-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    std::env::set_current_dir(&dir).expect("cd");
    let mut ran = 0;
    for s in SERVICES.iter().filter(|s| !s.doc.is_empty()) {
        let Some((_, example)) = s.doc.split_once("Example:") else {
            continue;
        };
        let mut repl = Repl::new(Box::new(|| Box::new(std::io::sink())), false);
        let help = repl.entry(&format!(":help {}", s.name)).text;
        let first = example.trim().lines().next().unwrap_or("");
        assert!(help.contains(first), "{}: {help}", s.name);
        assert!(!repl.entry("InitRobot;").failed);
        for line in example.lines().filter(|l| !l.trim().is_empty()) {
            let reply = repl.entry(line.trim());
            let no_terminal = s.name == "TeachBox" && reply.text.contains("COMMANDNOTSUPPORTED");
            assert!(
                !reply.failed || no_terminal,
                "{}: `{}`: {}",
                s.name,
                line.trim(),
                reply.text
            );
        }
        ran += 1;
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(ran >= 30, "only {ran} services have an example");
}

/// `:help` explains types (their declaration in the AdaIR package, with the
/// comment) and exceptions, not only subprograms; the overview names them.
#[test]
fn help_on_types_and_exceptions() {
    let mut repl = Repl::new(Box::new(|| Box::new(std::io::sink())), false);
    let frame = repl.entry(":help Frame").text;
    assert!(
        frame.contains("type Frame is array (1 .. 3, 1 .. 4) of Float;")
            && frame.contains("rotation | position (mm)"),
        "{frame}"
    );
    let tool = repl.entry(":help tooldescriptor").text;
    assert!(
        tool.contains("type ToolDescriptor is record") && tool.contains("end record;"),
        "{tool}"
    );
    assert!(
        tool.contains("ForceMin, ForceMax, CurrForce : ToolForce;"),
        "{tool}"
    );
    let vel = repl.entry(":help RobotVelocity").text;
    assert!(
        vel.contains("range 0.0 .. 100.0") && vel.contains("percent"),
        "{vel}"
    );
    let oor = repl.entry(":help OutOfReach").text;
    assert!(
        oor.contains("exception AdaIR.OutOfReach") && oor.contains("outside the arm's reach"),
        "{oor}"
    );
    let all = repl.entry(":help").text;
    assert!(
        all.contains("types") && all.contains("Frame, AxesVector"),
        "{all}"
    );
    let none = repl.entry(":help Nonsense").text;
    assert!(
        none.contains(
            "no service, subprogram, type, exception or other declaration named `Nonsense`"
        ),
        "{none}"
    );
}
