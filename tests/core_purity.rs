//! The core crate (`crates/core`) is pure library code: it exports no symbol, reads no
//! environment variable, starts no thread and holds no global state, so that a caller owns
//! its time and its state (the C ABI crate at the repository's root does those things for
//! the library). Its unit tests (`tests.rs` files, `#[cfg(test)] mod tests`) may use the
//! environment (a temporary directory) and are not read.

#[path = "support/code.rs"]
mod code;
#[path = "support/rust_files.rs"]
mod support;

use code::code_of;

use std::path::Path;

/// What the core's code must not contain, with why.
const FORBIDDEN: &[(&str, &str)] = &[
    ("#[no_mangle]", "an exported symbol"),
    ("export_name", "an exported symbol"),
    ("std::env", "the environment"),
    ("env::var", "the environment"),
    ("thread::spawn", "a thread"),
    ("thread::Builder", "a thread"),
    ("thread_local!", "per-thread global state"),
    ("static mut", "global state"),
];

/// Types that make a `static` global mutable state.
const INTERIOR: &[&str] = &[
    "Mutex", "RwLock", "Atomic", "Cell", "OnceLock", "OnceCell", "Lazy", "Condvar",
];

/// What `code` contains that the core must not.
fn offences(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    for (pat, why) in FORBIDDEN {
        if code.contains(pat) {
            out.push(format!("{pat} ({why})"));
        }
    }
    for line in code.lines() {
        let l = line.trim_start();
        let is_static = l.starts_with("static ")
            || l.starts_with("pub static ")
            || l.starts_with("pub(crate) static ");
        if is_static && INTERIOR.iter().any(|t| l.contains(t)) {
            out.push(format!("{l} (a static with interior mutability)"));
        }
    }
    out
}

#[test]
fn the_core_exports_nothing_reads_no_environment_starts_no_thread_holds_no_global() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/core/src");
    let mut found = Vec::new();
    for f in support::rust_files(&src) {
        let rel = f
            .strip_prefix(&src)
            .expect("under the core")
            .display()
            .to_string();
        let name = f
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        if name.starts_with("tests") || rel.contains("/tests/") {
            continue;
        }
        let text = std::fs::read_to_string(&f).expect("read a source file");
        for o in offences(&code_of(&text)) {
            found.push(format!("{rel}: {o}"));
        }
    }
    assert!(found.is_empty(), "the core crate is not pure: {found:#?}");
}

#[test]
fn the_check_sees_each_kind() {
    let code = "#[no_mangle]\nfn f() { std::env::var(\"X\"); std::thread::spawn(|| ()); }\nstatic N: AtomicU32 = AtomicU32::new(0);\n";
    assert_eq!(offences(code).len(), 5, "{:?}", offences(code));
    assert!(offences("static TABLE: [u8; 2] = [1, 2];").is_empty());
}
