//! Compiling bodies on their first call, and starting a run.

use super::*;

impl<'a, 'c> Run<'a, 'c> {
    /// Whether the calls of `f` go to a native (bound to one, or no body).
    pub(super) fn native_call(&self, f: FuncId) -> bool {
        self.m.natives.get(f as usize).copied().flatten().is_some()
            || self.c.funcs[f as usize].body.is_none()
    }

    pub(super) fn compile(
        &self,
        level: u16,
        own: u32,
        what: Compiled<'a>,
        func: Option<FuncId>,
    ) -> Code {
        let native_calls = |f: FuncId| self.native_call(f);
        let mut c = Compiler::new(level, own, &native_calls, self.c.types);
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
    pub(super) fn code_of(&mut self, f: FuncId) -> &'c Code {
        match self.codes.by_func.get(f as usize) {
            Some(Some(c)) => c,
            _ => self.compile_first(f),
        }
    }

    /// [`Self::code_of`] the first time.
    #[cold]
    #[inline(never)]
    pub(super) fn compile_first(&mut self, f: FuncId) -> &'c Code {
        let i = f as usize;
        if self.codes.by_func.len() <= i {
            self.codes
                .by_func
                .resize(self.c.funcs.len().max(i + 1), None);
        }
        if let Some(c) = self.codes.by_func[i] {
            return c;
        }
        let sub = &self.c.funcs[i];
        let own = sub.nslots.max(sub.params.len() as u32);
        let code: &'c Code = match sub.body.as_deref() {
            Some(body) => {
                self.codes
                    .arena
                    .alloc(self.compile(sub.level, own, Compiled::Body(body), Some(f)))
            }
            // A call compiled with a long body's part (see `compile_part`)
            // of a subprogram that has no body: `call_native` raises.
            None => self.codes.arena.alloc(Code {
                func: Some(f),
                all_in: true,
                scalar: false,
                quick: false,
                level: sub.level,
                ops: vec![
                    Op::CallNative(Box::new(NativeOp {
                        f,
                        ops: Box::new([]),
                        outs: Box::new([]),
                        dst: None,
                        span: sub.span,
                    })),
                    Op::FallOff,
                ],
                temps: 0,
                frame: own,
                regions: Vec::new(),
            }),
        };
        self.codes.by_func[i] = Some(code);
        code
    }

    /// Runs level-0 statements, then the main subprogram, in the compiled
    /// engine.
    pub(crate) fn run_compiled(&mut self, stmts: &'a [Stmt], main: Option<FuncId>) -> R<()> {
        let own = self.c.globals;
        for (a, t) in std::mem::take(&mut self.m.pending_irqs) {
            self.deliver(a, t);
        }
        let code = self
            .codes
            .arena
            .alloc(self.compile(0, own, Compiled::Stmts(stmts), None));
        let mut r = self.exec_code(code);
        if r.is_ok()
            && let Some(f) = main
        {
            let code = self
                .codes
                .arena
                .alloc(self.compile(0, own, Compiled::Main(f), None));
            r = self.exec_code(code);
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
            let code = self.codes.arena.alloc(Code {
                func: None,
                all_in: true,
                scalar: false,
                quick: false,
                level: 0,
                ops: vec![last, Op::FallOff],
                temps: 0,
                frame: 0,
                regions: Vec::new(),
            });
            let sched_cur = self.m.sched.cur;
            debug_assert_eq!(sched_cur, 0);
            self.exec_code(code)?;
        }
        r
    }

    /// Where the main program ends, where the environment waits for the
    /// library-level tasks: the end of the main subprogram's body, or of
    /// the script's last statement (never the predefined library's text).
    pub(super) fn program_end(&self, stmts: &[Stmt], main: Option<FuncId>) -> Span {
        let last = match main.and_then(|f| self.c.funcs[f as usize].body.as_ref()) {
            Some(b) => b.stmts.last().map(|s| s.span),
            None => stmts.last().map(|s| s.span),
        };
        last.map_or(crate::diag::span(0, 0, 0), |sp| Span {
            start: sp.end,
            ..sp
        })
    }

    /// Whether this instruction runs a second time (after its thread was
    /// blocked by it); clears the mark.
    pub(super) fn rerun(&mut self) -> bool {
        self.m.sched.active() && std::mem::take(&mut self.m.sched.me().rerun)
    }
}
