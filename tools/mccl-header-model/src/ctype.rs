//! A C type as far as the ABI is concerned, and the C types spelled with keywords.

/// A C type as far as the ABI is concerned (qualifiers such as `const` are dropped).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CType {
    /// `void` (only as a return type or behind a pointer).
    Void,
    /// A fixed-width integer (`WORD`, `DWORD`, `BYTE`, `int`, `int32_t`, `short`, ...).
    Int {
        /// Width in bytes.
        bytes: u8,
        /// Whether the C type is signed.
        signed: bool,
    },
    /// `BOOL` (an `int`, kept apart so the bindings can map it to a boolean).
    Bool,
    /// C99 `bool` / `_Bool` (`<stdbool.h>`): one byte, 0 or 1.
    CBool,
    /// Plain `char` (a character, or a string behind a pointer).
    Char,
    /// C `long` / `unsigned long`: 4 bytes on Windows (LLP64), 8 on LP64 Linux.
    CLong {
        /// Whether the C type is signed.
        signed: bool,
    },
    /// `double` (8) or `float` (4).
    Float(u8),
    /// A struct, by its canonical name (typedef aliases resolved).
    Struct(String),
    /// A callback typedef (a function pointer), by its canonical name (aliases resolved).
    Callback(String),
    /// A pointer (or a C++ reference) to the inner type.
    Ptr(Box<CType>),
}

impl CType {
    /// Whether this type, or anything it points to, is a C `long`.
    pub fn has_clong(&self) -> bool {
        match self {
            CType::CLong { .. } => true,
            CType::Ptr(t) => t.has_clong(),
            _ => false,
        }
    }

    /// The type behind every pointer (`int` for `const int **`), and how many pointers.
    pub fn pointee(&self) -> (&CType, usize) {
        match self {
            CType::Ptr(t) => {
                let (base, n) = t.pointee();
                (base, n + 1)
            }
            t => (t, 0),
        }
    }
}

/// The type a list of C keywords (and `<stdint.h>` names) spells, `const` ignored:
/// `["unsigned", "short"]` is a 2-byte unsigned integer; `None` for anything else.
pub(crate) fn primitive(words: &[&str]) -> Option<CType> {
    let w: Vec<&str> = words.iter().copied().filter(|w| *w != "const").collect();
    let int = |bytes, signed| CType::Int { bytes, signed };
    let t = match w.as_slice() {
        ["void"] => CType::Void,
        ["char"] => CType::Char,
        ["bool"] | ["_Bool"] => CType::CBool,
        ["signed", "char"] | ["int8_t"] => int(1, true),
        ["unsigned", "char"] | ["uint8_t"] => int(1, false),
        ["short"] | ["short", "int"] | ["int16_t"] => int(2, true),
        ["unsigned", "short"] | ["unsigned", "short", "int"] | ["uint16_t"] => int(2, false),
        ["int"] | ["signed"] | ["signed", "int"] | ["int32_t"] => int(4, true),
        ["unsigned"] | ["unsigned", "int"] | ["uint32_t"] => int(4, false),
        ["long"] | ["long", "int"] | ["signed", "long"] => CType::CLong { signed: true },
        ["unsigned", "long"] | ["unsigned", "long", "int"] => CType::CLong { signed: false },
        ["long", "long"] | ["long", "long", "int"] | ["int64_t"] => int(8, true),
        ["unsigned", "long", "long"] | ["uint64_t"] => int(8, false),
        ["double"] => CType::Float(8),
        ["float"] => CType::Float(4),
        _ => return None,
    };
    Some(t)
}
