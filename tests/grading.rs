//! `adair test` as a grading tool (issue 37): a folder of student scripts
//! with a hang, input files, a configuration error; the same result however
//! a script is named; each script in its own folder; a JUnit report; a
//! stable order with `-j`; a diff with a legend; colour only when asked for
//! or on a terminal.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const BIN: &str = env!("CARGO_BIN_EXE_adair");

/// A fresh folder for one test.
fn class(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("adair-grading-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn write(dir: &Path, name: &str, text: &str) {
    let p = dir.join(name);
    std::fs::create_dir_all(p.parent().unwrap()).unwrap();
    std::fs::write(p, text).unwrap();
}

struct Run {
    code: i32,
    out: String,
    err: String,
    took: Duration,
}

/// `adair ARGS` in `dir` (NO_COLOR set unless `env` says otherwise), ended
/// after 60 s: `adair test` must never hang.
fn adair_in(dir: &Path, args: &[&str], env: &[(&str, &str)]) -> Run {
    let mut cmd = Command::new(BIN);
    cmd.args(args)
        .current_dir(dir)
        .env("NO_COLOR", "1")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    for (k, v) in env {
        cmd.env(k, v);
    }
    let start = Instant::now();
    let mut child = cmd.spawn().expect("run adair");
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > Duration::from_secs(60) {
            let _ = child.kill();
            panic!("adair {args:?} still runs after 60 s");
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    let took = start.elapsed();
    let o = child.wait_with_output().unwrap();
    Run {
        code: o.status.code().unwrap_or(-1),
        out: String::from_utf8_lossy(&o.stdout).into_owned(),
        err: String::from_utf8_lossy(&o.stderr).into_owned(),
        took,
    }
}

/// The report without the times of slow scripts (` (1.2 s)`).
fn untimed(out: &str) -> String {
    out.lines()
        .map(|l| match l.rfind(" (") {
            Some(i) if l.ends_with(" s)") => &l[..i],
            _ => l,
        })
        .map(|l| format!("{l}\n"))
        .collect()
}

/// A script that fails at run time, so that its expected output holds a
/// diagnostic with the script's name and place.
const RAISES: &str = "Put_Line (\"before\");\nX : Integer := 1 / 0;\n";

#[test]
fn a_golden_passes_however_the_script_is_named() {
    let dir = class("names");
    write(&dir, "ex4.air", RAISES);
    // Blessed under one name...
    let r = adair_in(&dir, &["test", "--bless", "ex4.air"], &[]);
    assert_eq!(r.code, 0, "{}{}", r.out, r.err);
    let out = std::fs::read_to_string(dir.join("ex4.out")).unwrap();
    assert!(out.contains("\nex4.air:2:16: error[E0901]:"), "{out}");
    // ... it passes under every other: relative, `./`, absolute, the folder
    // (none given, `.`, from its parent), and from elsewhere.
    let abs = dir.join("ex4.air").to_string_lossy().into_owned();
    let d = dir.to_string_lossy().into_owned();
    let parent = dir.parent().unwrap();
    let leaf = dir.file_name().unwrap().to_string_lossy().into_owned();
    let from_parent = format!("{leaf}/ex4.air");
    for (cwd, args) in [
        (dir.as_path(), vec!["test", "ex4.air"]),
        (dir.as_path(), vec!["test", "./ex4.air"]),
        (dir.as_path(), vec!["test", &abs]),
        (dir.as_path(), vec!["test"]),
        (dir.as_path(), vec!["test", "."]),
        (parent, vec!["test", &from_parent]),
        (Path::new("/"), vec!["test", &d]),
    ] {
        let r = adair_in(cwd, &args, &[]);
        assert_eq!(
            (r.code, r.out.lines().last()),
            (0, Some("1 passed, 0 failed")),
            "adair {args:?} in {}: {}{}",
            cwd.display(),
            r.out,
            r.err
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn each_script_runs_in_its_own_folder() {
    let dir = class("cwd");
    // A path taught and saved by its file name lands beside the script.
    write(
        &dir,
        "cell/teach.air",
        "InitRobot;\nCreatePath (1);\nInsertPosition (1, 1, Trans (300.0, 0.0, 200.0));\n\
         SavePathSystem (\"taught.txt\");\nPut_Line (\"saved\");\n",
    );
    write(&dir, "cell/teach.out", "saved\n");
    // And a file beside the script is read by its name.
    write(
        &dir,
        "cell/reload.air",
        "InitRobot;\nLoadPathSystem (\"given.txt\");\nDeletePath (3);\n\
         Put_Line (\"path 3 was loaded\");\n",
    );
    write(&dir, "cell/reload.out", "path 3 was loaded\n");
    let r = adair_in(&dir, &["test", "cell/teach.air"], &[]);
    assert_eq!(r.code, 0, "{}{}", r.out, r.err);
    assert!(
        dir.join("cell/taught.txt").is_file(),
        "not beside the script"
    );
    assert!(
        !dir.join("taught.txt").exists(),
        "written in the caller's folder"
    );
    std::fs::rename(dir.join("cell/taught.txt"), dir.join("cell/given.txt")).unwrap();
    // (the saved path is path 1: make it path 3 by the file's own words)
    let text = std::fs::read_to_string(dir.join("cell/given.txt")).unwrap();
    let renumbered = text.replacen("path 1", "path 3", 1);
    assert_ne!(text, renumbered, "the saved file's format changed: {text}");
    std::fs::write(dir.join("cell/given.txt"), renumbered).unwrap();
    let r = adair_in(&dir, &["test", "cell/reload.air"], &[]);
    assert_eq!(r.code, 0, "{}{}", r.out, r.err);
    let _ = std::fs::remove_dir_all(&dir);
}

/// A script that reads a line and greets.
const GREETS: &str = "declare\n   S : String (1 .. 80);\n   L : Natural;\nbegin\n\
                      Get_Line (S, L);\n   Put_Line (\"hello \" & S (1 .. L));\nend;\n";

#[test]
fn x_in_is_the_standard_input_and_without_it_the_input_is_empty() {
    let dir = class("input");
    write(&dir, "greet.air", GREETS);
    write(&dir, "greet.in", "Ada\n");
    write(&dir, "greet.out", "hello Ada\n");
    write(&dir, "alone.air", GREETS);
    let r = adair_in(&dir, &["test", "--bless", "alone.air"], &[]);
    assert_eq!(r.code, 0, "{}{}", r.out, r.err);
    let alone = std::fs::read_to_string(dir.join("alone.out")).unwrap();
    assert!(alone.contains("END_ERROR"), "{alone}");
    let r = adair_in(&dir, &["test"], &[]);
    assert_eq!(r.code, 0, "{}{}", r.out, r.err);
    assert!(r.out.ends_with("2 passed, 0 failed\n"), "{}", r.out);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_hang_is_a_failure_at_the_time_limit_and_the_others_still_run() {
    let dir = class("hang");
    write(
        &dir,
        "a_hang.air",
        "Put_Line (\"started\");\nloop\n   null;\nend loop;\n",
    );
    write(&dir, "a_hang.out", "started\n");
    // One that swallows the interrupt: its process is killed.
    write(
        &dir,
        "b_stubborn.air",
        "loop\n   begin\n      loop\n         null;\n      end loop;\n   exception\n      \
         when others => null;\n   end;\nend loop;\n",
    );
    write(&dir, "b_stubborn.out", "");
    write(&dir, "c_fine.air", "Put_Line (\"fine\");\n");
    write(&dir, "c_fine.out", "fine\n");
    let r = adair_in(&dir, &["test", "--timeout", "1", "-j", "1"], &[]);
    assert_eq!(r.code, 1, "{}{}", r.out, r.err);
    assert!(r.out.ends_with("1 passed, 2 failed\n"), "{}", r.out);
    assert!(
        r.out
            .contains("FAIL ./a_hang.air: still running after 1 s (wall clock)")
            && r.out.contains("    started\n"),
        "the limit and what it printed: {}",
        r.out
    );
    assert!(
        r.out
            .contains("FAIL ./b_stubborn.air: still running after 1 s"),
        "{}",
        r.out
    );
    assert!(r.out.contains("ok   ./c_fine.air"), "{}", r.out);
    // 1 s each, and the stubborn one's grace: well under the default limit.
    assert!(r.took < Duration::from_secs(9), "took {:?}", r.took);
    // A script's own limit wins over the command line's.
    write(
        &dir,
        "a_hang.air",
        "-- adair: --timeout 1\nPut_Line (\"started\");\nloop\n   null;\nend loop;\n",
    );
    let r = adair_in(&dir, &["test", "--timeout", "60", "a_hang.air"], &[]);
    assert_eq!(r.code, 1, "{}{}", r.out, r.err);
    assert!(r.out.contains("still running after 1 s"), "{}", r.out);
    assert!(r.took < Duration::from_secs(8), "took {:?}", r.took);
    // A hang is never blessed.
    let r = adair_in(&dir, &["test", "--bless", "a_hang.air"], &[]);
    assert_eq!(r.code, 1, "{}{}", r.out, r.err);
    assert_eq!(
        std::fs::read_to_string(dir.join("a_hang.out")).unwrap(),
        "started\n"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn bless_refuses_a_configuration_error_and_shows_it_as_run_does() {
    let dir = class("config");
    write(
        &dir,
        "robot.air",
        "-- adair: --robot ur5\nPut_Line (\"x\");\n",
    );
    write(
        &dir,
        "option.air",
        "-- adair: --rbot rm-501\nPut_Line (\"x\");\n",
    );
    write(
        &dir,
        "devices.air",
        "-- adair: --devices cell.toml\nPut_Line (\"x\");\n",
    );
    write(&dir, "cell.toml", "this is not toml = = =\n");
    write(&dir, "good.air", "Put_Line (\"x\");\n");
    let r = adair_in(&dir, &["test", "--bless"], &[]);
    assert_eq!(r.code, 1, "{}{}", r.out, r.err);
    assert!(r.out.ends_with("1 passed, 3 failed\n"), "{}", r.out);
    for s in ["robot", "option", "devices"] {
        assert!(
            !dir.join(format!("{s}.out")).exists(),
            "{s}.air's configuration error was blessed"
        );
    }
    assert!(dir.join("good.out").exists());
    assert!(!r.out.contains("DescriptionError"), "{}", r.out);
    // As `adair run --robot ur5` says it.
    let run = adair_in(&dir, &["run", "--robot", "ur5", "good.air"], &[]);
    let said = run.err.trim().trim_start_matches("adair: ");
    assert!(r.out.contains(said), "{said}\n{}", r.out);
    assert!(r.out.contains("unknown option `--rbot`"), "{}", r.out);
    assert!(r.out.contains("cell.toml:1:"), "{}", r.out);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn with_jobs_the_report_keeps_the_order_of_the_scripts() {
    let dir = class("jobs");
    // The first scripts are the slow ones: in parallel they end last.
    for (i, n) in [20_000_000, 10_000_000, 0, 0, 0, 0].iter().enumerate() {
        write(
            &dir,
            &format!("s{i}.air"),
            &format!(
                "N : Integer := 0;\nfor I in 1 .. {n} loop\n   N := N + 1;\nend loop;\n\
                 Put_Line (\"s{i}\" & Integer'Image (N));\n"
            ),
        );
    }
    let r = adair_in(&dir, &["test", "--bless", "-j", "1"], &[]);
    assert_eq!(r.code, 0, "{}{}", r.out, r.err);
    // One script is wrong, to have a diff in the report.
    write(&dir, "s3.out", "s3 1\n");
    let one = adair_in(&dir, &["test", "-j", "1"], &[]);
    let four = adair_in(&dir, &["test", "-j", "4"], &[]);
    assert_eq!(one.code, 1);
    assert_eq!(untimed(&one.out), untimed(&four.out));
    let names: Vec<&str> = one
        .out
        .lines()
        .filter_map(|l| l.split_whitespace().nth(1))
        .filter(|w| w.starts_with("./s"))
        .collect();
    assert_eq!(
        names,
        [
            "./s0.air",
            "./s1.air",
            "./s2.air",
            "./s3.air:",
            "./s4.air",
            "./s5.air"
        ],
        "{}",
        one.out
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_diff_has_a_legend_context_and_colour_only_when_asked() {
    let dir = class("diff");
    write(
        &dir,
        "count.air",
        "for I in 1 .. 9 loop\n   Put_Line (Integer'Image (I));\nend loop;\n",
    );
    write(
        &dir,
        "count.out",
        " 1\n 2\n 3\n 4\n 5\n 6\n 7\n 8\n 9\n 10\n",
    );
    let r = adair_in(&dir, &["test"], &[]);
    assert_eq!(r.code, 1);
    assert!(
        r.out.contains(
            "--- expected: count.out\n+++ actual: count.air's output\n\
             @@ expected line 7, actual line 7 @@\n\
             \x20    7 |  7\n     8 |  8\n     9 |  9\n-   10 |  10\n"
        ),
        "{}",
        r.out
    );
    assert!(
        !r.out.contains('\x1b'),
        "colour without a terminal: {}",
        r.out
    );
    let r = adair_in(&dir, &["--color", "always", "test"], &[]);
    assert!(r.out.contains("\x1b[31m-   10 |  10\x1b[0m"), "{}", r.out);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Checks that `xml` is well-formed as far as a report needs: one root,
/// tags nested and closed, attribute values quoted, every `&` an entity,
/// no `<` or `>` in text or values. Returns the elements, in order.
fn well_formed(xml: &str) -> Vec<String> {
    let body = xml
        .strip_prefix("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n")
        .expect("XML declaration");
    let mut stack: Vec<String> = Vec::new();
    let mut seen = Vec::new();
    let mut rest = body;
    let check_text = |t: &str| {
        assert!(!t.contains('>'), "a raw > in {t:?}");
        let mut parts = t.split('&');
        parts.next();
        for p in parts {
            assert!(
                ["amp;", "lt;", "gt;", "quot;", "apos;", "#13;"]
                    .iter()
                    .any(|e| p.starts_with(e)),
                "a bare & in {t:?}"
            );
        }
        assert!(
            t.chars()
                .all(|c| c == '\t' || c == '\n' || c >= ' ' && c != '\u{FFFE}'),
            "a character XML cannot hold in {t:?}"
        );
    };
    while let Some(i) = rest.find('<') {
        check_text(&rest[..i]);
        let j = rest[i..].find('>').expect("an unclosed tag") + i;
        let tag = &rest[i + 1..j];
        assert!(!tag.contains('<'), "a < inside {tag}");
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(stack.pop().as_deref(), Some(name), "closing {name}");
        } else {
            let empty = tag.ends_with('/');
            let tag = tag.trim_end_matches('/');
            let name = tag.split_whitespace().next().unwrap().to_string();
            // name="value" pairs, each value quoted and clean.
            let attrs = &tag[name.len()..];
            let quoted: Vec<&str> = attrs.split('"').collect();
            assert!(quoted.len() % 2 == 1, "unbalanced quotes in {tag}");
            for (k, part) in quoted.iter().enumerate() {
                if k % 2 == 1 {
                    check_text(part);
                } else if k + 1 < quoted.len() {
                    assert!(part.trim().ends_with('='), "{tag}");
                }
            }
            if stack.is_empty() {
                assert!(seen.is_empty(), "a second root element {name}");
            }
            seen.push(name.clone());
            if !empty {
                stack.push(name);
            }
        }
        rest = &rest[j + 1..];
    }
    assert!(rest.trim().is_empty(), "text after the root: {rest}");
    assert!(stack.is_empty(), "unclosed {stack:?}");
    seen
}

#[test]
fn junit_reports_every_script_in_well_formed_xml() {
    let dir = class("junit");
    // Names and output with what XML must escape, and an escape character.
    write(
        &dir,
        "a&b.air",
        "Put_Line (\"<tag> & \"\"quote\"\" 'it'\" & Character'Val (27) & \"[31m\");\n",
    );
    write(&dir, "a&b.out", "something else\n");
    write(&dir, "good.air", "Put_Line (\"ok\");\n");
    write(&dir, "good.out", "ok\n");
    write(&dir, "hang.air", "loop\n   null;\nend loop;\n");
    write(&dir, "hang.out", "");
    write(&dir, "config.air", "-- adair: --robot <none>\nnull;\n");
    write(&dir, "new.air", "Put_Line (\"new\");\n");
    let report = dir.join("report.xml");
    let rep = report.to_string_lossy().into_owned();
    let r = adair_in(&dir, &["test", "--timeout", "1", "--junit", &rep], &[]);
    assert_eq!(r.code, 1, "{}{}", r.out, r.err);
    let xml = std::fs::read_to_string(&report).unwrap();
    let elements = well_formed(&xml);
    assert_eq!(
        elements.iter().filter(|e| *e == "testcase").count(),
        5,
        "{xml}"
    );
    assert!(
        xml.contains("<testsuites name=\"adair test\" tests=\"5\" failures=\"3\" errors=\"1\""),
        "{xml}"
    );
    assert!(xml.contains("name=\"a&amp;b.air\""), "{xml}");
    assert!(
        xml.contains("&lt;tag&gt; &amp; &quot;quote&quot; &apos;it&apos;"),
        "{xml}"
    );
    assert!(xml.contains("type=\"timeout\""), "{xml}");
    assert!(xml.contains("type=\"missing\""), "{xml}");
    assert!(xml.contains("<error type=\"configuration\""), "{xml}");
    assert!(xml.contains("`&lt;none&gt;`"), "{xml}");
    assert!(
        xml.contains("<testcase classname=\".\" name=\"good.air\""),
        "{xml}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The processes running `adair test --child` in `dir`.
fn children_in(dir: &Path) -> Vec<u32> {
    let Ok(procs) = std::fs::read_dir("/proc") else {
        return Vec::new();
    };
    procs
        .flatten()
        .filter_map(|e| e.file_name().to_str()?.parse::<u32>().ok())
        .filter(|pid| {
            let cmd = std::fs::read(format!("/proc/{pid}/cmdline")).unwrap_or_default();
            let child = cmd.split(|b| *b == 0).any(|a| a == b"--child");
            child
                && std::fs::read_link(format!("/proc/{pid}/cwd"))
                    .is_ok_and(|c| c == dir || std::fs::canonicalize(dir).is_ok_and(|d| c == d))
        })
        .collect()
}

/// `adair test` killed while a script runs that swallows every interrupt:
/// the script's process does not run on for ever without its parent.
#[test]
fn a_script_does_not_outlive_a_killed_adair_test() {
    let dir = class("orphan");
    write(
        &dir,
        "stubborn.air",
        "loop\n   begin\n      loop\n         null;\n      end loop;\n   exception\n      \
         when others => null;\n   end;\nend loop;\n",
    );
    let mut parent = Command::new(BIN)
        .args(["test", "--timeout", "1", "stubborn.air"])
        .current_dir(&dir)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let mut pids = Vec::new();
    while pids.is_empty() && start.elapsed() < Duration::from_secs(10) {
        std::thread::sleep(Duration::from_millis(20));
        pids = children_in(&dir);
    }
    assert!(!pids.is_empty(), "no child process seen");
    parent.kill().unwrap();
    parent.wait().unwrap();
    // The limit (1 s), then twice the grace (2 s), and a margin.
    while !children_in(&dir).is_empty() && start.elapsed() < Duration::from_secs(12) {
        std::thread::sleep(Duration::from_millis(50));
    }
    let left = children_in(&dir);
    for pid in &left {
        let _ = Command::new("kill").args(["-9", &pid.to_string()]).status();
    }
    assert!(left.is_empty(), "still running after {:?}", start.elapsed());
    let _ = std::fs::remove_dir_all(&dir);
}

/// The `--max-memory` each script's process was given, with `-j jobs`.
fn memory_given(name: &str, jobs: &str) -> Option<u64> {
    let dir = class(name);
    write(&dir, "a.air", "loop\n   null;\nend loop;\n");
    write(&dir, "b.air", "loop\n   null;\nend loop;\n");
    let mut parent = Command::new(BIN)
        .args(["test", "--timeout", "1", "-j", jobs])
        .current_dir(&dir)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let mut given = None;
    while start.elapsed() < Duration::from_secs(10) {
        if let Some(pid) = children_in(&dir).first() {
            let cmd = std::fs::read(format!("/proc/{pid}/cmdline")).unwrap_or_default();
            let args: Vec<String> = cmd
                .split(|b| *b == 0)
                .map(|a| String::from_utf8_lossy(a).into_owned())
                .collect();
            given = args
                .iter()
                .position(|a| a == "--max-memory")
                .and_then(|i| args.get(i + 1)?.parse().ok());
            break;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    parent.wait().unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    given
}

/// Scripts that run at once share the memory (a class of recursion bombs
/// must not take the machine): each process gets its part.
#[test]
fn scripts_run_at_once_share_the_memory() {
    assert_eq!(memory_given("memory1", "1"), None);
    let part = memory_given("memory2", "2").expect("a limit with -j 2");
    assert!(part > 0, "{part}");
}
