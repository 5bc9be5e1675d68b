//! The checker: resolves every name, types every expression, resolves
//! overloads and checks modes, before anything runs. Produces the IR of
//! [`ir`], in which names are slots and subprogram indices.
//!
//! The checker keeps its state between calls, so that the REPL can check one
//! entry at a time against everything declared before.

use crate::diag::Offsets as _;
mod decl;
mod diagnostics;
mod discriminants;
pub mod exact;
mod expr;
pub mod index;
pub mod ir;
mod names;
mod persist;
mod scopes;
mod stmt;
mod tables;
mod tasks;
pub mod types;

use crate::diag::{Diagnostic, Span};
use crate::syntax::ast;
use ir::*;
pub use persist::{PMap, PVec};
pub use scopes::edit_distance;
use std::collections::HashMap;
use std::rc::Rc;
use tables::ProtMember;
pub use tables::{Package, Tables};
use types::*;

#[derive(Clone, Debug, PartialEq)]
pub enum Static {
    Int(i128),
    /// Exact, as Ada's universal arithmetic requires.
    Real(exact::Exact),
}

#[derive(Clone, Debug)]
pub enum Entity {
    Var {
        var: Var,
        ty: TypeId,
        constant: bool,
        /// Static value of a constant, for case choices and static checks.
        value: Option<Static>,
    },
    Number(Static),
    Type(TypeId),
    Func(FuncId),
    EnumLit(TypeId, i64),
    Exc(ExcId),
    Package(usize),
    /// The element name of `for E of A`: it stands for `A (I)`, a variable
    /// when `A` is one.
    Alias(Box<Ex>),
}

#[derive(Clone)]
struct FuncCtx {
    func: Option<FuncId>,
    ret: Option<TypeId>,
    saw_return: bool,
    next_slot: u32,
}

/// Whether an import name names a builtin the runtime knows.
pub type KnownBuiltin = fn(&str) -> bool;

/// The profile an import name expects (from the service table), so that a
/// `with Import` declaration with another profile is a check error instead of
/// a native reading arguments that are not there.
#[derive(Clone, Debug)]
pub struct ImportProfile {
    /// Mode and type name of each parameter.
    pub params: Vec<(ast::Mode, String)>,
    /// The result type name of a function.
    pub ret: Option<String>,
    /// The expected declaration, for the message.
    pub text: String,
}

pub type ImportProfileOf = fn(&str) -> Option<ImportProfile>;

/// The modes of a checker's run: what its checked form is for.
#[derive(Clone, Copy, Default)]
pub struct Options {
    /// In `check_unit_consuming`: blocks' statements are taken from the AST.
    consume_ast: bool,
    /// Only the diagnostics are wanted (`adair check`): the checked form of
    /// a lazily parsed body is dropped a part at a time as it is made, so
    /// that checking a long program holds one part of it, not all. Such a
    /// program's bodies are empty afterwards: it cannot run.
    pub diagnostics_only: bool,
    /// The import names of the services that only the simulator has
    /// (`PlaceObject`): when set, a call of one is a warning that the
    /// script cannot finish on a real arm (`adair check`, `--port`).
    pub simulator_only: &'static [&'static str],
    /// Set for a run in the compiled engine (`adair run`): a lazily parsed
    /// subprogram body is compiled a part at a time as it is checked, and
    /// each part's checked statements dropped (see [`ir::PartCompiler`]).
    pub compile_parts: Option<ir::PartCompiler>,
}

/// The slots of an accept statement's parameters and their modes.
type AcceptSlots = Vec<(Var, ast::Mode)>;

/// An accept statement whose body encloses the statement being checked.
#[derive(Clone)]
struct Accepting {
    /// The task type and its entry.
    task: u32,
    entry: u32,
    /// Where the accept statement is.
    at: Span,
    /// Its parameters' slots.
    slots: AcceptSlots,
}

