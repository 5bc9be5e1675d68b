//! `adair explain`: every code of `diag::codes` has a page with a wrong and
//! a right example, and the examples do what the page says. The wrong one
//! gives a diagnostic of the page's code (`error[E0201]` or
//! `warning[W0001]` in its output: `adair check`, or `adair run` for the
//! run-time codes E09xx); the right one checks (and runs) without it.
//! A page that says `<!-- not run: WHY -->` (Ctrl-C, 10,000 levels) is
//! only checked for its form.

use std::path::{Path, PathBuf};
use std::process::Command;

fn adair(args: &[&str], dir: &Path) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_adair"))
        .args(args)
        .current_dir(dir)
        .env("NO_COLOR", "1")
        .stdin(std::process::Stdio::null())
        .output()
        .expect("run adair");
    (
        out.status.code().unwrap_or(-1),
        format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        ),
    )
}

/// The first ```ada block after the heading `## NAME`.
fn example<'a>(page: &'a str, heading: &str) -> Option<&'a str> {
    let at = page.find(&format!("\n## {heading}\n"))?;
    let rest = &page[at..];
    let start = rest.find("```ada\n")? + "```ada\n".len();
    let len = rest[start..].find("```")?;
    Some(&rest[start..start + len])
}

fn scratch() -> PathBuf {
    let d = std::env::temp_dir().join(format!("adair-explain-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn every_code_has_a_page_whose_examples_do_what_it_says() {
    let dir = scratch();
    let mut failures = Vec::new();
    for e in adair::diag::codes::ALL {
        let code = e.code.0;
        let page = e.page;
        let head = format!("# {code}: {}\n", e.title);
        if !page.starts_with(&head) {
            failures.push(format!(
                "{code}: the page must start with `{}`",
                head.trim()
            ));
            continue;
        }
        let (Some(wrong), Some(right)) = (example(page, "Wrong"), example(page, "Right")) else {
            failures.push(format!(
                "{code}: no ```ada example under `## Wrong` and `## Right`"
            ));
            continue;
        };
        if page.contains("<!-- not run:") {
            continue;
        }
        let runtime = code.starts_with("E09");
        let verb = if runtime { "run" } else { "check" };
        let mark = if code.starts_with('W') {
            format!("warning[{code}]")
        } else {
            format!("error[{code}]")
        };
        let file = dir.join(format!("{code}.air"));
        std::fs::write(&file, wrong).unwrap();
        let (status, out) = adair(&[verb, file.to_str().unwrap()], &dir);
        if !out.contains(&mark) {
            failures.push(format!(
                "{code}: `adair {verb}` of the wrong example (status {status}) does not show `{mark}`:\n{out}"
            ));
        }
        std::fs::write(&file, right).unwrap();
        let (status, out) = adair(&[verb, file.to_str().unwrap()], &dir);
        if status != 0 || out.contains(&format!("[{code}]")) {
            failures.push(format!(
                "{code}: `adair {verb}` of the right example ends with status {status}:\n{out}"
            ));
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

#[test]
fn explain_prints_a_page_lists_the_codes_and_refuses_an_unknown_one() {
    let dir = scratch();
    let (status, out) = adair(&["explain", "e0201"], &dir);
    assert_eq!(status, 0, "{out}");
    assert!(out.starts_with("# E0201: "), "{out}");
    assert!(
        out.contains("## Wrong") && out.contains("## Right"),
        "{out}"
    );
    let (status, out) = adair(&["explain"], &dir);
    assert_eq!(status, 0, "{out}");
    assert_eq!(out.lines().count(), adair::diag::codes::ALL.len(), "{out}");
    assert!(
        out.contains("W0001  a variable that is never read"),
        "{out}"
    );
    let (status, out) = adair(&["explain", "E9999"], &dir);
    assert_eq!(status, 2, "{out}");
    assert!(out.contains("no code `E9999`"), "{out}");
}

/// A diagnostic's first line carries its code, which `adair explain` takes.
#[test]
fn a_check_error_shows_its_code_in_its_first_line() {
    let dir = scratch();
    let file = dir.join("typo.air");
    std::fs::write(&file, "InitRobot;\nCountt := 1;\n").unwrap();
    let (status, out) = adair(&["check", "typo.air"], &dir);
    assert_eq!(status, 2, "{out}");
    assert!(
        out.starts_with("typo.air:2:1: error[E0201]: `Countt` is not declared"),
        "{out}"
    );
}
