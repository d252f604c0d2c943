//! The speed profiles the device's motions follow: piecewise constant acceleration.

/// Piecewise constant-acceleration speed profile, starting at speed `v0`.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Profile {
    pub(super) v0: f64,
    /// `(duration s, acceleration)` segments.
    pub(super) segs: Vec<(f64, f64)>,
    /// After the segments: keep the final speed forever (true) or stop.
    pub(super) cruise: bool,
}

impl Profile {
    pub(super) fn duration(&self) -> f64 {
        self.segs.iter().map(|s| s.0).sum()
    }

    /// `(distance, speed)` at time `t` (s) into the profile.
    pub(super) fn eval(&self, t: f64) -> (f64, f64) {
        let (mut left, mut x, mut v) = (t.max(0.0), 0.0, self.v0);
        for &(dur, acc) in &self.segs {
            let dt = left.min(dur);
            x += v * dt + 0.5 * acc * dt * dt;
            v = (v + acc * dt).max(0.0);
            left -= dt;
            if left <= 0.0 {
                return (x, v);
            }
        }
        if self.cruise {
            (x + v * left, v)
        } else {
            (x, 0.0)
        }
    }

    /// Rest-to-rest move of `dist` with acceleration `a`, deceleration `d`,
    /// top speed `v`: trapezoid, or triangle when the distance is too short.
    pub(super) fn trapezoid(dist: f64, a: f64, d: f64, v: f64) -> Profile {
        let mut segs = Vec::new();
        if dist > 0.0 && a > 0.0 && d > 0.0 && v > 0.0 {
            let (da, dd) = (v * v / (2.0 * a), v * v / (2.0 * d));
            if da + dd <= dist {
                segs.push((v / a, a));
                segs.push(((dist - da - dd) / v, 0.0));
                segs.push((v / d, -d));
            } else {
                let vp = (2.0 * dist * a * d / (a + d)).sqrt();
                segs.push((vp / a, a));
                segs.push((vp / d, -d));
            }
        }
        Profile {
            v0: 0.0,
            segs,
            cruise: false,
        }
    }

    /// From speed `v0` to speed `vt`, then cruise.
    pub(super) fn to_speed(v0: f64, vt: f64, a: f64, d: f64) -> Profile {
        let seg = if vt >= v0 {
            ((vt - v0) / a, a)
        } else {
            ((v0 - vt) / d, -d)
        };
        Profile {
            v0,
            segs: vec![seg],
            cruise: true,
        }
    }

    /// From speed `v0` down to rest.
    pub(super) fn to_rest(v0: f64, d: f64) -> Profile {
        Profile {
            v0,
            segs: vec![(v0 / d, -d)],
            cruise: false,
        }
    }

    /// Constant speed `v`, for `dist` steps or (None) forever.
    pub(super) fn constant(v: f64, dist: Option<f64>) -> Profile {
        match dist {
            Some(n) => Profile {
                v0: v,
                segs: vec![(n / v, 0.0)],
                cruise: false,
            },
            None => Profile {
                v0: v,
                segs: vec![],
                cruise: true,
            },
        }
    }
}
