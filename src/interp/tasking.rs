//! Tasks on the compiled engine (tasks.md): each task is a thread of the
//! engine's explicit frames (its own registers, display and occurrences),
//! all in one value stack; one runs at a time, chosen by a deterministic
//! scheduler on the virtual clock.
//!
//! - A task runs until it blocks (an entry call, an accept or select that
//!   must wait, a delay, a master waiting for its tasks, its end); then the
//!   ready task that has waited longest, highest priority first, runs.
//! - When no task is ready, the clock advances to the earliest wake-up
//!   (a delay, a timed call's or select's timeout); when there is none,
//!   the program is deadlocked and ends with a diagnostic naming each task
//!   and what it waits for.
//! - Frames of different tasks interleave in the one stack: a frame that
//!   is not on top when it ends leaves a hole, taken back when the frames
//!   above it end.
//!
//! Before the first task is created no thread exists and nothing here
//! costs anything: a sequential program runs exactly as before.

use super::vm::Regs;
use super::*;
use std::collections::{HashMap, VecDeque};

pub(crate) type Tid = usize;

/// The caller of an interrupt entry: the device, not a task.
pub(crate) const INTERRUPT: Tid = usize::MAX;

/// The entry queues an `accept` or `select` waits on (one or two held
/// inline: an `accept` blocks without an allocation).
pub(crate) type Queues = smallvec::SmallVec<[u32; 2]>;

/// What a thread waits for.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Wait {
    Running,
    Ready,
    /// Created by a declaration, not yet activated.
    Unactivated,
    /// An activator waiting for its tasks' activation.
    Activation,
    Delay(f64),
    /// An entry call queued on a task, not yet accepted.
    Call {
        server: Tid,
        entry: u32,
        deadline: Option<f64>,
    },
    /// An entry call being accepted.
    Rendezvous(Tid),
    /// An `accept` or `select` waiting for a caller.
    Accept {
        entries: Queues,
        deadline: Option<f64>,
        terminate: bool,
    },
    /// A protected entry call queued on a closed barrier.
    Prot {
        obj: usize,
        entry: u32,
        deadline: Option<f64>,
    },
    /// A master waiting for its dependent tasks.
    Dependents,
    Terminated,
}

/// How an entry call ended, for the caller.
#[derive(Clone, Debug, Default)]
pub(crate) enum Outcome {
    #[default]
    Pending,
    Done,
    Timeout,
    Error(Box<Occurrence>),
    /// The call was requeued (`Thread::requeue`): the caller makes it again
    /// on the new entry.
    Requeued,
}

/// Where a requeued call goes (RM 9.5.4): the entry's queue (of a task or
/// a protected object), the member's index, and whether the call takes
/// its parameters there and may still time out (`with abort`).
#[derive(Clone, Debug)]
pub(crate) struct Requeued {
    pub to: RequeueTo,
    pub entry: u32,
    pub queue: u32,
    pub index: Option<i64>,
    pub params: bool,
    pub abort: bool,
    /// Already on the protected object's queue (a requeue to an entry of
    /// the same object joins it within the protected action).
    pub queued: bool,
}

#[derive(Clone, Debug)]
pub(crate) enum RequeueTo {
    Task(Tid),
    /// The object's value, its number and its type.
    Prot(Value, usize, u32),
}

#[derive(Clone)]
pub(crate) struct Thread {
    pub name: String,
    pub wait: Wait,
    pub priority: i64,
    /// Registers of the engine while the thread does not run (a task not
    /// started yet has none).
    pub regs: Option<Regs>,
    /// A task not started yet: its body and the display it sees.
    pub start: Option<(FuncId, Vec<usize>)>,
    pub display: Vec<usize>,
    pub current: Vec<Rc<Occurrence>>,
    pub depth: usize,
    pub calls: Vec<Span>,
    /// Callers queued on each entry.
    pub entries: Vec<VecDeque<Tid>>,
    /// Callers in rendezvous with this task (nested accepts).
    pub rendezvous: Vec<Tid>,
    /// The stack slots of the entry call this thread makes (its operands).
    pub call: Vec<usize>,
    pub outcome: Outcome,
    /// The timeout of the call this thread makes (a timed call's deadline;
    /// `Some(-inf)`: a conditional call), which a `requeue ... with abort`
    /// keeps.
    pub call_deadline: Option<f64>,
    /// Where its requeued call goes next (see [`Outcome::Requeued`]).
    pub requeue: Option<Box<Requeued>>,
    /// The protected object whose entry body it runs for its requeued call:
    /// the queues are served when the body returns.
    pub requeue_body: Option<usize>,
    /// The task waiting for this task's activation (until it is reported).
    pub activator: Option<Tid>,
    pub activating: usize,
    pub activation_failed: bool,
    pub unactivated: Vec<Tid>,
    /// Dependent tasks of each master region being executed.
    pub masters: Vec<Vec<Tid>>,
    /// The thread that created this task.
    pub parent: Option<Tid>,
    /// The thread whose master region waits for this task (an allocator's
    /// task may belong to another thread's region; the library level's
    /// tasks to the environment thread, 0).
    pub master_thread: Option<Tid>,
    /// The blocking instruction runs again when the thread resumes.
    pub reexec: bool,
    /// The instruction now running is such a second run.
    pub rerun: bool,
    /// Resumed because its timeout passed.
    pub timed_out: bool,
    /// A protected entry call granted by another task (its barrier is open
    /// and the body is to run now).
    pub granted: bool,
    /// Running an entry body granted by another task, which waits for it.
    pub proxied: bool,
    pub deadline: Option<f64>,
    pub callable: bool,
    /// When it became ready or blocked (longest waiting first).
    pub seq: u64,
    /// The task's type (None: the environment task).
    pub ttype: Option<u32>,
    /// Its discriminants (RM 9.1): its body's parameters, and what
    /// `T.Id` reads from outside.
    pub discrs: Vec<Value>,
    /// Where it blocked last.
    pub at: Span,
}

