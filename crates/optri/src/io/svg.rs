//! SVG pictures of triangulations and graphs.
//!
//! The y axis points up (data y is flipped), the drawing is scaled to fit a
//! fixed-size panel with a margin, and stroke widths and point radii are in
//! panel pixels, so pictures of tiny and huge coordinates look alike. A
//! triangulation panel highlights its longest edge (thick red, chosen exactly
//! by [`Triangulation::longest_edge`]) and shades the worst triangle of the
//! measure its criterion optimises (e.g. the largest-angle triangle of
//! `minmax-angle`; [`Triangulation::worst_triangle`]), or the triangle with
//! the smallest angle when the criterion optimises no triangle measure.
//!
//! Every edge is drawn as exactly one `<line class="edge">` and every panel
//! title as one `<text class="title" …>`, so tests can count and read them.

use crate::kernel::{metrics, Point};
use crate::structures::{Domain, Measure, Triangulation};
use std::fmt::Write;

/// Plot width of one panel, pixels.
const PLOT_WIDTH: f64 = 560.0;
/// Space above the plot for the title and two stats lines.
const HEADER: f64 = 66.0;
/// Space below the plot for the legend.
const FOOTER: f64 = 26.0;
/// Margin around the plot.
const MARGIN: f64 = 16.0;

/// What one panel shows.
struct Panel<'a> {
    title: &'a str,
    /// One or two caption lines.
    stats: Vec<String>,
    points: Vec<Point>,
    all_points: &'a [Point],
    edges: &'a [[u32; 2]],
    longest: Option<[u32; 2]>,
    /// The shaded triangle and its legend.
    worst: Option<([u32; 3], &'static str)>,
    /// A polygon domain's boundary cycle (input indices), drawn as one
    /// `<polygon class="boundary">` under the edges.
    boundary: Option<&'a [u32]>,
}

