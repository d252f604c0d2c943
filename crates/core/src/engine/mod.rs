//! The engine's groups: planning a command (`command.rs`), a running motion's profile
//! (`track.rs`), custom motion (`custom.rs`, `custom_move.rs`), robot kinematics as a
//! group holds them (`kinematics.rs`), the events noted for the trace (`note.rs`), what a
//! group publishes (`snapshot.rs`), and one group on the card with its parts (`group/`).
//!
//! The caller owns time and threads: a group advances by one period when asked
//! ([`group::GroupState::tick`]); the library's engine runs every group's tick, the card's
//! channels and peripherals, on its clock and thread.

pub mod command;
pub mod custom;
pub mod custom_move;
pub mod group;
pub mod kinematics;
pub mod note;
pub mod snapshot;
pub mod track;
