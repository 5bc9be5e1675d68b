//! The type table: every type and subtype of a program, by index.

use super::ir::Ex;

pub type TypeId = u32;

/// Index types, component type and (for a constrained array) the bounds.
pub type ArrayInfo<'a> = (&'a [TypeId], TypeId, Option<&'a Vec<(Ex, Ex)>>);

#[derive(Clone, Debug)]
pub enum TypeKind {
    /// Signed integer types (Integer, user `range` types, their derivations).
    Integer,
    /// Floating point types (Float, `digits` types) and Duration.
    Float,
    /// Enumerations, including Boolean and Character (positions 0..n).
    Enum(Vec<Image>),
    Array {
        index: Vec<TypeId>,
        elem: TypeId,
        /// Bounds of a constrained array type, as expressions (often static).
        bounds: Option<Vec<(Ex, Ex)>>,
    },
    Record(Vec<Field>),
    Access(TypeId),
    /// `type T;` not yet completed.
    Incomplete,
    /// A private type's partial view (`type T is [limited] private;`):
    /// before its full declaration, and where only the partial view is
    /// visible (see [`Types::hidden`]).
    Private,
    /// The type of integer literals and named numbers.
    UnivInt,
    /// The type of real literals.
    UnivReal,
    /// The type of `null`.
    Null,
    /// An aggregate or allocator before its type is known from context.
    AnyComposite,
    /// `Ada.Exceptions.Exception_Occurrence`.
    Occurrence,
    /// `Ada.Calendar.Time` (seconds of virtual time).
    Time,
    /// A task type (index into the checker's task table); a task object's
    /// value is its task number.
    Task(u32),
    /// A protected type (index into the protected table).
    Protected(u32),
    /// A type the checker could not determine (after an error).
    Error,
}

#[derive(Clone, Debug)]
pub struct Field {
    pub name: String,
    pub key: String,
    pub ty: TypeId,
    pub default: Option<Ex>,
    /// A discriminant (RM 3.7): a record's discriminants are its first
    /// components.
    pub discriminant: bool,
    /// The variant the component belongs to (RM 3.8.1): it exists only
    /// while each discriminant named here (by index) has one of its
    /// values; one condition per enclosing variant part.
    pub variant: Option<Variant>,
    /// The component's subtype when its constraint reads the discriminants
    /// (`Data : String (1 .. Size)`): its bounds and values hold
    /// `ExKind::Discriminant` nodes, evaluated when a value of the record
    /// is built. `ty` is then the unconstrained type (the object's bounds
    /// are its value's).
    pub dependent: Option<TypeId>,
}

/// The conditions of a variant, one per enclosing variant part.
pub type Variant = std::rc::Rc<[Governs]>;

/// A condition of a variant: a discriminant (its index) has one of these
/// values (ranges).
pub type Governs = (u32, Box<[(i64, i64)]>);

impl Field {
    /// A component that is no discriminant, in no variant.
    pub fn plain(name: &str, key: &str, ty: TypeId, default: Option<Ex>) -> Field {
        Field {
            name: name.to_string(),
            key: key.to_string(),
            ty,
            default,
            discriminant: false,
            variant: None,
            dependent: None,
        }
    }
}

