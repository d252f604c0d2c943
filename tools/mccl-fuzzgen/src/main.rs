//! mccl-fuzzgen: writes the dispatch table of the random-call fuzzer (`c-tests/fuzz/`)
//! from the prototypes of the headers the library exports.
//!
//! `mccl-fuzzgen OUT.c include/*.h` reads every header given into the one header model
//! (`mccl-header-model`: typedefs, structs, callback types, function prototypes), takes
//! its view of them (`view`), and writes a C file with, for every function, a caller that
//! draws each argument from a generator chosen by the parameter's type (and, to reach
//! deeper code more often, by its name:
//! `wGroupIndex` draws group indices, `cAxis` axis letters, ...), logs the call, makes it
//! and checks the result (canaries around every pointer argument, the vendor's
//! `RUN_TIME_ERR`). Callback parameters get a routine that counts its deliveries and calls
//! back into the library. A new export is covered without editing the fuzzer; a parameter
//! type the generator does not know fails the build, so nothing is skipped silently.

mod c;
mod gen;
mod hint;
#[cfg(test)]
mod tests;
mod view;

use mccl_header_model::Header;
use std::path::Path;
use std::process::ExitCode;

/// Reads the headers (those that define types others use first: `MCCL.h` before
/// `MCCL_Fun.h`), each named by its file name (the generated file includes it so).
fn read_headers(paths: &[String]) -> Result<Header, String> {
    let mut paths: Vec<&String> = paths.iter().collect();
    paths.sort_by_key(|h| !h.ends_with("/MCCL.h") && *h != "MCCL.h");
    let mut h = Header::default();
    for path in paths {
        let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
        let file = Path::new(path)
            .file_name()
            .and_then(|f| f.to_str())
            .unwrap_or(path);
        h.read(file, &text).map_err(|e| e.to_string())?;
    }
    Ok(h)
}

fn run(out: &str, headers: &[String]) -> Result<(), String> {
    let h = read_headers(headers)?;
    let m = view::Model::of(&h)?;
    let code = gen::gen(&m)?;
    std::fs::write(out, code).map_err(|e| format!("{out}: {e}"))?;
    eprintln!(
        "mccl-fuzzgen: {} functions, {} callback types, {} structs from {} headers",
        m.funcs.len(),
        m.callbacks.len(),
        m.structs.len(),
        m.headers.len()
    );
    Ok(())
}

const USAGE: &str = "usage: mccl-fuzzgen OUT.c HEADER.h...";

/// Reads the command line: the output and the headers, `None` for the usage.
fn args(mut p: lexopt::Parser) -> Result<Option<(String, Vec<String>)>, String> {
    use lexopt::prelude::*;
    let mut paths = Vec::new();
    while let Some(arg) = p.next().map_err(|e| e.to_string())? {
        match arg {
            Short('h') | Long("help") => return Ok(None),
            Value(v) => paths.push(v.string().map_err(|e| e.to_string())?),
            a => return Err(a.unexpected().to_string()),
        }
    }
    match paths.split_first() {
        Some((out, headers)) if !headers.is_empty() => Ok(Some((out.clone(), headers.to_vec()))),
        _ => Err("an output and at least one header".into()),
    }
}

fn main() -> ExitCode {
    let (out, headers) = match args(lexopt::Parser::from_env()) {
        Ok(Some(a)) => a,
        Ok(None) => {
            println!("{USAGE}");
            return ExitCode::SUCCESS;
        }
        Err(e) => {
            eprintln!("mccl-fuzzgen: {e}\n{USAGE}");
            return ExitCode::from(2);
        }
    };
    match run(&out, &headers) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("mccl-fuzzgen: {e}");
            ExitCode::FAILURE
        }
    }
}
