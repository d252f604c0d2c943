//! The conical helix of `MCC_ConeXY_Z`/`YZ_X`/`ZX_Y` (vendor header, obsolete functions;
//! the manuals do not describe them), parameterised by path length like every path.
//!
//! Geometry, with `φ ≥ 0` the angle turned so far (radians), `σ = ±1` the direction
//! (+1 counter-clockwise about the plane normal), `k = CenterRate / 2π` the radius change
//! per radian and `h = rise / Φ` the normal travel per radian (`Φ` the whole angle):
//!
//! ```text
//! r(φ)   = r0 + k·φ                       (r0: distance start–center)
//! p(φ)   = c + r(φ)·(cos(θ0 + σφ)·u + sin(θ0 + σφ)·v) + (n0 + h·φ)·n
//! |p'(φ)| = sqrt(r(φ)² + k² + h²)          (u, v, n orthonormal)
//! ```
//!
//! The path length to `φ` is `L(φ) = ∫₀^φ sqrt((r0 + kψ)² + a²) dψ` with `a² = k² + h²`,
//! in closed form `[x·g + a²·asinh(x/a)] / 2k` between `x = r0` and `x = r(φ)` (`g =
//! sqrt(x² + a²)`), evaluated in a form without cancellation (see [`ConeSeg::length_to`]),
//! which is `φ·sqrt(r0² + h²)` for `k = 0` (a helix). The angle at a path length `s` is
//! the root of `L(φ) = s`, found by Newton's method (`L' = sqrt(r² + a²) > 0`) kept inside
//! a bisection bracket, to about 1e-15 of `Φ`. So `point(s)` moves at exactly the speed
//! the profile gives `s`.

use super::{Plane, MIN_RADIUS};
use crate::planner::{check_all_finite, check_finite, Axes, PlanError, NUM_AXES};
use std::f64::consts::TAU;

/// A conical helix segment in X/Y/Z; U..B do not move.
#[derive(Debug, Clone, PartialEq)]
pub struct ConeSeg {
    start: Axes,
    end: Axes,
    /// Center in X/Y/Z at the start (its normal coordinate is the start's).
    center: [f64; 3],
    u: [f64; 3],
    v: [f64; 3],
    axis: [f64; 3],
    theta0: f64,
    /// +1 counter-clockwise, −1 clockwise (about the normal).
    sigma: f64,
    r0: f64,
    /// Radius change per radian.
    k: f64,
    /// Whole angle turned, radians (≥ 0).
    phi_total: f64,
    /// Normal travel over the whole path.
    rise: f64,
    /// `k² + h²`.
    a2: f64,
    length: f64,
}

fn unit3(i: usize) -> [f64; 3] {
    let mut e = [0.0; 3];
    e[i] = 1.0;
    e
}

/// `asinh(y) / y`, also for `y` near 0 (series `1 − y²/6 + 3y⁴/40`).
fn asinh_ratio(y: f64) -> f64 {
    if y.abs() < 1e-4 {
        let y2 = y * y;
        1.0 - y2 / 6.0 + 3.0 * y2 * y2 / 40.0
    } else {
        y.asinh() / y
    }
}

impl ConeSeg {
    /// The same cone moved by `d` (see `Path::translate`): its shape, length and
    /// direction do not change.
    pub(crate) fn translate(&mut self, d: &Axes) {
        for (i, d) in d.iter().enumerate() {
            self.start[i] += d;
            self.end[i] += d;
            if let Some(c) = self.center.get_mut(i) {
                *c += d;
            }
        }
    }