#[derive(Clone, Debug)]
pub struct TypeInfo {
    pub name: String,
    pub kind: TypeKind,
    /// The type this is a subtype of (itself for a type): subtypes of one base
    /// are compatible with each other.
    pub base: TypeId,
    /// The scalar range constraint, if any (low, high).
    pub range: Option<(Ex, Ex)>,
    /// Static bounds of the range, when known: used for `case` coverage and
    /// static range checks.
    pub static_range: Option<(i128, i128)>,
    pub static_frange: Option<(f64, f64)>,
    /// A floating point type's decimal digits (`digits N`; Float's 6).
    pub digits: Option<u32>,
    /// For an access type's designated incomplete type, completed later.
    pub full_name: String,
    /// An access type whose objects hold tasks: the slot that holds the
    /// master of the tasks its allocators create (the region that declares
    /// the type, RM 9.3(2)), stored when the declaration is elaborated.
    pub master: Option<crate::check::ir::Var>,
    /// A modular type's modulus (`mod N`, 1 ..= 2**32; its values are
    /// 0 .. N - 1 and its arithmetic wraps), kept by its subtypes and the
    /// types derived from it.
    pub modulus: Option<i64>,
    /// Duration and the types derived from it (`Time_Span`): GNAT's fixed
    /// point of whole nanoseconds (`Duration'Small` = 1 ns), held as reals
    /// that the engines keep whole (`FloatOp::on_duration`).
    pub whole_ns: bool,
    /// A discriminant constraint (`Gripper (Vacuum)`, `Buffer (N)`): the
    /// value of each discriminant, in order (a bound that is not static is
    /// a slot elaborated with the declaration).
    pub discr: Option<std::rc::Rc<[Ex]>>,
    /// A private type (and its subtypes and derived types): the package
    /// whose private part completes it, and whether it is limited.
    pub private: Option<PrivateView>,
    /// The root of a derived type's derivation (`type Tool_Pose is new
    /// Pose;`: Pose's base type, or Pose's own root): types of one root
    /// convert to each other (RM 4.6(21)).
    pub root: Option<TypeId>,
}

/// What a private type's partial view says (`type T is [limited] private;`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PrivateView {
    /// The package (index into the checker's packages) that declares it.
    pub package: u32,
    pub limited: bool,
    /// `type T (<>) is private;`: unknown discriminants (RM 3.7(1)): where
    /// the full view is hidden, objects of `T` need an initial value.
    pub unknown: bool,
}

/// The kind a private type has where its full view is hidden.
const PRIVATE: &TypeKind = &TypeKind::Private;

pub const ERROR: TypeId = 0;
pub const UNIV_INT: TypeId = 1;
pub const UNIV_REAL: TypeId = 2;
pub const NULL_T: TypeId = 3;
pub const ANY_COMPOSITE: TypeId = 4;
pub const BOOLEAN: TypeId = 5;
pub const CHARACTER: TypeId = 6;
pub const INTEGER: TypeId = 7;
pub const NATURAL: TypeId = 8;
pub const POSITIVE: TypeId = 9;
pub const FLOAT: TypeId = 10;
pub const STRING: TypeId = 11;
pub const DURATION: TypeId = 12;
pub const OCCURRENCE: TypeId = 13;
pub const TIME: TypeId = 14;

pub const INT_FIRST: i128 = i32::MIN as i128;
pub const INT_LAST: i128 = i32::MAX as i128;

#[derive(Clone, Debug, Default)]
pub struct Types {
    pub list: super::PVec<TypeInfo>,
    /// The private types whose full view is hidden where the checker
    /// stands (outside their package's private part and body): the
    /// checker's questions about their kind see `TypeKind::Private`, so
    /// their components, literals, aggregates and operations are refused.
    pub hidden: super::PMap<TypeId, ()>,
    /// Whether `hidden` applies: while the checker checks. The engines see
    /// every full view (`false` otherwise).
    pub views: bool,
    /// The discriminants of task and protected types (RM 9.1, 9.4), by
    /// type: a task's are its body's parameters, a protected object's are
    /// the first components after its number.
    pub conc_discrs: std::collections::HashMap<TypeId, Vec<Field>>,
    /// The known discriminants of private types' partial views (`type
    /// Buffer (Size : Positive) is private;`), by type: where the full
    /// view is hidden (or not declared yet) they are the type's. They
    /// conform to the full view's (RM 7.3(13)), whose come first in the
    /// same order.
    pub partial_discrs: std::collections::HashMap<TypeId, Vec<Field>>,
}

