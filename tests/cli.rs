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
        first.starts_with(&format!("{bad}:2:1: error: ")),
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
    // block around it: 22 levels took over a minute, 40 would take days.
    let src = format!(
        "procedure P is\nbegin\n{}null;\n",
        "declare X : Integer;\nbegin\n".repeat(40)
    );
    let f = temp_file("unclosed_declares.air", &src);
    let (code, _, err) = adair(&["check", &f]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("end of input"),
        "{}",
        &err[..err.len().min(600)]
    );
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
        err.contains(":1:10016: error: nesting too deep: more than 10000 levels of parentheses"),
        "{}",
        &err[..err.len().min(400)]
    );
    assert_eq!(err.matches("error:").count(), 1, "one error only");

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
        err.contains(":10002:1: error: nesting too deep: more than 10000 levels of blocks"),
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
        err.contains("grow_unhandled.air:4:17: error: unhandled exception: raised STORAGE_ERROR : out of memory")
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