impl Thread {
    fn new(name: String, ttype: Option<u32>, entries: usize) -> Thread {
        Thread {
            name,
            wait: Wait::Unactivated,
            priority: DEFAULT_PRIORITY,
            regs: None,
            start: None,
            display: Vec::new(),
            current: Vec::new(),
            depth: 0,
            calls: Vec::new(),
            entries: vec![VecDeque::new(); entries],
            rendezvous: Vec::new(),
            call: Vec::new(),
            outcome: Outcome::Pending,
            call_deadline: None,
            requeue: None,
            requeue_body: None,
            activator: None,
            activating: 0,
            activation_failed: false,
            unactivated: Vec::new(),
            masters: Vec::new(),
            parent: None,
            master_thread: None,
            reexec: false,
            rerun: false,
            timed_out: false,
            proxied: false,
            granted: false,
            deadline: None,
            callable: true,
            seq: 0,
            ttype,
            discrs: Vec::new(),
            at: crate::diag::span(0, 0, 0),
        }
    }
}

/// The clock a service sees while tasks run: it keeps the time the service
/// spends (a motion's duration) instead of advancing the virtual clock,
/// which the caller then waits out as a delay.
pub(crate) struct DeferClock {
    pub base: f64,
    pub spent: f64,
}

impl Clock for DeferClock {
    fn now(&self) -> f64 {
        self.base + self.spent
    }
    fn sleep(&mut self, seconds: f64) {
        if seconds > 0.0 {
            self.spent = super::value::whole_ns(self.spent + seconds);
        }
    }
    fn pace(&mut self, _seconds: f64) {}
}

/// Level-0 slots later REPL entries may add while tasks live.
pub(crate) const KEPT_HEADROOM: usize = 1 << 16;

/// GNAT's `System.Default_Priority` (Linux): the main program's and that
/// of tasks without `pragma Priority`.
pub(crate) const DEFAULT_PRIORITY: i64 = 48;

/// GNAT's `System.Priority` (Linux).
pub(crate) const PRIORITY_RANGE: std::ops::RangeInclusive<i64> = 0..=97;

/// The entry queues of one protected object.
#[derive(Clone, Default)]
pub(crate) struct ProtState {
    pub queues: Vec<VecDeque<Tid>>,
    pub ptype: u32,
}

#[derive(Clone)]
pub(crate) struct Sched {
    /// Empty until the first task is created; then [0] is the environment
    /// task (the main program).
    pub threads: Vec<Thread>,
    pub cur: Tid,
    pub ready: VecDeque<Tid>,
    pub prots: Vec<ProtState>,
    /// Freed frame regions not on top of the stack: top -> base.
    pub holes: HashMap<usize, usize>,
    /// Set by an instruction that blocked the running thread.
    pub switch: bool,
    /// Tasks whose master is the library level (the environment).
    pub library: Vec<Tid>,
    pub seq: u64,
    /// Task switches so far (for `--trace`).
    pub switches: u64,
    /// The services are a monitor: the time until which the robot is in a
    /// motion another task started.
    pub robot_free_at: f64,
    /// Where task frames start in the stack when tasks outlive a run (the
    /// REPL): above every level-0 slot of later entries.
    pub floor: usize,
    /// While an allocator of an access type to tasks runs: the master of
    /// its tasks (see [`Run::master_code`]).
    pub alloc_master: Option<i64>,
    /// How many tasks of each task type were created (names `Worker #2`,
    /// ...): counting them for each new one took time quadratic in the
    /// number of tasks.
    pub created: HashMap<u32, usize>,
}

impl Default for Sched {
    fn default() -> Self {
        Sched {
            threads: Vec::new(),
            cur: 0,
            ready: VecDeque::new(),
            prots: Vec::new(),
            holes: HashMap::new(),
            switch: false,
            library: Vec::new(),
            seq: 0,
            switches: 0,
            robot_free_at: 0.0,
            floor: 0,
            alloc_master: None,
            created: HashMap::new(),
        }
    }
}

impl Sched {
    pub fn active(&self) -> bool {
        !self.threads.is_empty()
    }

    /// Whether a task (not the main program) has not ended.
    pub fn alive(&self) -> bool {
        self.threads
            .iter()
            .skip(1)
            .any(|t| !matches!(t.wait, Wait::Terminated))
    }

    pub fn me(&mut self) -> &mut Thread {
        &mut self.threads[self.cur]
    }

