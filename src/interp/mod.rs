//! The tree-walking interpreter over the checked program.
//!
//! [`Machine`] holds the state that outlives one run (globals, output, clock,
//! the native bindings), so that the REPL can run entry after entry. A run
//! reads the checked program through a [`ProgramRef`] (never the checker),
//! in which every name is already a slot or an index: nothing here looks a
//! name up by string.

mod aggregate;
pub mod builtins;
pub mod diagnostics;
pub mod elems;
pub mod memory;
mod stack;
pub mod tasking;
pub mod value;
pub mod vm;

use crate::check;
use crate::check::ir::*;
use crate::check::types::{Field, TypeId, TypeKind};
use crate::diag::Span;
use crate::syntax::ast::Mode;
use std::io::Write;
use std::rc::Rc;
pub use value::{Array, Ending, Obj, Occurrence, Value};

/// Why evaluation stopped early: an exception, a `return` or an `exit`.
#[derive(Debug)]
pub enum Flow {
    Raise(Box<Occurrence>),
    Return(Option<Value>),
    Exit(u32),
}

pub type R<T> = Result<T, Flow>;

/// The clock that `Ada.Calendar.Clock` and `delay` read. The simulator
/// provides a virtual one, so runs are deterministic.
pub trait Clock {
    fn now(&self) -> f64;
    fn sleep(&mut self, seconds: f64);
    /// Paces a motion to the wall clock (`--realtime`, `RealTime => True`).
    fn pace(&mut self, seconds: f64) {
        if seconds > 0.0 {
            std::thread::sleep(std::time::Duration::from_secs_f64(seconds.min(3600.0)));
        }
    }
}

/// Virtual time that advances only by `delay` (and, later, by motions).
#[derive(Default)]
pub struct VirtualClock {
    pub t: f64,
}

impl Clock for VirtualClock {
    fn now(&self) -> f64 {
        self.t
    }
    fn sleep(&mut self, seconds: f64) {
        // Whole nanoseconds, as `Time` values are (value::whole_ns).
        if seconds > 0.0 {
            self.t = value::whole_ns(self.t + seconds);
        }
    }
}

pub type Native = fn(&mut Run, &mut [Value], Span) -> R<Option<Value>>;

/// What an imported subprogram is bound to: a native body of the
/// interpreter's own library, or a robot service, which the run hands to the
/// [`Services`] the session lent it.
#[derive(Clone, Copy)]
pub enum Binding {
    Native(Native),
    Service(u32),
}

/// The label of the `exit` by which a service ends the whole program when
/// the user stops it (Ctrl-C): no loop carries it and no handler catches an
/// exit, so it leaves every frame; [`Machine::run`] ends there normally and
/// the caller asks the services where the robot stopped.
pub const STOP_LABEL: u32 = u32::MAX;

/// The first line of the report of a program with tasks that the user
/// stopped (Ctrl-C); one line per task follows, its place in the chain.
pub const STOPPED_TASKS: &str = "interrupted (Ctrl-C): every task stopped";

/// How a service call ends early.
#[derive(Debug)]
pub enum ServiceFault {
    /// An exception, raised at the call.
    Raise(ExcId, String),
    /// The user stopped the program (Ctrl-C): every frame is left.
    Stop,
}

/// The robot services, as the interpreter sees them: a typed value owned by
/// the session and lent to a run. The interpreter knows no robot.
pub trait Services {
    /// Calls service `index` (the [`Binding::Service`] its import name bound).
    fn call(
        &mut self,
        index: u32,
        cx: &mut ServiceCx<'_>,
        args: &mut [Value],
    ) -> Result<Option<Value>, ServiceFault>;
    /// Until when (virtual time) a `Control => True` motion keeps the
    /// robot busy: with tasks, a service call waits for it as for another
    /// task's motion (the services are a monitor).
    fn busy_until(&self) -> f64 {
        0.0
    }
    /// Until when (virtual time) the TeachBox was open: with tasks, a
    /// motion service another task calls before then does not wait (it
    /// raises `RobotBusy`), any other service waits for it.
    fn teach_until(&self) -> f64 {
        f64::NEG_INFINITY
    }
    /// Whether service `index` moves the arm or the hand.
    fn moves_the_arm(&self, _index: u32) -> bool {
        false
    }
}

/// The narrow part of a run that a service may use: the clock, the place
/// of the call, the user's stop request. Not the stack, not the program.
pub struct ServiceCx<'a> {
    pub clock: &'a mut dyn Clock,
    /// The simulated devices: the gripper picks and puts down their objects.
    pub world: Option<&'a mut crate::devices::World>,
    /// The call being served.
    pub span: Span,
    files: &'a [(String, Vec<u32>)],
    interrupted: Option<&'a std::sync::atomic::AtomicBool>,
}

impl ServiceCx<'_> {
    /// `file:line` of the call, as GNAT writes it.
    pub fn here(&self) -> String {
        location_in(self.files, self.span)
    }

    /// True (once) when the user has asked to stop (Ctrl-C).
    pub fn interrupt_requested(&self) -> bool {
        self.interrupted
            .is_some_and(|f| f.swap(false, std::sync::atomic::Ordering::SeqCst))
    }

    /// Paces `seconds` to the wall clock in short slices, stopping early
    /// when the user interrupts; returns the fraction done (1.0 = all).
    pub fn pace(&mut self, seconds: f64) -> f64 {
        pace(&mut *self.clock, self.interrupted, seconds)
    }
}

fn location_in(files: &[(String, Vec<u32>)], s: Span) -> String {
    match files.get(s.context as usize) {
        Some((name, starts)) => {
            let line = starts.partition_point(|&x| x <= s.start);
            format!("{name}:{line}")
        }
        None => String::new(),
    }
}

fn pace(
    clock: &mut dyn Clock,
    interrupted: Option<&std::sync::atomic::AtomicBool>,
    seconds: f64,
) -> f64 {
    if seconds <= 0.0 {
        return 1.0;
    }
    let slice: f64 = 0.05;
    let mut done = 0.0;
    while done < seconds {
        if interrupted.is_some_and(|f| f.swap(false, std::sync::atomic::Ordering::SeqCst)) {
            return done / seconds;
        }
        let step = slice.min(seconds - done);
        clock.pace(step);
        done += step;
    }
    1.0
}

pub struct Machine {
    stack: stack::Stack,
    display: Vec<usize>,
    pub out: Box<dyn Write>,
    /// Column of the output's current line (GNAT ends an unfinished line at exit).
    pub col: usize,
    pub clock: Box<dyn Clock>,
    natives: Vec<Option<Binding>>,
    depth: usize,
    calls: Vec<Span>,
    /// Line starts of each source, for GNAT-style exception messages.
    files: Vec<(String, Vec<u32>)>,
    pub input: Box<dyn std::io::BufRead>,
    /// What `Get_Line (Item, Last)` left of a line longer than Item (its
    /// terminator still to read): the next read starts with it. An empty
    /// rest is a line that filled Item exactly.
    pub line_rest: Option<String>,
    pub interrupted: Option<std::sync::Arc<std::sync::atomic::AtomicBool>>,
    /// Occurrences being handled (innermost last), for `raise;`.
    current: Vec<Rc<Occurrence>>,
    /// Binds an imported subprogram by its import name.
    pub resolver: fn(&str) -> Option<Binding>,
    /// The simulated devices (tasks.md): registers, belts, interrupts.
    pub world: Option<crate::devices::World>,
    /// Where `--trace` writes task switches, device events and interrupts.
    pub trace: Option<Box<dyn Write>>,
    /// Tasks and protected objects (empty without tasks). A run starts
    /// afresh unless `keep_tasks` (the REPL) keeps the tasks of earlier
    /// entries.
    pub(crate) sched: tasking::Sched,
    pub keep_tasks: bool,
    /// Interrupts that reached no entry (no live task has one bound to
    /// their address), so far.
    pub lost_interrupts: u64,
    /// `--realtime`: a `delay` (and every wait of tasks on the clock) takes
    /// its time on the wall clock too, as the motions do.
    pub realtime: bool,
    /// Interrupts raised between runs (`:irq`), delivered when the next run
    /// starts.
    pub pending_irqs: Vec<(crate::devices::Address, f64)>,
    /// The discriminants of the record values being built (innermost
    /// last), which `ExKind::Discriminant` reads.
    discrs: Vec<Vec<Value>>,
}

