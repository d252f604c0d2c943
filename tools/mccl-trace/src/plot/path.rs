//! The path panel's polyline, simplified as the trace streams by.

/// Largest distance, px, of a trace point from the drawn path (plus `MERGE_PX`).
pub const PATH_TOL_PX: f64 = 0.75;
/// Points closer than this to the last one kept for the check are not kept for it.
pub(super) const MERGE_PX: f64 = 0.2;
/// Most points between two vertices that are kept for the check.
pub(super) const BUF_MAX: usize = 512;

/// Streaming simplification of the path: a vertex is kept only when the segment from the
/// last vertex would pass further than [`PATH_TOL_PX`] from a point since it. Vertices
/// are rounded to whole pixels and the check is made against the rounded segment, so
/// every trace point lies within `PATH_TOL_PX + MERGE_PX` = 0.95 px of what is drawn.
#[derive(Default)]
pub(super) struct PathSimplifier {
    pub(super) kept: Vec<(i32, i32, i32)>,
    pub(super) anchor: Option<(i32, i32)>,
    pub(super) buf: Vec<(f64, f64)>,
    pub(super) last: Option<(f64, f64, i32)>,
    pub(super) last_kept: bool,
}

pub(super) fn seg_dist(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    ((p.0 - a.0 - t * dx).powi(2) + (p.1 - a.1 - t * dy).powi(2)).sqrt()
}

impl PathSimplifier {
    pub(super) fn keep(&mut self, p: (f64, f64), cmd: i32) {
        let r = (p.0.round() as i32, p.1.round() as i32);
        self.kept.push((r.0, r.1, cmd));
        self.anchor = Some(r);
        self.buf.clear();
        self.buf.push(p);
    }

    pub(super) fn push(&mut self, p: (f64, f64), cmd: i32) {
        let Some((lx, ly, lc)) = self.last else {
            self.keep(p, cmd);
            self.last = Some((p.0, p.1, cmd));
            self.last_kept = true;
            return;
        };
        if cmd != lc {
            if !self.last_kept {
                self.keep((lx, ly), lc);
            }
            self.keep(p, cmd);
            self.last = Some((p.0, p.1, cmd));
            self.last_kept = true;
            return;
        }
        let a = self
            .anchor
            .map_or((lx, ly), |a| (f64::from(a.0), f64::from(a.1)));
        let b = (p.0.round(), p.1.round());
        let fits =
            self.buf.len() < BUF_MAX && self.buf.iter().all(|&q| seg_dist(q, a, b) <= PATH_TOL_PX);
        if fits {
            self.last_kept = false;
        } else {
            if !self.last_kept {
                self.keep((lx, ly), lc);
            }
            self.last_kept = false;
        }
        let close = self
            .buf
            .last()
            .is_some_and(|q| (q.0 - p.0).hypot(q.1 - p.1) < MERGE_PX);
        if !close {
            self.buf.push(p);
        }
        self.last = Some((p.0, p.1, cmd));
    }

    pub(super) fn finish(&mut self) {
        if let (Some((x, y, c)), false) = (self.last, self.last_kept) {
            self.keep((x, y), c);
            self.last_kept = true;
        }
    }
}
