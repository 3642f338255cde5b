//! Truncated Taylor arithmetic ("jets") used for automatic differentiation.
//!
//! [`Dual2`] carries a value with its first and second derivative in one variable (φ);
//! [`Jet2`] carries a value with its gradient and Hessian in two variables (φ, t), i.e. the
//! quantities of eq. 6 of the specification. Both are closed under +, −, ×, ÷, √, sin, cos, so a
//! shape written once in terms of them yields every derivative the algorithms need.
//!
//! The crate uses these small hand-written types instead of `num-dual` because they are `Copy`,
//! allocation-free and about 1.8× cheaper per evaluation (README, "Dependencies").

use core::ops::{Add, Div, Mul, Neg, Sub};

/// A value with its first and second derivative in one variable: `v + d·ε + dd·ε²/2`.
#[derive(Copy, Clone, Debug, PartialEq, Default)]
pub struct Dual2 {
    /// Value.
    pub v: f64,
    /// First derivative.
    pub d: f64,
    /// Second derivative.
    pub dd: f64,
}

impl Dual2 {
    /// A constant (zero derivatives).
    #[inline]
    pub const fn cst(v: f64) -> Self {
        Self { v, d: 0.0, dd: 0.0 }
    }
    /// The independent variable at `v` (derivative 1).
    #[inline]
    pub const fn var(v: f64) -> Self {
        Self { v, d: 1.0, dd: 0.0 }
    }
    /// Applies a scalar function given its value and first two derivatives at `self.v`.
    #[inline]
    pub fn chain(self, f: f64, f1: f64, f2: f64) -> Self {
        Self {
            v: f,
            d: f1 * self.d,
            dd: f1 * self.dd + f2 * self.d * self.d,
        }
    }
    /// Square root (value must be positive).
    #[inline]
    pub fn sqrt(self) -> Self {
        let s = self.v.sqrt();
        self.chain(s, 0.5 / s, -0.25 / (s * self.v))
    }
    /// Sine.
    #[inline]
    pub fn sin(self) -> Self {
        let (s, c) = crate::numerics::math::sin_cos(self.v);
        self.chain(s, c, -s)
    }
    /// Cosine.
    #[inline]
    pub fn cos(self) -> Self {
        let (s, c) = crate::numerics::math::sin_cos(self.v);
        self.chain(c, -s, -c)
    }
    /// Sine and cosine together (one `sin_cos` of the value).
    #[inline]
    pub fn sin_cos(self) -> (Self, Self) {
        let (s, c) = crate::numerics::math::sin_cos(self.v);
        (self.chain(s, c, -s), self.chain(c, -s, -c))
    }
    /// Tangent.
    #[inline]
    pub fn tan(self) -> Self {
        let t = self.v.tan();
        let s2 = 1.0 + t * t;
        self.chain(t, s2, 2.0 * t * s2)
    }
    /// Reciprocal.
    #[inline]
    pub fn recip(self) -> Self {
        let r = 1.0 / self.v;
        self.chain(r, -r * r, 2.0 * r * r * r)
    }
    /// Multiplies by a constant.
    #[inline]
    pub fn scale(self, k: f64) -> Self {
        Self {
            v: self.v * k,
            d: self.d * k,
            dd: self.dd * k,
        }
    }
}

impl Add for Dual2 {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self {
            v: self.v + o.v,
            d: self.d + o.d,
            dd: self.dd + o.dd,
        }
    }
}
impl Sub for Dual2 {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Self {
            v: self.v - o.v,
            d: self.d - o.d,
            dd: self.dd - o.dd,
        }
    }
}
impl Neg for Dual2 {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Self {
            v: -self.v,
            d: -self.d,
            dd: -self.dd,
        }
    }
}
impl Mul for Dual2 {
    type Output = Self;
    #[inline]
    fn mul(self, o: Self) -> Self {
        Self {
            v: self.v * o.v,
            d: self.d * o.v + self.v * o.d,
            dd: self.dd * o.v + 2.0 * self.d * o.d + self.v * o.dd,
        }
    }
}
impl Div for Dual2 {
    type Output = Self;
    #[inline]
    fn div(self, o: Self) -> Self {
        let r = o.recip();
        Mul::mul(self, r)
    }
}

/// A value with gradient and Hessian in (φ, t) (eq. 6 of the specification).
#[derive(Copy, Clone, Debug, PartialEq, Default)]
pub struct Jet2 {
    /// Value f.
    pub v: f64,
    /// ∂f/∂φ.
    pub p: f64,
    /// ∂f/∂t.
    pub t: f64,
    /// ∂²f/∂φ².
    pub pp: f64,
    /// ∂²f/∂φ∂t.
    pub pt: f64,
    /// ∂²f/∂t².
    pub tt: f64,
}

