//! Every dependency a crate of the workspace declares is used by its code: a declared
//! crate that nothing names is built, audited and shipped for nothing.
//!
//! It reads each `Cargo.toml` of the workspace with `toml` and looks for the crate's
//! Rust name (its key with `-` as `_`, or a workspace crate's `[lib] name`) as a word in
//! that crate's Rust sources (`src/`, `tests/`, `benches/`, `build.rs`) outside comment
//! lines: a crate only mentioned in a comment is not used.

#[path = "support/rust_files.rs"]
mod support;

use std::path::Path;
use support::rust_files;

/// Whether `text` has `word` delimited by characters that cannot be part of a Rust path
/// segment.
fn has_word(text: &str, word: &str) -> bool {
    let ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    text.match_indices(word).any(|(i, _)| {
        let before = text[..i].chars().next_back();
        let after = text[i + word.len()..].chars().next();
        !before.is_some_and(ident) && !after.is_some_and(ident)
    })
}

/// The dependency tables of a manifest: `[dependencies]`, `[dev-dependencies]`,
/// `[build-dependencies]` and their `[target.'cfg(..)'.*]` forms.
fn dependency_tables(manifest: &toml::Table) -> Vec<&toml::Table> {
    let kinds = ["dependencies", "dev-dependencies", "build-dependencies"];
    let mut tables: Vec<&toml::Table> = kinds
        .iter()
        .filter_map(|k| manifest.get(*k).and_then(|v| v.as_table()))
        .collect();
    if let Some(targets) = manifest.get("target").and_then(|v| v.as_table()) {
        for t in targets.values().filter_map(|v| v.as_table()) {
            tables.extend(
                kinds
                    .iter()
                    .filter_map(|k| t.get(*k).and_then(|v| v.as_table())),
            );
        }
    }
    tables
}

/// The name a dependency has in Rust code: its key with `-` as `_` (the key is the name
/// the code uses, also when `package = ...` renames it), or its library's own name when
/// it is a workspace crate with a `[lib] name`.
fn rust_name(root: &Path, key: &str, spec: &toml::Value) -> String {
    if let Some(path) = spec.get("path").and_then(|p| p.as_str()) {
        let manifest = root.join(path).join("Cargo.toml");
        if let Ok(text) = std::fs::read_to_string(manifest) {
            let m: toml::Table = text.parse().expect("a dependency's Cargo.toml");
            if let Some(lib) = m
                .get("lib")
                .and_then(|l| l.get("name"))
                .and_then(|n| n.as_str())
            {
                return lib.to_string();
            }
        }
    }
    key.replace('-', "_")
}

#[test]
fn every_declared_dependency_is_used() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let top: toml::Table = std::fs::read_to_string(root.join("Cargo.toml"))
        .expect("Cargo.toml")
        .parse()
        .expect("Cargo.toml parses");
    let members: Vec<String> = top["workspace"]["members"]
        .as_array()
        .expect("workspace members")
        .iter()
        .map(|m| m.as_str().expect("a member path").to_string())
        .collect();
    assert!(members.len() > 1, "the workspace has its tools");
    let mut unused = Vec::new();
    let mut checked = 0;
    for member in &members {
        let dir = root.join(member);
        let manifest: toml::Table = std::fs::read_to_string(dir.join("Cargo.toml"))
            .expect("member Cargo.toml")
            .parse()
            .expect("member Cargo.toml parses");
        let mut files = Vec::new();
        for sub in ["src", "tests", "benches"] {
            // A crate without tests or benches has no such directory.
            if dir.join(sub).is_dir() {
                files.extend(rust_files(&dir.join(sub)));
            }
        }
        files.push(dir.join("build.rs"));
        let text: String = files
            .iter()
            .filter_map(|f| std::fs::read_to_string(f).ok())
            .flat_map(|t| {
                t.lines()
                    .filter(|l| !l.trim_start().starts_with("//"))
                    .map(str::to_string)
                    .collect::<Vec<_>>()
            })
            .collect::<Vec<_>>()
            .join("\n");
        for table in dependency_tables(&manifest) {
            for (key, spec) in table {
                let name = rust_name(&dir, key, spec);
                checked += 1;
                if !has_word(&text, &name) {
                    unused.push(format!("{member}: {key} (`{name}` appears nowhere)"));
                }
            }
        }
    }
    assert!(
        checked >= 10,
        "only {checked} dependencies found: the manifests moved?"
    );
    assert!(
        unused.is_empty(),
        "declared but not used:\n  {}",
        unused.join("\n  ")
    );
}

#[test]
fn the_word_test_finds_whole_names_only() {
    assert!(has_word("use toml::Table;", "toml"));
    assert!(!has_word("let tomlish = 1;", "toml"));
    assert!(!has_word("serde_json::to_string", "serde"));
    assert!(has_word("#[derive(serde::Serialize)]", "serde"));
}
