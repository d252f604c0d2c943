//! `mc3b-app`: the MC3B's sample application of the guide's chapter 5 as a page in the
//! browser, served on loopback like the project's machine panel (docs/mc3b.md).
//!
//! * [`checks`]: the page's requests and the checks every value passes before anything
//!   is sent (chapter 6's ranges, chapter 5's dialog rules).
//! * [`params`]: a motor's settings (§5.3) and the commands that set them.
//! * [`circle`]: the chained synchronous move of §5.4, a circle of chords.
//! * [`board`]: the thread that owns the serial line (the project's MC3B client).
//! * [`shared`]: where the HTTP threads and the board thread meet; stops first, the
//!   heartbeat watch.
//! * [`server`]: HTTP on `tiny_http`, the token, the event stream.
//! * [`ports`]: the system's serial ports.

pub mod board;
pub mod checks;
pub mod circle;
pub mod params;
pub mod ports;
pub mod server;
pub mod shared;
