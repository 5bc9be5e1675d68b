//! The instruction set: one [`Op`] per instruction, its operand structs,
//! and per-instruction metadata. Each instruction is declared once, in the
//! table below, with what the compiler and the loader need to know of it:
//! - `scalar`: whether it puts only scalars (`Int`, `Real`, `Undef`) in
//!   its frame's slots, so that a frame whose code has only such
//!   instructions is freed without looking at its slots (`Code::scalar`);
//! - `jumps`: where its jump targets (and other positions in the code)
//!   are; an instruction without the clause has none. `Op::targets_mut`
//!   visits them to move a compiled part's code (`relocate`) and to patch
//!   a forward jump (`Compiler::patch`). The clause binds the operands
//!   by the instruction's own form: `jumps (_, t) f => {...}` of a tuple,
//!   `jumps { target, .. } f => {...}` of named fields.
//!
//! An instruction with four operands or more names them (`IntBin { op,
//! dst, x, y, span }`); `dst` is the slot written, `x`, `y` the operands
//! read, `k` a literal operand, `span` where a failed check raises.
//!
//! The table makes the enum and those functions: a new instruction cannot
//! be left out of them.

use super::*;

/// Declares [`Op`] from the instruction table, with its metadata functions.
macro_rules! instructions {
    ($(
        $(#[$doc:meta])*
        $name:ident $(( $($ty:ty),* $(,)? ))? $({ $($(#[$fdoc:meta])* $field:ident : $fty:ty),* $(,)? })?
        => scalar: $scalar:literal
        $(, jumps $pat:tt $f:ident => $body:block)?
        ;
    )*) => {
        /// One instruction. Operands are frame slots (`Var`); `Span`s are
        /// where a check that fails raises.
        #[derive(Debug)]
        pub(super) enum Op {
            $( $(#[$doc])* $name $(( $($ty),* ))? $({ $($(#[$fdoc])* $field : $fty),* })? ,)*
        }

        impl Op {
            /// Whether it puts only scalars in its frame's slots (the
            /// table's `scalar`).
            pub(super) fn scalar(&self) -> bool {
                match self {
                    $( Op::$name { .. } => $scalar, )*
                }
            }

            /// Calls `f` on each of its jump targets (the table's `jumps`).
            pub(super) fn targets_mut(&mut self, f: &mut dyn FnMut(&mut u32)) {
                match self {
                    $( $( Op::$name $pat => {
                        let $f = &mut *f;
                        $body
                    } )? )*
                    _ => {}
                }
            }
        }
    };
}

instructions! {
    Int(Var, i64) => scalar: true;
    Real(Var, f64) => scalar: true;
    Move(Var, Var) => scalar: true;
    /// `dst := x op y` of integers (where an overflow or a division by
    /// zero raises: `span`).
    IntBin { op: IntOp, dst: Var, x: Var, y: Var, span: Span } => scalar: true;
    /// `IntBin` with an integer literal on the right.
    IntBinK { op: IntOp, dst: Var, x: Var, k: i64, span: Span } => scalar: true;
    IntNeg(Var, Var, Span) => scalar: true;
    /// An operation of a modular type whose values are `0 ..= last`
    /// (`ir::modular`).
    ModBin {
        op: ModOp,
        dst: Var,
        x: Var,
        y: Var,
        /// The type's last value.
        last: u32,
        span: Span,
    } => scalar: true;
    FloatBin { op: FloatOp, dst: Var, x: Var, y: Var } => scalar: true;
    /// `FloatBin` of `+`, `-`, `*`, `/` (IEEE, as `value::float_op`).
    RealAdd(Var, Var, Var) => scalar: true;
    RealSub(Var, Var, Var) => scalar: true;
    RealMul(Var, Var, Var) => scalar: true;
    RealDiv(Var, Var, Var) => scalar: true;
    ToReal(Var, Var) => scalar: true;
    /// `dst := x op y`, 1 for True and 0 for False.
    Cmp { op: CmpOp, dst: Var, x: Var, y: Var } => scalar: true;
    /// `Cmp` of an integer with an integer literal.
    CmpK { op: CmpOp, dst: Var, x: Var, k: i64 } => scalar: true;
    /// `dst := x = y` of any two values, or `x /= y` (`ne`).
    Eq { ne: bool, dst: Var, x: Var, y: Var } => scalar: true;
    /// `dst := x op y` of two Booleans (both already evaluated).
    Logic { op: LogicOp, dst: Var, x: Var, y: Var } => scalar: true;
    Not(Var, Var) => scalar: true;
    RangeCheck(Var, TypeId, Span) => scalar: true;
    /// The record in the slot has the variant of a component (a
    /// discriminant check, `Run::variant_check`).
    Variant(Var, Variant, Span) => scalar: true;
    /// The value in `x` has the first `n` discriminants of the record in
    /// `record` (`Run::same_discriminants`).
    SameDiscriminants { x: Var, record: Var, n: u32, span: Span } => scalar: true;
    /// `dst := arr (ix...)` for an array held in a slot (three or four
    /// indices; one and two are `Index1`, `Index2`, without an allocation).
    Index { dst: Var, arr: Var, ix: Box<[Var]>, span: Span } => scalar: true;
    Index1 { dst: Var, arr: Var, i: Var, span: Span } => scalar: true;
    Index2 { dst: Var, arr: Var, ix: [Var; 2], span: Span } => scalar: true;
    /// `arr (ix...) := src` (and with one or two indices).
    StoreIndex { arr: Var, ix: Box<[Var]>, src: Var, span: Span } => scalar: true;
    StoreIndex1 { arr: Var, i: Var, src: Var, span: Span } => scalar: true;
    StoreIndex2 { arr: Var, ix: [Var; 2], src: Var, span: Span } => scalar: true;
    /// `dst := record.field` (the component's index), and where its
    /// discriminant check fails.
    Field { dst: Var, record: Var, field: u32, span: Span } => scalar: true;
    /// `dst := ptr.all.field` (a component of the record an access
    /// designates, not a copy of the record); where the access check and
    /// where the discriminant check fails.
    DerefField {
        dst: Var,
        ptr: Var,
        field: u32,
        at_deref: Span,
        at_field: Span,
    } => scalar: true;
    /// `dst := null`.
    Null(Var) => scalar: true;
    /// `dst := "text"`: a string literal's value, made once when the code
    /// is compiled (a copy of it is one reference count: an assignment
    /// into it copies it first).
    Str(Var, Value) => scalar: true;
    /// The value of a static aggregate (literal components, static
    /// bounds): once it is made, `dst := value` and a jump to `end`, past
    /// the instructions that make it; the first time, on to them.
    Cached(Box<CachedOp>) => scalar: false, jumps (c) f => { f(&mut c.end) };
    /// The end of a static aggregate's instructions: its value (in the
    /// slot) is kept by the `Cached` at this index.
    CacheFill(u32, Var) => scalar: false, jumps (at, _) f => { f(at) };
    /// `dst := x & y` (each an array or an element).
    Concat(Box<ConcatOp>) => scalar: true;
    /// `dst := base (low .. high)`, and where its check fails.
    Slice { dst: Var, base: Var, bounds: [Var; 2], span: Span } => scalar: true;
    /// `dst := P'Attr (args)`, the arguments in slots.
    Attr(Box<AttrInstr>) => scalar: true;
    /// `dst := op x` (`Run::unary_of`).
    Un { op: UnOp, dst: Var, x: Var, span: Span } => scalar: true;
    /// `dst := x op y` of two Boolean arrays (`Run::arr_logic`).
    ArrLogic { op: LogicOp, dst: Var, x: Var, y: Var, span: Span } => scalar: true;
    /// `dst := T'First` (false) or `T'Last` (true) of a scalar subtype.
    TypeBound(Var, TypeId, bool) => scalar: true;
    /// `dst :=` the default value of a type without tasks.
    Default(Var, TypeId, Span) => scalar: true;
    /// `dst :=` a device register's value (its address, the value's type).
    Register { dst: Var, addr: u32, ty: TypeId, span: Span } => scalar: true;
    /// An assignment to a component, an element, a slice, a whole array,
    /// through an access value or to a device register (`Run::store`).
    Store(Box<StoreOp>) => scalar: false;
    /// `raise E [with msg];` (`Run::raise_stmt`).
    Raise(ExcId, Option<Var>, Span) => scalar: true;
    /// `raise;` in a handler (`Run::reraise`).
    Reraise(Span) => scalar: true;
    Jump(u32) => scalar: true, jumps (t) f => { f(t) };
    JumpIfNot(Var, u32) => scalar: true, jumps (_, t) f => { f(t) };
    /// `JumpIfNot` of a `CmpK`, in one instruction (`if N < 2 then`).
    CmpKJumpNot { op: CmpOp, x: Var, k: i64, target: u32 } => scalar: true,
        jumps { target, .. } f => { f(target) };
    /// `JumpIfNot` of a `Cmp`.
    CmpJumpNot { op: CmpOp, x: Var, y: Var, target: u32 } => scalar: true,
        jumps { target, .. } f => { f(target) };
    JumpIf(Var, u32) => scalar: true, jumps (_, t) f => { f(t) };
    /// Case: the subject, its choices, the `others` target (None: a
    /// value no choice covers fails the check at `span`).
    Case {
        x: Var,
        /// (low, high, target) of each choice.
        table: Box<[(i64, i64, u32)]>,
        others: Option<u32>,
        span: Span,
    } => scalar: true,
        jumps { table, others, .. } f => {
        table.iter_mut().for_each(|(_, _, t)| f(t));
        others.iter_mut().for_each(f);
    };
    /// First step of a `for` loop: the counter gets `low` (`high` in
    /// `reverse`); an empty range jumps to `exit`.
    ForStart { var: Var, low: Var, high: Var, reverse: bool, exit: u32 } => scalar: true,
        jumps { exit, .. } f => { f(exit) };
    /// Next step: the counter moves on and the loop goes back to `body`,
    /// or it was the last and the loop goes on past this; a step back
    /// polls (`Run::poll`, at `span`).
    ForNext {
        var: Var,
        low: Var,
        high: Var,
        reverse: bool,
        body: u32,
        span: Span,
    } => scalar: true,
        jumps { body, .. } f => { f(body) };
    Poll(Span) => scalar: true;
    /// A call of a subprogram with a body.
    Call {
        /// Whether it is a function (its result's slot is the last operand).
        function: bool,
        f: FuncId,
        /// Where its `out` and `in out` values go when it returns (the
        /// argument's position, the caller's slot: the instructions after
        /// the call check and store them into the actuals; None: all `in`,
        /// or none). Boxed twice, a thin pointer: it keeps `Op` at 48 bytes.
        outs: Option<Box<OutSlots>>,
        /// The arguments' slots, then the slot of a function's result.
        ops: Box<[Var]>,
        span: Span,
    } => scalar: true;
    /// A call of a native subprogram or a robot service, or of one without
    /// a body (Program_Error), its arguments in slots: as `Call`, the
    /// `out` values go to slots that the instructions after it store.
    CallNative(Box<NativeOp>) => scalar: true;
    /// A call whose one argument, `in`, is `x + k` or `x - k` for
    /// integers: the sum `x + add` goes straight into the callee's frame
    /// (`F (N - 1)`: `add` is -1). Then a function's result slot
    /// (`NO_VAR`: a procedure), the call's place and the argument's (in
    /// the call's file).
    CallK {
        f: FuncId,
        x: Var,
        add: i32,
        dst: Var,
        span: Span,
        arg_at: [u32; 2],
    } => scalar: true;
    Return(Option<Var>) => scalar: true;
    /// `return x op y` for integers, the operation and the return in one
    /// instruction (`return F (N - 1) + F (N - 2);`).
    ReturnIntBin { op: IntOp, x: Var, y: Var, span: Span } => scalar: true;
    /// The end of a body: a procedure returns, a function raises.
    FallOff => scalar: true;
    /// Handler dispatch for the pending occurrence: the handlers, the
    /// target of each, and the handler depth of the region. (A handler
    /// that names its occurrence puts it in a slot: the compiler marks
    /// such code as not scalar itself, `Compiler::body`.)
    Dispatch(Box<[Catch]>, u32) => scalar: true,
        jumps (catches, _) f => { catches.iter_mut().for_each(|c| f(&mut c.target)) };
    /// Leaves a handler body: its occurrence is no longer current.
    PopCurrent => scalar: true;
    /// Back to `frame's depth + n` current occurrences (an `exit` out of
    /// handler bodies).
    TruncCurrent(u32) => scalar: true;
    // ---- tasking (see `tasking.rs`) ----
    /// `delay` (false) or `delay until` (true).
    Delay(Var, bool, Span) => scalar: false;
    /// Activates the tasks created so far and waits for their activation.
    Activate(Span) => scalar: false;
    /// A master region begins; its end waits for its tasks.
    MasterEnter => scalar: false;
    MasterLeave(Span) => scalar: false;
    /// An exception leaves a master region: wait for its tasks, then
    /// propagate it.
    MasterUnwind(Span) => scalar: false;
    /// Library-level tasks, at the end of the run: where the main program
    /// ended (a deadlock or a Ctrl-C there names it).
    AwaitAll(Span) => scalar: false;
    /// The end of a REPL entry while tasks live on: the ready tasks run
    /// until every one has blocked.
    Settle => scalar: false;
    /// `accept`: the entry, the member's index, the parameters' slots.
    Accept(Box<AcceptOp>) => scalar: false;
    /// The end of a rendezvous: `out` values go to the caller.
    AcceptEnd(Box<[(Var, Mode)]>) => scalar: false;
    /// An exception leaves an accept body: the caller gets it too.
    AcceptFail => scalar: false;
    /// An entry call of a task.
    EntryCall(Box<EntryOp>) => scalar: false, jumps (e) f => { f(&mut e.other) };
    /// After an entry call: copy-out, the caller's exception, the jump to
    /// a timed call's delay (conditional call's else) statements, or to
    /// the call's `Requeued` when it was requeued.
    EntryDone(Box<DoneOp>) => scalar: false,
        jumps (d) f => {
        d.other.iter_mut().for_each(&mut *f);
        f(&mut d.requeued);
    };
    /// A protected entry call (its body's `out` values go to the
    /// operands, the `EntryDone` after it copies them out).
    ProtEntry(Box<EntryOp>) => scalar: false, jumps (e) f => { f(&mut e.other) };
    /// After a protected action: the object's queues are served.
    ProtDone(Var, Span) => scalar: false;
    Select(Box<SelectOp>) => scalar: false, jumps (sel) f => { sel.targets_mut(f) };
    /// `requeue`: the call being served goes on to another entry.
    Requeue(Box<RequeueOp>) => scalar: false;
    /// A requeued call, made again by its caller on the new entry (see
    /// `RequeuedOp`).
    Requeued(Box<RequeuedOp>) => scalar: false,
        jumps (r) f => {
        r.other.iter_mut().for_each(&mut *f);
        f(&mut r.end);
        f(&mut r.twin);
    };
    /// Never executed: the copy-back of the entry body that the
    /// `Requeued` after it calls (a frame's resume point reads the call
    /// before it, see `call_site`).
    RequeueArgs(OutSlots, Span) => scalar: false;
    Abort(Box<[Var]>) => scalar: false;
    /// `dst := new T` of an access type (`access`) to tasks or to a type
    /// with tasks (`ty`): the tasks are activated by the next instruction
    /// (`Activate`).
    AllocTask { dst: Var, access: TypeId, ty: TypeId, span: Span } => scalar: false;
    /// `dst := new T` of a type without tasks (`Run::allocated_default`).
    AllocDefault { dst: Var, access: TypeId, ty: TypeId, span: Span } => scalar: false;
    /// `dst := new T'(src)` (`Run::allocate`).
    Alloc(Var, Var, Span) => scalar: false;
    /// The bounds of an array aggregate and how many components its
    /// `others` covers, into three slots (`Run::agg_bounds`).
    AggBounds(Box<AggBoundsOp>) => scalar: false;
    /// An array aggregate's value from its parts (`Run::positional_agg`,
    /// `Run::named_agg`).
    ArrayAgg(Box<ArrayAggOp>) => scalar: false;
    /// A record aggregate's value from its components in slots, the
    /// discriminants first (`Run::record_agg`).
    Record(Box<RecordOp>) => scalar: false;
    /// `dst :=` an empty list, which `ListPush` grows: the values of an
    /// aggregate's choice evaluated once per component.
    ListNew(Var) => scalar: false;
    /// Appends the value of the second slot (a temporary, taken) to the
    /// list in the first.
    ListPush(Var, Var) => scalar: false;
    /// `dst :=` the discriminant `i` of the record whose components are
    /// being made (`Run::discriminant`).
    Discriminant(Var, u32, Span) => scalar: false;
    /// The discriminants of a record aggregate being built, in slots, are
    /// put in reach of the next instruction, which reads a subtype that
    /// depends on them; `PopDiscrs` after it takes them away (neither
    /// that instruction nor these can block, so no task runs between).
    PushDiscrs(Box<[Var]>) => scalar: false;
    PopDiscrs => scalar: false;
    /// Program_Error, with its message: an expression the checker found
    /// erroneous, or code that cannot run here (a long body's part
    /// compiled once already, a `requeue` or `exit` whose statement is not
    /// in this code).
    ProgramError(&'static str, Span) => scalar: false;
    /// An access type to tasks is declared: note its master.
    NoteMaster(Var) => scalar: false;
}

/// An entry call: the task (or object), entry, arguments and their
/// operands, the timeout (delay or time) of a timed call, whether it is
/// conditional, and where a timed call's delay statements begin.
#[derive(Debug)]
pub(super) struct EntryOp {
    pub(super) target: Var,
    pub(super) kind: u32,
    pub(super) entry: u32,
    /// The member of a family (of a protected entry: also an operand).
    pub(super) index: Option<Var>,
    pub(super) ops: Box<[Var]>,
    /// A protected entry body's copy-back: its `out` values into the
    /// operands.
    pub(super) back: OutSlots,
    pub(super) timed: Option<(Var, bool)>,
    pub(super) conditional: bool,
    pub(super) other: u32,
    pub(super) span: Span,
}

/// `accept`: the entry, the member of a family, the parameters' slots.
#[derive(Debug)]
pub(super) struct AcceptOp {
    pub(super) entry: u32,
    pub(super) index: Option<Var>,
    pub(super) params: Box<[(Var, Mode)]>,
    pub(super) span: Span,
}

/// After an entry call: its arguments and operands (the parameters'), the
/// timed call's other statements, the call's `Requeued`, whether the
/// operands are copied out (a task's entry; a protected entry body copies
/// its `out` values into them too).
#[derive(Debug)]
pub(super) struct DoneOp {
    pub(super) other: Option<u32>,
    pub(super) requeued: u32,
    pub(super) span: Span,
}

/// `requeue`: the entry (of a task: its value, None for the running
/// task; of a protected object: its value), the family member, `with
/// abort`, whether the entry takes the parameters, and in an accept
/// statement the accept's parameters (their values go to the caller).
#[derive(Debug)]
pub(super) struct RequeueOp {
    pub(super) target: Option<Var>,
    /// The task type, or the protected type.
    pub(super) kind: u32,
    pub(super) prot: bool,
    /// To an entry of the same protected object, named alone.
    pub(super) internal: bool,
    pub(super) entry: u32,
    pub(super) index: Option<Var>,
    pub(super) abort: bool,
    pub(super) params: bool,
    pub(super) accept: Option<Box<[(Var, Mode)]>>,
    pub(super) span: Span,
}

/// A requeued call made again by its caller (see `Thread::requeue`):
/// the call's arguments and the operands of its parameters, the
/// temporaries for a protected body's hidden arguments (object, index),
/// the timed call's other statements, the end of the call, and the twin
/// instruction: two follow each call, one for an entry that takes the
/// parameters and one for an entry without (their `RequeueArgs` differ).
#[derive(Debug)]
pub(super) struct RequeuedOp {
    pub(super) ops: Box<[Var]>,
    pub(super) params: bool,
    pub(super) obj: Var,
    pub(super) index: Var,
    pub(super) other: Option<u32>,
    pub(super) end: u32,
    pub(super) twin: u32,
    pub(super) span: Span,
}

/// A concatenation: where it goes, its operands, whether each is one
/// element (not an array) and whether each is a temporary that the
/// operation may take (its last use), the result's type, where a length
/// check fails.
#[derive(Debug)]
pub(super) struct ConcatOp {
    pub(super) dst: Var,
    pub(super) x: Var,
    pub(super) y: Var,
    pub(super) elems: (bool, bool),
    pub(super) takes: (bool, bool),
    pub(super) ty: TypeId,
    pub(super) span: Span,
}

/// Where a call's `out` values go: (argument position, caller's slot).
pub(super) type OutSlots = Box<[(u32, Var)]>;

/// A named array aggregate's choices: the slots of their ranges' bounds
/// and what each gives.
pub(super) type Choices = Box<[(Box<[[Var; 2]]>, PartOp)]>;

/// `Op::CallNative`: the subprogram, its arguments' slots, where its
/// `out` values go (argument position, slot), the result slot, the call's
/// place.
#[derive(Debug)]
pub(super) struct NativeOp {
    pub(super) f: FuncId,
    pub(super) ops: Box<[Var]>,
    pub(super) outs: OutSlots,
    pub(super) dst: Option<Var>,
    pub(super) span: Span,
}

/// `Op::AggBounds`: the slots for the first dimension's bounds and the
/// number of components `others` covers, the aggregate's type, how many
/// positional components it has, the slots of its named choices' ranges
/// (None: it is positional), and whether it has `others`.
#[derive(Debug)]
pub(super) struct AggBoundsOp {
    pub(super) out: [Var; 3],
    pub(super) ty: TypeId,
    pub(super) items: u32,
    pub(super) ranges: Option<Box<[[Var; 2]]>>,
    pub(super) has_others: bool,
    pub(super) span: Span,
}

/// The slot holding what a choice of an array aggregate gives: one value
/// (copied into each component) or a list of one per component
/// (`Op::ListNew`).
#[derive(Clone, Copy, Debug)]
pub(super) enum PartOp {
    One(Var),
    Each(Var),
}

/// `Op::ArrayAgg`: the result slot, the aggregate's type, the slots
/// `Op::AggBounds` filled, the positional components' slots or the named
/// choices (their ranges' slots and parts), and `others`. Every slot is a
/// temporary, emptied as it is read.
#[derive(Debug)]
pub(super) struct ArrayAggOp {
    pub(super) dst: Var,
    pub(super) ty: TypeId,
    pub(super) bounds: [Var; 3],
    pub(super) items: Box<[Var]>,
    pub(super) choices: Option<Choices>,
    pub(super) others: Option<PartOp>,
    pub(super) span: Span,
}

/// `Op::Record`: the result slot, the record's type, its components'
/// slots (temporaries, emptied as they are read).
#[derive(Debug)]
pub(super) struct RecordOp {
    pub(super) dst: Var,
    pub(super) ty: TypeId,
    /// The type has no discriminants: the components are the record.
    pub(super) plain: bool,
    pub(super) fields: Box<[Var]>,
    pub(super) span: Span,
}

/// An attribute: its operation, result slot, arguments (temporaries are
/// emptied once read), result type and where it fails.
#[derive(Debug)]
pub(super) struct AttrInstr {
    pub(super) op: crate::check::ir::AttrOp,
    pub(super) dst: Var,
    pub(super) args: Box<[Var]>,
    pub(super) temps: Box<[bool]>,
    pub(super) ty: TypeId,
    pub(super) span: Span,
}

/// An assignment's target, its operands in slots: the root, then the steps
/// from the root to the part written, then the value (taken: a temporary).
#[derive(Debug)]
pub(super) struct StoreOp {
    pub(super) root: StoreRoot,
    pub(super) steps: Box<[StoreStep]>,
    pub(super) src: Var,
    pub(super) span: Span,
}

/// Where a [`StoreOp`]'s path begins.
#[derive(Debug)]
pub(super) enum StoreRoot {
    Var(Var),
    /// The object the access value in the slot designates.
    Deref(Var, Span),
    /// A device register: its address and type.
    Register(u32, TypeId, Span),
    NotVariable(Span),
}

/// One step of a [`StoreOp`]'s path.
#[derive(Debug)]
pub(super) enum StoreStep {
    Index(Box<[Var]>, Span),
    Field(u32),
    /// The record has the variant of the component written next.
    Variant(Variant, Span),
    Slice(Var, Var, Span),
}

/// A handler of a dispatch: its exceptions (None: `others`), the slot of
/// its occurrence, where its statements begin.
#[derive(Debug)]
pub(super) struct Catch {
    pub(super) choices: Option<Box<[ExcId]>>,
    pub(super) occurrence: Option<Var>,
    pub(super) target: u32,
}

/// A select's accept alternative.
#[derive(Debug)]
pub(super) struct AcceptAlt {
    /// The guard's value (None: no guard).
    pub(super) guard: Option<Var>,
    pub(super) entry: u32,
    /// The member of an entry family.
    pub(super) index: Option<Var>,
    pub(super) params: Box<[(Var, Mode)]>,
    /// Where the accept's body begins.
    pub(super) target: u32,
}

/// A select's delay alternative.
#[derive(Debug, Clone, Copy)]
pub(super) struct DelayAlt {
    pub(super) guard: Option<Var>,
    /// The duration or time.
    pub(super) amount: Var,
    /// `delay until`.
    pub(super) until: bool,
    /// Where its statements begin.
    pub(super) target: u32,
}

#[derive(Debug)]
pub(super) struct SelectOp {
    pub(super) alts: Vec<AcceptAlt>,
    pub(super) delay: Option<DelayAlt>,
    pub(super) terminate: Option<Option<Var>>,
    pub(super) els: Option<u32>,
    pub(super) span: Span,
}

/// A static aggregate's value, made the first time its code runs (see
/// [`Op::Cached`]). Each run compiles its code afresh, so the value lives
/// as long as the run.
#[derive(Debug)]
pub(super) struct CachedOp {
    pub(super) value: std::cell::OnceCell<Value>,
    pub(super) dst: Var,
    pub(super) end: u32,
}

/// Moves `op`'s jump targets `by` instructions on (a compiled part
/// spliced into its body's code).
pub(super) fn relocate(op: &mut Op, by: u32) {
    op.targets_mut(&mut |t| *t += by);
}

impl SelectOp {
    /// Where its alternatives, its delay's and its `else` statements begin.
    fn targets_mut(&mut self, f: &mut dyn FnMut(&mut u32)) {
        self.alts.iter_mut().for_each(|a| f(&mut a.target));
        if let Some(d) = &mut self.delay {
            f(&mut d.target);
        }
        self.els.iter_mut().for_each(f);
    }
}
