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
        self.ops
            .push(Op::Accept(a.entry, a.params.as_slice().into(), span));
        self.accept_rest(a);
    }

    pub(in crate::interp::vm) fn accept_rest(&mut self, a: &Accept) {
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
    pub(in crate::interp::vm) fn obj_args(&self, obj: Var, like: &Ex) -> Box<[Arg]> {
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
    pub(in crate::interp::vm) fn entry_call(
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

    pub(in crate::interp::vm) fn set_other(&mut self, at: usize, target: u32) {
        match &mut self.ops[at] {
            Op::EntryDone(_, _, other, _) => *other = Some(target),
            Op::ProtEntry(e) => e.other = target,
            _ => unreachable!("an entry call"),
        }
    }

    pub(in crate::interp::vm) fn select(&mut self, sel: &Select, span: Span) {
        let mut alts = Vec::new();
        for (g, a, _) in &sel.alts {
            let g = g.as_ref().map(|g| self.expr(g));
            alts.push(AcceptAlt {
                guard: g,
                entry: a.entry,
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
