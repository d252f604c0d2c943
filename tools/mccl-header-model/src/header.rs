//! What the generated headers declare: the model every tool reads them into.

use crate::ctype::CType;
use crate::syntax::Declaration;
use std::collections::BTreeMap;

/// One struct field.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Field {
    /// Field name.
    pub name: String,
    /// Element type.
    pub ty: CType,
    /// Array length for `T name[N]`.
    pub count: Option<usize>,
    /// The element type's words as written (`["WORD"]`).
    pub written: Vec<String>,
}

/// A `typedef struct { ... } NAME;`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Struct {
    /// Typedef name.
    pub name: String,
    /// Fields in declaration order.
    pub fields: Vec<Field>,
}

/// A function or callback parameter.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Param {
    /// Parameter name (`arg<i>` when the header leaves it out).
    pub name: String,
    /// Whether the header names it.
    pub named: bool,
    /// Parameter type.
    pub ty: CType,
    /// The type's words as written (`["const", "double", "*"]`).
    pub written: Vec<String>,
    /// The C++ default argument (`MCC_DEFAULT(v)`), as written.
    pub default: Option<String>,
}

impl Param {
    /// The type as written, its words separated by spaces (`const double *`).
    pub fn written_text(&self) -> String {
        self.written.join(" ")
    }
}

/// A function prototype or a callback typedef signature.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Func {
    /// Function (or typedef) name.
    pub name: String,
    /// Return type.
    pub ret: CType,
    /// The return type's words as written.
    pub ret_written: Vec<String>,
    /// The calling-convention macros written with it (`MCC_CALLBACK`; `MCC_API`,
    /// `MCC_CALL`).
    pub conv: Vec<String>,
    /// Parameters in order.
    pub params: Vec<Param>,
    /// The header section (`/* System Management */`) it was declared under.
    pub section: String,
    /// The header it was declared in, as named to [`Header::parse`].
    pub header: String,
}

impl Func {
    /// Whether any parameter or the return value involves a C `long`.
    pub fn has_clong(&self) -> bool {
        self.ret.has_clong() || self.params.iter().any(|p| p.ty.has_clong())
    }
}

/// A `#define NAME value` with an integer value.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Const {
    /// Macro name.
    pub name: String,
    /// Evaluated value.
    pub value: i64,
    /// The header it was defined in.
    pub header: String,
}

/// One header read, in reading order.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct File {
    /// Its name as given to [`Header::parse`].
    pub name: String,
    /// The headers it includes with `#include "..."`.
    pub includes: Vec<String>,
}

/// What a type name stands for after `typedef`s.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum Named {
    Scalar(CType),
    Struct(String),
}

/// Everything the generated headers declare.
#[derive(Debug, Clone, Default)]
pub struct Header {
    /// The headers read, in order.
    pub files: Vec<File>,
    /// Integer constants in header order.
    pub consts: Vec<Const>,
    /// Structs in header order (aliases appear under their own name with the target's fields).
    pub structs: Vec<Struct>,
    /// `typedef STRUCT ALIAS;` pairs: alias -> canonical struct name.
    pub aliases: BTreeMap<String, String>,
    /// Callback typedefs in header order.
    pub callbacks: Vec<Func>,
    /// Function prototypes in header order.
    pub funcs: Vec<Func>,
    pub(crate) names: BTreeMap<String, Named>,
    pub(crate) values: BTreeMap<String, i64>,
}

impl Header {
    /// The struct called `name` (an alias gives the target's fields).
    pub fn find_struct(&self, name: &str) -> Option<&Struct> {
        self.structs.iter().find(|s| s.name == name)
    }

    /// The canonical name of a struct (`ENCODER_CONFIG` -> `SYS_ENCODER_CONFIG`).
    pub fn canonical<'a>(&'a self, name: &'a str) -> &'a str {
        self.aliases.get(name).map(String::as_str).unwrap_or(name)
    }

    /// The value of the constant `name`.
    pub fn value(&self, name: &str) -> Option<i64> {
        self.values.get(name).copied()
    }

    /// Resolves a type given as words (e.g. `["SYS_MAC_PARAM", "*"]`; `&` counts as a
    /// pointer, qualifiers are dropped).
    pub fn resolve(&self, ws: &[String]) -> Result<CType, String> {
        let mut base: Vec<&str> = Vec::new();
        let mut ptrs = 0;
        for w in ws {
            match w.as_str() {
                "*" | "&" => ptrs += 1,
                "const" | "volatile" | "struct" => {}
                s => base.push(s),
            }
        }
        let mut t = if let Some(p) = crate::ctype::primitive(&base) {
            p
        } else if base.len() == 1 {
            match self.names.get(base[0]) {
                Some(Named::Scalar(t)) => t.clone(),
                Some(Named::Struct(s)) => CType::Struct(s.clone()),
                None if self.callbacks.iter().any(|c| c.name == base[0]) => {
                    CType::Callback(base[0].to_string())
                }
                None => return Err(format!("unknown type {:?}", base[0])),
            }
        } else {
            return Err(format!("unknown type {:?}", base.join(" ")));
        };
        for _ in 0..ptrs {
            t = CType::Ptr(Box::new(t));
        }
        Ok(t)
    }

    /// The parameter `i` of a prototype, its type resolved.
    pub(crate) fn param(&self, i: usize, d: Declaration) -> Result<Param, String> {
        if d.array.is_some() {
            return Err(format!("array parameter {:?}", d.name.unwrap_or_default()));
        }
        Ok(Param {
            ty: self.resolve(&d.ty)?,
            named: d.name.is_some(),
            name: d.name.unwrap_or_else(|| format!("arg{i}")),
            written: d.ty,
            default: d.default,
        })
    }
}
