#![warn(missing_docs)]
//! RW Automation MC3B 3-channel stepper motor controller support.
//!
//! * [`codec`]: typed commands and responses of the ASCII serial command
//!   set (User's Guide §6), encoder, streaming parsers.
//! * [`emulator`]: a deterministic device model (injectable 1 kHz clock).
//! * [`client`]: command/response client over a byte transport (a serial
//!   port at 19200 8N1, or an in-process emulator).
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
pub mod client;
pub mod codec;
pub mod emulator;
pub mod mcl;
