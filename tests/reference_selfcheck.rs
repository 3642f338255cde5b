//! Checks of the test reference itself (tests/common): its distance and time of impact against
//! closed forms, its internal consistency on random scenarios, and the scenario generators.

mod common;

use common::rng::Rng;
use common::*;
use core::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, TAU};
use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::NonlinearRigidMotion;
use smooth_ccd2d::{BallCurve, CapsuleEllipse, ConvexCurve, Ellipse, RoundedPolygon};
use std::time::Instant;

fn still(pose: Pose) -> NonlinearRigidMotion {
    NonlinearRigidMotion::new(pose, Vector::ZERO, Vector::ZERO, 0.0)
}

fn moving(pos: Vector, angle: f64, linvel: Vector, angvel: f64) -> NonlinearRigidMotion {
    NonlinearRigidMotion::new(Pose::new(pos, angle), Vector::ZERO, linvel, angvel)
}

/// An axis-aligned sharp rectangle [x0, x0 + w] × [−h, h] (a wall whose face is x = x0).
fn wall(x0: f64, w: f64, h: f64) -> RoundedPolygon {
    RoundedPolygon::new(
        &[
            Vector::new(x0, -h),
            Vector::new(x0 + w, -h),
            Vector::new(x0 + w, h),
            Vector::new(x0, h),
        ],
        0.0,
    )
}

fn hit_time(r: &RefToi) -> f64 {
    match r.outcome {
        RefOutcome::Hit { time, crossed: true } => time,
        other => panic!("expected a crossed hit, got {other:?} ({r:?})"),
    }
}

