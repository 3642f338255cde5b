//! Composite shapes on either side of a query: parry2d's composite helpers with this package's
//! [`crate::SmoothDispatcher`] answering every sub-pair. The text is `smooth-ccd2d`'s own
//! (its hidden `composite_helpers!` macro), instantiated here for parry2d.

smooth_ccd2d::composite_helpers!(parry2d, crate::SmoothDispatcher);

impl crate::SmoothDispatcher {
    /// The target distance and the distance tolerance of the dispatcher's casts (those of its
    /// core), in f32: the options the culling of a composite's parts reads (`hit_level` of
    /// `composite_helpers!`).
    pub(crate) fn composite_cast_levels(&self) -> (Real, Real) {
        let o = &self.core.toi_options;
        (o.target_distance as Real, o.distance_tolerance as Real)
    }

    /// Whether the dispatcher's casts take an oriented polyline as rapier's CCD does, one-sided
    /// (its core's policy, `smooth_ccd2d::CastPolicy::is_rapier`).
    pub(crate) fn composite_one_sided(&self) -> bool {
        self.core.cast_policy.is_rapier()
    }
}
