//! The device world on a timeline, for the 3D view (docs/view.md): each
//! moment something happened ([`Moment`]) with how every object that
//! changed its course moves from then on, and the beams that changed.
//!
//! An object on a belt moves at a constant speed up to a stop (the belt's
//! end for the front object, the one ahead of it for the others) until
//! the next moment that names it: its position at a later time `t` is
//! `min(position + speed * (t - time), stop)`, as [`World`] computes it
//! (`positions_at`). A held object is wherever the TCP is; one put down
//! stays where it was put. So a page can place each object at any time
//! from a few numbers per change, and the moments are few: one per
//! instant at which the world changed, naming only what changed.
//!
//! The timeline is off until [`World::keep_timeline`] (a replay page
//! reads it at the end of the run) or [`World::set_sink`] (the live view
//! gets each moment as it is made); a run without `--view` keeps nothing.

use super::world::{Loc, State, World};
use super::{DeviceKind, Happening};
use std::sync::Arc;

/// How an object moves from a moment on.
#[derive(Clone, Debug, PartialEq)]
pub enum Course {
    /// On `belt`, its centre `position` mm from the belt's start at the
    /// moment, moving at `speed` mm/s (0 while the motor is off) up to
    /// `stop`.
    Belt {
        belt: String,
        position: f64,
        speed: f64,
        stop: f64,
    },
    /// In the gripper: at the TCP.
    Held,
    /// Put down there (robot base coordinates, mm).
    At([f64; 3]),
}

impl Course {
    /// Where along its belt an object on this course is `dt` seconds
    /// after the moment (`None` off a belt).
    pub fn position_after(&self, dt: f64) -> Option<f64> {
        match self {
            Course::Belt {
                position,
                speed,
                stop,
                ..
            } => Some((position + speed * dt.max(0.0)).min(*stop).max(*position)),
            _ => None,
        }
    }
}

/// An object whose course changed at a moment.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjectCourse {
    pub name: String,
    pub width: f64,
    pub course: Course,
}

/// One instant at which the device world changed.
#[derive(Clone, Debug, PartialEq)]
pub struct Moment {
    /// Virtual time, s.
    pub time: f64,
    /// What happened, one `--trace` text each (without the time).
    pub what: Vec<String>,
    /// The objects whose course changed (a new object, a belt started or
    /// stopped, an arrival, a pick, a put-down).
    pub objects: Vec<ObjectCourse>,
    /// The light barriers whose beam changed: (name, broken).
    pub beams: Vec<(String, bool)>,
}

/// Who gets each moment as it is made (the live view).
pub type Sink = Arc<dyn Fn(&Moment) + Send + Sync>;

#[derive(Clone)]
pub(super) struct Timeline {
    keep: bool,
    moments: Vec<Moment>,
    sink: Option<Sink>,
    /// What happened since the last moment.
    pending: Vec<String>,
    /// Each object's course as last told, with the time it was told.
    told: Vec<Option<(f64, Course)>>,
    /// Objects that may change course by themselves or were touched:
    /// those on a belt or held, and those picked or put down.
    moving: Vec<usize>,
    /// Each device's beam as last told (false for what is not a barrier).
    beams: Vec<bool>,
}

impl std::fmt::Debug for Timeline {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Timeline")
            .field("keep", &self.keep)
            .field("moments", &self.moments.len())
            .field("sink", &self.sink.is_some())
            .finish()
    }
}

impl Timeline {
    fn new(devices: usize) -> Timeline {
        Timeline {
            keep: false,
            moments: Vec::new(),
            sink: None,
            pending: Vec::new(),
            told: Vec::new(),
            moving: Vec::new(),
            beams: vec![false; devices],
        }
    }
}

/// Two courses are the same when the later one is where the earlier one
/// leads (1 µm), at the same speed and stop.
fn same(old: &(f64, Course), time: f64, new: &Course) -> bool {
    match (&old.1, new) {
        (
            a @ Course::Belt {
                belt: b1,
                speed: s1,
                stop: e1,
                ..
            },
            Course::Belt {
                belt: b2,
                position: p2,
                speed: s2,
                stop: e2,
            },
        ) => {
            b1 == b2
                && s1 == s2
                && (e1 - e2).abs() < 1e-9
                && a.position_after(time - old.0)
                    .is_some_and(|p| (p - p2).abs() < 1e-3)
        }
        (a, b) => a == b,
    }
}

impl World {
    /// Keeps every moment of the run from now on ([`World::timeline`]).
    pub fn keep_timeline(&mut self) {
        let n = self.devs.devices().len();
        self.timeline
            .get_or_insert_with(|| Box::new(Timeline::new(n)))
            .keep = true;
    }

