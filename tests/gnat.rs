//! The GNAT comparison: every `tests/ada/X.adb` runs in adair and must print
//! what GNAT printed and end with GNAT's exit status.
//!
//! GNAT's output is recorded beside the program in `tests/ada/X.gnat` (first
//! line `-- gnat exit: N`, then standard output byte for byte), so that
//! `cargo test` needs no Ada compiler. `ADAIR_GNAT` asks for the live compiler:
//! - `ADAIR_GNAT=verify` (what `.ci/run` sets): also compile each program
//!   with `gnatmake` and fail when GNAT's output differs from the recording;
//! - `ADAIR_GNAT=record`: compile with `gnatmake` and rewrite the recordings
//!   (read the diff before committing it).
//!
//! A program without a recording fails: record it with `ADAIR_GNAT=record`.
#![allow(clippy::print_stdout, clippy::print_stderr)]

use libtest_mimic::{Arguments, Failed, Trial};
use std::path::{Path, PathBuf};
use std::process::Command;

/// What GNAT printed and its exit status.
#[derive(Debug, PartialEq)]
struct Recorded {
    stdout: String,
    code: i32,
}

const HEADER: &str = "-- gnat exit: ";

fn parse_recording(text: &str) -> Result<Recorded, String> {
    let (first, rest) = text.split_once('\n').unwrap_or((text, ""));
    let code = first
        .strip_prefix(HEADER)
        .and_then(|c| c.trim().parse().ok())
        .ok_or_else(|| format!("the first line must be `{HEADER}N`, found {first:?}"))?;
    Ok(Recorded {
        stdout: rest.to_string(),
        code,
    })
}

fn render_recording(r: &Recorded) -> String {
    format!("{HEADER}{}\n{}", r.code, r.stdout)
}

fn gnat_output(src: &Path, work: &Path) -> Result<Recorded, String> {
    let stem = src
        .file_stem()
        .and_then(|s| s.to_str())
        .ok_or("bad file name")?;
    let dir = work.join(stem);
    std::fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
    let file = dir.join(format!("{stem}.adb"));
    std::fs::copy(src, &file).map_err(|e| e.to_string())?;
    let out = Command::new("gnatmake")
        .args(["-q", "-gnat2012", &format!("{stem}.adb")])
        .current_dir(&dir)
        .output()
        .map_err(|e| {
            format!("ADAIR_GNAT is set but gnatmake cannot run ({e}); install GNAT: apt-get install -y gnat")
        })?;
    if !out.status.success() {
        return Err(format!(
            "gnatmake failed:\n{}",
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    let run = Command::new(dir.join(stem))
        .output()
        .map_err(|e| e.to_string())?;
    Ok(Recorded {
        stdout: String::from_utf8_lossy(&run.stdout).into_owned(),
        code: run.status.code().unwrap_or(-1),
    })
}

fn adair_output(src: &Path) -> Recorded {
    let buf = adair::golden::SharedBuf::default();
    let mut s = adair::session::Session::new(Box::new(buf.clone()));
    let text = std::fs::read_to_string(src).unwrap_or_default();
    let outcome = s.run_source(&src.to_string_lossy(), &text);
    Recorded {
        stdout: buf.take(),
        code: outcome.exit_code(),
    }
}

#[derive(Clone, Copy, PartialEq)]
enum Mode {
    /// Compare adair with the recording only.
    Recorded,
    /// Also check the recording against a live gnatmake.
    Verify,
    /// Rewrite the recording from a live gnatmake.
    Record,
}

fn compare(what: &str, want: &Recorded, got: &Recorded) -> Result<(), Failed> {
    if want.stdout != got.stdout {
        return Err(Failed::from(format!(
            "{what}: stdout differs:\n{}",
            adair::golden::diff(&want.stdout, &got.stdout)
        )));
    }
    if want.code != got.code {
        return Err(Failed::from(format!(
            "{what}: exit status {} expected, {} found",
            want.code, got.code
        )));
    }
    Ok(())
}

fn trial(path: &Path, work: &Path, mode: Mode) -> Result<(), Failed> {
    let rec_path = path.with_extension("gnat");
    let recorded = match mode {
        Mode::Record => {
            let live = gnat_output(path, work).map_err(Failed::from)?;
            std::fs::write(&rec_path, render_recording(&live)).map_err(|e| e.to_string())?;
            live
        }
        _ => {
            let text = std::fs::read_to_string(&rec_path).map_err(|e| {
                format!(
                    "no recorded GNAT output {} ({e}); record it with ADAIR_GNAT=record cargo test --test gnat",
                    rec_path.display()
                )
            })?;
            let recorded =
                parse_recording(&text).map_err(|e| format!("{}: {e}", rec_path.display()))?;
            if mode == Mode::Verify {
                let live = gnat_output(path, work).map_err(Failed::from)?;
                compare("recording (-) against live GNAT (+)", &recorded, &live)?;
            }
            recorded
        }
    };
    compare("GNAT (-) against adair (+)", &recorded, &adair_output(path))
}

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let work = std::env::temp_dir().join(format!("adair-gnat-{}", std::process::id()));
    let mode = match std::env::var("ADAIR_GNAT").as_deref() {
        Ok("verify") => Mode::Verify,
        Ok("record") => Mode::Record,
        Ok("") | Err(_) => Mode::Recorded,
        Ok(other) => {
            eprintln!("ADAIR_GNAT={other}: expected `verify` or `record`");
            std::process::exit(2);
        }
    };
    if mode == Mode::Recorded {
        eprintln!(
            "gnat: comparing with the GNAT outputs recorded in tests/ada/*.gnat \
             (ADAIR_GNAT=verify also re-runs gnatmake; .ci/run does)"
        );
    }
    let mut files: Vec<PathBuf> = std::fs::read_dir(root.join("tests/ada"))
        .expect("tests/ada")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "adb"))
        .collect();
    files.sort();
    let trials = files
        .into_iter()
        .map(|path| {
            let work = work.clone();
            let name = format!(
                "ada::{}",
                path.file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default()
            );
            Trial::test(name, move || trial(&path, &work, mode))
        })
        .chain(std::iter::once(Trial::test(
            "recording_format_round_trips",
            || {
                let r = Recorded {
                    stdout: "a\n-- gnat exit: 3\nno newline".into(),
                    code: 1,
                };
                let back = parse_recording(&render_recording(&r)).map_err(Failed::from)?;
                if back != r {
                    return Err(Failed::from(format!("{back:?} != {r:?}")));
                }
                if parse_recording("hello\n").is_ok() {
                    return Err(Failed::from("a file without the header was accepted"));
                }
                Ok(())
            },
        )))
        .collect();
    let conclusion = libtest_mimic::run(&Arguments::from_args(), trials);
    let _ = std::fs::remove_dir_all(&work);
    conclusion.exit();
}
