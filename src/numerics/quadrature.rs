//! Gauss–Legendre quadrature nodes (the mass properties of user curves).

use core::f64::consts::PI;

/// Newton steps on each node at most …
const NEWTON_STEPS: usize = 100;
/// … until the node moves by less than this.
const NODE_TOLERANCE: f64 = 1e-16;

/// Gauss–Legendre nodes and weights on [−1, 1].
pub(crate) fn gauss_legendre<const N: usize>() -> ([f64; N], [f64; N]) {
    let mut x = [0.0; N];
    let mut w = [0.0; N];
    let n = N as f64;
    for i in 0..N {
        let mut z = (PI * (i as f64 + 0.75) / (n + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..NEWTON_STEPS {
            // Legendre recurrence.
            let (mut p0, mut p1) = (1.0, z);
            for k in 2..=N {
                let kf = k as f64;
                let p2 = ((2.0 * kf - 1.0) * z * p1 - (kf - 1.0) * p0) / kf;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (z * p1 - p0) / (z * z - 1.0);
            let dz = p1 / dp;
            z -= dz;
            if dz.abs() <= NODE_TOLERANCE {
                break;
            }
        }
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
    (x, w)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_legendre_integrates_polynomials_of_degree_23_exactly() {
        let (x, w) = gauss_legendre::<12>();
        assert!((w.iter().sum::<f64>() - 2.0).abs() < 1e-14);
        for deg in 0..24 {
            let q: f64 = x.iter().zip(w.iter()).map(|(x, w)| w * x.powi(deg)).sum();
            let exact = if deg % 2 == 1 { 0.0 } else { 2.0 / (deg as f64 + 1.0) };
            assert!((q - exact).abs() < 1e-14, "degree {deg}: {q} vs {exact}");
        }
    }
}
