//! No cycle between the modules of any crate of the workspace: within each module, the
//! uses among its children form a directed acyclic graph (`support/module_graph.rs` says
//! how the uses are read). The top level of the library is also ranked in layers by
//! `module_layers`; this check covers every level of every crate.

#[path = "support/code.rs"]
mod code;
#[path = "support/module_graph.rs"]
mod module_graph;
#[path = "support/rust_files.rs"]
mod support;

use module_graph::{cycles, Crate};
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// The root file of every crate of the workspace.
fn crate_roots() -> Vec<PathBuf> {
    let top = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut roots = vec![top.join("src/lib.rs")];
    for group in ["tools", "crates"] {
        let Ok(dirs) = std::fs::read_dir(top.join(group)) else {
            continue;
        };
        for d in dirs.flatten() {
            for root in ["src/lib.rs", "src/main.rs"] {
                let p = d.path().join(root);
                if p.exists() {
                    roots.push(p);
                }
            }
        }
    }
    roots.sort();
    roots
}

/// Every cycle of every crate, as `crate-root: parent: [a, b, …]` with the edges that make it.
fn all_cycles() -> Vec<String> {
    let mut out = Vec::new();
    for root in crate_roots() {
        let krate = Crate::read(&root);
        for (parent, edges) in krate.sibling_edges() {
            let pairs: BTreeSet<(String, String)> = edges.keys().cloned().collect();
            for cycle in cycles(&pairs) {
                let within: Vec<String> = edges
                    .iter()
                    .filter(|((a, b), _)| cycle.contains(a) && cycle.contains(b))
                    .map(|((a, b), by)| {
                        format!(
                            "{a} -> {b} ({})",
                            by.iter().cloned().collect::<Vec<_>>().join(", ")
                        )
                    })
                    .collect();
                out.push(format!(
                    "{}: {}: {:?}\n    {}",
                    root.display(),
                    if parent.is_empty() {
                        "crate".to_string()
                    } else {
                        parent.join("::")
                    },
                    cycle,
                    within.join("\n    ")
                ));
            }
        }
    }
    out
}

#[test]
fn no_module_cycle_in_any_crate() {
    let found = all_cycles();
    assert!(found.is_empty(), "module cycles:\n{}", found.join("\n"));
}

#[test]
fn the_check_sees_a_cycle() {
    let edges: BTreeSet<(String, String)> = [("a", "b"), ("b", "c"), ("c", "a"), ("c", "d")]
        .iter()
        .map(|(x, y)| (x.to_string(), y.to_string()))
        .collect();
    assert_eq!(
        cycles(&edges),
        vec![vec!["a".to_string(), "b".into(), "c".into()]]
    );
}
