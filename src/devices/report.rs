//! What the device world says about itself: refusals ([`DeviceError`]),
//! what happened ([`Happening`], one `--trace` line each), `:devices`
//! ([`World::describe`]) and the one-line state for `--trace`
//! ([`World::trace_line`]).

use super::file::{DeviceKind, Role};
use super::world::{Loc, State, World};
use super::{Address, ada_address, ada_word};
use std::fmt::{self, Write as _};

/// Why a register access or a gripper operation is refused.
#[derive(Clone, Debug, PartialEq)]
pub enum DeviceError {
    NoDevice(Address),
    /// An interrupt address is not a register.
    NotARegister {
        address: Address,
        device: String,
    },
    /// Writing an input register: the outside world sets it.
    ReadOnly {
        address: Address,
        device: String,
    },
    /// `:set` on something that is not an input register.
    NotAnInput {
        address: Address,
        device: String,
        role: Role,
    },
    /// `:irq` on something that is not an interrupt.
    NotAnInterrupt {
        address: Address,
        device: String,
        role: Role,
    },
    /// `:set` on a light barrier whose beam the belt's objects decide.
    FollowsBelt {
        address: Address,
        barrier: String,
        belt: String,
    },
    OutOfRange {
        address: Address,
        value: u16,
        max: u16,
    },
    /// No object of that name is in the world (yet).
    UnknownObject(String),
    AlreadyHeld(String),
    NotHeld(String),
}

impl fmt::Display for DeviceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use DeviceError::*;
        match self {
            NoDevice(a) => write!(f, "no device at {}", ada_address(*a)),
            NotARegister { address, device } => write!(
                f,
                "{} is the interrupt of `{device}`, not a register",
                ada_address(*address)
            ),
            ReadOnly { address, device } => write!(
                f,
                "{} is the input register of `{device}`: it is set from outside, not written",
                ada_address(*address)
            ),
            NotAnInput {
                address,
                device,
                role,
            } => write!(
                f,
                "{} is the {} of `{device}`, not an input register",
                ada_address(*address),
                role.describe()
            ),
            NotAnInterrupt {
                address,
                device,
                role,
            } => write!(
                f,
                "{} is the {} of `{device}`, not an interrupt",
                ada_address(*address),
                role.describe()
            ),
            FollowsBelt {
                address,
                barrier,
                belt,
            } => write!(
                f,
                "{} is light barrier `{barrier}` on `{belt}`: the objects on the belt break its beam",
                ada_address(*address)
            ),
            OutOfRange {
                address,
                value,
                max,
            } => write!(
                f,
                "{value} does not fit the register at {} (0 .. {max})",
                ada_address(*address)
            ),
            UnknownObject(n) => write!(f, "there is no object `{n}`"),
            AlreadyHeld(n) => write!(f, "object `{n}` is already in the gripper"),
            NotHeld(n) => write!(f, "object `{n}` is not in the gripper"),
        }
    }
}

impl std::error::Error for DeviceError {}

/// Something that happened in the device world, for `--trace`.
#[derive(Clone, Debug, PartialEq)]
pub enum Happening {
    Input {
        device: String,
        address: Address,
        value: u16,
    },
    /// The program wrote a register and changed it.
    Written {
        device: String,
        address: Address,
        role: Role,
        value: u16,
    },
    Placed {
        belt: String,
        object: String,
    },
    Arrived {
        belt: String,
        object: String,
    },
    Beam {
        barrier: String,
        broken: bool,
    },
    Interrupt {
        device: String,
        address: Address,
        delivered: bool,
        /// How many of this address's interrupts were dropped so far
        /// (this one included, when it is dropped).
        dropped: u64,
    },
    Picked {
        object: String,
    },
    PutDown {
        object: String,
        at: [f64; 3],
    },
}

