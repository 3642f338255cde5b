//! The pile of `examples/pile.rs` (200 ellipses, rounded polygons and `CapsuleEllipse`s dropped
//! into a box), built either with the exact shapes and `SmoothDispatcher` as rapier's narrow
//! phase, or with parry's polygon approximations (`POLYGON_VERTICES`-gons for the smooth shapes,
//! parry's `RoundConvexPolygon` for the rounded polygons) and parry's default dispatcher.

use super::{polygon_approximation, POLYGON_VERTICES};
use crate::common::world::World;
use rapier2d_f64::prelude::*;
use smooth_ccd2d::{CapsuleEllipse, Ellipse, RoundedPolygon, SmoothDispatcher};

/// Bodies in the pile.
pub const BODIES: usize = 200;
const COLUMNS: usize = 12;
const HALF_WIDTH: f64 = 6.0;
const WALL_HEIGHT: f64 = 24.0;

struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}

/// The shape of body `i` (the generator of `examples/pile.rs`), exact or as a polygon.
fn shape(i: usize, rng: &mut Lcg, exact: bool) -> SharedShape {
    let size = rng.range(0.15, 0.45);
    match i % 3 {
        0 => {
            let e = Ellipse::new(size, size * rng.range(0.3, 1.0));
            if exact {
                SharedShape::new(e)
            } else {
                SharedShape::new(polygon_approximation(&e, POLYGON_VERTICES))
            }
        }
        1 => {
            let sides = 3 + (rng.next() * 6.0) as usize;
            let p = RoundedPolygon::regular(sides, 0.85 * size, 0.15 * size * rng.range(0.3, 1.0));
            if exact {
                SharedShape::new(p)
            } else {
                SharedShape::new(p.to_parry().expect("a regular polygon"))
            }
        }
        _ => {
            let r1 = size * rng.range(0.35, 0.5);
            let c = CapsuleEllipse::new(r1, size * rng.range(0.1, 0.4), size * rng.range(0.4, 0.7));
            if exact {
                SharedShape::new(c)
            } else {
                SharedShape::new(polygon_approximation(&c, POLYGON_VERTICES))
            }
        }
    }
}

/// A rapier world stepping the pile.
pub struct Pile {
    world: World,
}

impl Pile {
    /// The pile at rest before the first step; `exact`: this crate's shapes and dispatcher.
    pub fn new(exact: bool) -> Self {
        let narrow_phase = if exact {
            NarrowPhase::with_query_dispatcher(SmoothDispatcher::default())
        } else {
            NarrowPhase::new()
        };
        let mut w = World::new(narrow_phase);
        let walls = [
            (Vector::new(0.0, -0.5), Vector::new(HALF_WIDTH + 1.0, 0.5)),
            (
                Vector::new(-HALF_WIDTH - 0.5, 0.5 * WALL_HEIGHT),
                Vector::new(0.5, 0.5 * WALL_HEIGHT),
            ),
            (
                Vector::new(HALF_WIDTH + 0.5, 0.5 * WALL_HEIGHT),
                Vector::new(0.5, 0.5 * WALL_HEIGHT),
            ),
        ];
        for (c, h) in walls {
            w.insert(
                RigidBodyBuilder::fixed().translation(c),
                ColliderBuilder::cuboid(h.x, h.y),
            );
        }
        let mut rng = Lcg(0x005e_ed2d);
        let spacing = 2.0 * HALF_WIDTH / COLUMNS as f64;
        for i in 0..BODIES {
            let s = shape(i, &mut rng, exact);
            let (row, col) = (i / COLUMNS, i % COLUMNS);
            let x = -HALF_WIDTH + spacing * (col as f64 + 0.5) + rng.range(-0.03, 0.03);
            let y = 1.0 + row as f64;
            w.insert(
                RigidBodyBuilder::dynamic()
                    .translation(Vector::new(x, y))
                    .rotation(rng.range(-3.0, 3.0))
                    .angvel(rng.range(-2.0, 2.0)),
                ColliderBuilder::new(s).friction(0.5),
            );
        }
        Pile { world: w }
    }

    /// One rapier step (1/60 s).
    pub fn step(&mut self) {
        self.world.step(Vector::new(0.0, -9.81), &());
    }

    /// Contact pairs with at least one contact point.
    pub fn touching_pairs(&self) -> usize {
        self.world
            .narrow_phase
            .contact_pairs()
            .filter(|p| p.manifolds().iter().any(|m| !m.points.is_empty()))
            .count()
    }
}
