//! Verification of a parsed binding against the C header model and the exports.

use super::*;

/// The ABI the C type has for a caller on a platform whose C `long` is `clong` bytes.
pub(super) fn c_abi(h: &Header, t: &CType, clong: u8) -> Abi {
    let pointee = |t: &CType| match t {
        CType::Int { bytes, .. } => Pointee::Int(*bytes),
        CType::Bool => Pointee::Int(4),
        CType::Char | CType::CBool => Pointee::Int(1),
        CType::CLong { .. } => Pointee::Int(clong),
        CType::Float(b) => Pointee::Float(*b),
        CType::Struct(s) => Pointee::Struct(h.canonical(s).to_string()),
        CType::Void => Pointee::Any,
        CType::Ptr(_) | CType::Callback(_) => Pointee::Int(8),
    };
    match t {
        CType::Void => Abi::Void,
        CType::Int { bytes, .. } => Abi::Int(*bytes),
        CType::Bool => Abi::Int(4),
        CType::Char | CType::CBool => Abi::Int(1),
        CType::CLong { .. } => Abi::Int(clong),
        CType::Float(b) => Abi::Float(*b),
        CType::Struct(s) => Abi::Struct(h.canonical(s).to_string()),
        CType::Callback(c) => Abi::Ptr(Pointee::Func(c.clone())),
        CType::Ptr(inner) => Abi::Ptr(pointee(inner)),
    }
}

pub(super) fn canon_abi(h: &Header, a: &Abi) -> Abi {
    match a {
        Abi::Struct(s) => Abi::Struct(h.canonical(&upper_struct(h, s)).to_string()),
        Abi::Ptr(Pointee::Struct(s)) => Abi::Ptr(Pointee::Struct(
            h.canonical(&upper_struct(h, s)).to_string(),
        )),
        a => a.clone(),
    }
}

/// VB names are case-insensitive: map a struct name to the header's spelling.
pub(super) fn upper_struct(h: &Header, s: &str) -> String {
    h.structs
        .iter()
        .find(|x| eqi(&x.name, s))
        .map(|x| x.name.clone())
        .unwrap_or_else(|| s.to_string())
}

/// Whether the binding's `b` is an acceptable declaration of C's `c` in `lang`.
pub(super) fn abi_ok(lang: Lang, c: &Abi, b: &Abi) -> bool {
    if c == b {
        return true;
    }
    match (c, b) {
        // IntPtr / As Any stand for any pointer, and void* accepts any pointer.
        (Abi::Ptr(_), Abi::Ptr(Pointee::Any)) | (Abi::Ptr(Pointee::Any), Abi::Ptr(_)) => true,
        // VB6 passes callbacks as `ByVal Long` (AddressOf; Win32 pointers are 4 bytes).
        (Abi::Ptr(Pointee::Func(_)), Abi::Int(4)) => lang == Lang::Vb6,
        _ => false,
    }
}

pub(super) fn show(a: &Abi) -> String {
    match a {
        Abi::Void => "void".into(),
        Abi::Int(w) => format!("{w}-byte integer by value"),
        Abi::Float(w) => format!("{w}-byte float by value"),
        Abi::Struct(s) => format!("struct {s} by value"),
        Abi::Ptr(Pointee::Int(w)) => format!("pointer to {w}-byte integer (by reference)"),
        Abi::Ptr(Pointee::Float(w)) => format!("pointer to {w}-byte float (by reference)"),
        Abi::Ptr(Pointee::Struct(s)) => format!("pointer to {s} (by reference)"),
        Abi::Ptr(Pointee::Func(f)) => format!("function pointer {f}"),
        Abi::Ptr(Pointee::Any) => "pointer".into(),
        Abi::Bad(r) => format!("invalid ({r})"),
    }
}

