//! The crate's top-level modules form layers, and every reference goes down: a module may
//! use only modules of a lower layer (docs/architecture.md). A reference upwards would tie two
//! layers into a cycle, which this test rejects with the file that makes it.
//!
//! It reads `src/` and collects every `crate::<module>` path outside comments and tests.
//! The lowest layers, from `vendor` to `card`, are the core crate's modules
//! (`crates/core`), which the library re-exports under their names: the core cannot
//! name the library, so the compiler keeps them below; the order among them is the
//! core's own.

use std::collections::BTreeMap;
#[path = "support/code.rs"]
mod code;
#[path = "support/rust_files.rs"]
mod support;

use code::code_of;
use std::path::Path;
use support::rust_files;

/// The layers, bottom up. A module may use the modules listed before it.
const LAYERS: &[&str] = &[
    "platform",     // what differs between the operating systems
    "vendor",       // the vendor's typedefs, constants, structs, callback types
    "error",        // return codes
    "error_record", // the 0xF... error records
    "fault",        // fault injection for tests (compiled out)
    "interrupt",    // interrupt causes as data
    "clock",        // when ticks happen
    "config",       // what the program configures
    "sim",          // the simulated machine's configuration file
    "planner",      // pure trajectory planning
    "machine",      // the simulated machine
    "card",         // the card's peripherals
    "engine",       // the tick, the groups, routines
    // The MC3B protocol, device and backend: above the engine, whose groups reach its
    // executor only through the trait the engine defines (engine::group::external).
    "mc3b",
    "panel",  // the browser panel (MCCL_PANEL): reads snapshots, works the simulated machine
    "system", // init and close, wiring
    "ffi",    // the C entry points
];

fn rank(m: &str) -> Option<usize> {
    LAYERS.iter().position(|&l| l == m)
}

/// The top-level modules a piece of code names as `crate::<module>`.
fn uses(code: &str) -> Vec<String> {
    code.match_indices("crate::")
        .map(|(i, _)| {
            code[i + 7..]
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect()
        })
        .collect()
}

#[test]
fn every_module_uses_only_lower_layers() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let files = rust_files(&src);
    let mut upward: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut unknown = Vec::new();
    for f in &files {
        let rel = f.strip_prefix(&src).expect("under src/");
        let rel_s = rel.to_string_lossy().replace('\\', "/");
        let first = rel.components().next().expect("a path");
        let top = first
            .as_os_str()
            .to_string_lossy()
            .trim_end_matches(".rs")
            .to_string();
        let name = f
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let is_test = name.starts_with("tests") || rel_s.contains("/tests/");
        if top == "lib" || top == "bin" || is_test {
            continue;
        }
        let Some(from) = rank(&top) else {
            unknown.push(top);
            continue;
        };
        let text = std::fs::read_to_string(f).expect("read a source file");
        for m in uses(&code_of(&text)) {
            match rank(&m) {
                Some(to) if to > from => upward
                    .entry(format!("{top} -> {m}"))
                    .or_default()
                    .push(rel_s.clone()),
                Some(_) => {}
                None => unknown.push(m),
            }
        }
    }
    unknown.sort();
    unknown.dedup();
    assert!(
        unknown.is_empty(),
        "modules missing from LAYERS: {unknown:?}"
    );
    for files in upward.values_mut() {
        files.sort();
        files.dedup();
    }
    assert!(
        upward.is_empty(),
        "references up the layers (lower -> higher: files): {upward:#?}"
    );
}

#[test]
fn the_check_sees_an_upward_reference() {
    // A card file naming the engine must be caught.
    let code = code_of("use crate::engine::Shared;\n// crate::system in a comment\n");
    assert_eq!(uses(&code), vec!["engine".to_string()]);
    assert!(rank("engine") > rank("card"));
}
