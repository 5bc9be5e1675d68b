//! `--plot FILE.svg`: a picture of a run, from the samples `--record` keeps
//! (tools.md): the joints and the hand's opening against time, and the TCP
//! path seen from above and from the side, scaled to the path with a scale
//! bar, with the arm's reach drawn where it is in view and a refused goal
//! marked. Legends sit beside or below the plots, never on a curve; a
//! joint curve that runs on an earlier one is dashed and the legend says
//! on which (docs/record.md). Drawn with plotters'
//! SVG backend; plotters measures text with a font, so one is built in
//! (`assets/fonts`, DejaVu Sans, free licence beside it): a fresh machine
//! needs no system fonts. The SVG names the family `sans-serif`, which the
//! viewer renders with its own fonts.

use crate::kinematics::{RobotDescription, deg};
use crate::services::record::Sample;
use plotters::prelude::*;

const WIDTH: u32 = 1000;
const HEIGHT: u32 = 1010;
/// The legend column beside the plots against time.
const LEGEND_W: u32 = 190;
/// Chart layout (pixels): margin around a chart and its axis label areas.
const MARGIN: u32 = 12;
const X_LABELS: u32 = 40;
const Y_LABELS: u32 = 55;
/// One colour per joint, J1 to J5.
const COLORS: [RGBColor; 5] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
];
/// Dash and gap (pixels) of the first, second, ... curve that runs on an
/// earlier one: each looks different from the others and from a solid line.
const DASHES: [(u32, u32); 4] = [(10, 8), (4, 6), (16, 5), (2, 4)];
const PATH: RGBColor = RGBColor(51, 51, 51);
const REACH: RGBColor = RGBColor(150, 150, 150);
const FLOOR: RGBColor = RGBColor(140, 86, 75);
const HAND: RGBColor = RGBColor(23, 190, 207);
const REFUSED: RGBColor = RGBColor(200, 0, 0);

/// The font plotters measures text with, registered once.
fn font() -> bool {
    static DONE: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *DONE.get_or_init(|| {
        plotters::style::register_font(
            "sans-serif",
            FontStyle::Normal,
            include_bytes!("../assets/fonts/DejaVuSans-ExtraLight.ttf"),
        )
        .is_ok()
    })
}

/// A range widened so that a millimetre is as long on both axes of a
/// `w` x `h` pixel panel (a path seen from above must not be squashed).
fn equal_aspect(xr: (f64, f64), yr: (f64, f64), w: f64, h: f64) -> ((f64, f64), (f64, f64)) {
    let sx = (xr.1 - xr.0) / w;
    let sy = (yr.1 - yr.0) / h;
    if sx > sy {
        let mid = (yr.0 + yr.1) / 2.0;
        let half = sx * h / 2.0;
        (xr, (mid - half, mid + half))
    } else {
        let mid = (xr.0 + xr.1) / 2.0;
        let half = sy * w / 2.0;
        ((mid - half, mid + half), yr)
    }
}

