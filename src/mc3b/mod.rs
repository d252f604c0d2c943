#![warn(missing_docs)]
//! RW Automation MC3B 3-channel stepper motor controller support: the library's side.
//! The board itself — its wire protocol, the client over a serial port, the emulator —
//! is the workspace crate `mc3b` (`crates/mc3b`); this module is what the C library
//! builds on it.
//!
//! * [`backend`]: the MC3B as the hardware behind a card of the virtual card
//!   (`mc3b_port` in `MCCL_SIM`): unit conversions, jobs, the worker thread.
//! * [`mcl`]: the MC3B's C library of §4 (`mcl_*`, exported with C linkage).
//!   COM port N is the device named by `MCL_COM<N>` if set, else
//!   `/dev/ttyS<N-1>` (Linux) or `COM<N>` (Windows).
//!
//! The `mc3b-emu` binary runs the emulator on a pseudo-terminal in real time
//! (see `mc3b-emu --help`); Windows has no pseudo-terminals, and there it
//! says so and exits.

pub mod backend;
pub mod mcl;
