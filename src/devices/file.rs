//! The device file (`--devices FILE.toml`): `[[device]]` tables say which
//! device sits at which address, `[[event]]` tables what the outside world
//! does when. Parsed with serde into spanned raw tables, then checked by
//! hand so that every problem is one message at its line and column.

use super::{Address, ada_address};
use serde::Deserialize;
use std::collections::{BTreeMap, HashMap};
use std::fmt;
use std::ops::Range;
use toml::{Spanned, Value};

/// The device kinds, as the `kind` field names them.
pub const KINDS: [&str; 3] = ["parallel", "light-barrier", "conveyor"];

/// A device file, or the built-in default set: the devices and the scripted
/// events (sorted by time; events at the same time keep their file order).
#[derive(Clone, Debug, PartialEq)]
pub struct Devices {
    source: String,
    devices: Vec<Device>,
    events: Vec<Event>,
    addresses: BTreeMap<Address, (usize, Role)>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Device {
    pub name: String,
    pub kind: DeviceKind,
    /// The line of its `[[device]]` table (0 for the default set).
    pub line: usize,
}

#[derive(Clone, Debug, PartialEq)]
pub enum DeviceKind {
    /// Appendix C: a 16-bit input and output register, a control/status
    /// register whose bit 0 enables the interrupt.
    Parallel {
        interrupt: Address,
        input: Address,
        output: Address,
        control: Address,
    },
    /// One input bit, set while an object is in the beam; interrupts on the
    /// rising edge, always enabled. `on` (an index into the devices) is the
    /// conveyor at whose end it sits; without it the beam is set by events
    /// and `:set`.
    LightBarrier {
        on: Option<usize>,
        input: Address,
        interrupt: Option<Address>,
    },
    /// A belt: bit 0 of the motor register runs it; objects travel from 0
    /// to `length` mm at `speed` mm/s and stop with their centre at `end`
    /// (robot base coordinates, mm).
    Conveyor {
        motor: Address,
        length: f64,
        speed: f64,
        end: [f64; 3],
    },
}

impl DeviceKind {
    pub fn name(&self) -> &'static str {
        match self {
            DeviceKind::Parallel { .. } => KINDS[0],
            DeviceKind::LightBarrier { .. } => KINDS[1],
            DeviceKind::Conveyor { .. } => KINDS[2],
        }
    }

    /// Every address of the device with what it is there, in the order the
    /// device file lists them.
    pub fn addresses(&self) -> Vec<(Address, Role)> {
        match *self {
            DeviceKind::Parallel {
                interrupt,
                input,
                output,
                control,
            } => vec![
                (interrupt, Role::Interrupt),
                (input, Role::Input),
                (output, Role::Output),
                (control, Role::Control),
            ],
            DeviceKind::LightBarrier {
                input, interrupt, ..
            } => {
                let mut v = vec![(input, Role::Input)];
                v.extend(interrupt.map(|a| (a, Role::Interrupt)));
                v
            }
            DeviceKind::Conveyor { motor, .. } => vec![(motor, Role::Motor)],
        }
    }
}

/// What an address of a device is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// An interrupt: an entry is bound to it, no object can be.
    Interrupt,
    /// An input register: the outside world sets it, the program reads it.
    Input,
    /// An output register: the program writes it.
    Output,
    /// The parallel port's control/status register (bit 0: interrupts
    /// enabled).
    Control,
    /// A conveyor's motor register (bit 0: the belt runs).
    Motor,
}

impl Role {
    pub fn is_register(self) -> bool {
        self != Role::Interrupt
    }
    /// The program may write it (inputs belong to the outside world).
    pub fn is_writable(self) -> bool {
        matches!(self, Role::Output | Role::Control | Role::Motor)
    }
    pub fn describe(self) -> &'static str {
        match self {
            Role::Interrupt => "interrupt",
            Role::Input => "input register",
            Role::Output => "output register",
            Role::Control => "control register",
            Role::Motor => "motor register",
        }
    }
}

