//! Runs of the engine nested in an instruction: the scheduler's calls of
//! barriers, and the expressions of the type table (defaults, dynamic
//! bounds, discriminant constraints, a task's priority), which the
//! declarations, allocators and aggregates that need them evaluate.

use super::*;

impl<'a, 'c> Run<'a, 'c> {
    /// Calls `f` with the argument values `args` in a run of the engine
    /// of its own, nested in the running instruction, and gives its
    /// result: the scheduler's call of a barrier (a function of the
    /// protected object, see `barrier_open`). The call cannot block: a
    /// potentially blocking operation in it is `Program_Error` (RM 9.5.1).
    pub(super) fn call_nested(
        &mut self,
        f: FuncId,
        args: impl IntoIterator<Item = Value>,
        span: Span,
    ) -> R<Option<Value>> {
        let code = self.code_of(f);
        match self.run_nested(code, args, span)? {
            Some(v) => Ok(Some(v)),
            None if self.c.funcs[f as usize].ret.is_none() => Ok(None),
            None => {
                let sub = &self.c.funcs[f as usize];
                Err(self.raise(
                    check::PROGRAM_ERROR,
                    format!("{} missing return", self.m.location(sub.span)),
                    sub.span,
                ))
            }
        }
    }

    /// The value of an expression of the type table, by its compiled code
    /// (compiled on its first use in the run).
    pub(crate) fn eval_table(&mut self, e: &Ex) -> R<Value> {
        match e.kind {
            ExKind::Int(n) => return Ok(Value::Int(n)),
            ExKind::Real(x) => return Ok(Value::Real(x)),
            _ => {}
        }
        // By where the expression is, and (against an address used again
        // by another expression) its place in the source.
        let key = TableKey {
            ex: e as *const Ex,
            span: e.span,
        };
        let code = match self.codes.table.get(&key) {
            Some(code) => *code,
            None => {
                // Its own level, above every subprogram's: the expression
                // reads the variables of the scopes it is in by the display.
                let level = self.c.funcs.iter().map(|f| f.level).max().unwrap_or(0) + 1;
                let natives = |f: FuncId| self.native_call(f);
                let mut c = Compiler::new(level, 0, &natives, self.c.types);
                let t = c.temp();
                c.expr_into(e, t);
                c.ops.push(Op::Return(Some(t)));
                let code: &'c Code = self.codes.arena.alloc(c.finish(None, true, false));
                self.codes.table.insert(key, code);
                code
            }
        };
        Ok(self.run_nested(code, [], e.span)?.unwrap_or_default())
    }

    /// Runs `code` (a body, or an expression's code) in a frame of its own
    /// whose first slots are `args`, to its return (`Some`: its value).
    fn run_nested(
        &mut self,
        code: &'c Code,
        args: impl IntoIterator<Item = Value>,
        span: Span,
    ) -> R<Option<Value>> {
        self.call_guard(span)?;
        let level = code.level as usize;
        let base = self.m.stack.len();
        for v in args {
            self.m.stack.push(v);
        }
        let own = (code.frame - code.temps) as usize;
        let top = base + code.frame as usize;
        self.m.stack.grow_to_clearing(base + own, top);
        if self.m.display.len() <= level {
            self.m.display.resize(level + 1, 0);
        }
        let saved = self.m.display[level];
        self.m.display[level] = base;
        self.m.depth += 1;
        let r = self.exec_loop(code, true);
        self.free_frame(base, top);
        self.m.display[level] = saved;
        self.m.depth -= 1;
        match r {
            Err(Flow::Return(v)) => Ok(v),
            Err(Flow::Raise(o)) => Err(self.caller_error(o, span)),
            Err(e) => Err(e),
            Ok(()) => Ok(None),
        }
    }
}
