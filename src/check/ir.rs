//! The checked program: every name resolved to a slot, a subprogram index,
//! a type id or a builtin; every operator to its typed form. The interpreter
//! runs this and never looks a name up by string.

use super::PVec;
use super::types::TypeId;
use crate::diag::Span;
use crate::syntax::ast::Mode;
use std::any::Any;
use std::rc::Rc;

pub type FuncId = u32;
pub type ExcId = u32;

/// A variable: the static nesting level of the frame that owns it and its
/// slot in that frame. Level 0 holds library-level (and script) objects.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Var {
    pub level: u16,
    pub slot: u32,
}

#[derive(Clone, Debug)]
pub struct Ex {
    pub kind: ExKind,
    pub ty: TypeId,
    pub span: Span,
}

impl Ex {
    pub fn int(v: i64) -> Ex {
        Ex {
            kind: ExKind::Int(v),
            ty: super::types::UNIV_INT,
            span: Span {
                start: 0,
                end: 0,
                context: 0,
            },
        }
    }

    pub fn real(v: f64) -> Ex {
        Ex {
            kind: ExKind::Real(v),
            ..Ex::int(0)
        }
        .with_type(super::types::UNIV_REAL)
    }

    fn with_type(mut self, t: super::types::TypeId) -> Ex {
        self.ty = t;
        self
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IntOp {
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    Rem,
    Pow,
}

/// The operations of a modular type (RM 4.5.1, 4.5.3, 4.5.4, 4.5.5,
/// 4.5.6): the unary `-` is `0 - X`, `not X` is `(N - 1) - X`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ModOp {
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    Rem,
    /// `X ** N`, N a Natural.
    Pow,
    And,
    Or,
    Xor,
}

/// `x op y` for a modular type whose values are `0 ..= last`: the result
/// reduced modulo `last + 1` (a logical operator works bit by bit, then
/// subtracts the modulus once if the result passed it, RM 4.5.1(6)).
/// `None`: a division by zero (`Constraint_Error`), or a negative
/// exponent. The one place modular arithmetic is defined: the checker's
/// static folding and both engines call it.
pub fn modular(op: ModOp, x: i64, y: i64, last: u32) -> Option<i64> {
    let n = last as i128 + 1;
    let (a, b) = (x as i128, y as i128);
    let r = match op {
        ModOp::Add => a + b,
        ModOp::Sub => a - b,
        ModOp::Mul => a * b,
        ModOp::Div => a.checked_div(b)?,
        // Both operands are in 0 .. N - 1: `mod` and `rem` agree.
        ModOp::Mod | ModOp::Rem => a.checked_rem(b)?,
        ModOp::Pow => {
            if b < 0 {
                return None;
            }
            let (mut base, mut e, mut acc) = (a.rem_euclid(n), b, 1 % n);
            while e > 0 {
                if e & 1 == 1 {
                    acc = acc * base % n;
                }
                base = base * base % n;
                e >>= 1;
            }
            acc
        }
        ModOp::And => a & b,
        ModOp::Or => a | b,
        ModOp::Xor => a ^ b,
    };
    Some(r.rem_euclid(n) as i64)
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FloatOp {
    Add,
    Sub,
    Mul,
    Div,
    /// Float ** Integer
    PowI,
    /// Duration / Integer (the integer as a real): GNAT's fixed point
    /// quotient, truncated toward zero to whole nanoseconds.
    DurDiv,
    /// `+`, `-`, `*` and `/` of Duration (and `Time_Span`) values: the
    /// result is a whole number of nanoseconds, as GNAT's fixed point
    /// Duration (`Duration'Small` = 1 ns) holds it, so `0.03 - 0.02 = 0.01`
    /// is True. A conversion to Duration from another real type is a
    /// `DurMul` by 1.0.
    DurAdd,
    DurSub,
    DurMul,
    DurQuo,
}

impl FloatOp {
    /// The Duration form of a real operation.
    pub fn on_duration(self) -> FloatOp {
        match self {
            FloatOp::Add => FloatOp::DurAdd,
            FloatOp::Sub => FloatOp::DurSub,
            FloatOp::Mul => FloatOp::DurMul,
            FloatOp::Div => FloatOp::DurQuo,
            other => other,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CmpOp {
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LogicOp {
    And,
    Or,
    Xor,
    AndThen,
    OrElse,
}

/// Attributes evaluated at run time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AttrOp {
    /// `A'First (N)`, `A'Last (N)`, `A'Length (N)` on an array value.
    ArrFirst(u8),
    ArrLast(u8),
    ArrLength(u8),
    /// `T'Image (X)` for the given scalar type kind.
    ImageInt,
    /// `T'Image` of a floating point type of this many digits.
    ImageFloat(u8),
    /// `Duration'Image`: fixed point with 9 decimals, as GNAT.
    ImageDuration,
    ImageEnum(TypeId),
    ImageChar,
    /// `T'Value (S)`
    ValueInt,
    ValueFloat,
    ValueEnum(TypeId),
    Succ,
    Pred,
    Min,
    Max,
    FloatMin,
    FloatMax,
    /// `T'Val (N)` with a range check against T.
    Val,
    /// `T'Pos (X)`
    Pos,
    /// Float'Floor etc.
    Floor,
    Ceiling,
    Truncation,
    Rounding,
    /// Discriminant `i` of a task value (`Controller.Axis`).
    TaskDiscriminant(u32),
    /// `T'Callable`, `T'Terminated` of a task value.
    Callable,
    Terminated,
    /// `E'Count` of an entry of the running task (a member of a family:
    /// the index is the argument).
    Count(u32),
    /// `E'Count` of an entry of a protected object (the first argument; a
    /// member of a family: the index is the second).
    ProtCount(u32),
}

#[derive(Clone, Debug)]
pub enum ExKind {
    Int(i64),
    Real(f64),
    /// A constant composite value (string literals).
    Str(Rc<str>),
    Null,
    Var(Var),
    /// Array component: prefix, indices.
    Index(Box<Ex>, Box<Vec<Ex>>),
    /// One-dimensional slice.
    Slice(Box<Ex>, Box<[Ex; 2]>),
    Field(Box<Ex>, u32),
    /// The record value of the prefix, once its component `i` is known to
    /// exist (the record's discriminants choose its variant, else
    /// `Constraint_Error`): the prefix of a `Field` of a variant, read or
    /// written.
    Variant(Box<Ex>, u32),
    Deref(Box<Ex>),
    /// `[value, target, when]`: the value of an assignment to an object
    /// constrained by its initial value or by its actual; when `when` is
    /// True, its discriminants must be those of the target's value
    /// (`Constraint_Error` otherwise).
    KeepDiscriminants(Box<[Ex; 3]>),
    Call(FuncId, Box<[Arg]>),
    IntBin(IntOp, Box<Ex>, Box<Ex>),
    /// An operation of the modular type `Ex::ty` (its modulus is in the
    /// type table): see [`modular`].
    ModBin(ModOp, Box<Ex>, Box<Ex>),
    FloatBin(FloatOp, Box<Ex>, Box<Ex>),
    /// Comparison of scalars (integers and enumeration positions, or floats).
    Cmp(CmpOp, Box<Ex>, Box<Ex>),
    /// Equality of any values (composites compared component-wise).
    Eq(bool, Box<Ex>, Box<Ex>),
    Logic(LogicOp, Box<Ex>, Box<Ex>),
    Not(Box<Ex>),
    /// `and`, `or`, `xor` of two one-dimensional Boolean arrays, component
    /// by component (the left operand's bounds; lengths must agree).
    ArrLogic(LogicOp, Box<Ex>, Box<Ex>),
    /// `not` of a one-dimensional Boolean array.
    ArrNot(Box<Ex>),
    IntNeg(Box<Ex>),
    FloatNeg(Box<Ex>),
    IntAbs(Box<Ex>),
    FloatAbs(Box<Ex>),
    /// Array concatenation (`&`); the flags say whether each side is one element.
    Concat(Box<Ex>, Box<Ex>, bool, bool),
    IntToFloat(Box<Ex>),
    FloatToInt(Box<Ex>),
    /// Checks that a scalar lies in the range of the type (`Constraint_Error`).
    RangeCheck(Box<Ex>, TypeId),
    /// Converts an array value to a constrained array subtype: checks the length
    /// and slides the bounds.
    ArrayConvert(Box<Ex>, TypeId),
    Attr(AttrOp, Box<Vec<Ex>>),
    /// `T'First`/`T'Last` of a scalar subtype: evaluated from the type table.
    TypeFirst(TypeId),
    TypeLast(TypeId),
    /// Membership in ranges, subtypes and values (each choice: low, high;
    /// a value is the range V .. V); the flag is `not in`.
    InRanges(Box<Ex>, Box<Vec<(Ex, Ex)>>, bool),
    ArrayAgg(Box<ArrayAgg>),
    RecordAgg(Box<[Ex]>),
    If(Box<Vec<(Ex, Ex)>>, Box<Ex>),
    /// The subject, the choices (static ranges) and values, `others`.
    Case(Box<CaseEx>),
    Alloc(Option<Box<Ex>>, TypeId),
    /// The default initial value of a type (records with defaults, arrays of them).
    Default(TypeId),
    /// Reads the current exception occurrence of a handler.
    Error,
    /// Discriminant `i` of the record value being built, in a record
    /// type's component subtypes and defaults (`Data : String (1 .. Size)`):
    /// the engines evaluate these while they build a value of the type.
    Discriminant(u32),
    /// A device register (`for X use at Addr;`): reads see the device,
    /// assignments reach it. Its type is an integer type or an array
    /// `(0 .. 15) of Boolean` (bit I is element I).
    Register(u32),
}

impl Ex {
    /// Whether `f` holds for this expression or one inside it.
    pub fn any(&self, f: &dyn Fn(&Ex) -> bool) -> bool {
        if f(self) {
            return true;
        }
        let all = |es: &mut dyn Iterator<Item = &Ex>| {
            for e in es {
                if e.any(f) {
                    return true;
                }
            }
            false
        };
        match &self.kind {
            ExKind::Int(_)
            | ExKind::Real(_)
            | ExKind::Str(_)
            | ExKind::Null
            | ExKind::Var(_)
            | ExKind::TypeFirst(_)
            | ExKind::TypeLast(_)
            | ExKind::Default(_)
            | ExKind::Error
            | ExKind::Register(_)
            | ExKind::Discriminant(_) => false,
            ExKind::Index(p, idx) => p.any(f) || all(&mut idx.iter()),
            ExKind::KeepDiscriminants(parts) => all(&mut parts.iter()),
            ExKind::Slice(p, lh) => p.any(f) || all(&mut lh.iter()),
            ExKind::Field(a, _)
            | ExKind::Variant(a, _)
            | ExKind::Deref(a)
            | ExKind::Not(a)
            | ExKind::ArrNot(a)
            | ExKind::IntNeg(a)
            | ExKind::FloatNeg(a)
            | ExKind::IntAbs(a)
            | ExKind::FloatAbs(a)
            | ExKind::IntToFloat(a)
            | ExKind::FloatToInt(a)
            | ExKind::RangeCheck(a, _)
            | ExKind::ArrayConvert(a, _) => a.any(f),
            ExKind::Call(_, args) => all(&mut args.iter().map(|a| &a.value)),
            ExKind::IntBin(_, a, b)
            | ExKind::ModBin(_, a, b)
            | ExKind::FloatBin(_, a, b)
            | ExKind::Cmp(_, a, b)
            | ExKind::Eq(_, a, b)
            | ExKind::Logic(_, a, b)
            | ExKind::ArrLogic(_, a, b)
            | ExKind::Concat(a, b, ..) => a.any(f) || b.any(f),
            ExKind::Attr(_, args) => all(&mut args.iter()),
            ExKind::InRanges(s, rs, _) => s.any(f) || all(&mut rs.iter().flat_map(|(l, h)| [l, h])),
            ExKind::ArrayAgg(agg) => match &agg.kind {
                ArrayAggKind::Positional(items, others) => {
                    all(&mut items.iter()) || others.as_ref().is_some_and(|o| o.any(f))
                }
                ArrayAggKind::Named(items, others) => {
                    items
                        .iter()
                        .any(|(rs, v)| v.any(f) || rs.iter().any(|(l, h)| l.any(f) || h.any(f)))
                        || others.as_ref().is_some_and(|o| o.any(f))
                }
            },
            ExKind::RecordAgg(fields) => all(&mut fields.iter()),
            ExKind::If(arms, els) => arms.iter().any(|(c, v)| c.any(f) || v.any(f)) || els.any(f),
            ExKind::Case(c) => {
                let (s, arms, others) = &**c;
                s.any(f)
                    || arms.iter().any(|(_, v)| v.any(f))
                    || others.as_ref().is_some_and(|o| o.any(f))
            }
            ExKind::Alloc(init, _) => init.as_ref().is_some_and(|i| i.any(f)),
        }
    }
}

/// Whether an expression reads a discriminant of the record being built.
pub fn reads_discriminant(e: &Ex) -> bool {
    e.any(&|x| matches!(x.kind, ExKind::Discriminant(_)))
}

/// A `case` expression: subject, (choice ranges, value) arms, `others`.
pub type CaseEx = (Ex, Vec<(Vec<(i64, i64)>, Ex)>, Option<Ex>);

/// An array aggregate, with the array type that fixes its bounds.
#[derive(Clone, Debug)]
pub struct ArrayAgg {
    pub ty: TypeId,
    pub kind: ArrayAggKind,
}

#[derive(Clone, Debug)]
pub enum ArrayAggKind {
    /// Positional components, then an optional `others` value.
    Positional(Vec<Ex>, Option<Box<Ex>>),
    /// Named choices (ranges of indices) and an optional `others`.
    Named(Vec<(Vec<(Ex, Ex)>, Ex)>, Option<Box<Ex>>),
}

#[derive(Clone, Debug)]
pub struct Arg {
    pub mode: Mode,
    pub value: Ex,
    /// Range check applied when copying an `out` value back into the actual.
    pub back_check: Option<TypeId>,
}

#[derive(Clone, Debug)]
pub struct Stmt {
    pub kind: StmtKind,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub enum StmtKind {
    Null,
    /// Initialises a fresh variable (declaration elaboration).
    Init(Var, Ex),
    Assign(Ex, Ex),
    Call(FuncId, Box<[Arg]>),
    If(Vec<(Ex, Vec<Stmt>)>, Vec<Stmt>),
    Case(Ex, CaseArms, Option<Vec<Stmt>>),
    Loop {
        id: u32,
        body: Vec<Stmt>,
    },
    While {
        id: u32,
        cond: Ex,
        body: Vec<Stmt>,
    },
    For(Box<ForLoop>),
    Exit(u32, Option<Ex>),
    Return(Option<Ex>),
    Block(Box<Body>),
    Raise(ExcId, Option<Ex>),
    Reraise,
    /// `delay D;` or `delay until T;` (true): seconds, or a time.
    Delay(bool, Ex),
    /// The `begin` of a declarative part that may have created tasks:
    /// activates them and waits for their activation; in a task body it
    /// also tells the task's activator that its own activation is done.
    Activate,
    /// A declarative region that may create tasks: its end waits for them
    /// (their master).
    Master(Box<Body>),
    /// The declaration of an access type to tasks: the slot records the
    /// master its allocators' tasks belong to (the enclosing region).
    NoteMaster(Var),
    Accept(Box<Accept>),
    EntryCall(Box<EntryCall>),
    /// A protected procedure called from outside the object: the call, then
    /// the object's entry queues are served (the last argument is the object).
    ProtCall(FuncId, Box<[Arg]>),
    Select(Box<Select>),
    /// A timed (`or delay`) or conditional (`else`) entry call.
    TimedCall(Box<TimedCall>),
    /// `requeue E [with abort];` in an accept statement or an entry body.
    Requeue(Box<Requeue>),
    Abort(Vec<Ex>),
    /// The statements of a long body, compiled by the engine a part at a
    /// time as they were checked (see [`PartCompiler`]); their checked
    /// form is gone.
    Compiled(Precompiled),
}

/// Compiles the checked statements of a part of a long body for the
/// compiled engine as soon as the checker has made them, so that a long
/// program's checked form is never held whole (issue 14: memory per
/// source byte). The part's code is added to the body's code so far;
/// returns how many temporaries it uses (slots the checker reserves for
/// it, above the body's slots so far).
pub type PartCompiler = fn(ProgramRef<'_>, PartAt, Vec<Stmt>, &Precompiled) -> u32;

/// Where a part of a long body is compiled: the body's level, its number
/// of slots so far (the part's temporaries go above them), and whether the
/// body is a master (its `return`s leave that region).
#[derive(Clone, Copy, Debug)]
pub struct PartAt {
    pub level: u16,
    pub own: u32,
    pub master: bool,
}

/// The code of a long body's compiled parts, in one list, opaque to the
/// checker: the checker makes the slot and keeps it in the body
/// (`StmtKind::Compiled`), the engine adds each part's code to it
/// ([`Precompiled::fill`]) and takes the code out when it compiles the body
/// ([`Precompiled::take`]). A body made of parts is compiled once (a second
/// compilation finds the code gone, and running it raises Program_Error).
/// The checker never names the engine's code type: the engine is the layer
/// above it (tests/layering.rs).
#[derive(Clone, Default)]
pub struct Precompiled(Rc<std::cell::RefCell<Slot>>);

/// What a [`Precompiled`] holds.
#[derive(Default)]
enum Slot {
    /// No code yet.
    #[default]
    Empty,
    /// The engine's code so far.
    Filled(Box<dyn Any>),
    /// Taken out by the engine's compilation of the body.
    Taken,
}

impl Precompiled {
    /// No code yet.
    pub fn new() -> Precompiled {
        Precompiled::default()
    }

    /// Runs `f` on the code so far (a `T::default()` at first); `None`
    /// once the code has been taken out. `T` is the engine's code type,
    /// the same at every call.
    pub fn fill<T: Any + Default, R>(&self, f: impl FnOnce(&mut T) -> R) -> Option<R> {
        let mut slot = self.0.borrow_mut();
        if let Slot::Empty = *slot {
            *slot = Slot::Filled(Box::new(T::default()));
        }
        let Slot::Filled(code) = &mut *slot else {
            return None;
        };
        let code = code
            .downcast_mut::<T>()
            .expect("a Precompiled holds one code type");
        Some(f(code))
    }

    /// Takes the code out, once: the code so far (a `T::default()` when no
    /// part was added), then `None`.
    pub fn take<T: Any + Default>(&self) -> Option<T> {
        match std::mem::replace(&mut *self.0.borrow_mut(), Slot::Taken) {
            Slot::Empty => Some(T::default()),
            Slot::Filled(code) => Some(
                *code
                    .downcast::<T>()
                    .expect("a Precompiled holds one code type"),
            ),
            Slot::Taken => None,
        }
    }
}

impl std::fmt::Debug for Precompiled {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Precompiled")
    }
}

/// A `for` loop: its id (for `exit`), counter, bounds, direction, body.
#[derive(Clone, Debug)]
pub struct ForLoop {
    pub id: u32,
    pub var: Var,
    pub lo: Ex,
    pub hi: Ex,
    pub reverse: bool,
    pub body: Vec<Stmt>,
}

/// `accept E (params) do body end E;`: the entry of the enclosing task's
/// type, and the slots of its parameters in the task body's frame.
#[derive(Clone, Debug)]
pub struct Accept {
    pub entry: u32,
    /// The member of an entry family (a value of the family's subtype).
    pub index: Option<Ex>,
    pub params: Vec<(Var, Mode)>,
    pub body: Option<Body>,
}

/// An entry call: of a task (the task value) or of a protected object (the
/// object, last among the arguments; the index of a family member just
/// before it, as the entry body takes them).
#[derive(Clone, Debug)]
pub struct EntryCall {
    pub target: CallTarget,
    pub args: Vec<Arg>,
    /// The member of an entry family (a value of its subtype; of a
    /// protected entry it is also the argument before the object).
    pub index: Option<Ex>,
}

/// `requeue E [with abort];`: the running call goes on to entry E, whose
/// caller stays blocked until E's call completes (RM 9.5.4).
#[derive(Clone, Debug)]
pub struct Requeue {
    pub target: RequeueTarget,
    /// The member of an entry family (a value of its subtype).
    pub index: Option<Ex>,
    /// `with abort`: a timed call's timeout may still cancel it.
    pub abort: bool,
    /// E takes the parameters of the call (false: E has none).
    pub params: bool,
    /// In an accept statement: the accept's parameters (their values go to
    /// the caller first), the statement ends; None: in a protected entry
    /// body, which returns.
    pub accept: Option<Vec<(Var, Mode)>>,
}

#[derive(Clone, Debug)]
pub enum RequeueTarget {
    /// An entry of a task (None: of the running task).
    Task {
        task: Option<Ex>,
        ttype: u32,
        entry: u32,
    },
    /// An entry of a protected object (the object's value); `internal`: of
    /// the object whose entry body requeues, named by the entry alone (the
    /// call joins its queue within the protected action, RM 9.5.4(13)).
    Prot {
        obj: Ex,
        prot: u32,
        entry: u32,
        internal: bool,
    },
}

#[derive(Clone, Debug)]
pub enum CallTarget {
    Task { task: Ex, ttype: u32, entry: u32 },
    Prot { prot: u32, entry: u32 },
}

#[derive(Clone, Debug)]
pub struct Select {
    pub alts: Vec<(Option<Ex>, Accept, Vec<Stmt>)>,
    /// `or delay [until] D; stmts`, with its guard.
    pub delay: Option<(Option<Ex>, bool, Ex, Vec<Stmt>)>,
    /// `or terminate;`, with its guard.
    pub terminate: Option<Option<Ex>>,
    pub els: Option<Vec<Stmt>>,
}

#[derive(Clone, Debug)]
pub struct TimedCall {
    pub call: EntryCall,
    pub then: Vec<Stmt>,
    /// The delay (until?, duration or time) and its statements; `None`: the
    /// conditional call's `else`.
    pub delay: Option<(bool, Ex)>,
    pub other: Vec<Stmt>,
}

/// A task type (a single task is an object of an anonymous one).
#[derive(Clone, Debug)]
pub struct TaskDef {
    pub name: String,
    /// Its discriminants (RM 9.1): the body's parameters.
    pub discriminants: Vec<super::types::Field>,
    pub entries: Vec<EntryDef>,
    /// The task body: a subprogram without parameters, one level below the
    /// type's declaration.
    pub body: Option<FuncId>,
    pub priority: Option<Ex>,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub struct EntryDef {
    pub name: String,
    /// The profile (a subprogram without body), for calls.
    pub profile: FuncId,
    /// `for E use at Addr;`: an interrupt entry.
    pub interrupt: Option<i64>,
    pub family: Option<Family>,
    /// Its first queue among the task's (see [`Family`]).
    pub first: u32,
}

/// The index range of an entry family: its subtype and static bounds. A
/// task or protected object has one queue of callers per entry and per
/// member of a family, numbered in the order of declaration (an entry's
/// `first` queue, then one per member from the low bound up).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Family {
    pub ty: TypeId,
    pub lo: i64,
    pub hi: i64,
}

impl Family {
    /// How many members (queues) it has.
    pub fn len(&self) -> u32 {
        u32::try_from((self.hi - self.lo + 1).max(0)).unwrap_or(u32::MAX)
    }

    pub fn is_empty(&self) -> bool {
        self.hi < self.lo
    }
}

/// The queues of entries laid out from their `first` and family: how
/// many, and which entry (and family index) queue `q` belongs to.
pub fn queue_count(entries: impl DoubleEndedIterator<Item = (u32, Option<Family>)>) -> usize {
    entries.last().map_or(0, |(first, f)| {
        first as usize + f.map_or(1, |f| f.len() as usize)
    })
}

pub fn queue_member(
    entries: impl Iterator<Item = (u32, Option<Family>)>,
    q: u32,
) -> Option<(usize, Option<i64>)> {
    entries.enumerate().find_map(|(i, (first, f))| match f {
        None if first == q => Some((i, None)),
        Some(f) if q >= first && q - first < f.len() => {
            Some((i, Some(f.lo + i64::from(q - first))))
        }
        _ => None,
    })
}

impl TaskDef {
    pub fn queues(&self) -> usize {
        queue_count(self.entries.iter().map(|e| (e.first, e.family)))
    }

    /// The entry and family index of queue `q`.
    pub fn member(&self, q: u32) -> Option<(usize, Option<i64>)> {
        queue_member(self.entries.iter().map(|e| (e.first, e.family)), q)
    }
}

impl ProtDef {
    pub fn queues(&self) -> usize {
        queue_count(self.entries.iter().map(|e| (e.first, e.family)))
    }

    /// The entry and family index of queue `q`.
    pub fn member(&self, q: u32) -> Option<(usize, Option<i64>)> {
        queue_member(self.entries.iter().map(|e| (e.first, e.family)), q)
    }
}

/// A protected type. Its value is an access to a record whose first
/// component is the object's number and the rest its components; every
/// operation takes the object as a last, hidden parameter.
#[derive(Clone, Debug)]
pub struct ProtDef {
    pub name: String,
    /// The record of the components (hidden number first).
    pub rec: TypeId,
    /// The access to it: the type of every operation's object parameter.
    pub access: TypeId,
    pub entries: Vec<ProtEntry>,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub struct ProtEntry {
    pub name: String,
    pub profile: FuncId,
    /// A function of the object only (of a family: of the index, then the
    /// object); and the body (parameters, the index of a family, object).
    pub barrier: Option<FuncId>,
    pub body: Option<FuncId>,
    pub family: Option<Family>,
    /// Its first queue among the object's (see [`Family`]).
    pub first: u32,
}

/// The alternatives of a `case`: static choice ranges and statements.
pub type CaseArms = Vec<(Vec<(i64, i64)>, Vec<Stmt>)>;

/// Statements with exception handlers.
#[derive(Clone, Debug)]
pub struct Body {
    pub stmts: Vec<Stmt>,
    pub handlers: Vec<Handler>,
}

#[derive(Clone, Debug)]
pub struct Handler {
    /// `None` = `others`.
    pub choices: Option<Vec<ExcId>>,
    pub occurrence: Option<Var>,
    pub stmts: Vec<Stmt>,
}

#[derive(Clone, Debug)]
pub struct Param {
    pub name: String,
    pub mode: Mode,
    pub ty: TypeId,
    pub default: Option<Ex>,
}

#[derive(Clone, Debug)]
pub struct Subprogram {
    pub name: String,
    pub params: Vec<Param>,
    pub ret: Option<TypeId>,
    pub level: u16,
    pub nslots: u32,
    pub body: Option<Rc<Body>>,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub struct Exception {
    /// Full upper-case name as GNAT prints it (`MAIN.GRIPPER_JAM`).
    pub name: String,
}

/// The checked program as the interpreter sees it: the checker's tables,
/// read-only (subprograms, their import names, types, exceptions, the
/// number of level-0 slots). The interpreter gets this view and never the
/// `Checker` itself.
#[derive(Clone, Copy)]
pub struct ProgramRef<'a> {
    pub funcs: &'a PVec<Subprogram>,
    pub imports: &'a PVec<Option<String>>,
    pub types: &'a crate::check::types::Types,
    pub excs: &'a PVec<Exception>,
    pub globals: u32,
    pub tasks: &'a PVec<TaskDef>,
    pub prots: &'a PVec<ProtDef>,
}

/// A whole checked program (or one REPL entry against kept state).
#[derive(Clone, Debug, Default)]
pub struct Program {
    /// Statements elaborating and running the library level (level 0).
    pub main: Vec<Stmt>,
    /// Number of level-0 slots.
    pub globals: u32,
}

#[cfg(test)]
mod tests {
    use super::{ModOp, modular};

    /// Modular arithmetic as GNAT computes it (checked against a GNAT
    /// program, tests/ada/modular_register.adb): wrap-around, `not` and
    /// the logical operators of a modulus that is not a power of two.
    #[test]
    fn modular_operations_wrap() {
        let last16 = u16::MAX as u32;
        assert_eq!(modular(ModOp::Add, 65535, 1, last16), Some(0));
        assert_eq!(modular(ModOp::Sub, 0, 1, last16), Some(65535));
        assert_eq!(modular(ModOp::Mul, 200, 3, 255), Some(88));
        assert_eq!(modular(ModOp::Pow, 3, 7, 255), Some(139));
        assert_eq!(modular(ModOp::Div, 5, 0, 255), None);
        assert_eq!(modular(ModOp::Rem, 5, 0, 255), None);
        // mod 10: 7 xor 9 = 14, less the modulus once.
        assert_eq!(modular(ModOp::Xor, 7, 9, 9), Some(4));
        assert_eq!(modular(ModOp::Or, 7, 2, 9), Some(7));
        // mod 2**32: no overflow on the way.
        let last32 = u32::MAX;
        assert_eq!(
            modular(ModOp::Mul, last32 as i64, last32 as i64, last32),
            Some(1)
        );
        assert_eq!(
            modular(ModOp::Pow, last32 as i64, 5, last32),
            Some(last32 as i64)
        );
    }

    /// A long program's checked statements are held whole until it runs
    /// (issue 14, at most 20 bytes of memory per source byte): an
    /// expression of 40 bytes takes a 48-byte heap block (one of 48 took
    /// 64), a statement holds an assignment's two expressions inline and
    /// boxes anything bigger.
    #[test]
    fn checked_nodes_stay_small() {
        use std::mem::size_of;
        assert!(size_of::<super::Ex>() <= 40, "{}", size_of::<super::Ex>());
        assert!(
            size_of::<super::Stmt>() <= 104,
            "{}",
            size_of::<super::Stmt>()
        );
    }
}