/// One scripted event: at `at` seconds, on device `device` (an index into
/// the devices), set the input, put an object on the belt's start, raise
/// the interrupt, in that order.
#[derive(Clone, Debug, PartialEq)]
pub struct Event {
    pub at: f64,
    pub device: usize,
    pub input: Option<u16>,
    pub object: Option<ObjectSpec>,
    pub interrupt: bool,
    /// The line of its `[[event]]` table.
    pub line: usize,
}

#[derive(Clone, Debug, PartialEq)]
pub struct ObjectSpec {
    pub name: String,
    /// mm, across the belt's direction of travel as well as along it: the
    /// gripper's jaws stop at it, and objects queue centre to centre at the
    /// sum of their half widths.
    pub width: f64,
}

/// A device file that cannot be used: one message at one place.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DeviceFileError {
    pub path: String,
    /// 1-based line and column; `None` when the file could not be read.
    pub at: Option<(usize, usize)>,
    pub message: String,
}

/// The project's one-line diagnostic form, `FILE:LINE:COL: error: message`.
impl fmt::Display for DeviceFileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.at {
            Some((line, col)) => write!(f, "{}:{line}:{col}: error: {}", self.path, self.message),
            None => write!(f, "{}: error: {}", self.path, self.message),
        }
    }
}

impl std::error::Error for DeviceFileError {}

impl Devices {
    /// The built-in set: the appendix C parallel port, interrupt at 8#340#,
    /// input 8#342#, output 8#344#, control 8#346#.
    pub fn default_set() -> Devices {
        let devices = vec![Device {
            name: "parallel".into(),
            kind: DeviceKind::Parallel {
                interrupt: 0o340,
                input: 0o342,
                output: 0o344,
                control: 0o346,
            },
            line: 0,
        }];
        Devices::assemble("the default device set".into(), devices, Vec::new())
    }

    /// Parses a device file; `path` names it in the error.
    pub fn from_toml(text: &str, path: &str) -> Result<Devices, DeviceFileError> {
        let newlines = text
            .bytes()
            .enumerate()
            .filter(|(_, b)| *b == b'\n')
            .map(|(i, _)| i)
            .collect();
        let cx = Cx {
            text,
            path,
            newlines,
        };
        let raw: RawFile = toml::from_str(text).map_err(|e| {
            let span = e.span().unwrap_or(0..0);
            let message = first_line(e.message());
            // `[device]` for `[[device]]` is the likely slip; serde would
            // only say that it expected a sequence.
            let line = text
                .get(span.start..)
                .and_then(|t| t.lines().next())
                .unwrap_or("");
            let key = ["device", "event"].into_iter().find(|k| line.contains(k));
            match key {
                Some(k) if message.contains("expected a sequence") => cx.err(
                    span,
                    format!(
                        "each {k} is a table `[[{k}]]` (double brackets), not `{}`",
                        line.trim()
                    ),
                ),
                _ => cx.err(span, message),
            }
        })?;
        let devices = parse_devices(&cx, &raw.device)?;
        let events = parse_events(&cx, &raw.event, &devices)?;
        Ok(Devices::assemble(path.to_string(), devices, events))
    }

    /// Reads and parses a device file.
    pub fn load(path: &std::path::Path) -> Result<Devices, DeviceFileError> {
        let name = path.display().to_string();
        match std::fs::read_to_string(path) {
            Ok(text) => Devices::from_toml(&text, &name),
            Err(e) => Err(DeviceFileError {
                path: name,
                at: None,
                message: format!("cannot read the device file: {e}"),
            }),
        }
    }

    fn assemble(source: String, devices: Vec<Device>, mut events: Vec<Event>) -> Devices {
        // Stable: events at the same time keep their file order.
        events.sort_by(|a, b| a.at.total_cmp(&b.at));
        let mut addresses = BTreeMap::new();
        for (i, d) in devices.iter().enumerate() {
            for (a, role) in d.kind.addresses() {
                addresses.insert(a, (i, role));
            }
        }
        Devices {
            source,
            devices,
            events,
            addresses,
        }
    }

