//! One run of a device set on the caller's virtual clock.
//!
//! Belts keep the position of each object as of `since` (the last change on
//! that belt: motor switched, object placed, arrived or picked) and compute
//! positions from it, so an arrival time is `since + (length - p) / speed`
//! however often the clock is advanced in between: `advance_to` of the time
//! `next_wakeup` gave puts the object exactly at the end, at exactly that
//! time.

use super::Address;
use super::file::{DeviceKind, Devices, Role};
use super::report::{DeviceError, Happening, TimedHappening};
use std::collections::BTreeMap;
use std::fmt;

/// The gripper takes an object whose centre is this close to the TCP.
pub const GRIP_TOLERANCE_MM: f64 = 5.0;

/// An interrupt that was raised while enabled: the scheduler queues it on
/// the entry bound to `address`, as Ada queues an entry call.
#[derive(Clone, Debug, PartialEq)]
pub struct Interrupt {
    pub time: f64,
    pub address: Address,
    /// Index into [`Devices::devices`].
    pub device: usize,
}

/// Where an object is.
#[derive(Clone, Debug, PartialEq)]
pub enum Place {
    /// On a belt (an index into the devices), its centre `position` mm from
    /// the start (negative: waiting at the start for room); `at_end` when it
    /// has reached the end and breaks the beam there.
    OnBelt {
        belt: usize,
        position: f64,
        at_end: bool,
    },
    /// In the gripper.
    Held,
    /// Put down at a position (robot base coordinates, mm), off every belt.
    At([f64; 3]),
}

#[derive(Clone, Debug, PartialEq)]
pub struct ObjectInfo {
    pub name: String,
    pub width: f64,
    pub place: Place,
    /// Its centre where the gripper can reach it: the belt's `end` when it
    /// is at the end, where it was put down; `None` on the way or held.
    pub centre: Option<[f64; 3]>,
}

// ------------------------------------------------------------------- state

#[derive(Clone, Debug)]
pub(super) enum State {
    Parallel {
        input: u16,
        output: u16,
        control: u16,
    },
    Barrier {
        beam: bool,
    },
    Conveyor(Belt),
}

#[derive(Clone, Debug)]
pub(super) struct Belt {
    pub(super) motor: u16,
    /// The time the positions in `queue` are for.
    pub(super) since: f64,
    /// Objects front first: (object index, centre position at `since`).
    pub(super) queue: Vec<(usize, f64)>,
    /// The front object has reached the end.
    pub(super) at_end: bool,
}

impl Belt {
    pub(super) fn running(&self) -> bool {
        self.motor & 1 != 0
    }
}

#[derive(Clone, Debug)]
pub(super) enum Loc {
    Belt(usize),
    Held,
    At([f64; 3]),
}

#[derive(Clone, Debug)]
pub(super) struct Object {
    pub(super) name: String,
    pub(super) width: f64,
    pub(super) loc: Loc,
}

/// The devices of one run at time [`World::now`]. Cloning it copies the
/// whole state (for a rehearsal).
#[derive(Clone, Debug)]
pub struct World {
    pub(super) devs: Devices,
    pub(super) now: f64,
    /// The next scripted event to apply.
    pub(super) cursor: usize,
    pub(super) state: Vec<State>,
    /// Every object put on a belt so far, in that order.
    pub(super) objects: Vec<Object>,
    pub(super) dropped: BTreeMap<Address, u64>,
    pub(super) delivered: BTreeMap<Address, u64>,
    pub(super) log: Option<Vec<TimedHappening>>,
    /// The gripper is closing on an object: it is picked when the jaws
    /// close on it (time, name); see [`World::pick_at`].
    pub(super) closing_on: Option<(f64, String)>,
    /// The moments of the run, for the 3D view (`timeline.rs`).
    pub(super) timeline: Option<Box<super::timeline::Timeline>>,
}