/// Where the statement being checked stands among tasks, protected bodies
/// and masters (tasks.md).
#[derive(Clone, Default)]
struct TaskContext {
    /// The task types whose bodies are being checked (innermost last).
    task_ctx: Vec<u32>,
    /// The entries whose accept bodies enclose the statement being checked
    /// (an accept of one of them inside is illegal, RM 9.5.2(15)), and
    /// the slots of each accept's parameters (for `requeue`).
    accepting: Vec<Accepting>,
    /// The protected entry bodies being checked: the body, the protected
    /// type and the entry (for `requeue`).
    entry_bodies: Vec<(FuncId, u32, u32)>,
    /// The protected bodies being checked: the type and the slot of the
    /// object parameter of the operation being checked.
    prot_ctx: Vec<(u32, Option<Var>)>,
    /// The object parameter of the protected function being checked: its
    /// components are constants there (RM 9.5.1).
    prot_function_obj: Option<Var>,
    /// Per declarative region being checked: whether it may create tasks.
    masters: Vec<bool>,
    /// Library-level tasks created and not yet activated.
    library_tasks: bool,
}

/// Cloning a checker snapshots its state, so that the REPL can undo an
/// entry that does not check.
#[derive(Clone)]
pub struct Checker {
    /// The run's modes: what the checked form is for.
    pub options: Options,
    /// The next subprogram body checked is the main program's, whose
    /// statements are compiled a part at a time (see `compile_parts`); other
    /// bodies are compiled whole on their first call.
    main_body: bool,
    /// The next block checked is the main program's own.
    parts_here: bool,
    /// An error was reported since the diagnostics were last taken (a
    /// program with errors does not run: its parts are not compiled).
    erred: bool,
    /// While a declaration's subtype indication is checked: the statements
    /// that evaluate its non-static bounds once (`elaborating`).
    bounds_out: Option<Vec<Stmt>>,
    /// While the components of a record with discriminants are checked:
    /// a bound that reads a discriminant is evaluated with each value built,
    /// not once with the declaration.
    in_discriminated: bool,
    /// What the program declares.
    pub tables: tables::Tables,
    scopes: scopes::Scopes,
    level: u16,
    ctx: Vec<FuncCtx>,
    loops: Vec<(Option<String>, u32)>,
    next_loop: u32,
    in_handler: u32,
    /// Enclosing unit names, for full exception names.
    unit_path: Vec<String>,
    /// The exact value of each static real expression the checker folded
    /// or took from a named number, by the span of its `Real` node.
    exact_reals: HashMap<(u32, u32, u32), exact::Exact>,
    pub diags: Vec<Diagnostic>,
    /// Per subprogram being checked (one per level above 0): its local
    /// variables, where each is declared, and whether it has been read
    /// (for the warning "variable never read").
    pub(super) unread: Vec<HashMap<Var, (String, Span, bool)>>,
    /// Hashes of the diagnostics recorded (see `err`).
    diag_keys: std::collections::HashSet<u64>,
    texts: PMap<u32, Rc<str>>,
    known_builtin: KnownBuiltin,
    import_profile: Option<ImportProfileOf>,
    /// Level-0 slot count so far.
    pub globals: u32,
    /// Script mode: the standard packages are use-visible at the top level.
    pub script: bool,
    /// Units named by a `with` that does not exist (reported once).
    missing_units: Vec<String>,
    /// What each subexpression of the expression being checked can mean
    /// (`interps`), so that overload resolution visits every node once
    /// instead of once per candidate of each enclosing operator. It lives
    /// for one outermost `expr` or `interps` call: no declaration happens
    /// inside an expression, so visibility is fixed while it lives.
    memo: Option<HashMap<MemoKey, Vec<TypeId>>>,
    /// Declarations and resolved uses, for tools (see [`index`]).
    pub index: index::Index,
    /// The declaration being checked, for [`index::Def::decl`].
    cur_decl: Option<Span>,
    /// Where the statement being checked stands among tasks, protected
    /// bodies and masters.
    tasking: TaskContext,
    /// Names an unsupported declaration would have declared (a generic
    /// unit, its formals, an instance): a use of one is no second error.
    unsupported_names: std::collections::HashSet<String>,
    /// The devices address clauses bind to (`--devices`, or the default set).
    pub devices: Rc<crate::devices::Devices>,
    /// Subprograms declared before their bodies: the hidden Boolean that
    /// says whether the body has been elaborated (RM 3.11(14)), an object
    /// of the declaration's declarative region, False from the declaration
    /// on, True from the body on. The body begins by checking it.
    elab_flags: HashMap<FuncId, Var>,
    /// The subprograms whose `out` and `in out` formals of a mutable
    /// record type get a hidden flag (see `discriminants.rs`).
    flagged_funcs: std::collections::HashSet<FuncId>,
    /// Private types with known discriminants one of which was read
    /// (`B.Size`) before the full declaration: as a record's component,
    /// where (a task or protected completion is then refused).
    early_discriminant_reads: HashMap<TypeId, Span>,
    /// Subprograms declared before the full view of one of their `out`
    /// or `in out` formals' types: their hidden flags wait for it (see
    /// `discriminants.rs`).
    pending_flags: Vec<FuncId>,
    /// In the body being checked: each flagged formal's flag; None for an
    /// `out` or `in out` formal of a mutable record type of an entry or a
    /// protected operation, which has no flag and counts as constrained.
    constrained_flags: HashMap<Var, Option<Var>>,
}

