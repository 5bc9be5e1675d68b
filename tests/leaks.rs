//! Memory that a parse, check or run leaves behind. The language server
//! and the REPL parse and check on every keystroke and entry, so a few
//! kilobytes lost per parse add up over an afternoon.
//!
//! The crate's counting allocator (`interp::memory::in_use`) gives the
//! bytes the process holds. This file is its own test binary, with one
//! test, so no other test allocates while it measures.

use adair::interp::memory::in_use;
use adair::session::{Outcome, Session};

const PROGRAM: &str = r#"with Ada.Text_IO; use Ada.Text_IO;
procedure Leaky is
   type Pair is record
      A, B : Integer := 0;
   end record;
   function Sum (P : Pair) return Integer is (P.A + P.B);
   procedure Bump (X : in out Integer) is
   begin
      X := X + 1;
   exception
      when Constraint_Error => X := 0;
   end Bump;
   P : Pair := (1, 2);
   N : Integer := 0;
begin
   for I in 1 .. 10 loop
      declare
         Q : Pair := (I, N);
      begin
         Bump (N);
         P.A := Sum (Q);
      end;
   end loop;
   Put_Line (Integer'Image (P.A + N));
end Leaky;
"#;

fn parse_once() {
    let (unit, diags) = adair::syntax::parse_source(PROGRAM, 0);
    assert!(unit.is_some() && diags.is_empty(), "{diags:?}");
}

fn run_once() {
    let mut s = Session::new(Box::new(std::io::sink()));
    let out = s.run_source("leaky.adb", PROGRAM);
    assert!(matches!(out, Outcome::Ok), "{out:?}");
}

/// The bytes held after `n` more calls of `f`, less those held before
/// them (after a warm-up, so that one-time caches are filled).
fn growth(n: usize, f: fn()) -> isize {
    for _ in 0..3 {
        f();
    }
    let before = in_use() as isize;
    for _ in 0..n {
        f();
    }
    in_use() as isize - before
}

#[test]
fn parsing_checking_and_running_again_and_again_holds_no_more_memory() {
    // Each parse used to leak its grammar (a `Recursive::declare` cycle):
    // 28 KB a parse, 2.8 MB here.
    let parse = growth(100, parse_once);
    assert!(parse < 64 << 10, "100 parses left {parse} bytes behind");
    let run = growth(30, run_once);
    assert!(run < 64 << 10, "30 checked runs left {run} bytes behind");
}
