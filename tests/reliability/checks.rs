//! The checks: every query of the crate on a case ([`run_case`]), each answer against what the
//! crate documents, with a digest of every number returned.

use super::*;

/// What one case produced.
#[derive(Clone, Debug, Default)]
pub struct Outcome {
    /// Broken promises, each naming the query.
    pub violations: Vec<String>,
    /// Every number and status returned, as bits (FNV-1a).
    pub digest: u64,
    /// Tags such as `toi:Hit`, `dist:Err(Degenerate)` for the summary.
    pub tags: Vec<String>,
    /// The slowest call of the case and which query it was.
    pub slowest: (Duration, &'static str),
}

struct Ctx<'a> {
    case: &'a Case,
    out: Outcome,
}

impl Ctx<'_> {
    fn bad(&mut self, what: impl Into<String>) {
        self.out.violations.push(what.into());
    }
    /// `f()`, timed: a call beyond [`CALL_LIMIT`] is a violation; the slowest is kept.
    fn timed<T>(&mut self, what: &'static str, f: impl FnOnce() -> T) -> T {
        let t = Instant::now();
        let r = f();
        let dt = t.elapsed();
        if dt > self.out.slowest.0 {
            self.out.slowest = (dt, what);
        }
        if dt > CALL_LIMIT {
            self.bad(format!("{what}: one call took {dt:?} (limit {CALL_LIMIT:?})"));
        }
        r
    }
    fn tag(&mut self, t: impl Into<String>) {
        self.out.tags.push(t.into());
    }
    fn word(&mut self, w: u64) {
        for b in w.to_le_bytes() {
            self.out.digest ^= b as u64;
            self.out.digest = self.out.digest.wrapping_mul(0x100_0000_01B3);
        }
    }
    fn num(&mut self, x: f64) {
        self.word(x.to_bits());
    }
    fn vec(&mut self, v: Vector) {
        self.num(v.x);
        self.num(v.y);
    }
    /// Records `x` and flags it when NaN (or infinite, when `finite` is asked).
    fn finite(&mut self, what: &str, x: f64) {
        self.num(x);
        if !x.is_finite() {
            self.bad(format!("{what}: non-finite value {x}"));
        }
    }
    fn finite_vec(&mut self, what: &str, v: Vector) {
        self.vec(v);
        if !v.is_finite() {
            self.bad(format!("{what}: non-finite vector {v:?}"));
        }
    }
    /// Flags the answer `r` of query `what` unless it is the `expected` error, or `Ok` where none
    /// is expected (or `Degenerate` on an unsupported case).
    fn expect_error<T: std::fmt::Debug>(
        &mut self,
        what: &str,
        r: &Result<T, QueryError>,
        expected: Option<QueryError>,
    ) {
        match (r, expected) {
            (Err(e), Some(x)) if *e == x => {}
            (Err(QueryError::Degenerate), None) if !self.case.supported => {}
            (Ok(_), None) => {}
            _ => self.bad(format!("{what}: got {r:?}, expected error {expected:?}")),
        }
    }
    /// Tags the answer `r` as `prefix:<status>` or `prefix:Err(<error>)`.
    fn tag_answer<T, S: std::fmt::Debug>(&mut self, prefix: &str, r: &Result<T, QueryError>, status: impl Fn(&T) -> S) {
        self.tag(match r {
            Ok(d) => format!("{prefix}:{:?}", status(d)),
            Err(e) => format!("{prefix}:Err({e:?})"),
        });
    }
}

fn motion_finite(m: &NonlinearRigidMotion) -> bool {
    m.start.is_finite() && m.local_center.is_finite() && m.linvel.is_finite() && m.angvel.is_finite()
}