/// A node of the expression being checked: its source range and its kind.
/// A clone of a node (the operands of a user operator become call
/// arguments) has the same key and the same meaning.
type MemoKey = (u32, u32, u32, std::mem::Discriminant<ast::ExprKind>);

pub const CONSTRAINT_ERROR: ExcId = 0;
pub const PROGRAM_ERROR: ExcId = 1;
pub const STORAGE_ERROR: ExcId = 2;
pub const TASKING_ERROR: ExcId = 3;
pub const NAME_ERROR: ExcId = 4;
pub const USE_ERROR: ExcId = 5;
pub const DATA_ERROR: ExcId = 6;
pub const END_ERROR: ExcId = 7;

impl Checker {
    pub fn new(known_builtin: KnownBuiltin) -> Checker {
        let mut c = Checker {
            options: Options::default(),
            main_body: false,
            parts_here: false,
            erred: false,
            bounds_out: None,
            in_discriminated: false,
            tables: tables::Tables::new(),
            scopes: scopes::Scopes::new(),
            level: 0,
            ctx: vec![FuncCtx {
                func: None,
                ret: None,
                saw_return: false,
                next_slot: 0,
            }],
            loops: Vec::new(),
            next_loop: 0,
            in_handler: 0,
            unit_path: Vec::new(),
            exact_reals: HashMap::new(),
            diags: Vec::new(),
            diag_keys: Default::default(),
            unread: Vec::new(),
            texts: PMap::new(),
            known_builtin,
            import_profile: None,
            globals: 0,
            script: false,
            missing_units: Vec::new(),
            memo: None,
            index: index::Index::recording(),
            cur_decl: None,
            tasking: TaskContext::default(),
            unsupported_names: Default::default(),
            devices: Rc::new(crate::devices::Devices::default_set()),
            elab_flags: HashMap::new(),
            flagged_funcs: Default::default(),
            early_discriminant_reads: HashMap::new(),
            pending_flags: Vec::new(),
            constrained_flags: HashMap::new(),
        };
        c.standard();
        c
    }

    fn standard(&mut self) {
        for (name, t) in [
            ("Boolean", BOOLEAN),
            ("Character", CHARACTER),
            ("Integer", INTEGER),
            ("Natural", NATURAL),
            ("Positive", POSITIVE),
            ("Float", FLOAT),
            ("String", STRING),
            ("Duration", DURATION),
        ] {
            self.declare(name, Entity::Type(t));
        }
        self.declare("False", Entity::EnumLit(BOOLEAN, 0));
        self.declare("True", Entity::EnumLit(BOOLEAN, 1));
        for (i, name) in [
            "Constraint_Error",
            "Program_Error",
            "Storage_Error",
            "Tasking_Error",
            "Name_Error",
            "Use_Error",
            "Data_Error",
            "End_Error",
        ]
        .iter()
        .enumerate()
        {
            let full = if i >= 4 {
                format!("ADA.IO_EXCEPTIONS.{}", name.to_uppercase())
            } else {
                name.to_uppercase()
            };
            self.tables.excs.push(Exception { name: full });
            if i < 4 {
                self.declare(name, Entity::Exc(i as ExcId));
            }
        }
        let io = self.package("Ada.IO_Exceptions");
        for (i, n) in ["name_error", "use_error", "data_error", "end_error"]
            .iter()
            .enumerate()
        {
            self.tables.packages[io]
                .names
                .insert(n.to_string(), vec![Entity::Exc(4 + i as ExcId)]);
        }
        let ex = self.package("Ada.Exceptions");
        self.tables.packages[ex].names.insert(
            "exception_occurrence".into(),
            vec![Entity::Type(OCCURRENCE)],
        );
        let cal = self.package("Ada.Calendar");
        self.tables.packages[cal]
            .names
            .insert("time".into(), vec![Entity::Type(TIME)]);
        self.tables.packages[cal]
            .names
            .insert("duration".into(), vec![Entity::Type(DURATION)]);
    }