impl World {
    /// The devices at time 0, before any event (events at 0 happen at the
    /// first `advance_to(0.0)`): registers 0, so the parallel port's
    /// interrupts are disabled until the program enables them.
    pub fn new(devices: Devices) -> World {
        let state = devices
            .devices()
            .iter()
            .map(|d| match d.kind {
                DeviceKind::Parallel { .. } => State::Parallel {
                    input: 0,
                    output: 0,
                    control: 0,
                },
                DeviceKind::LightBarrier { .. } => State::Barrier { beam: false },
                DeviceKind::Conveyor { .. } => State::Conveyor(Belt {
                    motor: 0,
                    since: 0.0,
                    queue: Vec::new(),
                    at_end: false,
                }),
            })
            .collect();
        World {
            devs: devices,
            now: 0.0,
            cursor: 0,
            state,
            objects: Vec::new(),
            dropped: BTreeMap::new(),
            delivered: BTreeMap::new(),
            log: None,
            closing_on: None,
            timeline: None,
        }
    }

    pub fn devices(&self) -> &Devices {
        &self.devs
    }

    /// The virtual time the world has been advanced to.
    pub fn now(&self) -> f64 {
        self.now
    }

    /// Keep a log of what happens, for `--trace` ([`World::take_log`]).
    pub fn set_logging(&mut self, on: bool) {
        self.log = if on { Some(Vec::new()) } else { None };
    }

    /// What happened since the last call, in order.
    pub fn take_log(&mut self) -> Vec<TimedHappening> {
        self.log.as_mut().map(std::mem::take).unwrap_or_default()
    }

    fn note(&mut self, time: f64, what: Happening) {
        self.timeline_note(&what);
        if let Some(log) = &mut self.log {
            log.push(TimedHappening { time, what });
        }
    }

    fn name(&self, device: usize) -> String {
        self.devs.devices()[device].name.clone()
    }

    // ------------------------------------------------------------- clock

    /// Applies everything that happens up to and including `t`, in time
    /// order: scripted events, objects reaching a belt's end (before the
    /// events of the same instant), and returns the interrupts delivered,
    /// each with its time. A `t` before [`World::now`] (or NaN) changes
    /// nothing.
    pub fn advance_to(&mut self, t: f64) -> Vec<Interrupt> {
        let mut out = Vec::new();
        if t.is_nan() || t < self.now {
            return out;
        }
        loop {
            // The jaws close on an object before whatever else happens at
            // or after that moment.
            if let Some((tc, _)) = &self.closing_on
                && *tc <= t
                && self.next_arrival().is_none_or(|(ta, _)| *tc <= ta)
                && self
                    .devs
                    .events()
                    .get(self.cursor)
                    .is_none_or(|e| *tc <= e.at)
            {
                let (tc, name) = self.closing_on.take().expect("closing");
                self.now = self.now.max(tc);
                let _ = self.pick(&name);
                continue;
            }
            let arrival = self.next_arrival().filter(|&(ta, _)| ta <= t);
            let event = self
                .devs
                .events()
                .get(self.cursor)
                .map(|e| e.at)
                .filter(|&te| te <= t);
            match (arrival, event) {
                (Some((ta, belt)), te) if te.is_none_or(|te| ta <= te) => {
                    self.now = self.now.max(ta);
                    self.arrive(belt, &mut out);
                    self.timeline_flush();
                }
                (_, Some(te)) => {
                    self.now = self.now.max(te);
                    let i = self.cursor;
                    self.cursor += 1;
                    self.apply_event(i, &mut out);
                    self.timeline_flush();
                }
                _ => break,
            }
        }
        self.now = t;
        out
    }

    /// The earliest time, not before `after`, at which [`World::advance_to`]
    /// has something to do: the next scripted event or the next object to
    /// reach a belt's end as the belts run now (a register write can change
    /// it: ask again after one). `None`: nothing will ever happen by
    /// itself. Something already due before `after` gives `after`.
    pub fn next_wakeup(&self, after: f64) -> Option<f64> {
        let event = self.devs.events().get(self.cursor).map(|e| e.at);
        let arrival = self.next_arrival().map(|(t, _)| t);
        let closing = self.closing_on.as_ref().map(|c| c.0);
        let t = [event, arrival, closing]
            .into_iter()
            .flatten()
            .reduce(f64::min)?;
        Some(t.max(after))
    }

