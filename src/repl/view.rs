//! The REPL's 3D view: `:view FILE.html` writes the replay page of the
//! session so far; `adair repl --view` streams every entry's motions to
//! the live page ([`crate::view::live`]).

use super::{Repl, Reply};
use crate::view::live::{self, Hub};
use std::sync::{Arc, OnceLock};

/// The live view's hub of this process (`adair repl --view`), set once by
/// the command line before the REPL starts.
static LIVE: OnceLock<Arc<Hub>> = OnceLock::new();

/// Streams the REPL's motions to `hub` (call before the REPL starts).
pub fn serve_live(hub: Arc<Hub>) {
    let _ = LIVE.set(hub);
}

pub(super) fn live_hub() -> Option<Arc<Hub>> {
    LIVE.get().cloned()
}

impl Repl {
    /// After a robot is (re)installed: the live view watches it, paced to
    /// the wall clock, and the pages draw that robot.
    pub(super) fn rewatch(&mut self) {
        let Some(hub) = self.live.clone() else { return };
        if let Some(w) = self.session.machine.world.as_mut() {
            w.set_sink(Some(live::device_sink(hub.clone())));
        }
        let world = self.session.machine.world.as_ref();
        let Some(st) = self.session.robot.as_mut() else {
            return;
        };
        st.watch = Some(Box::new(live::HubWatch(hub.clone())));
        if !st.robot.real_time() {
            st.realtime = true;
            self.session.machine.realtime = true;
        }
        live::publish_scene(&hub, st, world, "REPL session");
    }

    /// Checks and runs one entry; the live view gets how it ended.
    pub fn entry(&mut self, text: &str) -> Reply {
        let reply = self.entry_inner(text);
        if let Some(hub) = &self.live
            && let Some(st) = self.session.robot_state()
        {
            let t = self.session.machine.clock.now();
            let exception = reply
                .failed
                .then(|| reply.text.lines().next().unwrap_or("").to_string());
            let goal = match (&exception, st.refused) {
                (Some(_), Some((when, g))) if (when - t).abs() < 1e-9 => Some(g),
                _ => None,
            };
            let ending = crate::view::Ending { t, exception, goal };
            live::publish_state(hub, st, &ending, false);
        }
        reply
    }

    /// `:view FILE.html`: the replay page of the motions since the start
    /// (or `:reset`).
    pub(super) fn save_view(&self, path: &std::path::Path) -> Result<String, String> {
        crate::view::check_target(path)?;
        let st = self.session.robot_state().ok_or("no robot")?;
        let ending = crate::view::Ending {
            t: self.session.machine.clock.now(),
            ..Default::default()
        };
        let world = self.session.machine.world.as_ref();
        let n = crate::view::write_replay(path, st, world, "REPL session", &ending)?;
        Ok(format!(
            "wrote {} ({} support points, {} bytes)\n",
            path.display(),
            st.record.as_ref().map_or(0, |r| r.len()),
            n
        ))
    }
}
