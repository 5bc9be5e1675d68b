//! The GNAT comparison: every `tests/ada/X.adb` is compiled with `gnatmake`
//! and run, and `adair run` must print the same standard output and end with
//! the same exit status. GNAT must be installed (`.ci/run` installs it): a
//! missing GNAT fails these tests instead of skipping them.
#![allow(clippy::print_stdout, clippy::print_stderr)]

use libtest_mimic::{Arguments, Failed, Trial};
use std::path::{Path, PathBuf};
use std::process::Command;

fn gnat_output(src: &Path, work: &Path) -> Result<(String, i32), String> {
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
        .map_err(|e| format!("cannot run gnatmake ({e}); install GNAT: apt-get install -y gnat"))?;
    if !out.status.success() {
        return Err(format!(
            "gnatmake failed:\n{}",
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    let run = Command::new(dir.join(stem))
        .output()
        .map_err(|e| e.to_string())?;
    Ok((
        String::from_utf8_lossy(&run.stdout).into_owned(),
        run.status.code().unwrap_or(-1),
    ))
}

fn adair_output(src: &Path) -> (String, i32) {
    let buf = adair::golden::SharedBuf::default();
    let mut s = adair::session::Session::new(Box::new(buf.clone()));
    let text = std::fs::read_to_string(src).unwrap_or_default();
    let outcome = s.run_source(&src.to_string_lossy(), &text);
    (buf.take(), outcome.exit_code())
}

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let work = std::env::temp_dir().join(format!("adair-gnat-{}", std::process::id()));
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
            Trial::test(name, move || {
                let (want, want_code) = gnat_output(&path, &work).map_err(Failed::from)?;
                let (got, got_code) = adair_output(&path);
                if want != got {
                    return Err(Failed::from(format!(
                        "stdout differs (- GNAT, + adair):\n{}",
                        adair::golden::diff(&want, &got)
                    )));
                }
                if want_code != got_code {
                    return Err(Failed::from(format!(
                        "exit status: GNAT {want_code}, adair {got_code}"
                    )));
                }
                Ok(())
            })
        })
        .collect();
    let conclusion = libtest_mimic::run(&Arguments::from_args(), trials);
    let _ = std::fs::remove_dir_all(&work);
    conclusion.exit();
}
