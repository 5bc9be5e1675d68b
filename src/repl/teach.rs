//! The screen teach pendant (ratatui + crossterm), behind the `TeachBox`
//! service and the REPL's `:teach`. Keys jog each joint, or in Cartesian
//! mode move the TCP along the base axes and turn the tool (pitch about the
//! TCP, roll about the approach axis), with the orientation kept reachable
//! as `ValidFrame` does; open and close the hand, change step and speed, and
//! store the current pose into a path. Limits are shown and never crossed.
//! The arrow keys choose a joint (up, down) and jog it (left, right).

use crate::interp::Clock;
use crate::kinematics::{Joints, Pose, deg, joints_to_deg, rad};
use crate::services::{Pendant, RobotState};
use ratatui::Terminal;
use ratatui::backend::CrosstermBackend;
use ratatui::crossterm::event::{self, Event, KeyCode, KeyEventKind, KeyModifiers};
use ratatui::crossterm::execute;
use ratatui::crossterm::terminal::{
    EnterAlternateScreen, LeaveAlternateScreen, disable_raw_mode, enable_raw_mode,
};
use ratatui::layout::{Constraint, Direction, Layout};
use ratatui::style::{Color, Style};
use ratatui::text::Line;
use ratatui::widgets::canvas::{Canvas, Line as CLine};
use ratatui::widgets::{Block, Borders, Paragraph};

const STEPS: [f64; 4] = [0.5, 1.0, 5.0, 10.0];

/// The terminal teach pendant.
#[derive(Default)]
pub struct TermPendant {
    cartesian: bool,
    step: usize,
    path: i64,
    /// Position to store at (0 = after the last); never past the path's
    /// last position.
    position: usize,
    /// The joint (or Cartesian direction) the arrow keys jog, 0..5.
    selected: usize,
    message: String,
}

impl TermPendant {
    pub fn new() -> TermPendant {
        TermPendant {
            cartesian: false,
            step: 2,
            path: 1,
            position: 0,
            selected: 0,
            message: String::new(),
        }
    }
}

/// Key bindings, as the help line shows them: (key plus, key minus, what).
const KEYS: [(char, char, &str, &str); 5] = [
    ('q', 'a', "body J1", "x"),
    ('w', 's', "shoulder J2", "y"),
    ('e', 'd', "elbow J3", "z"),
    ('r', 'f', "wrist pitch J4", "pitch at TCP"),
    ('t', 'g', "wrist roll J5", "roll at TCP"),
];

impl TermPendant {
    /// The arm's pose now (a fresh `WH` on a real arm): false, with the
    /// reason on the screen, when it cannot be read.
    fn fresh(&mut self, st: &mut RobotState) -> bool {
        match crate::services::fresh_pose(st) {
            Ok(()) => true,
            Err(e) => {
                self.message = format!("cannot read the arm's pose: {e}");
                false
            }
        }
    }

    fn jog_joint(&mut self, st: &mut RobotState, clock: &mut dyn Clock, j: usize, sign: f64) {
        if !self.fresh(st) {
            return;
        }
        let mut q = st.robot.joints();
        let now = q[j];
        q[j] += sign * rad(STEPS[self.step]);
        let spec = &st.kin.description().joints()[j];
        if !spec.contains(q[j]) {
            self.message = limit_message(j, sign * STEPS[self.step], deg(now), spec);
            return;
        }
        self.go(st, clock, q);
    }

    fn jog_cartesian(
        &mut self,
        st: &mut RobotState,
        clock: &mut dyn Clock,
        axis: usize,
        sign: f64,
    ) {
        if !self.fresh(st) {
            return;
        }
        match cartesian_target(st, axis, sign * STEPS[self.step]) {
            Ok(q) => self.go(st, clock, q),
            Err(e) => {
                self.message = format!(
                    "{} {}: refused: {e}",
                    KEYS[axis].3,
                    if sign > 0.0 { "+" } else { "-" }
                )
            }
        }
    }

    /// A jog goes through the same service code as a program's motion:
    /// limits, speed, driver, clock and trace.
    fn go(&mut self, st: &mut RobotState, clock: &mut dyn Clock, q: Joints) {
        match crate::services::jog(st, clock, q) {
            Ok(()) => self.message.clear(),
            Err(e) => self.message = format!("refused: {e}"),
        }
    }

