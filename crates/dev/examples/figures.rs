//! Writes the specification's figures, computed from the crate's own functions, as PNG and SVG
//! files into a folder (default `target/figures`).
//!
//! Run: `cargo run --release --example figures -- [DIR]` (from the workspace's root; the example
//! belongs to the dev-only member `crates/dev`, whose dependencies draw the figures)
//!
//! Pure Rust: plotters draws the bitmaps and the SVG files; text uses DejaVu Sans (Bitstream
//! Vera licence) embedded by the `dejavu` crate, so no system font library is needed.
//!
//! * `fig1_shapes`: the ellipse a = 1, b = 2, the same moved by C = (1, 2) and rotated by 0.5,
//!   the regular heptagon with rounded corners, and shape1 of Appendix A with its pieces coloured.
//! * `fig2_transform`: the pair of the specification in the world, translated so that object2
//!   is at the origin, and rotated into object2's local space.
//! * `fig3_distances`: distanceEuclidean, −distanceFwd and distanceSide of that pair over φ, with
//!   the global extremum found by `stationary_distance`.
//! * `fig4_moving`: a moving version of that pair: the shapes at several times, and
//!   distanceSide(φ, t), distanceFwd(φ, t) with the zero level of distanceSide and the path
//!   tracked by `time_of_impact_traced`.
//! * `fig5_appendix_c`: distanceEuclidean over φ for ellipse pairs of axis ratios 1:5, 1:15 and
//!   1:100, with the basin of the global minimum shaded, against eq. 1's parameter and against the
//!   crate's normal angle.
//! * `fig6_appendix_d`: the heptagon spinning at 30 rad/s against an ellipse: the shapes up to the
//!   impact and distanceSide(φ, t) with the tracked path.

#[path = "../../../examples/common/mod.rs"]
mod common;

use common::appendix_d;
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::NonlinearRigidMotion;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use smooth_ccd2d::method::{eval_pair, PairFrame};
use smooth_ccd2d::{
    stationary_distance, time_of_impact_traced, CapsuleEllipse, ConvexCurve, DistanceOptions, Ellipse, RoundedPolygon,
    ToiOptions, ToiStatus, TraceEvent,
};
use std::error::Error;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};

type Res<T = ()> = Result<T, Box<dyn Error>>;
type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

const FONT: &str = "sans-serif";
const OBJ1: RGBColor = RGBColor(31, 119, 180);
const OBJ2: RGBColor = RGBColor(214, 39, 40);
const GREEN: RGBColor = RGBColor(44, 160, 44);
const ORANGE: RGBColor = RGBColor(255, 127, 14);
const PURPLE: RGBColor = RGBColor(148, 103, 189);
const GREY: RGBColor = RGBColor(120, 120, 120);
const PATH: RGBColor = RGBColor(0, 200, 0);
const GOLD: RGBColor = RGBColor(255, 215, 0);

fn main() {
    let dir = std::env::args_os()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("target/figures"));
    let start = std::time::Instant::now();
    match write_all(&dir) {
        Ok(files) => {
            for f in &files {
                let len = std::fs::metadata(f).map(|m| m.len()).unwrap_or(0);
                println!("{:>10} bytes  {}", len, f.display());
            }
            println!("{} files in {:.2} s", files.len(), start.elapsed().as_secs_f64());
        }
        Err(e) => {
            eprintln!("figures: {e}");
            std::process::exit(1);
        }
    }
}

/// Writes every figure as `<name>.png` and `<name>.svg` into `dir` (created if missing) and
/// returns the paths written.
pub fn write_all(dir: &Path) -> Res<Vec<PathBuf>> {
    register_font()?;
    std::fs::create_dir_all(dir)?;
    let mut out = Vec::new();
    emit(dir, &Fig1, &mut out)?;
    emit(dir, &Fig2::new()?, &mut out)?;
    emit(dir, &Fig3::new()?, &mut out)?;
    emit(dir, &Fig4::new()?, &mut out)?;
    emit(dir, &Fig5::new()?, &mut out)?;
    emit(dir, &Fig6::new()?, &mut out)?;
    Ok(out)
}

fn register_font() -> Res {
    static ONCE: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    let ok = *ONCE.get_or_init(|| {
        plotters::style::register_font(FONT, FontStyle::Normal, dejavu::sans::regular()).is_ok()
            && plotters::style::register_font(FONT, FontStyle::Bold, dejavu::sans::bold()).is_ok()
    });
    if ok {
        Ok(())
    } else {
        Err("could not load the embedded DejaVu Sans font".into())
    }
}

/// A figure: data computed once, drawn on any backend.
trait Figure {
    fn name(&self) -> &'static str;
    fn size(&self) -> (u32, u32);
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Res
    where
        DB::ErrorType: 'static;
}

fn emit<F: Figure>(dir: &Path, fig: &F, out: &mut Vec<PathBuf>) -> Res {
    let png = dir.join(format!("{}.png", fig.name()));
    {
        let root = BitMapBackend::new(&png, fig.size()).into_drawing_area();
        root.fill(&WHITE)?;
        fig.draw(&root)?;
        root.present()?;
    }
    out.push(png);
    let svg = dir.join(format!("{}.svg", fig.name()));
    {
        let root = SVGBackend::new(&svg, fig.size()).into_drawing_area();
        root.fill(&WHITE)?;
        fig.draw(&root)?;
        root.present()?;
    }
    out.push(svg);
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Geometry helpers

fn v(x: f64, y: f64) -> Vector {
    Vector::new(x, y)
}

fn xy(p: Vector) -> (f64, f64) {
    (p.x, p.y)
}

/// The closed outline of `c` placed at `pose`, sampled uniformly in φ plus the piece ends.
fn outline(c: &dyn ConvexCurve, pose: &Pose, n: usize) -> Vec<(f64, f64)> {
    let mut phis: Vec<f64> = (0..n).map(|i| -PI + 2.0 * PI * i as f64 / n as f64).collect();
    phis.extend_from_slice(c.breakpoints());
    phis.sort_by(f64::total_cmp);
    let mut pts: Vec<(f64, f64)> = phis.iter().map(|&p| xy(*pose * c.eval(p).point)).collect();
    pts.push(pts[0]);
    pts
}

/// The parts of a polyline inside the chart's visible range (plotters would clamp the rest
/// onto the border).
fn draw_clipped<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, pts: &[(f64, f64)], style: ShapeStyle) -> Res
where
    DB::ErrorType: 'static,
{
    let (xr, yr) = (chart.plotting_area().get_x_range(), chart.plotting_area().get_y_range());
    let inside = |p: &(f64, f64)| xr.contains(&p.0) && yr.contains(&p.1);
    let mut parts: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut cur = Vec::new();
    for p in pts {
        if inside(p) {
            cur.push(*p);
        } else if !cur.is_empty() {
            parts.push(std::mem::take(&mut cur));
        }
    }
    parts.push(cur);
    chart.draw_series(
        parts
            .into_iter()
            .filter(|p| p.len() > 1)
            .map(|p| PathElement::new(p, style)),
    )?;
    Ok(())
}

