//! The golden corpus: every `.air` under `tests/golden/` and `examples/` is
//! one named test, run as `adair test` runs it (a child process of the
//! `adair` binary in the script's own folder, `X.in` as its input), and must
//! print its `.out` file.
//! `BLESS=1 cargo test --test golden` rewrites the `.out` files.
#![allow(clippy::print_stdout, clippy::print_stderr)]

use adair::golden::{self, Isolated, Verdict};
use libtest_mimic::{Arguments, Failed, Trial};
use std::path::{Path, PathBuf};

/// A generous time limit: the debug build on a loaded machine (a script's
/// `-- adair: --timeout` line still wins).
const LIMIT: f64 = 300.0;

fn runner() -> Isolated {
    Isolated {
        exe: PathBuf::from(env!("CARGO_BIN_EXE_adair")),
        global: Vec::new(),
        args: Vec::new(),
        env: Vec::new(),
        timeout: LIMIT,
    }
}

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    std::env::set_current_dir(&root).expect("crate root");
    let bless = std::env::var_os("BLESS").is_some();
    let dirs: Vec<PathBuf> = ["tests/golden", "examples"]
        .iter()
        .map(PathBuf::from)
        .filter(|p| p.exists())
        .collect();
    let scripts = golden::collect(&dirs).expect("golden corpus");
    let trials = scripts
        .into_iter()
        .map(|path| {
            let name = path.with_extension("").to_string_lossy().replace('/', "::");
            Trial::test(name, move || match runner().check(&path, bless) {
                Verdict::Pass | Verdict::Blessed => Ok(()),
                other => Err(failed(&path, &other)),
            })
        })
        .collect();
    libtest_mimic::run(&Arguments::from_args(), trials).exit();
}

/// The report `adair test` prints for a failed script.
fn failed(path: &Path, v: &Verdict) -> Failed {
    let r = golden::CaseResult {
        script: path.to_path_buf(),
        verdict: v.clone(),
        seconds: 0.0,
    };
    Failed::from(golden::progress(&r, false))
}