/// The bounds of `points` widened by a margin (a tenth of the larger
/// extent, at least 20 mm on each side), so the path fills the view.
fn data_bounds(points: &[(f64, f64)]) -> ((f64, f64), (f64, f64)) {
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for &(x, y) in points {
        if x.is_finite() && y.is_finite() {
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
    }
    if x0 > x1 {
        (x0, x1, y0, y1) = (0.0, 0.0, 0.0, 0.0);
    }
    let m = ((x1 - x0).max(y1 - y0) * 0.1).max(20.0);
    ((x0 - m, x1 + m), (y0 - m, y1 + m))
}

/// A scale bar's length: 1, 2 or 5 times a power of ten, about a fifth of
/// `span` (mm).
fn scale_bar(span: f64) -> f64 {
    let target = (span / 5.0).max(1e-6);
    let p = 10f64.powf(target.log10().floor());
    [5.0, 2.0, 1.0]
        .iter()
        .map(|k| k * p)
        .find(|l| *l <= target)
        .unwrap_or(p)
}

/// Points of a circle of radius `r` about `c`.
fn circle(c: (f64, f64), r: f64) -> Vec<(f64, f64)> {
    (0..=360)
        .map(|i| {
            let a = i as f64 * std::f64::consts::TAU / 360.0;
            (c.0 + r * a.cos(), c.1 + r * a.sin())
        })
        .collect()
}

/// The runs of `points` that lie inside the view `xr` x `yr` (a curve is
/// drawn only where it is in view: plotters does not clip).
fn inside(points: &[(f64, f64)], xr: (f64, f64), yr: (f64, f64)) -> Vec<Vec<(f64, f64)>> {
    let mut runs = vec![Vec::new()];
    for &(x, y) in points {
        if x >= xr.0 && x <= xr.1 && y >= yr.0 && y <= yr.1 {
            if let Some(r) = runs.last_mut() {
                r.push((x, y));
            }
        } else if runs.last().is_some_and(|r| !r.is_empty()) {
            runs.push(Vec::new());
        }
    }
    runs.retain(|r| r.len() >= 2);
    runs
}

/// Where the segment from `from` (inside the view) towards `to` leaves the
/// view, or `to` when it is inside.
fn towards(from: (f64, f64), to: (f64, f64), xr: (f64, f64), yr: (f64, f64)) -> (f64, f64) {
    let mut f: f64 = 1.0;
    let (dx, dy) = (to.0 - from.0, to.1 - from.1);
    for (d, p, lo, hi) in [(dx, from.0, xr.0, xr.1), (dy, from.1, yr.0, yr.1)] {
        if d > 0.0 {
            f = f.min((hi - p) / d);
        } else if d < 0.0 {
            f = f.min((lo - p) / d);
        }
    }
    let f = f.clamp(0.0, 1.0);
    (from.0 + dx * f, from.1 + dy * f)
}

type Area<'a> = DrawingArea<SVGBackend<'a>, plotters::coord::Shift>;

fn err(e: impl std::fmt::Display) -> String {
    format!("cannot draw the plot: {e}")
}

/// A goal the arm refused: when (virtual time, s) and the TCP goal (mm).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Refused {
    pub t: f64,
    pub goal: [f64; 3],
}

/// The SVG of a run on `robot`: four panels, or a note when nothing moved.
/// `refused` is the goal of the last motion the arm refused, when no motion
/// ran after it.
pub fn svg(
    samples: &[Sample],
    robot: &RobotDescription,
    title: &str,
    refused: Option<Refused>,
) -> Result<String, String> {
    if !font() {
        return Err("the built-in font does not load".into());
    }
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, (WIDTH, HEIGHT)).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let root = root
            .titled(
                &format!("{title} on the {}", robot.name()),
                ("sans-serif", 20),
            )
            .map_err(err)?;
        if samples.is_empty() {
            root.draw(&Text::new(
                "no motion: the program moved no joint",
                (20, 30),
                ("sans-serif", 16),
            ))
            .map_err(err)?;
            if let Some(r) = refused {
                root.draw(&Text::new(
                    format!(
                        "refused goal at t = {:.3} s: TCP ({:.1}, {:.1}, {:.1}) mm",
                        r.t, r.goal[0], r.goal[1], r.goal[2]
                    ),
                    (20, 60),
                    ("sans-serif", 16).into_font().color(&REFUSED),
                ))
                .map_err(err)?;
            }
            root.present().map_err(err)?;
        } else {
            let (top, rest) = root.split_vertically(340);
            let (hand, bottom) = rest.split_vertically(190);
            let (above, side) = bottom.split_horizontally(WIDTH / 2);
            let t_end = samples.last().map_or(0.0, |s| s.t).max(1e-3);
            let t_end = refused.map_or(t_end, |r| t_end.max(r.t));
            joints_panel(&top, samples, t_end, refused)?;
            hand_panel(&hand, samples, t_end, robot, refused)?;
            let links = robot.links();
            // The farthest the TCP gets from the shoulder (arm stretched).
            let reach = links.l2 + links.l3 + links.l4 + links.tool;
            above_panel(&above, samples, reach, refused)?;
            side_panel(&side, samples, reach, links.l1, refused)?;
            root.present().map_err(err)?;
        }
    }
    if let Some(n) = samples.last() {
        out = out.replace(
            "</svg>",
            &format!(
                "<!-- {} support points over {:.3} s; reach {:.0} mm -->\n</svg>",
                samples.len(),
                n.t,
                robot.links().l2 + robot.links().l3 + robot.links().l4 + robot.links().tool
            ),
        );
    }
    Ok(out)
}