    fn tick(&mut self) -> u64 {
        self.seq += 1;
        self.seq
    }

    /// Makes `t` ready (at the end of the queue).
    pub fn make_ready(&mut self, t: Tid) {
        let s = self.tick();
        let th = &mut self.threads[t];
        if matches!(th.wait, Wait::Terminated) {
            return;
        }
        th.wait = Wait::Ready;
        th.seq = s;
        self.ready.push_back(t);
    }

    /// Makes `t` ready to run before every other ready task.
    pub fn make_first(&mut self, t: Tid) {
        let s = self.tick();
        let th = &mut self.threads[t];
        th.wait = Wait::Ready;
        th.seq = s;
        self.ready.retain(|x| *x != t);
        self.ready.push_front(t);
    }

    /// Blocks the running thread on `w`; `again`: its instruction runs
    /// again when it resumes.
    pub fn block(&mut self, w: Wait, again: bool, at: Span) {
        let s = self.tick();
        let me = self.me();
        me.at = at;
        me.wait = w;
        me.reexec = again;
        me.seq = s;
        self.switch = true;
    }

    /// The running thread gives way to the ready ones.
    pub fn yield_now(&mut self) {
        let c = self.cur;
        self.make_ready(c);
        self.switch = true;
    }

    /// The next ready thread: highest priority, then longest waiting.
    pub fn pick(&mut self) -> Option<Tid> {
        let best = self
            .ready
            .iter()
            .enumerate()
            .max_by(|(_, a), (_, b)| {
                let (pa, pb) = (self.threads[**a].priority, self.threads[**b].priority);
                // Equal priority: the one queued first wins (max_by keeps
                // the last maximum, so compare positions reversed).
                pa.cmp(&pb).then(std::cmp::Ordering::Greater)
            })
            .map(|(i, _)| i)?;
        self.ready.remove(best)
    }

    /// Whether the server `s` is waiting in an accept or select with
    /// `entry` open.
    pub fn accepting(&self, s: Tid, entry: u32) -> bool {
        matches!(&self.threads[s].wait, Wait::Accept { entries, .. } if entries.contains(&entry))
    }

    /// Whether task `t` can take its `terminate` alternative: it waits at
    /// one, and so does every task depending on it (or has ended).
    fn at_terminate(&self, t: Tid) -> bool {
        match &self.threads[t].wait {
            Wait::Terminated => true,
            Wait::Accept {
                terminate: true, ..
            } => self.threads[t]
                .masters
                .iter()
                .flatten()
                .all(|d| self.at_terminate(*d)),
            _ => false,
        }
    }

    /// The earliest time a blocked thread waits for.
    pub fn next_deadline(&self) -> Option<f64> {
        self.threads
            .iter()
            .filter_map(|t| match &t.wait {
                Wait::Delay(d) => Some(*d),
                Wait::Call { deadline, .. }
                | Wait::Accept { deadline, .. }
                | Wait::Prot { deadline, .. } => *deadline,
                _ => None,
            })
            .min_by(|a, b| a.total_cmp(b))
    }

    /// What each living task waits for, for the deadlock diagnostic and `:tasks`.
    pub fn describe(
        &self,
        tasks: &crate::check::PVec<TaskDef>,
        prots: &crate::check::PVec<ProtDef>,
        types: &crate::check::types::Types,
    ) -> Vec<(Span, String)> {
        let entry_name = |t: Tid, q: u32| {
            self.threads[t]
                .ttype
                .and_then(|k| tasks.get(k as usize))
                .and_then(|d| member_name(types, &d.entries, d.member(q), |e| (&e.name, e.family)))
                .unwrap_or_else(|| format!("entry {q}"))
        };
        self.threads
            .iter()
            .enumerate()
            .filter(|(_, t)| !matches!(t.wait, Wait::Terminated))
            .map(|(i, t)| {
                let what = match &t.wait {
                    Wait::Running => "runs".to_string(),
                    Wait::Ready => "is ready to run".to_string(),
                    Wait::Unactivated => "is not activated yet".to_string(),
                    Wait::Activation => "waits for the activation of its tasks".to_string(),
                    Wait::Delay(d) => format!("waits in a delay until {d:.3} s"),
                    Wait::Call { server, entry, .. } => format!(
                        "waits in a call of {}.{} (not accepted)",
                        self.threads[*server].name,
                        entry_name(*server, *entry)
                    ),
                    Wait::Rendezvous(s) => {
                        format!("waits for {} to end a rendezvous", self.threads[*s].name)
                    }
                    Wait::Accept { entries, .. } => {
                        let names: Vec<String> =
                            entries.iter().map(|e| entry_name(i, *e)).collect();
                        if names.len() == 1 {
                            format!("waits to accept {}", names[0])
                        } else {
                            format!("waits to accept one of {}", names.join(", "))
                        }
                    }
                    Wait::Prot { obj, entry, .. } => {
                        let p = &self.prots[*obj];
                        let (pn, en) = prots
                            .get(p.ptype as usize)
                            .map(|d| {
                                (
                                    d.name.clone(),
                                    member_name(types, &d.entries, d.member(*entry), |e| {
                                        (&e.name, e.family)
                                    })
                                    .unwrap_or_default(),
                                )
                            })
                            .unwrap_or_default();
                        format!("waits on the closed barrier of {pn}.{en}")
                    }
                    Wait::Dependents => "waits for its tasks to end".to_string(),
                    Wait::Terminated => "has ended".to_string(),
                };
                (t.at, format!("{} {what}", t.name))
            })
            .collect()
    }
}

