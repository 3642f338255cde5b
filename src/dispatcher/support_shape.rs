//! A shape as the exact contact query sees it ([`SupportShape`]): this crate's ellipses,
//! rounded polygons and capsule-ellipses, parry's discs, boxes, polygons, triangles, segments and
//! capsules (round or not) — read in place, or with their few vertices and normals written to a
//! caller's [`SupportScratch`] on the stack. No curve is built.

use super::input_guard;
use super::route::{box_vertices, triangle_hull};
use crate::numerics::math::{perp, Pose, Vector};
use crate::query::contact::{contact, Contact, SupportShape};
use crate::{CapsuleEllipse, Ellipse, RoundedPolygon};
use parry2d_f64::shape::{
    Ball, Capsule, ConvexPolygon, Cuboid, RoundConvexPolygon, RoundCuboid, RoundTriangle, Segment, Shape, ShapeType,
    Triangle,
};

/// Faces of the two shapes that face each other within this angle (radians) give the exact
/// contact's manifold two points, the incident face clipped to the reference face (as parry's and
/// Box2D's polygon manifolds clip the most anti-parallel face): the second point, a little apart
/// or already touching, lets rapier's solver see the rest of a face that a turning body brings
/// in, where one point would leave it blind until the faces meet.
pub(crate) const FACING_FACES_MAX_ANGLE: f64 = core::f64::consts::FRAC_PI_4;

/// Stack room for the vertices and normals of a parry box, triangle, segment or capsule.
#[derive(Default)]
pub(crate) struct SupportScratch {
    vertices: [Vector; 4],
    normals: [Vector; 4],
}

impl SupportScratch {
    /// The box `c` (half-extents positive, finite) dilated by `radius`: its normals are the
    /// axes, written without a division.
    fn cuboid(&mut self, c: &Cuboid, radius: f64) -> Option<SupportShape<'_>> {
        if !(radius.is_finite() && radius >= 0.0) {
            return None;
        }
        self.vertices = box_vertices(c);
        self.normals = [-Vector::Y, Vector::X, Vector::Y, -Vector::X];
        Some(SupportShape::Polygon {
            vertices: &self.vertices,
            normals: &self.normals,
            radius,
        })
    }

    /// The polygon with these vertices (counter-clockwise) and radius, normals computed here;
    /// `None` for a degenerate edge, a non-finite vertex or a bad radius.
    fn polygon(&mut self, v: &[Vector], radius: f64) -> Option<SupportShape<'_>> {
        let n = v.len();
        if !(radius.is_finite() && radius >= 0.0) {
            return None;
        }
        for i in 0..n {
            let e = v[(i + 1) % n] - v[i];
            let len = e.length();
            if !(len > 0.0 && len.is_finite()) {
                return None;
            }
            self.vertices[i] = v[i];
            self.normals[i] = -perp(e) / len;
        }
        Some(SupportShape::Polygon {
            vertices: &self.vertices[..n],
            normals: &self.normals[..n],
            radius,
        })
    }
}

/// A polygon stored with its normals (this crate's or parry's), unless a value is not finite
/// or the radius is negative.
fn stored<'a>(vertices: &'a [Vector], normals: &'a [Vector], radius: f64) -> Option<SupportShape<'a>> {
    let ok = radius.is_finite()
        && radius >= 0.0
        && vertices.len() >= 2
        && vertices.iter().chain(normals).all(|v| v.is_finite());
    ok.then_some(SupportShape::Polygon {
        vertices,
        normals,
        radius,
    })
}