    /// Registers the text of a source so that hints can quote it.
    pub fn add_text(&mut self, file: u32, text: Rc<str>) {
        self.texts.insert(file, text);
    }

    fn snippet(&self, s: Span) -> String {
        self.texts
            .get(&s.context)
            .and_then(|t| t.get(s.range()))
            .unwrap_or("?")
            .to_string()
    }

    /// Records a diagnostic once: the same message at the same place (a
    /// subtree checked again for another overload) is kept only the first
    /// time, found by hash so that many diagnostics stay linear.
    fn err(&mut self, d: Diagnostic) {
        use std::hash::BuildHasher;
        let key = self.diag_keys.hasher().hash_one((
            d.span.start,
            d.span.end,
            d.span.context,
            &d.message,
        ));
        if self.diag_keys.insert(key) {
            self.erred |= !d.is_warning();
            self.diags.push(d);
        }
    }

    // ---- frames and slots ----

    fn new_slot(&mut self) -> Var {
        let ctx = self.ctx.last_mut().expect("ctx");
        let slot = ctx.next_slot;
        ctx.next_slot += 1;
        if self.level == 0 {
            self.globals = self.globals.max(slot + 1);
        }
        Var {
            level: self.level,
            slot,
        }
    }

    fn new_loop(&mut self) -> u32 {
        self.next_loop += 1;
        self.next_loop
    }

    fn exc_name(&self, name: &str) -> String {
        let mut s = String::new();
        for p in &self.unit_path {
            s.push_str(&p.to_uppercase());
            s.push('.');
        }
        s.push_str(&name.to_uppercase());
        s
    }

    /// Checks a whole compilation unit. `script` decides whether top-level
    /// statements are allowed; returns the statements to run at level 0 and,
    /// for a main-procedure program, the main subprogram.
    pub fn check_unit(&mut self, unit: &ast::CompilationUnit) -> (Vec<Stmt>, Option<FuncId>) {
        // (A name only a failed unit meant to declare is not declared
        // afterwards: a later REPL entry that uses it is told so.)
        self.unsupported_names.clear();
        let (tasks0, prots0) = (self.tables.tasks.len(), self.tables.prots.len());
        // The checker sees private types as their place allows; the
        // engines (and the tools, after the check) see every full view.
        self.tables.types.views = true;
        let r = self.check_unit_items(unit);
        self.tables.types.views = false;
        // Every task and protected type declared here has its body here.
        let mut missing: Vec<Diagnostic> = self
            .tables
            .tasks
            .iter()
            .skip(tasks0)
            .filter(|t| t.body.is_none())
            .map(|t| diagnostics::task_without_body(t.span, &t.name))
            .collect();
        for (k, p) in self.tables.prots.iter().enumerate().skip(prots0) {
            let unfinished = p.entries.iter().any(|e| e.body.is_none())
                || self.tables.prot_members[k]
                    .iter()
                    .any(|m| self.tables.funcs[m.real as usize].body.is_none());
            if unfinished && !self.tables.prot_bodied.contains(&(k as u32)) {
                missing.push(diagnostics::protected_without_body(p.span, &p.name));
            }
        }
        for d in missing {
            self.err(d);
        }
        r
    }

    /// As `check_unit`, for a caller that drops the unit afterwards: the
    /// statements of every block are taken out of the AST and dropped as
    /// they are lowered (the AST of a long program and its checked form
    /// are not held whole at once). The unit's blocks are empty afterwards.
    pub fn check_unit_consuming(
        &mut self,
        unit: &ast::CompilationUnit,
    ) -> (Vec<Stmt>, Option<FuncId>) {
        self.options.consume_ast = true;
        let r = self.check_unit(unit);
        self.options.consume_ast = false;
        r
    }

