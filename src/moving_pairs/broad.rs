//! The pass's broad phase: the pairs of colliders of two moving bodies, one of them fast, whose
//! swept boxes overlap ([`Broad::pairs`]); a still target (`PassBody::still`) only with a fast
//! body that turns past the pass's turn (`PassBody::turning`).
//!
//! The fast colliders (those of fast bodies) are sorted by the lower x of their swept boxes;
//! a sweep over that order gives the fast–fast pairs (sort and sweep), and each other moving
//! collider finds the fast boxes whose x-interval meets its own by a binary search and a walk
//! back over at most the widest fast box. With k fast colliders among n moving ones the cost is
//! O((k + n) log k) plus the overlaps found: it follows the number of fast bodies, and is
//! nothing when there is none (the caller does not call it). Pairs come out sorted by their
//! collider indices, whatever the order of the sort, so the pass is deterministic.

use super::records::{PassBody, PassCollider, PassPair};

/// The broad phase's scratch (kept by the pass: no allocation once warm).
#[derive(Clone, Debug, Default)]
pub struct Broad {
    fast: Vec<u32>,
}

impl Broad {
    /// Writes to `out` (cleared first) the pairs of `colliders` of two different `bodies`, one
    /// of them fast, whose swept boxes overlap, sorted by (a, b); a pair with a still target
    /// only when its fast body turns.
    pub fn pairs(&mut self, bodies: &[PassBody], colliders: &[PassCollider], out: &mut Vec<PassPair>) {
        out.clear();
        let fast_of = |c: &PassCollider| bodies[c.body as usize].fast;
        self.fast.clear();
        self.fast
            .extend((0..colliders.len() as u32).filter(|&i| fast_of(&colliders[i as usize])));
        // Sorted by lower x; NaN-free boxes (the paths are finite), ties by index.
        self.fast.sort_unstable_by(|&i, &j| {
            colliders[i as usize]
                .min
                .x
                .total_cmp(&colliders[j as usize].min.x)
                .then(i.cmp(&j))
        });
        let mut widest: f64 = 0.0;
        for &i in &self.fast {
            let c = &colliders[i as usize];
            widest = widest.max(c.max.x - c.min.x);
        }
        // Fast against fast: sort and sweep.
        for (k, &i) in self.fast.iter().enumerate() {
            let ci = &colliders[i as usize];
            for &j in &self.fast[k + 1..] {
                let cj = &colliders[j as usize];
                if cj.min.x > ci.max.x {
                    break;
                }
                if ci.body != cj.body && ci.overlaps(cj) {
                    out.push(PassPair::new(i, j));
                }
            }
        }
        // Every other moving collider against the fast ones.
        for (o, co) in colliders.iter().enumerate() {
            if fast_of(co) {
                continue;
            }
            // The fast boxes with lower x ≤ co's upper x: a prefix of the order.
            let end = self.fast.partition_point(|&i| colliders[i as usize].min.x <= co.max.x);
            for &i in self.fast[..end].iter().rev() {
                let ci = &colliders[i as usize];
                if ci.min.x < co.min.x - widest {
                    break;
                }
                let allowed = !bodies[co.body as usize].still || bodies[ci.body as usize].turning;
                if ci.body != co.body && allowed && ci.overlaps(co) {
                    out.push(PassPair::new(i, o as u32));
                }
            }
        }
        out.sort_unstable_by_key(|p| (p.a, p.b));
    }
}

#[cfg(test)]
mod tests {
    use super::super::path::StepPath;
    use super::*;
    use crate::numerics::math::{Pose, Vector};
    use crate::numerics::test_rng::Lcg;

    /// The broad phase finds exactly the overlapping pairs with a fast side that a brute-force
    /// double loop finds, over random boxes.
    #[test]
    fn pairs_are_those_of_the_double_loop() {
        let mut rng = Lcg(7);
        let mut broad = Broad::default();
        let mut out = Vec::new();
        let mut total = 0;
        for round in 0..200 {
            let n = 1 + round % 40;
            let dt = 0.1;
            let bodies: Vec<PassBody> = (0..n)
                .map(|_| {
                    let start = Pose::translation(rng.range(-10.0, 10.0), rng.range(-10.0, 10.0));
                    let end = Pose::translation(rng.range(-10.0, 10.0), rng.range(-10.0, 10.0));
                    let path = StepPath::new(&start, &end, Vector::ZERO, Vector::ZERO, 0.0, dt).unwrap();
                    let mut b = PassBody::new(path, rng.range(0.0, 1.0) < 0.3, true, 1.0);
                    b.turning = b.fast && rng.range(0.0, 1.0) < 0.5;
                    if !b.fast && rng.range(0.0, 1.0) < 0.3 {
                        b = PassBody::target(&start, dt);
                    }
                    b
                })
                .collect();
            let colliders: Vec<PassCollider> = (0..2 * n)
                .map(|i| {
                    let b = (i / 2) as u32;
                    PassCollider::new(b, &bodies[b as usize], Pose::IDENTITY, rng.range(0.1, 2.0), false)
                })
                .collect();
            broad.pairs(&bodies, &colliders, &mut out);
            let mut brute = Vec::new();
            for i in 0..colliders.len() {
                for j in i + 1..colliders.len() {
                    let (ci, cj) = (&colliders[i], &colliders[j]);
                    let (bi, bj) = (&bodies[ci.body as usize], &bodies[cj.body as usize]);
                    let fast = bi.fast || bj.fast;
                    let allowed = (bi.turning || !bj.still) && (bj.turning || !bi.still);
                    if fast && allowed && ci.body != cj.body && ci.overlaps(cj) {
                        brute.push(PassPair::new(i as u32, j as u32));
                    }
                }
            }
            assert_eq!(out, brute, "round {round}");
            total += out.len();
        }
        assert!(total > 1000, "{total} pairs: the test must see many");
    }
}
