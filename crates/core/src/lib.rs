//! The core of libMCCLPCI_IMP: what the library computes and simulates, with no C export,
//! no thread, no global state and no environment variable (the library's C ABI crate, the
//! repository's root, holds those and reads the environment for it).
//!
//! Layers, lowest first: [`vendor`] (the vendor's typedefs, constants, structs and
//! callback types), [`error`] (return codes), [`error_record`] (the 0xF… error records),
//! [`interrupt`] (interrupt causes as data), [`config`] (what the program configures),
//! [`sim`] (the simulated machine's configuration file), [`planner`] (pure trajectory
//! planning), [`machine`] (the simulated machine: motors, encoders, sensors, triggers) and
//! [`card`] (the card's peripherals: timer, watchdog, converters, remote I/O), and on top
//! [`engine`] (the motion groups: planning a command, running it period by period, what
//! a group publishes). The caller owns time: a group or a channel advances one period
//! when asked.
//!
//! The façade is [`Card`]: a simulated card and its groups, to which the caller queues
//! commands and which it ticks, one interpolation period at a time, running the same
//! tick ([`engine::tick::tick`]) as the library's engine thread.

pub mod card;
pub mod config;
pub mod engine;
pub mod error;
pub mod error_record;
pub mod interrupt;
pub mod machine;
pub mod planner;
pub mod sim;
pub mod vendor;

pub use engine::card::Card;
