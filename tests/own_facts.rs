//! The repository carries its own facts: no tracked file may send a reader to reference
//! documents that are not in it (the specification files kept beside the project while it
//! was written, or any path under a sibling `shared` directory). The facts live in
//! `docs/vendor-interface.md` and `docs/decisions.md`; cite those instead.

use std::path::Path;
use std::process::Command;

/// The forbidden mentions, assembled from pieces so that this file does not match itself.
/// Matched case-sensitively: `docs/vendor-interface.md` is allowed.
fn forbidden() -> Vec<String> {
    let md = ".md";
    vec![
        format!("{}{md}", "DECISIONS"),
        format!("{}{md}", "INTERFACE"),
        format!("{}/{}/", "..", "shared"),
        format!("/{}/{}/", "work", "shared"),
    ]
}

/// Every tracked file, relative to the repository root (`git ls-files`), or `None` when
/// this is not a git checkout (a source archive): then there is nothing to check against.
fn tracked_files(root: &Path) -> Option<Vec<String>> {
    let out = Command::new("git")
        .arg("-C")
        .arg(root)
        .args(["ls-files", "-z"])
        .output()
        .ok()?;
    if !out.status.success() {
        return None;
    }
    let list = String::from_utf8_lossy(&out.stdout).into_owned();
    Some(
        list.split('\0')
            .filter(|s| !s.is_empty())
            .map(str::to_string)
            .collect(),
    )
}

/// The `(line number, line)` of every line of `text` that contains one of `needles`.
fn offending_lines<'a>(text: &'a str, needles: &[String]) -> Vec<(usize, &'a str)> {
    text.lines()
        .enumerate()
        .filter(|(_, l)| needles.iter().any(|n| l.contains(n.as_str())))
        .map(|(i, l)| (i + 1, l))
        .collect()
}

#[test]
fn the_needles_are_what_they_should_be() {
    // Hand-written expectations, so a mistake in `forbidden` cannot make the check empty.
    let f = forbidden();
    // Written in pieces: this file is tracked, so it must not hold a whole mention itself.
    let sample = [
        "see DECISIONS",
        ".md\nINTERFACE",
        ".md §2\nread ..",
        "/shared/spec/x\n/work",
        "/shared/seeds\n",
        "docs/decisions.md and docs/vendor-interface.md are ours\nshared library\n",
    ]
    .concat();
    let hits: Vec<usize> = offending_lines(&sample, &f).iter().map(|h| h.0).collect();
    assert_eq!(hits, vec![1, 2, 3, 4]);
}

#[test]
fn no_tracked_file_cites_documents_outside_the_repository() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let Some(files) = tracked_files(root) else {
        eprintln!("not a git checkout: nothing to check");
        return;
    };
    assert!(
        files.iter().any(|f| f == "README.md"),
        "git ls-files did not list README.md: {} files",
        files.len()
    );
    let needles = forbidden();
    let mut found = Vec::new();
    for f in &files {
        // A tracked file may be missing from the work tree (deleted, not yet committed).
        let Ok(bytes) = std::fs::read(root.join(f)) else {
            continue;
        };
        let text = String::from_utf8_lossy(&bytes);
        for (n, line) in offending_lines(&text, &needles) {
            found.push(format!("{f}:{n}: {}", line.trim()));
        }
    }
    assert!(
        found.is_empty(),
        "these lines cite files that are not in the repository; cite docs/decisions.md or \
         docs/vendor-interface.md (or state the fact) instead:\n{}",
        found.join("\n")
    );
}
