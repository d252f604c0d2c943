//! What a group's tick leaves for the engine to act on.

use crate::engine::command::Output;
use crate::engine::note::Note;

/// Output changes the queue reached and events for the trace.
#[derive(Debug, Default)]
pub(super) struct Emitted {
    /// Output changes the queue reached this tick (the engine makes them).
    pub(super) outputs: Vec<Output>,
    /// Events for the trace's events file, `Some` only while tracing (`MCCL_TRACE`).
    pub(super) trace_notes: Option<Vec<Note>>,
}
