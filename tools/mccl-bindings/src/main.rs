//! Generates and checks the C# and VB bindings of libMCCLPCI_IMP.
//!
//! The single source of truth is the pair of generated C headers `include/MCCL.h` and
//! `include/MCCL_Fun.h` (themselves generated from the Rust sources by `mccl-headers`).
//!
//! * `cargo run -p mccl-bindings` writes `csharp/MCCL.cs`, `vb-bindings/MCCLPCI_IMP.bas` and
//!   `vb-bindings/MCCL.vb`;
//! * `-- --check` regenerates in memory and fails if a committed file differs;
//! * `-- --verify <libMCCLPCI_IMP.so | MCCLPCI_IMP.dll>` parses the three committed files
//!   independently of the generator and checks every declaration against the headers and
//!   the library's exports (see [`check`]); for a Windows DLL, the names of its export
//!   table;
//! * `-- --exports <libMCCLPCI_IMP.so | MCCLPCI_IMP.dll>` checks that the four generated
//!   headers declare exactly the functions the library exports (see [`export_check`]).

mod check;
mod export_check;
mod exports;
mod gen;

use mccl_header_model as model;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

fn read(path: &Path) -> Result<String, String> {
    std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))
}

/// Parses the generated headers under `root/include`.
fn load_header(root: &Path) -> Result<model::Header, String> {
    let a = root.join("include/MCCL.h");
    let b = root.join("include/MCCL_Fun.h");
    let (ta, tb) = (read(&a)?, read(&b)?);
    model::Header::parse(&[
        (&a.display().to_string(), &ta),
        (&b.display().to_string(), &tb),
    ])
    .map_err(|e| e.to_string())
}

/// The three bindings with the paths they belong at.
fn generate(root: &Path, h: &model::Header) -> Result<Vec<(PathBuf, String)>, String> {
    Ok(vec![
        (root.join("csharp/MCCL.cs"), gen::csharp(h)?),
        (root.join("vb-bindings/MCCLPCI_IMP.bas"), gen::vb6(h)?),
        (root.join("vb-bindings/MCCL.vb"), gen::vbnet(h)?),
    ])
}

const USAGE: &str = "usage: mccl-bindings [--check | --verify <libMCCLPCI_IMP.so | MCCLPCI_IMP.dll> | --exports <libMCCLPCI_IMP.so | MCCLPCI_IMP.dll>]";

/// What the command line asks for.
#[derive(Debug, PartialEq)]
enum Mode {
    /// Write the bindings.
    Write,
    /// Compare them with what would be written.
    Check,
    /// Check the committed files against the headers and this library's exports.
    Verify(PathBuf),
    /// Check that the headers declare exactly what this library exports.
    Exports(PathBuf),
    /// Print the usage.
    Help,
}

/// Reads the command line.
fn mode(mut p: lexopt::Parser) -> Result<Mode, String> {
    use lexopt::prelude::*;
    let mut mode = Mode::Write;
    while let Some(arg) = p.next().map_err(|e| e.to_string())? {
        let next = match arg {
            Short('h') | Long("help") => return Ok(Mode::Help),
            Long("check") => Mode::Check,
            Long("verify") => Mode::Verify(
                p.value()
                    .map_err(|_| {
                        "usage: mccl-bindings --verify <libMCCLPCI_IMP.so | MCCLPCI_IMP.dll>"
                    })?
                    .into(),
            ),
            Long("exports") => Mode::Exports(
                p.value()
                    .map_err(|_| {
                        "usage: mccl-bindings --exports <libMCCLPCI_IMP.so | MCCLPCI_IMP.dll>"
                    })?
                    .into(),
            ),
            a => {
                let a = match a {
                    Short(c) => format!("-{c}"),
                    Long(l) => format!("--{l}"),
                    Value(v) => v.to_string_lossy().into_owned(),
                };
                return Err(format!(
                    "unknown argument {a:?}; usage: mccl-bindings [--check | --verify <lib> | --exports <lib>]"
                ));
            }
        };
        if mode != Mode::Write {
            return Err(format!("one of --check, --verify and --exports\n{USAGE}"));
        }
        mode = next;
    }
    Ok(mode)
}