    /// Stores the pose into the path at the chosen position and says what
    /// was stored: where, the TCP and the joints.
    fn store(&mut self, st: &mut RobotState) {
        let q = st.robot.read_joints();
        let f = st.kin.fk_tcp(&q, &st.tool.trans).to_rows();
        // As InsertPosition: before the chosen position, or after the last.
        let at = self.position.checked_sub(1).unwrap_or(usize::MAX);
        self.message = match st.paths.insert(self.path, at, f) {
            Ok(at) => {
                // The next store goes before the same position as this one
                // did: after the pose just stored.
                if self.position != 0 {
                    self.position = at + 2;
                }
                let d = joints_to_deg(&q);
                format!(
                    "stored as position {} of path {}:\n  TCP ({:.1}, {:.1}, {:.1}) mm\n  \
                     J ({:.1}, {:.1}, {:.1}, {:.1}, {:.1}) deg",
                    at + 1,
                    self.path,
                    f[0][3],
                    f[1][3],
                    f[2][3],
                    d[0],
                    d[1],
                    d[2],
                    d[3],
                    d[4]
                )
            }
            Err(e) => format!("not stored (PathMemOverflow): {e}"),
        };
    }

    /// The number of positions of the chosen path.
    fn path_len(&self, st: &RobotState) -> usize {
        st.paths.get(&self.path).map_or(0, |p| p.len())
    }

    /// `}`: the next position to store at, up to the path's last one, then
    /// the end (after the last); never past it.
    fn next_position(&mut self, st: &RobotState) {
        let n = self.path_len(st);
        self.position = match self.position {
            0 => {
                self.message = format!(
                    "store at the end already: path {} has {n} position{}",
                    self.path,
                    if n == 1 { "" } else { "s" }
                );
                0
            }
            k if k < n => k + 1,
            _ => 0,
        };
    }

    /// `{`: the position before, from the end to the path's last one.
    fn previous_position(&mut self, st: &RobotState) {
        let n = self.path_len(st);
        self.position = match self.position {
            0 if n == 0 => {
                self.message = format!("path {} has no positions: store at the end", self.path);
                0
            }
            0 => n,
            k => (k - 1).max(1),
        };
    }

    /// Another path chosen: a position past its end becomes the end.
    fn keep_position_in_path(&mut self, st: &RobotState) {
        if self.position > self.path_len(st) {
            self.position = 0;
        }
    }

    /// Jogs joint (or Cartesian direction) `j` by one step.
    fn jog_by_key(&mut self, st: &mut RobotState, clock: &mut dyn Clock, j: usize, sign: f64) {
        if self.cartesian {
            self.jog_cartesian(st, clock, j, sign);
        } else {
            self.jog_joint(st, clock, j, sign);
        }
    }

    /// Handles a key; true to leave.
    fn key(&mut self, st: &mut RobotState, clock: &mut dyn Clock, c: KeyCode) -> bool {
        match c {
            KeyCode::Esc | KeyCode::Char('x') => return true,
            KeyCode::Char('m') => {
                self.cartesian = !self.cartesian;
                self.message = if self.cartesian {
                    "Cartesian: x y z along the base axes, pitch and roll at the TCP".into()
                } else {
                    "joint jogging".into()
                };
            }
            KeyCode::Char('+') => self.step = (self.step + 1).min(STEPS.len() - 1),
            KeyCode::Char('-') => self.step = self.step.saturating_sub(1),
            KeyCode::Char('>') => st.velocity = (st.velocity + 10.0).min(100.0),
            KeyCode::Char('<') => st.velocity = (st.velocity - 10.0).max(10.0),
            KeyCode::Char(']') => {
                self.path = (self.path + 1).min(65000);
                self.keep_position_in_path(st);
            }
            KeyCode::Char('[') => {
                self.path = (self.path - 1).max(1);
                self.keep_position_in_path(st);
            }
            KeyCode::Char('}') => self.next_position(st),
            KeyCode::Char('{') => self.previous_position(st),
            KeyCode::Char('p') => self.store(st),
            // The arrows: choose a joint (or direction), jog it.
            KeyCode::Up => self.selected = self.selected.checked_sub(1).unwrap_or(KEYS.len() - 1),
            KeyCode::Down => self.selected = (self.selected + 1) % KEYS.len(),
            KeyCode::Left | KeyCode::Right => {
                let sign = if c == KeyCode::Right { 1.0 } else { -1.0 };
                self.jog_by_key(st, clock, self.selected, sign);
            }
            KeyCode::Char('o') | KeyCode::Char('c') => {
                let open = c == KeyCode::Char('o');
                self.message = match crate::services::jog_hand(st, clock, open) {
                    Ok(s) => format!("hand: opening {:.1} mm, force {:.1} N", s.opening, s.force),
                    Err(e) => format!("hand refused: {e}"),
                };
            }
            KeyCode::Char(ch) => {
                for (j, (plus, minus, _, _)) in KEYS.iter().enumerate() {
                    let sign = if ch == *plus {
                        1.0
                    } else if ch == *minus {
                        -1.0
                    } else {
                        continue;
                    };
                    self.selected = j;
                    self.jog_by_key(st, clock, j, sign);
                }
            }
            _ => {}
        }
        false
    }