impl<'c> Run<'_, 'c> {
    /// Creates the environment thread (the running program) when the first
    /// task appears.
    pub(crate) fn tasking_on(&mut self) {
        if self.m.sched.active() {
            return;
        }
        let mut main = Thread::new("main".into(), None, 0);
        main.wait = Wait::Running;
        self.m.sched.threads.push(main);
        self.m.sched.cur = 0;
        if self.m.keep_tasks {
            self.m.sched.floor = self.c.globals as usize + KEPT_HEADROOM;
        }
    }

    /// A new task of type `k` (a declaration's default value or an
    /// allocator): not activated; its master is the running thread's
    /// innermost master region.
    pub(crate) fn create_task(&mut self, k: u32, t: TypeId, span: Span) -> R<Value> {
        self.tasking_on();
        let def = &self.c.tasks[k as usize];
        let Some(body) = def.body else {
            return Err(self.raise(
                check::PROGRAM_ERROR,
                format!("task `{}` has no body", def.name),
                span,
            ));
        };
        let discrs = self.discriminant_values(t, &def.discriminants, span)?;
        let priority = match &def.priority {
            Some(p) => {
                self.m.discrs.push(discrs.clone());
                let v = self.eval_table(p);
                self.m.discrs.pop();
                v?.int()
            }
            None => DEFAULT_PRIORITY,
        };
        if !PRIORITY_RANGE.contains(&priority) {
            return Err(self.raise(
                check::CONSTRAINT_ERROR,
                format!(
                    "priority {priority} of task `{}` is outside System.Priority ({} .. {})",
                    def.name,
                    PRIORITY_RANGE.start(),
                    PRIORITY_RANGE.end()
                ),
                span,
            ));
        }
        let level = self.c.funcs[body as usize].level as usize;
        let display: Vec<usize> = self.m.display[..level.min(self.m.display.len())].to_vec();
        let tid = self.m.sched.threads.len();
        let same = {
            let n = self.m.sched.created.entry(k).or_default();
            *n += 1;
            *n - 1
        };
        let name = if same == 0 {
            def.name.clone()
        } else {
            format!("{} #{}", def.name, same + 1)
        };
        let mut t = Thread::new(name, Some(k), def.queues());
        t.priority = priority;
        t.discrs = discrs;
        t.start = Some((body, display));
        let cur = self.m.sched.cur;
        t.parent = Some(cur);
        self.m.sched.threads.push(t);
        // The master: the region of the allocator's access type, else the
        // innermost region of the creating thread.
        let (th, idx) = match self.m.sched.alloc_master {
            Some(code) if code >= 0 => ((code >> 32) as usize, Some((code & 0xFFFF_FFFF) as usize)),
            Some(_) => (cur, None),
            None => (cur, self.m.sched.threads[cur].masters.len().checked_sub(1)),
        };
        let holder = match idx.and_then(|i| self.m.sched.threads.get_mut(th)?.masters.get_mut(i)) {
            Some(m) => {
                m.push(tid);
                th
            }
            None => {
                self.m.sched.library.push(tid);
                0
            }
        };
        self.m.sched.threads[tid].master_thread = Some(holder);
        self.m.sched.threads[cur].unactivated.push(tid);
        Ok(Value::Int(tid as i64))
    }

    /// The master an access type's declaration recorded (see
    /// [`Run::master_code`]); None when it records none (not a type of
    /// tasks, or its declaration has not run).
    pub(crate) fn collection_master(&self, access: TypeId) -> Option<i64> {
        let v = self.c.types.get(access).master?;
        let i = self.m.display.get(v.level as usize)? + v.slot as usize;
        match self.m.stack.get(i) {
            Some(Value::Int(code)) => Some(*code),
            _ => None,
        }
    }

    /// The running thread's innermost master, as an access type's
    /// declaration records it: thread << 32 | index, or -1 for the library
    /// level (the environment task's tasks).
    pub(crate) fn master_code(&mut self) -> i64 {
        let me = self.m.sched.cur;
        match self.m.sched.threads.get(me).map(|t| t.masters.len()) {
            Some(n) if n > 0 => ((me as i64) << 32) | (n as i64 - 1),
            _ => -1,
        }
    }

    /// A new protected object of type `k`.
    /// Its components: its number, its discriminants (those of its
    /// subtype `t`), the private part's.
    pub(crate) fn create_protected(&mut self, k: u32, t: TypeId, span: Span) -> R<Value> {
        let types = self.c.types;
        let def = &self.c.prots[k as usize];
        let rec = def.rec;
        let n = def.queues();
        let pid = self.m.sched.prots.len();
        self.m.sched.prots.push(ProtState {
            queues: vec![VecDeque::new(); n],
            ptype: k,
        });
        let mut discrs = vec![Value::Int(pid as i64)];
        discrs.extend(self.discriminant_values(t, types.discriminants(t), span)?);
        let fields = types.fields(rec).unwrap_or_default();
        let v = self.record_of_discriminants(fields, discrs, span)?;
        Ok(Value::Ptr(Some(Obj::new(v))))
    }

    /// The number of the protected object an object value designates.
    pub(crate) fn prot_id(v: &Value) -> usize {
        match v {
            Value::Ptr(Some(p)) => p.with(|v| {
                v.fields()
                    .and_then(|r| r.first())
                    .map_or(0, |x| x.int() as usize)
            }),
            _ => 0,
        }
    }

    /// `'Count`, `'Callable`, `'Terminated`.
    pub(crate) fn task_attr(&mut self, op: AttrOp, args: &[Value]) -> Value {
        let b = |x: bool| Value::Int(x as i64);
        match op {
            AttrOp::Count(e) => {
                let n = if self.m.sched.active() {
                    let me = self.m.sched.cur;
                    let q = self.m.sched.threads[me]
                        .ttype
                        .and_then(|k| task_queue(&self.c.tasks[k as usize], e, args.first()));
                    q.and_then(|q| self.m.sched.threads[me].entries.get(q as usize))
                        .map_or(0, |q| q.len())
                } else {
                    0
                };
                Value::Int(n as i64)
            }
            AttrOp::ProtCount(e) => {
                let pid = Self::prot_id(&args[0]);
                let n = self.m.sched.prots.get(pid).and_then(|p| {
                    let q = prot_queue(&self.c.prots[p.ptype as usize], e, args.get(1))?;
                    p.queues.get(q as usize)
                });
                Value::Int(n.map_or(0, |q| q.len()) as i64)
            }
            AttrOp::TaskDiscriminant(i) => {
                let t = args[0].int() as usize;
                self.m
                    .sched
                    .threads
                    .get(t)
                    .and_then(|t| t.discrs.get(i as usize))
                    .cloned()
                    .unwrap_or(Value::Undef)
            }
            AttrOp::Callable => {
                let t = args[0].int() as usize;
                b(self.m.sched.threads.get(t).is_some_and(|t| t.callable))
            }
            AttrOp::Terminated => {
                let t = args[0].int() as usize;
                b(self
                    .m
                    .sched
                    .threads
                    .get(t)
                    .is_none_or(|t| matches!(t.wait, Wait::Terminated)))
            }
            _ => Value::Undef,
        }
    }

    /// Frees a frame's slots `base .. top`: truncates when they are on top
    /// of the stack, else leaves a hole.
    #[inline(always)]
    pub(crate) fn free_frame(&mut self, base: usize, top: usize) {
        if self.m.sched.holes.is_empty() && top >= self.m.stack.len() {
            // The common case (and the only one without tasks).
            self.m.stack.truncate(base);
            return;
        }
        self.free_frame_among_tasks(base, top);
    }

    fn free_frame_among_tasks(&mut self, base: usize, top: usize) {
        if !self.m.sched.active() || top >= self.m.stack.len() {
            self.m.stack.truncate(base);
            while let Some(b) = self.m.sched.holes.remove(&self.m.stack.len()) {
                self.m.stack.truncate(b);
            }
            return;
        }
        for v in &mut self.m.stack.as_mut_slice()[base..top] {
            *v = Value::Undef;
        }
        self.m.sched.holes.insert(top, base);
    }

    /// Ends thread `t`: its callers get Tasking_Error, its master and
    /// activator hear of it.
    pub(crate) fn end_thread(&mut self, t: Tid, failed_activation: bool) {
        let th = &mut self.m.sched.threads[t];
        th.wait = Wait::Terminated;
        th.callable = false;
        let queued: Vec<Tid> = th.entries.iter_mut().flat_map(|q| q.drain(..)).collect();
        let partners = std::mem::take(&mut th.rendezvous);
        let activator = th.activator.take();
        let waiting = [th.parent, th.master_thread];
        let name = th.name.clone();
        for c in queued.into_iter().chain(partners) {
            if c == INTERRUPT {
                continue;
            }
            let occ = Occurrence {
                exc: check::TASKING_ERROR,
                message: format!("the called task {name} has ended"),
                span: Span {
                    start: 0,
                    end: 0,
                    context: 0,
                },
                chain: Vec::new(),
                reraised: Vec::new(),
                chained: true,
                ending: crate::interp::Ending::Exception,
            };
            self.m.sched.threads[c].outcome = Outcome::Error(Box::new(occ));
            self.m.sched.make_ready(c);
        }
        self.m.sched.ready.retain(|x| *x != t);
        if let Some(a) = activator {
            self.activation_done(a, failed_activation);
        }
        // The thread whose master waits for it (and its creator) look again.
        for p in waiting.into_iter().flatten() {
            if matches!(self.m.sched.threads[p].wait, Wait::Dependents) {
                self.m.sched.make_ready(p);
            }
        }
    }

    /// One of `a`'s tasks finished its activation.
    pub(crate) fn activation_done(&mut self, a: Tid, failed: bool) {
        let th = &mut self.m.sched.threads[a];
        th.activating = th.activating.saturating_sub(1);
        th.activation_failed |= failed;
        if th.activating == 0 && matches!(th.wait, Wait::Activation) {
            self.m.sched.make_ready(a);
        }
    }

    /// Moves the clock on by `secs` (a delay, a wait of every task): under
    /// `--realtime` the wall clock takes that time too, in slices that end
    /// early when the user stops the run (the flag stays set for the next
    /// poll, which stops it).
    pub(crate) fn advance_clock(&mut self, secs: f64) {
        if self.m.realtime {
            let stop = self.m.interrupted.clone();
            let mut done = 0.0;
            while done < secs
                && stop
                    .as_ref()
                    .is_none_or(|f| !f.load(std::sync::atomic::Ordering::SeqCst))
            {
                let step = (secs - done).min(0.05);
                self.m.clock.pace(step);
                done += step;
            }
        }
        self.m.clock.sleep(secs);
    }

    /// When nothing is ready: tasks at `terminate` whose masters wait end;
    /// else the clock advances to the earliest wake-up. False: nothing can
    /// ever run again (deadlock).
    pub(crate) fn idle(&mut self) -> bool {
        // Terminate alternatives.
        let waiting: Vec<Tid> = (0..self.m.sched.threads.len())
            .filter(|t| matches!(self.m.sched.threads[*t].wait, Wait::Dependents))
            .collect();
        let mut ended = false;
        for m in waiting {
            let deps: Vec<Tid> = self.m.sched.threads[m]
                .masters
                .last()
                .cloned()
                .unwrap_or_default();
            let deps: Vec<Tid> = if m == 0 && self.m.sched.threads[m].masters.is_empty() {
                self.m.sched.library.clone()
            } else {
                deps
            };
            if !deps.is_empty() && deps.iter().all(|d| self.m.sched.at_terminate(*d)) {
                for d in deps {
                    self.terminate_tree(d);
                }
                // The master looks again (never a spin with nothing ready).
                self.m.sched.make_ready(m);
                ended = true;
            }
        }
        if ended || !self.m.sched.ready.is_empty() {
            return true;
        }
        let now = self.m.clock.now();
        let device = self.m.world.as_ref().and_then(|w| w.next_wakeup(now));
        let t = match (self.m.sched.next_deadline(), device) {
            (Some(a), Some(b)) => a.min(b),
            (a, b) => match a.or(b) {
                Some(t) => t,
                None => return false,
            },
        };
        // A wake-up may be any real (a belt's arrival, the end of another
        // task's motion): the clock, which keeps whole nanoseconds, goes to
        // the first one not before it, so what waits for it is due there.
        let t = super::value::ceil_ns(t);
        if t > now {
            self.advance_clock(t - now);
        }
        let now = self.m.clock.now().max(t);
        self.world_sync();
        let mut woken: Vec<(u64, Tid)> = Vec::new();
        for (i, th) in self.m.sched.threads.iter().enumerate() {
            let due = match &th.wait {
                Wait::Delay(d) => *d <= now,
                Wait::Call { deadline, .. }
                | Wait::Accept { deadline, .. }
                | Wait::Prot { deadline, .. } => deadline.is_some_and(|d| d <= now),
                _ => false,
            };
            if due {
                woken.push((th.seq, i));
            }
        }
        woken.sort();
        for (_, i) in woken {
            match self.m.sched.threads[i].wait.clone() {
                Wait::Call { server, entry, .. } => {
                    self.m.sched.threads[server].entries[entry as usize].retain(|c| *c != i);
                    self.m.sched.threads[i].outcome = Outcome::Timeout;
                }
                Wait::Prot { obj, entry, .. } => {
                    self.m.sched.prots[obj].queues[entry as usize].retain(|c| *c != i);
                    self.m.sched.threads[i].timed_out = true;
                }
                Wait::Accept { .. } => self.m.sched.threads[i].timed_out = true,
                _ => {}
            }
            self.m.sched.make_ready(i);
        }
        true
    }

    /// Ends a task waiting at `terminate`, and its dependents first.
    fn terminate_tree(&mut self, t: Tid) {
        if matches!(self.m.sched.threads[t].wait, Wait::Terminated) {
            return;
        }
        let deps: Vec<Tid> = self.m.sched.threads[t]
            .masters
            .iter()
            .flatten()
            .copied()
            .collect();
        for d in deps {
            self.terminate_tree(d);
        }
        self.discard_thread(t);
        self.end_thread(t, false);
    }

    /// Frees the frames of a thread that will not run again.
    pub(crate) fn discard_thread(&mut self, t: Tid) {
        if let Some(regs) = self.m.sched.threads[t].regs.take() {
            for (base, top) in regs.regions() {
                self.free_frame(base, top);
            }
        }
    }

    /// `abort T`: T and its dependents become not callable and end.
    pub(crate) fn abort_task(&mut self, t: Tid) {
        if t >= self.m.sched.threads.len()
            || matches!(self.m.sched.threads[t].wait, Wait::Terminated)
        {
            return;
        }
        self.m.sched.threads[t].callable = false;
        let deps: Vec<Tid> = self.m.sched.threads[t]
            .masters
            .iter()
            .flatten()
            .chain(self.m.sched.threads[t].unactivated.iter())
            .copied()
            .collect();
        for d in deps {
            self.abort_task(d);
        }
        if t == self.m.sched.cur {
            // The running task ends at once (the engine switches).
            self.m.sched.switch = true;
            self.m.sched.threads[t].wait = Wait::Terminated;
            return;
        }
        // Leave any queue it waits in.
        match self.m.sched.threads[t].wait.clone() {
            Wait::Call { server, entry, .. } => {
                self.m.sched.threads[server].entries[entry as usize].retain(|c| *c != t)
            }
            Wait::Prot { obj, entry, .. } => {
                self.m.sched.prots[obj].queues[entry as usize].retain(|c| *c != t)
            }
            _ => {}
        }
        self.discard_thread(t);
        self.end_thread(t, false);
    }

    /// Brings the devices to the clock's time and queues the interrupts
    /// that happened on their entries; writes the trace.
    pub(crate) fn world_sync(&mut self) {
        let now = self.m.clock.now();
        let Some(w) = self.m.world.as_mut() else {
            return;
        };
        let irqs = w.advance_to(now);
        let log = w.take_log();
        if let Some(t) = self.m.trace.as_mut() {
            for h in &log {
                let _ = writeln!(t, "{h}");
            }
        }
        for i in irqs {
            self.deliver(i.address, i.time);
        }
    }

    /// An interrupt at `address`: queued on the entry bound to it, as an
    /// entry call (its task wakes when it accepts that entry).
    pub(crate) fn deliver(&mut self, address: crate::devices::Address, time: f64) {
        let bound = (0..self.m.sched.threads.len()).find_map(|t| {
            let th = &self.m.sched.threads[t];
            if matches!(th.wait, Wait::Terminated) {
                return None;
            }
            let k = th.ttype?;
            let e = self.c.tasks[k as usize]
                .entries
                .iter()
                .position(|e| e.interrupt == Some(address as i64))?;
            Some((t, e))
        });
        let line = match bound {
            Some((t, e)) => {
                let def = &self.c.tasks[self.m.sched.threads[t].ttype.unwrap_or(0) as usize];
                let q = def.entries[e].first;
                self.m.sched.threads[t].entries[q as usize].push_back(INTERRUPT);
                if self.m.sched.accepting(t, q) {
                    self.m.sched.make_ready(t);
                }
                let name = &def.entries[e].name;
                format!(
                    "interrupt {} queued on {}.{name}",
                    crate::devices::ada_address(address),
                    self.m.sched.threads[t].name
                )
            }
            None => {
                self.m.lost_interrupts += 1;
                format!(
                    "interrupt {}: no task has an entry bound to it, lost",
                    crate::devices::ada_address(address)
                )
            }
        };
        self.trace_line(time, &line);
    }

    pub(crate) fn trace_line(&mut self, time: f64, what: &str) {
        if let Some(t) = self.m.trace.as_mut() {
            let _ = writeln!(t, "[t={time:9.3} s] tasks: {what}");
        }
    }

    /// A device register's value as a value of type `ty`.
    pub(crate) fn read_register(&mut self, a: u32, ty: TypeId, span: Span) -> R<Value> {
        self.world_sync();
        let v = self.m.world.as_ref().and_then(|w| w.read(a));
        let Some(v) = v else {
            return Err(self.raise(
                check::PROGRAM_ERROR,
                format!("no register at {}", crate::devices::ada_address(a)),
                span,
            ));
        };
        Ok(match self.c.types.array(ty) {
            Some(_) => {
                let (lo, hi) = self
                    .array_bounds(ty)?
                    .and_then(|b| b.first().copied())
                    .unwrap_or((0, 15));
                let data = (lo..=hi)
                    .map(|i| Value::Int(((v >> ((i - lo) & 15)) & 1) as i64))
                    .collect();
                Value::Arr(Array::vector(lo, data))
            }
            None => {
                // The register's 16 bits read as a value of the object's
                // type: one outside its range is Constraint_Error.
                let x = Value::Int(v as i64);
                self.range_check(&x, ty, span)?;
                x
            }
        })
    }

    /// Writes a value to a device register.
    pub(crate) fn write_register(&mut self, a: u32, v: &Value, span: Span) -> R<()> {
        self.world_sync();
        let word: u16 = match v {
            Value::Arr(arr) => arr
                .data()
                .iter()
                .enumerate()
                .take(16)
                .fold(0u16, |w, (i, b)| w | (u16::from(b.int() != 0) << i)),
            other => other.int() as u16,
        };
        let r = match self.m.world.as_mut() {
            Some(w) => w.write(a, word).map_err(|e| e.to_string()),
            None => Err("no devices".to_string()),
        };
        if let Err(msg) = r {
            return Err(self.raise(check::PROGRAM_ERROR, msg, span));
        }
        self.world_sync();
        Ok(())
    }

    /// The deadlock diagnostic: every task and what it waits for (one
    /// line each after the first; their places are the chain).
    pub(crate) fn deadlock(&mut self) -> Flow {
        let lines = self
            .m
            .sched
            .describe(self.c.tasks, self.c.prots, self.c.types);
        let mut msg = String::from(DEADLOCK);
        for (_, l) in &lines {
            msg.push('\n');
            msg.push_str(l);
        }
        Flow::Raise(Box::new(Occurrence {
            exc: check::PROGRAM_ERROR,
            message: msg,
            span: lines.first().map_or(crate::diag::span(0, 0, 0), |l| l.0),
            chain: lines.iter().map(|l| l.0).collect(),
            reraised: Vec::new(),
            // The chain is the tasks' places, not calls.
            chained: true,
            ending: crate::interp::Ending::Deadlock,
        }))
    }
}

