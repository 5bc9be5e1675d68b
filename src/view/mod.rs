//! `--view`: the run in 3D in a browser (tools.md "The 3D view").
//!
//! One page, `assets/view/page.html` with its script `view.js` and the
//! vendored `three` (`three.min.js`, built by `scripts/vendor-three.sh`),
//! all embedded in the binary. A replay page ([`replay_page`]) carries the
//! run in two `<script>` data blocks: the scene (robot description, path
//! positions, devices, how the run ended) as JSON, and the support points
//! exactly as `--record FILE.csv` writes them. The live page ([`live`])
//! is the same page, fed over Server-Sent Events instead.

pub mod live;

use crate::kinematics::{Joints, Kinematics, Pose};
use crate::services::RobotState;
use crate::services::record::Sample;
use serde_json::{Value, json};

const PAGE: &str = include_str!("../../assets/view/page.html");
const SCRIPT: &str = include_str!("../../assets/view/view.js");
const THREE: &str = include_str!("../../assets/view/three.min.js");

/// How a run ended, for the page: its virtual time, and when an exception
/// left the program, its message and the refused goal (TCP pose) if a
/// motion was refused then.
#[derive(Clone, Debug, Default)]
pub struct Ending {
    pub t: f64,
    pub exception: Option<String>,
    pub goal: Option<Pose>,
}

fn rows(p: &Pose) -> Value {
    json!(p.to_rows())
}

/// The robot description as the page draws it.
pub fn robot_json(kin: &Kinematics) -> Value {
    let d = kin.description();
    let l = d.links();
    let g = d.gripper();
    let joints: Vec<Value> = d
        .joints()
        .iter()
        .map(|j| json!({"name": j.name, "min": j.min.to_degrees(), "max": j.max.to_degrees()}))
        .collect();
    json!({
        "name": d.name(),
        "links": {"l1": l.l1, "l2": l.l2, "l3": l.l3, "l4": l.l4, "tool": l.tool},
        "gripper": [g.opening_min, g.opening_max],
        "joints": joints,
    })
}

/// The path system's positions: path, position number and frame.
pub fn paths_json(st: &RobotState) -> Value {
    let mut out = Vec::new();
    for (p, positions) in st.paths.iter() {
        for (i, f) in positions.iter().enumerate() {
            out.push(json!({"path": p, "pos": i + 1, "frame": f}));
        }
    }
    Value::Array(out)
}

/// One moment of the device world (a `devices` event of the live view, an
/// entry of a replay page's `devices.events`): its time, what happened
/// (the `--trace` texts), the objects whose course changed and the beams
/// that changed.
pub fn moment_json(m: &crate::devices::Moment) -> Value {
    use crate::devices::Course;
    let objects: Vec<Value> = m
        .objects
        .iter()
        .map(|o| match &o.course {
            Course::Belt {
                belt,
                position,
                speed,
                stop,
            } => json!({"name": o.name, "width": o.width, "belt": belt,
                        "position": position, "speed": speed, "stop": stop}),
            Course::Held => json!({"name": o.name, "width": o.width, "held": true}),
            Course::At(p) => json!({"name": o.name, "width": o.width, "at": p}),
        })
        .collect();
    let beams: Vec<Value> = m
        .beams
        .iter()
        .map(|(name, broken)| json!({"name": name, "broken": broken}))
        .collect();
    json!({"t": m.time, "what": m.what, "objects": objects, "beams": beams})
}

/// Where the page draws the point `position` mm from the start of a belt
/// of `length` mm that ends at `end`: the belt lies square to the line
/// from the base to its end (seen from above), its start to the left of
/// that line as seen from the base, at the height of its end.
pub fn belt_point(end: [f64; 3], length: f64, position: f64) -> [f64; 3] {
    let r = (end[0] * end[0] + end[1] * end[1]).sqrt();
    let (rx, ry) = if r < 1e-6 {
        (1.0, 0.0)
    } else {
        (end[0] / r, end[1] / r)
    };
    // From the end back to the start.
    let (dx, dy) = (-ry, rx);
    let back = length - position;
    [end[0] + dx * back, end[1] + dy * back, end[2]]
}

