use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{ContactManifold, PersistentQueryDispatcher};
use parry2d_f64::shape::Cuboid;
use smooth_ccd2d::{RoundedPolygon, SmoothDispatcher};
fn main() {
    let plank = Cuboid::new(Vector::new(20.0, 0.025));
    let sq = RoundedPolygon::regular(4, 0.35, 0.0);
    let pos12 = Pose::new(Vector::new(0.48049, 0.08687), 0.9166);
    let d = SmoothDispatcher::default();
    let mut ms: Vec<ContactManifold<(), ()>> = vec![];
    let mut ws = None;
    d.contact_manifolds(&pos12, &plank, &sq, 0.002, &mut ms, &mut ws).unwrap();
    for m in &ms { println!("n={:?}", m.local_n1); for p in &m.points { println!("  {:?} {:?} {}", p.local_p1, p.local_p2, p.dist); } }
}
