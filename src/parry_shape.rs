//! parry `Shape` implementations for the crate's shapes (in progress).
