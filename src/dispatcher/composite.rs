//! Composite shapes (compound, polyline, trimesh, heightfield, voxels) on either side of a
//! query: parry's composite helpers, called with [`crate::SmoothDispatcher`] as the inner dispatcher so
//! that every sub-pair comes back to it.
//!
//! The helpers are written once, as the hidden macro `composite_helpers!`, and instantiated
//! here for parry2d-f64 and in the f32 package (`smooth-ccd2d-f32`) for parry2d with its own
//! dispatcher: the two parry builds are distinct crates with the same API, and the routing of
//! composite pairs is the same text for both.

/// Expands, in the module it is called in, to the composite helpers of a dispatcher `$dispatcher`
/// (a path to a type implementing the `$parry` crate's `QueryDispatcher` and
/// `PersistentQueryDispatcher<M, C>` for every `M: Default + Clone + Send + Sync` and
/// `C: Default + Copy + Send + Sync`, with the methods `composite_cast_levels(&self) -> (Real, Real)`:
/// the target distance and the distance tolerance of its casts, and `composite_one_sided(&self) ->
/// bool`: whether its casts take an oriented polyline as rapier's CCD does, one-sided):
/// `composite_intersection`, `composite_distance`,
/// `composite_contact`, `composite_closest_points`, `composite_cast`,
/// `composite_cast_nonlinear` (each `Err(Unsupported)` when neither side is composite),
/// `is_composite_like` and `composite_manifolds` (parry's `DefaultQueryDispatcher` routing of
/// composite-like shapes, with `$dispatcher` answering the sub-pairs), and `single_manifold` (the
/// manifold list of a convex pair made one manifold with no sub-shapes). Not a public API: the
/// f32 package's use of it is its only purpose.
#[doc(hidden)]
#[macro_export]
macro_rules! composite_helpers {
    ($parry:ident, $dispatcher:path) => {
        $crate::composite_part_manifolds!($parry, $dispatcher);
        use $parry::math::{Pose, Real, Vector};
        use $parry::query::details::{self, ShapeCastOptions};
        use $parry::query::{
            ClosestPoints, Contact, ContactManifold, ContactManifoldsWorkspace, NonlinearRigidMotion, ShapeCastHit,
            ShapeDistance, ShapeIntersection, Unsupported,
        };
        use $parry::shape::{Shape, ShapeType};

        pub(crate) fn composite_intersection(
            d: &$dispatcher,
            pos12: &Pose,
            g1: &dyn Shape,
            g2: &dyn Shape,
        ) -> Result<ShapeIntersection, Unsupported> {
            if let Some(c1) = g1.as_composite_shape() {
                Ok(details::intersection_test_composite_shape_shape(d, pos12, c1, g2))
            } else if let Some(c2) = g2.as_composite_shape() {
                Ok(details::intersection_test_shape_composite_shape(d, pos12, g1, c2))
            } else {
                Err(Unsupported)
            }
        }

        pub(crate) fn composite_distance(
            d: &$dispatcher,
            pos12: &Pose,
            g1: &dyn Shape,
            g2: &dyn Shape,
        ) -> Result<ShapeDistance, Unsupported> {
            if let Some(c1) = g1.as_composite_shape() {
                Ok(details::distance_composite_shape_shape(d, pos12, c1, g2))
            } else if let Some(c2) = g2.as_composite_shape() {
                Ok(details::distance_shape_composite_shape(d, pos12, g1, c2))
            } else {
                Err(Unsupported)
            }
        }

        pub(crate) fn composite_contact(
            d: &$dispatcher,
            pos12: &Pose,
            g1: &dyn Shape,
            g2: &dyn Shape,
            prediction: Real,
        ) -> Result<Option<Contact>, Unsupported> {
            if let Some(c1) = g1.as_composite_shape() {
                Ok(details::contact_composite_shape_shape(
                    d, pos12, c1, g2, prediction,
                ))
            } else if let Some(c2) = g2.as_composite_shape() {
                Ok(details::contact_shape_composite_shape(
                    d, pos12, g1, c2, prediction,
                ))
            } else {
                Err(Unsupported)
            }
        }

        pub(crate) fn composite_closest_points(
            d: &$dispatcher,
            pos12: &Pose,
            g1: &dyn Shape,
            g2: &dyn Shape,
            max_dist: Real,
        ) -> Result<ClosestPoints, Unsupported> {
            if let Some(c1) = g1.as_composite_shape() {
                Ok(details::closest_points_composite_shape_shape(
                    d, pos12, c1, g2, max_dist,
                ))
            } else if let Some(c2) = g2.as_composite_shape() {
                Ok(details::closest_points_shape_composite_shape(
                    d, pos12, g1, c2, max_dist,
                ))
            } else {
                Err(Unsupported)
            }
        }

        pub(crate) fn composite_cast(
            d: &$dispatcher,
            pos12: &Pose,
            vel12: Vector,
            g1: &dyn Shape,
            g2: &dyn Shape,
            options: ShapeCastOptions,
        ) -> Result<Option<ShapeCastHit>, Unsupported> {
            if let Some(c1) = g1.as_composite_shape() {
                Ok(details::cast_shapes_composite_shape_shape(
                    d, pos12, vel12, c1, g2, options,
                ))
            } else if let Some(c2) = g2.as_composite_shape() {
                Ok(details::cast_shapes_shape_composite_shape(
                    d, pos12, vel12, g1, c2, options,
                ))
            } else {
                Err(Unsupported)
            }
        }

        /// Whether [`composite_cast_nonlinear`] casts the parts of a composite itself, each by
        /// the dispatcher (a heightfield against a convex shape; a convex shape against a
        /// composite that does not move, rapier's CCD against level geometry), rather than
        /// handing the pair to parry's composite helper.
        #[allow(dead_code)]
        pub(crate) fn composite_casts_its_parts(
            m1: &NonlinearRigidMotion,
            g1: &dyn Shape,
            m2: &NonlinearRigidMotion,
            g2: &dyn Shape,
        ) -> bool {
            let still = |m: &NonlinearRigidMotion| m.linvel == Vector::ZERO && m.angvel == 0.0;
            use $parry::shape::TypedShape;
            match (g1.as_typed_shape(), g2.as_typed_shape()) {
                (TypedShape::HeightField(_), TypedShape::HeightField(_)) => false,
                (_, TypedShape::HeightField(_)) | (TypedShape::HeightField(_), _) => true,
                _ => match (g1.as_composite_shape(), g2.as_composite_shape()) {
                    (None, Some(_)) => still(m2),
                    (Some(_), None) => still(m1),
                    _ => false,
                },
            }
        }

        #[allow(clippy::too_many_arguments)]
        pub(crate) fn composite_cast_nonlinear(
            d: &$dispatcher,
            m1: &NonlinearRigidMotion,
            g1: &dyn Shape,
            m2: &NonlinearRigidMotion,
            g2: &dyn Shape,
            t0: Real,
            t1: Real,
            stop: bool,
        ) -> Result<Option<ShapeCastHit>, Unsupported> {
            let still = |m: &NonlinearRigidMotion| m.linvel == Vector::ZERO && m.angvel == 0.0;
            // A heightfield is no composite shape to parry, which answers no cast against one.
            use $parry::shape::TypedShape;
            match (g1.as_typed_shape(), g2.as_typed_shape()) {
                (TypedShape::HeightField(_), TypedShape::HeightField(_)) => return Err(Unsupported),
                (_, TypedShape::HeightField(hf)) => {
                    return Ok(cast_against_heightfield(d, m1, g1, m2, hf, t0, t1, stop, false))
                }
                (TypedShape::HeightField(hf), _) => {
                    return Ok(cast_against_heightfield(d, m2, g2, m1, hf, t0, t1, stop, true))
                }
                _ => {}
            }
            match (g1.as_composite_shape(), g2.as_composite_shape()) {
                // A convex shape against a composite at rest (rapier's CCD against a polyline, a
                // mesh or a compound of the static world): the parts culled by the shape's swept
                // bounding circle, each cast in the caller's order.
                (None, Some(c2)) if still(m2) => Ok(cast_against_still_composite(
                    d,
                    m1,
                    g1,
                    m2,
                    (g2, c2),
                    t0,
                    t1,
                    stop,
                    false,
                )),
                (Some(c1), None) if still(m1) => Ok(cast_against_still_composite(
                    d,
                    m2,
                    g2,
                    m1,
                    (g1, c1),
                    t0,
                    t1,
                    stop,
                    true,
                )),
                (Some(c1), _) => Ok(details::cast_shapes_nonlinear_composite_shape_shape(
                    d, m1, c1, m2, g2, t0, t1, stop,
                )),
                (None, Some(c2)) => Ok(details::cast_shapes_nonlinear_shape_composite_shape(
                    d, m1, g1, m2, c2, t0, t1, stop,
                )),
                (None, None) => Err(Unsupported),
            }
        }

        /// The nonlinear cast of the convex `body` moving by `mb` against the composite `comp` at
        /// rest at `mc`'s pose (`whole`: the same composite as a shape), the pair in the caller's
        /// order (`comp` first when `comp_first`). The earliest hit over the composite's parts,
        /// each part cast by `d`; the BVH is walked from the earliest time the body can reach a
        /// node's box (the ray of its rotation centre against the box grown by the body's extent
        /// about that centre and by the level a part's cast may report a hit at, [`hit_level`]:
        /// a lower bound on any hit of a part inside it), so parts the body cannot reach are
        /// never cast. The extent ([`swept_extent`]): the bounding circle about the rotation
        /// centre, which the spin does not move; where the body turns by less than half a turn
        /// over the window, within it its boxes at both ends grown by what the turn can move a
        /// point (R·Δ/2, R the circle's radius, Δ the turn) — a body sliding over a long
        /// polyline without touching it casts none of the segments under its path.
        #[allow(clippy::too_many_arguments)]
        fn cast_against_still_composite(
            d: &$dispatcher,
            mb: &NonlinearRigidMotion,
            body: &dyn Shape,
            mc: &NonlinearRigidMotion,
            (whole, comp): (&dyn Shape, &dyn $parry::shape::CompositeShape),
            t0: Real,
            t1: Real,
            stop: bool,
            comp_first: bool,
        ) -> Option<ShapeCastHit> {
            let pose = mc.start;
            // The body's rotation centre in the composite's frame: c(t) = c0 + v·t.
            let c0 = pose.inverse_transform_point(mb.start * mb.local_center);
            let v = pose.rotation.inverse() * mb.linvel;
            let (lo_ext, hi_ext, reach) = swept_extent(mb, body, &pose, t0, t1);
            // The first time in [t0, t1] at which c(t) enters the box grown by the extent and
            // by the level of a hit of a part inside it, with a margin for rounding.
            let scale = c0.abs().max_element() + v.abs().max_element() * (t1 - t0).abs() + reach;
            let (body_scale, offset) = (origin_radius(body), part_offset(whole, comp));
            let entry = |mins: Vector, maxs: Vector| -> Real {
                let size = reach + 0.5 * (maxs - mins).length();
                let corner = mins.abs().max(maxs.abs());
                let far = scale + corner.max_element();
                let level = hit_level(d, body_scale.max(corner.length() + offset), size);
                let margin = level + 16.0 * Real::EPSILON * far;
                let (lo, hi) = (
                    mins - hi_ext - Vector::splat(margin),
                    maxs - lo_ext + Vector::splat(margin),
                );
                let (mut a, mut b) = (t0, t1);
                for k in 0..2 {
                    let (p, s) = (c0[k], v[k]);
                    if s == 0.0 {
                        if p < lo[k] || p > hi[k] {
                            return Real::MAX;
                        }
                    } else {
                        let (ta, tb) = ((lo[k] - p) / s, (hi[k] - p) / s);
                        a = a.max(ta.min(tb));
                        b = b.min(ta.max(tb));
                    }
                }
                // NaN (absurd input) reads as "may hit at once": the parts' casts decide.
                if a <= b {
                    a
                } else if a.is_nan() || b.is_nan() {
                    t0
                } else {
                    Real::MAX
                }
            };
            let cost = |node: &$parry::partitioning::BvhNode, _best: Real| entry(node.mins(), node.maxs());
            use $parry::query::QueryDispatcher as _;
            use $parry::shape::TypedCompositeShape as _;
            // An oriented polyline under rapier's policies: its segments skipped as rapier skips them.
            let one_sided = if d.composite_one_sided() {
                OneSided::of(mb, body, whole, &pose, t0, t1)
            } else {
                None
            };
            let leaf = |part: u32, _best: Real| -> Option<ShapeCastHit> {
                comp.map_untyped_part_at(part, |part_pose, part_shape, _| {
                    if let (Some(sides), Some(seg)) = (&one_sided, part_shape.as_shape::<$parry::shape::Segment>()) {
                        if sides.skips(seg) {
                            return None;
                        }
                    }
                    let mp = match part_pose {
                        Some(p) => mc.prepend(*p),
                        None => *mc,
                    };
                    let r = if comp_first {
                        d.cast_shapes_nonlinear(&mp, part_shape, mb, body, t0, t1, stop)
                    } else {
                        d.cast_shapes_nonlinear(mb, body, &mp, part_shape, t0, t1, stop)
                    };
                    r.ok().flatten().map(|mut hit| {
                        if let Some(p) = part_pose {
                            if comp_first {
                                hit = hit.transform1_by(p);
                            } else {
                                hit.witness2 = p * hit.witness2;
                                hit.normal2 = p.rotation * hit.normal2;
                            }
                        }
                        if comp_first {
                            hit.subshape1 = part;
                        } else {
                            hit.subshape2 = part;
                        }
                        hit
                    })
                })?
            };
            comp.bvh().find_best(Real::MAX, cost, leaf).map(|(_, hit)| hit)
        }

        /// rapier's early-outs for the segments of an oriented polyline (`PolylineFlags::ORIENTED`,
        /// a one-sided chain), as parry's `sweep_time_of_impact_composite` takes them in rapier's
        /// CCD of its own shapes, with the turn counted. With the body's centroid at k₁ and k₂ at
        /// the window's ends (in the polyline's frame) and s₁, s₂ their signed distances from a
        /// segment's line, on the side its pseudo-normals face (`(k − a) ⟂· e`, e the unit
        /// direction from the segment's end a to its end b), the segment is no obstacle when the
        /// centroid starts behind it (s₁ < 0: the chain has one side), or stays in front of it
        /// by more than m = `CORE_FRACTION` (¼) of the body's `ccd_thickness` while
        /// s₁ − s₂ + R·Δ < m, R the body's reach about its centroid and Δ = |ω|·(t₁ − t₀) its
        /// turn: no point of the body comes closer to the line by m over the window (its
        /// centroid's approach, plus at most R·Δ of turning), so a body apart from the segment at
        /// the start ends the window less than m inside it — a body resting on or sliding along
        /// the chain, which the solver's contacts hold. rapier's own rule leaves out R·Δ, and the
        /// thin ellipse's tip swung 0.17 m into a segment it started apart from (the CCD scene
        /// suite's chain box built as an oriented chain); cast against every segment, a box
        /// sliding on a flat chain was stopped at the segments' shared ends, where its corner,
        /// sunk a fraction of a millimetre by the soft contact, met the next segment's end. A
        /// segment of no length, or a value that is not finite, is cast as any other.
        struct OneSided {
            k1: Vector,
            k2: Vector,
            /// m: the approach below which a segment is skipped.
            margin: Real,
            /// R·Δ: how far the turn can move a point of the body.
            turning: Real,
        }

        impl OneSided {
            /// The early-outs of the convex `body` moving by `mb` against `whole` at rest at
            /// `pose`, over `[t0, t1]`, when `whole` is an oriented polyline; `None` otherwise.
            fn of(
                mb: &NonlinearRigidMotion,
                body: &dyn Shape,
                whole: &dyn Shape,
                pose: &Pose,
                t0: Real,
                t1: Real,
            ) -> Option<OneSided> {
                let polyline = whole.as_shape::<$parry::shape::Polyline>()?;
                if !polyline.flags().contains($parry::shape::PolylineFlags::ORIENTED) {
                    return None;
                }
                // rapier's centroid: the shape's, of its mass properties.
                let centroid = body.mass_properties(1.0).local_com;
                let at = |t: Real| pose.inv_mul(&mb.position_at_time(t)) * centroid;
                let sphere = body.compute_local_bounding_sphere();
                let reach = sphere.radius + (sphere.center - centroid).length();
                Some(OneSided {
                    k1: at(t0),
                    k2: at(t1),
                    margin: $parry::query::sweep_toi::CORE_FRACTION * body.ccd_thickness(),
                    turning: reach * mb.angvel.abs() * (t1 - t0).abs(),
                })
            }

            /// Whether `seg` (in the polyline's frame) is skipped.
            fn skips(&self, seg: &$parry::shape::Segment) -> bool {
                let e = seg.b - seg.a;
                let length = e.length();
                if !(length > 0.0 && length.is_finite()) {
                    return false;
                }
                let e = e / length;
                let (s1, s2) = ((self.k1 - seg.a).perp_dot(e), (self.k2 - seg.a).perp_dot(e));
                s1 < 0.0 || (s1 - s2 + self.turning < self.margin && s2 > self.margin)
            }
        }

        /// The box about its rotation centre c(t) that holds the convex `body` moving by `mb` at
        /// every time of [t0, t1], in the frame of `pose` (`lo`, `hi`: its corners less c(t)),
        /// and the radius R of the body's bounding circle about c. Always within the circle's
        /// box [−R, R]²; where the body turns by Δ = |ω|·(t1 − t0) < π — on parry's constant
        /// spin and on rapier's nlerp path alike, which then turn the same way between the same
        /// end poses, each monotonically —, within the hull of its boxes at t0 and t1 grown by
        /// R·Δ/2: at any time the body is within Δ/2 of one end's rotation, and a point at
        /// distance ρ ≤ R from c moves by at most ρ·α turning by α. Non-finite boxes fall back
        /// to the circle's.
        fn swept_extent(
            mb: &NonlinearRigidMotion,
            body: &dyn Shape,
            pose: &Pose,
            t0: Real,
            t1: Real,
        ) -> (Vector, Vector, Real) {
            let sphere = body.compute_local_bounding_sphere();
            let reach = sphere.radius + (sphere.center - mb.local_center).length();
            let circle = (Vector::splat(-reach), Vector::splat(reach), reach);
            let turn = mb.angvel.abs() * (t1 - t0).abs();
            if turn.is_nan() || turn >= core::f64::consts::PI as Real || !reach.is_finite() {
                return circle;
            }
            let grow = Vector::splat(0.5 * reach * turn);
            let at = |t: Real| {
                let p = pose.inv_mul(&mb.position_at_time(t));
                let aabb = body.compute_aabb(&p);
                let c = p * mb.local_center;
                (aabb.mins - c, aabb.maxs - c)
            };
            let ((lo0, hi0), (lo1, hi1)) = (at(t0), at(t1));
            let lo = (lo0.min(lo1) - grow).max(circle.0);
            let hi = (hi0.max(hi1) + grow).min(circle.1);
            if lo.is_finite() && hi.is_finite() {
                (lo, hi, reach)
            } else {
                circle
            }
        }

        /// The level under which the cast of a body against one part of a composite may report
        /// a hit, which the culling of [`cast_against_still_composite`] and
        /// [`cast_against_heightfield`] grows the parts' boxes by: the target distance δ, twice
        /// the tolerance τ·s of the trackers and of the separating-axis advancement (τ the
        /// dispatcher's `distance_tolerance`; s, `scale`, at least the pair's larger bounding
        /// radius about its shapes' local origins), and the start-contact gap of rapier's rule
        /// (of the pair's size, `size`). A part further from the body than this over the whole
        /// window is no hit; a part within it may be one (a target distance of 1 m; a segment
        /// 10¹³ m from its polyline's origin, whose tolerance is 2·10³ m).
        fn hit_level(d: &$dispatcher, scale: Real, size: Real) -> Real {
            let (delta, tau) = d.composite_cast_levels();
            delta.max(0.0) + 2.0 * tau.max(0.0) * scale + ($crate::CastPolicy::START_CONTACT_GAP as Real) * size
        }

        /// The radius of the shape `g`'s bounding circle about its local origin (the scale of its
        /// casts' tolerances, [`hit_level`]).
        fn origin_radius(g: &dyn Shape) -> Real {
            let sphere = g.compute_local_bounding_sphere();
            sphere.radius + sphere.center.length()
        }

        /// A bound on the distance from the composite's origin to the local origin of any of
        /// its parts (`whole`: the composite as a shape), so that a part within a box whose
        /// farthest corner is ρ from the composite's origin is within ρ plus this of its own
        /// ([`hit_level`]'s scale): 0 for a polyline or a mesh, whose parts are in its frame; the
        /// farthest child's translation for a compound (and for a user's composite, over its
        /// parts).
        fn part_offset(whole: &dyn Shape, comp: &dyn $parry::shape::CompositeShape) -> Real {
            use $parry::shape::TypedCompositeShape as _;
            use $parry::shape::TypedShape;
            match whole.as_typed_shape() {
                TypedShape::Polyline(_) | TypedShape::TriMesh(_) => 0.0,
                TypedShape::Compound(c) => c
                    .shapes()
                    .iter()
                    .fold(0.0, |m: Real, (p, _)| m.max(p.translation.length())),
                _ => comp.bvh().leaves(|_| true).fold(0.0, |m: Real, i| {
                    let p = comp.map_untyped_part_at(i, |p, _, _| p.map_or(0.0, |p| p.translation.length()));
                    m.max(p.unwrap_or(0.0))
                }),
            }
        }

        /// Calls `f` on each segment of `hf` whose bounding box meets `aabb` (both in the
        /// heightfield's frame), with its index: the cells under the box's x range and one more
        /// on each side (the rounding of the division), each segment's own box then checked;
        /// every cell when the division is not finite (a heightfield of width 0). Not parry's
        /// `map_elements_in_local_aabb`, which compares the box divided by the scale with the
        /// unscaled heights: a negative vertical scale (a flat heightfield's, whose box is then
        /// not inverted) turns the comparison around, and it skipped the segments under the box.
        fn heightfield_segments_in(
            hf: &$parry::shape::HeightField,
            aabb: &$parry::bounding_volume::Aabb,
            f: &mut impl FnMut(u32, &$parry::shape::Segment),
        ) {
            let n = hf.num_cells();
            let (x0, w) = (hf.start_x(), hf.cell_width());
            let (a, b) = ((aabb.mins.x - x0) / w, (aabb.maxs.x - x0) / w);
            let (lo, hi) = (a.min(b), a.max(b));
            let (first, last) = if lo.is_finite() && hi.is_finite() {
                if hi < -1.0 || lo > n as Real + 1.0 {
                    return;
                }
                (
                    (lo.floor() - 1.0).max(0.0) as usize,
                    (hi.ceil() + 1.0).min(n as Real) as usize,
                )
            } else {
                (0, n)
            };
            for i in first..last {
                if let Some(seg) = hf.segment_at(i) {
                    let (mins, maxs) = (seg.a.min(seg.b), seg.a.max(seg.b));
                    let meets = mins.x <= aabb.maxs.x
                        && maxs.x >= aabb.mins.x
                        && mins.y <= aabb.maxs.y
                        && maxs.y >= aabb.mins.y;
                    if meets {
                        f(i as u32, &seg);
                    }
                }
            }
        }

        /// The nonlinear cast of the convex `body` moving by `mb` against the heightfield `hf`
        /// moving by `mh`, in the caller's order (`hf` first when `hf_first`): the earliest hit
        /// over its segments, each cast by `d`. At rest (rapier's CCD), only the segments under
        /// the box the body sweeps (its centre's straight path grown by [`swept_extent`], in the
        /// heightfield's frame); moving, all.
        #[allow(clippy::too_many_arguments)]
        fn cast_against_heightfield(
            d: &$dispatcher,
            mb: &NonlinearRigidMotion,
            body: &dyn Shape,
            mh: &NonlinearRigidMotion,
            hf: &$parry::shape::HeightField,
            t0: Real,
            t1: Real,
            stop: bool,
            hf_first: bool,
        ) -> Option<ShapeCastHit> {
            use $parry::query::QueryDispatcher as _;
            let mut best: Option<ShapeCastHit> = None;
            let mut each = |i: u32, seg: &$parry::shape::Segment| {
                let r = if hf_first {
                    d.cast_shapes_nonlinear(mh, seg, mb, body, t0, t1, stop)
                } else {
                    d.cast_shapes_nonlinear(mb, body, mh, seg, t0, t1, stop)
                };
                if let Ok(Some(mut hit)) = r {
                    if hf_first {
                        hit.subshape1 = i;
                    } else {
                        hit.subshape2 = i;
                    }
                    if best
                        .as_ref()
                        .is_none_or(|b| hit.time_of_impact < b.time_of_impact)
                    {
                        best = Some(hit);
                    }
                }
            };
            if mh.linvel == Vector::ZERO && mh.angvel == 0.0 {
                let pose = mh.start;
                let centre = |t: Real| pose.inverse_transform_point(mb.start * mb.local_center + mb.linvel * t);
                let (lo, hi, reach) = swept_extent(mb, body, &pose, t0, t1);
                let (a, b) = (centre(t0), centre(t1));
                // The level of a hit ([`hit_level`]: the pair's size at most the body's circle and
                // the whole heightfield, whose segments are in its frame) and a margin for rounding.
                let whole = hf.local_aabb();
                let corner = whole.mins.abs().max(whole.maxs.abs());
                let far = a.abs().max(b.abs()).max_element() + reach + corner.max_element();
                let level = hit_level(
                    d,
                    origin_radius(body).max(corner.length()),
                    reach + 0.5 * (whole.maxs - whole.mins).length(),
                );
                let margin = Vector::splat(level + 16.0 * Real::EPSILON * far);
                let aabb = $parry::bounding_volume::Aabb::new(a.min(b) + lo - margin, a.max(b) + hi + margin);
                if aabb.mins.is_finite() && aabb.maxs.is_finite() {
                    heightfield_segments_in(hf, &aabb, &mut each);
                    return best;
                }
            }
            for (i, seg) in hf.segments().enumerate() {
                each(i as u32, &seg);
            }
            best
        }

        /// Whether one side is a shape parry decomposes (composite, trimesh, heightfield, voxels).
        pub(crate) fn is_composite_like(g: &dyn Shape, t: ShapeType) -> bool {
            match t {
                ShapeType::Compound
                | ShapeType::Polyline
                | ShapeType::TriMesh
                | ShapeType::HeightField
                | ShapeType::Voxels => true,
                // A user's shape may be a composite; parry's other shapes are not.
                ShapeType::Custom => g.as_composite_shape().is_some(),
                _ => false,
            }
        }

        /// parry's `DefaultQueryDispatcher::contact_manifolds` for composite-like shapes, with `d` as
        /// the dispatcher of the sub-pairs.
        pub(crate) fn composite_manifolds<M, C>(
            d: &$dispatcher,
            pos12: &Pose,
            g1: &dyn Shape,
            g2: &dyn Shape,
            prediction: Real,
            manifolds: &mut Vec<ContactManifold<M, C>>,
            workspace: &mut Option<ContactManifoldsWorkspace>,
        ) where
            M: Default + Clone + Send + Sync,
            C: Default + Copy + Send + Sync,
        {
            let composite1 = g1.as_composite_shape();
            let composite2 = g2.as_composite_shape();
            if let (Some(c1), Some(c2)) = (composite1, composite2) {
                details::contact_manifolds_composite_shape_composite_shape(
                    d, pos12, c1, c2, prediction, manifolds, workspace,
                );
                return;
            }
            match (g1.shape_type(), g2.shape_type()) {
                (ShapeType::TriMesh, _) | (_, ShapeType::TriMesh) => {
                    details::contact_manifolds_trimesh_shape_shapes(d, pos12, g1, g2, prediction, manifolds, workspace);
                }
                // A heightfield against one of the crate's shapes or a user's curve: two manifolds
                // a part, as a composite's below.
                (ShapeType::HeightField, ShapeType::Custom)
                    if composite2.is_none() && g1.as_heightfield().is_some() =>
                {
                    if let Some(hf1) = g1.as_heightfield() {
                        heightfield_shape_part_manifolds(d, pos12, hf1, g2, prediction, manifolds, workspace, false);
                    }
                }
                (ShapeType::Custom, ShapeType::HeightField)
                    if composite1.is_none() && g2.as_heightfield().is_some() =>
                {
                    if let Some(hf2) = g2.as_heightfield() {
                        let pos21 = pos12.inverse();
                        heightfield_shape_part_manifolds(d, &pos21, hf2, g1, prediction, manifolds, workspace, true);
                    }
                }
                (ShapeType::HeightField, _) => match (composite2, g1.as_heightfield()) {
                    (Some(c2), Some(hf1)) => details::contact_manifolds_heightfield_composite_shape(
                        d,
                        pos12,
                        &pos12.inverse(),
                        hf1,
                        c2,
                        prediction,
                        manifolds,
                        workspace,
                        false,
                    ),
                    _ => details::contact_manifolds_heightfield_shape_shapes(
                        d, pos12, g1, g2, prediction, manifolds, workspace,
                    ),
                },
                (_, ShapeType::HeightField) => match (composite1, g2.as_heightfield()) {
                    (Some(c1), Some(hf2)) => details::contact_manifolds_heightfield_composite_shape(
                        d,
                        &pos12.inverse(),
                        pos12,
                        hf2,
                        c1,
                        prediction,
                        manifolds,
                        workspace,
                        true,
                    ),
                    _ => details::contact_manifolds_heightfield_shape_shapes(
                        d, pos12, g1, g2, prediction, manifolds, workspace,
                    ),
                },
                (ShapeType::Voxels, ShapeType::Voxels) => {
                    details::contact_manifolds_voxels_voxels_shapes(d, pos12, g1, g2, prediction, manifolds, workspace)
                }
                (ShapeType::Voxels, ShapeType::Ball) | (ShapeType::Ball, ShapeType::Voxels) => {
                    details::contact_manifolds_voxels_ball_shapes(pos12, g1, g2, prediction, manifolds)
                }
                (ShapeType::Voxels, _) | (_, ShapeType::Voxels) => {
                    if composite1.is_some() || composite2.is_some() {
                        details::contact_manifolds_voxels_composite_shape_shapes(
                            d, pos12, g1, g2, prediction, manifolds, workspace,
                        )
                    } else {
                        details::contact_manifolds_voxels_shape_shapes(
                            d, pos12, g1, g2, prediction, manifolds, workspace,
                        )
                    }
                }
                // A composite against one of the crate's shapes or a user's curve: two manifolds
                // a part, the core contact beside the points (`composite_part_manifolds!`).
                (_, ShapeType::Custom) if composite1.is_some() && composite2.is_none() => {
                    if let Some(c1) = composite1 {
                        composite_shape_shape_part_manifolds(d, pos12, c1, g2, prediction, manifolds, workspace, false);
                    }
                }
                (ShapeType::Custom, _) if composite2.is_some() && composite1.is_none() => {
                    if let Some(c2) = composite2 {
                        let pos21 = pos12.inverse();
                        composite_shape_shape_part_manifolds(d, &pos21, c2, g1, prediction, manifolds, workspace, true);
                    }
                }
                _ => {
                    if let Some(c1) = composite1 {
                        details::contact_manifolds_composite_shape_shape(
                            d, pos12, c1, g2, prediction, manifolds, workspace, false,
                        );
                    } else if let Some(c2) = composite2 {
                        details::contact_manifolds_composite_shape_shape(
                            d,
                            &pos12.inverse(),
                            c2,
                            g1,
                            prediction,
                            manifolds,
                            workspace,
                            true,
                        );
                    }
                }
            }
        }

        /// The manifold list of a convex pair made one manifold (the first, kept for its data,
        /// or a new one) with no sub-shapes.
        #[allow(dead_code)]
        pub(crate) fn single_manifold<M: Default + Clone, C: Default + Copy>(
            manifolds: &mut Vec<ContactManifold<M, C>>,
        ) -> &mut ContactManifold<M, C> {
            if manifolds.is_empty() {
                manifolds.push(ContactManifold::new());
            }
            manifolds.truncate(1);
            let manifold = &mut manifolds[0];
            manifold.subshape1 = 0;
            manifold.subshape2 = 0;
            manifold.subshape_poses = None;
            manifold
        }
    };
}

composite_helpers!(parry2d_f64, crate::SmoothDispatcher);

impl crate::SmoothDispatcher {
    /// The target distance and the distance tolerance of the dispatcher's casts: the options
    /// the culling of a composite's parts reads (`hit_level` of `composite_helpers!`).
    pub(crate) fn composite_cast_levels(&self) -> (Real, Real) {
        (self.toi_options.target_distance, self.toi_options.distance_tolerance)
    }

    /// Whether the dispatcher's casts take an oriented polyline as rapier's CCD does, one-sided
    /// with rapier's early-outs (`OneSided` of `composite_helpers!`): under the rapier policies
    /// ([`crate::CastPolicy::is_rapier`]); under [`crate::CastPolicy::Plain`] every segment is cast.
    pub(crate) fn composite_one_sided(&self) -> bool {
        self.cast_policy.is_rapier()
    }
}
