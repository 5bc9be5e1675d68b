//! The parser and the checker stay linear on any text (issue 35): unfinished
//! and mistyped programs, what an editor sends on every keystroke.
//!
//! A program is a unit of statements repeated k times. proptest picks the
//! unit, the tokens deleted from every copy and where the text is cut (in
//! the last copy, always at the same place). The work done (the count of
//! `adair::work`: tokens read by the parser, expressions, names and
//! statements visited by the checker) at 4, 8 and 16 copies must grow by
//! the same amount from 4 to 8 as from 8 to 16, twice over: a linear cost
//! does, a quadratic one grows four times, an exponential one far more.
//! A count, not a clock, so the test is exact on a loaded machine.

use adair::session::Session;
use proptest::prelude::*;

/// Statements a unit is made of; `X`, `Y`, `R` and `Q` are declared.
const SNIPPETS: &[&str] = &[
    "for I in 1 .. 3 loop X := X + I; end loop;",
    "if X > 0 then X := F (G (X, 1), 2); elsif X < 0 then null; else X := 0; end if;",
    "case X is when 1 => null; when others => X := 2; end case;",
    "declare Z : Integer := X; begin X := Z * 2; end;",
    "R.A.B := R.A.B + abs (X);",
    "Put_Line (Integer'Image (X) & \"text\");",
    "while X < 10 loop X := X + 1; exit when X = 5; end loop;",
    "begin X := 1 / X; exception when others => null; end;",
    "Q := (1, 2, 3); Q (1 .. 2) := Q (2 .. 3);",
    "X := F (F (F (F (X, 1), 2), 3), 4);",
    "if X = 1 then if Y = 2 then loop exit; end loop; end if; end if;",
    "Y := (if X > 1 then 2 else 3) + Inner.Sum (X, Y);",
];

const HEADER: &str = "procedure P is
   type Inner_T is record B : Integer := 0; end record;
   type Outer_T is record A : Inner_T; end record;
   type Vec is array (1 .. 3) of Integer;
   R : Outer_T;
   Q : Vec := (others => 0);
   X, Y : Integer := 1;
   function F (A, B : Integer) return Integer is (A + B);
   function G (A, B : Integer) return Integer is (A - B);
   package Inner is
      function Sum (A, B : Integer) return Integer;
   end Inner;
   package body Inner is
      function Sum (A, B : Integer) return Integer is (A + B);
   end Inner;
begin
";

/// The tokens of Ada text, by the project's own lexer.
fn tokens(s: &str) -> Vec<String> {
    let (toks, _) = adair::syntax::lexer::lex(s, 0);
    toks.iter()
        .map(|(_, sp)| s[sp.start as usize..sp.end as usize].to_string())
        .collect()
}

#[derive(Debug)]
struct Shape {
    unit: Vec<String>,
    deleted: Vec<bool>,
    cut: usize,
    finished: bool,
}

impl Shape {
    fn text(&self, copies: usize) -> String {
        let kept: Vec<&str> = self
            .unit
            .iter()
            .zip(&self.deleted)
            .filter(|(_, d)| !**d)
            .map(|(t, _)| t.as_str())
            .collect();
        let copy = kept.join(" ");
        let mut s = String::from(HEADER);
        for _ in 0..copies {
            s.push_str(&copy);
            s.push('\n');
        }
        s.push_str(&kept[..self.cut.min(kept.len())].join(" "));
        if self.finished {
            s.push_str("\nend P;\n");
        }
        s
    }
}

fn shape() -> impl Strategy<Value = Shape> {
    (
        proptest::collection::vec(0..SNIPPETS.len(), 1..5),
        proptest::collection::vec(0u8..100, 64),
        0u8..20,
        0usize..200,
        any::<bool>(),
    )
        .prop_map(|(picks, rolls, rate, cut, finished)| {
            let unit: Vec<String> = picks.iter().flat_map(|&i| tokens(SNIPPETS[i])).collect();
            let deleted = (0..unit.len())
                .map(|i| rolls[i % rolls.len()] < rate)
                .collect();
            let cut = cut % (unit.len() + 1);
            Shape {
                unit,
                deleted,
                cut,
                finished,
            }
        })
}

