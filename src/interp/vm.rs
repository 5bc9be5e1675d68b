//! The compiled engine. Each subprogram body (and the level-0 statements of
//! a run) is compiled, once per run and on first call, into a flat list of
//! instructions over the slots of its frame: the frame's own variables
//! (`Var { level, slot }`, as the checker numbered them) followed by
//! temporaries. A loop runs the instructions with explicit frames: a call
//! pushes a [`Frame`] and jumps, a return pops it, an exception unwinds
//! through handler regions and frames, with no Rust recursion, so that a
//! task can later be suspended between two instructions.
//!
//! Nodes without an instruction of their own (aggregates, attributes,
//! slices, raise, delay, ...) are evaluated by the tree walker
//! ([`Run::eval`], [`Run::exec`], [`Run::assign`]), which stays the
//! reference engine: `Engine::Walker` runs a whole program in it, and the
//! golden and GNAT tests run every program in both (differential testing).
//! The compiled engine keeps every Ada check the walker makes; it calls the
//! walker's own check functions.

use super::*;

/// Which engine runs a program.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Engine {
    /// Compiled instructions with explicit frames (the default).
    #[default]
    Compiled,
    /// The tree walker over the checked program (the reference).
    Walker,
}

impl Engine {
    /// The engine a setting names: `walker` the reference engine; anything
    /// else, or nothing, the compiled one (the session reads
    /// `ADAIR_ENGINE`: the machine reads no environment).
    pub fn named(setting: Option<&str>) -> Engine {
        match setting {
            Some("walker") => Engine::Walker,
            _ => Engine::Compiled,
        }
    }
}

/// One instruction. Operands are frame slots (`Var`); `Span`s are where a
/// check that fails raises.
#[derive(Debug)]
enum Op {
    Int(Var, i64),
    Real(Var, f64),
    Move(Var, Var),
    IntBin(IntOp, Var, Var, Var, Span),
    /// `IntBin` with an integer literal on the right.
    IntBinK(IntOp, Var, Var, i64, Span),
    IntNeg(Var, Var, Span),
    /// An operation of a modular type whose values are `0 ..= last`
    /// (`ir::modular`, which the walker calls too).
    ModBin(ModOp, Var, Var, Var, u32, Span),
    FloatBin(FloatOp, Var, Var, Var),
    ToReal(Var, Var),
    Cmp(CmpOp, Var, Var, Var),
    /// `Cmp` of an integer with an integer literal.
    CmpK(CmpOp, Var, Var, i64),
    Eq(bool, Var, Var, Var),
    Logic(LogicOp, Var, Var, Var),
    Not(Var, Var),
    RangeCheck(Var, TypeId, Span),
    /// `dst := arr (ix...)` for an array held in a slot (three or four
    /// indices; one and two are `Index1`, `Index2`, without an allocation).
    Index(Var, Var, Box<[Var]>, Span),
    Index1(Var, Var, Var, Span),
    Index2(Var, Var, [Var; 2], Span),
    /// `arr (ix...) := src` (and with one or two indices).
    StoreIndex(Var, Box<[Var]>, Var, Span),
    StoreIndex1(Var, Var, Var, Span),
    StoreIndex2(Var, [Var; 2], Var, Span),
    Field(Var, Var, u32, Span),
    /// `dst := ptr.all.field` (a component of the record an access
    /// designates, not a copy of the record); where the access check and
    /// where the discriminant check fails.
    DerefField(Var, Var, u32, Span, Span),
    /// `dst := null`.
    Null(Var),
    /// `dst := "text"`: a string literal's value, made once when the code
    /// is compiled (a copy of it is one reference count: an assignment
    /// into it copies it first).
    Str(Var, Value),
    /// `dst := x & y` (each an array or an element).
    Concat(Box<ConcatOp>),
    /// `dst := base (low .. high)`, and where its check fails.
    Slice(Var, Var, [Var; 2], Span),
    /// `dst := P'Attr (args)`, the arguments in slots.
    Attr(Box<AttrInstr>),
    /// The walker evaluates an expression into a slot. The expression may
    /// be a copy whose operands were computed here first (replaced by the
    /// temporaries holding them, listed last, which are emptied once it is
    /// evaluated: a chain `F (X) & "a" & ...` would keep every intermediate
    /// string alive until the frame ends).
    Eval(Var, Box<Ex>, Box<[Var]>),
    /// The walker assigns a slot's value to a target.
    Assign(Box<Ex>, Var),
    /// The walker executes a statement.
    Exec(Box<Stmt>),
    Jump(u32),
    JumpIfNot(Var, u32),
    /// `JumpIfNot` of a `CmpK`, in one instruction (`if N < 2 then`).
    CmpKJumpNot(CmpOp, Var, i64, u32),
    /// `JumpIfNot` of a `Cmp`.
    CmpJumpNot(CmpOp, Var, Var, u32),
    JumpIf(Var, u32),
    /// Case: the subject, (low, high, target) choices, the `others` target.
    Case(Var, Box<[(i64, i64, u32)]>, Option<u32>, Span),
    /// First step of a `for` loop: the counter, low, high, reverse, the
    /// exit target (an empty range jumps there).
    ForStart(Var, Var, Var, bool, u32),
    /// Next step: counter, low, high, reverse, the body's start.
    ForNext(Var, Var, Var, bool, u32, Span),
    Poll(Span),
    /// A call of a subprogram with a body: whether it is a function, its
    /// arguments when one is not `in` (for the copy-back; None: all `in`,
    /// or none), their operands followed by the slot for a function's
    /// result. The arguments are boxed twice, a thin pointer: it keeps `Op`
    /// at 48 bytes.
    Call(bool, FuncId, Option<Box<Box<[Arg]>>>, Box<[Var]>, Span),
    /// A call the walker makes (natives, services, a subprogram without
    /// body), its `in` arguments with calls in them computed here first.
    CallWalker(FuncId, Box<[Arg]>, Option<Var>, Span),
    /// A call whose one argument, `in`, is `x op k` for integers: the
    /// operation goes straight into the callee's frame (`F (N - 1)`).
    /// Then a function's result slot (`NO_VAR`: a procedure), the call's
    /// place and the argument's (in the call's file).
    CallK(FuncId, Var, IntOp, i32, Var, Span, [u32; 2]),
    Return(Option<Var>),
    /// `return x op y` for integers, the operation and the return in one
    /// instruction (`return F (N - 1) + F (N - 2);`).
    ReturnIntBin(IntOp, Var, Var, Span),
    /// The end of a body: a procedure returns, a function raises.
    FallOff,
    /// Handler dispatch for the pending occurrence: the handlers, the
    /// target of each, and the handler depth of the region.
    Dispatch(Box<[Catch]>, u32),
    /// Leaves a handler body: its occurrence is no longer current.
    PopCurrent,
    /// Back to `frame's depth + n` current occurrences (an `exit` out of
    /// handler bodies).
    TruncCurrent(u32),
    // ---- tasking (see `tasking.rs`) ----
    /// `delay` (false) or `delay until` (true).
    Delay(Var, bool, Span),
    /// Activates the tasks created so far and waits for their activation.
    Activate(Span),
    /// A master region begins; its end waits for its tasks.
    MasterEnter,
    MasterLeave(Span),
    /// An exception leaves a master region: wait for its tasks, then
    /// propagate it.
    MasterUnwind(Span),
    /// Library-level tasks, at the end of the run: where the main program
    /// ended (a deadlock or a Ctrl-C there names it).
    AwaitAll(Span),
    /// The end of a REPL entry while tasks live on: the ready tasks run
    /// until every one has blocked.
    Settle,
    /// `accept`: the entry and the parameters' slots.
    Accept(u32, Box<[(Var, Mode)]>, Span),
    /// The end of a rendezvous: `out` values go to the caller.
    AcceptEnd(Box<[(Var, Mode)]>),
    /// An exception leaves an accept body: the caller gets it too.
    AcceptFail,
    /// An entry call of a task.
    EntryCall(Box<EntryOp>),
    /// After an entry call: copy-out, the caller's exception, or the jump
    /// to a timed call's delay (conditional call's else) statements.
    EntryDone(Box<Box<[Arg]>>, Box<[Var]>, Option<u32>, Span),
    /// A protected entry call.
    ProtEntry(Box<EntryOp>),
    /// After a protected action: the object's queues are served.
    ProtDone(Var, Box<[Arg]>, Span),
    Select(Box<SelectOp>),
    Abort(Box<[Var]>),
    /// An allocator of a task: the task is activated by the next
    /// instruction (`Activate`), not left to the walker.
    AllocTask(Var, Box<Ex>),
    /// An access type to tasks is declared: note its master.
    NoteMaster(Var),
}

/// An entry call: the task (or object), entry, arguments and their
/// operands, the timeout (delay or time) of a timed call, whether it is
/// conditional, and where a timed call's delay statements begin.
#[derive(Debug)]
struct EntryOp {
    target: Var,
    kind: u32,
    entry: u32,
    args: Box<[Arg]>,
    ops: Box<[Var]>,
    timed: Option<(Var, bool)>,
    conditional: bool,
    other: u32,
    /// The barrier's argument (the object), for protected entries.
    barrier_args: Box<[Arg]>,
    span: Span,
}

/// A concatenation: where it goes, its operands, whether each is one
/// element (not an array) and whether each is a temporary that the
/// operation may take (its last use), the result's type, where a length
/// check fails.
#[derive(Debug)]
struct ConcatOp {
    dst: Var,
    x: Var,
    y: Var,
    elems: (bool, bool),
    takes: (bool, bool),
    ty: TypeId,
    span: Span,
}

/// An attribute: its operation, result slot, arguments (temporaries are
/// emptied once read), result type and where it fails.
#[derive(Debug)]
struct AttrInstr {
    op: crate::check::ir::AttrOp,
    dst: Var,
    args: Box<[Var]>,
    temps: Box<[bool]>,
    ty: TypeId,
    span: Span,
}

/// A handler of a dispatch: its exceptions (None: `others`), the slot of
/// its occurrence, where its statements begin.
#[derive(Debug)]
struct Catch {
    choices: Option<Box<[ExcId]>>,
    occurrence: Option<Var>,
    target: u32,
}

/// A select's accept alternative: guard, entry, parameters, target.
type AcceptAlt = (Option<Var>, u32, Box<[(Var, Mode)]>, u32);

#[derive(Debug)]
struct SelectOp {
    alts: Vec<AcceptAlt>,
    /// Guard, amount, until, target.
    delay: Option<(Option<Var>, Var, bool, u32)>,
    terminate: Option<Option<Var>>,
    els: Option<u32>,
    span: Span,
}

/// The registers of a thread of the engine that is not running. They do
/// not borrow the program: each frame's code is found again by its
/// subprogram (compiled again, identically, in a later run: the REPL keeps
/// tasks between entries), a call's arguments from the call instruction.
#[derive(Clone)]
pub(crate) struct Regs {
    frames: Vec<SavedFrame>,
    /// The running code's subprogram (None: the level-0 code).
    cur: Option<FuncId>,
    pc: u32,
    current_base: usize,
    pending: Option<Box<Occurrence>>,
    /// A task's own frame (its body): base and top.
    root: Option<(usize, usize)>,
}

/// A [`Frame`] saved in [`Regs`].
#[derive(Clone)]
struct SavedFrame {
    func: Option<FuncId>,
    pc: u32,
    current: usize,
    /// The callee's frame: base, top, and the display entry it replaced.
    base: usize,
    top: usize,
    saved: usize,
    /// The caller's frame and result slot (see [`Frame`]).
    fp: usize,
    dst: usize,
}

impl Regs {
    /// The stack regions of the thread's frames.
    pub(crate) fn regions(&self) -> Vec<(usize, usize)> {
        self.root
            .into_iter()
            .chain(self.frames.iter().map(|f| (f.base, f.top)))
            .collect()
    }
}

/// The live registers of the running thread, as the engine's loop holds them.
type Live<'c> = (
    Vec<Frame<'c>>,
    &'c Code,
    u32,
    usize,
    Option<Box<Occurrence>>,
    Option<(usize, usize)>,
);

/// A part of a long body compiled as it was checked (see
/// [`compile_part`]): its instructions, handler regions and loop exits,
/// with targets counted from its first instruction.
#[derive(Default)]
pub struct Part {
    /// None: no code yet; then whether the code only puts scalars in the
    /// frame (see `Code::scalar`).
    scalar: Option<bool>,
    ops: Vec<Op>,
    regions: Vec<Region>,
    exits: Vec<(u32, u32, u32)>,
}

/// Compiles a part of a long subprogram body as soon as the checker has
/// made it (an [`crate::check::ir::PartCompiler`]), for `adair run`: the
/// checked statements are dropped here, the instructions are added to the
/// body's code so far (`into`), which waits for [`Compiler::splice`].
/// Which calls the walker makes is decided now: those of an imported
/// subprogram (a native, as [`Run::walker_call`] binds it). A subprogram
/// whose body is not checked yet (the body itself, when it calls itself;
/// one declared before and completed later) gets a compiled call (one left
/// without body raises when called, see `compile_first`).
pub(crate) fn compile_part(
    prog: ProgramRef<'_>,
    at: crate::check::ir::PartAt,
    stmts: Vec<Stmt>,
    into: &crate::check::ir::Precompiled,
) -> u32 {
    let walker_calls = |f: FuncId| prog.imports.get(f as usize).is_some_and(|n| n.is_some());
    let mut c = Compiler::new(at.level, at.own, &walker_calls, prog.types);
    c.masters = u32::from(at.master);
    c.stmts(&stmts);
    drop(stmts);
    into.fill(|body: &mut Part| {
        // One list for the whole body, grown in place (a big list's memory
        // is remapped, not copied, as it grows).
        let by = body.ops.len() as u32;
        body.ops.extend(c.ops.into_iter().map(|mut op| {
            relocate(&mut op, by);
            op
        }));
        body.regions
            .extend(c.regions.into_iter().map(|r| r.moved(by)));
        body.exits
            .extend(c.exits.into_iter().map(|(id, t, d)| (id, t + by, d)));
        body.scalar = Some(body.scalar.unwrap_or(true) && c.scalar);
    });
    c.max_temp
}

