//! The compiled engine on whole programs (moved from the unit tests of
//! `src/interp/vm/`, which may not build a `Session`: the engine is a
//! layer below it, tests/layering.rs): a long body compiled a part at a
//! time as it is checked, frames freed as scalars, a fused argument's
//! overflow, an exception's chain of calls.

use adair::diag::Diagnostic;
use adair::golden::SharedBuf;
use adair::session::{Outcome, Session};

/// A long program (over `LAZY_FROM`, so its bodies are parsed a part
/// at a time), with in each part: assignments, indexing, a call with an
/// `in out` parameter, a declare block (slots declared in a late part),
/// a loop left by `exit`, an exception handled inside the part, a call
/// in an aggregate (the function's body is not compiled as parts, only
/// the main program's is); a nested
/// recursive function, two mutually recursive ones and a procedure
/// with a handler; a task (the body is a master, which a
/// `return` leaves); and a `return`
/// in the last part.
fn long_program(task: bool) -> String {
    let mut t = String::from(
        "with Ada.Text_IO; use Ada.Text_IO;\nprocedure Big is\n\
         X : Integer := 0;\n\
         A : array (1 .. 10) of Integer := (others => 0);\n\
         type Pair is record L, R : Integer; end record;\n\
         P : Pair := (0, 0);\n\
         procedure Bump (V : in out Integer; K : Integer) is\n\
         begin\n   V := V + K;\n   if V < 0 then raise Constraint_Error; end if;\n\
         exception\n   when Constraint_Error => V := 0;\nend Bump;\n\
         function Twice (V : Integer) return Integer is\n\
         begin\n   if V > 1000 then return Twice (V - 1000); end if;\n   return V * 2;\nend Twice;\n\
         function Odd (N : Natural) return Boolean;\n\
         function Even (N : Natural) return Boolean is\n\
         begin\n   if N = 0 then return True; else return Odd (N - 1); end if;\nend Even;\n\
         function Odd (N : Natural) return Boolean is\n\
         begin\n   if N = 0 then return False; else return Even (N - 1); end if;\nend Odd;\n\
         begin\n",
    );
    if task {
        t = t.replace(
            "procedure Bump",
            "task T;\ntask body T is begin Put_Line (\"task\"); end T;\nprocedure Bump",
        );
    }
    for i in 0..2400 {
        t.push_str(&format!("   X := X + {i} mod 7;\n"));
        t.push_str(&format!(
            "   A ({}) := A ({}) + X mod 3;\n",
            i % 10 + 1,
            i % 10 + 1
        ));
        t.push_str(&format!("   Bump (X, {} - 3);\n", i % 5));
        t.push_str("   if X > 100000 then X := X - 99999; end if;\n");
        if i % 300 == 0 {
            t.push_str(&format!(
                "   declare\n      Y{i} : Integer := Twice (X);\n   begin\n      X := X + Y{i} mod 5;\n      if Even (X mod 10) then X := X + 1; end if;\n      P := (L => Twice (X mod 100), R => 1);\n      X := X + P.L mod 3;\n   end;\n"
            ));
            t.push_str("   for J in 1 .. 5 loop\n      X := X + J;\n      exit when J = 3;\n   end loop;\n");
            t.push_str(
                "   begin\n      if X mod 2 = 0 then raise Constraint_Error; end if;\n   \
                 exception\n      when Constraint_Error => X := X + 1;\n   end;\n",
            );
            t.push_str("   Put_Line (Integer'Image (X) & Integer'Image (A (3)));\n");
        }
    }
    t.push_str(
        "   if X > 0 then\n      Put_Line (\"returning\" & Integer'Image (X));\n      return;\n   end if;\n\
         Put_Line (\"not reached\");\nexception\n   when others => Put_Line (\"unexpected\");\nend Big;\n",
    );
    t
}

