//! The functions a built library exports: a shared library's dynamic symbols (`nm -D`)
//! or a Windows DLL's export table (`objdump -p`).

use std::path::Path;
use std::process::Command;

/// The exported functions of a library: of a Windows DLL its export table (`objdump -p`:
/// the names `DllImport` and VB6 `Declare` look up), else the exported, defined text
/// symbols of a shared library (`nm -D --defined-only`).
pub fn exports(lib: &Path) -> Result<Vec<String>, String> {
    if is_windows_dll(lib) {
        return dll_exports(lib);
    }
    let out = Command::new("nm")
        .args(["-D", "--defined-only"])
        .arg(lib)
        .output()
        .map_err(|e| format!("nm: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "nm -D {}: {}",
            lib.display(),
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    Ok(String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter_map(|l| {
            let f: Vec<&str> = l.split_whitespace().collect();
            match f.as_slice() {
                [_, "T", name] => Some(name.to_string()),
                _ => None,
            }
        })
        .collect())
}

/// Whether `lib` is a Windows DLL (PE), by its first bytes: `MZ`, then the `PE\0\0`
/// signature where the DOS header's `e_lfanew` (offset 0x3c) points.
fn is_windows_dll(lib: &Path) -> bool {
    let Ok(b) = std::fs::read(lib) else {
        return false;
    };
    let pe_at = b
        .get(0x3c..0x40)
        .and_then(|s| <[u8; 4]>::try_from(s).ok())
        .map(|s| u32::from_le_bytes(s) as usize);
    b.starts_with(b"MZ") && pe_at.and_then(|at| b.get(at..at + 4)) == Some(&b"PE\0\0"[..])
}

/// The names of a DLL's export table (`objdump -p`, section "[Ordinal/Name Pointer]
/// Table").
fn dll_exports(lib: &Path) -> Result<Vec<String>, String> {
    let out = Command::new("objdump")
        .arg("-p")
        .arg(lib)
        .output()
        .map_err(|e| format!("objdump: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "objdump -p {}: {}",
            lib.display(),
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    let text = String::from_utf8_lossy(&out.stdout);
    let names: Vec<String> = text
        .lines()
        .skip_while(|l| !l.contains("[Ordinal/Name Pointer] Table"))
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .filter_map(|l| l.split_once(']').map(|(_, n)| n.trim().to_string()))
        .collect();
    if names.is_empty() {
        return Err(format!("{}: no export table", lib.display()));
    }
    Ok(names)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_windows_dll_is_told_by_its_pe_signature() {
        let dir = std::env::temp_dir().join(format!("mccl-bindings-pe-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        // MZ, e_lfanew = 0x40 at 0x3c, "PE\0\0" at 0x40.
        let mut pe = vec![0u8; 0x48];
        pe[..2].copy_from_slice(b"MZ");
        pe[0x3c] = 0x40;
        pe[0x40..0x44].copy_from_slice(b"PE\0\0");
        let dll = dir.join("x.dll");
        std::fs::write(&dll, &pe).unwrap();
        assert!(is_windows_dll(&dll));
        // An ELF library, an MZ stub without the signature, a missing file.
        let elf = dir.join("x.so");
        std::fs::write(&elf, b"\x7fELF\x02\x01\x01\0\0\0\0\0\0\0\0\0").unwrap();
        assert!(!is_windows_dll(&elf));
        pe[0x40] = b'X';
        std::fs::write(&dll, &pe).unwrap();
        assert!(!is_windows_dll(&dll));
        assert!(!is_windows_dll(&dir.join("missing.dll")));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