    /// Gives every moment from now on to `sink` as it is made (`None`:
    /// to no one).
    pub fn set_sink(&mut self, sink: Option<Sink>) {
        if sink.is_none() && self.timeline.is_none() {
            return;
        }
        let n = self.devs.devices().len();
        self.timeline
            .get_or_insert_with(|| Box::new(Timeline::new(n)))
            .sink = sink;
    }

    /// The moments kept so far (none unless [`World::keep_timeline`]).
    pub fn timeline(&self) -> &[Moment] {
        self.timeline.as_ref().map_or(&[], |t| &t.moments)
    }

    /// Notes a happening for the next moment (from `note`).
    pub(super) fn timeline_note(&mut self, what: &Happening) {
        let Some(tl) = self.timeline.as_mut() else {
            return;
        };
        tl.pending.push(what.to_string());
        if let Happening::Picked { object } | Happening::PutDown { object, .. } = what
            && let Some(i) = self.objects.iter().position(|o| &o.name == object)
        {
            tl.moving.push(i);
        }
    }

    /// Makes a moment of what happened since the last one, when anything
    /// did: called where the world is whole again (after each step of
    /// `advance_to`, at the end of each operation).
    pub(super) fn timeline_flush(&mut self) {
        if self.timeline.as_ref().is_none_or(|t| t.pending.is_empty()) {
            return;
        }
        let now = self.now;
        let mut tl = self.timeline.take().expect("a timeline");
        // The candidates: what moved or was touched, and new objects.
        let mut candidates = std::mem::take(&mut tl.moving);
        candidates.extend(tl.told.len()..self.objects.len());
        tl.told.resize(self.objects.len(), None);
        candidates.sort_unstable();
        candidates.dedup();
        // Each belt's positions now and stops, computed once.
        let mut belts: Vec<Option<Vec<(usize, f64, f64)>>> = vec![None; self.state.len()];
        let mut objects = Vec::new();
        for i in candidates {
            let course = match self.objects[i].loc {
                Loc::Held => Course::Held,
                Loc::At(p) => Course::At(p),
                Loc::Belt(b) => {
                    let rows = belts[b].get_or_insert_with(|| self.belt_courses(b));
                    let Some(&(_, position, stop)) = rows.iter().find(|r| r.0 == i) else {
                        continue;
                    };
                    let speed = match &self.state[b] {
                        State::Conveyor(belt) if belt.running() => self.belt_spec(b).1,
                        _ => 0.0,
                    };
                    Course::Belt {
                        belt: self.devs.devices()[b].name.clone(),
                        position,
                        speed,
                        stop,
                    }
                }
            };
            if matches!(course, Course::Belt { .. } | Course::Held) {
                tl.moving.push(i);
            }
            if tl.told[i]
                .as_ref()
                .is_some_and(|old| same(old, now, &course))
            {
                continue;
            }
            tl.told[i] = Some((now, course.clone()));
            objects.push(ObjectCourse {
                name: self.objects[i].name.clone(),
                width: self.objects[i].width,
                course,
            });
        }
        let mut beams = Vec::new();
        for (d, s) in self.state.iter().enumerate() {
            if let State::Barrier { beam } = s
                && tl.beams[d] != *beam
            {
                tl.beams[d] = *beam;
                beams.push((self.devs.devices()[d].name.clone(), *beam));
            }
        }
        let m = Moment {
            time: now,
            what: std::mem::take(&mut tl.pending),
            objects,
            beams,
        };
        if let Some(s) = &tl.sink {
            s(&m);
        }
        if tl.keep {
            tl.moments.push(m);
        }
        self.timeline = Some(tl);
    }

