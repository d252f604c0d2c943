//! The modules of a crate and which sibling uses which, read from the sources as text,
//! for the test that keeps them acyclic (`module_cycles`).
//!
//! A module is a file (`a/b.rs` or `a/b/mod.rs` is `a::b`; `lib.rs`/`main.rs` is the
//! root). A reference is a path that starts with `crate::`, `super::` or `self::`, in
//! code or in a `use` tree, or a `use` of a child module by its bare name; it is resolved
//! to the deepest module it names, through the `use` lines of the modules on the way (so
//! `crate::engine::Shared`, re-exported by `engine` from `engine::shared`, names
//! `engine::shared`). A reference from module `A::x::…` to `A::y::…` is an edge `x -> y`
//! among the children of `A`; a module's references to its own ancestors or descendants
//! are not edges (a parent declares its children; a child may use what its parent
//! declares). Unit tests (`tests.rs`, files under a `tests/` folder, the part of a file
//! after `#[cfg(test)]\nmod tests {`) and comments are left out.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// A module path, from the crate root: `["engine", "group"]`.
pub type ModPath = Vec<String>;

/// The modules of one crate, their code and their `use` lines.
pub struct Crate {
    /// Each module's code, comments and unit tests left out.
    pub code: BTreeMap<ModPath, String>,
}

impl Crate {
    /// Reads the crate whose root file is `root` (`src/lib.rs`): every `.rs` file under
    /// its folder except binaries (`bin/`) and unit tests.
    pub fn read(root: &Path) -> Crate {
        let dir = root.parent().expect("a root file in a folder");
        let mut code = BTreeMap::new();
        for f in crate::support::rust_files(dir) {
            let rel = f.strip_prefix(dir).expect("under the folder");
            let parts: Vec<String> = rel
                .components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect();
            if parts.first().is_some_and(|p| p == "bin") {
                continue;
            }
            let file = parts.last().expect("a file name").clone();
            if file.starts_with("tests") || parts.iter().any(|p| p == "tests") {
                continue;
            }
            let mut path: ModPath = parts[..parts.len() - 1].to_vec();
            let stem = file.trim_end_matches(".rs");
            if f == root {
                path.clear();
            } else if stem != "mod" {
                path.push(stem.to_string());
            }
            let text = std::fs::read_to_string(&f).expect("read a source file");
            code.insert(path, crate::code::code_of(&text));
        }
        Crate { code }
    }

    /// The edges among siblings: for each parent module, `child -> child` with the file
    /// (module) that makes each.
    pub fn sibling_edges(&self) -> BTreeMap<ModPath, BTreeMap<(String, String), BTreeSet<String>>> {
        let mut out: BTreeMap<ModPath, BTreeMap<(String, String), BTreeSet<String>>> =
            BTreeMap::new();
        for (from, code) in &self.code {
            for target in self.references(from, code) {
                let common = from.iter().zip(&target).take_while(|(a, b)| a == b).count();
                if common == from.len() || common == target.len() {
                    continue;
                }
                out.entry(from[..common].to_vec())
                    .or_default()
                    .entry((from[common].clone(), target[common].clone()))
                    .or_default()
                    .insert(from.join("::"));
            }
        }
        out
    }

    /// The modules `code` (of module `from`) refers to.
    fn references(&self, from: &ModPath, code: &str) -> BTreeSet<ModPath> {
        let mut out = BTreeSet::new();
        for path in paths_in(code) {
            let Some(abs) = self.absolute(from, &path) else {
                continue;
            };
            out.insert(self.resolve(&abs, 0));
        }
        out
    }

    /// `path` (as written in module `from`) from the crate root, or `None` when it does
    /// not start at a module of this crate.
    fn absolute(&self, from: &ModPath, path: &[String]) -> Option<ModPath> {
        let mut base = match path.first().map(String::as_str) {
            Some("crate") => Vec::new(),
            Some("self") => from.clone(),
            Some("super") => from.clone(),
            Some(_) => {
                let mut child = from.clone();
                child.push(path[0].clone());
                if !self.code.contains_key(&child) {
                    return None;
                }
                return Some(path.iter().fold(from.clone(), |mut p, s| {
                    p.push(s.clone());
                    p
                }));
            }
            None => return None,
        };
        let mut rest = &path[1..];
        if path[0] == "super" {
            base.pop();
            while rest.first().is_some_and(|s| s == "super") {
                base.pop();
                rest = &rest[1..];
            }
        }
        base.extend(rest.iter().cloned());
        Some(base)
    }