/// Output and outcome of a run of `src`, compiled as checked or not; and
/// whether the body of `Big` kept any checked assignment.
fn run(src: &str, parts: bool) -> (String, String, bool) {
    let buf = SharedBuf::default();
    let mut s = Session::new(Box::new(buf.clone()));
    if parts {
        s.compile_as_checked();
    }
    let outcome = s.run_source("big.adb", src);
    let kept = s
        .front
        .checker
        .tables
        .funcs
        .iter()
        .find(|f| f.name.eq_ignore_ascii_case("big"))
        .and_then(|f| f.body.as_ref())
        .is_some_and(|b| format!("{b:?}").contains("Assign"));
    let said = match &outcome {
        Outcome::CheckFailed(d) => format!("{d:?}"),
        Outcome::Raised(d) => format!("{d:?}"),
        Outcome::Ok => String::new(),
    };
    (buf.take(), format!("{} {said}", outcome.exit_code()), kept)
}

/// A long body compiled a part at a time as it is checked (`adair run`)
/// runs as the body compiled whole, and keeps none of its checked
/// statements.
#[test]
fn a_long_body_compiled_as_checked_runs_as_the_whole_body() {
    for task in [false, true] {
        let src = long_program(task);
        assert!(src.len() >= adair::syntax::LAZY_FROM, "{}", src.len());
        let (whole, code, kept) = run(&src, false);
        assert!(kept, "the checked body is kept without parts");
        assert!(whole.contains("returning"), "{whole}");
        assert!(!whole.contains("not reached") && !whole.contains("unexpected"));
        let lines = 1 + task as usize + 2400 / 300;
        assert_eq!(whole.lines().count(), lines, "{whole}");
        assert_eq!(code, "0 ");
        let (parts, code2, kept) = run(&src, true);
        assert!(!kept, "no checked statement of the long body is kept");
        assert_eq!((&parts, &code2), (&whole, &code));
    }
}

/// A long library procedure in a file the program names (`with`) is not
/// compiled as parts, though it is its unit's last: it is compiled whole
/// when a function called in an aggregate calls it.
#[test]
fn a_named_units_long_body_is_not_compiled_as_parts() {
    let dir = std::env::temp_dir().join(format!("adair-parts-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut helper =
        String::from("with Ada.Text_IO;\nprocedure Extra is\n   X : Integer := 0;\nbegin\n");
    for i in 0..6000 {
        helper.push_str(&format!("   X := X + {i} mod 7;\n"));
    }
    helper.push_str(
        "   Ada.Text_IO.Put_Line (\"extra\" & Integer'Image (X));\nend Extra;\n\
         package Helper is\n   function Run return Integer;\nend Helper;\n\
         package body Helper is\n   function Run return Integer is\n   begin\n\
         Extra;\n      return 1;\n   end Run;\nend Helper;\n",
    );
    assert!(helper.len() >= adair::syntax::LAZY_FROM);
    std::fs::write(dir.join("helper.adb"), helper).unwrap();
    let main = "with Helper;\nwith Ada.Text_IO;\nprocedure Main is\n\
        type Pair is record L, R : Integer; end record;\n\
        P : Pair := (0, 0);\n\
        begin\n   P := (L => Helper.Run, R => 2);\n\
        Ada.Text_IO.Put_Line (Integer'Image (P.L + P.R));\nend Main;\n";
    let buf = SharedBuf::default();
    let mut s = Session::new(Box::new(buf.clone()));
    s.compile_as_checked();
    let outcome = s.run_source(&dir.join("main.adb").to_string_lossy(), main);
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(
        (buf.take().as_str(), outcome.exit_code()),
        ("extra 17997\n 3\n", 0)
    );
}

/// A long program with an error in a late part is not compiled (it does
/// not run), and reports what the check without parts reports.
#[test]
fn a_long_body_with_an_error_reports_it_and_compiles_nothing() {
    let src = long_program(false).replace(
        "return;\n   end if;",
        "return;\n   end if;\n   X := \"late\";",
    );
    let (out, code, _) = run(&src, true);
    let (out2, code2, _) = run(&src, false);
    assert!(
        out.is_empty() && code.starts_with("2 ") && code.contains("late"),
        "{code}"
    );
    assert_eq!((out, code), (out2, code2));
}

/// Frames freed without looking at their slots (`Code::scalar`) hold
/// only scalars: functions of scalar parameters whose frames also hold
/// a string, a record, an access value or an exception occurrence are
/// freed the long way. (A frame freed as scalars
/// that holds anything else fails the debug assertion in
/// `Stack::truncate_scalars`, on in test builds.)
#[test]
#[cfg_attr(
    not(debug_assertions),
    ignore = "the check is a debug assertion: run in a build with them"
)]
fn frames_freed_as_scalars_hold_only_scalars() {
    let src = "with Ada.Text_IO; use Ada.Text_IO;\n\
        procedure Frames is\n\
           type Rec is record A : Integer; S : String (1 .. 3); end record;\n\
           type Acc is access Integer;\n\
           type Recs is array (1 .. 3) of Rec;\n\
           RS : Recs := (others => (1, \"abc\"));\n\
           function Img (N : Integer) return Integer is\n\
              L : constant Integer := Integer'Image (N)'Length;\n\
           begin\n   return L;\nend Img;\n\
           function Fld (K : Integer) return Integer is\n\
              R : constant Rec := RS (K);\n\
           begin\n   return R.A + Character'Pos (RS (K).S (1));\nend Fld;\n\
           function Ptr (N : Integer) return Integer is\n\
              P : constant Acc := new Integer'(N);\n\
           begin\n   return P.all;\nend Ptr;\n\
           function Occ (N : Integer) return Integer is\n\
           begin\n   if N > 0 then raise Constraint_Error; end if;\n   return 0;\n\
           exception\n   when E : others => return 1;\nend Occ;\n\
           function Both (N : Integer) return Integer is\n\
           begin\n   return Img (N) + Fld (N mod 3 + 1) + Ptr (N) + Occ (N);\nend Both;\n\
           function Plain (N : Integer) return Integer is\n\
           begin\n   if N < 2 then return N; end if;\n   return Plain (N - 1) + Both (N) - Both (N);\nend Plain;\n\
           T : Integer := 0;\n\
        begin\n\
           for I in 1 .. 200 loop\n      T := T + Both (I) + Plain (I mod 7);\n   end loop;\n\
           Put_Line (Integer'Image (T));\n\
        end Frames;\n";
    let buf = SharedBuf::default();
    let mut s = Session::new(Box::new(buf.clone()));
    let outcome = s.run_source("frames.adb", src);
    assert_eq!(outcome.exit_code(), 0, "{}", buf.take());
    // GNAT prints 40764.
    assert_eq!(buf.take().trim(), "40764");
}