/// Compares a binding signature with a C one; returns the differences.
pub(super) fn sig_diff(
    h: &Header,
    lang: Lang,
    clong: u8,
    c_params: &[crate::model::Param],
    c_ret: &CType,
    params: &[BParam],
    ret: &Abi,
) -> Vec<String> {
    let mut d = Vec::new();
    if c_params.len() != params.len() {
        d.push(format!(
            "{} parameters, the C prototype has {}",
            params.len(),
            c_params.len()
        ));
        return d;
    }
    for (i, (cp, bp)) in c_params.iter().zip(params).enumerate() {
        let ca = c_abi(h, &cp.ty, clong);
        let ba = canon_abi(h, &bp.abi);
        if !abi_ok(lang, &ca, &ba) {
            d.push(format!(
                "parameter {} ({}): declared as {}, C has {}",
                i + 1,
                bp.name,
                show(&ba),
                show(&ca)
            ));
        }
    }
    let cr = c_abi(h, c_ret, clong);
    let br = canon_abi(h, ret);
    if !abi_ok(lang, &cr, &br) {
        d.push(format!(
            "return: declared as {}, C has {}",
            show(&br),
            show(&cr)
        ));
    }
    d
}

pub(super) fn vb_eq(lang: Lang, c: &str, b: &str) -> bool {
    match lang {
        Lang::CSharp => c == b,
        Lang::Vb6 => eqi(c, b) || eqi(&format!("{c}_"), b),
        Lang::VbNet => eqi(c, b),
    }
}

/// A binding struct's layout: `(field name, offset, size)` per field, total size, alignment.
pub(super) type BLayout = (Vec<(String, usize, usize)>, usize, usize);

/// Layout of a binding struct, computed from the binding's own declarations.
pub(super) fn b_layout(
    lang: Lang,
    b: &Binding,
    name: &str,
    seen: &mut Vec<String>,
) -> Result<BLayout, String> {
    if seen.iter().any(|s| eqi(s, name)) {
        return Err(format!("{name} contains itself"));
    }
    let s = b
        .structs
        .iter()
        .find(|s| eqi(&s.name, name))
        .ok_or_else(|| format!("struct {name} is not declared"))?;
    let max_align = if lang == Lang::Vb6 { 4 } else { 8 };
    seen.push(name.to_string());
    let mut off = 0usize;
    let mut align = 1usize;
    let mut out = Vec::new();
    for f in &s.fields {
        let (size, al) = match &f.elem {
            Elem::Int(w) | Elem::Float(w) => (usize::from(*w), usize::from(*w)),
            Elem::Struct(n) => {
                let (_, sz, al) = b_layout(lang, b, n, seen)?;
                (sz, al)
            }
            Elem::Bad(r) => return Err(format!("{}.{}: {r}", s.name, f.name)),
        };
        let a = al.clamp(1, max_align);
        off = off.div_ceil(a) * a;
        let n = f.count.unwrap_or(1);
        out.push((f.name.clone(), off, size * n));
        off += size * n;
        align = align.max(a);
    }
    seen.pop();
    Ok((out, off.div_ceil(align) * align, align))
}

pub(super) fn c_elem(h: &Header, t: &CType) -> Elem {
    match t {
        CType::Int { bytes, .. } => Elem::Int(*bytes),
        CType::Bool => Elem::Int(4),
        CType::Char => Elem::Int(1),
        CType::Float(b) => Elem::Float(*b),
        CType::Struct(s) => Elem::Struct(h.canonical(s).to_string()),
        other => Elem::Bad(format!("{other:?}")),
    }
}

pub(super) fn is_pad(name: &str) -> bool {
    name.starts_with("MCCL_pad")
}

/// Checks one binding file against the header and the exported symbols.
pub fn verify(lang: Lang, file: &str, text: &str, h: &Header, exports: &[String]) -> Report {
    let mut r = Report::default();
    let b = match match lang {
        Lang::CSharp => parse_cs(file, text),
        Lang::Vb6 => parse_vb(file, text, true),
        Lang::VbNet => parse_vb(file, text, false),
    } {
        Ok(b) => b,
        Err(e) => {
            r.problems.push(e);
            return r;
        }
    };
    verify_binding(lang, file, &b, h, exports, &mut r);
    r
}