    /// The file's path, or "the default device set" (for messages such as
    /// "no device at 8#360# in FILE").
    pub fn source(&self) -> &str {
        &self.source
    }
    pub fn devices(&self) -> &[Device] {
        &self.devices
    }
    pub fn events(&self) -> &[Event] {
        &self.events
    }
    pub fn device(&self, name: &str) -> Option<usize> {
        self.devices.iter().position(|d| d.name == name)
    }
    /// The device at an address and what the address is there.
    pub fn lookup(&self, address: Address) -> Option<(usize, Role)> {
        self.addresses.get(&address).copied()
    }
    /// Whether an interrupt sits at `address` (`for E use at` binds to it).
    pub fn is_interrupt(&self, address: Address) -> bool {
        matches!(self.lookup(address), Some((_, Role::Interrupt)))
    }
    /// Every address in use, in ascending order.
    pub fn addresses(&self) -> impl Iterator<Item = (Address, usize, Role)> + '_ {
        self.addresses.iter().map(|(&a, &(d, r))| (a, d, r))
    }
}

// ---------------------------------------------------------------- raw file

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    #[serde(default)]
    device: Vec<Spanned<RawDevice>>,
    #[serde(default)]
    event: Vec<Spanned<RawEvent>>,
}

/// Every field of every kind; which belong to which kind is checked by
/// hand (so the message can name the kind). Values stay untyped so that a
/// wrong type is our message, not serde's.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawDevice {
    name: Option<Spanned<Value>>,
    kind: Option<Spanned<Value>>,
    interrupt: Option<Spanned<Value>>,
    input: Option<Spanned<Value>>,
    output: Option<Spanned<Value>>,
    control: Option<Spanned<Value>>,
    motor: Option<Spanned<Value>>,
    length: Option<Spanned<Value>>,
    speed: Option<Spanned<Value>>,
    end: Option<Spanned<Value>>,
    on: Option<Spanned<Value>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawEvent {
    at: Option<Spanned<Value>>,
    device: Option<Spanned<Value>>,
    input: Option<Spanned<Value>>,
    interrupt: Option<Spanned<Value>>,
    object: Option<Spanned<RawObject>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawObject {
    name: Option<Spanned<Value>>,
    width: Option<Spanned<Value>>,
}

type Field<'a> = &'a Option<Spanned<Value>>;

struct Cx<'a> {
    text: &'a str,
    path: &'a str,
    /// Where each `\n` is: a line number is a binary search (counting
    /// them for each of 40,000 events took 44 s).
    newlines: Vec<usize>,
}

