//! Composite shapes on either side of a query: parry2d's composite helpers with this package's
//! [`crate::SmoothDispatcher`] answering every sub-pair. The text is `smooth-ccd2d`'s own
//! (its hidden `composite_helpers!` macro), instantiated here for parry2d.

smooth_ccd2d::composite_helpers!(parry2d, crate::SmoothDispatcher);