/// The checks on an already parsed binding.
pub fn verify_binding(
    lang: Lang,
    file: &str,
    b: &Binding,
    h: &Header,
    exports: &[String],
    r: &mut Report,
) {
    let mut p = |line: usize, m: String| r.problems.push(format!("{file}:{line}: {m}"));
    // --- functions
    let mut by_entry: BTreeMap<&str, Vec<&Extern>> = BTreeMap::new();
    for e in &b.externs {
        by_entry.entry(e.entry.as_str()).or_default().push(e);
        if !e.lib.to_ascii_lowercase().starts_with("mcclpci_imp") {
            p(
                e.line,
                format!("{}: library {:?} is not MCCLPCI_IMP", e.name, e.lib),
            );
        }
        if let Some(c) = &e.conv {
            if !matches!(c.as_str(), "Winapi" | "StdCall") {
                p(e.line, format!("{}: calling convention {c}; MCC_CALL is stdcall on Windows (use the default/Winapi)", e.name));
            }
        }
        if !exports.iter().any(|s| s == &e.entry) {
            p(
                e.line,
                format!(
                    "{}: entry point {} is not exported by the library",
                    e.name, e.entry
                ),
            );
        }
        if !h.funcs.iter().any(|f| f.name == e.entry) {
            p(
                e.line,
                format!(
                    "{}: entry point {} is not declared in MCCL_Fun.h",
                    e.name, e.entry
                ),
            );
        }
    }
    let mut n_externs = 0;
    let mut n_params = 0;
    for f in &h.funcs {
        r.functions += 1;
        let decls = by_entry.get(f.name.as_str()).cloned().unwrap_or_default();
        if decls.is_empty() {
            p(
                0,
                format!(
                    "{} is missing (declared in MCCL_Fun.h{})",
                    f.name,
                    if exports.contains(&f.name) {
                        ", exported by the library"
                    } else {
                        ""
                    }
                ),
            );
            continue;
        }
        let mut covered = [false, false]; // clong 4, clong 8
        for e in &decls {
            n_externs += 1;
            n_params += e.params.len();
            let d4 = sig_diff(h, lang, 4, &f.params, &f.ret, &e.params, &e.ret);
            let d8 = sig_diff(h, lang, 8, &f.params, &f.ret, &e.params, &e.ret);
            covered[0] |= d4.is_empty();
            covered[1] |= d8.is_empty();
            if d4.is_empty() || (d8.is_empty() && lang != Lang::Vb6) {
                continue;
            }
            let d = if lang == Lang::Vb6 || !f.has_clong() {
                d4
            } else {
                d8
            };
            for m in d {
                p(e.line, format!("{}: {m}", e.name));
            }
        }
        if f.has_clong() && lang != Lang::Vb6 {
            for (ok, w) in covered.iter().zip([4, 8]) {
                if !ok {
                    p(
                        decls[0].line,
                        format!(
                            "{}: no declaration for a {w}-byte C long (needed on {})",
                            f.name,
                            if w == 4 { "Windows" } else { "LP64 Linux" }
                        ),
                    );
                }
            }
        }
        // Callable by its own name with the C parameter count.
        let callable = decls
            .iter()
            .any(|e| e.public && vb_eq(lang, &f.name, &e.name) && e.params.len() == f.params.len())
            || b.methods
                .iter()
                .any(|m| vb_eq(lang, &f.name, &m.name) && m.nparams == f.params.len());
        if !callable {
            p(
                decls[0].line,
                format!(
                    "{}: no public method of that name with {} parameters",
                    f.name,
                    f.params.len()
                ),
            );
        }
    }
    for s in exports.iter().filter(|s| s.starts_with("MCC_")) {
        if !by_entry.contains_key(s.as_str()) && !h.funcs.iter().any(|f| &f.name == s) {
            p(
                0,
                format!("{s} is exported by the library but declared nowhere"),
            );
        }
    }
    // --- structs
    let mut n_structs = 0;
    let mut n_fields = 0;
    for cs in &h.structs {
        let Some(bs) = b.structs.iter().find(|s| vb_eq(lang, &cs.name, &s.name)) else {
            p(0, format!("struct {} is missing", cs.name));
            continue;
        };
        n_structs += 1;
        if !bs.sequential {
            p(
                bs.line,
                format!(
                    "{}: not [StructLayout(LayoutKind.Sequential)] with the default pack",
                    bs.name
                ),
            );
        }
        let named: Vec<&BField> = bs.fields.iter().filter(|f| !is_pad(&f.name)).collect();
        if named.len() != cs.fields.len() {
            p(
                bs.line,
                format!(
                    "{}: {} fields, C has {}",
                    bs.name,
                    named.len(),
                    cs.fields.len()
                ),
            );
        }
        for (i, (cf, bf)) in cs.fields.iter().zip(&named).enumerate() {
            n_fields += 1;
            if !vb_eq(lang, &cf.name, &bf.name) {
                p(
                    bs.line,
                    format!(
                        "{}: field {} is {}, C has {}",
                        bs.name,
                        i + 1,
                        bf.name,
                        cf.name
                    ),
                );
            }
            let ce = c_elem(h, &cf.ty);
            let be = match &bf.elem {
                Elem::Struct(s) => Elem::Struct(h.canonical(&upper_struct(h, s)).to_string()),
                e => e.clone(),
            };
            if ce != be {
                p(
                    bs.line,
                    format!("{}.{}: element {:?}, C has {:?}", bs.name, bf.name, be, ce),
                );
            }
            if cf.count != bf.count {
                p(
                    bs.line,
                    format!(
                        "{}.{}: array length {:?}, C has {:?}",
                        bs.name, bf.name, bf.count, cf.count
                    ),
                );
            }
        }
        match (
            b_layout(lang, b, &bs.name, &mut Vec::new()),
            h.struct_layout(&cs.name, WIN),
        ) {
            (Ok((slots, size, _)), Ok(cl)) => {
                let named: Vec<&(String, usize, usize)> =
                    slots.iter().filter(|s| !is_pad(&s.0)).collect();
                for (bsl, csl) in named.iter().zip(&cl.slots) {
                    if bsl.1 != csl.offset {
                        p(
                            bs.line,
                            format!(
                                "{}.{}: offset {}, C has {}",
                                bs.name, bsl.0, bsl.1, csl.offset
                            ),
                        );
                    }
                }
                if size != cl.size {
                    p(
                        bs.line,
                        format!("{}: size {size}, C has {}", bs.name, cl.size),
                    );
                }
                if let Some((_, known)) = KNOWN_SIZES.iter().find(|(n, _)| *n == cs.name) {
                    if cl.size != *known {
                        p(
                            bs.line,
                            format!(
                                "{}: the C header gives {} bytes, the vendor layout is {known}",
                                cs.name, cl.size
                            ),
                        );
                    }
                }
            }
            (Err(e), _) | (_, Err(e)) => p(bs.line, e),
        }
    }
    for bs in &b.structs {
        if !h.structs.iter().any(|c| vb_eq(lang, &c.name, &bs.name)) {
            p(bs.line, format!("struct {} is not in MCCL.h", bs.name));
        }
    }
    // --- delegates (not in VB6: callbacks are AddressOf Longs there)
    let mut n_delegates = 0;
    if lang != Lang::Vb6 {
        for cb in &h.callbacks {
            let Some(d) = b.delegates.iter().find(|d| vb_eq(lang, &cb.name, &d.name)) else {
                p(0, format!("delegate {} is missing", cb.name));
                continue;
            };
            n_delegates += 1;
            for m in sig_diff(h, lang, 4, &cb.params, &cb.ret, &d.params, &d.ret) {
                p(d.line, format!("delegate {}: {m}", d.name));
            }
            if let Some(c) = &d.conv {
                if !matches!(c.as_str(), "Winapi" | "StdCall") {
                    p(d.line, format!("delegate {}: calling convention {c}; MCC_CALLBACK is stdcall on Windows", d.name));
                }
            }
        }
    }
    // --- constants
    let mut n_consts = 0;
    for c in &h.consts {
        if lang == Lang::Vb6 && c.name.starts_with('_') {
            continue;
        }
        match b.consts.iter().find(|(n, _, _)| vb_eq(lang, &c.name, n)) {
            None => p(0, format!("constant {} is missing", c.name)),
            Some((n, v, line)) => {
                n_consts += 1;
                let same = *v == c.value
                    || (lang == Lang::Vb6
                        && u32::try_from(c.value).is_ok_and(|u| i64::from(u) == *v));
                if !same {
                    p(*line, format!("constant {n} = {v}, C has {}", c.value));
                }
            }
        }
    }
    r.externs = n_externs;
    r.params = n_params;
    r.structs = n_structs;
    r.fields = n_fields;
    r.delegates = n_delegates;
    r.consts = n_consts;
}