type Chart<'a, 'b> = ChartContext<
    'a,
    SVGBackend<'b>,
    Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
>;

/// The plotting area's size (pixels) of a [`panel`] on an area of `dim`
/// below its caption.
fn plot_size(dim: (u32, u32)) -> (f64, f64) {
    (
        dim.0.saturating_sub(2 * MARGIN + Y_LABELS).max(1) as f64,
        dim.1.saturating_sub(2 * MARGIN + X_LABELS).max(1) as f64,
    )
}

/// A panel on `area` (below its caption) with axes and grid.
fn panel<'a, 'b>(
    area: &'a Area<'b>,
    xr: (f64, f64),
    yr: (f64, f64),
    (xdesc, ydesc): (&str, &str),
) -> Result<Chart<'a, 'b>, String> {
    let mut chart = ChartBuilder::on(area)
        .margin(MARGIN)
        .x_label_area_size(X_LABELS)
        .y_label_area_size(Y_LABELS)
        .build_cartesian_2d(xr.0..xr.1, yr.0..yr.1)
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc(xdesc)
        .y_desc(ydesc)
        .draw()
        .map_err(err)?;
    Ok(chart)
}

/// A legend entry: a sample of the line (solid, or dashed `dash`) or a
/// marker, and its text.
enum Mark {
    Line(RGBColor, Option<(u32, u32)>),
    Dot(RGBColor),
    Square(RGBColor),
    Cross(RGBColor),
}

/// Draws `entries` one under the other from `(x, y)` on `area` (outside
/// every plot).
fn legend(area: &Area<'_>, (x, y): (i32, i32), entries: &[(Mark, String)]) -> Result<(), String> {
    for (k, (mark, text)) in entries.iter().enumerate() {
        let y = y + 20 * k as i32;
        match mark {
            Mark::Line(c, None) => area
                .draw(&PathElement::new(
                    vec![(x, y), (x + 24, y)],
                    c.stroke_width(2),
                ))
                .map_err(err)?,
            Mark::Line(c, Some((d, g))) => {
                let mut at = 0;
                while at < 24 {
                    let to = (at + *d as i32).min(24);
                    area.draw(&PathElement::new(
                        vec![(x + at, y), (x + to, y)],
                        c.stroke_width(2),
                    ))
                    .map_err(err)?;
                    at = to + *g as i32;
                }
            }
            Mark::Dot(c) => area
                .draw(&Circle::new((x + 12, y), 5, c.filled()))
                .map_err(err)?,
            Mark::Square(c) => area
                .draw(&Rectangle::new(
                    [(x + 8, y - 4), (x + 16, y + 4)],
                    c.filled(),
                ))
                .map_err(err)?,
            Mark::Cross(c) => area
                .draw(&Cross::new((x + 12, y), 6, c.stroke_width(2)))
                .map_err(err)?,
        }
        area.draw(&Text::new(
            text.clone(),
            (x + 30, y - 7),
            ("sans-serif", 13),
        ))
        .map_err(err)?;
    }
    Ok(())
}

/// Writes what a run recorded to `path`, by its extension: `.svg` the
/// picture (titled `title`), `.json` or `.csv` the support points. Returns
/// the number of support points.
pub fn write_run(
    path: &std::path::Path,
    st: &crate::services::RobotState,
    title: &str,
) -> Result<usize, String> {
    let samples = st.record.as_deref().unwrap_or(&[]);
    let text = match path.extension().and_then(|e| e.to_str()) {
        Some("svg") => {
            let refused = st.refused.map(|(t, goal)| Refused {
                t,
                goal: [goal.translation.x, goal.translation.y, goal.translation.z],
            });
            svg(samples, st.kin.description(), title, refused)?
        }
        Some("json") => crate::services::record::to_json(samples),
        _ => crate::services::record::to_csv(samples),
    };
    // Only a regular file is replaced, whole (as SavePathSystem does).
    crate::services::paths::write_whole(path, text.as_bytes()).map_err(|(_, msg)| msg)?;
    Ok(samples.len())
}