impl Types {
    pub fn get(&self, t: TypeId) -> &TypeInfo {
        &self.list[t as usize]
    }
    pub fn base(&self, t: TypeId) -> TypeId {
        self.list[t as usize].base
    }
    /// Whether `t` is Duration or derived from it (see [`TypeInfo::whole_ns`]).
    pub fn whole_ns(&self, t: TypeId) -> bool {
        self.list[self.base(t) as usize].whole_ns
    }
    pub fn kind(&self, t: TypeId) -> &TypeKind {
        let b = self.base(t);
        if self.is_hidden(b) {
            return PRIVATE;
        }
        &self.list[b as usize].kind
    }
    /// The kind of the full view, wherever the checker stands: what the
    /// objects of `t` hold (tasks), not what may be done with them.
    pub fn full_kind(&self, t: TypeId) -> &TypeKind {
        &self.list[self.base(t) as usize].kind
    }
    /// Whether the full view of `t` (a private type) is hidden here.
    pub fn is_hidden(&self, t: TypeId) -> bool {
        self.views && !self.hidden.is_empty() && self.hidden.contains_key(&self.base(t))
    }
    /// The partial view of a private type (of its base type), if it is one.
    pub fn private_view(&self, t: TypeId) -> Option<PrivateView> {
        self.list[self.base(t) as usize].private
    }
    /// Whether a private type has its full declaration (a type that is not
    /// private has).
    pub fn completed(&self, t: TypeId) -> bool {
        !matches!(self.list[self.base(t) as usize].kind, TypeKind::Private)
    }
    /// The root of `t`'s derivation: the base type it was derived from
    /// (through every derivation), or its own base type.
    pub fn derivation_root(&self, t: TypeId) -> TypeId {
        let b = self.base(t);
        self.list[b as usize].root.unwrap_or(b)
    }
    pub fn name(&self, t: TypeId) -> &str {
        &self.list[t as usize].name
    }
    pub fn add(&mut self, name: &str, kind: TypeKind) -> TypeId {
        let id = self.list.len() as TypeId;
        self.list.push(TypeInfo {
            name: name.to_string(),
            kind,
            base: id,
            range: None,
            static_range: None,
            static_frange: None,
            digits: None,
            full_name: name.to_string(),
            master: None,
            modulus: None,
            whole_ns: false,
            discr: None,
            private: None,
            root: None,
        });
        id
    }
    pub fn add_subtype(&mut self, name: &str, of: TypeId) -> TypeId {
        let id = self.list.len() as TypeId;
        let mut info = self.list[of as usize].clone();
        info.name = name.to_string();
        info.full_name = name.to_string();
        info.base = self.base(of);
        self.list.push(info);
        id
    }
    /// The decimal digits of a floating point type: its `digits N`, Float's
    /// 6, else those of a 64-bit double (15).
    pub fn digits(&self, t: TypeId) -> u32 {
        self.list[t as usize]
            .digits
            .or(self.list[self.base(t) as usize].digits)
            .unwrap_or(15)
    }
    /// The modulus of a modular type (of its base type), None for every
    /// other type.
    pub fn modulus(&self, t: TypeId) -> Option<i64> {
        if self.is_hidden(t) {
            return None;
        }
        self.list[self.base(t) as usize].modulus
    }
    /// The last value of a modular type (`modulus - 1`, which fits a u32):
    /// what the engine's [`modular`](crate::check::ir::modular) takes.
    pub fn modular_last(&self, t: TypeId) -> Option<u32> {
        self.modulus(t).map(|n| (n - 1) as u32)
    }
    pub fn is_integer(&self, t: TypeId) -> bool {
        matches!(self.kind(t), TypeKind::Integer | TypeKind::UnivInt)
    }
    pub fn is_float(&self, t: TypeId) -> bool {
        matches!(self.kind(t), TypeKind::Float | TypeKind::UnivReal)
    }
    pub fn is_numeric(&self, t: TypeId) -> bool {
        self.is_integer(t) || self.is_float(t)
    }
    pub fn is_discrete(&self, t: TypeId) -> bool {
        matches!(
            self.kind(t),
            TypeKind::Integer | TypeKind::UnivInt | TypeKind::Enum(_)
        )
    }
    pub fn is_scalar(&self, t: TypeId) -> bool {
        self.is_discrete(t) || self.is_float(t) || self.base(t) == TIME
    }
    pub fn is_universal(&self, t: TypeId) -> bool {
        matches!(self.kind(t), TypeKind::UnivInt | TypeKind::UnivReal)
    }
    pub fn is_array(&self, t: TypeId) -> bool {
        matches!(self.kind(t), TypeKind::Array { .. })
    }
    pub fn is_access(&self, t: TypeId) -> bool {
        matches!(self.kind(t), TypeKind::Access(_))
    }
    /// A one-dimensional array of Boolean (`and`, `or`, `xor`, `not` apply).
    pub fn is_bool_array(&self, t: TypeId) -> bool {
        self.array(self.base(t))
            .or_else(|| self.array(t))
            .is_some_and(|(idx, elem, _)| idx.len() == 1 && self.base(elem) == BOOLEAN)
    }
    /// Array information of `t` (which may be a constrained subtype).
    pub fn array(&self, t: TypeId) -> Option<ArrayInfo<'_>> {
        if self.is_hidden(t) {
            return None;
        }
        match &self.list[t as usize].kind {
            TypeKind::Array {
                index,
                elem,
                bounds,
            } => Some((index, *elem, bounds.as_ref())),
            _ => None,
        }
    }
    pub fn fields(&self, t: TypeId) -> Option<&[Field]> {
        match self.kind(t) {
            TypeKind::Record(f) => Some(f),
            _ => None,
        }
    }
    /// The discriminants of a record type (its first components), of a
    /// task or a protected type, or of a private type's partial view where
    /// its full view is hidden.
    pub fn discriminants(&self, t: TypeId) -> &[Field] {
        match self.kind(t) {
            TypeKind::Private => self
                .partial_discrs
                .get(&self.base(t))
                .map_or(&[], |v| v.as_slice()),
            TypeKind::Record(f) => {
                let n = f.iter().take_while(|f| f.discriminant).count();
                &f[..n]
            }
            TypeKind::Task(_) | TypeKind::Protected(_) => self
                .conc_discrs
                .get(&self.base(t))
                .map_or(&[], |v| v.as_slice()),
            _ => &[],
        }
    }
    /// The discriminants of `t`'s full view, wherever the checker stands
    /// (the partial view's before the full declaration): what its
    /// objects hold at run time, so whether they can change (see
    /// `check/discriminants.rs`), not what may be named.
    pub fn full_discriminants(&self, t: TypeId) -> &[Field] {
        match self.full_kind(t) {
            TypeKind::Record(f) => {
                let n = f.iter().take_while(|f| f.discriminant).count();
                &f[..n]
            }
            TypeKind::Task(_) | TypeKind::Protected(_) => self
                .conc_discrs
                .get(&self.base(t))
                .map_or(&[], |v| v.as_slice()),
            TypeKind::Private => self
                .partial_discrs
                .get(&self.base(t))
                .map_or(&[], |v| v.as_slice()),
            _ => &[],
        }
    }
    /// Whether the full view of `t` has discriminants with defaults: its
    /// objects declared without a constraint are mutable (RM 3.7(28)),
    /// outside the package too, whatever its partial view says.
    pub fn full_discriminant_defaults(&self, t: TypeId) -> bool {
        self.full_discriminants(t)
            .first()
            .is_some_and(|d| d.default.is_some())
    }
    /// Whether `t` is a private type declared with unknown discriminants
    /// (`type T (<>) is private;`) whose full view is hidden here.
    pub fn unknown_discriminants(&self, t: TypeId) -> bool {
        matches!(self.kind(t), TypeKind::Private) && self.private_view(t).is_some_and(|v| v.unknown)
    }
    /// Whether `t` is a record type with discriminants that have defaults
    /// (its objects declared without a constraint are mutable, RM 3.7(28)).
    pub fn discriminant_defaults(&self, t: TypeId) -> bool {
        self.discriminants(t)
            .first()
            .is_some_and(|d| d.default.is_some())
    }
    /// The discriminant constraint of a subtype, if it has one.
    pub fn discriminant_constraint(&self, t: TypeId) -> Option<&[Ex]> {
        self.list[t as usize].discr.as_deref()
    }
    pub fn enum_lits(&self, t: TypeId) -> Option<&[Image]> {
        match self.kind(t) {
            TypeKind::Enum(l) => Some(l),
            _ => None,
        }
    }
    /// Whether an object of type `t` holds a task (so that its declaration
    /// creates one and its scope is the task's master).
    pub fn has_task(&self, t: TypeId) -> bool {
        // A constrained array subtype keeps its own kind (its bounds).
        let kind = match &self.list[t as usize].kind {
            k @ TypeKind::Array { .. } => k,
            _ => self.full_kind(t),
        };
        match kind {
            TypeKind::Task(_) => true,
            TypeKind::Array { elem, .. } => self.has_task(*elem),
            TypeKind::Record(fs) => fs.iter().any(|f| self.has_task(f.ty)),
            _ => false,
        }
    }
    /// Whether a default value of `t` must be built once per component
    /// (tasks and protected objects are not copied).
    pub fn is_unique(&self, t: TypeId) -> bool {
        match self.full_kind(t) {
            TypeKind::Task(_) | TypeKind::Protected(_) => true,
            TypeKind::Array { elem, .. } => self.is_unique(*elem),
            TypeKind::Record(fs) => fs.iter().any(|f| self.is_unique(f.ty)),
            _ => false,
        }
    }
    pub fn designated(&self, t: TypeId) -> Option<TypeId> {
        match self.kind(t) {
            TypeKind::Access(d) => Some(*d),
            _ => None,
        }
    }

    /// Can a value of type `from` be used where `to` is expected?
    pub fn compatible(&self, from: TypeId, to: TypeId) -> bool {
        if from == ERROR || to == ERROR {
            return true;
        }
        let (bf, bt) = (self.base(from), self.base(to));
        if bf == bt {
            return true;
        }
        matches!(
            (self.kind(from), self.kind(to)),
            (TypeKind::UnivInt, TypeKind::Integer)
                | (TypeKind::UnivReal, TypeKind::Float)
                | (TypeKind::Null, TypeKind::Access(_))
                | (
                    TypeKind::AnyComposite,
                    TypeKind::Array { .. } | TypeKind::Record(_) | TypeKind::Access(_)
                )
                | (TypeKind::Integer, TypeKind::UnivInt)
                | (TypeKind::Float, TypeKind::UnivReal)
        )
    }

    /// Static bounds of a discrete subtype, if known.
    pub fn discrete_bounds(&self, t: TypeId) -> Option<(i128, i128)> {
        if self.is_hidden(t) {
            return None;
        }
        let info = self.get(t);
        if let Some(r) = info.static_range {
            return Some(r);
        }
        match self.kind(t) {
            TypeKind::Enum(l) => Some((0, l.len() as i128 - 1)),
            _ => None,
        }
    }

    /// The predefined types, at fixed ids.
    pub fn standard() -> Types {
        let mut t = Types::default();
        let e = t.add("<error>", TypeKind::Error);
        debug_assert_eq!(e, ERROR);
        t.add("universal_integer", TypeKind::UnivInt);
        t.add("universal_real", TypeKind::UnivReal);
        t.add("null", TypeKind::Null);
        t.add("aggregate", TypeKind::AnyComposite);
        t.add(
            "Boolean",
            TypeKind::Enum(vec![Image::Borrowed("FALSE"), Image::Borrowed("TRUE")]),
        );
        let chars = CHAR_IMAGES.iter().map(|&i| Image::Borrowed(i)).collect();
        t.add("Character", TypeKind::Enum(chars));
        let int = t.add("Integer", TypeKind::Integer);
        t.list[int as usize].range = Some((Ex::int(INT_FIRST as i64), Ex::int(INT_LAST as i64)));
        t.list[int as usize].static_range = Some((INT_FIRST, INT_LAST));
        let nat = t.add_subtype("Natural", INTEGER);
        t.list[nat as usize].range = Some((Ex::int(0), Ex::int(INT_LAST as i64)));
        t.list[nat as usize].static_range = Some((0, INT_LAST));
        let pos = t.add_subtype("Positive", INTEGER);
        t.list[pos as usize].range = Some((Ex::int(1), Ex::int(INT_LAST as i64)));
        t.list[pos as usize].static_range = Some((1, INT_LAST));
        let f = t.add("Float", TypeKind::Float);
        t.list[f as usize].static_frange = Some((-f32::MAX as f64, f32::MAX as f64));
        t.list[f as usize].digits = Some(6);
        t.add(
            "String",
            TypeKind::Array {
                index: vec![POSITIVE],
                elem: CHARACTER,
                bounds: None,
            },
        );
        let d = t.add("Duration", TypeKind::Float);
        // GNAT's Duration: 64-bit fixed point, Duration'Small = 1 ns.
        let (lo, hi) = (i64::MIN as f64 / 1e9, i64::MAX as f64 / 1e9);
        t.list[d as usize].static_frange = Some((lo, hi));
        t.list[d as usize].whole_ns = true;
        // A value outside it is a check error when static, else
        // Constraint_Error (GNAT's overflow check), never a saturated value.
        t.list[d as usize].range = Some((Ex::real(lo), Ex::real(hi)));
        t.add("Exception_Occurrence", TypeKind::Occurrence);
        t.add("Time", TypeKind::Time);
        t
    }
}

