//! Unit tests of the gap tracker: the exact distance against dense sampling of the gap, the
//! guard's bound against the true distance over its span, its step against plain bisection, and
//! closed-form impacts.

use super::frame::GapMotion;
use super::maxgap::Pair;
use super::*;
use crate::numerics::math::{unit, Pose};
use crate::query::toi::ToiStatus;
use crate::{ConvexCurve, RoundedPolygon};
use core::f64::consts::PI;

/// splitmix64, for the randomised checks below.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}

/// A random convex polygon: 2 to 8 vertices (2: a segment), radius 0 about a third of the time.
fn random_polygon(rng: &mut Rng) -> RoundedPolygon {
    let n = 2 + (rng.next() * 7.0) as usize;
    let r = if rng.next() < 0.35 { 0.0 } else { rng.range(0.0, 0.3) };
    let verts: Vec<Vector> = if n == 2 {
        let a = rng.range(0.0, PI);
        let l = rng.range(0.1, 1.0);
        vec![-unit(a) * l, unit(a) * l]
    } else {
        // Points on a circle in counter-clockwise order (a convex polygon), gaps below π.
        let rad = rng.range(0.2, 1.0);
        let mut angles: Vec<f64> = (0..n)
            .map(|i| (i as f64 + rng.range(0.0, 0.8)) * 2.0 * PI / n as f64)
            .collect();
        angles.sort_by(|a, b| a.partial_cmp(b).expect("finite"));
        angles.iter().map(|a| unit(*a) * rad).collect()
    };
    RoundedPolygon::from_core_unchecked(verts, r)
}

fn side(p: &RoundedPolygon) -> Side<'_> {
    Side::Poly(PolySide::new(p.vertices(), p.edge_normals(), p.corner_radius()).expect("a polygon"))
}

fn random_motion(rng: &mut Rng, reach: f64, spin: f64) -> NonlinearRigidMotion {
    NonlinearRigidMotion::new(
        Pose::new(
            Vector::new(rng.range(-reach, reach), rng.range(-reach, reach)),
            rng.range(-PI, PI),
        ),
        Vector::new(rng.range(-0.3, 0.3), rng.range(-0.3, 0.3)),
        Vector::new(rng.range(-3.0, 3.0), rng.range(-3.0, 3.0)),
        rng.range(-spin, spin),
    )
}

/// max over 40,000 axes of the gap from the shapes' support points, refined by golden-section
/// search around the best sample: the distance to about 1e-14 of the size.
fn sampled_distance(pair: &Pair, t: f64) -> f64 {
    let fr = pair.motion.frame(t);
    let gap = |th: f64| {
        let u = unit(th);
        let m1 = fr.to_body(0, u);
        let m2 = fr.to_body(1, -u);
        let [s1, s2] = pair.sides;
        let a = fr.point(&pair.motion, 0, s1.support(s1.feature_of(m1, 0), m1).0);
        let b = fr.point(&pair.motion, 1, s2.support(s2.feature_of(m2, 0), m2).0);
        (b - a).dot(u)
    };
    const N: usize = 40_000;
    let mut best = (0.0, f64::NEG_INFINITY);
    for k in 0..N {
        let th = 2.0 * PI * k as f64 / N as f64;
        let g = gap(th);
        if g > best.1 {
            best = (th, g);
        }
    }
    let (mut a, mut b) = (best.0 - 2.0 * PI / N as f64, best.0 + 2.0 * PI / N as f64);
    for _ in 0..80 {
        let (x1, x2) = (a + (b - a) * 0.382, a + (b - a) * 0.618);
        if gap(x1) > gap(x2) {
            b = x2;
        } else {
            a = x1;
        }
    }
    best.1.max(gap(0.5 * (a + b)))
}