    /// The cone about `center` (plane coordinates) from `start` until the normal axis
    /// reaches `end_n`: `|end_n − start_n| / |pitch|` turns, counter-clockwise when
    /// `ccw`, the radius changing by `center_rate` per turn.
    ///
    /// Errors: `BadArc` for a start on the center (radius below `MIN_RADIUS`);
    /// `BadParameter` for NaN/inf, a zero pitch, or a radius that would shrink below 0
    /// before the end.
    pub fn new(
        plane: Plane,
        start: &Axes,
        center: [f64; 2],
        end_n: f64,
        pitch: f64,
        center_rate: f64,
        ccw: bool,
    ) -> Result<ConeSeg, PlanError> {
        check_all_finite(start, "start position")?;
        check_all_finite(&center, "cone center")?;
        check_finite(end_n, "cone end position")?;
        check_finite(pitch, "cone pitch")?;
        check_finite(center_rate, "cone radius rate")?;
        if pitch == 0.0 {
            return Err(PlanError::BadParameter("cone pitch"));
        }
        let (ia, ib, n) = plane.axes();
        let r0 = (start[ia] - center[0]).hypot(start[ib] - center[1]);
        if !(r0.is_finite() && r0 >= MIN_RADIUS) {
            return Err(PlanError::BadArc);
        }
        let rise = end_n - start[n];
        let turns = (rise / pitch).abs();
        let phi_total = TAU * turns;
        let r1 = r0 + center_rate * turns;
        check_finite(phi_total, "cone turns")?;
        check_finite(r1, "cone end radius")?;
        if r1 < 0.0 {
            return Err(PlanError::BadParameter("cone radius shrinks below 0"));
        }
        let k = center_rate / TAU;
        let h = if phi_total > 0.0 {
            rise / phi_total
        } else {
            0.0
        };
        let a2 = k * k + h * h;
        check_finite(a2, "cone geometry")?;
        let mut c3 = [0.0; 3];
        c3[ia] = center[0];
        c3[ib] = center[1];
        c3[n] = start[n];
        let theta0 = (start[ib] - center[1]).atan2(start[ia] - center[0]);
        let sigma = if ccw { 1.0 } else { -1.0 };
        let mut seg = ConeSeg {
            start: *start,
            end: *start,
            center: c3,
            u: unit3(ia),
            v: unit3(ib),
            axis: unit3(n),
            theta0,
            sigma,
            r0,
            k,
            phi_total,
            rise,
            a2,
            length: 0.0,
        };
        seg.length = seg.length_to(phi_total);
        check_finite(seg.length, "cone length")?;
        if phi_total > 0.0 {
            let th = theta0 + sigma * phi_total;
            seg.end[ia] = center[0] + r1 * th.cos();
            seg.end[ib] = center[1] + r1 * th.sin();
        }
        seg.end[n] = end_n;
        Ok(seg)
    }

    /// Path length from the start to angle `phi` (0..=Φ): `L(φ)` of the module
    /// documentation. With `x0 = r0`, `x1 = r0 + kφ`, `d = kφ`, `g = sqrt(x² + a²)`:
    /// `L = φ/2 · [g1 + x0(x1 + x0)/(g1 + g0) + a²·m·asinh(d·m)/(d·m)]`,
    /// `m = (x1 + x0) / (a²·(p·sqrt(1 + q²) + q·sqrt(1 + p²)))`, `p = x1/a`, `q = x0/a`:
    /// the closed form with both differences (`x·g`, `asinh`) divided by `d` exactly.
    pub fn length_to(&self, phi: f64) -> f64 {
        if phi.is_nan() || phi <= 0.0 {
            return 0.0;
        }
        let (x0, x1) = (self.r0, self.r0 + self.k * phi);
        if self.a2 <= f64::MIN_POSITIVE {
            // No radius change and no rise: a plain circle arc.
            return phi * (x0 + x1) / 2.0;
        }
        let d = self.k * phi;
        let (g0, g1) = ((x0 * x0 + self.a2).sqrt(), (x1 * x1 + self.a2).sqrt());
        let first = g1 + x0 * (x1 + x0) / (g1 + g0);
        let a = self.a2.sqrt();
        let (p, q) = (x1 / a, x0 / a);
        let den = p * (1.0 + q * q).sqrt() + q * (1.0 + p * p).sqrt();
        let m = (x1 + x0) / (self.a2 * den);
        phi / 2.0 * (first + self.a2 * m * asinh_ratio(d * m))
    }