/// Whether `path` may take a run's recording or picture when the run ends:
/// it does not exist yet, or it is a regular file (through symbolic links)
/// that may be written. Checked before the program runs, so that a FIFO,
/// a device or a directory is refused at once (and not written into at
/// the end).
pub fn check_target(path: &std::path::Path) -> Result<(), String> {
    match std::fs::metadata(path) {
        Ok(m) => match crate::services::paths::not_a_file(&m.file_type()) {
            Some(kind) => Err(format!("it is {kind}, not a regular file")),
            None => Ok(()),
        },
        Err(_) => Ok(()),
    }
}

/// For each joint, the earlier joint its curve runs on (within a
/// two-hundredth of the plot's range, or 0.05 deg) for at least a third of
/// the run's samples, and that share: such a curve would hide the one
/// under it, so it is dashed and the legend says on which it runs.
fn coincident(samples: &[Sample], range: f64) -> [Option<(usize, f64)>; 5] {
    let tol = (range / 200.0).max(0.05);
    let mut out = [None; 5];
    for (j, slot) in out.iter_mut().enumerate() {
        for i in 0..j {
            let same = samples
                .iter()
                .filter(|s| (deg(s.joints[i]) - deg(s.joints[j])).abs() <= tol)
                .count();
            let share = same as f64 / samples.len().max(1) as f64;
            if share >= 1.0 / 3.0 {
                *slot = Some((i, share));
                break;
            }
        }
    }
    out
}

/// A vertical line at the refused goal's time, red, dashed.
fn refused_line(chart: &mut Chart<'_, '_>, t: f64, yr: (f64, f64)) -> Result<(), String> {
    chart
        .draw_series(DashedLineSeries::new(
            vec![(t, yr.0), (t, yr.1)],
            6,
            4,
            REFUSED.stroke_width(2),
        ))
        .map_err(err)?;
    Ok(())
}

fn joints_panel(
    area: &Area<'_>,
    samples: &[Sample],
    t_end: f64,
    refused: Option<Refused>,
) -> Result<(), String> {
    let (plot, side) = area.split_horizontally(WIDTH - LEGEND_W);
    let plot = plot
        .titled("Joints against time", ("sans-serif", 16))
        .map_err(err)?;
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for s in samples {
        for q in s.joints.iter() {
            lo = lo.min(deg(*q));
            hi = hi.max(deg(*q));
        }
    }
    let pad = ((hi - lo) * 0.08).max(5.0);
    let yr = (lo - pad, hi + pad);
    let mut chart = panel(
        &plot,
        (0.0, t_end),
        yr,
        ("virtual time (s)", "joint angle (deg)"),
    )?;
    let on = coincident(samples, yr.1 - yr.0);
    let mut entries = Vec::new();
    // Solid curves first, then the dashed ones on top of them.
    for (j, color) in COLORS.iter().enumerate() {
        if on[j].is_none() {
            chart
                .draw_series(LineSeries::new(
                    samples.iter().map(|s| (s.t, deg(s.joints[j]))),
                    color.stroke_width(2),
                ))
                .map_err(err)?;
        }
    }
    let mut dashed = 0;
    for (j, color) in COLORS.iter().enumerate() {
        match on[j] {
            None => entries.push((Mark::Line(*color, None), format!("J{}", j + 1))),
            Some((i, share)) => {
                let (d, g) = DASHES[dashed % DASHES.len()];
                dashed += 1;
                chart
                    .draw_series(DashedLineSeries::new(
                        samples.iter().map(|s| (s.t, deg(s.joints[j]))),
                        d,
                        g,
                        color.stroke_width(2),
                    ))
                    .map_err(err)?;
                let how = if share > 0.999 {
                    "all the run".to_string()
                } else {
                    format!("{:.0} % of the run", share * 100.0)
                };
                entries.push((
                    Mark::Line(*color, Some((d, g))),
                    format!("J{} dashed: on J{} {how}", j + 1, i + 1),
                ));
            }
        }
    }
    if let Some(r) = refused {
        refused_line(&mut chart, r.t, yr)?;
        entries.push((
            Mark::Line(REFUSED, Some((6, 4))),
            format!("refused goal, {:.3} s", r.t),
        ));
    }
    legend(&side, (4, 40), &entries)
}

