//! `--plot FILE.svg`: a picture of a run, from the samples `--record` keeps
//! (tools.md): the joints against time, and the TCP path seen from above
//! and from the side, with the arm's reach drawn. Drawn with plotters'
//! SVG backend; plotters measures text with a font, so one is built in
//! (`assets/fonts`, DejaVu Sans, free licence beside it): a fresh machine
//! needs no system fonts. The SVG names the family `sans-serif`, which the
//! viewer renders with its own fonts.

use crate::kinematics::{RobotDescription, deg};
use crate::services::record::Sample;
use plotters::prelude::*;

const WIDTH: u32 = 1000;
const HEIGHT: u32 = 780;
/// One colour per joint, J1 to J5.
const COLORS: [RGBColor; 5] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
];
const PATH: RGBColor = RGBColor(51, 51, 51);
const REACH: RGBColor = RGBColor(150, 150, 150);
const FLOOR: RGBColor = RGBColor(140, 86, 75);

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

/// Points of a circle of radius `r` about `c`.
fn circle(c: (f64, f64), r: f64) -> Vec<(f64, f64)> {
    (0..=180)
        .map(|i| {
            let a = i as f64 * std::f64::consts::TAU / 180.0;
            (c.0 + r * a.cos(), c.1 + r * a.sin())
        })
        .collect()
}

type Area<'a> = DrawingArea<SVGBackend<'a>, plotters::coord::Shift>;

fn err(e: impl std::fmt::Display) -> String {
    format!("cannot draw the plot: {e}")
}

/// The SVG of a run on `robot`: three panels, or a note when nothing moved.
pub fn svg(samples: &[Sample], robot: &RobotDescription, title: &str) -> Result<String, String> {
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
            root.present().map_err(err)?;
        } else {
            let (top, bottom) = root.split_vertically(360);
            let (above, side) = bottom.split_horizontally(500);
            joints_panel(&top, samples)?;
            let links = robot.links();
            // The farthest the TCP gets from the shoulder (arm stretched).
            let reach = links.l2 + links.l3 + links.l4 + links.tool;
            above_panel(&above, samples, reach)?;
            side_panel(&side, samples, reach, links.l1)?;
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

/// A panel with its caption, axes and grid.
fn panel<'a, 'b>(
    area: &'a Area<'b>,
    caption: &str,
    xr: (f64, f64),
    yr: (f64, f64),
    (xdesc, ydesc): (&str, &str),
) -> Result<Chart<'a, 'b>, String> {
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 16))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(55)
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
        Some("svg") => svg(samples, st.kin.description(), title)?,
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

fn joints_panel(area: &Area<'_>, samples: &[Sample]) -> Result<(), String> {
    let t_end = samples.last().map_or(0.0, |s| s.t).max(1e-3);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for s in samples {
        for q in s.joints.iter() {
            lo = lo.min(deg(*q));
            hi = hi.max(deg(*q));
        }
    }
    let pad = ((hi - lo) * 0.08).max(5.0);
    let mut chart = panel(
        area,
        "Joints against time",
        (0.0, t_end),
        (lo - pad, hi + pad),
        ("virtual time (s)", "joint angle (deg)"),
    )?;
    for (j, color) in COLORS.iter().enumerate() {
        chart
            .draw_series(LineSeries::new(
                samples.iter().map(|s| (s.t, deg(s.joints[j]))),
                color.stroke_width(2),
            ))
            .map_err(err)?
            .label(format!("J{}", j + 1))
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(3))
            });
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(err)?;
    Ok(())
}

/// Start (green circle) and end (red square) of a path.
fn ends(chart: &mut Chart<'_, '_>, first: (f64, f64), last: (f64, f64)) -> Result<(), String> {
    chart
        .draw_series(std::iter::once(Circle::new(first, 6, GREEN.filled())))
        .map_err(|_| "cannot draw the start".to_string())?;
    chart
        .draw_series(std::iter::once(
            EmptyElement::at(last) + Rectangle::new([(-5, -5), (5, 5)], RED.filled()),
        ))
        .map_err(|_| "cannot draw the end".to_string())?;
    Ok(())
}

fn above_panel(area: &Area<'_>, samples: &[Sample], reach: f64) -> Result<(), String> {
    let r = reach * 1.05;
    let xs = samples.iter().map(|s| s.tcp[0]);
    let ys = samples.iter().map(|s| s.tcp[1]);
    let (xr, yr) = equal_aspect(
        (xs.clone().fold(-r, f64::min), xs.fold(r, f64::max)),
        (ys.clone().fold(-r, f64::min), ys.fold(r, f64::max)),
        420.0,
        330.0,
    );
    let mut chart = panel(area, "TCP path from above", xr, yr, ("x (mm)", "y (mm)"))?;
    chart
        .draw_series(std::iter::once(PathElement::new(
            circle((0.0, 0.0), reach),
            REACH.stroke_width(1),
        )))
        .map_err(err)?
        .label("reach");
    let path: Vec<(f64, f64)> = samples.iter().map(|s| (s.tcp[0], s.tcp[1])).collect();
    chart
        .draw_series(LineSeries::new(path.clone(), PATH.stroke_width(2)))
        .map_err(err)?;
    ends(&mut chart, path[0], path[path.len() - 1])
}

fn side_panel(
    area: &Area<'_>,
    samples: &[Sample],
    reach: f64,
    shoulder: f64,
) -> Result<(), String> {
    let r = reach * 1.05;
    let rz: Vec<(f64, f64)> = samples
        .iter()
        .map(|s| (s.tcp[0].hypot(s.tcp[1]), s.tcp[2]))
        .collect();
    let (xr, yr) = equal_aspect(
        (
            rz.iter().map(|p| p.0).fold(-0.2 * reach, f64::min),
            rz.iter().map(|p| p.0).fold(r, f64::max),
        ),
        (
            rz.iter().map(|p| p.1).fold(shoulder - r, f64::min),
            rz.iter().map(|p| p.1).fold(shoulder + r, f64::max),
        ),
        420.0,
        330.0,
    );
    let mut chart = panel(
        area,
        "TCP path from the side",
        xr,
        yr,
        ("distance from the waist axis (mm)", "z (mm)"),
    )?;
    chart
        .draw_series(std::iter::once(PathElement::new(
            circle((0.0, shoulder), reach),
            REACH.stroke_width(1),
        )))
        .map_err(err)?;
    chart
        .draw_series(std::iter::once(PathElement::new(
            vec![(xr.0, 0.0), (xr.1, 0.0)],
            FLOOR.stroke_width(2),
        )))
        .map_err(err)?;
    chart
        .draw_series(LineSeries::new(rz.clone(), PATH.stroke_width(2)))
        .map_err(err)?;
    ends(&mut chart, rz[0], rz[rz.len() - 1])
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

    #[test]
    fn the_built_in_font_loads() {
        assert!(font());
    }
}