/// Moves `op`'s jump targets `by` instructions on (a compiled part
/// spliced into its body's code).
fn relocate(op: &mut Op, by: u32) {
    match op {
        Op::Jump(t)
        | Op::JumpIfNot(_, t)
        | Op::JumpIf(_, t)
        | Op::CmpKJumpNot(.., t)
        | Op::CmpJumpNot(.., t)
        | Op::ForStart(.., t)
        | Op::ForNext(_, _, _, _, t, _) => *t += by,
        Op::Case(_, table, other, _) => {
            for (_, _, t) in table.iter_mut() {
                *t += by;
            }
            if let Some(t) = other {
                *t += by;
            }
        }
        Op::Dispatch(catches, _) => {
            for c in catches.iter_mut() {
                c.target += by;
            }
        }
        Op::EntryDone(_, _, other, _) => {
            if let Some(t) = other {
                *t += by;
            }
        }
        Op::EntryCall(e) | Op::ProtEntry(e) => e.other += by,
        Op::Select(sel) => {
            for a in sel.alts.iter_mut() {
                a.3 += by;
            }
            if let Some(d) = &mut sel.delay {
                d.3 += by;
            }
            if let Some(t) = &mut sel.els {
                *t += by;
            }
        }
        Op::Int(..)
        | Op::Real(..)
        | Op::Move(..)
        | Op::IntBin(..)
        | Op::IntBinK(..)
        | Op::IntNeg(..)
        | Op::ModBin(..)
        | Op::FloatBin(..)
        | Op::ToReal(..)
        | Op::Cmp(..)
        | Op::CmpK(..)
        | Op::Eq(..)
        | Op::Logic(..)
        | Op::Not(..)
        | Op::RangeCheck(..)
        | Op::Index(..)
        | Op::Index1(..)
        | Op::Index2(..)
        | Op::StoreIndex(..)
        | Op::StoreIndex1(..)
        | Op::StoreIndex2(..)
        | Op::Field(..)
        | Op::DerefField(..)
        | Op::Null(..)
        | Op::Str(..)
        | Op::Slice(..)
        | Op::Concat(..)
        | Op::Attr(..)
        | Op::Eval(..)
        | Op::Assign(..)
        | Op::Exec(..)
        | Op::Poll(..)
        | Op::Call(..)
        | Op::CallK(..)
        | Op::CallWalker(..)
        | Op::Return(..)
        | Op::ReturnIntBin(..)
        | Op::FallOff
        | Op::PopCurrent
        | Op::TruncCurrent(..)
        | Op::Delay(..)
        | Op::Activate(..)
        | Op::MasterEnter
        | Op::MasterLeave(..)
        | Op::MasterUnwind(..)
        | Op::AwaitAll(..)
        | Op::Settle
        | Op::Accept(..)
        | Op::AcceptEnd(..)
        | Op::AcceptFail
        | Op::ProtDone(..)
        | Op::Abort(..)
        | Op::AllocTask(..)
        | Op::NoteMaster(..) => {}
    }
}

/// A part of the code whose exceptions go to handlers.
struct Region {
    start: u32,
    end: u32,
    dispatch: u32,
}

impl Region {
    /// The region `by` instructions on.
    fn moved(&self, by: u32) -> Region {
        Region {
            start: self.start + by,
            end: self.end + by,
            dispatch: self.dispatch + by,
        }
    }
}

/// A compiled body.
pub(crate) struct Code {
    /// The subprogram whose body this is (None: level-0 code).
    func: Option<FuncId>,
    /// Every parameter is `in`: a return has nothing to copy back.
    all_in: bool,
    /// Every value in its frame is a scalar (`Undef`, `Int`, `Real`: its
    /// parameters' and variables' types are scalar, and no instruction
    /// puts anything else there): freeing the frame drops nothing, so it
    /// is freed without looking at its slots.
    scalar: bool,
    /// The static level of its frame (its own slots are `Var`s of it).
    level: u16,
    ops: Vec<Op>,
    /// Slots beyond the subprogram's own: temporaries.
    temps: u32,
    /// The frame's size: the subprogram's own slots and the temporaries.
    frame: u32,
    /// Handler regions, innermost first.
    regions: Vec<Region>,
    /// `exit` targets of this code's loops, for an `exit` that a statement
    /// run by the walker returns: (loop id, target, handler depth).
    exits: Vec<(u32, u32, u32)>,
}

struct Compiler<'r> {
    level: u16,
    own: u32,
    ntemp: u32,
    max_temp: u32,
    ops: Vec<Op>,
    regions: Vec<Region>,
    exits: Vec<(u32, u32, u32)>,
    /// The loops being compiled: id, jumps to patch with the exit, handler
    /// depth, master regions open at the loop.
    loops: Vec<(u32, Vec<usize>, u32, u32)>,
    hdepth: u32,
    /// Master regions open at this point of the code.
    masters: u32,
    /// Which subprograms the walker calls (bound to natives or without body).
    walker_calls: &'r dyn Fn(FuncId) -> bool,
    types: &'r crate::check::types::Types,
    /// Every value this code puts in its frame is a scalar (`Undef`, `Int`,
    /// `Real`) so far: freeing the frame drops nothing (see `Code::scalar`).
    scalar: bool,
}

/// True when evaluating `e` may run a call or other code with effects
/// (so that an operand read before it must be copied first).
fn effects(e: &Ex) -> bool {
    effects_unless(e, &|_| None)
}

/// [`effects`], where `judge` has the first word on each node (`Some`:
/// its answer for the node and everything under it).
pub(crate) fn effects_unless(e: &Ex, judge: &dyn Fn(&Ex) -> Option<bool>) -> bool {
    if let Some(answer) = judge(e) {
        return answer;
    }
    let eff = |x: &Ex| effects_unless(x, judge);
    match &e.kind {
        ExKind::Int(_) | ExKind::Real(_) | ExKind::Var(_) | ExKind::Str(_) | ExKind::Null => false,
        ExKind::IntBin(_, a, b)
        | ExKind::ModBin(_, a, b)
        | ExKind::FloatBin(_, a, b)
        | ExKind::Cmp(_, a, b)
        | ExKind::Eq(_, a, b)
        | ExKind::Logic(_, a, b) => eff(a) || eff(b),
        ExKind::Not(a)
        | ExKind::IntNeg(a)
        | ExKind::FloatNeg(a)
        | ExKind::IntAbs(a)
        | ExKind::FloatAbs(a)
        | ExKind::IntToFloat(a)
        | ExKind::FloatToInt(a)
        | ExKind::RangeCheck(a, _)
        | ExKind::Field(a, _) => eff(a),
        ExKind::Index(p, idx) => eff(p) || idx.iter().any(eff),
        ExKind::Concat(a, b, ..) | ExKind::ArrLogic(_, a, b) => eff(a) || eff(b),
        ExKind::ArrNot(a) => eff(a),
        _ => true,
    }
}

impl<'r> Compiler<'r> {
    /// A compiler for code at `level` whose own slots are below `own`.
    fn new(
        level: u16,
        own: u32,
        walker_calls: &'r dyn Fn(FuncId) -> bool,
        types: &'r crate::check::types::Types,
    ) -> Self {
        Compiler {
            level,
            own,
            ntemp: 0,
            max_temp: 0,
            ops: Vec::new(),
            regions: Vec::new(),
            exits: Vec::new(),
            loops: Vec::new(),
            hdepth: 0,
            masters: 0,
            walker_calls,
            types,
            scalar: true,
        }
    }

    /// Whether an access type designates a task (its allocator activates it).
    fn has_task(&self, t: TypeId) -> bool {
        self.types
            .designated(t)
            .is_some_and(|d| self.types.has_task(d))
    }

    /// Whether a type is an array type (an assignment to it keeps the
    /// target's bounds).
    fn is_array(&self, t: TypeId) -> bool {
        self.types.array(t).is_some()
    }

    /// A value of type `t` goes into this code's frame.
    fn holds(&mut self, t: TypeId) {
        if !self.types.is_scalar(t) {
            self.scalar = false;
        }
    }

    fn temp(&mut self) -> Var {
        let v = Var {
            level: self.level,
            slot: self.own + self.ntemp,
        };
        self.ntemp += 1;
        self.max_temp = self.max_temp.max(self.ntemp);
        v
    }

    fn is_temp(&self, v: Var) -> bool {
        v.level == self.level && v.slot >= self.own
    }

    fn here(&self) -> u32 {
        self.ops.len() as u32
    }

    fn patch(&mut self, at: usize, target: u32) {
        match &mut self.ops[at] {
            Op::Jump(t)
            | Op::JumpIfNot(_, t)
            | Op::JumpIf(_, t)
            | Op::ForStart(.., t)
            | Op::CmpKJumpNot(.., t)
            | Op::CmpJumpNot(.., t) => *t = target,
            _ => unreachable!("only jumps are patched"),
        }
    }

    /// A jump (to be patched) taken when the condition `c` is False: a
    /// comparison jumps itself.
    fn jump_unless(&mut self, c: &Ex) -> usize {
        let op = match &c.kind {
            ExKind::Cmp(op, a, b) => match b.kind {
                ExKind::Int(k) => Op::CmpKJumpNot(*op, self.expr(a), k, 0),
                _ => {
                    let x = self.left(a, b);
                    Op::CmpJumpNot(*op, x, self.expr(b), 0)
                }
            },
            _ => Op::JumpIfNot(self.expr(c), 0),
        };
        self.ops.push(op);
        self.ops.len() - 1
    }

    /// The operand holding `e`'s value: a variable itself, or a temporary.
    fn expr(&mut self, e: &Ex) -> Var {
        if let ExKind::Var(v) = e.kind {
            return v;
        }
        let t = self.temp();
        self.expr_into(e, t);
        t
    }

    /// An operand for the left side of a binary operation whose right side
    /// is `right`: copied to a temporary when the right side may change it.
    fn left(&mut self, e: &Ex, right: &Ex) -> Var {
        self.operand_before(e, [right])
    }