    fn draw(&self, f: &mut ratatui::Frame, st: &RobotState, text: &str) {
        let area = f.area();
        let cols = Layout::default()
            .direction(Direction::Horizontal)
            .constraints([Constraint::Length(58), Constraint::Min(20)])
            .split(area);
        let q = st.robot.read_joints();
        let d = joints_to_deg(&q);
        let tcp = st.kin.fk_tcp(&q, &st.tool.trans).to_rows();
        let g = crate::services::grip_reading(st);
        let mut lines: Vec<Line> = Vec::new();
        lines.push(Line::from(format!(
            "TeachBox  {}",
            st.kin.description().name()
        )));
        lines.push(Line::from(text.to_string()));
        lines.push(Line::from(format!(
            "mode {}  step {} {}  speed {:.0} %",
            if self.cartesian { "Cartesian" } else { "joint" },
            STEPS[self.step],
            if self.cartesian { "mm/deg" } else { "deg" },
            st.velocity,
        )));
        lines.push(Line::from(format!(
            "move mode {}",
            if st.straight {
                "StraightLine"
            } else {
                "JointInterpolated"
            }
        )));
        lines.push(Line::from(""));
        for (j, spec) in st.kin.description().joints().iter().enumerate() {
            let (plus, minus, name, cart) = KEYS[j];
            let what = if self.cartesian { cart } else { name };
            lines.push(Line::from(format!(
                "{}J{} {:>8.2} [{:>6.1} ..{:>6.1}] {plus}/{minus} {what}",
                if j == self.selected { '>' } else { ' ' },
                j + 1,
                d[j],
                deg(spec.min),
                deg(spec.max)
            )));
        }
        lines.push(Line::from(format!(
            "hand {:.1} mm, {:.1} N  o/c open/close",
            g.opening, g.force
        )));
        lines.push(Line::from("TCP frame:"));
        for row in tcp {
            lines.push(Line::from(format!(
                "  {:8.4} {:8.4} {:8.4} {:9.2}",
                row[0], row[1], row[2], row[3]
            )));
        }
        lines.push(Line::from(""));
        lines.push(Line::from(format!(
            "path {}: {} positions, store at {}",
            self.path,
            self.path_len(st),
            if self.position == 0 {
                "the end".to_string()
            } else {
                format!("position {}", self.position)
            }
        )));
        for legend in LEGEND {
            lines.push(Line::from(legend));
        }
        for m in self.message.lines() {
            lines.push(Line::styled(
                m.to_string(),
                Style::default().fg(Color::Yellow),
            ));
        }
        f.render_widget(
            Paragraph::new(lines).block(
                Block::default()
                    .borders(Borders::ALL)
                    .title("AdaIR teach box"),
            ),
            cols[0],
        );

        // The arm in its plane (side view) and from above (top view).
        let views = Layout::default()
            .direction(Direction::Vertical)
            .constraints([Constraint::Percentage(60), Constraint::Percentage(40)])
            .split(cols[1]);
        let pts = arm_points(st, &q);
        let reach = {
            let l = st.kin.description().links();
            l.l2 + l.l3 + l.l4 + l.tool + 50.0
        };
        let l1 = st.kin.description().links().l1;
        let side = Canvas::default()
            .block(
                Block::default()
                    .borders(Borders::ALL)
                    .title("side view (r, z)"),
            )
            .x_bounds([-reach, reach])
            .y_bounds([0.0, l1 + reach])
            .paint(|ctx| {
                for w in pts.windows(2) {
                    ctx.draw(&CLine {
                        x1: w[0].0,
                        y1: w[0].2,
                        x2: w[1].0,
                        y2: w[1].2,
                        color: Color::Cyan,
                    });
                }
            });
        f.render_widget(side, views[0]);
        let top = Canvas::default()
            .block(
                Block::default()
                    .borders(Borders::ALL)
                    .title("top view (x, y)"),
            )
            .x_bounds([-reach, reach])
            .y_bounds([-reach, reach])
            .paint(|ctx| {
                let (c, s) = (q[0].cos(), q[0].sin());
                for w in pts.windows(2) {
                    ctx.draw(&CLine {
                        x1: w[0].0 * c,
                        y1: w[0].0 * s,
                        x2: w[1].0 * c,
                        y2: w[1].0 * s,
                        color: Color::Green,
                    });
                }
            });
        f.render_widget(top, views[1]);
    }
}

