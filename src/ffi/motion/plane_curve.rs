//! A curve in a plane as C passes it, what the arcs, circles, helices and cones share: its
//! points and U..B ends checked finite and against the position range, and a curve about
//! a center ([`About`]) queued.

use crate::engine::command::Curve;
use crate::error::McclResult;
use crate::ffi::{finite, finite2, queue_curve};
use crate::planner::{Path, Plane};
use crate::vendor::WORD;
use std::os::raw::c_int;

/// Checks plane points (on `plane`'s two axes) and aux ends (U..B) against the position
/// range before any geometry is built from them.
pub(super) fn check_plane(
    ctx: &crate::engine::command::Ctx<'_>,
    plane: Plane,
    pts: &[[f64; 2]],
    aux: Option<[f64; 5]>,
) -> Result<(), crate::planner::PlanError> {
    let (a, b, _) = plane.axes();
    let mut all: Vec<(usize, f64)> = pts.iter().flat_map(|p| [(a, p[0]), (b, p[1])]).collect();
    if let Some(x) = aux {
        all.extend(x.iter().enumerate().map(|(k, v)| (3 + k, *v)));
    }
    ctx.check_points(&all)
}

pub(super) fn aux5(v: [f64; 5]) -> McclResult<[f64; 5]> {
    v.iter().try_for_each(|&x| finite(x).map(|_| ()))?;
    Ok(v)
}

/// A curve about a center `c` of a plane (arc by an angle, circle, helix, cone), with
/// the U..B ends `aux` moving linearly along, as C passed them.
#[derive(Clone, Copy)]
pub(in crate::ffi) struct About {
    pub plane: Plane,
    pub c: [f64; 2],
    pub aux: Option<[f64; 5]>,
}

impl About {
    /// About the center `c` of `plane`, with the U..B ends `aux` (`None`: U..B stay).
    pub(in crate::ffi) fn new(plane: Plane, c: [f64; 2], aux: Option<[f64; 5]>) -> Self {
        About { plane, c, aux }
    }
}

/// Queues the curve `build` makes about `at` (`helix`: reported as a helix): the center
/// and the ends are checked finite, resolved against the group (absolute or relative)
/// and checked against the position range before `build` runs with them.
pub(in crate::ffi) fn queue_about(
    at: About,
    kind: Curve,
    g: WORD,
    build: impl FnOnce(
        &crate::engine::command::Ctx<'_>,
        [f64; 2],
        Option<[f64; 5]>,
    ) -> Result<Path, crate::planner::PlanError>,
) -> McclResult<c_int> {
    let cxy = finite2(at.c)?;
    let aux = at.aux.map(aux5).transpose()?;
    let plan = |ctx: &crate::engine::command::Ctx<'_>| {
        let aux = aux.map(|a| std::array::from_fn(|k| ctx.resolve_axis(3 + k, a[k])));
        let c = ctx.resolve_plane(at.plane, cxy);
        check_plane(ctx, at.plane, &[c], aux)?;
        build(ctx, c, aux)
    };
    queue_curve(g, plan, kind)
}