    /// An operand read before the operands `later`: copied to a temporary
    /// when one of them may change it.
    fn operand_before<'e>(&mut self, e: &Ex, later: impl IntoIterator<Item = &'e Ex>) -> Var {
        let a = self.expr(e);
        if !self.is_temp(a) && later.into_iter().any(effects) {
            self.holds(e.ty);
            let t = self.temp();
            self.ops.push(Op::Move(t, a));
            return t;
        }
        a
    }

    /// Evaluates `e` into `dst`, which is written once, at the end.
    fn expr_into(&mut self, e: &Ex, dst: Var) {
        self.holds(e.ty);
        let span = e.span;
        match &e.kind {
            ExKind::Int(v) => self.ops.push(Op::Int(dst, *v)),
            ExKind::Real(v) => self.ops.push(Op::Real(dst, *v)),
            ExKind::Var(v) => self.ops.push(Op::Move(dst, *v)),
            ExKind::IntBin(op, a, b) => {
                if let ExKind::Int(k) = b.kind {
                    let x = self.expr(a);
                    self.ops.push(Op::IntBinK(*op, dst, x, k, span));
                    return;
                }
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::IntBin(*op, dst, x, y, span));
            }
            ExKind::IntNeg(a) => {
                let x = self.expr(a);
                self.ops.push(Op::IntNeg(dst, x, span));
            }
            ExKind::ModBin(op, a, b) => {
                let last = self.types.modular_last(e.ty).unwrap_or(u32::MAX);
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::ModBin(*op, dst, x, y, last, span));
            }
            ExKind::FloatBin(op, a, b) => {
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::FloatBin(*op, dst, x, y));
            }
            ExKind::IntToFloat(a) => {
                let x = self.expr(a);
                self.ops.push(Op::ToReal(dst, x));
            }
            ExKind::Cmp(op, a, b) if matches!(b.kind, ExKind::Int(_)) => {
                let ExKind::Int(k) = b.kind else {
                    unreachable!()
                };
                let x = self.expr(a);
                self.ops.push(Op::CmpK(*op, dst, x, k));
            }
            ExKind::Cmp(op, a, b) => {
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::Cmp(*op, dst, x, y));
            }
            ExKind::Eq(ne, a, b) => {
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::Eq(*ne, dst, x, y));
            }
            ExKind::Logic(op @ (LogicOp::AndThen | LogicOp::OrElse), a, b) => {
                // The result is built in a temporary: `dst` may be read by `b`.
                let t = self.temp();
                self.expr_into(a, t);
                let j = self.ops.len();
                self.ops.push(if *op == LogicOp::AndThen {
                    Op::JumpIfNot(t, 0)
                } else {
                    Op::JumpIf(t, 0)
                });
                self.expr_into(b, t);
                let end = self.here();
                self.patch(j, end);
                self.ops.push(Op::Move(dst, t));
            }
            ExKind::Logic(op, a, b) => {
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::Logic(*op, dst, x, y));
            }
            ExKind::Not(a) => {
                let x = self.expr(a);
                self.ops.push(Op::Not(dst, x));
            }
            ExKind::RangeCheck(a, t) => {
                let x = self.expr(a);
                self.ops.push(Op::RangeCheck(x, *t, span));
                self.ops.push(Op::Move(dst, x));
            }
            ExKind::Index(p, idx) if matches!(p.kind, ExKind::Var(_)) && idx.len() <= 4 => {
                let ExKind::Var(arr) = p.kind else {
                    unreachable!()
                };
                let mut ix = Vec::with_capacity(idx.len());
                for (k, x) in idx.iter().enumerate() {
                    let later_effects = idx[k + 1..].iter().any(effects);
                    let mut v = self.expr(x);
                    if later_effects && !self.is_temp(v) {
                        let t = self.temp();
                        self.ops.push(Op::Move(t, v));
                        v = t;
                    }
                    ix.push(v);
                }
                self.ops.push(match ix[..] {
                    [i] => Op::Index1(dst, arr, i, span),
                    [i, j] => Op::Index2(dst, arr, [i, j], span),
                    _ => Op::Index(dst, arr, ix.into(), span),
                });
            }
            ExKind::Field(p, i) => match &p.kind {
                ExKind::Deref(a) => {
                    let x = self.expr(a);
                    self.ops.push(Op::DerefField(dst, x, *i, p.span, span));
                }
                _ => {
                    let x = self.expr(p);
                    self.ops.push(Op::Field(dst, x, *i, span));
                }
            },
            ExKind::Null => self.ops.push(Op::Null(dst)),
            ExKind::Call(f, args) => self.call(*f, Some(args), Some(dst), span),
            ExKind::If(arms, els) => {
                let t = self.temp();
                let mut ends = Vec::new();
                for (c, v) in arms.iter() {
                    let x = self.expr(c);
                    let j = self.ops.len();
                    self.ops.push(Op::JumpIfNot(x, 0));
                    self.expr_into(v, t);
                    ends.push(self.ops.len());
                    self.ops.push(Op::Jump(0));
                    let next = self.here();
                    self.patch(j, next);
                }
                self.expr_into(els, t);
                let end = self.here();
                for j in ends {
                    self.patch(j, end);
                }
                self.ops.push(Op::Move(dst, t));
            }
            // A task made by an allocator is activated by it, which waits
            // for the activation (Tasking_Error when it fails, and the
            // target keeps its value).
            ExKind::Alloc(None, _) if self.has_task(e.ty) => {
                let t = self.temp();
                self.ops.push(Op::AllocTask(t, Box::new(e.clone())));
                self.ops.push(Op::Activate(span));
                self.ops.push(Op::Move(dst, t));
            }
            ExKind::Case(c) => {
                let (subj, arms, others) = &**c;
                let t = self.temp();
                let x = self.expr(subj);
                self.case(x, span, arms, others.as_ref(), |c, v| c.expr_into(v, t));
                self.ops.push(Op::Move(dst, t));
            }
            ExKind::Str(s) => self.ops.push(Op::Str(dst, Value::str(s))),
            ExKind::Slice(p, lh) => {
                let (l, h) = (&lh[0], &lh[1]);
                // The base is read before the bounds, as the walker does.
                let base = self.operand_before(p, [l, h]);
                let lo = self.left(l, h);
                let hi = self.expr(h);
                self.ops.push(Op::Slice(dst, base, [lo, hi], span));
            }
            ExKind::Concat(a, b, xe, ye) => {
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::Concat(Box::new(ConcatOp {
                    dst,
                    x,
                    y,
                    elems: (*xe, *ye),
                    takes: (self.is_temp(x), self.is_temp(y) && x != y),
                    ty: e.ty,
                    span,
                })));
            }
            // `'Pos` and `'Val` are the value itself (a check of `'Val`'s
            // range is a node of its own).
            ExKind::Attr(AttrOp::Pos | AttrOp::Val, args) if args.len() == 1 => {
                self.expr_into(&args[0], dst)
            }
            ExKind::Attr(op, args) if args.len() <= 2 => {
                // Each argument before the next is evaluated (a later one
                // with effects must not change an earlier one).
                let mut vars = Vec::with_capacity(args.len());
                for (i, a) in args.iter().enumerate() {
                    vars.push(self.operand_before(a, &args[i + 1..]));
                }
                let temps = vars
                    .iter()
                    .enumerate()
                    .map(|(i, v)| self.is_temp(*v) && !vars[..i].contains(v))
                    .collect();
                self.ops.push(Op::Attr(Box::new(AttrInstr {
                    op: *op,
                    dst,
                    args: vars.into(),
                    temps,
                    ty: e.ty,
                    span,
                })));
            }
            _ => {
                let (copy, temps) = self
                    .strict_copy(e)
                    .unwrap_or_else(|| (e.clone(), Vec::new()));
                self.ops.push(Op::Eval(dst, Box::new(copy), temps.into()));
            }
        }
    }

    /// For a node that evaluates each of its operands once, in order, and
    /// has a call among them: the operands computed here (so that the calls
    /// run compiled), and a copy of the node that reads them from their
    /// temporaries, for the walker. None: the walker takes the node whole.
    fn strict_copy(&mut self, e: &Ex) -> Option<(Ex, Vec<Var>)> {
        let kids: Vec<&Ex> = match &e.kind {
            ExKind::Attr(_, args) => args.iter().collect(),
            ExKind::Concat(a, b, ..) | ExKind::ArrLogic(_, a, b) => vec![a, b],
            ExKind::ArrNot(a) => vec![a],
            ExKind::FloatNeg(a)
            | ExKind::IntAbs(a)
            | ExKind::FloatAbs(a)
            | ExKind::FloatToInt(a)
            | ExKind::Deref(a)
            | ExKind::ArrayConvert(a, _) => vec![a],
            ExKind::Slice(p, lh) => vec![p, &lh[0], &lh[1]],
            ExKind::Index(p, idx) => std::iter::once(&**p).chain(idx.iter()).collect(),
            _ => return None,
        };
        if !kids.iter().any(|k| effects(k)) {
            return None;
        }
        let mut temps = Vec::with_capacity(kids.len());
        let vars: Vec<Ex> = kids
            .iter()
            .map(|k| {
                let t = self.temp();
                self.expr_into(k, t);
                temps.push(t);
                Ex {
                    kind: ExKind::Var(t),
                    ty: k.ty,
                    span: k.span,
                }
            })
            .collect();
        let mut v = vars.into_iter();
        let mut next = || Box::new(v.next().expect("an operand"));
        let kind = match &e.kind {
            ExKind::Attr(op, args) => {
                ExKind::Attr(*op, Box::new(args.iter().map(|_| *next()).collect()))
            }
            ExKind::Concat(_, _, x, y) => ExKind::Concat(next(), next(), *x, *y),
            ExKind::ArrLogic(op, ..) => ExKind::ArrLogic(*op, next(), next()),
            ExKind::ArrNot(_) => ExKind::ArrNot(next()),
            ExKind::FloatNeg(_) => ExKind::FloatNeg(next()),
            ExKind::IntAbs(_) => ExKind::IntAbs(next()),
            ExKind::FloatAbs(_) => ExKind::FloatAbs(next()),
            ExKind::FloatToInt(_) => ExKind::FloatToInt(next()),
            ExKind::Deref(_) => ExKind::Deref(next()),
            ExKind::ArrayConvert(_, t) => ExKind::ArrayConvert(next(), *t),
            ExKind::Slice(..) => ExKind::Slice(next(), Box::new([*next(), *next()])),
            ExKind::Index(_, idx) => {
                let p = next();
                ExKind::Index(p, Box::new(idx.iter().map(|_| *next()).collect()))
            }
            _ => unreachable!("only the kinds above are copied"),
        };
        Some((
            Ex {
                kind,
                ty: e.ty,
                span: e.span,
            },
            temps,
        ))
    }

    fn call(&mut self, f: FuncId, args: Option<&[Arg]>, dst: Option<Var>, span: Span) {
        let all: &[Arg] = args.unwrap_or_default();
        if (self.walker_calls)(f) {
            // The walker copies `out` values back into their targets.
            if all.iter().any(|a| a.mode != Mode::In) {
                self.scalar = false;
            }
            // `in` arguments with calls in them are computed here, so that
            // those calls run compiled.
            if all.iter().any(|a| effects(&a.value))
                && all.iter().all(|a| a.mode == Mode::In || !effects(&a.value))
            {
                let owned: Vec<Arg> = all
                    .iter()
                    .map(|a| {
                        if a.mode != Mode::In {
                            return a.clone();
                        }
                        let t = self.temp();
                        self.expr_into(&a.value, t);
                        Arg {
                            mode: a.mode,
                            value: Ex {
                                kind: ExKind::Var(t),
                                ty: a.value.ty,
                                span: a.value.span,
                            },
                            back_check: a.back_check,
                        }
                    })
                    .collect();
                self.ops.push(Op::CallWalker(f, owned.into(), dst, span));
            } else {
                self.ops.push(Op::CallWalker(f, all.into(), dst, span));
            }
            return;
        }
        if let [a] = all
            && a.mode == Mode::In
            && a.value.span.context == span.context
            && let ExKind::IntBin(op, x, k) = &a.value.kind
            && let ExKind::Int(k) = k.kind
            && let Ok(k) = i32::try_from(k)
        {
            let x = self.expr(x);
            let at = [a.value.span.start, a.value.span.end];
            let dst = dst.unwrap_or(NO_VAR);
            self.ops.push(Op::CallK(f, x, *op, k, dst, span, at));
            return;
        }
        let mut ops = Vec::with_capacity(all.len() + 1);
        for (k, a) in all.iter().enumerate() {
            let later = all[k + 1..].iter().any(|b| effects(&b.value));
            let mut v = self.expr(&a.value);
            if later && !self.is_temp(v) {
                self.holds(a.value.ty);
                let t = self.temp();
                self.ops.push(Op::Move(t, v));
                v = t;
            }
            ops.push(v);
        }
        ops.extend(dst);
        // The copy-back needs the arguments (see `call_site`).
        let args = all
            .iter()
            .any(|a| a.mode != Mode::In)
            .then(|| Box::new(Box::from(all)));
        self.ops
            .push(Op::Call(dst.is_some(), f, args, ops.into(), span));
    }

    fn stmts(&mut self, ss: &[Stmt]) {
        for s in ss {
            let mark = self.ntemp;
            self.stmt(s);
            self.ntemp = mark;
        }
    }

    fn stmt(&mut self, s: &Stmt) {
        match &s.kind {
            StmtKind::Null => {}
            StmtKind::Init(v, e) => self.expr_into(e, *v),
            // An array target keeps its bounds (the walker's `assign`
            // checks the length and slides).
            StmtKind::Assign(t, e) => match &t.kind {
                ExKind::Var(v) if !self.is_array(t.ty) => self.expr_into(e, *v),
                ExKind::Index(p, idx)
                    if matches!(p.kind, ExKind::Var(_))
                        && !self.is_array(t.ty)
                        && idx.len() <= 4
                        && !idx.iter().any(effects) =>
                {
                    let ExKind::Var(arr) = p.kind else {
                        unreachable!()
                    };
                    let src = self.expr(e);
                    let src = if self.is_temp(src) {
                        src
                    } else {
                        self.holds(e.ty);
                        let t = self.temp();
                        self.ops.push(Op::Move(t, src));
                        t
                    };
                    let ix: Vec<Var> = idx.iter().map(|x| self.expr(x)).collect();
                    self.ops.push(match ix[..] {
                        [i] => Op::StoreIndex1(arr, i, src, t.span),
                        [i, j] => Op::StoreIndex2(arr, [i, j], src, t.span),
                        _ => Op::StoreIndex(arr, ix.into(), src, t.span),
                    });
                }
                _ => {
                    let src = self.temp();
                    self.expr_into(e, src);
                    self.ops.push(Op::Assign(Box::new(t.clone()), src));
                }
            },
            StmtKind::Call(f, args) => self.call(*f, Some(args), None, s.span),
            StmtKind::If(arms, els) => {
                let mut ends = Vec::new();
                for (c, body) in arms {
                    let mark = self.ntemp;
                    let j = self.jump_unless(c);
                    self.ntemp = mark;
                    self.stmts(body);
                    ends.push(self.ops.len());
                    self.ops.push(Op::Jump(0));
                    let next = self.here();
                    self.patch(j, next);
                }
                self.stmts(els);
                let end = self.here();
                for j in ends {
                    self.patch(j, end);
                }
            }
            StmtKind::Case(subj, arms, others) => {
                let x = self.expr(subj);
                self.case(x, s.span, arms, others.as_ref(), |c, b| c.stmts(b));
            }
            StmtKind::Loop { id, body } => {
                let top = self.here();
                self.ops.push(Op::Poll(s.span));
                self.loop_body(*id, body);
                self.ops.push(Op::Jump(top));
                self.end_loop(*id);
            }
            StmtKind::While { id, cond, body } => {
                let top = self.here();
                let j = self.jump_unless(cond);
                self.ops.push(Op::Poll(s.span));
                self.loop_body(*id, body);
                self.ops.push(Op::Jump(top));
                let end = self.end_loop(*id);
                self.patch(j, end);
            }
            StmtKind::For(f) => {
                let (l, h) = (self.temp(), self.temp());
                self.expr_into(&f.lo, l);
                self.expr_into(&f.hi, h);
                let start = self.ops.len();
                self.ops.push(Op::ForStart(f.var, l, h, f.reverse, 0));
                let body_pc = self.here();
                self.loop_body(f.id, &f.body);
                self.ops
                    .push(Op::ForNext(f.var, l, h, f.reverse, body_pc, s.span));
                let end = self.end_loop(f.id);
                self.patch(start, end);
            }
            StmtKind::Exit(id, cond) => {
                let Some(k) = self.loops.iter().rposition(|(l, ..)| l == id) else {
                    self.ops.push(Op::Exec(Box::new(s.clone())));
                    return;
                };
                let skip = cond.as_ref().map(|c| self.jump_unless(c));
                let depth = self.loops[k].2;
                if depth < self.hdepth {
                    self.ops.push(Op::TruncCurrent(depth));
                }
                for _ in self.loops[k].3..self.masters {
                    self.ops.push(Op::MasterLeave(s.span));
                }
                let j = self.ops.len();
                self.ops.push(Op::Jump(0));
                self.loops[k].1.push(j);
                if let Some(j) = skip {
                    let next = self.here();
                    self.patch(j, next);
                }
            }
            StmtKind::Return(Some(e)) if self.masters == 0 && int_bin(e).is_some() => {
                let (op, a, b) = int_bin(e).expect("an integer operation");
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::ReturnIntBin(op, x, y, e.span));
            }
            StmtKind::Return(v) => {
                let x = v.as_ref().map(|e| self.expr(e));
                for _ in 0..self.masters {
                    self.ops.push(Op::MasterLeave(s.span));
                }
                self.ops.push(Op::Return(x));
            }
            StmtKind::Block(b) => self.body(b),
            StmtKind::Raise(..) | StmtKind::Reraise => self.ops.push(Op::Exec(Box::new(s.clone()))),
            StmtKind::Delay(until, d) => {
                let x = self.expr(d);
                self.ops.push(Op::Delay(x, *until, s.span));
            }
            StmtKind::Activate => self.ops.push(Op::Activate(s.span)),
            StmtKind::NoteMaster(v) => self.ops.push(Op::NoteMaster(*v)),
            StmtKind::Master(b) => {
                self.ops.push(Op::MasterEnter);
                self.masters += 1;
                self.guarded(
                    |c| c.body(b),
                    Op::MasterLeave(s.span),
                    Op::MasterUnwind(s.span),
                );
                self.masters -= 1;
            }
            StmtKind::Accept(a) => self.accept(a, s.span),
            StmtKind::EntryCall(ec) => {
                let other = self.entry_call(ec, None, false, s.span);
                debug_assert!(other.is_none());
            }
            StmtKind::TimedCall(tc) => {
                let amount = tc.delay.as_ref().map(|(until, d)| (self.expr(d), *until));
                let at = self.entry_call(&tc.call, amount, tc.delay.is_none(), s.span);
                self.stmts(&tc.then);
                let j = self.ops.len();
                self.ops.push(Op::Jump(0));
                let other = self.here();
                if let Some(at) = at {
                    self.set_other(at, other);
                }
                self.stmts(&tc.other);
                let end = self.here();
                self.patch(j, end);
            }
            StmtKind::ProtCall(f, args) => {
                self.call(*f, Some(args), None, s.span);
                let obj = self.expr(&args.last().expect("the object").value);
                let bargs = self.obj_args(obj, &args.last().expect("the object").value);
                self.ops.push(Op::ProtDone(obj, bargs, s.span));
            }
            StmtKind::Select(sel) => self.select(sel, s.span),
            StmtKind::Compiled(p) => {
                match p.take::<Part>() {
                    Some(part) => self.splice(part),
                    // Compiled once already: the walker raises.
                    None => self.ops.push(Op::Exec(Box::new(s.clone()))),
                }
            }
            StmtKind::Abort(ts) => {
                let ops: Vec<Var> = ts.iter().map(|t| self.expr(t)).collect();
                self.ops.push(Op::Abort(ops.into()));
            }
        }
    }

    /// Compiles `inner` as a region whose normal end runs `leave` and
    /// whose exceptions go to `unwind` (which propagates them).
    fn guarded(&mut self, inner: impl FnOnce(&mut Self), leave: Op, unwind: Op) {
        let start = self.here();
        inner(self);
        let end = self.here();
        self.ops.push(leave);
        let j = self.ops.len();
        self.ops.push(Op::Jump(0));
        let dispatch = self.here();
        self.ops.push(unwind);
        let after = self.here();
        self.patch(j, after);
        self.regions.push(Region {
            start,
            end,
            dispatch,
        });
    }

    /// `accept`: wait for a caller, then the body (whose exception the
    /// caller gets too), then the end of the rendezvous.
    fn accept(&mut self, a: &Accept, span: Span) {
        self.ops
            .push(Op::Accept(a.entry, a.params.as_slice().into(), span));
        self.accept_rest(a);
    }

    fn accept_rest(&mut self, a: &Accept) {
        match &a.body {
            Some(b) => self.guarded(
                |c| c.body(b),
                Op::AcceptEnd(a.params.as_slice().into()),
                Op::AcceptFail,
            ),
            None => self.ops.push(Op::AcceptEnd(a.params.as_slice().into())),
        }
    }

    /// The object as the argument of its barriers.
    fn obj_args(&self, obj: Var, like: &Ex) -> Box<[Arg]> {
        Box::new([Arg {
            mode: Mode::In,
            value: Ex {
                kind: ExKind::Var(obj),
                ty: like.ty,
                span: like.span,
            },
            back_check: None,
        }])
    }

    /// An entry call; returns the instruction whose `other` target (timed
    /// and conditional calls) is to be set.
    fn entry_call(
        &mut self,
        ec: &EntryCall,
        timed: Option<(Var, bool)>,
        conditional: bool,
        span: Span,
    ) -> Option<usize> {
        // Each argument in a temporary of its own: the server writes the
        // `out` values there.
        let (target, kind, entry) = match &ec.target {
            CallTarget::Task { task, entry, .. } => {
                let t = self.temp();
                self.expr_into(task, t);
                (t, u32::MAX, *entry)
            }
            CallTarget::Prot { prot, entry } => (Var { level: 0, slot: 0 }, *prot, *entry),
        };
        let ops: Vec<Var> = ec
            .args
            .iter()
            .map(|a| {
                let t = self.temp();
                self.expr_into(&a.value, t);
                t
            })
            .collect();
        let is_timed = timed.is_some() || conditional;
        match &ec.target {
            CallTarget::Task { .. } => {
                self.ops.push(Op::EntryCall(Box::new(EntryOp {
                    target,
                    kind,
                    entry,
                    args: ec.args.as_slice().into(),
                    ops: ops.clone().into(),
                    timed,
                    conditional,
                    other: 0,
                    barrier_args: Box::new([]),
                    span,
                })));
                let at = self.ops.len();
                self.ops.push(Op::EntryDone(
                    Box::new(ec.args.as_slice().into()),
                    ops.into(),
                    None,
                    span,
                ));
                is_timed.then_some(at)
            }
            CallTarget::Prot { .. } => {
                let obj = *ops.last().expect("the object");
                let last = &ec.args.last().expect("the object").value;
                let bargs = self.obj_args(obj, last);
                let at = self.ops.len();
                self.ops.push(Op::ProtEntry(Box::new(EntryOp {
                    target: obj,
                    kind,
                    entry,
                    args: ec.args.as_slice().into(),
                    ops: ops.into(),
                    timed,
                    conditional,
                    other: 0,
                    barrier_args: bargs.clone(),
                    span,
                })));
                self.ops.push(Op::ProtDone(obj, bargs, span));
                is_timed.then_some(at)
            }
        }
    }

    fn set_other(&mut self, at: usize, target: u32) {
        match &mut self.ops[at] {
            Op::EntryDone(_, _, other, _) => *other = Some(target),
            Op::ProtEntry(e) => e.other = target,
            _ => unreachable!("an entry call"),
        }
    }

    fn select(&mut self, sel: &Select, span: Span) {
        let mut alts = Vec::new();
        for (g, a, _) in &sel.alts {
            let g = g.as_ref().map(|g| self.expr(g));
            alts.push((g, a.entry, a.params.as_slice().into(), 0u32));
        }
        let delay = sel.delay.as_ref().map(|(g, until, d, _)| {
            let g = g.as_ref().map(|g| self.expr(g));
            let x = self.expr(d);
            (g, x, *until, 0u32)
        });
        let terminate = sel
            .terminate
            .as_ref()
            .map(|g| g.as_ref().map(|g| self.expr(g)));
        let at = self.ops.len();
        self.ops.push(Op::Jump(0));
        let mut ends = Vec::new();
        for (k, (_, a, then)) in sel.alts.iter().enumerate() {
            alts[k].3 = self.here();
            self.accept_rest(a);
            self.stmts(then);
            ends.push(self.ops.len());
            self.ops.push(Op::Jump(0));
        }
        let delay = delay.map(|(g, x, until, _)| {
            let t = self.here();
            if let Some((_, _, _, then)) = &sel.delay {
                self.stmts(then);
            }
            ends.push(self.ops.len());
            self.ops.push(Op::Jump(0));
            (g, x, until, t)
        });
        let els = sel.els.as_ref().map(|then| {
            let t = self.here();
            self.stmts(then);
            ends.push(self.ops.len());
            self.ops.push(Op::Jump(0));
            t
        });
        let end = self.here();
        for j in ends {
            self.patch(j, end);
        }
        self.ops[at] = Op::Select(Box::new(SelectOp {
            alts,
            delay,
            terminate,
            els,
            span,
        }));
    }

    /// A `case` (statement or expression) on `x`: a jump table to each
    /// alternative, compiled by `each`, and from each to the end.
    fn case<T>(
        &mut self,
        x: Var,
        span: Span,
        arms: &[(Vec<(i64, i64)>, T)],
        others: Option<&T>,
        mut each: impl FnMut(&mut Self, &T),
    ) {
        let at = self.ops.len();
        self.ops.push(Op::Case(x, Box::new([]), None, span));
        let mut table = Vec::new();
        let mut ends = Vec::new();
        for (ranges, alt) in arms {
            let target = self.here();
            table.extend(ranges.iter().map(|(l, h)| (*l, *h, target)));
            each(self, alt);
            ends.push(self.ops.len());
            self.ops.push(Op::Jump(0));
        }
        let other = others.map(|alt| {
            let target = self.here();
            each(self, alt);
            target
        });
        let end = self.here();
        for j in ends {
            self.patch(j, end);
        }
        self.ops[at] = Op::Case(x, table.into(), other, span);
    }

    fn loop_body(&mut self, id: u32, body: &[Stmt]) {
        self.loops.push((id, Vec::new(), self.hdepth, self.masters));
        self.stmts(body);
    }

    /// Ends the innermost loop: its exits jump here. Returns the target.
    fn end_loop(&mut self, id: u32) -> u32 {
        let end = self.here();
        let (_, jumps, depth, _) = self.loops.pop().expect("a loop");
        for j in jumps {
            self.patch(j, end);
        }
        self.exits.push((id, end, depth));
        end
    }

    fn body(&mut self, b: &Body) {
        if b.handlers.is_empty() {
            self.stmts(&b.stmts);
            return;
        }
        let start = self.here();
        self.stmts(&b.stmts);
        let end = self.here();
        let mut ends = vec![self.ops.len()];
        self.ops.push(Op::Jump(0));
        let dispatch = self.here();
        let at = self.ops.len();
        self.ops.push(Op::Dispatch(Box::new([]), self.hdepth));
        let mut catches = Vec::with_capacity(b.handlers.len());
        for h in &b.handlers {
            catches.push(Catch {
                choices: h.choices.as_deref().map(Box::from),
                occurrence: h.occurrence,
                target: self.here(),
            });
            self.hdepth += 1;
            self.stmts(&h.stmts);
            self.hdepth -= 1;
            self.ops.push(Op::PopCurrent);
            ends.push(self.ops.len());
            self.ops.push(Op::Jump(0));
        }
        self.ops[at] = Op::Dispatch(catches.into(), self.hdepth);
        let after = self.here();
        for j in ends {
            self.patch(j, after);
        }
        self.regions.push(Region {
            start,
            end,
            dispatch,
        });
    }

    /// Moves a compiled part's code here.
    /// The code so far goes in front of the part's, in its list (a long
    /// body's code is most of a long program's memory: it is not copied
    /// into a second list).
    fn splice(&mut self, part: Part) {
        let by = self.here();
        self.scalar &= part.scalar.unwrap_or(true);
        let mut ops = part.ops;
        ops.splice(0..0, self.ops.drain(..));
        for op in &mut ops[by as usize..] {
            relocate(op, by);
        }
        self.ops = ops;
        self.regions
            .extend(part.regions.iter().map(|r| r.moved(by)));
        self.exits
            .extend(part.exits.into_iter().map(|(id, t, d)| (id, t + by, d)));
    }

    /// The compiled code; `scalar_params`: its parameters' types are
    /// scalar.
    fn finish(mut self, func: Option<FuncId>, all_in: bool, scalar_params: bool) -> Code {
        self.ops.push(Op::FallOff);
        // Only what the engine itself puts in slots is known: the walker's
        // and the tasking instructions may put anything there.
        let scalar = scalar_params
            && self.scalar
            && self.ops.iter().all(|op| match op {
                Op::Dispatch(catches, _) => catches.iter().all(|c| c.occurrence.is_none()),
                Op::Eval(..)
                | Op::Assign(..)
                | Op::Exec(..)
                | Op::Delay(..)
                | Op::Activate(..)
                | Op::MasterEnter
                | Op::MasterLeave(..)
                | Op::MasterUnwind(..)
                | Op::AwaitAll(..)
                | Op::Settle
                | Op::Accept(..)
                | Op::AcceptEnd(..)
                | Op::AcceptFail
                | Op::EntryCall(..)
                | Op::EntryDone(..)
                | Op::ProtEntry(..)
                | Op::ProtDone(..)
                | Op::Select(..)
                | Op::Abort(..)
                | Op::AllocTask(..)
                | Op::NoteMaster(..) => false,
                Op::Int(..)
                | Op::Real(..)
                | Op::Move(..)
                | Op::IntBin(..)
                | Op::IntBinK(..)
                | Op::IntNeg(..)
                | Op::ModBin(..)
                | Op::FloatBin(..)
                | Op::ToReal(..)
                | Op::Cmp(..)
                | Op::CmpK(..)
                | Op::Eq(..)
                | Op::Logic(..)
                | Op::Not(..)
                | Op::RangeCheck(..)
                | Op::Index(..)
                | Op::Index1(..)
                | Op::Index2(..)
                | Op::StoreIndex(..)
                | Op::StoreIndex1(..)
                | Op::StoreIndex2(..)
                | Op::Field(..)
                | Op::DerefField(..)
                | Op::Null(..)
                | Op::Str(..)
                | Op::Slice(..)
                | Op::Concat(..)
                | Op::Attr(..)
                | Op::Jump(..)
                | Op::JumpIfNot(..)
                | Op::CmpKJumpNot(..)
                | Op::CmpJumpNot(..)
                | Op::JumpIf(..)
                | Op::Case(..)
                | Op::ForStart(..)
                | Op::ForNext(..)
                | Op::Poll(..)
                | Op::Call(..)
                | Op::CallK(..)
                | Op::CallWalker(..)
                | Op::Return(..)
                | Op::ReturnIntBin(..)
                | Op::FallOff
                | Op::PopCurrent
                | Op::TruncCurrent(..) => true,
            });
        // Exact sizes: the main body of a long program is compiled once.
        self.ops.shrink_to_fit();
        self.regions.shrink_to_fit();
        self.exits.shrink_to_fit();
        Code {
            func,
            all_in,
            scalar,
            level: self.level,
            ops: self.ops,
            temps: self.max_temp,
            frame: self.own + self.max_temp,
            regions: self.regions,
            exits: self.exits,
        }
    }
}

