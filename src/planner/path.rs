//! Geometry of general-motion segments (line, arc, circle, helix), each
//! parameterised by the path length the feed speed applies to.

use super::cone::ConeSeg;
use super::{check_all_finite, check_finite, Axes, PlanError, NUM_AXES};
use std::f64::consts::TAU;

mod v6;

/// Number of X/Y/Z axes (the ones that define general-motion path length).
const XYZ: usize = 3;

/// A coordinate plane for arcs, circles and helices.
///
/// Each plane has in-plane axes `(a, b)` and a normal axis `n`, forming a
/// right-handed frame: `XY = (X, Y; Z)`, `YZ = (Y, Z; X)`, `ZX = (Z, X; Y)`.
/// Note that in `ZX` the first plane coordinate is Z. A positive sweep is
/// counter-clockwise looking down the normal, i.e. from `+a` toward `+b`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Plane {
    /// Plane X-Y, normal Z.
    XY,
    /// Plane Y-Z, normal X.
    YZ,
    /// Plane Z-X, normal Y.
    ZX,
}

impl Plane {
    /// Axis indices `(a, b, n)`: the two plane coordinates and the normal.
    pub fn axes(self) -> (usize, usize, usize) {
        match self {
            Plane::XY => (0, 1, 2),
            Plane::YZ => (1, 2, 0),
            Plane::ZX => (2, 0, 1),
        }
    }
}

/// A straight segment from `start` to `end` in all eight axes.
#[derive(Debug, Clone, PartialEq)]
pub struct LineSeg {
    start: Axes,
    end: Axes,
    length: f64,
    /// `end - start` per axis.
    delta: Axes,
    /// `direction(s)`, the same all along the line: `(end - start) / length`, or all
    /// zeros for a zero-length line.
    dir: Axes,
}

/// A circular arc or helix segment in X/Y/Z, with U..B interpolated linearly.
///
/// The X/Y/Z position at angle `θ` is `center + r·(cos θ·u + sin θ·v) + axis·rise·f`
/// where `f = s/length` is the path fraction and `θ = θ0 + sweep·f`. For plane
/// arcs `u`, `v`, `axis` are the plane's unit axes `a`, `b`, `n`; for a 3-D arc
/// `u` points from the center to the start and `v = axis × u`.
#[derive(Debug, Clone, PartialEq)]
pub struct ArcSeg {
    start: Axes,
    end: Axes,
    center: [f64; 3],
    u: [f64; 3],
    v: [f64; 3],
    axis: [f64; 3],
    radius: f64,
    theta0: f64,
    sweep: f64,
    rise: f64,
    length: f64,
}

/// Geometry of one general-motion segment, parameterised by path length `s`
/// in `[0, length()]`.
///
/// Path length: only X/Y/Z count (`sqrt((r·|sweep|)² + rise²)` for an arc or
/// helix); U..B move linearly with the path fraction `s/length` so they start
/// and end with X/Y/Z. If X/Y/Z do not move, the aux axis with the longest
/// travel is the path (it moves at the feed speed) and the others follow it.
///
/// `end()` is computed exactly from the command (never sampled), and
/// `point(length()) == end()`, `point(0) == start()` exactly.
#[derive(Debug, Clone, PartialEq)]
pub enum Path {
    /// Straight line (`MCC_Line`).
    Line(LineSeg),
    /// Arc or circle (`MCC_Arc*`, `MCC_ArcTheta*`, `MCC_Circle*`).
    Arc(ArcSeg),
    /// Helix (`MCC_Helical*`): an arc whose normal axis moves linearly with angle.
    Helix(ArcSeg),
    /// Conical helix (`MCC_Cone*`): a helix whose radius changes linearly with angle.
    Cone(ConeSeg),
}