/// The work of checking `text` in a new session (the predefined library's
/// own checking is not counted).
/// On a thread with the command line's big stack, as deep names need.
fn work(text: &str) -> u64 {
    let text = text.to_string();
    std::thread::Builder::new()
        .stack_size(256 << 20)
        .spawn(move || {
            let mut s = Session::new(Box::new(std::io::sink()));
            let before = adair::work::count();
            let _ = s.check_source("linear.air", text.as_str(), false);
            adair::work::count() - before
        })
        .expect("thread")
        .join()
        .expect("no panic")
}

/// Fails when the growth from 8 to 16 copies is more than about twice the
/// growth from 4 to 8.
fn assert_linear(shape: &Shape) {
    assert_linear_at(shape, [4, 8, 16]);
}

/// [`assert_linear`] at `copies` (each twice the one before).
fn assert_linear_at(shape: &Shape, copies: [usize; 3]) {
    let texts: Vec<String> = copies.iter().map(|&k| shape.text(k)).collect();
    let w: Vec<u64> = texts.iter().map(|t| work(t)).collect();
    let (d1, d2) = (w[1].saturating_sub(w[0]), w[2].saturating_sub(w[1]));
    assert!(
        d2 <= d1 * 5 / 2 + 64,
        "work at {copies:?} copies: {w:?} (growth {d1} then {d2}: not linear)\n\
         the program at {} copies:\n{}",
        copies[0],
        texts[0]
    );
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: std::env::var("ADAIR_LINEAR_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(64),
        failure_persistence: None,
        ..ProptestConfig::default()
    })]
    #[test]
    fn unfinished_text_is_checked_in_linear_work(shape in shape()) {
        assert_linear(&shape);
    }
}

/// The shapes that were exponential or quadratic before (issue 35): loops
/// and `if`s never closed, nested calls missing one parenthesis, stray
/// characters, a long dotted name.
#[test]
fn known_worst_shapes_are_linear() {
    let unit = |s: &str| Shape {
        unit: tokens(s),
        deleted: vec![false; tokens(s).len()],
        cut: 0,
        finished: false,
    };
    for s in [
        "for I in 1 .. 3 loop",
        "if X > 0 then",
        "case X is when 1 =>",
        "X := F ( F ( F ( F ( 1 , 2 ) , 3 ) , 4 ) , 5 ;",
        "# # # $ $ ?",
        "X := R . A . B . A . B . A . B ;",
        "declare begin",
        "for I in 1 .. 3 loop X := X + I ; if X > 0 then",
        // Closed scopes and undeclared names: each closing looked at every
        // "not declared" report so far.
        "for I in 1 .. 3 loop X := Nowhere + I ; end loop ;",
        "declare begin Nowhere ( X ) ; end ; if X > 0 then Y := Nope ; end if ;",
    ] {
        // Deep enough for a cost per level of nesting to show (each name
        // looked up in every enclosing scope did).
        assert_linear_at(&unit(s), [100, 200, 400]);
    }
}

/// A dotted name of n parts (30,000 took 28 s: each level looked at its
/// whole prefix again).
#[test]
fn a_long_dotted_name_is_linear() {
    let text = |n: usize| format!("{HEADER}X := R{};\nend P;\n", ".A".repeat(n));
    let w: Vec<u64> = [1000, 2000, 4000].iter().map(|&n| work(&text(n))).collect();
    let (d1, d2) = (w[1] - w[0], w[2] - w[1]);
    assert!(d2 <= d1 * 5 / 2, "work at 1000, 2000, 4000 parts: {w:?}");
}
