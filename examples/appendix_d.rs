//! The specification's Appendix D scene inside rapier: a rounded regular heptagon (circumradius 1,
//! corner radius 0.15) starting at (−1.85, 0), spinning at 30 rad/s and drifting at (2, 0) m/s,
//! against a fixed ellipse (a = 0.5, b = 1.5) at the origin; no gravity, CCD on, 60 Hz, narrow
//! phase `SmoothDispatcher`.
//!
//! Prints the step of first contact, then compares the heptagon's pose where rapier's CCD clamped
//! it with the exact impact of [`smooth_ccd2d::time_of_impact`] (t ≈ 0.1128168 s). rapier clamps
//! the body on its own interpolation between the start and end poses of the step (centre of mass
//! lerped, rotation nlerped), not on the constant-spin motion the time of impact is computed on.
//!
//! Run: `cargo run --release --example appendix_d [output folder]` (default `target/examples-out`);
//! writes `appendix_d.svg` (the heptagon at every step until the impact).

#[path = "common/mod.rs"]
mod common;

use common::{out_dir, outline, Panel, Scene, Svg};
use parry2d_f64::query::NonlinearRigidMotion;
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{
    stationary_distance, time_of_impact, DistanceOptions, Ellipse, RoundedPolygon, SmoothDispatcher, ToiOptions,
};

const DT: f64 = 1.0 / 60.0;
const STEPS: usize = 10;

