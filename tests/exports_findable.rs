//! Every function the library exports is written out in src/ffi, so that searching for
//! `fn MCC_Line` finds it: for each name the generated headers declare (the vendor's
//! functions in include/MCCL_Fun.h, the simulated machine's in include/MCCL_Sim.h, the
//! MC3B library's in include/mcl.h) exactly one `fn NAME` stands in the sources of
//! src/ffi, and it is `#[no_mangle]`. A function made by a `macro_rules!` macro from a
//! name passed to it has no such line, and fails here.

#[path = "support/rust_files.rs"]
mod support;

use std::path::Path;
use support::rust_files;

/// The headers that declare exported functions, and how many each declares (a lower
/// count means the parser below missed some and the test would pass without looking).
const HEADERS: [(&str, usize); 3] = [("MCCL_Fun.h", 345), ("MCCL_Sim.h", 7), ("mcl.h", 19)];

/// The names of the functions a generated header declares: each prototype stands on one
/// line ending in `);`, its name right before the first `(`.
fn declared(header: &str) -> Vec<String> {
    header
        .lines()
        .map(str::trim)
        .filter(|l| l.ends_with(");") && !l.starts_with('#') && !l.starts_with("typedef"))
        .filter_map(|l| {
            let before = &l[..l.find('(')?];
            let name: String = before
                .chars()
                .rev()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect::<Vec<_>>()
                .into_iter()
                .rev()
                .collect();
            (!name.is_empty()).then_some(name)
        })
        .collect()
}

fn is_ident(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// Whether `line` (code, not a comment) defines function `name`: `fn name` with no
/// identifier character on either side.
fn defines(line: &str, name: &str) -> bool {
    let code = line.trim_start();
    if code.starts_with("//") {
        return false;
    }
    let pat = format!("fn {name}");
    code.match_indices(&pat).any(|(at, _)| {
        let before = code[..at].chars().next_back();
        let after = code[at + pat.len()..].chars().next();
        !before.is_some_and(is_ident) && !after.is_some_and(is_ident)
    })
}

/// Whether the attributes and doc comments right above line `at` of `lines` include
/// `#[no_mangle]`.
fn no_mangle_above(lines: &[&str], at: usize) -> bool {
    lines[..at]
        .iter()
        .rev()
        .map(|l| l.trim())
        .take_while(|l| l.starts_with("#[") || l.starts_with("//"))
        .any(|l| l == "#[no_mangle]")
}

/// Where `name` is defined in `files` (path and line number), and whether each place is
/// `#[no_mangle]`.
fn definitions(files: &[(String, String)], name: &str) -> Vec<(String, usize, bool)> {
    let mut out = Vec::new();
    for (path, src) in files {
        let lines: Vec<&str> = src.lines().collect();
        for (i, line) in lines.iter().enumerate() {
            if defines(line, name) {
                out.push((path.clone(), i + 1, no_mangle_above(&lines, i)));
            }
        }
    }
    out
}

#[test]
fn every_exported_function_is_written_out_once() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let files: Vec<(String, String)> = rust_files(&root.join("src/ffi"))
        .into_iter()
        .map(|p| {
            let src = std::fs::read_to_string(&p).expect("a readable source file");
            let rel = p.strip_prefix(root).unwrap_or(&p).display().to_string();
            (rel, src)
        })
        .collect();
    let mut names = Vec::new();
    for (header, count) in HEADERS {
        let text = std::fs::read_to_string(root.join("include").join(header))
            .unwrap_or_else(|e| panic!("cannot read include/{header}: {e}"));
        let found = declared(&text);
        assert_eq!(found.len(), count, "functions declared in include/{header}");
        names.extend(found);
    }
    let mut failures = Vec::new();
    for name in &names {
        match definitions(&files, name).as_slice() {
            [(_, _, true)] => {}
            [] => failures.push(format!("{name}: no `fn {name}` in src/ffi")),
            [(path, line, false)] => {
                failures.push(format!("{name}: {path}:{line} is not #[no_mangle]"))
            }
            many => failures.push(format!(
                "{name}: defined {} times: {}",
                many.len(),
                many.iter()
                    .map(|(p, l, _)| format!("{p}:{l}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            )),
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} exported functions are not written out once in src/ffi:\n{}",
        failures.len(),
        names.len(),
        failures.join("\n")
    );
}

#[test]
fn the_scan_finds_a_written_out_definition_and_nothing_else() {
    let src = "/// Doc.\n#[no_mangle]\npub extern \"system\" fn MCC_Line(x: f64) -> c_int {\n\
               ffi_boundary! { line(x) }\n}\n\
               // fn MCC_LineX is not here: a comment.\n\
               pub fn MCC_LineY() {}\n\
               on_off! { MCC_LineZ, MCC_LineZOff(w: u16) = |on| f(w, on); }\n";
    let files = vec![("a.rs".to_string(), src.to_string())];
    assert_eq!(definitions(&files, "MCC_Line"), [("a.rs".into(), 3, true)]);
    assert_eq!(definitions(&files, "MCC_LineX"), []);
    assert_eq!(
        definitions(&files, "MCC_LineY"),
        [("a.rs".into(), 7, false)]
    );
    assert_eq!(definitions(&files, "MCC_LineZ"), []);
    let twice = vec![
        ("a.rs".to_string(), src.to_string()),
        ("b.rs".to_string(), src.to_string()),
    ];
    assert_eq!(definitions(&twice, "MCC_Line").len(), 2);
    assert_eq!(
        declared(
            "MCC_API int MCC_CALL MCC_Line(double dfX0, WORD w MCC_DEFAULT(0));\n\
                  typedef void (MCC_CALLBACK *LIOISR)(LIOINT*);\n#define MCC_DEFAULT(v) = v\n\
                  int mcl_deinitialize(void);"
        ),
        ["MCC_Line", "mcl_deinitialize"]
    );
}
