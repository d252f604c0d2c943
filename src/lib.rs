//! libMCCLPCI_IMP: a drop-in replacement for the EPCIO IMP-series motion card
//! library, with a virtual card that runs the motion in software.
#![allow(non_snake_case, non_camel_case_types, non_upper_case_globals)]
pub mod mc3b;
