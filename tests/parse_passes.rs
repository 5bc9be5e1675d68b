//! The parser's lean first pass (src/syntax/parser/lean.rs) gives the tree
//! and the diagnostics the rich pass alone gives: on every program of the
//! repository, whole and cut short (where most have a syntax error).

use adair::syntax::{lexer, parser};
use std::path::{Path, PathBuf};

fn programs(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            programs(&p, out);
        } else if p
            .extension()
            .is_some_and(|x| x == "air" || x == "adb" || x == "ads")
        {
            out.push(p);
        }
    }
}

/// Both ways of parsing `text`, as text to compare.
fn both(text: &str) -> (String, String) {
    let (tokens, _) = lexer::lex(text, 0);
    let lean = parser::parse_passes(&tokens, 0, text.len(), false, true);
    let rich = parser::parse_passes(&tokens, 0, text.len(), false, false);
    (format!("{lean:?}"), format!("{rich:?}"))
}

#[test]
fn the_lean_pass_parses_every_program_as_the_rich_one() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for d in ["tests", "examples", "stdlib", "bench"] {
        programs(&root.join(d), &mut files);
    }
    files.sort();
    assert!(files.len() > 100, "only {} programs found", files.len());
    let (mut whole, mut with_errors) = (0, 0);
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap_or_default();
        let cuts = [text.len(), text.len() / 3, text.len() * 2 / 3];
        for cut in cuts {
            let Some(t) = text.get(..cut) else { continue };
            let (lean, rich) = both(t);
            assert!(
                lean == rich,
                "{} cut at {cut}:\nlean: {lean}\nrich: {rich}",
                f.display()
            );
            if rich.contains("Some(CompilationUnit") && rich.ends_with("[])") {
                whole += 1;
            } else {
                with_errors += 1;
            }
        }
    }
    // Both kinds were compared.
    assert!(
        whole > 100 && with_errors > 100,
        "{whole} without errors, {with_errors} with"
    );
}