impl Cx<'_> {
    fn err(&self, span: Range<usize>, message: impl Into<String>) -> DeviceFileError {
        DeviceFileError {
            path: self.path.to_string(),
            at: Some(crate::diag::line_col_in(self.text, span.start)),
            message: message.into(),
        }
    }

    fn line(&self, span: &Range<usize>) -> usize {
        self.newlines.partition_point(|&n| n < span.start) + 1
    }

    /// A field the table must have; `table` is the table's span.
    fn required<'v>(
        &self,
        field: Field<'v>,
        name: &str,
        table: &Range<usize>,
        what: &str,
    ) -> Result<&'v Spanned<Value>, DeviceFileError> {
        field
            .as_ref()
            .ok_or_else(|| self.err(table.clone(), format!("{what} has no `{name}`")))
    }

    fn string<'v>(&self, v: &'v Spanned<Value>, name: &str) -> Result<&'v str, DeviceFileError> {
        match v.get_ref() {
            Value::String(s) if !s.trim().is_empty() => Ok(s),
            Value::String(_) => Err(self.err(v.span(), format!("`{name}` is empty"))),
            other => Err(self.err(
                v.span(),
                format!("`{name}` must be a string, not {}", type_name(other)),
            )),
        }
    }

    /// A finite number (integers are welcome: `length = 500`) passing `ok`.
    fn number(
        &self,
        v: &Spanned<Value>,
        name: &str,
        ok: fn(f64) -> bool,
        want: &str,
    ) -> Result<f64, DeviceFileError> {
        let x = match v.get_ref() {
            Value::Float(x) => *x,
            Value::Integer(i) => *i as f64,
            other => {
                return Err(self.err(
                    v.span(),
                    format!("`{name}` must be {want}, not {}", type_name(other)),
                ));
            }
        };
        if x.is_finite() && ok(x) {
            Ok(x)
        } else {
            Err(self.err(v.span(), format!("`{name}` = {x:?}: must be {want}")))
        }
    }

    fn address(&self, v: &Spanned<Value>, name: &str) -> Result<Address, DeviceFileError> {
        match v.get_ref() {
            Value::Integer(i) => Address::try_from(*i).map_err(|_| {
                self.err(
                    v.span(),
                    format!(
                        "`{name}` = {i}: an address is from 0 to {} (0o{:o})",
                        Address::MAX,
                        Address::MAX
                    ),
                )
            }),
            Value::String(s) => Err(self.err(
                v.span(),
                format!(
                    "`{name}` must be an integer address; for Ada's `8#340#` write `0o340` (got the string \"{s}\")"
                ),
            )),
            other => Err(self.err(
                v.span(),
                format!("`{name}` must be an integer address such as 0o340, not {}", type_name(other)),
            )),
        }
    }

    fn word(&self, v: &Spanned<Value>, name: &str, max: u16) -> Result<u16, DeviceFileError> {
        match v.get_ref() {
            Value::Integer(i) if (0..=i64::from(max)).contains(i) => Ok(*i as u16),
            Value::Integer(i) => Err(self.err(
                v.span(),
                format!("`{name}` = {i}: must be from 0 to {max} (0x{max:X})"),
            )),
            other => Err(self.err(
                v.span(),
                format!(
                    "`{name}` must be an integer such as 0x00FF, not {}",
                    type_name(other)
                ),
            )),
        }
    }

    fn point(&self, v: &Spanned<Value>, name: &str) -> Result<[f64; 3], DeviceFileError> {
        let bad = || {
            self.err(
                v.span(),
                format!("`{name}` must be a position [x, y, z] of three finite numbers (mm)"),
            )
        };
        let Value::Array(items) = v.get_ref() else {
            return Err(bad());
        };
        if items.len() != 3 {
            return Err(bad());
        }
        let mut p = [0.0; 3];
        for (slot, item) in p.iter_mut().zip(items) {
            *slot = match item {
                Value::Float(x) if x.is_finite() => *x,
                Value::Integer(i) => *i as f64,
                _ => return Err(bad()),
            };
        }
        Ok(p)
    }
}

fn type_name(v: &Value) -> &'static str {
    match v {
        Value::String(_) => "a string",
        Value::Integer(_) => "an integer",
        Value::Float(_) => "a float",
        Value::Boolean(_) => "a boolean",
        Value::Datetime(_) => "a date",
        Value::Array(_) => "an array",
        Value::Table(_) => "a table",
    }
}

fn first_line(s: &str) -> String {
    s.lines().next().unwrap_or("").trim_end().to_string()
}

fn positive(x: f64) -> bool {
    x > 0.0
}

/// A time on the virtual clock: a `Duration` from the start.
fn a_time(x: f64) -> bool {
    (0.0..=9_223_372_036.854_776).contains(&x)
}

// ----------------------------------------------------------------- devices

/// The fields each kind takes (besides `name` and `kind`).
fn fields_of(kind: &str) -> &'static [&'static str] {
    match kind {
        "parallel" => &["interrupt", "input", "output", "control"],
        "light-barrier" => &["on", "input", "interrupt"],
        _ => &["motor", "length", "speed", "end"],
    }
}

