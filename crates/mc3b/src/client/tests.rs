use super::*;
use crate::codec::ErrorCode;
use std::collections::VecDeque;
use std::io;

fn client() -> Client<EmulatorLink> {
    Client::new(EmulatorLink::new(), Duration::from_millis(100))
}

#[test]
fn queries_and_acks_over_the_loopback() {
    let mut c = client();
    assert!(c.initialize(0).is_ok());
    assert_eq!(c.product_id(0).ok(), Some((1, 100)));
    assert_eq!(c.query_limits(0).ok(), Some(0));
    let st = c.query_status(0, 0).ok();
    assert_eq!(
        st,
        Some(MotorStatus {
            running: false,
            home0: false,
            home1: false
        })
    );
    assert!(c
        .command(&Command::Move {
            id: 0,
            motor: 0,
            steps: 100,
            direction: 0
        })
        .is_ok());
    assert_eq!(c.query_status(0, 0).ok().map(|s| s.bits()), Some(1));
}

#[test]
fn device_errors_and_timeouts() {
    let mut c = client();
    let r = c.command(&Command::SetAcceleration {
        id: 0,
        motor: 0,
        value: 5,
    });
    assert!(matches!(r, Err(ClientError::Device(ErrorCode::OutOfRange))));
    // Controller 1 does not exist: silence -> timeout.
    let r = c.query_limits(1);
    assert!(matches!(r, Err(ClientError::Timeout)));
}

struct Scripted {
    replies: VecDeque<Vec<u8>>,
    sent: Vec<u8>,
}
impl Transport for Scripted {
    fn send(&mut self, data: &[u8]) -> io::Result<()> {
        self.sent.extend_from_slice(data);
        Ok(())
    }
    fn recv(&mut self, buf: &mut [u8], _t: Duration) -> io::Result<usize> {
        match self.replies.pop_front() {
            Some(r) => {
                let n = r.len().min(buf.len());
                buf[..n].copy_from_slice(&r[..n]);
                Ok(n)
            }
            None => Ok(0),
        }
    }
}

#[test]
fn garbage_and_foreign_replies_fail_at_once_then_the_line_resyncs() {
    let t = Scripted {
        replies: VecDeque::from(vec![b"garbage\r".to_vec()]),
        sent: vec![],
    };
    let mut c = Client::new(t, Duration::from_millis(50));
    let r = c.query_limits(0);
    assert!(matches!(r, Err(ClientError::Garbled(_))), "{r:?}");
    assert!(!c.in_sync());
    // The next command first resyncs with 0P: the stale 0B5 before its answer is
    // dropped, then 0B is sent and its reply, in chunks, reassembled.
    c.transport().sent.clear();
    c.transport().replies = VecDeque::from(vec![
        b"0B5\r0P1,100\r".to_vec(),
        b"0".to_vec(),
        b"B3".to_vec(),
        b"7\r".to_vec(),
    ]);
    assert_eq!(c.query_limits(0).ok(), Some(37));
    assert_eq!(c.transport().sent, b"0P\r0B\r");
    assert!(c.in_sync());
    // Another controller's reply: no waiting for ours.
    c.transport().replies.push_back(b"1B4\r".to_vec());
    let r = c.query_limits(0);
    assert!(matches!(r, Err(ClientError::Unexpected(_))), "{r:?}");
    // A mismatched ack is reported, not taken as success.
    c.transport().replies = VecDeque::from(vec![b"0P1,100\r".to_vec(), b"0A\r".to_vec()]);
    let r = c.command(&Command::Stop { id: 0, motor: 0 });
    assert!(matches!(r, Err(ClientError::Unexpected(_))), "{r:?}");
    // A line longer than any reply fails before its CR arrives.
    c.transport().replies = VecDeque::from(vec![b"0P1,100\r".to_vec(), vec![b'7'; 200]]);
    let r = c.query_limits(0);
    assert!(
        matches!(r, Err(ClientError::Garbled(ProtocolError::LineTooLong))),
        "{r:?}"
    );
}

/// A transport whose reads overrun: each takes `stall` times what it was asked
/// to wait (the reading thread not scheduled on a loaded host); the reply is
/// there from the `ready_at`th read on.
struct Stalling {
    reads: usize,
    ready_at: usize,
    stall: u32,
    reply: Vec<u8>,
    clock: Duration,
}
impl Transport for Stalling {
    fn send(&mut self, _: &[u8]) -> io::Result<()> {
        Ok(())
    }
    fn recv(&mut self, buf: &mut [u8], t: Duration) -> io::Result<usize> {
        self.reads += 1;
        if self.reads < self.ready_at {
            self.clock += t * self.stall;
            return Ok(0);
        }
        // Data was waiting: the read returns as soon as it is scheduled.
        self.clock += Duration::from_millis(1) * self.stall;
        let n = self.reply.len().min(buf.len());
        buf[..n].copy_from_slice(&self.reply[..n]);
        self.reply.clear();
        Ok(n)
    }
    fn now(&self) -> Duration {
        self.clock
    }
}

