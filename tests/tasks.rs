//! Tasks, devices and their mistakes as a user meets them (tasks.md): the
//! real binary, its exit status and what it prints. The scheduling order
//! itself is pinned by the golden scenarios in `tests/golden/tasks/` and the
//! GNAT programs `tests/ada/task_*.adb`.

use std::process::Command;

fn adair_env(args: &[&str], env: &[(&str, &str)], input: Option<&str>) -> (i32, String, String) {
    use std::io::Write;
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_adair"));
    cmd.args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("NO_COLOR", "1")
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped());
    for (k, v) in env {
        cmd.env(k, v);
    }
    let mut child = cmd.spawn().expect("run adair");
    let mut stdin = child.stdin.take().expect("stdin");
    stdin
        .write_all(input.unwrap_or("").as_bytes())
        .expect("write stdin");
    drop(stdin);
    let out = child.wait_with_output().expect("wait for adair");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn adair(args: &[&str]) -> (i32, String, String) {
    adair_env(args, &[], None)
}

fn temp_file(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("adair-tasks-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let p = dir.join(name);
    std::fs::write(&p, text).expect("write");
    p.to_string_lossy().into_owned()
}

const SERVER: &str = "with Ada.Text_IO; use Ada.Text_IO;
procedure Server_Main is
   task Server is
      entry Put (X : Integer);
      entry Get (Y : out Integer);
   end Server;
   task body Server is
      V : Integer := 0;
   begin
      accept Put (X : Integer) do
         V := X;
      end Put;
      accept Get (Y : out Integer) do
         Y := V * 2;
      end Get;
   end Server;
   R : Integer;
begin
   Server.Put (21);
   Server.Get (R);
   Put_Line (Integer'Image (R));
end Server_Main;
";

#[test]
fn a_rendezvous_passes_in_and_out_parameters() {
    let f = temp_file("server.adb", SERVER);
    let (code, out, err) = adair(&["run", &f]);
    assert_eq!((code, out.as_str()), (0, " 42\n"), "{err}");
}

#[test]
fn a_deadlock_names_every_task_and_what_it_waits_for_and_exits_1() {
    let f = temp_file(
        "dead.air",
        "task A is
   entry Ping;
end A;
task B is
   entry Ping;
end B;
task body A is
begin
   B.Ping;
   accept Ping;
end A;
task body B is
begin
   A.Ping;
   accept Ping;
end B;
",
    );
    let (code, _, err) = adair(&["run", &f]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("error[E0902]: deadlock"), "{err}");
    assert!(!err.contains("unhandled exception"), "{err}");
    assert!(err.contains("A waits in a call of B.Ping"), "{err}");
    assert!(err.contains("B waits in a call of A.Ping"), "{err}");
    assert!(err.contains("main waits for its tasks to end"), "{err}");
}

#[test]
fn a_call_to_an_ended_task_is_tasking_error() {
    let f = temp_file(
        "ended.air",
        "task T is
   entry E;
end T;
task body T is
begin
   null;
end T;
delay 0.1;
begin
   T.E;
exception
   when Tasking_Error => Put_Line (\"Tasking_Error\");
end;
",
    );
    let (code, out, err) = adair(&["run", &f]);
    assert_eq!((code, out.as_str()), (0, "Tasking_Error\n"), "{err}");
}

#[test]
fn a_malformed_device_file_is_one_error_with_its_line_and_exit_2() {
    let toml = temp_file(
        "bad.toml",
        "[[device]]\nname = \"p\"\nkind = \"parallel\"\ninterrupt = \"8#340#\"\n",
    );
    let prog = temp_file("p.air", "Put_Line (\"never\");\n");
    let (code, out, err) = adair(&["--devices", &toml, "run", &prog]);
    assert_eq!(code, 2, "{err}");
    assert!(out.is_empty(), "nothing ran: {out}");
    assert!(
        err.contains("bad.toml:4:"),
        "the line of the mistake: {err}"
    );
    assert_eq!(err.matches("error").count(), 1, "one error: {err}");
}

#[test]
fn an_address_no_device_has_is_a_check_error_naming_it_and_the_device_file() {
    let f = temp_file(
        "noaddr.air",
        "type Word is range 0 .. 16#FFFF#;
R : Word;
for R use at 8#360#;
Put_Line (Word'Image (R));
",
    );
    let (code, _, err) = adair(&["run", &f]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("no device has the address 8#360#"), "{err}");
    assert!(err.contains("the default device set"), "{err}");
    assert!(
        err.contains("8#342#"),
        "the addresses there are listed: {err}"
    );
    let cell = "examples/devices/cell.toml";
    let (code, _, err) = adair(&["--devices", cell, "check", &f]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains(cell), "names the device file: {err}");
}

#[test]
fn an_interrupt_entry_with_parameters_is_a_check_error() {
    let f = temp_file(
        "irqparam.air",
        "task H is
   entry Interrupt (X : Integer);
   for Interrupt use at 8#340#;
end H;
task body H is
begin
   accept Interrupt (X : Integer);
end H;
",
    );
    let (code, _, err) = adair(&["check", &f]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("the interrupt entry `Interrupt` has parameters"),
        "{err}"
    );
}

#[test]
fn an_input_register_cannot_be_assigned() {
    let f = temp_file(
        "input.air",
        "type Word is range 0 .. 16#FFFF#;
R : Word;
for R use at 8#342#;
R := 5;
",
    );
    let (code, _, err) = adair(&["check", &f]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("input register of device `parallel`"), "{err}");
}

#[test]
fn registers_read_the_device_and_bits_are_written_back() {
    // The output register keeps what was written, bit by bit; the input
    // register reads what the device file's event set at 0.5 s.
    let f = temp_file(
        "regs.air",
        "type Bits is array (0 .. 15) of Boolean;
type Word is range 0 .. 16#FFFF#;
Output : Bits;
for Output use at 8#344#;
Output_Word : Word;
for Output_Word use at 8#344#;
Input : Word;
for Input use at 8#342#;
Output := (others => False);
Output (0) := True;
Output (4) := True;
Put_Line (Word'Image (Output_Word));
Put_Line (Word'Image (Input));
delay 1.0;
Put_Line (Word'Image (Input));
",
    );
    let (code, out, err) = adair(&["--devices", "examples/devices/parallel.toml", "run", &f]);
    assert_eq!((code, out.as_str()), (0, " 17\n 0\n 255\n"), "{err}");
}

#[test]
fn the_repl_shows_and_sets_the_devices() {
    let input = ":set 8#342# 16#00FF#\n:devices\n:irq 8#340#\n:set 8#344# 1\n:tasks\n";
    let (code, out, err) = adair_env(&["repl"], &[], Some(input));
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("8#342# := 16#00FF#"), "{out}");
    assert!(
        out.contains("16#00FF#"),
        ":devices shows the input register: {out}"
    );
    assert!(
        out.contains("interrupt 8#340# dropped"),
        "interrupts are disabled at the start: {out}"
    );
    assert!(
        out.contains(":set:"),
        "an output register is not an input: {out}"
    );
    assert!(out.contains("no tasks"), "{out}");
}

#[test]
fn trace_shows_task_switches_interrupts_and_device_events() {
    let (code, _, err) = adair(&[
        "--devices",
        "examples/devices/cell.toml",
        "run",
        "--trace",
        "examples/tasks/conveyor_cell.air",
    ]);
    assert_eq!(code, 0, "{err}");
    for want in [
        "tasks: main -> Belt",
        "tasks: interrupt 8#354# queued on Barrier.Interrupt",
        "devices: belt: box1 reaches the end",
        "devices: gripper: box1 picked",
    ] {
        assert!(err.contains(want), "missing `{want}` in:\n{err}");
    }
}

#[test]
fn in_the_repl_tasks_live_on_between_entries_and_take_interrupts() {
    let input = "\
type Bits is array (0 .. 15) of Boolean;
Control : Bits; for Control use at 8#346#;
task Handler is entry Interrupt; for Interrupt use at 8#340#; entry Count (N : out Integer); end Handler; task body Handler is Seen : Integer := 0; begin loop select accept Interrupt; Seen := Seen + 1; Put_Line (\"handled interrupt\" & Integer'Image (Seen)); or accept Count (N : out Integer) do N := Seen; end Count; end select; end loop; end Handler;
:tasks
:irq 8#340#
Control (0) := True;
:irq 8#340#
N : Integer;
Handler.Count (N);
N
";
    let (code, out, err) = adair_env(&["repl", "--strict"], &[], Some(input));
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.contains("Handler waits to accept one of Interrupt, Count"),
        ":tasks shows what the task waits for: {out}"
    );
    assert!(out.contains("interrupt 8#340# dropped"), "{out}");
    assert_eq!(
        out.matches("handled interrupt 1").count(),
        1,
        "the enabled interrupt reaches the task between entries: {out}"
    );
    assert!(
        out.trim_end().ends_with('1'),
        "a later entry calls the task: {out}"
    );
}

#[test]
fn in_the_repl_a_task_needs_its_body_in_the_same_entry() {
    let (code, out, err) = adair_env(
        &["repl", "--strict"],
        &[],
        Some("task T is entry E; end T;\n"),
    );
    assert_eq!(code, 1, "{out}{err}");
    let all = format!("{out}{err}");
    assert!(all.contains("task `T` has no body"), "{all}");
    assert!(all.contains("in the same entry"), "{all}");
}

#[test]
fn in_the_repl_an_entry_after_a_deadlock_runs_and_the_tasks_live_on() {
    // The second entry deadlocks (nobody accepts B); the REPL reports it,
    // and later entries run: the task still accepts A.
    let input = "\
task T is entry A; entry B; end T; task body T is begin loop accept A; Put_Line (\"A accepted\"); end loop; end T;
T.B;
Put_Line (\"after the deadlock\");
T.A;
:tasks
";
    let (code, out, err) = adair_env(&["repl"], &[], Some(input));
    let all = format!("{out}{err}");
    assert!(
        !all.contains("panicked") && !all.contains("internal error"),
        "{all}"
    );
    assert!(all.contains("deadlock"), "{all}");
    assert!(out.contains("after the deadlock"), "{all}");
    assert!(out.contains("A accepted"), "{all}");
    assert!(out.contains("T waits to accept A"), "{all}");
    assert_eq!(code, 0, "{all}");
}

#[test]
fn in_the_repl_a_call_to_a_task_ended_in_an_earlier_entry_is_tasking_error() {
    // Once every task has ended, the REPL keeps their table: a call of an
    // ended task is Tasking_Error (not a task of a later entry, nor
    // "not elaborated"), in a plain, a conditional and a timed call.
    let input = "\
task T is entry A; end T; task body T is begin accept A; end T;
T.A;
begin T.A; exception when Tasking_Error => Put_Line (\"TE plain\"); end;
begin select T.A; else Put_Line (\"else\"); end select; exception when Tasking_Error => Put_Line (\"TE conditional\"); end;
begin select T.A; or delay 1.0; Put_Line (\"timeout\"); end select; exception when Tasking_Error => Put_Line (\"TE timed\"); end;
task U is entry A; end U; task body U is begin accept A; Put_Line (\"U accepted\"); end U;
U.A;
begin T.A; exception when Tasking_Error => Put_Line (\"TE again\"); end;
";
    let (code, out, err) = adair_env(&["repl", "--strict"], &[], Some(input));
    let all = format!("{out}{err}");
    for line in [
        "TE plain",
        "TE conditional",
        "TE timed",
        "U accepted",
        "TE again",
    ] {
        assert!(out.contains(line), "{line}: {all}");
    }
    assert!(!all.contains("PROGRAM_ERROR"), "{all}");
    assert_eq!(code, 0, "{all}");
}

#[test]
fn realtime_paces_delays_to_the_wall_clock_with_and_without_tasks() {
    // tasks.md: `--realtime` paces the virtual clock to the wall clock: a
    // delay takes its time, also while tasks wait on the clock. (A lower
    // bound only: how much longer a loaded machine takes is not asserted.)
    let plain = temp_file("rt_plain.air", "delay 0.4;\nPut_Line (\"done\");\n");
    let tasks = temp_file(
        "rt_tasks.air",
        "task T; task body T is begin delay 0.4; Put_Line (\"T done\"); end T;\nPut_Line (\"main\");\n",
    );
    for (file, want) in [(&plain, "done"), (&tasks, "T done")] {
        let start = std::time::Instant::now();
        let (code, out, err) = adair(&["run", "--realtime", file]);
        let took = start.elapsed().as_secs_f64();
        assert_eq!(code, 0, "{out}{err}");
        assert!(out.contains(want), "{out}");
        assert!(
            took >= 0.38,
            "{file}: --realtime took {took:.3} s for a 0.4 s delay"
        );
    }
}

#[test]
fn a_register_is_16_bits_and_its_value_is_checked_against_the_object_type() {
    // tasks.md: an object mapped to a register is of an integer type or an
    // array (0 .. 15) of Boolean; 8 bits is a check error.
    let f = temp_file(
        "bits8.air",
        "type Bits is array (0 .. 7) of Boolean;\nB : Bits;\nfor B use at 8#342#;\n",
    );
    let (code, _, err) = adair(&["check", &f]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("array (0 .. 15) of Boolean"), "{err}");
    // A value the register holds outside the object's range is
    // Constraint_Error where it is read (the input is 255 after 0.5 s).
    let f = temp_file(
        "small.air",
        "type Small is range 0 .. 10;\nS : Small;\nfor S use at 8#342#;\nPut_Line (Small'Image (S));\ndelay 1.0;\nbegin\n   Put_Line (Small'Image (S));\nexception\n   when Constraint_Error => Put_Line (\"Constraint_Error\");\nend;\n",
    );
    let (code, out, err) = adair(&["--devices", "examples/devices/parallel.toml", "run", &f]);
    assert_eq!((code, out.as_str()), (0, " 0\nConstraint_Error\n"), "{err}");
    // An address beyond 32 bits is named whole.
    let f = temp_file(
        "bigaddr.air",
        "type Word is range 0 .. 16#FFFF#;\nX : Word;\nfor X use at 16#FF_FFFF_FFFF#;\n",
    );
    let (code, _, err) = adair(&["check", &f]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("8#17777777777777#"), "{err}");
}

#[test]
fn in_the_repl_an_interrupt_no_live_entry_takes_is_reported_lost() {
    // As `run --trace` says: an interrupt with no task's entry bound to
    // its address (none yet, or the handler has ended) is lost.
    let input = "\
type Bits is array (0 .. 15) of Boolean;
Control : Bits; for Control use at 8#346#;
Control (0) := True;
:irq 8#340#
task H is entry Interrupt; for Interrupt use at 8#340#; end H; task body H is begin accept Interrupt; Put_Line (\"handled\"); end H;
:irq 8#340#
:irq 8#340#
";
    let (code, out, err) = adair_env(&["repl", "--strict"], &[], Some(input));
    assert_eq!(code, 0, "{out}{err}");
    let lost = "interrupt 8#340# lost: no task has an entry bound to it";
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(
        lines,
        [lost, "handled", "interrupt 8#340# raised", lost],
        "{out}{err}"
    );
}

#[test]
fn the_repl_traces_task_switches_and_device_events_with_trace_on() {
    // `repl --trace` starts traced; `:trace on` traces what `run --trace`
    // does: task switches, device events and interrupts, not only motions.
    let input = "task T is entry E; end T; task body T is begin accept E; end T;\nT.E;\n";
    let (code, out, err) = adair_env(&["repl", "--strict", "--trace"], &[], Some(input));
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("tasks: main -> T"), "{out}{err}");
    let input = ":trace on\ndelay 1.0;\n:trace off\n";
    let (code, out, err) = adair_env(
        &[
            "--devices",
            "examples/devices/parallel.toml",
            "repl",
            "--strict",
        ],
        &[],
        Some(input),
    );
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.contains("[t=    0.500 s] devices: parallel: input 8#342# := 16#00FF#"),
        "{out}{err}"
    );
}

#[test]
fn in_the_repl_a_motion_after_every_task_has_ended_is_a_plain_call() {
    // The REPL keeps the table of ended tasks; a motion in an expression
    // entry then runs as without tasks (it reported a bogus deadlock).
    let input = "\
task T; task body T is begin null; end T;
InitRobot;
function G return Integer is begin MoveAxesRelative ((0.5, 0.0, 0.0, 0.0, 0.0), Time => 2.0); return 1; end G;
G
Put_Line (\"next\");
";
    let (code, out, err) = adair_env(&["repl", "--strict"], &[], Some(input));
    assert_eq!(code, 0, "{out}{err}");
    assert!(!format!("{out}{err}").contains("deadlock"), "{out}{err}");
    assert!(out.contains("next"), "{out}{err}");
}
