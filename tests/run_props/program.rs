//! The programs of `tests/run_props.rs`: a random program built as a small
//! tree, written out as Ada text, and run by this module's own evaluator,
//! which follows the Ada rules (RM 4.5, 4.6, 6.4.1, 11) and not adair's
//! code: it is the oracle that knows each program's output by construction.
//!
//! What the evaluator knows exactly: `Integer` is 32-bit and its operations
//! raise `Constraint_Error` on overflow and division by zero, `mod` takes the
//! sign of the divisor and `rem` the sign of the dividend, indexes and the
//! range of the subtype `Small` are checked, modular operations wrap
//! (`and`/`or`/`xor` of `mod 10` subtract the modulus once, `not` is
//! `Last - X`), variant components are checked against the discriminant,
//! `in out` parameters are copied back (with the actual's range check) only
//! on a normal return, and exceptions propagate to the innermost handler.
//!
//! Where the outcome is not fixed by Ada or not exactly predictable, the
//! evaluator says `Unknown` and the program is left out of the exact
//! comparison: a `Float` value GNAT's 32-bit `Float` would round (adair
//! stores a double), a float division by zero (GNAT gives an infinity),
//! and a membership test whose upper bound raises when the lower test
//! already failed (RM 11.6 lets GNAT skip it). Every `Float` value is kept
//! a multiple of 2**-24 below 2**24 in magnitude with a 24-bit mantissa, so
//! both representations hold it exactly and its `Image` is known.
//!
//! No operator ever has only static operands: a static expression is
//! evaluated exactly at compile time (RM 4.9) and one out of range is
//! illegal, so the generator puts a variable in place of one operand.

use std::collections::BTreeMap;

/// An exception a program may raise.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Exc {
    Constraint,
    Oops,
}

impl Exc {
    /// The name GNAT (and adair) print for it when it ends the program.
    pub fn ada_name(self) -> &'static str {
        match self {
            Exc::Constraint => "CONSTRAINT_ERROR",
            Exc::Oops => "GENERATED.OOPS",
        }
    }
}

/// How a program ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ending {
    Normal,
    Raised(Exc),
}

/// A program's observable behaviour.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Expected {
    /// Standard output, byte for byte.
    pub output: String,
    pub ending: Ending,
}

// ---------------------------------------------------------------- the tree

