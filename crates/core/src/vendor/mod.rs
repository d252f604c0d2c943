//! The vendor interface as data: typedefs, constants, struct layouts and callback types of
//! `MCCL.h` (docs/vendor-interface.md; IMP values per docs/decisions.md). cbindgen reads these to
//! generate `include/MCCL.h`.
// The vendor's names live here and only here: the vendor's typedefs, constants and struct fields keep their names (`SYS_MAC_PARAM`, `dwPPR`, `GMS_RUNNING`).
#![allow(non_snake_case, non_camel_case_types, non_upper_case_globals)]

pub mod callbacks;
pub mod consts;
pub mod structs;

pub use callbacks::*;
pub use consts::*;
pub use structs::*;

/// 16-bit unsigned (`unsigned short` on Windows).
pub type WORD = u16;
/// 32-bit unsigned: `uint32_t`, not `unsigned long`, so structs keep their Windows sizes.
pub type DWORD = u32;
/// 8-bit unsigned.
pub type BYTE = u8;
/// Win32 `BOOL`: a 4-byte int.
pub type BOOL = std::os::raw::c_int;
