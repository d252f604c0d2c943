//! `mc3b-app`: the MC3B control application in the browser. See `--help` and
//! docs/mc3b.md.

use std::io::Write;
use std::net::SocketAddr;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use mc3b::client::timeout_from_env;
use mc3b_app::board::{serial_opener, Board};
use mc3b_app::checks::Op;
use mc3b_app::server::Http;
use mc3b_app::shared::Shared;

const HELP: &str = "\
mc3b-app: the MC3B stepper controller's control application, as a page in the browser

USAGE: mc3b-app [--port PATH] [--listen ADDRESS:PORT]

  --port PATH        open this serial port at once (as the port selection dialog
                     does), e.g. /dev/ttyUSB0 or an emulator's /dev/pts/N
  --listen ADDR:PORT serve there (default 127.0.0.1:8322; port 0: a free one).
                     Anything but a loopback address is served with a warning.

The first line on stdout is the page's address with its token:
  mc3b-app: open http://127.0.0.1:8322/?token=<32 hex digits>
Every request must carry the token. MCL_TIMEOUT_MS (a positive number of ms) sets
the reply timeout (default 500 ms).

Safety: closing the page, a browser that ends, or no heartbeat from any page for
1 s stops every motor; ending the application (Ctrl-C, SIGTERM) turns the motors
off (0I). A SIGKILL of the application cannot: the MC3B has no watchdog.
";

/// Default address: loopback, next to the machine panel's 8321.
const DEFAULT_LISTEN: &str = "127.0.0.1:8322";

static SIGNALLED: AtomicBool = AtomicBool::new(false);

extern "C" fn on_signal(_: libc::c_int) {
    SIGNALLED.store(true, Ordering::Release);
}

fn catch_signals() {
    for sig in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP] {
        // SAFETY: the handler only stores to an atomic, which is async-signal-safe; the
        // function pointer has the C signature signal() expects.
        unsafe {
            libc::signal(
                sig,
                on_signal as extern "C" fn(libc::c_int) as libc::sighandler_t,
            );
        }
    }
}

struct Args {
    port: Option<String>,
    listen: SocketAddr,
}

/// Reads the command line (`p`): the arguments, `None` for the usage.
fn args(mut p: lexopt::Parser) -> Result<Option<Args>, String> {
    use lexopt::prelude::*;
    let mut port = None;
    let mut listen = DEFAULT_LISTEN.to_string();
    let text = |v: std::ffi::OsString, what: &str| {
        v.into_string()
            .map_err(|v| format!("{what} {v:?}: not valid text"))
    };
    while let Some(a) = p.next().map_err(|e| format!("{e} (see --help)"))? {
        match a {
            Short('h') | Long("help") => return Ok(None),
            Long("port") => {
                let v = p.value().map_err(|_| "--port needs a path")?;
                port = Some(text(v, "--port")?);
            }
            Long("listen") => {
                let v = p.value().map_err(|_| "--listen needs ADDRESS:PORT")?;
                listen = text(v, "--listen")?;
            }
            a => return Err(format!("{} (see --help)", a.unexpected())),
        }
    }
    let listen = listen
        .parse::<SocketAddr>()
        .map_err(|_| format!("--listen {listen:?}: not an address such as 127.0.0.1:8322"))?;
    Ok(Some(Args { port, listen }))
}

/// One line on stdout, flushed; a closed stdout is no reason to stop (the motors
/// would be left to the heartbeat watch).
fn say(line: &str) {
    let mut out = std::io::stdout();
    let _ = writeln!(out, "{line}");
    let _ = out.flush();
}

fn run(a: Args) -> Result<(), String> {
    if !a.listen.ip().is_loopback() {
        eprintln!(
            "mc3b-app: warning: serving on {}, not on loopback: anyone who can reach it and \
             has the token can move the motors",
            a.listen
        );
    }
    let shared = Shared::new();
    let http = Http::bind(a.listen, shared.clone())?;
    let board = Board::new(shared.clone(), serial_opener(), timeout_from_env());
    let board_thread = std::thread::Builder::new()
        .name("mc3b-app-board".into())
        .spawn(move || board.run())
        .map_err(|e| format!("cannot start the board thread: {e}"))?;
    catch_signals();
    let workers = http.start();
    say(&format!("mc3b-app: open {}", http.url()));
    if let Some(path) = a.port {
        match shared.submit(Op::Connect(path.clone())) {
            Ok(msg) => say(&format!("mc3b-app: {msg}")),
            Err(r) => eprintln!("mc3b-app: {path}: {}", r.message),
        }
    }
    while !SIGNALLED.load(Ordering::Acquire) {
        std::thread::sleep(Duration::from_millis(100));
    }
    eprintln!("mc3b-app: ending: motors off");
    shared.shutdown();
    let _ = board_thread.join();
    for w in workers {
        let _ = w.join();
    }
    Ok(())
}

fn main() {
    match args(lexopt::Parser::from_env()) {
        Ok(None) => print!("{HELP}"),
        Ok(Some(a)) => {
            if let Err(e) = run(a) {
                eprintln!("mc3b-app: {e}");
                std::process::exit(1);
            }
        }
        Err(e) => {
            eprintln!("mc3b-app: {e}");
            std::process::exit(2);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::args;

    fn parse(a: &[&str]) -> Result<Option<(Option<String>, String)>, String> {
        args(lexopt::Parser::from_args(a.iter().copied()))
            .map(|o| o.map(|a| (a.port, a.listen.to_string())))
    }

    #[test]
    fn reads_the_port_and_the_address_in_either_form() {
        assert_eq!(
            parse(&["--port", "/dev/ttyUSB0", "--listen=127.0.0.1:9000"]),
            Ok(Some((Some("/dev/ttyUSB0".into()), "127.0.0.1:9000".into())))
        );
        assert_eq!(
            parse(&[]),
            Ok(Some((None, super::DEFAULT_LISTEN.to_string())))
        );
        assert_eq!(parse(&["-h"]), Ok(None));
    }

    #[test]
    fn refuses_what_it_cannot_use() {
        assert_eq!(parse(&["--port"]), Err("--port needs a path".into()));
        assert!(parse(&["--listen", "nope"]).is_err_and(|e| e.contains("not an address")));
        assert!(parse(&["--verbose"]).is_err_and(|e| e.contains("--verbose")));
        assert!(parse(&["stray"]).is_err_and(|e| e.contains("stray")));
    }
}