/// A fused argument that overflows is reported at the argument (line 10),
/// not at the call (line 9).
#[test]
fn an_overflow_in_a_fused_argument_is_reported_at_the_argument() {
    let src = "with Ada.Text_IO; use Ada.Text_IO;\n\
        procedure Loc is\n\
           function Twice (N : Integer) return Integer is\n\
           begin\n   return N * 2;\nend Twice;\n\
           X : Integer := Integer'Last;\n\
        begin\n\
           Put_Line (Integer'Image (Twice\n     (X\n      + 1)));\n\
        end Loc;\n";
    let buf = SharedBuf::default();
    let mut s = Session::new(Box::new(buf.clone()));
    let said = match s.run_source("loc.adb", src) {
        Outcome::Raised(d) => d.message,
        other => panic!("{other:?}"),
    };
    assert!(said.contains("loc.adb:10 overflow check failed"), "{said}");
}

/// The diagnostic of the exception that ends `src`.
fn raised(src: &str) -> Diagnostic {
    let buf = SharedBuf::default();
    let mut s = Session::new(Box::new(buf.clone()));
    match s.run_source("chain.adb", src) {
        Outcome::Raised(d) => d,
        other => panic!("{other:?}: {}", buf.take()),
    }
}

/// An occurrence's notes, innermost first, as "line: label".
fn notes(src: &str, d: &Diagnostic) -> Vec<String> {
    let line = |at: u32| src[..at as usize].matches('\n').count() + 1;
    d.notes
        .iter()
        .map(|(sp, label)| format!("{}: {label}", line(sp.start)))
        .collect()
}

