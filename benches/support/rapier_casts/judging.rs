//! Each answer judged against the reference: this crate's against its own rule, parry's
//! against its sweep's band (or its core circle at a fraction 0).

use super::*;

fn nlerp_opts() -> RefToiOptions {
    RefToiOptions {
        nlerp: true,
        ..RefToiOptions::default()
    }
}

/// One answer judged: (miss, false, off, |Δf| where both hit).
#[derive(Copy, Clone, Debug, Default)]
pub struct Verdict {
    pub miss: bool,
    pub false_hit: bool,
    pub off: bool,
    pub undecided: bool,
    pub err: Option<f64>,
}

/// The judged case: the answers, the reference's hit and the verdicts.
pub struct Judged {
    pub ours: Option<f64>,
    pub parry: Option<f64>,
    /// The reference's fraction of this crate's event (touching, or its rule), if any.
    pub ref_hit: Option<f64>,
    pub ours_v: Verdict,
    pub parry_v: Verdict,
}

/// The sum of the proxies' radii of parry's cast of `body` (a `ToiProxy`) against the target.
fn proxy_radii(body: &dyn Shape, target: &dyn Shape) -> f64 {
    let r = |s: &dyn Shape| ToiProxy::from_shape(s).map_or(0.0, |p| p.radius);
    r(body) + r(target)
}

/// The reference of `body` (a curve) moving by `m` against the target, down to `level` of the
/// signed distance: the target's support pushed out by `level` (the pair's signed distance less
/// `level`) at target 0 where that keeps a genuine shape (an erosion by at most `erodible`, the
/// pair's rounding), else the reference's own target (a slower search below 0).
fn reference_level(c: &RCase, body: &dyn ConvexCurve, m: &NonlinearRigidMotion, level: f64, erodible: f64) -> RefToi {
    let fixed = NonlinearRigidMotion::constant_position(c.target_pose);
    if level >= -erodible {
        let target = ParryCurve {
            shape: c.target_shape.clone(),
            shift: Vector::ZERO,
            offset: level,
        };
        reference_toi_with(body, m, &target, &fixed, 0.0, DT, 0.0, &nlerp_opts())
    } else {
        let target = ParryCurve {
            shape: c.target_shape.clone(),
            shift: Vector::ZERO,
            offset: 0.0,
        };
        reference_toi_with(body, m, &target, &fixed, 0.0, DT, level, &nlerp_opts())
    }
}

/// parry's answer judged against its band: `body` the curve of the proxy it casts, `radii` the
/// sum of the proxies' radii, `d0` their signed distance at the start.
fn judge_parry_band(
    c: &RCase,
    body: &dyn ConvexCurve,
    m: &NonlinearRigidMotion,
    radii: f64,
    answer: Option<f64>,
    physical: bool,
) -> Verdict {
    let tau = SLOP.max(radii - SLOP);
    let (lo, hi) = (tau - 0.25 * SLOP - radii, tau + 0.25 * SLOP - radii);
    let size = body
        .bounding_radius()
        .max(c.target_shape.compute_local_bounding_sphere().radius);
    let mut v = Verdict::default();
    let touch = physical.then(|| reference_level(c, body, m, 0.0, radii));
    let crossed = |r: &RefToi| matches!(r.outcome, RefOutcome::Hit { crossed: true, .. });
    let capped = |r: &RefToi| r.is_capped();
    match answer {
        None => {
            // A miss: the pair goes past the band's deep end (and, physically, touches).
            let need = touch.as_ref().is_none_or(crossed);
            if need {
                let r_lo = if physical && lo >= 0.0 {
                    touch.unwrap()
                } else {
                    reference_level(c, body, m, lo, radii)
                };
                v.undecided = capped(&r_lo);
                v.miss = crossed(&r_lo);
            }
        }
        Some(f) => {
            let r_hi = reference_level(c, body, m, hi, radii);
            let r_lo = reference_level(c, body, m, lo, radii);
            v.undecided = capped(&r_hi) || capped(&r_lo);
            let t = f * DT;
            match r_hi.hit_time() {
                // Never within the band's shallow end: a false impact; physically, only where
                // the shapes never touch either (else a hit outside the band).
                None => {
                    let touches = touch.as_ref().is_some_and(|r| r.is_hit());
                    v.false_hit = r_hi.min_gap >= 1e-9 * size && !touches;
                    v.off = touches;
                }
                Some(th) => {
                    let tol = 1e-6 * DT;
                    let tl = r_lo.hit_time().unwrap_or(DT);
                    v.off = t < th - tol || t > tl + tol;
                }
            }
            if let Some(tr) = touch.as_ref().and_then(|r| r.hit_time()) {
                v.err = Some((f - tr / DT).abs());
            } else if !physical {
                let th = r_hi.hit_time().unwrap_or(t);
                let tl = r_lo.hit_time().unwrap_or(DT);
                v.err = Some(((th - t).max(t - tl)).max(0.0) / DT);
            }
        }
    }
    v
}