/// Splits a polyline in φ where it wraps from ±π to ∓π.
fn split_wrap(pts: &[(f64, f64)]) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut cur: Vec<(f64, f64)> = Vec::new();
    for &p in pts {
        if let Some(&q) = cur.last() {
            if (p.0 - q.0).abs() > PI {
                out.push(std::mem::take(&mut cur));
            }
        }
        cur.push(p);
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

// ---------------------------------------------------------------------------------------------
// Drawing helpers

/// A chart with equal scales on both axes that contains the box `[x0, x1] × [y0, y1]`.
fn world_chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    title: &str,
    (x0, x1): (f64, f64),
    (y0, y1): (f64, f64),
) -> Res<Chart<'a, DB>>
where
    DB::ErrorType: 'static,
{
    let (margin, xl, yl, cap) = (12u32, 30u32, 40u32, 30u32);
    let (w, h) = area.dim_in_pixel();
    let pw = w.saturating_sub(2 * margin + yl).max(10) as f64;
    let ph = h.saturating_sub(2 * margin + xl + cap).max(10) as f64;
    let scale = ((x1 - x0) / pw).max((y1 - y0) / ph);
    let (cx, cy) = (0.5 * (x0 + x1), 0.5 * (y0 + y1));
    let (hx, hy) = (0.5 * pw * scale, 0.5 * ph * scale);
    let mut chart = ChartBuilder::on(area)
        .margin(margin)
        .caption(title, (FONT, 20))
        .x_label_area_size(xl)
        .y_label_area_size(yl)
        .build_cartesian_2d(cx - hx..cx + hx, cy - hy..cy + hy)?;
    chart
        .configure_mesh()
        .light_line_style(WHITE.mix(0.0))
        .bold_line_style(BLACK.mix(0.08))
        .label_style((FONT, 13))
        .draw()?;
    Ok(chart)
}

/// A chart over `x` × `y` with axis descriptions.
fn plot_chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    title: &str,
    x: (f64, f64),
    y: (f64, f64),
    xdesc: &str,
    ydesc: &str,
) -> Res<Chart<'a, DB>>
where
    DB::ErrorType: 'static,
{
    let mut chart = ChartBuilder::on(area)
        .margin(12)
        .caption(title, (FONT, 20))
        .x_label_area_size(42)
        .y_label_area_size(52)
        .build_cartesian_2d(x.0..x.1, y.0..y.1)?;
    chart
        .configure_mesh()
        .light_line_style(WHITE.mix(0.0))
        .bold_line_style(BLACK.mix(0.08))
        .label_style((FONT, 13))
        .axis_desc_style((FONT, 15))
        .x_desc(xdesc)
        .y_desc(ydesc)
        .draw()?;
    Ok(chart)
}

fn draw_outline<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, pts: Vec<(f64, f64)>, style: ShapeStyle) -> Res
where
    DB::ErrorType: 'static,
{
    chart.draw_series(std::iter::once(PathElement::new(pts, style)))?;
    Ok(())
}

fn draw_dashed<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, pts: Vec<(f64, f64)>, style: ShapeStyle) -> Res
where
    DB::ErrorType: 'static,
{
    chart.draw_series(DashedLineSeries::new(pts, 6, 4, style))?;
    Ok(())
}

fn marker<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, p: (f64, f64), color: RGBColor) -> Res
where
    DB::ErrorType: 'static,
{
    chart.draw_series(std::iter::once(Cross::new(p, 5, color.stroke_width(2))))?;
    Ok(())
}

fn legend<'a, DB: DrawingBackend + 'a>(chart: &mut Chart<'a, DB>, pos: SeriesLabelPosition) -> Res
where
    DB::ErrorType: 'static,
{
    chart
        .configure_series_labels()
        .position(pos)
        .label_font((FONT, 14))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.4))
        .draw()?;
    Ok(())
}

fn line_legend(c: RGBColor) -> impl Fn((i32, i32)) -> PathElement<(i32, i32)> {
    move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
}

/// Diverging colour map on [−1, 1]: blue, white, red.
fn diverging(s: f64) -> RGBColor {
    const STOPS: [(f64, [f64; 3]); 5] = [
        (-1.0, [5.0, 48.0, 97.0]),
        (-0.5, [67.0, 147.0, 195.0]),
        (0.0, [247.0, 247.0, 247.0]),
        (0.5, [214.0, 96.0, 77.0]),
        (1.0, [103.0, 0.0, 31.0]),
    ];
    let s = s.clamp(-1.0, 1.0);
    let k = STOPS.iter().position(|st| st.0 >= s).unwrap_or(4).clamp(1, 4);
    let (a, b) = (STOPS[k - 1], STOPS[k]);
    let u = (s - a.0) / (b.0 - a.0);
    let c = |i: usize| (a.1[i] + u * (b.1[i] - a.1[i])).round() as u8;
    RGBColor(c(0), c(1), c(2))
}

const LEVELS: i32 = 16;

fn level(value: f64, vmax: f64) -> i32 {
    if !value.is_finite() {
        return i32::MIN;
    }
    ((value / vmax).clamp(-1.0, 1.0) * LEVELS as f64).round() as i32
}

/// A function of (φ, t) sampled on a regular grid.
struct Grid {
    x: (f64, f64),
    y: (f64, f64),
    nx: usize,
    ny: usize,
    /// Row-major: value at (x_i, y_j) is `vals[j * nx + i]`.
    vals: Vec<f64>,
}

impl Grid {
    fn xi(&self, i: usize) -> f64 {
        self.x.0 + (self.x.1 - self.x.0) * i as f64 / (self.nx - 1) as f64
    }
    fn yj(&self, j: usize) -> f64 {
        self.y.0 + (self.y.1 - self.y.0) * j as f64 / (self.ny - 1) as f64
    }
    fn at(&self, i: usize, j: usize) -> f64 {
        self.vals[j * self.nx + i]
    }

    /// A colour scale: the 97th percentile of |value|.
    fn scale(&self) -> f64 {
        let mut a: Vec<f64> = self.vals.iter().filter(|v| v.is_finite()).map(|v| v.abs()).collect();
        a.sort_by(f64::total_cmp);
        a.get((a.len() as f64 * 0.97) as usize)
            .copied()
            .unwrap_or(1.0)
            .max(1e-12)
    }

    /// The zero level by marching squares, as segments.
    fn zero_level(&self) -> Vec<[(f64, f64); 2]> {
        let mut segs = Vec::new();
        for j in 0..self.ny - 1 {
            for i in 0..self.nx - 1 {
                let c = [
                    (self.xi(i), self.yj(j), self.at(i, j)),
                    (self.xi(i + 1), self.yj(j), self.at(i + 1, j)),
                    (self.xi(i + 1), self.yj(j + 1), self.at(i + 1, j + 1)),
                    (self.xi(i), self.yj(j + 1), self.at(i, j + 1)),
                ];
                if c.iter().any(|p| !p.2.is_finite()) {
                    continue;
                }
                let mut cross = Vec::with_capacity(4);
                for k in 0..4 {
                    let (a, b) = (c[k], c[(k + 1) % 4]);
                    if (a.2 < 0.0) != (b.2 < 0.0) {
                        let u = a.2 / (a.2 - b.2);
                        cross.push((a.0 + u * (b.0 - a.0), a.1 + u * (b.1 - a.1)));
                    }
                }
                match cross.len() {
                    2 => segs.push([cross[0], cross[1]]),
                    4 => {
                        segs.push([cross[0], cross[1]]);
                        segs.push([cross[2], cross[3]]);
                    }
                    _ => {}
                }
            }
        }
        segs
    }
}