/// The shape as the contact query sees it; `None` for any other shape (a user's curve, a
/// half-space, a composite) or invalid parameters.
pub(crate) fn support_shape<'a>(s: &'a dyn Shape, scratch: &'a mut SupportScratch) -> Option<SupportShape<'a>> {
    let box_ok = |c: &Cuboid| c.half_extents.x > 0.0 && c.half_extents.y > 0.0 && c.half_extents.is_finite();
    match s.shape_type() {
        ShapeType::Custom => {
            if let Some(e) = s.as_shape::<Ellipse>() {
                Some(SupportShape::Ellipse(e.half_x(), e.half_y()))
            } else if let Some(p) = s.as_shape::<RoundedPolygon>() {
                // Checked finite when it was built.
                Some(SupportShape::Polygon {
                    vertices: p.vertices(),
                    normals: p.edge_normals(),
                    radius: p.corner_radius(),
                })
            } else {
                let (r1, r2, r3) = s.as_shape::<CapsuleEllipse>()?.params();
                Some(SupportShape::CapsuleEllipse(r1, r2, r3))
            }
        }
        ShapeType::Ball => {
            let r = s.as_shape::<Ball>()?.radius;
            (r.is_finite() && r > 0.0).then_some(SupportShape::Disc(r))
        }
        ShapeType::Cuboid => {
            let c = s.as_shape::<Cuboid>()?;
            box_ok(c).then(|| scratch.cuboid(c, 0.0)).flatten()
        }
        ShapeType::RoundCuboid => {
            let c = s.as_shape::<RoundCuboid>()?;
            let inner = &c.inner_shape;
            box_ok(inner).then(|| scratch.cuboid(inner, c.border_radius)).flatten()
        }
        ShapeType::ConvexPolygon => {
            let p = s.as_shape::<ConvexPolygon>()?;
            stored(p.points(), p.normals(), 0.0)
        }
        ShapeType::RoundConvexPolygon => {
            let p = s.as_shape::<RoundConvexPolygon>()?;
            stored(p.inner_shape.points(), p.inner_shape.normals(), p.border_radius)
        }
        ShapeType::Triangle => {
            let t = s.as_shape::<Triangle>()?;
            let (v, n) = triangle_hull([t.a, t.b, t.c])?;
            scratch.polygon(&v[..n], 0.0)
        }
        ShapeType::RoundTriangle => {
            let t = s.as_shape::<RoundTriangle>()?;
            let t2 = &t.inner_shape;
            let (v, n) = triangle_hull([t2.a, t2.b, t2.c])?;
            scratch.polygon(&v[..n], t.border_radius)
        }
        ShapeType::Segment => {
            let sg = s.as_shape::<Segment>()?;
            scratch.polygon(&[sg.a, sg.b], 0.0)
        }
        ShapeType::Capsule => {
            let c = s.as_shape::<Capsule>()?;
            scratch.polygon(&[c.segment.a, c.segment.b], c.radius)
        }
        _ => None,
    }
}

/// The exact contact query ([`crate::query::contact`]) of a pair the dispatcher answers with it:
/// both shapes readable by [`support_shape`] and a proper pose; `None` otherwise (the caller
/// answers the pair another way). `hint`: a direction near the normal (rapier's previous one).
pub(crate) fn exact_contact(pos12: &Pose, g1: &dyn Shape, g2: &dyn Shape, hint: Option<Vector>) -> Option<Contact> {
    if !input_guard::pose_ok(pos12) {
        return None;
    }
    let (mut st1, mut st2) = (SupportScratch::default(), SupportScratch::default());
    let s1 = support_shape(g1, &mut st1)?;
    let s2 = support_shape(g2, &mut st2)?;
    contact(s1, s2, pos12, FACING_FACES_MAX_ANGLE.cos(), hint)
}

/// [`exact_contact`] of two shapes already read by [`support_shape`].
pub(crate) fn exact_contact_of(
    s1: SupportShape,
    s2: SupportShape,
    pos12: &Pose,
    hint: Option<Vector>,
) -> Option<Contact> {
    if !input_guard::pose_ok(pos12) {
        return None;
    }
    contact(s1, s2, pos12, FACING_FACES_MAX_ANGLE.cos(), hint)
}
