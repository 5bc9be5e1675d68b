//! REPL transcripts: each `tests/repl/NAME.in` is fed to the REPL as piped
//! input; the output must equal `NAME.out` (`BLESS=1` rewrites it).

use adair::golden::SharedBuf;
use libtest_mimic::{Arguments, Failed, Trial};
use std::io::Write;
use std::path::PathBuf;

fn transcript(input: &str) -> String {
    let buf = SharedBuf::default();
    let b2 = buf.clone();
    let mut out = buf.clone();
    let code = adair::repl::term::piped_with(
        input.as_bytes(),
        Box::new(move || Box::new(b2.clone()) as Box<dyn Write>),
        &mut out,
        true,
    );
    let mut text = buf.take();
    text.push_str(&format!("-- exit: {code}\n"));
    text
}

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    std::env::set_current_dir(&root).expect("crate root");
    let bless = std::env::var_os("BLESS").is_some();
    let mut files: Vec<PathBuf> = std::fs::read_dir("tests/repl")
        .expect("tests/repl")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "in"))
        .collect();
    files.sort();
    let trials = files
        .into_iter()
        .map(|path| {
            let name = format!(
                "repl::{}",
                path.file_stem()
                    .map(|s| s.to_string_lossy().into_owned())
                    .unwrap_or_default()
            );
            Trial::test(name, move || {
                let input =
                    std::fs::read_to_string(&path).map_err(|e| Failed::from(e.to_string()))?;
                let actual = transcript(&input);
                let exp = path.with_extension("out");
                if bless {
                    std::fs::write(&exp, &actual).map_err(|e| Failed::from(e.to_string()))?;
                    return Ok(());
                }
                match std::fs::read_to_string(&exp) {
                    Ok(e) if e == actual => Ok(()),
                    Ok(e) => Err(Failed::from(format!(
                        "transcript differs (- expected, + actual):\n{}",
                        adair::golden::diff(&e, &actual)
                    ))),
                    Err(_) => Err(Failed::from(format!(
                        "{} is missing (run with BLESS=1)",
                        exp.display()
                    ))),
                }
            })
        })
        .collect::<Vec<_>>();
    let mut trials = trials;
    trials.push(Trial::test(
        "repl::private_components_are_not_completed",
        private_components_are_not_completed,
    ));
    libtest_mimic::run(&Arguments::from_args(), trials).exit();
}

/// Tab after `Var.` offers a record's components, but not those of a
/// private type outside its package (its full view is hidden there).
fn private_components_are_not_completed() -> Result<(), Failed> {
    let mut s = adair::session::Session::new(Box::new(std::io::sink()));
    let script = "\
package Axes is
   type Axis_Handle is private;
   function Make (Joint : Positive) return Axis_Handle;
private
   type Axis_Handle is record
      Joint : Positive := 1;
   end record;
end Axes;
package body Axes is
   function Make (Joint : Positive) return Axis_Handle is ((Joint => Joint));
end Axes;
type Plain is record
   Joint : Positive := 1;
end record;
Shoulder : Axes.Axis_Handle := Axes.Make (2);
Elbow : Plain;
";
    s.check_source("<entry 1>", script, true)
        .map_err(|d| Failed::from(format!("{d:?}")))?;
    let c = &s.front.checker;
    let plain = c.record_fields_of("Elbow");
    let private = c.record_fields_of("Shoulder");
    if plain != ["Joint"] || !private.is_empty() {
        return Err(Failed::from(format!(
            "Elbow. offers {plain:?}, Shoulder. offers {private:?}"
        )));
    }
    Ok(())
}
