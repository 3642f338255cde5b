//! Shapes and random motions the advancement's unit tests share: a hexagon-like polygon with
//! round corners and an ellipse as the turning body B, a flat box as the target A at rest, and
//! B's random motion on the nlerp path against it.

use super::PairOnPath;
use crate::numerics::math::{perp, Pose, Real, Vector};
use crate::query::contact::SupportShape;
use crate::query::path::OnPath;
use crate::MotionPath;
use core::f64::consts::PI;
use parry2d_f64::query::NonlinearRigidMotion;

/// The vertices and edge normals of the test shapes (borrowed by their `SupportShape`s).
pub(super) struct TestShapes {
    hex: Vec<Vector>,
    hex_normals: Vec<Vector>,
    box_v: [Vector; 4],
    box_n: [Vector; 4],
}

impl TestShapes {
    pub(super) fn new() -> Self {
        let hex: Vec<Vector> = (0..6)
            .map(|i| {
                let a = i as Real * PI / 3.0;
                Vector::new(0.5 * a.cos(), 0.3 * a.sin())
            })
            .collect();
        let hex_normals = (0..6).map(|i| -perp(hex[(i + 1) % 6] - hex[i]).normalize()).collect();
        TestShapes {
            hex,
            hex_normals,
            box_v: [
                Vector::new(-1.0, -0.2),
                Vector::new(1.0, -0.2),
                Vector::new(1.0, 0.2),
                Vector::new(-1.0, 0.2),
            ],
            box_n: [-Vector::Y, Vector::X, Vector::Y, -Vector::X],
        }
    }

    /// The turning bodies: the hexagon (corner radius 0.05) and a 0.6 × 0.15 ellipse.
    pub(super) fn bodies(&self) -> [SupportShape<'_>; 2] {
        [
            SupportShape::Polygon {
                vertices: &self.hex,
                normals: &self.hex_normals,
                radius: 0.05,
            },
            SupportShape::Ellipse(0.6, 0.15),
        ]
    }

    /// The target at rest: a 2 × 0.4 box.
    pub(super) fn flat_box(&self) -> SupportShape<'_> {
        SupportShape::Polygon {
            vertices: &self.box_v,
            normals: &self.box_n,
            radius: 0.0,
        }
    }
}

/// B's random motion over [0, 1] against A at rest at the origin, on the nlerp path, drawn from
/// `uniform` in this order: the start (x, y, angle), the velocity, the rotation centre (when
/// `centre_spread` is given: each coordinate within it; else B's origin), the spin.
pub(super) fn random_pair(
    uniform: &mut impl FnMut(Real, Real) -> Real,
    centre_spread: Option<Real>,
) -> (NonlinearRigidMotion, PairOnPath) {
    let start = Pose::new(Vector::new(uniform(-4.0, 4.0), uniform(-4.0, 4.0)), uniform(-3.2, 3.2));
    let v = Vector::new(uniform(-6.0, 6.0), uniform(-6.0, 6.0));
    let centre = centre_spread.map_or(Vector::ZERO, |s| Vector::new(uniform(-s, s), uniform(-s, s)));
    let mb = NonlinearRigidMotion::new(start, centre, v, uniform(-3.0, 3.0));
    let ma = NonlinearRigidMotion::constant_position(Pose::IDENTITY);
    let on = OnPath::new(&ma, &mb, 0.0, 1.0, MotionPath::Nlerp).unwrap();
    (mb, PairOnPath::of(&on).unwrap())
}
