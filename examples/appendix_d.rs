//! The specification's Appendix D scene inside rapier: a rounded regular heptagon (circumradius 1,
//! corner radius 0.15) starting at (−1.85, 0), spinning at 30 rad/s and drifting at (2, 0) m/s,
//! against a fixed ellipse (a = 0.5, b = 1.5) at the origin; no gravity, CCD on, 60 Hz, narrow
//! phase `SmoothDispatcher`. The scene is `tests/common/appendix_d.rs`.
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

use common::appendix_d::{ellipse, ellipse_motion, heptagon, heptagon_motion, impact, ANGVEL, LINVEL, START};
use common::world::World;
use common::{out_dir, outline, Panel, Svg};
use parry2d_f64::query::NonlinearRigidMotion;
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{stationary_distance, time_of_impact, DistanceOptions, SmoothDispatcher, TimeOfImpact, ToiOptions};

const DT: f64 = 1.0 / 60.0;
const STEPS: usize = 10;

/// The scene in rapier: the world, the heptagon's body, the ellipse's and the heptagon's colliders.
fn rapier_scene() -> (World, RigidBodyHandle, ColliderHandle, ColliderHandle) {
    let mut world = World::new(NarrowPhase::with_query_dispatcher(SmoothDispatcher::default()));
    world.params.dt = DT;
    let (_, c_ell) = world.insert(
        RigidBodyBuilder::fixed(),
        ColliderBuilder::new(SharedShape::new(ellipse())),
    );
    let (h, c_hept) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(START)
            .linvel(LINVEL)
            .angvel(ANGVEL)
            .ccd_enabled(true)
            .can_sleep(false),
        ColliderBuilder::new(SharedShape::new(heptagon())),
    );
    (world, h, c_ell, c_hept)
}

/// The exact signed distance of the heptagon at `pose` to the ellipse.
fn signed(pose: &Pose) -> f64 {
    stationary_distance(&heptagon(), &ellipse(), &pose.inverse(), &DistanceOptions::default())
        .expect("finite poses")
        .distance
}

/// What the steps showed: the heptagon's pose at the start and after each step, the CCD clamp
/// (step, fraction of the step travelled, pose) and the step of first contact.
struct Steps {
    poses: Vec<Pose>,
    clamp: Option<(usize, f64, Pose)>,
    first_contact: Option<usize>,
}

fn print_header(exact: &TimeOfImpact) {
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
}

/// Steps the scene [`STEPS`] times, printing a row per step.
fn run_steps() -> Steps {
    let (mut world, h, c_ell, c_hept) = rapier_scene();
    let mut steps = Steps {
        poses: vec![*world.bodies[h].position()],
        clamp: None,
        first_contact: None,
    };
    for k in 1..=STEPS {
        let before = *world.bodies[h].position();
        let v = world.bodies[h].linvel();
        world.step(Vector::ZERO, &());
        let after = *world.bodies[h].position();
        steps.poses.push(after);
        // CCD clamps the pose only, keeping the velocity: while the velocity is unchanged (no
        // contact impulse), the fraction of the step actually travelled tells whether (and
        // where) it clamped.
        let same_velocity = world.bodies[h].linvel() == v;
        let fraction = (after.translation.x - before.translation.x) / (v.x * DT);
        let pair = world.narrow_phase.contact_pair(c_ell, c_hept);
        let contacts = pair.map_or(0, |p| p.manifolds().iter().map(|m| m.points.len()).sum::<usize>());
        let touching = pair.is_some_and(|p| p.has_any_active_contact());
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
            world.bodies[h].linvel().x
        );
        if steps.clamp.is_none() && same_velocity && fraction < 1.0 - 1e-9 {
            steps.clamp = Some((k, fraction, after));
        }
        if steps.first_contact.is_none() && (touching || d <= 1e-9 || steps.clamp.is_some()) {
            steps.first_contact = Some(k);
        }
    }
    steps
}

/// The time of impact on rapier's own motion of clamp step `k` (its effective spin: rapier
/// integrates the rotation in 4 substeps of atan(ω·dt/4) each, and its CCD sweeps with the
/// effective velocities of the step, pose change / dt), against the clamp at `f`, `pose`.
fn report_rapier_motion(poses: &[Pose], k: usize, f: f64, pose: &Pose) {
    let spin = (poses[k - 1].rotation.angle() - poses[k - 2].rotation.angle()) / DT;
    let mm = NonlinearRigidMotion::new(poses[k - 1], Vector::ZERO, LINVEL, spin);
    let r = time_of_impact(
        &heptagon(),
        &mm,
        &ellipse(),
        &ellipse_motion(),
        0.0,
        DT,
        &ToiOptions::default(),
    )
    .expect("finite motions");
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

/// The clamp in step `k` at fraction `f` (pose `pose`) against the exact impact.
fn report_clamp(poses: &[Pose], (k, f, pose): (usize, f64, Pose), exact: &TimeOfImpact) {
    let m1 = heptagon_motion();
    let exact_pose = m1.position_at_time(exact.time);
    let t = (k as f64 - 1.0 + f) * DT;
    let on_motion = m1.position_at_time(t);
    println!("CCD clamp in step {k}: fraction {f:.9}, clamped time t = {t:.10} s");
    if k >= 2 {
        report_rapier_motion(poses, k, f, &pose);
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
}

/// The picture: the ellipse, the heptagon at every step until the impact (the clamp, or the first
/// contact), and the exact impact pose with its contact point.
fn draw(steps: &Steps, exact: &TimeOfImpact, path: &std::path::Path) {
    let (hept, ell) = (heptagon(), ellipse());
    let exact_pose = heptagon_motion().position_at_time(exact.time);
    let last = steps.clamp.map(|c| c.0).or(steps.first_contact).unwrap_or(STEPS);
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
    for (k, pose) in steps.poses.iter().enumerate().take(last + 1) {
        let (stroke, w) = if k == last && steps.clamp.is_some() {
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
    svg.save(path);
}

fn main() {
    let dir = out_dir();
    let exact = impact();
    print_header(&exact);
    let steps = run_steps();
    match steps.first_contact {
        Some(k) => println!(
            "first contact at step {k} (t in [{:.6}, {:.6}] s)",
            (k - 1) as f64 * DT,
            k as f64 * DT
        ),
        None => println!("no contact in {STEPS} steps"),
    }
    match steps.clamp {
        Some(clamp) => report_clamp(&steps.poses, clamp, &exact),
        None => println!("rapier's CCD did not clamp the heptagon in {STEPS} steps"),
    }
    let path = dir.join("appendix_d.svg");
    draw(&steps, &exact, &path);
    println!("wrote {}", path.display());
}