    /// The objects on belt `b` now: (object, position, stop), front first.
    fn belt_courses(&self, b: usize) -> Vec<(usize, f64, f64)> {
        let State::Conveyor(belt) = &self.state[b] else {
            return Vec::new();
        };
        let DeviceKind::Conveyor { length, .. } = self.devs.devices()[b].kind else {
            return Vec::new();
        };
        let positions = self.positions_at(b, self.now);
        let mut out = Vec::with_capacity(belt.queue.len());
        let mut stop = length;
        for (k, (&(obj, _), p)) in belt.queue.iter().zip(positions).enumerate() {
            if k > 0 {
                let ahead = belt.queue[k - 1].0;
                stop -= (self.objects[ahead].width + self.objects[obj].width) / 2.0;
            }
            out.push((obj, p, stop));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::devices::{Devices, Place};

    const BELT: &str = r#"
[[device]]
name = "belt"
kind = "conveyor"
motor = 0o350
length = 200.0
speed = 100.0
end = [250.0, 250.0, 30.0]

[[device]]
name = "exit"
kind = "light-barrier"
on = "belt"
input = 0o352
interrupt = 0o354

[[event]]
at = 0.5
device = "belt"
object = { name = "box1", width = 30.0 }

[[event]]
at = 1.0
device = "belt"
object = { name = "box2", width = 20.0 }

[[event]]
at = 1.5
device = "belt"
object = { name = "box3", width = 40.0 }
"#;

    /// Where each object is at `t` according to the moments up to `t`:
    /// (name, position on its belt, or None held / put down).
    fn from_moments(moments: &[Moment], t: f64) -> Vec<(String, Option<f64>)> {
        let mut last: Vec<(String, f64, Course)> = Vec::new();
        for m in moments.iter().filter(|m| m.time <= t) {
            for o in &m.objects {
                match last.iter_mut().find(|x| x.0 == o.name) {
                    Some(x) => *x = (o.name.clone(), m.time, o.course.clone()),
                    None => last.push((o.name.clone(), m.time, o.course.clone())),
                }
            }
        }
        last.into_iter()
            .map(|(n, at, c)| (n, c.position_after(t - at)))
            .collect()
    }

    fn from_world(w: &World) -> Vec<(String, Option<f64>)> {
        w.objects()
            .into_iter()
            .map(|o| {
                let p = match o.place {
                    Place::OnBelt { position, .. } => Some(position),
                    _ => None,
                };
                (o.name, p)
            })
            .collect()
    }

    /// The moments place every object where the world has it, at any time
    /// between them: objects queue behind one another (box2 and box3 stop
    /// behind the one ahead at 2.75 s and 2.95 s, with no happening of
    /// their own), the belt stops and starts, an object is picked and put
    /// down.
    #[test]
    fn the_moments_give_every_objects_place_at_any_time() {
        let devs = Devices::from_toml(BELT, "t.toml").unwrap();
        let mut w = World::new(devs);
        w.keep_timeline();
        type Step = Box<dyn Fn(&mut World)>;
        let script: Vec<(f64, Step)> = vec![
            (0.0, Box::new(|w| w.write(0o350, 1).unwrap())),
            (3.2, Box::new(|w| w.write(0o350, 0).unwrap())),
            (3.5, Box::new(|w| drop(w.pick("box1").unwrap()))),
            (4.0, Box::new(|w| w.write(0o350, 1).unwrap())),
            (
                4.1,
                Box::new(|w| w.put_down("box1", [1.0, 2.0, 3.0]).unwrap()),
            ),
            (6.0, Box::new(|_| {})),
        ];
        let mut probes = Vec::new();
        for (at, f) in &script {
            // Probe a copy at times up to this step.
            let from = w.now();
            for k in 1..37 {
                let t = from + (at - from) * k as f64 / 37.0;
                let mut c = w.clone();
                c.advance_to(t);
                probes.push((t, from_world(&c)));
            }
            w.advance_to(*at);
            f(&mut w);
        }
        let moments = w.timeline().to_vec();
        assert!(moments.len() >= 8, "{moments:?}");
        for (t, want) in probes {
            let got = from_moments(&moments, t);
            assert_eq!(got.len(), want.len(), "t = {t}: {got:?} {want:?}");
            for ((gn, gp), (wn, wp)) in got.iter().zip(&want) {
                assert_eq!(gn, wn);
                match (gp, wp) {
                    (Some(g), Some(w)) => {
                        assert!((g - w).abs() < 1e-6, "t = {t}: {gn} at {g}, world {w}")
                    }
                    _ => assert_eq!(gp.is_some(), wp.is_some(), "t = {t}: {gn}"),
                }
            }
        }
        // The beam: broken when box1 arrives (2.5 s), clear when picked.
        let beams: Vec<(f64, bool)> = moments
            .iter()
            .flat_map(|m| m.beams.iter().map(move |b| (m.time, b.1)))
            .collect();
        assert_eq!(beams, [(2.5, true), (3.5, false), (4.25, true)]);
    }

    #[test]
    fn without_a_timeline_nothing_is_kept_and_a_sink_gets_each_moment() {
        let devs = Devices::from_toml(BELT, "t.toml").unwrap();
        let mut w = World::new(devs.clone());
        w.write(0o350, 1).unwrap();
        w.advance_to(10.0);
        assert!(w.timeline().is_empty());
        let got = Arc::new(std::sync::Mutex::new(Vec::new()));
        let g = got.clone();
        let mut w = World::new(devs);
        w.set_sink(Some(Arc::new(move |m: &Moment| {
            g.lock().unwrap().push(m.time)
        })));
        w.write(0o350, 1).unwrap();
        w.advance_to(10.0);
        assert!(w.timeline().is_empty(), "a sink alone keeps nothing");
        let times = got.lock().unwrap().clone();
        assert_eq!(times.first(), Some(&0.0));
        assert!(times.windows(2).all(|p| p[0] <= p[1]), "{times:?}");
        assert!(times.contains(&2.5), "{times:?}");
    }
}
