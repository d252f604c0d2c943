use super::*;

/// One example of every command, with optional parameters both ways.
pub(crate) fn all_commands() -> Vec<Command> {
    vec![
        Command::Initialize { id: 0 },
        Command::SetAcceleration {
            id: 0,
            motor: 1,
            value: 5000,
        },
        Command::SetDeceleration {
            id: 2,
            motor: 2,
            value: 100000,
        },
        Command::SetMaxVelocity {
            id: 0,
            motor: 0,
            value: 1000,
            direction_modifier: None,
        },
        Command::SetMaxVelocity {
            id: 0,
            motor: 0,
            value: 1000,
            direction_modifier: Some(1),
        },
        Command::SetLimits {
            id: 0,
            motor: 2,
            h0_and: 8,
            h0_xor: 0,
            h1_and: 32,
            h1_xor: 32,
        },
        Command::SetHalfStep {
            id: 0,
            motor: 1,
            half: 0,
        },
        Command::Run {
            id: 0,
            motor: 0,
            direction: 1,
        },
        Command::Move {
            id: 0,
            motor: 2,
            steps: u32::MAX,
            direction: 0,
        },
        Command::Home {
            id: 0,
            motor: 1,
            direction: 0,
        },
        Command::RateMove {
            id: 0,
            motor: 1,
            steps: 100,
            direction: 0,
            rate: 75,
        },
        Command::Stop { id: 0, motor: 2 },
        Command::SyncMove {
            id: 0,
            steps: [1000, 1000, 0],
            directions: [0, 1, 0],
            execute: None,
        },
        Command::SyncMove {
            id: 0,
            steps: [1000, 1000, 0],
            directions: [1, 1, 0],
            execute: Some(0),
        },
        Command::QueryStatus { id: 0, motor: 1 },
        Command::QueryLimits { id: 255 },
        Command::SetHoldingCurrent {
            id: 0,
            motor: 0,
            enable: 1,
        },
        Command::SetCurrentLimits {
            id: 0,
            motor: 0,
            holding: 500,
            running: 2000,
        },
        Command::SetDebounce { id: 0, count: 100 },
        Command::QueryProductId { id: 0 },
    ]
}

#[test]
fn every_command_round_trips() {
    let cmds = all_commands();
    let codes: std::collections::HashSet<_> = cmds.iter().map(|c| c.code()).collect();
    assert_eq!(codes.len(), CommandCode::ALL.len(), "every letter covered");
    for c in cmds {
        let bytes = encode(&c);
        assert_eq!(bytes.last(), Some(&CR));
        let parsed = parse_command(&bytes[..bytes.len() - 1]);
        assert_eq!(
            parsed,
            Ok(c.clone()),
            "{:?}",
            String::from_utf8_lossy(&bytes)
        );
        assert_eq!(c.validate(), Ok(()), "{c:?}");
    }
}

#[test]
fn guide_examples_encode_exactly() {
    let ex = Command::SetLimits {
        id: 0,
        motor: 2,
        h0_and: 8,
        h0_xor: 0,
        h1_and: 32,
        h1_xor: 32,
    };
    assert_eq!(encode(&ex), b"0L2,8,0,32,32\r");
    let g = Command::RateMove {
        id: 0,
        motor: 1,
        steps: 100,
        direction: 0,
        rate: 75,
    };
    assert_eq!(encode(&g), b"0G1,100,0,75\r");
    let y = Command::SyncMove {
        id: 0,
        steps: [1000, 1000, 0],
        directions: [1, 0, 0],
        execute: Some(1),
    };
    assert_eq!(encode(&y), b"0Y1000,1,1000,0,0,0,1\r");
    let v = Command::SetMaxVelocity {
        id: 0,
        motor: 0,
        value: 1000,
        direction_modifier: Some(1),
    };
    assert_eq!(encode(&v), b"0V0,1000,1\r");
}

#[test]
fn every_response_round_trips_through_the_stream_parser() {
    let mut resps: Vec<Response> = CommandCode::ALL
        .iter()
        .filter(|c| c.is_acknowledged())
        .map(|&code| Response::Ack { id: 0, code })
        .collect();
    resps.push(Response::Status {
        id: 0,
        running: true,
        home0: false,
        home1: true,
    });
    resps.push(Response::Limits { id: 0, bits: 63 });
    resps.push(Response::ProductId {
        id: 0,
        product: 1,
        version: 100,
    });
    for code in [
        ErrorCode::InvalidCommand,
        ErrorCode::MotorRunning,
        ErrorCode::WrongParameterCount,
        ErrorCode::OutOfRange,
    ] {
        resps.push(Response::Error { id: 7, code });
    }
    // Concatenate with LFs sprinkled in and feed one byte at a time.
    let mut stream = Vec::new();
    for r in &resps {
        let b = encode_response(r);
        stream.push(LF);
        stream.extend_from_slice(&b[..1]);
        stream.push(LF);
        stream.extend_from_slice(&b[1..]);
    }
    let mut p = ResponseParser::new();
    for chunk in stream.chunks(3) {
        p.feed(chunk);
    }
    for r in &resps {
        assert_eq!(p.next_response(), Some(Ok(*r)));
    }
    assert_eq!(p.next_response(), None);
}

