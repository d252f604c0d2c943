//! The VB6 writer: `vb-bindings/MCCLPCI_IMP.bas`.

use super::*;

pub(super) fn vb6_scalar(t: &CType) -> Result<&'static str, String> {
    Ok(match t {
        CType::Int { bytes: 1, .. } | CType::Char => "Byte",
        CType::Int { bytes: 2, .. } => "Integer",
        CType::Int { bytes: 4, .. } | CType::Bool | CType::CLong { .. } => "Long",
        CType::Int { bytes: 8, .. } => "Currency",
        CType::Float(8) => "Double",
        CType::Float(_) => "Single",
        CType::Ptr(_) | CType::Callback(_) => "Long",
        t => return Err(format!("no VB6 type for {t:?}")),
    })
}

pub(super) fn vb6_param(p: &Param) -> Result<String, String> {
    let n = vb6_name(&p.name);
    Ok(match &p.ty {
        CType::Callback(_) => format!("ByVal {n} As Long"),
        CType::Struct(s) => return Err(format!("{}: struct {s} by value", p.name)),
        CType::Ptr(inner) => match inner.as_ref() {
            CType::Char => format!("ByVal {n} As String"),
            CType::Void => format!("ByRef {n} As Any"),
            CType::Struct(s) => format!("ByRef {n} As {s}"),
            CType::Ptr(_) | CType::Callback(_) => format!("ByRef {n} As Long"),
            t => format!("ByRef {n} As {}", vb6_scalar(t)?),
        },
        t => format!("ByVal {n} As {}", vb6_scalar(t)?),
    })
}

/// VB6 aligns UDT members to min(size, 4); the C (and .NET) layout aligns to 8. Returns
/// the padding (in bytes) to insert before each field and at the end so that the VB6 `Type`
/// has the C offsets and size.
pub fn vb6_padding(h: &Header, name: &str) -> Result<(Vec<usize>, usize), String> {
    let c = h.struct_layout(name, WIN)?;
    let s = h
        .find_struct(name)
        .ok_or_else(|| format!("unknown struct {name}"))?;
    let mut off = 0usize;
    let mut before = Vec::new();
    for (f, slot) in s.fields.iter().zip(&c.slots) {
        let (size, al) = vb6_size_align(h, &f.ty)?;
        let a = al.min(4);
        let aligned = off.div_ceil(a) * a;
        if slot.offset < aligned {
            return Err(format!(
                "{name}.{}: VB6 offset {aligned} beyond C offset {}",
                f.name, slot.offset
            ));
        }
        // Pad bytes (alignment 1) fill the whole gap from the end of the previous field.
        before.push(if aligned == slot.offset {
            0
        } else {
            slot.offset - off
        });
        off = slot.offset + size * f.count.unwrap_or(1);
    }
    Ok((before, c.size - off))
}

/// Size and VB6 alignment of a member (nested structs keep the C size thanks to padding).
pub(super) fn vb6_size_align(h: &Header, t: &CType) -> Result<(usize, usize), String> {
    match t {
        CType::Struct(s) => {
            let c = h.struct_layout(s, WIN)?;
            Ok((c.size, c.align.min(4)))
        }
        t => {
            let vb = Target {
                clong: 4,
                ptr: 4,
                max_align: 4,
            };
            h.size_align(t, vb)
        }
    }
}