/// The hand's opening against time.
fn hand_panel(
    area: &Area<'_>,
    samples: &[Sample],
    t_end: f64,
    robot: &RobotDescription,
    refused: Option<Refused>,
) -> Result<(), String> {
    let (plot, side) = area.split_horizontally(WIDTH - LEGEND_W);
    let plot = plot
        .titled("Hand opening against time", ("sans-serif", 16))
        .map_err(err)?;
    let most = samples
        .iter()
        .map(|s| s.grip)
        .fold(robot.gripper().opening_max, f64::max);
    let yr = (0.0, (most * 1.1).max(1.0));
    let mut chart = panel(
        &plot,
        (0.0, t_end),
        yr,
        ("virtual time (s)", "opening (mm)"),
    )?;
    chart
        .draw_series(LineSeries::new(
            samples.iter().map(|s| (s.t, s.grip)),
            HAND.stroke_width(2),
        ))
        .map_err(err)?;
    let mut entries = vec![(Mark::Line(HAND, None), "hand opening".to_string())];
    if let Some(r) = refused {
        refused_line(&mut chart, r.t, yr)?;
        entries.push((Mark::Line(REFUSED, Some((6, 4))), "refused goal".into()));
    }
    legend(&side, (4, 40), &entries)
}

/// One view of the TCP path (`points`, mm in the view's plane): scaled to
/// the path with a margin and a scale bar, the reach circle (`reach` about
/// `centre`) where it is in view, the floor line `floor` when given, start
/// and end, and the refused goal; the legend below the plot.
struct View<'p> {
    caption: &'p str,
    axes: (&'p str, &'p str),
    points: &'p [(f64, f64)],
    centre: (f64, f64),
    reach: f64,
    floor: Option<f64>,
    goal: Option<(f64, f64)>,
}