fn run() -> Result<bool, String> {
    let mode = mode(lexopt::Parser::from_env())?;
    if mode == Mode::Help {
        println!("{USAGE}\n\nWrites csharp/MCCL.cs, vb-bindings/MCCLPCI_IMP.bas and vb-bindings/MCCL.vb from\ninclude/MCCL.h and include/MCCL_Fun.h; --check fails if a committed file differs;\n--verify checks the committed files against the headers and the library's exports;\n--exports checks that MCCL.h, MCCL_Fun.h, mcl.h and MCCL_Sim.h declare exactly the\nfunctions the library exports, under undecorated names.");
        return Ok(true);
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let root = root.canonicalize().unwrap_or(root);
    if let Mode::Exports(lib) = &mode {
        return check_exports(&root, lib);
    }
    let h = load_header(&root)?;
    match mode {
        Mode::Write | Mode::Check | Mode::Help => {
            let check = mode == Mode::Check;
            let mut ok = true;
            for (path, text) in generate(&root, &h)? {
                let old = std::fs::read_to_string(&path).unwrap_or_default();
                if old == text {
                    continue;
                }
                if check {
                    eprintln!(
                        "mccl-bindings: {} is out of date; run `cargo run -p mccl-bindings` and commit it",
                        path.display()
                    );
                    ok = false;
                } else {
                    if let Some(dir) = path.parent() {
                        std::fs::create_dir_all(dir)
                            .map_err(|e| format!("{}: {e}", dir.display()))?;
                    }
                    std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
                    println!("wrote {}", path.display());
                }
            }
            if check && ok {
                println!("mccl-bindings: MCCL.cs, MCCLPCI_IMP.bas and MCCL.vb are up to date");
            }
            Ok(ok)
        }
        Mode::Exports(_) => unreachable!("checked above"),
        Mode::Verify(lib) => {
            let syms = exports::exports(&lib)?;
            let files = [
                (check::Lang::CSharp, root.join("csharp/MCCL.cs")),
                (check::Lang::Vb6, root.join("vb-bindings/MCCLPCI_IMP.bas")),
                (check::Lang::VbNet, root.join("vb-bindings/MCCL.vb")),
            ];
            let mut total = 0;
            for (lang, path) in files {
                let text = read(&path)?;
                let name = path.display().to_string();
                let rep = check::verify(lang, &name, &text, &h, &syms);
                for p in &rep.problems {
                    eprintln!("{p}");
                }
                println!("{name}: {}", rep.summary());
                total += rep.problems.len();
            }
            if total > 0 {
                eprintln!("mccl-bindings --verify: {total} problem(s)");
            }
            Ok(total == 0)
        }
    }
}

/// `--exports`: the functions the four generated headers declare against `lib`'s exports.
fn check_exports(root: &Path, lib: &Path) -> Result<bool, String> {
    let names = ["MCCL.h", "MCCL_Fun.h", "mcl.h", "MCCL_Sim.h"];
    let paths: Vec<PathBuf> = names.iter().map(|n| root.join("include").join(n)).collect();
    let texts = paths
        .iter()
        .map(|p| read(p))
        .collect::<Result<Vec<_>, _>>()?;
    let shown: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
    let files: Vec<(&str, &str)> = shown
        .iter()
        .zip(&texts)
        .map(|(n, t)| (n.as_str(), t.as_str()))
        .collect();
    let h = model::Header::parse(&files).map_err(|e| e.to_string())?;
    let exported = exports::exports(lib)?;
    let r = export_check::compare(
        h.funcs.iter().map(|f| f.name.as_str()),
        exported.iter().map(String::as_str),
    );
    for p in r.problems() {
        eprintln!("{p}");
    }
    let name = lib.file_name().map_or(lib.display().to_string(), |n| {
        n.to_string_lossy().into_owned()
    });
    println!(
        "exports of {name}: {} MCC_*/mcl_*/MCCL_Sim* functions exported and declared",
        r.matched
    );
    Ok(r.problems().is_empty())
}

fn main() -> ExitCode {
    match run() {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(e) => {
            eprintln!("mccl-bindings: {e}");
            ExitCode::FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_command_line() {
        let m = |args: &[&str]| mode(lexopt::Parser::from_args(args));
        assert_eq!(m(&[]), Ok(Mode::Write));
        assert_eq!(m(&["--check"]), Ok(Mode::Check));
        assert_eq!(m(&["--verify", "x.so"]), Ok(Mode::Verify("x.so".into())));
        assert_eq!(m(&["--verify=x.dll"]), Ok(Mode::Verify("x.dll".into())));
        assert_eq!(m(&["-h"]), Ok(Mode::Help));
        assert!(m(&["--verify"])
            .unwrap_err()
            .starts_with("usage: mccl-bindings --verify"));
        assert!(m(&["--frob"])
            .unwrap_err()
            .starts_with("unknown argument \"--frob\""));
        assert!(m(&["x.so"])
            .unwrap_err()
            .starts_with("unknown argument \"x.so\""));
        assert!(m(&["--check", "--verify", "x.so"]).is_err());
        assert_eq!(
            m(&["--exports", "x.dll"]),
            Ok(Mode::Exports("x.dll".into()))
        );
        assert!(m(&["--exports"])
            .unwrap_err()
            .starts_with("usage: mccl-bindings --exports"));
    }
}