/// This crate's answer judged against a reference of its event (`support::judge`).
fn judge_ours(answer: Option<f64>, rf: &RefToi, size: f64) -> Verdict {
    let mut v = Verdict::default();
    let Some(right) = judge(answer.map(|f| f * DT), rf, size, DT) else {
        v.undecided = true;
        return v;
    };
    let ref_hit = rf.hit_time();
    if let (Some(f), Some(t)) = (answer, ref_hit) {
        v.err = Some((f - t / DT).abs());
    }
    if !right {
        match (answer, ref_hit) {
            (None, Some(_)) => v.miss = true,
            (Some(_), None) => v.false_hit = true,
            _ => v.off = true,
        }
    }
    v
}

/// The earlier-hitting of two references (the first when neither hits), with the smaller least
/// gap.
fn earlier(a: RefToi, b: RefToi) -> RefToi {
    let mut e = match (a.hit_time(), b.hit_time()) {
        (Some(x), Some(y)) if y < x => b,
        (None, Some(_)) => b,
        _ => a,
    };
    if a.is_capped() || b.is_capped() {
        e.outcome = RefOutcome::Capped { reached: 0.0 };
    }
    e.min_gap = a.min_gap.min(b.min_gap);
    e
}

/// The contact rule 3 measures `c`'s start contact on where it is not the exact one (against a
/// `Segment`, the contact from the side of the body's centre): its normal from the body to the
/// target in the body's frame and its signed distance.
fn line_contact(c: &RCase) -> Option<(Vector, f64)> {
    let pos12 = c.motion.start.inv_mul(&c.target_pose);
    smooth_ccd2d::__rule3_line_contact(&pos12, &*c.ours, &*c.target_shape)
}

/// The half-plane behind a segment's line, on the side away from the body (`n`: the normal from
/// the body to the segment, the body's frame at the start), as a box of half-side `L` = 10³ m
/// whose face lies on the line, centred on the foot of the body's centre there: the body's signed
/// distance to it is its reach past the line while the body stays within `L` along it. The box
/// and its pose.
fn half_plane_behind(c: &RCase, n: Vector) -> (ParryCurve, Pose) {
    const L: f64 = 1e3;
    let seg = c.target_shape.as_shape::<Segment>().expect("a segment target");
    let on_line = c.target_pose * seg.a;
    let out = c.motion.start.rotation * (-n); // from the line towards the body, in the world
    let centre = c.motion.start * c.motion.local_center;
    let foot = centre - out * (centre - on_line).dot(out);
    // The box's +y axis along `out`, its top face on the line.
    let rotation = parry2d_f64::math::Rotation::new(out.y.atan2(out.x) - core::f64::consts::FRAC_PI_2);
    let pose = Pose::from_parts(foot - out * L, rotation);
    let shape = ParryCurve {
        shape: Arc::new(Cuboid::new(Vector::new(L, L))),
        shift: Vector::ZERO,
        offset: 0.0,
    };
    (shape, pose)
}