#[test]
fn the_timeout_counts_only_time_the_reply_could_have_been_read() {
    // Timeout 100 ms, slices of 20 ms, each read taking 10x as long: the reply
    // waiting at the 4th read comes after 3 x 200 + 10 = 610 ms of the host's
    // time but after 3 x 20 + 1 = 61 ms of watching: in time.
    let t = Stalling {
        reads: 0,
        ready_at: 4,
        stall: 10,
        reply: b"0B9\r".to_vec(),
        clock: Duration::ZERO,
    };
    let mut c = Client::new(t, Duration::from_millis(100));
    assert_eq!(c.query_limits(0).ok(), Some(9));
    assert_eq!(c.transport().clock, Duration::from_millis(610));
    // With nothing coming, the timeout is 5 slices of watching (1 s of stalls).
    c.transport().ready_at = usize::MAX;
    c.transport().reads = 0;
    let r = c.query_limits(0);
    assert!(matches!(r, Err(ClientError::Timeout)), "{r:?}");
    assert_eq!(c.transport().reads, 5);
}

/// A device that answers each command line it is sent with the next scripted
/// reply, only once the command was sent (unlike [`Scripted`], whose replies are
/// there whenever the client reads); `arrived` holds bytes on the line not read yet.
struct Answering {
    answers: VecDeque<Vec<u8>>,
    arrived: VecDeque<u8>,
    sent: Vec<u8>,
}
impl Answering {
    fn new(answers: &[&[u8]]) -> Answering {
        Answering {
            answers: answers.iter().map(|a| a.to_vec()).collect(),
            arrived: VecDeque::new(),
            sent: Vec::new(),
        }
    }
}
impl Transport for Answering {
    fn send(&mut self, data: &[u8]) -> io::Result<()> {
        self.sent.extend_from_slice(data);
        for _ in data.iter().filter(|&&b| b == b'\r') {
            if let Some(a) = self.answers.pop_front() {
                self.arrived.extend(a);
            }
        }
        Ok(())
    }
    fn recv(&mut self, buf: &mut [u8], _t: Duration) -> io::Result<usize> {
        let mut n = 0;
        while let (Some(slot), Some(b)) = (buf.get_mut(n), self.arrived.pop_front()) {
            *slot = b;
            n += 1;
        }
        Ok(n)
    }
}

#[test]
fn a_reply_that_lost_its_carriage_return_does_not_fail_the_next_call() {
    // 0B is answered "0B5" and the CR is lost on the line: the call times out.
    // The next call resyncs (0P) and then asks 0B again. The answer to 0P,
    // "0P1,100\r", follows the partial "0B5" on the line; read as one line it is
    // "0B50P1,100", which answers nothing, and the resync would time out too. The
    // partial line was complete as far as it will ever be when the timeout
    // expired: it is a reply of its own (a stale one), and the call succeeds.
    let t = Answering::new(&[b"0B5", b"0P1,100\r", b"0B7\r"]);
    let mut c = Client::new(t, Duration::from_millis(50));
    let r = c.query_limits(0);
    assert!(matches!(r, Err(ClientError::Timeout)), "{r:?}");
    assert_eq!(c.query_limits(0).ok(), Some(7));
    assert_eq!(c.transport().sent, b"0B\r0P\r0B\r");
    assert!(c.in_sync());
    // The same when the bytes without their CR only arrive after the timeout,
    // before the next call: "0B6" waits on the line when the resync starts.
    c.transport().answers = VecDeque::from(vec![b"".to_vec()]);
    let r = c.query_limits(0);
    assert!(matches!(r, Err(ClientError::Timeout)), "{r:?}");
    c.transport().arrived.extend(b"0B6");
    c.transport().answers = VecDeque::from(vec![b"0P1,100\r".to_vec(), b"0B3\r".to_vec()]);
    assert_eq!(c.query_limits(0).ok(), Some(3));
    // A command whose acknowledgement lost its CR is found done by `settle`.
    let stop = Command::Stop { id: 0, motor: 1 };
    c.transport().answers = VecDeque::from(vec![b"0S".to_vec(), b"0P1,100\r".to_vec()]);
    let e = c.command(&stop).err();
    assert!(matches!(e, Some(ClientError::Timeout)), "{e:?}");
    let r = c.settle(&stop, ClientError::Timeout);
    assert!(r.is_ok(), "{r:?}");
}

#[test]
fn settle_finds_a_late_acknowledgement() {
    // The ack of 0S1 comes only after the timeout: settle's resync reads it before
    // the 0P answer and reports the command done.
    let t = Scripted {
        replies: VecDeque::new(),
        sent: vec![],
    };
    let mut c = Client::new(t, Duration::from_millis(20));
    let stop = Command::Stop { id: 0, motor: 1 };
    let e = c.command(&stop).err();
    assert!(matches!(e, Some(ClientError::Timeout)), "{e:?}");
    c.transport().replies = VecDeque::from(vec![b"0S\r0P1,100\r".to_vec()]);
    let r = c.settle(&stop, ClientError::Timeout);
    assert!(r.is_ok(), "{r:?}");
    assert_eq!(c.transport().sent, b"0S1\r0P\r");
    // No late reply: the original error stands (the command's fate is unknown).
    let e = c.command(&stop).err();
    assert!(matches!(e, Some(ClientError::Timeout)), "{e:?}");
    c.transport().replies = VecDeque::from(vec![b"0P1,100\r".to_vec()]);
    let r = c.settle(&stop, ClientError::Timeout);
    assert!(matches!(r, Err(ClientError::Timeout)), "{r:?}");
    // A late refusal is the device's error.
    let _ = c.command(&stop);
    c.transport().replies = VecDeque::from(vec![b"0E1\r0P1,100\r".to_vec()]);
    let r = c.settle(&stop, ClientError::Timeout);
    assert!(
        matches!(r, Err(ClientError::Device(ErrorCode::MotorRunning))),
        "{r:?}"
    );
}
