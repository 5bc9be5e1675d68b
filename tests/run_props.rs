//! Random well-typed programs whose output is known by construction (issues
//! 14 and 32). The generator (`run_props/program.rs`) builds each program as
//! a small tree, writes it out as Ada and evaluates the tree itself by Ada's
//! rules; adair must print exactly what that oracle expects and end the same
//! way (normally, or with the same unhandled exception), never with a panic
//! or a check error. Every loop is bounded, so each program ends. Its
//! integer expressions overflow, divide by zero and index out of range often
//! enough that the exception paths run as much as the normal ones.
//!
//! The oracle is itself checked against GNAT: when `gnatmake` is on the
//! `PATH` (CI installs it), `the_oracle_agrees_with_gnat` compiles 50 of the
//! programs and compares; without it, that test says it is skipped.
//!
//! `PROPTEST_CASES` sets the number of programs (default 256);
//! `PROPS_GNAT_CASES` the number compared with GNAT (default 50) and
//! `PROPS_GNAT_SEED` the first seed of those (default 1000);
//! `PROPS_SHOW=1` prints each program and its expected output.
#![allow(clippy::print_stderr)]

#[path = "run_props/program.rs"]
mod program;

use adair::session::{Outcome, Session};
use program::{Ending, Expected, known_program};
use proptest::prelude::*;
use std::process::Command;

/// Runs a program on a thread with a large stack (a debug build's deep
/// expressions) and returns the outcome and what the program printed.
fn run(src: &str) -> (Outcome, String) {
    let src = src.to_string();
    std::thread::Builder::new()
        .stack_size(256 << 20)
        .spawn(move || {
            let buf = adair::golden::SharedBuf::default();
            let mut s = Session::new(Box::new(buf.clone()));
            let o = s.run_source("generated.air", &src);
            (o, buf.take())
        })
        .expect("thread")
        .join()
        .unwrap_or_else(|p| std::panic::resume_unwind(p))
}

/// adair's outcome as the oracle writes it, or why it is none of those.
fn adair_ending(outcome: &Outcome) -> Result<Ending, String> {
    match outcome {
        Outcome::Ok => Ok(Ending::Normal),
        Outcome::Raised(d) => {
            for e in [program::Exc::Constraint, program::Exc::Oops] {
                if d.message.contains(e.ada_name()) {
                    return Ok(Ending::Raised(e));
                }
            }
            Err(format!("an unexpected exception: {}", d.message))
        }
        Outcome::CheckFailed(ds) => Err(format!(
            "a well-typed program was refused: {}",
            ds.iter()
                .filter(|d| !d.is_warning())
                .map(|d| d.message.clone())
                .collect::<Vec<_>>()
                .join("; ")
        )),
    }
}

fn check_program(seed: u64) -> Result<(), TestCaseError> {
    let (src, expected, _) = known_program(seed);
    let (outcome, printed) = run(&src);
    if std::env::var_os("PROPS_SHOW").is_some() {
        eprintln!("{src}\n=> {expected:?}\nadair: {outcome:?}");
    }
    let ending = adair_ending(&outcome).map_err(|e| TestCaseError::fail(format!("{e}\n{src}")))?;
    prop_assert_eq!(
        &printed,
        &expected.output,
        "adair (left) prints other than the oracle (right) on\n{}",
        src
    );
    prop_assert_eq!(
        ending,
        expected.ending,
        "adair (left) ends other than the oracle (right) on\n{}",
        src
    );
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn generated_programs_print_and_end_as_the_oracle_expects(seed in any::<u64>()) {
        check_program(seed)?;
    }
}

