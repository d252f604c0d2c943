//! The C# writer: `csharp/MCCL.cs`.

use super::*;

pub(super) fn cs_scalar(t: &CType, la: LongAs) -> Result<String, String> {
    Ok(match t {
        CType::Int { bytes, signed } => match (bytes, signed) {
            (1, true) => "sbyte",
            (1, false) => "byte",
            (2, true) => "short",
            (2, false) => "ushort",
            (4, true) => "int",
            (4, false) => "uint",
            (8, true) => "long",
            (8, false) => "ulong",
            _ => return Err(format!("no C# type for a {bytes}-byte integer")),
        }
        .into(),
        CType::Bool => "bool".into(),
        CType::Char => "sbyte".into(),
        // Only mcl.h has one, and the bindings cover MCCL.h and MCCL_Fun.h.
        CType::CBool => return Err("C99 bool: no C# binding".into()),
        CType::CLong { signed } => match (la, signed) {
            (LongAs::Int, true) => "int",
            (LongAs::Int, false) => "uint",
            (LongAs::Long, true) => "long",
            (LongAs::Long, false) => "ulong",
        }
        .into(),
        CType::Float(8) => "double".into(),
        CType::Float(_) => "float".into(),
        CType::Struct(s) => s.clone(),
        CType::Callback(c) => c.clone(),
        CType::Ptr(_) => "IntPtr".into(),
        CType::Void => "void".into(),
    })
}

/// One C# parameter: `(attribute prefix, type with ref/array, name)`.
pub(super) fn cs_param(p: &Param, la: LongAs, alt: bool) -> Result<String, String> {
    let name = cs_name(&p.name);
    Ok(match &p.ty {
        CType::Bool => format!("[MarshalAs(UnmanagedType.Bool)] bool {name}"),
        CType::Ptr(inner) => match inner.as_ref() {
            CType::Char if alt => format!("byte[] {name}"),
            CType::Char => format!("StringBuilder {name}"),
            CType::Void | CType::Ptr(_) | CType::Callback(_) => format!("IntPtr {name}"),
            CType::Bool => format!("[MarshalAs(UnmanagedType.Bool)] ref bool {name}"),
            CType::Struct(s) if alt && is_struct_array(p) => format!("{s}[] {name}"),
            t => format!("ref {} {name}", cs_scalar(t, la)?),
        },
        t => format!("{} {name}", cs_scalar(t, la)?),
    })
}

/// The C# default value of a parameter, if C# can express it.
pub(super) fn cs_default(p: &Param) -> Option<String> {
    let d = p.default.as_ref()?;
    match &p.ty {
        CType::Ptr(_) | CType::Callback(_) | CType::Struct(_) => None,
        CType::Bool => Some(if d == "0" { "false" } else { "true" }.into()),
        _ => Some(d.clone()),
    }
}

pub(super) fn int_const_cs(c: &Const) -> String {
    if i32::try_from(c.value).is_ok() {
        format!("public const int {} = {};", c.name, c.value)
    } else if u32::try_from(c.value).is_ok() {
        format!("public const uint {} = {};", c.name, c.value)
    } else {
        format!("public const long {} = {};", c.name, c.value)
    }
}

