//! The bindings checker: parses `MCCL.cs`, `MCCLPCI_IMP.bas` and `MCCL.vb` on its own (it
//! shares no code with the generator's writers) and verifies every declaration against the
//! C header model and the library's exported symbols:
//!
//! * every `MCC_*` function of the header and every exported `MCC_*` symbol is declared,
//!   under its entry point, in a library called `MCCLPCI_IMP`, and is callable by its name;
//! * parameter count, order, by-value/by-reference and width (and int/float class) of every
//!   parameter, and the return width; a C `long` must be covered by a 4-byte and an 8-byte
//!   extern in the .NET files (Windows and LP64 Linux), and is 4 bytes in VB6 (Win32);
//! * struct field order, names, element widths, array lengths, offsets and sizes, computed
//!   with each language's layout rule (pack 8 for .NET, 4 for VB6 UDTs) against the C layout
//!   and a table of known vendor sizes;
//! * delegate signatures against the callback typedefs, and constant values.

use crate::model::{CType, Header, WIN};
use std::collections::BTreeMap;

/// The sizes of the vendor structs (docs/vendor-interface.md, Windows layout).
pub const KNOWN_SIZES: &[(&str, usize)] = &[
    ("SYS_MAC_PARAM", 72),
    ("SYS_MAC_PARAM_EX", 72),
    ("SYS_ENCODER_CONFIG", 16),
    ("ENCODER_CONFIG", 16),
    ("SYS_PULSE_CONFIG", 8),
    ("PULSE_CONFIG", 8),
    ("SYS_HOME_CONFIG", 56),
    ("SYS_HOME_CONFIG_EX", 88),
    ("SYS_COMP_PARAM", 2056),
    ("SYS_CARD_CONFIG", 8),
    ("HOME_CONFIG", 16),
    ("SYS_MACH_PARAM", 104),
    ("SYS_GROUP_INFO", 36),
    ("SYS_GROUP_CONFIG", 3840),
    ("COMMAND_INFO", 104),
    ("LIOINT", 24),
    ("ENCINT", 16),
    ("PCLINT", 16),
    ("ADCINT", 10),
    ("RIOINT", 8),
    ("TMRINT", 1),
    ("HSKINT", 1),
];

/// Which binding file is being checked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Lang {
    /// `MCCL.cs`.
    CSharp,
    /// `MCCLPCI_IMP.bas` (VB6: 32-bit Windows only).
    Vb6,
    /// `MCCL.vb`.
    VbNet,
}

/// What a pointer points to, as far as the ABI can tell.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Pointee {
    /// An integer of this width.
    Int(u8),
    /// A float of this width.
    Float(u8),
    /// A struct (canonical name).
    Struct(String),
    /// A function (delegate or callback typedef name).
    Func(String),
    /// Anything (`IntPtr`, `As Any`, `void*`).
    Any,
}

/// The ABI shape of a parameter or return value.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Abi {
    /// No value (`void`, `Sub`).
    Void,
    /// An integer passed by value, of this width.
    Int(u8),
    /// A float passed by value, of this width.
    Float(u8),
    /// A struct passed by value.
    Struct(String),
    /// A pointer (by reference, array, string buffer, delegate).
    Ptr(Pointee),
    /// Something that cannot cross the C ABI as declared (reason).
    Bad(String),
}

/// One parameter as the binding declares it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BParam {
    /// Declared name.
    pub name: String,
    /// ABI shape.
    pub abi: Abi,
}

/// An extern declaration (`DllImport` method or `Declare`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Extern {
    /// The method name in the binding.
    pub name: String,
    /// The native symbol it binds (`EntryPoint`/`Alias`, else the name).
    pub entry: String,
    /// The library name.
    pub lib: String,
    /// Whether callers can use it directly.
    pub public: bool,
    /// Parameters.
    pub params: Vec<BParam>,
    /// Return value.
    pub ret: Abi,
    /// An explicit calling convention, if any.
    pub conv: Option<String>,
    /// Line in the file.
    pub line: usize,
}

/// A public non-extern method (the wrappers around C `long` functions).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Method {
    /// Name.
    pub name: String,
    /// Parameter count.
    pub nparams: usize,
    /// Line in the file.
    pub line: usize,
}

/// Element type of a struct field.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Elem {
    /// Integer of this width.
    Int(u8),
    /// Float of this width.
    Float(u8),
    /// A nested struct (binding name).
    Struct(String),
    /// Cannot be laid out inline (reason).
    Bad(String),
}

/// One struct field as the binding declares it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BField {
    /// Field name.
    pub name: String,
    /// Element type.
    pub elem: Elem,
    /// Array length (`SizeConst`, VB6 bounds).
    pub count: Option<usize>,
}

/// A struct / `Type` / `Structure`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BStruct {
    /// Name.
    pub name: String,
    /// Fields in order.
    pub fields: Vec<BField>,
    /// Whether it is declared with a sequential layout (always true for VB6 `Type`).
    pub sequential: bool,
    /// Line in the file.
    pub line: usize,
}

/// A delegate type.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BDelegate {
    /// Name.
    pub name: String,
    /// Parameters.
    pub params: Vec<BParam>,
    /// Return value.
    pub ret: Abi,
    /// An explicit calling convention, if any.
    pub conv: Option<String>,
    /// Line in the file.
    pub line: usize,
}

/// Everything parsed out of one binding file.
#[derive(Debug, Clone, Default)]
pub struct Binding {
    /// Extern declarations.
    pub externs: Vec<Extern>,
    /// Public wrapper methods.
    pub methods: Vec<Method>,
    /// Structs.
    pub structs: Vec<BStruct>,
    /// Delegates.
    pub delegates: Vec<BDelegate>,
    /// Integer constants (name, value, line).
    pub consts: Vec<(String, i64, usize)>,
}

/// The outcome of checking one file.
#[derive(Debug, Default)]
pub struct Report {
    /// Problems, each `file:line: message`.
    pub problems: Vec<String>,
    /// Functions checked.
    pub functions: usize,
    /// Extern declarations checked (overloads and width variants included).
    pub externs: usize,
    /// Parameters checked.
    pub params: usize,
    /// Structs checked.
    pub structs: usize,
    /// Struct fields checked.
    pub fields: usize,
    /// Delegates checked.
    pub delegates: usize,
    /// Constants checked.
    pub consts: usize,
}

impl Report {
    /// One line: the counts and the verdict.
    pub fn summary(&self) -> String {
        format!(
            "{} functions ({} externs, {} parameters), {} structs ({} fields), {} delegates, {} constants checked: {}",
            self.functions,
            self.externs,
            self.params,
            self.structs,
            self.fields,
            self.delegates,
            self.consts,
            if self.problems.is_empty() {
                "OK".to_string()
            } else {
                format!("{} problem(s)", self.problems.len())
            }
        )
    }
}

mod cs;
mod lex;
mod vb;
mod verify;

use cs::*;
use lex::*;
use vb::*;
pub use verify::*;

#[cfg(test)]
mod tests;
