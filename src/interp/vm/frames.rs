//! Call frames of the compiled engine, and the registers of a thread that
//! is not running.

use super::*;

/// The registers of a thread of the engine that is not running. They do
/// not borrow the program: each frame's code is found again by its
/// subprogram (compiled again, identically, in a later run: the REPL keeps
/// tasks between entries), a call's arguments from the call instruction.
#[derive(Clone)]
pub(crate) struct Regs {
    pub(super) frames: Vec<SavedFrame>,
    /// The running code's subprogram (None: the level-0 code).
    pub(super) cur: Option<FuncId>,
    pub(super) pc: u32,
    pub(super) current_base: usize,
    pub(super) pending: Option<Box<Occurrence>>,
    /// A task's own frame (its body): base and top.
    pub(super) root: Option<(usize, usize)>,
}

/// A [`Frame`] saved in [`Regs`].
#[derive(Clone)]
pub(super) struct SavedFrame {
    pub(super) func: Option<FuncId>,
    pub(super) pc: u32,
    pub(super) current: usize,
    /// The callee's frame: base, top, and the display entry it replaced.
    pub(super) base: usize,
    pub(super) top: usize,
    pub(super) saved: usize,
    /// The caller's frame and result slot (see [`Frame`]).
    pub(super) fp: usize,
    pub(super) dst: usize,
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

/// The live registers of the running thread, as the engine's loop holds them
/// (in local variables of the same names).
pub(super) struct Live<'c> {
    /// The callers' frames, innermost last.
    pub(super) frames: Vec<Frame<'c>>,
    /// The running code and the next instruction in it.
    pub(super) cur: &'c Code,
    pub(super) pc: u32,
    /// The first of the running frame's current occurrences.
    pub(super) current_base: usize,
    /// An exception on its way out of the running code.
    pub(super) pending: Option<Box<Occurrence>>,
    /// A task's own frame (its body): base and top.
    pub(super) root: Option<(usize, usize)>,
}

/// A call in progress in the compiled engine: what its return goes back
/// to. The rest of the call is found without storing it: the callee (its
/// subprogram, level, frame size, whether it has `out` parameters) is the
/// code that runs until the return, and the arguments and result slot are
/// in the call instruction before `pc` (see [`call_site`]).
pub(crate) struct Frame<'c> {
    /// The caller's code and where it goes on when the callee returns.
    pub(super) code: &'c Code,
    pub(super) pc: u32,
    /// Current occurrences when the callee was entered.
    pub(super) current: usize,
    /// The display entry of the callee's level that the call replaced.
    /// (Where the callee's frame begins is not kept: it is the callee's
    /// display entry while the callee runs, `Run::frame_base`.)
    pub(super) saved: usize,
    /// Where the caller's own frame begins, and the stack slot a
    /// function's result goes to (`NO_DST`: none, or the copy-back path):
    /// a return finds both without the display or the call instruction.
    pub(super) fp: usize,
    pub(super) dst: usize,
}

/// [`Frame::dst`] of a call whose result, if any, is not put by the
/// quick return.
pub(super) const NO_DST: usize = usize::MAX;

/// No operand (`Op::CallK` of a procedure).
pub(super) const NO_VAR: Var = Var {
    level: u16::MAX,
    slot: u32::MAX,
};

/// The arguments of a call: in slots of the caller, or one integer.
#[derive(Clone, Copy)]
pub(super) enum Args<'x> {
    Slots(&'x [Var]),
    Int(i64),
}

/// A called frame just set up: the callee's code, where its frame begins,
/// and the display entry it replaced.
pub(super) type Entered<'c> = (&'c Code, usize, usize);

/// The compiled bodies of a run, each compiled on its subprogram's first
/// call. A body stays where it is while others are added, so the engine
/// holds plain references to them.
pub(crate) struct Codes<'c> {
    pub(super) arena: &'c typed_arena::Arena<Code>,
    pub(super) by_func: Vec<Option<&'c Code>>,
    /// The code of the type table's expressions (see `eval_table`), by
    /// where the expression is.
    pub(super) table: std::collections::HashMap<TableKey, &'c Code>,
    /// Emptied lists of frames, live and saved, kept for the next switch
    /// between threads (see [`Run::save_regs`]): a rendezvous allocates
    /// no frame list.
    pub(super) spare_frames: Vec<Frame<'c>>,
    pub(super) spare_saved: Vec<SavedFrame>,
}

/// The key of a type table expression's code (see `Run::eval_table`):
/// where the expression is, and (against an address used again by another
/// expression) its place in the source.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub(super) struct TableKey {
    pub(super) ex: *const Ex,
    pub(super) span: Span,
}

