//! The instructions that block or switch threads: delays, activation,
//! rendezvous, protected entries, select, and the scheduler's switch.

use super::*;

impl<'a> Run<'a> {
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
            if self.m.sched.threads[t].wait == tasking::Wait::Unactivated {
                self.end_thread(t, false);
            }
        }
        let done = deps
            .iter()
            .all(|d| self.m.sched.threads[*d].wait == tasking::Wait::Terminated);
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
        if self.m.sched.threads[c].wait == tasking::Wait::Terminated {
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

    pub(super) fn op_entry_call(&mut self, ec: &EntryOp) -> R<()> {
        self.tasking_on();
        let me = self.m.sched.cur;
        let s = self.int_at(ec.target) as usize;
        let known = self
            .m
            .sched
            .threads
            .get(s)
            .is_some_and(|t| t.ttype.is_some() && (ec.entry as usize) < t.entries.len());
        if !known {
            return Err(self.raise(
                check::PROGRAM_ERROR,
                format!(
                    "{} the called task is not elaborated yet",
                    self.m.location(ec.span)
                ),
                ec.span,
            ));
        }
        let alive = self
            .m
            .sched
            .threads
            .get(s)
            .is_some_and(|t| t.callable && t.wait != tasking::Wait::Terminated);
        if !alive {
            let name = self
                .m
                .sched
                .threads
                .get(s)
                .map(|t| t.name.clone())
                .unwrap_or_default();
            return Err(self.raise(
                check::TASKING_ERROR,
                format!(
                    "{} the called task {name} has ended",
                    self.m.location(ec.span)
                ),
                ec.span,
            ));
        }
        let slots: Vec<usize> = ec.ops.iter().map(|v| self.sl(*v)).collect();
        self.m.sched.threads[me].call = slots;
        self.m.sched.threads[me].outcome = tasking::Outcome::Pending;
        let open = self.m.sched.accepting(s, ec.entry);
        let deadline = self.deadline(ec.timed);
        let now = self.m.clock.now();
        if !open && (ec.conditional || deadline.is_some_and(|d| d <= now)) {
            self.m.sched.threads[me].outcome = tasking::Outcome::Timeout;
            return Ok(());
        }
        self.m.sched.threads[s].entries[ec.entry as usize].push_back(me);
        if open {
            self.m.sched.make_ready(s);
        }
        self.m.sched.block(
            tasking::Wait::Call {
                server: s,
                entry: ec.entry,
                deadline,
            },
            false,
            ec.span,
        );
        Ok(())
    }

    /// After an entry call: false when it timed out (or was not taken).
    pub(super) fn entry_done(&mut self, args: &[Arg], ops: &[Var], span: Span) -> R<bool> {
        let me = self.m.sched.cur;
        match std::mem::take(&mut self.m.sched.threads[me].outcome) {
            tasking::Outcome::Timeout => Ok(false),
            tasking::Outcome::Error(mut o) => {
                if o.span.start == 0 && o.span.end == 0 {
                    o.span = span;
                    o.message = format!("{} {}", self.m.location(span), o.message);
                }
                Err(Flow::Raise(o))
            }
            tasking::Outcome::Done | tasking::Outcome::Pending => {
                for (a, v) in args.iter().zip(ops.iter()) {
                    if a.mode != Mode::In {
                        let i = self.sl(*v);
                        let x = std::mem::take(&mut self.m.stack[i]);
                        if let Some(t) = a.back_check {
                            self.range_check(&x, t, a.value.span)?;
                        }
                        self.assign(&a.value, x)?;
                    }
                }
                Ok(true)
            }
        }
    }

    pub(super) fn barrier_open(
        &mut self,
        k: u32,
        entry: u32,
        bargs: &[Arg],
        span: Span,
    ) -> R<bool> {
        let Some(b) = self.c.prots[k as usize].entries[entry as usize].barrier else {
            return Ok(false);
        };
        Ok(self.call(b, bargs, span)?.is_some_and(|v| v.int() != 0))
    }

    pub(super) fn op_prot_entry(&mut self, ec: &EntryOp) -> R<ProtStep> {
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
                if let Some(w) = self.first_open_call(pid, &ec.barrier_args, ec.span)? {
                    self.m.sched.threads[w].granted = true;
                    self.m.sched.make_ready(w);
                }
                return Ok(ProtStep::Other);
            }
            if std::mem::take(&mut self.m.sched.threads[me].granted) {
                self.m.sched.threads[me].proxied = true;
                return Ok(ProtStep::Body);
            }
        }
        let obj = self.m.stack[self.sl(ec.target)].clone();
        let pid = Self::prot_id(&obj);
        let queued = self
            .m
            .sched
            .prots
            .get(pid)
            .is_some_and(|p| !p.queues[ec.entry as usize].is_empty());
        if !queued && self.barrier_open(ec.kind, ec.entry, &ec.barrier_args, ec.span)? {
            return Ok(ProtStep::Body);
        }
        let deadline = self.deadline(ec.timed);
        if ec.conditional || deadline.is_some_and(|d| d <= self.m.clock.now()) {
            return Ok(ProtStep::Other);
        }
        self.tasking_on();
        let me = self.m.sched.cur;
        self.m.sched.prots[pid].queues[ec.entry as usize].push_back(me);
        // Queuing the call ends a protected action, so the queues are
        // served (RM 9.5.3(7-8)): a barrier that reads an entry's 'Count
        // may have opened now that the queue is longer (the cyclic
        // barrier `when Wait'Count = N or Releasing`).
        let granted = self.first_open_call(pid, &ec.barrier_args, ec.span)?;
        if granted == Some(me) {
            return Ok(ProtStep::Body);
        }
        self.m.sched.block(
            tasking::Wait::Prot {
                obj: pid,
                entry: ec.entry,
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
    /// barrier is open (entries in declaration order, each queue first
    /// in, first out) off its queue.
    pub(super) fn first_open_call(
        &mut self,
        pid: usize,
        bargs: &[Arg],
        span: Span,
    ) -> R<Option<usize>> {
        let k = self.m.sched.prots[pid].ptype;
        let n = self.m.sched.prots[pid].queues.len();
        for e in 0..n {
            if self.m.sched.prots[pid].queues[e].is_empty() {
                continue;
            }
            if self.barrier_open(k, e as u32, bargs, span)? {
                return Ok(self.m.sched.prots[pid].queues[e].pop_front());
            }
        }
        Ok(None)
    }

    /// The end of a protected action on `obj`: the first queued call whose
    /// barrier is now open runs its body next (before any other task), and
    /// the task that ran an entry body for another gives way.
    pub(super) fn serve(&mut self, obj: Var, bargs: &[Arg], span: Span) -> R<()> {
        if !self.m.sched.active() {
            return Ok(());
        }
        let me = self.m.sched.cur;
        let proxied = std::mem::take(&mut self.m.sched.threads[me].proxied);
        let v = self.m.stack[self.sl(obj)].clone();
        let pid = Self::prot_id(&v);
        match self.first_open_call(pid, bargs, span)? {
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
        for a in &sel.alts {
            if open(self, a.guard)
                && let Some(c) = self.m.sched.threads[me].entries[a.entry as usize].pop_front()
            {
                self.begin_rendezvous(c, &a.params);
                return Ok(Some(a.target));
            }
        }
        if let Some(t) = sel.els {
            return Ok(Some(t));
        }
        let entries: Vec<u32> = sel
            .alts
            .iter()
            .filter(|a| open(self, a.guard))
            .map(|a| a.entry)
            .collect();
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
    pub(super) fn resume<'c>(
        &mut self,
        cache: &mut Codes<'c>,
        level0: &'c Code,
        t: tasking::Tid,
    ) -> R<Live<'c>> {
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
            return Ok(self.load_regs(cache, level0, r));
        }
        let (body, mut display) = self.m.sched.threads[t]
            .start
            .take()
            .expect("a task to start");
        let code = self.code_of(cache, body);
        let sub = &self.c.funcs[body as usize];
        let level = sub.level as usize;
        let own = (sub.nslots as usize).max(sub.params.len());
        let base = self.m.stack.len().max(self.m.sched.floor);
        let top = base + own + code.temps as usize;
        self.m.stack.grow_to(top);
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
    pub(super) fn next_thread<'c>(
        &mut self,
        cache: &mut Codes<'c>,
        level0: &'c Code,
    ) -> R<Live<'c>> {
        let next = loop {
            if let Some(n) = self.m.sched.pick() {
                break n;
            }
            if !self.idle() {
                return Err(self.deadlock());
            }
        };
        self.resume(cache, level0, next)
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