/// The key legend below the pose; each line fits the panel (56 columns) of
/// an 80-column terminal.
const LEGEND: [&str; 3] = [
    "[ ] path  { } position  p store  m joint/Cartesian",
    "+ - step  < > speed  x, Esc or Ctrl-C leave",
    "arrows: up/down choose the joint (>), left/right jog",
];

/// The limit a joint jog of `step` degrees from `now` degrees runs
/// towards: which one, where (degrees) and how far the joint is from it.
pub(super) fn limit_ahead(
    step: f64,
    now: f64,
    spec: &crate::kinematics::JointSpec,
) -> (&'static str, f64, f64) {
    let (which, limit) = if step > 0.0 {
        ("upper", deg(spec.max))
    } else {
        ("lower", deg(spec.min))
    };
    (which, limit, (limit - now).abs())
}

/// Why a joint jog of `step` degrees from `now` degrees is refused: the
/// limit it would pass and how far the joint is from it.
fn limit_message(j: usize, step: f64, now: f64, spec: &crate::kinematics::JointSpec) -> String {
    let (which, limit, left) = limit_ahead(step, now, spec);
    let name = format!("J{}", j + 1);
    if left < 0.05 {
        format!("{name} {step:+} deg refused:\n  {name} is at its {which} limit {limit:.1} deg")
    } else {
        format!(
            "{name} {step:+} deg would pass its {which} limit {limit:.1} deg:\n  \
             {left:.1} deg left (a smaller step: -)"
        )
    }
}

/// The joints for a Cartesian jog by `amount` (mm, or degrees for pitch and
/// roll) along `axis`: 0..2 moves the TCP along the base x, y, z; 3 turns
/// the tool about the horizontal axis through the TCP across the arm's
/// plane (pitch); 4 turns it about its approach axis (roll). The new frame's
/// orientation is then made reachable as `ValidFrame` does (a 5-axis arm
/// cannot keep every orientation while the TCP moves sideways), and the
/// nearest inverse solution in the current configuration is chosen.
pub fn cartesian_target(st: &RobotState, axis: usize, amount: f64) -> Result<Joints, String> {
    let q = st.robot.joints();
    let tool = &st.tool.trans;
    let mut pose = st.kin.fk_tcp(&q, tool);
    match axis {
        0..=2 => pose.translation[axis] += amount,
        3 => {
            let p = pose.translation;
            let angle = if p[0].hypot(p[1]) > 1e-6 {
                p[1].atan2(p[0])
            } else {
                q[0]
            };
            let across = nalgebra::Vector3::new(-angle.sin(), angle.cos(), 0.0);
            let turn = nalgebra::Rotation3::from_axis_angle(
                &nalgebra::Unit::new_normalize(across),
                rad(amount),
            );
            pose = Pose::new(turn.into_inner() * pose.rotation, p);
        }
        _ => {
            pose = Pose::new(
                pose.rotation * Pose::rot_z(rad(amount)).rotation,
                pose.translation,
            )
        }
    }
    let pose = st.kin.valid_frame(&pose, tool).map_err(|e| e.to_string())?;
    st.kin
        .ik_choose(&pose, tool, &q, st.arm, st.elbow)
        .map(|s| s.joints)
        .map_err(|e| e.to_string())
}