/// An enumeration literal's image: the predefined ones are static text.
pub type Image = std::borrow::Cow<'static, str>;

/// `Character`'s literals (as [`char_image`] shows them), static: they
/// were 256 strings made at every start (issue 32 item 4, start-up).
#[rustfmt::skip]
pub static CHAR_IMAGES: [&str; 256] = [
    "NUL", "SOH", "STX", "ETX", "EOT", "ENQ", "ACK", "BEL", "BS", "HT", "LF", "VT", "FF", "CR",
    "SO", "SI", "DLE", "DC1", "DC2", "DC3", "DC4", "NAK", "SYN", "ETB", "CAN", "EM", "SUB", "ESC",
    "FS", "GS", "RS", "US", "' '", "'!'", "'\"'", "'#'", "'$'", "'%'", "'&'", "'''", "'('", "')'",
    "'*'", "'+'", "','", "'-'", "'.'", "'/'", "'0'", "'1'", "'2'", "'3'", "'4'", "'5'", "'6'",
    "'7'", "'8'", "'9'", "':'", "';'", "'<'", "'='", "'>'", "'?'", "'@'", "'A'", "'B'", "'C'",
    "'D'", "'E'", "'F'", "'G'", "'H'", "'I'", "'J'", "'K'", "'L'", "'M'", "'N'", "'O'", "'P'",
    "'Q'", "'R'", "'S'", "'T'", "'U'", "'V'", "'W'", "'X'", "'Y'", "'Z'", "'['", "'\\'", "']'",
    "'^'", "'_'", "'`'", "'a'", "'b'", "'c'", "'d'", "'e'", "'f'", "'g'", "'h'", "'i'", "'j'",
    "'k'", "'l'", "'m'", "'n'", "'o'", "'p'", "'q'", "'r'", "'s'", "'t'", "'u'", "'v'", "'w'",
    "'x'", "'y'", "'z'", "'{'", "'|'", "'}'", "'~'", "DEL", "Character'Val(128)",
    "Character'Val(129)", "Character'Val(130)", "Character'Val(131)", "Character'Val(132)",
    "Character'Val(133)", "Character'Val(134)", "Character'Val(135)", "Character'Val(136)",
    "Character'Val(137)", "Character'Val(138)", "Character'Val(139)", "Character'Val(140)",
    "Character'Val(141)", "Character'Val(142)", "Character'Val(143)", "Character'Val(144)",
    "Character'Val(145)", "Character'Val(146)", "Character'Val(147)", "Character'Val(148)",
    "Character'Val(149)", "Character'Val(150)", "Character'Val(151)", "Character'Val(152)",
    "Character'Val(153)", "Character'Val(154)", "Character'Val(155)", "Character'Val(156)",
    "Character'Val(157)", "Character'Val(158)", "Character'Val(159)", "'\u{a0}'", "'\u{a1}'",
    "'\u{a2}'", "'\u{a3}'", "'\u{a4}'", "'\u{a5}'", "'\u{a6}'", "'\u{a7}'", "'\u{a8}'",
    "'\u{a9}'", "'\u{aa}'", "'\u{ab}'", "'\u{ac}'", "'\u{ad}'", "'\u{ae}'", "'\u{af}'",
    "'\u{b0}'", "'\u{b1}'", "'\u{b2}'", "'\u{b3}'", "'\u{b4}'", "'\u{b5}'", "'\u{b6}'",
    "'\u{b7}'", "'\u{b8}'", "'\u{b9}'", "'\u{ba}'", "'\u{bb}'", "'\u{bc}'", "'\u{bd}'",
    "'\u{be}'", "'\u{bf}'", "'\u{c0}'", "'\u{c1}'", "'\u{c2}'", "'\u{c3}'", "'\u{c4}'",
    "'\u{c5}'", "'\u{c6}'", "'\u{c7}'", "'\u{c8}'", "'\u{c9}'", "'\u{ca}'", "'\u{cb}'",
    "'\u{cc}'", "'\u{cd}'", "'\u{ce}'", "'\u{cf}'", "'\u{d0}'", "'\u{d1}'", "'\u{d2}'",
    "'\u{d3}'", "'\u{d4}'", "'\u{d5}'", "'\u{d6}'", "'\u{d7}'", "'\u{d8}'", "'\u{d9}'",
    "'\u{da}'", "'\u{db}'", "'\u{dc}'", "'\u{dd}'", "'\u{de}'", "'\u{df}'", "'\u{e0}'",
    "'\u{e1}'", "'\u{e2}'", "'\u{e3}'", "'\u{e4}'", "'\u{e5}'", "'\u{e6}'", "'\u{e7}'",
    "'\u{e8}'", "'\u{e9}'", "'\u{ea}'", "'\u{eb}'", "'\u{ec}'", "'\u{ed}'", "'\u{ee}'",
    "'\u{ef}'", "'\u{f0}'", "'\u{f1}'", "'\u{f2}'", "'\u{f3}'", "'\u{f4}'", "'\u{f5}'",
    "'\u{f6}'", "'\u{f7}'", "'\u{f8}'", "'\u{f9}'", "'\u{fa}'", "'\u{fb}'", "'\u{fc}'",
    "'\u{fd}'", "'\u{fe}'", "'\u{ff}'",
];