/// Samples distanceSide and distanceFwd of object1 moving by `m1` against object2 moving by `m2`
/// over φ ∈ [−π, π] and `t`.
fn side_fwd_grids(
    o1: &dyn ConvexCurve,
    o2: &dyn ConvexCurve,
    m1: &NonlinearRigidMotion,
    m2: &NonlinearRigidMotion,
    t: (f64, f64),
    (nx, ny): (usize, usize),
) -> (Grid, Grid) {
    let mut side = Grid {
        x: (-PI, PI),
        y: t,
        nx,
        ny,
        vals: Vec::with_capacity(nx * ny),
    };
    let mut fwd = Grid {
        vals: Vec::with_capacity(nx * ny),
        ..side
    };
    for j in 0..ny {
        let fr = PairFrame::at_time(m1, m2, side.yj(j));
        for i in 0..nx {
            match eval_pair(o1, o2, &fr, side.xi(i)) {
                Some(jet) => {
                    side.vals.push(jet.side.v);
                    fwd.vals.push(jet.fwd.v);
                }
                None => {
                    side.vals.push(f64::NAN);
                    fwd.vals.push(f64::NAN);
                }
            }
        }
    }
    (side, fwd)
}

/// A panel of `area`: `grid` over φ ∈ [−π, π] and its t range as a heat map with the zero level
/// of `zero`, the tracked path `trace` (and the legend, when `labels`), and a colour bar.
fn heat_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    x_desc: &str,
    grid: &Grid,
    zero: &Grid,
    trace: &[TraceEvent],
    labels: bool,
) -> Res
where
    DB::ErrorType: 'static,
{
    let (plot, bar) = area.split_horizontally(area.dim_in_pixel().0 - 70);
    let vmax = grid.scale();
    let mut c = plot_chart(&plot, title, (-PI, PI), grid.y, x_desc, "t")?;
    draw_heat(&mut c, grid, vmax, zero)?;
    draw_trace(&mut c, trace, labels)?;
    if labels {
        legend(&mut c, SeriesLabelPosition::UpperLeft)?;
    }
    colorbar(&bar, vmax, 40, 54)
}

/// The title of a figure of a moving pair: `on_hit(t)` for an impact at t, else the status.
fn impact_title(hit: &smooth_ccd2d::TimeOfImpact, on_hit: impl FnOnce(f64) -> String) -> String {
    if hit.status == ToiStatus::Hit {
        on_hit(hit.time)
    } else {
        format!("no impact ({:?})", hit.status)
    }
}

/// Draws the grid as cells (runs of equal colour merged) and the zero level of `zero`.
fn draw_heat<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, g: &Grid, vmax: f64, zero: &Grid) -> Res
where
    DB::ErrorType: 'static,
{
    let dx = (g.x.1 - g.x.0) / (g.nx - 1) as f64;
    let dy = (g.y.1 - g.y.0) / (g.ny - 1) as f64;
    let mut rects = Vec::new();
    for j in 0..g.ny {
        let mut i = 0;
        while i < g.nx {
            let l = level(g.at(i, j), vmax);
            let mut k = i + 1;
            while k < g.nx && level(g.at(k, j), vmax) == l {
                k += 1;
            }
            let color = if l == i32::MIN {
                RGBColor(0, 0, 0)
            } else {
                diverging(l as f64 / LEVELS as f64)
            };
            // Each cell reaches half a cell into the next run and row, which are drawn later and cover
            // it: no seams between rounded pixel edges.
            let (x0, x1) = ((g.xi(i) - 0.5 * dx).max(g.x.0), (g.xi(k - 1) + dx).min(g.x.1));
            let (y0, y1) = ((g.yj(j) - 0.5 * dy).max(g.y.0), (g.yj(j) + dy).min(g.y.1));
            rects.push(Rectangle::new([(x0, y0), (x1, y1)], color.filled()));
            i = k;
        }
    }
    chart.draw_series(rects)?;
    let segs = zero.zero_level();
    chart
        .draw_series(
            segs.into_iter()
                .map(|s| PathElement::new(vec![s[0], s[1]], BLACK.mix(0.75).stroke_width(1))),
        )?
        .label("distanceSide = 0")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(1)));
    Ok(())
}

/// A vertical colour bar for [−vmax, vmax].
fn colorbar<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, vmax: f64, top: u32, bottom: u32) -> Res
where
    DB::ErrorType: 'static,
{
    let area = area.margin(top, bottom, 4, 4);
    let mut chart = ChartBuilder::on(&area)
        .y_label_area_size(0)
        .right_y_label_area_size(48)
        .build_cartesian_2d(0.0..1.0, -vmax..vmax)?
        .set_secondary_coord(0.0..1.0, -vmax..vmax);
    chart.draw_series((-LEVELS..=LEVELS).map(|l| {
        let (a, b) = ((l as f64 - 0.5) / LEVELS as f64, (l as f64 + 0.5) / LEVELS as f64);
        let (a, b) = (a.max(-1.0) * vmax, b.min(1.0) * vmax);
        Rectangle::new([(0.0, a), (1.0, b)], diverging(l as f64 / LEVELS as f64).filled())
    }))?;
    chart
        .configure_secondary_axes()
        .label_style((FONT, 12))
        .y_labels(7)
        .y_label_formatter(&|v| format!("{v:.2}"))
        .draw()?;
    Ok(())
}