/// The compiled engine keeps its calls in its frames, not in
/// `Machine::calls`, and adds them to an occurrence's chain (the "called
/// from here" notes): for an exception raised in compiled code below
/// plain and fused calls, in a function called in an aggregate below a
/// declaration's call, and re-raised by a handler in each of a recursion's
/// frames (a recursion's calls from one place are one note, each
/// re-raise is one).
#[test]
fn an_exceptions_notes_name_each_call_once() {
    const CALL: &str = "called from here";
    const RERAISED: &str = "re-raised here by `raise;`";
    let programs: [(&str, Vec<String>); 3] = [
        // Plain calls and a fused one (`Down (N - 1)`).
        (
            "procedure Chain is\n\
               function Down (N : Integer) return Integer is\n\
               begin\n   if N = 0 then raise Constraint_Error; end if;\n   return Down (N - 1) + 1;\nend Down;\n\
               function Twice (N : Integer; M : Integer) return Integer is\n\
               begin\n   return Down (N) + Down (M);\nend Twice;\n\
               X : Integer;\n\
            begin\n   X := Twice (3, 2);\nend Chain;\n",
            vec![
                format!("5: {CALL} 3 times in a row"),
                format!("9: {CALL}"),
                format!("13: {CALL}"),
            ],
        ),
        // A function called in an aggregate, below a declaration's call.
        (
            "procedure Chain is\n\
               type Pair is array (1 .. 2) of Integer;\n\
               function Bad (N : Integer) return Integer is\n\
               begin\n   if N > 1 then raise Program_Error; end if;\n   return N;\nend Bad;\n\
               function Make (N : Integer) return Pair is\n\
               begin\n   return (Bad (1), Bad (N));\nend Make;\n\
               function Outer (N : Integer) return Integer is\n\
                  P : Pair := Make (N);\n\
               begin\n   return P (1);\nend Outer;\n\
               X : Integer;\n\
            begin\n   X := Outer (2);\nend Chain;\n",
            vec![
                format!("10: {CALL}"),
                format!("13: {CALL}"),
                format!("19: {CALL}"),
            ],
        ),
        // Re-raised by a handler in each of four frames.
        (
            "procedure Chain is\n\
               procedure Fail (N : Integer) is\n\
               begin\n   if N = 0 then raise Tasking_Error; end if;\n   Fail (N - 1);\n\
               exception\n   when Tasking_Error => raise;\nend Fail;\n\
            begin\n   Fail (3);\nend Chain;\n",
            std::iter::repeat_n(format!("7: {RERAISED}"), 4)
                .chain([format!("5: {CALL} 3 times in a row"), format!("10: {CALL}")])
                .collect(),
        ),
    ];
    for (src, want) in programs {
        let d = raised(src);
        assert_eq!(notes(src, &d), want, "{d:?}");
    }
}

/// A recursion too deep raises Storage_Error when the compiled engine's
/// inner loop makes the calls (a fused call `Down (N - 1)`, a call with two
/// arguments `Walk (N - 1, M + 1)`): the inner loop leaves a call past the
/// depth limit to the big loop, which raises. Without that check,
/// `Down (30_000)` returned.
#[test]
fn a_recursion_too_deep_raises_storage_error_in_quick_calls() {
    let src = "with Ada.Text_IO; use Ada.Text_IO;\n\
        procedure Deep is\n\
           function Down (N : Integer) return Integer is\n\
           begin\n   if N = 0 then\n      return 0;\n   end if;\n   return Down (N - 1) + 1;\nend Down;\n\
           function Walk (N : Integer; M : Integer) return Integer is\n\
           begin\n   if N = 0 then\n      return M;\n   end if;\n   return Walk (N - 1, M + 1);\nend Walk;\n\
        begin\n\
           Put_Line (Integer'Image (Down (1_000)) & Integer'Image (Walk (1_000, 0)));\n\
           begin\n   Put_Line (Integer'Image (Down (30_000)));\n\
           exception\n   when Storage_Error => Put_Line (\"too deep (Down)\");\nend;\n\
           begin\n   Put_Line (Integer'Image (Walk (30_000, 0)));\n\
           exception\n   when Storage_Error => Put_Line (\"too deep (Walk)\");\nend;\n\
        end Deep;\n";
    let (out, code, _) = run(src, false);
    assert_eq!(
        out, " 1000 1000\ntoo deep (Down)\ntoo deep (Walk)\n",
        "{code}"
    );
}