/// The queue of entry `e` of a task of type `def` (of a family: of the
/// member `index`, None when it is outside the family).
pub(crate) fn task_queue(def: &TaskDef, e: u32, index: Option<&Value>) -> Option<u32> {
    let x = def.entries.get(e as usize)?;
    member_queue(x.first, x.family, index)
}

/// The queue of entry `e` of a protected object of type `def`.
pub(crate) fn prot_queue(def: &ProtDef, e: u32, index: Option<&Value>) -> Option<u32> {
    let x = def.entries.get(e as usize)?;
    member_queue(x.first, x.family, index)
}

fn member_queue(
    first: u32,
    family: Option<crate::check::ir::Family>,
    index: Option<&Value>,
) -> Option<u32> {
    match (family, index) {
        (None, _) => Some(first),
        (Some(f), Some(v)) => {
            let i = v.int();
            (f.lo..=f.hi)
                .contains(&i)
                .then(|| first + (i - f.lo) as u32)
        }
        (Some(_), None) => None,
    }
}

/// The name of a queue's entry (`member`: the entry and family index):
/// `Request (HIGH)` for a member of a family.
fn member_name<E>(
    types: &crate::check::types::Types,
    entries: &[E],
    member: Option<(usize, Option<i64>)>,
    name: impl Fn(&E) -> (&String, Option<crate::check::ir::Family>),
) -> Option<String> {
    let (i, index) = member?;
    let (n, family) = name(entries.get(i)?);
    Some(match (index, family) {
        (Some(x), Some(f)) => match types.enum_lits(f.ty) {
            Some(l) => format!("{n} ({})", l.get(x as usize).map_or("?", |s| s)),
            None => format!("{n} ({x})"),
        },
        _ => n.clone(),
    })
}