/// The path of `time_of_impact_traced` over a (φ, t) chart.
fn draw_trace<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, trace: &[TraceEvent], with_labels: bool) -> Res
where
    DB::ErrorType: 'static,
{
    let (n_pred, n_corr, n_back) = trace_counts(trace);
    let mut accepted = Vec::new();
    let mut predicted = Vec::new();
    let mut corrected = Vec::new();
    let mut corrections = Vec::new();
    let mut backtracks = Vec::new();
    let mut impact = None;
    let mut last: Option<(f64, f64)> = None;
    for e in trace {
        match e.wrapped() {
            TraceEvent::Start { phi, t, .. } | TraceEvent::Accept { phi, t, .. } => {
                accepted.push((phi, t));
                last = Some((phi, t));
            }
            TraceEvent::Predict { phi, t } => {
                predicted.push((phi, t));
                last = Some((phi, t));
            }
            TraceEvent::Correct { phi, t, .. } => {
                if let Some(p) = last {
                    if (p.0 - phi).abs() < PI {
                        corrections.push(vec![p, (phi, t)]);
                    }
                }
                corrected.push((phi, t));
                last = Some((phi, t));
            }
            TraceEvent::Backtrack { phi, t } => {
                backtracks.push((phi, t));
                last = None;
            }
            TraceEvent::Impact { phi, t } => {
                accepted.push((phi, t));
                impact = Some((phi, t));
            }
        }
    }
    let mut first = true;
    for seg in split_wrap(&accepted) {
        let s = chart.draw_series(std::iter::once(PathElement::new(seg, PATH.stroke_width(3))))?;
        if first && with_labels {
            s.label("accepted steps").legend(line_legend(PATH));
        }
        first = false;
    }
    let s = chart.draw_series(
        corrections
            .into_iter()
            .map(|c| PathElement::new(c, ORANGE.stroke_width(2))),
    )?;
    if with_labels {
        s.label(format!("{n_corr} corrections (Halley, fixed t)"))
            .legend(line_legend(ORANGE));
    }
    let s = chart.draw_series(predicted.iter().map(|&p| Circle::new(p, 4, PURPLE.stroke_width(2))))?;
    if with_labels {
        s.label(format!("{n_pred} predictor steps"))
            .legend(|(x, y)| Circle::new((x + 10, y), 4, PURPLE.stroke_width(2)));
    }
    chart.draw_series(corrected.iter().map(|&p| Circle::new(p, 2, ORANGE.filled())))?;
    let s = chart.draw_series(backtracks.iter().map(|&p| Cross::new(p, 6, BLACK.stroke_width(2))))?;
    if with_labels {
        s.label(format!("{n_back} backtracks (rejected points)"))
            .legend(|(x, y)| Cross::new((x + 10, y), 6, BLACK.stroke_width(2)));
    }
    if let Some(p) = impact {
        let s = chart.draw_series([
            Circle::new(p, 8, GOLD.filled()),
            Circle::new(p, 8, BLACK.stroke_width(2)),
        ])?;
        if with_labels {
            s.label("impact")
                .legend(|(x, y)| Circle::new((x + 10, y), 6, GOLD.filled()));
        }
    }
    Ok(())
}

trait Wrapped {
    fn wrapped(&self) -> TraceEvent;
}

impl Wrapped for TraceEvent {
    /// The event with φ wrapped into [−π, π) (the tracker lets φ run past ±π).
    fn wrapped(&self) -> TraceEvent {
        let w = smooth_ccd2d::method::wrap_phi;
        match *self {
            TraceEvent::Start { phi, t, distance } => TraceEvent::Start {
                phi: w(phi),
                t,
                distance,
            },
            TraceEvent::Predict { phi, t } => TraceEvent::Predict { phi: w(phi), t },
            TraceEvent::Correct { phi, t, side } => TraceEvent::Correct { phi: w(phi), t, side },
            TraceEvent::Backtrack { phi, t } => TraceEvent::Backtrack { phi: w(phi), t },
            TraceEvent::Accept { phi, t, distance } => TraceEvent::Accept {
                phi: w(phi),
                t,
                distance,
            },
            TraceEvent::Impact { phi, t } => TraceEvent::Impact { phi: w(phi), t },
        }
    }
}

/// Counts of the trace's events: (predictor steps, corrections, backtracks).
fn trace_counts(trace: &[TraceEvent]) -> (usize, usize, usize) {
    let mut c = (0, 0, 0);
    for e in trace {
        match e {
            TraceEvent::Predict { .. } => c.0 += 1,
            TraceEvent::Correct { .. } => c.1 += 1,
            TraceEvent::Backtrack { .. } => c.2 += 1,
            _ => {}
        }
    }
    c
}

// ---------------------------------------------------------------------------------------------
// Figure 1: shapes

struct Fig1;

