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

/// The relative links of a markdown text, `(line number, target)`: the `(...)` after
/// every `](`, outside fenced code blocks and inline code. Links to a scheme
/// (`https:`, `mailto:`) are left out: they do not point into the repository.
fn relative_links(text: &str) -> Vec<(usize, String)> {
    let mut links = Vec::new();
    let mut fenced = false;
    for (i, line) in text.lines().enumerate() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            continue;
        }
        // Inline code spans are the odd-numbered pieces between backticks.
        for (k, piece) in line.split('`').enumerate() {
            if k % 2 == 1 {
                continue;
            }
            let mut rest = piece;
            while let Some(at) = rest.find("](") {
                let after = &rest[at + 2..];
                let Some(end) = after.find(')') else { break };
                let target = &after[..end];
                if !target.contains(':') {
                    links.push((i + 1, target.to_string()));
                }
                rest = &after[end..];
            }
        }
    }
    links
}

/// The anchors GitHub gives the headings of a markdown text: lower case, spaces become
/// `-`, everything but letters, digits, `-` and `_` dropped; a repeated anchor gets `-1`,
/// `-2`, ... Headings inside fenced code blocks are not headings.
fn anchors(text: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        let title = line.trim_start_matches('#');
        if fenced || title.len() == line.len() || !title.starts_with(' ') {
            continue;
        }
        let slug: String = title
            .trim()
            .to_lowercase()
            .chars()
            .filter_map(|c| match c {
                ' ' => Some('-'),
                c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
                _ => None,
            })
            .collect();
        let seen = out
            .iter()
            .filter(|a| {
                **a == slug
                    || a.strip_prefix(&format!("{slug}-"))
                        .is_some_and(|n| n.parse::<u32>().is_ok())
            })
            .count();
        out.push(if seen == 0 {
            slug
        } else {
            format!("{slug}-{seen}")
        });
    }
    out
}

#[test]
fn links_and_anchors_are_read_as_github_does() {
    // Hand-written: what each line should give.
    let doc = "# Tracing: `MCCL_TRACE`\n\
               see [a](b.md) and [c](b.md#x-y), [web](https://e.org), `[no](code.md)`\n\
               ```\n[no](fenced.md)\n# not a heading\n```\n\
               ## An MC3B as a card\n## Ranges\n### Ranges\n#hashtag\n[self](#ranges-1)\n";
    assert_eq!(
        relative_links(doc),
        vec![
            (2, "b.md".to_string()),
            (2, "b.md#x-y".to_string()),
            (11, "#ranges-1".to_string())
        ]
    );
    assert_eq!(
        anchors(doc),
        vec![
            "tracing-mccl_trace",
            "an-mc3b-as-a-card",
            "ranges",
            "ranges-1"
        ]
    );
}

/// Every relative link of README.md and docs/*.md points to a file of the repository,
/// and a link to a heading (`file.md#anchor`, `#anchor`) to a heading that exists; and
/// README.md's index links every file of docs/ that is markdown.
#[test]
fn the_documentation_links_resolve() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut docs: Vec<String> = std::fs::read_dir(root.join("docs"))
        .expect("docs/ is readable")
        .filter_map(|e| e.ok())
        .map(|e| format!("docs/{}", e.file_name().to_string_lossy()))
        .filter(|f| f.ends_with(".md"))
        .collect();
    docs.sort();
    assert!(docs.len() >= 2, "docs/ has no markdown files: {docs:?}");
    let readme = std::fs::read_to_string(root.join("README.md")).expect("README.md");
    let mut broken = Vec::new();
    for doc in &docs {
        if !relative_links(&readme).iter().any(|(_, t)| t == doc) {
            broken.push(format!("README.md does not link {doc} in its index"));
        }
    }
    for file in std::iter::once("README.md".to_string()).chain(docs.iter().cloned()) {
        let path = root.join(&file);
        let text = std::fs::read_to_string(&path).expect("a markdown file");
        let dir = path.parent().expect("a file has a directory");
        for (n, target) in relative_links(&text) {
            let (to, anchor) = target.split_once('#').unwrap_or((&target, ""));
            let to_path = if to.is_empty() {
                path.clone()
            } else {
                dir.join(to)
            };
            if !to_path.exists() {
                broken.push(format!("{file}:{n}: {target}: no such file"));
                continue;
            }
            if !anchor.is_empty() {
                let headings = std::fs::read_to_string(&to_path).unwrap_or_default();
                if !anchors(&headings).iter().any(|a| a == anchor) {
                    broken.push(format!("{file}:{n}: {target}: no such heading"));
                }
            }
        }
    }
    assert!(
        broken.is_empty(),
        "broken documentation links:\n{}",
        broken.join("\n")
    );
}