    /// The earliest arrival on any belt (earlier belts first on a tie).
    fn next_arrival(&self) -> Option<(f64, usize)> {
        let mut best: Option<(f64, usize)> = None;
        for (i, s) in self.state.iter().enumerate() {
            if let State::Conveyor(b) = s
                && let Some(t) = self.arrival(i, b)
                && best.is_none_or(|(bt, _)| t < bt)
            {
                best = Some((t, i));
            }
        }
        best
    }

    fn arrival(&self, device: usize, b: &Belt) -> Option<f64> {
        let (length, speed, _) = self.belt_spec(device);
        let &(_, p) = b.queue.first()?;
        (b.running() && !b.at_end).then(|| b.since + (length - p) / speed)
    }

    pub(super) fn belt_spec(&self, device: usize) -> (f64, f64, [f64; 3]) {
        match self.devs.devices()[device].kind {
            DeviceKind::Conveyor {
                length, speed, end, ..
            } => (length, speed, end),
            _ => unreachable!("belt_spec of a device that is not a conveyor"),
        }
    }

    /// Positions of the objects on a belt at time `t` (>= since): each one
    /// moves `speed * dt` while the motor runs, the front one up to the
    /// end, every other one up to the one in front of it.
    pub(super) fn positions_at(&self, device: usize, t: f64) -> Vec<f64> {
        let State::Conveyor(b) = &self.state[device] else {
            return Vec::new();
        };
        let (length, speed, _) = self.belt_spec(device);
        let step = if b.running() {
            speed * (t - b.since)
        } else {
            0.0
        };
        let mut out: Vec<f64> = Vec::with_capacity(b.queue.len());
        for (k, &(obj, p)) in b.queue.iter().enumerate() {
            let limit = match k {
                0 => length,
                _ => {
                    let (ahead, _) = b.queue[k - 1];
                    out[k - 1] - (self.objects[ahead].width + self.objects[obj].width) / 2.0
                }
            };
            out.push((p + step).min(limit).max(p));
        }
        out
    }

    /// Makes the stored positions those of `now` and `since` now.
    fn settle(&mut self, device: usize) {
        let now = self.now;
        let pos = self.positions_at(device, now);
        if let State::Conveyor(b) = &mut self.state[device] {
            for (slot, p) in b.queue.iter_mut().zip(pos) {
                slot.1 = p;
            }
            b.since = now;
        }
    }

    fn arrive(&mut self, belt: usize, out: &mut Vec<Interrupt>) {
        self.settle(belt);
        let (length, _, _) = self.belt_spec(belt);
        let State::Conveyor(b) = &mut self.state[belt] else {
            return;
        };
        // Exactly at the end, whatever rounding made of `since + dt`.
        b.queue[0].1 = length;
        b.at_end = true;
        let obj = b.queue[0].0;
        let (name, object) = (self.name(belt), self.objects[obj].name.clone());
        self.note(self.now, Happening::Arrived { belt: name, object });
        for barrier in self.barriers_on(belt) {
            self.set_beam(barrier, true, out);
        }
    }

    fn barriers_on(&self, belt: usize) -> Vec<usize> {
        self.devs
            .devices()
            .iter()
            .enumerate()
            .filter(|(_, d)| matches!(d.kind, DeviceKind::LightBarrier { on: Some(b), .. } if b == belt))
            .map(|(i, _)| i)
            .collect()
    }

    /// Sets a light barrier's beam; the rising edge interrupts.
    fn set_beam(&mut self, barrier: usize, broken: bool, out: &mut Vec<Interrupt>) {
        let State::Barrier { beam } = &mut self.state[barrier] else {
            return;
        };
        if *beam == broken {
            return;
        }
        *beam = broken;
        let name = self.name(barrier);
        self.note(
            self.now,
            Happening::Beam {
                barrier: name,
                broken,
            },
        );
        if broken
            && let DeviceKind::LightBarrier {
                interrupt: Some(a), ..
            } = self.devs.devices()[barrier].kind
        {
            out.extend(self.interrupt(barrier, a));
        }
    }