#[test]
fn exact_distance_of_dilated_polygons_matches_dense_sampling() {
    let mut rng = Rng(3);
    let (mut apart, mut overlapping) = (0, 0);
    for case in 0..300 {
        let (a, b) = (random_polygon(&mut rng), random_polygon(&mut rng));
        let m1 = random_motion(&mut rng, 1.5, 5.0);
        let m2 = random_motion(&mut rng, 1.5, 5.0);
        let pair = Pair {
            sides: [side(&a), side(&b)],
            motion: GapMotion::new(&m1, &m2),
        };
        let t = rng.range(0.0, 1.0);
        let fr = pair.motion.frame(t);
        // A cold start from an arbitrary axis.
        let u0 = unit(rng.range(-PI, PI));
        let at = pair.max_gap(&fr, u0, (0, 0)).expect("finite");
        let reference = sampled_distance(&pair, t);
        let size = a.bounding_radius().max(b.bounding_radius());
        assert!(
            (at.d - reference).abs() <= 1e-12 * size,
            "case {case}: exact {} sampled {reference} ({:?})",
            at.d,
            at.kind
        );
        if at.d > 0.0 {
            apart += 1;
        } else {
            overlapping += 1;
        }
    }
    assert!(
        apart > 30 && overlapping > 30,
        "{apart} apart, {overlapping} overlapping"
    );
}

