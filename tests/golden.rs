//! Golden digests: the bits of every answer the crate gives on a fixed batch of inputs, recorded
//! once and compared on every run. A change meant to preserve behaviour (a refactor, a move of
//! code between modules) must leave every digest here unchanged; a change of behaviour shows
//! which class of inputs it touched, and the new digests are recorded with it, saying why.
//!
//! * The fuzz batch of `tests/adversarial.rs` (seed `0x7_5EED`, 40,000 cases): every query of
//!   the crate on each case (`reliability::run_case`), FNV-1a over the bits of every number and
//!   status returned, combined per scenario class.
//! * rapier: the final state of `scenes::mixed_pile` (153 bodies, fast CCD shots) after 250 steps
//!   with `SmoothDispatcher` as the narrow phase, on one worker (FNV-1a over the bits of every
//!   body's pose and velocities).
//!
//! Run with `cargo test --test golden -- --nocapture` to see the digests.

mod common;
mod reliability;

use common::scenes::mixed_pile;
use common::world::{state_hash, World, GRAVITY};
use rapier2d_f64::prelude::*;
use reliability::{generate, run_case, CLASSES};
use smooth_ccd2d::SmoothDispatcher;
use std::collections::BTreeMap;

/// The fuzz batch of `tests/adversarial.rs`.
const FUZZ_SEED: u64 = 0x0007_5EED;
const FUZZ_CASES: u64 = 40_000;

/// Digest per scenario class of the fuzz batch, recorded on the layout before issue 19's move
/// (commit 'Golden digests ...').
const FUZZ_DIGESTS: [(&str, u64); 9] = [
    ("coincident", 0xC4ACE59A8E8DD5F1),
    ("concentric", 0x6DB60D8F4E5BAD90),
    ("extreme-scale", 0xB238112E1CF1738A),
    ("grazing", 0xB0A1F1147626216B),
    ("parry-pair", 0x674E0BAE1AE42D0D),
    ("random", 0x7C2023CEF18FB330),
    ("thin-ellipse", 0xF94A2D3B271CD5C4),
    ("touching-at-t0", 0x75395A6AA9B826CC),
    ("wild", 0xF8CC341763794CAE),
];

/// Final-state hash of the rapier scene.
const RAPIER_STATE: u64 = 0x97F3_2395_5B85_4751;

/// FNV-1a of a sequence of words.
fn fnv(words: impl IntoIterator<Item = u64>) -> u64 {
    let mut h = 0xCBF2_9CE4_8422_2325u64;
    for w in words {
        for b in w.to_le_bytes() {
            h ^= b as u64;
            h = h.wrapping_mul(0x100_0000_01B3);
        }
    }
    h
}

#[test]
fn fuzz_batch_answers_keep_their_recorded_bits() {
    let mut per_class: BTreeMap<&str, Vec<u64>> = BTreeMap::new();
    for i in 0..FUZZ_CASES {
        let case = generate(FUZZ_SEED, i);
        per_class.entry(case.class).or_default().push(run_case(&case).digest);
    }
    println!("golden: fuzz batch of {FUZZ_CASES} cases (seed {FUZZ_SEED:#x}), digest per class:");
    let got: Vec<(&str, u64)> = per_class.iter().map(|(k, v)| (*k, fnv(v.iter().copied()))).collect();
    for (class, d) in &got {
        println!("    (\"{class}\", 0x{d:016X}),");
    }
    assert_eq!(got.len(), CLASSES.len(), "every class of the batch is digested");
    let recorded: Vec<(&str, u64)> = FUZZ_DIGESTS.to_vec();
    assert_eq!(got, recorded, "the answers of the fuzz batch changed");
}

#[test]
fn rapier_scene_final_state_keeps_its_recorded_bits() {
    const STEPS: usize = 250;
    let mut w = World::new(NarrowPhase::with_query_dispatcher(SmoothDispatcher::default()));
    w.pipeline.configure_thread_pool(1).expect("thread pool");
    let handles = mixed_pile(&mut w);
    for _ in 0..STEPS {
        w.step(GRAVITY, &());
    }
    let (hash, _) = state_hash(&w, &handles);
    println!(
        "golden: rapier scene, {} bodies, {STEPS} steps, final-state hash 0x{hash:016X}",
        handles.len()
    );
    assert_eq!(hash, RAPIER_STATE, "rapier's final state changed");
}
