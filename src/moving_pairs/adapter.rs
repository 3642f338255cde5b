//! The rapier adapter of the pass: `MovingPairs`, the struct a rapier user keeps beside the
//! pipeline, written once as the hidden macro `moving_pairs_rapier!` and instantiated for
//! rapier2d-f64 here (`rapier_f64`, feature `rapier`) and for rapier2d in the f32 package (its
//! feature `rapier`): the two rapier builds are distinct crates with the same API.
//!
//! The adapter reads rapier's sets into the pass's f64 records (`records`), runs the broad
//! phase (`broad`) and the event loop (`schedule`), and writes the stops back. What is
//! precision-specific — widening a pose to f64, rounding it back, a cast, an intersection test —
//! is a module of functions the caller names (`$b`): `pose64`, `pose_back`, `vector64`,
//! `real64`, `dispatcher`, `cast` and `intersects`.

/// Expands, in the module it is called in, to `MovingPairs` for the rapier crate `$rapier`
/// (`rapier2d_f64` or `rapier2d`), whose casts and intersection tests are those of the
/// dispatcher type `$dispatcher`, through the functions of the module `$b` (module docs).
/// `$example` is the struct's example (a doc string). Not a public API: the f32 package's use
/// of it is its only purpose.
#[doc(hidden)]
#[macro_export]
macro_rules! moving_pairs_rapier {
    ($rapier:ident, $dispatcher:ty, $b:ident, $example:literal) => {
        use $crate::__moving_pairs::{
            may_be_fast, sensor_crossing, Broad, CastOutcome, PairCast, PassBody, PassCollider, PassPair, Schedule,
            StepPath,
        };
        use $crate::{MovingPairsOptions, MovingPairsReport, PairScope, PassStatus};
        use $rapier::dynamics::{IntegrationParameters, RigidBody, RigidBodyHandle, RigidBodySet};
        use $rapier::geometry::{ColliderHandle, ColliderSet, CollisionEvent, CollisionEventFlags, SolverFlags};
        use $rapier::math::Pose;
        use $rapier::pipeline::{ActiveEvents, ActiveHooks, EventHandler, PairFilterContext, PhysicsHooks};

        /// The moving-pairs CCD pass: exact continuous collision detection between two bodies
        /// that both move within a step, which rapier's CCD never does (it sweeps a fast body
        /// against targets held at their end-of-step pose, and a bullet never against another
        /// bullet). Keep one beside the pipeline; call [`MovingPairs::before_step`] before
        /// `PhysicsPipeline::step` and [`MovingPairs::after_step`] after it.
        ///
        /// **What it does.** For every pair of colliders of two bodies that both moved within
        /// the step, one of them a fast body of the scope ([`MovingPairsOptions`]), whose swept
        /// boxes overlap and that rapier would make collide (collision groups, solver groups,
        /// the `FILTER_CONTACT_PAIRS` hook), it finds the exact first time of impact of the two
        /// motions over the step — each body from its pose before the step to its pose after
        /// it, at constant velocity and constant spin (the turn unwrapped to the spin rapier
        /// integrated) — earliest first; stops both bodies at their poses at that
        /// time (velocities kept: the next step's solver resolves the contact, as after
        /// rapier's own CCD clamp), and checks the other pairs of a stopped body again with
        /// its shortened motion. A kinematic body is never stopped. Sensor pairs stop nothing:
        /// a crossing that neither end of the step sees is reported as a `Started` and a
        /// `Stopped` intersection event (with `ActiveEvents::COLLISION_EVENTS` on either
        /// collider, after the `FILTER_INTERSECTION_PAIR` hook), as rapier's CCD reports one.
        /// Disabled bodies and colliders, fixed bodies and bodies asleep at the start of the
        /// step take no part as moving bodies.
        ///
        /// **Bodies spun past rapier's regime** (`MovingPairsOptions::fixed_targets`, on by
        /// default). A fast body that turns by more than `MovingPairsOptions::fast_turn` (π/4,
        /// rapier's cap) in the step is also checked against the solid colliders rapier holds
        /// still — of no body, of a fixed body, of a body asleep — whose boxes meet its swept
        /// box, in the same event loop: its first contact on its own path stops it there,
        /// where rapier's sweep (which nlerps the turn the short way) may have left it inside
        /// a wall with contact points the solver sees leaving.
        ///
        /// **Cost.** `before_step` copies the pose of every awake dynamic or kinematic body;
        /// `after_step` compares them with the new poses, and stops there when no body is a
        /// fast body of the scope. Otherwise the pairs come from a sort and sweep of the fast
        /// bodies' swept boxes, O((k + n) log k) for k fast colliders among n moving ones,
        /// plus one time of impact per pair found; a step with a body past the turn also scans
        /// the collider set once for its still targets (O(n) box tests). No allocation once
        /// the buffers have grown to the scene.
        ///
        /// **Determinism.** The records follow the order of the body set and the pairs are
        /// sorted by collider, so two runs of the same scene give the same bits (with rapier's
        /// `parallel` feature too). The struct is `Send + Sync`.
        ///
        /// **Where it is not exact.** A body stopped by the pass is put on its constant-spin
        /// path, not on rapier's nlerp clamp path: for a body that also turns more than a
        /// small angle in the step, the pose differs from where rapier's own sweep against
        /// fixed geometry would have put it at that time (the end pose is the same, and the
        /// centre of mass is on the same segment: a centre never passes a wall). With
        /// `IntegrationParameters::max_ccd_substeps` above 1, the path of a step is still the
        /// straight one from its start to its end. Hooks and events are called from the
        /// calling thread.
        ///
        #[doc = $example]
        #[derive(Clone, Debug)]
        pub struct MovingPairs {
            options: MovingPairsOptions,
            dispatcher: $dispatcher,
            starts: Vec<(RigidBodyHandle, Pose)>,
            bodies: Vec<PassBody>,
            body_handles: Vec<RigidBodyHandle>,
            colliders: Vec<PassCollider>,
            collider_handles: Vec<ColliderHandle>,
            pairs: Vec<PassPair>,
            broad: Broad,
            schedule: Schedule,
            /// Each collider's CCD thickness by its handle's index: (generation, shape, thickness).
            thickness_cache: Vec<(u32, usize, f64)>,
        }

        /// The casts of the pass: the shapes of the colliders, the dispatcher.
        struct Caster<'a> {
            dispatcher: &'a $dispatcher,
            colliders: &'a ColliderSet,
            handles: &'a [ColliderHandle],
        }

        impl PairCast for Caster<'_> {
            fn cast(
                &mut self,
                c1: u32,
                m1: &$crate::__moving_pairs::NonlinearRigidMotion,
                c2: u32,
                m2: &$crate::__moving_pairs::NonlinearRigidMotion,
                t0: f64,
                t1: f64,
                sensor: bool,
            ) -> CastOutcome {
                let (Some(co1), Some(co2)) = (
                    self.colliders.get(self.handles[c1 as usize]),
                    self.colliders.get(self.handles[c2 as usize]),
                ) else {
                    return CastOutcome::Unsupported;
                };
                $b::cast(self.dispatcher, co1.shape(), m1, co2.shape(), m2, t0, t1, sensor)
            }
        }

        impl Default for MovingPairs {
            /// A pass with the default options.
            fn default() -> Self {
                MovingPairs::new(MovingPairsOptions::default())
            }
        }

        impl MovingPairs {
            /// A pass with these options (its dispatcher: the crate's, with
            /// `CastPolicy::RapierConstantSpin`).
            pub fn new(options: MovingPairsOptions) -> Self {
                MovingPairs {
                    options,
                    dispatcher: $b::dispatcher(),
                    starts: Vec::new(),
                    bodies: Vec::new(),
                    body_handles: Vec::new(),
                    colliders: Vec::new(),
                    collider_handles: Vec::new(),
                    pairs: Vec::new(),
                    broad: Broad::default(),
                    schedule: Schedule::default(),
                    thickness_cache: Vec::new(),
                }
            }

            /// The options.
            pub fn options(&self) -> &MovingPairsOptions {
                &self.options
            }

            /// The bodies the last [`MovingPairs::after_step`] stopped, each with the fraction of
            /// the step at which it stopped (its pose is its path's pose there: it moved over
            /// that part of the step and stood still after it).
            pub fn stops(&self) -> impl Iterator<Item = (RigidBodyHandle, f64)> + '_ {
                self.bodies
                    .iter()
                    .zip(&self.body_handles)
                    .filter(|(b, _)| b.stopped())
                    .map(|(b, h)| (*h, b.stop / b.path.dt))
            }

            /// Records the pose of every enabled, awake dynamic or kinematic body: the start of
            /// the step. Call it right before `PhysicsPipeline::step`.
            pub fn before_step(&mut self, bodies: &RigidBodySet) {
                self.starts.clear();
                for (h, rb) in bodies.iter() {
                    if rb.is_enabled() && !rb.is_fixed() && !rb.is_sleeping() {
                        self.starts.push((h, *rb.position()));
                    }
                }
            }

            /// The pass (the struct's docs), right after `PhysicsPipeline::step` with the same
            /// `params`, `hooks` and `events`: the bodies that have to stop are put at their
            /// poses at their first impact. Returns what it did, with its status.
            pub fn after_step(
                &mut self,
                params: &IntegrationParameters,
                bodies: &mut RigidBodySet,
                colliders: &mut ColliderSet,
                hooks: &dyn PhysicsHooks,
                events: &dyn EventHandler,
            ) -> MovingPairsReport {
                let mut report = MovingPairsReport::default();
                let dt = $b::real64(params.dt);
                if !(dt > 0.0 && dt.is_finite()) || self.starts.is_empty() {
                    report.status = PassStatus::Skipped;
                    self.starts.clear();
                    return report;
                }
                self.gather_bodies(dt, bodies, colliders, &mut report);
                self.pairs.clear();
                if report.fast_bodies > 0 {
                    self.gather_colliders(bodies, colliders);
                    if report.turning_bodies > 0 {
                        self.gather_targets(dt, bodies, colliders);
                    }
                    self.broad.pairs(&self.bodies, &self.colliders, &mut self.pairs);
                    self.filter_pairs(bodies, colliders, hooks);
                    report.pairs = self.pairs.len();
                    let mut caster = Caster {
                        dispatcher: &self.dispatcher,
                        colliders,
                        handles: &self.collider_handles,
                    };
                    self.schedule.run(
                        &mut self.bodies,
                        &self.colliders,
                        &mut self.pairs,
                        &mut caster,
                        &mut report,
                    );
                    self.sensor_events(bodies, colliders, events, &mut report);
                    self.apply(bodies, colliders);
                }
                self.starts.clear();
                report
            }

            /// Whether `rb` may be a fast body of the scope.
            fn in_scope(&self, rb: &RigidBody) -> bool {
                rb.is_dynamic() && (self.options.scope == PairScope::FastBodies || rb.is_ccd_enabled())
            }

            /// The bodies that moved, with their paths and whether they are fast.
            fn gather_bodies(
                &mut self,
                dt: f64,
                bodies: &RigidBodySet,
                colliders: &ColliderSet,
                report: &mut MovingPairsReport,
            ) {
                self.bodies.clear();
                self.body_handles.clear();
                // First the screen: the paths are built only when a body of the scope may be
                // fast (`may_be_fast`); a step with none costs a pose comparison a body.
                let mut any = false;
                for &(h, start) in &self.starts {
                    let Some(rb) = bodies.get(h).filter(|rb| rb.is_enabled() && !rb.is_fixed()) else {
                        continue;
                    };
                    if *rb.position() == start {
                        continue;
                    }
                    report.moving_bodies += 1;
                    if !any && self.in_scope(rb) {
                        let thickness = Self::thickness(&mut self.thickness_cache, rb, colliders);
                        any = may_be_fast(
                            &$b::pose64(&start),
                            &$b::pose64(rb.position()),
                            $b::vector64(rb.local_center_of_mass()),
                            $b::real64(rb.angvel()) * dt,
                            $b::real64(rb.mass_properties().max_extent()),
                            self.options.fast_fraction * thickness,
                        );
                    }
                }
                if !any {
                    return;
                }
                for &(h, start) in &self.starts {
                    let Some(rb) = bodies.get(h).filter(|rb| rb.is_enabled() && !rb.is_fixed()) else {
                        continue;
                    };
                    if *rb.position() == start {
                        continue;
                    }
                    let path = StepPath::new(
                        &$b::pose64(&start),
                        &$b::pose64(rb.position()),
                        $b::vector64(rb.local_center_of_mass()),
                        $b::vector64(rb.linvel()),
                        $b::real64(rb.angvel()),
                        dt,
                    );
                    let Some(path) = path.filter(|p| p.moves()) else {
                        report.refused_bodies += 1;
                        continue;
                    };
                    let reach = $b::real64(rb.mass_properties().max_extent());
                    let fast = self.in_scope(rb)
                        && path.max_point_travel(reach)
                            > self.options.fast_fraction * Self::thickness(&mut self.thickness_cache, rb, colliders);
                    report.fast_bodies += usize::from(fast);
                    let mut body = PassBody::new(path, fast, rb.is_dynamic(), reach);
                    // Past rapier's regime: its spin over the step (what rapier's sweep had to
                    // follow, whatever its clamp left of it) or the path's turn.
                    let spin_turn = ($b::real64(rb.angvel()) * dt).abs();
                    body.turning = fast
                        && rb.is_dynamic()
                        && self.options.fixed_targets
                        && spin_turn.max(path.turn().abs()) > self.options.fast_turn;
                    report.turning_bodies += usize::from(body.turning);
                    self.bodies.push(body);
                    self.body_handles.push(h);
                }
            }

            /// The thinnest `Shape::ccd_thickness` of the body's enabled colliders, each kept
            /// in a cache by collider (its handle and shape: a collider whose shape was
            /// replaced is measured again) — a user curve's thickness takes an integral.
            fn thickness(cache: &mut Vec<(u32, usize, f64)>, rb: &RigidBody, colliders: &ColliderSet) -> f64 {
                let mut thinnest = f64::INFINITY;
                for ch in rb.colliders() {
                    let Some(co) = colliders.get(*ch).filter(|co| co.is_enabled()) else {
                        continue;
                    };
                    let (index, generation) = ch.into_raw_parts();
                    let shape = co.shape() as *const dyn $rapier::geometry::Shape as *const u8 as usize;
                    let slot = index as usize;
                    if cache.len() <= slot {
                        cache.resize(slot + 1, (u32::MAX, 0, 0.0));
                    }
                    let cached = &mut cache[slot];
                    if cached.0 != generation || cached.1 != shape {
                        *cached = (generation, shape, $b::real64(co.shape().ccd_thickness()));
                    }
                    thinnest = thinnest.min(cached.2);
                }
                thinnest
            }

            /// The enabled colliders of the moving bodies, with their swept boxes.
            fn gather_colliders(&mut self, bodies: &RigidBodySet, colliders: &ColliderSet) {
                self.colliders.clear();
                self.collider_handles.clear();
                for (i, h) in self.body_handles.iter().enumerate() {
                    let rb = &bodies[*h];
                    let com = $b::vector64(rb.local_center_of_mass());
                    for ch in rb.colliders() {
                        let Some(co) = colliders.get(*ch).filter(|co| co.is_enabled()) else {
                            continue;
                        };
                        let local = co.position_wrt_parent().copied().unwrap_or(Pose::IDENTITY);
                        let sphere = co.shape().compute_bounding_sphere(&local);
                        let radius = ($b::vector64(sphere.center) - com).length() + $b::real64(sphere.radius);
                        let body = &mut self.bodies[i];
                        body.reach = body.reach.max(radius);
                        let c = PassCollider::new(i as u32, body, $b::pose64(&local), radius, co.is_sensor());
                        self.colliders.push(c);
                        self.collider_handles.push(*ch);
                    }
                }
            }

            /// The still targets of the turning bodies (`MovingPairsOptions::fixed_targets`):
            /// every enabled solid collider of no body, of a fixed body or of a body asleep
            /// whose box meets the box of the turning bodies' swept boxes, each a still body of
            /// its own at its pose. A scan of the collider set, done only in a step with a
            /// turning body.
            fn gather_targets(&mut self, dt: f64, bodies: &RigidBodySet, colliders: &ColliderSet) {
                let (mut lo, mut hi) = (
                    $crate::__moving_pairs::Vector::splat(f64::INFINITY),
                    $crate::__moving_pairs::Vector::splat(f64::NEG_INFINITY),
                );
                for c in &self.colliders {
                    if self.bodies[c.body as usize].turning {
                        lo = lo.min(c.min);
                        hi = hi.max(c.max);
                    }
                }
                for (ch, co) in colliders.iter_enabled() {
                    if co.is_sensor() {
                        continue;
                    }
                    let still = co
                        .parent()
                        .and_then(|h| bodies.get(h))
                        .is_none_or(|rb| rb.is_enabled() && (rb.is_fixed() || rb.is_sleeping()));
                    if !still {
                        continue;
                    }
                    let aabb = co.compute_aabb();
                    let (min, max) = ($b::vector64(aabb.mins), $b::vector64(aabb.maxs));
                    if !(min.x <= hi.x && lo.x <= max.x && min.y <= hi.y && lo.y <= max.y) {
                        continue;
                    }
                    let index = self.bodies.len() as u32;
                    self.bodies.push(PassBody::target(&$b::pose64(co.position()), dt));
                    self.body_handles
                        .push(co.parent().unwrap_or(RigidBodyHandle::invalid()));
                    self.colliders.push(PassCollider::target(index, min, max));
                    self.collider_handles.push(ch);
                }
            }

            /// Keeps the pairs rapier would make collide (solid) or report (sensors).
            fn filter_pairs(&mut self, bodies: &RigidBodySet, colliders: &ColliderSet, hooks: &dyn PhysicsHooks) {
                let handles = &self.collider_handles;
                self.pairs.retain_mut(|p| {
                    let (ch1, ch2) = (handles[p.a as usize], handles[p.b as usize]);
                    let (co1, co2) = (&colliders[ch1], &colliders[ch2]);
                    if !co1.collision_groups().test(co2.collision_groups()) {
                        return false;
                    }
                    let context = PairFilterContext {
                        bodies,
                        colliders,
                        collider1: ch1,
                        collider2: ch2,
                        rigid_body1: co1.parent(),
                        rigid_body2: co2.parent(),
                    };
                    let active_hooks = co1.active_hooks() | co2.active_hooks();
                    if co1.is_sensor() || co2.is_sensor() {
                        p.solid = false;
                        (co1.active_events() | co2.active_events()).contains(ActiveEvents::COLLISION_EVENTS)
                            && (!active_hooks.contains(ActiveHooks::FILTER_INTERSECTION_PAIR)
                                || hooks.filter_intersection_pair(&context))
                    } else {
                        co1.solver_groups().test(co2.solver_groups())
                            && (!active_hooks.contains(ActiveHooks::FILTER_CONTACT_PAIRS)
                                || hooks
                                    .filter_contact_pair(&context)
                                    .is_some_and(|f| f.contains(SolverFlags::COMPUTE_RIGID_IMPULSES)))
                    }
                });
            }

            /// The sensor crossings neither end of the step sees: a `Started` and a `Stopped`
            /// event each.
            fn sensor_events(
                &self,
                bodies: &RigidBodySet,
                colliders: &ColliderSet,
                events: &dyn EventHandler,
                report: &mut MovingPairsReport,
            ) {
                let mut caster = Caster {
                    dispatcher: &self.dispatcher,
                    colliders,
                    handles: &self.collider_handles,
                };
                for p in self.pairs.iter().filter(|p| !p.solid) {
                    if sensor_crossing(p, &self.bodies, &self.colliders, &mut caster, report).is_none() {
                        continue;
                    }
                    let (ca, cb) = (&self.colliders[p.a as usize], &self.colliders[p.b as usize]);
                    let (ba, bb) = (&self.bodies[ca.body as usize], &self.bodies[cb.body as usize]);
                    let (ch1, ch2) = (
                        self.collider_handles[p.a as usize],
                        self.collider_handles[p.b as usize],
                    );
                    let (g1, g2) = (colliders[ch1].shape(), colliders[ch2].shape());
                    let seen = |pa: $crate::__moving_pairs::Pose, pb: $crate::__moving_pairs::Pose| {
                        let pos12 = (pa * ca.local).inverse() * (pb * cb.local);
                        $b::intersects(&self.dispatcher, &pos12, g1, g2)
                    };
                    if seen(ba.path.pose_at(0.0), bb.path.pose_at(0.0)) || seen(ba.end_pose(), bb.end_pose()) {
                        continue;
                    }
                    for event in [
                        CollisionEvent::Started(ch1, ch2, CollisionEventFlags::SENSOR),
                        CollisionEvent::Stopped(ch1, ch2, CollisionEventFlags::SENSOR),
                    ] {
                        events.handle_collision_event(bodies, colliders, event, None);
                    }
                    report.sensor_events += 1;
                }
            }

            /// Puts every stopped body, and its colliders, at its pose where it stopped.
            fn apply(&self, bodies: &mut RigidBodySet, colliders: &mut ColliderSet) {
                for (body, h) in self.bodies.iter().zip(&self.body_handles) {
                    if body.stopped() {
                        if let Some(rb) = bodies.get_mut(*h) {
                            rb.set_position($b::pose_back(&body.end_pose()), false);
                        }
                    }
                }
                for (c, ch) in self.colliders.iter().zip(&self.collider_handles) {
                    let body = &self.bodies[c.body as usize];
                    if body.stopped() {
                        if let Some(co) = colliders.get_mut(*ch) {
                            co.set_position($b::pose_back(&(body.end_pose() * c.local)));
                        }
                    }
                }
            }
        }
    };
}
