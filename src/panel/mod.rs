//! `MCCL_PANEL`: a live machine panel in the browser for an unchanged program
//! (docs/panel.md).
//!
//! `MCC_InitSystem` starts it when `MCCL_PANEL` names an address (`127.0.0.1:8321`, or `1`
//! for that default); it is one thread serving HTTP on that address, with a random token
//! every request must carry, and `MCC_CloseSystem` stops and joins it. The page it serves
//! is built into the library. It reads what the engine publishes without locking it (the
//! groups' snapshots, the engine's [`crate::engine::view`] copy, atomic counters) and
//! works the simulated machine through the same core calls the `MCCL_Sim*` functions
//! make; it never calls the C entry points.
//!
//! Layer: above the engine, below the system (which starts and stops it).

mod control;
mod http;
mod state;

use crate::config::GroupDef;
use crate::engine::Shared;
use parking_lot::Mutex;
use std::net::{SocketAddr, TcpListener};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::thread::JoinHandle;

/// The address `MCCL_PANEL=1` means: loopback, port 8321.
pub const DEFAULT_ADDR: &str = "127.0.0.1:8321";

/// The URL of the running panel (with its token), for tests and tools in the same process.
static URL: Mutex<Option<String>> = Mutex::new(None);

/// The URL of the running panel, `None` when none runs.
pub fn url() -> Option<String> {
    URL.lock().clone()
}

/// A running panel: its thread stops and is joined when this is dropped.
#[derive(Debug)]
pub struct Panel {
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

impl Drop for Panel {
    fn drop(&mut self) {
        self.stop.store(true, Ordering::Release);
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
        *URL.lock() = None;
    }
}

/// What `MCCL_PANEL` asks for: `None` when unset, empty or `0`.
fn address_from(v: Option<&str>) -> Result<Option<SocketAddr>, String> {
    let v = match v.map(str::trim) {
        None | Some("") | Some("0") => return Ok(None),
        Some("1") => DEFAULT_ADDR,
        Some(v) => v,
    };
    v.parse::<SocketAddr>()
        .map(Some)
        .map_err(|_| format!("MCCL_PANEL={v:?}: not an address such as 127.0.0.1:8321 (or 1)"))
}

/// 16 random bytes from the system's generator (`getrandom`) as 32 hex digits.
fn token() -> std::io::Result<String> {
    let mut b = [0u8; 16];
    getrandom::fill(&mut b).map_err(std::io::Error::other)?;
    Ok(b.iter().map(|x| format!("{x:02x}")).collect())
}

/// Starts the panel if `MCCL_PANEL` asks for one (called by `MCC_InitSystem` once the
/// engine runs). Any problem (a bad address, a port in use) is a message on stderr and
/// no panel: the program runs as it would without one.
pub fn start_from_env(shared: &Arc<Shared>, groups: &[(usize, GroupDef)]) -> Option<Panel> {
    let addr = match address_from(std::env::var("MCCL_PANEL").ok().as_deref()) {
        Ok(Some(a)) => a,
        Ok(None) => return None,
        Err(msg) => {
            eprintln!("MCCL: {msg}; no panel");
            return None;
        }
    };
    match start(addr, shared, groups) {
        Ok(p) => Some(p),
        Err(e) => {
            eprintln!("MCCL: MCCL_PANEL: cannot serve on {addr}: {e}; no panel");
            None
        }
    }
}

/// The panel is a best-effort observer: its thread runs below normal priority (nice 10 on
/// Linux), so under CPU contention (a flood of requests, a busy 2-core host) the engine
/// thread and the program's threads go first. Lowering one's own priority is always
/// permitted; should it fail anyway, the panel runs at normal priority.
fn background_priority() {
    let _ = crate::platform::lower_thread_priority();
}

/// Starts a panel on `addr` and prints its URL on stderr.
pub fn start(
    addr: SocketAddr,
    shared: &Arc<Shared>,
    groups: &[(usize, GroupDef)],
) -> std::io::Result<Panel> {
    let token = token()?;
    let listener = TcpListener::bind(addr)?;
    listener.set_nonblocking(true)?;
    let bound = listener.local_addr()?;
    let url = format!("http://{bound}/?token={token}");
    if !bound.ip().is_loopback() {
        eprintln!(
            "MCCL: warning: the panel listens on {} (not loopback): anyone who can reach it \
             and learns the token can work the simulated machine",
            bound.ip()
        );
    }
    let stop = Arc::new(AtomicBool::new(false));
    let server = http::Server::new(
        listener,
        token,
        state::Source::new(shared.clone(), groups),
        stop.clone(),
    );
    let thread = std::thread::Builder::new()
        .name("mccl-panel".into())
        .spawn(move || {
            background_priority();
            server.run()
        })?;
    eprintln!("MCCL: panel at {url}");
    *URL.lock() = Some(url);
    Ok(Panel {
        stop,
        thread: Some(thread),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn addresses() {
        assert_eq!(address_from(None), Ok(None));
        assert_eq!(address_from(Some("")), Ok(None));
        assert_eq!(address_from(Some("0")), Ok(None));
        assert_eq!(
            address_from(Some("1")),
            Ok(Some("127.0.0.1:8321".parse().unwrap()))
        );
        assert_eq!(
            address_from(Some(" 127.0.0.1:0 ")),
            Ok(Some("127.0.0.1:0".parse().unwrap()))
        );
        assert_eq!(
            address_from(Some("[::1]:9000")),
            Ok(Some("[::1]:9000".parse().unwrap()))
        );
        assert!(address_from(Some("localhost")).is_err());
        assert!(address_from(Some("yes")).is_err());
    }

    #[test]
    fn tokens_are_32_hex_digits_and_differ() {
        let (a, b) = (token().unwrap(), token().unwrap());
        assert_eq!(a.len(), 32);
        assert!(a.bytes().all(|c| c.is_ascii_hexdigit()));
        assert_ne!(a, b);
    }
}