/// A call in progress in the compiled engine: what its return goes back
/// to. The rest of the call is found without storing it: the callee (its
/// subprogram, level, frame size, whether it has `out` parameters) is the
/// code that runs until the return, and the arguments and result slot are
/// in the call instruction before `pc` (see [`call_site`]).
pub(crate) struct Frame<'c> {
    /// The caller's code and where it goes on when the callee returns.
    code: &'c Code,
    pc: u32,
    /// Current occurrences when the callee was entered.
    current: usize,
    /// Where the callee's frame begins, and the display entry of the
    /// callee's level that the call replaced.
    base: usize,
    saved: usize,
    /// Where the caller's own frame begins, and the stack slot a
    /// function's result goes to (`NO_DST`: none, or the copy-back path):
    /// a return finds both without the display or the call instruction.
    fp: usize,
    dst: usize,
}

/// [`Frame::dst`] of a call whose result, if any, is not put by the
/// quick return.
const NO_DST: usize = usize::MAX;

/// No operand (`Op::CallK` of a procedure).
const NO_VAR: Var = Var {
    level: u16::MAX,
    slot: u32::MAX,
};

/// The arguments of a call: in slots of the caller, or one integer.
#[derive(Clone, Copy)]
enum Args<'x> {
    Slots(&'x [Var]),
    Int(i64),
}

/// A called frame just set up: the callee's code, where its frame begins,
/// and the display entry it replaced.
type Entered<'c> = (&'c Code, usize, usize);

/// The compiled bodies of a run, each compiled on its subprogram's first
/// call. A body stays where it is while others are added, so the engine
/// holds plain references to them.
pub(crate) struct Codes<'c> {
    arena: &'c typed_arena::Arena<Code>,
    by_func: Vec<Option<&'c Code>>,
}

impl<'a> Run<'a> {
    /// Whether the walker makes the calls of `f` (a native or no body).
    fn walker_call(&self, f: FuncId) -> bool {
        self.m.natives.get(f as usize).copied().flatten().is_some()
            || self.c.funcs[f as usize].body.is_none()
    }

    fn compile(&self, level: u16, own: u32, what: Compiled<'a>, func: Option<FuncId>) -> Code {
        let walker_calls = |f: FuncId| self.walker_call(f);
        let mut c = Compiler::new(level, own, &walker_calls, self.c.types);
        match what {
            Compiled::Body(b) => c.body(b),
            Compiled::Stmts(ss) => c.stmts(ss),
            Compiled::Main(f) => c.call(
                f,
                None,
                None,
                Span {
                    start: 0,
                    end: 0,
                    context: 0,
                },
            ),
        }
        let all_in = func.is_none_or(|f| {
            self.c.funcs[f as usize]
                .params
                .iter()
                .all(|p| p.mode == Mode::In)
        });
        let scalar_params = func.is_some_and(|f| {
            self.c.funcs[f as usize]
                .params
                .iter()
                .all(|p| self.c.types.is_scalar(p.ty))
        });
        c.finish(func, all_in, scalar_params)
    }

