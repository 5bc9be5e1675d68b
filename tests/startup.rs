//! Start-up (issue 32 item 4): a run parses its own text, not the
//! predefined library's, which is kept parsed in `stdlib/parsed/`.

use adair::session::{STDLIB, Session, stdlib_text};
use adair::syntax::ast::CompilationUnit;
use adair::syntax::compact;

/// Each stdlib file's parsed form is its text's syntax tree (with the
/// AdaIR package's services, generated from their table). After a change
/// of a stdlib file, of the services or of the syntax tree's types,
/// `ADAIR_BLESS=1 cargo test --test startup` writes them again.
#[test]
fn the_parsed_library_is_its_text() {
    let bless = std::env::var_os("ADAIR_BLESS").is_some();
    let mut stale = Vec::new();
    for u in STDLIB {
        let text = stdlib_text(u.text);
        let (unit, diags) = adair::syntax::parse_source(&text, 3);
        assert!(diags.is_empty(), "{}: {diags:?}", u.name);
        let unit = unit.expect("the stdlib parses");
        let bytes = compact::encode(&unit).expect("a syntax tree encodes");
        // Read back (in another source), it is the tree parsed there.
        assert_eq!(
            compact::decode::<CompilationUnit>(&bytes, 3).as_ref(),
            Some(&unit),
            "{}",
            u.name
        );
        if bytes == u.parsed {
            continue;
        }
        let stem = std::path::Path::new(u.name)
            .file_stem()
            .and_then(|s| s.to_str())
            .expect("a stdlib file's name");
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("stdlib/parsed")
            .join(format!("{stem}.bin"));
        if bless {
            std::fs::write(&path, &bytes).expect("write the parsed form");
        } else {
            stale.push(path.display().to_string());
        }
    }
    assert!(
        stale.is_empty(),
        "stale parsed forms of the stdlib: {stale:?}; \
         `ADAIR_BLESS=1 cargo test --test startup` writes them"
    );
}

const HELLO: &str = "with Ada.Text_IO; use Ada.Text_IO;
procedure Hello is
begin
   Put_Line (\"Hello\");
end Hello;
";

/// A session parses no text of the library: neither the file it checks
/// at its start nor those a program names or a script may use (the REPL,
/// the language server). Only the program's own text is parsed.
#[test]
fn a_session_parses_no_library_text() {
    let before = adair::work::texts_parsed();
    let mut s = Session::new(Box::new(std::io::sink()));
    assert_eq!(adair::work::texts_parsed(), before, "Session::new");
    s.check_source("hello.adb", HELLO, false)
        .expect("hello checks");
    assert_eq!(adair::work::texts_parsed(), before + 1, "hello.adb");
    s.load_stdlib();
    assert_eq!(adair::work::texts_parsed(), before + 1, "load_stdlib");
    let robot = "with AdaIR; use AdaIR;
with Ada.Calendar; with Ada.Numerics.Elementary_Functions;
procedure Arm is
begin
   null;
end Arm;
";
    let mut s = Session::new(Box::new(std::io::sink()));
    s.check_source("arm.adb", robot, false).expect("arm checks");
    assert_eq!(adair::work::texts_parsed(), before + 2, "arm.adb");
}