fn parse_devices(cx: &Cx, raw: &[Spanned<RawDevice>]) -> Result<Vec<Device>, DeviceFileError> {
    let mut devices: Vec<Device> = Vec::new();
    let mut names: HashMap<String, usize> = HashMap::new();
    let mut used: HashMap<Address, (String, &'static str, usize)> = HashMap::new();
    // Barriers name their belt by name; resolved once every device is known.
    let mut on_names: Vec<(usize, &Spanned<Value>)> = Vec::new();

    for table in raw {
        let span = table.span();
        let d = table.get_ref();
        let what = "this `[[device]]`";
        let name_v = cx.required(&d.name, "name", &span, what)?;
        let name = cx.string(name_v, "name")?.to_string();
        let line = cx.line(&span);
        if let Some(&first) = names.get(&name) {
            return Err(cx.err(
                name_v.span(),
                format!("a device named `{name}` is already defined at line {first}"),
            ));
        }
        let what = format!("device `{name}`");
        let kind_v = cx.required(&d.kind, "kind", &span, &what)?;
        let kind = cx.string(kind_v, "kind")?;
        if !KINDS.contains(&kind) {
            return Err(cx.err(
                kind_v.span(),
                format!(
                    "unknown kind `{kind}` for device `{name}`; the kinds are {}",
                    KINDS.join(", ")
                ),
            ));
        }
        let all: [(&str, Field); 9] = [
            ("interrupt", &d.interrupt),
            ("input", &d.input),
            ("output", &d.output),
            ("control", &d.control),
            ("motor", &d.motor),
            ("length", &d.length),
            ("speed", &d.speed),
            ("end", &d.end),
            ("on", &d.on),
        ];
        let fields = fields_of(kind);
        for (field, v) in &all {
            if let Some(v) = v
                && !fields.contains(field)
            {
                return Err(cx.err(
                    v.span(),
                    format!(
                        "a {kind} device has no `{field}`; its fields are name, kind, {}",
                        fields.join(", ")
                    ),
                ));
            }
        }
        let index = devices.len();
        let mut addr = |field: Field, fname: &'static str| -> Result<Address, DeviceFileError> {
            let v = cx.required(field, fname, &span, &what)?;
            let a = cx.address(v, fname)?;
            if let Some((other, role, at)) = used.get(&a) {
                return Err(cx.err(
                    v.span(),
                    format!(
                        "address {} (0o{a:o}) is used twice: it is already the {role} of `{other}` (line {at})",
                        ada_address(a)
                    ),
                ));
            }
            used.insert(a, (name.clone(), fname, cx.line(&v.span())));
            Ok(a)
        };
        let kind = match kind {
            "parallel" => DeviceKind::Parallel {
                interrupt: addr(&d.interrupt, "interrupt")?,
                input: addr(&d.input, "input")?,
                output: addr(&d.output, "output")?,
                control: addr(&d.control, "control")?,
            },
            "light-barrier" => {
                let input = addr(&d.input, "input")?;
                let interrupt = match d.interrupt {
                    Some(_) => Some(addr(&d.interrupt, "interrupt")?),
                    None => None,
                };
                if let Some(on) = &d.on {
                    on_names.push((index, on));
                }
                DeviceKind::LightBarrier {
                    on: None,
                    input,
                    interrupt,
                }
            }
            _ => {
                let motor = addr(&d.motor, "motor")?;
                let length = cx.number(
                    cx.required(&d.length, "length", &span, &what)?,
                    "length",
                    positive,
                    "a length in mm > 0",
                )?;
                let speed = cx.number(
                    cx.required(&d.speed, "speed", &span, &what)?,
                    "speed",
                    positive,
                    "a speed in mm/s > 0",
                )?;
                let end = cx.point(cx.required(&d.end, "end", &span, &what)?, "end")?;
                DeviceKind::Conveyor {
                    motor,
                    length,
                    speed,
                    end,
                }
            }
        };
        names.insert(name.clone(), line);
        devices.push(Device { name, kind, line });
    }

    for (barrier, v) in on_names {
        let belt_name = cx.string(v, "on")?;
        let belt = devices.iter().position(|d| d.name == belt_name);
        let Some(belt) = belt.filter(|&b| matches!(devices[b].kind, DeviceKind::Conveyor { .. }))
        else {
            let why = match belt {
                Some(b) => format!("`{belt_name}` is a {}", devices[b].kind.name()),
                None => format!("no device is named `{belt_name}`"),
            };
            return Err(cx.err(
                v.span(),
                format!(
                    "light barrier `{}` is `on` a belt that is not there: {why}; `on` names a conveyor",
                    devices[barrier].name
                ),
            ));
        };
        if let DeviceKind::LightBarrier { on, .. } = &mut devices[barrier].kind {
            *on = Some(belt);
        }
    }
    Ok(devices)
}

