//! `mc3b-emu`: runs the MC3B emulator on a pseudo-terminal in real time.
//! See `--help` (the [`HELP`] text) for the control channel.

use std::io::{self, BufRead, Read, Write};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use mc3b::codec::CommandCode;
use mc3b::emulator::Emulator;
use mc3b::serial::pseudo_terminal_pair;
use serialport::SerialPort;

/// Usage and control-channel documentation.
const HELP: &str = "\
mc3b-emu: an RW Automation MC3B stepper controller emulated on a pseudo-terminal

USAGE: mc3b-emu [--help]

The emulator opens a pty pair and prints the device path of the slave side
(e.g. /dev/pts/7) as the FIRST line on stdout. (Windows has no pseudo-terminals:
there the emulator says so and exits with status 1.) Point a client at it, e.g.
MCL_COM1=/dev/pts/7 for mcl_initialize(1, ..). The serial side speaks the
MC3B ASCII command set (User's Guide section 6); the emulated device runs in
real time with its limit inputs sampled at 1 kHz.

CONTROL CHANNEL (stdin, one command per line; each gets one reply line on
stdout, starting with 'ok', 'err' or the command's name):
  input <bit 0-5> <0|1>          set one limit input to 0 V (0) or 5 V (1)
  inputs <byte>                  set all limit inputs at once (decimal)
  home <motor 0-2> <dir 0|1> <1|0>
                                 make that motor's configured home for that
                                 direction active (1) or inactive (0), by
                                 driving the lowest bit of its AND mask to the
                                 needed level (err if no home is configured)
  pos                            reply 'pos <p0> <p1> <p2>': step counters
                                 (direction 0 counts up)
  state                          reply 'state t_ms=<t> id=<id> running=<r0><r1><r2>
                                 raw=<inputs> debounced=<inputs>'
  velocity                       reply 'velocity <v0> <v1> <v2>': each motor's speed
                                 now, steps/s, one decimal, negative in
                                 direction 1 (a free run's on-the-fly changes)
  settings <motor 0-2>           reply 'settings v=<max velocity> a=<acc> d=<dec>
                                 half=<0|1> hold=<0|1> ih=<holding mA>
                                 ir=<running mA> masks=<h0a>,<h0x>,<h1a>,<h1x>
                                 modifier=<0|1> debounce=<count> chain=<stored>':
                                 what the device holds (V, A, D, F, C, K, L, N)
  received                       reply 'received I=<n> A=<n> ...': frames the
                                 device handled per command letter, all 18
  quit                           reply 'ok' and exit
The emulator exits when stdin reaches end of file (so it dies with the
process that spawned it); run it as `sleep infinity | mc3b-emu` to keep it
alive without a controller.
";

enum Control {
    Line(String),
    Eof,
}

fn control(emu: &mut Emulator, line: &str) -> (String, bool) {
    let words: Vec<&str> = line.split_whitespace().collect();
    let num = |i: usize| words.get(i).and_then(|w| w.parse::<u32>().ok());
    match words.first().copied() {
        None => ("err empty command".into(), false),
        Some("input") => match (num(1), num(2)) {
            (Some(bit), Some(level)) if bit < 6 && level < 2 => {
                emu.set_input(bit as u8, level == 1);
                ("ok".into(), false)
            }
            _ => ("err usage: input <bit 0-5> <0|1>".into(), false),
        },
        Some("inputs") => match num(1).and_then(|b| u8::try_from(b).ok()) {
            Some(b) => {
                emu.set_inputs(b);
                ("ok".into(), false)
            }
            None => ("err usage: inputs <byte>".into(), false),
        },
        Some("home") => match (num(1), num(2), num(3)) {
            (Some(m), Some(dir), Some(on)) if m < 3 && dir < 2 && on < 2 => {
                let masks = emu
                    .settings(m as usize)
                    .map(|s| s.limit_masks)
                    .unwrap_or([0; 4]);
                let (and, xor) = if dir == 0 {
                    (masks[0], masks[1])
                } else {
                    (masks[2], masks[3])
                };
                if and == 0 {
                    return ("err no home configured".into(), false);
                }
                let bit = and.trailing_zeros() as u8;
                let xor_bit = (xor >> bit) & 1 == 1;
                // Active when (level ^ xor_bit) is 1.
                let level = if on == 1 { !xor_bit } else { xor_bit };
                emu.set_input(bit, level);
                (format!("ok input {bit} {}", u8::from(level)), false)
            }
            _ => ("err usage: home <motor 0-2> <dir 0|1> <1|0>".into(), false),
        },
        Some("pos") => (
            format!(
                "pos {} {} {}",
                emu.position(0),
                emu.position(1),
                emu.position(2)
            ),
            false,
        ),
        Some("state") => (
            format!(
                "state t_ms={} id={} running={}{}{} raw={} debounced={}",
                emu.now().as_millis(),
                emu.id(),
                u8::from(emu.is_running(0)),
                u8::from(emu.is_running(1)),
                u8::from(emu.is_running(2)),
                emu.raw_inputs(),
                emu.inputs()
            ),
            false,
        ),
        Some("velocity") => (
            format!(
                "velocity {:.1} {:.1} {:.1}",
                emu.velocity(0),
                emu.velocity(1),
                emu.velocity(2)
            ),
            false,
        ),
        Some("settings") => match num(1).and_then(|m| emu.settings(m as usize)) {
            Some(s) => (
                format!(
                    "settings v={} a={} d={} half={} hold={} ih={} ir={} masks={},{},{},{} \
                     modifier={} debounce={} chain={}",
                    s.max_velocity,
                    s.acceleration,
                    s.deceleration,
                    u8::from(s.half_steps),
                    u8::from(s.use_holding_current),
                    s.holding_current,
                    s.running_current,
                    s.limit_masks[0],
                    s.limit_masks[1],
                    s.limit_masks[2],
                    s.limit_masks[3],
                    u8::from(s.direction_modifier),
                    emu.debounce_count(),
                    emu.chain_len()
                ),
                false,
            ),
            None => ("err usage: settings <motor 0-2>".into(), false),
        },
        Some("received") => {
            let counts: Vec<String> = CommandCode::ALL
                .iter()
                .map(|&c| format!("{}={}", char::from(c.letter()), emu.received(c)))
                .collect();
            (format!("received {}", counts.join(" ")), false)
        }
        Some("quit") => ("ok".into(), true),
        Some(other) => (format!("err unknown command '{other}'"), false),
    }
}

fn run() -> io::Result<()> {
    let (mut master, slave) = pseudo_terminal_pair()?;
    let path = slave
        .name()
        .ok_or_else(|| io::Error::other("pty has no name"))?;
    let mut out = io::stdout();
    writeln!(out, "{path}")?;
    out.flush()?;

    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let stdin = io::stdin();
        for line in stdin.lock().lines() {
            match line {
                Ok(l) => {
                    if tx.send(Control::Line(l)).is_err() {
                        return;
                    }
                }
                Err(_) => break,
            }
        }
        let _ = tx.send(Control::Eof);
    });

    // A read returns as soon as a frame's bytes arrive; the timeout only bounds how
    // long control commands wait while the line is quiet (the device's clock catches
    // up with real time at every wake). 10 ms rather than 1 ms: a tenth of the
    // wake-ups of an idle emulator on a shared host.
    master
        .set_timeout(Duration::from_millis(10))
        .map_err(io::Error::from)?;
    let mut emu = Emulator::new();
    let mut last = Instant::now();
    let mut buf = [0u8; 512];
    // The slave end stays open here so the master never sees a hang-up
    // while no client has the device open.
    let _slave = slave;
    loop {
        let n = match master.read(&mut buf) {
            Ok(n) => n,
            Err(e)
                if matches!(
                    e.kind(),
                    io::ErrorKind::TimedOut
                        | io::ErrorKind::Interrupted
                        | io::ErrorKind::WouldBlock
                ) =>
            {
                0
            }
            Err(_) => {
                std::thread::sleep(Duration::from_millis(1));
                0
            }
        };
        let now = Instant::now();
        emu.advance(now - last);
        last = now;
        if n > 0 {
            let reply = emu.receive(buf.get(..n).unwrap_or(&[]));
            if !reply.is_empty() {
                // A client that went away must not stop the emulator.
                let _ = master.write_all(&reply).and_then(|_| master.flush());
            }
        }
        while let Ok(msg) = rx.try_recv() {
            match msg {
                Control::Line(l) => {
                    let (reply, quit) = control(&mut emu, &l);
                    writeln!(out, "{reply}")?;
                    out.flush()?;
                    if quit {
                        return Ok(());
                    }
                }
                Control::Eof => return Ok(()),
            }
        }
    }
}

fn main() {
    if std::env::args().skip(1).any(|a| a == "--help" || a == "-h") {
        print!("{HELP}");
        return;
    }
    if let Some(a) = std::env::args().nth(1) {
        eprintln!("mc3b-emu: unknown argument '{a}' (see --help)");
        std::process::exit(2);
    }
    if let Err(e) = run() {
        eprintln!("mc3b-emu: {e}");
        std::process::exit(1);
    }
}