/// Writes `csharp/MCCL.cs`.
pub fn csharp(h: &Header) -> Result<String, String> {
    let mut o = String::new();
    for l in BANNER.lines() {
        let _ = writeln!(o, "// {l}");
    }
    o.push_str(
        "//
// C# binding of libMCCLPCI_IMP (drop-in for the vendor's MCCLPCI_IMP.dll). Vendor code such as
// `MCCL.MCC_GetCurPos(ref x, ..., group)` compiles against it unchanged: the functions,
// constants and delegates are members of the global static class MCCL; the structs live at
// global level. C# 7.2 (mcs) and later.
// * Library lookup: [DllImport(\"MCCLPCI_IMP.dll\")]. On Windows .NET loads MCCLPCI_IMP.dll
//   from the application's folder (then the system's DLL path): the x64 DLL of `make windows`
//   for a 64-bit process, the x86 one for a 32-bit process (x86 or AnyCPU with Prefer 32-bit).
//   Mono/.NET on Linux find libMCCLPCI_IMP.so via LD_LIBRARY_PATH, the application directory,
//   or the installed aliases libMCCLPCI_IMP.dll.so / MCCLPCI_IMP.dll.so.
// * Callbacks: keep the delegate you pass to MCC_Set*Routine alive (a static field) for as long
//   as the library may call it; a collected delegate crashes the process at the next call.
//   Callbacks run on the library's engine thread; an exception escaping them is fatal.
// * Types: WORD=ushort, DWORD=uint, int=int, BYTE=byte, char=sbyte, BOOL=bool (4-byte Win32
//   BOOL), char* = StringBuilder (or byte[]), T* = ref T, SYS_CARD_CONFIG* = ref or array.
//   C long is int-shaped here; the native width (4 on Windows, 8 on LP64 Linux) is marshalled
//   inside. MCC_GetVersion has a StringBuilder and a byte[] overload (so pass a buffer, not null).
// * Calling convention: the platform default (Winapi) for functions and callback delegates,
//   i.e. stdcall on 32-bit Windows like the vendor's MCC_CALL/MCC_CALLBACK; x86-64 has only one.
using System;
using System.Runtime.InteropServices;
using System.Text;
",
    );
    // Structs at global level.
    for s in &h.structs {
        let _ = writeln!(
            o,
            "\n[StructLayout(LayoutKind.Sequential)]\npublic struct {}\n{{",
            s.name
        );
        for f in &s.fields {
            if f.ty.has_clong() {
                return Err(format!(
                    "{}.{}: a C long in a struct has no portable layout",
                    s.name, f.name
                ));
            }
            let t = cs_scalar(&f.ty, LongAs::Int)?;
            match (&f.ty, f.count) {
                (_, Some(n)) => {
                    let _ = writeln!(
                        o,
                        "    [MarshalAs(UnmanagedType.ByValArray, SizeConst = {n})]\n    public {t}[] {};",
                        cs_name(&f.name)
                    );
                }
                (CType::Bool, None) => {
                    let _ = writeln!(
                        o,
                        "    [MarshalAs(UnmanagedType.Bool)]\n    public bool {};",
                        cs_name(&f.name)
                    );
                }
                _ => {
                    let _ = writeln!(o, "    public {t} {};", cs_name(&f.name));
                }
            }
        }
        o.push_str("}\n");
    }
    o.push_str("\n/// <summary>The MCCL functions, constants and callback types.</summary>\npublic static class MCCL\n{\n");
    let _ = writeln!(o, "    /// <summary>The library name used by every DllImport.</summary>\n    public const string DLL_NAME = \"{DLL}\";\n");
    for c in &h.consts {
        let _ = writeln!(o, "    {}", int_const_cs(c));
    }
    o.push_str(
        "\n    // ---- Callback types (keep the delegate instance alive while registered) ----\n",
    );
    for cb in &h.callbacks {
        let ps: Vec<String> = cb
            .params
            .iter()
            .map(|p| {
                let q = cb_param(p, cb.params.len());
                cs_param(&q, LongAs::Int, false)
            })
            .collect::<Result<_, _>>()?;
        let ret = cs_scalar(&cb.ret, LongAs::Int)?;
        let ra = if cb.ret == CType::Bool {
            "    [return: MarshalAs(UnmanagedType.Bool)]\n"
        } else {
            ""
        };
        if cb.has_clong() {
            return Err(format!(
                "{}: a C long in a callback has no portable delegate",
                cb.name
            ));
        }
        let _ = writeln!(
            o,
            "    [UnmanagedFunctionPointer(CallingConvention.Winapi)]\n{ra}    public delegate {ret} {}({});",
            cb.name,
            ps.join(", ")
        );
    }
    if h.funcs.iter().any(Func::has_clong) {
        o.push_str("\n    // C long is 8 bytes on LP64 Unix and 4 on Windows (and on 32-bit systems).\n    private static readonly bool NativeLongIs64 = IntPtr.Size == 8 && Environment.OSVersion.Platform != PlatformID.Win32NT;\n");
    }
    for (sec, funcs) in sections(h) {
        let _ = writeln!(o, "\n    // ---- {sec} ----");
        for f in funcs {
            cs_func(&mut o, f)?;
        }
    }
    o.push_str("}\n");
    Ok(o)
}

pub(super) fn cs_ret(f: &Func, la: LongAs) -> Result<(String, &'static str), String> {
    let attr = if f.ret == CType::Bool {
        "    [return: MarshalAs(UnmanagedType.Bool)]\n"
    } else {
        ""
    };
    Ok((cs_scalar(&f.ret, la)?, attr))
}

