//! `--plot FILE.svg`: a picture of a run, from the samples `--record` keeps
//! (tools.md): the joints against time, and the TCP path seen from above
//! and from the side, with the arm's reach drawn.
//!
//! The SVG is written here, not with a plotting crate: plotters lays out
//! text with a font file even for SVG, which a fresh machine may not have,
//! while an SVG viewer renders `<text>` with its own fonts. What is drawn is
//! polylines, circles and text; [`nice_ticks`] chooses the axis labels.

use crate::kinematics::{RobotDescription, deg};
use crate::services::record::Sample;
use std::fmt::Write as _;

const WIDTH: f64 = 1000.0;
const HEIGHT: f64 = 760.0;
/// One colour per joint, J1 to J5.
const COLORS: [&str; 5] = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"];

/// A panel: where it is on the page and which data range it shows.
struct Panel {
    x: f64,
    y: f64,
    w: f64,
    h: f64,
    xr: (f64, f64),
    yr: (f64, f64),
}

impl Panel {
    fn px(&self, v: f64) -> f64 {
        self.x + (v - self.xr.0) / (self.xr.1 - self.xr.0) * self.w
    }
    fn py(&self, v: f64) -> f64 {
        self.y + self.h - (v - self.yr.0) / (self.yr.1 - self.yr.0) * self.h
    }
    /// Widens one range so that a unit is as long on both axes (a path
    /// seen from above must not be squashed).
    fn equal_aspect(mut self) -> Panel {
        let sx = (self.xr.1 - self.xr.0) / self.w;
        let sy = (self.yr.1 - self.yr.0) / self.h;
        if sx > sy {
            let mid = (self.yr.0 + self.yr.1) / 2.0;
            let half = sx * self.h / 2.0;
            self.yr = (mid - half, mid + half);
        } else {
            let mid = (self.xr.0 + self.xr.1) / 2.0;
            let half = sy * self.w / 2.0;
            self.xr = (mid - half, mid + half);
        }
        self
    }
}

/// About `n` round axis values covering `lo .. hi` (steps of 1, 2 or 5
/// times a power of ten).
pub fn nice_ticks(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    if !(lo.is_finite() && hi.is_finite()) || hi <= lo || n == 0 {
        return vec![lo];
    }
    let raw = (hi - lo) / n as f64;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * mag)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * mag);
    let mut v = (lo / step).ceil() * step;
    let mut out = Vec::new();
    while v <= hi + step * 1e-9 {
        out.push(if v.abs() < step * 1e-9 { 0.0 } else { v });
        v += step;
    }
    out
}