    fn check_unit_items(&mut self, unit: &ast::CompilationUnit) -> (Vec<Stmt>, Option<FuncId>) {
        let mut out = Vec::new();
        let has_stmts = unit
            .items
            .iter()
            .any(|i| matches!(i, ast::TopItem::Stmt(_)));
        let mut main = None;
        let last_main = unit.items.iter().rev().find(|i| {
            matches!(i, ast::TopItem::Decl(d) if matches!(&d.kind,
                ast::DeclKind::SubprogramBody(b) if b.spec.params.is_empty() && b.spec.ret.is_none()))
        });
        for item in &unit.items {
            match item {
                ast::TopItem::With(names, _) => {
                    for n in names {
                        self.with_clause(n);
                    }
                }
                ast::TopItem::Use(names, _) => self.use_clause(names),
                ast::TopItem::Decl(d) => {
                    if let ast::DeclKind::SubprogramBody(b) = &d.kind
                        && b.spec.params.is_empty()
                        && b.spec.ret.is_none()
                        && !has_stmts
                    {
                        // Library-level procedure: the last one is the main program.
                        let before = self.tables.funcs.len();
                        self.main_body = std::ptr::eq(item, last_main.unwrap_or(item));
                        self.decl(d, &mut out);
                        self.main_body = false;
                        main = self.funcs_named(&b.spec.name.key(), before);
                        continue;
                    }
                    self.decl(d, &mut out);
                }
                ast::TopItem::Stmt(s) => self.stmt(s, &mut out),
            }
        }
        // At the end of the unit: where the text ends.
        let end = unit.items.last().map_or(crate::diag::span(0, 0, 0), |i| {
            let sp = match i {
                ast::TopItem::With(_, sp) | ast::TopItem::Use(_, sp) => *sp,
                ast::TopItem::Decl(d) => d.span,
                ast::TopItem::Stmt(s) => s.span,
            };
            Span {
                start: sp.end,
                ..sp
            }
        });
        self.activate_library_tasks(&mut out, end);
        (out, main)
    }

    /// Library-level (and script) tasks are activated together before the
    /// next statement that is no declaration, or at the end of the unit
    /// (before the main program runs), so that they can call each other
    /// whatever their order of declaration.
    pub(super) fn activate_library_tasks(&mut self, out: &mut Vec<Stmt>, at: Span) {
        if std::mem::take(&mut self.tasking.library_tasks) {
            out.push(Stmt {
                kind: StmtKind::Activate,
                span: Span {
                    end: at.start,
                    ..at
                },
            });
        }
    }

    /// Finishes a check: the level-0 statements and the slot count.
    pub fn take_diags(&mut self) -> Vec<Diagnostic> {
        self.diag_keys.clear();
        self.scopes.forget_reports();
        self.erred = false;
        std::mem::take(&mut self.diags)
    }

    /// Checks one expression in the top-level scope (a REPL entry), with no
    /// expected type. Errors are left in `diags`.
    pub fn check_expr(&mut self, e: &ast::Expr) -> Ex {
        self.tables.types.views = true;
        let ex = self.expr(e, None);
        self.tables.types.views = false;
        if self.tables.types.is_universal(ex.ty) {
            let t = if self.tables.types.is_float(ex.ty) {
                FLOAT
            } else {
                INTEGER
            };
            return self.coerce(ex, t);
        }
        ex
    }

    pub fn known_builtin(&self, name: &str) -> bool {
        (self.known_builtin)(name)
    }

    /// Where the expected profiles of import names come from.
    pub fn set_import_profiles(&mut self, f: ImportProfileOf) {
        self.import_profile = Some(f);
    }

    /// The expected profile of `name` when `f`'s declared one differs from it.
    pub fn import_mismatch(&self, f: FuncId, name: &str) -> Option<ImportProfile> {
        let want = (self.import_profile?)(name)?;
        let sub = &self.tables.funcs[f as usize];
        let same_type = |t: TypeId, n: &str| self.tables.types.name(t).eq_ignore_ascii_case(n);
        let params_match = sub.params.len() == want.params.len()
            && sub
                .params
                .iter()
                .zip(&want.params)
                .all(|(p, (m, n))| p.mode == *m && same_type(p.ty, n));
        let ret_match = match (sub.ret, &want.ret) {
            (None, None) => true,
            (Some(t), Some(n)) => same_type(t, n),
            _ => false,
        };
        (!(params_match && ret_match)).then_some(want)
    }
}