const MAX_DEPTH: usize = 20_000;
/// The largest array the interpreter builds (Storage_Error beyond).
const MAX_ELEMENTS: i64 = 50_000_000;

impl Machine {
    pub fn new(out: Box<dyn Write>) -> Machine {
        Machine {
            stack: stack::Stack::default(),
            display: vec![0; 4],
            out,
            col: 0,
            clock: Box::new(VirtualClock::default()),
            natives: Vec::new(),
            depth: 0,
            calls: Vec::new(),
            files: Vec::new(),
            input: Box::new(std::io::BufReader::new(std::io::stdin())),
            line_rest: None,
            interrupted: None,
            current: Vec::new(),
            resolver: |n| builtins::lookup(n).map(Binding::Native),
            world: Some(crate::devices::World::new(
                crate::devices::Devices::default_set(),
            )),
            trace: None,
            sched: tasking::Sched::default(),
            keep_tasks: false,
            lost_interrupts: 0,
            realtime: false,
            pending_irqs: Vec::new(),
            discrs: Vec::new(),
        }
    }

    pub fn add_source(&mut self, id: u32, name: &str, text: &str) {
        let id = id as usize;
        if self.files.len() <= id {
            self.files.resize(id + 1, (String::new(), Vec::new()));
        }
        let starts = crate::diag::line_starts(text);
        let base = std::path::Path::new(name)
            .file_name()
            .map(|s| s.to_string_lossy().to_string())
            .unwrap_or_default();
        self.files[id] = (base, starts);
    }

    /// `file:line` of a span, as GNAT writes it in exception messages.
    pub fn location(&self, s: Span) -> String {
        location_in(&self.files, s)
    }

    /// Runs level-0 statements (a script, a REPL entry or the library level),
    /// then the main subprogram, if any. `svc` serves the robot services
    /// for this run (None: a call of one raises `Program_Error`).
    pub fn run<'s>(
        &'s mut self,
        chk: ProgramRef<'s>,
        stmts: &'s [Stmt],
        main: Option<FuncId>,
        svc: Option<&'s mut dyn Services>,
    ) -> Result<(), Box<Occurrence>> {
        let need = self.prepare(chk);
        let _cap = memory::HardCap::arm();
        if self.keep_tasks && self.sched.active() && !self.sched.alive() {
            // Every task of earlier entries has ended and its frames are
            // gone: later tasks' frames start above this entry's slots.
            self.sched.floor = need + tasking::KEPT_HEADROOM;
            self.sched.holes.clear();
            self.reset_main();
        } else if self.keep_tasks && self.sched.alive() {
            // The REPL's tasks live on; the new entry's level-0 slots must
            // stay below their frames.
            if need + 1024 > self.sched.floor {
                return Err(Box::new(Occurrence {
                    exc: check::STORAGE_ERROR,
                    message: format!(
                        "too many declarations while tasks run ({need} level-0 slots; :reset starts afresh)"
                    ),
                    span: crate::diag::span(0, 0, 0),
                    chain: Vec::new(),
                    reraised: Vec::new(),
                    chained: true,
                    ending: crate::interp::Ending::Exception,
                }));
            }
            self.reset_main();
        }
        let arena = typed_arena::Arena::new();
        let mut run = Run {
            m: self,
            c: chk,
            svc,
            codes: vm::Codes::new(&arena),
        };
        let r = run.run_compiled(stmts, main);
        let tasks = run.m.sched.active();
        let alive = run.m.sched.alive();
        // The user's stop in a program with tasks (see `poll`): where each
        // task was, the main program's place first.
        let stopped = (tasks && matches!(r, Err(Flow::Exit(STOP_LABEL))))
            .then(|| run.m.sched.describe(run.c.tasks, run.c.prots, run.c.types));
        if !(run.m.keep_tasks && alive) {
            // Any frames left by an exception are dropped; level-0 slots stay.
            run.m.stack.truncate(need);
            // The REPL keeps the table of its ended tasks and protected
            // objects: an object of a later entry must not take an ended
            // task's number, and a call of one raises Tasking_Error.
            if !run.m.keep_tasks {
                run.m.sched = tasking::Sched::default();
            }
        }
        let _ = run.m.out.flush();
        match r {
            Err(Flow::Exit(STOP_LABEL)) if tasks => {
                let lines = stopped.unwrap_or_default();
                let mut message = String::from(STOPPED_TASKS);
                for (_, l) in &lines {
                    message.push('\n');
                    message.push_str(l);
                }
                Err(Box::new(Occurrence {
                    exc: check::PROGRAM_ERROR,
                    message,
                    span: lines.first().map_or(crate::diag::span(0, 0, 0), |l| l.0),
                    // The chain is the tasks' places, not calls.
                    chain: lines.iter().map(|l| l.0).collect(),
                    reraised: Vec::new(),
                    chained: true,
                    ending: crate::interp::Ending::Stopped,
                }))
            }
            Ok(()) | Err(Flow::Return(_)) | Err(Flow::Exit(_)) => Ok(()),
            Err(Flow::Raise(o)) => Err(o),
        }
    }

    /// Paces `seconds` to the wall clock in short slices, stopping early
    /// when the user interrupts; returns the fraction done (1.0 = all).
    pub fn pace(&mut self, seconds: f64) -> f64 {
        pace(&mut *self.clock, self.interrupted.as_deref(), seconds)
    }

    /// `:tasks`: every task and what it waits for.
    pub fn describe_tasks(&self, chk: ProgramRef<'_>) -> Vec<String> {
        self.sched
            .describe(chk.tasks, chk.prots, chk.types)
            .into_iter()
            .map(|(_, l)| l)
            .collect()
    }

    /// Before a REPL entry while tasks of earlier entries live: the main
    /// program (thread 0) starts afresh, out of every queue, its frames of
    /// an entry that ended blocked (a deadlock) freed.
    fn reset_main(&mut self) {
        let sc = &mut self.sched;
        for t in sc.threads.iter_mut() {
            for q in t.entries.iter_mut() {
                q.retain(|c| *c != 0);
            }
            t.rendezvous.retain(|c| *c != 0);
        }
        for p in sc.prots.iter_mut() {
            for q in p.queues.iter_mut() {
                q.retain(|c| *c != 0);
            }
        }
        sc.ready.retain(|c| *c != 0);
        let main = &mut sc.threads[0];
        // Registers the main program saved when it blocked are its old
        // entry's: the next switch away from it must not bring them back.
        main.display = Vec::new();
        main.current = Vec::new();
        main.depth = 0;
        main.calls = Vec::new();
        main.wait = tasking::Wait::Running;
        main.masters.clear();
        main.reexec = false;
        main.rerun = false;
        main.outcome = tasking::Outcome::Pending;
        let regions = main.regs.take().map(|r| r.regions()).unwrap_or_default();
        let never: Vec<tasking::Tid> = std::mem::take(&mut main.unactivated);
        for t in never {
            sc.threads[t].wait = tasking::Wait::Terminated;
        }
        sc.cur = 0;
        let len = self.stack.len();
        for (b, t) in regions {
            for v in &mut self.stack.as_mut_slice()[b.min(len)..t.min(len)] {
                *v = Value::Undef;
            }
        }
    }

    /// What compiles a long body a part at a time as it is checked, for
    /// a program this machine runs once.
    pub fn part_compiler(&self) -> Option<crate::check::ir::PartCompiler> {
        Some(vm::compile_part as crate::check::ir::PartCompiler)
    }

    /// Makes ready for a run at level 0: natives bound, the level-0 slots
    /// there (kept between runs), no frames. Returns the level-0 slot count.
    fn prepare(&mut self, chk: ProgramRef<'_>) -> usize {
        self.bind_natives(chk);
        // `--trace` shows what the devices do.
        if self.trace.is_some()
            && let Some(w) = self.world.as_mut()
        {
            w.set_logging(true);
        }
        let need = chk.globals as usize;
        self.stack.grow_to(need);
        if self.display.is_empty() {
            // A REPL entry ended with every thread blocked (a deadlock):
            // the machine holds the idle registers, and the main program
            // starts afresh (`reset_main` drops its old frames).
            self.display = vec![0; 4];
            self.current.clear();
        }
        self.display[0] = 0;
        self.depth = 0;
        self.calls.clear();
        need
    }

    /// Evaluates one checked expression at level 0 (a REPL entry).
    pub fn eval_expr<'s>(
        &'s mut self,
        chk: ProgramRef<'s>,
        e: &Ex,
        svc: Option<&'s mut dyn Services>,
    ) -> Result<Value, Box<Occurrence>> {
        let need = self.prepare(chk);
        let _cap = memory::HardCap::arm();
        let arena = typed_arena::Arena::new();
        let mut run = Run {
            m: self,
            c: chk,
            svc,
            codes: vm::Codes::new(&arena),
        };
        let r = run.eval_table(e);
        if !(run.m.keep_tasks && run.m.sched.alive()) {
            run.m.stack.truncate(need);
        }
        let _ = run.m.out.flush();
        match r {
            Ok(v) => Ok(v),
            Err(Flow::Raise(o)) => Err(o),
            Err(_) => Ok(Value::Undef),
        }
    }

    /// Ends the program's output as GNAT does: an unfinished line gets its newline.
    pub fn finish(&mut self) {
        if self.col != 0 {
            let _ = self.out.write_all(b"\n");
            self.col = 0;
        }
        let _ = self.out.flush();
    }

    fn bind_natives(&mut self, chk: ProgramRef<'_>) {
        while self.natives.len() < chk.funcs.len() {
            let i = self.natives.len();
            self.natives
                .push(chk.imports[i].as_deref().and_then(self.resolver));
        }
    }

    /// Puts `globals` in place of the level-0 data and returns what was
    /// there (a rehearsal runs on a copy, then the original comes back).
    pub fn swap_globals(&mut self, globals: Vec<Value>) -> Vec<Value> {
        std::mem::replace(&mut self.stack, globals.into()).into_vec()
    }

    /// A deep copy of the level-0 data: arrays, records and the objects
    /// reached through access values are new, with their aliasing kept, so
    /// that nothing a run does to the copy reaches the original.
    pub fn copy_globals(&self) -> Vec<Value> {
        let mut seen = std::collections::HashMap::new();
        let mut todo = Vec::new();
        let copy = self
            .stack
            .as_slice()
            .iter()
            .map(|v| deep_copy(v, &mut seen, &mut todo))
            .collect();
        // Objects are filled in a loop, not by recursion along their
        // accesses (a long list would overflow the native stack).
        while let Some((from, to)) = todo.pop() {
            let inner = deep_copy(&from.get(), &mut seen, &mut todo);
            to.set(inner);
        }
        copy
    }

    /// The value of a level-0 variable (for the REPL).
    pub fn global(&self, v: Var) -> Option<&Value> {
        self.stack.get(v.slot as usize)
    }

    pub fn write_str(&mut self, s: &str) {
        let _ = self.out.write_all(s.as_bytes());
        match s.rfind('\n') {
            Some(i) => self.col = s.len() - i - 1,
            None => self.col += s.len(),
        }
    }
}

