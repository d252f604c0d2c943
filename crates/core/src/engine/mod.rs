//! The engine's groups: planning a command (`command.rs`), a running motion's profile
//! (`track.rs`), custom motion (`custom.rs`, `custom_move.rs`), robot kinematics as a
//! group holds them (`kinematics.rs`), the events noted for the trace (`note.rs`), what a
//! group publishes (`snapshot.rs`), and one group on the card with its parts (`group/`).
//!
//! The caller owns time and threads: a group advances by one period when asked
//! ([`group::GroupState::tick`]); the library's engine runs every group's tick, the card's
//! channels and peripherals, on its clock and thread.

pub mod card;
pub mod command;
pub mod custom;
pub mod custom_move;
pub mod group;
pub mod homing;
pub mod kinematics;
pub mod note;
pub mod safety;
pub mod snapshot;
pub mod tick;
pub mod track;

use crate::config::{GroupDef, MacTable, AXES};
use command::AxisMech;

/// The mechanism facts of a group's axes: mapped axes from their channel's parameters,
/// unmapped ones from the defaults (their planning result is ignored, §2.4.4).
pub fn axes_of(def: &GroupDef, mac: &MacTable) -> [AxisMech; AXES] {
    std::array::from_fn(|i| match def.channels[i] {
        Some(ch) => AxisMech::new(&mac[def.card.0][ch.0], Some((def.card.0, ch.0))),
        None => AxisMech::new(&crate::config::default_mac_param(), None),
    })
    .map(|a| a.in_unit(crate::config::unit_scale(def.unit)))
}
