//! Generates and checks the C# and VB bindings of libMCCLPCI_IMP.
//!
//! The single source of truth is the pair of generated C headers `include/MCCL.h` and
//! `include/MCCL_Fun.h` (themselves generated from the Rust sources by `mccl-headers`).
//!
//! * `cargo run -p mccl-bindings` writes `csharp/MCCL.cs`, `vb-bindings/MCCLPCI_IMP.bas` and
//!   `vb-bindings/MCCL.vb`;
//! * `-- --check` regenerates in memory and fails if a committed file differs;
//! * `-- --verify <libMCCLPCI_IMP.so>` parses the three committed files independently of the
//!   generator and checks every declaration against the headers and the library's exports
//!   (see [`check`]).

mod check;
mod gen;
mod model;

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

fn read(path: &Path) -> Result<String, String> {
    std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))
}

/// Parses the generated headers under `root/include`.
fn load_header(root: &Path) -> Result<model::Header, String> {
    let a = root.join("include/MCCL.h");
    let b = root.join("include/MCCL_Fun.h");
    let (ta, tb) = (read(&a)?, read(&b)?);
    model::Header::parse(
        (&a.display().to_string(), &ta),
        (&b.display().to_string(), &tb),
    )
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

/// Exported, defined text symbols of a shared library (`nm -D --defined-only`).
fn exports(lib: &Path) -> Result<Vec<String>, String> {
    let out = Command::new("nm")
        .args(["-D", "--defined-only"])
        .arg(lib)
        .output()
        .map_err(|e| format!("nm: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "nm -D {}: {}",
            lib.display(),
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    Ok(String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter_map(|l| {
            let f: Vec<&str> = l.split_whitespace().collect();
            match f.as_slice() {
                [_, "T", name] => Some(name.to_string()),
                _ => None,
            }
        })
        .collect())
}

fn run() -> Result<bool, String> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let root = root.canonicalize().unwrap_or(root);
    let h = load_header(&root)?;
    match args.first().map(String::as_str) {
        None | Some("--check") => {
            let check = !args.is_empty();
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
        Some("--verify") => {
            let lib = args
                .get(1)
                .ok_or("usage: mccl-bindings --verify <libMCCLPCI_IMP.so>")?;
            let syms = exports(Path::new(lib))?;
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
        Some(a) => Err(format!(
            "unknown argument {a:?}; usage: mccl-bindings [--check | --verify <lib.so>]"
        )),
    }
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
