//! The screen teach pendant (ratatui + crossterm), behind the `TeachBox`
//! service and the REPL's `:teach`. Keys jog each joint (or the TCP along
//! the base axes), open and close the hand, change step and speed, and store
//! the current pose into a path. Limits are shown and never crossed.

use crate::interp::Clock;
use crate::kinematics::{Joints, deg, joints_to_deg, rad};
use crate::services::{Pendant, RobotState};
use ratatui::Terminal;
use ratatui::backend::CrosstermBackend;
use ratatui::crossterm::event::{self, Event, KeyCode, KeyEventKind};
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
    /// Position to store at (0 = after the last).
    position: usize,
    message: String,
}

impl TermPendant {
    pub fn new() -> TermPendant {
        TermPendant {
            cartesian: false,
            step: 2,
            path: 1,
            position: 0,
            message: String::new(),
        }
    }
}

/// Key bindings, as the help line shows them: (key plus, key minus, what).
const KEYS: [(char, char, &str, &str); 5] = [
    ('q', 'a', "body J1", "x"),
    ('w', 's', "shoulder J2", "y"),
    ('e', 'd', "elbow J3", "z"),
    ('r', 'f', "wrist pitch J4", "wrist pitch J4"),
    ('t', 'g', "wrist roll J5", "wrist roll J5"),
];

impl TermPendant {
    fn jog_joint(&mut self, st: &mut RobotState, clock: &mut dyn Clock, j: usize, sign: f64) {
        let mut q = st.robot.joints();
        q[j] += sign * rad(STEPS[self.step]);
        let spec = &st.kin.description().joints()[j];
        if !spec.contains(q[j]) {
            self.message = format!(
                "J{} at its limit ({:.1} .. {:.1} deg): jog refused",
                j + 1,
                deg(spec.min),
                deg(spec.max)
            );
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
        let q = st.robot.joints();
        let mut pose = st.kin.fk_tcp(&q, &st.tool.trans);
        pose.translation[axis] += sign * STEPS[self.step];
        match st
            .kin
            .ik_choose(&pose, &st.tool.trans, &q, st.arm, st.elbow)
        {
            Ok(s) => self.go(st, clock, s.joints),
            Err(e) => {
                self.message = format!(
                    "{} {}: refused: {e}",
                    ["x", "y", "z"][axis],
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

    fn store(&mut self, st: &mut RobotState) {
        let f = st.kin.fk_tcp(&st.robot.joints(), &st.tool.trans).to_rows();
        let path = st.paths.entry(self.path).or_default();
        // As InsertPosition: before the chosen position, or after the last.
        let at = if self.position == 0 {
            path.len()
        } else {
            (self.position - 1).min(path.len())
        };
        path.insert(at, f);
        self.message = format!("stored as position {} of path {}", at + 1, self.path);
    }

    /// Handles a key; true to leave.
    fn key(&mut self, st: &mut RobotState, clock: &mut dyn Clock, c: KeyCode) -> bool {
        match c {
            KeyCode::Esc | KeyCode::Char('x') => return true,
            KeyCode::Char('m') => {
                self.cartesian = !self.cartesian;
                self.message = if self.cartesian {
                    "Cartesian jogging (x, y, z along the base axes)".into()
                } else {
                    "joint jogging".into()
                };
            }
            KeyCode::Char('+') => self.step = (self.step + 1).min(STEPS.len() - 1),
            KeyCode::Char('-') => self.step = self.step.saturating_sub(1),
            KeyCode::Char('>') => st.velocity = (st.velocity + 10.0).min(100.0),
            KeyCode::Char('<') => st.velocity = (st.velocity - 10.0).max(10.0),
            KeyCode::Char(']') => self.path = (self.path + 1).min(65000),
            KeyCode::Char('[') => self.path = (self.path - 1).max(1),
            KeyCode::Char('}') => self.position = (self.position + 1).min(65000),
            KeyCode::Char('{') => self.position = self.position.saturating_sub(1),
            KeyCode::Char('p') => self.store(st),
            KeyCode::Char('o') | KeyCode::Char('c') => {
                let g = *st.kin.description().gripper();
                let r = if c == KeyCode::Char('o') {
                    st.robot.move_gripper(g.opening_max, None)
                } else {
                    st.robot.move_gripper(g.opening_min, Some(st.force_setting))
                };
                self.message = match r {
                    Ok(_) => {
                        let s = crate::services::grip_reading(st);
                        format!("hand: opening {:.1} mm, force {:.1} N", s.opening, s.force)
                    }
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
                    if self.cartesian && j < 3 {
                        self.jog_cartesian(st, clock, j, sign);
                    } else {
                        self.jog_joint(st, clock, j, sign);
                    }
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
            "mode {}  step {} {}  speed {:.0} %  move mode {}",
            if self.cartesian { "Cartesian" } else { "joint" },
            STEPS[self.step],
            if self.cartesian { "mm/deg" } else { "deg" },
            st.velocity,
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
                "J{} {:>9.3} deg  [{:>7.1} .. {:>6.1}]  {plus}/{minus} {what}",
                j + 1,
                d[j],
                deg(spec.min),
                deg(spec.max)
            )));
        }
        lines.push(Line::from(format!(
            "hand: opening {:.1} mm, force {:.1} N   o/c open/close",
            g.opening, g.force
        )));
        lines.push(Line::from(""));
        lines.push(Line::from("TCP frame:"));
        for row in tcp {
            lines.push(Line::from(format!(
                "  {:8.4} {:8.4} {:8.4} {:9.2}",
                row[0], row[1], row[2], row[3]
            )));
        }
        lines.push(Line::from(""));
        lines.push(Line::from(format!(
            "path {} ({} positions), store at {}   [ ] path  {{ }} position  p store",
            self.path,
            st.paths.get(&self.path).map(Vec::len).unwrap_or(0),
            if self.position == 0 {
                "the end".to_string()
            } else {
                format!("position {}", self.position)
            }
        )));
        lines.push(Line::from(
            "m joint/Cartesian  + - step  < > speed  x or Esc leave",
        ));
        lines.push(Line::from(""));
        lines.push(Line::styled(
            self.message.clone(),
            Style::default().fg(Color::Yellow),
        ));
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
