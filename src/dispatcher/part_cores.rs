//! The contact manifolds of a composite shape (a polyline, a compound, a user's composite) or a
//! heightfield against one of this crate's shapes or a user's curve: parry's
//! `contact_manifolds_composite_shape_shape` and `contact_manifolds_heightfield_shape` with *two*
//! manifolds a part (a heightfield's parts as `Segment`s, where parry's helper takes capsules of
//! radius 0: the dispatcher's casts of a heightfield take segments, and a segment's rules apply).
//!
//! parry's helper gives each part one manifold, and parry's 2D manifolds hold at most two
//! points. A part's manifold from the exact contact query holds the pair's points (two where a
//! face faces a face) and the smaller body's *core contact* (`core_disc`), which then took the
//! place of the second point wherever the two points did not hold the core's centre between
//! them — so a face that a spin turns into a part (a box tumbling onto a two-sided chain) lost
//! its speculative far point, and rapier's solver met the corner a step late. Here each part
//! reached by the query has its manifold of points and, where it would have taken the second
//! point's place, a manifold holding its core contact right after it
//! (`SmoothDispatcher::part_manifolds`; none where that manifold would be empty: rapier
//! processes every manifold of a pair, an empty one too). Both carry the part's sub-shape id and
//! pose, and each keeps its points' impulses from the previous call by feature id (rapier's warm
//! start).
//!
//! The bookkeeping is parry's: the parts whose bounding boxes meet the shape's box loosened by
//! the prediction, in the order the composite's BVH reaches them, each part's manifolds kept
//! from the last call (a workspace mapping a part to its place in the list) and a part no
//! longer reached dropped with them. parry's typed view of a workspace (which only its
//! serialisation reads; parry names no variant for a dispatcher's own) shows an empty workspace
//! of parry's: a pair restored from a snapshot starts its manifolds afresh, its impulses
//! dropped once. parry's helper runs
//! its parts on several threads for composites of 256 parts reached or more (its `parallel`
//! feature); here they run in turn, the same manifolds either way.
//!
//! Written once, as the hidden macro `composite_part_manifolds!`, expanded by
//! `composite_helpers!` for both parry builds (f64 here, f32 in the f32 package).

