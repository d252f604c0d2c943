//! What the fuzzer sees of the headers: every function with the scalar kind each
//! parameter draws from, the structs it fills and the callback types it gives routines
//! for, taken from the one header model. A declaration the fuzzer cannot call (a pointer
//! return, a pointer to a pointer or to a callback, a `void` parameter) is an error: the
//! build fails instead of skipping it.

use mccl_header_model::{CType, Header};
use std::collections::BTreeMap;

/// A scalar C type as the fuzzer draws it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Prim {
    /// Integer of this many bits, signed or not.
    Int(u32, bool),
    /// `char` (drawn from letters and edge bytes).
    Char,
    /// `bool` / `_Bool`.
    Bool,
    /// `float`.
    F32,
    /// `double`.
    F64,
}

/// The base type of a parameter or field (pointers counted apart).
#[derive(Clone, Debug, PartialEq)]
pub enum Base {
    Void,
    Prim(Prim),
    Struct(String),
    Callback(String),
}

/// A parameter, struct field or return type.
#[derive(Clone, Debug)]
pub struct Decl {
    /// The C spelling of the type without the name (`const int *`).
    pub cty: String,
    /// The C spelling of the base type (`int`, `SYS_MAC_PARAM`).
    pub cbase: String,
    pub base: Base,
    pub ptr: usize,
    pub is_const: bool,
    /// The name, empty when the header leaves it out.
    pub name: String,
    /// Array length of a struct field (`int32_t nForwardTable[256]`).
    pub array: Option<usize>,
}

/// How a function's return value is checked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Codes {
    /// Vendor codes (`MCCL.h`): `RUN_TIME_ERR` is a failure (a caught panic).
    Vendor,
    /// MC3B library codes (`MCL_*`, 0..7): anything else is a failure.
    Mcl,
    /// Unknown convention: not checked.
    None,
}

#[derive(Debug)]
pub struct Func {
    pub ret: Decl,
    pub name: String,
    pub params: Vec<Decl>,
    /// The header's file name.
    pub header: String,
    pub codes: Codes,
}

/// A callback typedef: `RET (CONV *NAME)(ARGS)`.
pub struct CbSig {
    /// Calling-convention macro text.
    pub conv: String,
    /// The pointee of a routine's one argument (`LIOINT`), `void` for none.
    pub arg: String,
    /// Several (or named) arguments: their types as written (`const double *`); the
    /// routine declares them, hands none to the runtime, and returns 1 (`TRUE`) if it
    /// returns anything.
    pub several: Option<Vec<String>>,
    /// Return type.
    pub ret: String,
}

pub struct Model {
    pub structs: BTreeMap<String, Vec<Decl>>,
    /// Callback typedef name -> its signature.
    pub callbacks: BTreeMap<String, CbSig>,
    pub funcs: Vec<Func>,
    /// The headers' file names, in reading order.
    pub headers: Vec<String>,
}

/// The scalar kind, or struct or callback, a C type's base draws from.
fn base_of(t: &CType) -> Base {
    match t {
        CType::Void => Base::Void,
        CType::Int { bytes, signed } => Base::Prim(Prim::Int(u32::from(*bytes) * 8, *signed)),
        CType::Bool => Base::Prim(Prim::Int(32, true)), // BOOL is an int
        CType::CBool => Base::Prim(Prim::Bool),
        CType::Char => Base::Prim(Prim::Char),
        CType::CLong { signed } => Base::Prim(Prim::Int(64, *signed)),
        CType::Float(4) => Base::Prim(Prim::F32),
        CType::Float(_) => Base::Prim(Prim::F64),
        CType::Struct(s) => Base::Struct(s.clone()),
        CType::Callback(c) => Base::Callback(c.clone()),
        CType::Ptr(t) => base_of(t.pointee().0),
    }
}

