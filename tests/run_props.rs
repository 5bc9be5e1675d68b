//! Random well-typed programs run to their end or to an Ada exception, never
//! to a panic (issue 14). The generator writes programs that the checker
//! must accept (a check error outside the static-evaluation errors Ada
//! requires is a failure too: either the generator or the checker is wrong),
//! with every loop bounded, so each program ends. Its integer expressions
//! overflow, divide by zero and index out of range often enough that the
//! exception paths run as much as the normal ones.
//!
//! `PROPTEST_CASES` sets the number of programs (default 256 per test).
#![allow(clippy::print_stderr)]

use adair::session::{Outcome, Session};
use proptest::prelude::*;

/// A small deterministic generator (xorshift64*), seeded by proptest.
struct Gen {
    state: u64,
    depth: u32,
    /// Names of the integer loop parameters in scope.
    loop_vars: Vec<String>,
    next_id: u32,
}

impl Gen {
    fn new(seed: u64) -> Gen {
        Gen {
            state: seed | 1,
            depth: 0,
            loop_vars: Vec::new(),
            next_id: 0,
        }
    }
    fn next(&mut self) -> u64 {
        self.state ^= self.state >> 12;
        self.state ^= self.state << 25;
        self.state ^= self.state >> 27;
        self.state.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn pick<'a>(&mut self, items: &[&'a str]) -> &'a str {
        items[self.below(items.len() as u64) as usize]
    }
    fn id(&mut self) -> u32 {
        self.next_id += 1;
        self.next_id
    }

    fn int_lit(&mut self) -> String {
        match self.below(6) {
            0 => "0".into(),
            1 => "2_147_483_647".into(),
            2 => format!("{}", self.below(100_000)),
            _ => format!("{}", self.below(10)),
        }
    }

    /// An Integer expression.
    fn int(&mut self) -> String {
        self.depth += 1;
        let leaf = self.depth > 3 || self.below(3) == 0;
        let e = if leaf {
            match self.below(7) {
                0 | 1 => self.int_lit(),
                2 if !self.loop_vars.is_empty() => {
                    let i = self.below(self.loop_vars.len() as u64) as usize;
                    self.loop_vars[i].clone()
                }
                3 if self.below(2) == 0 => "R.A".into(),
                3 => "G1.Id".into(),
                4 => "S'Length".into(),
                _ => self.pick(&["I1", "I2", "I3"]).into(),
            }
        } else {
            match self.below(12) {
                0..=4 => {
                    let op = self.pick(&["+", "-", "*", "/", "mod", "rem"]);
                    let l = self.int();
                    // A variable on the right keeps a division from being static.
                    let r = if matches!(op, "/" | "mod" | "rem") {
                        format!("({} + {})", self.pick(&["I1", "I2", "I3"]), self.int())
                    } else {
                        self.int()
                    };
                    format!("({l} {op} {r})")
                }
                5 => format!("abs ({})", self.int()),
                6 => format!("(I1 ** {})", self.below(4)),
                7 if self.below(2) == 0 => format!("A ({})", self.int()),
                7 => format!("A (1 + {} mod 8)", self.int()),
                8 if self.below(3) == 0 => {
                    let (t, n) = self.modular_type();
                    format!("Integer ({t}'({}))", self.modular(t, n))
                }
                8 => format!("Integer ({})", self.float()),
                9 => format!("Twice ({}, {})", self.int(), self.int()),
                10 if self.below(3) == 0 => {
                    // A variant's component: Constraint_Error (discriminant
                    // check) when the record holds the other variant.
                    self.pick(&["G1.Suction", "G1.Width", "G2.Width", "G2.Id"])
                        .into()
                }
                10 => format!("Character'Pos (S ({}))", self.int()),
                _ => format!(
                    "(if {} then {} else {})",
                    self.boolean(),
                    self.int(),
                    self.int()
                ),
            }
        };
        self.depth -= 1;
        e
    }

    /// One of the program's modular types and its modulus: a 16-bit word
    /// or a modulus that is not a power of two.
    fn modular_type(&mut self) -> (&'static str, u64) {
        if self.below(2) == 0 {
            ("Word", 1 << 16)
        } else {
            ("Ring", 10)
        }
    }

    /// An expression of the modular type `t` (values 0 .. n - 1): every
    /// operation wraps, a conversion from an Integer outside them raises.
    fn modular(&mut self, t: &str, n: u64) -> String {
        self.depth += 1;
        let leaf = self.depth > 3 || self.below(3) == 0;
        let var = if t == "Word" { "W1" } else { "N1" };
        let e = if leaf {
            match self.below(4) {
                0 => format!("{}", self.below(n)),
                1 => format!("{t}'Last"),
                _ => var.into(),
            }
        } else {
            match self.below(8) {
                0..=2 => {
                    let op = self.pick(&["+", "-", "*", "/", "mod", "rem", "and", "or", "xor"]);
                    let l = self.modular(t, n);
                    // A variable on the right keeps a division from being static.
                    let r = if matches!(op, "/" | "mod" | "rem") {
                        format!("({var} - {})", self.modular(t, n))
                    } else {
                        self.modular(t, n)
                    };
                    format!("({l} {op} {r})")
                }
                3 => format!("(not {})", self.modular(t, n)),
                4 => format!("(-{})", self.modular(t, n)),
                5 => format!("({} ** {})", self.modular(t, n), self.below(40)),
                6 => format!("{t} ({})", self.int()),
                _ => format!("{t}'Succ ({})", self.modular(t, n)),
            }
        };
        self.depth -= 1;
        e
    }

    /// A Float expression.
    fn float(&mut self) -> String {
        self.depth += 1;
        let leaf = self.depth > 3 || self.below(3) == 0;
        let e = if leaf {
            match self.below(5) {
                0 => format!("{}.{}", self.below(1000), self.below(100)),
                // Near Float'Last but not static: a static expression out
                // of Float's range is illegal (RM 4.9(35)), a computed one
                // raises Constraint_Error at run time.
                1 => "(R.B * 5.0E37)".into(),
                2 => "R.B".into(),
                _ => self.pick(&["F1", "F2"]).into(),
            }
        } else {
            match self.below(5) {
                0..=2 => {
                    let op = self.pick(&["+", "-", "*", "/"]);
                    let l = self.float();
                    let r = if op == "/" {
                        format!("(F1 + {})", self.float())
                    } else {
                        self.float()
                    };
                    format!("({l} {op} {r})")
                }
                3 => format!("Float ({})", self.int()),
                _ => format!("abs ({})", self.float()),
            }
        };
        self.depth -= 1;
        e
    }

    /// A Boolean expression.
    fn boolean(&mut self) -> String {
        self.depth += 1;
        let leaf = self.depth > 3 || self.below(3) == 0;
        let e = if leaf {
            match self.below(4) {
                0 => self.pick(&["True", "False"]).into(),
                1 => "R.C".into(),
                _ => self.pick(&["B1", "B2"]).into(),
            }
        } else {
            match self.below(6) {
                0 if self.below(3) == 0 => {
                    let (t, n) = self.modular_type();
                    let op = self.pick(&["=", "/=", "<", ">="]);
                    format!("({t}'({}) {op} {})", self.modular(t, n), self.modular(t, n))
                }
                0 | 1 => {
                    let op = self.pick(&["=", "/=", "<", "<=", ">", ">="]);
                    format!("({} {op} {})", self.int(), self.int())
                }
                2 => format!("({} < {})", self.float(), self.float()),
                3 => {
                    let op = self.pick(&["and", "or", "xor", "and then", "or else"]);
                    format!("({} {op} {})", self.boolean(), self.boolean())
                }
                4 if self.below(3) == 0 => self
                    .pick(&[
                        "(G1.K = Vacuum)",
                        "(G1 = G2)",
                        "(G1 /= (Fingers, 0, 2))",
                        "G1'Constrained",
                        "G2'Constrained",
                    ])
                    .into(),
                4 => format!("(not {})", self.boolean()),
                _ => format!("({} in 1 .. {})", self.int(), self.int()),
            }
        };
        self.depth -= 1;
        e
    }

    fn stmts(&mut self, out: &mut String, indent: usize, n: u64) {
        for _ in 0..=self.below(n) {
            self.stmt(out, indent);
        }
    }

    fn stmt(&mut self, out: &mut String, indent: usize) {
        let pad = " ".repeat(indent);
        let nested = indent < 12;
        let k = self.below(if nested { 15 } else { 8 });
        match k {
            0 | 1 => {
                let v = self.pick(&["I1", "I2", "I3"]);
                out.push_str(&format!("{pad}{v} := {};\n", self.int()));
            }
            2 if self.below(3) == 0 => {
                let (t, n) = self.modular_type();
                let v = if t == "Word" { "W1" } else { "N1" };
                let e = self.modular(t, n);
                if self.below(2) == 0 {
                    out.push_str(&format!("{pad}{v} := {e};\n"));
                } else {
                    out.push_str(&format!("{pad}Put_Line ({t}'Image ({e}));\n"));
                }
            }
            2 => {
                let v = self.pick(&["F1", "F2"]);
                out.push_str(&format!("{pad}{v} := {};\n", self.float()));
            }
            3 => {
                let v = self.pick(&["B1", "B2", "R.C"]);
                out.push_str(&format!("{pad}{v} := {};\n", self.boolean()));
            }
            4 => {
                let (i, v) = (self.int(), self.int());
                out.push_str(&format!("{pad}A ({i}) := {v};\n"));
            }
            5 => out.push_str(&format!(
                "{pad}Put_Line (Integer'Image ({}));\n",
                self.int()
            )),
            6 => {
                let v = self.pick(&["I1", "I2", "I3"]);
                out.push_str(&format!("{pad}Bump ({v}, {});\n", self.float()));
            }
            7 => {
                let (i, c) = (self.int(), self.pick(&["'a'", "'Z'", "' '"]));
                out.push_str(&format!("{pad}S ({i}) := {c};\n"));
            }
            8 => {
                out.push_str(&format!("{pad}if {} then\n", self.boolean()));
                self.stmts(out, indent + 3, 3);
                out.push_str(&format!("{pad}else\n"));
                self.stmts(out, indent + 3, 2);
                out.push_str(&format!("{pad}end if;\n"));
            }
            9 => {
                let var = format!("K{}", self.id());
                let hi = self.below(5);
                let rev = if self.below(3) == 0 { "reverse " } else { "" };
                out.push_str(&format!("{pad}for {var} in {rev}1 .. {hi} loop\n"));
                self.loop_vars.push(var);
                self.stmts(out, indent + 3, 3);
                if self.below(3) == 0 {
                    out.push_str(&format!("{pad}   exit when {};\n", self.boolean()));
                }
                self.loop_vars.pop();
                out.push_str(&format!("{pad}end loop;\n"));
            }
            10 => {
                let c = format!("C{}", self.id());
                out.push_str(&format!(
                    "{pad}declare\n{pad}   {c} : Integer := 0;\n{pad}begin\n\
                     {pad}   while {c} < {} and then {} loop\n{pad}      {c} := {c} + 1;\n",
                    self.below(5),
                    self.boolean()
                ));
                self.stmts(out, indent + 6, 2);
                out.push_str(&format!("{pad}   end loop;\n{pad}end;\n"));
            }
            11 => {
                out.push_str(&format!("{pad}case {} mod 3 is\n", self.int()));
                for choice in ["0", "1", "others"] {
                    out.push_str(&format!("{pad}   when {choice} =>\n"));
                    self.stmts(out, indent + 6, 1);
                }
                out.push_str(&format!("{pad}end case;\n"));
            }
            12 => {
                out.push_str(&format!("{pad}begin\n"));
                self.stmts(out, indent + 3, 3);
                if self.below(4) == 0 {
                    out.push_str(&format!("{pad}   raise Oops;\n"));
                }
                out.push_str(&format!(
                    "{pad}exception\n{pad}   when Constraint_Error =>\n\
                     {pad}      Put_Line (\"CE\");\n{pad}   when Oops =>\n\
                     {pad}      Put_Line (\"Oops\");\n{pad}end;\n"
                ));
            }
            13 if self.below(2) == 0 => self.grip_stmt(out, &pad),
            13 => out.push_str(&format!(
                "{pad}R := (A => {}, B => {}, C => {});\n",
                self.int(),
                self.float(),
                self.boolean()
            )),
            _ => out.push_str(&format!(
                "{pad}Put_Line (S & Float'Image ({}));\n",
                self.float()
            )),
        }
    }

    /// A statement on the discriminated records: `G1` is mutable (its
    /// discriminant has a default), `G2` is constrained to `Fingers`.
    fn grip_stmt(&mut self, out: &mut String, pad: &str) {
        let line = match self.below(7) {
            0 => format!("G1 := (Fingers, {}, {});", self.int(), self.int()),
            1 => format!(
                "G1 := (K => Vacuum, Id => {}, Suction => {});",
                self.int(),
                self.int()
            ),
            2 => format!("G1.Suction := {};", self.int()),
            3 => format!("G2.Width := {};", self.int()),
            // Constraint_Error when G1 holds the other variant.
            4 => "G2 := G1;".into(),
            5 => "G1 := G2;".into(),
            _ => "Put_Line (Kind'Image (G1.K) & Integer'Image (G1.Id));".into(),
        };
        out.push_str(&format!("{pad}{line}\n"));
    }

    fn program(&mut self) -> String {
        // Most top-level statements handle Constraint_Error, so that one
        // overflow does not end the program before the rest has run.
        let mut body = String::new();
        for _ in 0..=self.below(12) {
            if self.below(4) == 0 {
                self.stmt(&mut body, 3);
            } else {
                body.push_str("   begin\n");
                self.stmt(&mut body, 6);
                body.push_str(
                    "   exception\n      when Constraint_Error => Put_Line (\"CE\");\n   end;\n",
                );
            }
        }
        let mut bump = String::new();
        self.stmt(&mut bump, 6);
        let twice = self.int();
        format!(
            "with Ada.Text_IO; use Ada.Text_IO;\n\
             procedure Generated is\n\
             \x20  type Vec is array (1 .. 8) of Integer;\n\
             \x20  type Rec is record\n      A : Integer;\n      B : Float;\n      C : Boolean;\n   end record;\n\
             \x20  I1 : Integer := {};\n   I2 : Integer := {};\n   I3 : Integer := 7;\n\
             \x20  F1 : Float := 1.5;\n   F2 : Float := -0.25;\n\
             \x20  type Word is mod 2**16;\n   type Ring is mod 10;\n\
             \x20  W1 : Word := 65_000;\n   N1 : Ring := 7;\n\
             \x20  B1 : Boolean := True;\n   B2 : Boolean := False;\n\
             \x20  A : Vec := (others => 3);\n\
             \x20  R : Rec := (A => 1, B => 2.0, C => True);\n\
             \x20  type Kind is (Vacuum, Fingers);\n\
             \x20  type Grip (K : Kind := Vacuum) is record\n      Id : Integer := 0;\n      case K is\n         when Vacuum => Suction : Integer := 1;\n         when Fingers => Width : Integer := 2;\n      end case;\n   end record;\n\
             \x20  G1 : Grip;\n   G2 : Grip (Fingers);\n\
             \x20  S : String (1 .. 4) := \"abcd\";\n\
             \x20  Oops : exception;\n\
             \x20  function Twice (X, Y : Integer) return Integer is\n   begin\n      return {twice};\n   end Twice;\n\
             \x20  procedure Bump (X : in out Integer; Y : Float) is\n   begin\n{bump}      X := X + Integer (Y);\n   end Bump;\n\
             begin\n{body}end Generated;\n",
            self.int_lit(),
            self.int_lit(),
        )
    }
}