/// Base, shoulder, elbow, wrist and TCP in the arm plane: (r, unused, z).
fn arm_points(st: &RobotState, q: &Joints) -> Vec<(f64, f64, f64)> {
    let l = st.kin.description().links();
    let (a2, a3) = (q[1], q[1] + q[2]);
    let shoulder = (0.0, 0.0, l.l1);
    let elbow = (l.l2 * a2.sin(), 0.0, l.l1 + l.l2 * a2.cos());
    let wrist = (elbow.0 + l.l3 * a3.sin(), 0.0, elbow.2 + l.l3 * a3.cos());
    let tcp = st.kin.fk_tcp(q, &st.tool.trans).translation;
    let r = (tcp[0] * q[0].cos() + tcp[1] * q[0].sin()).clamp(-1e4, 1e4);
    vec![(0.0, 0.0, 0.0), shoulder, elbow, wrist, (r, 0.0, tcp[2])]
}

impl Pendant for TermPendant {
    fn teach(
        &mut self,
        st: &mut RobotState,
        clock: &mut dyn Clock,
        text: &str,
        refresh: bool,
        clear: bool,
    ) -> Result<(), String> {
        let mut out = std::io::stdout();
        enable_raw_mode().map_err(|e| format!("cannot use the terminal: {e}"))?;
        let _ = execute!(out, EnterAlternateScreen);
        let result = (|| -> Result<(), String> {
            let mut term = Terminal::new(CrosstermBackend::new(std::io::stdout()))
                .map_err(|e| e.to_string())?;
            if clear {
                let _ = term.clear();
            }
            // Refresh => False keeps the screen until the first key.
            let mut draw = refresh;
            self.message.clear();
            loop {
                if draw {
                    term.draw(|f| self.draw(f, st, text))
                        .map_err(|e| e.to_string())?;
                }
                draw = true;
                match event::read().map_err(|e| e.to_string())? {
                    // Ctrl-C leaves, as x does (it is not `c`, which
                    // closes the hand); other control keys do nothing.
                    Event::Key(k)
                        if k.kind == KeyEventKind::Press
                            && k.modifiers.contains(KeyModifiers::CONTROL)
                            && k.code == KeyCode::Char('c') =>
                    {
                        return Ok(());
                    }
                    Event::Key(k) if k.modifiers.contains(KeyModifiers::CONTROL) => {}
                    Event::Key(k)
                        if k.kind == KeyEventKind::Press && self.key(st, clock, k.code) =>
                    {
                        return Ok(());
                    }
                    _ => {}
                }
            }
        })();
        let _ = execute!(out, LeaveAlternateScreen);
        let _ = disable_raw_mode();
        result
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::session::Session;

    fn session(robot: &str, setup: &str) -> Session {
        let mut s = Session::new(Box::new(std::io::sink()));
        s.set_robot(
            crate::kinematics::RobotDescription::builtin(robot).expect("robot"),
            None,
            false,
        );
        let o = s.run_source("setup.air", setup);
        assert_eq!(o.exit_code(), 0, "{o:?}");
        s
    }

    const POSES: [&str; 2] = [
        "InitRobot;\nMoveAxesAbsolute ((0.0, 0.5, 1.0, -0.5, 0.0));\n",
        "InitRobot;\nMoveAxesAbsolute ((0.6, 0.3, 1.2, 0.2, 0.4));\n",
    ];

    /// Every Cartesian direction works from an ordinary pose on both arms:
    /// x, y and z move the TCP by the step and nothing else (y used to be
    /// refused as "orientation not reachable"); pitch and roll keep the TCP
    /// where it is and turn the tool by the step.
    #[test]
    fn cartesian_jogs_move_along_every_axis_and_turn_at_the_tcp() {
        for robot in ["rv-m1", "rm-501"] {
            for setup in POSES {
                let s = session(robot, setup);
                let st = s.robot_state().expect("state");
                let q = st.robot.joints();
                let before = st.kin.fk_tcp(&q, &st.tool.trans);
                for axis in 0..5 {
                    for sign in [1.0, -1.0] {
                        let t = cartesian_target(st, axis, sign * 5.0).unwrap_or_else(|e| {
                            panic!("{robot} {setup} axis {axis} sign {sign}: {e}")
                        });
                        st.kin.description().check_limits(&t).expect("limits");
                        let after = st.kin.fk_tcp(&t, &st.tool.trans);
                        let d = after.translation - before.translation;
                        let mut want = nalgebra::Vector3::zeros();
                        if axis < 3 {
                            want[axis] = sign * 5.0;
                        }
                        assert!(
                            (d - want).norm() < 1e-6,
                            "{robot} axis {axis} {sign}: moved {d:?}"
                        );
                        let turned = deg(before.rotation_angle_to(&after));
                        if axis >= 3 {
                            assert!((turned - 5.0).abs() < 1e-6, "{robot} axis {axis}: {turned}");
                        } else {
                            assert!(turned < 5.0, "{robot} axis {axis}: turned {turned}");
                        }
                    }
                }
            }
        }
    }

    /// A sideways move needs the orientation adjusted: the new one is what
    /// ValidFrame makes of the old orientation at the new place.
    #[test]
    fn a_sideways_jog_keeps_the_orientation_reachable_as_validframe_does() {
        let s = session("rv-m1", POSES[0]);
        let st = s.robot_state().expect("state");
        let q = st.robot.joints();
        let mut goal = st.kin.fk_tcp(&q, &st.tool.trans);
        goal.translation[1] += 10.0;
        let valid = st.kin.valid_frame(&goal, &st.tool.trans).expect("valid");
        let t = cartesian_target(st, 1, 10.0).expect("y jog");
        let after = st.kin.fk_tcp(&t, &st.tool.trans);
        assert!(after.rotation_angle_to(&valid) < 1e-6);
        assert!(
            goal.rotation_angle_to(&valid) > 1e-4,
            "y needs an adjustment"
        );
    }

    /// At the end of its reach the jog is refused with the reason, and the
    /// joints are not changed.
    #[test]
    fn a_jog_out_of_reach_is_refused() {
        let s = session("rv-m1", "InitRobot;\n");
        let st = s.robot_state().expect("state");
        let e = cartesian_target(st, 2, 500.0).unwrap_err();
        assert!(!e.is_empty());
    }

    /// On an 80 x 24 terminal every legend line and every joint line is
    /// shown whole (the legend used to be cut at the panel's edge).
    #[test]
    fn the_legend_fits_an_80_column_terminal() {
        let s = session("rv-m1", POSES[1]);
        let st = s.robot_state().expect("state");
        for cartesian in [false, true] {
            let p = TermPendant {
                cartesian,
                ..TermPendant::new()
            };
            let mut term =
                Terminal::new(ratatui::backend::TestBackend::new(80, 24)).expect("terminal");
            term.draw(|f| p.draw(f, st, "Jog J1, then store"))
                .expect("draw");
            let buf = term.backend().buffer().clone();
            let rows: Vec<String> = (0..buf.area.height)
                .map(|y| {
                    (0..buf.area.width)
                        .map(|x| buf[(x, y)].symbol().to_string())
                        .collect()
                })
                .collect();
            let screen = rows.join("\n");
            let mut wanted: Vec<String> = LEGEND.iter().map(|l| l.to_string()).collect();
            for (plus, minus, name, cart) in KEYS {
                wanted.push(format!(
                    "{plus}/{minus} {}",
                    if cartesian { cart } else { name }
                ));
            }
            wanted.push("o/c open/close".into());
            wanted.push("store at the end".into());
            for w in wanted {
                assert!(screen.contains(&w), "`{w}` not shown whole:\n{screen}");
            }
        }
    }
}
