//! libMCCLPCI_IMP: a drop-in replacement for the EPCIO IMP-series motion card library,
//! with a virtual card that runs the motion in software.
//!
//! Layers, outermost first: [`ffi`] (the C entry points), [`system`] (the one
//! process-wide system), [`engine`] and [`clock`] (the virtual card's tick thread),
//! [`planner`] (pure trajectory math), [`config`] and [`vendor`] (the vendor's data),
//! [`mc3b`] (the MC3B stepper controller: protocol, emulator, its `mcl_*` C library), and
//! at the bottom [`platform`] (what differs between Linux and Windows).
#![allow(non_snake_case, non_camel_case_types, non_upper_case_globals)]

pub mod card;
pub mod clock;
pub mod config;
pub mod engine;
pub(crate) mod error;
pub(crate) mod error_record;
pub(crate) mod fault;
pub mod ffi;
pub(crate) mod interrupt;
pub(crate) mod machine;
pub mod mc3b;
#[cfg(feature = "panel")]
pub mod panel;
pub mod planner;
pub mod platform;
pub(crate) mod sim;
pub mod system;
pub mod vendor;