/// A copy of `v` that shares no mutable object with it; `seen` maps each
/// designated object already copied to its copy (aliasing and cycles kept).
/// A newly met object's copy is made empty and queued in `todo` with its
/// original, for the caller to fill.
fn deep_copy(
    v: &Value,
    seen: &mut std::collections::HashMap<*const (), Obj>,
    todo: &mut Vec<(Obj, Obj)>,
) -> Value {
    match v {
        Value::Arr(a) => Value::Arr(match a.data() {
            value::Elems::Vals(v) => {
                let mut c = Array::with_capacity(value::Form::Vals, v.len());
                for x in v {
                    c.push(deep_copy(x, seen, todo));
                }
                c.with_bounds(a.bounds())
            }
            // Scalars: a copy of the block.
            _ => {
                let mut c = a.clone();
                c.make_mut();
                c
            }
        }),
        v if v.is_record() => Value::record(
            v.fields()
                .unwrap_or_default()
                .iter()
                .map(|x| deep_copy(x, seen, todo))
                .collect(),
        ),
        Value::Ptr(Some(p)) => {
            if let Some(c) = seen.get(&p.addr()) {
                return Value::Ptr(Some(c.clone()));
            }
            let c = Obj::new(Value::Undef);
            seen.insert(p.addr(), c.clone());
            todo.push((p.clone(), c.clone()));
            Value::Ptr(Some(c))
        }
        other => other.clone(),
    }
}

/// One run: the machine plus the program's tables, and the robot services
/// the session lent it.
pub struct Run<'a, 'c> {
    pub m: &'a mut Machine,
    pub c: ProgramRef<'a>,
    svc: Option<&'a mut dyn Services>,
    /// The compiled engine's code of this run: each body compiled on its
    /// first call (and kept for the run), in an arena that outlives it.
    codes: vm::Codes<'c>,
}

/// One step of an assignment's path from its root to the part written.
pub(crate) enum Step {
    Index(Vec<i64>, Span),
    Field(u32),
    /// The record's discriminants must choose the variant of a component.
    Variant(value::Variant, Span),
    Slice(i64, i64, Span),
}

/// Where an assignment's path begins (see [`Run::store`]).
pub(crate) enum Root {
    /// A variable's stack slot.
    Slot(usize),
    /// The object an access value designates (`P.all`), and where its
    /// access check fails.
    Ptr(Value, Span),
    /// A device register (its address and type): read, changed, written back.
    Register(u32, TypeId, Span),
    /// Not a variable (a checker error left in the program).
    NotVariable(Span),
}