#[test]
fn guard_bound_holds_below_the_distance_over_its_span() {
    let mut rng = Rng(5);
    let mut checked = 0;
    for _ in 0..300 {
        let (a, b) = (random_polygon(&mut rng), random_polygon(&mut rng));
        let m1 = random_motion(&mut rng, 3.0, 30.0);
        let m2 = random_motion(&mut rng, 3.0, 30.0);
        let pair = Pair {
            sides: [side(&a), side(&b)],
            motion: GapMotion::new(&m1, &m2),
        };
        let t = rng.range(0.0, 1.0);
        let fr = pair.motion.frame(t);
        let at = pair.max_gap(&fr, unit(0.3), (0, 0)).expect("finite");
        let radius = [
            side(&a).radius_about(m1.local_center),
            side(&b).radius_about(m2.local_center),
        ];
        for lam in [m1.angvel, m2.angvel, 0.0, 7.0] {
            for dir in [1.0, -1.0] {
                let span = rng.range(1e-3, 0.2);
                let par = pair.guard(&fr, &at, lam, span, dir, radius);
                for k in 0..=16 {
                    let s = span * k as f64 / 16.0;
                    let tt = t + dir * s;
                    let frs = pair.motion.frame(tt);
                    let d = pair.max_gap(&frs, at.u, (at.i, at.j)).expect("finite").d;
                    let bound = par.q(at.d, s);
                    assert!(
                        d >= bound - 1e-12 * (1.0 + bound.abs()),
                        "D {d} < bound {bound} (λ {lam}, dir {dir}, s {s})"
                    );
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 10_000);
}

/// The first root of q on [0, span] by bisection over a fine grid's first sign change (the
/// guard's step before its safeguarded Newton): the reference for the next test.
fn first_root_by_bisection(b: &guard::Bound, gap: f64, span: f64) -> f64 {
    let n = 4096;
    let mut lo = 0.0;
    for k in 1..=n {
        let hi = span * k as f64 / n as f64;
        if b.q(gap, hi) <= 0.0 {
            let (mut x, mut y) = (lo, hi);
            for _ in 0..200 {
                let m = 0.5 * (x + y);
                if !(m > x && m < y) {
                    break;
                }
                if b.q(gap, m) > 0.0 {
                    x = m;
                } else {
                    y = m;
                }
            }
            return x;
        }
        lo = hi;
    }
    span
}

#[test]
fn guard_step_is_the_first_root_of_its_bound_from_the_safe_side() {
    let mut rng = Rng(11);
    let (mut roots, mut whole) = (0, 0);
    for _ in 0..20_000 {
        let b = guard::Bound {
            a1: rng.range(-10.0, 10.0),
            a2: rng.range(-100.0, 100.0),
            a3: if rng.next() < 0.2 { 0.0 } else { rng.range(0.0, 1e4) },
        };
        let gap = 10f64.powf(rng.range(-12.0, 0.0));
        let span = 10f64.powf(rng.range(-6.0, 0.0));
        let s = b.step(gap, span);
        let r = first_root_by_bisection(&b, gap, span);
        // The grid can miss a root where q only dips to zero between two of its points; the
        // step must never be beyond the reference, and is within 1e-13 of it otherwise.
        assert!(
            s <= r,
            "step {s} beyond the first root {r} ({b:?}, gap {gap}, span {span})"
        );
        assert!(
            s > 0.0 && b.q(gap, s) > 0.0 || s == span,
            "q ≤ 0 at the step {s} ({b:?})"
        );
        if r < span {
            assert!(
                s >= r * (1.0 - 1e-13),
                "step {s} short of the root {r} ({b:?}, gap {gap})"
            );
            roots += 1;
        } else {
            whole += 1;
        }
    }
    println!("guard step: {roots} roots, {whole} spans without one");
    assert!(roots > 5_000 && whole > 1_000);
}

#[test]
fn boxes_closing_head_on_touch_at_the_closed_form_time() {
    let cube = RoundedPolygon::new(
        &[
            Vector::new(-0.5, -0.5),
            Vector::new(0.5, -0.5),
            Vector::new(0.5, 0.5),
            Vector::new(-0.5, 0.5),
        ],
        0.1,
    );
    let m1 = NonlinearRigidMotion::new(Pose::translation(-3.0, 0.2), Vector::ZERO, Vector::new(2.0, 0.0), 0.0);
    let m2 = NonlinearRigidMotion::new(Pose::translation(3.0, 0.0), Vector::ZERO, Vector::new(-1.0, 0.0), 0.0);
    let r = gap_time_of_impact(side(&cube), &m1, side(&cube), &m2, 0.0, 5.0, &ToiOptions::default()).unwrap();
    // Faces 6 − 1.2 apart close at 3 m/s.
    assert_eq!(r.status, ToiStatus::Hit);
    assert!((r.time - 4.8 / 3.0).abs() < 1e-12, "{}", r.time);
    assert!(r.distance.abs() < 1e-12);
    assert!((r.normal1 - Vector::X).length() < 1e-12);
}

#[test]
fn spinning_square_corner_reaches_a_wall_when_its_support_does() {
    // A unit-diagonal square spinning at 40 rad/s about its centre at x = −1, a wall face at
    // x = 0: contact when the support along +x, |cos| + |sin| of the turn over √2 … reaches 1.
    let sq = RoundedPolygon::regular(4, 1.2, 0.0);
    let wall = RoundedPolygon::new(
        &[
            Vector::new(0.0, -5.0),
            Vector::new(1.0, -5.0),
            Vector::new(1.0, 5.0),
            Vector::new(0.0, 5.0),
        ],
        0.0,
    );
    let m1 = NonlinearRigidMotion::new(
        Pose::new(Vector::new(-1.0, 0.0), PI / 4.0),
        Vector::ZERO,
        Vector::ZERO,
        40.0,
    );
    let m2 = NonlinearRigidMotion::identity();
    let r = gap_time_of_impact(side(&sq), &m1, side(&wall), &m2, 0.0, 1.0, &ToiOptions::default()).unwrap();
    // The support of the square along +x at angle α: 1.2·max over its corners of cos(α + kπ/2).
    let support = |t: f64| {
        (0..4)
            .map(|k| (PI / 4.0 + 40.0 * t + k as f64 * PI / 2.0).cos())
            .fold(f64::MIN, f64::max)
            * 1.2
    };
    // First time the support reaches 1 (= the wall at 0 from the centre at −1), by dense sampling.
    let mut t_ref = None;
    for k in 0..1_000_000 {
        let t = k as f64 * 1e-6;
        if support(t) >= 1.0 {
            let (mut lo, mut hi) = (t - 1e-6, t);
            for _ in 0..100 {
                let mid = 0.5 * (lo + hi);
                if support(mid) >= 1.0 {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            t_ref = Some(hi);
            break;
        }
    }
    let t_ref = t_ref.expect("the corner reaches the wall");
    assert_eq!(r.status, ToiStatus::Hit);
    assert!((r.time - t_ref).abs() < 1e-12, "{} vs {t_ref}", r.time);
}

#[test]
fn guard_bound_holds_below_the_distance_with_curve_sides() {
    use super::side::CurveSide;
    use crate::CapsuleEllipse;
    let mut rng = Rng(9);
    let mut checked = 0;
    for case in 0..300 {
        let c = CapsuleEllipse::new(rng.range(0.1, 0.5), rng.range(0.1, 0.8), rng.range(0.1, 0.8));
        let b = random_polygon(&mut rng);
        let s1 = Side::Curve(CurveSide {
            curve: &c,
            faces: c.flats(),
        });
        let m1 = random_motion(&mut rng, 3.0, 30.0);
        let m2 = random_motion(&mut rng, 3.0, 30.0);
        let pair = Pair {
            sides: [s1, side(&b)],
            motion: GapMotion::new(&m1, &m2),
        };
        let t = rng.range(0.0, 1.0);
        let fr = pair.motion.frame(t);
        let at = pair.max_gap(&fr, unit(0.3), (0, 0)).expect("finite");
        let radius = [s1.radius_about(m1.local_center), side(&b).radius_about(m2.local_center)];
        for lam in [m1.angvel, m2.angvel, 0.0] {
            for dir in [1.0, -1.0] {
                let span = rng.range(1e-3, 0.2);
                let par = pair.guard(&fr, &at, lam, span, dir, radius);
                for k in 0..=32 {
                    let s = span * k as f64 / 32.0;
                    let frs = pair.motion.frame(t + dir * s);
                    let d = pair.max_gap(&frs, at.u, (at.i, at.j)).expect("finite").d;
                    let bound = par.q(at.d, s);
                    assert!(
                        d >= bound - 1e-12 * (1.0 + bound.abs()),
                        "case {case}: D {d} < bound {bound} (λ {lam}, dir {dir}, s {s}, span {span}, kind {:?})",
                        at.kind
                    );
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 10_000, "{checked}");
}

#[test]
fn exact_distance_with_a_capsule_ellipse_matches_dense_sampling_also_deep() {
    use super::side::CurveSide;
    use crate::CapsuleEllipse;
    let mut rng = Rng(21);
    let (mut apart, mut deep) = (0, 0);
    for case in 0..200 {
        let c = CapsuleEllipse::new(rng.range(0.1, 0.5), rng.range(0.1, 0.8), rng.range(0.1, 0.8));
        let b = random_polygon(&mut rng);
        let m1 = random_motion(&mut rng, 1.0, 5.0);
        let m2 = random_motion(&mut rng, 1.0, 5.0);
        let s1 = Side::Curve(CurveSide {
            curve: &c,
            faces: c.flats(),
        });
        let pair = Pair {
            sides: [s1, side(&b)],
            motion: GapMotion::new(&m1, &m2),
        };
        let t = rng.range(0.0, 1.0);
        let fr = pair.motion.frame(t);
        let at = pair.max_gap(&fr, unit(rng.range(-PI, PI)), (0, 0)).expect("finite");
        let reference = sampled_distance(&pair, t);
        let size = c.bounding_radius().max(b.bounding_radius());
        assert!(
            (at.d - reference).abs() <= 1e-11 * size,
            "case {case}: exact {} sampled {reference} ({:?})",
            at.d,
            at.kind
        );
        if at.d > 0.0 {
            apart += 1;
        } else if at.d < -(c.min_radius_of_curvature() + b.corner_radius()) {
            deep += 1;
        }
    }
    assert!(
        apart > 20 && deep > 20,
        "{apart} apart, {deep} deeper than the smallest radii"
    );
}

/// A polygon of `n` vertices on an ellipse of semi-axes 1.0 and 0.6 (cones of unequal widths)
/// dilated by 0.05.
fn many_sided(n: usize) -> RoundedPolygon {
    let verts: Vec<Vector> = (0..n)
        .map(|i| {
            let a = 2.0 * PI * i as f64 / n as f64;
            Vector::new(a.cos(), 0.6 * a.sin())
        })
        .collect();
    RoundedPolygon::from_core_unchecked(verts, 0.05)
}

/// The far-direction search of a polygon's support answers what the brute-force maximum of v·m
/// does (the same value: a tie may pick either vertex), from any hint, on polygons of 3 to 10⁵
/// vertices, regular, squashed or with collinear vertices (edges whose normals repeat).
#[test]
fn support_search_from_a_far_hint_finds_the_support_of_any_direction() {
    let mut rng = Rng(41);
    let mut checked = 0;
    for &n in &[3usize, 7, 16, 17, 40, 1000, 100_000] {
        let p = many_sided(n);
        let mut verts = p.vertices().to_vec();
        // The same polygon with a vertex in the middle of each of a few edges (collinear triples).
        for k in (0..n.min(30)).rev().step_by(3) {
            let mid = (verts[k] + verts[(k + 1) % n]) * 0.5;
            verts.insert(k + 1, mid);
        }
        let q = RoundedPolygon::from_core_unchecked(verts, 0.05);
        for poly in [&p, &q] {
            let s = PolySide::new(poly.vertices(), poly.edge_normals(), 0.05).expect("a polygon");
            for _ in 0..200 {
                let m = unit(rng.range(-PI, PI));
                let hint = (rng.next() * s.len() as f64) as usize;
                let best = s.verts.iter().map(|v| v.dot(m)).fold(f64::NEG_INFINITY, f64::max);
                let got = s.support_index_far(m, hint);
                assert_eq!(s.verts[got].dot(m), best, "{n} vertices, hint {hint}, direction {m:?}");
                checked += 1;
            }
            // Each edge normal (a tie of its two ends, to the rounding of v·m).
            for k in (0..s.len()).step_by(s.len() / 50 + 1) {
                let m = s.normals[k];
                let best = s.verts.iter().map(|v| v.dot(m)).fold(f64::NEG_INFINITY, f64::max);
                let got = s.verts[s.support_index_far(m, 0)].dot(m);
                assert!(
                    best - got <= 2.0 * f64::EPSILON * best.abs(),
                    "{n} vertices, edge {k}: {got} vs {best}"
                );
                checked += 1;
            }
        }
    }
    println!("support search: {checked} directions");
}

/// The exact distance of a polygon of 20,000 vertices and a `CapsuleEllipse` is the same from
/// any starting axis, apart or overlapping, and the walk from an axis far from the answer jumps
/// across the polygon's tiny cones: at most 200 intervals where a walk one interval at a time
/// visits thousands (hostile seed 5105: 19,000 a call, 3.8 s for a time of impact).
#[test]
fn the_walk_from_a_far_axis_jumps_across_the_cones_of_a_many_sided_polygon() {
    use super::maxgap::WALK_INTERVALS;
    use super::side::CurveSide;
    use crate::CapsuleEllipse;
    let b = many_sided(20_000);
    let mut rng = Rng(53);
    let (mut apart, mut overlapping, mut most) = (0, 0, 0);
    for case in 0..60 {
        let c = CapsuleEllipse::new(rng.range(0.1, 0.4), rng.range(0.1, 0.6), rng.range(0.1, 0.6));
        let m1 = NonlinearRigidMotion::constant_position(Pose::new(
            unit(rng.range(-PI, PI)) * rng.range(0.3, 2.5),
            rng.range(-PI, PI),
        ));
        let m2 = NonlinearRigidMotion::constant_position(Pose::new(Vector::ZERO, rng.range(-PI, PI)));
        let pair = Pair {
            sides: [
                Side::Curve(CurveSide {
                    curve: &c,
                    faces: c.flats(),
                }),
                side(&b),
            ],
            motion: GapMotion::new(&m1, &m2),
        };
        let fr = pair.motion.frame(0.0);
        let mut answers = Vec::new();
        for k in 0..8 {
            let u0 = unit(rng.range(-PI, PI) + k as f64);
            WALK_INTERVALS.with(|w| w.set(0));
            let at = pair.max_gap(&fr, u0, (0, 0)).expect("finite");
            most = most.max(WALK_INTERVALS.with(|w| w.get()));
            answers.push(at.d);
        }
        let size = 1.05;
        let (lo, hi) = answers
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), d| (l.min(*d), h.max(*d)));
        assert!(hi - lo <= 1e-12 * size, "case {case}: distances {answers:?}");
        if lo > 0.0 {
            apart += 1;
        } else {
            overlapping += 1;
        }
    }
    println!("many-sided walk: {apart} apart, {overlapping} overlapping, at most {most} intervals a walk");
    assert!(
        apart >= 10 && overlapping >= 10,
        "{apart} apart, {overlapping} overlapping"
    );
    assert!(most <= 200, "a walk visited {most} intervals");
}