impl Jet2 {
    /// A constant.
    #[inline]
    pub const fn cst(v: f64) -> Self {
        Self {
            v,
            p: 0.0,
            t: 0.0,
            pp: 0.0,
            pt: 0.0,
            tt: 0.0,
        }
    }
    /// Multiplies by a constant.
    #[inline]
    pub fn scale(self, k: f64) -> Self {
        Self {
            v: self.v * k,
            p: self.p * k,
            t: self.t * k,
            pp: self.pp * k,
            pt: self.pt * k,
            tt: self.tt * k,
        }
    }
    /// Applies a scalar function given its value and first two derivatives at `self.v`.
    #[inline]
    pub fn chain(self, f: f64, f1: f64, f2: f64) -> Self {
        Self {
            v: f,
            p: f1 * self.p,
            t: f1 * self.t,
            pp: f1 * self.pp + f2 * self.p * self.p,
            pt: f1 * self.pt + f2 * self.p * self.t,
            tt: f1 * self.tt + f2 * self.t * self.t,
        }
    }
    /// Square root (value must be positive).
    #[inline]
    pub fn sqrt(self) -> Self {
        let s = self.v.sqrt();
        self.chain(s, 0.5 / s, -0.25 / (s * self.v))
    }
    /// The gradient as `[∂φ, ∂t]`.
    #[inline]
    pub fn gradient(&self) -> [f64; 2] {
        [self.p, self.t]
    }
    /// The Hessian as a symmetric 2×2 array.
    #[inline]
    pub fn hessian(&self) -> [[f64; 2]; 2] {
        [[self.pp, self.pt], [self.pt, self.tt]]
    }
    /// True when every component is finite.
    #[inline]
    pub fn is_finite(&self) -> bool {
        self.v.is_finite()
            && self.p.is_finite()
            && self.t.is_finite()
            && self.pp.is_finite()
            && self.pt.is_finite()
            && self.tt.is_finite()
    }
}

impl Add for Jet2 {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self {
            v: self.v + o.v,
            p: self.p + o.p,
            t: self.t + o.t,
            pp: self.pp + o.pp,
            pt: self.pt + o.pt,
            tt: self.tt + o.tt,
        }
    }
}
impl Sub for Jet2 {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        self + (-o)
    }
}
impl Neg for Jet2 {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        self.scale(-1.0)
    }
}
impl Mul for Jet2 {
    type Output = Self;
    #[inline]
    fn mul(self, o: Self) -> Self {
        Self {
            v: self.v * o.v,
            p: self.p * o.v + self.v * o.p,
            t: self.t * o.v + self.v * o.t,
            pp: self.pp * o.v + 2.0 * self.p * o.p + self.v * o.pp,
            pt: self.pt * o.v + self.p * o.t + self.t * o.p + self.v * o.pt,
            tt: self.tt * o.v + 2.0 * self.t * o.t + self.v * o.tt,
        }
    }
}

/// A 2D vector whose components are [`Jet2`]s.
#[derive(Copy, Clone, Debug, PartialEq, Default)]
pub struct JetVec {
    /// x component.
    pub x: Jet2,
    /// y component.
    pub y: Jet2,
}

impl JetVec {
    /// Dot product.
    #[inline]
    pub fn dot(self, o: Self) -> Jet2 {
        self.x * o.x + self.y * o.y
    }
    /// 2D cross product `a × b = a_x b_y − a_y b_x`.
    #[inline]
    pub fn cross(self, o: Self) -> Jet2 {
        self.x * o.y - self.y * o.x
    }
}
impl Add for JetVec {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Self {
            x: self.x + o.x,
            y: self.y + o.y,
        }
    }
}
impl Sub for JetVec {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Self {
            x: self.x - o.x,
            y: self.y - o.y,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dual2_matches_closed_form_derivatives() {
        let x = Dual2::var(0.7);
        let f = (x.sin() * x.cos() + x.sqrt()) / (x * x + Dual2::cst(1.0));
        let g = |x: f64| (x.sin() * x.cos() + x.sqrt()) / (x * x + 1.0);
        let h = 1e-5;
        let d = (g(0.7 + h) - g(0.7 - h)) / (2.0 * h);
        let dd = (g(0.7 + h) - 2.0 * g(0.7) + g(0.7 - h)) / (h * h);
        assert!((f.v - g(0.7)).abs() < 1e-15);
        assert!((f.d - d).abs() < 1e-8);
        assert!((f.dd - dd).abs() < 1e-4);
        let t = Dual2::var(0.3).tan();
        assert!((t.d - 1.0 / 0.3f64.cos().powi(2)).abs() < 1e-14);
    }

    #[test]
    fn jet2_product_rule_gives_mixed_partials() {
        // f(φ, t) = φ² t³ at (2, 3): value 108, f_φ = 2φt³ = 108, f_t = 3φ²t² = 108,
        // f_φφ = 2t³ = 54, f_φt = 6φt² = 108, f_tt = 6φ²t = 72.
        let phi = Jet2 {
            v: 2.0,
            p: 1.0,
            ..Jet2::cst(0.0)
        };
        let t = Jet2 {
            v: 3.0,
            t: 1.0,
            ..Jet2::cst(0.0)
        };
        let f = phi * phi * t * t * t;
        assert_eq!(
            [f.v, f.p, f.t, f.pp, f.pt, f.tt],
            [108.0, 108.0, 108.0, 54.0, 108.0, 72.0]
        );
    }
}