impl<'c> Run<'_, 'c> {
    pub fn raise(&self, exc: ExcId, msg: impl Into<String>, span: Span) -> Flow {
        let mut chain: Vec<Span> = self.m.calls.clone();
        chain.reverse();
        Flow::Raise(Box::new(Occurrence {
            exc,
            message: msg.into(),
            span,
            chain,
            reraised: Vec::new(),
            chained: false,
            ending: crate::interp::Ending::Exception,
        }))
    }

    /// A `'Value` of text that is no value of the type: GNAT's message, with
    /// the text and without a location (`bad input for 'Value: "12x"`).
    fn bad_value(&self, text: &Value, span: Span) -> Flow {
        let msg = format!("bad input for 'Value: \"{}\"", text.text());
        self.raise(check::CONSTRAINT_ERROR, msg, span)
    }

    /// `Constraint_Error` with GNAT's message form (`file.adb:9 index check failed`).
    fn check_failed(&self, what: &str, span: Span) -> Flow {
        let loc = self.m.location(span);
        self.raise(check::CONSTRAINT_ERROR, format!("{loc} {what}"), span)
    }

    /// `Storage_Error` at `span` unless `values` more values fit in the
    /// program's memory limit (`--max-memory`).
    fn reserve(&self, values: i64, span: Span) -> R<()> {
        let bytes = (values.max(0) as usize).saturating_mul(std::mem::size_of::<Value>());
        if memory::room_for(bytes) {
            return Ok(());
        }
        let mib = |b: usize| b.div_ceil(1 << 20);
        Err(self.raise(
            check::STORAGE_ERROR,
            format!(
                "out of memory: {} MiB more would pass the limit of {} MiB (--max-memory)",
                mib(bytes),
                mib(memory::limit())
            ),
            span,
        ))
    }

    pub fn exc_by_name(&self, full: &str) -> ExcId {
        self.c
            .excs
            .iter()
            .position(|e| e.name == full)
            .map(|i| i as ExcId)
            .unwrap_or(check::PROGRAM_ERROR)
    }

    /// Checks for a user interrupt (Ctrl-C in the REPL) at loop heads.
    fn poll(&mut self, span: Span) -> R<()> {
        // A plain load first: a swap on every loop step costs a locked
        // instruction.
        if let Some(flag) = &self.m.interrupted
            && flag.load(std::sync::atomic::Ordering::Relaxed)
            && flag.swap(false, std::sync::atomic::Ordering::SeqCst)
        {
            // With tasks, the user's stop ends the whole program (an
            // exception would end only the task that saw it); the report
            // says where each task was.
            if self.m.sched.active() {
                let me = self.m.sched.cur;
                self.m.sched.threads[me].at = span;
                return Err(Flow::Exit(STOP_LABEL));
            }
            return Err(self.raise(check::PROGRAM_ERROR, "interrupted (Ctrl-C)", span));
        }
        Ok(())
    }

    /// Hands a service call to the lent services with a narrow context.
    fn call_service(&mut self, i: u32, args: &mut [Value], span: Span) -> R<Option<Value>> {
        self.world_sync();
        let Some(svc) = self.svc.as_deref_mut() else {
            return Err(self.raise(
                check::PROGRAM_ERROR,
                "no robot: this session was started without one (choose one with --robot)",
                span,
            ));
        };
        // With tasks, a motion blocks only its caller: the service runs on
        // a clock that keeps the time it takes, and the caller then waits
        // that long on the virtual clock while the other tasks run. Once
        // every task has ended (the REPL keeps their table), it is a plain
        // call again.
        let tasks = self.m.sched.alive();
        let mut deferred = tasking::DeferClock {
            base: self.m.clock.now(),
            spent: 0.0,
        };
        let clock: &mut dyn Clock = if tasks {
            &mut deferred
        } else {
            &mut *self.m.clock
        };
        let mut cx = ServiceCx {
            clock,
            world: self.m.world.as_mut(),
            span,
            files: &self.m.files,
            interrupted: self.m.interrupted.as_deref(),
        };
        let r = svc.call(i, &mut cx, args);
        if tasks && deferred.spent > 0.0 && r.is_ok() {
            let until = deferred.base + deferred.spent;
            self.m.sched.robot_free_at = until;
            self.m.sched.block(tasking::Wait::Delay(until), false, span);
        }
        match r {
            Ok(v) => Ok(v),
            Err(ServiceFault::Raise(exc, msg)) => Err(self.raise(exc, msg, span)),
            Err(ServiceFault::Stop) => Err(Flow::Exit(STOP_LABEL)),
        }
    }

    /// Whether `f` is a robot service.
    pub(crate) fn is_service(&self, f: FuncId) -> bool {
        matches!(
            self.m.natives.get(f as usize),
            Some(Some(Binding::Service(_)))
        )
    }

    /// A native subprogram or a robot service called with its arguments'
    /// values (its `out` values are left in `vals`).
    fn call_binding(
        &mut self,
        binding: Binding,
        vals: &mut [Value],
        span: Span,
    ) -> R<Option<Value>> {
        self.m.calls.push(span);
        let r = match binding {
            Binding::Native(native) => native(self, vals, span),
            Binding::Service(i) => self.call_service(i, vals, span),
        };
        self.m.calls.pop();
        r
    }

    /// The compiled engine's call of a subprogram it does not compile: a
    /// native or service (`out` values left in `vals`), or one without a
    /// body (Program_Error).
    pub(crate) fn call_native(
        &mut self,
        f: FuncId,
        vals: &mut [Value],
        span: Span,
    ) -> R<Option<Value>> {
        self.call_guard(span)?;
        match self.m.natives.get(f as usize).copied().flatten() {
            Some(binding) => self.call_binding(binding, vals, span),
            None => Err(self.raise(
                check::PROGRAM_ERROR,
                format!("`{}` has no body", self.c.funcs[f as usize].name),
                span,
            )),
        }
    }

    /// Before every call, in both engines: Ctrl-C (also in a recursion
    /// that polls no loop), and the depth limit (Storage_Error).
    #[inline(always)]
    pub(crate) fn call_guard(&mut self, span: Span) -> R<()> {
        if let Some(flag) = &self.m.interrupted
            && flag.load(std::sync::atomic::Ordering::Relaxed)
        {
            self.poll(span)?;
        }
        if self.m.depth >= MAX_DEPTH {
            return Err(self.raise(
                check::STORAGE_ERROR,
                "stack overflow (recursion too deep)",
                span,
            ));
        }
        Ok(())
    }

    // ---- places ----

    /// Writes `val` to the part of `root` that `steps` lead to, with the
    /// checks of each step and of the value's bounds (what both engines
    /// run for an assignment to a component, an element, a slice or an
    /// array).
    pub(crate) fn store(&mut self, root: Root, steps: &[Step], val: Value, at: Span) -> R<()> {
        let fail = |this: &Self, (what, sp): (&'static str, Span)| this.check_failed(what, sp);
        match root {
            Root::Slot(i) => {
                write_path(&mut self.m.stack[i], steps, val, at).map_err(|e| fail(self, e))
            }
            Root::Ptr(ptr, sp) => {
                let Value::Ptr(Some(rc)) = ptr else {
                    return Err(self.check_failed("access check failed", sp));
                };
                rc.update(|b| write_path(b, steps, val, at))
                    .map_err(|e| fail(self, e))
            }
            Root::Register(a, ty, sp) => {
                let mut word = self.read_register(a, ty, sp)?;
                write_path(&mut word, steps, val, at).map_err(|e| fail(self, e))?;
                self.write_register(a, &word, sp)
            }
            Root::NotVariable(sp) => Err(self.raise(check::PROGRAM_ERROR, "not a variable", sp)),
        }
    }

    // ---- expressions ----

    fn int_op(&self, op: IntOp, x: i64, y: i64, span: Span) -> R<i64> {
        let r = match op {
            IntOp::Add => x + y,
            IntOp::Sub => x - y,
            IntOp::Mul => x.checked_mul(y).unwrap_or(i64::MAX),
            IntOp::Div => {
                if y == 0 {
                    return Err(self.check_failed("divide by zero", span));
                }
                x / y
            }
            IntOp::Rem => {
                if y == 0 {
                    return Err(self.check_failed("divide by zero", span));
                }
                x % y
            }
            IntOp::Mod => {
                if y == 0 {
                    return Err(self.check_failed("divide by zero", span));
                }
                let m = x % y;
                if m != 0 && ((m < 0) != (y < 0)) {
                    m + y
                } else {
                    m
                }
            }
            IntOp::Pow => {
                if y < 0 {
                    return Err(self.check_failed("range check failed", span));
                }
                let mut acc: i64 = 1;
                for _ in 0..y.min(64) {
                    acc = acc.checked_mul(x).unwrap_or(i64::MAX);
                    if acc.abs() > i32::MAX as i64 + 1 {
                        break;
                    }
                }
                if y > 64 && x.abs() > 1 {
                    i64::MAX
                } else if y > 64 {
                    if x == -1 && y % 2 == 1 { -1 } else { x.abs() }
                } else {
                    acc
                }
            }
        };
        if r < i32::MIN as i64 || r > i32::MAX as i64 {
            return Err(self.check_failed("overflow check failed", span));
        }
        Ok(r)
    }

    /// Low and high bound of a scalar subtype.
    pub(crate) fn type_bounds(&mut self, t: TypeId) -> R<(Value, Value)> {
        let info = self.c.types.get(t);
        if let Some((l, h)) = info.static_range {
            return Ok((Value::Int(l as i64), Value::Int(h as i64)));
        }
        if let Some((l, h)) = info.static_frange {
            return Ok((Value::Real(l), Value::Real(h)));
        }
        if let Some((l, h)) = &info.range {
            return Ok((self.eval_table(l)?, self.eval_table(h)?));
        }
        Ok(match self.c.types.kind(t) {
            TypeKind::Enum(l) => (Value::Int(0), Value::Int(l.len() as i64 - 1)),
            TypeKind::Float => (Value::Real(-f64::MAX), Value::Real(f64::MAX)),
            _ => (Value::Int(i32::MIN as i64), Value::Int(i32::MAX as i64)),
        })
    }

    fn range_check(&mut self, v: &Value, t: TypeId, span: Span) -> R<()> {
        if let Some(r) = v.fields() {
            return self.discriminant_check(r, t, span);
        }
        let info = self.c.types.get(t);
        let ok = match (v, info.static_range, info.static_frange) {
            (Value::Int(x), Some((l, h)), _) => (l as i64) <= *x && *x <= (h as i64),
            (Value::Real(x), _, Some((l, h))) => l <= *x && *x <= h,
            _ => {
                let (l, h) = self.type_bounds(t)?;
                v.compare(&l) != std::cmp::Ordering::Less
                    && v.compare(&h) != std::cmp::Ordering::Greater
            }
        };
        if ok {
            Ok(())
        } else {
            Err(self.check_failed("range check failed", span))
        }
    }

    /// Bounds of a constrained array subtype.
    fn array_bounds(&mut self, t: TypeId) -> R<Option<value::Bounds>> {
        let types = self.c.types;
        let Some((_, _, Some(bs))) = types.array(t) else {
            return Ok(None);
        };
        let mut out = value::Bounds::with_capacity(bs.len());
        for (l, h) in bs {
            out.push((self.eval_table(l)?.int(), self.eval_table(h)?.int()));
        }
        Ok(Some(out))
    }

    pub(crate) fn array_convert(&mut self, v: Value, t: TypeId, span: Span) -> R<Value> {
        let Some(bounds) = self.array_bounds(t)? else {
            return Ok(v);
        };
        let Value::Arr(mut a) = v else { return Ok(v) };
        if a.bounds() == &bounds[..] {
            return Ok(Value::Arr(a));
        }
        for (d, (l, h)) in bounds.iter().enumerate() {
            if a.len(d) != (h - l + 1).max(0) {
                return Err(self.check_failed("length check failed", span));
            }
        }
        a.set_bounds(&bounds);
        Ok(Value::Arr(a))
    }

    /// A record value whose component of the variant `conds` is read or
    /// written: its discriminants choose that variant (RM 4.1.3(15)),
    /// else "discriminant check failed". Both engines call it.
    pub(crate) fn variant_check(
        &self,
        v: &Value,
        conds: &[check::types::Governs],
        span: Span,
    ) -> R<()> {
        match v {
            v if v.fields().is_some_and(|r| value::variant_holds(r, conds)) => Ok(()),
            _ => Err(self.check_failed("discriminant check failed", span)),
        }
    }

    /// The value assigned to a record object constrained by its initial
    /// value or by its actual: its `n` discriminants are the object's
    /// (RM 5.2(10)), else "discriminant check failed". Both engines call it.
    pub(crate) fn same_discriminants(&self, v: &Value, cur: &Value, n: usize, span: Span) -> R<()> {
        match (v.fields(), cur.fields()) {
            (Some(a), Some(b)) if a.get(..n) == b.get(..n) => Ok(()),
            _ => Err(self.check_failed("discriminant check failed", span)),
        }
    }

    /// A record value of the subtype `t` (RM 3.7.1, 4.6(51)): its
    /// discriminants are those of `t`'s discriminant constraint, if it has
    /// one ("discriminant check failed").
    fn discriminant_check(&mut self, r: &[Value], t: TypeId, span: Span) -> R<()> {
        let types = self.c.types;
        let Some(want) = types.discriminant_constraint(t) else {
            return Ok(());
        };
        for (i, w) in want.iter().enumerate() {
            let w = self.eval_table(w)?;
            if r.get(i) != Some(&w) {
                return Err(self.check_failed("discriminant check failed", span));
            }
        }
        Ok(())
    }

    /// A record value of the type `t` just built, with its discriminants
    /// in reach (`Machine::discrs`): the components of the variants not
    /// chosen are cleared (so that equality compares the chosen ones), and
    /// a component whose subtype reads the discriminants fits it (length
    /// check and sliding of an array, discriminant check of a record).
    fn shape_record(&mut self, t: TypeId, v: &mut value::Fields, span: Span) -> R<()> {
        let types = self.c.types;
        let TypeKind::Record(fields) = types.kind(t) else {
            return Ok(());
        };
        for (i, f) in fields.iter().enumerate() {
            if let Some(conds) = &f.variant
                && !value::variant_holds(v, conds)
            {
                v[i] = Value::Undef;
                continue;
            }
            if let Some(dep) = f.dependent {
                let x = std::mem::take(&mut v[i]);
                v[i] = self.fit_subtype(x, dep, span)?;
            }
        }
        Ok(())
    }

    /// A value converted to a subtype: an array slides to its bounds (the
    /// same length), a scalar or record is checked against it.
    fn fit_subtype(&mut self, x: Value, t: TypeId, span: Span) -> R<Value> {
        match x {
            Value::Arr(_) => self.array_convert(x, t, span),
            _ => {
                self.range_check(&x, t, span)?;
                Ok(x)
            }
        }
    }

    /// The default value of a record type with discriminants: those of the
    /// subtype's constraint, else their defaults; then the components of
    /// the variant they choose, with the discriminants in reach.
    fn default_record(&mut self, t: TypeId, fields: &[Field], nd: usize, span: Span) -> R<Value> {
        let v = self.discriminant_values(t, &fields[..nd], span)?;
        self.record_of_discriminants(fields, v, span)
    }

    /// The discriminants of a new object of subtype `t` (its `ds`): its
    /// constraint's values, else their defaults.
    pub(crate) fn discriminant_values(
        &mut self,
        t: TypeId,
        ds: &[Field],
        span: Span,
    ) -> R<Vec<Value>> {
        let types = self.c.types;
        let mut v = Vec::with_capacity(ds.len());
        match types.discriminant_constraint(t) {
            Some(cs) => {
                for c in cs {
                    v.push(self.eval_table(c)?);
                }
            }
            None => {
                for f in ds {
                    v.push(match &f.default {
                        Some(d) => self.eval_table(d)?,
                        None => self.default_value(f.ty, span)?,
                    });
                }
            }
        }
        Ok(v)
    }

    /// A record value of these components whose discriminants (the first
    /// ones) are `discrs`: the other components' defaults, read under them.
    pub(crate) fn record_of_discriminants(
        &mut self,
        fields: &[Field],
        discrs: Vec<Value>,
        span: Span,
    ) -> R<Value> {
        let nd = discrs.len();
        let mut v = value::Fields::with_capacity(fields.len());
        v.extend(discrs.iter().cloned());
        self.m.discrs.push(discrs);
        let r = (|| {
            for f in &fields[nd..] {
                if let Some(conds) = &f.variant
                    && !value::variant_holds(&v, conds)
                {
                    v.push(Value::Undef);
                    continue;
                }
                v.push(match &f.default {
                    Some(d) => self.eval_table(d)?,
                    None => self.default_value(f.dependent.unwrap_or(f.ty), span)?,
                });
            }
            Ok(())
        })();
        self.m.discrs.pop();
        r?;
        Ok(Value::record(v))
    }

    pub fn default_value(&mut self, t: TypeId, span: Span) -> R<Value> {
        let types = self.c.types;
        Ok(match types.kind(t) {
            TypeKind::Float => Value::Real(0.0),
            TypeKind::Record(fields) if fields.first().is_some_and(|f| f.discriminant) => {
                let nd = fields.iter().take_while(|f| f.discriminant).count();
                self.default_record(t, fields, nd, span)?
            }
            TypeKind::Record(fields) => {
                let mut v = value::Fields::with_capacity(fields.len());
                for f in fields {
                    v.push(match &f.default {
                        Some(d) => self.eval_table(d)?,
                        None => self.default_value(f.ty, span)?,
                    });
                }
                Value::record(v)
            }
            TypeKind::Task(k) => self.create_task(*k, t, span)?,
            TypeKind::Protected(k) => self.create_protected(*k, t, span)?,
            &TypeKind::Array { elem, .. } => {
                let bounds = self.array_bounds(t)?.unwrap_or_default();
                let n: i64 = bounds
                    .iter()
                    .map(|(l, h)| (h - l + 1).max(0))
                    .fold(1i64, |a, b| a.saturating_mul(b));
                if n > MAX_ELEMENTS {
                    return Err(self.raise(
                        check::STORAGE_ERROR,
                        format!("an array of {n} components is too large (at most {MAX_ELEMENTS})"),
                        span,
                    ));
                }
                self.reserve(n, span)?;
                let data = if self.c.types.is_unique(elem) || !self.default_repeatable(elem) {
                    // Each component its own task or protected object, or
                    // its own evaluation of its defaults (RM 3.3.1(18-20):
                    // `V : Integer := Next;`, `P : Ptr := new ...`).
                    let mut v = Vec::with_capacity(n as usize);
                    for _ in 0..n {
                        v.push(self.default_value(elem, span)?);
                    }
                    Array::from_vals(v).with_bounds(&bounds)
                } else {
                    let d = self.default_value(elem, span)?;
                    Array::repeat_in(d, n as usize, &bounds)
                };
                Value::Arr(data)
            }
            TypeKind::Access(_) => Value::Ptr(None),
            TypeKind::Time => Value::Real(0.0),
            _ => match self.c.types.get(t).static_range {
                // An uninitialised scalar: the lower bound when it is positive, else 0.
                Some((l, _)) if l > 0 => Value::Int(l as i64),
                _ => Value::Int(0),
            },
        })
    }

    fn concat(
        &mut self,
        x: Value,
        y: Value,
        xe: bool,
        ye: bool,
        t: TypeId,
        span: Span,
    ) -> R<Value> {
        let first_of_index = || -> i64 {
            self.c
                .types
                .array(t)
                .and_then(|(i, _, _)| i.first().copied())
                .and_then(|it| self.c.types.get(it).static_range)
                .map(|r| r.0 as i64)
                .unwrap_or(1)
        };
        let len = |v: &Value, elem: bool| match (v, elem) {
            (Value::Arr(a), false) => a.len_all() as i64,
            _ => 1,
        };
        let n = len(&x, xe) + len(&y, ye);
        self.reserve(n, span)?;
        let (mut data, lo) = match (x, xe) {
            (v, true) => (Array::from_vals(vec![v]), first_of_index()),
            (Value::Arr(a), false) => {
                if a.len_all() == 0 {
                    // An empty left operand: the result is the right operand.
                    return Ok(match (y, ye) {
                        (v, true) => {
                            let one = Array::from_vals(vec![v]);
                            Value::Arr(Array::vector(first_of_index(), one))
                        }
                        (v, false) => v,
                    });
                }
                let lo = a.bounds()[0].0;
                // The left operand's components, kept in place when no
                // one else holds them (else copied), with room for the
                // right one's.
                let mut data = a;
                data.reserve((n as usize).saturating_sub(data.len_all()));
                (data, lo)
            }
            _ => (Array::default(), 1),
        };
        match (y, ye) {
            (v, true) => data.push(v),
            (Value::Arr(b), false) => data.extend_from(b.data()),
            _ => {}
        }
        let hi = lo + data.len_all() as i64 - 1;
        if hi > i32::MAX as i64 {
            return Err(self.check_failed("range check failed", span));
        }
        Ok(Value::Arr(Array::vector(lo, data)))
    }

    /// Whether a value of `t` by default can be computed once and copied
    /// (its components' defaults are [`Self::repeatable`]).
    fn default_repeatable(&self, t: TypeId) -> bool {
        match self.c.types.kind(t) {
            TypeKind::Record(fs) => fs.iter().all(|f| match &f.default {
                Some(d) => aggregate::repeatable(self.c.types, d),
                None => self.default_repeatable(f.ty),
            }),
            TypeKind::Array { elem, .. } => self.default_repeatable(*elem),
            _ => true,
        }
    }

    /// Builds an array from its first-dimension components (elements, or rows
    /// of the remaining dimensions).
    fn rows_to_array(
        &mut self,
        vals: Vec<Value>,
        first: (i64, i64),
        fixed: Option<value::Bounds>,
        dims: usize,
        span: Span,
    ) -> R<Value> {
        let multi = fixed.as_ref().map(|b| b.len() > 1).unwrap_or(false)
            || matches!(vals.first(), Some(Value::Arr(_))) && dims > 1;
        if !multi {
            return Ok(Value::Arr(Array::from_vals(vals).with_bounds(&[first])));
        }
        let mut bounds: value::Bounds = smallvec::smallvec![first];
        // Every row as long as the first (checked below).
        let row_len = match vals.first() {
            Some(Value::Arr(r)) => r.len_all(),
            _ => 0,
        };
        // The bounds' number known before the components go in (setting
        // the bounds then moves nothing).
        let dims = match (&fixed, vals.first()) {
            (Some(f), _) => f.len(),
            (None, Some(Value::Arr(r))) => r.bounds().len() + 1,
            _ => 1,
        };
        let mut data = match vals.first() {
            Some(Value::Arr(r)) => Array::with_capacity_dims(
                r.form(),
                dims,
                vals.len()
                    .saturating_mul(row_len)
                    .min(MAX_ELEMENTS as usize),
            ),
            _ => Array::default(),
        };
        let mut inner: Option<value::Bounds> = None;
        for v in vals {
            let Value::Arr(row) = v else {
                return Err(self.check_failed("length check failed", span));
            };
            match &inner {
                None => inner = Some(row.bounds().iter().copied().collect()),
                Some(b) => {
                    if b.iter()
                        .zip(row.bounds())
                        .any(|(x, y)| x.1 - x.0 != y.1 - y.0)
                    {
                        return Err(self.check_failed("length check failed", span));
                    }
                }
            }
            data.extend_from(row.data());
        }
        let inner = match fixed {
            Some(f) => f[1..].iter().copied().collect(),
            None => inner.unwrap_or_default(),
        };
        bounds.extend(inner);
        Ok(Value::Arr(data.with_bounds(&bounds)))
    }

    /// A unary operation on a value (what both engines run).
    pub(crate) fn unary_of(&mut self, op: UnOp, v: Value, span: Span) -> R<Value> {
        Ok(match op {
            UnOp::FloatNeg => Value::Real(-v.real()),
            UnOp::FloatAbs => Value::Real(v.real().abs()),
            UnOp::IntAbs => {
                let x = v.int().abs();
                if x > i32::MAX as i64 {
                    return Err(self.check_failed("overflow check failed", span));
                }
                Value::Int(x)
            }
            UnOp::FloatToInt => {
                let r = v.real().round();
                if !(r >= i32::MIN as f64 && r <= i32::MAX as f64) {
                    // Outside the 32-bit base type: GNAT's "overflow check".
                    return Err(self.check_failed("overflow check failed", span));
                }
                Value::Int(r as i64)
            }
            UnOp::Deref => match v {
                Value::Ptr(Some(rc)) => rc.get(),
                _ => return Err(self.check_failed("access check failed", span)),
            },
            UnOp::ArrNot => {
                let Value::Arr(x) = v else {
                    return Err(self.check_failed("access check failed", span));
                };
                bool_array(&x, x.data().iter().map(|p| p.int() == 0))
            }
            UnOp::ArrayConvert(t) => self.array_convert(v, t, span)?,
        })
    }

    /// `x op y` of two Boolean arrays (what both engines run).
    pub(crate) fn arr_logic(&self, op: LogicOp, x: &Value, y: &Value, span: Span) -> R<Value> {
        let (Value::Arr(x), Value::Arr(y)) = (x, y) else {
            return Err(self.check_failed("access check failed", span));
        };
        if x.len_all() != y.len_all() {
            return Err(self.check_failed("length check failed", span));
        }
        Ok(bool_array(
            x,
            x.data().iter().zip(y.data().iter()).map(|(p, q)| {
                let (p, q) = (p.int() != 0, q.int() != 0);
                match op {
                    LogicOp::Or | LogicOp::OrElse => p || q,
                    LogicOp::Xor => p ^ q,
                    LogicOp::And | LogicOp::AndThen => p && q,
                }
            }),
        ))
    }

    /// The occurrence a `raise E [with Msg];` statement raises (what both
    /// engines run).
    pub(crate) fn raise_stmt(&mut self, e: ExcId, msg: Option<Value>, span: Span) -> Flow {
        let m = match msg {
            Some(x) => x.text(),
            // GNAT: the place, and for the language-defined checks'
            // exceptions "explicit raise" (`file.adb:6 explicit raise`).
            None if matches!(
                e,
                check::CONSTRAINT_ERROR | check::PROGRAM_ERROR | check::STORAGE_ERROR
            ) =>
            {
                format!("{} explicit raise", self.m.location(span))
            }
            None => self.m.location(span),
        };
        self.raise(e, m, span)
    }

    /// What a `raise;` statement raises: the handler's occurrence again
    /// (what both engines run).
    pub(crate) fn reraise(&mut self, span: Span) -> Flow {
        // The handler keeps the current occurrence in a hidden slot.
        match self.m.current.last().cloned() {
            Some(o) => {
                let mut o = (*o).clone();
                o.reraised.push(span);
                Flow::Raise(Box::new(o))
            }
            None => self.raise(check::PROGRAM_ERROR, "no exception to re-raise", span),
        }
    }

    /// `base (l .. h)` (what both engines run).
    pub(crate) fn slice_of(&mut self, base: &Value, l: i64, h: i64, span: Span) -> R<Value> {
        let Value::Arr(a) = base else {
            return Err(self.check_failed("access check failed", span));
        };
        if l > h {
            return Ok(Value::Arr(
                Array::with_capacity(a.form(), 0).with_bounds(&[(l, h)]),
            ));
        }
        let (lo, hi) = a.bounds()[0];
        if l < lo || h > hi {
            return Err(self.check_failed("range check failed", span));
        }
        self.reserve(h - l + 1, span)?;
        let data = a.data().slice((l - lo) as usize..(h - lo + 1) as usize);
        Ok(Value::Arr(Array::from_elems(l, data)))
    }

    /// An attribute of its evaluated arguments (`a0`, `a1`: `Undef` when
    /// it has fewer; `ty` is the attribute's type): what both engines run.
    pub(crate) fn attr_of(
        &mut self,
        op: AttrOp,
        a0: Value,
        a1: Value,
        ty: TypeId,
        sp: Span,
    ) -> R<Value> {
        Ok(match op {
            AttrOp::Callable
            | AttrOp::Terminated
            | AttrOp::Count(_)
            | AttrOp::ProtCount(_)
            | AttrOp::TaskDiscriminant(_) => self.task_attr(op, &[a0, a1]),
            AttrOp::ArrFirst(d) | AttrOp::ArrLast(d) | AttrOp::ArrLength(d) => {
                let Value::Arr(a) = a0 else {
                    return Err(self.check_failed("access check failed", sp));
                };
                let d = d as usize - 1;
                match op {
                    AttrOp::ArrFirst(_) => Value::Int(a.bounds()[d].0),
                    AttrOp::ArrLast(_) => Value::Int(a.bounds()[d].1),
                    _ => Value::Int(a.len(d)),
                }
            }
            AttrOp::ImageInt => Value::Arr(Array::from_elems(
                1,
                value::Elems::Bytes(&value::image_int_bytes(a0.int())),
            )),
            AttrOp::ImageFloat(d) => Value::string(value::image_float_digits(a0.real(), d as u32)),
            AttrOp::ImageDuration => Value::string(value::image_duration(a0.real())),
            AttrOp::ImageChar => {
                let c = char::from_u32(a0.int() as u32).unwrap_or('?');
                Value::str(&crate::check::types::char_image(c))
            }
            AttrOp::ImageEnum(t) => {
                let lits = self.c.types.enum_lits(t).unwrap_or(&[]);
                Value::str(lits.get(a0.int() as usize).map(|l| &**l).unwrap_or("?"))
            }
            AttrOp::ValueInt => match (value::value_int(&a0.text()), self.c.types.modulus(ty)) {
                // A modular type's values are 0 .. modulus - 1.
                (Some(v), Some(n)) if (0..n).contains(&v) => Value::Int(v),
                (Some(v), None) if v >= i32::MIN as i64 && v <= i32::MAX as i64 => Value::Int(v),
                _ => return Err(self.bad_value(&a0, sp)),
            },
            AttrOp::ValueFloat => match value::value_float(&a0.text()) {
                Some(v) => Value::Real(v),
                None => return Err(self.bad_value(&a0, sp)),
            },
            AttrOp::ValueEnum(t) => {
                let s = a0.text();
                let s = s.trim();
                let lits = self.c.types.enum_lits(t).unwrap_or(&[]);
                let found = if t == crate::check::types::CHARACTER {
                    let cs: Vec<char> = s.chars().collect();
                    (cs.len() == 3 && cs[0] == '\'' && cs[2] == '\'').then(|| cs[1] as usize)
                } else {
                    lits.iter().position(|l| l.eq_ignore_ascii_case(s))
                };
                match found {
                    Some(i) => Value::Int(i as i64),
                    None => return Err(self.bad_value(&a0, sp)),
                }
            }
            AttrOp::Succ | AttrOp::Pred => {
                let v = a0.int() + if op == AttrOp::Succ { 1 } else { -1 };
                // Past the base type's bounds: GNAT's overflow check.
                let (lo, hi) = self.type_bounds(ty)?;
                if v < lo.int() || v > hi.int() {
                    return Err(self.check_failed("overflow check failed", sp));
                }
                Value::Int(v)
            }
            AttrOp::Pos | AttrOp::Val => a0,
            AttrOp::Min | AttrOp::Max | AttrOp::FloatMin | AttrOp::FloatMax => {
                let b = a1;
                let less = a0.compare(&b) == std::cmp::Ordering::Less;
                match op {
                    AttrOp::Min | AttrOp::FloatMin => {
                        if less {
                            a0
                        } else {
                            b
                        }
                    }
                    _ => {
                        if less {
                            b
                        } else {
                            a0
                        }
                    }
                }
            }
            AttrOp::Floor => Value::Real(a0.real().floor()),
            AttrOp::Ceiling => Value::Real(a0.real().ceil()),
            AttrOp::Truncation => Value::Real(a0.real().trunc()),
            AttrOp::Rounding => Value::Real(a0.real().round()),
        })
    }
}

