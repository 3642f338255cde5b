//! Figures 1 to 3: the shapes, the coordinate transformation, the three distances over φ.

use super::*;

// Figure 1: shapes

pub(super) struct Fig1;

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
pub(super) fn spec_pair() -> (Ellipse, Pose, Ellipse, Pose) {
    (
        Ellipse::new(0.5, 0.8),
        Pose::new(v(-1.5, 0.0), 0.3),
        Ellipse::new(0.5, 2.0),
        Pose::new(v(1.0, 0.5), 1.0),
    )
}

pub(super) struct Fig2 {
    witness: smooth_ccd2d::StationaryDistance,
}

impl Fig2 {
    pub(super) fn new() -> Res<Self> {
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

pub(super) struct Curves {
    x: Vec<f64>,
    euclid: Vec<f64>,
    neg_fwd: Vec<f64>,
    side: Vec<f64>,
}

pub(super) struct Fig3 {
    ecc: Curves,
    normal: Curves,
    best: smooth_ccd2d::StationaryDistance,
}

/// distanceEuclidean, −distanceFwd and distanceSide of a stationary pair against eq. 1's
/// parameter (`eccentric`) or against the crate's normal angle.
pub(super) fn distance_curves(
    e1: &Ellipse,
    o2: &dyn ConvexCurve,
    frame: &PairFrame,
    n: usize,
    eccentric: bool,
) -> Curves {
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
    pub(super) fn new() -> Res<Self> {
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
