//! The `mc3b-emu` binary as a test's MC3B: spawned on a pseudo-terminal, driven over its
//! control channel (stdin/stdout), killed when dropped.

use super::Watchdog;
use std::io::{BufRead, BufReader, Write};
use std::process::{Child, ChildStdin, ChildStdout, Command, Stdio};
use std::time::Duration;

/// A running emulator; its device side is the pseudo-terminal at `path`.
pub struct Emu {
    /// The emulator's process (a test may stop it, or wait for it after `quit`).
    pub child: Child,
    stdin: ChildStdin,
    stdout: BufReader<ChildStdout>,
    /// The device path it printed (`/dev/pts/N`).
    pub path: String,
    /// Each test that talks to an emulator is bounded (60 s).
    _watchdog: Watchdog,
}

impl Emu {
    /// Starts an emulator and reads the device path it prints first.
    pub fn spawn() -> Emu {
        let mut child = Command::new(env!("CARGO_BIN_EXE_mc3b-emu"))
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .spawn()
            .expect("spawn mc3b-emu");
        let stdin = child.stdin.take().expect("stdin");
        let mut stdout = BufReader::new(child.stdout.take().expect("stdout"));
        let mut path = String::new();
        stdout.read_line(&mut path).expect("device path");
        let path = path.trim().to_string();
        assert!(path.starts_with("/dev/"), "path {path:?}");
        Emu {
            child,
            stdin,
            stdout,
            path,
            _watchdog: Watchdog::for_this_test(Duration::from_secs(60)),
        }
    }

    /// One control-channel command, one reply line.
    pub fn ctl(&mut self, cmd: &str) -> String {
        writeln!(self.stdin, "{cmd}").expect("write control");
        self.stdin.flush().expect("flush");
        let mut line = String::new();
        self.stdout.read_line(&mut line).expect("control reply");
        line.trim().to_string()
    }

    /// The step counters of motors 0..2 (`pos`).
    pub fn pos(&mut self) -> (i64, i64, i64) {
        let r = self.ctl("pos");
        let v: Vec<i64> = r
            .split_whitespace()
            .skip(1)
            .map(|w| w.parse().expect("number"))
            .collect();
        (v[0], v[1], v[2])
    }

    /// Ends the emulator now: its device side closes.
    pub fn kill(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Drop for Emu {
    fn drop(&mut self) {
        self.kill();
    }
}
