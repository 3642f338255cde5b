//! Geometry and drawing helpers of the figures: outlines, charts, heat maps, traces.

use super::*;

// Geometry helpers

pub(super) fn v(x: f64, y: f64) -> Vector {
    Vector::new(x, y)
}

pub(super) fn xy(p: Vector) -> (f64, f64) {
    (p.x, p.y)
}

/// The closed outline of `c` placed at `pose`, sampled uniformly in φ plus the piece ends.
pub(super) fn outline(c: &dyn ConvexCurve, pose: &Pose, n: usize) -> Vec<(f64, f64)> {
    let mut phis: Vec<f64> = (0..n).map(|i| -PI + 2.0 * PI * i as f64 / n as f64).collect();
    phis.extend_from_slice(c.breakpoints());
    phis.sort_by(f64::total_cmp);
    let mut pts: Vec<(f64, f64)> = phis.iter().map(|&p| xy(*pose * c.eval(p).point)).collect();
    pts.push(pts[0]);
    pts
}

/// The parts of a polyline inside the chart's visible range (plotters would clamp the rest
/// onto the border).
pub(super) fn draw_clipped<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, pts: &[(f64, f64)], style: ShapeStyle) -> Res
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
pub(super) fn split_wrap(pts: &[(f64, f64)]) -> Vec<Vec<(f64, f64)>> {
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
pub(super) fn world_chart<'a, DB: DrawingBackend>(
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
pub(super) fn plot_chart<'a, DB: DrawingBackend>(
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

pub(super) fn draw_outline<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    pts: Vec<(f64, f64)>,
    style: ShapeStyle,
) -> Res
where
    DB::ErrorType: 'static,
{
    chart.draw_series(std::iter::once(PathElement::new(pts, style)))?;
    Ok(())
}

pub(super) fn draw_dashed<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, pts: Vec<(f64, f64)>, style: ShapeStyle) -> Res
where
    DB::ErrorType: 'static,
{
    chart.draw_series(DashedLineSeries::new(pts, 6, 4, style))?;
    Ok(())
}

pub(super) fn marker<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, p: (f64, f64), color: RGBColor) -> Res
where
    DB::ErrorType: 'static,
{
    chart.draw_series(std::iter::once(Cross::new(p, 5, color.stroke_width(2))))?;
    Ok(())
}

pub(super) fn legend<'a, DB: DrawingBackend + 'a>(chart: &mut Chart<'a, DB>, pos: SeriesLabelPosition) -> Res
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

pub(super) fn line_legend(c: RGBColor) -> impl Fn((i32, i32)) -> PathElement<(i32, i32)> {
    move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
}

/// Diverging colour map on [−1, 1]: blue, white, red.
pub(super) fn diverging(s: f64) -> RGBColor {
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

pub(super) const LEVELS: i32 = 16;

pub(super) fn level(value: f64, vmax: f64) -> i32 {
    if !value.is_finite() {
        return i32::MIN;
    }
    ((value / vmax).clamp(-1.0, 1.0) * LEVELS as f64).round() as i32
}

/// A function of (φ, t) sampled on a regular grid.
pub(super) struct Grid {
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
pub(super) fn side_fwd_grids(
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
pub(super) fn heat_panel<DB: DrawingBackend>(
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
pub(super) fn impact_title(hit: &smooth_ccd2d::TimeOfImpact, on_hit: impl FnOnce(f64) -> String) -> String {
    if hit.status == ToiStatus::Hit {
        on_hit(hit.time)
    } else {
        format!("no impact ({:?})", hit.status)
    }
}

/// Draws the grid as cells (runs of equal colour merged) and the zero level of `zero`.
pub(super) fn draw_heat<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, g: &Grid, vmax: f64, zero: &Grid) -> Res
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
pub(super) fn colorbar<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, vmax: f64, top: u32, bottom: u32) -> Res
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
pub(super) fn draw_trace<DB: DrawingBackend>(chart: &mut Chart<'_, DB>, trace: &[TraceEvent], with_labels: bool) -> Res
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

pub(super) trait Wrapped {
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
pub(super) fn trace_counts(trace: &[TraceEvent]) -> (usize, usize, usize) {
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
