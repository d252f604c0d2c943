//! mccl-trace: look at what the machine did. Reads `MCCL_TRACE` files (and the
//! `.events.csv` beside them) as streams, plots them ([`plot`]), writes a self-contained
//! HTML report ([`report`]) and compares two traces ([`diff`]).
#![allow(clippy::needless_range_loop)] // axis loops index several arrays at once
pub mod data;
pub mod diff;
mod lines;
pub mod plot;
pub mod report;
pub mod scan;
