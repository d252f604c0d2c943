//! One frame on the wire, `<id><letter>[p1][,p2]...<CR>`: encoding commands and
//! responses, and parsing one line into either.

use super::{Command, CommandCode, ErrorCode, ProtocolError, Response, CR, LF};

/// Why a command frame was rejected. `id` is `None` when no controller ID
/// could be read: the device then stays silent (it cannot address a reply).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CommandError {
    /// ID the reply goes to, if one was read.
    pub id: Option<u8>,
    /// Error to report.
    pub code: ErrorCode,
}

fn push_num(out: &mut Vec<u8>, n: u32) {
    out.extend_from_slice(n.to_string().as_bytes());
}

fn frame(id: u8, letter: u8, params: &[u32]) -> Vec<u8> {
    let mut out = Vec::with_capacity(8 + params.len() * 6);
    push_num(&mut out, u32::from(id));
    out.push(letter);
    for (i, p) in params.iter().enumerate() {
        if i > 0 {
            out.push(b',');
        }
        push_num(&mut out, *p);
    }
    out.push(CR);
    out
}

/// Encode a command as wire bytes, CR included.
pub fn encode(cmd: &Command) -> Vec<u8> {
    frame(cmd.id(), cmd.code().letter(), &cmd.params())
}

/// Encode a response as wire bytes, CR included.
pub fn encode_response(resp: &Response) -> Vec<u8> {
    match *resp {
        Response::Ack { id, code } => frame(id, code.letter(), &[]),
        Response::Status {
            id,
            running,
            home0,
            home1,
        } => frame(
            id,
            b'Q',
            &[u32::from(running), u32::from(home0), u32::from(home1)],
        ),
        Response::Limits { id, bits } => frame(id, b'B', &[u32::from(bits)]),
        Response::ProductId {
            id,
            product,
            version,
        } => frame(id, b'P', &[product, version]),
        Response::Error { id, code } => frame(id, b'E', &[code.number()]),
    }
}

/// A frame split into its parts; fields are still text.
pub(super) struct RawFrame<'a> {
    /// The controller ID.
    pub(super) id: u8,
    letter: Option<u8>,
    fields: Vec<&'a [u8]>,
}

/// Split `<id><letter>[f1][,f2]...` (no CR, no LF). `None` if no valid ID.
pub(super) fn split_frame(line: &[u8]) -> Option<RawFrame<'_>> {
    let digits = line.iter().take_while(|b| b.is_ascii_digit()).count();
    if digits == 0 || digits > 3 {
        return None;
    }
    let id = parse_u32(line.get(..digits)?)?;
    let id = u8::try_from(id).ok()?;
    let letter = line.get(digits).copied();
    let rest = line.get(digits + 1..).unwrap_or(&[]);
    let fields = if rest.is_empty() {
        Vec::new()
    } else {
        rest.split(|b| *b == b',').collect()
    };
    Some(RawFrame { id, letter, fields })
}

/// Parse an unsigned decimal of at most 32 bits; `None` for anything else.
fn parse_u32(s: &[u8]) -> Option<u32> {
    if s.is_empty() || s.len() > 10 {
        return None;
    }
    let mut v: u64 = 0;
    for &b in s {
        if !b.is_ascii_digit() {
            return None;
        }
        v = v * 10 + u64::from(b - b'0');
    }
    u32::try_from(v).ok()
}

/// Parse one command frame (without CR; LFs are skipped). Applies the syntax,
/// letter and count checks; not the range checks ([`Command::validate`]).
pub fn parse_command(line: &[u8]) -> Result<Command, CommandError> {
    let clean: Vec<u8> = line.iter().copied().filter(|b| *b != LF).collect();
    let raw = split_frame(&clean).ok_or(CommandError {
        id: None,
        code: ErrorCode::InvalidCommand,
    })?;
    let err = |code| CommandError {
        id: Some(raw.id),
        code,
    };
    let code = raw
        .letter
        .and_then(CommandCode::from_letter)
        .ok_or(err(ErrorCode::InvalidCommand))?;
    let (lo, hi) = code.param_counts();
    if raw.fields.len() < lo || raw.fields.len() > hi {
        return Err(err(ErrorCode::WrongParameterCount));
    }
    let mut params = Vec::with_capacity(raw.fields.len());
    for f in &raw.fields {
        params.push(parse_u32(f).ok_or(err(ErrorCode::OutOfRange))?);
    }
    Command::from_parts(raw.id, code, &params).ok_or(err(ErrorCode::WrongParameterCount))
}

/// Parse one response frame (without CR; LFs are skipped).
pub fn parse_response(line: &[u8]) -> Result<Response, ProtocolError> {
    let clean: Vec<u8> = line.iter().copied().filter(|b| *b != LF).collect();
    let raw = split_frame(&clean).ok_or(ProtocolError::BadId)?;
    let letter = raw.letter.ok_or(ProtocolError::UnknownCode(None))?;
    let id = raw.id;
    let mut nums = Vec::with_capacity(raw.fields.len());
    for f in &raw.fields {
        nums.push(parse_u32(f).ok_or(ProtocolError::BadField)?);
    }
    let wrong = || ProtocolError::WrongFieldCount {
        code: letter,
        got: nums.len(),
    };
    let flag = |v: u32| match v {
        0 => Ok(false),
        1 => Ok(true),
        _ => Err(ProtocolError::BadField),
    };
    match (letter, nums.as_slice()) {
        (b'E', &[n]) => {
            let code = ErrorCode::from_number(n).ok_or(ProtocolError::UnknownErrorNumber(n))?;
            Ok(Response::Error { id, code })
        }
        (b'Q', &[r, h0, h1]) => Ok(Response::Status {
            id,
            running: r != 0,
            home0: flag(h0)?,
            home1: flag(h1)?,
        }),
        (b'B', &[b]) => {
            let bits = u8::try_from(b).map_err(|_| ProtocolError::BadField)?;
            Ok(Response::Limits { id, bits })
        }
        (b'P', &[product, version]) => Ok(Response::ProductId {
            id,
            product,
            version,
        }),
        (b'E' | b'Q' | b'B' | b'P', _) => Err(wrong()),
        (other, fields) => {
            let code = CommandCode::from_letter(other)
                .filter(|c| c.is_acknowledged())
                .ok_or(ProtocolError::UnknownCode(Some(other)))?;
            if fields.is_empty() {
                Ok(Response::Ack { id, code })
            } else {
                Err(wrong())
            }
        }
    }
}