/// The first line of the deadlock diagnostic.
pub const DEADLOCK: &str = "deadlock: every task is blocked and nothing can wake one";

#[cfg(test)]
mod tests {
    use super::*;

    fn sched(priorities: &[i64]) -> Sched {
        let mut s = Sched::default();
        for (i, p) in priorities.iter().enumerate() {
            let mut t = Thread::new(format!("T{i}"), Some(0), 1);
            t.priority = *p;
            s.threads.push(t);
        }
        s
    }

    #[test]
    fn the_ready_task_that_waited_longest_runs_first() {
        let mut s = sched(&[15, 15, 15]);
        for t in [2, 0, 1] {
            s.make_ready(t);
        }
        let order: Vec<Tid> = std::iter::from_fn(|| s.pick()).collect();
        assert_eq!(order, vec![2, 0, 1]);
    }

    #[test]
    fn a_higher_priority_runs_first_then_the_longest_waiting() {
        let mut s = sched(&[10, 20, 10, 20]);
        for t in [0, 1, 2, 3] {
            s.make_ready(t);
        }
        let order: Vec<Tid> = std::iter::from_fn(|| s.pick()).collect();
        assert_eq!(order, vec![1, 3, 0, 2]);
    }

    #[test]
    fn make_first_goes_before_every_ready_task_of_its_priority() {
        let mut s = sched(&[15, 15, 15]);
        s.make_ready(0);
        s.make_ready(1);
        s.make_first(2);
        assert_eq!(s.pick(), Some(2));
        assert_eq!(s.pick(), Some(0));
    }

