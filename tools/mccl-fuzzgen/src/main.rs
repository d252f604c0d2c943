//! mccl-fuzzgen: writes the dispatch table of the random-call fuzzer (`c-tests/fuzz/`)
//! from the prototypes of the headers the library exports.
//!
//! `mccl-fuzzgen OUT.c include/*.h` reads every header given, collects its typedefs
//! (integer aliases, structs, callback types) and its function prototypes, and writes a C
//! file with, for every function, a caller that draws each argument from a generator
//! chosen by the parameter's type (and, to reach deeper code more often, by its name:
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

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.len() < 2 {
        eprintln!("usage: mccl-fuzzgen OUT.c HEADER.h...");
        return ExitCode::from(2);
    }
    match run(&args[0], &args[1..]) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("mccl-fuzzgen: {e}");
            ExitCode::FAILURE
        }
    }
}