/// How GNAT's `Character'Image` shows a character: `'A'`, or the name of a
/// control character (`NUL`, `LF`, ...).
pub fn char_image(c: char) -> String {
    const CTRL: [&str; 32] = [
        "NUL", "SOH", "STX", "ETX", "EOT", "ENQ", "ACK", "BEL", "BS", "HT", "LF", "VT", "FF", "CR",
        "SO", "SI", "DLE", "DC1", "DC2", "DC3", "DC4", "NAK", "SYN", "ETB", "CAN", "EM", "SUB",
        "ESC", "FS", "GS", "RS", "US",
    ];
    let n = c as u32;
    if n < 32 {
        CTRL[n as usize].to_string()
    } else if n == 127 {
        "DEL".to_string()
    } else if (128..160).contains(&n) {
        format!("Character'Val({n})")
    } else {
        let mut s = String::with_capacity(2 + c.len_utf8());
        s.push('\'');
        s.push(c);
        s.push('\'');
        s
    }
}

#[cfg(test)]
mod tests {
    /// The static literals of `Character` are what `char_image` makes.
    #[test]
    fn character_literals_are_their_images() {
        for (n, image) in super::CHAR_IMAGES.iter().enumerate() {
            let c = char::from_u32(n as u32).expect("a Latin-1 character");
            assert_eq!(*image, super::char_image(c), "{n}");
        }
    }
}