/// Expands, inside `composite_helpers!`, to `composite_shape_shape_part_manifolds` (module docs)
/// for the `$parry` crate and the dispatcher `$dispatcher`, which must have the method
/// `part_manifolds` of [`crate::SmoothDispatcher::part_manifolds`]'s signature. Not a public
/// API.
#[doc(hidden)]
#[macro_export]
macro_rules! composite_part_manifolds {
    ($parry:ident, $dispatcher:path) => {
        /// The workspace of [`composite_shape_shape_part_manifolds`]: each part reached by the
        /// last call: the place of its manifolds in the list, whether its core contact's
        /// manifold follows, and the call's stamp.
        #[derive(Clone, Default)]
        pub(crate) struct PartManifoldsWorkspace {
            stamp: bool,
            parts: std::collections::HashMap<u32, (usize, bool, bool)>,
            /// An empty workspace of parry's, what the typed view shows (module docs).
            typed: $parry::query::details::VoxelsShapeContactManifoldsWorkspace<2>,
        }

        impl $parry::query::details::WorkspaceData for PartManifoldsWorkspace {
            fn as_typed_workspace_data(&self) -> $parry::query::details::TypedWorkspaceData<'_> {
                $parry::query::details::TypedWorkspaceData::VoxelsShapeContactManifoldsWorkspace(&self.typed)
            }

            fn clone_dyn(&self) -> Box<dyn $parry::query::details::WorkspaceData> {
                Box::new(self.clone())
            }
        }

        /// The manifolds of the composite `composite1` against the convex `shape2` (module
        /// docs), `pos12` mapping `shape2`'s frame into the composite's, as parry's helper takes
        /// them; `flipped` when the caller's pair has the composite second (each part is then
        /// sub-shape 2, and its pair is queried in the caller's order: the shape first).
        #[allow(clippy::too_many_arguments)]
        pub(crate) fn composite_shape_shape_part_manifolds<M, C>(
            d: &$dispatcher,
            pos12: &Pose,
            composite1: &(dyn $parry::shape::CompositeShape + Sync),
            shape2: &dyn Shape,
            prediction: Real,
            manifolds: &mut Vec<ContactManifold<M, C>>,
            workspace: &mut Option<ContactManifoldsWorkspace>,
            flipped: bool,
        ) where
            M: Default + Clone + Send + Sync,
            C: Default + Copy + Send + Sync,
        {
            let deformable = composite1.is_deformable();
            let parts = |aabb: &$parry::bounding_volume::Aabb, each: &mut dyn FnMut(u32, PartView<'_>)| {
                for part in composite1.bvh().intersect_aabb(aabb) {
                    composite1.map_part_at(part, &mut |pose, shape, constraints| {
                        each(part, (pose, shape, constraints))
                    });
                }
            };
            let ctx = (pos12, shape2, prediction, flipped, deformable);
            part_manifolds_over(d, ctx, manifolds, workspace, parts);
        }

        /// [`composite_shape_shape_part_manifolds`] for a heightfield (`hf`), whose parts are its
        /// segments (parry's helper takes each as a capsule of radius 0; a `Segment` here, as
        /// the dispatcher's casts of a heightfield take it, so that a segment's own rules apply:
        /// the contact from the side of the body's centre).
        #[allow(clippy::too_many_arguments)]
        pub(crate) fn heightfield_shape_part_manifolds<M, C>(
            d: &$dispatcher,
            pos12: &Pose,
            hf: &$parry::shape::HeightField,
            shape2: &dyn Shape,
            prediction: Real,
            manifolds: &mut Vec<ContactManifold<M, C>>,
            workspace: &mut Option<ContactManifoldsWorkspace>,
            flipped: bool,
        ) where
            M: Default + Clone + Send + Sync,
            C: Default + Copy + Send + Sync,
        {
            let parts = |aabb: &$parry::bounding_volume::Aabb, each: &mut dyn FnMut(u32, PartView<'_>)| {
                hf.map_elements_in_local_aabb(aabb, &mut |part, seg| each(part, (None, seg, None)));
            };
            let ctx = (pos12, shape2, prediction, flipped, false);
            part_manifolds_over(d, ctx, manifolds, workspace, parts);
        }

        /// A part as a composite shows it: its pose in the composite (none: the identity), its
        /// shape and its normal constraints.
        type PartView<'a> = (
            Option<&'a Pose>,
            &'a dyn Shape,
            Option<&'a dyn $parry::query::details::NormalConstraints>,
        );

        /// The walk of the module docs over the parts `parts` hands a box (the parts whose boxes
        /// meet it), with `ctx` = (`pos12`, `shape2`, the prediction, `flipped`, whether the
        /// composite is deformable).
        fn part_manifolds_over<M, C>(
            d: &$dispatcher,
            (pos12, shape2, prediction, flipped, deformable): (&Pose, &dyn Shape, Real, bool, bool),
            manifolds: &mut Vec<ContactManifold<M, C>>,
            workspace: &mut Option<ContactManifoldsWorkspace>,
            parts: impl FnOnce(&$parry::bounding_volume::Aabb, &mut dyn FnMut(u32, PartView<'_>)),
        ) where
            M: Default + Clone + Send + Sync,
            C: Default + Copy + Send + Sync,
        {
            use $parry::bounding_volume::BoundingVolume as _;
            use $parry::utils::PoseOpt as _;
            let ours = workspace
                .as_ref()
                .is_some_and(|w| w.0.downcast_ref::<PartManifoldsWorkspace>().is_some());
            if !ours {
                *workspace = Some(ContactManifoldsWorkspace(Box::new(
                    PartManifoldsWorkspace::default(),
                )));
            }
            let Some(ws) = workspace
                .as_mut()
                .and_then(|w| w.0.downcast_mut::<PartManifoldsWorkspace>())
            else {
                return;
            };
            let stamp = !ws.stamp;
            ws.stamp = stamp;
            let pos21 = pos12.inverse();
            let aabb2 = shape2.compute_aabb(pos12).loosened(prediction);
            let mut old = core::mem::take(manifolds);
            parts(
                &aabb2,
                &mut |part, (part_pos1, part_shape1, normal_constraints1)| {
                    // The part's manifolds from the last call, moved to the end of the list, or new
                    // ones there (their sub-shape ids and poses set here), its core's always (taken
                    // out again below when empty). The list is taken to be the one this
                    // bookkeeping returned last, as parry's helper takes it (rapier only clears
                    // it); a shorter one reads as new.
                    let fresh = || {
                        let mut m = ContactManifold::new();
                        if flipped {
                            (m.subshape1, m.subshape2) = (0, part);
                            m.set_subshape_pos2(part_pos1.copied());
                        } else {
                            (m.subshape1, m.subshape2) = (part, 0);
                            m.set_subshape_pos1(part_pos1.copied());
                        }
                        m
                    };
                    let at = manifolds.len();
                    // A new part's slot reads as a list too short for it.
                    let slot = ws.parts.entry(part).or_insert((usize::MAX, false, stamp));
                    let (last, with_core, _) = *slot;
                    let kept = last.saturating_add(if with_core { 2 } else { 1 }) <= old.len();
                    if kept {
                        manifolds.push(old[last].take());
                        manifolds.push(if with_core { old[last + 1].take() } else { fresh() });
                    }
                    if !kept {
                        manifolds.push(fresh());
                        manifolds.push(fresh());
                    }
                    let (main, core) = manifolds[at..].split_at_mut(1);
                    let (main, core) = (&mut main[0], &mut core[0]);
                    if deformable {
                        main.mark_shapes_deformed();
                        core.mark_shapes_deformed();
                    }
                    let _ = if flipped {
                        d.part_manifolds(
                            &part_pos1.prepend_to(&pos21),
                            shape2,
                            part_shape1,
                            [None, normal_constraints1],
                            prediction,
                            main,
                            core,
                        )
                    } else {
                        d.part_manifolds(
                            &part_pos1.inv_mul(pos12),
                            part_shape1,
                            shape2,
                            [normal_constraints1, None],
                            prediction,
                            main,
                            core,
                        )
                    };
                    let with_core = !core.points.is_empty();
                    if !with_core {
                        manifolds.pop();
                    }
                    *slot = (at, with_core, stamp);
                },
            );
            ws.parts.retain(|_, e| e.2 == stamp);
        }
    };
}