#[derive(Clone, Copy, PartialEq, Eq)]
enum IOp {
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    Rem,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum ModT {
    /// `type Word is mod 2**16;`
    Word,
    /// `type Ring is mod 10;`
    Ring,
}

impl ModT {
    fn modulus(self) -> u64 {
        match self {
            ModT::Word => 1 << 16,
            ModT::Ring => 10,
        }
    }
    fn name(self) -> &'static str {
        match self {
            ModT::Word => "Word",
            ModT::Ring => "Ring",
        }
    }
    fn var(self) -> &'static str {
        match self {
            ModT::Word => "W1",
            ModT::Ring => "N1",
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum MOp {
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    Rem,
    And,
    Or,
    Xor,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum FOp {
    Add,
    Sub,
    Mul,
    Div,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Cmp {
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum LOp {
    And,
    Or,
    Xor,
    AndThen,
    OrElse,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum GripTest {
    G1IsVacuum,
    Equal,
    NotFingers02,
    G1Constrained,
    G2Constrained,
}

/// An `Integer` expression.
enum Int {
    Lit(i64),
    /// A variable, a parameter, a loop parameter or a record component.
    Name(String),
    /// `S'Length`: static.
    Length,
    Bin(IOp, Box<Int>, Box<Int>),
    Neg(Box<Int>),
    Abs(Box<Int>),
    Pow(Box<Int>, u32),
    /// `A (E)`
    Index(Box<Int>),
    /// `Integer (T'(M))`
    FromMod(ModT, Box<Modu>),
    /// `Integer (F)`
    FromFloat(Box<Flt>),
    Twice(Box<Int>, Box<Int>),
    /// `Character'Pos (S (E))`
    Pos(Box<Int>),
    If(Box<Bool>, Box<Int>, Box<Int>),
}

/// An expression of a modular type (the type is known from the context).
enum Modu {
    Lit(u64),
    Last,
    Var,
    Bin(MOp, Box<Modu>, Box<Modu>),
    Not(Box<Modu>),
    Neg(Box<Modu>),
    Pow(Box<Modu>, u32),
    Conv(Box<Int>),
    Succ(Box<Modu>),
}

/// A `Float` expression.
enum Flt {
    Lit(f64),
    Name(String),
    Bin(FOp, Box<Flt>, Box<Flt>),
    FromInt(Box<Int>),
    Abs(Box<Flt>),
}

/// A `Boolean` expression.
enum Bool {
    Lit(bool),
    Name(String),
    CmpInt(Cmp, Box<Int>, Box<Int>),
    CmpMod(ModT, Cmp, Box<Modu>, Box<Modu>),
    LtFloat(Box<Flt>, Box<Flt>),
    Logic(LOp, Box<Bool>, Box<Bool>),
    Not(Box<Bool>),
    Grip(GripTest),
    /// `E in 1 .. H`
    In(Box<Int>, Box<Int>),
}

enum GripStmt {
    /// `G1 := (Fingers, Id, Width);`
    SetFingers(Int, Int),
    /// `G1 := (K => Vacuum, Id => .., Suction => ..);`
    SetVacuum(Int, Int),
    SetSuction(Int),
    SetWidth(Int),
    G2FromG1,
    G1FromG2,
    Show,
}

enum Stmt {
    SetInt(String, Int),
    SetMod(ModT, Modu),
    PutMod(ModT, Modu),
    SetFloat(String, Flt),
    SetBool(String, Bool),
    SetElem(Int, Int),
    PutInt(Int),
    PutBool(Bool),
    Bump(String, Flt),
    SetChar(Int, u8),
    If(Bool, Vec<Stmt>, Vec<Stmt>),
    For {
        var: String,
        hi: i64,
        rev: bool,
        body: Vec<Stmt>,
        exit: Option<Bool>,
    },
    While {
        var: String,
        limit: i64,
        cond: Bool,
        body: Vec<Stmt>,
    },
    /// `case Sel is when 0 => .. when 1 => .. when others => ..`
    Case(Int, [Vec<Stmt>; 3]),
    /// A block with handlers: `Constraint_Error` always, `Oops` when
    /// `oops`, and `others` (which prints and re-raises) when `others`.
    Block {
        body: Vec<Stmt>,
        raise: Option<Exc>,
        oops: bool,
        others: bool,
    },
    Grip(GripStmt),
    SetRec(Int, Flt, Bool),
    PutFloat(Flt),
}

/// A whole generated program.
pub struct Program {
    i1: i64,
    i2: i64,
    twice: Int,
    bump: Stmt,
    body: Vec<Stmt>,
}

// ---------------------------------------------------------- static-ness

impl Int {
    fn is_static(&self) -> bool {
        match self {
            Int::Lit(_) | Int::Length => true,
            Int::Bin(_, l, r) => l.is_static() && r.is_static(),
            Int::Neg(e) | Int::Abs(e) | Int::Pow(e, _) => e.is_static(),
            Int::FromMod(_, m) => m.is_static(),
            Int::FromFloat(f) => f.is_static(),
            Int::If(c, a, b) => c.is_static() && a.is_static() && b.is_static(),
            Int::Name(_) | Int::Index(_) | Int::Twice(..) | Int::Pos(_) => false,
        }
    }
}

impl Int {
    /// Of the subtype `Small`: `P1`, or an `if` expression whose first
    /// branch is.
    fn is_small(&self) -> bool {
        match self {
            Int::Name(n) => n == "P1",
            Int::If(_, a, _) => a.is_small(),
            _ => false,
        }
    }
}

impl Modu {
    fn is_static(&self) -> bool {
        match self {
            Modu::Lit(_) | Modu::Last => true,
            Modu::Var => false,
            Modu::Bin(_, l, r) => l.is_static() && r.is_static(),
            Modu::Not(e) | Modu::Neg(e) | Modu::Pow(e, _) | Modu::Succ(e) => e.is_static(),
            Modu::Conv(i) => i.is_static(),
        }
    }
}

impl Flt {
    fn is_static(&self) -> bool {
        match self {
            Flt::Lit(_) => true,
            Flt::Name(_) => false,
            Flt::Bin(_, l, r) => l.is_static() && r.is_static(),
            Flt::FromInt(i) => i.is_static(),
            Flt::Abs(e) => e.is_static(),
        }
    }
}

impl Bool {
    fn is_static(&self) -> bool {
        match self {
            Bool::Lit(_) => true,
            Bool::Name(_) | Bool::Grip(_) => false,
            Bool::CmpInt(_, l, r) | Bool::In(l, r) => l.is_static() && r.is_static(),
            Bool::CmpMod(_, _, l, r) => l.is_static() && r.is_static(),
            Bool::LtFloat(l, r) => l.is_static() && r.is_static(),
            Bool::Logic(_, l, r) => l.is_static() && r.is_static(),
            Bool::Not(e) => e.is_static(),
        }
    }
}

// ------------------------------------------------------------ generator

/// Where the code being generated goes: what names it may use, which
/// subprogram it must not call (no recursion).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Ctx {
    Main,
    /// The body of `Twice (X, Y : Integer)`.
    Twice,
    /// The body of `Bump (X : in out Integer; Y : Float)`.
    Bump,
}

/// A small deterministic generator (xorshift64*), seeded by proptest.
pub struct Gen {
    state: u64,
    depth: u32,
    /// Names of the integer loop parameters in scope.
    loop_vars: Vec<String>,
    next_id: u32,
    ctx: Ctx,
    /// How many compound statements enclose the one being generated.
    nest: u32,
}

impl Gen {
    pub fn new(seed: u64) -> Gen {
        Gen {
            // xorshift must not start at zero; mix the seed so that nearby
            // seeds give unrelated programs.
            state: (seed ^ 0x9E37_79B9_7F4A_7C15).wrapping_mul(0xBF58_476D_1CE4_E5B9) | 1,
            depth: 0,
            loop_vars: Vec::new(),
            next_id: 0,
            ctx: Ctx::Main,
            nest: 0,
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
    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len() as u64) as usize]
    }
    fn id(&mut self) -> u32 {
        self.next_id += 1;
        self.next_id
    }

    fn int_lit(&mut self) -> i64 {
        match self.below(6) {
            0 => 0,
            1 => 2_147_483_647,
            2 => self.below(100_000) as i64,
            _ => self.below(10) as i64,
        }
    }

    /// A variable of type Integer: what replaces a static operand.
    fn int_var(&mut self) -> Int {
        Int::Name(self.pick(&["I1", "I2", "I3"]).into())
    }

    /// `op (l, r)`, with a variable for `l` when both are static.
    fn int_bin(&mut self, op: IOp, l: Int, r: Int) -> Int {
        let l = if l.is_static() && r.is_static() {
            self.int_var()
        } else {
            l
        };
        Int::Bin(op, Box::new(l), Box::new(r))
    }

    /// An operand that is not static.
    fn int_dynamic(&mut self, e: Int) -> Box<Int> {
        Box::new(if e.is_static() { self.int_var() } else { e })
    }

    /// An Integer expression.
    fn int(&mut self) -> Int {
        self.depth += 1;
        let leaf = self.depth > 3 || self.below(3) == 0;
        let e = if leaf {
            match self.below(9) {
                0 | 1 => Int::Lit(self.int_lit()),
                2 if !self.loop_vars.is_empty() => {
                    let i = self.below(self.loop_vars.len() as u64) as usize;
                    Int::Name(self.loop_vars[i].clone())
                }
                3 => Int::Name(self.pick(&["R.A", "G1.Id"]).into()),
                4 => Int::Length,
                5 if self.ctx == Ctx::Twice => Int::Name(self.pick(&["X", "Y"]).into()),
                5 if self.ctx == Ctx::Bump => Int::Name("X".into()),
                6 => Int::Name("P1".into()),
                _ => self.int_var(),
            }
        } else {
            match self.below(13) {
                0..=4 => {
                    let op =
                        self.pick(&[IOp::Add, IOp::Sub, IOp::Mul, IOp::Div, IOp::Mod, IOp::Rem]);
                    let l = self.int();
                    let r = self.int();
                    let r = if matches!(op, IOp::Div | IOp::Mod | IOp::Rem) {
                        // A variable in the divisor: GNAT refuses a division
                        // whose divisor it knows to be zero (`I1 * 0`) when
                        // the dividend is static, though the RM does not.
                        let v = self.int_var();
                        Int::Bin(IOp::Add, Box::new(v), Box::new(r))
                    } else {
                        r
                    };
                    self.int_bin(op, l, r)
                }
                5 => {
                    let e = self.int();
                    Int::Abs(self.int_dynamic(e))
                }
                6 if self.below(2) == 0 => {
                    let e = self.int();
                    Int::Neg(self.int_dynamic(e))
                }
                6 => {
                    let e = self.int();
                    let n = self.below(4) as u32;
                    Int::Pow(self.int_dynamic(e), n)
                }
                7 if self.below(2) == 0 => Int::Index(Box::new(self.int())),
                7 => {
                    // A (1 + E mod 8): in range unless E overflows.
                    let e = self.int();
                    let m = self.int_bin(IOp::Mod, e, Int::Lit(8));
                    Int::Index(Box::new(self.int_bin(IOp::Add, Int::Lit(1), m)))
                }
                8 if self.below(3) == 0 => {
                    let t = self.modular_type();
                    let m = self.modular(t);
                    Int::FromMod(t, Box::new(m))
                }
                8 => {
                    let f = self.float();
                    if f.is_static() {
                        Int::FromFloat(Box::new(Flt::Name("F1".into())))
                    } else {
                        Int::FromFloat(Box::new(f))
                    }
                }
                9 if self.ctx != Ctx::Twice => {
                    Int::Twice(Box::new(self.int()), Box::new(self.int()))
                }
                10 if self.below(3) == 0 => {
                    // A variant's component: Constraint_Error (discriminant
                    // check) when the record holds the other variant.
                    Int::Name(
                        self.pick(&["G1.Suction", "G1.Width", "G2.Width", "G2.Id"])
                            .into(),
                    )
                }
                10 => Int::Pos(Box::new(self.int())),
                _ => {
                    let mut c = self.boolean();
                    if c.is_static() {
                        // GNAT 12 crashes ("GNAT BUG DETECTED") on
                        // `(if False then 2 else I3) <= 5`.
                        c = Bool::Name(self.pick(&["B1", "B2"]).into());
                    }
                    let mut a = self.int();
                    let b = self.int();
                    if a.is_small() {
                        // GNAT 12 checks every branch against the subtype
                        // of the first one when the `if` expression is
                        // converted: `Float ((if C then P1 else 60647))`
                        // raises Constraint_Error, which the RM does not
                        // say (the expression is of type Integer).
                        a = self.int_var();
                    }
                    Int::If(Box::new(c), Box::new(a), Box::new(b))
                }
            }
        };
        self.depth -= 1;
        e
    }

    fn modular_type(&mut self) -> ModT {
        if self.below(2) == 0 {
            ModT::Word
        } else {
            ModT::Ring
        }
    }

    fn mod_dynamic(&mut self, e: Modu) -> Box<Modu> {
        Box::new(if e.is_static() { Modu::Var } else { e })
    }

    /// An expression of the modular type `t`.
    fn modular(&mut self, t: ModT) -> Modu {
        self.depth += 1;
        let leaf = self.depth > 3 || self.below(3) == 0;
        let e = if leaf {
            match self.below(4) {
                0 => Modu::Lit(self.below(t.modulus())),
                1 => Modu::Last,
                _ => Modu::Var,
            }
        } else {
            match self.below(8) {
                0..=2 => {
                    let op = self.pick(&[
                        MOp::Add,
                        MOp::Sub,
                        MOp::Mul,
                        MOp::Div,
                        MOp::Mod,
                        MOp::Rem,
                        MOp::And,
                        MOp::Or,
                        MOp::Xor,
                    ]);
                    let l = self.modular(t);
                    let r = self.modular(t);
                    let l = if l.is_static() && r.is_static() {
                        Modu::Var
                    } else {
                        l
                    };
                    Modu::Bin(op, Box::new(l), Box::new(r))
                }
                3 => {
                    let e = self.modular(t);
                    Modu::Not(self.mod_dynamic(e))
                }
                4 => {
                    let e = self.modular(t);
                    Modu::Neg(self.mod_dynamic(e))
                }
                5 => {
                    let e = self.modular(t);
                    let k = self.below(40) as u32;
                    Modu::Pow(self.mod_dynamic(e), k)
                }
                6 => {
                    let i = self.int();
                    Modu::Conv(self.int_dynamic(i))
                }
                _ => {
                    let e = self.modular(t);
                    Modu::Succ(self.mod_dynamic(e))
                }
            }
        };
        self.depth -= 1;
        e
    }

    fn flt_dynamic(&mut self, e: Flt) -> Box<Flt> {
        Box::new(if e.is_static() {
            Flt::Name(self.pick(&["F1", "F2"]).into())
        } else {
            e
        })
    }

    /// A Float expression.
    fn float(&mut self) -> Flt {
        self.depth += 1;
        let leaf = self.depth > 3 || self.below(3) == 0;
        let e = if leaf {
            match self.below(6) {
                0 | 1 => {
                    let whole = self.below(1000) as f64;
                    let frac = self.pick(&[0.0, 0.125, 0.25, 0.375, 0.5, 0.75]);
                    Flt::Lit(whole + frac)
                }
                2 => Flt::Name("R.B".into()),
                3 if self.ctx == Ctx::Bump => Flt::Name("Y".into()),
                _ => Flt::Name(self.pick(&["F1", "F2"]).into()),
            }
        } else {
            match self.below(6) {
                0..=2 => {
                    let op = self.pick(&[FOp::Add, FOp::Sub, FOp::Mul, FOp::Add, FOp::Div]);
                    let l = self.float();
                    let r = if op == FOp::Div {
                        // (F1 + E): not static
                        Flt::Bin(
                            FOp::Add,
                            Box::new(Flt::Name("F1".into())),
                            Box::new(self.float()),
                        )
                    } else {
                        self.float()
                    };
                    let l = if l.is_static() && r.is_static() {
                        Flt::Name(self.pick(&["F1", "F2"]).into())
                    } else {
                        l
                    };
                    Flt::Bin(op, Box::new(l), Box::new(r))
                }
                3 | 4 => {
                    let i = self.int();
                    Flt::FromInt(self.int_dynamic(i))
                }
                _ => {
                    let e = self.float();
                    Flt::Abs(self.flt_dynamic(e))
                }
            }
        };
        self.depth -= 1;
        e
    }

    /// A Boolean expression.
    fn boolean(&mut self) -> Bool {
        self.depth += 1;
        let leaf = self.depth > 3 || self.below(3) == 0;
        let cmps = [Cmp::Eq, Cmp::Ne, Cmp::Lt, Cmp::Le, Cmp::Gt, Cmp::Ge];
        let e = if leaf {
            match self.below(4) {
                0 => Bool::Lit(self.below(2) == 0),
                1 => Bool::Name("R.C".into()),
                _ => Bool::Name(self.pick(&["B1", "B2"]).into()),
            }
        } else {
            match self.below(6) {
                0 if self.below(3) == 0 => {
                    let t = self.modular_type();
                    let op = self.pick(&[Cmp::Eq, Cmp::Ne, Cmp::Lt, Cmp::Ge]);
                    let l = self.modular(t);
                    let r = self.modular(t);
                    Bool::CmpMod(t, op, Box::new(l), Box::new(r))
                }
                0 | 1 => {
                    let op = self.pick(&cmps);
                    Bool::CmpInt(op, Box::new(self.int()), Box::new(self.int()))
                }
                2 => Bool::LtFloat(Box::new(self.float()), Box::new(self.float())),
                3 => {
                    let op = self.pick(&[LOp::And, LOp::Or, LOp::Xor, LOp::AndThen, LOp::OrElse]);
                    Bool::Logic(op, Box::new(self.boolean()), Box::new(self.boolean()))
                }
                4 if self.below(3) == 0 => Bool::Grip(self.pick(&[
                    GripTest::G1IsVacuum,
                    GripTest::Equal,
                    GripTest::NotFingers02,
                    GripTest::G1Constrained,
                    GripTest::G2Constrained,
                ])),
                4 => Bool::Not(Box::new(self.boolean())),
                _ => Bool::In(Box::new(self.int()), Box::new(self.int())),
            }
        };
        self.depth -= 1;
        e
    }

    /// One to `n` statements, one level deeper.
    fn nested(&mut self, n: u64) -> Vec<Stmt> {
        self.nest += 1;
        let v = (0..=self.below(n)).map(|_| self.stmt()).collect();
        self.nest -= 1;
        v
    }

    /// A statement; compound ones only up to three levels deep.
    fn stmt(&mut self) -> Stmt {
        let k = self.below(if self.nest < 3 { 16 } else { 9 });
        let int_targets: &[&str] = if self.ctx == Ctx::Bump {
            &["I1", "I2", "I3", "P1", "X", "X"]
        } else {
            &["I1", "I2", "I3", "I1", "I2", "P1"]
        };
        match k {
            0 | 1 => {
                let v = self.pick(int_targets);
                Stmt::SetInt(v.into(), self.int())
            }
            2 if self.below(3) == 0 => {
                let t = self.modular_type();
                let e = self.modular(t);
                if self.below(2) == 0 {
                    Stmt::SetMod(t, e)
                } else {
                    Stmt::PutMod(t, e)
                }
            }
            2 => {
                let v = self.pick(&["F1", "F2"]);
                Stmt::SetFloat(v.into(), self.float())
            }
            3 => {
                let v = self.pick(&["B1", "B2", "R.C"]);
                Stmt::SetBool(v.into(), self.boolean())
            }
            4 => Stmt::SetElem(self.int(), self.int()),
            5 => Stmt::PutInt(self.int()),
            6 if self.ctx != Ctx::Bump => {
                let v = self.pick(&["I1", "I2", "I3", "P1"]);
                Stmt::Bump(v.into(), self.float())
            }
            6 => Stmt::PutBool(self.boolean()),
            7 => {
                let c = self.pick(b"aZ ");
                Stmt::SetChar(self.int(), c)
            }
            8 if self.below(2) == 0 => Stmt::PutBool(self.boolean()),
            8 => Stmt::PutFloat(self.float()),
            9 => {
                let c = self.boolean();
                let t = self.nested(3);
                let e = self.nested(2);
                Stmt::If(c, t, e)
            }
            10 => {
                let var = format!("K{}", self.id());
                let hi = self.below(5) as i64;
                let rev = self.below(3) == 0;
                self.loop_vars.push(var.clone());
                let body = self.nested(3);
                let exit = if self.below(3) == 0 {
                    Some(self.boolean())
                } else {
                    None
                };
                self.loop_vars.pop();
                Stmt::For {
                    var,
                    hi,
                    rev,
                    body,
                    exit,
                }
            }
            11 => {
                let var = format!("C{}", self.id());
                let limit = self.below(5) as i64;
                let cond = self.boolean();
                let body = self.nested(2);
                Stmt::While {
                    var,
                    limit,
                    cond,
                    body,
                }
            }
            12 => {
                let e = self.int();
                let sel = self.int_bin(IOp::Mod, e, Int::Lit(3));
                let arms = [self.nested(1), self.nested(1), self.nested(1)];
                Stmt::Case(sel, arms)
            }
            13 => {
                let body = self.nested(3);
                let raise = match self.below(8) {
                    0 | 1 => Some(Exc::Oops),
                    2 => Some(Exc::Constraint),
                    _ => None,
                };
                let oops = self.below(4) != 0;
                let others = self.below(4) == 0;
                Stmt::Block {
                    body,
                    raise,
                    oops,
                    others,
                }
            }
            14 if self.below(2) == 0 => Stmt::Grip(self.grip_stmt()),
            14 => Stmt::SetRec(self.int(), self.float(), self.boolean()),
            _ => Stmt::Grip(self.grip_stmt()),
        }
    }

    /// A statement on the discriminated records: `G1` is mutable (its
    /// discriminant has a default), `G2` is constrained to `Fingers`.
    fn grip_stmt(&mut self) -> GripStmt {
        match self.below(7) {
            0 => GripStmt::SetFingers(self.int(), self.int()),
            1 => GripStmt::SetVacuum(self.int(), self.int()),
            2 => GripStmt::SetSuction(self.int()),
            3 => GripStmt::SetWidth(self.int()),
            // Constraint_Error when G1 holds the other variant.
            4 => GripStmt::G2FromG1,
            5 => GripStmt::G1FromG2,
            _ => GripStmt::Show,
        }
    }

    pub fn program(&mut self) -> Program {
        self.ctx = Ctx::Twice;
        let twice = self.int();
        self.ctx = Ctx::Bump;
        self.nest = 1;
        let bump = self.stmt();
        self.nest = 0;
        self.ctx = Ctx::Main;
        // Most top-level statements handle Constraint_Error, so that one
        // overflow does not end the program before the rest has run.
        let mut body = Vec::new();
        for _ in 0..=self.below(12) {
            if self.below(4) == 0 {
                body.push(self.stmt());
            } else {
                self.nest = 1;
                let s = self.stmt();
                self.nest = 0;
                body.push(Stmt::Block {
                    body: vec![s],
                    raise: None,
                    oops: false,
                    others: false,
                });
            }
        }
        Program {
            i1: self.int_lit(),
            i2: self.int_lit(),
            twice,
            bump,
            body,
        }
    }
}

// ------------------------------------------------------------ rendering

impl IOp {
    fn text(self) -> &'static str {
        match self {
            IOp::Add => "+",
            IOp::Sub => "-",
            IOp::Mul => "*",
            IOp::Div => "/",
            IOp::Mod => "mod",
            IOp::Rem => "rem",
        }
    }
}

impl MOp {
    fn text(self) -> &'static str {
        match self {
            MOp::Add => "+",
            MOp::Sub => "-",
            MOp::Mul => "*",
            MOp::Div => "/",
            MOp::Mod => "mod",
            MOp::Rem => "rem",
            MOp::And => "and",
            MOp::Or => "or",
            MOp::Xor => "xor",
        }
    }
}

impl Cmp {
    fn text(self) -> &'static str {
        match self {
            Cmp::Eq => "=",
            Cmp::Ne => "/=",
            Cmp::Lt => "<",
            Cmp::Le => "<=",
            Cmp::Gt => ">",
            Cmp::Ge => ">=",
        }
    }
    fn holds<T: PartialOrd>(self, l: T, r: T) -> bool {
        match self {
            Cmp::Eq => l == r,
            Cmp::Ne => l != r,
            Cmp::Lt => l < r,
            Cmp::Le => l <= r,
            Cmp::Gt => l > r,
            Cmp::Ge => l >= r,
        }
    }
}

impl Int {
    fn render(&self) -> String {
        match self {
            Int::Lit(2_147_483_647) => "2_147_483_647".into(),
            Int::Lit(v) => v.to_string(),
            Int::Name(n) => n.clone(),
            Int::Length => "S'Length".into(),
            Int::Bin(op, l, r) => format!("({} {} {})", l.render(), op.text(), r.render()),
            Int::Neg(e) => format!("(-{})", e.render()),
            Int::Abs(e) => format!("abs ({})", e.render()),
            Int::Pow(e, n) => format!("(({}) ** {n})", e.render()),
            Int::Index(e) => format!("A ({})", e.render()),
            Int::FromMod(t, m) => format!("Integer ({}'({}))", t.name(), m.render(*t)),
            Int::FromFloat(f) => format!("Integer ({})", f.render()),
            Int::Twice(a, b) => format!("Twice ({}, {})", a.render(), b.render()),
            Int::Pos(e) => format!("Character'Pos (S ({}))", e.render()),
            Int::If(c, a, b) => format!(
                "(if {} then {} else {})",
                c.render(),
                a.render(),
                b.render()
            ),
        }
    }
}

impl Modu {
    fn render(&self, t: ModT) -> String {
        match self {
            Modu::Lit(v) => v.to_string(),
            Modu::Last => format!("{}'Last", t.name()),
            Modu::Var => t.var().into(),
            Modu::Bin(op, l, r) => format!("({} {} {})", l.render(t), op.text(), r.render(t)),
            Modu::Not(e) => format!("(not {})", e.render(t)),
            Modu::Neg(e) => format!("(-{})", e.render(t)),
            Modu::Pow(e, k) => format!("(({}) ** {k})", e.render(t)),
            Modu::Conv(i) => format!("{} ({})", t.name(), i.render()),
            Modu::Succ(e) => format!("{}'Succ ({})", t.name(), e.render(t)),
        }
    }
}

impl Flt {
    fn render(&self) -> String {
        match self {
            Flt::Lit(v) if v.fract() == 0.0 => format!("{v:.1}"),
            Flt::Lit(v) => format!("{v}"),
            Flt::Name(n) => n.clone(),
            Flt::Bin(op, l, r) => {
                let op = match op {
                    FOp::Add => "+",
                    FOp::Sub => "-",
                    FOp::Mul => "*",
                    FOp::Div => "/",
                };
                format!("({} {op} {})", l.render(), r.render())
            }
            Flt::FromInt(i) => format!("Float ({})", i.render()),
            Flt::Abs(e) => format!("abs ({})", e.render()),
        }
    }
}

impl Bool {
    fn render(&self) -> String {
        match self {
            Bool::Lit(true) => "True".into(),
            Bool::Lit(false) => "False".into(),
            Bool::Name(n) => n.clone(),
            Bool::CmpInt(op, l, r) => format!("({} {} {})", l.render(), op.text(), r.render()),
            Bool::CmpMod(t, op, l, r) => format!(
                "({}'({}) {} {})",
                t.name(),
                l.render(*t),
                op.text(),
                r.render(*t)
            ),
            Bool::LtFloat(l, r) => format!("({} < {})", l.render(), r.render()),
            Bool::Logic(op, l, r) => {
                let op = match op {
                    LOp::And => "and",
                    LOp::Or => "or",
                    LOp::Xor => "xor",
                    LOp::AndThen => "and then",
                    LOp::OrElse => "or else",
                };
                format!("({} {op} {})", l.render(), r.render())
            }
            Bool::Not(e) => format!("(not {})", e.render()),
            Bool::Grip(g) => match g {
                GripTest::G1IsVacuum => "(G1.K = Vacuum)",
                GripTest::Equal => "(G1 = G2)",
                GripTest::NotFingers02 => "(G1 /= (Fingers, 0, 2))",
                GripTest::G1Constrained => "G1'Constrained",
                GripTest::G2Constrained => "G2'Constrained",
            }
            .into(),
            Bool::In(e, h) => format!("({} in 1 .. {})", e.render(), h.render()),
        }
    }
}

impl Stmt {
    fn render(&self, out: &mut String, indent: usize) {
        let pad = " ".repeat(indent);
        let all = |out: &mut String, ss: &[Stmt], indent: usize| {
            for s in ss {
                s.render(out, indent);
            }
        };
        let line = |out: &mut String, text: String| {
            out.push_str(&pad);
            out.push_str(&text);
            out.push('\n');
        };
        match self {
            Stmt::SetInt(v, e) => line(out, format!("{v} := {};", e.render())),
            Stmt::SetMod(t, e) => line(out, format!("{} := {};", t.var(), e.render(*t))),
            Stmt::PutMod(t, e) => line(
                out,
                format!("Put_Line ({}'Image ({}));", t.name(), e.render(*t)),
            ),
            Stmt::SetFloat(v, e) => line(out, format!("{v} := {};", e.render())),
            Stmt::SetBool(v, e) => line(out, format!("{v} := {};", e.render())),
            Stmt::SetElem(i, e) => line(out, format!("A ({}) := {};", i.render(), e.render())),
            Stmt::PutInt(e) => line(out, format!("Put_Line (Integer'Image ({}));", e.render())),
            Stmt::PutBool(e) => line(out, format!("Put_Line (Boolean'Image ({}));", e.render())),
            Stmt::Bump(v, f) => line(out, format!("Bump ({v}, {});", f.render())),
            Stmt::SetChar(i, c) => line(out, format!("S ({}) := '{}';", i.render(), *c as char)),
            Stmt::If(c, t, e) => {
                line(out, format!("if {} then", c.render()));
                all(out, t, indent + 3);
                line(out, "else".into());
                all(out, e, indent + 3);
                line(out, "end if;".into());
            }
            Stmt::For {
                var,
                hi,
                rev,
                body,
                exit,
            } => {
                let rev = if *rev { "reverse " } else { "" };
                line(out, format!("for {var} in {rev}1 .. {hi} loop"));
                all(out, body, indent + 3);
                if let Some(c) = exit {
                    line(out, format!("   exit when {};", c.render()));
                }
                line(out, "end loop;".into());
            }
            Stmt::While {
                var,
                limit,
                cond,
                body,
            } => {
                line(out, "declare".into());
                line(out, format!("   {var} : Integer := 0;"));
                line(out, "begin".into());
                line(
                    out,
                    format!("   while {var} < {limit} and then {} loop", cond.render()),
                );
                line(out, format!("      {var} := {var} + 1;"));
                all(out, body, indent + 6);
                line(out, "   end loop;".into());
                line(out, "end;".into());
            }
            Stmt::Case(sel, arms) => {
                line(out, format!("case {} is", sel.render()));
                for (choice, arm) in ["0", "1", "others"].iter().zip(arms) {
                    line(out, format!("   when {choice} =>"));
                    all(out, arm, indent + 6);
                }
                line(out, "end case;".into());
            }
            Stmt::Block {
                body,
                raise,
                oops,
                others,
            } => {
                line(out, "begin".into());
                all(out, body, indent + 3);
                match raise {
                    Some(Exc::Oops) => line(out, "   raise Oops;".into()),
                    Some(Exc::Constraint) => line(out, "   raise Constraint_Error;".into()),
                    None => {}
                }
                line(out, "exception".into());
                line(out, "   when Constraint_Error =>".into());
                line(out, "      Put_Line (\"CE\");".into());
                if *oops {
                    line(out, "   when Oops =>".into());
                    line(out, "      Put_Line (\"Oops\");".into());
                }
                if *others {
                    line(out, "   when others =>".into());
                    line(out, "      Put_Line (\"Others\");".into());
                    line(out, "      raise;".into());
                }
                line(out, "end;".into());
            }
            Stmt::Grip(g) => line(
                out,
                match g {
                    GripStmt::SetFingers(a, b) => {
                        format!("G1 := (Fingers, {}, {});", a.render(), b.render())
                    }
                    GripStmt::SetVacuum(a, b) => format!(
                        "G1 := (K => Vacuum, Id => {}, Suction => {});",
                        a.render(),
                        b.render()
                    ),
                    GripStmt::SetSuction(e) => format!("G1.Suction := {};", e.render()),
                    GripStmt::SetWidth(e) => format!("G2.Width := {};", e.render()),
                    GripStmt::G2FromG1 => "G2 := G1;".into(),
                    GripStmt::G1FromG2 => "G1 := G2;".into(),
                    GripStmt::Show => {
                        "Put_Line (Kind'Image (G1.K) & Integer'Image (G1.Id));".into()
                    }
                },
            ),
            Stmt::SetRec(a, b, c) => line(
                out,
                format!(
                    "R := (A => {}, B => {}, C => {});",
                    a.render(),
                    b.render(),
                    c.render()
                ),
            ),
            Stmt::PutFloat(f) => line(out, format!("Put_Line (S & Float'Image ({}));", f.render())),
        }
    }
}

impl Program {
    /// The program's Ada text: a main procedure `Generated` that GNAT
    /// compiles as `generated.adb` and adair runs.
    pub fn render(&self) -> String {
        let mut body = String::new();
        for s in &self.body {
            s.render(&mut body, 3);
        }
        let mut bump = String::new();
        self.bump.render(&mut bump, 6);
        format!(
            "with Ada.Text_IO; use Ada.Text_IO;\n\
             procedure Generated is\n\
             \x20  type Vec is array (1 .. 8) of Integer;\n\
             \x20  type Rec is record\n      A : Integer;\n      B : Float;\n      C : Boolean;\n   end record;\n\
             \x20  subtype Small is Integer range -1000 .. 1000;\n\
             \x20  I1 : Integer := {};\n   I2 : Integer := {};\n   I3 : Integer := 7;\n   P1 : Small := 0;\n\
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
             \x20  function Twice (X, Y : Integer) return Integer is\n   begin\n      return {};\n   end Twice;\n\
             \x20  procedure Bump (X : in out Integer; Y : Float) is\n   begin\n{bump}      X := X + Integer (Y);\n   end Bump;\n\
             begin\n{body}end Generated;\n",
            Int::Lit(self.i1).render(),
            Int::Lit(self.i2).render(),
            self.twice.render(),
        )
    }
}

// ------------------------------------------------------------ the oracle

const INT_FIRST: i64 = -(1 << 31);
const INT_LAST: i64 = (1 << 31) - 1;
const SMALL: std::ops::RangeInclusive<i64> = -1000..=1000;

/// Why an evaluation stopped before its end.
enum Stop {
    Raise(Exc),
    /// The outcome is not exactly predictable (see the module's comment).
    Unknown,
}

type Ev<T> = Result<T, Stop>;

const CE: Stop = Stop::Raise(Exc::Constraint);

/// An Integer result: Constraint_Error outside Integer's range.
fn int_check(v: i64) -> Ev<i64> {
    if (INT_FIRST..=INT_LAST).contains(&v) {
        Ok(v)
    } else {
        Err(CE)
    }
}

/// The `Float` values both GNAT's 32-bit `Float` and a double hold exactly:
/// a 24-bit mantissa, a multiple of 2**-24, below 2**24 in magnitude. Sums,
/// differences and products of two of them are exact in a double, so
/// checking the result is enough to know that GNAT computes the same.
fn float_check(v: f64) -> Ev<f64> {
    let scaled = v * (1u64 << 24) as f64;
    if v.is_finite()
        && v.abs() < (1u64 << 24) as f64
        && scaled.fract() == 0.0
        && f64::from(v as f32) == v
    {
        Ok(v)
    } else {
        Err(Stop::Unknown)
    }
}

/// `Integer'Image`, `Word'Image`: a leading blank when not negative.
fn int_image(v: i64) -> String {
    if v < 0 {
        v.to_string()
    } else {
        format!(" {v}")
    }
}

/// `Float'Image` of a value `float_check` accepted: GNAT's six significant
/// digits (`" 1.50000E+00"`), rounded half away from zero from the exact
/// decimal expansion.
fn float_image(v: f64) -> String {
    let sign = if v.is_sign_negative() { "-" } else { " " };
    // |v| = n / 2**24 = n * 5**24 / 10**24, exactly.
    let n = (v.abs() * (1u64 << 24) as f64) as u128;
    if n == 0 {
        return format!("{sign}0.00000E+00");
    }
    let digits = (n * 5u128.pow(24)).to_string();
    let mut exp = digits.len() as i64 - 1 - 24;
    let mut lead: u64 = if digits.len() > 6 {
        let first: u64 = digits[..6].parse().unwrap_or(0);
        if digits.as_bytes()[6] >= b'5' {
            first + 1
        } else {
            first
        }
    } else {
        let mut d = digits.clone();
        while d.len() < 6 {
            d.push('0');
        }
        d.parse().unwrap_or(0)
    };
    if lead == 1_000_000 {
        lead = 100_000;
        exp += 1;
    }
    let lead = lead.to_string();
    let esign = if exp < 0 { '-' } else { '+' };
    format!(
        "{sign}{}.{}E{esign}{:02}",
        &lead[..1],
        &lead[1..],
        exp.abs()
    )
}

#[derive(Clone, Copy, PartialEq)]
struct GripVal {
    fingers: bool,
    id: i64,
    /// `Suction` for a `Vacuum` grip, `Width` for `Fingers`.
    other: i64,
}

/// The state of a running program.
struct Machine<'p> {
    prog: &'p Program,
    ints: BTreeMap<String, i64>,
    floats: BTreeMap<String, f64>,
    bools: BTreeMap<String, bool>,
    w1: u64,
    n1: u64,
    a: [i64; 8],
    s: [u8; 4],
    g1: GripVal,
    g2: GripVal,
    out: String,
}

