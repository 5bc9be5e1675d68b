//! The checker through a session (moved from the unit tests of
//! `src/check/`, which may not build a `Session`: the checker is a layer
//! below it, tests/layering.rs).

use adair::session::Session;

/// A long program (its bodies parsed lazily, a part at a time) checked
/// for its diagnostics only (`adair check`) keeps no checked statement
/// of its lazy bodies, and reports what a check that keeps them reports:
/// an error in a late part, a warning.
#[test]
fn a_check_for_diagnostics_only_keeps_no_lazy_body() {
    let mut text =
        String::from("procedure Big is\n   X : Integer := 0;\n   Unused : Integer := 1;\nbegin\n");
    for i in 0..6000 {
        text.push_str(&format!("   X := X + {i} mod 7;\n"));
    }
    let good = format!("{text}end Big;\n");
    let bad = format!("{text}   X := \"late\";\nend Big;\n");
    let check = |src: &str, only: bool| {
        let mut s = Session::new(Box::new(std::io::sink()));
        s.front.checker.options.diagnostics_only = only;
        let r = s.check_source("big.adb", src, false);
        let body = s
            .front
            .checker
            .tables
            .funcs
            .iter()
            .find(|f| f.name.eq_ignore_ascii_case("big"))
            .and_then(|f| f.body.as_ref())
            .map(|b| format!("{b:?}").matches("Assign").count());
        let diags = match r {
            Ok(_) => s.warnings.clone(),
            Err(d) => d,
        };
        (format!("{diags:?}"), body)
    };
    assert!(good.len() >= 64 * 1024, "a lazily parsed source");
    let (kept, n) = check(&good, false);
    assert_eq!(n, Some(6000));
    let (only, n) = check(&good, true);
    assert_eq!(n, Some(0));
    assert_eq!(kept, only);
    assert!(kept.contains("Unused"), "{kept}");
    let (kept, _) = check(&bad, false);
    let (only, _) = check(&bad, true);
    assert!(kept.contains("late"), "{kept}");
    assert_eq!(kept, only);
}
