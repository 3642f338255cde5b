//! Resting quality in rapier (`tests/common/resting.rs`): a stack of 10 rounded boxes, a stack of
//! 10 ellipses lying flat and a rounded hexagon on a 20° slope, started at rest and stepped for
//! 10 s, with the exact shapes and `SmoothDispatcher` against parry's `RoundConvexPolygon` /
//! inscribed 64-gons with parry's default dispatcher (given the exact shapes' mass properties, so
//! that only the contacts differ). `cargo test --test resting -- --nocapture` prints the tables
//! (`cargo run --release --example resting` adds parry's own mass properties and the pile).

mod common;

use common::resting::{rest_table, run_scene, RestReport, RestScene, RestVariant, REST_STEPS};

/// The most the exact variant's measure may exceed parry's (both as magnitudes, m): 10 % of
/// parry's, and at least 10⁻⁴ m in all (for measures that are about 0 in both).
fn allowed(parry: f64) -> f64 {
    (1.1 * parry.abs()).max(1e-4)
}

/// The comparisons of one scene: (what, exact, parry), as magnitudes.
fn comparisons(exact: &RestReport, parry: &RestReport) -> Vec<(&'static str, f64, f64)> {
    let mut v = vec![
        ("max drift", exact.drift, parry.drift),
        ("max horizontal drift", exact.horizontal_drift, parry.horizontal_drift),
        (
            "worst penetration, exact",
            exact.worst_exact.abs(),
            parry.worst_exact.abs(),
        ),
        (
            "worst penetration, manifolds",
            exact.worst_manifold.abs(),
            parry.worst_manifold.abs(),
        ),
    ];
    if exact.scene == RestScene::Slope {
        v.push(("slope slide", exact.slope_slide.abs(), parry.slope_slide.abs()));
    }
    v
}

#[test]
fn exact_shapes_rest_with_no_more_drift_or_penetration_than_parry_stand_ins_and_do_not_topple() {
    let mut failures = Vec::new();
    for recycling in [true, false] {
        let mut reports = Vec::new();
        for scene in RestScene::ALL {
            let exact = run_scene(scene, RestVariant::Exact, REST_STEPS, recycling);
            let parry = run_scene(scene, RestVariant::Parry, REST_STEPS, recycling);
            // The flat ellipse stack is balanced but unstable (tests/common/resting.rs): with every
            // contact recomputed every step (recycling off), rounding grows until the stack sways
            // and falls, in both variants (the exact one sways from about 6 s and falls at about
            // 11 s, parry's 64-gons fall at about 3 s). That run is no longer a resting scene:
            // printed, not compared.
            if scene == RestScene::EllipseStack && !recycling {
                reports.push(exact);
                reports.push(parry);
                continue;
            }
            for (what, e, p) in comparisons(&exact, &parry) {
                if e > allowed(p) {
                    failures.push(format!(
                        "{} (recycling {recycling}): {what} {e:.3e} m, parry's {p:.3e} m, allowed {:.3e} m",
                        scene.label(),
                        allowed(p)
                    ));
                }
            }
            if exact.toppled {
                failures.push(format!("{} (recycling {recycling}): toppled", scene.label()));
            }
            reports.push(exact);
            reports.push(parry);
        }
        println!(
            "\ncontact recycling {}:\n\n{}",
            if recycling { "on (rapier's default)" } else { "off" },
            rest_table(&reports)
        );
    }
    assert!(failures.is_empty(), "{failures:#?}");
}
