//! The serial line to an MC3B: the port as the system names and opens it, and the
//! [`Transport`] over it. The line is RS-232 at 19200 baud, 8 data bits, no parity, one
//! stop bit, no flow control (§3.2).
//!
//! On a pseudo-terminal the modem-control ioctls (DTR/RTS/CTS...) fail with `ENOTTY`;
//! the client never needs them, so nothing here sets or reads them.
//!
//! What differs between the systems is one file each (`serial/unix.rs`,
//! `serial/windows.rs`), both implementing every item of the table:
//!
//! | | Linux (Unix) | Windows |
//! |---|---|---|
//! | [`SerialLine`] | `serialport::TTYPort` | `serialport::COMPort` |
//! | [`com_port_device`] | COM N is `/dev/ttyS<N-1>` | COM N is `COMN` |
//! | [`pseudo_terminal_pair`] (the emulator's line) | `openpty` | refused: Windows has none |

use std::io;
use std::time::Duration;

use serialport::{ClearBuffer, DataBits, FlowControl, Parity, SerialPort, StopBits};

use crate::client::Transport;

#[cfg(unix)]
mod unix;
#[cfg(unix)]
use unix as os;

#[cfg(windows)]
mod windows;
#[cfg(windows)]
use windows as os;

/// Baud rate of the MC3B (fixed, §2.2).
pub const BAUD_RATE: u32 = 19_200;

/// A serial port of this system (`serialport::TTYPort` or `serialport::COMPort`).
pub type SerialLine = os::SerialLine;

/// The device name of COM port `n` (1 = COM1) when nothing else names it.
pub fn com_port_device(n: u32) -> String {
    os::com_port_device(n)
}

/// A connected pseudo-terminal pair `(master, slave)`: a serial line whose other end is
/// this program (the emulator's). `Err` on a system without pseudo-terminals.
pub fn pseudo_terminal_pair() -> io::Result<(SerialLine, SerialLine)> {
    os::pseudo_terminal_pair()
}

/// Open a serial device (`/dev/ttyS0`, `COM1`, ...) at 19200 8N1 without flow control.
pub fn open_port(path: &str, timeout: Duration) -> Result<SerialLine, serialport::Error> {
    let builder = serialport::new(path, BAUD_RATE)
        .data_bits(DataBits::Eight)
        .parity(Parity::None)
        .stop_bits(StopBits::One)
        .flow_control(FlowControl::None)
        .timeout(timeout);
    let port = SerialLine::open(&builder)?;
    // Best effort: a pty may refuse some tty requests.
    let _ = port.clear(ClearBuffer::All);
    Ok(port)
}

fn serial_send(port: &mut dyn SerialPort, data: &[u8]) -> io::Result<()> {
    port.write_all(data)?;
    port.flush()
}

fn serial_recv(port: &mut dyn SerialPort, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
    port.set_timeout(timeout.max(Duration::from_millis(1)))
        .map_err(io::Error::from)?;
    match port.read(buf) {
        Ok(0) => {
            // EOF on a tty: the other side hung up.
            Err(io::Error::new(
                io::ErrorKind::BrokenPipe,
                "serial line hung up",
            ))
        }
        Ok(n) => Ok(n),
        Err(e) if e.kind() == io::ErrorKind::TimedOut => Ok(0),
        Err(e) if e.kind() == io::ErrorKind::Interrupted => Ok(0),
        Err(e) => Err(e),
    }
}

impl Transport for SerialLine {
    fn send(&mut self, data: &[u8]) -> io::Result<()> {
        serial_send(self, data)
    }
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        serial_recv(self, buf, timeout)
    }
    fn discard_input(&mut self) -> io::Result<()> {
        self.clear(ClearBuffer::Input).map_err(io::Error::from)
    }
}

impl Transport for Box<dyn SerialPort> {
    fn send(&mut self, data: &[u8]) -> io::Result<()> {
        serial_send(self.as_mut(), data)
    }
    fn recv(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        serial_recv(self.as_mut(), buf, timeout)
    }
    fn discard_input(&mut self) -> io::Result<()> {
        self.clear(ClearBuffer::Input).map_err(io::Error::from)
    }
}
