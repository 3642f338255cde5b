//! A bracketed, safeguarded Newton root finder for increasing functions (ray casts and point
//! projections of the parry shapes).

/// Iterations of [`solve_increasing`] at most.
const MAX_ITERATIONS: usize = 200;
/// A bracket narrower than this many ulps of its ends has converged.
const BRACKET_ULPS: f64 = 4.0;
/// A secant step is taken only when it lands at least this fraction of the bracket inside it.
const SECANT_MARGIN: f64 = 0.1;
/// A floor for the scale of the convergence tests (zero-width brackets at 0).
const TINY: f64 = 1e-300;

/// Bracketed, safeguarded Newton for an increasing function: `f(a) ≤ 0 ≤ f(b)`. `eval`
/// returns (f, f′). Returns the best root estimate (never leaves `[a, b]`).
pub(crate) fn solve_increasing(
    mut a: f64,
    mut b: f64,
    mut fa: f64,
    mut fb: f64,
    mut eval: impl FnMut(f64) -> (f64, f64),
) -> f64 {
    if fa == 0.0 {
        return a;
    }
    if fb == 0.0 {
        return b;
    }
    if !(fa < 0.0 && fb > 0.0) {
        // Not a proper bracket (NaN or rounding): the end closer to zero.
        return if fa.abs() <= fb.abs() || fb.is_nan() { a } else { b };
    }
    let (mut best_x, mut best_f) = if -fa < fb { (a, -fa) } else { (b, fb) };
    // Regula falsi start.
    let mut x = a - fa * (b - a) / (fb - fa);
    if !(x > a && x < b) {
        x = 0.5 * (a + b);
    }
    let mut width_before = b - a;
    for iter in 0..MAX_ITERATIONS {
        let (fx, dfx) = eval(x);
        if fx.is_nan() {
            // Outside the curve's domain of validity: bisect.
            x = 0.5 * (a + b);
            if b - a <= BRACKET_ULPS * f64::EPSILON * (a.abs() + b.abs()) {
                break;
            }
            continue;
        }
        if fx.abs() < best_f {
            best_f = fx.abs();
            best_x = x;
        }
        if fx == 0.0 {
            return x;
        }
        if fx < 0.0 {
            a = x;
            fa = fx;
        } else {
            b = x;
            fb = fx;
        }
        let width = b - a;
        if width <= BRACKET_ULPS * f64::EPSILON * (a.abs() + b.abs()).max(TINY) {
            break;
        }
        let newton = x - fx / dfx;
        let force_bisect = iter % 3 == 2 && width > 0.5 * width_before;
        if iter % 3 == 2 {
            width_before = width;
        }
        let next = if !force_bisect && newton.is_finite() && newton > a && newton < b {
            newton
        } else {
            // Secant on the bracket when it is well inside, else bisection.
            let s = a - fa * (b - a) / (fb - fa);
            let lo = a + SECANT_MARGIN * width;
            let hi = b - SECANT_MARGIN * width;
            if !force_bisect && s > lo && s < hi {
                s
            } else {
                0.5 * (a + b)
            }
        };
        if (next - x).abs() <= 2.0 * f64::EPSILON * x.abs().max(TINY) {
            // Converged: one more evaluation would not move x.
            let (fn_, _) = eval(next);
            if fn_.abs() <= best_f {
                return next;
            }
            return best_x;
        }
        x = next;
    }
    best_x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solve_increasing_converges_across_a_kink_and_on_flat_ends() {
        // f = x for x < 0.3, 100 (x − 0.3) + 0.3 after: a derivative jump; root at 0.
        let f = |x: f64| {
            if x < 0.3 {
                (x, 1.0)
            } else {
                (100.0 * (x - 0.3) + 0.3, 100.0)
            }
        };
        let r = solve_increasing(-1.0, 2.0, f(-1.0).0, f(2.0).0, f);
        assert!(r.abs() < 1e-15);
        let g = |x: f64| ((x - 1.0).powi(3), 3.0 * (x - 1.0).powi(2));
        let r = solve_increasing(0.0, 3.0, g(0.0).0, g(3.0).0, g);
        assert!((r - 1.0).abs() < 1e-5);
        // Degenerate brackets return an end.
        assert_eq!(solve_increasing(0.0, 1.0, 0.0, 1.0, g), 0.0);
        assert_eq!(solve_increasing(0.0, 1.0, 1.0, 2.0, g), 0.0);
    }
}
