//! The serial ports of the system, for the port selection dialog (§5.1).

use serde::Serialize;
use serialport::SerialPortType;

/// One port: its device path and what kind of port it is.
#[derive(Debug, Clone, Serialize, PartialEq, Eq)]
pub struct PortInfo {
    /// Device path (`/dev/ttyUSB0`).
    pub path: String,
    /// "USB 0403:6001 FT232R USB UART", "PCI", "Bluetooth" or "serial".
    pub kind: String,
}

/// The system's serial ports, sorted by path. Pseudo-terminals (an emulator's) are not
/// among them: the dialog takes a typed path too. A listing that fails is empty.
pub fn list() -> Vec<PortInfo> {
    // serialport reads sysfs on Linux; it panics where /sys/class/tty is missing.
    let found = std::panic::catch_unwind(serialport::available_ports)
        .ok()
        .and_then(Result::ok)
        .unwrap_or_default();
    let mut ports: Vec<PortInfo> = found
        .into_iter()
        .map(|p| PortInfo {
            kind: match p.port_type {
                SerialPortType::UsbPort(u) => {
                    let mut k = format!("USB {:04x}:{:04x}", u.vid, u.pid);
                    if let Some(prod) = u.product {
                        k.push(' ');
                        k.push_str(&prod);
                    }
                    k
                }
                SerialPortType::PciPort => "PCI".into(),
                SerialPortType::BluetoothPort => "Bluetooth".into(),
                SerialPortType::Unknown => "serial".into(),
            },
            path: p.port_name,
        })
        .collect();
    ports.sort_by_key(|p| natural(&p.path));
    ports
}

/// Sort key that puts ttyS2 before ttyS10.
fn natural(s: &str) -> (String, u64) {
    let digits = s.len() - s.trim_end_matches(|c: char| c.is_ascii_digit()).len();
    let (head, tail) = s.split_at(s.len() - digits);
    (head.to_string(), tail.parse().unwrap_or(0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn natural_order() {
        let mut v = vec!["/dev/ttyS10", "/dev/ttyS2", "/dev/ttyACM0", "/dev/ttyS0"];
        v.sort_by_key(|s| natural(s));
        assert_eq!(
            v,
            ["/dev/ttyACM0", "/dev/ttyS0", "/dev/ttyS2", "/dev/ttyS10"]
        );
    }
}