/// Runs every query on `case` and checks the answers.
pub fn run_case(case: &Case) -> Outcome {
    let mut cx = Ctx {
        case,
        out: Outcome {
            digest: 0xCBF2_9CE4_8422_2325,
            ..Outcome::default()
        },
    };
    let b1 = check_constructor(&mut cx, &case.s1, "shape1");
    let b2 = check_constructor(&mut cx, &case.s2, "shape2");
    let (Some(b1), Some(b2)) = (b1, b2) else {
        return cx.out;
    };
    for (b, name) in [(&b1, "shape1"), (&b2, "shape2")] {
        check_shape_methods(&mut cx, b, name);
    }
    if let (Some(c1), Some(c2)) = (&b1.curve, &b2.curve) {
        check_stationary(&mut cx, &**c1, &**c2);
        check_toi(&mut cx, &**c1, &**c2);
    }
    if let (Some(c), Some(hs)) = (&b1.curve, &b2.halfspace) {
        check_halfspace(&mut cx, &**c, hs, true);
    }
    if let (Some(hs), Some(c)) = (&b1.halfspace, &b2.curve) {
        check_halfspace(&mut cx, &**c, hs, false);
    }
    check_dispatcher(&mut cx, &*b1.shape, &*b2.shape, "d12");
    check_dispatcher(&mut cx, &*b2.shape, &*b1.shape, "d21");
    cx.out
}

fn check_constructor(cx: &mut Ctx, spec: &ShapeSpec, name: &str) -> Option<Built> {
    let built = cx.timed("constructor", || build(spec));
    cx.word(built.is_ok() as u64);
    match (spec.valid_numbers(), &built) {
        (Some(false), Ok(_)) => cx.bad(format!("{name}: invalid numbers {spec:?} built a shape")),
        (Some(true), Err(e)) if cx.case.supported => cx.bad(format!("{name}: valid {spec:?} rejected: {e}")),
        _ => {}
    }
    if let Err(e) = &built {
        cx.tag(format!("ctor:{}", e.split(':').next().unwrap_or("")));
    }
    built.ok()
}