/// The devices of `--devices` that have a place in the cell: belts (their
/// end, length and speed), light barriers (the belt they sit on), the
/// objects where they are at the end of the run, and the moments of the
/// run (`events`, when the world kept them: [`crate::devices::World::keep_timeline`]),
/// which the page places the objects by.
pub fn devices_json(world: Option<&crate::devices::World>, st: &RobotState) -> Value {
    use crate::devices::{DeviceKind, Place};
    let Some(w) = world else { return Value::Null };
    let devs = w.devices().devices();
    let mut belts = Vec::new();
    let mut barriers = Vec::new();
    for d in devs {
        match &d.kind {
            DeviceKind::Conveyor {
                length, speed, end, ..
            } => belts.push(json!({"name": d.name, "length": length, "speed": speed, "end": end})),
            DeviceKind::LightBarrier { on, .. } => barriers.push(json!({
                "name": d.name,
                "on": on.map(|i| devs[i].name.clone()),
            })),
            DeviceKind::Parallel { .. } => {}
        }
    }
    let tcp = st
        .kin
        .fk_tcp(&st.robot.joints(), &st.tool.trans)
        .translation;
    let objects: Vec<Value> = w
        .objects()
        .iter()
        .map(|o| {
            let place = match &o.place {
                Place::OnBelt { belt, position, .. } => {
                    json!({"belt": devs[*belt].name, "position": position})
                }
                Place::Held => json!({"at": [tcp.x, tcp.y, tcp.z], "held": true}),
                Place::At(p) => json!({"at": p}),
            };
            json!({"name": o.name, "width": o.width, "place": place})
        })
        .collect();
    if belts.is_empty() && barriers.is_empty() && objects.is_empty() {
        return Value::Null;
    }
    let events: Vec<Value> = w.timeline().iter().map(moment_json).collect();
    json!({"belts": belts, "barriers": barriers, "objects": objects, "events": events})
}

/// The scene of a replay page (everything but the support points).
pub fn scene_json(
    st: &RobotState,
    world: Option<&crate::devices::World>,
    title: &str,
    ending: &Ending,
) -> Value {
    json!({
        "title": title,
        "robot": robot_json(&st.kin),
        "paths": paths_json(st),
        "devices": devices_json(world, st),
        "end": {
            "t": ending.t,
            "exception": ending.exception,
            "goal": ending.goal.as_ref().map(rows),
        },
    })
}

/// Text safe inside a `<script>` element: no `</script>` or `<!--` can
/// end or change it (JSON and CSV never need a `<`).
fn script_safe(s: &str) -> String {
    s.replace('<', "\\u003c")
}

/// The page with `scene` (JSON) and `csv` (the support points as
/// `--record` writes them); `live` pages fetch both from the server.
fn page(scene: &str, csv: &str, live: bool) -> String {
    // The three pieces of code go in last: their text is never searched
    // for placeholders.
    let head = PAGE
        .replace("{{SCENE}}", &script_safe(scene))
        .replace("{{RECORD}}", csv)
        .replace("{{MODE}}", if live { "live" } else { "replay" });
    let (before, after) = head
        .split_once("{{THREE}}")
        .expect("page.html has {{THREE}}");
    let (mid, end) = after
        .split_once("{{SCRIPT}}")
        .expect("page.html has {{SCRIPT}}");
    let mut out = String::with_capacity(head.len() + THREE.len() + SCRIPT.len());
    out.push_str(before);
    out.push_str(THREE);
    out.push_str(mid);
    out.push_str(SCRIPT);
    out.push_str(end);
    out
}

/// The replay page of a run.
pub fn replay_page(scene: &Value, samples: &[Sample]) -> String {
    page(
        &scene.to_string(),
        &crate::services::record::to_csv(samples),
        false,
    )
}

/// The live page: its scene and samples come from the server.
pub fn live_page() -> String {
    page("null", "", true)
}

/// The support points a page carries, as `--record` writes them.
pub fn embedded_record(page: &str) -> Option<&str> {
    let start = page.find("<script type=\"text/csv\" id=\"adair-record\">")?;
    let rest = &page[start..];
    let open = rest.find('>')? + 1;
    let close = rest.find("</script>")?;
    Some(&rest[open..close])
}