fn main() {
    let dir = out_dir();
    let hept = RoundedPolygon::regular(7, 1.0, 0.15);
    let ell = Ellipse::new(0.5, 1.5);
    let (start, linvel, angvel) = (Vector::new(-1.85, 0.0), Vector::new(2.0, 0.0), 30.0);

    // The exact impact.
    let m1 = NonlinearRigidMotion::new(Pose::new(start, 0.0), Vector::ZERO, linvel, angvel);
    let m2 = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    let exact = time_of_impact(&hept, &m1, &ell, &m2, 0.0, 1.0, &ToiOptions::default()).expect("finite motions");
    let exact_pose = m1.position_at_time(exact.time);

    // rapier.
    let mut scene = Scene::new(
        NarrowPhase::with_query_dispatcher(SmoothDispatcher::default()),
        Vector::ZERO,
    );
    scene.params.dt = DT;
    let (_, c_ell) = scene.insert(RigidBodyBuilder::fixed(), ColliderBuilder::new(SharedShape::new(ell)));
    let (h, c_hept) = scene.insert(
        RigidBodyBuilder::dynamic()
            .translation(start)
            .linvel(linvel)
            .angvel(angvel)
            .ccd_enabled(true)
            .can_sleep(false),
        ColliderBuilder::new(SharedShape::new(hept.clone())),
    );

    let signed = |pose: &Pose| {
        stationary_distance(&hept, &ell, &pose.inverse(), &DistanceOptions::default())
            .expect("finite poses")
            .distance
    };
    println!("Appendix D in rapier (dt = 1/60 s, CCD on, SmoothDispatcher)");
    println!(
        "exact time of impact (time_of_impact): t = {:.10} s, status {:?}, i.e. during step {} (steps numbered from 1)",
        exact.time,
        exact.status,
        (exact.time / DT).floor() as usize + 1
    );
    println!(
        "fraction: share of the step travelled (while the velocity is unchanged); signed dist: exact, at the \
         end-of-step pose; contacts: manifold points of the pair (narrow phase, start-of-step poses; act: active)"
    );
    println!(
        "{:>4} {:>9} {:>11} {:>11} {:>10} {:>13} {:>9} {:>8}",
        "step", "t end", "centre x", "angle", "fraction", "signed dist", "contacts", "linvel x"
    );
    let mut poses = vec![*scene.bodies[h].position()];
    let mut clamp: Option<(usize, f64, Pose)> = None;
    let mut first_contact: Option<usize> = None;
    for k in 1..=STEPS {
        let before = *scene.bodies[h].position();
        let v = scene.bodies[h].linvel();
        scene.step();
        let after = *scene.bodies[h].position();
        poses.push(after);
        // CCD clamps the pose only, keeping the velocity: while the velocity is unchanged (no
        // contact impulse), the fraction of the step actually travelled tells whether (and
        // where) it clamped.
        let same_velocity = scene.bodies[h].linvel() == v;
        let fraction = (after.translation.x - before.translation.x) / (v.x * DT);
        let contacts = scene
            .narrow_phase
            .contact_pair(c_ell, c_hept)
            .map_or(0, |p| p.manifolds().iter().map(|m| m.points.len()).sum::<usize>());
        let touching = scene
            .narrow_phase
            .contact_pair(c_ell, c_hept)
            .is_some_and(|p| p.has_any_active_contact());
        let d = signed(&after);
        println!(
            "{k:>4} {:>9.6} {:>11.7} {:>11.7} {:>10} {d:>13.3e} {:>9} {:>8.4}",
            k as f64 * DT,
            after.translation.x,
            after.rotation.angle(),
            if same_velocity {
                format!("{fraction:.7}")
            } else {
                "-".into()
            },
            format!("{contacts}{}", if touching { " act" } else { "" }),
            scene.bodies[h].linvel().x
        );
        if clamp.is_none() && same_velocity && fraction < 1.0 - 1e-9 {
            clamp = Some((k, fraction, after));
        }
        if first_contact.is_none() && (touching || d <= 1e-9 || clamp.is_some()) {
            first_contact = Some(k);
        }
    }
    match first_contact {
        Some(k) => println!(
            "first contact at step {k} (t in [{:.6}, {:.6}] s)",
            (k - 1) as f64 * DT,
            k as f64 * DT
        ),
        None => println!("no contact in {STEPS} steps"),
    }
    if let Some((k, f, pose)) = clamp {
        let t = (k as f64 - 1.0 + f) * DT;
        let on_motion = m1.position_at_time(t);
        println!("CCD clamp in step {k}: fraction {f:.9}, clamped time t = {t:.10} s");
        // rapier integrates the rotation in 4 substeps of atan(ω·dt/4) each, and its CCD sweeps
        // with the effective velocities of the step (pose change / dt).
        if k >= 2 {
            let spin = (poses[k - 1].rotation.angle() - poses[k - 2].rotation.angle()) / DT;
            let mm = NonlinearRigidMotion::new(poses[k - 1], Vector::ZERO, linvel, spin);
            let r = time_of_impact(&hept, &mm, &ell, &m2, 0.0, DT, &ToiOptions::default()).expect("finite motions");
            println!(
                "  rapier's effective spin {spin:.7} rad/s (30 asked); time_of_impact on rapier's own step motion: \
                 fraction {:.9} (clamp - it {:+.1e})",
                r.time / DT,
                f - r.time / DT
            );
            let on_step = mm.position_at_time(r.time);
            println!(
                "  that motion's pose at the impact: angle {:.9} rad, signed distance {:+.3e}; rapier's clamp \
                 (nlerp between the step's end poses) differs by {:+.3e} rad",
                on_step.rotation.angle(),
                signed(&on_step),
                pose.rotation.angle() - on_step.rotation.angle()
            );
        }
        println!("  time error vs exact impact   {:+.3e} s", t - exact.time);
        println!(
            "  pose at the clamp (rapier)   centre ({:.9}, {:.9}), angle {:.9} rad; signed distance {:+.3e}",
            pose.translation.x,
            pose.translation.y,
            pose.rotation.angle(),
            signed(&pose)
        );
        println!(
            "  exact pose at impact         centre ({:.9}, {:.9}), angle {:.9} rad; signed distance {:+.3e}",
            exact_pose.translation.x,
            exact_pose.translation.y,
            exact_pose.rotation.angle(),
            signed(&exact_pose)
        );
        println!(
            "  specification's motion (30 rad/s) at the clamped time: angle {:.9} rad (rapier differs by {:+.3e} rad)",
            on_motion.rotation.angle(),
            pose.rotation.angle() - on_motion.rotation.angle()
        );
        println!(
            "  |centre difference| vs exact {:.3e} m, angle difference {:+.3e} rad",
            (pose.translation - exact_pose.translation).length(),
            pose.rotation.angle() - exact_pose.rotation.angle()
        );
    } else {
        println!("rapier's CCD did not clamp the heptagon in {STEPS} steps");
    }

    // Picture: the ellipse, the heptagon at every step until the impact (the clamp, or the first
    // contact), and the exact impact pose with its contact point.
    let last = clamp.map(|c| c.0).or(first_contact).unwrap_or(STEPS);
    let p = Panel::fit(20.0, 40.0, 560.0, -3.2, 1.2, -2.0, 2.0);
    let mut svg = Svg::new(600.0, p.height + 60.0);
    svg.text(
        20.0,
        22.0,
        13.0,
        "Appendix D in rapier: steps of 1/60 s (grey), CCD clamp (blue), exact impact (red)",
    );
    svg.begin_panel(&p, "");
    let ell_pts = outline(&ell, &Pose::IDENTITY, 256);
    svg.polyline(&p, &ell_pts, true, "#333", 1.0, "#e8e8e8");
    for (k, pose) in poses.iter().enumerate().take(last + 1) {
        let (stroke, w) = if k == last && clamp.is_some() {
            ("#1f77b4", 1.4)
        } else {
            ("#999", 0.7)
        };
        svg.polyline(&p, &outline(&hept, pose, 256), true, stroke, w, "none");
        svg.circle(&p, pose.translation, 1.5, stroke);
    }
    svg.polyline(&p, &outline(&hept, &exact_pose, 256), true, "#d62728", 1.0, "none");
    svg.circle(&p, exact_pose * exact.point1, 3.0, "#d62728");
    svg.end_panel();
    let path = dir.join("appendix_d.svg");
    svg.save(&path);
    println!("wrote {}", path.display());
}