/// A declaration of type `ty`, written `written`, named `name`.
fn decl(ty: &CType, written: &[String], name: &str, array: Option<usize>) -> Decl {
    let is_const = written.iter().any(|w| w == "const");
    let cbase = written
        .iter()
        .filter(|w| !matches!(w.as_str(), "*" | "&" | "const" | "struct"))
        .cloned()
        .collect::<Vec<_>>()
        .join(" ");
    let ptr = ty.pointee().1;
    let mut cty = String::new();
    if is_const {
        cty.push_str("const ");
    }
    cty.push_str(&cbase);
    if ptr > 0 {
        cty.push(' ');
        cty.push_str(&"*".repeat(ptr));
    }
    Decl {
        cty,
        cbase,
        base: base_of(ty),
        ptr,
        is_const,
        name: name.to_string(),
        array,
    }
}

impl Model {
    /// The fuzzer's view of the headers read into `h`.
    pub fn of(h: &Header) -> Result<Model, String> {
        let structs = h
            .structs
            .iter()
            .filter(|s| !h.aliases.contains_key(&s.name))
            .map(|s| {
                let fields = s
                    .fields
                    .iter()
                    .map(|f| decl(&f.ty, &f.written, &f.name, f.count))
                    .collect();
                (s.name.clone(), fields)
            })
            .collect();
        let mut callbacks = BTreeMap::new();
        for cb in &h.callbacks {
            callbacks.insert(cb.name.clone(), callback(cb)?);
        }
        let mut funcs = Vec::new();
        for f in &h.funcs {
            let (file, name) = (&f.header, &f.name);
            let ret = decl(&f.ret, &f.ret_written, "", None);
            if ret.ptr > 0 {
                return Err(format!(
                    "{file}: {name}: pointer return types are not fuzzed"
                ));
            }
            let mut params = Vec::new();
            for p in &f.params {
                let pname = if p.named { p.name.as_str() } else { "" };
                let d = decl(&p.ty, &p.written, pname, None);
                let text = format!("{} {pname}", p.written_text());
                if d.base == Base::Void && d.ptr == 0 {
                    return Err(format!("{file}: {name}: void parameter"));
                }
                if d.ptr > 1 {
                    return Err(format!("{file}: {name}: `{text}`: pointer to pointer"));
                }
                if matches!(d.base, Base::Callback(_)) && d.ptr > 0 {
                    return Err(format!("{file}: {name}: `{text}`: pointer to callback"));
                }
                params.push(d);
            }
            funcs.push(Func {
                ret,
                name: name.clone(),
                params,
                header: file.clone(),
                codes: codes(h, file),
            });
        }
        Ok(Model {
            structs,
            callbacks,
            funcs,
            headers: h.files.iter().map(|f| f.name.clone()).collect(),
        })
    }
}

/// A callback type's routine signature.
fn callback(cb: &mccl_header_model::Func) -> Result<CbSig, String> {
    let ret = cb.ret_written.join(" ");
    let several = cb.params.len() > 1 || cb.params.iter().any(|p| p.named);
    if several {
        return Ok(CbSig {
            conv: cb.conv.join(" "),
            arg: String::new(),
            several: Some(cb.params.iter().map(|p| p.written_text()).collect()),
            ret,
        });
    }
    if ret != "void" {
        return Err(format!("callback {}: one argument and a result", cb.name));
    }
    let arg = match cb.params.first() {
        None => "void".to_string(),
        Some(p) if p.ty.pointee().1 == 1 => p
            .written
            .iter()
            .filter(|w| *w != "*")
            .cloned()
            .collect::<Vec<_>>()
            .join(" "),
        Some(p) => {
            return Err(format!(
                "callback {}: its one argument `{}` is not a pointer",
                cb.name,
                p.written_text()
            ))
        }
    };
    Ok(CbSig {
        conv: cb.conv.join(" "),
        arg,
        several: None,
        ret,
    })
}

/// The return codes of the functions of header `file`: the vendor's where it includes
/// `MCCL.h` or defines `RUN_TIME_ERR`, the MC3B library's where it defines
/// `MCL_NO_ERROR`.
fn codes(h: &Header, file: &str) -> Codes {
    let defines = |c: &str| h.consts.iter().any(|k| k.name == c && k.header == file);
    let includes = h
        .files
        .iter()
        .any(|f| f.name == file && f.includes.iter().any(|i| i == "MCCL.h"));
    if includes || defines("RUN_TIME_ERR") {
        Codes::Vendor
    } else if defines("MCL_NO_ERROR") {
        Codes::Mcl
    } else {
        Codes::None
    }
}
