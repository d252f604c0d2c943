//! Reading traces and events: rows with their line numbers, line ends, and lines that are
//! empty, cut short or of the wrong shape.
mod common;

use mccl_trace::data::{read_events, Reader};

const HEADER: &str = "time_ms,group,command,status,x,y,z,u,v,w,a,b,speed";

fn row(t: u32) -> String {
    format!("{t}.000000,0,7,1,1.5,-2,3,0,0,0,0,0,0.5")
}

/// Writes `text` as a trace and reads it: the rows' times and line numbers, or the error.
fn read(name: &str, text: &str) -> Result<Vec<(f64, usize)>, String> {
    let d = common::dir(name);
    let p = d.join("t.csv");
    std::fs::write(&p, text).unwrap();
    let mut r = Reader::open(p.to_str().unwrap())?;
    let mut out = Vec::new();
    while let Some(row) = r.next_row()? {
        assert_eq!(
            (row.cmd, row.pos[0], row.pos[1], row.speed),
            (7, 1.5, -2.0, 0.5)
        );
        out.push((row.t_ms, r.line_no()));
    }
    Ok(out)
}

#[test]
fn rows_with_their_line_numbers_also_after_windows_line_ends() {
    let lf = format!("{HEADER}\n{}\n{}\n", row(1), row(2));
    assert_eq!(read("lf", &lf), Ok(vec![(1.0, 2), (2.0, 3)]));
    let crlf = lf.replace('\n', "\r\n");
    assert_eq!(read("crlf", &crlf), Ok(vec![(1.0, 2), (2.0, 3)]));
}

#[test]
fn lines_that_are_not_rows_are_errors_at_their_line() {
    let cases = [
        // An empty line (a CSV reader would skip it; a trace never has one).
        (
            format!("{HEADER}\n{}\n\n{}\n", row(1), row(2)),
            ":3: empty line",
        ),
        // Only a Windows line end: a row of one empty field.
        (
            format!("{HEADER}\n{}\n\r\n{}\n", row(1), row(2)),
            ":3: expected 13 fields, found 1",
        ),
        // The last line cut short, or ending in a lone carriage return.
        (
            format!("{HEADER}\n{}\n{}", row(1), row(2)),
            ":3: truncated line",
        ),
        (format!("{HEADER}\n{}\r", row(1)), ":2: truncated line"),
        (HEADER.to_string(), ":1: truncated line"),
        // A quote is read as itself, not as CSV quoting.
        (
            format!("{HEADER}\n\"1\",0,0,1,0,0,0,0,0,0,0,0,0\n"),
            ":2: field time_ms: not a finite number: \"\"1\"\"",
        ),
        (
            format!("{HEADER}\n1,0,0,1,\"0,0\",0,0,0,0,0,0,0\n"),
            ":2: field x: not a finite number: \"\"0\"",
        ),
        (format!("\n{HEADER}\n"), ":1: empty line"),
    ];
    for (i, (text, msg)) in cases.iter().enumerate() {
        let e = read(&format!("bad{i}"), text).unwrap_err();
        assert!(e.contains(&format!("t.csv{msg}")), "{text:?}: {e}");
    }
}

#[test]
fn events_are_read_to_the_end_of_the_file() {
    let d = common::dir("events");
    let p = d.join("t.csv");
    let ep = d.join("t.events.csv");
    // No end of line after the last event; a Windows line end; a comma in a detail.
    std::fs::write(
        &ep,
        "time_ms,card,group,kind,detail\r\n1.5,0,2,cmd_start,index=3 type=LINE\n2,0,-1,note,a=1,b=2",
    )
    .unwrap();
    let ev = read_events(p.to_str().unwrap()).unwrap();
    assert_eq!(ev.len(), 2);
    assert_eq!(
        (ev[0].t_ms, ev[0].group, ev[0].kind.as_str()),
        (1.5, 2, "cmd_start")
    );
    assert_eq!(ev[0].num("index"), Some(3.0));
    assert_eq!(ev[1].detail, "a=1,b=2");
    std::fs::write(&ep, "time_ms,card,group,kind,detail\n1,0,0,hold\n").unwrap();
    let e = read_events(p.to_str().unwrap()).unwrap_err();
    assert!(e.ends_with("t.events.csv:2: expected 5 fields"), "{e}");
    // An empty events file: no events.
    std::fs::write(&ep, "").unwrap();
    assert_eq!(read_events(p.to_str().unwrap()), Ok(Vec::new()));
}
