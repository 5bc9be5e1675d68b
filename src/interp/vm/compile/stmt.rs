//! Compiling statements: assignments, control flow, loops, case, blocks.

use super::*;

impl<'r> Compiler<'r> {
    pub(in crate::interp::vm) fn stmts(&mut self, ss: &[Stmt]) {
        for s in ss {
            let mark = self.ntemp;
            self.stmt(s);
            self.ntemp = mark;
        }
    }

    pub(in crate::interp::vm) fn stmt(&mut self, s: &Stmt) {
        match &s.kind {
            StmtKind::Null => {}
            StmtKind::Init(v, e) => self.expr_into(e, *v),
            // An array target keeps its bounds (`Run::store` checks the
            // length and slides).
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
                        [i] => Op::StoreIndex1 {
                            arr,
                            i,
                            src,
                            span: t.span,
                        },
                        [i, j] => Op::StoreIndex2 {
                            arr,
                            ix: [i, j],
                            src,
                            span: t.span,
                        },
                        _ => Op::StoreIndex {
                            arr,
                            ix: ix.into(),
                            src,
                            span: t.span,
                        },
                    });
                }
                _ => {
                    let src = self.temp();
                    self.expr_into(e, src);
                    self.store(t, src);
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
                self.end_loop();
            }
            StmtKind::While { id, cond, body } => {
                let top = self.here();
                let j = self.jump_unless(cond);
                self.ops.push(Op::Poll(s.span));
                self.loop_body(*id, body);
                self.ops.push(Op::Jump(top));
                let end = self.end_loop();
                self.patch(j, end);
            }
            StmtKind::For(f) => {
                let (l, h) = (self.temp(), self.temp());
                self.expr_into(&f.lo, l);
                self.expr_into(&f.hi, h);
                let start = self.ops.len();
                self.ops.push(Op::ForStart {
                    var: f.var,
                    low: l,
                    high: h,
                    reverse: f.reverse,
                    exit: 0,
                });
                let body_pc = self.here();
                self.loop_body(f.id, &f.body);
                self.ops.push(Op::ForNext {
                    var: f.var,
                    low: l,
                    high: h,
                    reverse: f.reverse,
                    body: body_pc,
                    span: s.span,
                });
                let end = self.end_loop();
                self.patch(start, end);
            }
            StmtKind::Exit(id, cond) => {
                let Some(k) = self.loops.iter().rposition(|l| l.id == *id) else {
                    self.ops.push(Op::ProgramError(
                        "an exit outside the loop it leaves",
                        s.span,
                    ));
                    return;
                };
                let skip = cond.as_ref().map(|c| self.jump_unless(c));
                let depth = self.loops[k].hdepth;
                if depth < self.hdepth {
                    self.ops.push(Op::TruncCurrent(depth));
                }
                for _ in self.loops[k].masters..self.masters {
                    self.ops.push(Op::MasterLeave(s.span));
                }
                let j = self.ops.len();
                self.ops.push(Op::Jump(0));
                self.loops[k].exits.push(j);
                if let Some(j) = skip {
                    let next = self.here();
                    self.patch(j, next);
                }
            }
            StmtKind::Return(Some(e)) if self.masters == 0 && int_bin(e).is_some() => {
                let (op, a, b) = int_bin(e).expect("an integer operation");
                let x = self.left(a, b);
                let y = self.expr(b);
                self.ops.push(Op::ReturnIntBin {
                    op,
                    x,
                    y,
                    span: e.span,
                });
            }
            StmtKind::Return(v) => {
                let x = v.as_ref().map(|e| self.expr(e));
                for _ in 0..self.masters {
                    self.ops.push(Op::MasterLeave(s.span));
                }
                self.ops.push(Op::Return(x));
            }
            StmtKind::Block(b) => self.body(b),
            StmtKind::Raise(e, msg) => {
                let m = msg.as_ref().map(|m| self.expr(m));
                self.ops.push(Op::Raise(*e, m, s.span));
            }
            StmtKind::Reraise => self.ops.push(Op::Reraise(s.span)),
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
                debug_assert!(other.is_empty());
            }
            StmtKind::TimedCall(tc) => {
                let amount = tc.delay.as_ref().map(|(until, d)| (self.expr(d), *until));
                let at = self.entry_call(&tc.call, amount, tc.delay.is_none(), s.span);
                self.stmts(&tc.then);
                let j = self.ops.len();
                self.ops.push(Op::Jump(0));
                let other = self.here();
                for at in at {
                    self.set_other(at, other);
                }
                self.stmts(&tc.other);
                let end = self.here();
                self.patch(j, end);
            }
            StmtKind::ProtCall(f, args) => {
                self.call(*f, Some(args), None, s.span);
                let obj = self.expr(&args.last().expect("the object").value);
                self.ops.push(Op::ProtDone(obj, s.span));
            }
            StmtKind::Select(sel) => self.select(sel, s.span),
            StmtKind::Requeue(r) => self.requeue(r, s.span),
            StmtKind::Compiled(p) => {
                match p.take::<Part>() {
                    Some(part) => self.splice(part),
                    // Compiled once already: it cannot run again.
                    None => self.ops.push(Op::ProgramError(
                        "this part of a long body was compiled for one run of the compiled engine",
                        s.span,
                    )),
                }
            }
            StmtKind::Abort(ts) => {
                let ops: Vec<Var> = ts.iter().map(|t| self.expr(t)).collect();
                self.ops.push(Op::Abort(ops.into()));
            }
        }
    }

    /// A `case` (statement or expression) on `x`: a jump table to each
    /// alternative, compiled by `each`, and from each to the end.
    pub(in crate::interp::vm) fn case<T>(
        &mut self,
        x: Var,
        span: Span,
        arms: &[(Vec<(i64, i64)>, T)],
        others: Option<&T>,
        mut each: impl FnMut(&mut Self, &T),
    ) {
        let at = self.ops.len();
        self.ops.push(Op::Case {
            x,
            table: Box::new([]),
            others: None,
            span,
        });
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
        self.ops[at] = Op::Case {
            x,
            table: table.into(),
            others: other,
            span,
        };
    }

    /// `t := src`, `src` a temporary: a scalar or record variable is moved
    /// into, any other target stored (see [`Self::store`]).
    pub(in crate::interp::vm) fn assign_from(&mut self, t: &Ex, src: Var) {
        match t.kind {
            ExKind::Var(v) if !self.is_array(t.ty) => self.ops.push(Op::Move(v, src)),
            _ => self.store(t, src),
        }
    }

    /// `t := src` for a target with a path (components, elements,
    /// slices, `.all`, a register) or a whole array: the operands of the
    /// path are evaluated after the value, from the part written back to
    /// the root (GNAT's order), then `Run::store` writes.
    pub(in crate::interp::vm) fn store(&mut self, t: &Ex, src: Var) {
        // The path, from the part written to the root.
        let mut path = Vec::new();
        let mut e = t;
        while let ExKind::Index(p, _)
        | ExKind::Field(p, _)
        | ExKind::Variant(p, _)
        | ExKind::Slice(p, _) = &e.kind
        {
            path.push(e);
            e = p;
        }
        // Its operands in the order they are evaluated.
        let mut operands: Vec<&Ex> = Vec::new();
        for step in &path {
            match &step.kind {
                ExKind::Index(_, idx) => operands.extend(idx.iter()),
                ExKind::Slice(_, lh) => operands.extend(lh.iter()),
                _ => {}
            }
        }
        if let ExKind::Deref(p) = &e.kind {
            operands.push(p);
        }
        let vars: Vec<Var> = (0..operands.len())
            .map(|k| self.operand_before(operands[k], operands[k + 1..].iter().copied()))
            .collect();
        let mut next = vars.into_iter();
        let mut steps = Vec::with_capacity(path.len());
        for step in &path {
            if let ExKind::Variant(p, i) = &step.kind {
                if let Some(conds) = self.variant_of(p.ty, *i) {
                    steps.push(StoreStep::Variant(conds, step.span));
                }
                continue;
            }
            steps.push(match &step.kind {
                ExKind::Index(_, idx) => {
                    StoreStep::Index(next.by_ref().take(idx.len()).collect(), step.span)
                }
                ExKind::Slice(..) => {
                    let (l, h) = (next.next(), next.next());
                    match (l, h) {
                        (Some(l), Some(h)) => StoreStep::Slice(l, h, step.span),
                        _ => unreachable!("a slice has two bounds"),
                    }
                }
                ExKind::Field(_, i) => StoreStep::Field(*i),
                _ => unreachable!("a step of the path"),
            });
        }
        steps.reverse();
        let root = match &e.kind {
            ExKind::Var(v) => StoreRoot::Var(*v),
            ExKind::Deref(_) => match next.next() {
                Some(p) => StoreRoot::Deref(p, e.span),
                None => unreachable!("the access value"),
            },
            ExKind::Register(a) => StoreRoot::Register(*a, e.ty, e.span),
            _ => StoreRoot::NotVariable(e.span),
        };
        self.ops.push(Op::Store(Box::new(StoreOp {
            root,
            steps: steps.into(),
            src,
            span: t.span,
        })));
    }

    pub(in crate::interp::vm) fn loop_body(&mut self, id: u32, body: &[Stmt]) {
        self.loops.push(OpenLoop {
            id,
            exits: Vec::new(),
            hdepth: self.hdepth,
            masters: self.masters,
        });
        self.stmts(body);
    }

    /// Ends the innermost loop: its exits jump here. Returns the target.
    pub(in crate::interp::vm) fn end_loop(&mut self) -> u32 {
        let end = self.here();
        let l = self.loops.pop().expect("a loop");
        for j in l.exits {
            self.patch(j, end);
        }
        end
    }
}
