//! Figures 4 to 6: the moving pair, Appendix C's thin ellipses, Appendix D's spinning heptagon.

use super::*;

// Figure 4: the moving pair of figure 2

/// Object1's velocity and spin in figure 4.
pub(super) const FIG4_VEL: (f64, f64) = (0.8, 0.2);
pub(super) const FIG4_SPIN: f64 = 4.0;

pub(super) struct Fig4 {
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

    pub(super) fn new() -> Res<Self> {
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

pub(super) struct Basin {
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

pub(super) struct Fig5 {
    ratios: [f64; 3],
    ecc: Vec<Basin>,
    normal: Vec<Basin>,
}

/// Object1: an ellipse with semi-axes 1 × 1/ratio; object2: an ellipse 0.3 × 0.6 near its tip,
/// so that the closest points sit where eq. 1's parameter squeezes the normal's turn.
pub(super) fn appendix_c_pair(ratio: f64) -> (Ellipse, Pose, Ellipse, Pose) {
    (
        Ellipse::new(1.0, 1.0 / ratio),
        Pose::new(v(0.0, 0.0), 0.0),
        Ellipse::new(0.3, 0.6),
        Pose::new(v(1.05, 0.75), 0.4),
    )
}

pub(super) fn basin_of(e1: &Ellipse, o2: &dyn ConvexCurve, frame: &PairFrame, eccentric: bool, x_star: f64) -> Basin {
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
    pub(super) fn new() -> Res<Self> {
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

pub(super) struct Fig6 {
    m1: NonlinearRigidMotion,
    m2: NonlinearRigidMotion,
    side: Grid,
    trace: Vec<TraceEvent>,
    hit: smooth_ccd2d::TimeOfImpact,
}

/// The Appendix D scene of `tests/common/appendix_d.rs`: heptagon, its motion, ellipse, its motion.
pub(super) fn appendix_d_scene() -> (RoundedPolygon, NonlinearRigidMotion, Ellipse, NonlinearRigidMotion) {
    (
        appendix_d::heptagon(),
        appendix_d::heptagon_motion(),
        appendix_d::ellipse(),
        appendix_d::ellipse_motion(),
    )
}

impl Fig6 {
    pub(super) fn new() -> Res<Self> {
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
