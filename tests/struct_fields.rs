//! No struct of the engine (`src/engine`) or the core crate (`crates/core/src`: the
//! simulated machine, the card's peripherals, the planner) has more than [`MOST`] fields:
//! a type with more holds several concerns, each of which should be a part with its own
//! methods.

#[path = "support/code.rs"]
mod code;
#[path = "support/rust_files.rs"]
mod support;

use code::code_of;

use std::collections::BTreeMap;
use std::path::Path;

/// The most fields a struct may have.
const MOST: usize = 15;

/// Per struct name (braced structs only): its field count and file.
fn field_counts(dir: &Path, out: &mut BTreeMap<String, (String, usize)>) {
    for f in support::rust_files(dir) {
        if f.components().any(|c| c.as_os_str() == "tests") {
            continue;
        }
        let text = code_of(&std::fs::read_to_string(&f).expect("read a source file"));
        let mut current: Option<(String, String, usize)> = None;
        for line in text.lines() {
            let t = line.trim_start();
            let indent = line.len() - t.len();
            if current.is_none() {
                let rest = t
                    .split_once("struct ")
                    .filter(|(vis, _)| vis.is_empty() || vis.starts_with("pub"))
                    .map(|(_, r)| r);
                if let Some(rest) = rest.filter(|_| t.ends_with('{')) {
                    let name: String = rest
                        .chars()
                        .take_while(|c| c.is_alphanumeric() || *c == '_')
                        .collect();
                    let close = format!("{}}}", " ".repeat(indent));
                    current = Some((name, close, 0));
                }
                continue;
            }
            let Some((name, close, n)) = current.as_mut() else {
                continue;
            };
            if line == close.as_str() {
                let e = out
                    .entry(name.clone())
                    .or_insert_with(|| (f.display().to_string(), 0));
                e.1 = e.1.max(*n);
                current = None;
                continue;
            }
            // A field: `[vis] name: Type`, at the struct's first level of indentation.
            let field = t
                .strip_prefix("pub ")
                .or_else(|| {
                    t.split_once(") ")
                        .filter(|(v, _)| v.starts_with("pub("))
                        .map(|(_, r)| r)
                })
                .unwrap_or(t);
            if let Some((n_, _)) = field.split_once(':') {
                if !n_.is_empty()
                    && n_
                        .chars()
                        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
                    && indent == close.len() - 1 + 4
                {
                    *n += 1;
                }
            }
        }
    }
}

fn all_counts() -> BTreeMap<String, (String, usize)> {
    let top = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut counts = BTreeMap::new();
    field_counts(&top.join("src/engine"), &mut counts);
    field_counts(&top.join("crates/core/src"), &mut counts);
    counts
}

#[test]
fn no_struct_has_more_than_fifteen_fields() {
    let counts = all_counts();
    let over: Vec<String> = counts
        .iter()
        .filter(|(_, (_, c))| *c > MOST)
        .map(|(n, (f, c))| format!("{n} ({f}): {c} fields"))
        .collect();
    assert!(
        over.is_empty(),
        "structs over {MOST} fields (cut them into parts): {over:#?}"
    );
}

#[test]
fn the_counter_sees_the_known_structs() {
    // Shared has 13 fields (clock, tick length, machine, lock_wanted, peripherals, view,
    // and its seven parts); the counter must find them all, or the limit means nothing.
    let counts = all_counts();
    assert_eq!(counts.get("Shared").map(|(_, c)| *c), Some(13));
    // GroupState: status, error, homing, index, settings and nine parts; Channel: its six
    // parts (step, index, deferred steps, sensors, compensation, encoder), its spec, its
    // parameters and its two pulse limits.
    assert_eq!(counts.get("GroupState").map(|(_, c)| *c), Some(14));
    assert_eq!(counts.get("Channel").map(|(_, c)| *c), Some(10));
}
