//! A parry2d (f32) shape as the parry2d-f64 shape the core dispatcher reads: this package's
//! shapes give their f64 shape by reference; parry's convex shapes that the core converts to
//! curves (ball, cuboid, capsule, segment, triangle, convex polygon, their round versions) and
//! the half-space are rebuilt in f64 from their widened parameters, on the stack except for a
//! polygon's vertex list. Anything else (composites, voxels, a user's own shape) is not widened.

use crate::convert::v64;
use crate::shapes::own_f64;
use parry2d::shape::{RoundShape, Shape, TypedShape};
use parry2d_f64::shape as s64;

/// A shape in f64, borrowed (this package's shapes) or rebuilt (parry's).
pub(crate) enum Wide<'a> {
    /// One of this package's shapes: its f64 shape.
    Own(&'a dyn s64::Shape),
    /// A parry ball.
    Ball(s64::Ball),
    /// A parry cuboid.
    Cuboid(s64::Cuboid),
    /// A parry round cuboid.
    RoundCuboid(s64::RoundCuboid),
    /// A parry capsule.
    Capsule(s64::Capsule),
    /// A parry segment.
    Segment(s64::Segment),
    /// A parry triangle.
    Triangle(s64::Triangle),
    /// A parry round triangle.
    RoundTriangle(s64::RoundTriangle),
    /// A parry convex polygon.
    Polygon(s64::ConvexPolygon),
    /// A parry round convex polygon.
    RoundPolygon(s64::RoundConvexPolygon),
    /// A parry half-space.
    HalfSpace(s64::HalfSpace),
}

impl Wide<'_> {
    /// The f64 shape.
    pub(crate) fn get(&self) -> &dyn s64::Shape {
        match self {
            Wide::Own(s) => *s,
            Wide::Ball(s) => s,
            Wide::Cuboid(s) => s,
            Wide::RoundCuboid(s) => s,
            Wide::Capsule(s) => s,
            Wide::Segment(s) => s,
            Wide::Triangle(s) => s,
            Wide::RoundTriangle(s) => s,
            Wide::Polygon(s) => s,
            Wide::RoundPolygon(s) => s,
            Wide::HalfSpace(s) => s,
        }
    }
}

fn segment(s: &parry2d::shape::Segment) -> s64::Segment {
    s64::Segment::new(v64(s.a), v64(s.b))
}

fn triangle(t: &parry2d::shape::Triangle) -> s64::Triangle {
    s64::Triangle::new(v64(t.a), v64(t.b), v64(t.c))
}

fn polygon(p: &parry2d::shape::ConvexPolygon) -> Option<s64::ConvexPolygon> {
    s64::ConvexPolygon::from_convex_polyline_unmodified(p.points().iter().map(|&v| v64(v)).collect())
}

fn round<S>(inner_shape: S, border_radius: f32) -> s64::RoundShape<S> {
    s64::RoundShape {
        inner_shape,
        border_radius: border_radius as f64,
    }
}

/// `g` in f64, or `None` when the core does not take it (see the module docs).
pub(crate) fn widen(g: &dyn Shape) -> Option<Wide<'_>> {
    Some(match g.as_typed_shape() {
        TypedShape::Custom(_) => Wide::Own(own_f64(g)?),
        TypedShape::Ball(b) => Wide::Ball(s64::Ball::new(b.radius as f64)),
        TypedShape::Cuboid(c) => Wide::Cuboid(s64::Cuboid::new(v64(c.half_extents))),
        TypedShape::RoundCuboid(RoundShape {
            inner_shape,
            border_radius,
        }) => Wide::RoundCuboid(round(s64::Cuboid::new(v64(inner_shape.half_extents)), *border_radius)),
        TypedShape::Capsule(c) => Wide::Capsule(s64::Capsule {
            segment: segment(&c.segment),
            radius: c.radius as f64,
        }),
        TypedShape::Segment(s) => Wide::Segment(segment(s)),
        TypedShape::Triangle(t) => Wide::Triangle(triangle(t)),
        TypedShape::RoundTriangle(RoundShape {
            inner_shape,
            border_radius,
        }) => Wide::RoundTriangle(round(triangle(inner_shape), *border_radius)),
        TypedShape::ConvexPolygon(p) => Wide::Polygon(polygon(p)?),
        TypedShape::RoundConvexPolygon(RoundShape {
            inner_shape,
            border_radius,
        }) => Wide::RoundPolygon(round(polygon(inner_shape)?, *border_radius)),
        TypedShape::HalfSpace(h) => {
            let n = v64(h.normal);
            let len = n.length();
            if !(len > 0.0 && len.is_finite()) {
                return None;
            }
            Wide::HalfSpace(s64::HalfSpace::new(n / len))
        }
        _ => return None,
    })
}

/// The pair in f64 when at least one side is this package's shape and both widen; `None`
/// otherwise (the pair is parry2d's).
pub(crate) fn widen_pair<'a>(g1: &'a dyn Shape, g2: &'a dyn Shape) -> Option<(Wide<'a>, Wide<'a>)> {
    if own_f64(g1).is_none() && own_f64(g2).is_none() {
        return None;
    }
    Some((widen(g1)?, widen(g2)?))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Ellipse;
    use parry2d::math::Vector;
    use parry2d::shape::{Ball, Compound, ConvexPolygon, Cuboid, HalfSpace, SharedShape};
    use parry2d_f64::math as m64;

    #[test]
    fn parry_shapes_widen_to_the_same_geometry() {
        let c = Cuboid::new(Vector::new(0.5, 0.25));
        let w = widen(&c).expect("cuboid widens");
        let aabb = w.get().compute_local_aabb();
        assert_eq!(aabb.maxs, m64::Vector::new(0.5, 0.25));
        let poly = ConvexPolygon::from_convex_polyline(vec![
            Vector::new(0.0, 0.0),
            Vector::new(1.0, 0.0),
            Vector::new(0.0, 1.0),
        ])
        .unwrap();
        assert!(widen(&poly).is_some());
        let hs = HalfSpace::new(Vector::new(0.6, 0.8));
        match widen(&hs) {
            Some(Wide::HalfSpace(h)) => assert!((h.normal.length() - 1.0).abs() < 1e-15),
            _ => panic!("half-space widens"),
        }
    }

    #[test]
    fn only_pairs_with_one_of_ours_widen() {
        let (e, b) = (Ellipse::new(0.5, 0.2), Ball::new(0.3));
        assert!(widen_pair(&e, &b).is_some());
        assert!(widen_pair(&b, &b).is_none());
        let compound = Compound::new(vec![(parry2d::math::Pose::identity(), SharedShape::ball(0.1))]);
        assert!(widen_pair(&e, &compound).is_none());
    }
}
