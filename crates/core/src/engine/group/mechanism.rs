//! The group's mechanism: its mapping, the facts of each axis and the channels its axes
//! command.

use super::Commanded;
use crate::config::{GroupDef, AXES};
use crate::engine::command::AxisMech;

/// The mapping and queue size, the axes' mechanism facts and the channels they command.
#[derive(Debug)]
pub(super) struct Mechanism {
    /// The mapping and queue size the group runs with.
    pub(super) def: GroupDef,
    /// Mechanism facts per axis (from the parameters in effect).
    pub(super) axes: [AxisMech; AXES],
    /// The axes whose pulses command a channel, with the channel (set when the engine
    /// starts, `engine::shared`: it depends on every group's mapping).
    pub(super) commanded: Commanded,
}

impl Mechanism {
    /// The mechanism of `def` with the facts `axes`; no channel commanded yet.
    pub(super) fn new(def: GroupDef, axes: [AxisMech; AXES]) -> Mechanism {
        Mechanism {
            def,
            axes,
            commanded: Commanded::default(),
        }
    }
}
