//! The instructions that block or switch threads: delays, activation,
//! rendezvous, protected entries, select, and the scheduler's switch.

use super::*;

impl<'a, 'c> Run<'a, 'c> {
    pub(super) fn op_delay(&mut self, x: Var, until: bool, span: Span) -> R<()> {
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
    pub(super) fn op_activate(&mut self, span: Span) -> R<()> {
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
    pub(super) fn dependents_done(&mut self, all: bool, span: Span) -> bool {
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
            if matches!(self.m.sched.threads[t].wait, tasking::Wait::Unactivated) {
                self.end_thread(t, false);
            }
        }
        let done = deps
            .iter()
            .all(|d| matches!(self.m.sched.threads[*d].wait, tasking::Wait::Terminated));
        if !done {
            self.m.sched.block(tasking::Wait::Dependents, true, span);
        }
        done
    }

    /// Starts the rendezvous with caller `c`: its arguments into the
    /// accept's parameters.
    pub(super) fn begin_rendezvous(&mut self, c: tasking::Tid, params: &[(Var, Mode)]) {
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
    pub(super) fn end_rendezvous(&mut self, params: &[(Var, Mode)], err: Option<Box<Occurrence>>) {
        let me = self.m.sched.cur;
        let Some(c) = self.m.sched.threads[me].rendezvous.pop() else {
            return;
        };
        if c == tasking::INTERRUPT {
            return;
        }
        if matches!(self.m.sched.threads[c].wait, tasking::Wait::Terminated) {
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

    pub(super) fn deadline(&mut self, timed: Option<(Var, bool)>) -> Option<f64> {
        timed.map(|(v, until)| {
            let x = self.m.stack[self.sl(v)].real();
            value::whole_ns(if until { x } else { self.m.clock.now() + x })
        })
    }

    /// The value of a family member's index operand.
    fn index_value(&self, index: Option<Var>) -> Option<Value> {
        index.map(|i| self.m.stack[self.sl(i)].clone())
    }

    /// Constraint_Error: an index outside its entry family.
    fn family_check_failed(&self, span: Span) -> Flow {
        self.check_failed("index check failed (entry family)", span)
    }

    /// The queue of entry `entry` of task `s` (of a family: of the member
    /// `index`).
    fn task_queue_of(
        &self,
        s: tasking::Tid,
        entry: u32,
        index: Option<&Value>,
        span: Span,
    ) -> R<u32> {
        let k = self.m.sched.threads[s].ttype.unwrap_or(0);
        tasking::task_queue(&self.c.tasks[k as usize], entry, index)
            .ok_or_else(|| self.family_check_failed(span))
    }

    /// Task `s` as the target of an entry call: Program_Error when it is
    /// not a task yet, Tasking_Error when it has ended.
    fn callable_task(&self, s: usize, span: Span) -> R<()> {
        let known = self
            .m
            .sched
            .threads
            .get(s)
            .is_some_and(|t| t.ttype.is_some());
        if !known {
            return Err(self.raise(
                check::PROGRAM_ERROR,
                format!(
                    "{} the called task is not elaborated yet",
                    self.m.location(span)
                ),
                span,
            ));
        }
        let t = &self.m.sched.threads[s];
        if !t.callable || matches!(t.wait, tasking::Wait::Terminated) {
            let name = t.name.clone();
            return Err(self.raise(
                check::TASKING_ERROR,
                format!("{} the called task {name} has ended", self.m.location(span)),
                span,
            ));
        }
        Ok(())
    }

    pub(super) fn op_entry_call(&mut self, ec: &EntryOp) -> R<()> {
        self.tasking_on();
        let me = self.m.sched.cur;
        let s = self.int_at(ec.target) as usize;
        self.callable_task(s, ec.span)?;
        let index = self.index_value(ec.index);
        let q = self.task_queue_of(s, ec.entry, index.as_ref(), ec.span)?;
        // (Into the thread's list of the last call: no allocation.)
        let mut slots = std::mem::take(&mut self.m.sched.threads[me].call);
        slots.clear();
        slots.extend(ec.ops.iter().map(|v| self.sl(*v)));
        let deadline = if ec.conditional {
            Some(f64::NEG_INFINITY)
        } else {
            self.deadline(ec.timed)
        };
        let th = &mut self.m.sched.threads[me];
        th.call = slots;
        th.outcome = tasking::Outcome::Pending;
        th.requeue = None;
        th.call_deadline = deadline;
        self.enqueue_call(me, s, q, deadline, ec.span);
        Ok(())
    }

    /// Thread `c` calls queue `q` of task `s` (`deadline`: of a timed
    /// call, -inf: of a conditional one): it waits there, unless the call
    /// is not taken at once and the deadline has passed (its outcome is
    /// then Timeout). The running thread blocks; another is put in the
    /// queue without waking (a requeue).
    fn enqueue_call(
        &mut self,
        c: tasking::Tid,
        s: tasking::Tid,
        q: u32,
        deadline: Option<f64>,
        span: Span,
    ) {
        let open = self.m.sched.accepting(s, q);
        let now = self.m.clock.now();
        if !open && deadline.is_some_and(|d| d <= now) {
            self.m.sched.threads[c].outcome = tasking::Outcome::Timeout;
            return;
        }
        self.m.sched.threads[s].entries[q as usize].push_back(c);
        if open {
            self.m.sched.make_ready(s);
        }
        let wait = tasking::Wait::Call {
            server: s,
            entry: q,
            deadline: deadline.filter(|d| d.is_finite()),
        };
        if c == self.m.sched.cur {
            self.m.sched.block(wait, false, span);
        } else {
            self.m.sched.threads[c].wait = wait;
        }
    }

    /// After an entry call: None when it is complete (the instructions
    /// at the end of the call copy the `out` values out), else where to go:
    /// the timed call's other way, or its `Requeued` when it was requeued.
    pub(super) fn entry_done(&mut self, d: &DoneOp) -> R<Option<u32>> {
        if !self.m.sched.active() {
            return Ok(None);
        }
        let me = self.m.sched.cur;
        match std::mem::take(&mut self.m.sched.threads[me].outcome) {
            tasking::Outcome::Timeout => Ok(Some(d.other.expect("a timed or conditional call"))),
            tasking::Outcome::Error(o) => Err(self.caller_error(o, d.span)),
            tasking::Outcome::Requeued => {
                self.m.sched.threads[me].outcome = tasking::Outcome::Requeued;
                Ok(Some(d.requeued))
            }
            tasking::Outcome::Done | tasking::Outcome::Pending => Ok(None),
        }
    }

    /// The exception a server or the scheduler gave the caller, placed at
    /// the call when it has no place.
    pub(super) fn caller_error(&self, mut o: Box<Occurrence>, span: Span) -> Flow {
        if o.span.start == 0 && o.span.end == 0 {
            o.span = span;
            o.message = format!("{} {}", self.m.location(span), o.message);
        }
        Flow::Raise(o)
    }

    /// Whether the barrier of queue `q` of a protected object of type `k`
    /// is open; `obj`: the object (its barrier functions' last argument).
    pub(super) fn barrier_open(&mut self, k: u32, q: u32, obj: &Value, span: Span) -> R<bool> {
        let def = &self.c.prots[k as usize];
        let Some((e, index)) = def.member(q) else {
            return Ok(false);
        };
        let entry = &def.entries[e];
        let Some(b) = entry.barrier else {
            return Ok(false);
        };
        let index = match (index, entry.family) {
            (Some(i), Some(_)) => Some(Value::Int(i)),
            _ => None,
        };
        let args = index.into_iter().chain([obj.clone()]);
        Ok(self
            .call_nested(b, args, span)?
            .is_some_and(|v| v.int() != 0))
    }

    pub(super) fn op_prot_entry(&mut self, ec: &EntryOp) -> R<ProtStep> {
        if ec.timed.is_some() || ec.conditional {
            // A `requeue ... with abort` of its body keeps its timeout.
            self.tasking_on();
        }
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
                if let Some(w) = self.first_open_call(pid, &obj, ec.span)? {
                    self.m.sched.threads[w].granted = true;
                    self.m.sched.make_ready(w);
                }
                return Ok(ProtStep::Other);
            }
            if std::mem::take(&mut self.m.sched.threads[me].granted) {
                self.m.sched.threads[me].proxied = true;
                return Ok(ProtStep::Body);
            }
            let deadline = if ec.conditional {
                Some(f64::NEG_INFINITY)
            } else {
                self.deadline(ec.timed)
            };
            let th = &mut self.m.sched.threads[me];
            th.outcome = tasking::Outcome::Pending;
            th.requeue = None;
            th.call_deadline = deadline;
        }
        let obj = self.m.stack[self.sl(ec.target)].clone();
        let pid = Self::prot_id(&obj);
        let index = self.index_value(ec.index);
        let q = tasking::prot_queue(&self.c.prots[ec.kind as usize], ec.entry, index.as_ref())
            .ok_or_else(|| self.family_check_failed(ec.span))?;
        let queued = self
            .m
            .sched
            .prots
            .get(pid)
            .is_some_and(|p| !p.queues[q as usize].is_empty());
        if !queued && self.barrier_open(ec.kind, q, &obj, ec.span)? {
            return Ok(ProtStep::Body);
        }
        let deadline = self.deadline(ec.timed);
        if ec.conditional || deadline.is_some_and(|d| d <= self.m.clock.now()) {
            return Ok(ProtStep::Other);
        }
        self.tasking_on();
        let me = self.m.sched.cur;
        self.m.sched.threads[me].call_deadline = deadline;
        self.m.sched.prots[pid].queues[q as usize].push_back(me);
        // Queuing the call ends a protected action, so the queues are
        // served (RM 9.5.3(7-8)): a barrier that reads an entry's 'Count
        // may have opened now that the queue is longer (the cyclic
        // barrier `when Wait'Count = N or Releasing`).
        let granted = self.first_open_call(pid, &obj, ec.span)?;
        if granted == Some(me) {
            return Ok(ProtStep::Body);
        }
        self.m.sched.block(
            tasking::Wait::Prot {
                obj: pid,
                entry: q,
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
    /// barrier is open (entries in declaration order, a family's members
    /// from its low bound, each queue first in, first out) off its queue;
    /// `obj`: the object.
    pub(super) fn first_open_call(
        &mut self,
        pid: usize,
        obj: &Value,
        span: Span,
    ) -> R<Option<usize>> {
        let k = self.m.sched.prots[pid].ptype;
        let n = self.m.sched.prots[pid].queues.len();
        for q in 0..n {
            if self.m.sched.prots[pid].queues[q].is_empty() {
                continue;
            }
            if self.barrier_open(k, q as u32, obj, span)? {
                return Ok(self.m.sched.prots[pid].queues[q].pop_front());
            }
        }
        Ok(None)
    }

    /// The end of a protected action on `obj`: the first queued call whose
    /// barrier is now open runs its body next (before any other task), and
    /// the task that ran an entry body for another gives way.
    pub(super) fn serve(&mut self, obj: Var, span: Span) -> R<()> {
        if !self.m.sched.active() {
            return Ok(());
        }
        let v = self.m.stack[self.sl(obj)].clone();
        let pid = Self::prot_id(&v);
        self.serve_object(pid, &v, span)
    }

    fn serve_object(&mut self, pid: usize, obj: &Value, span: Span) -> R<()> {
        let me = self.m.sched.cur;
        let proxied = std::mem::take(&mut self.m.sched.threads[me].proxied);
        match self.first_open_call(pid, obj, span)? {
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

    /// `accept`: a caller now, or wait for one.
    pub(super) fn op_accept(&mut self, a: &AcceptOp) -> R<()> {
        let me = self.m.sched.cur;
        self.m.sched.threads[me].rerun = false;
        let index = self.index_value(a.index);
        let q = self.task_queue_of(me, a.entry, index.as_ref(), a.span)?;
        match self.m.sched.threads[me].entries[q as usize].pop_front() {
            Some(c) => self.begin_rendezvous(c, &a.params),
            None => self.m.sched.block(
                tasking::Wait::Accept {
                    entries: smallvec::smallvec![q],
                    deadline: None,
                    terminate: false,
                },
                true,
                a.span,
            ),
        }
        Ok(())
    }

    /// `requeue`: the call being served (the rendezvous' caller, or the
    /// running thread's own protected call) goes on to the target entry.
    pub(super) fn op_requeue(&mut self, r: &RequeueOp) -> R<()> {
        self.tasking_on();
        let me = self.m.sched.cur;
        let index = self.index_value(r.index);
        let (to, queue) = if r.prot {
            let obj = self.m.stack[self.sl(r.target.expect("the object"))].clone();
            let pid = Self::prot_id(&obj);
            let q = tasking::prot_queue(&self.c.prots[r.kind as usize], r.entry, index.as_ref())
                .ok_or_else(|| self.family_check_failed(r.span))?;
            (tasking::RequeueTo::Prot(obj, pid, r.kind), q)
        } else {
            let s = match r.target {
                Some(t) => self.int_at(t) as usize,
                None => me,
            };
            let q = match self.m.sched.threads.get(s).and_then(|t| t.ttype) {
                Some(k) => tasking::task_queue(&self.c.tasks[k as usize], r.entry, index.as_ref())
                    .ok_or_else(|| self.family_check_failed(r.span))?,
                None => r.entry,
            };
            (tasking::RequeueTo::Task(s), q)
        };
        let mut rq = tasking::Requeued {
            to,
            entry: r.entry,
            queue,
            index: index.map(|v| v.int()),
            params: r.params,
            abort: r.abort,
            queued: false,
        };
        let Some(params) = &r.accept else {
            // In a protected entry body: the caller is this thread, which
            // makes the call again when the body has returned. To an entry
            // of the same object, the call joins its queue now, within the
            // protected action (RM 9.5.4(13)).
            if let tasking::RequeueTo::Prot(_, pid, _) = &rq.to
                && r.internal
            {
                self.m.sched.prots[*pid].queues[queue as usize].push_back(me);
                rq.queued = true;
            }
            let th = &mut self.m.sched.threads[me];
            th.requeue = Some(Box::new(rq));
            th.outcome = tasking::Outcome::Requeued;
            return Ok(());
        };
        // In an accept statement: the rendezvous ends without releasing
        // its caller, whose parameters keep the values they have now.
        let Some(c) = self.m.sched.threads[me].rendezvous.pop() else {
            return Ok(());
        };
        if c == tasking::INTERRUPT
            || matches!(self.m.sched.threads[c].wait, tasking::Wait::Terminated)
        {
            return Ok(());
        }
        for (i, (v, mode)) in params.iter().enumerate() {
            if *mode != Mode::In {
                let x = self.m.stack[self.sl(*v)].clone();
                let slot = self.m.sched.threads[c].call[i];
                self.m.stack[slot] = x;
            }
        }
        match rq.to {
            tasking::RequeueTo::Task(s) => {
                // Queued on the task at once, as if the caller called.
                if let Err(Flow::Raise(o)) = self.callable_task(s, r.span) {
                    self.m.sched.threads[c].outcome = tasking::Outcome::Error(o);
                    self.m.sched.make_ready(c);
                    return Ok(());
                }
                let deadline = if r.abort {
                    self.m.sched.threads[c].call_deadline
                } else {
                    None
                };
                self.enqueue_call(c, s, queue, deadline, r.span);
                if matches!(self.m.sched.threads[c].outcome, tasking::Outcome::Timeout) {
                    self.m.sched.make_ready(c);
                }
            }
            tasking::RequeueTo::Prot(..) => {
                // The caller makes the protected call (its thread runs the
                // entry body), before this task goes on.
                let th = &mut self.m.sched.threads[c];
                th.requeue = Some(Box::new(rq));
                th.outcome = tasking::Outcome::Requeued;
                self.m.sched.make_first(me);
                self.m.sched.make_first(c);
                self.m.sched.switch = true;
            }
        }
        Ok(())
    }

    /// A requeued call, made again by its caller: on a task's entry as a
    /// call; on a protected entry, the caller runs the body (`Body`) when
    /// the barrier is open, else waits in the queue. When the body returns
    /// here, the object's queues are served; then the call's outcome: done
    /// (copy-out), timed out, an exception, or requeued again.
    pub(super) fn op_requeued(&mut self, r: &RequeuedOp) -> R<RequeueStep> {
        let me = self.m.sched.cur;
        self.rerun();
        if let Some(pid) = self.m.sched.threads[me].requeue_body.take() {
            let obj = self.m.stack[self.sl(r.obj)].clone();
            self.serve_object(pid, &obj, r.span)?;
            if self.m.sched.switch {
                self.m.sched.threads[me].reexec = true;
                return Ok(RequeueStep::Wait);
            }
        }
        let other = |this: &mut Self| {
            this.m.sched.threads[me].requeue = None;
            Ok(RequeueStep::Jump(
                r.other.expect("a timed or conditional call"),
            ))
        };
        match std::mem::take(&mut self.m.sched.threads[me].outcome) {
            tasking::Outcome::Timeout => return other(self),
            tasking::Outcome::Error(o) => {
                self.m.sched.threads[me].requeue = None;
                return Err(self.caller_error(o, r.span));
            }
            tasking::Outcome::Done => {
                self.m.sched.threads[me].requeue = None;
                return Ok(RequeueStep::Jump(r.end));
            }
            tasking::Outcome::Requeued | tasking::Outcome::Pending => {}
        }
        let Some(rq) = self.m.sched.threads[me].requeue.clone() else {
            // The requeued call's body has returned: the call is complete.
            return Ok(RequeueStep::Jump(r.end));
        };
        let deadline = if rq.abort {
            self.m.sched.threads[me].call_deadline
        } else {
            None
        };
        match rq.to.clone() {
            tasking::RequeueTo::Task(s) => {
                self.m.sched.threads[me].requeue = None;
                self.callable_task(s, r.span)?;
                let slots: Vec<usize> = r.ops.iter().map(|v| self.sl(*v)).collect();
                self.m.sched.threads[me].call = slots;
                self.enqueue_call(me, s, rq.queue, deadline, r.span);
                if matches!(
                    std::mem::take(&mut self.m.sched.threads[me].outcome),
                    tasking::Outcome::Timeout
                ) {
                    return other(self);
                }
                self.m.sched.threads[me].reexec = true;
                Ok(RequeueStep::Wait)
            }
            tasking::RequeueTo::Prot(obj, pid, k) => {
                self.put(r.obj, obj);
                if let Some(i) = rq.index {
                    self.put(r.index, Value::Int(i));
                }
                let obj_arg = self.m.stack[self.sl(r.obj)].clone();
                if rq.queued {
                    if std::mem::take(&mut self.m.sched.threads[me].timed_out) {
                        // Left its queue (RM 9.5.3(20)): a protected action.
                        if let Some(w) = self.first_open_call(pid, &obj_arg, r.span)? {
                            self.m.sched.threads[w].granted = true;
                            self.m.sched.make_ready(w);
                        }
                        return other(self);
                    }
                    if self.m.sched.threads[me].granted {
                        return Ok(self.requeued_body(r, &rq, pid, k));
                    }
                    // Queued within the protected action and not taken at
                    // its end: a conditional call (or one past its
                    // timeout) requeued with abort is cancelled.
                    if deadline.is_some_and(|d| d <= self.m.clock.now()) {
                        self.m.sched.prots[pid].queues[rq.queue as usize].retain(|c| *c != me);
                        if let Some(w) = self.first_open_call(pid, &obj_arg, r.span)? {
                            self.m.sched.threads[w].granted = true;
                            self.m.sched.make_ready(w);
                        }
                        return other(self);
                    }
                } else {
                    let empty = self.m.sched.prots[pid].queues[rq.queue as usize].is_empty();
                    if empty && self.barrier_open(k, rq.queue, &obj_arg, r.span)? {
                        self.m.sched.threads[me].granted = true;
                        return Ok(self.requeued_body(r, &rq, pid, k));
                    }
                    if deadline.is_some_and(|d| d <= self.m.clock.now()) {
                        return other(self);
                    }
                    self.m.sched.prots[pid].queues[rq.queue as usize].push_back(me);
                    if let Some(x) = self.m.sched.threads[me].requeue.as_mut() {
                        x.queued = true;
                    }
                    let granted = self.first_open_call(pid, &obj_arg, r.span)?;
                    if granted == Some(me) {
                        self.m.sched.threads[me].granted = true;
                        return Ok(self.requeued_body(r, &rq, pid, k));
                    }
                    if let Some(w) = granted {
                        self.m.sched.threads[w].granted = true;
                        self.m.sched.make_first(w);
                    }
                }
                self.m.sched.block(
                    tasking::Wait::Prot {
                        obj: pid,
                        entry: rq.queue,
                        deadline: deadline.filter(|d| d.is_finite()),
                    },
                    true,
                    r.span,
                );
                Ok(RequeueStep::Wait)
            }
        }
    }

    /// The requeued call's entry body runs now (its barrier is open, the
    /// call granted): from the twin instruction when the entry's
    /// parameters differ from this one's (see `RequeuedOp`).
    fn requeued_body(
        &mut self,
        r: &RequeuedOp,
        rq: &tasking::Requeued,
        pid: usize,
        k: u32,
    ) -> RequeueStep {
        let me = self.m.sched.cur;
        if rq.params != r.params {
            if let Some(x) = self.m.sched.threads[me].requeue.as_mut() {
                x.queued = true;
            }
            return RequeueStep::Jump(r.twin);
        }
        let th = &mut self.m.sched.threads[me];
        th.granted = false;
        th.requeue = None;
        th.outcome = tasking::Outcome::Pending;
        th.requeue_body = Some(pid);
        let entry = &self.c.prots[k as usize].entries[rq.entry as usize];
        let mut slots: Vec<Var> = if rq.params {
            r.ops.to_vec()
        } else {
            Vec::new()
        };
        if entry.family.is_some() {
            slots.push(r.index);
        }
        slots.push(r.obj);
        RequeueStep::Body(entry.body.expect("an entry body"), slots)
    }

    /// A selective accept: Some(target) when an alternative is taken now.
    pub(super) fn op_select(&mut self, sel: &SelectOp) -> R<Option<u32>> {
        let me = self.m.sched.cur;
        let again = self.rerun();
        if std::mem::take(&mut self.m.sched.threads[me].timed_out)
            && let Some(d) = sel.delay
        {
            return Ok(Some(d.target));
        }
        let open = |this: &Self, g: Option<Var>| g.is_none_or(|g| this.int_at(g) != 0);
        // The queues of the open alternatives (a family member's index is
        // checked when its alternative is open, RM 9.7.1(15)).
        let mut entries = tasking::Queues::with_capacity(sel.alts.len());
        for a in &sel.alts {
            if !open(self, a.guard) {
                continue;
            }
            let index = self.index_value(a.index);
            let q = self.task_queue_of(me, a.entry, index.as_ref(), sel.span)?;
            if let Some(c) = self.m.sched.threads[me].entries[q as usize].pop_front() {
                self.begin_rendezvous(c, &a.params);
                return Ok(Some(a.target));
            }
            entries.push(q);
        }
        if let Some(t) = sel.els {
            return Ok(Some(t));
        }
        let delay = sel.delay.filter(|d| open(self, d.guard));
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
            let d = delay.and_then(|d| self.deadline(Some((d.amount, d.until))));
            self.m.sched.threads[me].deadline = d;
            d
        };
        if let (Some(d), Some(alt)) = (deadline, delay)
            && d <= self.m.clock.now()
        {
            return Ok(Some(alt.target));
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
    pub(super) fn robot_free_at(&self, f: FuncId) -> f64 {
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
    pub(super) fn swap_registers(&mut self, t: tasking::Tid) {
        let th = &mut self.m.sched.threads[t];
        std::mem::swap(&mut self.m.display, &mut th.display);
        std::mem::swap(&mut self.m.current, &mut th.current);
        std::mem::swap(&mut self.m.depth, &mut th.depth);
        std::mem::swap(&mut self.m.calls, &mut th.calls);
    }

    /// Makes `t` the running thread: its saved registers, or its body's
    /// first frame when it starts.
    pub(super) fn resume(&mut self, level0: &'c Code, t: tasking::Tid) -> R<Live<'c>> {
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
            return Ok(self.load_regs(level0, r));
        }
        let (body, mut display) = self.m.sched.threads[t]
            .start
            .take()
            .expect("a task to start");
        let code = self.code_of(body);
        let sub = &self.c.funcs[body as usize];
        let level = sub.level as usize;
        let own = (sub.nslots as usize).max(sub.params.len());
        let base = self.m.stack.len().max(self.m.sched.floor);
        let top = base + own + code.temps as usize;
        self.m.stack.grow_to(top);
        // The discriminants: the body's parameters.
        for (i, v) in self.m.sched.threads[t]
            .discrs
            .clone()
            .into_iter()
            .enumerate()
        {
            self.m.stack[base + i] = v;
        }
        display.resize(level + 1, 0);
        display[level] = base;
        let th = &mut self.m.sched.threads[t];
        th.display = display;
        th.current = Vec::new();
        th.depth = 0;
        th.calls = Vec::new();
        self.swap_registers(t);
        Ok(Live {
            frames: Vec::new(),
            cur: code,
            pc: 0,
            current_base: 0,
            pending: None,
            root: Some((base, top)),
        })
    }

    /// The running task's body has ended (`failed`: by an exception).
    pub(super) fn task_ends(&mut self, root: Option<(usize, usize)>, failed: bool) {
        let me = self.m.sched.cur;
        if let Some((b, t)) = root {
            self.free_frame(b, t);
        }
        let during_activation = failed && self.m.sched.threads[me].activator.is_some();
        self.end_thread(me, during_activation);
        self.swap_registers(me);
    }

    /// Switches to the next ready thread after the running one ended.
    pub(super) fn next_thread(&mut self, level0: &'c Code) -> R<Live<'c>> {
        let next = loop {
            if let Some(n) = self.m.sched.pick() {
                break n;
            }
            if !self.idle() {
                return Err(self.deadlock());
            }
        };
        self.resume(level0, next)
    }
}

/// What a protected entry call does now.
pub(super) enum ProtStep {
    /// The barrier is open (or the call was granted): run the body.
    Body,
    /// A conditional call not taken, or a timed one that timed out.
    Other,
    /// Queued: the task waits.
    Wait,
}

/// What a requeued call (`Op::Requeued`) does now.
pub(super) enum RequeueStep {
    /// Goes on at this instruction (the end of the call, a timed call's
    /// other statements, the twin).
    Jump(u32),
    /// Runs this entry body with these operands, then this instruction
    /// again.
    Body(FuncId, Vec<Var>),
    /// Waits (or gives way), then this instruction again.
    Wait,
}