fn check_shape_methods(cx: &mut Ctx, b: &Built, name: &str) {
    let c = cx.case;
    let g = &*b.shape;
    if b.halfspace.is_some() || g.as_composite_shape().is_some() {
        return;
    }
    // Shapes whose own numbers are out of range (parry shapes with wild sizes): no panic, no
    // check of the values.
    let sane = b.curve.as_ref().is_none_or(|cv| {
        let r = cv.bounding_radius();
        r.is_finite() && r > 0.0
    });
    let aabb = cx.timed("compute_local_aabb", || g.compute_local_aabb());
    let bs = cx.timed("compute_local_bounding_sphere", || g.compute_local_bounding_sphere());
    // Mass properties scale with the density: their values are checked for densities in
    // 1e-100..1e100.
    let density = if (1e-100..=1e100).contains(&c.density) {
        c.density
    } else {
        1.0
    };
    let m = cx.timed("mass_properties", || g.mass_properties(density));
    let _ = cx.timed("mass_properties", || g.mass_properties(c.density));
    let thick = cx.timed("ccd_thickness", || g.ccd_thickness());
    let ang = cx.timed("ccd_angular_thickness", || g.ccd_angular_thickness());
    let sp = cx.timed("local_support_point", || {
        g.as_support_map().map(|s| s.local_support_point(c.dir))
    });
    let ray = cx.timed("cast_local_ray", || {
        g.cast_local_ray_and_get_normal(&c.ray, c.max_toi, c.solid)
    });
    // A parry shape's own methods are parry's, under parry's contract: its `Capsule` asserts
    // (panics) in `project_local_point` at a non-finite point when its segment has no length
    // (parry 0.31, `point_segment.rs`), which no query of this crate reaches. Parry's shapes are
    // asked at finite points; this crate's at every point.
    let point_ok = b.own || c.point.is_finite();
    let proj = point_ok.then(|| cx.timed("project_local_point", || g.project_local_point(c.point, c.solid)));
    if point_ok {
        let _ = cx.timed("contains_local_point", || g.contains_local_point(c.point));
    }
    let world = cx.timed("compute_aabb", || g.compute_aabb(&c.pos12));
    let scaled = cx.timed("scale_dyn", || {
        g.scale_dyn(c.rescale, 8).map(|s| s.compute_local_aabb())
    });
    if !sane {
        return;
    }
    let (true, Some(proj)) = (b.own, proj) else {
        return;
    };
    cx.finite_vec(&format!("{name}.aabb.mins"), aabb.mins);
    cx.finite_vec(&format!("{name}.aabb.maxs"), aabb.maxs);
    if !(aabb.mins.x <= aabb.maxs.x && aabb.mins.y <= aabb.maxs.y) {
        cx.bad(format!("{name}.aabb: mins > maxs {aabb:?}"));
    }
    cx.finite(&format!("{name}.bounding_sphere.radius"), bs.radius);
    cx.finite(&format!("{name}.mass"), m.mass());
    cx.finite(&format!("{name}.inv_mass"), m.inv_mass);
    cx.finite_vec(&format!("{name}.local_com"), m.local_com);
    cx.finite(&format!("{name}.inv_inertia"), m.inv_principal_inertia);
    let positive_mass = m.mass() > 0.0;
    if !positive_mass && c.supported {
        cx.bad(format!("{name}: mass {} not positive", m.mass()));
    }
    cx.finite(&format!("{name}.ccd_thickness"), thick);
    cx.finite(&format!("{name}.ccd_angular_thickness"), ang);
    if let Some(p) = sp {
        cx.finite_vec(&format!("{name}.support_point({:?})", c.dir), p);
    }
    if let Some(h) = ray {
        cx.finite(&format!("{name}.ray.toi"), h.time_of_impact);
        cx.finite_vec(&format!("{name}.ray.normal"), h.normal);
        if !(h.time_of_impact >= 0.0 && h.time_of_impact <= c.max_toi) {
            cx.bad(format!(
                "{name}.ray: toi {} outside [0, {}]",
                h.time_of_impact, c.max_toi
            ));
        }
    } else {
        cx.word(0);
    }
    if c.point.is_finite() {
        cx.finite_vec(&format!("{name}.project_point({:?})", c.point), proj.point);
    }
    cx.word(proj.is_inside as u64);
    if c.pos12.is_finite() && c.supported {
        cx.finite_vec(&format!("{name}.world_aabb.mins"), world.mins);
        cx.finite_vec(&format!("{name}.world_aabb.maxs"), world.maxs);
    }
    if let Some(a) = scaled {
        if c.rescale.is_finite() && c.supported {
            cx.finite_vec(&format!("{name}.scaled_aabb.mins"), a.mins);
            cx.finite_vec(&format!("{name}.scaled_aabb.maxs"), a.maxs);
        }
    }
}

fn size_of(c1: &dyn ConvexCurve, c2: &dyn ConvexCurve) -> f64 {
    c1.bounding_radius().max(c2.bounding_radius())
}

fn check_distance_value(cx: &mut Ctx, what: &str, d: &StationaryDistance) {
    cx.finite(&format!("{what}.distance"), d.distance);
    cx.finite(&format!("{what}.phi"), d.phi);
    cx.finite_vec(&format!("{what}.point1"), d.point1);
    cx.finite_vec(&format!("{what}.point2"), d.point2);
    cx.finite_vec(&format!("{what}.normal1"), d.normal1);
    cx.finite_vec(&format!("{what}.normal2"), d.normal2);
    cx.word(d.status as u64);
    match d.status {
        DistanceStatus::Separated if d.distance.is_nan() || d.distance <= 0.0 => {
            cx.bad(format!("{what}: Separated with distance {}", d.distance))
        }
        DistanceStatus::Penetrating if d.distance.is_nan() || d.distance > 0.0 => {
            cx.bad(format!("{what}: Penetrating with distance {}", d.distance))
        }
        _ => {}
    }
    // Poses are taken as given: a rotation that is not a unit complex number (built with
    // `from_cos_sin_unchecked`) is outside the contract and scales the answer.
    let r = cx.case.pos12.rotation;
    let unit_rotation = ((r.re * r.re + r.im * r.im) - 1.0).abs() < 1e-9;
    // A user's curve gives its normals unit to the checks' tolerance (1e-6: computed in f32),
    // and the answer's normal is its own.
    let liar = |s: &ShapeSpec| matches!(s, ShapeSpec::Liar(..));
    let tol = if liar(&cx.case.s1) || liar(&cx.case.s2) {
        1e-6
    } else {
        1e-9
    };
    for (n, v) in [("normal1", d.normal1), ("normal2", d.normal2)] {
        if unit_rotation && (v.length() - 1.0).abs() > tol {
            cx.bad(format!("{what}.{n} not unit: {v:?}"));
        }
    }
}