impl Figure for Fig1 {
    fn name(&self) -> &'static str {
        "fig1_shapes"
    }
    fn size(&self) -> (u32, u32) {
        (1000, 1000)
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Res
    where
        DB::ErrorType: 'static,
    {
        let panels = root.split_evenly((2, 2));
        let e = Ellipse::new(1.0, 2.0);
        let id = Pose::IDENTITY;
        let moved = Pose::new(v(1.0, 2.0), 0.5);

        let mut c = world_chart(&panels[0], "Ellipse a = 1, b = 2 (eq. 1)", (-2.3, 2.3), (-2.3, 2.3))?;
        draw_outline(&mut c, outline(&e, &id, 400), OBJ1.stroke_width(2))?;
        marker(&mut c, (0.0, 0.0), OBJ1)?;

        let mut c = world_chart(
            &panels[1],
            "Translated by C = (1, 2), rotated by 0.5",
            (-1.8, 3.8),
            (-2.2, 4.6),
        )?;
        draw_dashed(&mut c, outline(&e, &id, 400), GREY.stroke_width(1))?;
        draw_outline(&mut c, outline(&e, &moved, 400), OBJ1.stroke_width(2))?;
        marker(&mut c, (1.0, 2.0), OBJ1)?;
        let ax = moved.rotation * v(1.0, 0.0);
        c.draw_series(std::iter::once(PathElement::new(
            vec![(1.0, 2.0), (1.0 + ax.x, 2.0 + ax.y)],
            OBJ1.stroke_width(1),
        )))?;

        let hept = RoundedPolygon::regular(7, 1.0, 0.15);
        let mut c = world_chart(
            &panels[2],
            "RoundedPolygon::regular(7, 1.0, 0.15)",
            (-1.3, 1.3),
            (-1.3, 1.3),
        )?;
        let core: Vec<(f64, f64)> = hept
            .vertices()
            .iter()
            .chain(hept.vertices().first())
            .map(|p| xy(*p))
            .collect();
        draw_dashed(&mut c, core, GREY.stroke_width(1))?;
        draw_outline(&mut c, outline(&hept, &id, 700), OBJ1.stroke_width(2))?;

        let shape1 = CapsuleEllipse::new(0.5, 1.0, 0.8);
        let mut c = world_chart(
            &panels[3],
            "Shape1 of Appendix A (r1 = 0.5, r2 = 1, r3 = 0.8)",
            (-1.0, 2.6),
            (-1.6, 1.6),
        )?;
        let colors = [OBJ1, ORANGE, GREEN];
        let names = [
            "half-ellipse |φ| > π/2",
            "arcs, atan(r2/r1) ≤ |φ| ≤ π/2",
            "segment |φ| < atan(r2/r1)",
        ];
        let mut labelled = [false; 3];
        let n = 900;
        let mut run: Vec<(f64, f64)> = Vec::new();
        let mut run_piece = shape1.piece_index(-PI);
        let mut phis: Vec<f64> = (0..=n).map(|i| -PI + 2.0 * PI * i as f64 / n as f64).collect();
        phis.extend_from_slice(shape1.breakpoints());
        phis.sort_by(f64::total_cmp);
        for &phi in &phis {
            let piece = shape1.piece_index(phi);
            let p = xy(shape1.eval(phi).point);
            if piece != run_piece {
                // Close the run at the piece end so the pieces join.
                run.push(p);
                let s = c.draw_series(std::iter::once(PathElement::new(
                    std::mem::take(&mut run),
                    colors[run_piece].stroke_width(3),
                )))?;
                if !labelled[run_piece] {
                    s.label(names[run_piece]).legend(line_legend(colors[run_piece]));
                    labelled[run_piece] = true;
                }
                run_piece = piece;
            }
            run.push(p);
        }
        c.draw_series(std::iter::once(PathElement::new(
            run,
            colors[run_piece].stroke_width(3),
        )))?;
        c.draw_series(
            shape1
                .breakpoints()
                .iter()
                .map(|&b| Circle::new(xy(shape1.eval(b).point), 4, BLACK.filled())),
        )?;
        legend(&mut c, SeriesLabelPosition::UpperRight)?;
        Ok(())
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 2: coordinate transformation

/// The specification's stationary pair.
fn spec_pair() -> (Ellipse, Pose, Ellipse, Pose) {
    (
        Ellipse::new(0.5, 0.8),
        Pose::new(v(-1.5, 0.0), 0.3),
        Ellipse::new(0.5, 2.0),
        Pose::new(v(1.0, 0.5), 1.0),
    )
}

struct Fig2 {
    witness: smooth_ccd2d::StationaryDistance,
}

impl Fig2 {
    fn new() -> Res<Self> {
        let (e1, p1, e2, p2) = spec_pair();
        let witness = stationary_distance(&e1, &e2, &p1.inv_mul(&p2), &DistanceOptions::default())?;
        Ok(Self { witness })
    }
}

impl Figure for Fig2 {
    fn name(&self) -> &'static str {
        "fig2_transform"
    }
    fn size(&self) -> (u32, u32) {
        (1500, 560)
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Res
    where
        DB::ErrorType: 'static,
    {
        let (e1, p1, e2, p2) = spec_pair();
        let panels = root.split_evenly((1, 3));
        let range = ((-3.2, 3.2), (-2.6, 2.6));
        // Poses of both objects in the three panels.
        let shift = Pose::new(-p2.translation, 0.0);
        let frame = PairFrame::from_pos12(&p1.inv_mul(&p2));
        let local1 = frame.pos12().inverse();
        let poses = [
            (p1, p2, "World"),
            (shift * p1, shift * p2, "Translated by −C2: object2 at the origin"),
            (local1, Pose::IDENTITY, "Rotated by −1: object2 local space"),
        ];
        for (k, (q1, q2, title)) in poses.iter().enumerate() {
            let mut c = world_chart(&panels[k], title, range.0, range.1)?;
            c.draw_series(std::iter::once(PathElement::new(
                outline(&e1, q1, 400),
                OBJ1.stroke_width(2),
            )))?
            .label("object1 (a1 = 0.5, b1 = 0.8)")
            .legend(line_legend(OBJ1));
            c.draw_series(DashedLineSeries::new(outline(&e2, q2, 400), 6, 4, OBJ2.stroke_width(2)))?
                .label("object2 (a2 = 0.5, b2 = 2)")
                .legend(line_legend(OBJ2));
            marker(&mut c, xy(q1.translation), OBJ1)?;
            marker(&mut c, xy(q2.translation), OBJ2)?;
            // Each object's local x axis.
            for (q, col) in [(q1, OBJ1), (q2, OBJ2)] {
                let a = q.rotation * v(0.6, 0.0);
                c.draw_series(std::iter::once(PathElement::new(
                    vec![xy(q.translation), xy(q.translation + a)],
                    col.stroke_width(1),
                )))?;
            }
            // The closest points of the stationary distance.
            let (w1, w2) = (*q1 * self.witness.point1, *q2 * self.witness.point2);
            c.draw_series(std::iter::once(PathElement::new(
                vec![xy(w1), xy(w2)],
                BLACK.stroke_width(1),
            )))?
            .label(format!("closest points, distance {:.4}", self.witness.distance))
            .legend(line_legend(BLACK));
            c.draw_series([w1, w2].map(|w| Circle::new(xy(w), 3, BLACK.filled())))?;
            legend(&mut c, SeriesLabelPosition::LowerLeft)?;
        }
        Ok(())
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 3: the three distances over φ

struct Curves {
    x: Vec<f64>,
    euclid: Vec<f64>,
    neg_fwd: Vec<f64>,
    side: Vec<f64>,
}

struct Fig3 {
    ecc: Curves,
    normal: Curves,
    best: smooth_ccd2d::StationaryDistance,
}

/// distanceEuclidean, −distanceFwd and distanceSide of a stationary pair against eq. 1's
/// parameter (`eccentric`) or against the crate's normal angle.
fn distance_curves(e1: &Ellipse, o2: &dyn ConvexCurve, frame: &PairFrame, n: usize, eccentric: bool) -> Curves {
    let mut c = Curves {
        x: Vec::with_capacity(n + 1),
        euclid: Vec::with_capacity(n + 1),
        neg_fwd: Vec::with_capacity(n + 1),
        side: Vec::with_capacity(n + 1),
    };
    for i in 0..=n {
        let x = -PI + 2.0 * PI * i as f64 / n as f64;
        let phi = if eccentric {
            e1.normal_angle_from_eccentric(x)
        } else {
            x
        };
        if let Some(j) = eval_pair(e1, o2, frame, phi) {
            c.x.push(x);
            c.euclid.push(j.euclidean().v);
            c.neg_fwd.push(-j.fwd.v);
            c.side.push(j.side.v);
        }
    }
    c
}

impl Fig3 {
    fn new() -> Res<Self> {
        let (e1, p1, e2, p2) = spec_pair();
        let pos12 = p1.inv_mul(&p2);
        let frame = PairFrame::from_pos12(&pos12);
        let best = stationary_distance(&e1, &e2, &pos12, &DistanceOptions::default())?;
        Ok(Self {
            ecc: distance_curves(&e1, &e2, &frame, 1000, true),
            normal: distance_curves(&e1, &e2, &frame, 1000, false),
            best,
        })
    }
}

impl Figure for Fig3 {
    fn name(&self) -> &'static str {
        "fig3_distances"
    }
    fn size(&self) -> (u32, u32) {
        (1500, 900)
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Res
    where
        DB::ErrorType: 'static,
    {
        let (e1, p1, e2, p2) = spec_pair();
        let (left, right) = root.split_horizontally(560);
        let (left, notes) = left.split_vertically(600);
        let mut c = world_chart(&left, "The pair (world), normals at φ = kπ/4", (-2.4, 3.0), (-1.4, 2.0))?;
        c.draw_series(std::iter::once(PathElement::new(
            outline(&e1, &p1, 400),
            OBJ1.stroke_width(2),
        )))?
        .label("object1")
        .legend(line_legend(OBJ1));
        c.draw_series(DashedLineSeries::new(
            outline(&e2, &p2, 400),
            6,
            4,
            OBJ2.stroke_width(2),
        ))?
        .label("object2")
        .legend(line_legend(OBJ2));
        let (w1, w2) = (p1 * self.best.point1, p2 * self.best.point2);
        c.draw_series(std::iter::once(PathElement::new(
            vec![xy(w1), xy(w2)],
            BLACK.stroke_width(2),
        )))?
        .label(format!("global minimum, distance {:.4}", self.best.distance))
        .legend(line_legend(BLACK));
        // Object1's points at a few φ with their normals, to read the parameter.
        for k in 0..8 {
            let phi = -PI + PI * k as f64 / 4.0;
            let cp = e1.eval(phi);
            let (a, b) = (p1 * cp.point, p1 * cp.point + p1.rotation * cp.normal * 0.35);
            c.draw_series(std::iter::once(PathElement::new(
                vec![xy(a), xy(b)],
                OBJ1.mix(0.5).stroke_width(1),
            )))?;
        }
        legend(&mut c, SeriesLabelPosition::LowerRight)?;
        let lines = [
            "For each φ: P1(φ), N(φ) on object1; P2 = S2(−N), the point",
            "of object2 whose outward normal is −N (eq. 4); d = P2 − P1.",
            "distanceEuclidean = |d|,  distanceFwd = d·N,  distanceSide = d × N.",
            "The global extremum is the root of distanceSide with",
            "distanceFwd > 0; max distanceFwd is the signed distance.",
        ];
        for (k, line) in lines.iter().enumerate() {
            notes.draw(&Text::new(*line, (20, 20 + 24 * k as i32), (FONT, 15).into_font()))?;
        }

        let rows = right.split_evenly((2, 1));
        let phi_star = self.best.phi;
        let panels = [
            (
                &self.ecc,
                e1.eccentric_from_normal_angle(phi_star),
                "Against eq. 1's parameter φ of object1 (x = a cos φ, y = b sin φ)",
                "φ (eq. 1)",
            ),
            (
                &self.normal,
                phi_star,
                "Against the crate's parameter: the normal angle of object1",
                "φ (normal angle)",
            ),
        ];
        for (k, (cv, xs, title, xdesc)) in panels.into_iter().enumerate() {
            let all = cv.euclid.iter().chain(&cv.neg_fwd).chain(&cv.side);
            let (lo, hi) = all.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &y| (a.min(y), b.max(y)));
            let pad = 0.05 * (hi - lo);
            let bottom = lo - 0.6 * (hi - lo);
            let mut c = plot_chart(&rows[k], title, (-PI, PI), (bottom, hi + pad), xdesc, "distance")?;
            c.draw_series(std::iter::once(PathElement::new(
                vec![(-PI, 0.0), (PI, 0.0)],
                BLACK.mix(0.4).stroke_width(1),
            )))?;
            let zip = |ys: &[f64]| cv.x.iter().copied().zip(ys.iter().copied()).collect::<Vec<_>>();
            c.draw_series(LineSeries::new(zip(&cv.euclid), GREEN.stroke_width(2)))?
                .label("distanceEuclidean")
                .legend(line_legend(GREEN));
            c.draw_series(LineSeries::new(zip(&cv.neg_fwd), OBJ1.stroke_width(2)))?
                .label("−distanceFwd")
                .legend(line_legend(OBJ1));
            c.draw_series(LineSeries::new(zip(&cv.side), ORANGE.stroke_width(2)))?
                .label("distanceSide")
                .legend(line_legend(ORANGE));
            c.draw_series(std::iter::once(PathElement::new(
                vec![(xs, bottom), (xs, hi + pad)],
                BLACK.mix(0.5).stroke_width(1),
            )))?;
            let d = self.best.distance;
            c.draw_series([(xs, d), (xs, -d), (xs, 0.0)].map(|p| Circle::new(p, 5, BLACK.filled())))?
                .label(format!("global extremum φ = {xs:.4} (stationary_distance)"))
                .legend(|(x, y)| Circle::new((x + 10, y), 4, BLACK.filled()));
            legend(&mut c, SeriesLabelPosition::LowerLeft)?;
        }
        Ok(())
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 4: the moving pair of figure 2

/// Object1's velocity and spin in figure 4.
const FIG4_VEL: (f64, f64) = (0.8, 0.2);
const FIG4_SPIN: f64 = 4.0;

struct Fig4 {
    m1: NonlinearRigidMotion,
    m2: NonlinearRigidMotion,
    t_end: f64,
    side: Grid,
    fwd: Grid,
    trace: Vec<TraceEvent>,
    hit: smooth_ccd2d::TimeOfImpact,
}

impl Fig4 {
    fn motions() -> (NonlinearRigidMotion, NonlinearRigidMotion) {
        let (_, p1, _, p2) = spec_pair();
        (
            NonlinearRigidMotion::new(p1, Vector::ZERO, v(FIG4_VEL.0, FIG4_VEL.1), FIG4_SPIN),
            NonlinearRigidMotion::constant_position(p2),
        )
    }

    fn new() -> Res<Self> {
        let (e1, _, e2, _) = spec_pair();
        let (m1, m2) = Self::motions();
        let t_end = 2.0;
        let mut trace = Vec::new();
        let hit = time_of_impact_traced(&e1, &m1, &e2, &m2, 0.0, t_end, &ToiOptions::default(), &mut trace)?;
        let (side, fwd) = side_fwd_grids(&e1, &e2, &m1, &m2, (0.0, t_end), (200, 140));
        Ok(Self {
            m1,
            m2,
            t_end,
            side,
            fwd,
            trace,
            hit,
        })
    }
}

impl Figure for Fig4 {
    fn name(&self) -> &'static str {
        "fig4_moving"
    }
    fn size(&self) -> (u32, u32) {
        (1800, 620)
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Res
    where
        DB::ErrorType: 'static,
    {
        let (e1, _, e2, _) = spec_pair();
        let (left, rest) = root.split_horizontally(560);
        let (mid, right) = rest.split_horizontally(620);
        let t_hit = self.hit.time;
        let title = impact_title(&self.hit, |t_hit| {
            format!(
                "object1: v = ({}, {}), ω = {} rad/s; impact at t = {t_hit:.4}",
                FIG4_VEL.0, FIG4_VEL.1, FIG4_SPIN
            )
        });
        let mut c = world_chart(&left, &title, (-3.0, 3.0), (-2.6, 2.6))?;
        draw_dashed(&mut c, outline(&e2, &self.m2.start, 400), OBJ2.stroke_width(2))?;
        let times = [0.0, 0.25 * t_hit, 0.5 * t_hit, 0.75 * t_hit, t_hit, self.t_end];
        for (k, &t) in times.iter().enumerate() {
            let pose = self.m1.position_at_time(t);
            let alpha = 0.3 + 0.7 * (k as f64 / 4.0).min(1.0);
            let style = if k == times.len() - 1 {
                GREY.mix(0.6).stroke_width(1)
            } else {
                OBJ1.mix(alpha).stroke_width(2)
            };
            let pts = outline(&e1, &pose, 300);
            if k == 0 || k == 4 || k == times.len() - 1 {
                let top = pts
                    .iter()
                    .fold((0.0, f64::NEG_INFINITY), |a, &p| if p.1 > a.1 { p } else { a });
                c.draw_series(std::iter::once(Text::new(
                    format!("t = {t:.2}"),
                    (top.0 - 0.3, top.1 + 0.25),
                    (FONT, 13).into_font().color(&BLACK),
                )))?;
            }
            c.draw_series(std::iter::once(PathElement::new(pts, style)))?;
        }
        if self.hit.status == ToiStatus::Hit {
            let pose = self.m1.position_at_time(t_hit);
            c.draw_series(std::iter::once(Circle::new(
                xy(pose * self.hit.point1),
                5,
                GOLD.filled(),
            )))?;
        }

        for (area, grid, name, labels) in [
            (&mid, &self.side, "distanceSide(φ, t) and the tracked path", true),
            (
                &right,
                &self.fwd,
                "distanceFwd(φ, t), zero level of distanceSide",
                false,
            ),
        ] {
            heat_panel(
                area,
                name,
                "φ (normal angle of object1)",
                grid,
                &self.side,
                &self.trace,
                labels,
            )?;
        }
        Ok(())
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 5: Appendix C, thin ellipses

struct Basin {
    /// Samples (x, distanceEuclidean) decimated for drawing.
    line: Vec<(f64, f64)>,
    /// The global minimum.
    min: (f64, f64),
    /// Where the function stops decreasing towards the minimum.
    basin: (f64, f64),
    /// Where it is convex about the minimum (Newton's method in optimization heads downhill).
    convex: (f64, f64),
    range: (f64, f64),
}

struct Fig5 {
    ratios: [f64; 3],
    ecc: Vec<Basin>,
    normal: Vec<Basin>,
}

/// Object1: an ellipse with semi-axes 1 × 1/ratio; object2: an ellipse 0.3 × 0.6 near its tip,
/// so that the closest points sit where eq. 1's parameter squeezes the normal's turn.
fn appendix_c_pair(ratio: f64) -> (Ellipse, Pose, Ellipse, Pose) {
    (
        Ellipse::new(1.0, 1.0 / ratio),
        Pose::new(v(0.0, 0.0), 0.0),
        Ellipse::new(0.3, 0.6),
        Pose::new(v(1.05, 0.75), 0.4),
    )
}

fn basin_of(e1: &Ellipse, o2: &dyn ConvexCurve, frame: &PairFrame, eccentric: bool, x_star: f64) -> Basin {
    let n = 100_000;
    let mut xs = Vec::with_capacity(n + 1);
    let mut ys = Vec::with_capacity(n + 1);
    for i in 0..=n {
        let x = -PI + 2.0 * PI * i as f64 / n as f64;
        let phi = if eccentric {
            e1.normal_angle_from_eccentric(x)
        } else {
            x
        };
        if let Some(j) = eval_pair(e1, o2, frame, phi) {
            xs.push(x);
            ys.push(j.euclidean().v);
        }
    }
    // The sample nearest to the global minimum of `stationary_distance`, then walk outwards
    // while the function keeps increasing.
    let mut k = xs.partition_point(|&x| x < x_star).min(xs.len() - 1);
    while k > 0 && ys[k - 1] < ys[k] {
        k -= 1;
    }
    while k + 1 < xs.len() && ys[k + 1] < ys[k] {
        k += 1;
    }
    let (mut lo, mut hi) = (k, k);
    while lo > 0 && ys[lo - 1] >= ys[lo] {
        lo -= 1;
    }
    while hi + 1 < xs.len() && ys[hi + 1] >= ys[hi] {
        hi += 1;
    }
    let dd = |i: usize| ys[i - 1] - 2.0 * ys[i] + ys[i + 1];
    let (mut clo, mut chi) = (k.max(1), k.min(xs.len() - 2));
    while clo > 1 && dd(clo - 1) > 0.0 {
        clo -= 1;
    }
    while chi + 2 < xs.len() && dd(chi + 1) > 0.0 {
        chi += 1;
    }
    // Min/max per pixel-sized bin so that a narrow basin stays visible.
    let bins = 1500;
    let mut line = Vec::with_capacity(2 * bins);
    let per = xs.len().div_ceil(bins);
    for chunk in xs.iter().zip(&ys).collect::<Vec<_>>().chunks(per) {
        let (mut a, mut b) = (chunk[0], chunk[0]);
        for &p in chunk {
            if p.1 < a.1 {
                a = p;
            }
            if p.1 > b.1 {
                b = p;
            }
        }
        let (first, second) = if a.0 <= b.0 { (a, b) } else { (b, a) };
        line.push((*first.0, *first.1));
        line.push((*second.0, *second.1));
    }
    let range = ys
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &y| (a.min(y), b.max(y)));
    Basin {
        line,
        min: (xs[k], ys[k]),
        basin: (xs[lo], xs[hi]),
        convex: (xs[clo], xs[chi]),
        range,
    }
}

impl Fig5 {
    fn new() -> Res<Self> {
        let ratios = [5.0, 15.0, 100.0];
        let mut ecc = Vec::new();
        let mut normal = Vec::new();
        for r in ratios {
            let (e1, p1, e2, p2) = appendix_c_pair(r);
            let pos12 = p1.inv_mul(&p2);
            let frame = PairFrame::from_pos12(&pos12);
            let best = stationary_distance(&e1, &e2, &pos12, &DistanceOptions::default())?;
            ecc.push(basin_of(
                &e1,
                &e2,
                &frame,
                true,
                e1.eccentric_from_normal_angle(best.phi),
            ));
            normal.push(basin_of(&e1, &e2, &frame, false, best.phi));
        }
        Ok(Self { ratios, ecc, normal })
    }
}

impl Figure for Fig5 {
    fn name(&self) -> &'static str {
        "fig5_appendix_c"
    }
    fn size(&self) -> (u32, u32) {
        (1650, 1250)
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Res
    where
        DB::ErrorType: 'static,
    {
        let (top, bottom) = root.split_vertically(420);
        let cols = top.split_evenly((1, 3));
        let rows = bottom.split_evenly((2, 3));
        for (k, r) in self.ratios.iter().enumerate() {
            let (e1, p1, e2, p2) = appendix_c_pair(*r);
            let mut c = world_chart(
                &cols[k],
                &format!("object1 1:{r} (solid), object2 0.3 × 0.6 (dashed)"),
                (-1.2, 1.5),
                (-0.5, 1.5),
            )?;
            draw_outline(&mut c, outline(&e1, &p1, 2000), OBJ1.stroke_width(2))?;
            draw_dashed(&mut c, outline(&e2, &p2, 400), OBJ2.stroke_width(2))?;
            let pos12 = p1.inv_mul(&p2);
            let best = stationary_distance(&e1, &e2, &pos12, &DistanceOptions::default())?;
            let (w1, w2) = (p1 * best.point1, p2 * best.point2);
            c.draw_series(std::iter::once(PathElement::new(
                vec![xy(w1), xy(w2)],
                BLACK.stroke_width(2),
            )))?;
        }
        for (row, (set, xdesc)) in [(&self.ecc, "φ (eq. 1)"), (&self.normal, "φ (normal angle)")]
            .into_iter()
            .enumerate()
        {
            for (k, b) in set.iter().enumerate() {
                let pad = 0.05 * (b.range.1 - b.range.0);
                let (y0, y1) = (b.range.0 - pad, b.range.1 + pad);
                let title = format!(
                    "1:{}: basin {:.3}, convex part {:.4}",
                    self.ratios[k],
                    b.basin.1 - b.basin.0,
                    b.convex.1 - b.convex.0,
                );
                let mut c = plot_chart(
                    &rows[3 * row + k],
                    &title,
                    (-PI, PI),
                    (y0, y1),
                    xdesc,
                    "distanceEuclidean",
                )?;
                c.draw_series(std::iter::once(Rectangle::new(
                    [(b.basin.0, y0), (b.basin.1, y1)],
                    GREEN.mix(0.25).filled(),
                )))?
                .label("decreasing towards the global minimum")
                .legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 20, y + 5)], GREEN.mix(0.25).filled()));
                c.draw_series(std::iter::once(Rectangle::new(
                    [(b.convex.0, y0), (b.convex.1, y1)],
                    GREEN.mix(0.6).filled(),
                )))?
                .label("convex about it")
                .legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 20, y + 5)], GREEN.mix(0.6).filled()));
                c.draw_series(LineSeries::new(b.line.clone(), OBJ1.stroke_width(2)))?;
                c.draw_series(std::iter::once(Circle::new(b.min, 5, BLACK.filled())))?
                    .label("global minimum")
                    .legend(|(x, y)| Circle::new((x + 10, y), 4, BLACK.filled()));
                legend(&mut c, SeriesLabelPosition::UpperRight)?;
            }
        }
        Ok(())
    }
}