/// Writes `val` at the end of a path of steps into `root` (copy-on-write).
/// An array object keeps its bounds (every array object is constrained,
/// RM 3.3.1): a new value of another length fails the length check, one of
/// the same length slides to the object's bounds (RM 5.2(10-11)).
fn keep_bounds(old: &Value, val: Value) -> Result<Value, &'static str> {
    let Value::Arr(o) = old else {
        return Ok(val);
    };
    let n = match val {
        Value::Arr(n) if n.bounds() != o.bounds() => n,
        other => return Ok(other),
    };
    let dims = o.bounds().len();
    if dims != n.bounds().len() || (0..dims).any(|d| o.len(d) != n.len(d)) {
        return Err("length check failed");
    }
    Ok(Value::Arr(n.with_bounds(o.bounds())))
}

fn write_path(
    root: &mut Value,
    steps: &[Step],
    val: Value,
    at: Span,
) -> Result<(), (&'static str, Span)> {
    let Some((first, rest)) = steps.split_first() else {
        *root = keep_bounds(root, val).map_err(|what| (what, at))?;
        return Ok(());
    };
    match first {
        Step::Index(ix, sp) => {
            let Value::Arr(a) = root else {
                return Err(("access check failed", *sp));
            };
            let a = a.make_mut();
            let Some(o) = a.offset(ix) else {
                return Err(("index check failed", *sp));
            };
            if rest.is_empty()
                && a.data()
                    .val(o)
                    .is_none_or(|old| !matches!(old, Value::Arr(_)))
            {
                // A component that is no array: no bounds to keep.
                a.set(o, val);
                return Ok(());
            }
            write_path(a.get_mut(o), rest, val, at)
        }
        Step::Field(i) => {
            let Some(r) = root.fields_mut() else {
                return Err((
                    "discriminant check failed",
                    Span {
                        start: 0,
                        end: 0,
                        context: 0,
                    },
                ));
            };
            write_path(&mut r[*i as usize], rest, val, at)
        }
        Step::Variant(conds, sp) => {
            if root
                .fields()
                .is_some_and(|r| value::variant_holds(r, conds))
            {
                write_path(root, rest, val, at)
            } else {
                Err(("discriminant check failed", *sp))
            }
        }
        // A component or a slice of a slice (`Code (6 .. 8)(7)`, an element
        // of a renamed slice): of the sliced array, within the slice.
        Step::Slice(l, h, sp) if !rest.is_empty() => {
            let Value::Arr(a) = root else {
                return Err(("access check failed", *sp));
            };
            let (lo, hi) = a.bounds()[0];
            if l <= h && (*l < lo || *h > hi) {
                return Err(("range check failed", *sp));
            }
            match &rest[0] {
                Step::Index(ix, isp) if ix[0] < *l || ix[0] > *h => {
                    Err(("index check failed", *isp))
                }
                Step::Slice(l2, h2, s2) if l2 <= h2 && (l2 < l || h2 > h) => {
                    Err(("range check failed", *s2))
                }
                _ => write_path(root, rest, val, at),
            }
        }
        Step::Slice(l, h, sp) => {
            let Value::Arr(a) = root else {
                return Err(("access check failed", *sp));
            };
            let Value::Arr(src) = val else {
                return Err(("length check failed", *sp));
            };
            let n = (h - l + 1).max(0) as usize;
            if src.len_all() != n {
                return Err(("length check failed", *sp));
            }
            if n == 0 {
                return Ok(());
            }
            let (lo, hi) = a.bounds()[0];
            if *l < lo || *h > hi {
                return Err(("range check failed", *sp));
            }
            a.copy_from((*l - lo) as usize, src.data());
            Ok(())
        }
    }
}

