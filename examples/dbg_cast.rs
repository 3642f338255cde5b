#[path = "common/mod.rs"]
mod common;
use common::ccd_scenes::*;
use parry2d_f64::query::details::NormalConstraints;
use parry2d_f64::query::{ClosestPoints, Contact, ContactManifold, ContactManifoldsWorkspace, NonlinearRigidMotion,
    PersistentQueryDispatcher, QueryDispatcher, ShapeCastHit, ShapeCastOptions, ShapeDistance, ShapeIntersection, Unsupported};
use parry2d_f64::query::sweep_toi::Sweep;
use rapier2d_f64::prelude::*;
use smooth_ccd2d::SmoothDispatcher;

struct Log(SmoothDispatcher);
impl QueryDispatcher for Log {
    fn intersection_test(&self, p: &Pose, a: &dyn Shape, b: &dyn Shape) -> Result<ShapeIntersection, Unsupported> { self.0.intersection_test(p, a, b) }
    fn distance(&self, p: &Pose, a: &dyn Shape, b: &dyn Shape) -> Result<ShapeDistance, Unsupported> { self.0.distance(p, a, b) }
    fn contact(&self, p: &Pose, a: &dyn Shape, b: &dyn Shape, pr: Real) -> Result<Option<Contact>, Unsupported> { self.0.contact(p, a, b, pr) }
    fn closest_points(&self, p: &Pose, a: &dyn Shape, b: &dyn Shape, m: Real) -> Result<ClosestPoints, Unsupported> { self.0.closest_points(p, a, b, m) }
    fn cast_shapes(&self, p: &Pose, v: Vector, a: &dyn Shape, b: &dyn Shape, o: ShapeCastOptions) -> Result<Option<ShapeCastHit>, Unsupported> { self.0.cast_shapes(p, v, a, b, o) }
    fn cast_shapes_nonlinear(&self, m1: &NonlinearRigidMotion, g1: &dyn Shape, m2: &NonlinearRigidMotion, g2: &dyn Shape, t0: Real, t1: Real, stop: bool) -> Result<Option<ShapeCastHit>, Unsupported> {
        let r = self.0.cast_shapes_nonlinear(m1, g1, m2, g2, t0, t1, stop);
        if std::env::var("QUIET").is_err() {
        println!("   cast {:?} vs {:?} v={:?} w={:.3} -> {:?}", g1.shape_type(), g2.shape_type(), m1.linvel, m1.angvel, r.as_ref().map(|h| h.map(|h| (h.time_of_impact / (t1 - t0), h.status))));
        let sw = |m: &NonlinearRigidMotion| Sweep::from_poses(&m.position_at_time(t0), &m.position_at_time(t1), m.local_center);
        let (s1, s2) = (sw(m1), sw(m2));
        let mut line = String::new();
        for k in 0..=10 { let s = k as f64 / 10.0; let p12 = s1.transform_at(s).inv_mul(&s2.transform_at(s));
            let d = self.0.contact(&p12, g1, g2, 10.0).ok().flatten().map(|c| c.dist).unwrap_or(f64::NAN);
            line += &format!(" {:.4}", d); }
        println!("     d(s): {line}");
        }
        r
    }
}
impl<M: Default + Clone + Send + Sync, C: Default + Copy + Send + Sync> PersistentQueryDispatcher<M, C> for Log {
    fn contact_manifolds(&self, p: &Pose, a: &dyn Shape, b: &dyn Shape, pr: Real, m: &mut Vec<ContactManifold<M, C>>, w: &mut Option<ContactManifoldsWorkspace>) -> Result<(), Unsupported> { self.0.contact_manifolds(p, a, b, pr, m, w) }
    fn contact_manifold_convex_convex(&self, p: &Pose, a: &dyn Shape, b: &dyn Shape, n1: Option<&dyn NormalConstraints>, n2: Option<&dyn NormalConstraints>, pr: Real, m: &mut ContactManifold<M, C>) -> Result<(), Unsupported> { self.0.contact_manifold_convex_convex(p, a, b, n1, n2, pr, m) }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let fam = Family::ALL.into_iter().find(|f| f.name().replace(' ', "-") == args[1]).unwrap();
    let body = Body::ALL.into_iter().find(|b| b.name().replace(' ', "-") == args[2]).unwrap();
    let speed: f64 = args[3].parse().unwrap();
    let spin: f64 = args[4].parse().unwrap();
    let variant = SPINS.iter().position(|s| *s == spin).unwrap_or(0);
    let case = Case { family: fam, body, speed, spin, variant };
    let mut scene = build(&case, Method::Smooth);
    scene.world.narrow_phase = NarrowPhase::with_query_dispatcher(Log(SmoothDispatcher::default()));
    let h = scene.dynamic[0];
    let from: usize = args.get(5).map(|s| s.parse().unwrap()).unwrap_or(0);
    let to: usize = args.get(6).map(|s| s.parse().unwrap()).unwrap_or(40);
    for step in 0..to {
        if step < from { unsafe { std::env::set_var("QUIET", "1"); } } else { unsafe { std::env::remove_var("QUIET"); } }
        drive(&mut scene, step);
        scene.world.step(scene.gravity, &());
        if step < from { continue; }
        for pair in scene.world.narrow_phase.contact_pairs() {
            for m in pair.manifolds() {
                println!("     manifold n={:?} solver={:?} pts={:?}", m.data.normal, m.data.solver_contacts.iter().map(|s| s.dist).collect::<Vec<_>>(), m.points.iter().map(|p| (p.dist, p.data.impulse)).collect::<Vec<_>>());
            }
        }
        let rb = &scene.world.bodies[h];
        println!("{step:3} c=({:.5},{:.5}) a={:.4} v=({:.3},{:.3}) w={:.3}", rb.center_of_mass().x, rb.center_of_mass().y, rb.rotation().angle(), rb.linvel().x, rb.linvel().y, rb.angvel());
    }
}