fn fmt_tick(v: f64) -> String {
    if v.fract().abs() < 1e-9 {
        format!("{v:.0}")
    } else {
        format!("{v:.2}")
            .trim_end_matches('0')
            .trim_end_matches('.')
            .to_string()
    }
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn frame(out: &mut String, p: &Panel, title: &str, xlabel: &str, ylabel: &str) {
    let _ = writeln!(
        out,
        r##"<g class="panel"><text x="{:.1}" y="{:.1}" font-size="15" font-weight="bold">{}</text>"##,
        p.x,
        p.y - 10.0,
        escape(title)
    );
    let _ = writeln!(
        out,
        r##"<rect x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}" fill="none" stroke="#888"/>"##,
        p.x, p.y, p.w, p.h
    );
    for t in nice_ticks(p.xr.0, p.xr.1, 8) {
        let x = p.px(t);
        let _ = writeln!(
            out,
            r##"<line x1="{x:.1}" y1="{:.1}" x2="{x:.1}" y2="{:.1}" stroke="#eee"/><text x="{x:.1}" y="{:.1}" font-size="11" text-anchor="middle">{}</text>"##,
            p.y,
            p.y + p.h,
            p.y + p.h + 14.0,
            fmt_tick(t)
        );
    }
    for t in nice_ticks(p.yr.0, p.yr.1, 6) {
        let y = p.py(t);
        let _ = writeln!(
            out,
            r##"<line x1="{:.1}" y1="{y:.1}" x2="{:.1}" y2="{y:.1}" stroke="#eee"/><text x="{:.1}" y="{:.1}" font-size="11" text-anchor="end">{}</text>"##,
            p.x,
            p.x + p.w,
            p.x - 4.0,
            y + 4.0,
            fmt_tick(t)
        );
    }
    let _ = writeln!(
        out,
        r##"<text x="{:.1}" y="{:.1}" font-size="12" text-anchor="middle">{}</text>"##,
        p.x + p.w / 2.0,
        p.y + p.h + 30.0,
        escape(xlabel)
    );
    let _ = writeln!(
        out,
        r##"<text x="{:.1}" y="{:.1}" font-size="12" text-anchor="middle" transform="rotate(-90 {:.1} {:.1})">{}</text></g>"##,
        p.x - 38.0,
        p.y + p.h / 2.0,
        p.x - 38.0,
        p.y + p.h / 2.0,
        escape(ylabel)
    );
}

fn polyline(out: &mut String, p: &Panel, pts: &[(f64, f64)], color: &str, class: &str) {
    let mut d = String::new();
    for (x, y) in pts {
        let _ = write!(d, "{:.1},{:.1} ", p.px(*x), p.py(*y));
    }
    let _ = writeln!(
        out,
        r##"<polyline class="{class}" points="{}" fill="none" stroke="{color}" stroke-width="1.6"/>"##,
        d.trim_end()
    );
}

/// Start (green circle) and end (red square) of a path.
fn ends(out: &mut String, p: &Panel, first: (f64, f64), last: (f64, f64)) {
    let _ = writeln!(
        out,
        r##"<circle class="start" cx="{:.1}" cy="{:.1}" r="5" fill="#2ca02c"><title>start</title></circle>"##,
        p.px(first.0),
        p.py(first.1)
    );
    let _ = writeln!(
        out,
        r##"<rect class="end" x="{:.1}" y="{:.1}" width="9" height="9" fill="#d62728"><title>end</title></rect>"##,
        p.px(last.0) - 4.5,
        p.py(last.1) - 4.5
    );
}

/// The SVG of a run on `robot`: three panels, or a note when nothing moved.
pub fn svg(samples: &[Sample], robot: &RobotDescription, title: &str) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" viewBox="0 0 {WIDTH} {HEIGHT}" font-family="sans-serif">"##
    );
    let _ = writeln!(out, r##"<rect width="100%" height="100%" fill="white"/>"##);
    let _ = writeln!(
        out,
        r##"<text x="20" y="28" font-size="18">{} on the {}</text>"##,
        escape(title),
        escape(robot.name())
    );
    let links = robot.links();
    // The farthest the TCP gets from the shoulder (arm stretched).
    let reach = links.l2 + links.l3 + links.l4 + links.tool;
    if samples.is_empty() {
        let _ = writeln!(
            out,
            r##"<text class="no-motion" x="20" y="70" font-size="15">no motion: the program moved no joint</text></svg>"##
        );
        return out;
    }
    let t_end = samples.last().map_or(0.0, |s| s.t).max(1e-3);

    // Joints against time, degrees, with each joint's limits as the range.
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for s in samples {
        for q in s.joints.iter() {
            lo = lo.min(deg(*q));
            hi = hi.max(deg(*q));
        }
    }
    let pad = ((hi - lo) * 0.08).max(5.0);
    let joints = Panel {
        x: 70.0,
        y: 70.0,
        w: 760.0,
        h: 260.0,
        xr: (0.0, t_end),
        yr: (lo - pad, hi + pad),
    };
    frame(
        &mut out,
        &joints,
        "Joints against time",
        "virtual time (s)",
        "joint angle (deg)",
    );
    for (j, color) in COLORS.iter().enumerate() {
        let pts: Vec<(f64, f64)> = samples.iter().map(|s| (s.t, deg(s.joints[j]))).collect();
        polyline(&mut out, &joints, &pts, color, &format!("joint j{}", j + 1));
        let y = 90.0 + 20.0 * j as f64;
        let _ = writeln!(
            out,
            r##"<line x1="850" y1="{y:.1}" x2="875" y2="{y:.1}" stroke="{color}" stroke-width="3"/><text x="882" y="{:.1}" font-size="12">J{}</text>"##,
            y + 4.0,
            j + 1,
        );
    }

    // The TCP from above: x, y, with the reach around the waist axis.
    let xs = samples.iter().map(|s| s.tcp[0]);
    let ys = samples.iter().map(|s| s.tcp[1]);
    let r = reach * 1.05;
    let top = Panel {
        x: 70.0,
        y: 400.0,
        w: 400.0,
        h: 300.0,
        xr: (xs.clone().fold(-r, f64::min), xs.fold(r, f64::max)),
        yr: (ys.clone().fold(-r, f64::min), ys.fold(r, f64::max)),
    }
    .equal_aspect();
    frame(&mut out, &top, "TCP path from above", "x (mm)", "y (mm)");
    let _ = writeln!(
        out,
        r##"<circle class="workspace" cx="{:.1}" cy="{:.1}" r="{:.1}" fill="none" stroke="#999" stroke-dasharray="6 4"><title>reach {reach:.0} mm</title></circle>"##,
        top.px(0.0),
        top.py(0.0),
        top.px(reach) - top.px(0.0)
    );
    let path: Vec<(f64, f64)> = samples.iter().map(|s| (s.tcp[0], s.tcp[1])).collect();
    polyline(&mut out, &top, &path, "#333", "tcp top");
    ends(&mut out, &top, path[0], path[path.len() - 1]);

    // The TCP from the side: distance from the waist axis, height; the
    // reach is a circle about the shoulder.
    let rz: Vec<(f64, f64)> = samples
        .iter()
        .map(|s| (s.tcp[0].hypot(s.tcp[1]), s.tcp[2]))
        .collect();
    let side = Panel {
        x: 560.0,
        y: 400.0,
        w: 400.0,
        h: 300.0,
        xr: (
            rz.iter().map(|p| p.0).fold(-0.2 * reach, f64::min),
            rz.iter().map(|p| p.0).fold(r, f64::max),
        ),
        yr: (
            rz.iter().map(|p| p.1).fold(links.l1 - r, f64::min),
            rz.iter().map(|p| p.1).fold(links.l1 + r, f64::max),
        ),
    }
    .equal_aspect();
    frame(
        &mut out,
        &side,
        "TCP path from the side",
        "distance from the waist axis (mm)",
        "z (mm)",
    );
    let _ = writeln!(
        out,
        r##"<circle class="workspace" cx="{:.1}" cy="{:.1}" r="{:.1}" fill="none" stroke="#999" stroke-dasharray="6 4"><title>reach {reach:.0} mm about the shoulder</title></circle>"##,
        side.px(0.0),
        side.py(links.l1),
        side.px(reach) - side.px(0.0)
    );
    let _ = writeln!(
        out,
        r##"<line class="floor" x1="{:.1}" y1="{y:.1}" x2="{:.1}" y2="{y:.1}" stroke="#8c564b" stroke-width="2"><title>the robot's base plane (z = 0)</title></line>"##,
        side.x,
        side.x + side.w,
        y = side.py(0.0)
    );
    polyline(&mut out, &side, &rz, "#333", "tcp side");
    ends(&mut out, &side, rz[0], rz[rz.len() - 1]);
    let _ = writeln!(
        out,
        r##"<text x="70" y="745" font-size="12">green circle: start, red square: end, dashed: the arm's reach ({reach:.0} mm from the shoulder); {} support points over {:.3} s</text>"##,
        samples.len(),
        t_end
    );
    out.push_str("</svg>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_are_round_and_cover_the_range() {
        assert_eq!(
            nice_ticks(0.0, 10.0, 5),
            vec![0.0, 2.0, 4.0, 6.0, 8.0, 10.0]
        );
        assert_eq!(nice_ticks(-90.0, 90.0, 4), vec![-50.0, 0.0, 50.0]);
        let t = nice_ticks(0.0, 2.37, 8);
        assert_eq!(t.first(), Some(&0.0));
        assert!(t.last().is_some_and(|l| *l <= 2.37 && *l >= 2.0), "{t:?}");
        assert_eq!(nice_ticks(5.0, 5.0, 4), vec![5.0]);
        assert_eq!(nice_ticks(f64::NAN, 1.0, 4).len(), 1);
    }

    #[test]
    fn equal_aspect_makes_a_millimetre_as_long_on_both_axes() {
        let p = Panel {
            x: 0.0,
            y: 0.0,
            w: 400.0,
            h: 300.0,
            xr: (-100.0, 100.0),
            yr: (-100.0, 100.0),
        }
        .equal_aspect();
        let sx = (p.px(100.0) - p.px(0.0)) / 100.0;
        let sy = (p.py(0.0) - p.py(100.0)) / 100.0;
        assert!((sx - sy).abs() < 1e-9, "{sx} {sy}");
        assert!(p.xr.0 <= -100.0 && p.xr.1 >= 100.0);
    }

    #[test]
    fn text_is_escaped() {
        assert_eq!(escape("a<b & \"c\">"), "a&lt;b &amp; &quot;c&quot;&gt;");
    }
}