    /// Raises a device's interrupt now: delivered when enabled, else
    /// dropped and counted.
    fn interrupt(&mut self, device: usize, address: Address) -> Option<Interrupt> {
        let enabled = match self.state[device] {
            State::Parallel { control, .. } => control & 1 != 0,
            _ => true,
        };
        let counter = if enabled {
            &mut self.delivered
        } else {
            &mut self.dropped
        };
        *counter.entry(address).or_insert(0) += 1;
        let dropped = self.dropped.get(&address).copied().unwrap_or(0);
        let name = self.name(device);
        self.note(
            self.now,
            Happening::Interrupt {
                device: name,
                address,
                delivered: enabled,
                dropped,
            },
        );
        enabled.then_some(Interrupt {
            time: self.now,
            address,
            device,
        })
    }

    fn apply_event(&mut self, i: usize, out: &mut Vec<Interrupt>) {
        let e = self.devs.events()[i].clone();
        let dev = e.device;
        if let Some(v) = e.input {
            match (&mut self.state[dev], &self.devs.devices()[dev].kind) {
                (State::Parallel { input, .. }, DeviceKind::Parallel { input: a, .. }) => {
                    *input = v;
                    let (address, device) = (*a, self.name(dev));
                    self.note(
                        self.now,
                        Happening::Input {
                            device,
                            address,
                            value: v,
                        },
                    );
                }
                (State::Barrier { .. }, _) => self.set_beam(dev, v != 0, out),
                _ => {}
            }
        }
        if let Some(o) = e.object {
            self.place(dev, o.name, o.width);
        }
        if e.interrupt
            && let Some((a, _)) = self.devs.devices()[dev]
                .kind
                .addresses()
                .into_iter()
                .find(|(_, r)| *r == Role::Interrupt)
        {
            out.extend(self.interrupt(dev, a));
        }
    }

    /// Puts an object on a belt's start, or, when the last object is still
    /// too close to it, just behind that one (it waits for room).
    fn place(&mut self, belt: usize, name: String, width: f64) {
        self.settle(belt);
        let State::Conveyor(b) = &self.state[belt] else {
            return;
        };
        let position = match b.queue.last() {
            Some(&(last, p)) => (p - (self.objects[last].width + width) / 2.0).min(0.0),
            None => 0.0,
        };
        let index = self.objects.len();
        self.objects.push(Object {
            name: name.clone(),
            width,
            loc: Loc::Belt(belt),
        });
        if let State::Conveyor(b) = &mut self.state[belt] {
            b.queue.push((index, position));
        }
        let belt = self.name(belt);
        self.note(self.now, Happening::Placed { belt, object: name });
    }

    // --------------------------------------------------------- registers

    /// Whether an interrupt sits at `address` (for `for E use at`).
    pub fn is_interrupt(&self, address: Address) -> bool {
        self.devs.is_interrupt(address)
    }

    /// The register at `address` now; `None` when no register is there (no
    /// device, or an interrupt). A light barrier reads 1 while its beam is
    /// broken; output, control and motor registers read what was written.
    pub fn read(&self, address: Address) -> Option<u16> {
        let (d, role) = self.devs.lookup(address)?;
        match (&self.state[d], role) {
            (State::Parallel { input, .. }, Role::Input) => Some(*input),
            (State::Parallel { output, .. }, Role::Output) => Some(*output),
            (State::Parallel { control, .. }, Role::Control) => Some(*control),
            (State::Barrier { beam }, Role::Input) => Some(u16::from(*beam)),
            (State::Conveyor(b), Role::Motor) => Some(b.motor),
            _ => None,
        }
    }