// ------------------------------------------------------------------ events

fn parse_events(
    cx: &Cx,
    raw: &[Spanned<RawEvent>],
    devices: &[Device],
) -> Result<Vec<Event>, DeviceFileError> {
    let mut events = Vec::new();
    let mut objects: HashMap<String, usize> = HashMap::new();
    for table in raw {
        let span = table.span();
        let e = table.get_ref();
        let what = "this `[[event]]`";
        let at = cx.number(
            cx.required(&e.at, "at", &span, what)?,
            "at",
            a_time,
            "a time in seconds from 0 to Duration'Last (9223372036.854775807)",
        )?;
        let dev_v = cx.required(&e.device, "device", &span, what)?;
        let dev_name = cx.string(dev_v, "device")?;
        let Some(device) = devices.iter().position(|d| d.name == dev_name) else {
            let known: Vec<&str> = devices.iter().map(|d| d.name.as_str()).collect();
            let known = if known.is_empty() {
                "the file defines no device".to_string()
            } else {
                format!("the devices are {}", known.join(", "))
            };
            return Err(cx.err(
                dev_v.span(),
                format!("the event names an unknown device `{dev_name}`; {known}"),
            ));
        };
        let dev = &devices[device];
        let kind = dev.kind.name();
        let refuse = |span: Range<usize>, field: &str, why: &str| {
            cx.err(
                span,
                format!(
                    "an event on {kind} `{}` cannot have `{field}`: {why}",
                    dev.name
                ),
            )
        };

        let input = match &e.input {
            None => None,
            Some(v) => match &dev.kind {
                DeviceKind::Parallel { .. } => Some(cx.word(v, "input", u16::MAX)?),
                DeviceKind::LightBarrier { on: None, .. } => Some(cx.word(v, "input", 1)?),
                DeviceKind::LightBarrier { on: Some(b), .. } => {
                    return Err(refuse(
                        v.span(),
                        "input",
                        &format!("its beam follows the objects on `{}`", devices[*b].name),
                    ));
                }
                DeviceKind::Conveyor { .. } => {
                    return Err(refuse(
                        v.span(),
                        "input",
                        "a conveyor has no input register",
                    ));
                }
            },
        };

        let interrupt = match &e.interrupt {
            None => false,
            Some(v) => {
                let Value::Boolean(b) = v.get_ref() else {
                    return Err(cx.err(
                        v.span(),
                        format!(
                            "`interrupt` must be true or false, not {}",
                            type_name(v.get_ref())
                        ),
                    ));
                };
                let has = dev
                    .kind
                    .addresses()
                    .iter()
                    .any(|(_, r)| *r == Role::Interrupt);
                if *b && !has {
                    return Err(refuse(v.span(), "interrupt", "it has no interrupt address"));
                }
                *b
            }
        };

        let object = match &e.object {
            None => None,
            Some(o) => {
                if !matches!(dev.kind, DeviceKind::Conveyor { .. }) {
                    return Err(refuse(o.span(), "object", "objects are put on conveyors"));
                }
                let ospan = o.span();
                let what = "the `object`";
                let name_v = cx.required(&o.get_ref().name, "name", &ospan, what)?;
                let name = cx.string(name_v, "name")?.to_string();
                if let Some(first) = objects.get(&name) {
                    return Err(cx.err(
                        name_v.span(),
                        format!(
                            "an object named `{name}` is already put on a belt at line {first}"
                        ),
                    ));
                }
                objects.insert(name.clone(), cx.line(&name_v.span()));
                let width = cx.number(
                    cx.required(&o.get_ref().width, "width", &ospan, what)?,
                    "width",
                    positive,
                    "a width in mm > 0",
                )?;
                Some(ObjectSpec { name, width })
            }
        };

        if input.is_none() && object.is_none() && !interrupt {
            return Err(cx.err(
                span,
                "this `[[event]]` does nothing: give it `input`, `interrupt = true` or `object`",
            ));
        }
        events.push(Event {
            at,
            device,
            input,
            object,
            interrupt,
            line: cx.line(&span),
        });
    }
    Ok(events)
}