/// A unary operation that both engines run through [`Run::unary_of`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum UnOp {
    FloatNeg,
    IntAbs,
    FloatAbs,
    FloatToInt,
    /// `P.all`.
    Deref,
    /// `not` of a Boolean array.
    ArrNot,
    /// A conversion to an array type (bounds and length checks).
    ArrayConvert(TypeId),
}

impl UnOp {
    /// The operation and operand of `e` when it is a unary operation.
    pub(crate) fn of(e: &Ex) -> Option<(UnOp, &Ex)> {
        Some(match &e.kind {
            ExKind::FloatNeg(a) => (UnOp::FloatNeg, a),
            ExKind::IntAbs(a) => (UnOp::IntAbs, a),
            ExKind::FloatAbs(a) => (UnOp::FloatAbs, a),
            ExKind::FloatToInt(a) => (UnOp::FloatToInt, a),
            ExKind::Deref(a) => (UnOp::Deref, a),
            ExKind::ArrNot(a) => (UnOp::ArrNot, a),
            ExKind::ArrayConvert(a, t) => (UnOp::ArrayConvert(*t), a),
            _ => return None,
        })
    }
}

/// A Boolean array with the bounds of `like` and the components `bits`.
fn bool_array(like: &value::Array, bits: impl Iterator<Item = bool>) -> Value {
    let bits: value::ByteVec = bits.map(u8::from).collect();
    let mut a = value::Array::from_elems(1, value::Elems::Bytes(&bits));
    a.set_bounds(like.bounds());
    Value::Arr(a)
}

