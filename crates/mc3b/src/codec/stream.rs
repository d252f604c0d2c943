//! Streams of bytes into frames: lines split at CR, and the streaming parsers of
//! either side.

use std::collections::VecDeque;

use super::frame::split_frame;
use super::{
    parse_command, parse_response, Command, CommandError, ErrorCode, ProtocolError, Response, CR,
    LF, MAX_LINE,
};

/// Splits a byte stream into CR-terminated lines, dropping LFs and capping
/// line length at [`MAX_LINE`].
#[derive(Debug, Default, Clone)]
struct LineSplitter {
    buf: Vec<u8>,
    overflow: bool,
}

/// One line out of a [`LineSplitter`].
#[derive(Debug, Clone, PartialEq, Eq)]
enum Line {
    /// A complete line (without CR).
    Complete(Vec<u8>),
    /// A line longer than [`MAX_LINE`]; its first bytes are kept so the ID
    /// can still be read.
    TooLong(Vec<u8>),
}

impl LineSplitter {
    /// Feed one byte; returns a line when `b` is a CR. Empty lines are
    /// skipped.
    fn push(&mut self, b: u8) -> Option<Line> {
        match b {
            LF => None,
            CR => {
                let line = std::mem::take(&mut self.buf);
                if std::mem::take(&mut self.overflow) {
                    Some(Line::TooLong(line))
                } else if line.is_empty() {
                    None
                } else {
                    Some(Line::Complete(line))
                }
            }
            _ => {
                if self.buf.len() < MAX_LINE {
                    self.buf.push(b);
                } else {
                    self.overflow = true;
                }
                None
            }
        }
    }

    /// Drop any partial line.
    fn clear(&mut self) {
        self.buf.clear();
        self.overflow = false;
    }

    /// Whether the current (unfinished) line has passed [`MAX_LINE`] bytes.
    fn overflowing(&self) -> bool {
        self.overflow
    }
}

/// Streaming response parser: feed arbitrary chunks, take parsed frames.
#[derive(Debug, Default, Clone)]
pub struct ResponseParser {
    lines: LineSplitter,
    ready: VecDeque<Result<Response, ProtocolError>>,
}

impl ResponseParser {
    /// Empty parser.
    pub fn new() -> Self {
        Self::default()
    }

    /// Feed a chunk of bytes (any length, any split). A line is reported
    /// [`ProtocolError::LineTooLong`] as soon as it passes [`MAX_LINE`] bytes (no
    /// reply is that long, so a reader need not wait for its CR, which may never
    /// come); the rest of it, up to its CR, is dropped without a second report.
    pub fn feed(&mut self, data: &[u8]) {
        for &b in data {
            let was_over = self.lines.overflowing();
            match self.lines.push(b) {
                Some(Line::Complete(l)) => self.ready.push_back(parse_response(&l)),
                Some(Line::TooLong(_)) => {
                    if !was_over {
                        self.ready.push_back(Err(ProtocolError::LineTooLong));
                    }
                }
                None => {
                    if !was_over && self.lines.overflowing() {
                        self.ready.push_back(Err(ProtocolError::LineTooLong));
                    }
                }
            }
        }
    }

    /// Ends the line being received as if its CR had come: for a reader that knows no
    /// more of it will come (its reply timeout expired), what arrived is a frame of its
    /// own, and the next line is not read glued to it. Nothing when no line is begun.
    pub fn end_line(&mut self) {
        self.feed(&[CR]);
    }

    /// Next complete frame, if any.
    pub fn next_response(&mut self) -> Option<Result<Response, ProtocolError>> {
        self.ready.pop_front()
    }

    /// Drop partial input and unread frames.
    pub fn clear(&mut self) {
        self.lines.clear();
        self.ready.clear();
    }
}

/// Streaming command parser (device side).
#[derive(Debug, Default, Clone)]
pub struct CommandParser {
    lines: LineSplitter,
    ready: VecDeque<Result<Command, CommandError>>,
}

impl CommandParser {
    /// Empty parser.
    pub fn new() -> Self {
        Self::default()
    }

    /// Feed a chunk of bytes.
    pub fn feed(&mut self, data: &[u8]) {
        for &b in data {
            match self.lines.push(b) {
                Some(Line::Complete(l)) => self.ready.push_back(parse_command(&l)),
                Some(Line::TooLong(l)) => {
                    let id = split_frame(&l).map(|r| r.id);
                    self.ready.push_back(Err(CommandError {
                        id,
                        code: ErrorCode::InvalidCommand,
                    }))
                }
                None => {}
            }
        }
    }

    /// Next complete command (or its error), if any.
    pub fn next_command(&mut self) -> Option<Result<Command, CommandError>> {
        self.ready.pop_front()
    }
}