    /// The compiled body of `f`, compiled on its first call.
    #[inline(always)]
    fn code_of<'c>(&mut self, cache: &mut Codes<'c>, f: FuncId) -> &'c Code {
        match cache.by_func.get(f as usize) {
            Some(Some(c)) => c,
            _ => self.compile_first(cache, f),
        }
    }

    /// [`Self::code_of`] the first time.
    #[cold]
    #[inline(never)]
    fn compile_first<'c>(&mut self, cache: &mut Codes<'c>, f: FuncId) -> &'c Code {
        let i = f as usize;
        if cache.by_func.len() <= i {
            cache.by_func.resize(self.c.funcs.len().max(i + 1), None);
        }
        if let Some(c) = cache.by_func[i] {
            return c;
        }
        let sub = &self.c.funcs[i];
        let own = sub.nslots.max(sub.params.len() as u32);
        let code: &'c Code = match sub.body.as_deref() {
            Some(body) => {
                cache
                    .arena
                    .alloc(self.compile(sub.level, own, Compiled::Body(body), Some(f)))
            }
            // A call compiled with a long body's part (see `compile_part`)
            // of a subprogram that has no body: the walker raises.
            None => cache.arena.alloc(Code {
                func: Some(f),
                all_in: true,
                scalar: false,
                level: sub.level,
                ops: vec![Op::CallWalker(f, Box::new([]), None, sub.span), Op::FallOff],
                temps: 0,
                frame: own,
                regions: Vec::new(),
                exits: Vec::new(),
            }),
        };
        cache.by_func[i] = Some(code);
        code
    }

    /// Runs level-0 statements, then the main subprogram, in the compiled
    /// engine.
    pub(crate) fn run_compiled(&mut self, stmts: &'a [Stmt], main: Option<FuncId>) -> R<()> {
        let arena = typed_arena::Arena::new();
        let mut cache = Codes {
            arena: &arena,
            by_func: Vec::new(),
        };
        let own = self.c.globals;
        for (a, t) in std::mem::take(&mut self.m.pending_irqs) {
            self.deliver(a, t);
        }
        let code = arena.alloc(self.compile(0, own, Compiled::Stmts(stmts), None));
        let mut r = self.exec_code(&mut cache, code);
        if r.is_ok()
            && let Some(f) = main
        {
            let code = arena.alloc(self.compile(0, own, Compiled::Main(f), None));
            r = self.exec_code(&mut cache, code);
        }
        // The environment waits for the library-level tasks, also after an
        // exception (which then ends the run).
        // (Not after a deadlock: that diagnostic already names every task.)
        let deadlocked =
            matches!(&r, Err(Flow::Raise(o)) if o.ending == crate::interp::Ending::Deadlock);
        if self.m.sched.active() && !deadlocked && !matches!(r, Err(Flow::Exit(_))) {
            // The REPL keeps its tasks: the entry ends when no task is ready.
            let last = if self.m.keep_tasks {
                Op::Settle
            } else {
                Op::AwaitAll(self.program_end(stmts, main))
            };
            let code = arena.alloc(Code {
                func: None,
                all_in: true,
                scalar: false,
                level: 0,
                ops: vec![last, Op::FallOff],
                temps: 0,
                frame: 0,
                regions: Vec::new(),
                exits: Vec::new(),
            });
            let sched_cur = self.m.sched.cur;
            debug_assert_eq!(sched_cur, 0);
            self.exec_code(&mut cache, code)?;
        }
        r
    }

    /// Where the main program ends, where the environment waits for the
    /// library-level tasks: the end of the main subprogram's body, or of
    /// the script's last statement (never the predefined library's text).
    fn program_end(&self, stmts: &[Stmt], main: Option<FuncId>) -> Span {
        let last = match main.and_then(|f| self.c.funcs[f as usize].body.as_ref()) {
            Some(b) => b.stmts.last().map(|s| s.span),
            None => stmts.last().map(|s| s.span),
        };
        last.map_or(crate::diag::span(0, 0, 0), |sp| Span {
            start: sp.end,
            ..sp
        })
    }

    /// Pushes the frame of a call of `f` whose arguments are in `ops`.
    #[inline(always)]
    fn push_call<'c>(
        &mut self,
        cache: &mut Codes<'c>,
        f: FuncId,
        args: Args<'_>,
        (lvl, fp): (u16, usize),
        span: Span,
    ) -> R<Entered<'c>> {
        // Ctrl-C, also in a recursion that polls no loop.
        if let Some(flag) = &self.m.interrupted
            && flag.load(std::sync::atomic::Ordering::Relaxed)
        {
            self.poll(span)?;
        }
        if self.m.depth >= MAX_DEPTH {
            return Err(self.raise(
                check::STORAGE_ERROR,
                "stack overflow (recursion too deep)",
                span,
            ));
        }
        let code = self.code_of(cache, f);
        let level = code.level as usize;
        let base = self.m.stack.len();
        // The arguments go straight into the new frame; the display is
        // still the caller's while they are read (an operand of the
        // caller's own frame, at `lvl`, begins at `fp`).
        let ops = match args {
            Args::Slots(ops) => ops,
            Args::Int(n) => {
                self.m.stack.push_int(n);
                &[]
            }
        };
        for v in ops.iter() {
            let i = if v.level == lvl {
                fp + v.slot as usize
            } else {
                self.sl(*v)
            };
            match &self.m.stack[i] {
                Value::Int(i) => {
                    let i = *i;
                    self.m.stack.push_int(i);
                }
                other => {
                    let x = other.clone();
                    self.m.stack.push(x);
                }
            }
        }
        // A frame holds its parameters (see `compile_first`).
        debug_assert!(code.frame as usize >= self.m.stack.len() - base);
        let own = (code.frame - code.temps) as usize;
        let top = base + code.frame as usize;
        self.m.stack.grow_to_clearing(base + own, top);
        if self.m.display.len() <= level {
            self.m.display.resize(level + 1, 0);
        }
        let saved = self.m.display[level];
        self.m.display[level] = base;
        self.m.depth += 1;
        Ok((code, base, saved))
    }

    /// Whether this instruction runs a second time (after its thread was
    /// blocked by it); clears the mark.
    fn rerun(&mut self) -> bool {
        self.m.sched.active() && std::mem::take(&mut self.m.sched.me().rerun)
    }

    fn op_delay(&mut self, x: Var, until: bool, span: Span) -> R<()> {
        let v = self.m.stack[self.sl(x)].real();
        if !v.is_finite() {
            return Err(self.check_failed("delay of a non-finite duration", span));
        }
        let now = self.m.clock.now();
        let t = value::whole_ns(if until { v } else { now + v });
        if !self.m.sched.active() {
            // The devices live on while the program waits (their events
            // and interrupts at their own times, in --trace too).
            self.advance_clock(t - now);
            self.world_sync();
        } else if t <= now {
            self.m.sched.yield_now();
        } else {
            self.m.sched.block(tasking::Wait::Delay(t), false, span);
        }
        Ok(())
    }

    /// `Activate`: a task reports its own activation to its activator,
    /// then activates the tasks it created and waits for their activation.
    fn op_activate(&mut self, span: Span) -> R<()> {
        if !self.m.sched.active() {
            return Ok(());
        }
        let me = self.m.sched.cur;
        if self.rerun() {
            if std::mem::take(&mut self.m.sched.threads[me].activation_failed) {
                return Err(self.raise(
                    check::TASKING_ERROR,
                    "a task raised an exception during its activation",
                    span,
                ));
            }
            return Ok(());
        }
        if let Some(a) = self.m.sched.threads[me].activator.take() {
            self.activation_done(a, false);
        }
        let new = std::mem::take(&mut self.m.sched.threads[me].unactivated);
        if new.is_empty() {
            return Ok(());
        }
        for t in &new {
            self.m.sched.threads[*t].activator = Some(me);
            self.m.sched.make_ready(*t);
        }
        self.m.sched.threads[me].activating = new.len();
        self.m.sched.block(tasking::Wait::Activation, true, span);
        Ok(())
    }

    /// Whether the tasks of the running thread's innermost master (or,
    /// `all`, the library level's) have ended; if not, the thread waits.
    fn dependents_done(&mut self, all: bool, span: Span) -> bool {
        if !self.m.sched.active() {
            return true;
        }
        self.rerun();
        let me = self.m.sched.cur;
        let sc = &self.m.sched;
        let deps: Vec<tasking::Tid> = if all {
            sc.library.clone()
        } else {
            sc.threads[me].masters.last().cloned().unwrap_or_default()
        };
        // Tasks created but never activated (an exception before the
        // `begin`) are not waited for: they end now.
        for &t in &deps {
            if self.m.sched.threads[t].wait == tasking::Wait::Unactivated {
                self.end_thread(t, false);
            }
        }
        let done = deps
            .iter()
            .all(|d| self.m.sched.threads[*d].wait == tasking::Wait::Terminated);
        if !done {
            self.m.sched.block(tasking::Wait::Dependents, true, span);
        }
        done
    }

    /// Starts the rendezvous with caller `c`: its arguments into the
    /// accept's parameters.
    fn begin_rendezvous(&mut self, c: tasking::Tid, params: &[(Var, Mode)]) {
        let me = self.m.sched.cur;
        if c == tasking::INTERRUPT {
            self.m.sched.threads[me].rendezvous.push(c);
            return;
        }
        for (i, (v, _)) in params.iter().enumerate() {
            let x = self.m.stack[self.m.sched.threads[c].call[i]].clone();
            self.put(*v, x);
        }
        self.m.sched.threads[c].wait = tasking::Wait::Rendezvous(me);
        self.m.sched.threads[me].rendezvous.push(c);
    }

    /// Ends the innermost rendezvous: `out` values (or the exception) to
    /// the caller, who becomes ready.
    fn end_rendezvous(&mut self, params: &[(Var, Mode)], err: Option<Box<Occurrence>>) {
        let me = self.m.sched.cur;
        let Some(c) = self.m.sched.threads[me].rendezvous.pop() else {
            return;
        };
        if c == tasking::INTERRUPT {
            return;
        }
        if self.m.sched.threads[c].wait == tasking::Wait::Terminated {
            // The caller was aborted during the rendezvous: its frames are
            // gone (their slots may be above the stack's top), nothing to
            // copy back or to wake.
            return;
        }
        for (i, (v, mode)) in params.iter().enumerate() {
            if *mode != Mode::In {
                let x = self.m.stack[self.sl(*v)].clone();
                let slot = self.m.sched.threads[c].call[i];
                self.m.stack[slot] = x;
            }
        }
        self.m.sched.threads[c].outcome = match err {
            Some(o) => tasking::Outcome::Error(o),
            None => tasking::Outcome::Done,
        };
        self.m.sched.make_ready(c);
    }

    fn deadline(&mut self, timed: Option<(Var, bool)>) -> Option<f64> {
        timed.map(|(v, until)| {
            let x = self.m.stack[self.sl(v)].real();
            value::whole_ns(if until { x } else { self.m.clock.now() + x })
        })
    }

    fn op_entry_call(&mut self, ec: &EntryOp) -> R<()> {
        self.tasking_on();
        let me = self.m.sched.cur;
        let s = self.int_at(ec.target) as usize;
        let known = self
            .m
            .sched
            .threads
            .get(s)
            .is_some_and(|t| t.ttype.is_some() && (ec.entry as usize) < t.entries.len());
        if !known {
            return Err(self.raise(
                check::PROGRAM_ERROR,
                format!(
                    "{} the called task is not elaborated yet",
                    self.m.location(ec.span)
                ),
                ec.span,
            ));
        }
        let alive = self
            .m
            .sched
            .threads
            .get(s)
            .is_some_and(|t| t.callable && t.wait != tasking::Wait::Terminated);
        if !alive {
            let name = self
                .m
                .sched
                .threads
                .get(s)
                .map(|t| t.name.clone())
                .unwrap_or_default();
            return Err(self.raise(
                check::TASKING_ERROR,
                format!(
                    "{} the called task {name} has ended",
                    self.m.location(ec.span)
                ),
                ec.span,
            ));
        }
        let slots: Vec<usize> = ec.ops.iter().map(|v| self.sl(*v)).collect();
        self.m.sched.threads[me].call = slots;
        self.m.sched.threads[me].outcome = tasking::Outcome::Pending;
        let open = self.m.sched.accepting(s, ec.entry);
        let deadline = self.deadline(ec.timed);
        let now = self.m.clock.now();
        if !open && (ec.conditional || deadline.is_some_and(|d| d <= now)) {
            self.m.sched.threads[me].outcome = tasking::Outcome::Timeout;
            return Ok(());
        }
        self.m.sched.threads[s].entries[ec.entry as usize].push_back(me);
        if open {
            self.m.sched.make_ready(s);
        }
        self.m.sched.block(
            tasking::Wait::Call {
                server: s,
                entry: ec.entry,
                deadline,
            },
            false,
            ec.span,
        );
        Ok(())
    }

    /// After an entry call: false when it timed out (or was not taken).
    fn entry_done(&mut self, args: &[Arg], ops: &[Var], span: Span) -> R<bool> {
        let me = self.m.sched.cur;
        match std::mem::take(&mut self.m.sched.threads[me].outcome) {
            tasking::Outcome::Timeout => Ok(false),
            tasking::Outcome::Error(mut o) => {
                if o.span.start == 0 && o.span.end == 0 {
                    o.span = span;
                    o.message = format!("{} {}", self.m.location(span), o.message);
                }
                Err(Flow::Raise(o))
            }
            tasking::Outcome::Done | tasking::Outcome::Pending => {
                for (a, v) in args.iter().zip(ops.iter()) {
                    if a.mode != Mode::In {
                        let i = self.sl(*v);
                        let x = std::mem::take(&mut self.m.stack[i]);
                        if let Some(t) = a.back_check {
                            self.range_check(&x, t, a.value.span)?;
                        }
                        self.assign(&a.value, x)?;
                    }
                }
                Ok(true)
            }
        }
    }

    fn barrier_open(&mut self, k: u32, entry: u32, bargs: &[Arg], span: Span) -> R<bool> {
        let Some(b) = self.c.prots[k as usize].entries[entry as usize].barrier else {
            return Ok(false);
        };
        Ok(self.call(b, bargs, span)?.is_some_and(|v| v.int() != 0))
    }

    fn op_prot_entry(&mut self, ec: &EntryOp) -> R<ProtStep> {
        let active = self.m.sched.active();
        let me = self.m.sched.cur;
        if active {
            self.rerun();
            if std::mem::take(&mut self.m.sched.threads[me].timed_out) {
                // The call left its queue (RM 9.5.3(20)): that is a
                // protected action, after which the queues are served, as
                // a barrier that reads the entry's 'Count may open now.
                let obj = self.m.stack[self.sl(ec.target)].clone();
                let pid = Self::prot_id(&obj);
                if let Some(w) = self.first_open_call(pid, &ec.barrier_args, ec.span)? {
                    self.m.sched.threads[w].granted = true;
                    self.m.sched.make_ready(w);
                }
                return Ok(ProtStep::Other);
            }
            if std::mem::take(&mut self.m.sched.threads[me].granted) {
                self.m.sched.threads[me].proxied = true;
                return Ok(ProtStep::Body);
            }
        }
        let obj = self.m.stack[self.sl(ec.target)].clone();
        let pid = Self::prot_id(&obj);
        let queued = self
            .m
            .sched
            .prots
            .get(pid)
            .is_some_and(|p| !p.queues[ec.entry as usize].is_empty());
        if !queued && self.barrier_open(ec.kind, ec.entry, &ec.barrier_args, ec.span)? {
            return Ok(ProtStep::Body);
        }
        let deadline = self.deadline(ec.timed);
        if ec.conditional || deadline.is_some_and(|d| d <= self.m.clock.now()) {
            return Ok(ProtStep::Other);
        }
        self.tasking_on();
        let me = self.m.sched.cur;
        self.m.sched.prots[pid].queues[ec.entry as usize].push_back(me);
        // Queuing the call ends a protected action, so the queues are
        // served (RM 9.5.3(7-8)): a barrier that reads an entry's 'Count
        // may have opened now that the queue is longer (the cyclic
        // barrier `when Wait'Count = N or Releasing`).
        let granted = self.first_open_call(pid, &ec.barrier_args, ec.span)?;
        if granted == Some(me) {
            return Ok(ProtStep::Body);
        }
        self.m.sched.block(
            tasking::Wait::Prot {
                obj: pid,
                entry: ec.entry,
                deadline,
            },
            true,
            ec.span,
        );
        if let Some(w) = granted {
            self.m.sched.threads[w].granted = true;
            self.m.sched.make_first(w);
        }
        Ok(ProtStep::Wait)
    }

    /// Takes the first queued call of protected object `pid` whose
    /// barrier is open (entries in declaration order, each queue first
    /// in, first out) off its queue.
    fn first_open_call(&mut self, pid: usize, bargs: &[Arg], span: Span) -> R<Option<usize>> {
        let k = self.m.sched.prots[pid].ptype;
        let n = self.m.sched.prots[pid].queues.len();
        for e in 0..n {
            if self.m.sched.prots[pid].queues[e].is_empty() {
                continue;
            }
            if self.barrier_open(k, e as u32, bargs, span)? {
                return Ok(self.m.sched.prots[pid].queues[e].pop_front());
            }
        }
        Ok(None)
    }

    /// The end of a protected action on `obj`: the first queued call whose
    /// barrier is now open runs its body next (before any other task), and
    /// the task that ran an entry body for another gives way.
    fn serve(&mut self, obj: Var, bargs: &[Arg], span: Span) -> R<()> {
        if !self.m.sched.active() {
            return Ok(());
        }
        let me = self.m.sched.cur;
        let proxied = std::mem::take(&mut self.m.sched.threads[me].proxied);
        let v = self.m.stack[self.sl(obj)].clone();
        let pid = Self::prot_id(&v);
        match self.first_open_call(pid, bargs, span)? {
            Some(w) => {
                self.m.sched.threads[w].granted = true;
                if proxied {
                    self.m.sched.make_ready(me);
                } else {
                    self.m.sched.make_first(me);
                }
                self.m.sched.make_first(w);
                self.m.sched.switch = true;
            }
            None if proxied => self.m.sched.yield_now(),
            None => {}
        }
        Ok(())
    }

    /// A selective accept: Some(target) when an alternative is taken now.
    fn op_select(&mut self, sel: &SelectOp) -> R<Option<u32>> {
        let me = self.m.sched.cur;
        let again = self.rerun();
        if std::mem::take(&mut self.m.sched.threads[me].timed_out)
            && let Some((.., t)) = sel.delay
        {
            return Ok(Some(t));
        }
        let open = |this: &Self, g: Option<Var>| g.is_none_or(|g| this.int_at(g) != 0);
        for (g, entry, params, target) in &sel.alts {
            if open(self, *g)
                && let Some(c) = self.m.sched.threads[me].entries[*entry as usize].pop_front()
            {
                self.begin_rendezvous(c, params);
                return Ok(Some(*target));
            }
        }
        if let Some(t) = sel.els {
            return Ok(Some(t));
        }
        let entries: Vec<u32> = sel
            .alts
            .iter()
            .filter(|a| open(self, a.0))
            .map(|a| a.1)
            .collect();
        let delay = sel.delay.filter(|d| open(self, d.0));
        let terminate = sel.terminate.is_some_and(|g| open(self, g));
        if entries.is_empty() && delay.is_none() && !terminate {
            return Err(self.raise(
                check::PROGRAM_ERROR,
                format!(
                    "{} every alternative of the select is closed",
                    self.m.location(sel.span)
                ),
                sel.span,
            ));
        }
        let deadline = if again {
            self.m.sched.threads[me].deadline
        } else {
            let d = delay.and_then(|(_, x, until, _)| self.deadline(Some((x, until))));
            self.m.sched.threads[me].deadline = d;
            d
        };
        if let (Some(d), Some((.., t))) = (deadline, delay)
            && d <= self.m.clock.now()
        {
            return Ok(Some(t));
        }
        self.m.sched.block(
            tasking::Wait::Accept {
                entries,
                deadline,
                terminate,
            },
            true,
            sel.span,
        );
        Ok(None)
    }

    /// Until when the robot is busy for service `f`: another task's
    /// motion, or a `Control => True` motion still running (except for
    /// `EndRobot`, which raises ControlCommandActive then, services.md).
    /// While the TeachBox is open a motion service does not wait: it
    /// raises `RobotBusy` (tasks.md); any other service waits for the box.
    fn robot_free_at(&self, f: FuncId) -> f64 {
        let end_robot = self.c.imports[f as usize].as_deref() == Some("EndRobot");
        if let Some(s) = self.svc.as_deref()
            && let Some(Some(Binding::Service(i))) = self.m.natives.get(f as usize)
            && s.moves_the_arm(*i)
            && self.m.clock.now() < s.teach_until()
        {
            return f64::NEG_INFINITY;
        }
        let busy = match self.svc.as_deref() {
            Some(s) if !end_robot => s.busy_until(),
            _ => 0.0,
        };
        self.m.sched.robot_free_at.max(busy)
    }

    /// Exchanges the machine's per-thread registers with thread `t`'s.
    fn swap_registers(&mut self, t: tasking::Tid) {
        let th = &mut self.m.sched.threads[t];
        std::mem::swap(&mut self.m.display, &mut th.display);
        std::mem::swap(&mut self.m.current, &mut th.current);
        std::mem::swap(&mut self.m.depth, &mut th.depth);
        std::mem::swap(&mut self.m.calls, &mut th.calls);
    }

    /// Makes `t` the running thread: its saved registers, or its body's
    /// first frame when it starts.
    fn resume<'c>(
        &mut self,
        cache: &mut Codes<'c>,
        level0: &'c Code,
        t: tasking::Tid,
    ) -> R<Live<'c>> {
        if self.m.trace.is_some() && self.m.sched.cur != t {
            let (from, to) = (
                self.m.sched.threads[self.m.sched.cur].name.clone(),
                self.m.sched.threads[t].name.clone(),
            );
            let now = self.m.clock.now();
            self.trace_line(now, &format!("{from} -> {to}"));
        }
        self.m.sched.cur = t;
        self.m.sched.switches += 1;
        self.m.sched.threads[t].wait = tasking::Wait::Running;
        if let Some(r) = self.m.sched.threads[t].regs.take() {
            self.swap_registers(t);
            return Ok(self.load_regs(cache, level0, r));
        }
        let (body, mut display) = self.m.sched.threads[t]
            .start
            .take()
            .expect("a task to start");
        let code = self.code_of(cache, body);
        let sub = &self.c.funcs[body as usize];
        let level = sub.level as usize;
        let own = (sub.nslots as usize).max(sub.params.len());
        let base = self.m.stack.len().max(self.m.sched.floor);
        let top = base + own + code.temps as usize;
        self.m.stack.grow_to(top);
        display.resize(level + 1, 0);
        display[level] = base;
        let th = &mut self.m.sched.threads[t];
        th.display = display;
        th.current = Vec::new();
        th.depth = 0;
        th.calls = Vec::new();
        self.swap_registers(t);
        Ok((Vec::new(), code, 0, 0, None, Some((base, top))))
    }

    /// Live registers from saved ones: each frame's code compiled (or
    /// taken from this run's cache) again.
    fn load_regs<'c>(&mut self, cache: &mut Codes<'c>, level0: &'c Code, r: Regs) -> Live<'c> {
        let mut fetch = |this: &mut Self, func: Option<FuncId>| match func {
            Some(f) => this.code_of(cache, f),
            None => level0,
        };
        let mut frames = Vec::with_capacity(r.frames.len());
        for sf in r.frames {
            frames.push(Frame {
                code: fetch(self, sf.func),
                pc: sf.pc,
                current: sf.current,
                base: sf.base,
                saved: sf.saved,
                fp: sf.fp,
                dst: sf.dst,
            });
        }
        let cur = fetch(self, r.cur);
        (frames, cur, r.pc, r.current_base, r.pending, r.root)
    }

    /// The running task's body has ended (`failed`: by an exception).
    fn task_ends(&mut self, root: Option<(usize, usize)>, failed: bool) {
        let me = self.m.sched.cur;
        if let Some((b, t)) = root {
            self.free_frame(b, t);
        }
        let during_activation = failed && self.m.sched.threads[me].activator.is_some();
        self.end_thread(me, during_activation);
        self.swap_registers(me);
    }

    /// Switches to the next ready thread after the running one ended.
    fn next_thread<'c>(&mut self, cache: &mut Codes<'c>, level0: &'c Code) -> R<Live<'c>> {
        let next = loop {
            if let Some(n) = self.m.sched.pick() {
                break n;
            }
            if !self.idle() {
                return Err(self.deadlock());
            }
        };
        self.resume(cache, level0, next)
    }

    #[inline(always)]
    fn sl(&self, v: Var) -> usize {
        self.m.display[v.level as usize] + v.slot as usize
    }

    #[inline(always)]
    fn int_at(&self, v: Var) -> i64 {
        self.int_ix(self.sl(v))
    }

    /// How the values in slots `a` and `b` compare (as `Value::compare`,
    /// integers inline).
    #[inline(always)]
    fn order_ix(&self, a: usize, b: usize) -> std::cmp::Ordering {
        let (x, y) = (&self.m.stack[a], &self.m.stack[b]);
        match (x, y) {
            (Value::Int(p), Value::Int(q)) => p.cmp(q),
            _ => x.compare(y),
        }
    }

    /// How the value in slot `a` compares with the integer `k`.
    #[inline(always)]
    fn order_k(&self, a: usize, k: i64) -> std::cmp::Ordering {
        match &self.m.stack[a] {
            Value::Int(x) => x.cmp(&k),
            other => other.compare(&Value::Int(k)),
        }
    }

    /// The integer in stack slot `i`.
    #[inline(always)]
    fn int_ix(&self, i: usize) -> i64 {
        match &self.m.stack[i] {
            Value::Int(i) => *i,
            other => other.int(),
        }
    }

    /// `dst := x op y` for integers: addition and subtraction inline, the
    /// rest (and every overflow) through the walker's own checks.
    #[inline(always)]
    fn int_arith(&mut self, o: IntOp, d: usize, x: i64, y: i64, span: Span) -> R<()> {
        self.int_value(o, x, y, span).map(|v| self.put_int_ix(d, v))
    }

    /// `x op y` for integers, as [`Self::int_arith`] computes it.
    #[inline(always)]
    fn int_value(&self, o: IntOp, x: i64, y: i64, span: Span) -> R<i64> {
        self.int_value_at(o, x, y, || span)
    }

    /// [`Self::int_value`] whose place is made only when a check fails.
    #[inline(always)]
    fn int_value_at(&self, o: IntOp, x: i64, y: i64, span: impl FnOnce() -> Span) -> R<i64> {
        let quick = match o {
            IntOp::Add => Some(x + y),
            IntOp::Sub => Some(x - y),
            _ => None,
        };
        match quick {
            Some(v) if (i32::MIN as i64..=i32::MAX as i64).contains(&v) => Ok(v),
            _ => self.int_op(o, x, y, span()),
        }
    }

    #[inline(always)]
    fn put(&mut self, v: Var, x: Value) {
        self.put_ix(self.sl(v), x);
    }

    #[inline(always)]
    fn put_ix(&mut self, i: usize, x: Value) {
        set(&mut self.m.stack[i], x);
    }

    /// `put_ix` of an integer: a slot that holds one already is written in
    /// place (nothing to drop).
    #[inline(always)]
    fn put_int_ix(&mut self, i: usize, x: i64) {
        match &mut self.m.stack[i] {
            Value::Int(y) => *y = x,
            s => value::overwrite(s, Value::Int(x)),
        }
    }

    /// `put_ix` of a real, in place like [`Self::put_int`].
    #[inline(always)]
    fn put_real_ix(&mut self, i: usize, x: f64) {
        match &mut self.m.stack[i] {
            Value::Real(y) => *y = x,
            s => value::overwrite(s, Value::Real(x)),
        }
    }

    /// Runs level-0 code to its end.
    fn exec_code<'c>(&mut self, cache: &mut Codes<'c>, code: &'c Code) -> R<()> {
        let need = self.c.globals as usize + code.temps as usize;
        self.m.stack.grow_to(need);
        let mut frames: Vec<Frame<'c>> = Vec::new();
        let level0 = code;
        let mut cur = code;
        let mut pc: u32 = 0;
        let mut current_base = self.m.current.len();
        let mut pending: Option<Box<Occurrence>> = None;
        let mut enter: Option<Entered<'c>> = None;
        // A task's own frame (None: the main program's code).
        let mut root: Option<(usize, usize)> = None;
        // The running code's level and where its frame begins: an operand
        // of the code's own frame is found without the display.
        let mut lvl = cur.level;
        let mut fp = self.m.display.get(lvl as usize).copied().unwrap_or(0);
        macro_rules! ix {
            ($v:expr) => {{
                let v: Var = $v;
                if v.level == lvl {
                    fp + v.slot as usize
                } else {
                    self.sl(v)
                }
            }};
        }
        // Enters a called frame: the running code is saved with its resume
        // point, and the callee's code starts.
        macro_rules! push_frame {
            ($entered:expr, $dst:expr) => {
                let (code, base, saved) = $entered;
                frames.push(Frame {
                    code: std::mem::replace(&mut cur, code),
                    pc,
                    current: current_base,
                    base,
                    saved,
                    fp,
                    dst: $dst,
                });
                current_base = self.m.current.len();
                pc = 0;
            };
        }
        // A call's quick way in: the callee's frame is the running one.
        macro_rules! enter {
            ($entered:expr, $dst:expr) => {{
                let entered = $entered;
                let base = entered.1;
                push_frame!(entered, $dst);
                lvl = cur.level;
                fp = base;
                continue;
            }};
        }
        macro_rules! reload {
            () => {
                lvl = cur.level;
                fp = self.m.display.get(lvl as usize).copied().unwrap_or(0);
            };
        }
        // `dst := arr (idx)` and `arr (idx) := src` for the first `n`
        // indices (the instructions with one, two and more indices).
        macro_rules! load_index {
            ($d:ident, $arr:ident, $idx:ident, $n:expr, $span:ident) => {{
                // Scalars are copied out as such: a `Value` moved through
                // the native stack costs a drop call and a store stall.
                let got = match &self.m.stack[ix!(*$arr)] {
                    Value::Arr(a) => match a.offset(&$idx[..$n]) {
                        Some(o) => match &a.data[o] {
                            Value::Real(x) => Ok(Err(*x)),
                            v => Ok(Ok(v.clone())),
                        },
                        None => Err("index check failed"),
                    },
                    _ => Err("access check failed"),
                };
                match got {
                    Ok(Err(x)) => {
                        self.put_real_ix(ix!(*$d), x);
                        continue;
                    }
                    Ok(Ok(v)) => {
                        self.put_ix(ix!(*$d), v);
                        continue;
                    }
                    Err(what) => Err(self.check_failed(what, *$span)),
                }
            }};
        }
        macro_rules! store_index {
            ($arr:ident, $idx:ident, $n:expr, $src:ident, $span:ident) => {{
                let i = ix!(*$src);
                // A real goes as such (see `Index`), anything else is
                // taken from its temporary.
                let val = match &mut self.m.stack[i] {
                    Value::Real(x) => Err(*x),
                    v => Ok(std::mem::take(v)),
                };
                let slot = ix!(*$arr);
                let r = match &mut self.m.stack[slot] {
                    Value::Arr(a) => {
                        let a = Rc::make_mut(a);
                        match a.offset(&$idx[..$n]) {
                            Some(o) => {
                                match (val, &mut a.data[o]) {
                                    (Err(x), Value::Real(y)) => *y = x,
                                    (Err(x), s) => value::overwrite(s, Value::Real(x)),
                                    (Ok(v), s) => set(s, v),
                                }
                                Ok(())
                            }
                            None => Err("index check failed"),
                        }
                    }
                    _ => Err("access check failed"),
                };
                match r {
                    Ok(()) => continue,
                    Err(what) => Err(self.check_failed(what, *$span)),
                }
            }};
        }
        // A return of `$value` (an integer, or any value, or none): from a
        // call without `out` parameters the frame goes and the value lands
        // here; everything else takes the long way after the match.
        macro_rules! ret {
            ($value:expr) => {{
                let value: Result<i64, Option<Value>> = $value;
                let frame = if cur.all_in { frames.pop() } else { None };
                if let Some(frame) = frame {
                    self.pop_frame(&frame, cur, current_base);
                    cur = frame.code;
                    pc = frame.pc;
                    current_base = frame.current;
                    lvl = cur.level;
                    fp = frame.fp;
                    debug_assert_eq!(fp, self.m.display.get(lvl as usize).copied().unwrap_or(0));
                    if frame.dst != NO_DST {
                        match value {
                            Ok(n) => self.put_int_ix(frame.dst, n),
                            Err(v) => self.put_ix(frame.dst, v.unwrap_or_default()),
                        }
                    }
                    continue;
                }
                Err(Flow::Return(match value {
                    Ok(n) => Some(Value::Int(n)),
                    Err(v) => v,
                }))
            }};
        }
        loop {
            let op = &cur.ops[pc as usize];
            pc += 1;
            let r: R<()> = match op {
                // The instructions that cannot block, call or return go on
                // with the next one straight away (`continue`) when they
                // succeed; only the others pass the checks after the match.
                Op::Int(d, v) => {
                    self.put_int_ix(ix!(*d), *v);
                    continue;
                }
                Op::Real(d, v) => {
                    self.put_real_ix(ix!(*d), *v);
                    continue;
                }
                Op::Move(d, s) => {
                    let v = self.m.stack[ix!(*s)].clone();
                    self.put_ix(ix!(*d), v);
                    continue;
                }
                Op::IntBin(o, d, a, b, span) => {
                    let (x, y) = (self.int_ix(ix!(*a)), self.int_ix(ix!(*b)));
                    match self.int_arith(*o, ix!(*d), x, y, *span) {
                        Ok(()) => continue,
                        r => r,
                    }
                }
                Op::IntBinK(o, d, a, y, span) => {
                    let x = self.int_ix(ix!(*a));
                    match self.int_arith(*o, ix!(*d), x, *y, *span) {
                        Ok(()) => continue,
                        r => r,
                    }
                }
                Op::CmpK(o, d, a, k) => {
                    let ord = self.order_k(ix!(*a), *k);
                    let r = holds(*o, ord);
                    self.put_int_ix(ix!(*d), r as i64);
                    continue;
                }
                Op::IntNeg(d, a, span) => {
                    let x = self.int_ix(ix!(*a));
                    self.int_op(IntOp::Sub, 0, x, *span)
                        .map(|v| self.put_ix(ix!(*d), Value::Int(v)))
                }
                Op::ModBin(o, d, a, b, last, span) => {
                    let (x, y) = (self.int_ix(ix!(*a)), self.int_ix(ix!(*b)));
                    match crate::check::ir::modular(*o, x, y, *last) {
                        Some(v) => {
                            self.put_int_ix(ix!(*d), v);
                            continue;
                        }
                        None => Err(self.check_failed("divide by zero", *span)),
                    }
                }
                Op::FloatBin(o, d, a, b) => {
                    let x = self.m.stack[ix!(*a)].real();
                    let yv = &self.m.stack[ix!(*b)];
                    let v = value::float_op(*o, x, yv);
                    self.put_real_ix(ix!(*d), v);
                    continue;
                }
                Op::ToReal(d, a) => {
                    let x = self.m.stack[ix!(*a)].real();
                    self.put_real_ix(ix!(*d), x);
                    continue;
                }
                Op::Cmp(o, d, a, b) => {
                    let ord = self.order_ix(ix!(*a), ix!(*b));
                    let r = holds(*o, ord);
                    self.put_int_ix(ix!(*d), r as i64);
                    continue;
                }
                Op::Eq(ne, d, a, b) => {
                    let same = self.m.stack[ix!(*a)] == self.m.stack[ix!(*b)];
                    self.put_int_ix(ix!(*d), (same != *ne) as i64);
                    continue;
                }
                Op::Logic(o, d, a, b) => {
                    let (x, y) = (self.int_ix(ix!(*a)) != 0, self.int_ix(ix!(*b)) != 0);
                    let r = match o {
                        LogicOp::And | LogicOp::AndThen => x && y,
                        LogicOp::Or | LogicOp::OrElse => x || y,
                        LogicOp::Xor => x ^ y,
                    };
                    self.put_int_ix(ix!(*d), r as i64);
                    continue;
                }
                Op::Not(d, a) => {
                    let x = self.int_ix(ix!(*a)) == 0;
                    self.put_int_ix(ix!(*d), x as i64);
                    continue;
                }
                Op::RangeCheck(a, t, span) => {
                    let v = self.m.stack[ix!(*a)].clone();
                    match self.range_check(&v, *t, *span) {
                        Ok(()) => continue,
                        r => r,
                    }
                }
                Op::Index(d, arr, ix, span) => {
                    let mut idx = [0i64; 4];
                    for (k, v) in ix.iter().enumerate() {
                        idx[k] = self.int_ix(ix!(*v));
                    }
                    load_index!(d, arr, idx, ix.len(), span)
                }
                Op::Index1(d, arr, i, span) => {
                    let idx = [self.int_ix(ix!(*i))];
                    load_index!(d, arr, idx, 1, span)
                }
                Op::Index2(d, arr, [i, j], span) => {
                    let idx = [self.int_ix(ix!(*i)), self.int_ix(ix!(*j))];
                    load_index!(d, arr, idx, 2, span)
                }
                Op::StoreIndex(arr, ix, src, span) => {
                    let mut idx = [0i64; 4];
                    for (k, v) in ix.iter().enumerate() {
                        idx[k] = self.int_ix(ix!(*v));
                    }
                    store_index!(arr, idx, ix.len(), src, span)
                }
                Op::StoreIndex1(arr, i, src, span) => {
                    let idx = [self.int_ix(ix!(*i))];
                    store_index!(arr, idx, 1, src, span)
                }
                Op::StoreIndex2(arr, [i, j], src, span) => {
                    let idx = [self.int_ix(ix!(*i)), self.int_ix(ix!(*j))];
                    store_index!(arr, idx, 2, src, span)
                }
                Op::Field(d, a, i, span) => {
                    let got = match &self.m.stack[ix!(*a)] {
                        Value::Rec(r) => Some(r[*i as usize].clone()),
                        _ => None,
                    };
                    match got {
                        Some(v) => {
                            self.put_ix(ix!(*d), v);
                            continue;
                        }
                        None => Err(self.check_failed("discriminant check failed", *span)),
                    }
                }
                Op::DerefField(d, a, i, at_deref, at_field) => {
                    let got = match &self.m.stack[ix!(*a)] {
                        Value::Ptr(Some(o)) => match &*o.borrow() {
                            Value::Rec(r) => Ok(r[*i as usize].clone()),
                            _ => Err(("discriminant check failed", *at_field)),
                        },
                        _ => Err(("access check failed", *at_deref)),
                    };
                    match got {
                        Ok(v) => {
                            self.put_ix(ix!(*d), v);
                            continue;
                        }
                        Err((what, span)) => Err(self.check_failed(what, span)),
                    }
                }
                Op::Null(d) => {
                    self.put_ix(ix!(*d), Value::Ptr(None));
                    continue;
                }
                Op::Slice(d, b, [l, h], span) => {
                    let (l, h) = (self.int_ix(ix!(*l)), self.int_ix(ix!(*h)));
                    let bi = ix!(*b);
                    let base = std::mem::take(&mut self.m.stack[bi]);
                    let r = self.slice_of(&base, l, h, *span);
                    self.m.stack[bi] = base;
                    r.map(|v| self.put_ix(ix!(*d), v))
                }
                Op::Str(d, v) => {
                    self.put_ix(ix!(*d), v.clone());
                    continue;
                }
                Op::Concat(c) => {
                    let (xi, yi) = (ix!(c.x), ix!(c.y));
                    let x = if c.takes.0 {
                        std::mem::take(&mut self.m.stack[xi])
                    } else {
                        self.m.stack[xi].clone()
                    };
                    let y = if c.takes.1 {
                        std::mem::take(&mut self.m.stack[yi])
                    } else {
                        self.m.stack[yi].clone()
                    };
                    let (xe, ye) = c.elems;
                    self.concat(x, y, xe, ye, c.ty, c.span)
                        .map(|v| self.put_ix(ix!(c.dst), v))
                }
                Op::Attr(a) => {
                    let mut vals = [Value::Undef, Value::Undef];
                    for ((v, take), val) in a.args.iter().zip(a.temps.iter()).zip(&mut vals) {
                        let i = ix!(*v);
                        *val = if *take {
                            std::mem::take(&mut self.m.stack[i])
                        } else {
                            self.m.stack[i].clone()
                        };
                    }
                    let [a0, a1] = vals;
                    self.attr_of(a.op, a0, a1, a.ty, a.span)
                        .map(|v| self.put_ix(ix!(a.dst), v))
                }
                Op::Eval(d, e, temps) => {
                    let r = self.eval(e).map(|v| self.put_ix(ix!(*d), v));
                    for t in temps.iter() {
                        let i = ix!(*t);
                        self.m.stack[i] = Value::Undef;
                    }
                    r
                }
                Op::Assign(t, s) => {
                    let i = ix!(*s);
                    let v = std::mem::take(&mut self.m.stack[i]);
                    self.assign(t, v)
                }
                Op::Exec(s) => self.exec(s),
                Op::Jump(t) => {
                    pc = *t;
                    continue;
                }
                Op::JumpIfNot(c, t) => {
                    if self.int_ix(ix!(*c)) == 0 {
                        pc = *t;
                    }
                    continue;
                }
                Op::CmpKJumpNot(o, a, k, t) => {
                    let ord = self.order_k(ix!(*a), *k);
                    if !holds(*o, ord) {
                        pc = *t;
                    }
                    continue;
                }
                Op::CmpJumpNot(o, a, b, t) => {
                    let ord = self.order_ix(ix!(*a), ix!(*b));
                    if !holds(*o, ord) {
                        pc = *t;
                    }
                    continue;
                }
                Op::JumpIf(c, t) => {
                    if self.int_ix(ix!(*c)) != 0 {
                        pc = *t;
                    }
                    continue;
                }
                Op::Case(x, table, others, span) => {
                    let v = self.int_ix(ix!(*x));
                    match table.iter().find(|(l, h, _)| *l <= v && v <= *h) {
                        Some((_, _, t)) => {
                            pc = *t;
                            Ok(())
                        }
                        None => match others {
                            Some(t) => {
                                pc = *t;
                                Ok(())
                            }
                            None => Err(self.check_failed("case choice not covered", *span)),
                        },
                    }
                }
                Op::ForStart(v, l, h, rev, exit) => {
                    let (lo, hi) = (self.int_ix(ix!(*l)), self.int_ix(ix!(*h)));
                    if lo > hi {
                        pc = *exit;
                    } else {
                        self.put_int_ix(ix!(*v), if *rev { hi } else { lo });
                    }
                    continue;
                }
                Op::ForNext(v, l, h, rev, body, span) => {
                    let i = self.int_ix(ix!(*v));
                    let last = if *rev {
                        self.int_ix(ix!(*l))
                    } else {
                        self.int_ix(ix!(*h))
                    };
                    if i == last {
                        continue;
                    }
                    self.put_int_ix(ix!(*v), if *rev { i - 1 } else { i + 1 });
                    pc = *body;
                    match self.poll(*span) {
                        Ok(()) => continue,
                        r => r,
                    }
                }
                Op::Poll(span) => self.poll(*span),
                // A motion service while another task's motion runs waits
                // for it (the services are a monitor).
                Op::CallWalker(f, _, _, span)
                    if self.m.sched.active()
                        && self.is_service(*f)
                        && self.m.clock.now() < self.robot_free_at(*f) =>
                {
                    let until = self.robot_free_at(*f);
                    self.m.sched.block(tasking::Wait::Delay(until), true, *span);
                    Ok(())
                }
                Op::CallWalker(f, args, d, span) => {
                    self.rerun();
                    self.call(*f, args, *span).map(|v| {
                        if let Some(d) = d {
                            self.put_ix(ix!(*d), v.unwrap_or_default());
                        }
                    })
                }
                Op::Call(func, f, _, ops, span) => {
                    // (The result slot before the call: it changes the display.)
                    let (args, dst) = match (*func, ops.split_last()) {
                        (true, Some((d, args))) => (args, ix!(*d)),
                        _ => (&ops[..], NO_DST),
                    };
                    match self.push_call(cache, *f, Args::Slots(args), (lvl, fp), *span) {
                        Ok(entered) => enter!(entered, dst),
                        Err(e) => Err(e),
                    }
                }
                Op::CallK(f, a, o, k, d, span, [start, end]) => {
                    let x = self.int_ix(ix!(*a));
                    // (Before the call: it changes the display.)
                    let dst = if *d == NO_VAR { NO_DST } else { ix!(*d) };
                    let at = || Span {
                        start: *start,
                        end: *end,
                        context: span.context,
                    };
                    let entered = self
                        .int_value_at(*o, x, *k as i64, at)
                        .and_then(|n| self.push_call(cache, *f, Args::Int(n), (lvl, fp), *span));
                    match entered {
                        Ok(entered) => enter!(entered, dst),
                        Err(e) => Err(e),
                    }
                }
                Op::Return(x) => {
                    // Cloned, not taken: the value may be a variable of an
                    // enclosing frame. An integer goes as such (see `Index`).
                    let value = match x {
                        Some(x) => match &self.m.stack[ix!(*x)] {
                            Value::Int(n) => Ok(*n),
                            v => Err(Some(v.clone())),
                        },
                        None => Err(None),
                    };
                    ret!(value)
                }
                Op::ReturnIntBin(o, a, b, span) => {
                    let (x, y) = (self.int_ix(ix!(*a)), self.int_ix(ix!(*b)));
                    match self.int_value(*o, x, y, *span) {
                        Ok(n) => ret!(Ok(n)),
                        Err(e) => Err(e),
                    }
                }
                Op::FallOff => Err(Flow::Exit(FALL_OFF)),
                Op::Dispatch(catches, depth) => {
                    let occ = pending.take().expect("an occurrence to dispatch");
                    self.m.current.truncate(current_base + *depth as usize);
                    match catches.iter().find(|h| match &h.choices {
                        None => true,
                        Some(list) => list.contains(&occ.exc),
                    }) {
                        Some(h) => {
                            let occ: Rc<Occurrence> = Rc::from(occ);
                            if let Some(v) = h.occurrence {
                                self.put(v, Value::Occ(occ.clone()));
                            }
                            self.m.current.push(occ);
                            pc = h.target;
                            Ok(())
                        }
                        None => Err(Flow::Raise(occ)),
                    }
                }
                Op::PopCurrent => {
                    self.m.current.pop();
                    Ok(())
                }
                Op::TruncCurrent(n) => {
                    self.m.current.truncate(current_base + *n as usize);
                    Ok(())
                }
                Op::Delay(x, until, span) => self.op_delay(*x, *until, *span),
                Op::Activate(span) => self.op_activate(*span),
                Op::MasterEnter => {
                    self.tasking_on();
                    self.m.sched.me().masters.push(Vec::new());
                    Ok(())
                }
                Op::MasterLeave(span) => {
                    if self.dependents_done(false, *span) {
                        self.m.sched.me().masters.pop();
                    }
                    Ok(())
                }
                Op::MasterUnwind(span) => {
                    if self.dependents_done(false, *span) {
                        self.m.sched.me().masters.pop();
                        Err(Flow::Raise(pending.take().expect("an occurrence")))
                    } else {
                        Ok(())
                    }
                }
                Op::Settle => {
                    self.rerun();
                    if !self.m.sched.ready.is_empty() {
                        let me = self.m.sched.cur;
                        self.m.sched.make_ready(me);
                        self.m.sched.threads[me].reexec = true;
                        self.m.sched.switch = true;
                    }
                    Ok(())
                }
                Op::AwaitAll(span) => {
                    self.dependents_done(true, *span);
                    Ok(())
                }
                Op::Accept(entry, params, span) => {
                    let me = self.m.sched.cur;
                    self.m.sched.threads[me].rerun = false;
                    match self.m.sched.threads[me].entries[*entry as usize].pop_front() {
                        Some(c) => {
                            self.begin_rendezvous(c, params);
                            Ok(())
                        }
                        None => {
                            self.m.sched.block(
                                tasking::Wait::Accept {
                                    entries: vec![*entry],
                                    deadline: None,
                                    terminate: false,
                                },
                                true,
                                *span,
                            );
                            Ok(())
                        }
                    }
                }
                Op::AcceptEnd(params) => {
                    self.end_rendezvous(params, None);
                    Ok(())
                }
                Op::AcceptFail => {
                    let occ = pending.take().expect("an occurrence");
                    self.end_rendezvous(&[], Some(occ.clone()));
                    Err(Flow::Raise(occ))
                }
                Op::EntryCall(ec) => self.op_entry_call(ec),
                Op::EntryDone(args, ops, other, span) => match self.entry_done(args, ops, *span) {
                    Ok(true) => Ok(()),
                    Ok(false) => {
                        pc = other.expect("a timed or conditional call");
                        Ok(())
                    }
                    Err(e) => Err(e),
                },
                Op::ProtEntry(ec) => match self.op_prot_entry(ec) {
                    Ok(ProtStep::Body) => {
                        let sub = &self.c.prots[ec.kind as usize].entries[ec.entry as usize];
                        let body = sub.body.expect("an entry body");
                        match self.push_call(cache, body, Args::Slots(&ec.ops), (lvl, fp), ec.span)
                        {
                            Ok(e) => {
                                enter = Some(e);
                                Ok(())
                            }
                            Err(e) => Err(e),
                        }
                    }
                    Ok(ProtStep::Other) => {
                        // Skip the ProtDone after it.
                        pc = ec.other;
                        Ok(())
                    }
                    Ok(ProtStep::Wait) => Ok(()),
                    Err(e) => Err(e),
                },
                Op::ProtDone(obj, bargs, span) => self.serve(*obj, bargs, *span),
                Op::Select(sel) => match self.op_select(sel) {
                    Ok(Some(t)) => {
                        pc = t;
                        Ok(())
                    }
                    Ok(None) => Ok(()),
                    Err(e) => Err(e),
                },
                Op::AllocTask(d, e) => {
                    self.m.sched.alloc_activates = false;
                    let r = self.eval(e);
                    self.m.sched.alloc_activates = true;
                    r.map(|v| self.put_ix(ix!(*d), v))
                }
                Op::NoteMaster(v) => {
                    let code = self.master_code();
                    self.put_ix(ix!(*v), Value::Int(code));
                    Ok(())
                }
                Op::Abort(ts) => {
                    for t in ts.iter() {
                        let t = self.int_ix(ix!(*t)) as usize;
                        self.abort_task(t);
                    }
                    Ok(())
                }
            };
            // The slow way: a thread switch, a frame to enter, a return,
            // an exit or an exception. Then the running code may differ.
            'slow: {
                if self.m.sched.switch {
                    // The running thread blocked (or ended): save it, run the
                    // next ready one.
                    self.m.sched.switch = false;
                    let th = &mut self.m.sched.threads[self.m.sched.cur];
                    if std::mem::take(&mut th.reexec) {
                        pc -= 1;
                        th.rerun = true;
                    }
                    let me = self.m.sched.cur;
                    let regs = save_regs(&mut frames, cur, pc, current_base, pending.take(), root);
                    if self.m.sched.threads[me].wait == tasking::Wait::Terminated && me != 0 {
                        for (b, t) in regs.regions() {
                            self.free_frame(b, t);
                        }
                        self.end_thread(me, false);
                    } else {
                        self.m.sched.threads[me].regs = Some(regs);
                    }
                    self.swap_registers(me);
                    let next = loop {
                        if let Some(n) = self.m.sched.pick() {
                            break n;
                        }
                        if !self.idle() {
                            return Err(self.deadlock());
                        }
                    };
                    (frames, cur, pc, current_base, pending, root) =
                        self.resume(cache, level0, next)?;
                    break 'slow;
                }
                if let Some(entered) = enter.take() {
                    push_frame!(entered, NO_DST);
                    break 'slow;
                }
                let Err(flow) = r else { break 'slow };
                // Something other than the next instruction: a return, an exit
                // a statement run by the walker gave back, or an exception.
                let mut flow = flow;
                loop {
                    match flow {
                        Flow::Exit(id) if id != FALL_OFF => {
                            if let Some((_, t, depth)) = cur.exits.iter().find(|(l, ..)| *l == id) {
                                self.m.current.truncate(current_base + *depth as usize);
                                pc = *t;
                                break;
                            }
                            // Not a loop of this code (the user's stop): leave
                            // every frame.
                            while let Some(f) = frames.pop() {
                                self.pop_frame(&f, cur, current_base);
                                current_base = f.current;
                                cur = f.code;
                            }
                            return Err(Flow::Exit(id));
                        }
                        Flow::Exit(_) | Flow::Return(_) => {
                            let (value, fell_off) = match flow {
                                Flow::Return(v) => (v, false),
                                _ => (None, true),
                            };
                            let Some(frame) = frames.pop() else {
                                self.m.current.truncate(current_base);
                                if root.is_none() {
                                    // The end of the level-0 code.
                                    return Ok(());
                                }
                                // The end of a task body.
                                self.task_ends(root, false);
                                (frames, cur, pc, current_base, pending, root) =
                                    self.next_thread(cache, level0)?;
                                break;
                            };
                            let (args, dst) = call_site(frame.code, frame.pc);
                            // Copy-out values live in the frame.
                            let mut outs = Vec::new();
                            for (i, a) in args.iter().enumerate() {
                                if a.mode != Mode::In {
                                    outs.push((
                                        a,
                                        std::mem::take(&mut self.m.stack[frame.base + i]),
                                    ));
                                }
                            }
                            let f = cur.func.expect("a called frame");
                            self.pop_frame(&frame, cur, current_base);
                            cur = frame.code;
                            pc = frame.pc;
                            current_base = frame.current;
                            let sub = &self.c.funcs[f as usize];
                            let r = if fell_off && sub.ret.is_some() {
                                Err(self.raise(
                                    check::PROGRAM_ERROR,
                                    format!("{} missing return", self.m.location(sub.span)),
                                    sub.span,
                                ))
                            } else {
                                (|| {
                                    for (a, v) in outs {
                                        if let Some(t) = a.back_check {
                                            self.range_check(&v, t, a.value.span)?;
                                        }
                                        self.assign(&a.value, v)?;
                                    }
                                    if let Some(d) = dst {
                                        self.put(d, value.unwrap_or_default());
                                    }
                                    Ok(())
                                })()
                            };
                            match r {
                                Ok(()) => break,
                                Err(e) => flow = e,
                            }
                        }
                        Flow::Raise(mut occ) => {
                            // The calls of the compiled frames, innermost
                            // first, after the walker's (see `Occurrence::chained`).
                            if !occ.chained {
                                occ.chain
                                    .extend(frames.iter().rev().map(|f| call_span(f.code, f.pc)));
                                occ.chained = true;
                            }
                            let at = pc - 1;
                            if let Some(r) =
                                cur.regions.iter().find(|r| r.start <= at && at < r.end)
                            {
                                pc = r.dispatch;
                                pending = Some(occ);
                                break;
                            }
                            let Some(frame) = frames.pop() else {
                                self.m.current.truncate(current_base);
                                if root.is_none() {
                                    return Err(Flow::Raise(occ));
                                }
                                // An exception ends a task silently.
                                self.task_ends(root, true);
                                (frames, cur, pc, current_base, pending, root) =
                                    self.next_thread(cache, level0)?;
                                break;
                            };
                            self.pop_frame(&frame, cur, current_base);
                            cur = frame.code;
                            pc = frame.pc;
                            current_base = frame.current;
                            flow = Flow::Raise(occ);
                        }
                    }
                }
            }
            reload!();
        }
    }

    /// Leaves the frame of a call to `callee`: its slots, display entry,
    /// depth, and the occurrences it made current (back to
    /// `entry`, their number when it was entered); no copy-out.
    #[inline(always)]
    fn pop_frame(&mut self, f: &Frame<'_>, callee: &Code, entry: usize) {
        let top = f.base + callee.frame as usize;
        if callee.scalar && self.m.sched.holes.is_empty() && top >= self.m.stack.len() {
            self.m.stack.truncate_scalars(f.base);
        } else {
            self.free_frame(f.base, top);
        }
        self.m.display[callee.level as usize] = f.saved;
        self.m.depth -= 1;
        // (Tested first: `truncate` calls the drop glue on an empty tail.)
        if self.m.current.len() > entry {
            self.m.current.truncate(entry);
        }
    }
}