/// Judges both answers of `c`.
pub fn judge_case(c: &RCase, ours: Option<f64>, parry: Option<f64>) -> Judged {
    let size = c
        .ours_curve
        .bounding_radius()
        .max(c.target_shape.compute_local_bounding_sphere().radius);
    let parry_curve: Arc<dyn ConvexCurve> = if c.body == Body::Ellipse {
        Arc::new(ParryCurve {
            shape: c.parry.clone(),
            shift: Vector::ZERO,
            offset: 0.0,
        })
    } else {
        c.ours_curve.clone()
    };
    let radii = proxy_radii(&*c.parry, &*c.target_shape);
    match c.set {
        Set::Apart | Set::Beyond | Set::Still => {
            let rf = reference_level(c, &*c.ours_curve, &c.motion, 0.0, 0.0);
            let ours_v = judge_ours(ours, &rf, size);
            let parry_v = judge_parry_band(c, &*parry_curve, &c.motion, radii, parry, true);
            Judged {
                ours,
                parry,
                ref_hit: rf.hit_time().map(|t| t / DT),
                ours_v,
                parry_v,
            }
        }
        Set::Contact => {
            // This crate's rule: the core, and the translation's deepening.
            let r = c.inradius;
            let spinless = NonlinearRigidMotion {
                angvel: 0.0,
                ..c.motion
            };
            let fixed = NonlinearRigidMotion::constant_position(c.target_pose);
            let target = ParryCurve {
                shape: c.target_shape.clone(),
                shift: Vector::ZERO,
                offset: 0.0,
            };
            let trans = match line_contact(c) {
                // Against a segment with the body's centre on one side: the contact from the
                // centre's side, the body's reach past the segment's line (the rule's choice of
                // contact is the crate's, `__rule3_line_contact`; its time the reference's).
                Some((n, d_line)) => {
                    let level = (-OUR_ALLOWANCE * r).min(d_line - OUR_ALLOWANCE * r);
                    let (half_plane, pose) = half_plane_behind(c, n);
                    let behind = NonlinearRigidMotion::constant_position(pose);
                    reference_toi_with(
                        &*c.ours_curve,
                        &spinless,
                        &half_plane,
                        &behind,
                        0.0,
                        DT,
                        level,
                        &nlerp_opts(),
                    )
                }
                None => {
                    let level = (-OUR_ALLOWANCE * r).min(c.d0 - OUR_ALLOWANCE * r);
                    reference_toi_with(
                        &*c.ours_curve,
                        &spinless,
                        &target,
                        &fixed,
                        0.0,
                        DT,
                        level,
                        &nlerp_opts(),
                    )
                }
            };
            let centre = NonlinearRigidMotion::new(
                Pose::from_translation(c.motion.start * c.motion.local_center),
                Vector::ZERO,
                c.motion.linvel,
                0.0,
            );
            let core = BallCurve { radius: OUR_CORE * r };
            let core_ref = reference_toi_with(&core, &centre, &target, &fixed, 0.0, DT, 0.0, &nlerp_opts());
            let rule = earlier(trans, core_ref);
            let ours_v = judge_ours(ours, &rule, size);
            // rapier's rule for parry: the sweep's band, or its core circle's at a fraction 0.
            let tau = SLOP.max(radii - SLOP);
            let parry_d0 = if c.body == Body::Ellipse {
                distance(&*parry_curve, &c.motion.start, &target, &c.target_pose)
            } else {
                c.d0
            };
            let parry_v = if parry_d0 > tau + 0.25 * SLOP - radii {
                judge_parry_band(c, &*parry_curve, &c.motion, radii, parry, false)
            } else {
                let rc = CORE_FRACTION * c.parry_thickness;
                let core = ParryCurve {
                    shape: Arc::new(Ball::new(rc)),
                    shift: c.parry_centroid,
                    offset: 0.0,
                };
                let core_radii = rc + ToiProxy::from_shape(&*c.target_shape).map_or(0.0, |p| p.radius);
                judge_parry_band(c, &core, &c.motion, core_radii, parry, false)
            };
            Judged {
                ours,
                parry,
                ref_hit: rule.hit_time().map(|t| t / DT),
                ours_v,
                parry_v,
            }
        }
    }
}