/// A number for captions: about five significant digits.
pub(crate) fn short_number(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 {
        "0".into()
    } else if (1e-3..1e6).contains(&a) {
        let decimals = (4 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{v:.decimals$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        format!("{v:.4e}")
    }
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn triangulation_stats_lines(t: &Triangulation) -> Vec<String> {
    stats_lines(t, &t.stats())
}

fn stats_lines(t: &Triangulation, s: &crate::structures::Stats) -> Vec<String> {
    vec![
        format!(
            "{} points · {} triangles · {} edges · {} hull points",
            t.point_set().len(),
            s.triangles,
            s.edges,
            s.hull_points
        ),
        format!(
            "max edge {} · total length {} · min angle {}° · area {} to {}",
            short_number(s.max_edge_length),
            short_number(s.total_edge_length),
            short_number(s.min_angle_deg),
            short_number(s.min_area),
            short_number(s.max_area)
        ),
    ]
}

/// The triangle a panel shades for a criterion optimising `measure`, and
/// its legend.
fn shaded_triangle(t: &Triangulation, measure: Option<Measure>) -> ([u32; 3], &'static str) {
    let label = |m: Measure| match m {
        Measure::MinArea => "smallest triangle",
        Measure::MaxArea => "largest triangle",
        Measure::MaxAngle => "largest-angle triangle",
        Measure::MinHeight => "smallest-height triangle",
        Measure::MaxEccentricity => "most eccentric triangle",
        Measure::MaxSlope => "steepest triangle",
        _ => "smallest-angle triangle",
    };
    measure
        .and_then(|m| Some((t.worst_triangle(m)?, label(m))))
        .unwrap_or_else(|| (t.sharpest_triangle(), "smallest-angle triangle"))
}

fn triangulation_panel<'a>(
    t: &'a Triangulation,
    edges: &'a [[u32; 2]],
    title: &'a str,
    measure: Option<Measure>,
) -> Panel<'a> {
    Panel {
        title,
        stats: triangulation_stats_lines(t),
        points: t.point_set().points().to_vec(),
        all_points: t.points(),
        edges,
        longest: Some(t.longest_edge()),
        worst: Some(shaded_triangle(t, measure)),
        boundary: match t.domain() {
            Domain::Polygon { boundary } => Some(boundary),
            _ => None,
        },
    }
}

/// Plot height for points with this bounding box, keeping the aspect ratio
/// within 1:3 either way.
fn plot_height(points: &[Point]) -> f64 {
    let (lo, hi) = bounds(points);
    let (w, h) = (hi[0] - lo[0], hi[1] - lo[1]);
    let aspect = if w > 0.0 && h > 0.0 { h / w } else { 1.0 };
    PLOT_WIDTH * aspect.clamp(1.0 / 3.0, 3.0)
}

fn bounds(points: &[Point]) -> (Point, Point) {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in points {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    if points.is_empty() {
        return ([0.0; 2], [1.0; 2]);
    }
    (lo, hi)
}

/// Draws `panel` with its top-left corner at `(x0, y0)`; the plot area is
/// `PLOT_WIDTH × plot_h`.
fn draw_panel(out: &mut String, x0: f64, y0: f64, plot_h: f64, panel: &Panel) {
    let (lo, hi) = bounds(panel.all_points);
    // Halving before subtracting keeps spans of ±2^201 coordinates finite.
    let span = [(hi[0] / 2.0 - lo[0] / 2.0), (hi[1] / 2.0 - lo[1] / 2.0)];
    let sx = if span[0] > 0.0 {
        PLOT_WIDTH / 2.0 / span[0]
    } else {
        f64::INFINITY
    };
    let sy = if span[1] > 0.0 {
        plot_h / 2.0 / span[1]
    } else {
        f64::INFINITY
    };
    let scale = if sx.min(sy).is_finite() {
        sx.min(sy)
    } else {
        1.0
    };
    let left = x0 + MARGIN + (PLOT_WIDTH - 2.0 * span[0] * scale) / 2.0;
    let top = y0 + HEADER + (plot_h - 2.0 * span[1] * scale) / 2.0;
    let map = |p: Point| -> (f64, f64) {
        (
            left + (p[0] / 2.0 - lo[0] / 2.0) * 2.0 * scale,
            top + (hi[1] / 2.0 - p[1] / 2.0) * 2.0 * scale,
        )
    };
    let n = panel.points.len().max(1) as f64;
    let edge_width = (6.0 / n.sqrt()).clamp(0.35, 1.5);
    let radius = (12.0 / n.sqrt()).clamp(0.6, 3.5);
    let total_w = PLOT_WIDTH + 2.0 * MARGIN;
    let _ = writeln!(
        out,
        r##"<g class="panel"><rect x="{x0:.2}" y="{y0:.2}" width="{total_w:.2}" height="{:.2}" fill="#ffffff" stroke="#cccccc"/>"##,
        HEADER + plot_h + FOOTER + MARGIN
    );
    let _ = writeln!(
        out,
        r#"<text class="title" x="{:.2}" y="{:.2}" font-size="16" font-weight="bold">{}</text>"#,
        x0 + MARGIN,
        y0 + 22.0,
        escape(panel.title)
    );
    for (k, line) in panel.stats.iter().enumerate() {
        let _ = writeln!(
            out,
            r##"<text x="{:.2}" y="{:.2}" font-size="11" fill="#444444">{}</text>"##,
            x0 + MARGIN,
            y0 + 40.0 + 14.0 * k as f64,
            escape(line)
        );
    }
    // The `points` attribute of a polygon through the given input indices.
    let polygon_points = |indices: &[u32]| -> String {
        let corners: Vec<String> = indices
            .iter()
            .map(|&i| {
                let (x, y) = map(panel.all_points[i as usize]);
                format!("{x:.2},{y:.2}")
            })
            .collect();
        corners.join(" ")
    };
    if let Some(boundary) = panel.boundary {
        let _ = writeln!(
            out,
            r##"<polygon class="boundary" points="{}" fill="#e8eef8" stroke="#1b2f52" stroke-width="{:.2}" stroke-linejoin="round"/>"##,
            polygon_points(boundary),
            (edge_width * 2.5).max(1.5)
        );
    }
    if let Some((tri, _)) = panel.worst {
        let _ = writeln!(
            out,
            r##"<polygon class="worst" data-triangle="{},{},{}" points="{}" fill="#f4a742" fill-opacity="0.6" stroke="#e07b00" stroke-width="{:.2}" stroke-linejoin="round"/>"##,
            tri[0],
            tri[1],
            tri[2],
            polygon_points(&tri),
            (edge_width * 2.5).max(1.5)
        );
    }
    let _ = writeln!(
        out,
        r##"<g stroke="#3b5b92" stroke-width="{edge_width:.2}" stroke-linecap="round">"##
    );
    for &[a, b] in panel.edges {
        let (x1, y1) = map(panel.all_points[a as usize]);
        let (x2, y2) = map(panel.all_points[b as usize]);
        let _ = writeln!(
            out,
            r#"<line class="edge" x1="{x1:.2}" y1="{y1:.2}" x2="{x2:.2}" y2="{y2:.2}"/>"#
        );
    }
    out.push_str("</g>\n");
    if let Some([a, b]) = panel.longest {
        let (x1, y1) = map(panel.all_points[a as usize]);
        let (x2, y2) = map(panel.all_points[b as usize]);
        let _ = writeln!(
            out,
            r##"<line class="longest" x1="{x1:.2}" y1="{y1:.2}" x2="{x2:.2}" y2="{y2:.2}" stroke="#d62728" stroke-width="{:.2}" stroke-linecap="round"/>"##,
            (edge_width * 3.0).max(2.0)
        );
    }
    let _ = writeln!(out, r##"<g fill="#111111">"##);
    for &p in &panel.points {
        let (x, y) = map(p);
        let _ = writeln!(
            out,
            r#"<circle class="point" cx="{x:.2}" cy="{y:.2}" r="{radius:.2}"/>"#
        );
    }
    out.push_str("</g>\n");
    let ly = y0 + HEADER + plot_h + MARGIN + 8.0;
    let lx = x0 + MARGIN;
    if let (Some(_), Some((_, shaded))) = (panel.longest, panel.worst) {
        let _ = writeln!(
            out,
            r##"<g class="legend" font-size="11"><line x1="{lx:.2}" y1="{ly:.2}" x2="{:.2}" y2="{ly:.2}" stroke="#d62728" stroke-width="3"/><text x="{:.2}" y="{:.2}">longest edge</text><rect x="{:.2}" y="{:.2}" width="14" height="10" fill="#f4a742" fill-opacity="0.55"/><text x="{:.2}" y="{:.2}">{shaded}</text></g>"##,
            lx + 22.0,
            lx + 28.0,
            ly + 4.0,
            lx + 120.0,
            ly - 5.0,
            lx + 140.0,
            ly + 4.0
        );
    }
    out.push_str("</g>\n");
}

fn document(width: f64, height: f64, body: &str) -> String {
    format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width:.0}\" height=\"{height:.0}\" \
         viewBox=\"0 0 {width:.2} {height:.2}\" font-family=\"sans-serif\">\n{body}</svg>\n"
    )
}

fn panel_height(plot_h: f64) -> f64 {
    HEADER + plot_h + FOOTER + MARGIN
}

/// A picture of `t`: edges, points, the longest edge and the smallest-angle
/// triangle highlighted, `title` and a stats line on top.
#[cfg(test)]
pub(crate) fn triangulation_to_svg(t: &Triangulation, title: &str) -> String {
    panels_to_svg(&[(title, t)])
}

/// The picture of a report's triangulation: as [`triangulation_to_svg`],
/// with the report's coordinates and measures (the user's units).
pub(super) fn report_to_svg(report: &super::TriangulationReport, title: &str) -> String {
    let t = report.triangulation();
    let edges = t.edges();
    let measure = report.criterion().and_then(|c| c.info().measure);
    let mut panel = triangulation_panel(t, &edges, title, measure);
    let user = report.coordinates();
    if !std::ptr::eq(user, t.points()) {
        let ps = t.point_set();
        panel.points = (0..ps.len() as u32)
            .map(|d| user[ps.input_index(d) as usize])
            .collect();
        panel.all_points = user;
        panel.stats = stats_lines(t, &report.stats());
    }
    let plot_h = plot_height(&panel.points);
    let mut body = String::new();
    draw_panel(&mut body, 0.0, 0.0, plot_h, &panel);
    document(PLOT_WIDTH + 2.0 * MARGIN, panel_height(plot_h), &body)
}

/// A picture of a plain edge set over `points` (edges are index pairs into
/// `points`), e.g. a proximity graph.
///
/// # Panics
/// If an edge refers to an index outside `points`.
pub(crate) fn graph_to_svg(points: &[Point], edges: &[[u32; 2]], title: &str) -> String {
    let total = metrics::total_length(points, edges);
    let panel = Panel {
        title,
        stats: vec![format!(
            "{} points · {} edges · total length {}",
            points.len(),
            edges.len(),
            short_number(total)
        )],
        points: points.to_vec(),
        all_points: points,
        edges,
        longest: None,
        worst: None,
        boundary: None,
    };
    let plot_h = plot_height(points);
    let mut body = String::new();
    draw_panel(&mut body, 0.0, 0.0, plot_h, &panel);
    document(PLOT_WIDTH + 2.0 * MARGIN, panel_height(plot_h), &body)
}

/// Several triangulations side by side in a grid (up to three columns), each
/// panel with its title and stats line.
pub fn panels_to_svg(panels: &[(&str, &Triangulation)]) -> String {
    let panels: Vec<_> = panels.iter().map(|&(title, t)| (title, t, None)).collect();
    criterion_panels_to_svg(&panels)
}

/// [`panels_to_svg`] with the measure each panel's criterion optimises
/// (its worst triangle is shaded).
pub(crate) fn criterion_panels_to_svg(
    panels: &[(&str, &Triangulation, Option<Measure>)],
) -> String {
    let columns = panels.len().clamp(1, 3);
    let rows = panels.len().div_ceil(columns).max(1);
    let plot_h = panels
        .iter()
        .map(|(_, t, _)| plot_height(t.points()))
        .fold(0.0, f64::max)
        .max(PLOT_WIDTH / 3.0);
    let cell_w = PLOT_WIDTH + 2.0 * MARGIN;
    let cell_h = panel_height(plot_h);
    let mut body = String::new();
    for (k, (title, t, measure)) in panels.iter().enumerate() {
        let edges = t.edges();
        let panel = triangulation_panel(t, &edges, title, *measure);
        let (col, row) = (k % columns, k / columns);
        draw_panel(
            &mut body,
            col as f64 * cell_w,
            row as f64 * cell_h,
            plot_h,
            &panel,
        );
    }
    document(cell_w * columns as f64, cell_h * rows as f64, &body)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{delaunay, PointSet};

    #[test]
    fn svg_has_one_line_per_edge_and_flips_y() {
        let ps =
            PointSet::new(&[[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0], [1.0, 1.0]]).unwrap();
        let t = delaunay(&ps).unwrap();
        let svg = triangulation_to_svg(&t, "a <test> & more");
        assert!(svg.starts_with("<svg"), "{svg}");
        assert!(svg.trim_end().ends_with("</svg>"));
        assert_eq!(svg.matches("<line class=\"edge\"").count(), t.edges().len());
        assert_eq!(svg.matches("class=\"longest\"").count(), 1);
        assert_eq!(svg.matches("<polygon class=\"worst\"").count(), 1);
        assert_eq!(svg.matches("<circle").count(), 5);
        assert!(svg.contains("a &lt;test&gt; &amp; more"));
        assert_eq!(svg.matches("<text class=\"title\"").count(), 1);
        // Point (0,0) is the bottom-left corner: larger SVG y than (0,3).
        let cy: Vec<f64> = svg
            .match_indices("cy=\"")
            .map(|(i, _)| {
                let rest = &svg[i + 4..];
                rest[..rest.find('"').unwrap()].parse().unwrap()
            })
            .collect();
        assert!(cy[0] > cy[3], "{cy:?}");
        // Start and end tags balance.
        assert_eq!(svg.matches("<g").count(), svg.matches("</g>").count());
    }

    #[test]
    fn huge_coordinates_stay_finite_and_panels_form_a_grid() {
        let big = 2f64.powi(200);
        let ps = PointSet::new(&[[-big, -big], [big, -big], [0.0, big], [0.0, 0.0]]).unwrap();
        let t = delaunay(&ps).unwrap();
        let svg = triangulation_to_svg(&t, "huge");
        assert!(!svg.contains("NaN") && !svg.contains("inf"), "{svg}");
        let svg = panels_to_svg(&[("a", &t), ("b", &t), ("c", &t), ("d", &t)]);
        assert_eq!(svg.matches("<g class=\"panel\"").count(), 4);
        assert_eq!(
            svg.matches("<line class=\"edge\"").count(),
            4 * t.edges().len()
        );
        let g = graph_to_svg(t.points(), &[[0, 1], [1, 2]], "graph");
        assert_eq!(g.matches("<line class=\"edge\"").count(), 2);
        assert!(!g.contains("class=\"longest\""));
    }

    #[test]
    fn a_polygon_triangulation_draws_its_boundary() {
        let ring = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [1.0, 1.0], [0.0, 2.0]];
        let polygon = crate::SimplePolygon::new(&ring).unwrap();
        let t = crate::triangulate(&polygon, crate::Criterion::MinMaxArea)
            .unwrap()
            .triangulation;
        let svg = triangulation_to_svg(&t, "notch");
        assert_eq!(svg.matches("<polygon class=\"boundary\"").count(), 1);
        assert_eq!(svg.matches("<line class=\"edge\"").count(), t.edges().len());
        let hull = crate::delaunay(&crate::PointSet::new(&ring).unwrap()).unwrap();
        assert!(!triangulation_to_svg(&hull, "hull").contains("class=\"boundary\""));
    }

    #[test]
    fn short_numbers() {
        assert_eq!(short_number(0.0), "0");
        assert_eq!(short_number(1234.5678), "1234.6");
        assert_eq!(short_number(0.5), "0.5");
        assert_eq!(short_number(2.0), "2");
        assert_eq!(short_number(1e9), "1.0000e9");
    }
}
