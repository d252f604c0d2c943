//! The VB.NET writer: `vb-bindings/MCCL.vb`.

use super::*;

pub(super) fn vbnet_scalar(t: &CType, la: LongAs) -> Result<String, String> {
    Ok(match t {
        CType::Int { bytes, signed } => match (bytes, signed) {
            (1, true) => "SByte",
            (1, false) => "Byte",
            (2, true) => "Short",
            (2, false) => "UShort",
            (4, true) => "Integer",
            (4, false) => "UInteger",
            (8, true) => "Long",
            (8, false) => "ULong",
            _ => return Err(format!("no VB.NET type for a {bytes}-byte integer")),
        }
        .into(),
        CType::Bool => "Boolean".into(),
        CType::Char => "SByte".into(),
        // Only mcl.h has one, and the bindings cover MCCL.h and MCCL_Fun.h.
        CType::CBool => return Err("C99 bool: no VB.NET binding".into()),
        CType::CLong { signed } => match (la, signed) {
            (LongAs::Int, true) => "Integer",
            (LongAs::Int, false) => "UInteger",
            (LongAs::Long, true) => "Long",
            (LongAs::Long, false) => "ULong",
        }
        .into(),
        CType::Float(8) => "Double".into(),
        CType::Float(_) => "Single".into(),
        CType::Struct(s) => s.clone(),
        CType::Callback(c) => c.clone(),
        CType::Ptr(_) => "IntPtr".into(),
        CType::Void => return Err("void is not a VB.NET type".into()),
    })
}

pub(super) fn vbnet_param(p: &Param, la: LongAs, alt: bool) -> Result<String, String> {
    let n = vbnet_name(&p.name);
    Ok(match &p.ty {
        CType::Bool => format!("<MarshalAs(UnmanagedType.Bool)> ByVal {n} As Boolean"),
        CType::Ptr(inner) => match inner.as_ref() {
            CType::Char => format!("ByVal {n} As StringBuilder"),
            CType::Void | CType::Ptr(_) | CType::Callback(_) => format!("ByVal {n} As IntPtr"),
            CType::Bool => format!("<MarshalAs(UnmanagedType.Bool)> ByRef {n} As Boolean"),
            CType::Struct(s) if alt && is_struct_array(p) => format!("ByVal {n}() As {s}"),
            t => format!("ByRef {n} As {}", vbnet_scalar(t, la)?),
        },
        t => format!("ByVal {n} As {}", vbnet_scalar(t, la)?),
    })
}

/// Writes `vb-bindings/MCCL.vb` (VB.NET).
pub fn vbnet(h: &Header) -> Result<String, String> {
    let mut o = String::new();
    for l in BANNER.lines() {
        let _ = writeln!(o, "' {l}");
    }
    o.push_str(
        "'
' VB.NET binding of libMCCLPCI_IMP: the same declarations as csharp/MCCL.cs. Functions,
' constants and delegates are members of Module MCCL (callable unqualified); structures are
' at namespace level. Keep a delegate passed to MCC_Set*Routine in a Shared field while it is
' registered. C long is Integer-shaped; the native width is marshalled inside.
Option Strict On
Imports System
Imports System.Runtime.InteropServices
Imports System.Text
",
    );
    for s in &h.structs {
        let _ = writeln!(
            o,
            "\n<StructLayout(LayoutKind.Sequential)>\nPublic Structure {}",
            s.name
        );
        for f in &s.fields {
            let t = vbnet_scalar(&f.ty, LongAs::Int)?;
            let n = vbnet_name(&f.name);
            match (&f.ty, f.count) {
                (_, Some(c)) => {
                    let _ = writeln!(o, "    <MarshalAs(UnmanagedType.ByValArray, SizeConst:={c})> Public {n}() As {t}");
                }
                (CType::Bool, None) => {
                    let _ = writeln!(
                        o,
                        "    <MarshalAs(UnmanagedType.Bool)> Public {n} As Boolean"
                    );
                }
                _ => {
                    let _ = writeln!(o, "    Public {n} As {t}");
                }
            }
        }
        o.push_str("End Structure\n");
    }
    o.push_str("\nPublic Module MCCL\n");
    let _ = writeln!(o, "    Public Const DLL_NAME As String = \"{DLL}\"\n");
    for c in &h.consts {
        let t = if i32::try_from(c.value).is_ok() {
            "Integer"
        } else if u32::try_from(c.value).is_ok() {
            "UInteger"
        } else {
            "Long"
        };
        let _ = writeln!(
            o,
            "    Public Const {} As {t} = {}",
            vbnet_name(&c.name),
            vb_const_value(c.value, false)
        );
    }
    o.push_str(
        "\n    ' ---- Callback types (keep the delegate instance alive while registered) ----\n",
    );
    for cb in &h.callbacks {
        let ps: Vec<String> = cb
            .params
            .iter()
            .map(|p| {
                let q = cb_param(p, cb.params.len());
                vbnet_param(&q, LongAs::Int, false)
            })
            .collect::<Result<_, _>>()?;
        let _ = writeln!(
            o,
            "    <UnmanagedFunctionPointer(CallingConvention.Winapi)>"
        );
        if cb.ret == CType::Void {
            let _ = writeln!(o, "    Public Delegate Sub {}({})", cb.name, ps.join(", "));
        } else {
            let _ = writeln!(
                o,
                "    Public Delegate Function {}({}) As {}",
                cb.name,
                ps.join(", "),
                vbnet_scalar(&cb.ret, LongAs::Int)?
            );
        }
    }
    if h.funcs.iter().any(Func::has_clong) {
        o.push_str("\n    ' C long is 8 bytes on LP64 Unix and 4 on Windows (and on 32-bit systems).\n    Private ReadOnly NativeLongIs64 As Boolean = IntPtr.Size = 8 AndAlso Environment.OSVersion.Platform <> PlatformID.Win32NT\n");
    }
    for (sec, funcs) in sections(h) {
        let _ = writeln!(o, "\n    ' ---- {sec} ----");
        for f in funcs {
            vbnet_func(&mut o, f)?;
        }
    }
    o.push_str("End Module\n");
    Ok(o)
}

