//! Prints the stationary distance between the specification's two ellipses (object1 a1 = 0.5,
//! b1 = 0.8 at C1 = (−1.5, 0), angle 0.3; object2 a2 = 0.5, b2 = 2 at C2 = (1, 0.5), angle 1) with its
//! witness points, then the time of impact of the Appendix D scene (`tests/common/appendix_d.rs`).
//!
//! Run: `cargo run --release --example stationary`

#[path = "common/mod.rs"]
mod common;

use common::appendix_d::{heptagon_motion, impact, ANGVEL};
use parry2d_f64::math::{Pose, Vector};
use smooth_ccd2d::{stationary_distance, DistanceOptions, Ellipse};

fn main() {
    let e1 = Ellipse::new(0.5, 0.8);
    let e2 = Ellipse::new(0.5, 2.0);
    let pos1 = Pose::new(Vector::new(-1.5, 0.0), 0.3);
    let pos2 = Pose::new(Vector::new(1.0, 0.5), 1.0);
    let pos12 = pos1.inv_mul(&pos2);
    let d = stationary_distance(&e1, &e2, &pos12, &DistanceOptions::default()).expect("finite poses");
    println!("stationary distance between the specification's ellipses");
    println!("  distance      {:.15}", d.distance);
    println!(
        "  status        {:?} after {} Newton/Halley iterations, {} evaluations",
        d.status, d.newton_iterations, d.evaluations
    );
    println!("  witness 1     {:?} (world)", pos1 * d.point1);
    println!("  witness 2     {:?} (world)", pos2 * d.point2);
    println!("  normal 1      {:?} (world)", pos1.rotation * d.normal1);
    println!("  φ (object1)   {:.12} (normal angle)", d.phi);

    let r = impact();
    let p1 = heptagon_motion().position_at_time(r.time);
    println!("\nAppendix D: heptagon spinning at 30 rad/s against an ellipse");
    println!("  status        {:?}", r.status);
    println!(
        "  time          {:.15} s ({:.3} turns)",
        r.time,
        ANGVEL * r.time / std::f64::consts::TAU
    );
    println!("  contact point {:?} (world)", p1 * r.point1);
    println!(
        "  normal        {:?} (world, out of the heptagon)",
        p1.rotation * r.normal1
    );
    println!("  cost          {:?}", r.cost);
}