    /// The program writes a register now. Output, control and motor
    /// registers take the value (bit 0 of control enables the interrupt,
    /// bit 0 of motor runs the belt); an input register or an interrupt
    /// refuses, and nothing changes.
    pub fn write(&mut self, address: Address, value: u16) -> Result<(), DeviceError> {
        let (d, role) = self
            .devs
            .lookup(address)
            .ok_or(DeviceError::NoDevice(address))?;
        let device = self.name(d);
        match role {
            Role::Interrupt => return Err(DeviceError::NotARegister { address, device }),
            Role::Input => return Err(DeviceError::ReadOnly { address, device }),
            Role::Motor => self.settle(d),
            Role::Output | Role::Control => {}
        }
        let slot = match (&mut self.state[d], role) {
            (State::Parallel { output, .. }, Role::Output) => output,
            (State::Parallel { control, .. }, Role::Control) => control,
            (State::Conveyor(b), Role::Motor) => &mut b.motor,
            _ => unreachable!("a writable role of the wrong device"),
        };
        if *slot != value {
            *slot = value;
            self.note(
                self.now,
                Happening::Written {
                    device,
                    address,
                    role,
                    value,
                },
            );
        }
        self.timeline_flush();
        Ok(())
    }

    /// The REPL's `:set ADDR VALUE`: sets an input register now. A light
    /// barrier that is not on a belt takes 0 or 1 (1 breaks the beam and
    /// interrupts on the rising edge); one on a belt refuses.
    pub fn set_input(
        &mut self,
        address: Address,
        value: u16,
    ) -> Result<Option<Interrupt>, DeviceError> {
        let (d, role) = self
            .devs
            .lookup(address)
            .ok_or(DeviceError::NoDevice(address))?;
        let device = self.name(d);
        if role != Role::Input {
            return Err(DeviceError::NotAnInput {
                address,
                device,
                role,
            });
        }
        let mut out = Vec::new();
        match (&mut self.state[d], &self.devs.devices()[d].kind) {
            (State::Parallel { input, .. }, _) => {
                *input = value;
                self.note(
                    self.now,
                    Happening::Input {
                        device,
                        address,
                        value,
                    },
                );
            }
            (_, DeviceKind::LightBarrier { on: Some(b), .. }) => {
                let belt = self.name(*b);
                return Err(DeviceError::FollowsBelt {
                    address,
                    barrier: device,
                    belt,
                });
            }
            _ if value > 1 => {
                return Err(DeviceError::OutOfRange {
                    address,
                    value,
                    max: 1,
                });
            }
            _ => self.set_beam(d, value == 1, &mut out),
        }
        self.timeline_flush();
        Ok(out.pop())
    }

    /// The REPL's `:irq ADDR`: raises the interrupt now. `Some` when it is
    /// delivered, `None` when interrupts are disabled (dropped, counted).
    pub fn raise_interrupt(&mut self, address: Address) -> Result<Option<Interrupt>, DeviceError> {
        let (d, role) = self
            .devs
            .lookup(address)
            .ok_or(DeviceError::NoDevice(address))?;
        if role != Role::Interrupt {
            let device = self.name(d);
            return Err(DeviceError::NotAnInterrupt {
                address,
                device,
                role,
            });
        }
        let r = self.interrupt(d, address);
        self.timeline_flush();
        Ok(r)
    }

    /// Interrupts at `address` dropped because they were disabled.
    pub fn dropped(&self, address: Address) -> u64 {
        self.dropped.get(&address).copied().unwrap_or(0)
    }

    /// Interrupts at `address` delivered to the caller.
    pub fn delivered(&self, address: Address) -> u64 {
        self.delivered.get(&address).copied().unwrap_or(0)
    }

    // ----------------------------------------------------------- objects

    fn info(&self, index: usize) -> ObjectInfo {
        let o = &self.objects[index];
        let (place, centre) = match &o.loc {
            Loc::Held => (Place::Held, None),
            Loc::At(p) => (Place::At(*p), Some(*p)),
            Loc::Belt(belt) => {
                let belt = *belt;
                let State::Conveyor(b) = &self.state[belt] else {
                    unreachable!("an object on a device that is not a belt")
                };
                let k = b.queue.iter().position(|&(i, _)| i == index).unwrap_or(0);
                let position = self.positions_at(belt, self.now)[k];
                let at_end = k == 0 && b.at_end;
                let centre = at_end.then(|| self.belt_spec(belt).2);
                (
                    Place::OnBelt {
                        belt,
                        position,
                        at_end,
                    },
                    centre,
                )
            }
        };
        ObjectInfo {
            name: o.name.clone(),
            width: o.width,
            place,
            centre,
        }
    }