// ---------------------------------------------------------------------------------------------
// Figure 6: Appendix D, a heptagon spinning at 30 rad/s

struct Fig6 {
    m1: NonlinearRigidMotion,
    m2: NonlinearRigidMotion,
    side: Grid,
    trace: Vec<TraceEvent>,
    hit: smooth_ccd2d::TimeOfImpact,
}

/// The Appendix D scene of `tests/common/appendix_d.rs`: heptagon, its motion, ellipse, its motion.
fn appendix_d_scene() -> (RoundedPolygon, NonlinearRigidMotion, Ellipse, NonlinearRigidMotion) {
    (
        appendix_d::heptagon(),
        appendix_d::heptagon_motion(),
        appendix_d::ellipse(),
        appendix_d::ellipse_motion(),
    )
}

impl Fig6 {
    fn new() -> Res<Self> {
        let (hept, m1, ell, m2) = appendix_d_scene();
        let mut trace = Vec::new();
        let (t0, t1) = appendix_d::WINDOW;
        let hit = time_of_impact_traced(&hept, &m1, &ell, &m2, t0, t1, &ToiOptions::default(), &mut trace)?;
        let t_max = if hit.status == ToiStatus::Hit {
            1.25 * hit.time
        } else {
            0.2
        };
        let (side, _) = side_fwd_grids(&hept, &ell, &m1, &m2, (0.0, t_max), (220, 150));
        Ok(Self {
            m1,
            m2,
            side,
            trace,
            hit,
        })
    }
}