impl Checker {
    /// Marks a variable as read (see `unread`).
    pub(super) fn mark_read(&mut self, v: Var) {
        self.set_read(v, true);
    }

    /// Sets whether a tracked local variable counts as read.
    pub(super) fn set_read(&mut self, v: Var, read: bool) {
        if v.level > 0
            && let Some(frame) = self.unread.get_mut(v.level as usize - 1)
            && let Some(e) = frame.get_mut(&v)
        {
            e.2 = read;
        }
    }

    /// Whether a variable has been read (true for untracked ones).
    pub(super) fn was_read(&self, v: Var) -> bool {
        v.level == 0
            || self
                .unread
                .get(v.level as usize - 1)
                .and_then(|f| f.get(&v))
                .is_none_or(|e| e.2)
    }

    /// Ends a subprogram's tracking: a warning for each local variable that
    /// was never read.
    pub(super) fn report_unread(&mut self) {
        let Some(frame) = self.unread.pop() else {
            return;
        };
        let mut never: Vec<(String, Span)> = frame
            .into_values()
            .filter(|e| !e.2)
            .map(|e| (e.0, e.1))
            .collect();
        never.sort_by_key(|e| e.1.start);
        for (name, span) in never {
            self.err(diagnostics::never_read(span, &name));
        }
    }
}

/// The name under which a character literal of an enumeration type is
/// declared: case kept (`'B'` is not `'b'`) through the lower-casing of
/// names, as its code in hex.
pub(crate) fn char_lit_key(c: char) -> String {
    format!("'{:x}'", c as u32)
}

/// For the unit tests of the layer above (the engine's, which may not
/// build a `Session`): `src` checked by a bare checker, without the
/// stdlib; it must check. The engine reads it through [`Checker::program`].
#[cfg(test)]
pub(crate) fn checked_for_tests(src: &str) -> Checker {
    let (unit, d) = crate::syntax::parse_source(src, 0);
    assert!(d.is_empty(), "{d:?}");
    let mut c = Checker::new(|_| false);
    c.check_unit(&unit.expect("the program parses"));
    let d = c.take_diags();
    assert!(
        d.iter().all(|d| d.is_warning()),
        "the program checks: {d:?}"
    );
    c
}

#[cfg(test)]
mod consume_tests {
    use crate::syntax::ast::{CompilationUnit, DeclKind, TopItem};

    fn body_len(unit: &CompilationUnit) -> usize {
        match &unit.items[..] {
            [TopItem::Decl(d)] => match &d.kind {
                DeclKind::SubprogramBody(b) => b.body.stmts.borrow().len(),
                k => panic!("{k:?}"),
            },
            i => panic!("{i:?}"),
        }
    }

    /// `check_unit_consuming` drops each statement of a body once it is
    /// lowered (a long program's AST and checked form are not held whole
    /// together: issue 14); `check_unit` leaves the AST whole (the language
    /// server reads it after the check). Both give the same program.
    #[test]
    fn the_consuming_check_empties_the_blocks_and_the_other_keeps_them() {
        let text = "procedure P is\n   X : Integer := 0;\nbegin\n   X := X + 1;\n   \
                    declare\n      Y : Integer := X;\n   begin\n      X := Y;\n   end;\nend P;\n";
        let (unit, d) = crate::syntax::parse_source(text, 0);
        assert!(d.is_empty(), "{d:?}");
        let unit = unit.unwrap();
        let mut c = super::Checker::new(|_| false);
        let (kept, _) = c.check_unit(&unit);
        assert_eq!(body_len(&unit), 2);
        let mut c = super::Checker::new(|_| false);
        let (consumed, _) = c.check_unit_consuming(&unit);
        assert_eq!(body_len(&unit), 0);
        assert_eq!(format!("{kept:?}"), format!("{consumed:?}"));
        assert!(!c.options.consume_ast);
    }
}