fn view_panel(area: &Area<'_>, v: &View<'_>) -> Result<(), String> {
    let area = area.titled(v.caption, ("sans-serif", 16)).map_err(err)?;
    let (plot, below) = area.split_vertically(area.dim_in_pixel().1.saturating_sub(70));
    let (w, h) = plot_size(plot.dim_in_pixel());
    let mut pts: Vec<(f64, f64)> = v.points.to_vec();
    let (xr, yr) = {
        // A refused goal near the path is in view; a far one is marked at
        // the view's edge, towards it.
        if let Some(g) = v.goal {
            let (bx, by) = data_bounds(&pts);
            let span = (bx.1 - bx.0).max(by.1 - by.0);
            let near = g.0 >= bx.0 - span
                && g.0 <= bx.1 + span
                && g.1 >= by.0 - span
                && g.1 <= by.1 + span;
            if near {
                pts.push(g);
            }
        }
        let (bx, by) = data_bounds(&pts);
        equal_aspect(bx, by, w, h)
    };
    let mut chart = panel(&plot, xr, yr, v.axes)?;
    let mut entries = vec![(Mark::Line(PATH, None), "TCP path".to_string())];
    let ring = inside(&circle(v.centre, v.reach), xr, yr);
    let reach_text = if ring.is_empty() {
        format!("reach {:.0} mm: outside this view", v.reach)
    } else {
        format!("reach {:.0} mm", v.reach)
    };
    for run in ring {
        chart
            .draw_series(std::iter::once(PathElement::new(
                run,
                REACH.stroke_width(1),
            )))
            .map_err(err)?;
    }
    entries.push((Mark::Line(REACH, None), reach_text));
    if let Some(z) = v.floor.filter(|z| *z >= yr.0 && *z <= yr.1) {
        chart
            .draw_series(std::iter::once(PathElement::new(
                vec![(xr.0, z), (xr.1, z)],
                FLOOR.stroke_width(2),
            )))
            .map_err(err)?;
        entries.push((Mark::Line(FLOOR, None), "base plane z = 0".into()));
    }
    chart
        .draw_series(LineSeries::new(v.points.to_vec(), PATH.stroke_width(2)))
        .map_err(err)?;
    let (first, last) = (v.points[0], v.points[v.points.len() - 1]);
    chart
        .draw_series(std::iter::once(Circle::new(first, 6, GREEN.filled())))
        .map_err(err)?;
    chart
        .draw_series(std::iter::once(
            EmptyElement::at(last) + Rectangle::new([(-5, -5), (5, 5)], RED.filled()),
        ))
        .map_err(err)?;
    entries.push((Mark::Dot(GREEN), "start".into()));
    entries.push((Mark::Square(RED), "end".into()));
    if let Some(g) = v.goal {
        let at = towards(last, g, xr, yr);
        chart
            .draw_series(DashedLineSeries::new(
                vec![last, at],
                6,
                4,
                REFUSED.stroke_width(2),
            ))
            .map_err(err)?;
        chart
            .draw_series(std::iter::once(Cross::new(at, 8, REFUSED.stroke_width(3))))
            .map_err(err)?;
        let text = if at == g {
            "refused goal".to_string()
        } else {
            format!("refused goal ({:.0}, {:.0}) mm, out of view", g.0, g.1)
        };
        entries.push((Mark::Cross(REFUSED), text));
    }
    // The scale bar, at the lower left of the plot.
    let bar = scale_bar(xr.1 - xr.0);
    let (x0, y0) = (xr.0 + (xr.1 - xr.0) * 0.05, yr.0 + (yr.1 - yr.0) * 0.06);
    chart
        .draw_series(std::iter::once(PathElement::new(
            vec![(x0, y0), (x0 + bar, y0)],
            BLACK.stroke_width(3),
        )))
        .map_err(err)?;
    chart
        .draw_series(std::iter::once(Text::new(
            format!("{bar} mm"),
            // Its top 18 pixels above the bar: the text stands on it.
            (x0, y0 + (yr.1 - yr.0) * 18.0 / h),
            ("sans-serif", 13),
        )))
        .map_err(err)?;
    // The legend below the plot, in two columns.
    let half = entries.len().div_ceil(2);
    let (left, right) = entries.split_at(half);
    legend(&below, (20, 12), left)?;
    legend(&below, (250, 12), right)
}

fn above_panel(
    area: &Area<'_>,
    samples: &[Sample],
    reach: f64,
    refused: Option<Refused>,
) -> Result<(), String> {
    let path: Vec<(f64, f64)> = samples.iter().map(|s| (s.tcp[0], s.tcp[1])).collect();
    view_panel(
        area,
        &View {
            caption: "TCP path from above",
            axes: ("x (mm)", "y (mm)"),
            points: &path,
            centre: (0.0, 0.0),
            reach,
            floor: None,
            goal: refused.map(|r| (r.goal[0], r.goal[1])),
        },
    )
}