/// The operation and operands of `e` when it is an integer operation whose
/// right side is not a literal (those are `IntBinK`).
fn int_bin(e: &Ex) -> Option<(IntOp, &Ex, &Ex)> {
    match &e.kind {
        ExKind::IntBin(op, a, b) if !matches!(b.kind, ExKind::Int(_)) => Some((*op, a, b)),
        _ => None,
    }
}

/// `*slot = v`, a scalar over a scalar written in place (no drop call).
#[inline(always)]
fn set(slot: &mut Value, v: Value) {
    match (slot, v) {
        (Value::Int(y), Value::Int(x)) => *y = x,
        (Value::Real(y), Value::Real(x)) => *y = x,
        (s, v) => value::overwrite(s, v),
    }
}

/// Saves the running thread's registers (see [`Regs`]).
fn save_regs(
    frames: &mut Vec<Frame<'_>>,
    cur: &Code,
    pc: u32,
    current_base: usize,
    pending: Option<Box<Occurrence>>,
    root: Option<(usize, usize)>,
) -> Regs {
    // Each frame's callee is the next frame's code, the last one's the
    // running code.
    let callees: Vec<u32> = frames
        .iter()
        .skip(1)
        .map(|f| f.code.frame)
        .chain([cur.frame])
        .collect();
    Regs {
        frames: frames
            .drain(..)
            .zip(callees)
            .map(|(f, size)| SavedFrame {
                func: f.code.func,
                pc: f.pc,
                current: f.current,
                base: f.base,
                top: f.base + size as usize,
                saved: f.saved,
                fp: f.fp,
                dst: f.dst,
            })
            .collect(),
        cur: cur.func,
        pc,
        current_base,
        pending,
        root,
    }
}