/// Tracks the worst relative error of a family of checks (and what produced it).
struct Worst(&'static str, f64, String);
impl Worst {
    fn new(name: &'static str) -> Self {
        Worst(name, 0.0, String::new())
    }
    fn see(&mut self, err: f64, bound: f64, what: impl Fn() -> String) {
        assert!(err <= bound, "{}: error {err:e} > {bound:e}: {}", self.0, what());
        if err > self.1 {
            self.1 = err;
            self.2 = what();
        }
    }
}
impl Drop for Worst {
    fn drop(&mut self) {
        if !std::thread::panicking() {
            println!("{}: worst error {:.2e} ({})", self.0, self.1, self.2);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Foundations: the support functions the reference relies on.

#[test]
fn support_points_are_the_maxima_of_the_sampled_boundary() {
    let shapes: Vec<Box<dyn ConvexCurve>> = vec![
        Box::new(Ellipse::new(1.0, 0.01)),
        Box::new(Ellipse::new(0.3, 2.0)),
        Box::new(BallCurve { radius: 0.7 }),
        Box::new(RoundedPolygon::regular(5, 1.0, 0.2)),
        Box::new(RoundedPolygon::regular(3, 1.0, 0.0)),
        Box::new(wall(0.5, 1.0, 2.0)),
        Box::new(CapsuleEllipse::new(0.5, 1.0, 0.8)),
        Box::new(CapsuleEllipse::new(0.2, 0.1, 1.5)),
    ];
    let mut worst = Worst::new("support vs sampled boundary");
    for s in &shapes {
        let size = s.bounding_radius();
        let pts: Vec<Vector> = (0..20_000)
            .map(|i| s.eval(-PI + TAU * (i as f64 + 0.5) / 20_000.0).point)
            .collect();
        for k in 0..97 {
            let a = TAU * k as f64 / 97.0 + 0.01;
            let n = Vector::new(a.cos(), a.sin());
            let h = s.support_point(n).dot(n);
            let sampled = pts.iter().map(|p| p.dot(n)).fold(f64::NEG_INFINITY, f64::max);
            // The support value is an upper bound of the samples, and the samples come within the
            // sampling resolution of it.
            assert!(
                h >= sampled - 1e-13 * size,
                "{s:?}: support {h} below sample {sampled} at n = {n}"
            );
            worst.see((h - sampled) / size, 1e-6, || format!("{s:?} at n = {n}"));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Reference distance against closed forms.

#[test]
fn distance_of_discs_matches_closed_form() {
    let mut rng = Rng::new(7);
    let mut worst = Worst::new("distance disc-disc");
    for _ in 0..300 {
        let s = rng.log_uniform(0.01, 100.0);
        let (r1, r2) = (s * rng.uniform(0.1, 1.0), s * rng.uniform(0.1, 1.0));
        let p1 = rng.in_disc(3.0 * s);
        let p2 = rng.in_disc(3.0 * s);
        let d = reference_distance(
            &BallCurve { radius: r1 },
            &Pose::new(p1, rng.uniform(0.0, TAU)),
            &BallCurve { radius: r2 },
            &Pose::new(p2, rng.uniform(0.0, TAU)),
        );
        let exact = (p2 - p1).length() - r1 - r2;
        // Overlap depth of two discs is r1 + r2 − |p2 − p1| unless one contains the other.
        if exact < -2.0 * r1.min(r2) {
            continue;
        }
        worst.see((d.distance - exact).abs() / s, 1e-14, || format!("{r1} {r2} {p1} {p2}"));
        if (p2 - p1).length() > 1e-3 * s {
            assert!((d.normal - (p2 - p1).normalize()).length() < 1e-6);
        }
    }
}

#[test]
fn distance_of_disc_and_ellipse_matches_closed_forms() {
    let mut worst = Worst::new("distance disc-ellipse");
    let mut rng = Rng::new(11);
    for _ in 0..200 {
        let s = rng.log_uniform(0.01, 100.0);
        let (a, b) = (s * rng.uniform(0.05, 1.5), s * rng.uniform(0.01, 1.5));
        let e = Ellipse::new(a, b);
        let r = s * rng.uniform(0.01, 1.0);
        let c = Vector::new(s * rng.uniform(-5.0, 5.0), s * rng.uniform(-5.0, 5.0));
        // Along the axes: the ellipse at c rotated by 0, π/2, π, 3π/2; the disc on a world axis.
        for (k, rot) in [0.0, FRAC_PI_2, PI, 1.5 * PI].into_iter().enumerate() {
            let ext_x = if k % 2 == 0 { a } else { b };
            let ext_y = if k % 2 == 0 { b } else { a };
            let gap = rng.uniform(0.0, 2.0) * ext_x.min(ext_y);
            let dx = ext_x + r + gap;
            let d = reference_distance(
                &e,
                &Pose::new(c, rot),
                &BallCurve { radius: r },
                &Pose::new(c + Vector::new(dx, 0.0), 0.3),
            );
            if gap >= 0.0 {
                worst.see((d.distance - gap).abs() / s, 1e-14, || {
                    format!("x-axis {a} {b} {r} {gap} rot {rot}")
                });
            }
            let dy = ext_y + r + gap;
            let d = reference_distance(
                &BallCurve { radius: r },
                &Pose::new(c - Vector::new(0.0, dy), 0.0),
                &e,
                &Pose::new(c, rot),
            );
            if gap >= 0.0 {
                worst.see((d.distance - gap).abs() / s, 1e-14, || {
                    format!("y-axis {a} {b} {r} {gap} rot {rot}")
                });
            }
        }
        // General position, outside: distance from the disc's centre to the ellipse, by an
        // independent minimisation over the eccentric anomaly, minus r.
        let q = Vector::new(rng.uniform(-3.0, 3.0), rng.uniform(-3.0, 3.0)) * s;
        let inside = (q.x / a).powi(2) + (q.y / b).powi(2) <= 1.0;
        if inside {
            continue;
        }
        let exact = point_ellipse_distance(a, b, q) - r;
        let d = reference_distance(&e, &Pose::IDENTITY, &BallCurve { radius: r }, &Pose::new(q, 0.0));
        worst.see((d.distance - exact).abs() / s, 2e-14, || {
            format!("general {a} {b} {r} {q}")
        });
    }
}

/// Distance from an outside point q to the ellipse (a cos E, b sin E): dense samples in E then
/// golden-section minimisation of the squared distance around the best samples.
fn point_ellipse_distance(a: f64, b: f64, q: Vector) -> f64 {
    let f = |e: f64| (Vector::new(a * e.cos(), b * e.sin()) - q).length_squared();
    let n = 2000;
    let h = TAU / n as f64;
    let mut best = f64::INFINITY;
    let vals: Vec<f64> = (0..n).map(|i| f(i as f64 * h)).collect();
    for i in 0..n {
        let (l, r) = (vals[(i + n - 1) % n], vals[(i + 1) % n]);
        if vals[i] <= l && vals[i] <= r {
            let (mut lo, mut hi) = ((i as f64 - 1.0) * h, (i as f64 + 1.0) * h);
            for _ in 0..200 {
                let m1 = lo + 0.381_966 * (hi - lo);
                let m2 = hi - 0.381_966 * (hi - lo);
                if f(m1) < f(m2) {
                    hi = m2;
                } else {
                    lo = m1;
                }
            }
            best = best.min(f(0.5 * (lo + hi)));
        }
    }
    best.sqrt()
}

#[test]
fn distance_of_rotated_ellipse_to_wall_and_overlapping_boxes_match_closed_forms() {
    let mut worst = Worst::new("distance ellipse-wall / box-box");
    let mut rng = Rng::new(13);
    for _ in 0..200 {
        let s = rng.log_uniform(0.01, 100.0);
        let (a, b) = (s * rng.uniform(0.05, 1.0), s * rng.uniform(0.005, 1.0));
        let alpha = rng.uniform(0.0, TAU);
        let x0 = s * rng.uniform(1.2, 3.0);
        let w = wall(x0, s, 4.0 * s);
        // h of the ellipse along world x: body direction at −α.
        let h = (a * a * alpha.cos().powi(2) + b * b * alpha.sin().powi(2)).sqrt();
        let d = reference_distance(
            &Ellipse::new(a, b),
            &Pose::new(Vector::ZERO, alpha),
            &w,
            &Pose::IDENTITY,
        );
        worst.see((d.distance - (x0 - h)).abs() / s, 1e-14, || {
            format!("{a} {b} {alpha} {x0}")
        });
        // The wall moved and turned rigidly: same distance.
        let shift = Pose::new(rng.in_disc(5.0 * s), rng.uniform(0.0, TAU));
        let d2 = reference_distance(
            &Ellipse::new(a, b),
            &(shift * Pose::new(Vector::ZERO, alpha)),
            &w,
            &shift,
        );
        worst.see((d2.distance - (x0 - h)).abs() / s, 1e-14, || {
            format!("moved {a} {b} {alpha} {x0}")
        });

        // Two axis-aligned squares overlapping by p along x (less than along y): distance −p.
        let half = s * rng.uniform(0.2, 1.0);
        let p = half * rng.uniform(0.01, 0.5);
        let sq = RoundedPolygon::regular(4, half * 2f64.sqrt(), 0.0);
        let dy = half * rng.uniform(-0.3, 0.3);
        let d = reference_distance(
            &sq,
            &Pose::new(Vector::ZERO, FRAC_PI_4),
            &sq,
            &Pose::new(Vector::new(2.0 * half - p, dy), FRAC_PI_4),
        );
        worst.see((d.distance + p).abs() / s, 1e-14, || format!("boxes {half} {p} {dy}"));
    }
}

// ---------------------------------------------------------------------------------------------
// Reference time of impact against closed forms.

#[test]
fn toi_of_discs_head_on_and_oblique_matches_closed_form() {
    let mut worst = Worst::new("toi disc-disc");
    let mut rng = Rng::new(17);
    for i in 0..300 {
        let s = rng.log_uniform(0.01, 100.0);
        let (r1, r2) = (s * rng.uniform(0.05, 1.0), s * rng.uniform(0.05, 1.0));
        let target = if i % 2 == 0 { 0.0 } else { s * rng.uniform(1e-6, 0.1) };
        let reach = r1 + r2 + target;
        let off = if i % 3 == 0 {
            0.0
        } else {
            reach * rng.uniform(-0.95, 0.95)
        };
        let x = reach + s * rng.uniform(0.01, 3.0);
        let v = s * rng.log_uniform(0.05, 50.0);
        let exact = ((x - (reach * reach - off * off).sqrt()) / v).max(0.0);
        // Spins about the discs' centres do not matter (but enlarge the speed bound).
        let (w1, w2) = (rng.uniform(-60.0, 60.0), rng.uniform(-60.0, 60.0));
        let base = rng.in_disc(10.0 * s);
        let dir = rng.direction_tau();
        let perp = Vector::new(-dir.y, dir.x);
        let m1 = moving(base, 0.2, Vector::ZERO, w1);
        let m2 = moving(base + dir * x + perp * off, 0.0, -dir * v, w2);
        let r = reference_toi(
            &BallCurve { radius: r1 },
            &m1,
            &BallCurve { radius: r2 },
            &m2,
            0.0,
            1.0,
            target,
        );
        if exact > 1.0 {
            assert_eq!(r.outcome, RefOutcome::Miss, "{r:?}");
            continue;
        }
        let t = hit_time(&r);
        worst.see((t - exact).abs(), 1e-13, || {
            format!("{r1} {r2} {x} {off} {v} {target}: {r:?}")
        });
    }
}

#[test]
fn toi_of_disc_hitting_ellipse_along_its_axes_matches_closed_form() {
    let mut worst = Worst::new("toi disc-ellipse along axes");
    let mut rng = Rng::new(19);
    for i in 0..200 {
        let s = rng.log_uniform(0.01, 100.0);
        let (a, b) = (s, s * rng.log_uniform(0.01, 1.0));
        let r = s * rng.uniform(0.01, 1.0);
        let target = if i % 2 == 0 { 0.0 } else { s * rng.uniform(1e-6, 0.05) };
        let v = s * rng.log_uniform(0.1, 20.0);
        let along_x = i % 4 < 2;
        let ext = if along_x { a } else { b };
        let x0 = ext + r + target + s * rng.uniform(0.01, 1.0) * v / s * 0.9;
        let exact = (x0 - ext - r - target) / v;
        let axis = if along_x { Vector::X } else { Vector::Y };
        let ell = Ellipse::new(a, b);
        let disc = BallCurve { radius: r };
        let me = still(Pose::IDENTITY);
        let md = moving(axis * x0, 0.0, -axis * v, 0.0);
        let r12 = reference_toi(&ell, &me, &disc, &md, 0.0, 1.0, target);
        let r21 = reference_toi(&disc, &md, &ell, &me, 0.0, 1.0, target);
        for rr in [r12, r21] {
            let t = hit_time(&rr);
            worst.see((t - exact).abs(), 1e-13, || format!("{a} {b} {r} {x0} {v}: {rr:?}"));
        }
    }
}

/// First time the support of the ellipse (a, b) spinning at ω from angle π/2 reaches `reach`
/// along +x: h(α) = √(a² cos² α + b² sin² α) = reach ⇒ t = arcsin(c)/|ω|,
/// c = √((reach² − b²)/(a² − b²)).
fn spinning_ellipse_support_time(a: f64, b: f64, reach: f64, omega: f64) -> f64 {
    (((reach * reach - b * b) / (a * a - b * b)).sqrt()).asin() / omega.abs()
}

#[test]
fn toi_of_spinning_ellipse_against_wall_matches_closed_form() {
    let mut worst = Worst::new("toi spinning ellipse-wall");
    let mut steps = Vec::new();
    for &omega in &[1.0, -3.0, 10.0, 30.0, -60.0, 60.0] {
        for &(a, b) in &[(1.0, 0.2), (1.0, 0.01), (2.0, 1.5)] {
            for &frac in &[0.05, 0.5, 0.95, 0.9999] {
                for &target in &[0.0, 1e-6, 0.01] {
                    for &s in &[0.01, 1.0, 100.0] {
                        let (a, b) = (a * s, b * s);
                        let target = target * s;
                        let reach = b + frac * (a - b);
                        let x0 = reach + target;
                        let exact = spinning_ellipse_support_time(a, b, reach, omega);
                        let m = moving(Vector::ZERO, FRAC_PI_2, Vector::ZERO, omega);
                        let w = wall(x0, s, 3.0 * a);
                        let r = reference_toi(&Ellipse::new(a, b), &m, &w, &still(Pose::IDENTITY), 0.0, 1.0, target);
                        if exact > 1.0 {
                            assert_eq!(r.outcome, RefOutcome::Miss, "{r:?}");
                            continue;
                        }
                        let t = hit_time(&r);
                        worst.see((t - exact).abs(), 1e-13, || {
                            format!("a {a} b {b} ω {omega} reach {reach} target {target}: {r:?}")
                        });
                        steps.push(r.steps);
                    }
                }
            }
        }
    }
    println!("spinning ellipse-wall: max steps {}", steps.iter().max().unwrap());
}

#[test]
fn toi_of_spinning_ellipse_against_disc_matches_closed_form() {
    // Ellipse (a, b) = (1, 0.2) spinning about its centre from angle π/2 at ω, disc of radius r at
    // (L, 0). The disc is touched when its centre lies on the ellipse's parallel curve at offset
    // r' = r + target: Q(ψ) = P(ψ) + r'·N(ψ), P(ψ) = (a² cos ψ, b² sin ψ)/h(ψ). |Q| decreases on
    // [0, π/2]: solve |Q(ψ)| = L by bisection, γ = arg Q(ψ), then ω t = π/2 − γ.
    //
    // (Solving h(ωt) = L − r instead — the ellipse's support along the disc direction reaching
    // the disc's nearest point — only gives a lower bound on this time: the support point is
    // generally off the x axis, where the disc's boundary lies further right.)
    let mut worst = Worst::new("toi spinning ellipse-disc");
    for &omega in &[1.0f64, 7.0, -25.0, 60.0] {
        for &(a, b) in &[(1.0, 0.2), (1.0, 0.01), (1.0, 0.7)] {
            for &r in &[0.001, 0.1, 0.5] {
                for &frac in &[0.1, 0.5, 0.9, 0.999] {
                    for &target in &[0.0, 3e-6] {
                        for &s in &[0.01, 1.0, 100.0] {
                            let (a, b, r, target) = (a * s, b * s, r * s, target * s);
                            let rp = r + target;
                            let l = b + rp + frac * (a - b);
                            let q = |psi: f64| {
                                let (sn, cs) = psi.sin_cos();
                                let h = (a * a * cs * cs + b * b * sn * sn).sqrt();
                                Vector::new(a * a * cs / h + rp * cs, b * b * sn / h + rp * sn)
                            };
                            let (mut lo, mut hi) = (0.0, FRAC_PI_2);
                            for _ in 0..200 {
                                let mid = 0.5 * (lo + hi);
                                if q(mid).length() > l {
                                    lo = mid;
                                } else {
                                    hi = mid;
                                }
                            }
                            let qq = q(0.5 * (lo + hi));
                            let gamma = qq.y.atan2(qq.x);
                            let exact = (FRAC_PI_2 - gamma) / omega.abs();
                            let m = moving(Vector::ZERO, FRAC_PI_2, Vector::ZERO, omega);
                            let disc = still(Pose::new(Vector::new(l, 0.0), 0.0));
                            let res = reference_toi(
                                &Ellipse::new(a, b),
                                &m,
                                &BallCurve { radius: r },
                                &disc,
                                0.0,
                                1.0,
                                target,
                            );
                            if exact > 1.0 {
                                assert_eq!(res.outcome, RefOutcome::Miss);
                                continue;
                            }
                            let t = hit_time(&res);
                            worst.see((t - exact).abs(), 1e-12, || {
                                format!("a {a} b {b} r {r} ω {omega} L {l} target {target}: {res:?}")
                            });
                            // The support-function shortcut is a strict lower bound (off-axis contact).
                            let shortcut = spinning_ellipse_support_time(a, b, l - rp, omega);
                            assert!(shortcut <= t + 1e-12, "shortcut {shortcut} > {t}");
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn toi_of_spinning_square_corner_against_wall_matches_closed_form() {
    // A regular square, circumradius R (+ corner radius rc), starting at angle π/4 (a face
    // towards +x, h = R cos π/4 + rc), spinning at ω: h = R cos(π/4 − |ω| t) + rc for |ω| t ≤ π/4.
    let mut worst = Worst::new("toi spinning square-wall");
    for &omega in &[2.0f64, -15.0, 60.0] {
        for &rc in &[0.0, 0.05] {
            for &frac in &[0.1, 0.6, 0.999] {
                for &target in &[0.0, 2e-6] {
                    for &s in &[0.01, 3.0, 100.0] {
                        let (big_r, rc, target) = (s, rc * s, target * s);
                        let hx = big_r * FRAC_PI_4.cos() + frac * (big_r - big_r * FRAC_PI_4.cos());
                        let x0 = hx + rc + target;
                        let exact = (FRAC_PI_4 - (hx / big_r).acos()) / omega.abs();
                        let sq = RoundedPolygon::regular(4, big_r, rc);
                        let m = moving(Vector::ZERO, FRAC_PI_4, Vector::ZERO, omega);
                        let w = wall(x0, s, 3.0 * s);
                        let r = reference_toi(&sq, &m, &w, &still(Pose::IDENTITY), 0.0, 1.0, target);
                        let t = hit_time(&r);
                        worst.see((t - exact).abs(), 1e-12, || {
                            format!("R {big_r} rc {rc} ω {omega}: {r:?}")
                        });
                    }
                }
            }
        }
    }
}

#[test]
fn toi_of_capsule_ellipse_translating_onto_a_disc_matches_closed_form() {
    // Appendix A shape: the flat segment x = r1 faces +x, the half-ellipse's tip x = −r3 faces −x.
    let mut worst = Worst::new("toi capsule_ellipse-disc");
    let mut rng = Rng::new(23);
    for i in 0..100 {
        let s = rng.log_uniform(0.01, 100.0);
        let (r1, r2, r3) = (
            s * rng.uniform(0.2, 0.8),
            s * rng.uniform(0.1, 0.8),
            s * rng.uniform(0.1, 1.5),
        );
        let c = CapsuleEllipse::new(r1, r2, r3);
        let rd = s * rng.uniform(0.01, 0.5);
        let target = if i % 2 == 0 { 0.0 } else { 1e-6 * s };
        let v = s * rng.uniform(0.5, 5.0);
        let right = i % 4 < 2;
        let (ext, dir) = if right { (r1, Vector::X) } else { (r3, -Vector::X) };
        // Off-axis height on the segment (right side) stays within its half-length r2.
        let y = if right { rng.uniform(-0.9, 0.9) * r2 } else { 0.0 };
        let x = ext + rd + target + rng.uniform(0.0, 0.9) * v;
        let exact = (x - ext - rd - target) / v;
        let mc = still(Pose::IDENTITY);
        let md = moving(dir * x + Vector::new(0.0, y), 0.0, -dir * v, 0.0);
        let r = reference_toi(&c, &mc, &BallCurve { radius: rd }, &md, 0.0, 1.0, target);
        let t = hit_time(&r);
        worst.see((t - exact).abs(), 1e-13, || {
            format!("{r1} {r2} {r3} {rd} {x} {y}: {r:?}")
        });
    }
}

// ---------------------------------------------------------------------------------------------
// Scenario generators, and the reference's own consistency on them.

#[test]
fn scenario_generators_are_deterministic_finite_and_start_separated() {
    for class in ScenarioClass::ALL {
        for seed in 0..200 {
            let a = generate(class, seed);
            let b = generate(class, seed);
            assert_eq!(format!("{:?}", a), format!("{:?}", b), "not deterministic");
            assert!(a.is_finite(), "{}", a.describe());
            assert!((a.t0, a.t1) == (0.0, 1.0) && a.target >= 0.0);
            let d0 = a.distance_at(a.t0);
            assert!(d0 - a.target > 0.0, "starts within target: {}", a.describe());
            assert!((0.005..=200.0).contains(&a.size()), "{}", a.size());
            // The motion reproduces the constructed configuration's gap at tc: distance at tc is
            // at least the aimed gap when that is positive.
            if a.aimed_gap > 0.0 {
                assert!(a.distance_at(a.tc) - a.target >= a.aimed_gap * (1.0 - 1e-9) - 1e-12 * a.size());
            }
        }
    }
}

struct ClassStats {
    hits: usize,
    grazes: usize,
    misses: usize,
    capped: usize,
    initially: usize,
    steps: Vec<u64>,
    evals: u64,
    max_turns: f64,
    multi_turn_hits: usize,
    kinds: [usize; 5],
    hits_by_kind: [usize; 5],
}

fn stats(scs: &[Scenario], refs: &[RefToi]) -> ClassStats {
    let mut st = ClassStats {
        hits: 0,
        grazes: 0,
        misses: 0,
        capped: 0,
        initially: 0,
        steps: Vec::new(),
        evals: 0,
        max_turns: 0.0,
        multi_turn_hits: 0,
        kinds: [0; 5],
        hits_by_kind: [0; 5],
    };
    for (sc, r) in scs.iter().zip(refs) {
        let k = ScenarioKind::ALL.iter().position(|&k| k == sc.kind).unwrap();
        st.kinds[k] += 1;
        st.steps.push(r.steps);
        st.evals += r.evals;
        st.initially += r.initially_within_target as usize;
        match r.outcome {
            RefOutcome::Hit { time, crossed } => {
                st.hits += 1;
                st.hits_by_kind[k] += 1;
                st.grazes += (!crossed) as usize;
                let turns = sc.turns_until(time);
                st.max_turns = st.max_turns.max(turns);
                st.multi_turn_hits += (turns >= 2.0) as usize;
            }
            RefOutcome::Miss => st.misses += 1,
            RefOutcome::Capped { .. } => st.capped += 1,
        }
    }
    st.steps.sort_unstable();
    st
}

fn report(class: ScenarioClass, st: &ClassStats, n: usize, secs: f64) {
    let med = st.steps[st.steps.len() / 2];
    let p99 = st.steps[st.steps.len() * 99 / 100];
    let max = *st.steps.last().unwrap();
    println!(
        "{:<24} n {n}: hits {} (grazes {}, ≥2 turns before impact {}, max turns {:.1}), misses {}, capped {}, \
         initially within target {}; kinds [ordinary, fast, multi-turn, grazing, pass-by] {:?} hits {:?}; \
         steps median {med} p99 {p99} max {max}; evals/scenario {:.0}; {:.0} scenarios/s ({:.2} s)",
        class.name(),
        st.hits,
        st.grazes,
        st.multi_turn_hits,
        st.max_turns,
        st.misses,
        st.capped,
        st.initially,
        st.kinds,
        st.hits_by_kind,
        st.evals as f64 / n as f64,
        n as f64 / secs,
        secs
    );
}

fn run_class(class: ScenarioClass, n: usize) -> (Vec<Scenario>, Vec<RefToi>, f64) {
    let scs = scenarios(class, 1000, n);
    let start = Instant::now();
    let refs = par_map(&scs, |s| s.reference());
    (scs, refs, start.elapsed().as_secs_f64())
}

#[test]
fn scenario_classes_hit_about_half_the_time_and_the_reference_is_consistent() {
    let n = 400;
    for class in ScenarioClass::ALL {
        let (scs, refs, secs) = run_class(class, n);
        let st = stats(&scs, &refs);
        report(class, &st, n, secs);
        assert_eq!(st.capped, 0, "capped scenarios");
        assert_eq!(st.initially, 0);
        let frac = st.hits as f64 / n as f64;
        assert!((0.3..=0.7).contains(&frac), "hit fraction {frac}");
        assert!(st.multi_turn_hits > 0, "no hit after several turns");
        for (sc, r) in scs.iter().zip(&refs) {
            let size = sc.size();
            if let RefOutcome::Hit { time, crossed } = r.outcome {
                // At the reported time: target − 1e-12 s ≤ D ≤ target + tol (the `Hit` contract of `ToiStatus`).
                let d = sc.distance_at(time) - sc.target;
                assert!(
                    d >= -1e-12 * size && d <= r.tol,
                    "D − target = {d:e} at hit: {}",
                    sc.describe()
                );
                if crossed {
                    // Just after the bracket the pair is within the target (bisection invariant).
                    let after = (time + 1e-12 * (sc.t1 - sc.t0)).min(sc.t1);
                    let da = sc.distance_at(after) - sc.target;
                    assert!(da <= 1e-11 * size, "D − target = {da:e} after hit: {}", sc.describe());
                }
            }
        }
    }
}

/// Brute force in time: D sampled on a fine grid with the cold reference distance never falls
/// to the target before the reference's hit time, nor anywhere for a miss.
#[test]
fn reference_agrees_with_brute_force_time_sampling() {
    let per_class = 24;
    let grid = 1500;
    for class in ScenarioClass::ALL {
        let scs = scenarios(class, 5000, per_class);
        let checked = par_map(&scs, |sc| {
            let r = sc.reference();
            let size = sc.size();
            let end = r.hit_time().unwrap_or(sc.t1);
            let mut min_gap = f64::INFINITY;
            for i in 0..=grid {
                let t = sc.t0 + (end - sc.t0) * i as f64 / grid as f64;
                let g = sc.distance_at(t) - sc.target;
                min_gap = min_gap.min(g);
                assert!(
                    g > -1e-12 * size,
                    "D − target = {g:e} at t = {t} before {end}: {} {r:?}",
                    sc.describe()
                );
            }
            // For a hit the minimum over the grid (which ends at the hit) is ~0.
            if r.is_hit() {
                assert!(min_gap <= r.tol, "{min_gap:e}");
            }
            (r.is_hit(), min_gap / size)
        });
        let hits = checked.iter().filter(|c| c.0).count();
        println!(
            "{:<24} brute force: {} scenarios ({} hits) agree",
            class.name(),
            checked.len(),
            hits
        );
    }
}

#[test]
fn reference_is_symmetric_in_object_order_and_scale_invariant() {
    let mut worst = Worst::new("toi swap/scale");
    for class in ScenarioClass::ALL {
        for seed in 0..40 {
            let sc = generate(class, 9000 + seed);
            let r = sc.reference();
            let swapped = reference_toi(
                sc.curve2(),
                &sc.motion2,
                sc.curve1(),
                &sc.motion1,
                sc.t0,
                sc.t1,
                sc.target,
            );
            match (r.outcome, swapped.outcome) {
                (RefOutcome::Hit { time: a, crossed: true }, RefOutcome::Hit { time: b, crossed: true }) => {
                    // Time resolution: 1e-12 of the window, or the distance round-off over |D'|.
                    let res = 1e-12_f64.max(1e-13 * sc.size() / r.slope.abs());
                    worst.see((a - b).abs() / res, 1.0, || sc.describe());
                }
                (RefOutcome::Miss, RefOutcome::Miss) => {}
                (a, b) => {
                    // Only grazes may disagree.
                    assert!(
                        r.min_gap.min(swapped.min_gap) < 1e-9 * sc.size(),
                        "{a:?} vs {b:?}: {}",
                        sc.describe()
                    );
                }
            }
        }
    }
}

/// The directional rate bound (default) and the plain Lipschitz bound V give the same answers.
#[test]
fn directional_and_plain_advancement_agree() {
    let plain = RefToiOptions {
        directional: false,
        ..RefToiOptions::default()
    };
    let mut steps = (0u64, 0u64);
    for class in ScenarioClass::ALL {
        let scs = scenarios(class, 7000, 20);
        let pairs = par_map(&scs, |sc| {
            let a = sc.reference();
            let b = reference_toi_with(
                sc.curve1(),
                &sc.motion1,
                sc.curve2(),
                &sc.motion2,
                sc.t0,
                sc.t1,
                sc.target,
                &plain,
            );
            (a, b)
        });
        for (sc, (a, b)) in scs.iter().zip(&pairs) {
            steps.0 += a.steps;
            steps.1 += b.steps;
            match (a.hit_time(), b.hit_time()) {
                (Some(x), Some(y)) => {
                    let res = 1e-12_f64.max(1e-13 * sc.size() / a.slope.abs());
                    assert!((x - y).abs() <= res, "{x} vs {y}: {}", sc.describe());
                }
                (None, None) => assert!(!a.is_capped() && !b.is_capped()),
                _ => panic!("{a:?} vs {b:?}: {}", sc.describe()),
            }
        }
    }
    println!("steps: directional {} plain {}", steps.0, steps.1);
}

/// Throughput of the reference: 5,000 scenarios per class (run with `--ignored --nocapture`).
#[test]
#[ignore]
fn reference_throughput_5000_per_class() {
    for class in ScenarioClass::ALL {
        let n = 5000;
        let (scs, refs, secs) = run_class(class, n);
        let st = stats(&scs, &refs);
        report(class, &st, n, secs);
    }
}