fn side_panel(
    area: &Area<'_>,
    samples: &[Sample],
    reach: f64,
    shoulder: f64,
    refused: Option<Refused>,
) -> Result<(), String> {
    let rz: Vec<(f64, f64)> = samples
        .iter()
        .map(|s| (s.tcp[0].hypot(s.tcp[1]), s.tcp[2]))
        .collect();
    view_panel(
        area,
        &View {
            caption: "TCP path from the side",
            axes: ("distance from the waist axis (mm)", "z (mm)"),
            points: &rz,
            centre: (0.0, shoulder),
            reach,
            floor: Some(0.0),
            goal: refused.map(|r| (r.goal[0].hypot(r.goal[1]), r.goal[2])),
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_aspect_makes_a_millimetre_as_long_on_both_axes() {
        let (xr, yr) = equal_aspect((-100.0, 100.0), (-100.0, 100.0), 400.0, 300.0);
        let sx = 400.0 / (xr.1 - xr.0);
        let sy = 300.0 / (yr.1 - yr.0);
        assert!((sx - sy).abs() < 1e-9, "{sx} {sy}");
        assert!(xr.0 <= -100.0 && xr.1 >= 100.0 && yr.0 <= -100.0 && yr.1 >= 100.0);
    }

    #[test]
    fn the_circle_has_its_radius() {
        for (x, y) in circle((0.0, 200.0), 50.0) {
            assert!(((x * x + (y - 200.0) * (y - 200.0)).sqrt() - 50.0).abs() < 1e-9);
        }
    }

    /// A sample at `t` with joints `q` (degrees), TCP `tcp` and opening `grip`.
    fn at(t: f64, q: [f64; 5], tcp: [f64; 3], grip: f64) -> Sample {
        Sample {
            t,
            joints: q.map(f64::to_radians),
            tcp,
            grip,
        }
    }

    /// A 100 mm square drawn at z = 200 mm, 250 mm in front of the base,
    /// with J5 turning as J1 does; the jaws close at the end.
    fn square() -> Vec<Sample> {
        let corners = [
            (250.0, -50.0),
            (350.0, -50.0),
            (350.0, 50.0),
            (250.0, 50.0),
            (250.0, -50.0),
        ];
        let mut v: Vec<Sample> = corners
            .iter()
            .enumerate()
            .map(|(k, &(x, y))| {
                let j1 = f64::atan2(y, x).to_degrees();
                at(k as f64, [j1, 40.0, 80.0, 50.0, j1], [x, y, 200.0], 60.0)
            })
            .collect();
        v.push(at(
            5.0,
            [-11.3, 40.0, 80.0, 50.0, -11.3],
            [250.0, -50.0, 200.0],
            20.0,
        ));
        v
    }

    fn rv_m1() -> RobotDescription {
        RobotDescription::builtin("rv-m1").unwrap()
    }

    /// The points of every polyline drawn in `stroke`.
    fn polylines(svg: &str, stroke: &str) -> Vec<Vec<(f64, f64)>> {
        svg.split("<polyline")
            .skip(1)
            .filter(|p| p.contains(&format!("stroke=\"{stroke}\"")))
            .filter_map(|p| p.split("points=\"").nth(1)?.split('"').next())
            .map(|pts| {
                pts.split_whitespace()
                    .filter_map(|xy| {
                        let (x, y) = xy.split_once(',')?;
                        Some((x.parse().ok()?, y.parse().ok()?))
                    })
                    .collect()
            })
            .collect()
    }

    /// The x of each text element whose text is `text`.
    fn text_x(svg: &str, text: &str) -> Vec<f64> {
        svg.split("<text x=\"")
            .skip(1)
            .filter(|t| {
                t.split('>')
                    .nth(1)
                    .is_some_and(|b| b.trim_start().starts_with(text))
            })
            .filter_map(|t| t.split('"').next()?.parse().ok())
            .collect()
    }

    /// Issue 37: the path from above is scaled to the data (a 100 mm square
    /// was 60 pixels inside the full reach) and a scale bar says how long.
    #[test]
    fn a_100_mm_square_fills_the_view_from_above_with_a_scale_bar() {
        let svg = svg(&square(), &rv_m1(), "square", None).unwrap();
        let above = &polylines(&svg, "#333333")[0];
        let xs: Vec<f64> = above.iter().map(|p| p.0).collect();
        let wide = xs.iter().cloned().fold(f64::MIN, f64::max)
            - xs.iter().cloned().fold(f64::MAX, f64::min);
        assert!(wide >= 180.0, "the square is {wide} pixels wide");
        assert!(
            svg.contains("50 mm") || svg.contains("20 mm"),
            "no scale bar"
        );
        assert!(svg.contains("reach 589 mm: outside this view"));
    }

    #[test]
    fn the_scale_bar_is_a_round_fifth_of_the_view() {
        assert_eq!(scale_bar(140.0), 20.0);
        assert_eq!(scale_bar(1000.0), 200.0);
        assert_eq!(scale_bar(2600.0), 500.0);
        assert_eq!(scale_bar(4.0), 0.5);
    }

    /// Issue 37: a joint curve on an earlier one (J5 = J1 with the tool
    /// down) is dashed and the legend says so; legends are outside every
    /// plot (the joints' legend covered the curves).
    #[test]
    fn coincident_curves_are_dashed_and_legends_are_beside_the_plots() {
        let samples = square();
        let on = coincident(&samples, 100.0);
        assert_eq!(on[4], Some((0, 1.0)), "{on:?}");
        assert_eq!(&on[..4], &[None; 4]);
        let svg = svg(&samples, &rv_m1(), "square", None).unwrap();
        assert!(
            svg.contains("J5 dashed: on J1 all the run"),
            "no legend note"
        );
        // J5's curve is drawn as dashes: many short pieces in its colour.
        assert!(polylines(&svg, "#FF7F0E").len() > 20, "J5 not dashed");
        // Every legend entry of the joints starts right of the plot.
        for name in ["J1", "J2", "J3", "J4", "J5 dashed"] {
            let x = text_x(&svg, name);
            assert!(!x.is_empty(), "{name} not in the legend");
            assert!(
                x.iter().all(|x| *x >= (WIDTH - LEGEND_W) as f64),
                "{name} at {x:?}"
            );
        }
    }

    /// Issue 37: the hand's opening is drawn against time.
    #[test]
    fn the_hand_opening_is_drawn() {
        let svg = svg(&square(), &rv_m1(), "square", None).unwrap();
        assert!(svg.contains("Hand opening against time"));
        let hand = polylines(&svg, "#17BECF");
        let curve = hand.iter().max_by_key(|p| p.len()).unwrap();
        // Open at 60 mm, then closing to 20 mm: the line goes down (y grows).
        assert!(curve.len() >= 6, "{curve:?}");
        assert!(curve[curve.len() - 1].1 > curve[0].1 + 20.0, "{curve:?}");
    }

    /// Issue 37: a refused goal is marked: a red line at its time, a cross
    /// at the goal (or at the view's edge towards a far one), in the legend.
    #[test]
    fn a_refused_goal_is_marked() {
        let near = Refused {
            t: 5.0,
            goal: [400.0, 0.0, 200.0],
        };
        let drawn = svg(&square(), &rv_m1(), "square", Some(near)).unwrap();
        assert!(drawn.contains("refused goal, 5.000 s"), "joints legend");
        assert!(drawn.contains("stroke=\"#C80000\""), "nothing drawn in red");
        assert!(text_x(&drawn, "refused goal").len() >= 3, "legends");
        let far = Refused {
            t: 5.0,
            goal: [5000.0, 0.0, 200.0],
        };
        let svg = svg(&square(), &rv_m1(), "square", Some(far)).unwrap();
        assert!(
            svg.contains("refused goal (5000, 0) mm, out of view"),
            "above"
        );
        // The square keeps its size: a far goal does not shrink the view.
        let above = &polylines(&svg, "#333333")[0];
        let xs: Vec<f64> = above.iter().map(|p| p.0).collect();
        let wide = xs.iter().cloned().fold(f64::MIN, f64::max)
            - xs.iter().cloned().fold(f64::MAX, f64::min);
        assert!(wide >= 180.0, "the square is {wide} pixels wide");
    }

    #[test]
    fn towards_stops_at_the_views_edge() {
        let p = towards((0.0, 0.0), (100.0, 50.0), (-10.0, 10.0), (-10.0, 10.0));
        assert!(
            (p.0 - 10.0).abs() < 1e-9 && (p.1 - 5.0).abs() < 1e-9,
            "{p:?}"
        );
        assert_eq!(
            towards((0.0, 0.0), (5.0, 5.0), (-10.0, 10.0), (-10.0, 10.0)),
            (5.0, 5.0)
        );
    }

    #[test]
    fn the_built_in_font_loads() {
        assert!(font());
    }
}