/// Where the call before `pc` (a frame's resume point) is.
fn call_span(code: &Code, pc: u32) -> Span {
    match code.ops.get(pc as usize - 1) {
        Some(Op::Call(.., span) | Op::CallK(_, _, _, _, _, span, _)) => *span,
        Some(Op::ProtEntry(e)) => e.span,
        _ => crate::diag::span(0, 0, 0),
    }
}

/// The arguments and result slot of the call instruction before `pc` (a
/// frame's resume point).
#[inline(always)]
fn call_site(code: &Code, pc: u32) -> (&[Arg], Option<Var>) {
    match code.ops.get(pc as usize - 1) {
        Some(Op::CallK(_, _, _, _, dst, ..)) => (&[], Some(*dst).filter(|d| *d != NO_VAR)),
        Some(Op::Call(func, _, args, ops, _)) => {
            let dst = if *func { ops.last().copied() } else { None };
            (args.as_deref().map_or(&[], |a| a), dst)
        }
        Some(Op::ProtEntry(e)) => (&e.args, None),
        _ => (&[], None),
    }
}

/// What a protected entry call does now.
enum ProtStep {
    /// The barrier is open (or the call was granted): run the body.
    Body,
    /// A conditional call not taken, or a timed one that timed out.
    Other,
    /// Queued: the task waits.
    Wait,
}