    /// Every object put on a belt so far, in that order, with where it is.
    pub fn objects(&self) -> Vec<ObjectInfo> {
        (0..self.objects.len()).map(|i| self.info(i)).collect()
    }

    /// The object the gripper would take at `position`: the nearest one
    /// whose centre is within `tolerance` mm (at a belt's end, or where it
    /// was put down), the first put on a belt on a tie.
    pub fn object_at(&self, position: [f64; 3], tolerance: f64) -> Option<ObjectInfo> {
        let mut best: Option<(f64, ObjectInfo)> = None;
        for i in 0..self.objects.len() {
            let info = self.info(i);
            let Some(c) = info.centre else { continue };
            let d = dist(c, position);
            if d <= tolerance && best.as_ref().is_none_or(|(bd, _)| d < *bd) {
                best = Some((d, info));
            }
        }
        best.map(|(_, info)| info)
    }

    /// The gripper starts closing on an object and its jaws reach it at
    /// `time` (tasks.md: picking it from the belt's end clears the beam at
    /// the moment the jaws close on it): it is picked when the world is
    /// advanced to that time, or now if that time has passed. Refused at
    /// once for an object that does not exist or is held.
    pub fn pick_at(&mut self, name: &str, time: f64) -> Result<(), DeviceError> {
        let o = self
            .objects
            .iter()
            .find(|o| o.name == name)
            .ok_or_else(|| DeviceError::UnknownObject(name.to_string()))?;
        if matches!(o.loc, Loc::Held) {
            return Err(DeviceError::AlreadyHeld(name.to_string()));
        }
        if time <= self.now {
            return self.pick(name).map(|_| ());
        }
        self.closing_on = Some((time, name.to_string()));
        Ok(())
    }

    /// The gripper closes on an object now: it leaves its belt (the beam at
    /// the end clears at this moment) or the place it was put down. Returns
    /// where it was.
    pub fn pick(&mut self, name: &str) -> Result<ObjectInfo, DeviceError> {
        let index = self
            .objects
            .iter()
            .position(|o| o.name == name)
            .ok_or_else(|| DeviceError::UnknownObject(name.to_string()))?;
        let was = self.info(index);
        match self.objects[index].loc {
            Loc::Held => return Err(DeviceError::AlreadyHeld(name.to_string())),
            Loc::At(_) => {}
            Loc::Belt(belt) => {
                self.settle(belt);
                let mut cleared = false;
                if let State::Conveyor(b) = &mut self.state[belt] {
                    let k = b.queue.iter().position(|&(i, _)| i == index).unwrap_or(0);
                    b.queue.remove(k);
                    if k == 0 && b.at_end {
                        b.at_end = false;
                        cleared = true;
                    }
                }
                if cleared {
                    for barrier in self.barriers_on(belt) {
                        self.set_beam(barrier, false, &mut Vec::new());
                    }
                }
            }
        }
        self.objects[index].loc = Loc::Held;
        self.note(
            self.now,
            Happening::Picked {
                object: name.to_string(),
            },
        );
        self.timeline_flush();
        Ok(was)
    }

    /// The gripper opens: the object it holds lies at `position` now, off
    /// every belt.
    pub fn put_down(&mut self, name: &str, position: [f64; 3]) -> Result<(), DeviceError> {
        let o = self
            .objects
            .iter_mut()
            .find(|o| o.name == name)
            .ok_or_else(|| DeviceError::UnknownObject(name.to_string()))?;
        if !matches!(o.loc, Loc::Held) {
            return Err(DeviceError::NotHeld(name.to_string()));
        }
        o.loc = Loc::At(position);
        self.note(
            self.now,
            Happening::PutDown {
                object: name.to_string(),
                at: position,
            },
        );
        self.timeline_flush();
        Ok(())
    }
}

impl fmt::Display for World {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.describe())
    }
}

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}
