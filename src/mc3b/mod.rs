#![warn(missing_docs)]
//! RW Automation MC3B 3-channel stepper motor controller support: the
//! RS-232 protocol codec (§6 of the MC3B User's Guide), a device emulator, a
//! serial client and the MC3B's own C library (§4, `mcl_*`).

pub mod client;
pub mod codec;
pub mod emulator;
pub mod mcl;