/// What is compiled: a body, level-0 statements, or the call of the main
/// subprogram.
enum Compiled<'a> {
    Body(&'a Body),
    Stmts(&'a [Stmt]),
    Main(FuncId),
}

/// Whether a comparison holds for operands ordered `ord`.
fn holds(o: CmpOp, ord: std::cmp::Ordering) -> bool {
    use std::cmp::Ordering::*;
    match o {
        CmpOp::Lt => ord == Less,
        CmpOp::Le => ord != Greater,
        CmpOp::Gt => ord == Greater,
        CmpOp::Ge => ord != Less,
        CmpOp::Eq => ord == Equal,
        CmpOp::Ne => ord != Equal,
    }
}

/// The label by which the end of a body is signalled inside the engine.
const FALL_OFF: u32 = u32::MAX - 1;

#[cfg(test)]
mod size_tests {
    /// A long program's main body is one compiled code (issue 14): an
    /// instruction of 48 bytes, not 64 (a call keeps its result slot among
    /// its operands).
    #[test]
    fn instructions_stay_small() {
        let op = std::mem::size_of::<super::Op>();
        assert!(op <= 48, "{op}");
    }
}

#[cfg(test)]
mod fused_tests {
    use super::{Compiler, Op};

    /// The instructions of the body of `name` in `src` (checked by a bare
    /// checker, without the stdlib, and read as the engine reads a
    /// program: not run). The tests of whole runs are in tests/engine.rs.
    fn ops_of(src: &str, name: &str) -> Vec<String> {
        let checked = crate::check::checked_for_tests(src);
        let prog = checked.program();
        let f = prog
            .funcs
            .iter()
            .find(|f| f.name.eq_ignore_ascii_case(name))
            .expect("the function");
        let body = f.body.as_deref().expect("its body");
        let walker_calls = |_| false;
        let own = f.nslots.max(f.params.len() as u32);
        let mut c = Compiler::new(f.level, own, &walker_calls, prog.types);
        c.body(body);
        let code = c.finish(None, true, true);
        code.ops
            .iter()
            .map(|op| match op {
                Op::CallK(..) => "CallK".to_string(),
                Op::ReturnIntBin(..) => "ReturnIntBin".to_string(),
                Op::Call(..) => "Call".to_string(),
                other => format!("{other:?}"),
            })
            .collect()
    }

    /// `F (N - 1)` and `return X + Y` are one instruction each; an
    /// argument of a constrained subtype (a range check) or a literal
    /// argument is not fused.
    #[test]
    fn a_call_of_x_op_k_and_a_return_of_x_op_y_are_one_instruction() {
        let src = "procedure P is\n\
               function F (N : Integer) return Integer is\n\
               begin\n   if N < 2 then return N; end if;\n   return F (N - 1) + F (N - 2);\nend F;\n\
               function G (N : Natural) return Integer is\n\
               begin\n   if N = 0 then return 0; end if;\n   return G (N - 1) * 2 + F (3);\nend G;\n\
            begin\n   null;\nend P;\n";
        let f = ops_of(src, "F");
        assert_eq!(f.iter().filter(|o| *o == "CallK").count(), 2, "{f:?}");
        assert_eq!(
            f.iter().filter(|o| *o == "ReturnIntBin").count(),
            1,
            "{f:?}"
        );
        assert!(
            !f.iter().any(|o| o == "Call" || o.starts_with("IntBin")),
            "{f:?}"
        );
        // `G (N - 1)` converts to Natural (a range check): a plain call;
        // `... * 2 + F (3)` returns `IntBin` of a temporary and a call.
        let g = ops_of(src, "G");
        assert!(!g.iter().any(|o| o == "CallK"), "{g:?}");
        assert_eq!(g.iter().filter(|o| *o == "Call").count(), 2, "{g:?}");
        assert_eq!(
            g.iter().filter(|o| *o == "ReturnIntBin").count(),
            1,
            "{g:?}"
        );
    }
}
