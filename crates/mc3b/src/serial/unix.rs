//! The serial line on Linux (and other Unix systems).

use std::io;

pub(super) type SerialLine = serialport::TTYPort;

/// COM1 = `/dev/ttyS0`, the usual Linux name of the first serial port.
pub(super) fn com_port_device(n: u32) -> String {
    format!("/dev/ttyS{}", n.saturating_sub(1))
}

pub(super) fn pseudo_terminal_pair() -> io::Result<(SerialLine, SerialLine)> {
    SerialLine::pair().map_err(io::Error::from)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn com_ports_are_the_serial_devices() {
        assert_eq!(com_port_device(1), "/dev/ttyS0");
        assert_eq!(com_port_device(77), "/dev/ttyS76");
    }
}