fn sub3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot3(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn norm3(a: [f64; 3]) -> f64 {
    dot3(a, a).sqrt()
}
fn scale3(a: [f64; 3], k: f64) -> [f64; 3] {
    [a[0] * k, a[1] * k, a[2] * k]
}
fn unit3(i: usize) -> [f64; 3] {
    let mut e = [0.0; 3];
    e[i] = 1.0;
    e
}

/// True for a finite number > 0.
fn positive_finite(x: f64) -> bool {
    x.is_finite() && x > 0.0
}

/// Longest |end - start| over the aux axes U..B.
fn aux_travel(start: &Axes, end: &Axes) -> f64 {
    (XYZ..NUM_AXES)
        .map(|i| (end[i] - start[i]).abs())
        .fold(0.0, f64::max)
}

/// Three points must be distinct and not collinear: `|d1 × d2| > EPS·|d1|·|d2|`.
const COLLINEAR_EPS: f64 = 1e-12;

/// End position: `start` with the aux axes replaced by `aux_end` when given.
fn with_aux(start: &Axes, aux_end: Option<[f64; 5]>) -> Result<Axes, PlanError> {
    let mut end = *start;
    if let Some(aux) = aux_end {
        check_all_finite(&aux, "aux axis position")?;
        end[XYZ..].copy_from_slice(&aux);
    }
    Ok(end)
}

impl LineSeg {
    /// [`Path::point_velocity_into`] for this line.
    #[inline(always)]
    fn point_velocity_into(&self, s: f64, v: f64, pos: &mut Axes, vel: &mut Axes) {
        for (vi, d) in vel.iter_mut().zip(&self.dir) {
            *vi = v * d;
        }
        let len = self.length;
        if s.is_nan() || s <= 0.0 || len <= 0.0 {
            *pos = self.start;
        } else if s >= len {
            *pos = self.end;
        } else {
            let f = s / len;
            #[allow(clippy::needless_range_loop)] // indexes three arrays
            for i in 0..NUM_AXES {
                pos[i] = self.start[i] + self.delta[i] * f;
            }
        }
    }
}

impl ArcSeg {
    /// Finish an arc: set length and validate. `end` must already hold the exact end.
    ///
    /// The length the feed applies to is the arc in its plane (`r·|θ|`): a helix's rise
    /// comes on top, as the vendor's library times it.
    fn finish(mut self) -> ArcSeg {
        let arc = (self.radius * self.sweep).abs();
        self.length = if arc > 0.0 {
            arc
        } else if self.rise != 0.0 {
            self.rise.abs()
        } else {
            aux_travel(&self.start, &self.end)
        };
        self
    }

    /// X/Y/Z position at angle `theta` and path fraction `f` (not clamped).
    fn xyz_at(&self, theta: f64, f: f64) -> [f64; 3] {
        let (c, s) = (theta.cos() * self.radius, theta.sin() * self.radius);
        let h = self.rise * f;
        let mut p = [0.0; 3];
        for (i, pi) in p.iter_mut().enumerate() {
            *pi = self.center[i] + c * self.u[i] + s * self.v[i] + h * self.axis[i];
        }
        p
    }

    /// Signed sweep in radians (> 0 counter-clockwise about the normal).
    pub fn sweep(&self) -> f64 {
        self.sweep
    }

    /// Radius of the arc.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// Center in X/Y/Z (for a helix: the center's start position on the axis).
    pub fn center(&self) -> [f64; 3] {
        self.center
    }

    /// Travel along the normal axis (helix; 0 for an arc).
    pub fn rise(&self) -> f64 {
        self.rise
    }
}

impl Path {
    /// Straight line from `start` to `end` (all eight axes).
    pub fn line(start: &Axes, end: &Axes) -> Path {
        let d = [end[0] - start[0], end[1] - start[1], end[2] - start[2]];
        let xyz = norm3(d);
        let length = if xyz > 0.0 {
            xyz
        } else {
            aux_travel(start, end)
        };
        Path::line_with_length(start, end, length)
    }

    /// Straight line from `start` to `end` whose path length (what the feed speed is
    /// measured along) is `length` (`super::compose`: the composing axes).
    pub fn line_with_length(start: &Axes, end: &Axes, length: f64) -> Path {
        let delta: Axes = std::array::from_fn(|i| end[i] - start[i]);
        let dir = if length <= 0.0 {
            [0.0; NUM_AXES]
        } else {
            delta.map(|d| d / length)
        };
        Path::Line(LineSeg {
            start: *start,
            end: *end,
            length,
            delta,
            dir,
        })
    }

    /// Whether X, Y and Z stand still along the path (its length is then the longest
    /// auxiliary travel, see [`Path`]).
    pub fn aux_only(&self) -> bool {
        match self {
            Path::Line(l) => l.delta[..XYZ].iter().all(|d| *d == 0.0),
            _ => false,
        }
    }

    /// The auxiliary axis with the longest travel (the path of an
    /// [`aux-only`](Path::aux_only) line); X for any other path.
    pub fn lead_axis(&self) -> usize {
        match self {
            Path::Line(l) if self.aux_only() => {
                let mut best = XYZ;
                for i in XYZ..NUM_AXES {
                    if l.delta[i].abs() > l.delta[best].abs() {
                        best = i;
                    }
                }
                best
            }
            _ => 0,
        }
    }

    /// [`Path::line`] with input validation: `BadParameter` if any coordinate
    /// is NaN or infinite.
    pub fn try_line(start: &Axes, end: &Axes) -> Result<Path, PlanError> {
        check_all_finite(start, "start position")?;
        check_all_finite(end, "end position")?;
        Ok(Path::line(start, end))
    }

    /// Arc in `plane` from `start` through the plane point `via` to `end_plane`
    /// (`MCC_ArcXY` etc.). The normal axis does not move; aux axes go to `aux_end`
    /// (U..B, absolute) when given, else stay.
    ///
    /// The center is the circumcenter of the three points; the direction is the
    /// one that passes `via` (counter-clockwise iff the triangle start, via, end
    /// is counter-clockwise in plane coordinates).
    ///
    /// Errors: `BadArc` for coincident or collinear points, `BadParameter` for NaN/inf.
    pub fn arc_3pt(
        plane: Plane,
        start: &Axes,
        via: [f64; 2],
        end_plane: [f64; 2],
        aux_end: Option<[f64; 5]>,
    ) -> Result<Path, PlanError> {
        check_all_finite(start, "start position")?;
        check_all_finite(&via, "arc reference point")?;
        check_all_finite(&end_plane, "arc end point")?;
        let (ia, ib, _) = plane.axes();
        let p0 = [start[ia], start[ib]];
        let d1 = [via[0] - p0[0], via[1] - p0[1]];
        let d2 = [end_plane[0] - p0[0], end_plane[1] - p0[1]];
        let d12 = [end_plane[0] - via[0], end_plane[1] - via[1]];
        let n1 = d1[0].hypot(d1[1]);
        let n2 = d2[0].hypot(d2[1]);
        if n1 == 0.0 || n2 == 0.0 || d12[0].hypot(d12[1]) == 0.0 {
            return Err(PlanError::BadArc);
        }
        let cross = d1[0] * d2[1] - d1[1] * d2[0];
        if cross.is_nan() || cross.abs() <= COLLINEAR_EPS * n1 * n2 {
            return Err(PlanError::BadArc);
        }
        // Circumcenter relative to p0.
        let (b2, c2) = (n1 * n1, n2 * n2);
        let den = 2.0 * cross;
        let ux = (d2[1] * b2 - d1[1] * c2) / den;
        let uy = (d1[0] * c2 - d2[0] * b2) / den;
        let center = [p0[0] + ux, p0[1] + uy];
        let radius = ux.hypot(uy);
        if !positive_finite(radius) {
            return Err(PlanError::BadArc);
        }
        // Sweep from start to end, in the direction that passes via.
        let r0 = [p0[0] - center[0], p0[1] - center[1]];
        let r2 = [end_plane[0] - center[0], end_plane[1] - center[1]];
        let mut sweep = (r0[0] * r2[1] - r0[1] * r2[0]).atan2(r0[0] * r2[0] + r0[1] * r2[1]);
        if cross > 0.0 {
            if sweep <= 0.0 {
                sweep += TAU;
            }
        } else if sweep >= 0.0 {
            sweep -= TAU;
        }
        let mut end = with_aux(start, aux_end)?;
        end[ia] = end_plane[0];
        end[ib] = end_plane[1];
        Ok(Path::Arc(plane_arc(
            plane, start, end, center, radius, sweep, 0.0,
        )))
    }

    /// 3-D arc from `start` through `via` to `end` in X/Y/Z (`MCC_ArcXYZ`), on the
    /// plane of the three points. Aux axes go to `aux_end` when given.
    ///
    /// Errors: `BadArc` for coincident or collinear points, `BadParameter` for NaN/inf.
    pub fn arc_3pt_xyz(
        start: &Axes,
        via: [f64; 3],
        end: [f64; 3],
        aux_end: Option<[f64; 5]>,
    ) -> Result<Path, PlanError> {
        check_all_finite(start, "start position")?;
        check_all_finite(&via, "arc reference point")?;
        check_all_finite(&end, "arc end point")?;
        let p0 = [start[0], start[1], start[2]];
        let a = sub3(via, p0);
        let b = sub3(end, p0);
        let (na, nb) = (norm3(a), norm3(b));
        if na == 0.0 || nb == 0.0 || norm3(sub3(end, via)) == 0.0 {
            return Err(PlanError::BadArc);
        }
        let n = cross3(a, b);
        let nn = norm3(n);
        if nn.is_nan() || nn <= COLLINEAR_EPS * na * nb {
            return Err(PlanError::BadArc);
        }
        // Circumcenter: p0 + ((|a|² b − |b|² a) × (a × b)) / (2 |a × b|²).
        let w = sub3(scale3(b, na * na), scale3(a, nb * nb));
        let off = scale3(cross3(w, n), 1.0 / (2.0 * nn * nn));
        let center = [p0[0] + off[0], p0[1] + off[1], p0[2] + off[2]];
        let radius = norm3(off);
        if !positive_finite(radius) {
            return Err(PlanError::BadArc);
        }
        let axis = scale3(n, 1.0 / nn);
        let u = scale3(sub3(p0, center), 1.0 / radius);
        let v = cross3(axis, u);
        // The triangle p0, via, end is counter-clockwise about `axis` by
        // construction, so the arc through via sweeps positively.
        let r2 = sub3(end, center);
        let mut sweep = dot3(r2, v).atan2(dot3(r2, u));
        if sweep <= 0.0 {
            sweep += TAU;
        }
        let mut e = with_aux(start, aux_end)?;
        e[..XYZ].copy_from_slice(&end);
        Ok(Path::Arc(
            ArcSeg {
                start: *start,
                end: e,
                center,
                u,
                v,
                axis,
                radius,
                theta0: 0.0,
                sweep,
                rise: 0.0,
                length: 0.0,
            }
            .finish(),
        ))
    }

    /// Arc about `center` (plane coordinates) through the signed angle `theta_deg`
    /// from `start` (`MCC_ArcThetaXY` etc.); `theta_deg > 0` is counter-clockwise.
    /// Aux axes stay. A zero angle is a zero-length arc.
    ///
    /// Errors: `BadArc` for zero radius, `BadParameter` for NaN/inf.
    pub fn arc_theta(
        plane: Plane,
        start: &Axes,
        center: [f64; 2],
        theta_deg: f64,
    ) -> Result<Path, PlanError> {
        check_finite(theta_deg, "arc angle")?;
        let seg = theta_arc(plane, start, center, theta_deg, 0.0, None)?;
        Ok(Path::Arc(seg))
    }

    /// Full circle about `center` from `start`, back to `start`
    /// (`MCC_CircleXY` etc.): counter-clockwise when `ccw`. Aux axes go to
    /// `aux_end` when given.
    ///
    /// Errors: `BadArc` for zero radius, `BadParameter` for NaN/inf.
    pub fn circle(
        plane: Plane,
        start: &Axes,
        center: [f64; 2],
        ccw: bool,
        aux_end: Option<[f64; 5]>,
    ) -> Result<Path, PlanError> {
        let theta = if ccw { 360.0 } else { -360.0 };
        let seg = theta_arc(plane, start, center, theta, 0.0, aux_end)?;
        Ok(Path::Arc(seg))
    }

    /// Helix about `center` (plane coordinates) through the signed angle
    /// `theta_deg` (`MCC_HelicalXY_Z(cx, cy, pitch, theta)` etc.): the plane part
    /// is the arc of [`Path::arc_theta`], the normal axis moves `pitch·|theta|/360`
    /// in total (the pitch's sign gives the direction, whichever way it turns, as the
    /// vendor's library moves it), linearly in the angle. Path length is the plane
    /// arc's, `r·|θ|` with `θ` in radians.
    ///
    /// Errors: `BadArc` for zero radius, `BadParameter` for NaN/inf.
    pub fn helix(
        plane: Plane,
        start: &Axes,
        center: [f64; 2],
        pitch: f64,
        theta_deg: f64,
        aux_end: Option<[f64; 5]>,
    ) -> Result<Path, PlanError> {
        check_finite(pitch, "helix pitch")?;
        check_finite(theta_deg, "helix angle")?;
        let rise = pitch * theta_deg.abs() / 360.0;
        check_finite(rise, "helix pitch")?;
        let seg = theta_arc(plane, start, center, theta_deg, rise, aux_end)?;
        Ok(Path::Helix(seg))
    }

    /// Conical helix (`MCC_ConeXY_Z(cx, cy, pos, pitch, rate, dir)` etc.): from `start`
    /// about `center` until the normal axis reaches `end_n`, `|end_n − start_n| / |pitch|`
    /// turns, counter-clockwise when `ccw`, the radius changing by `center_rate` per
    /// turn; see [`ConeSeg`].
    ///
    /// Errors: `BadArc` for a start on the center, `BadParameter` for a zero pitch, a
    /// radius that would fall below 0, NaN/inf.
    pub fn cone(
        plane: Plane,
        start: &Axes,
        center: [f64; 2],
        end_n: f64,
        pitch: f64,
        center_rate: f64,
        ccw: bool,
    ) -> Result<Path, PlanError> {
        ConeSeg::new(plane, start, center, end_n, pitch, center_rate, ccw).map(Path::Cone)
    }

    /// Helix ending at normal-axis position `end_n` (the obsolete
    /// `MCC_HelicaXY_Z(cx, cy, pos, pitch, dir)`): it turns `|end_n − start_n| / |pitch|`
    /// turns, counter-clockwise when `ccw`, and ends exactly at `end_n`.
    ///
    /// Errors: `BadArc` for zero radius, `BadParameter` for a zero pitch or NaN/inf.
    pub fn helix_to(
        plane: Plane,
        start: &Axes,
        center: [f64; 2],
        end_n: f64,
        pitch: f64,
        ccw: bool,
        aux_end: Option<[f64; 5]>,
    ) -> Result<Path, PlanError> {
        check_finite(end_n, "helix end position")?;
        check_finite(pitch, "helix pitch")?;
        if pitch == 0.0 {
            return Err(PlanError::BadParameter("helix pitch"));
        }
        check_all_finite(start, "start position")?;
        let (_, _, n) = plane.axes();
        let rise = end_n - start[n];
        let turns = (rise / pitch).abs();
        let theta = 360.0 * if ccw { turns } else { -turns };
        check_finite(theta, "helix turns")?;
        let mut seg = theta_arc(plane, start, center, theta, rise, aux_end)?;
        seg.end[n] = end_n;
        Ok(Path::Helix(seg))
    }

    #[inline]
    fn common(&self) -> (&Axes, &Axes, f64) {
        match self {
            Path::Line(l) => (&l.start, &l.end, l.length),
            Path::Arc(a) | Path::Helix(a) => (&a.start, &a.end, a.length),
            Path::Cone(c) => (c.start(), c.end(), c.length()),
        }
    }

    /// The length the feed speed applies to (see the type's rules).
    pub fn length(&self) -> f64 {
        self.common().2
    }

    /// Start position (all axes).
    #[inline]
    pub fn start(&self) -> Axes {
        *self.common().0
    }

    /// The chord of a stretch `ds` long over `ds` (1 but on an arc).
    pub fn chord_ratio(&self, ds: f64) -> f64 {
        match self {
            Path::Arc(a) if a.radius > 0.0 && ds > 0.0 => {
                2.0 * a.radius * (ds / (2.0 * a.radius)).sin() / ds
            }
            _ => 1.0,
        }
    }

    /// Start position (all axes), borrowed.
    #[inline]
    pub fn start_ref(&self) -> &Axes {
        self.common().0
    }

    /// End position (all axes), exact as commanded (not sampled).
    pub fn end(&self) -> Axes {
        *self.common().1
    }

    /// The same path moved by `d` (a command queued behind a custom motion, which ended
    /// elsewhere than the queue assumed). Lengths and directions do not change.
    pub fn translate(&mut self, d: &Axes) {
        let add = |p: &mut Axes| {
            for (x, d) in p.iter_mut().zip(d) {
                *x += d;
            }
        };
        match self {
            Path::Line(l) => {
                add(&mut l.start);
                add(&mut l.end);
            }
            Path::Arc(a) | Path::Helix(a) => {
                add(&mut a.start);
                add(&mut a.end);
                for (c, d) in a.center.iter_mut().zip(d) {
                    *c += d;
                }
            }
            Path::Cone(c) => c.translate(d),
        }
    }

    /// Per axis, an interval `(low, high)` holding the coordinate over the whole path:
    /// from start to end for a line and for U..B; for X/Y/Z of an arc or helix the
    /// center's travel (0, or rise along the normal) widened by radius · √(u_i² + v_i²),
    /// the circle's reach along the axis (exact for a full circle). Used to refuse paths
    /// that leave the counters' range.
    pub fn extent(&self) -> [(f64, f64); NUM_AXES] {
        if let Path::Cone(c) = self {
            return c.extent();
        }
        let (start, end, _) = self.common();
        let mut e: [(f64, f64); NUM_AXES] =
            std::array::from_fn(|i| (start[i].min(end[i]), start[i].max(end[i])));
        if let Path::Arc(a) | Path::Helix(a) = self {
            for (i, ei) in e.iter_mut().enumerate().take(XYZ) {
                let reach = a.radius * (a.u[i] * a.u[i] + a.v[i] * a.v[i]).sqrt();
                let (c0, c1) = (a.center[i], a.center[i] + a.rise * a.axis[i]);
                ei.0 = ei.0.min(c0.min(c1) - reach);
                ei.1 = ei.1.max(c0.max(c1) + reach);
            }
        }
        e
    }

    /// For arcs and helices: `Some(true)` if counter-clockwise about the plane
    /// normal (for a 3-D arc: always true about its own normal). `None` for lines.
    pub fn is_ccw(&self) -> Option<bool> {
        match self {
            Path::Line(_) => None,
            Path::Arc(a) | Path::Helix(a) => Some(a.sweep >= 0.0),
            Path::Cone(c) => Some(c.sweep() >= 0.0),
        }
    }

    /// Position at path length `s` (clamped to `[0, length()]`).
    /// `point(0) == start()` and `point(length()) == end()` exactly.
    pub fn point(&self, s: f64) -> Axes {
        let (start, end, len) = self.common();
        if s.is_nan() || s <= 0.0 || len <= 0.0 {
            return *start;
        }
        if s >= len {
            return *end;
        }
        let f = s / len;
        let mut p = [0.0; NUM_AXES];
        match self {
            Path::Cone(c) => return c.point(s),
            Path::Line(l) => {
                for i in 0..NUM_AXES {
                    p[i] = start[i] + l.delta[i] * f;
                }
            }
            Path::Arc(a) | Path::Helix(a) => {
                for i in 0..NUM_AXES {
                    p[i] = start[i] + (end[i] - start[i]) * f;
                }
                let xyz = a.xyz_at(a.theta0 + a.sweep * f, f);
                p[..XYZ].copy_from_slice(&xyz);
            }
        }
        p
    }

    /// The point at fraction `f` of the path (0 the start, 1 the end): [`Path::point`]
    /// of `f·length()`, computed from the fraction itself (a line: `start + delta·f`), as
    /// the vendor's library computes it.
    pub fn point_at(&self, f: f64) -> Axes {
        let (start, end, len) = self.common();
        if f.is_nan() || f <= 0.0 || len <= 0.0 {
            return *start;
        }
        if f >= 1.0 {
            return *end;
        }
        let mut p = [0.0; NUM_AXES];
        match self {
            Path::Cone(c) => return c.point(f * len),
            Path::Line(l) => {
                for i in 0..NUM_AXES {
                    p[i] = start[i] + l.delta[i] * f;
                }
            }
            Path::Arc(a) | Path::Helix(a) => {
                for i in 0..NUM_AXES {
                    p[i] = start[i] + (end[i] - start[i]) * f;
                }
                let xyz = a.xyz_at(a.theta0 + a.sweep * f, f);
                p[..XYZ].copy_from_slice(&xyz);
            }
        }
        p
    }

    /// `pos = point(s)`, `vel = v x direction(s)`: position at path length `s` and the
    /// per-axis velocity at path speed `v`, written in place (the engine samples every
    /// running motion on every tick).
    #[inline(always)]
    pub fn point_velocity_into(&self, s: f64, v: f64, pos: &mut Axes, vel: &mut Axes) {
        if let Path::Line(l) = self {
            return l.point_velocity_into(s, v, pos, vel);
        }
        *vel = self.direction(s).map(|d| v * d);
        *pos = self.point(s);
    }

    /// Derivative of position with respect to path length at `s` (clamped):
    /// a unit vector in X/Y/Z (or in the leading aux axis for aux-only moves);
    /// aux axes get `Δaux/length`. Per-axis speed is `v·direction(s)`.
    /// All zeros for a zero-length path.
    pub fn direction(&self, s: f64) -> Axes {
        match self {
            Path::Line(l) => return l.dir,
            Path::Cone(c) => return c.direction(s),
            _ => {}
        }
        let (start, end, len) = self.common();
        let mut d = [0.0; NUM_AXES];
        if len <= 0.0 {
            return d;
        }
        for i in 0..NUM_AXES {
            d[i] = (end[i] - start[i]) / len;
        }
        if let Path::Arc(a) | Path::Helix(a) = self {
            let f = (s / len).clamp(0.0, 1.0);
            let th = a.theta0 + a.sweep * f;
            let k = a.radius * a.sweep / len; // dθ/ds · r
            let (c, sn) = (th.cos(), th.sin());
            for (i, di) in d.iter_mut().take(XYZ).enumerate() {
                *di = k * (-sn * a.u[i] + c * a.v[i]) + a.axis[i] * a.rise / len;
            }
        }
        d
    }
}

/// A plane arc/helix from the circle `center`/`radius` in plane coordinates.
fn plane_arc(
    plane: Plane,
    start: &Axes,
    end: Axes,
    center: [f64; 2],
    radius: f64,
    sweep: f64,
    rise: f64,
) -> ArcSeg {
    let (ia, ib, n) = plane.axes();
    let mut c3 = [0.0; 3];
    c3[ia] = center[0];
    c3[ib] = center[1];
    c3[n] = start[n];
    let theta0 = (start[ib] - center[1]).atan2(start[ia] - center[0]);
    ArcSeg {
        start: *start,
        end,
        center: c3,
        u: unit3(ia),
        v: unit3(ib),
        axis: unit3(n),
        radius,
        theta0,
        sweep,
        rise,
        length: 0.0,
    }
    .finish()
}

/// Arc/circle/helix about a plane center through `theta_deg` with normal travel `rise`.
/// A radius below this (UU) is a center on the start point: the end point of a previous
/// arc carries rounding of about 1e-15, which must not pass as a circle.
pub const MIN_RADIUS: f64 = 1e-9;

fn theta_arc(
    plane: Plane,
    start: &Axes,
    center: [f64; 2],
    theta_deg: f64,
    rise: f64,
    aux_end: Option<[f64; 5]>,
) -> Result<ArcSeg, PlanError> {
    check_all_finite(start, "start position")?;
    check_all_finite(&center, "arc center")?;
    let (ia, ib, n) = plane.axes();
    let radius = (start[ia] - center[0]).hypot(start[ib] - center[1]);
    if !positive_finite(radius) || radius < MIN_RADIUS {
        return Err(PlanError::BadArc);
    }
    let sweep = theta_deg.to_radians();
    let mut end = with_aux(start, aux_end)?;
    // Whole turns return exactly to the start point in the plane.
    if theta_deg % 360.0 != 0.0 {
        let th = (start[ib] - center[1]).atan2(start[ia] - center[0]) + sweep;
        end[ia] = center[0] + radius * th.cos();
        end[ib] = center[1] + radius * th.sin();
    }
    end[n] = start[n] + rise;
    Ok(plane_arc(plane, start, end, center, radius, sweep, rise))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn line_point_and_direction_are_the_formulas_bit_for_bit() {
        let lines = [
            (
                [0.1, -3.3, 7.0, 1.0, 2.0, 3.0, 4.0, 5.0],
                [1000.0; NUM_AXES],
            ),
            ([0.0; NUM_AXES], [0.0, 0.0, 0.0, 1.0, -7.7, 0.3, 0.0, 2.0]),
            ([1.0; NUM_AXES], [1.0; NUM_AXES]),
        ];
        for (a, b) in lines {
            let p = Path::line(&a, &b);
            let len = p.length();
            for k in 0..=40 {
                let s = len * f64::from(k) / 37.0;
                let d = p.direction(s);
                let q = p.point(s);
                for i in 0..NUM_AXES {
                    let want = if len <= 0.0 { 0.0 } else { (b[i] - a[i]) / len };
                    assert_eq!(d[i].to_bits(), want.to_bits());
                    let at = if s <= 0.0 || len <= 0.0 {
                        a[i]
                    } else if s >= len {
                        b[i]
                    } else {
                        a[i] + (b[i] - a[i]) * (s / len)
                    };
                    assert_eq!(q[i].to_bits(), at.to_bits());
                }
            }
        }
    }

    fn ax(x: f64, y: f64, z: f64) -> Axes {
        [x, y, z, 0.0, 0.0, 0.0, 0.0, 0.0]
    }

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol
    }

    fn assert_axes_close(a: &Axes, b: &Axes, tol: f64) {
        for i in 0..NUM_AXES {
            assert!(close(a[i], b[i], tol), "axis {i}: {a:?} vs {b:?}");
        }
    }

    /// Every sample lies on the circle (radius error <= 1e-9 R) in the plane,
    /// consecutive samples are close, the ends are exact, and `direction`
    /// matches a finite difference of `point`.
    fn check_on_circle(p: &Path, c3: [f64; 3], axis: [f64; 3], r: f64) {
        let n = 1000;
        let len = p.length();
        let mut prev = p.point(0.0);
        assert_eq!(prev, p.start());
        for k in 0..=n {
            let s = len * k as f64 / n as f64;
            let q = p.point(s);
            let d = sub3([q[0], q[1], q[2]], c3);
            // Remove the axial component (helix rise / 3-D plane offset).
            let h = dot3(d, axis);
            let radial = sub3(d, scale3(axis, h));
            assert!(
                (norm3(radial) - r).abs() <= 1e-9 * r,
                "radius at s={s}: {}",
                norm3(radial)
            );
            // Chord between samples, in the plane, never longer than the arc step (the
            // length is the arc's in the plane; a helix rises besides).
            let step = sub3([q[0], q[1], q[2]], [prev[0], prev[1], prev[2]]);
            let chord = norm3(sub3(step, scale3(axis, dot3(step, axis))));
            assert!(chord <= len / n as f64 * (1.0 + 1e-9) + 1e-12);
            prev = q;
            // Tangent check by central difference (interior).
            if k > 0 && k < n {
                let e = 1e-6 * len;
                let (a, b) = (p.point(s - e), p.point(s + e));
                let dir = p.direction(s);
                for i in 0..NUM_AXES {
                    assert!(
                        close((b[i] - a[i]) / (2.0 * e), dir[i], 1e-6),
                        "tangent axis {i}"
                    );
                }
                // Per unit of the length (the arc in the plane): unit in the plane.
                let d3 = [dir[0], dir[1], dir[2]];
                let unit = norm3(sub3(d3, scale3(axis, dot3(d3, axis))));
                assert!(close(unit, 1.0, 1e-12));
            }
        }
        assert_eq!(p.point(len), p.end());
        assert_eq!(p.point(len * 2.0), p.end());
    }

    #[test]
    fn line_endpoints_and_length() {
        let a = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0];
        let b = [4.0, 6.0, 3.0, 14.0, 5.0, -6.0, 7.0, 9.0];
        let p = Path::line(&a, &b);
        assert_eq!(p.length(), 5.0); // 3-4-5 in XY; aux ignored
        assert_eq!(p.point(0.0), a);
        assert_eq!(p.point(5.0), b);
        assert_eq!(p.start(), a);
        assert_eq!(p.end(), b);
        let mid = p.point(2.5);
        assert_axes_close(&mid, &[2.5, 4.0, 3.0, 9.0, 5.0, 0.0, 7.0, 8.5], 1e-12);
        let d = p.direction(1.0);
        assert_axes_close(&d, &[0.6, 0.8, 0.0, 2.0, 0.0, -2.4, 0.0, 0.2], 1e-12);
        assert_eq!(p.is_ccw(), None);
    }

    #[test]
    fn try_line_rejects_non_finite() {
        let a = [0.0; 8];
        let mut b = [1.0; 8];
        assert!(Path::try_line(&a, &b).is_ok());
        b[6] = f64::INFINITY;
        assert!(matches!(
            Path::try_line(&a, &b),
            Err(PlanError::BadParameter(_))
        ));
        assert!(matches!(
            Path::try_line(&b, &a),
            Err(PlanError::BadParameter(_))
        ));
    }

    #[test]
    fn aux_only_line_uses_longest_aux_axis() {
        // No XYZ travel: U moves 10, V moves -20 -> the path is V, length 20.
        let a = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let b = [1.0, 1.0, 1.0, 10.0, -20.0, 0.0, 0.0, 0.0];
        let p = Path::line(&a, &b);
        assert_eq!(p.length(), 20.0);
        let d = p.direction(3.0);
        assert_eq!(d, [0.0, 0.0, 0.0, 0.5, -1.0, 0.0, 0.0, 0.0]);
        assert_axes_close(
            &p.point(10.0),
            &[1.0, 1.0, 1.0, 5.0, -10.0, 0.0, 0.0, 0.0],
            1e-12,
        );
        // Nothing moves at all: zero length, point is the start, direction zero.
        let z = Path::line(&a, &a);
        assert_eq!(z.length(), 0.0);
        assert_eq!(z.point(1.0), a);
        assert_eq!(z.direction(0.0), [0.0; 8]);
    }

    #[test]
    fn arc_xy_half_circle_ccw() {
        // start (10,0), via (0,10), end (-10,0): center (0,0), R = 10, CCW, length 10π.
        let start = ax(10.0, 0.0, 5.0);
        let p = Path::arc_3pt(Plane::XY, &start, [0.0, 10.0], [-10.0, 0.0], None).unwrap();
        let Path::Arc(a) = &p else { panic!() };
        assert!(close(a.radius(), 10.0, 1e-12));
        assert_axes_close(
            &[
                a.center()[0],
                a.center()[1],
                a.center()[2],
                0.,
                0.,
                0.,
                0.,
                0.,
            ],
            &ax(0.0, 0.0, 5.0),
            1e-12,
        );
        assert!(close(a.sweep(), PI, 1e-12));
        assert_eq!(p.is_ccw(), Some(true));
        assert!(close(p.length(), 10.0 * PI, 1e-12));
        assert_eq!(p.end(), ax(-10.0, 0.0, 5.0));
        // Quarter way: (0, 10).
        assert_axes_close(&p.point(5.0 * PI), &ax(0.0, 10.0, 5.0), 1e-12);
        check_on_circle(&p, [0.0, 0.0, 5.0], [0.0, 0.0, 1.0], 10.0);
    }

    #[test]
    fn arc_xy_cw_and_long_way() {
        // start (10,0), via (0,-10), end (-10,0): clockwise half circle.
        let p = Path::arc_3pt(
            Plane::XY,
            &ax(10.0, 0.0, 0.0),
            [0.0, -10.0],
            [-10.0, 0.0],
            None,
        )
        .unwrap();
        assert_eq!(p.is_ccw(), Some(false));
        assert_axes_close(&p.point(p.length() / 2.0), &ax(0.0, -10.0, 0.0), 1e-12);
        // start (10,0), via (-10,0), end (0,-10): 270° CCW the long way round.
        let p = Path::arc_3pt(
            Plane::XY,
            &ax(10.0, 0.0, 0.0),
            [-10.0, 0.0],
            [0.0, -10.0],
            None,
        )
        .unwrap();
        assert_eq!(p.is_ccw(), Some(true));
        assert!(close(p.length(), 15.0 * PI, 1e-12));
        assert_axes_close(&p.point(5.0 * PI), &ax(0.0, 10.0, 0.0), 1e-12);
        check_on_circle(&p, [0.0; 3], [0.0, 0.0, 1.0], 10.0);
    }

    #[test]
    fn arc_offset_center_known_points() {
        // Circle center (3,-2), R = 5: points (8,-2), (6,2), (-2,-2) (3-4-5 triangle).
        let p = Path::arc_3pt(
            Plane::XY,
            &ax(8.0, -2.0, 0.0),
            [6.0, 2.0],
            [-2.0, -2.0],
            None,
        )
        .unwrap();
        let Path::Arc(a) = &p else { panic!() };
        assert!(close(a.center()[0], 3.0, 1e-12) && close(a.center()[1], -2.0, 1e-12));
        assert!(close(a.radius(), 5.0, 1e-12));
        assert!(close(p.length(), 5.0 * PI, 1e-12));
        check_on_circle(&p, [3.0, -2.0, 0.0], [0.0, 0.0, 1.0], 5.0);
    }

    #[test]
    fn arc_yz_and_zx_planes() {
        // YZ: plane coords (Y, Z), X is the normal and stays.
        // start Y=10,Z=0; via (0,10); end (-10,0): CCW about +X, passes Z=+10.
        let start = [7.0, 10.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
        let p = Path::arc_3pt(Plane::YZ, &start, [0.0, 10.0], [-10.0, 0.0], None).unwrap();
        assert_eq!(p.is_ccw(), Some(true));
        assert_eq!(p.end(), [7.0, -10.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0]);
        assert_axes_close(
            &p.point(p.length() / 2.0),
            &[7.0, 0.0, 10.0, 1.0, 2.0, 3.0, 4.0, 5.0],
            1e-12,
        );
        check_on_circle(&p, [7.0, 0.0, 0.0], [1.0, 0.0, 0.0], 10.0);
        // ZX: plane coords (Z, X): the first coordinate is Z. Y stays.
        // start Z=10,X=0; via (Z=0, X=10); end (Z=-10, X=0).
        let start = ax(0.0, 3.0, 10.0);
        let p = Path::arc_3pt(Plane::ZX, &start, [0.0, 10.0], [-10.0, 0.0], None).unwrap();
        assert_eq!(p.is_ccw(), Some(true));
        assert_eq!(p.end(), ax(0.0, 3.0, -10.0));
        assert_axes_close(&p.point(p.length() / 2.0), &ax(10.0, 3.0, 0.0), 1e-12);
        check_on_circle(&p, [0.0, 3.0, 0.0], [0.0, 1.0, 0.0], 10.0);
    }

    #[test]
    fn arc_aux_axes_follow_fraction() {
        let start = ax(10.0, 0.0, 0.0);
        let p = Path::arc_3pt(
            Plane::XY,
            &start,
            [0.0, 10.0],
            [-10.0, 0.0],
            Some([10.0, 0.0, -4.0, 0.0, 2.0]),
        )
        .unwrap();
        assert_eq!(p.end(), [-10.0, 0.0, 0.0, 10.0, 0.0, -4.0, 0.0, 2.0]);
        let q = p.point(p.length() / 4.0);
        assert!(close(q[3], 2.5, 1e-12) && close(q[5], -1.0, 1e-12) && close(q[7], 0.5, 1e-12));
        let d = p.direction(1.0);
        assert!(close(d[3], 10.0 / (10.0 * PI), 1e-12));
    }

    #[test]
    fn arc_xyz_tilted_plane() {
        // Circle of radius 5 centered at c = (1,2,3) in the plane spanned by
        // e1 = (1,0,1)/√2 and e2 = (0,1,0): start c+5e1, via c+5e2, end c−5e1.
        let c = [1.0, 2.0, 3.0];
        let k = 5.0 / 2f64.sqrt();
        let start = ax(c[0] + k, c[1], c[2] + k);
        let via = [c[0], c[1] + 5.0, c[2]];
        let end = [c[0] - k, c[1], c[2] - k];
        let p = Path::arc_3pt_xyz(&start, via, end, None).unwrap();
        let Path::Arc(a) = &p else { panic!() };
        for (ci, ce) in a.center().iter().zip(c) {
            assert!(close(*ci, ce, 1e-12));
        }
        assert!(close(a.radius(), 5.0, 1e-12));
        assert!(close(p.length(), 5.0 * PI, 1e-12));
        assert_eq!(p.end(), ax(end[0], end[1], end[2]));
        assert_axes_close(
            &p.point(p.length() / 2.0),
            &ax(via[0], via[1], via[2]),
            1e-12,
        );
        // Normal = e1 × e2 ∝ (−1, 0, 1)/√2.
        let nrm = [-1.0 / 2f64.sqrt(), 0.0, 1.0 / 2f64.sqrt()];
        check_on_circle(&p, c, nrm, 5.0);
        // Every sample on the plane: (q − c)·n = 0.
        for k in 0..=100 {
            let q = p.point(p.length() * k as f64 / 100.0);
            assert!(dot3(sub3([q[0], q[1], q[2]], c), nrm).abs() < 1e-12);
        }
        // Short arc (via between): 90° arc from e1 through 45° to e2.
        let h = 5.0 * (PI / 4.0).cos();
        let via45 = [c[0] + h / 2f64.sqrt(), c[1] + h, c[2] + h / 2f64.sqrt()];
        let p = Path::arc_3pt_xyz(&start, via45, [c[0], c[1] + 5.0, c[2]], Some([1.0; 5])).unwrap();
        assert!(close(p.length(), 2.5 * PI, 1e-12));
        assert_eq!(p.end()[3..], [1.0; 5]);
        check_on_circle(&p, c, nrm, 5.0);
    }

    #[test]
    fn degenerate_arcs_are_bad_arc() {
        let s = ax(0.0, 0.0, 0.0);
        // Collinear.
        assert_eq!(
            Path::arc_3pt(Plane::XY, &s, [1.0, 1.0], [2.0, 2.0], None),
            Err(PlanError::BadArc)
        );
        // Via coincides with start / end; start == end.
        assert_eq!(
            Path::arc_3pt(Plane::XY, &s, [0.0, 0.0], [2.0, 2.0], None),
            Err(PlanError::BadArc)
        );
        assert_eq!(
            Path::arc_3pt(Plane::XY, &s, [2.0, 2.0], [2.0, 2.0], None),
            Err(PlanError::BadArc)
        );
        assert_eq!(
            Path::arc_3pt(Plane::XY, &s, [1.0, 2.0], [0.0, 0.0], None),
            Err(PlanError::BadArc)
        );
        // Collinear in 3-D and coincident in 3-D.
        assert_eq!(
            Path::arc_3pt_xyz(&s, [1.0, 2.0, 3.0], [2.0, 4.0, 6.0], None),
            Err(PlanError::BadArc)
        );
        assert_eq!(
            Path::arc_3pt_xyz(&s, [0.0, 0.0, 0.0], [2.0, 4.0, 6.0], None),
            Err(PlanError::BadArc)
        );
        // Zero radius.
        assert_eq!(
            Path::arc_theta(Plane::XY, &s, [0.0, 0.0], 90.0),
            Err(PlanError::BadArc)
        );
        assert_eq!(
            Path::circle(Plane::YZ, &s, [0.0, 0.0], true, None),
            Err(PlanError::BadArc)
        );
        assert_eq!(
            Path::helix(Plane::ZX, &s, [0.0, 0.0], 1.0, 90.0, None),
            Err(PlanError::BadArc)
        );
        // In XY the normal axis does not matter for the radius.
        let s2 = ax(0.0, 0.0, 5.0);
        assert_eq!(
            Path::circle(Plane::XY, &s2, [0.0, 0.0], true, None),
            Err(PlanError::BadArc)
        );
        // NaN is a parameter error.
        assert!(matches!(
            Path::arc_theta(Plane::XY, &s, [1.0, 0.0], f64::NAN),
            Err(PlanError::BadParameter(_))
        ));
        assert!(matches!(
            Path::arc_3pt(Plane::XY, &s, [f64::NAN, 1.0], [2.0, 0.0], None),
            Err(PlanError::BadParameter(_))
        ));
    }

    #[test]
    fn arc_theta_sign_convention_per_plane() {
        // Start on +a of a unit circle about the origin; +90° must reach +b, −90° must reach −b.
        for plane in [Plane::XY, Plane::YZ, Plane::ZX] {
            let (ia, ib, n) = plane.axes();
            let mut start = [0.0; 8];
            start[ia] = 2.0;
            start[n] = 0.5;
            for (theta, b_sign) in [(90.0, 1.0), (-90.0, -1.0)] {
                let p = Path::arc_theta(plane, &start, [0.0, 0.0], theta).unwrap();
                let mut expect = [0.0; 8];
                expect[ib] = 2.0 * b_sign;
                expect[n] = 0.5;
                assert_axes_close(&p.end(), &expect, 1e-12);
                assert_axes_close(&p.point(p.length()), &expect, 1e-12);
                assert!(close(p.length(), PI, 1e-12));
                assert_eq!(p.is_ccw(), Some(theta > 0.0));
                let mut c3 = [0.0; 3];
                c3[n] = 0.5;
                check_on_circle(&p, c3, unit3(n), 2.0);
            }
        }
        // Handedness in world coordinates: XY +90° from +X reaches +Y (about +Z);
        // YZ +90° from +Y reaches +Z (about +X); ZX +90° from +Z reaches +X (about +Y).
        let p = Path::arc_theta(Plane::ZX, &ax(0.0, 0.0, 1.0), [0.0, 0.0], 90.0).unwrap();
        assert_axes_close(&p.end(), &ax(1.0, 0.0, 0.0), 1e-15);
        let p = Path::arc_theta(Plane::YZ, &ax(0.0, 1.0, 0.0), [0.0, 0.0], 90.0).unwrap();
        assert_axes_close(&p.end(), &ax(0.0, 0.0, 1.0), 1e-15);
        // A zero angle is a valid zero-length arc.
        let p = Path::arc_theta(Plane::XY, &ax(1.0, 0.0, 0.0), [0.0, 0.0], 0.0).unwrap();
        assert_eq!(p.length(), 0.0);
        assert_eq!(p.end(), ax(1.0, 0.0, 0.0));
    }

    #[test]
    fn circle_returns_to_start() {
        for ccw in [true, false] {
            let start = [3.0, 4.0, 1.0, 9.0, 0.0, 0.0, 0.0, 0.0];
            let p = Path::circle(Plane::XY, &start, [0.0, 0.0], ccw, None).unwrap();
            assert_eq!(p.end(), start);
            assert!(close(p.length(), 10.0 * PI, 1e-12));
            assert_eq!(p.is_ccw(), Some(ccw));
            // A quarter of the way: rotate (3,4) by ±90° -> (−4,3) or (4,−3).
            let q = p.point(p.length() / 4.0);
            let e = if ccw { (-4.0, 3.0) } else { (4.0, -3.0) };
            assert!(close(q[0], e.0, 1e-12) && close(q[1], e.1, 1e-12));
            check_on_circle(&p, [0.0, 0.0, 1.0], [0.0, 0.0, 1.0], 5.0);
        }
        // With aux: aux moves over the full circle.
        let p = Path::circle(
            Plane::ZX,
            &ax(1.0, 0.0, 0.0),
            [0.0, 0.0],
            false,
            Some([4.0, 0.0, 0.0, 0.0, 0.0]),
        )
        .unwrap();
        assert_eq!(p.end(), [1.0, 0.0, 0.0, 4.0, 0.0, 0.0, 0.0, 0.0]);
        assert!(close(p.point(p.length() / 2.0)[3], 2.0, 1e-12));
    }

    #[test]
    fn helix_end_point_and_length() {
        // XY helix, R = 2 about (0,0), from (2,0,0), pitch 3 per turn, θ = 450°:
        // Z travel = 3 * 450/360 = 3.75; end angle 90° -> (0, 2, 3.75).
        // Length: the arc in the plane, 2 * 2.5π, as the vendor's library measures a
        // helix (its feed runs along the arc; the rise follows the angle).
        let start = ax(2.0, 0.0, 0.0);
        let p = Path::helix(Plane::XY, &start, [0.0, 0.0], 3.0, 450.0, None).unwrap();
        assert_axes_close(&p.end(), &ax(0.0, 2.0, 3.75), 1e-12);
        let expect = 2.0 * 2.5 * PI;
        assert!(close(p.length(), expect, 1e-12));
        assert_eq!(p.point(p.length()), p.end());
        // Z is linear in the angle: after one full turn (fraction 360/450) z = 3, back at (2, 0).
        let q = p.point(p.length() * 0.8);
        assert_axes_close(&q, &ax(2.0, 0.0, 3.0), 1e-12);
        // Direction: unit in XYZ, constant axial component 3.75/length.
        let d = p.direction(1.0);
        assert!(close(d[2], 3.75 / expect, 1e-12));
        assert!(matches!(&p, Path::Helix(_)));
        assert_eq!(p.is_ccw(), Some(true));
        check_on_circle(&p, [0.0; 3], [0.0, 0.0, 1.0], 2.0);
        // CW helix in YZ (normal X) with negative pitch: X travel = -1 * |-180|/360 = -0.5
        // (the rise follows the pitch's sign, whichever way the helix turns, as the
        // vendor's library moves it).
        let start = [0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let p = Path::helix(
            Plane::YZ,
            &start,
            [0.0, 0.0],
            -1.0,
            -180.0,
            Some([0.0, 6.0, 0.0, 0.0, 0.0]),
        )
        .unwrap();
        assert_axes_close(&p.end(), &[-0.5, 0.0, -1.0, 0.0, 6.0, 0.0, 0.0, 0.0], 1e-12);
        assert!(close(p.length(), PI, 1e-12));
        // Half way: angle from +Z (90° in YZ) by −90° -> +Y, X = -0.25, V = 3.
        assert_axes_close(
            &p.point(p.length() / 2.0),
            &[-0.25, 1.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0],
            1e-12,
        );
        check_on_circle(&p, [0.0; 3], [1.0, 0.0, 0.0], 1.0);
        // Zero pitch helix is a plain arc in geometry.
        let p = Path::helix(Plane::XY, &ax(1.0, 0.0, 0.0), [0.0, 0.0], 0.0, 180.0, None).unwrap();
        assert!(close(p.length(), PI, 1e-12));
    }

    #[test]
    fn helix_to_end_position() {
        // Obsolete form: end at Z = 5 with pitch 2 -> 2.5 turns, CW.
        let start = ax(1.0, 0.0, 0.0);
        let p = Path::helix_to(Plane::XY, &start, [0.0, 0.0], 5.0, 2.0, false, None).unwrap();
        assert_eq!(p.end()[2], 5.0);
        assert!(close(p.end()[0], -1.0, 1e-12) && close(p.end()[1], 0.0, 1e-12));
        assert_eq!(p.is_ccw(), Some(false));
        let expect = 2.0 * 2.5 * PI;
        assert!(close(p.length(), expect, 1e-12));
        assert!(matches!(
            Path::helix_to(Plane::XY, &start, [0.0, 0.0], 5.0, 0.0, false, None),
            Err(PlanError::BadParameter(_))
        ));
    }

    #[test]
    fn aux_only_arc_uses_aux_length() {
        // θ = 0 helix with aux travel: XYZ don't move, U is the path.
        let p = Path::helix(
            Plane::XY,
            &ax(1.0, 0.0, 0.0),
            [0.0, 0.0],
            1.0,
            0.0,
            Some([0.0, 0.0, 7.0, 0.0, 0.0]),
        )
        .unwrap();
        assert_eq!(p.length(), 7.0);
        assert_eq!(p.end(), [1.0, 0.0, 0.0, 0.0, 0.0, 7.0, 0.0, 0.0]);
        assert_eq!(p.direction(1.0)[5], 1.0);
        assert_axes_close(
            &p.point(3.5),
            &[1.0, 0.0, 0.0, 0.0, 0.0, 3.5, 0.0, 0.0],
            1e-12,
        );
    }

    #[test]
    fn consecutive_lines_do_not_drift() {
        // 10^6 small moves; each starts exactly where the previous ended and the
        // final position is the exact commanded target.
        let mut cur = [0.0; 8];
        let n = 1_000_000u32;
        for k in 1..=n {
            let x = f64::from(k) * 1e-3;
            let target = [x, -x, 0.5 * x, x, 0.0, 0.0, 0.0, 1e-7 * f64::from(k)];
            let p = Path::line(&cur, &target);
            assert_eq!(p.start(), cur);
            assert_eq!(p.end(), target);
            if k % 4096 == 0 {
                assert_eq!(p.point(p.length()), target);
            }
            cur = p.end();
        }
        assert_eq!(cur[0], f64::from(n) * 1e-3);
        assert_eq!(cur[7], f64::from(n) * 1e-7);
    }
}
