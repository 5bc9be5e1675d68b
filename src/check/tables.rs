//! The symbol tables of the checked program (types, subprograms, imports,
//! exceptions, packages, task and protected types) and the engine's
//! read-only view of them, [`ir::ProgramRef`].

use super::*;

#[derive(Debug, Clone)]
pub struct Package {
    pub name: String,
    pub(super) names: PMap<String, Vec<Entity>>,
    /// Names of the package body (and private part), visible inside it only.
    pub(super) private: PMap<String, Vec<Entity>>,
    /// The deferred constants of its visible part (`C : constant T;`),
    /// which its private part completes.
    pub(super) deferred: Vec<Deferred>,
    /// Its private types (and the types derived from them while their
    /// full views are hidden), whose full views its body sees.
    pub(super) private_types: Vec<TypeId>,
    /// Its spec and body (their text), where those full views are
    /// visible: for the tools, which ask after the check.
    pub(super) full_view_at: Vec<Span>,
}

/// A deferred constant: its name, slot and type, where it is declared,
/// and whether the private part has completed it.
#[derive(Debug, Clone)]
pub(super) struct Deferred {
    pub key: String,
    pub name: String,
    pub var: Var,
    pub ty: TypeId,
    pub span: Span,
    pub completed: bool,
}

/// What the program declares, by id: the tables a `TypeId`, `FuncId`,
/// `ExcId` or package index points into.
#[derive(Clone)]
pub struct Tables {
    pub types: Types,
    pub funcs: PVec<Subprogram>,
    /// Import name of each subprogram bound to a builtin.
    pub imports: PVec<Option<String>>,
    pub excs: PVec<Exception>,
    pub packages: PVec<Package>,
    /// Task types and protected types.
    pub tasks: PVec<TaskDef>,
    pub prots: PVec<ProtDef>,
    /// Each protected type's subprograms.
    pub(super) prot_members: Vec<Vec<ProtMember>>,
    /// Profile -> real subprogram of protected operations.
    pub(super) prot_real: HashMap<FuncId, (FuncId, u32)>,
    /// The profiles of the operations declared in a protected type's
    /// private part (called from its body only).
    pub(super) prot_private: std::collections::HashSet<FuncId>,
    /// Protected types whose body was seen (missing operations in it are
    /// reported there).
    pub(super) prot_bodied: Vec<u32>,
    /// Subprogram renamings -> the subprogram they rename: a call of the
    /// renaming is a call of it (RM 8.5.4(7)).
    pub(super) renames: PMap<FuncId, FuncId>,
}

impl Tables {
    /// The predefined types alone.
    pub(super) fn new() -> Tables {
        Tables {
            types: Types::standard(),
            funcs: PVec::new(),
            imports: PVec::new(),
            excs: PVec::new(),
            packages: PVec::new(),
            tasks: PVec::new(),
            prots: PVec::new(),
            prot_members: Vec::new(),
            prot_real: HashMap::new(),
            prot_private: std::collections::HashSet::new(),
            prot_bodied: Vec::new(),
            renames: PMap::new(),
        }
    }
}

impl Tables {
    /// The subprogram a call of `f` calls: the one it renames, if it is a
    /// renaming.
    pub(super) fn callee(&self, f: FuncId) -> FuncId {
        self.renames.get(&f).copied().unwrap_or(f)
    }
}

impl Checker {
    /// The program checked so far, as the interpreter reads it.
    pub fn program(&self) -> ir::ProgramRef<'_> {
        ir::ProgramRef {
            funcs: &self.tables.funcs,
            imports: &self.tables.imports,
            types: &self.tables.types,
            excs: &self.tables.excs,
            globals: self.globals,
            tasks: &self.tables.tasks,
            prots: &self.tables.prots,
        }
    }
}

/// A subprogram of a protected type.
#[derive(Clone, Debug)]
pub(super) struct ProtMember {
    /// Its name's key.
    pub(super) name: String,
    /// The profile callers see (without the object).
    pub(super) profile: FuncId,
    /// The real subprogram (the object its first parameter).
    pub(super) real: FuncId,
}
