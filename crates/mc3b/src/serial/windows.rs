//! The serial line on Windows.

use std::io;

pub(super) type SerialLine = serialport::COMPort;

/// `COMn`; serialport opens it as `\\.\COMn`, which also reaches COM10 and above.
pub(super) fn com_port_device(n: u32) -> String {
    format!("COM{n}")
}

pub(super) fn pseudo_terminal_pair() -> io::Result<(SerialLine, SerialLine)> {
    Err(io::Error::new(
        io::ErrorKind::Unsupported,
        "Windows has no pseudo-terminals, which the MC3B emulator needs: run it on Linux \
         (on Windows the library talks to a real MC3B on COM<N>, or the port MCL_COM<N> names)",
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn com_ports_are_named_comn() {
        assert_eq!(com_port_device(1), "COM1");
        assert_eq!(com_port_device(12), "COM12");
    }

    #[test]
    fn windows_has_no_pseudo_terminals() {
        let e = pseudo_terminal_pair().err().expect("refused");
        assert_eq!(e.kind(), io::ErrorKind::Unsupported);
    }
}
