//! Every exported function of `src/ffi` (`extern "system"`, the vendor's calling
//! convention, or `extern "C"`) enters the panic boundary: its body
//! is exactly one `ffi_boundary! { ... }` (src/ffi/mod.rs), so no panic can cross the C
//! boundary and every error maps to a vendor code the same way (the MC3B library's
//! `mcl_*` functions to their §4 status, `ffi_boundary! { @mcl ... }`). A body that calls a
//! helper which enters the boundary somewhere else is refused too: the boundary must be
//! visible where the function is exported.
//!
//! Every exported function is written out in src/ffi (tests/exports_findable.rs), so the
//! scan, which reads src/ffi and its subfolders, sees each one and accounts for every
//! vendor function: 345 `MCC_*` names (docs/functions.md).

#[path = "support/rust_files.rs"]
mod support;

use std::path::Path;
use support::rust_files;

/// Index of the bracket that closes the one at `open`, skipping comments, strings and
/// character literals.
fn matching(s: &[u8], open: usize) -> Option<usize> {
    let mut depth = 0usize;
    let mut i = open;
    while i < s.len() {
        match s[i] {
            b'/' if s.get(i + 1) == Some(&b'/') => {
                while i < s.len() && s[i] != b'\n' {
                    i += 1;
                }
                continue;
            }
            b'"' => {
                i += 1;
                while i < s.len() && s[i] != b'"' {
                    if s[i] == b'\\' {
                        i += 1;
                    }
                    i += 1;
                }
            }
            // A character literal ('x', '\n'); a lifetime ('a) has no closing quote.
            b'\'' if s.get(i + 2) == Some(&b'\'') => i += 2,
            b'\'' if s.get(i + 1) == Some(&b'\\') && s.get(i + 3) == Some(&b'\'') => i += 3,
            b'(' | b'{' | b'[' => depth += 1,
            b')' | b'}' | b']' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i);
                }
            }
            _ => {}
        }
        i += 1;
    }
    None
}

/// How an exported function begins, for each calling convention the library exports.
const EXTERN_FNS: [&str; 2] = ["extern \"system\" fn ", "extern \"C\" fn "];

/// Where the first exported-function keywords ([`EXTERN_FNS`]) of `s` are, and their
/// length.
fn find_extern_fn(s: &str) -> Option<(usize, usize)> {
    EXTERN_FNS
        .iter()
        .filter_map(|k| s.find(k).map(|at| (at, k.len())))
        .min()
}

/// The next `extern "..." fn` at or after byte `from` of `src`: the byte after its
/// `fn `, and its name.
fn next_extern_fn(src: &str, from: usize) -> Option<(usize, String)> {
    let (at, len) = find_extern_fn(&src[from..])?;
    let start = from + at + len;
    let name = src[start..]
        .chars()
        .take_while(|c| c.is_alphanumeric() || *c == '_')
        .collect();
    Some((start, name))
}

/// The names of the exported functions of one file whose body is not one boundary.
fn offenders(src: &str) -> (usize, Vec<String>) {
    let b = src.as_bytes();
    let mut found = 0;
    let mut bad = Vec::new();
    let mut from = 0;
    while let Some((start, name)) = next_extern_fn(src, from) {
        // The parameter list, then the body's opening brace.
        let params = start + src[start..].find('(').expect("a parameter list");
        let close = matching(b, params).expect("a closed parameter list");
        let open = close + src[close..].find('{').expect("a body");
        let end = matching(b, open).expect("a closed body");
        found += 1;
        let body = src[open + 1..end].trim();
        let whole = body
            .strip_prefix("ffi_boundary!")
            .map(str::trim_start)
            .and_then(|rest| {
                let off = body.len() - rest.len();
                let rb = body.as_bytes();
                (rest.starts_with('{') || rest.starts_with('('))
                    .then(|| matching(rb, off))
                    .flatten()
                    .map(|e| e == rb.len() - 1)
            });
        if whole != Some(true) {
            bad.push(name);
        }
        from = end;
    }
    (found, bad)
}

/// The names of the functions a file exports (`extern "system" fn MCC_X`, `extern "C" fn
/// mcl_x`).
fn exported_names(src: &str) -> Vec<String> {
    let mut names = Vec::new();
    let mut from = 0;
    while let Some((start, name)) = next_extern_fn(src, from) {
        names.push(name);
        from = start;
    }
    names
}

#[test]
fn every_exported_body_is_one_ffi_boundary() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/ffi");
    let mut total = 0;
    let mut bad = Vec::new();
    let mut sources = Vec::new();
    // Its subfolders too: a chapter split into files (`motion.rs` and `motion/`).
    for path in rust_files(&dir) {
        let file = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
        if file.starts_with("tests") {
            continue;
        }
        let name = path.strip_prefix(&dir).expect("under src/ffi").display();
        let src = std::fs::read_to_string(&path).expect("a readable source file");
        sources.push((name.to_string(), src));
    }
    let mut names = Vec::new();
    for (file, src) in &sources {
        let (n, b) = offenders(src);
        total += n;
        names.extend(exported_names(src));
        bad.extend(b.into_iter().map(|f| format!("{file}: {f}")));
    }
    // Every vendor function (344 and MCC_SetLIORoutineEx, docs/functions.md) once; a
    // lower count means the scan missed some and would pass without looking.
    names.sort();
    let vendor: Vec<&String> = names.iter().filter(|n| n.starts_with("MCC_")).collect();
    let mut unique = vendor.clone();
    unique.dedup();
    assert_eq!(
        unique.len(),
        vendor.len(),
        "a name exported twice: {vendor:?}"
    );
    assert_eq!(
        vendor.len(),
        345,
        "found {} exported MCC_ functions in src/ffi",
        vendor.len()
    );
    // The MC3B library's 19 `mcl_*` functions (MC3B User's Guide §4) go through the same
    // boundary (`ffi_boundary! { @mcl ... }`, src/ffi/mcl.rs).
    let mcl = names.iter().filter(|n| n.starts_with("mcl_")).count();
    assert_eq!(mcl, 19, "found {mcl} exported mcl_ functions in src/ffi");
    assert!(total > 0);
    assert!(
        bad.is_empty(),
        "{} exported bodies are not one `ffi_boundary! {{ ... }}`:\n{}",
        bad.len(),
        bad.join("\n")
    );
}

#[test]
fn the_scan_refuses_a_body_outside_the_boundary() {
    let ok = "pub extern \"C\" fn A(x: u16) -> c_int { ffi_boundary! { f(x, '{') } }";
    let helper = "pub extern \"C\" fn B(x: u16) -> c_int { helper(x) }";
    let after = "pub extern \"C\" fn C() -> c_int { ffi_boundary! { f() }; g() }";
    let stdcall = "pub extern \"system\" fn D() -> c_int { helper() }";
    assert_eq!(offenders(stdcall), (1, vec!["D".to_string()]));
    assert_eq!(offenders(ok), (1, vec![]));
    assert_eq!(offenders(helper), (1, vec!["B".to_string()]));
    assert_eq!(offenders(after), (1, vec!["C".to_string()]));
}
