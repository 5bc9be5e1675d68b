//! The compiler from checked statements and expressions to instructions.
//! By concern: `expr.rs`, `stmt.rs`, `calls.rs`, `rendezvous.rs`.

use super::*;

mod agg;
mod calls;
mod expr;
mod rendezvous;
mod stmt;

/// A loop being compiled.
pub(in crate::interp::vm) struct OpenLoop {
    pub(in crate::interp::vm) id: u32,
    /// The jumps to patch with the loop's exit.
    pub(in crate::interp::vm) exits: Vec<usize>,
    /// The handler depth and the master regions open at the loop.
    pub(in crate::interp::vm) hdepth: u32,
    pub(in crate::interp::vm) masters: u32,
}

pub(in crate::interp::vm) struct Compiler<'r> {
    pub(in crate::interp::vm) level: u16,
    pub(in crate::interp::vm) own: u32,
    pub(in crate::interp::vm) ntemp: u32,
    pub(in crate::interp::vm) max_temp: u32,
    pub(in crate::interp::vm) ops: Vec<Op>,
    pub(in crate::interp::vm) regions: Vec<Region>,
    /// The loops being compiled, innermost last.
    pub(in crate::interp::vm) loops: Vec<OpenLoop>,
    pub(in crate::interp::vm) hdepth: u32,
    /// Master regions open at this point of the code.
    pub(in crate::interp::vm) masters: u32,
    /// The accept bodies being compiled: the jumps of their `requeue`s to
    /// the end of the accept statement, the handler depth and the master
    /// regions open at the accept.
    pub(in crate::interp::vm) accepts: Vec<(Vec<usize>, u32, u32)>,
    /// Which subprograms are called as natives (bound to one, or without body).
    pub(in crate::interp::vm) native_calls: &'r dyn Fn(FuncId) -> bool,
    pub(in crate::interp::vm) types: &'r crate::check::types::Types,
    /// Every value this code puts in its frame is a scalar (`Undef`, `Int`,
    /// `Real`) so far: freeing the frame drops nothing (see `Code::scalar`).
    pub(in crate::interp::vm) scalar: bool,
    /// The slots of the discriminants of the record aggregates being
    /// compiled, innermost last: their components read them.
    pub(in crate::interp::vm) discrs: Vec<Box<[Var]>>,
    /// A static aggregate's instructions are being compiled: the
    /// aggregates inside it are made with it, not cached again.
    pub(in crate::interp::vm) caching: bool,
}

/// True when evaluating `e` may run a call or other code with effects
/// (so that an operand read before it must be copied first).
pub(in crate::interp::vm) fn effects(e: &Ex) -> bool {
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
        | ExKind::Variant(a, _)
        | ExKind::Field(a, _) => eff(a),
        ExKind::Index(p, idx) => eff(p) || idx.iter().any(eff),
        ExKind::Concat(a, b, ..) | ExKind::ArrLogic(_, a, b) => eff(a) || eff(b),
        ExKind::ArrNot(a) => eff(a),
        _ => true,
    }
}

impl<'r> Compiler<'r> {
    /// A compiler for code at `level` whose own slots are below `own`.
    pub(in crate::interp::vm) fn new(
        level: u16,
        own: u32,
        native_calls: &'r dyn Fn(FuncId) -> bool,
        types: &'r crate::check::types::Types,
    ) -> Self {
        Compiler {
            level,
            own,
            ntemp: 0,
            max_temp: 0,
            ops: Vec::new(),
            regions: Vec::new(),
            loops: Vec::new(),
            hdepth: 0,
            masters: 0,
            accepts: Vec::new(),
            native_calls,
            types,
            scalar: true,
            discrs: Vec::new(),
            caching: false,
        }
    }

    /// The variant component `i` of the record type `t` belongs to.
    pub(in crate::interp::vm) fn variant_of(&self, t: TypeId, i: u32) -> Option<Variant> {
        self.types
            .fields(t)
            .and_then(|f| f.get(i as usize))
            .and_then(|f| f.variant.clone())
    }

    /// Whether an access type designates a task (its allocator activates it).
    pub(in crate::interp::vm) fn has_task(&self, t: TypeId) -> bool {
        self.types
            .designated(t)
            .is_some_and(|d| self.types.has_task(d))
    }

    /// Whether a type is an array type (an assignment to it keeps the
    /// target's bounds).
    pub(in crate::interp::vm) fn is_array(&self, t: TypeId) -> bool {
        self.types.array(t).is_some()
    }

    /// A value of type `t` goes into this code's frame.
    pub(in crate::interp::vm) fn holds(&mut self, t: TypeId) {
        if !self.types.is_scalar(t) {
            self.scalar = false;
        }
    }

    pub(in crate::interp::vm) fn temp(&mut self) -> Var {
        let v = Var {
            level: self.level,
            slot: self.own + self.ntemp,
        };
        self.ntemp += 1;
        self.max_temp = self.max_temp.max(self.ntemp);
        v
    }

    pub(in crate::interp::vm) fn is_temp(&self, v: Var) -> bool {
        v.level == self.level && v.slot >= self.own
    }

    pub(in crate::interp::vm) fn here(&self) -> u32 {
        self.ops.len() as u32
    }

    /// Sets the jump target of the instruction at `at`, an instruction
    /// with one (a forward jump, emitted before its target was known).
    pub(in crate::interp::vm) fn patch(&mut self, at: usize, target: u32) {
        let mut n = 0;
        self.ops[at].targets_mut(&mut |t| {
            *t = target;
            n += 1;
        });
        debug_assert_eq!(n, 1, "only an instruction with one target is patched");
    }

    pub(in crate::interp::vm) fn body(&mut self, b: &Body) {
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
            // A handler's occurrence is a value of its own in a slot.
            self.scalar &= h.occurrence.is_none();
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
    pub(in crate::interp::vm) fn splice(&mut self, part: Part) {
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
    }

    /// The compiled code; `scalar_params`: its parameters' types are
    /// scalar.
    pub(in crate::interp::vm) fn finish(
        mut self,
        func: Option<FuncId>,
        all_in: bool,
        scalar_params: bool,
    ) -> Code {
        self.ops.push(Op::FallOff);
        // Only what the engine itself puts in slots is known: natives
        // and the tasking instructions may put anything there.
        let scalar = scalar_params && self.scalar && self.ops.iter().all(|op| op.scalar());
        // Exact sizes: the main body of a long program is compiled once.
        self.ops.shrink_to_fit();
        self.regions.shrink_to_fit();
        Code {
            func,
            all_in,
            scalar,
            quick: all_in && scalar,
            level: self.level,
            ops: self.ops,
            temps: self.max_temp,
            frame: self.own + self.max_temp,
            regions: self.regions,
        }
    }
}

/// The operation and operands of `e` when it is an integer operation whose
/// right side is not a literal (those are `IntBinK`).
pub(in crate::interp::vm) fn int_bin(e: &Ex) -> Option<(IntOp, &Ex, &Ex)> {
    match &e.kind {
        ExKind::IntBin(op, a, b) if !matches!(b.kind, ExKind::Int(_)) => Some((*op, a, b)),
        _ => None,
    }
}