    #[test]
    fn a_terminated_task_is_never_made_ready() {
        let mut s = sched(&[15, 15]);
        s.threads[1].wait = Wait::Terminated;
        s.make_ready(1);
        s.make_ready(0);
        assert_eq!(s.pick(), Some(0));
        assert_eq!(s.pick(), None);
    }

    #[test]
    fn the_next_deadline_is_the_earliest_of_delays_and_timeouts() {
        let mut s = sched(&[15, 15, 15]);
        s.threads[0].wait = Wait::Delay(3.0);
        s.threads[1].wait = Wait::Accept {
            entries: vec![0].into(),
            deadline: Some(2.5),
            terminate: false,
        };
        s.threads[2].wait = Wait::Call {
            server: 1,
            entry: 0,
            deadline: None,
        };
        assert_eq!(s.next_deadline(), Some(2.5));
    }

    #[test]
    fn a_task_at_terminate_with_dependents_waits_for_them_to_terminate_too() {
        let mut s = sched(&[15, 15]);
        s.threads[0].wait = Wait::Accept {
            entries: Queues::new(),
            deadline: None,
            terminate: true,
        };
        s.threads[0].masters = vec![vec![1]];
        s.threads[1].wait = Wait::Delay(1.0);
        assert!(!s.at_terminate(0));
        s.threads[1].wait = Wait::Terminated;
        assert!(s.at_terminate(0));
    }
}