/// Check errors Ada itself requires of some generated programs: a static
/// expression outside its type, a static division by zero.
fn static_error(message: &str) -> bool {
    message.contains("static") || message.contains("division by zero")
}

/// Runs a program on a thread with the command line's 512 MiB stack: a
/// generated `Twice` may call itself until Storage_Error, 20,000 calls deep.
/// Returns the outcome and what the program printed.
fn run(src: &str) -> (Outcome, String) {
    let src = src.to_string();
    std::thread::Builder::new()
        .stack_size(512 << 20)
        .spawn(move || {
            let buf = adair::golden::SharedBuf::default();
            let mut s = Session::new(Box::new(buf.clone()));
            let o = s.run_source("generated.air", &src);
            (o, buf.take())
        })
        .expect("thread")
        .join()
        .unwrap_or_else(|p| std::panic::resume_unwind(p))
}

fn run_program(seed: u64) -> Result<(), TestCaseError> {
    let src = Gen::new(seed).program();
    let (outcome, _printed) = run(&src);
    if std::env::var_os("PROPS_SHOW").is_some() {
        eprintln!("{src}\n=> {outcome:?}");
    }
    match outcome {
        Outcome::Ok => {}
        Outcome::Raised(d) => {
            let ok = ["CONSTRAINT_ERROR", "STORAGE_ERROR", "GENERATED.OOPS"]
                .iter()
                .any(|e| d.message.contains(e));
            prop_assert!(ok, "unexpected exception {}\n{}", d.message, src);
        }
        Outcome::CheckFailed(ds) => {
            // Warnings come beside errors; they refuse nothing.
            for d in ds.iter().filter(|d| !d.is_warning()) {
                prop_assert!(
                    static_error(&d.message),
                    "a well-typed program was refused: {}\n{}",
                    d.message,
                    src
                );
            }
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn generated_programs_end_normally_or_with_an_ada_exception(seed in any::<u64>()) {
        run_program(seed)?;
    }
}

/// The generator writes every kind of statement and reaches the exception
/// paths: a test of the test, so that it cannot pass by generating nothing.
#[test]
fn the_generator_covers_what_it_claims() {
    let mut text = String::new();
    let mut raised = 0;
    let mut ran = 0;
    for seed in 0..64 {
        let src = Gen::new(seed).program();
        match run(&src).0 {
            Outcome::Ok => ran += 1,
            Outcome::Raised(_) => raised += 1,
            Outcome::CheckFailed(_) => {}
        }
        text.push_str(&src);
    }
    for construct in [
        "for K",
        "while C",
        "case ",
        "exception",
        "raise Oops",
        "Bump (",
        "Twice (",
        " mod ",
        "Integer (",
        "(if ",
        "Word'Image (",
        "Ring'Image (",
        " xor ",
        "(not ",
        "G1 := (Fingers",
        "G2 := G1;",
        "G1.Suction",
        "'Constrained",
    ] {
        assert!(text.contains(construct), "never generated: {construct}");
    }
    assert!(ran >= 8 && raised >= 8, "ran {ran}, raised {raised}");
}