#[cfg(test)]
mod copy_tests {
    use super::{Machine, Obj, Value};

    /// The rehearsal's copy of the program's data: a long list is copied
    /// in constant native stack (a 256 KiB thread), with aliasing and
    /// cycles kept and nothing shared with the original.
    #[test]
    fn a_long_circular_list_is_copied_without_recursion() {
        std::thread::Builder::new()
            .stack_size(256 * 1024)
            .spawn(|| {
                let node = |v: i64, next: Value| {
                    Value::Ptr(Some(Obj::new(Value::record(smallvec::smallvec![
                        Value::Int(v),
                        next
                    ]))))
                };
                let last = node(0, Value::Ptr(None));
                let mut head = last.clone();
                for i in 1..200_000 {
                    head = node(i, head);
                }
                // The last node points back to the head: a cycle.
                let (Value::Ptr(Some(l)), Value::Ptr(Some(h))) = (&last, &head) else {
                    panic!()
                };
                l.update(|v| v.fields_mut().unwrap()[1] = Value::Ptr(Some(h.clone())));
                let mut m = Machine::new(Box::new(std::io::sink()));
                m.stack = vec![head.clone(), last.clone()].into();
                let copy = m.copy_globals();
                let next = |p: &Value| match p {
                    Value::Ptr(Some(o)) => match o.get().fields() {
                        Some(r) => (r[0].int(), r[1].clone()),
                        None => panic!(),
                    },
                    _ => panic!(),
                };
                // Walk the copy once round: 199999 .. 0, then its own head.
                let mut p = copy[0].clone();
                for want in (0..200_000).rev() {
                    let (v, n) = next(&p);
                    assert_eq!(v, want);
                    p = n;
                }
                assert!(p == copy[0], "the cycle leads back to the copy's head");
                assert!(
                    copy[1] != last && copy[0] != head,
                    "a copy shares an object"
                );
                // Break both cycles so that they can be freed.
                for l in [&last, &copy[1]] {
                    if let Value::Ptr(Some(o)) = l {
                        o.update(|v| v.fields_mut().unwrap()[1] = Value::Ptr(None));
                    }
                }
            })
            .unwrap()
            .join()
            .expect("the copy overflowed the stack");
    }
}