    /// The angle turned at path length `s` (clamped to 0..=Φ): the root of
    /// `length_to(φ) = s`.
    pub fn angle_at(&self, s: f64) -> f64 {
        if s.is_nan() || s <= 0.0 || self.length <= 0.0 {
            return 0.0;
        }
        if s >= self.length {
            return self.phi_total;
        }
        let (mut lo, mut hi) = (0.0, self.phi_total);
        let mut phi = self.phi_total * (s / self.length);
        let tol = 1e-15 * self.phi_total;
        for _ in 0..100 {
            let f = self.length_to(phi) - s;
            if f > 0.0 {
                hi = phi;
            } else {
                lo = phi;
            }
            let r = self.r0 + self.k * phi;
            let slope = (r * r + self.a2).sqrt();
            let newton = phi - f / slope;
            let next = if slope > 0.0 && newton > lo && newton < hi {
                newton
            } else {
                (lo + hi) / 2.0
            };
            let done = (next - phi).abs() <= tol || hi - lo <= tol;
            phi = next;
            if done {
                break;
            }
        }
        phi
    }

    /// The radius at angle `phi`.
    pub fn radius_at(&self, phi: f64) -> f64 {
        self.r0 + self.k * phi
    }

    /// Path length.
    pub fn length(&self) -> f64 {
        self.length
    }

    /// Start position.
    pub fn start(&self) -> &Axes {
        &self.start
    }

    /// End position, exact (`end_n` on the normal axis).
    pub fn end(&self) -> &Axes {
        &self.end
    }

    /// Whole angle turned, radians.
    pub fn total_angle(&self) -> f64 {
        self.phi_total
    }

    /// Signed sweep, radians (> 0 counter-clockwise).
    pub fn sweep(&self) -> f64 {
        self.sigma * self.phi_total
    }

    /// The smaller of the start and end radius.
    pub fn min_radius(&self) -> f64 {
        self.r0.min(self.radius_at(self.phi_total))
    }

    /// The larger of the start and end radius.
    pub fn max_radius(&self) -> f64 {
        self.r0.max(self.radius_at(self.phi_total))
    }

    /// Position at path length `s` (clamped); exact at both ends.
    pub fn point(&self, s: f64) -> Axes {
        if s.is_nan() || s <= 0.0 || self.length <= 0.0 {
            return self.start;
        }
        if s >= self.length {
            return self.end;
        }
        let phi = self.angle_at(s);
        let th = self.theta0 + self.sigma * phi;
        let r = self.radius_at(phi);
        let (c, sn) = (th.cos() * r, th.sin() * r);
        let hn = self.rise * (phi / self.phi_total);
        let mut p = self.start;
        for (i, pi) in p.iter_mut().enumerate().take(3) {
            *pi = self.center[i] + c * self.u[i] + sn * self.v[i] + hn * self.axis[i];
        }
        p
    }

    /// Unit tangent (d position / d s) at path length `s` (clamped); U..B 0.
    pub fn direction(&self, s: f64) -> Axes {
        let mut d = [0.0; NUM_AXES];
        if self.length <= 0.0 {
            return d;
        }
        let phi = self.angle_at(s.clamp(0.0, self.length));
        let th = self.theta0 + self.sigma * phi;
        let r = self.radius_at(phi);
        let speed = (r * r + self.a2).sqrt(); // ds/dφ
        let h = self.rise / self.phi_total;
        let (c, sn) = (th.cos(), th.sin());
        for (i, di) in d.iter_mut().enumerate().take(3) {
            let radial = c * self.u[i] + sn * self.v[i];
            let tangential = -sn * self.u[i] + c * self.v[i];
            *di = (self.k * radial + self.sigma * r * tangential + h * self.axis[i]) / speed;
        }
        d
    }