pub(super) fn vbnet_decl(
    o: &mut String,
    f: &Func,
    vis: &str,
    name: &str,
    la: LongAs,
    alt: bool,
    defaults: bool,
) -> Result<(), String> {
    let ps = vb_params(
        f,
        |p| vbnet_param(p, la, alt),
        false,
        defaults,
        |p| alt && is_struct_array(p),
    )?;
    let _ = writeln!(o, "    <DllImport(\"{DLL}\", EntryPoint:=\"{}\")>", f.name);
    if f.ret == CType::Void {
        let _ = writeln!(o, "    {vis} Sub {name}({ps})\n    End Sub");
    } else {
        let ra = if f.ret == CType::Bool {
            "<MarshalAs(UnmanagedType.Bool)> "
        } else {
            ""
        };
        let _ = writeln!(
            o,
            "    {vis} Function {name}({ps}) As {ra}{}\n    End Function",
            vbnet_scalar(&f.ret, la)?
        );
    }
    Ok(())
}

pub(super) fn vbnet_func(o: &mut String, f: &Func) -> Result<(), String> {
    if !f.has_clong() {
        vbnet_decl(o, f, "Public", &f.name, LongAs::Int, false, true)?;
        if has_alt(f) && f.params.iter().any(is_struct_array) {
            vbnet_decl(o, f, "Public", &f.name, LongAs::Int, true, true)?;
        }
        return Ok(());
    }
    vbnet_decl(
        o,
        f,
        "Private",
        &format!("{}_L32", f.name),
        LongAs::Int,
        false,
        false,
    )?;
    vbnet_decl(
        o,
        f,
        "Private",
        &format!("{}_L64", f.name),
        LongAs::Long,
        false,
        false,
    )?;
    let ps = vb_params(
        f,
        |p| vbnet_param(p, LongAs::Int, false),
        false,
        true,
        |_| false,
    )?;
    let args: Vec<String> = f.params.iter().map(|p| vbnet_name(&p.name)).collect();
    let (kw, ret) = if f.ret == CType::Void {
        ("Sub", String::new())
    } else {
        (
            "Function",
            format!(" As {}", vbnet_scalar(&f.ret, LongAs::Int)?),
        )
    };
    let _ = writeln!(
        o,
        "    Public {kw} {}({ps}){ret}\n        If NativeLongIs64 Then",
        f.name
    );
    let mut args64 = Vec::new();
    let mut back = Vec::new();
    for (i, p) in f.params.iter().enumerate() {
        let n = vbnet_name(&p.name);
        match &p.ty {
            CType::Ptr(inner) if matches!(inner.as_ref(), CType::CLong { .. }) => {
                let signed = matches!(inner.as_ref(), CType::CLong { signed: true });
                let (wide, conv) = if signed {
                    ("Long", "CInt")
                } else {
                    ("ULong", "CUInt")
                };
                let _ = writeln!(o, "            Dim t{i} As {wide} = {n}");
                args64.push(format!("t{i}"));
                back.push(format!("            {n} = {conv}(t{i})"));
            }
            _ => args64.push(n),
        }
    }
    let call = format!("{}_L64({})", f.name, args64.join(", "));
    if f.ret == CType::Void {
        let _ = writeln!(o, "            {call}");
        for b in &back {
            let _ = writeln!(o, "{b}");
        }
        let _ = writeln!(o, "            Return");
    } else {
        let _ = writeln!(
            o,
            "            Dim r As {} = {call}",
            vbnet_scalar(&f.ret, LongAs::Long)?
        );
        for b in &back {
            let _ = writeln!(o, "{b}");
        }
        let conv = match f.ret {
            CType::CLong { signed: true } => "CInt(r)",
            CType::CLong { signed: false } => "CUInt(r)",
            _ => "r",
        };
        let _ = writeln!(o, "            Return {conv}");
    }
    let ret_kw = if f.ret == CType::Void { "" } else { "Return " };
    let _ = writeln!(
        o,
        "        End If\n        {ret_kw}{}_L32({})\n    End {kw}",
        f.name,
        args.join(", ")
    );
    Ok(())
}