/// Writes `vb-bindings/MCCLPCI_IMP.bas` (VB6, 32-bit Windows).
pub fn vb6(h: &Header) -> Result<String, String> {
    let mut o = String::from("Attribute VB_Name = \"MCCLPCI_IMP\"\n");
    for l in BANNER.lines() {
        let _ = writeln!(o, "' {l}");
    }
    o.push_str(
        "'
' VB6 declarations of the MCCLPCI_IMP library (32-bit Windows, stdcall): put the x86
' MCCLPCI_IMP.dll of `make windows` beside the program's .exe (or on the DLL path).
' * Types: WORD = Integer, DWORD/int/BOOL/long = Long, BYTE/char = Byte, double = Double,
'   float = Single, long long = Currency (raw 64 bits), char* = a pre-sized ByVal String
'   (e.g. s = Space$(16)), struct pointers = ByRef UDT, callbacks = ByVal Long (AddressOf
'   a procedure in a .bas module). Pass the first element of an array of UDTs (cards(0)) for
'   SYS_CARD_CONFIG arrays.
' * VB6 aligns UDT members to 4 bytes at most, C to 8: where that would change an offset or
'   the size, the Type carries explicit MCCL_pad* bytes so it matches the C layout exactly.
' * _YES_ and _NO_ are not legal VB6 names; use 1 and 0.
Option Explicit
",
    );
    o.push_str("\n' ---- Constants ----\n");
    for c in &h.consts {
        if c.name.starts_with('_') {
            let _ = writeln!(o, "' {} = {} (not a legal VB6 name)", c.name, c.value);
            continue;
        }
        let _ = writeln!(
            o,
            "Public Const {} As Long = {}",
            c.name,
            vb_const_value(c.value, true)
        );
    }
    o.push_str("\n' ---- Structures ----\n");
    for s in &h.structs {
        let (pads, tail) = vb6_padding(h, &s.name)?;
        let _ = writeln!(o, "Public Type {}", s.name);
        let mut npad = 0;
        for (f, pad) in s.fields.iter().zip(pads) {
            if pad > 0 {
                let _ = writeln!(o, "    MCCL_pad{npad}(0 To {}) As Byte", pad - 1);
                npad += 1;
            }
            let t = match &f.ty {
                CType::Struct(x) => x.clone(),
                t => vb6_scalar(t)?.to_string(),
            };
            match f.count {
                Some(n) => {
                    let _ = writeln!(o, "    {}(0 To {}) As {t}", vb6_name(&f.name), n - 1);
                }
                None => {
                    let _ = writeln!(o, "    {} As {t}", vb6_name(&f.name));
                }
            }
        }
        if tail > 0 {
            let _ = writeln!(
                o,
                "    MCCL_pad{npad}(0 To {}) As Byte ' VB6 aligns to 4, C to 8",
                tail - 1
            );
        }
        o.push_str("End Type\n\n");
    }
    o.push_str("' ---- Callbacks ----\n");
    for cb in &h.callbacks {
        let ps: Vec<String> = cb
            .params
            .iter()
            .map(|p| {
                let q = cb_param(p, cb.params.len());
                match &q.ty {
                    // An address (VB6 is 32-bit): read with CopyMemory.
                    CType::Ptr(i) if matches!(i.as_ref(), CType::Void) => {
                        Ok(format!("ByVal {} As Long", vb6_name(&q.name)))
                    }
                    _ => vb6_param(&q),
                }
            })
            .collect::<Result<_, _>>()?;
        let (kind, ret) = if cb.ret == CType::Void {
            ("Sub", String::new())
        } else {
            ("Function", format!(" As {}", vb6_scalar(&cb.ret)?))
        };
        let _ = writeln!(
            o,
            "' {}: {kind} MyIsr({}){ret}, passed as AddressOf MyIsr",
            cb.name,
            ps.join(", ")
        );
    }
    for (sec, funcs) in sections(h) {
        let _ = writeln!(o, "\n' ---- {sec} ----");
        for f in funcs {
            let ps = vb_params(f, vb6_param, true, true, |_| false)?;
            if f.ret == CType::Void {
                let _ = writeln!(o, "Public Declare Sub {} Lib \"{DLL}\" ({ps})", f.name);
            } else {
                let _ = writeln!(
                    o,
                    "Public Declare Function {} Lib \"{DLL}\" ({ps}) As {}",
                    f.name,
                    vb6_scalar(&f.ret)?
                );
            }
        }
    }
    Ok(o)
}
