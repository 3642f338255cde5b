//! The degenerate starts of `tests/degenerate_starts.rs` as timed cases (`cargo bench --bench
//! ratios -- corner`, `cargo bench --bench toi -- corner`): a unit disc centred on the corner of
//! the unit box (the pathological cast: 4,002 evaluations, 1.7 ms, before the stationary
//! distance's sinusoid bound) and its neighbours — the centre within 1e-6 of the vertex, on and
//! near an edge, on and near the box's centre, an ellipse instead of the disc, parry's `Ball`
//! and `Cuboid`, a square on a square (the gap tracker), `BallCurve` and `CustomCurve` through
//! `time_of_impact`, and the walk out of a separating contact without `stop_at_penetration`.
//! parry's own cast is timed beside ours where parry has the pair (`Ball`, `Cuboid`).

use parry2d_f64::math::{Pose, Vector};
use parry2d_f64::query::{DefaultQueryDispatcher, NonlinearRigidMotion, QueryDispatcher, ShapeCastHit};
use parry2d_f64::shape::{Ball, Cuboid, Shape};
use smooth_ccd2d::{
    shape_time_of_impact, time_of_impact, BallCurve, ConvexCurve, CustomCurve, Ellipse, QueryError, RoundedPolygon,
    TimeOfImpact, ToiOptions,
};

/// The unit box: the core square [0, 1]², sharp.
pub fn unit_box() -> RoundedPolygon {
    RoundedPolygon::new(
        &[
            Vector::new(0.0, 0.0),
            Vector::new(1.0, 0.0),
            Vector::new(1.0, 1.0),
            Vector::new(0.0, 1.0),
        ],
        0.0,
    )
}

/// A square of side 1 centred on its origin.
fn square() -> RoundedPolygon {
    RoundedPolygon::new(
        &[
            Vector::new(-0.5, -0.5),
            Vector::new(0.5, -0.5),
            Vector::new(0.5, 0.5),
            Vector::new(-0.5, 0.5),
        ],
        0.0,
    )
}

/// parry's own shapes for a pair, with their motions (its `Cuboid` is centred on its origin).
pub struct ParryPair {
    pub g1: Box<dyn Shape>,
    pub m1: NonlinearRigidMotion,
    pub g2: Box<dyn Shape>,
    pub m2: NonlinearRigidMotion,
}

/// How a case is asked.
pub enum Query {
    /// `shape_time_of_impact` on parry shapes; parry's own cast on `parry` when it has the pair.
    Shapes {
        g1: Box<dyn Shape>,
        g2: Box<dyn Shape>,
        parry: Option<ParryPair>,
    },
    /// `time_of_impact` on the curves themselves.
    Curves {
        c1: Box<dyn ConvexCurve>,
        c2: Box<dyn ConvexCurve>,
    },
}

/// One timed degenerate start over the window [0, 1].
pub struct CornerCase {
    pub name: String,
    pub query: Query,
    pub m1: NonlinearRigidMotion,
    pub m2: NonlinearRigidMotion,
    pub stop: bool,
}

impl CornerCase {
    /// This crate's answer.
    #[inline]
    pub fn ours(&self) -> Result<TimeOfImpact, QueryError> {
        let o = ToiOptions::default().with_stop_at_penetration(self.stop);
        match &self.query {
            Query::Shapes { g1, g2, .. } => shape_time_of_impact(&**g1, &self.m1, &**g2, &self.m2, 0.0, 1.0, &o),
            Query::Curves { c1, c2 } => time_of_impact(&**c1, &self.m1, &**c2, &self.m2, 0.0, 1.0, &o),
        }
    }

    /// Whether parry has the pair (then [`CornerCase::parry`] answers).
    pub fn has_parry(&self) -> bool {
        matches!(&self.query, Query::Shapes { parry: Some(_), .. })
    }

    /// parry's nonlinear cast of its own shapes for the pair (`None` without them, or no hit).
    #[inline]
    pub fn parry(&self) -> Option<ShapeCastHit> {
        let Query::Shapes { parry: Some(p), .. } = &self.query else {
            return None;
        };
        DefaultQueryDispatcher
            .cast_shapes_nonlinear(&p.m1, &*p.g1, &p.m2, &*p.g2, 0.0, 1.0, self.stop)
            .ok()
            .flatten()
    }
}

/// A shape at `at` turned by `angle`, at rest or translating and spinning away.
fn placed(at: Vector, angle: f64, moving: bool) -> NonlinearRigidMotion {
    let (v, w) = if moving {
        (Vector::new(0.3, -0.2), 1.5)
    } else {
        (Vector::ZERO, 0.0)
    };
    NonlinearRigidMotion::new(Pose::new(at, angle), Vector::ZERO, v, w)
}