/// Writes the replay page of the run in `st` to `path` (whole, as
/// `--record` writes). Returns its size in bytes.
pub fn write_replay(
    path: &std::path::Path,
    st: &RobotState,
    world: Option<&crate::devices::World>,
    title: &str,
    ending: &Ending,
) -> Result<usize, String> {
    let scene = scene_json(st, world, title, ending);
    let text = replay_page(&scene, st.record.as_deref().unwrap_or(&[]));
    crate::services::paths::write_whole(path, text.as_bytes()).map_err(|(_, msg)| msg)?;
    Ok(text.len())
}

/// World positions (mm) of the points the page draws the arm through,
/// from adair's own forward kinematics: the base, the shoulder axis, the
/// elbow axis, the wrist-pitch axis, the flange and the TCP (with `tool`).
/// The page's `adairView.jointPositions(t)` gives the same six points.
pub fn joint_points(kin: &Kinematics, q: &Joints, tool: &Pose) -> [[f64; 3]; 6] {
    let l = kin.description().links();
    let flange = kin.fk_flange(q);
    let tcp = kin.fk_tcp(q, tool).translation;
    let (s1, c1) = q[0].sin_cos();
    let at = |r: f64, z: f64| [r * c1, r * s1, z];
    let shoulder = at(0.0, l.l1);
    let elbow = at(l.l2 * q[1].sin(), l.l1 + l.l2 * q[1].cos());
    // The wrist-pitch axis lies L4 behind the flange along the tool axis.
    let a = flange.approach();
    let f = flange.translation;
    let wrist = [f.x - l.l4 * a.x, f.y - l.l4 * a.y, f.z - l.l4 * a.z];
    [
        [0.0, 0.0, 0.0],
        shoulder,
        elbow,
        wrist,
        [f.x, f.y, f.z],
        [tcp.x, tcp.y, tcp.z],
    ]
}

/// Checks a `--view FILE.html` path before the run (as `--record`'s).
pub fn check_target(p: &std::path::Path) -> Result<(), String> {
    if p.extension().and_then(|e| e.to_str()) != Some("html") {
        return Err("the file must end in .html".into());
    }
    crate::plot::check_target(p)?;
    match p.parent() {
        Some(d) if !d.as_os_str().is_empty() && !d.is_dir() => {
            Err(format!("the directory {} does not exist", d.display()))
        }
        _ => Ok(()),
    }
}

/// How the run in `s` ended, for the page.
pub fn ending(s: &crate::session::Session, outcome: &crate::session::Outcome) -> Ending {
    let t = s.machine.clock.now();
    let exception = match outcome {
        crate::session::Outcome::Raised(d) => Some(d.message.clone()),
        _ => None,
    };
    let goal = match (&exception, s.robot_state().and_then(|st| st.refused)) {
        (Some(_), Some((when, goal))) if (when - t).abs() < 1e-9 => Some(goal),
        _ => None,
    };
    Ending { t, exception, goal }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_page_carries_the_record_unchanged() {
        let s = Sample {
            t: 0.5,
            joints: [0.0, 0.5, 0.0, 0.0, 0.0],
            tcp: [1.0, 2.0, 3.0],
            grip: 40.0,
        };
        let scene = json!({"title": "</script><script>alert(1)</script>"});
        let p = replay_page(&scene, &[s, s]);
        assert_eq!(
            embedded_record(&p),
            Some(crate::services::record::to_csv(&[s, s]).as_str())
        );
        assert!(!p.contains("</script><script>alert"));
        assert!(!p.contains("{{SCENE}}") && !p.contains("{{MODE}}"));
    }

    #[test]
    fn joint_points_end_at_the_tcp_of_fk() {
        let desc = crate::kinematics::RobotDescription::builtin("rv-m1").unwrap();
        let kin = Kinematics::new(desc.clone());
        let tool = desc.standard_tool();
        let p = joint_points(&kin, &[0.0; 5], &tool);
        assert!((p[5][2] - 889.0).abs() < 1e-9, "{p:?}");
        assert!((p[3][2] - (300.0 + 250.0 + 160.0)).abs() < 1e-9, "{p:?}");
    }
}