#[test]
fn command_errors_follow_the_documented_order() {
    let e = |s: &str| parse_command(s.as_bytes()).err();
    assert_eq!(
        e("0Z1"),
        Some(CommandError {
            id: Some(0),
            code: ErrorCode::InvalidCommand
        })
    );
    assert_eq!(
        e("0A1"),
        Some(CommandError {
            id: Some(0),
            code: ErrorCode::WrongParameterCount
        })
    );
    assert_eq!(
        e("0Y1,0,1,0,1,0,1,1"),
        Some(CommandError {
            id: Some(0),
            code: ErrorCode::WrongParameterCount
        })
    );
    assert_eq!(
        e("0A1,-5"),
        Some(CommandError {
            id: Some(0),
            code: ErrorCode::OutOfRange
        })
    );
    assert_eq!(
        e("0M0,4294967296,0"),
        Some(CommandError {
            id: Some(0),
            code: ErrorCode::OutOfRange
        })
    );
    assert_eq!(e("A1,5").map(|x| x.id), Some(None));
    assert_eq!(parse_command(b"0I\n"), Ok(Command::Initialize { id: 0 }));
    let a = parse_command(b"0A3,5000").map(|c| c.validate());
    assert_eq!(a, Ok(Err(ErrorCode::OutOfRange)));
    let r = parse_command(b"0G1,100,0,49").map(|c| c.validate());
    assert_eq!(r, Ok(Err(ErrorCode::OutOfRange)));
}

#[test]
fn malformed_responses_are_errors() {
    assert_eq!(parse_response(b"E1"), Err(ProtocolError::BadId));
    assert_eq!(
        parse_response(b"0E9"),
        Err(ProtocolError::UnknownErrorNumber(9))
    );
    assert_eq!(
        parse_response(b"0Q1,0"),
        Err(ProtocolError::WrongFieldCount { code: b'Q', got: 2 })
    );
    assert_eq!(parse_response(b"0B256"), Err(ProtocolError::BadField));
    assert_eq!(
        parse_response(b"0Z"),
        Err(ProtocolError::UnknownCode(Some(b'Z')))
    );
    assert_eq!(
        parse_response(b"0A5"),
        Err(ProtocolError::WrongFieldCount { code: b'A', got: 1 })
    );
    let mut p = ResponseParser::new();
    p.feed(&[b'0'; MAX_LINE]);
    assert_eq!(
        p.next_response(),
        None,
        "a line of MAX_LINE bytes may still end"
    );
    p.feed(b"0");
    // Reported at its (MAX_LINE + 1)th byte, before any CR: a reader need not wait.
    assert_eq!(p.next_response(), Some(Err(ProtocolError::LineTooLong)));
    p.feed(&[b'0'; 500]);
    p.feed(b"\r0I\r");
    assert_eq!(
        p.next_response(),
        Some(Ok(Response::Ack {
            id: 0,
            code: CommandCode::Initialize
        }))
    );
}

/// xorshift64* PRNG: deterministic, no crates.
pub(crate) struct XorShift(pub u64);
impl XorShift {
    pub(crate) fn next(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.0 = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
}

#[test]
fn fuzz_100k_random_byte_strings_never_panic() {
    let mut rng = XorShift(0x9E37_79B9_7F4A_7C15);
    // Bias the alphabet toward the protocol's own bytes so that deep
    // paths are exercised, with raw bytes mixed in.
    const ALPHA: &[u8] = b"0123456789,,,IADVLFRMHGSYQBCKNPEZ\r\r\n- ";
    let mut rp = ResponseParser::new();
    let mut cp = CommandParser::new();
    let (mut ok_r, mut ok_c, mut frames) = (0u32, 0u32, 0u32);
    for _ in 0..100_000 {
        let len = (rng.next() % 40) as usize;
        let bytes: Vec<u8> = (0..len)
            .map(|_| {
                let r = rng.next();
                if r % 4 == 0 {
                    (r >> 8) as u8
                } else {
                    ALPHA[((r >> 8) % ALPHA.len() as u64) as usize]
                }
            })
            .collect();
        // Whole-line parsers.
        let _ = parse_response(&bytes);
        let _ = parse_command(&bytes).map(|c| c.validate());
        // Streaming parsers.
        rp.feed(&bytes);
        cp.feed(&bytes);
        while let Some(r) = rp.next_response() {
            frames += 1;
            if let Ok(resp) = r {
                ok_r += 1;
                // Anything accepted re-encodes to something that parses
                // back to the same value.
                let enc = encode_response(&resp);
                assert_eq!(parse_response(&enc[..enc.len() - 1]), Ok(resp));
            }
        }
        while let Some(c) = cp.next_command() {
            if let Ok(cmd) = c {
                ok_c += 1;
                let enc = encode(&cmd);
                assert_eq!(parse_command(&enc[..enc.len() - 1]), Ok(cmd));
            }
        }
    }
    assert!(frames > 10_000, "frames {frames}");
    assert!(ok_r > 0 && ok_c > 0, "ok_r {ok_r} ok_c {ok_c}");
}
