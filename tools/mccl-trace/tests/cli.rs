//! diff, and bad input: a clear message and a non-zero exit, never a panic.
mod common;

use std::process::Output;

fn run(args: &[&str]) -> Output {
    common::bin().args(args).output().unwrap()
}

fn text(o: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    )
}

#[test]
fn diff_agrees_with_itself_and_finds_an_injected_change() {
    let d = common::dir("diff");
    let a = d.join("a.csv");
    common::write_trace(&a);
    let a = a.to_str().unwrap();
    let o = run(&["diff", a, a]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o));
    assert!(text(&o).contains("traces agree"));
    // Change y of group 0 at 1234 ms by 1e-6 UU.
    let src = std::fs::read_to_string(a).unwrap();
    let mut lines: Vec<String> = src.lines().map(String::from).collect();
    let n = lines
        .iter()
        .position(|l| l.starts_with("1234.000000,0,"))
        .unwrap();
    let mut f: Vec<String> = lines[n].split(',').map(String::from).collect();
    let y: f64 = f[5].parse().unwrap();
    f[5] = format!("{:.9}", y + 1e-6);
    lines[n] = f.join(",");
    let b = d.join("b.csv");
    std::fs::write(&b, lines.join("\n") + "\n").unwrap();
    let b = b.to_str().unwrap();
    let o = run(&["diff", a, b]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    let t = text(&o);
    assert!(
        t.contains("first difference: 1234.000000 ms, group 0, axis y"),
        "{t}"
    );
    assert!(t.contains("y=1.000e-6"), "{t}");
    // Within a tolerance of 2e-6 they agree; the library says where.
    assert_eq!(run(&["diff", a, b, "--tol", "2e-6"]).status.code(), Some(0));
    let r = mccl_trace::diff::diff(a, b, 1e-7).unwrap();
    assert_eq!(r.first, Some((1234.0, 0, "y".to_string())));
}

#[test]
fn diff_of_different_lengths_and_groups() {
    let d = common::dir("diff2");
    let a = d.join("a.csv");
    common::write_trace(&a);
    let src = std::fs::read_to_string(&a).unwrap();
    let a = a.to_str().unwrap();
    // Shorter: the first 100 rows.
    let short: String = src.lines().take(101).map(|l| format!("{l}\n")).collect();
    let b = d.join("short.csv");
    std::fs::write(&b, short).unwrap();
    let o = run(&["diff", a, b.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        text(&o).contains("short.csv ends after 100 rows"),
        "{}",
        text(&o)
    );
    // Group 1 renamed 2.
    let other: String = src
        .lines()
        .map(|l| format!("{}\n", l.replacen(".000000,1,", ".000000,2,", 1)))
        .collect();
    let c = d.join("other.csv");
    std::fs::write(&c, other).unwrap();
    let o = run(&["diff", a, c.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        text(&o).contains("different ticks or groups"),
        "{}",
        text(&o)
    );
}

#[test]
fn bad_input_is_a_clear_error() {
    let d = common::dir("bad");
    let good = d.join("good.csv");
    common::write_trace(&good);
    let src = std::fs::read_to_string(&good).unwrap();
    let write = |name: &str, s: &str| {
        let p = d.join(name);
        std::fs::write(&p, s).unwrap();
        p.to_str().unwrap().to_string()
    };
    let header = "time_ms,group,command,status,x,y,z,u,v,w,a,b,speed\n";
    let cases = [
        (
            d.join("missing.csv").to_str().unwrap().to_string(),
            "cannot open",
        ),
        (write("trunc.csv", &src[..src.len() - 20]), "truncated line"),
        (
            write("hdr.csv", &src.replacen("speed", "sped", 1)),
            "not a trace header",
        ),
        (write("empty.csv", header), "empty trace"),
        (write("nothing.csv", ""), "empty file"),
        (
            write(
                "nan.csv",
                &format!("{header}1.000000,0,0,1,abc,0,0,0,0,0,0,0,0\n"),
            ),
            "field x: not a finite number: \"abc\"",
        ),
        (
            write(
                "grp.csv",
                &format!("{header}1.000000,g,0,1,0,0,0,0,0,0,0,0,0\n"),
            ),
            "field group: not an integer",
        ),
        (
            write("short.csv", &format!("{header}1.000000,0,0,1,0,0\n")),
            "expected 13 fields, found 6",
        ),
    ];
    let out = d.join("o.svg");
    let out = out.to_str().unwrap();
    let html = d.join("o.html");
    for (file, msg) in &cases {
        for args in [
            vec!["plot", file, "-o", out],
            vec!["report", file, "-o", html.to_str().unwrap()],
            vec!["diff", file, good.to_str().unwrap()],
        ] {
            let o = run(&args);
            let t = text(&o);
            assert_eq!(o.status.code(), Some(2), "{args:?}: {t}");
            assert!(t.contains(msg), "{args:?}: expected \"{msg}\" in: {t}");
            assert!(!t.contains("panicked"), "{t}");
        }
    }
    for (args, msg) in [
        (vec!["plot"], "one trace file"),
        (vec!["plot", "x.csv"], "-o OUT is required"),
        (vec!["frob"], "unknown command"),
        (
            vec!["plot", "x.csv", "-o", "a.svg", "--plane", "qq"],
            "--plane",
        ),
        (
            vec!["diff", "a.csv", "b.csv", "--tol", "x"],
            "--tol: not a number",
        ),
        (
            vec!["plot", good.to_str().unwrap(), "-o", "a.gif"],
            "must end in .svg or .png",
        ),
    ] {
        let o = run(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(text(&o).contains(msg), "{args:?}: {}", text(&o));
    }
}

#[test]
fn options_values_and_help() {
    let d = common::dir("opts");
    let a = d.join("a.csv");
    common::write_trace(&a);
    let a = a.to_str().unwrap();
    let svg = d.join("o.svg");
    let svg = svg.to_str().unwrap();
    // The usage, on standard output with success, also asked for after a command.
    for args in [
        vec!["--help"],
        vec!["-h"],
        vec!["help"],
        vec!["plot", a, "--help"],
    ] {
        let o = run(&args);
        assert_eq!(o.status.code(), Some(0), "{args:?}");
        let out = String::from_utf8_lossy(&o.stdout);
        assert!(
            out.contains("usage:\n  mccl-trace plot TRACE.csv"),
            "{args:?}: {out}"
        );
    }
    // A value follows its option or is joined to it with '='; a value that starts with
    // '-' is a value (a time window before the trace: -5 ms).
    let o = run(&["diff", a, a, "--tol=2e-6"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o));
    let o = run(&["plot", a, "-o", svg, "--from", "-5", "--to", "100"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o));
    assert!(std::fs::metadata(svg).unwrap().len() > 0);
    for (args, msg) in [
        (vec!["plot", a, "-o"], "-o needs a file name"),
        (vec!["plot", a, "--group"], "--group needs a value"),
        (
            vec!["plot", a, "-o", svg, "--width", "10"],
            "--width: 600 to 20000",
        ),
        (
            vec!["plot", a, "-o", svg, "--bogus"],
            "unknown option --bogus",
        ),
        (
            vec!["plot", a, "-o", svg, "--from", "9", "--to", "1"],
            "--from is after --to",
        ),
        (
            vec!["diff", a, a, "--tol", "-1"],
            "--tol must not be negative",
        ),
    ] {
        let o = run(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(text(&o).contains(msg), "{args:?}: {}", text(&o));
    }
}