impl Machine<'_> {
    fn put_line(&mut self, text: &str) {
        self.out.push_str(text);
        self.out.push('\n');
    }

    fn read_int(&self, name: &str) -> Ev<i64> {
        match name {
            "G1.Id" => Ok(self.g1.id),
            "G2.Id" => Ok(self.g2.id),
            "G1.Suction" if !self.g1.fingers => Ok(self.g1.other),
            "G1.Width" if self.g1.fingers => Ok(self.g1.other),
            "G1.Suction" | "G1.Width" => Err(CE),
            "G2.Width" => Ok(self.g2.other),
            _ => Ok(self.ints[name]),
        }
    }

    fn int(&mut self, e: &Int) -> Ev<i64> {
        Ok(match e {
            Int::Lit(v) => *v,
            Int::Name(n) => self.read_int(n)?,
            Int::Length => 4,
            Int::Bin(op, l, r) => {
                let (a, b) = (self.int(l)?, self.int(r)?);
                match op {
                    IOp::Add => int_check(a + b)?,
                    IOp::Sub => int_check(a - b)?,
                    IOp::Mul => int_check(a * b)?,
                    _ if b == 0 => return Err(CE),
                    // Truncates toward zero, as Ada's "/".
                    IOp::Div => int_check(a / b)?,
                    // The sign of the dividend.
                    IOp::Rem => a % b,
                    // The sign of the divisor.
                    IOp::Mod => {
                        let r = a % b;
                        if r != 0 && (r < 0) != (b < 0) {
                            r + b
                        } else {
                            r
                        }
                    }
                }
            }
            Int::Neg(x) => int_check(-self.int(x)?)?,
            Int::Abs(x) => int_check(self.int(x)?.abs())?,
            Int::Pow(x, n) => {
                let v = self.int(x)?;
                let mut r = 1;
                for _ in 0..*n {
                    r = int_check(r * v)?;
                }
                r
            }
            Int::Index(i) => {
                let i = self.int(i)?;
                if !(1..=8).contains(&i) {
                    return Err(CE);
                }
                self.a[i as usize - 1]
            }
            Int::FromMod(t, m) => self.modular(*t, m)? as i64,
            Int::FromFloat(f) => {
                // Rounds half away from zero (RM 4.6(33)), as f64::round.
                int_check(self.float(f)?.round() as i64)?
            }
            Int::Twice(x, y) => {
                let (x, y) = (self.int(x)?, self.int(y)?);
                let saved = (
                    self.ints.insert("X".into(), x),
                    self.ints.insert("Y".into(), y),
                );
                let prog = self.prog;
                let r = self.int(&prog.twice);
                for (name, old) in [("X", saved.0), ("Y", saved.1)] {
                    match old {
                        Some(v) => self.ints.insert(name.into(), v),
                        None => self.ints.remove(name),
                    };
                }
                r?
            }
            Int::Pos(i) => {
                let i = self.int(i)?;
                if !(1..=4).contains(&i) {
                    return Err(CE);
                }
                i64::from(self.s[i as usize - 1])
            }
            Int::If(c, a, b) => {
                if self.boolean(c)? {
                    self.int(a)?
                } else {
                    self.int(b)?
                }
            }
        })
    }

    fn modular(&mut self, t: ModT, e: &Modu) -> Ev<u64> {
        let n = t.modulus();
        Ok(match e {
            Modu::Lit(v) => *v,
            Modu::Last => n - 1,
            Modu::Var => match t {
                ModT::Word => self.w1,
                ModT::Ring => self.n1,
            },
            Modu::Bin(op, l, r) => {
                let (a, b) = (self.modular(t, l)?, self.modular(t, r)?);
                // RM 4.5.1(6): a logical operation outside the base range
                // has the modulus subtracted once.
                let once = |v: u64| if v >= n { v - n } else { v };
                match op {
                    MOp::Add => (a + b) % n,
                    MOp::Sub => (a + n - b) % n,
                    MOp::Mul => (a * b) % n,
                    MOp::And => a & b,
                    MOp::Or => once(a | b),
                    MOp::Xor => once(a ^ b),
                    _ if b == 0 => return Err(CE),
                    MOp::Div => a / b,
                    MOp::Mod | MOp::Rem => a % b,
                }
            }
            // RM 4.5.6(5): the largest value minus the operand.
            Modu::Not(x) => n - 1 - self.modular(t, x)?,
            Modu::Neg(x) => (n - self.modular(t, x)?) % n,
            Modu::Pow(x, k) => {
                let v = self.modular(t, x)?;
                let mut r = 1 % n;
                for _ in 0..*k {
                    r = r * v % n;
                }
                r
            }
            Modu::Conv(i) => {
                let v = self.int(i)?;
                if v < 0 || v as u64 >= n {
                    return Err(CE);
                }
                v as u64
            }
            Modu::Succ(x) => (self.modular(t, x)? + 1) % n,
        })
    }

    fn float(&mut self, e: &Flt) -> Ev<f64> {
        match e {
            Flt::Lit(v) => float_check(*v),
            Flt::Name(n) => Ok(self.floats[n.as_str()]),
            Flt::Bin(op, l, r) => {
                let (a, b) = (self.float(l)?, self.float(r)?);
                match op {
                    FOp::Add => float_check(a + b),
                    FOp::Sub => float_check(a - b),
                    FOp::Mul => float_check(a * b),
                    // GNAT's Float division by zero gives an infinity.
                    FOp::Div if b == 0.0 => Err(Stop::Unknown),
                    FOp::Div => {
                        let q = float_check(a / b)?;
                        // Both hold 24-bit mantissas: the product is exact.
                        if q * b == a {
                            Ok(q)
                        } else {
                            Err(Stop::Unknown)
                        }
                    }
                }
            }
            Flt::FromInt(i) => float_check(self.int(i)? as f64),
            Flt::Abs(x) => Ok(self.float(x)?.abs()),
        }
    }

    fn boolean(&mut self, e: &Bool) -> Ev<bool> {
        Ok(match e {
            Bool::Lit(b) => *b,
            Bool::Name(n) => self.bools[n.as_str()],
            Bool::CmpInt(op, l, r) => {
                let (a, b) = (self.int(l)?, self.int(r)?);
                op.holds(a, b)
            }
            Bool::CmpMod(t, op, l, r) => {
                let (a, b) = (self.modular(*t, l)?, self.modular(*t, r)?);
                op.holds(a, b)
            }
            Bool::LtFloat(l, r) => {
                let (a, b) = (self.float(l)?, self.float(r)?);
                a < b
            }
            Bool::Logic(op, l, r) => {
                let a = self.boolean(l)?;
                match op {
                    LOp::AndThen if !a => false,
                    LOp::OrElse if a => true,
                    LOp::AndThen | LOp::OrElse => self.boolean(r)?,
                    LOp::And => self.boolean(r)? && a,
                    LOp::Or => self.boolean(r)? || a,
                    LOp::Xor => self.boolean(r)? != a,
                }
            }
            Bool::Not(x) => !self.boolean(x)?,
            Bool::Grip(g) => match g {
                GripTest::G1IsVacuum => !self.g1.fingers,
                GripTest::Equal => self.g1 == self.g2,
                GripTest::NotFingers02 => {
                    self.g1
                        != GripVal {
                            fingers: true,
                            id: 0,
                            other: 2,
                        }
                }
                // A variable whose discriminant has a default is
                // unconstrained; G2 is declared with a constraint.
                GripTest::G1Constrained => false,
                GripTest::G2Constrained => true,
            },
            Bool::In(x, hi) => {
                let v = self.int(x)?;
                if v < 1 {
                    // The upper bound does not decide the result: RM 11.6
                    // lets an implementation skip a check that fails in it.
                    match self.int(hi) {
                        Ok(_) => false,
                        Err(_) => return Err(Stop::Unknown),
                    }
                } else {
                    v <= self.int(hi)?
                }
            }
        })
    }

    fn exec_all(&mut self, ss: &[Stmt]) -> Ev<()> {
        for s in ss {
            self.exec(s)?;
        }
        Ok(())
    }

    fn set_int(&mut self, name: &str, v: i64) -> Ev<()> {
        if name == "P1" && !SMALL.contains(&v) {
            return Err(CE);
        }
        self.ints.insert(name.into(), v);
        Ok(())
    }

    fn exec(&mut self, s: &Stmt) -> Ev<()> {
        match s {
            Stmt::SetInt(v, e) => {
                let x = self.int(e)?;
                self.set_int(v, x)?;
            }
            Stmt::SetMod(t, e) => {
                let x = self.modular(*t, e)?;
                match t {
                    ModT::Word => self.w1 = x,
                    ModT::Ring => self.n1 = x,
                }
            }
            Stmt::PutMod(t, e) => {
                let x = self.modular(*t, e)?;
                self.put_line(&int_image(x as i64));
            }
            Stmt::SetFloat(v, e) => {
                let x = self.float(e)?;
                self.floats.insert(v.clone(), x);
            }
            Stmt::SetBool(v, e) => {
                let x = self.boolean(e)?;
                self.bools.insert(v.clone(), x);
            }
            Stmt::SetElem(i, e) => {
                let (i, x) = (self.int(i)?, self.int(e)?);
                if !(1..=8).contains(&i) {
                    return Err(CE);
                }
                self.a[i as usize - 1] = x;
            }
            Stmt::PutInt(e) => {
                let x = self.int(e)?;
                self.put_line(&int_image(x));
            }
            Stmt::PutBool(e) => {
                let x = self.boolean(e)?;
                self.put_line(if x { "TRUE" } else { "FALSE" });
            }
            Stmt::Bump(v, f) => {
                // Copy in (no check: Small's values are Integers), run the
                // body, copy back only on a normal return (RM 6.4.1(17)),
                // with the check of the actual's subtype.
                let y = self.float(f)?;
                let x = self.ints[v.as_str()];
                self.ints.insert("X".into(), x);
                self.floats.insert("Y".into(), y);
                let prog = self.prog;
                let r = self.exec(&prog.bump).and_then(|()| {
                    let x = int_check(self.ints["X"] + y.round() as i64)?;
                    self.ints.insert("X".into(), x);
                    Ok(())
                });
                let x = self.ints.remove("X").unwrap_or(0);
                self.floats.remove("Y");
                r?;
                self.set_int(v, x)?;
            }
            Stmt::SetChar(i, c) => {
                let i = self.int(i)?;
                if !(1..=4).contains(&i) {
                    return Err(CE);
                }
                self.s[i as usize - 1] = *c;
            }
            Stmt::If(c, t, e) => {
                if self.boolean(c)? {
                    self.exec_all(t)?;
                } else {
                    self.exec_all(e)?;
                }
            }
            Stmt::For {
                var,
                hi,
                rev,
                body,
                exit,
            } => {
                let mut ks: Vec<i64> = (1..=*hi).collect();
                if *rev {
                    ks.reverse();
                }
                for k in ks {
                    self.ints.insert(var.clone(), k);
                    self.exec_all(body)?;
                    if let Some(c) = exit
                        && self.boolean(c)?
                    {
                        break;
                    }
                }
            }
            Stmt::While {
                var,
                limit,
                cond,
                body,
            } => {
                self.ints.insert(var.clone(), 0);
                while self.ints[var.as_str()] < *limit && self.boolean(cond)? {
                    let c = self.ints[var.as_str()] + 1;
                    self.ints.insert(var.clone(), c);
                    self.exec_all(body)?;
                }
            }
            Stmt::Case(sel, arms) => {
                let v = self.int(sel)?;
                self.exec_all(&arms[v.clamp(0, 2) as usize])?;
            }
            Stmt::Block {
                body,
                raise,
                oops,
                others,
            } => {
                let r = self.exec_all(body).and(match raise {
                    Some(e) => Err(Stop::Raise(*e)),
                    None => Ok(()),
                });
                match r {
                    Err(Stop::Raise(Exc::Constraint)) => self.put_line("CE"),
                    Err(Stop::Raise(Exc::Oops)) if *oops => self.put_line("Oops"),
                    Err(Stop::Raise(e)) if *others => {
                        self.put_line("Others");
                        return Err(Stop::Raise(e));
                    }
                    r => r?,
                }
            }
            Stmt::Grip(g) => match g {
                GripStmt::SetFingers(a, b) | GripStmt::SetVacuum(a, b) => {
                    let (id, other) = (self.int(a)?, self.int(b)?);
                    self.g1 = GripVal {
                        fingers: matches!(g, GripStmt::SetFingers(..)),
                        id,
                        other,
                    };
                }
                GripStmt::SetSuction(e) => {
                    let v = self.int(e)?;
                    if self.g1.fingers {
                        return Err(CE);
                    }
                    self.g1.other = v;
                }
                GripStmt::SetWidth(e) => self.g2.other = self.int(e)?,
                GripStmt::G2FromG1 => {
                    if !self.g1.fingers {
                        return Err(CE);
                    }
                    self.g2 = self.g1;
                }
                GripStmt::G1FromG2 => self.g1 = self.g2,
                GripStmt::Show => {
                    let k = if self.g1.fingers { "FINGERS" } else { "VACUUM" };
                    let line = format!("{k}{}", int_image(self.g1.id));
                    self.put_line(&line);
                }
            },
            Stmt::SetRec(a, b, c) => {
                let (a, b, c) = (self.int(a)?, self.float(b)?, self.boolean(c)?);
                self.ints.insert("R.A".into(), a);
                self.floats.insert("R.B".into(), b);
                self.bools.insert("R.C".into(), c);
            }
            Stmt::PutFloat(f) => {
                let v = self.float(f)?;
                let line = format!("{}{}", String::from_utf8_lossy(&self.s), float_image(v));
                self.put_line(&line);
            }
        }
        Ok(())
    }
}

