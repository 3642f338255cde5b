#[path = "common/mod.rs"]
mod common;
use common::ccd_scenes::*;
use rapier2d_f64::prelude::*;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let fam = Family::ALL.into_iter().find(|f| f.name().replace(' ', "-") == args[1]).unwrap();
    let body = Body::ALL.into_iter().find(|b| b.name().replace(' ', "-") == args[2]).unwrap();
    let speed: f64 = args[3].parse().unwrap();
    let spin: f64 = args[4].parse().unwrap();
    let method = if args.get(5).map(|s| s.as_str()) == Some("rapier") { Method::Rapier } else { Method::Smooth };
    let variant = SPINS.iter().position(|s| *s == spin).unwrap_or(0);
    let case = Case { family: fam, body, speed, spin, variant };
    let mut scene = build(&case, method);
    let h = scene.dynamic[0];
    for step in 0..scene.steps.min(args.get(6).map(|s| s.parse().unwrap()).unwrap_or(40)) {
        drive(&mut scene, step);
        scene.world.step(scene.gravity, &());
        let rb = &scene.world.bodies[h];
        for pair in scene.world.narrow_phase.contact_pairs() {
            for m in pair.manifolds() {
                println!("     manifold n={:?} solver={} flags={:?} pts={:?}", m.data.normal, m.data.solver_contacts.len(), m.data.solver_flags, m.points.iter().map(|p| (p.dist, p.local_p1)).collect::<Vec<_>>());
            }
        }
        println!("{step:3} c=({:.5},{:.5}) a={:.4} v=({:.3},{:.3}) w={:.3} ccd={}", rb.center_of_mass().x, rb.center_of_mass().y, rb.rotation().angle(), rb.linvel().x, rb.linvel().y, rb.angvel(), rb.is_ccd_active());
    }
}