fn check_stationary(cx: &mut Ctx, c1: &dyn ConvexCurve, c2: &dyn ConvexCurve) {
    let case = cx.case;
    let r = cx.timed("stationary_distance", || {
        stationary_distance(c1, c2, &case.pos12, &DistanceOptions::default())
    });
    let expected_err = if !case.pos12.is_finite() {
        Some(QueryError::NonFinite)
    } else if !c2.is_strictly_convex() {
        Some(QueryError::NotStrictlyConvex)
    } else {
        None
    };
    cx.expect_error("stationary_distance", &r, expected_err);
    cx.tag_answer("dist", &r, |d| d.status);
    let Ok(d) = r else {
        cx.word(0xE);
        return;
    };
    check_distance_value(cx, "stationary_distance", &d);
    if !case.supported {
        return;
    }
    let size = size_of(c1, c2);
    let sep = case.pos12.translation.length();
    // The shapes lie within their bounding radii of their origins: D ≥ |c2 − c1| − R1 − R2.
    let (r1, r2) = (c1.bounding_radius(), c2.bounding_radius());
    if d.distance < sep - r1 - r2 - 1e-9 * size {
        cx.bad(format!(
            "stationary_distance {} below |c2 − c1| − R1 − R2 = {}",
            d.distance,
            sep - r1 - r2
        ));
    }
    // The witnesses realise it.
    let w = case.pos12 * d.point2 - d.point1;
    if (w.dot(d.normal1) - d.distance).abs() > 1e-8 * size {
        cx.bad(format!(
            "stationary_distance: witnesses {w:?} do not realise {}",
            d.distance
        ));
    }
    // Both strictly convex: the other order agrees.
    if c1.is_strictly_convex() {
        if let Ok(e) = stationary_distance(c2, c1, &case.pos12.inverse(), &DistanceOptions::default()) {
            if (e.distance - d.distance).abs() > 1e-8 * size {
                cx.bad(format!("stationary_distance: swapped {} vs {}", e.distance, d.distance));
            }
        }
    }
    if let (Some(g), true) = (case.min_gap, case.class == "touching-at-t0") {
        if (d.distance - g).abs() > 1e-12 * size {
            cx.bad(format!("touching pair: distance {} (expected {g})", d.distance));
        }
    }
}

/// The signed distance at time t by the stationary distance (the check's own reference).
fn distance_at(c1: &dyn ConvexCurve, c2: &dyn ConvexCurve, case: &Case, t: f64) -> Option<f64> {
    let (o1, o2) = if c2.is_strictly_convex() { (c1, c2) } else { (c2, c1) };
    let (m1, m2) = if c2.is_strictly_convex() {
        (&case.m1, &case.m2)
    } else {
        (&case.m2, &case.m1)
    };
    let pos12 = m1.position_at_time(t).inv_mul(&m2.position_at_time(t));
    stationary_distance(o1, o2, &pos12, &DistanceOptions::default())
        .ok()
        .map(|d| d.distance)
}

