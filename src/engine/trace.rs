//! `MCCL_TRACE=path.csv`: a CSV row per group per tick — virtual time, group, command
//! index, motion status, the 8 axis positions (UU, user coordinates) and the path speed.
//! Numbers are printed with fixed precision, so under the fast and stepped clocks the same
//! program writes the same file byte for byte.

use super::group::GroupState;
use std::fs::File;
use std::io::{BufWriter, Write};

/// An open trace file.
#[derive(Debug)]
pub struct Trace {
    out: BufWriter<File>,
    path: String,
    failed: bool,
}

impl Trace {
    /// Opens the file named by `MCCL_TRACE` (none when unset or empty).
    pub fn from_env() -> Result<Option<Trace>, String> {
        match std::env::var("MCCL_TRACE") {
            Ok(p) if !p.is_empty() => Trace::create(&p).map(Some),
            _ => Ok(None),
        }
    }

    /// Creates `path` and writes the header line.
    pub fn create(path: &str) -> Result<Trace, String> {
        let f = File::create(path).map_err(|e| format!("MCCL_TRACE={path}: {e}"))?;
        let mut t = Trace {
            out: BufWriter::new(f),
            path: path.to_string(),
            failed: false,
        };
        t.write("time_ms,group,command,status,x,y,z,u,v,w,a,b,speed\n");
        Ok(t)
    }

    fn write(&mut self, s: &str) {
        if self.failed {
            return;
        }
        if let Err(e) = self.out.write_all(s.as_bytes()) {
            eprintln!("MCCL: trace {} stopped: {e}", self.path);
            self.failed = true;
        }
    }

    /// One row for group `g` at virtual time `t_ns`.
    pub fn row(&mut self, t_ns: u128, g: &GroupState) {
        let s = g.snapshot();
        let mut line = format!(
            "{}.{:06},{},{},{}",
            t_ns / 1_000_000,
            t_ns % 1_000_000,
            g.index,
            s.cmd.nCommandIndex,
            s.status
        );
        for p in s.pos {
            line.push_str(&format!(",{:.9}", p));
        }
        line.push_str(&format!(",{:.9}\n", s.path_speed));
        self.write(&line);
    }

    /// Writes buffered rows out.
    pub fn flush(&mut self) {
        if !self.failed {
            let _ = self.out.flush();
        }
    }
}
