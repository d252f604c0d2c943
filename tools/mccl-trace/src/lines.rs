//! The records of a CSV file the library writes (a trace or its events), read with the
//! `csv` crate as a stream, with the checks the files' format asks for: every line holds
//! a record (an empty line is an error, where CSV readers skip it), and a trace's last
//! line ends with an end of line (a file cut short while it was written is reported,
//! not read as a short last row). Lines end with `\n` (a `\r` before it is dropped, as
//! from a file that went through Windows). The library writes numbers and `key=value`
//! words, never quotes: a quote is read as itself.

use std::fs::File;
use std::io::Read;

/// A reader that remembers its last byte and whether it reached the end.
struct Tail<R> {
    inner: R,
    last: Option<u8>,
    ended: bool,
}

impl<R: Read> Read for Tail<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.inner.read(buf)?;
        match n {
            0 => self.ended = true,
            n => self.last = Some(buf[n - 1]),
        }
        Ok(n)
    }
}

/// The records of one file, one a line.
pub struct Lines {
    name: String,
    csv: csv::Reader<Tail<File>>,
    record: csv::StringRecord,
    line_no: usize,
    /// Whether a last line without an end of line is an error.
    needs_eol: bool,
}

impl Lines {
    /// Reads `file`, called `name` in messages.
    pub fn new(name: &str, file: File, needs_eol: bool) -> Lines {
        let csv = csv::ReaderBuilder::new()
            .has_headers(false)
            .flexible(true)
            .quoting(false)
            .terminator(csv::Terminator::Any(b'\n'))
            .buffer_capacity(1 << 16)
            .from_reader(Tail {
                inner: file,
                last: None,
                ended: false,
            });
        Lines {
            name: name.to_string(),
            csv,
            record: csv::StringRecord::new(),
            line_no: 0,
            needs_eol,
        }
    }

    /// The line number of the last record read.
    pub fn line_no(&self) -> usize {
        self.line_no
    }

    /// The next record with its line number, `None` at the end of the file.
    pub fn next_record(&mut self) -> Result<Option<(usize, &csv::StringRecord)>, String> {
        let here = self.line_no + 1;
        let read = self
            .csv
            .read_record(&mut self.record)
            .map_err(|e| format!("{}:{here}: cannot read: {e}", self.name))?;
        if !read {
            return Ok(None);
        }
        let tail = self.csv.get_ref();
        // A record the end of the file ended, not an end of line.
        let cut = tail.ended && tail.last != Some(b'\n');
        // The reader counts the ends of line it has passed.
        let after = usize::try_from(self.csv.position().line()).unwrap_or(usize::MAX);
        let line = if cut { after } else { after.saturating_sub(1) };
        if line > here {
            return Err(format!("{}:{here}: empty line", self.name));
        }
        self.line_no = line;
        if cut && self.needs_eol {
            return Err(format!(
                "{}:{line}: truncated line (the file ends without an end of line)",
                self.name
            ));
        }
        let last = self.record.len().saturating_sub(1);
        if self.record.get(last).is_some_and(|f| f.ends_with('\r')) {
            let fields: Vec<String> = self.record.iter().map(String::from).collect();
            self.record.clear();
            for (i, f) in fields.iter().enumerate() {
                let f = if i == last {
                    f.trim_end_matches('\r')
                } else {
                    f
                };
                self.record.push_field(f);
            }
        }
        Ok(Some((line, &self.record)))
    }
}

/// A record as the line it was read from (its fields joined by commas).
pub fn text(r: &csv::StringRecord) -> String {
    r.iter().collect::<Vec<_>>().join(",")
}
