//! `mccl-trace plot|report|diff`: see what the machine did (see `--help`).

use lexopt::prelude::*;
use lexopt::{Arg, Parser};
use mccl_trace::{diff, plot, report};
use std::process::ExitCode;

const HELP: &str = "mccl-trace: look at an MCCL_TRACE file (and the .events.csv beside it)

usage:
  mccl-trace plot TRACE.csv -o OUT.svg|OUT.png [options]
  mccl-trace report TRACE.csv -o OUT.html [options]
  mccl-trace diff A.csv B.csv [--tol UU]

options of plot and report:
  --group N[,N...]   groups to show (default: every group in the trace)
  --plane xy|xz|yz|3d  the plane of the path (default xy; 3d: isometric view)
  --from MS --to MS  time window, ms of virtual time
  --axes x,y,z,...   axes in the time panels (default: those that move)
  --width PX         picture width (default 1400; 720 px of height per group)

diff compares positions per axis (UU) beyond --tol (default 0: any difference in the
printed digits), and times, groups, commands and statuses exactly. Exit status: 0 when
the traces agree, 1 when they differ, 2 on bad input.";

fn main() -> ExitCode {
    match run(lexopt::Parser::from_env()) {
        Ok(code) => ExitCode::from(code),
        Err(msg) => {
            eprintln!("mccl-trace: {msg}");
            ExitCode::from(2)
        }
    }
}

/// The value of option `flag` as text.
fn value(p: &mut Parser, flag: &str, missing: &str) -> Result<String, String> {
    p.value()
        .map_err(|_| missing.to_string())?
        .into_string()
        .map_err(|v| format!("{flag}: not text: {v:?}"))
}

/// The value of option `flag` as a finite number.
fn num(p: &mut Parser, flag: &str) -> Result<f64, String> {
    let v = value(p, flag, &format!("{flag} needs a value"))?;
    v.parse::<f64>()
        .ok()
        .filter(|x| x.is_finite())
        .ok_or_else(|| format!("{flag}: not a number: {v}"))
}

/// An option as the user wrote it, for messages.
fn spelled(arg: &Arg) -> String {
    match arg {
        Short(c) => format!("-{c}"),
        Long(s) => format!("--{s}"),
        Value(v) => v.to_string_lossy().into_owned(),
    }
}

fn run(mut p: Parser) -> Result<u8, String> {
    let cmd = match p.next().map_err(|e| e.to_string())? {
        None => return Err(format!("no command\n\n{HELP}")),
        Some(Short('h') | Long("help")) => {
            println!("{HELP}");
            return Ok(0);
        }
        Some(Value(v)) if v == "help" => {
            println!("{HELP}");
            return Ok(0);
        }
        Some(arg) => spelled(&arg),
    };
    let mut files = Vec::new();
    let mut out: Option<String> = None;
    let mut opts = plot::Options::default();
    let mut tol = 0.0;
    while let Some(arg) = p.next().map_err(|e| e.to_string())? {
        match arg {
            Short('h') | Long("help") => {
                println!("{HELP}");
                return Ok(0);
            }
            Short('o') | Long("output") => out = Some(value(&mut p, "-o", "-o needs a file name")?),
            Long("tol") => {
                tol = num(&mut p, "--tol")?;
                if tol < 0.0 {
                    return Err("--tol must not be negative".into());
                }
            }
            Long("group") => {
                let v = value(&mut p, "--group", "--group needs a value")?;
                let gs = v
                    .split(',')
                    .map(|g| {
                        g.parse::<u32>()
                            .map_err(|_| format!("--group: not a group: {g}"))
                    })
                    .collect::<Result<Vec<_>, _>>()?;
                opts.groups = Some(gs);
            }
            Long("plane") => {
                let v = value(&mut p, "--plane", "--plane needs a value")?;
                opts.plane = plot::Plane::parse(&v)
                    .ok_or_else(|| format!("--plane: {v} (xy, xz, yz or 3d)"))?;
            }
            Long("from") => opts.from = num(&mut p, "--from")?,
            Long("to") => opts.to = num(&mut p, "--to")?,
            Long("width") => {
                let w = num(&mut p, "--width")?;
                if !(600.0..=20000.0).contains(&w) {
                    return Err("--width: 600 to 20000".into());
                }
                opts.width = w as u32;
            }
            Long("axes") => {
                let v = value(&mut p, "--axes", "--axes needs a value")?;
                let ax = v
                    .split(',')
                    .map(|n| {
                        mccl_trace::data::AXIS_NAMES
                            .iter()
                            .position(|x| x.eq_ignore_ascii_case(n))
                            .ok_or_else(|| format!("--axes: not an axis: {n} (x y z u v w a b)"))
                    })
                    .collect::<Result<Vec<_>, _>>()?;
                opts.axes = Some(ax);
            }
            Value(v) => files.push(
                v.into_string()
                    .map_err(|v| format!("not a file name in text: {v:?}"))?,
            ),
            arg => return Err(format!("unknown option {}\n\n{HELP}", spelled(&arg))),
        }
    }
    if opts.from > opts.to {
        return Err("--from is after --to".into());
    }
    match cmd.as_str() {
        "plot" | "report" => {
            let [trace] = files.as_slice() else {
                return Err(format!("{cmd} takes one trace file\n\n{HELP}"));
            };
            let out = out.ok_or_else(|| format!("{cmd}: -o OUT is required"))?;
            if cmd == "report" {
                let h = report::html(trace, &opts)?;
                std::fs::write(&out, h).map_err(|e| format!("{out}: {e}"))?;
            } else if out.ends_with(".png") {
                plot::png(trace, &opts, &out)?;
            } else if out.ends_with(".svg") {
                let (s, _) = plot::svg(trace, &opts)?;
                std::fs::write(&out, s).map_err(|e| format!("{out}: {e}"))?;
            } else {
                return Err(format!("{out}: the output must end in .svg or .png"));
            }
            Ok(0)
        }
        "diff" => {
            let [a, b] = files.as_slice() else {
                return Err(format!("diff takes two trace files\n\n{HELP}"));
            };
            let r = diff::diff(a, b, tol)?;
            print!("{}", r.text);
            Ok(if r.agree { 0 } else { 1 })
        }
        _ => Err(format!("unknown command {cmd}\n\n{HELP}")),
    }
}