pub(super) fn cs_params(f: &Func, la: LongAs, alt: bool, defaults: bool) -> Result<String, String> {
    let from = if defaults {
        defaults_from(&f.params, |p| {
            cs_default(p).is_some() && !(alt && is_struct_array(p))
        })
    } else {
        f.params.len()
    };
    let mut v = Vec::new();
    for (i, p) in f.params.iter().enumerate() {
        let mut s = cs_param(p, la, alt)?;
        if i >= from {
            if let Some(d) = cs_default(p) {
                let _ = write!(s, " = {d}");
            }
        }
        v.push(s);
    }
    Ok(v.join(", "))
}

pub(super) fn cs_func(o: &mut String, f: &Func) -> Result<(), String> {
    let imp = format!("    [DllImport(\"{DLL}\", EntryPoint = \"{}\")]\n", f.name);
    if !f.has_clong() {
        let (ret, ra) = cs_ret(f, LongAs::Int)?;
        let _ = writeln!(
            o,
            "{imp}{ra}    public static extern {ret} {}({});",
            f.name,
            cs_params(f, LongAs::Int, false, true)?
        );
        if has_alt(f) {
            let _ = writeln!(
                o,
                "{imp}{ra}    public static extern {ret} {}({});",
                f.name,
                cs_params(f, LongAs::Int, true, true)?
            );
        }
        return Ok(());
    }
    // C long: two private externs and an int-shaped public wrapper.
    for (la, suffix) in [(LongAs::Int, "L32"), (LongAs::Long, "L64")] {
        let (ret, ra) = cs_ret(f, la)?;
        let _ = writeln!(
            o,
            "{imp}{ra}    private static extern {ret} {}_{suffix}({});",
            f.name,
            cs_params(f, la, false, false)?
        );
    }
    let (ret, ra) = cs_ret(f, LongAs::Int)?;
    let ra = ra.replace("[return: MarshalAs(UnmanagedType.Bool)]", "");
    let ra = if ra.trim().is_empty() {
        String::new()
    } else {
        ra
    };
    let _ = writeln!(
        o,
        "{ra}    public static {ret} {}({})\n    {{\n        if (NativeLongIs64)\n        {{",
        f.name,
        cs_params(f, LongAs::Int, false, true)?
    );
    let mut args = Vec::new();
    let mut back = Vec::new();
    for (i, p) in f.params.iter().enumerate() {
        let n = cs_name(&p.name);
        match &p.ty {
            CType::Ptr(inner) if matches!(inner.as_ref(), CType::CLong { .. }) => {
                let signed = matches!(inner.as_ref(), CType::CLong { signed: true });
                let (wide, narrow) = if signed {
                    ("long", "int")
                } else {
                    ("ulong", "uint")
                };
                let _ = writeln!(o, "            {wide} t{i} = {n};");
                args.push(format!("ref t{i}"));
                back.push(format!("            {n} = unchecked(({narrow})t{i});"));
            }
            CType::Ptr(inner)
                if !matches!(
                    inner.as_ref(),
                    CType::Char | CType::Void | CType::Ptr(_) | CType::Callback(_)
                ) =>
            {
                args.push(format!("ref {n}"))
            }
            _ => args.push(n),
        }
    }
    let call = format!("{}_L64({})", f.name, args.join(", "));
    if f.ret == CType::Void {
        let _ = writeln!(o, "            {call};");
        for b in &back {
            let _ = writeln!(o, "{b}");
        }
        let _ = writeln!(o, "            return;");
    } else {
        let wide = cs_scalar(&f.ret, LongAs::Long)?;
        let _ = writeln!(o, "            {wide} r = {call};");
        for b in &back {
            let _ = writeln!(o, "{b}");
        }
        if f.ret.has_clong() {
            let _ = writeln!(o, "            return unchecked(({ret})r);");
        } else {
            let _ = writeln!(o, "            return r;");
        }
    }
    let args32: Vec<String> = f
        .params
        .iter()
        .map(|p| {
            let n = cs_name(&p.name);
            match &p.ty {
                CType::Ptr(inner)
                    if !matches!(
                        inner.as_ref(),
                        CType::Char | CType::Void | CType::Ptr(_) | CType::Callback(_)
                    ) =>
                {
                    format!("ref {n}")
                }
                _ => n,
            }
        })
        .collect();
    let ret_kw = if f.ret == CType::Void { "" } else { "return " };
    let _ = writeln!(
        o,
        "        }}\n        {ret_kw}{}_L32({});\n    }}",
        f.name,
        args32.join(", ")
    );
    Ok(())
}
