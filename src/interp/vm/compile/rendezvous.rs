//! Compiling accept, entry calls and select.

use super::*;

impl<'r> Compiler<'r> {
    /// Compiles `inner` as a region whose normal end runs `leave` and
    /// whose exceptions go to `unwind` (which propagates them).
    pub(in crate::interp::vm) fn guarded(
        &mut self,
        inner: impl FnOnce(&mut Self),
        leave: Op,
        unwind: Op,
    ) {
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
    pub(in crate::interp::vm) fn accept(&mut self, a: &Accept, span: Span) {
        let index = a.index.as_ref().map(|x| self.expr(x));
        self.ops.push(Op::Accept(Box::new(AcceptOp {
            entry: a.entry,
            index,
            params: a.params.as_slice().into(),
            span,
        })));
        self.accept_rest(a);
    }

    pub(in crate::interp::vm) fn accept_rest(&mut self, a: &Accept) {
        match &a.body {
            Some(b) => {
                self.accepts.push((Vec::new(), self.hdepth, self.masters));
                self.guarded(
                    |c| c.body(b),
                    Op::AcceptEnd(a.params.as_slice().into()),
                    Op::AcceptFail,
                );
                // A `requeue` ends the accept statement here.
                let (jumps, ..) = self.accepts.pop().expect("the accept");
                let after = self.here();
                for j in jumps {
                    self.patch(j, after);
                }
            }
            None => self.ops.push(Op::AcceptEnd(a.params.as_slice().into())),
        }
    }

    /// `requeue`: in an accept statement, the accept ends (its handlers
    /// and master regions are left); in a protected entry body, the body
    /// returns.
    pub(in crate::interp::vm) fn requeue(&mut self, r: &Requeue, span: Span) {
        let (target, kind, prot, entry, internal) = match &r.target {
            RequeueTarget::Task { task, ttype, entry } => (
                task.as_ref().map(|t| self.expr(t)),
                *ttype,
                false,
                *entry,
                false,
            ),
            RequeueTarget::Prot {
                obj,
                prot,
                entry,
                internal,
            } => (Some(self.expr(obj)), *prot, true, *entry, *internal),
        };
        let index = r.index.as_ref().map(|x| self.expr(x));
        let op = Op::Requeue(Box::new(RequeueOp {
            target,
            kind,
            prot,
            internal,
            entry,
            index,
            abort: r.abort,
            params: r.params,
            accept: r.accept.as_deref().map(Box::from),
            span,
        }));
        match &r.accept {
            Some(_) => {
                let Some(&(_, depth, masters)) = self.accepts.last() else {
                    self.ops.push(Op::ProgramError(
                        "a requeue outside the accept statement it ends",
                        span,
                    ));
                    return;
                };
                if depth < self.hdepth {
                    self.ops.push(Op::TruncCurrent(depth));
                }
                for _ in masters..self.masters {
                    self.ops.push(Op::MasterLeave(span));
                }
                self.ops.push(op);
                let j = self.ops.len();
                self.ops.push(Op::Jump(0));
                if let Some(a) = self.accepts.last_mut() {
                    a.0.push(j);
                }
            }
            None => {
                for _ in 0..self.masters {
                    self.ops.push(Op::MasterLeave(span));
                }
                self.ops.push(op);
                self.ops.push(Op::Return(None));
            }
        }
    }

    /// An entry call; returns the instructions whose `other` target (timed
    /// and conditional calls) is to be set.
    pub(in crate::interp::vm) fn entry_call(
        &mut self,
        ec: &EntryCall,
        timed: Option<(Var, bool)>,
        conditional: bool,
        span: Span,
    ) -> Vec<usize> {
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
        // The parameters' arguments and operands (a protected entry's
        // index and object follow them).
        let n = match &ec.target {
            CallTarget::Task { .. } => ops.len(),
            CallTarget::Prot { .. } => ops.len() - 1 - usize::from(ec.index.is_some()),
        };
        let is_timed = timed.is_some() || conditional;
        let mut others = Vec::new();
        let index = match (&ec.target, &ec.index) {
            (CallTarget::Task { .. }, Some(x)) => {
                let t = self.temp();
                self.expr_into(x, t);
                Some(t)
            }
            (CallTarget::Prot { .. }, Some(_)) => Some(ops[n]),
            (_, None) => None,
        };
        let back = out_slots(&ec.args[..n], &ops[..n]);
        match &ec.target {
            CallTarget::Task { .. } => {
                self.ops.push(Op::EntryCall(Box::new(EntryOp {
                    target,
                    kind,
                    entry,
                    index,
                    ops: ops.clone().into(),
                    back: Box::new([]),
                    timed,
                    conditional,
                    other: 0,
                    span,
                })));
            }
            CallTarget::Prot { .. } => {
                let obj = *ops.last().expect("the object");
                if is_timed {
                    others.push(self.ops.len());
                }
                self.ops.push(Op::ProtEntry(Box::new(EntryOp {
                    target: obj,
                    kind,
                    entry,
                    index,
                    ops: ops.clone().into(),
                    back,
                    timed,
                    conditional,
                    other: 0,
                    span,
                })));
                self.ops.push(Op::ProtDone(obj, span));
            }
        }
        // Then the copy-out (or the timed call's other way, or the
        // requeued call), and the requeued call made again: twice, for an
        // entry with the parameters and one without (see `RequeuedOp`).
        let pops: Box<[Var]> = ops[..n].into();
        if is_timed && matches!(ec.target, CallTarget::Task { .. }) {
            others.push(self.ops.len());
        }
        let done = self.ops.len();
        self.ops.push(Op::EntryDone(Box::new(DoneOp {
            other: None,
            requeued: 0,
            span,
        })));
        let skip = self.ops.len();
        self.ops.push(Op::Jump(0));
        let (obj, idx) = (self.temp(), self.temp());
        let mut twins = Vec::new();
        for params in [true, false] {
            let back = if params {
                out_slots(&ec.args[..n], &pops)
            } else {
                Box::new([])
            };
            self.ops.push(Op::RequeueArgs(back, span));
            twins.push(self.ops.len());
            if is_timed {
                others.push(self.ops.len());
            }
            self.ops.push(Op::Requeued(Box::new(RequeuedOp {
                ops: pops.clone(),
                params,
                obj,
                index: idx,
                other: None,
                end: 0,
                twin: 0,
                span,
            })));
        }
        let end = self.here();
        self.patch(skip, end);
        // The call is complete here: its `out` values go to the actuals.
        let outs = out_slots(&ec.args[..n], &pops);
        self.copy_back(&ec.args[..n], &outs);
        if let Op::EntryDone(d) = &mut self.ops[done] {
            d.requeued = twins[0] as u32;
        }
        for (k, &at) in twins.iter().enumerate() {
            if let Op::Requeued(r) = &mut self.ops[at] {
                r.end = end;
                r.twin = twins[1 - k] as u32;
            }
        }
        others
    }

    pub(in crate::interp::vm) fn set_other(&mut self, at: usize, target: u32) {
        match &mut self.ops[at] {
            Op::EntryDone(d) => d.other = Some(target),
            Op::Requeued(r) => r.other = Some(target),
            Op::ProtEntry(e) => e.other = target,
            _ => unreachable!("an entry call"),
        }
    }

    pub(in crate::interp::vm) fn select(&mut self, sel: &Select, span: Span) {
        let mut alts = Vec::new();
        for (g, a, _) in &sel.alts {
            let guard = g.as_ref().map(|g| self.expr(g));
            let index = a.index.as_ref().map(|x| self.expr(x));
            alts.push(AcceptAlt {
                guard,
                entry: a.entry,
                index,
                params: a.params.as_slice().into(),
                target: 0,
            });
        }
        let delay = sel.delay.as_ref().map(|(g, until, d, _)| {
            let g = g.as_ref().map(|g| self.expr(g));
            let x = self.expr(d);
            DelayAlt {
                guard: g,
                amount: x,
                until: *until,
                target: 0,
            }
        });
        let terminate = sel
            .terminate
            .as_ref()
            .map(|g| g.as_ref().map(|g| self.expr(g)));
        let at = self.ops.len();
        self.ops.push(Op::Jump(0));
        let mut ends = Vec::new();
        for (k, (_, a, then)) in sel.alts.iter().enumerate() {
            alts[k].target = self.here();
            self.accept_rest(a);
            self.stmts(then);
            ends.push(self.ops.len());
            self.ops.push(Op::Jump(0));
        }
        let delay = delay.map(|mut alt| {
            alt.target = self.here();
            if let Some((_, _, _, then)) = &sel.delay {
                self.stmts(then);
            }
            ends.push(self.ops.len());
            self.ops.push(Op::Jump(0));
            alt
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
}

/// Where an entry body's `out` values go: the call's own operands (the
/// instructions after the call copy them to the actuals).
fn out_slots(args: &[Arg], ops: &[Var]) -> OutSlots {
    args.iter()
        .zip(ops)
        .enumerate()
        .filter(|(_, (a, _))| a.mode != Mode::In)
        .map(|(k, (_, v))| (k as u32, *v))
        .collect()
}