    /// Per axis an interval holding the coordinate over the whole path: start to end,
    /// widened in X/Y/Z by the largest radius around the center and the normal travel.
    pub fn extent(&self) -> [(f64, f64); NUM_AXES] {
        let mut e: [(f64, f64); NUM_AXES] = std::array::from_fn(|i| {
            (
                self.start[i].min(self.end[i]),
                self.start[i].max(self.end[i]),
            )
        });
        let reach = self.max_radius();
        for (i, ei) in e.iter_mut().enumerate().take(3) {
            let w = reach * (self.u[i] * self.u[i] + self.v[i] * self.v[i]).sqrt();
            let (c0, c1) = (self.center[i], self.center[i] + self.rise * self.axis[i]);
            ei.0 = ei.0.min(c0.min(c1) - w);
            ei.1 = ei.1.max(c0.max(c1) + w);
        }
        e
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ax(x: f64, y: f64, z: f64) -> Axes {
        [x, y, z, 7.0, 0.0, 0.0, 0.0, -1.0]
    }

    /// `∫₀^φ sqrt((r0 + kψ)² + a²) dψ` by composite Simpson with `n` intervals.
    fn simpson(r0: f64, k: f64, a2: f64, phi: f64, n: usize) -> f64 {
        let f = |t: f64| ((r0 + k * t).powi(2) + a2).sqrt();
        let h = phi / n as f64;
        let mut s = f(0.0) + f(phi);
        for i in 1..n {
            s += f(i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
        }
        s * h / 3.0
    }

    /// A cone moved by d (a command queued behind a custom motion) is the same cone: at
    /// every arc length its point is the original's plus d, and its length is unchanged.
    #[test]
    fn translated_cone_is_the_cone_moved() {
        use crate::planner::{Path, Plane};
        let start = ax(12.0, 0.0, 0.0);
        let orig = Path::cone(Plane::XY, &start, [2.0, 0.0], 6.0, 2.0, 2.0, true).unwrap();
        let d = [1.5, -2.0, 0.25, 3.0, 0.0, 0.0, 0.0, 1.0];
        let mut moved = orig.clone();
        moved.translate(&d);
        assert_eq!(moved.length(), orig.length());
        for i in 0..=20 {
            let s = orig.length() * f64::from(i) / 20.0;
            let (p, q) = (orig.point(s), moved.point(s));
            for k in 0..8 {
                assert!(
                    (q[k] - p[k] - d[k]).abs() < 1e-9,
                    "axis {k} at s={s}: {} vs {}",
                    q[k],
                    p[k]
                );
            }
        }
    }

    #[test]
    fn closed_form_length_matches_quadrature_and_the_helix_limit() {
        for (r0, rate, rise, pitch) in [
            (10.0, 2.0, 6.0, 2.0),   // growing: 3 turns, 10 -> 16
            (10.0, -3.0, -6.0, 2.0), // shrinking: 3 turns, 10 -> 1
            (5.0, 1e-9, 4.0, 1.0),   // almost a helix (cancellation-prone)
            (5.0, 0.0, 4.0, 1.0),    // a helix
            (3.0, 0.5, 1e-6, 1e-6),  // a flat spiral, one turn
            (1e-3, 1e3, 1.0, 0.25),  // from near the center, fast growth
        ] {
            let start = ax(r0, 0.0, 1.0);
            let seg =
                ConeSeg::new(Plane::XY, &start, [0.0, 0.0], 1.0 + rise, pitch, rate, true).unwrap();
            let phi = seg.total_angle();
            let want = simpson(r0, seg.k, seg.a2, phi, 200_000);
            let got = seg.length();
            assert!(
                (got - want).abs() <= 1e-9 * want,
                "r0 {r0} rate {rate}: {got} vs {want}"
            );
            if rate == 0.0 {
                let helix = phi * (r0 * r0 + (rise / phi).powi(2)).sqrt();
                assert!((got - helix).abs() <= 1e-12 * helix);
            }
            // angle_at inverts length_to.
            for j in 0..=50 {
                let s = got * j as f64 / 50.0;
                let a = seg.angle_at(s);
                assert!((seg.length_to(a) - s).abs() <= 1e-12 * got.max(1.0), "{j}");
            }
        }
    }

    #[test]
    fn radius_rise_direction_ends_and_tangent() {
        // XY, center (1, 2), start (4, 2, 0): r0 = 3; to Z = -5 with pitch 2: 2.5 turns
        // clockwise; +0.4 per turn: end radius 3 + 0.4 x 2.5 = 4.
        let start = [4.0, 2.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
        let seg = ConeSeg::new(Plane::XY, &start, [1.0, 2.0], -5.0, 2.0, 0.4, false).unwrap();
        assert_eq!(seg.point(0.0), start);
        assert_eq!(seg.point(seg.length()), *seg.end());
        // 2.5 turns from angle 0: the end is at angle -5π = π, radius 4: (1 - 4, 2).
        let e = seg.end();
        assert!((e[0] - -3.0).abs() < 1e-12 && (e[1] - 2.0).abs() < 1e-12);
        assert_eq!(e[2], -5.0);
        assert_eq!(&e[3..], &start[3..], "aux axes stay");
        assert!(seg.sweep() < 0.0);
        let n = 997;
        let mut unwrapped = 0.0;
        let mut prev_angle = 0.0_f64;
        for j in 0..=n {
            let s = seg.length() * j as f64 / n as f64;
            let p = seg.point(s);
            let ang = (p[1] - 2.0).atan2(p[0] - 1.0);
            let mut dth = ang - prev_angle;
            while dth > std::f64::consts::PI {
                dth -= TAU;
            }
            while dth < -std::f64::consts::PI {
                dth += TAU;
            }
            assert!(dth <= 1e-12, "clockwise: the angle never grows");
            unwrapped += dth;
            prev_angle = ang;
            let turns = -unwrapped / TAU;
            let r = (p[0] - 1.0).hypot(p[1] - 2.0);
            assert!((r - (3.0 + 0.4 * turns)).abs() <= 1e-9, "radius at {j}");
            assert!((p[2] - -2.0 * turns).abs() <= 1e-9, "Z at {j}");
            // The tangent is a unit vector and matches a central difference.
            if j > 0 && j < n {
                let d = seg.direction(s);
                let norm = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
                assert!((norm - 1.0).abs() <= 1e-12);
                let eps = 1e-6;
                let (a, b) = (seg.point(s - eps), seg.point(s + eps));
                for i in 0..3 {
                    assert!(((b[i] - a[i]) / (2.0 * eps) - d[i]).abs() <= 1e-6);
                }
            }
        }
        assert!((unwrapped / TAU - -2.5).abs() <= 1e-9);
    }

    #[test]
    fn refusals() {
        let s = ax(3.0, 0.0, 0.0);
        let c = [0.0, 0.0];
        assert_eq!(
            ConeSeg::new(Plane::XY, &ax(0.0, 0.0, 0.0), c, 1.0, 1.0, 0.0, true),
            Err(PlanError::BadArc)
        );
        assert!(matches!(
            ConeSeg::new(Plane::XY, &s, c, 1.0, 0.0, 0.0, true),
            Err(PlanError::BadParameter(_))
        ));
        // 3 turns at -1.5 per turn would end at radius -1.5.
        assert!(matches!(
            ConeSeg::new(Plane::XY, &s, c, 3.0, 1.0, -1.5, true),
            Err(PlanError::BadParameter(_))
        ));
        // Exactly to the center is allowed.
        assert!(ConeSeg::new(Plane::XY, &s, c, 3.0, 1.0, -1.0, true).is_ok());
        for bad in [f64::NAN, f64::INFINITY] {
            assert!(ConeSeg::new(Plane::XY, &s, c, bad, 1.0, 0.0, true).is_err());
            assert!(ConeSeg::new(Plane::XY, &s, c, 1.0, bad, 0.0, true).is_err());
            assert!(ConeSeg::new(Plane::XY, &s, c, 1.0, 1.0, bad, true).is_err());
            assert!(ConeSeg::new(Plane::XY, &s, [bad, 0.0], 1.0, 1.0, 0.0, true).is_err());
        }
        // No rise: no turn, a zero-length path at the start.
        let z = ConeSeg::new(Plane::XY, &s, c, 0.0, 1.0, 0.5, true).unwrap();
        assert_eq!((z.length(), z.point(1.0)), (0.0, s));
    }
}