impl<'c> Codes<'c> {
    pub(crate) fn new(arena: &'c typed_arena::Arena<Code>) -> Codes<'c> {
        Codes {
            arena,
            by_func: Vec::new(),
            table: std::collections::HashMap::new(),
            spare_frames: Vec::new(),
            spare_saved: Vec::new(),
        }
    }
}

impl<'a, 'c> Run<'a, 'c> {
    /// Pushes the frame of a call of `f` whose arguments are in `ops`.
    #[inline(always)]
    pub(super) fn push_call(
        &mut self,
        f: FuncId,
        args: Args<'_>,
        (lvl, fp): (u16, usize),
        span: Span,
    ) -> R<Entered<'c>> {
        self.call_guard(span)?;
        let code = self.code_of(f);
        let base = self.m.stack.len();
        // The arguments go straight into the new frame; the display is
        // still the caller's while they are read (an operand of the
        // caller's own frame, at `lvl`, begins at `fp`).
        let ops = match args {
            Args::Slots(ops) => ops,
            Args::Int(n) => {
                // The one argument and the frame in one step.
                let own = (code.frame - code.temps) as usize;
                self.m.stack.open_frame_int(n, own, code.frame as usize);
                return Ok(self.enter_display(code, base));
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
        Ok(self.enter_display(code, base))
    }

    /// The display entry of a called frame that begins at `base`, and the
    /// call's depth: what [`Self::push_call`] does once the frame is there.
    #[inline(always)]
    fn enter_display(&mut self, code: &'c Code, base: usize) -> Entered<'c> {
        let level = code.level as usize;
        if self.m.display.len() <= level {
            self.m.display.resize(level + 1, 0);
        }
        let saved = std::mem::replace(&mut self.m.display[level], base);
        self.m.depth += 1;
        (code, base, saved)
    }

    /// Live registers from saved ones: each frame's code compiled (or
    /// taken from this run's cache) again.
    pub(super) fn load_regs(&mut self, level0: &'c Code, r: Regs) -> Live<'c> {
        let fetch = |this: &mut Self, func: Option<FuncId>| match func {
            Some(f) => this.code_of(f),
            None => level0,
        };
        let mut frames = std::mem::take(&mut self.codes.spare_frames);
        frames.clear();
        let mut saved = r.frames;
        for sf in saved.drain(..) {
            frames.push(Frame {
                code: fetch(self, sf.func),
                pc: sf.pc,
                current: sf.current,
                saved: sf.saved,
                fp: sf.fp,
                dst: sf.dst,
            });
        }
        self.codes.spare_saved = saved;
        let cur = fetch(self, r.cur);
        Live {
            frames,
            cur,
            pc: r.pc,
            current_base: r.current_base,
            pending: r.pending,
            root: r.root,
        }
    }

    /// Saves the running thread's registers (see [`Regs`]); `frames` is
    /// left empty. The lists are the spares of the last switch.
    pub(super) fn save_regs(
        &mut self,
        frames: &mut Vec<Frame<'c>>,
        cur: &Code,
        pc: u32,
        current_base: usize,
        pending: Option<Box<Occurrence>>,
        root: Option<(usize, usize)>,
    ) -> Regs {
        let mut saved = std::mem::take(&mut self.codes.spare_saved);
        saved.clear();
        // Each frame's callee is the next frame's code, whose frame begins
        // where the next frame's caller's does; the last one's is the
        // running code, whose frame its level's display entry gives.
        let running = (
            self.m.display.get(cur.level as usize).copied().unwrap_or(0),
            cur.frame,
        );
        for (i, f) in frames.iter().enumerate() {
            let (base, size) = frames
                .get(i + 1)
                .map_or(running, |next| (next.fp, next.code.frame));
            saved.push(SavedFrame {
                func: f.code.func,
                pc: f.pc,
                current: f.current,
                base,
                top: base + size as usize,
                saved: f.saved,
                fp: f.fp,
                dst: f.dst,
            });
        }
        frames.clear();
        std::mem::swap(frames, &mut self.codes.spare_frames);
        Regs {
            frames: saved,
            cur: cur.func,
            pc,
            current_base,
            pending,
            root,
        }
    }

    /// Where the frame of `callee`, a called subprogram's code that is
    /// running or was left by a raise, begins: its level's display entry,
    /// which its call set and its return restores.
    #[inline(always)]
    pub(super) fn frame_base(&self, callee: &Code) -> usize {
        self.m.display[callee.level as usize]
    }

    /// Leaves the frame of a call to `callee`: its slots, display entry,
    /// depth, and the occurrences it made current (back to
    /// `entry`, their number when it was entered); no copy-out.
    #[inline(always)]
    pub(super) fn pop_frame(&mut self, f: &Frame<'_>, callee: &Code, entry: usize) {
        let base = self.frame_base(callee);
        let top = base + callee.frame as usize;
        if callee.scalar && self.m.sched.holes.is_empty() && top >= self.m.stack.len() {
            self.m.stack.truncate_scalars(base);
        } else {
            self.free_frame(base, top);
        }
        self.m.display[callee.level as usize] = f.saved;
        self.m.depth -= 1;
        // (Tested first: `truncate` calls the drop glue on an empty tail.)
        if self.m.current.len() > entry {
            self.m.current.truncate(entry);
        }
    }
}

/// Where the call before `pc` (a frame's resume point) is.
pub(super) fn call_span(code: &Code, pc: u32) -> Span {
    match code.ops.get(pc as usize - 1) {
        Some(Op::Call { span, .. } | Op::CallK { span, .. }) => *span,
        Some(Op::ProtEntry(e)) => e.span,
        Some(Op::RequeueArgs(_, span)) => *span,
        _ => crate::diag::span(0, 0, 0),
    }
}

/// Where the `out` values and the result of the call instruction before
/// `pc` (a frame's resume point) go.
#[inline(always)]
pub(super) fn call_site(code: &Code, pc: u32) -> (&[(u32, Var)], Option<Var>) {
    match code.ops.get(pc as usize - 1) {
        Some(Op::CallK { dst, .. }) => (&[], Some(*dst).filter(|d| *d != NO_VAR)),
        Some(Op::Call {
            function,
            outs,
            ops,
            ..
        }) => {
            let dst = if *function { ops.last().copied() } else { None };
            (outs.as_deref().map_or(&[], |a| a), dst)
        }
        Some(Op::ProtEntry(e)) => (&e.back, None),
        Some(Op::RequeueArgs(back, _)) => (back, None),
        _ => (&[], None),
    }
}