/// The generator writes every kind of statement, most programs have a known
/// output, and both endings happen: a test of the test, so that it cannot
/// pass by generating nothing or by leaving everything out.
#[test]
fn the_generator_covers_what_it_claims() {
    let mut text = String::new();
    let (mut normal, mut raised, mut unknown) = (0, 0, 0);
    let mut lines = 0;
    for seed in 0..64 {
        let (src, expected, used) = known_program(seed);
        unknown += used - seed;
        match expected.ending {
            Ending::Normal => normal += 1,
            Ending::Raised(_) => raised += 1,
        }
        lines += expected.output.lines().count();
        text.push_str(&src);
    }
    for construct in [
        "for K",
        "while C",
        "case ",
        "exception",
        "raise Oops",
        "raise Constraint_Error",
        "when others",
        "Bump (",
        "Bump (P1",
        "Twice (",
        " mod ",
        " rem ",
        " / ",
        " ** ",
        "abs (",
        "(-",
        "Integer (",
        "Float (",
        "(if ",
        " in 1 .. ",
        "Word'Image (",
        "Ring'Image (",
        "Boolean'Image (",
        "Float'Image (",
        "'Succ (",
        " xor ",
        "(not ",
        "P1 := ",
        "G1 := (Fingers",
        "G2 := G1;",
        "G1.Suction",
        "'Constrained",
        "Character'Pos",
    ] {
        assert!(text.contains(construct), "never generated: {construct}");
    }
    assert!(
        normal >= 8 && raised >= 8,
        "ended normally {normal}, raised {raised}"
    );
    assert!(lines >= 100, "only {lines} lines of output in 64 programs");
    assert!(
        unknown <= 64,
        "{unknown} programs left out as unpredictable for 64 known ones"
    );
}

/// GNAT compiles and runs a program: its standard output and how it ended.
fn gnat_run(dir: &std::path::Path, src: &str) -> Result<(String, Ending), String> {
    std::fs::create_dir_all(dir).map_err(|e| e.to_string())?;
    std::fs::write(dir.join("generated.adb"), src).map_err(|e| e.to_string())?;
    let out = Command::new("gnatmake")
        .args(["-q", "-gnat2012", "generated.adb"])
        .current_dir(dir)
        .output()
        .map_err(|e| e.to_string())?;
    if !out.status.success() {
        return Err(format!(
            "gnatmake refused it:\n{}",
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    let run = Command::new(dir.join("generated"))
        .output()
        .map_err(|e| e.to_string())?;
    let stdout = String::from_utf8_lossy(&run.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&run.stderr);
    let ending = match run.status.code() {
        Some(0) => Ending::Normal,
        Some(1) if stderr.contains("raised CONSTRAINT_ERROR") => {
            Ending::Raised(program::Exc::Constraint)
        }
        Some(1) if stderr.contains("raised GENERATED.OOPS") => Ending::Raised(program::Exc::Oops),
        code => return Err(format!("exit status {code:?}, stderr:\n{stderr}")),
    };
    Ok((stdout, ending))
}

/// The oracle is right: GNAT prints and ends as it expects, on programs of
/// the generator's fixed seeds. Needs `gnatmake` (skipped without it).
#[test]
#[allow(clippy::print_stdout)] // says when it is skipped
fn the_oracle_agrees_with_gnat() {
    if Command::new("gnatmake").arg("--version").output().is_err() {
        println!("skipped: gnatmake is not on the PATH (apt-get install gnat); CI runs it");
        return;
    }
    let cases: u64 = std::env::var("PROPS_GNAT_CASES")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(50);
    let work = std::env::temp_dir().join(format!("adair-run-props-{}", std::process::id()));
    let mut failures = Vec::new();
    let mut kept = 0;
    let mut seed: u64 = std::env::var("PROPS_GNAT_SEED")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(1_000);
    for _ in 0..cases {
        let (src, expected, used) = known_program(seed);
        seed = used + 1;
        let dir = work.join(used.to_string());
        let result = gnat_run(&dir, &src);
        // Only the source of a failure is kept: a binary is a megabyte.
        let _ = std::fs::remove_dir_all(&dir);
        match result {
            Ok((output, ending)) => {
                let got = Expected { output, ending };
                if got != expected {
                    failures.push(format!(
                        "seed {used}: GNAT {got:?}\noracle {expected:?}\n{}",
                        adair::golden::diff(&expected.output, &got.output)
                    ));
                }
            }
            Err(e) => failures.push(format!("seed {used}: {e}")),
        }
        if failures.len() > kept {
            kept = failures.len();
            let _ = std::fs::write(work.join(format!("{used}.adb")), &src);
        }
    }
    if failures.is_empty() {
        let _ = std::fs::remove_dir_all(&work);
    }
    assert!(
        failures.is_empty(),
        "{} of {cases} programs differ (sources kept in {}):\n{}",
        failures.len(),
        work.display(),
        failures.join("\n\n")
    );
}