impl Figure for Fig6 {
    fn name(&self) -> &'static str {
        "fig6_appendix_d"
    }
    fn size(&self) -> (u32, u32) {
        (1900, 640)
    }
    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Res
    where
        DB::ErrorType: 'static,
    {
        let (hept, _, ell, _) = appendix_d_scene();
        let (left, rest) = root.split_horizontally(580);
        let (zoom, right) = rest.split_horizontally(500);
        let t_hit = self.hit.time;
        let title = impact_title(&self.hit, |t_hit| {
            format!("Heptagon at 30 rad/s, drifting at (2, 0): impact t = {t_hit:.5}")
        });
        let mut c = world_chart(&left, &title, (-3.0, 1.0), (-1.7, 1.7))?;
        draw_dashed(&mut c, outline(&ell, &self.m2.start, 400), OBJ2.stroke_width(2))?;
        let n = 6;
        for k in 0..=n {
            let t = t_hit * k as f64 / n as f64;
            let pose = self.m1.position_at_time(t);
            let alpha = 0.25 + 0.75 * k as f64 / n as f64;
            let s = c.draw_series(std::iter::once(PathElement::new(
                outline(&hept, &pose, 700),
                OBJ1.mix(alpha).stroke_width(if k == n { 3 } else { 1 }),
            )))?;
            if k == n {
                s.label(format!("object1 at t = k·{:.4}, k = 0..{n}", t_hit / n as f64))
                    .legend(line_legend(OBJ1));
            }
            // A body-fixed mark on vertex 0 to show the spin.
            let tip = pose * hept.vertices()[0];
            c.draw_series(std::iter::once(Circle::new(xy(tip), 3, OBJ1.mix(alpha).filled())))?;
        }
        if self.hit.status == ToiStatus::Hit {
            let pose = self.m1.position_at_time(t_hit);
            c.draw_series(std::iter::once(Circle::new(
                xy(pose * self.hit.point1),
                6,
                GOLD.filled(),
            )))?
            .label("contact point")
            .legend(|(x, y)| Circle::new((x + 10, y), 5, GOLD.filled()));
            legend(&mut c, SeriesLabelPosition::LowerLeft)?;
        }

        if self.hit.status == ToiStatus::Hit {
            let pose = self.m1.position_at_time(t_hit);
            let p = pose * self.hit.point1;
            let h = 0.1;
            let mut c = world_chart(
                &zoom,
                "Near the contact, scaled 20:1",
                (p.x - h, p.x + h),
                (p.y - h, p.y + h),
            )?;
            draw_clipped(&mut c, &outline(&ell, &self.m2.start, 20_000), OBJ2.stroke_width(2))?;
            let dt = 0.0015;
            for k in (0..=5).rev() {
                let t = t_hit - dt * k as f64;
                let pose = self.m1.position_at_time(t);
                let alpha = 1.0 - 0.14 * k as f64;
                let style = OBJ1.mix(alpha).stroke_width(if k == 0 { 3 } else { 1 });
                draw_clipped(&mut c, &outline(&hept, &pose, 20_000), style)?;
            }
            let n = pose.rotation * self.hit.normal1;
            c.draw_series(std::iter::once(PathElement::new(
                vec![xy(p), xy(p + n * 0.05)],
                BLACK.stroke_width(2),
            )))?
            .label("contact normal of object1")
            .legend(line_legend(BLACK));
            c.draw_series(std::iter::once(Circle::new(xy(p), 5, GOLD.filled())))?;
            c.draw_series(std::iter::empty::<PathElement<(f64, f64)>>())?
                .label(format!("object1 at t_impact − k·{dt} s, k = 0..5"))
                .legend(line_legend(OBJ1));
            c.draw_series(std::iter::empty::<PathElement<(f64, f64)>>())?
                .label("object2 (solid here)")
                .legend(line_legend(OBJ2));
            legend(&mut c, SeriesLabelPosition::LowerLeft)?;
        }

        heat_panel(
            &right,
            "distanceSide(φ, t) and the tracked path",
            "φ (heptagon parameter: corner and edge pieces)",
            &self.side,
            &self.side,
            &self.trace,
            true,
        )
    }
}