fn check_toi_value(cx: &mut Ctx, what: &str, r: &TimeOfImpact, t0: f64, t1: f64) {
    cx.word(r.status as u64);
    cx.finite(&format!("{what}.time"), r.time);
    cx.finite(&format!("{what}.distance"), r.distance);
    cx.finite(&format!("{what}.distance_rate"), r.distance_rate);
    cx.finite_vec(&format!("{what}.point1"), r.point1);
    cx.finite_vec(&format!("{what}.point2"), r.point2);
    cx.finite_vec(&format!("{what}.normal1"), r.normal1);
    cx.finite_vec(&format!("{what}.normal2"), r.normal2);
    if !(r.time >= t0 && r.time <= t1) {
        cx.bad(format!("{what}: time {} outside [{t0}, {t1}]", r.time));
    }
    if r.status == ToiStatus::PenetratingAtStart && r.time != t0 {
        cx.bad(format!("{what}: PenetratingAtStart at {} ≠ t0 = {t0}", r.time));
    }
}

fn check_toi(cx: &mut Ctx, c1: &dyn ConvexCurve, c2: &dyn ConvexCurve) {
    let case = cx.case;
    let (t0, t1) = (case.t0, case.t1);
    let opts = ToiOptions::default()
        .with_target_distance(case.target)
        .with_stop_at_penetration(case.stop);
    let r = cx.timed("time_of_impact", || {
        time_of_impact(c1, &case.m1, c2, &case.m2, t0, t1, &opts)
    });
    let finite_in = motion_finite(&case.m1)
        && motion_finite(&case.m2)
        && t0.is_finite()
        && t1.is_finite()
        && case.target.is_finite()
        && case.target >= 0.0;
    let expected_err = if !(c1.is_strictly_convex() || c2.is_strictly_convex()) {
        Some(QueryError::NotStrictlyConvex)
    } else if !finite_in {
        Some(QueryError::NonFinite)
    } else if t1 < t0 {
        Some(QueryError::EmptyWindow)
    } else {
        None
    };
    cx.expect_error("time_of_impact", &r, expected_err);
    cx.tag_answer("toi", &r, |d| d.status);
    let Ok(r) = r else {
        cx.word(0xE);
        return;
    };
    check_toi_value(cx, "time_of_impact", &r, t0, t1);
    if t1 == t0 && !matches!(r.status, ToiStatus::NoHit | ToiStatus::PenetratingAtStart) {
        cx.bad(format!("time_of_impact: empty window answered {:?}", r.status));
    }
    if !case.supported {
        return;
    }
    let size = size_of(c1, c2);
    let slack = 1e-9 * size;
    let at = |t: f64| distance_at(c1, c2, case, t);
    // With `stop_at_penetration = false` and a contact at the start, a contact that separates
    // is ignored: the answer may be NoHit while the shapes still overlap, or a Hit, still in
    // contact, where the approach resumes (ToiStatus docs). Only the time range is checked.
    if !case.stop && at(t0).is_some_and(|d| d <= case.target + 1e-10 * size + slack) {
        if r.status == ToiStatus::Hit && at(r.time).is_some_and(|d| d > case.target + 1e-10 * size + slack) {
            cx.bad(format!(
                "time_of_impact: Hit at {} above the target after a start contact",
                r.time
            ));
        }
        return;
    }
    match r.status {
        ToiStatus::Hit => {
            if let Some(d) = at(r.time) {
                if d < case.target - slack || d > case.target + 1e-10 * size + slack {
                    cx.bad(format!(
                        "time_of_impact: Hit at {} with distance {d} (target {})",
                        r.time, case.target
                    ));
                }
            }
        }
        ToiStatus::PenetratingAtStart => {
            if let Some(d) = at(t0) {
                if d > case.target + 1e-10 * size + slack {
                    cx.bad(format!("time_of_impact: PenetratingAtStart with distance {d}"));
                }
            }
        }
        ToiStatus::NoHit => {
            // No missed contact at sampled times (and at the grazing pass's closest time).
            for k in 0..=16 {
                let t = t0 + (t1 - t0) * k as f64 / 16.0;
                if let Some(d) = at(t) {
                    if (case.stop || k != 0) && d < case.target - slack {
                        cx.bad(format!("time_of_impact: NoHit but distance {d} at t = {t}"));
                        break;
                    }
                }
            }
            if case.min_gap.is_some_and(|g| g < -slack) && case.class == "grazing" {
                cx.bad(format!(
                    "time_of_impact: grazing pass with gap {:?} reported NoHit",
                    case.min_gap
                ));
            }
        }
        ToiStatus::OutOfIterations => {}
    }
    if case.class == "grazing" && r.status == ToiStatus::Hit && case.min_gap.is_some_and(|g| g > 1e-10 * size + slack) {
        cx.bad(format!("time_of_impact: grazing gap {:?} reported a Hit", case.min_gap));
    }
}