impl Program {
    /// What the program prints and how it ends, by Ada's rules; `None` when
    /// that is not exactly predictable (see the module's comment).
    pub fn expected(&self) -> Option<Expected> {
        let mut m = Machine {
            prog: self,
            ints: [
                ("I1", self.i1),
                ("I2", self.i2),
                ("I3", 7),
                ("P1", 0),
                ("R.A", 1),
            ]
            .into_iter()
            .map(|(k, v)| (k.to_string(), v))
            .collect(),
            floats: [("F1", 1.5), ("F2", -0.25), ("R.B", 2.0)]
                .into_iter()
                .map(|(k, v)| (k.to_string(), v))
                .collect(),
            bools: [("B1", true), ("B2", false), ("R.C", true)]
                .into_iter()
                .map(|(k, v)| (k.to_string(), v))
                .collect(),
            w1: 65_000,
            n1: 7,
            a: [3; 8],
            s: *b"abcd",
            g1: GripVal {
                fingers: false,
                id: 0,
                other: 1,
            },
            g2: GripVal {
                fingers: true,
                id: 0,
                other: 2,
            },
            out: String::new(),
        };
        let ending = match m.exec_all(&self.body) {
            Ok(()) => Ending::Normal,
            Err(Stop::Raise(e)) => Ending::Raised(e),
            Err(Stop::Unknown) => return None,
        };
        Some(Expected {
            output: m.out,
            ending,
        })
    }
}

/// The first program from `seed`, `seed + 1`, ... whose output is known,
/// with that output and the seed that made it.
pub fn known_program(seed: u64) -> (String, Expected, u64) {
    let mut s = seed;
    loop {
        let p = Gen::new(s).program();
        if let Some(e) = p.expected() {
            return (p.render(), e, s);
        }
        s = s.wrapping_add(1);
    }
}