    /// The deepest module `path` names, following `use` re-exports.
    fn resolve(&self, path: &[String], depth: usize) -> ModPath {
        let mut module: ModPath = Vec::new();
        for (i, seg) in path.iter().enumerate() {
            let mut next = module.clone();
            next.push(seg.clone());
            if self.code.contains_key(&next) {
                module = next;
                continue;
            }
            // A name the module brings in with `use`: follow it.
            if depth < 8 {
                if let Some(code) = self.code.get(&module) {
                    for used in use_paths(code) {
                        if used.last() == Some(seg) {
                            if let Some(abs) = self.absolute(&module, &used) {
                                let mut full = abs;
                                full.extend(path[i + 1..].iter().cloned());
                                return self.resolve(&full, depth + 1);
                            }
                        }
                    }
                }
            }
            break;
        }
        module
    }
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Every path of the code that starts with `crate::`, `super::` or `self::`, and every
/// path of its `use` trees.
fn paths_in(code: &str) -> Vec<Vec<String>> {
    let mut out = use_paths(code);
    for start in ["crate::", "super::", "self::"] {
        for (i, _) in code.match_indices(start) {
            if i > 0 && code[..i].ends_with(|c: char| is_ident(c) || c == ':') {
                continue;
            }
            let mut segs = Vec::new();
            let mut rest = &code[i..];
            loop {
                let n = rest.find(|c: char| !is_ident(c)).unwrap_or(rest.len());
                if n == 0 {
                    break;
                }
                segs.push(rest[..n].to_string());
                rest = &rest[n..];
                match rest.strip_prefix("::") {
                    Some(r) if r.starts_with(is_ident) => rest = r,
                    _ => break,
                }
            }
            out.push(segs);
        }
    }
    out
}

/// The leaf paths of every `use` tree of the code: `use a::{b, c::d};` gives `a::b` and
/// `a::c::d`.
fn use_paths(code: &str) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    for (i, _) in code.match_indices("use ") {
        if i > 0 && !code[..i].ends_with(|c: char| c.is_whitespace() || c == ')') {
            continue;
        }
        let Some(end) = code[i..].find(';') else {
            continue;
        };
        let tree: String = code[i + 4..i + end]
            .chars()
            .filter(|c| !c.is_whitespace())
            .collect();
        expand(&tree, &[], &mut out);
    }
    out
}

fn expand(tree: &str, prefix: &[String], out: &mut Vec<Vec<String>>) {
    let tree = tree.trim_start_matches("::");
    if let Some(open) = tree.find('{') {
        let mut base = prefix.to_vec();
        base.extend(
            tree[..open]
                .split("::")
                .filter(|s| !s.is_empty())
                .map(String::from),
        );
        let inner = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
        let mut depth = 0;
        let mut from = 0;
        for (j, c) in inner.char_indices() {
            match c {
                '{' => depth += 1,
                '}' => depth -= 1,
                ',' if depth == 0 => {
                    expand(&inner[from..j], &base, out);
                    from = j + 1;
                }
                _ => {}
            }
        }
        expand(&inner[from..], &base, out);
    } else {
        let item = tree.split(" as ").next().unwrap_or(tree);
        let item = item.split("as").next().unwrap_or(item);
        let mut p = prefix.to_vec();
        p.extend(
            item.split("::")
                .filter(|s| !s.is_empty() && *s != "*" && *s != "self")
                .map(String::from),
        );
        if !p.is_empty() {
            out.push(p);
        }
    }
}

/// The cycles of a directed graph: its strongly connected components of more than one
/// node, each sorted.
pub fn cycles(edges: &BTreeSet<(String, String)>) -> Vec<Vec<String>> {
    let nodes: BTreeSet<&String> = edges.iter().flat_map(|(a, b)| [a, b]).collect();
    let reach = |from: &String| {
        let mut seen = BTreeSet::from([from.clone()]);
        let mut todo = vec![from.clone()];
        while let Some(n) = todo.pop() {
            for (a, b) in edges {
                if *a == n && seen.insert(b.clone()) {
                    todo.push(b.clone());
                }
            }
        }
        seen
    };
    let reaches: BTreeMap<&String, BTreeSet<String>> =
        nodes.iter().map(|n| (*n, reach(n))).collect();
    let mut out: Vec<Vec<String>> = Vec::new();
    for n in &nodes {
        let scc: Vec<String> = nodes
            .iter()
            .filter(|m| reaches[n].contains(**m) && reaches[*m].contains(*n))
            .map(|m| (*m).clone())
            .collect();
        if scc.len() > 1 && !out.contains(&scc) {
            out.push(scc);
        }
    }
    out
}