fn check_halfspace(cx: &mut Ctx, c: &dyn ConvexCurve, hs: &HalfSpace, curve_first: bool) {
    let case = cx.case;
    let r = cx.timed("halfspace_distance", || {
        halfspace_distance(c, hs, &case.pos12, curve_first)
    });
    let finite_pose = case.pos12.is_finite() && hs.normal.is_finite();
    match &r {
        Err(QueryError::NonFinite) if !finite_pose => {}
        Err(QueryError::Degenerate) if !case.supported => {}
        Ok(_) if finite_pose => {}
        _ => cx.bad(format!(
            "halfspace_distance: got {r:?} (pose finite: {})",
            case.pos12.is_finite()
        )),
    }
    cx.tag_answer("hs-dist", &r, |d| d.status);
    if let Ok(d) = &r {
        check_distance_value(cx, "halfspace_distance", d);
    }
    let (mc, mh) = if curve_first {
        (&case.m1, &case.m2)
    } else {
        (&case.m2, &case.m1)
    };
    let opts = ToiOptions::default()
        .with_target_distance(case.target)
        .with_stop_at_penetration(case.stop);
    let r = cx.timed("time_of_impact_halfspace", || {
        time_of_impact_halfspace(c, mc, hs, mh, case.t0, case.t1, &opts)
    });
    let finite_in = motion_finite(mc)
        && motion_finite(mh)
        && hs.normal.is_finite()
        && case.t0.is_finite()
        && case.t1.is_finite()
        && case.target.is_finite()
        && case.target >= 0.0;
    let expected_err = if !finite_in {
        Some(QueryError::NonFinite)
    } else if case.t1 < case.t0 {
        Some(QueryError::EmptyWindow)
    } else {
        None
    };
    cx.expect_error("time_of_impact_halfspace", &r, expected_err);
    cx.tag_answer("hs-toi", &r, |d| d.status);
    if let Ok(r) = &r {
        check_toi_value(cx, "time_of_impact_halfspace", r, case.t0, case.t1);
        if case.t1 == case.t0 && !matches!(r.status, ToiStatus::NoHit | ToiStatus::PenetratingAtStart) {
            cx.bad(format!(
                "time_of_impact_halfspace: empty window answered {:?}",
                r.status
            ));
        }
    }
}

fn check_hit(cx: &mut Ctx, what: &str, h: &Option<ShapeCastHit>, lo: f64, hi: f64) {
    match h {
        None => cx.word(0),
        Some(h) => {
            cx.finite(&format!("{what}.time_of_impact"), h.time_of_impact);
            cx.finite_vec(&format!("{what}.witness1"), h.witness1);
            cx.finite_vec(&format!("{what}.witness2"), h.witness2);
            cx.finite_vec(&format!("{what}.normal1"), h.normal1);
            cx.finite_vec(&format!("{what}.normal2"), h.normal2);
            cx.word(match h.status {
                ShapeCastStatus::Converged => 1,
                ShapeCastStatus::OutOfIterations => 2,
                ShapeCastStatus::Failed => 3,
                ShapeCastStatus::PenetratingOrWithinTargetDist => 4,
            });
            if !(h.time_of_impact >= lo && h.time_of_impact <= hi) {
                cx.bad(format!("{what}: time {} outside [{lo}, {hi}]", h.time_of_impact));
            }
        }
    }
}

