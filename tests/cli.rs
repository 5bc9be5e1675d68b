//! The command line as a user meets it: the real binary, its exit status and
//! what it prints.

use std::process::Command;

fn adair(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_adair"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("NO_COLOR", "1")
        .output()
        .expect("run adair");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn temp_file(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("adair-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let p = dir.join(name);
    std::fs::write(&p, text).expect("write");
    p.to_string_lossy().into_owned()
}

#[test]
fn check_goes_on_past_a_missing_file_and_reports_every_problem() {
    let bad = temp_file("bad_type.air", "X : Integer := True;\n");
    let good = temp_file("good.air", "Put_Line (\"hi\");\n");
    let (code, out, err) = adair(&["check", "no/such/file.air", &bad, &good]);
    assert_eq!(code, 2, "{err}");
    assert!(out.is_empty(), "check prints nothing on stdout: {out}");
    assert!(err.contains("no/such/file.air"), "{err}");
    assert!(
        err.contains("bad_type.air:1:"),
        "the second file is checked too: {err}"
    );
}

#[test]
fn check_of_good_files_exits_0_silently() {
    let good = temp_file("good2.air", "Put_Line (\"hi\");\n");
    let (code, out, err) = adair(&["check", &good, "examples/square.air"]);
    assert_eq!((code, out.as_str(), err.as_str()), (0, "", ""));
}

#[test]
fn run_of_a_missing_file_is_one_line_and_exit_2() {
    let (code, _, err) = adair(&["run", "no/such/file.air"]);
    assert_eq!(code, 2);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("no/such/file.air"), "{err}");
}

#[test]
fn a_diagnostic_starts_with_file_line_col_error() {
    let bad = temp_file("typo.air", "Put_Line (\"a\");\nPut_Lin (\"b\");\n");
    let (code, _, err) = adair(&["run", &bad]);
    assert_eq!(code, 2);
    let first = err.lines().next().unwrap_or("");
    assert!(
        first.starts_with(&format!("{bad}:2:1: error[E0201]: ")),
        "first line: {first}"
    );
}

/// Runs `adair ARGS` with `input` (raw bytes) on standard input.
fn adair_stdin(args: &[&str], input: &[u8]) -> (i32, String, String) {
    use std::io::Write;
    let mut child = Command::new(env!("CARGO_BIN_EXE_adair"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("NO_COLOR", "1")
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("run adair");
    child
        .stdin
        .take()
        .expect("stdin")
        .write_all(input)
        .expect("write stdin");
    let out = child.wait_with_output().expect("wait");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn piped_repl_reports_a_line_that_is_not_utf8_and_goes_on() {
    let input = b"Put_Line (\"a\");\nPut_Line (\"\xff\");\nPut_Line (\"b\");\n";
    let (code, out, err) = adair_stdin(&["repl"], input);
    let all = format!("{out}{err}");
    assert!(
        all.contains("<stdin>:2:12: error: this line is not valid UTF-8"),
        "{all}"
    );
    assert!(out.contains("a\n") && out.contains("b\n"), "{all}");
    assert_eq!(code, 0, "{all}");
    let (code, _, _) = adair_stdin(&["repl", "--strict"], input);
    assert_eq!(code, 1, "--strict: exit 1 after a bad line");
}

#[test]
fn unclosed_nested_declare_blocks_are_reported_not_retried_exponentially() {
    // Each unclosed block used to be parsed again after the recovery of the
    // block around it: 22 levels took over a minute, 40 would take days;
    // then 1,000 levels took 4.4 s (quadratic). Now a `declare` block and a
    // body that the text ends inside are taken as ended, with one error
    // naming the innermost unclosed block.
    let src = format!(
        "procedure P is\nbegin\n{}null;\n",
        "declare X : Integer;\nbegin\n".repeat(1000)
    );
    let f = temp_file("unclosed_declares.air", &src);
    let (code, _, err) = adair(&["check", &f]);
    assert_eq!(code, 2, "{err}");
    let first = err.lines().next().unwrap_or("");
    assert!(
        first.ends_with(":2004:1: error[E0102]: `end;` expected to close the block at 2001:1"),
        "{}",
        &err[..err.len().min(600)]
    );
    assert!(err.contains("this block is not closed"), "{err}");
    assert_eq!(err.matches(": error[").count(), 1, "{err}");
}

#[test]
fn a_body_the_text_ends_inside_is_one_error_naming_the_subprogram() {
    let f = temp_file(
        "unclosed_body.adb",
        "procedure P is\n   X : Integer := 1;\nbegin\n   X := X + 1;\n",
    );
    let (code, _, err) = adair(&["check", &f]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.lines().next().unwrap_or("").ends_with(
            ":5:1: error[E0102]: the text ends inside the body of the subprogram at 1:1"
        ),
        "{err}"
    );
    assert!(err.contains("end NAME;"), "{err}");
    assert_eq!(err.matches(": error[").count(), 1, "{err}");
}

#[test]
fn nesting_past_the_limit_is_one_error_with_its_place_and_below_it_runs() {
    let n = 100_000;
    let deep = format!(
        "X : Integer := {}1{};\nPut_Line (Integer'Image (X));\n",
        "(".repeat(n),
        ")".repeat(n)
    );
    let f = temp_file("deep_parens.air", &deep);
    let (code, _, err) = adair(&["run", &f]);
    assert_eq!(code, 2, "{err}");
    // The 10,001st `(` is at column 15 + 10,000.
    assert!(
        err.contains(
            ":1:10016: error[E0105]: nesting too deep: more than 10000 levels of parentheses"
        ),
        "{}",
        &err[..err.len().min(400)]
    );
    assert_eq!(err.matches("error[").count(), 1, "one error only");

    let calls = format!(
        "function F (X : Integer) return Integer is begin return X; end F;\n\
         X : Integer := {}1{};\nPut_Line (Integer'Image (X));\n",
        "F (".repeat(9_000),
        ")".repeat(9_000)
    );
    let f = temp_file("deep_calls.air", &calls);
    let (code, out, err) = adair(&["run", &f]);
    assert_eq!((code, out.as_str()), (0, " 1\n"), "{err}");

    let blocks = format!(
        "X : Integer := 0;\n{}X := 1;\n{}",
        "if X = 0 then\n".repeat(20_000),
        "end if;\n".repeat(20_000)
    );
    let f = temp_file("deep_ifs.air", &blocks);
    let (code, _, err) = adair(&["check", &f]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains(":10002:1: error[E0105]: nesting too deep: more than 10000 levels of blocks"),
        "{}",
        &err[..err.len().min(400)]
    );
}

/// A program that doubles a string until memory runs out gets Storage_Error
/// at the concatenation, which it can handle; unhandled, the report points
/// into the user's program. `--max-memory` sets the limit.
#[test]
fn running_out_of_memory_is_storage_error_at_the_place_that_asked() {
    let grow = "function Grow (S : String; N : Natural) return Natural is\n\
                begin\n   if N = 0 then return S'Length; end if;\n   return Grow (S & S, N - 1);\nend Grow;\n";
    let handled = temp_file(
        "grow_handled.air",
        &format!(
            "{grow}begin\n   Put_Line (Natural'Image (Grow (\"x\", 40)));\n\
             exception\n   when Storage_Error => Put_Line (\"Storage_Error handled\");\nend;\n\
             Put_Line (Natural'Image (Grow (\"x\", 10)));\n"
        ),
    );
    let (code, out, err) = adair(&["run", "--max-memory", "64M", &handled]);
    assert_eq!(
        (code, out.as_str()),
        (0, "Storage_Error handled\n 1024\n"),
        "{err}"
    );
    let unhandled = temp_file(
        "grow_unhandled.air",
        &format!("{grow}Put_Line (Natural'Image (Grow (\"x\", 40)));\n"),
    );
    let (code, _, err) = adair(&["run", "--max-memory", "64M", &unhandled]);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("grow_unhandled.air:4:17: error[E0901]: unhandled exception: raised STORAGE_ERROR : out of memory")
            && err.contains("limit of 64 MiB (--max-memory)"),
        "{err}"
    );
    // An array too large for the limit, declared in the program: the place
    // is its declaration, not the library.
    let big = temp_file(
        "big_array.air",
        "type Big is array (1 .. 40_000_000) of Integer;\nB : Big;\nPut_Line (\"not reached\");\n",
    );
    let (code, out, err) = adair(&["run", "--max-memory", "64M", &big]);
    assert_eq!((code, out.as_str()), (1, ""), "{err}");
    assert!(err.contains("big_array.air:2:"), "{err}");
    assert!(err.contains("STORAGE_ERROR : out of memory"), "{err}");
    let (code, _, err) = adair(&["run", "--max-memory", "lots", &big]);
    assert_eq!(code, 2);
    assert!(err.contains("`lots` is not a size"), "{err}");
}

/// `--plot` draws the run: the three panels, a line per joint, the reach,
/// start and end, and the time axis of this run (the same support points
/// `--record` writes); a bad path is refused before anything runs; a run
/// without motion still gives a picture that says so.
#[test]
fn plot_draws_the_run_and_refuses_a_bad_path_first() {
    let dir = std::env::temp_dir().join(format!("adair-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    let svg = dir.join("square.svg");
    let csv = dir.join("square.csv");
    let (code, _, err) = adair(&[
        "run",
        "--plot",
        svg.to_str().unwrap(),
        "--record",
        csv.to_str().unwrap(),
        "examples/square.air",
    ]);
    assert_eq!(code, 0, "{err}");
    let text = std::fs::read_to_string(&svg).expect("svg written");
    assert!(text.starts_with("<svg ") && text.contains("xmlns=\"http://www.w3.org/2000/svg\""));
    assert!(text.trim_end().ends_with("</svg>"));
    for part in [
        "Joints against time",
        "TCP path from above",
        "TCP path from the side",
        "square.air on the RV-M1",
        // One line per joint, in its colour, named in the legend.
        "stroke=\"#1F77B4\"",
        "stroke=\"#D62728\"",
        "stroke=\"#2CA02C\"",
        "stroke=\"#9467BD\"",
        "stroke=\"#FF7F0E\"",
        "\nJ1\n",
        "\nJ4\n",
        // Start and end of the TCP path.
        "fill=\"#00FF00\"",
        "fill=\"#FF0000\"",
        // The hand's opening against time.
        "Hand opening against time",
        "stroke=\"#17BECF\"",
        // J5 runs on J1 (the pen points straight down): dashed, and said.
        "J5 dashed: on J1 all the run",
        // The path from above fills its view: the reach is out of it, and
        // a scale bar says how long 100 mm is.
        "reach 589 mm: outside this view",
        "\n100 mm\n",
    ] {
        assert!(text.contains(part), "missing {part}");
    }
    // The reach, seen from the side (and named in both legends).
    assert!(text.contains("stroke=\"#969696\""));
    assert_eq!(text.matches("\nreach 589 mm").count(), 2);
    // The tutorial shows this picture: it must be what adair draws now
    // (BLESS=1 rewrites it).
    let shown = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/images/square.svg");
    if std::env::var_os("BLESS").is_some() {
        std::fs::write(&shown, &text).expect("bless docs/images/square.svg");
    }
    assert!(
        std::fs::read_to_string(&shown).is_ok_and(|s| s == text),
        "docs/images/square.svg is not what `adair run --plot` draws now (BLESS=1 rewrites it)"
    );
    let rows: Vec<String> = std::fs::read_to_string(&csv)
        .expect("csv")
        .lines()
        .skip(1)
        .map(str::to_string)
        .collect();
    let last_t: f64 = rows
        .last()
        .unwrap()
        .split(',')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(
        text.contains(&format!(
            "{} support points over {last_t:.3} s;",
            rows.len()
        )),
        "the plot does not show this run's {} points and {last_t} s",
        rows.len()
    );

    let (code, out, err) = adair(&["run", "--plot", "/no/such/dir/x.svg", "examples/square.air"]);
    assert_eq!((code, out.as_str()), (2, ""), "nothing runs: {err}");
    assert!(
        err.contains("adair: --plot /no/such/dir/x.svg: the directory /no/such/dir does not exist"),
        "{err}"
    );
    let (code, _, err) = adair(&["run", "--plot", "x.png", "examples/square.air"]);
    assert_eq!(code, 2);
    assert!(err.contains("must end in .svg"), "{err}");

    let still = temp_file("still.air", "Put_Line (\"no motion here\");\n");
    let empty = dir.join("still.svg");
    let (code, _, err) = adair(&["run", "--plot", empty.to_str().unwrap(), &still]);
    assert_eq!(code, 0, "{err}");
    assert!(
        std::fs::read_to_string(&empty)
            .unwrap()
            .contains("no motion")
    );

    // The REPL draws what was done since it started.
    let repl_svg = dir.join("repl.svg");
    let input = format!(
        "InitRobot;\nMoveAxesAbsolute ((0.0, 0.5, 1.0, -0.5, 0.0));\n:plot {}\n:plot x.png\n",
        repl_svg.display()
    );
    let (_, out, err) = adair_stdin(&["repl"], input.as_bytes());
    assert!(
        out.contains("wrote") && out.contains("support points"),
        "{out}{err}"
    );
    assert!(
        format!("{out}{err}").contains(":plot x.png: the file must end in .svg"),
        "{out}{err}"
    );
    let drawn = std::fs::read_to_string(&repl_svg).expect("repl svg");
    assert!(drawn.contains("\nJ2\n") && drawn.contains("REPL session"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// Warnings never stop a run or fail a check, unless `--strict`.
#[test]
fn warnings_stop_nothing_unless_strict() {
    let f = temp_file(
        "warned.air",
        "with Ada.Text_IO; use Ada.Text_IO;\nprocedure Warned is\n   Spare : Integer := 0;\nbegin\n   Put_Line (\"ran\");\nend Warned;\n",
    );
    let (code, out, err) = adair(&["run", &f]);
    assert_eq!((code, out.as_str()), (0, "ran\n"), "{err}");
    assert!(
        err.contains("warned.air:3:4: warning[W0001]: variable `Spare` is never read"),
        "{err}"
    );
    let (code, _, err) = adair(&["check", &f]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("warning[W0001]: variable `Spare`"), "{err}");
    let (code, out, err) = adair(&["run", "--strict", &f]);
    assert_eq!((code, out.as_str()), (2, ""), "nothing runs: {err}");
    assert!(err.contains("warning[W0001]: variable `Spare`"), "{err}");
    let (code, _, _) = adair(&["check", "--strict", &f]);
    assert_eq!(code, 2);
}

#[test]
fn the_repl_takes_robot_and_refuses_rehearse_without_a_port() {
    let (code, out, err) = adair_stdin(&["repl", "--strict", "--robot", "rm-501"], b":where\n");
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.starts_with("robot: simulated RM-501"), "{out}");
    let (code, out, err) = adair_stdin(&["repl", "--robot", "bogus"], b"");
    assert_eq!(code, 2);
    assert!(out.is_empty(), "{out}");
    assert!(
        err.contains("--robot") && err.contains("rv-m1, rm-501"),
        "{err}"
    );
    let (code, _, err) = adair_stdin(&["repl", "--rehearse"], b"");
    assert_eq!(code, 2);
    assert!(err.contains("--port"), "{err}");
}

#[test]
fn a_first_argument_naming_a_program_is_short_for_run() {
    let f = temp_file(
        "short.air",
        "Put_Line (\"short\");\nInitRobot;\nMoveAxesAbsolute ((0.0, 0.0, 0.0, 0.0, 0.0));\n",
    );
    let (code, out, err) = adair(&[&f]);
    assert_eq!((code, out.as_str()), (0, "short\n"), "{err}");
    // Options after the file are `run`'s; global options may come first.
    let (code, out, err) = adair(&["--color", "never", &f, "--trace", "--robot", "rm-501"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out, "short\n");
    // The trace (on stderr) of the RM-501, whose zero pose is not the
    // RV-M1's (0, 0, 889.0).
    assert!(err.contains("MoveAxesAbsolute at"), "{err}");
    assert!(!err.contains("889.0"), "{err}");
    // Anything else is still a usage error.
    let (code, _, err) = adair(&["short.txt"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("unrecognized subcommand"), "{err}");
    let (_, help, _) = adair(&["--help"]);
    assert!(help.contains("adair FILE.air"), "{help}");
}

#[test]
fn test_takes_the_default_robot_and_the_trace() {
    // J3 at 100 degrees is inside the RV-M1's limits (0 .. 110) and outside
    // the RM-501's (0 .. 90): the same script passes on one robot only.
    let script = "InitRobot;\nMoveAxesAbsolute ((0.0, 0.0, Rad (100.0), 0.0, 0.0));\nPut_Line (\"moved\");\n";
    let f = temp_file("robot_default.air", script);
    let out_file = f.replace(".air", ".out");
    std::fs::write(&out_file, "moved\n").expect("write");
    let (code, out, err) = adair(&["test", &f]);
    assert_eq!(code, 0, "{out}{err}");
    let (code, out, err) = adair(&["test", "--robot", "rm-501", &f]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(
        out.contains("OutOfReach") || out.contains("OUTOFREACH"),
        "{out}{err}"
    );
    // A script's own `-- adair: --robot` line wins over the default.
    std::fs::write(&f, format!("-- adair: --robot rv-m1\n{script}")).expect("write");
    let (code, out, err) = adair(&["test", "--robot", "rm-501", &f]);
    assert_eq!(code, 0, "{out}{err}");
    // --trace puts the motion into the output: the recorded one lacks it.
    let (code, out, err) = adair(&["test", "--trace", &f]);
    assert_eq!(code, 1, "{out}{err}");
    let (code, _, err) = adair(&["test", "--trace", "--bless", &f]);
    assert_eq!(code, 0, "{err}");
    let blessed = std::fs::read_to_string(&out_file).expect("read");
    assert!(
        blessed.contains("moved\n") && blessed.lines().count() > 1,
        "{blessed}"
    );
    let (code, _, err) = adair(&["test", "--robot", "ur5", &f]);
    assert_eq!(code, 2, "{err}");
}

#[test]
fn get_line_into_a_string_keeps_the_rest_of_a_longer_line_as_gnat_does() {
    // The expected text is what the same program compiled by GNAT prints
    // on this input: a longer line's rest is the next read; a line that
    // fills the string exactly leaves an empty line behind.
    let prog = temp_file(
        "get_line_rest.adb",
        "with Ada.Text_IO; use Ada.Text_IO;
procedure Get_Line_Rest is
   S : String (1 .. 10);
   L : Natural;
begin
   for I in 1 .. 3 loop
      Get_Line (S, L);
      Put_Line (\"[\" & S (1 .. L) & \"]\" & Integer'Image (L));
   end loop;
   Put_Line (\"<\" & Get_Line & \">\");
   Put_Line (\"<\" & Get_Line & \">\");
   Get_Line (S, L);
   Put_Line (\"[\" & S (1 .. L) & \"]\" & Integer'Image (L));
end Get_Line_Rest;
",
    );
    let (code, out, err) = adair_stdin(&["run", &prog], b"abcdefghijklmno\nabcdefghij\nxyz\nq\n");
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        out,
        "[abcdefghij] 10\n[klmno] 5\n[abcdefghij] 10\n<>\n<xyz>\n[q] 1\n"
    );
}

/// An expression chaining more operators than the limit is one error at the
/// first operator past it (150,000 `+` overflowed the native stack and
/// aborted); a chain at the limit checks and runs.
#[test]
fn an_operator_chain_past_the_limit_is_one_error_and_at_it_runs() {
    let chain = |n: usize, op: &str, x: &str| vec![x; n + 1].join(op);
    let long = format!(
        "B : constant Boolean := {};\nPut_Line (Boolean'Image (B));\n",
        chain(200_000, " and ", "True")
    );
    let f = temp_file("long_and.air", &long);
    let (code, _, err) = adair(&["check", &f]);
    assert_eq!(code, 2, "{}", &err[..err.len().min(400)]);
    // The 50,001st ` and ` ends at column 24 + 50,001 * 9 - 4.
    assert!(
        err.contains(&format!(
            ":1:{}: error[E0105]: expression too long: more than 50000 operators in a row",
            24 + 50_000 * 9 + 6
        )),
        "{}",
        &err[..err.len().min(400)]
    );
    assert_eq!(err.matches("error[").count(), 1, "one error only");
    let at = format!(
        "X : Integer := ({});\nPut_Line (Integer'Image (X));\n",
        chain(50_000, " + ", "1")
    );
    let f = temp_file("chain_at_limit.air", &at);
    let (code, out, err) = adair(&["run", &f]);
    assert_eq!(
        (code, out.as_str()),
        (0, " 50001\n"),
        "{}",
        &err[..err.len().min(400)]
    );
}

/// A long `&` chain needs memory in proportion to its result, in the checker
/// and in the engine, with a call among its operands or without: 10,000
/// terms used about 900 MB before (each intermediate string was kept, and
/// the checker listed one meaning per `&`), so 64 MiB did not do.
#[test]
fn a_long_concatenation_chain_needs_memory_in_proportion() {
    let terms = |first: &str| {
        let mut s = String::from(first);
        for _ in 1..10_000 {
            s.push_str(" & \"a\"");
        }
        s
    };
    let text = format!(
        "function F (N : Integer) return String is begin return Integer'Image (N); end F;\n\
         C : constant String := \"a\";\n\
         S : constant String := {};\n\
         T : constant String := {};\n\
         Put_Line (Integer'Image (S'Length) & Integer'Image (T'Length));\n",
        terms("C"),
        terms("F (7)")
    );
    let f = temp_file("long_concat.air", &text);
    let (code, out, err) = adair(&["run", "--max-memory", "64M", &f]);
    assert_eq!(
        (code, out.as_str()),
        (0, " 10000 10001\n"),
        "{}",
        &err[..err.len().min(400)]
    );
}

/// `adair check` warns of a service only the simulator has, naming it and
/// its place: such a script cannot finish on a real arm (`--port`), and
/// its rehearsal refuses it too. A plain simulator run says nothing.
#[test]
fn check_warns_of_a_simulator_only_service() {
    let f = temp_file(
        "sim_only.air",
        "InitRobot;\nMoveTool (40.0, 0.0);\nPlaceObject (30.0);\nMoveTool (0.0, 5.0);\n",
    );
    let (code, out, err) = adair(&["check", &f]);
    assert_eq!((code, out.as_str()), (0, ""), "{err}");
    assert!(
        err.contains(
            "sim_only.air:3:1: warning[W0002]: `PlaceObject` exists only on the simulator"
        ),
        "{err}"
    );
    let (code, _, err) = adair(&["run", &f]);
    assert_eq!((code, err.as_str()), (0, ""));
}

/// Runs `adair ARGS` in the repository with standard output (`out_full`)
/// or standard error going to `/dev/full`, where every write fails with
/// ENOSPC; the other stream is captured. `None` where there is no
/// `/dev/full`.
fn adair_full(args: &[&str], input: &str, out_full: bool) -> Option<(i32, String)> {
    use std::io::Write;
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .ok()?;
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_adair"));
    cmd.args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("NO_COLOR", "1")
        .stdin(std::process::Stdio::piped());
    if out_full {
        cmd.stdout(full).stderr(std::process::Stdio::piped());
    } else {
        cmd.stderr(full).stdout(std::process::Stdio::piped());
    }
    let mut child = cmd.spawn().expect("run adair");
    let mut stdin = child.stdin.take().unwrap();
    stdin.write_all(input.as_bytes()).unwrap();
    drop(stdin);
    let out = child.wait_with_output().unwrap();
    let other = if out_full { out.stderr } else { out.stdout };
    Some((
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&other).into_owned(),
    ))
}

/// Output or diagnostics that cannot be written (a full disk: `/dev/full`)
/// end the process with a failure status (1, or 2 after a check error),
/// never with a panic (101) or an internal error (3), and never with 0.
#[test]
#[allow(clippy::print_stdout)] // says when it is skipped
fn a_full_stdout_or_stderr_is_an_error_exit_not_a_panic() {
    let ok = temp_file("full_ok.air", "Put_Line (\"hi\");\n");
    let raise = temp_file(
        "full_raise.air",
        "Put_Line (\"hi\");\nraise Constraint_Error;\n",
    );
    let bad = temp_file("full_bad.air", "X : Integer := True;\n");
    let dir = std::path::Path::new(&ok)
        .parent()
        .unwrap()
        .join("full_test");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("t.air"), "Put_Line (\"hi\");\n").unwrap();
    std::fs::write(dir.join("t.out"), "hi\n").unwrap();
    let dir = dir.to_string_lossy().into_owned();
    // (arguments, standard input, stdout full?, expected status)
    let cases: [(&[&str], &str, bool, i32); 13] = [
        (&["run", &ok], "", true, 1),
        (&["run", &raise], "", true, 1),
        (&["run", &raise], "", false, 1),
        (&["run", &bad], "", false, 2),
        (&["check", &bad], "", false, 2),
        (&["run", "examples/square.air", "--trace"], "", false, 1),
        (&["test", &dir], "", true, 1),
        (&["test", "no/such/dir"], "", false, 2),
        (&["repl"], "Put_Line (\"hi\");\n", true, 1),
        (&["--help"], "", true, 2),
        (&["ports"], "", true, 1),
        (&["run", "--serial-timeout"], "", false, 2),
        (&["no-such-command"], "", false, 2),
    ];
    for (args, input, out_full, want) in cases {
        let Some((code, other)) = adair_full(args, input, out_full) else {
            println!("skipped: no /dev/full");
            return;
        };
        let stream = if out_full { "stdout" } else { "stderr" };
        assert_eq!(code, want, "adair {args:?} with a full {stream}: {other}");
        if out_full {
            assert!(
                other.contains("standard output"),
                "adair {args:?}: say that the output was lost: {other}"
            );
        }
    }
}

/// A float option of run, repl and test takes a finite number of seconds
/// in its range: NaN, an infinity, a negative number or one too large for
/// a timeout is one line and exit 2, before anything runs.
#[test]
fn float_options_refuse_nan_and_infinities() {
    let ok = temp_file("nan_ok.air", "Put_Line (\"ran\");\n");
    for bad in ["nan", "NaN", "inf", "-inf", "infinity", "-1", "1e300"] {
        for cmd in [vec!["run", &ok], vec!["repl"], vec!["test", &ok]] {
            let mut args = cmd.clone();
            let flag = format!("--serial-timeout={bad}");
            args.extend(["--port", "/nonexistent/tty", &flag]);
            let (code, out, err) = adair(&args);
            assert_eq!(code, 2, "adair {args:?}: {out}{err}");
            assert!(out.is_empty(), "adair {args:?} ran: {out}");
            assert_eq!(err.lines().count(), 1, "{err}");
            assert!(err.contains("--serial-timeout"), "{err}");
        }
    }
}

/// A run of unary operators nests as deep as it is long (each one's
/// operand is the rest): 400,000 `not`, `abs` or `-` overflowed the stack
/// (abort); now the 10,001st level is one "nesting too deep" error, the
/// levels of parentheses counting with them; 9,000 `not` run.
#[test]
fn a_unary_chain_past_the_nesting_limit_is_one_error_and_below_it_runs() {
    for (op, ty, lit) in [
        ("not ", "Boolean", "True"),
        ("abs ", "Integer", "1"),
        ("- ", "Integer", "1"),
    ] {
        let text = format!("X : {ty} := {}{lit};\n", op.repeat(400_000));
        let f = temp_file("unary_chain.air", &text);
        let (code, _, err) = adair(&["check", &f]);
        assert_eq!(code, 2, "{op}: {}", &err[..err.len().min(400)]);
        // `X : Boolean := ` is 15 columns; the 10,001st operator follows.
        let col = 16 + 10_000 * op.len();
        assert!(
            err.contains(&format!(
                ":1:{col}: error[E0105]: nesting too deep: more than 10000 levels of parentheses and unary operators"
            )),
            "{op}: {}",
            &err[..err.len().min(400)]
        );
        assert_eq!(err.matches("error[").count(), 1, "one error only");
    }
    // `not (` is two levels: the 5,001st `not` is the 10,001st level.
    let mixed = format!(
        "X : Boolean := {}True{};\n",
        "not (".repeat(6_000),
        ")".repeat(6_000)
    );
    let f = temp_file("unary_parens.air", &mixed);
    let (code, _, err) = adair(&["check", &f]);
    assert_eq!(code, 2, "{}", &err[..err.len().min(400)]);
    assert!(
        err.contains(&format!(
            ":1:{}: error[E0105]: nesting too deep",
            16 + 5_000 * 5
        )),
        "{}",
        &err[..err.len().min(400)]
    );
    let below = format!(
        "X : Boolean := {}True;\nPut_Line (Boolean'Image (X));\n",
        "not ".repeat(9_000)
    );
    let f = temp_file("unary_below.air", &below);
    let (code, out, err) = adair(&["run", &f]);
    assert_eq!((code, out.as_str()), (0, "TRUE\n"), "{err}");
}

/// Unclosed `if`, `case` and loop statements nested 40 deep, each with a
/// statement inside: every level used to be parsed again after the
/// recovery of the level around it, doubling the time with each (14
/// levels took 0.7 s, 40 would take years). Each compound statement is now
/// remembered by its position. The check must end (a watchdog kills it
/// after two minutes) with errors and exit 2.
#[test]
fn unclosed_nested_compound_statements_are_not_retried_exponentially() {
    let kinds = [
        "if X > 1 then",
        "for I in 1 .. 3 loop",
        "while X > 1 loop",
        "case X is when 1 =>",
        "loop",
    ];
    let mut src = String::from("X : Integer := 1;\n");
    for i in 0..40 {
        src.push_str(kinds[i % kinds.len()]);
        src.push_str("\n   X := X + 1;\n");
    }
    let f = temp_file("unclosed_compounds.air", &src);
    let mut child = Command::new(env!("CARGO_BIN_EXE_adair"))
        .args(["check", &f])
        .env("NO_COLOR", "1")
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("run adair");
    let t0 = std::time::Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait") {
            break s;
        }
        if t0.elapsed() > std::time::Duration::from_secs(120) {
            let _ = child.kill();
            let _ = child.wait();
            panic!("adair check did not end within two minutes on 40 unclosed statements");
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    };
    let mut err = String::new();
    use std::io::Read;
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    assert_eq!(status.code(), Some(2), "{err}");
    assert!(err.contains("unclosed_compounds.air:"), "{err}");
}

/// Under an address-space limit (`ulimit -v`) smaller than the default
/// 4G, the default `--max-memory` follows it: a program that doubles a
/// string gets `Storage_Error` at its place; it aborted when an allocation
/// failed past the real limit.
#[test]
fn the_default_memory_limit_follows_ulimit_v() {
    let grow = temp_file(
        "grow_ulimit.air",
        "function Grow (S : String; N : Natural) return Natural is\n\
         begin\n   if N = 0 then return S'Length; end if;\n   return Grow (S & S, N - 1);\nend Grow;\n\
         Put_Line (Natural'Image (Grow (\"x\", 40)));\n",
    );
    for kib in [1 << 20, 2 << 20] {
        let out = Command::new("sh")
            .arg("-c")
            .arg(format!("ulimit -v {kib} && exec \"$0\" run \"$1\""))
            .arg(env!("CARGO_BIN_EXE_adair"))
            .arg(&grow)
            .env("NO_COLOR", "1")
            .output()
            .expect("sh");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "ulimit -v {kib}: {err}");
        assert!(
            err.contains("grow_ulimit.air:4:17: error[E0901]: unhandled exception: raised STORAGE_ERROR : out of memory"),
            "ulimit -v {kib}: {err}"
        );
    }
}

/// `adair test` on a folder with a symbolic link loop (`sub/up -> ..`), a
/// link to a folder inside (`alias -> sub`) and a linked script (`c.air ->
/// a.air`): each script is run and counted once (it followed the loop
/// until the kernel's 40 links: one script counted 41 times).
#[test]
fn adair_test_walks_a_symlink_loop_once() {
    let dir = std::env::temp_dir().join(format!("adair-cli-loop-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    std::fs::write(dir.join("a.air"), "Put_Line (\"a\");\n").unwrap();
    std::fs::write(dir.join("a.out"), "a\n").unwrap();
    std::fs::write(dir.join("sub/b.air"), "Put_Line (\"b\");\n").unwrap();
    std::fs::write(dir.join("sub/b.out"), "b\n").unwrap();
    std::os::unix::fs::symlink("..", dir.join("sub/up")).unwrap();
    std::os::unix::fs::symlink("sub", dir.join("alias")).unwrap();
    std::os::unix::fs::symlink("a.air", dir.join("c.air")).unwrap();
    // `adair test` in at most 30 s (the loop was walked 2^40 ways).
    let adair = |args: &[&str]| {
        let mut child = Command::new(env!("CARGO_BIN_EXE_adair"))
            .args(args)
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .expect("run adair");
        let start = std::time::Instant::now();
        while child.try_wait().unwrap().is_none() {
            if start.elapsed() > std::time::Duration::from_secs(30) {
                let _ = child.kill();
                panic!("adair {args:?} still runs after 30 s");
            }
            std::thread::sleep(std::time::Duration::from_millis(20));
        }
        let out = child.wait_with_output().unwrap();
        (
            out.status.code().unwrap_or(-1),
            String::from_utf8_lossy(&out.stdout).into_owned(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    let d = dir.to_string_lossy().into_owned();
    // A progress line per script, then the count.
    let once = |out: &str| {
        let lines: Vec<&str> = out.lines().collect();
        lines.len() == 3
            && lines[..2].iter().all(|l| l.starts_with("ok "))
            && lines[2] == "2 passed, 0 failed"
    };
    let (code, out, err) = adair(&["test", &d]);
    assert!(code == 0 && once(&out), "{out}{err}");
    // Named twice, and through the link: still once each.
    let sub = dir.join("sub").to_string_lossy().into_owned();
    let alias = dir.join("alias").to_string_lossy().into_owned();
    let (code, out, err) = adair(&["test", &d, &sub, &alias]);
    assert!(code == 0 && once(&out), "{out}{err}");
    // From inside the loop: it leads to the outer folder, each script once.
    let (code, out, err) = adair(&["test", &sub]);
    assert!(code == 0 && once(&out), "{out}{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `adair sim-controller --time-scale inf` panicked: it, `nan`, `0` and
/// `--slow nan`/`inf` are each one error line and exit 2 before any port is
/// opened. (A finite huge scale such as `1e300` is taken as given: its
/// times saturate, see `simctl::tests::faults_are_checked`.)
#[test]
fn sim_controller_refuses_non_finite_times() {
    for args in [
        ["--time-scale", "inf"],
        ["--time-scale", "nan"],
        ["--time-scale", "0"],
        ["--slow", "nan"],
        ["--slow", "inf"],
    ] {
        let mut all = vec!["sim-controller"];
        all.extend(args);
        let (code, out, err) = adair(&all);
        assert_eq!(code, 2, "adair {all:?}: {out}{err}");
        assert!(!err.contains("panicked"), "adair {all:?}: {err}");
        assert!(err.contains(args[0]), "adair {all:?}: {err}");
    }
}

/// `adair test --timeout nan` (or `inf`, `-1`) is refused as `--timeout`,
/// before any script runs.
#[test]
fn test_timeout_refuses_nan_and_infinities() {
    let ok = temp_file("timeout_ok.air", "Put_Line (\"ran\");\n");
    for bad in ["nan", "inf", "-1"] {
        let flag = format!("--timeout={bad}");
        let (code, out, err) = adair(&["test", &flag, &ok]);
        assert_eq!(code, 2, "{flag}: {out}{err}");
        assert!(!out.contains("passed"), "{flag} ran: {out}");
        assert!(err.contains("--timeout"), "{flag}: {err}");
    }
}

/// Recursion with big frames under an address-space limit (`ulimit -v`)
/// is `Storage_Error` that the program can handle, not an abort (the
/// default `--max-memory` ignored the process's real limit).
#[test]
fn deep_recursion_with_big_frames_under_ulimit_v_is_storage_error() {
    let deep = temp_file(
        "deep_frames.air",
        "type Block is array (1 .. 100_000) of Integer;\n\
         function Down (N : Natural) return Natural is\n\
            B : Block := (others => N);\n\
         begin\n   return Down (N + 1) + B (1);\nend Down;\n\
         begin\n   Put_Line (Natural'Image (Down (0)));\n\
         exception\n   when Storage_Error => Put_Line (\"Storage_Error caught\");\nend;\n",
    );
    let out = Command::new("sh")
        .arg("-c")
        .arg("ulimit -v 1048576 && exec \"$0\" run \"$1\"")
        .arg(env!("CARGO_BIN_EXE_adair"))
        .arg(&deep)
        .env("NO_COLOR", "1")
        .output()
        .expect("sh");
    let (stdout, err) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert_eq!(out.status.code(), Some(0), "{stdout}{err}");
    assert_eq!(stdout, "Storage_Error caught\n", "{err}");
}
