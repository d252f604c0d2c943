//! The C struct layout rules: sizes, alignments and offsets of the headers' types on a
//! target.

use crate::ctype::CType;
use crate::header::Header;

/// Platform rules for sizes and alignment.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Target {
    /// Size of C `long`.
    pub clong: u8,
    /// Size of a pointer.
    pub ptr: u8,
    /// Largest member alignment (8 for C and .NET's default pack, 4 for VB6 UDTs).
    pub max_align: usize,
}

/// Windows x86/x64 C (MSVC /Zp8) with a 4-byte `long`: the vendor layout.
pub const WIN: Target = Target {
    clong: 4,
    ptr: 8,
    max_align: 8,
};

/// A member's size, alignment and offset.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Slot {
    /// Field name.
    pub name: String,
    /// Offset in bytes.
    pub offset: usize,
    /// Size in bytes (element size times count).
    pub size: usize,
}

/// The layout of a struct: slots in order and the total size.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Layout {
    /// Every field with its offset.
    pub slots: Vec<Slot>,
    /// `sizeof`.
    pub size: usize,
    /// Alignment of the whole struct.
    pub align: usize,
}

/// Sequential layout of `(name, element size, element alignment, count)` members.
pub fn layout(members: &[(String, usize, usize, usize)], max_align: usize) -> Layout {
    let mut off = 0usize;
    let mut align = 1usize;
    let mut slots = Vec::new();
    for (name, size, al, count) in members {
        let a = (*al).clamp(1, max_align);
        off = off.div_ceil(a) * a;
        slots.push(Slot {
            name: name.clone(),
            offset: off,
            size: size * count,
        });
        off += size * count;
        align = align.max(a);
    }
    Layout {
        slots,
        size: off.div_ceil(align) * align,
        align,
    }
}

impl Header {
    /// Size and alignment of one C type on `t`.
    pub fn size_align(&self, ty: &CType, t: Target) -> Result<(usize, usize), String> {
        Ok(match ty {
            CType::Void => return Err("void has no size".into()),
            CType::Int { bytes, .. } => (usize::from(*bytes), usize::from(*bytes)),
            CType::Bool => (4, 4),
            CType::Char | CType::CBool => (1, 1),
            CType::CLong { .. } => (usize::from(t.clong), usize::from(t.clong)),
            CType::Float(b) => (usize::from(*b), usize::from(*b)),
            CType::Ptr(_) | CType::Callback(_) => (usize::from(t.ptr), usize::from(t.ptr)),
            CType::Struct(s) => {
                let l = self.struct_layout(s, t)?;
                (l.size, l.align)
            }
        })
    }

    /// The C layout of struct `name` on `t`.
    pub fn struct_layout(&self, name: &str, t: Target) -> Result<Layout, String> {
        let s = self
            .find_struct(name)
            .ok_or_else(|| format!("unknown struct {name}"))?;
        let mut m = Vec::new();
        for f in &s.fields {
            let (size, al) = self.size_align(&f.ty, t)?;
            m.push((f.name.clone(), size, al, f.count.unwrap_or(1)));
        }
        Ok(layout(&m, t.max_align))
    }
}