fn check_dispatcher(cx: &mut Ctx, g1: &dyn Shape, g2: &dyn Shape, tag: &str) {
    let case = cx.case;
    let d = SmoothDispatcher::default();
    let p = &case.pos12;
    match cx.timed("intersection_test", || d.intersection_test(p, g1, g2)) {
        Ok(i) => cx.word(i.intersecting as u64),
        Err(_) => cx.word(0xE),
    }
    match cx.timed("distance", || d.distance(p, g1, g2)) {
        Ok(r) => {
            cx.finite(&format!("{tag}.distance"), r.distance);
            if r.distance < 0.0 {
                cx.bad(format!("{tag}.distance negative: {}", r.distance));
            }
        }
        Err(_) => cx.word(0xE),
    }
    match cx.timed("contact", || d.contact(p, g1, g2, case.prediction)) {
        Ok(Some(c)) => {
            cx.finite(&format!("{tag}.contact.dist"), c.dist);
            cx.finite_vec(&format!("{tag}.contact.point1"), c.point1);
            cx.finite_vec(&format!("{tag}.contact.point2"), c.point2);
            cx.finite_vec(&format!("{tag}.contact.normal1"), c.normal1);
            cx.finite_vec(&format!("{tag}.contact.normal2"), c.normal2);
        }
        Ok(None) => cx.word(0),
        Err(_) => cx.word(0xE),
    }
    match cx.timed("closest_points", || d.closest_points(p, g1, g2, case.prediction)) {
        Ok(ClosestPoints::WithinMargin(a, b)) => {
            cx.finite_vec(&format!("{tag}.closest_points.1"), a);
            cx.finite_vec(&format!("{tag}.closest_points.2"), b);
        }
        Ok(ClosestPoints::Intersecting) => cx.word(1),
        Ok(ClosestPoints::Disjoint) => cx.word(2),
        Err(_) => cx.word(0xE),
    }
    let max_toi = if case.max_toi.is_nan() { 1.0 } else { case.max_toi };
    let opts = ShapeCastOptions {
        max_time_of_impact: max_toi,
        target_distance: if case.target.is_finite() { case.target } else { 0.0 },
        stop_at_penetration: case.stop,
        compute_impact_geometry_on_penetration: true,
    };
    match cx.timed("cast_shapes", || d.cast_shapes(p, case.local_vel12, g1, g2, opts)) {
        Ok(h) => check_hit(cx, &format!("{tag}.cast_shapes"), &h, 0.0, max_toi.max(0.0)),
        Err(_) => cx.word(0xE),
    }
    match cx.timed("cast_shapes_nonlinear", || {
        d.cast_shapes_nonlinear(&case.m1, g1, &case.m2, g2, case.t0, case.t1, case.stop)
    }) {
        Ok(h) => {
            let (lo, hi) = (case.t0, case.t1);
            if h.is_some() && (hi.is_nan() || lo.is_nan() || hi < lo) {
                cx.bad(format!("{tag}.cast_shapes_nonlinear: a hit in the window [{lo}, {hi}]"));
            }
            check_hit(cx, &format!("{tag}.cast_shapes_nonlinear"), &h, lo, hi)
        }
        Err(_) => cx.word(0xE),
    }
    let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::new();
    let mut ws = None;
    let pred = if case.prediction.is_finite() {
        case.prediction
    } else {
        0.0
    };
    match cx.timed("contact_manifolds", || {
        d.contact_manifolds(p, g1, g2, pred, &mut manifolds, &mut ws)
    }) {
        Ok(()) => {
            for m in &manifolds {
                if !m.points.is_empty() {
                    cx.finite_vec(&format!("{tag}.manifold.local_n1"), m.local_n1);
                    cx.finite_vec(&format!("{tag}.manifold.local_n2"), m.local_n2);
                }
                for c in &m.points {
                    cx.finite_vec(&format!("{tag}.manifold.p1"), c.local_p1);
                    cx.finite_vec(&format!("{tag}.manifold.p2"), c.local_p2);
                    cx.finite(&format!("{tag}.manifold.dist"), c.dist);
                }
            }
        }
        Err(_) => cx.word(0xE),
    }
}
