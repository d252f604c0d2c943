//! The one model of the C headers libMCCLPCI_IMP generates (`include/*.h`), shared by
//! every tool that reads them: the C# and VB bindings generator and checker
//! (`mccl-bindings`), the fuzzer's dispatch-table generator (`mccl-fuzzgen`) and the
//! header generator (`mccl-headers`, which reads the vendor prototype table and cbindgen's
//! prototypes with the same declaration syntax).
//!
//! Two levels:
//!
//! * [`syntax`]: one C declaration or prototype as written (its type's words, its name,
//!   array length, default argument), without knowing what the names stand for;
//! * [`Header`]: the headers read in order into types ([`CType`], resolved through their
//!   typedefs), constants, structs, callback types and function prototypes, each keeping
//!   the words it was written with; [`layout`] adds the C struct layout rules.
//!
//! The parser reads the regular format the generator writes (one declaration per line,
//! structs one field per line) and fails on a line it does not understand, so a change of
//! the headers' form cannot make a tool skip a declaration silently.

mod ctype;
mod expr;
mod header;
pub mod layout;
mod parse;
pub mod syntax;
#[cfg(test)]
mod tests;

pub use ctype::CType;
pub use expr::eval_expr;
pub use header::{Const, Field, File, Func, Header, Param, Struct};
pub use layout::{Layout, Slot, Target, WIN};

use std::fmt;

/// An error with the place it was found (`file:line: message`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Error(pub String);

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Error {}

/// Builds an [`Error`] located at `file:line`.
pub(crate) fn err_at(file: &str, line: usize, msg: impl fmt::Display) -> Error {
    Error(format!("{file}:{line}: {msg}"))
}
