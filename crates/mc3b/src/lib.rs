#![warn(missing_docs)]
//! The RW Automation MC3B 3-channel stepper motor controller, as far as it is the board
//! itself: what goes over its RS-232 line and how a program talks to it, and a software
//! MC3B to talk to when there is no board. Nothing here knows a motion card: the motion
//! library drives an MC3B through [`client`], and the control application `mc3b-app` and
//! the `mc3b-emu` program use the same modules.
//!
//! * [`codec`]: the ASCII command set of the User's Guide §6: typed commands and
//!   responses, their encoding, streaming parsers.
//! * [`client`]: commands and their replies over any byte [`Transport`](client::Transport):
//!   reply timeouts, bringing the line back in step after a failure.
//! * [`serial`]: the serial port (19200 baud, 8N1, §3.2) as the system names and opens
//!   it, and a pseudo-terminal pair for the emulator (Linux only).
//! * [`emulator`]: a deterministic model of the device on an injectable 1 kHz clock:
//!   what the tests talk to, and the model behind position estimates (the board never
//!   reports a position).

pub mod client;
pub mod codec;
pub mod emulator;
pub mod serial;