/// The cases, in the order of the table.
pub fn cases() -> Vec<CornerCase> {
    let e = 1e-6;
    let (v, m, c) = (Vector::new(1.0, 1.0), Vector::new(1.0, 0.5), Vector::new(0.5, 0.5));
    let id = NonlinearRigidMotion::identity();
    let half = Vector::new(0.5, 0.5);
    let mut out = Vec::new();
    // The unit disc against the unit box; parry's pair: its `Ball` against its `Cuboid` moved
    // onto [0, 1]².
    let mut disc = |name: &str, at: Vector, stop: bool, moving: bool, swapped: bool| {
        let m_disc = placed(at, 0.0, moving);
        let (ball, cuboid): (Box<dyn Shape>, Box<dyn Shape>) = (Box::new(Ball::new(1.0)), Box::new(Cuboid::new(half)));
        let (disc, bx): (Box<dyn Shape>, Box<dyn Shape>) = (Box::new(Ellipse::new(1.0, 1.0)), Box::new(unit_box()));
        let m_cuboid = placed(c, 0.0, false);
        let (query, m1, m2) = if swapped {
            let parry = ParryPair {
                g1: cuboid,
                m1: m_cuboid,
                g2: ball,
                m2: m_disc,
            };
            let q = Query::Shapes {
                g1: bx,
                g2: disc,
                parry: Some(parry),
            };
            (q, id, m_disc)
        } else {
            let parry = ParryPair {
                g1: ball,
                m1: m_disc,
                g2: cuboid,
                m2: m_cuboid,
            };
            let q = Query::Shapes {
                g1: disc,
                g2: bx,
                parry: Some(parry),
            };
            (q, m_disc, id)
        };
        out.push(CornerCase {
            name: name.to_string(),
            query,
            m1,
            m2,
            stop,
        });
    };
    disc("disc on the box's corner (the issue)", v, true, false, false);
    disc("box, disc on its corner (swapped)", v, true, false, true);
    disc(
        "disc at (1.01, 1) (the issue's comparison)",
        Vector::new(1.01, 1.0),
        true,
        false,
        false,
    );
    disc(
        "disc 1e-6 outside the corner",
        v + Vector::new(e, e),
        true,
        false,
        false,
    );
    disc("disc 1e-6 inside the corner", v - Vector::new(e, e), true, false, false);
    disc("disc on an edge's middle", m, true, false, false);
    disc("disc 1e-6 inside an edge", m - Vector::new(e, 0.0), true, false, false);
    disc("disc on the box's centre", c, true, false, false);
    disc(
        "disc 1e-6 from the box's centre",
        c + Vector::new(e, -e),
        true,
        false,
        false,
    );
    disc("disc on the corner, moving", v, true, true, false);
    disc("disc on the corner, moving, without stop", v, false, true, false);
    let ellipse = |name: &str, at: Vector| CornerCase {
        name: name.to_string(),
        query: Query::Shapes {
            g1: Box::new(Ellipse::new(1.0, 0.5)),
            g2: Box::new(unit_box()),
            parry: None,
        },
        m1: placed(at, 0.0, false),
        m2: id,
        stop: true,
    };
    out.push(ellipse("ellipse 1×0.5 on the corner", v));
    out.push(ellipse("ellipse 1×0.5 on an edge's middle", m));
    out.push(ellipse("ellipse 1×0.5 on the box's centre", c));
    let curves = |name: &str, c1: Box<dyn ConvexCurve>| CornerCase {
        name: name.to_string(),
        query: Query::Curves {
            c1,
            c2: Box::new(unit_box()),
        },
        m1: placed(v, 0.0, false),
        m2: id,
        stop: true,
    };
    out.push(curves(
        "BallCurve on the corner (time_of_impact)",
        Box::new(BallCurve { radius: 1.0 }),
    ));
    out.push(curves(
        "CustomCurve disc on the corner (time_of_impact)",
        Box::new(CustomCurve::new(Ellipse::new(1.0, 1.0))),
    ));
    // A square (centred on its origin) on a feature of another at the origin; parry's pair: two
    // `Cuboid`s, the same boundaries.
    let squares = |name: &str, at: Vector, angle: f64| {
        let m1 = placed(at, angle, false);
        CornerCase {
            name: name.to_string(),
            query: Query::Shapes {
                g1: Box::new(square()),
                g2: Box::new(square()),
                parry: Some(ParryPair {
                    g1: Box::new(Cuboid::new(half)),
                    m1,
                    g2: Box::new(Cuboid::new(half)),
                    m2: id,
                }),
            },
            m1,
            m2: id,
            stop: true,
        }
    };
    out.push(squares("square on a square's corner", half, 0.0));
    out.push(squares(
        "square turned 45° on a square's corner",
        half,
        core::f64::consts::FRAC_PI_4,
    ));
    out.push(squares("square on a square's edge", Vector::new(0.5, 0.0), 0.0));
    out.push(squares("square turned 0.3 on a square's centre", Vector::ZERO, 0.3));
    out
}
