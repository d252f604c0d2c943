//! libMCCLPCI_IMP: a drop-in replacement for the EPCIO IMP-series motion card library,
//! with a virtual card that runs the motion in software.
//!
//! Layers, outermost first: [`ffi`] (the C entry points), [`system`] (the one
//! process-wide system), [`engine`] and [`clock`] (the virtual card's tick thread),
//! [`planner`] (pure trajectory math), [`config`] and [`vendor`] (the vendor's data),
//! [`mc3b`] (the MC3B stepper controller as the library uses it: the bodies of its `mcl_*`
//! C library and the backend behind a card; the board's protocol, client and emulator
//! are the workspace crate `mc3b`), and at the bottom [`platform`] (what differs between
//! Linux and Windows).
// The crate is named after the vendor's library (`MCCLPCI_IMP`), which the naming lint
// checks at the root; every module but `ffi` and `vendor` (where the vendor's names
// live) has the lint back.
#![allow(non_snake_case)]

// The core: the vendor's data, the configuration, the planner, the simulated machine and
// the card's peripherals (crates/core). Re-exported under their names, so that the
// library's modules and its Rust users name them as before.
pub use mccl_core::{card, config, planner, vendor};
pub(crate) use mccl_core::{error, error_record, interrupt, machine, sim};

#[warn(non_snake_case)]
pub mod clock;
#[warn(non_snake_case)]
pub mod engine;
#[warn(non_snake_case)]
pub(crate) mod fault;
pub mod ffi;
#[warn(non_snake_case)]
pub mod mc3b;
#[cfg(feature = "panel")]
#[warn(non_snake_case)]
pub mod panel;
#[warn(non_snake_case)]
pub mod platform;
#[warn(non_snake_case)]
pub mod system;