impl fmt::Display for Happening {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use Happening::*;
        match self {
            Input {
                device,
                address,
                value,
            } => write!(
                f,
                "{device}: input {} := {}",
                ada_address(*address),
                ada_word(*value)
            ),
            Written {
                device,
                address,
                role,
                value,
            } => write!(
                f,
                "{device}: {} {} := {}",
                role.describe(),
                ada_address(*address),
                ada_word(*value)
            ),
            Placed { belt, object } => write!(f, "{belt}: {object} put on the start"),
            Arrived { belt, object } => write!(f, "{belt}: {object} reaches the end"),
            Beam { barrier, broken } => {
                let s = if *broken { "broken" } else { "clear" };
                write!(f, "{barrier}: beam {s}")
            }
            Interrupt {
                device,
                address,
                delivered,
                dropped,
            } => {
                let s = if *delivered {
                    "delivered".to_string()
                } else {
                    format!("dropped (interrupts disabled; {dropped} dropped so far)")
                };
                write!(f, "{device}: interrupt {} {s}", ada_address(*address))
            }
            Picked { object } => write!(f, "gripper: {object} picked"),
            PutDown { object, at } => write!(f, "gripper: {object} put down at {}", mm3(at)),
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct TimedHappening {
    pub time: f64,
    pub what: Happening,
}

/// One `--trace` line, in the services' trace form:
/// `[t=    6.000 s] devices: belt: box1 reaches the end`.
impl fmt::Display for TimedHappening {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "[t={:9.3} s] devices: {}", self.time, self.what)
    }
}
impl World {
    /// What `:devices` shows: each device with its registers (Ada octal
    /// addresses, hexadecimal values), interrupt counts, the objects on
    /// each belt, then the objects off the belts.
    pub fn describe(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "devices of {} at t = {:.3} s",
            self.devs.source(),
            self.now
        );
        for (d, dev) in self.devs.devices().iter().enumerate() {
            match (&dev.kind, &self.state[d]) {
                (
                    DeviceKind::Parallel {
                        interrupt,
                        input,
                        output,
                        control,
                    },
                    State::Parallel {
                        input: i,
                        output: o,
                        control: c,
                    },
                ) => {
                    let _ = writeln!(s, "{} (parallel)", dev.name);
                    let on = if c & 1 != 0 { "enabled" } else { "disabled" };
                    self.interrupt_line(&mut s, *interrupt, on);
                    let _ = writeln!(
                        s,
                        "  {:<8} input      {}",
                        ada_address(*input),
                        ada_word(*i)
                    );
                    let _ = writeln!(
                        s,
                        "  {:<8} output     {}",
                        ada_address(*output),
                        ada_word(*o)
                    );
                    let _ = writeln!(
                        s,
                        "  {:<8} control    {} (interrupts {on})",
                        ada_address(*control),
                        ada_word(*c)
                    );
                }
                (
                    DeviceKind::LightBarrier {
                        on,
                        input,
                        interrupt,
                    },
                    State::Barrier { beam },
                ) => {
                    let at = match on {
                        Some(b) => format!(" at the end of {}", self.devs.devices()[*b].name),
                        None => String::new(),
                    };
                    let _ = writeln!(s, "{} (light barrier{at})", dev.name);
                    if let Some(a) = interrupt {
                        self.interrupt_line(&mut s, *a, "always enabled, rising edge");
                    }
                    let state = if *beam { "beam broken" } else { "beam clear" };
                    let _ = writeln!(
                        s,
                        "  {:<8} input      {} ({state})",
                        ada_address(*input),
                        u8::from(*beam)
                    );
                }
                (
                    DeviceKind::Conveyor {
                        motor,
                        length,
                        speed,
                        end,
                    },
                    State::Conveyor(b),
                ) => {
                    let _ = writeln!(
                        s,
                        "{} (conveyor, {length} mm at {speed} mm/s, end at {})",
                        dev.name,
                        mm3(end)
                    );
                    let run = if b.running() { "running" } else { "stopped" };
                    let _ = writeln!(
                        s,
                        "  {:<8} motor      {} ({run})",
                        ada_address(*motor),
                        ada_word(b.motor)
                    );
                    let pos = self.positions_at(d, self.now);
                    if b.queue.is_empty() {
                        let _ = writeln!(s, "  no objects");
                    }
                    for (k, &(o, _)) in b.queue.iter().enumerate() {
                        let _ =
                            writeln!(s, "  {}", self.object_words(o, pos[k], k == 0 && b.at_end));
                    }
                }
                _ => {}
            }
        }
        for o in &self.objects {
            match &o.loc {
                Loc::Held => {
                    let _ = writeln!(s, "{} ({} mm) in the gripper", o.name, o.width);
                }
                Loc::At(p) => {
                    let _ = writeln!(s, "{} ({} mm) put down at {}", o.name, o.width, mm3(p));
                }
                Loc::Belt(_) => {}
            }
        }
        s
    }

    fn interrupt_line(&self, s: &mut String, a: Address, how: &str) {
        let _ = writeln!(
            s,
            "  {:<8} interrupt  {how}; {} delivered, {} dropped",
            ada_address(a),
            self.delivered(a),
            self.dropped(a)
        );
    }

    fn object_words(&self, o: usize, position: f64, at_end: bool) -> String {
        let o = &self.objects[o];
        let w = if at_end {
            "at the end".to_string()
        } else if position < 0.0 {
            "waiting at the start".to_string()
        } else {
            format!("at {position:.1} mm")
        };
        format!("{} ({} mm) {w}", o.name, o.width)
    }

    /// The devices in one line, for `--trace`:
    /// `[t=    6.000 s] devices: parallel in=16#00FF# out=16#0000# ctl=16#0001# dropped=0; belt motor=16#0001# box1@500.0(end); exit beam=1`.
    pub fn trace_line(&self) -> String {
        let mut parts = Vec::new();
        for (d, dev) in self.devs.devices().iter().enumerate() {
            let p = match (&self.state[d], &dev.kind) {
                (
                    State::Parallel {
                        input,
                        output,
                        control,
                    },
                    DeviceKind::Parallel { interrupt, .. },
                ) => {
                    format!(
                        "{} in={} out={} ctl={} dropped={}",
                        dev.name,
                        ada_word(*input),
                        ada_word(*output),
                        ada_word(*control),
                        self.dropped(*interrupt)
                    )
                }
                (State::Barrier { beam }, _) => format!("{} beam={}", dev.name, u8::from(*beam)),
                (State::Conveyor(b), _) => {
                    let pos = self.positions_at(d, self.now);
                    let mut t = format!("{} motor={}", dev.name, ada_word(b.motor));
                    for (k, &(o, _)) in b.queue.iter().enumerate() {
                        let end = if k == 0 && b.at_end { "(end)" } else { "" };
                        let _ = write!(t, " {}@{:.1}{end}", self.objects[o].name, pos[k]);
                    }
                    t
                }
                _ => continue,
            };
            parts.push(p);
        }
        for o in &self.objects {
            match &o.loc {
                Loc::Held => parts.push(format!("{} held", o.name)),
                Loc::At(p) => parts.push(format!("{} at {}", o.name, mm3(p))),
                Loc::Belt(_) => {}
            }
        }
        format!("[t={:9.3} s] devices: {}", self.now, parts.join("; "))
    }
}

fn mm3(p: &[f64; 3]) -> String {
    format!("({:.1}, {:.1}, {:.1}) mm", p[0], p[1], p[2])
}
