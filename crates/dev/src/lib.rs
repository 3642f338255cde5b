//! Dev-only member of the smooth-ccd2d workspace (never published): the targets whose
//! dependencies are heavy — the benches of the root's `benches/` (criterion), the proptest tests
//! (`tests/adversarial.rs`, `tests/properties.rs`) and the figures (`examples/figures.rs`,
//! `tests/figures.rs`: plotters, image, DejaVu). The library itself is empty.
