//! `mccl-trace plot|report|diff`: see what the machine did (see `--help`).

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
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(code) => ExitCode::from(code),
        Err(msg) => {
            eprintln!("mccl-trace: {msg}");
            ExitCode::from(2)
        }
    }
}

fn num(flag: &str, v: Option<&String>) -> Result<f64, String> {
    let v = v.ok_or_else(|| format!("{flag} needs a value"))?;
    v.parse::<f64>()
        .ok()
        .filter(|x| x.is_finite())
        .ok_or_else(|| format!("{flag}: not a number: {v}"))
}

fn run(args: &[String]) -> Result<u8, String> {
    let Some(cmd) = args.first() else {
        return Err(format!("no command\n\n{HELP}"));
    };
    if cmd == "--help" || cmd == "-h" || cmd == "help" {
        println!("{HELP}");
        return Ok(0);
    }
    let mut files = Vec::new();
    let mut out: Option<String> = None;
    let mut opts = plot::Options::default();
    let mut tol = 0.0;
    let mut i = 1;
    while i < args.len() {
        let a = &args[i];
        let v = args.get(i + 1);
        match a.as_str() {
            "-o" | "--output" => {
                out = Some(v.ok_or("-o needs a file name")?.clone());
                i += 1;
            }
            "--tol" => {
                tol = num(a, v)?;
                if tol < 0.0 {
                    return Err("--tol must not be negative".into());
                }
                i += 1;
            }
            "--group" => {
                let v = v.ok_or("--group needs a value")?;
                let gs = v
                    .split(',')
                    .map(|g| {
                        g.parse::<u32>()
                            .map_err(|_| format!("--group: not a group: {g}"))
                    })
                    .collect::<Result<Vec<_>, _>>()?;
                opts.groups = Some(gs);
                i += 1;
            }
            "--plane" => {
                let v = v.ok_or("--plane needs a value")?;
                opts.plane = plot::Plane::parse(v)
                    .ok_or_else(|| format!("--plane: {v} (xy, xz, yz or 3d)"))?;
                i += 1;
            }
            "--from" => {
                opts.from = num(a, v)?;
                i += 1;
            }
            "--to" => {
                opts.to = num(a, v)?;
                i += 1;
            }
            "--width" => {
                let w = num(a, v)?;
                if !(600.0..=20000.0).contains(&w) {
                    return Err("--width: 600 to 20000".into());
                }
                opts.width = w as u32;
                i += 1;
            }
            "--axes" => {
                let v = v.ok_or("--axes needs a value")?;
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
                i += 1;
            }
            s if s.starts_with('-') => return Err(format!("unknown option {s}\n\n{HELP}")),
            _ => files.push(a.clone()),
        }
        i += 1;
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
