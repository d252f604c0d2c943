//! The axes that compose the path speed of a line (`MCC_SetComposeAxis`).
//!
//! By default X, Y and Z compose the path: a line's length is its X/Y/Z length and the
//! feed speed is measured along it; with no X/Y/Z travel the aux axis with the longest
//! travel is the path ([`super::Path::line`]). A compose mask generalises the rule: the
//! length is the Euclidean length over the axes of the mask, and with no travel on them
//! the longest travel of the other axes.

use super::{Axes, Path};

/// The default compose mask: X, Y and Z (bits 0..2).
pub const XYZ_MASK: u32 = 0b111;

/// The path length of a line from `start` to `end` composed over the axes of `mask`
/// (bit i = axis i): `sqrt(Σ_{i in mask} d_i²)`, or, when that is 0, the longest
/// `|d_i|` of the axes outside the mask (0 for a line that does not move).
pub fn composed_length(start: &Axes, end: &Axes, mask: u32) -> f64 {
    composed_norm(&std::array::from_fn(|i| end[i] - start[i]), mask)
}

/// The path (tangential) speed of axis velocities `vel` composed over `mask`, by the
/// rule of [`composed_length`]: what `MCC_GetCurFeedSpeed` reports.
///
/// Inlined where it is called (every group's period computes it) as far as the default
/// composition goes; the rest is out of line.
#[inline]
pub fn composed_speed(vel: &Axes, mask: u32) -> f64 {
    if mask == XYZ_MASK {
        let inside = xyz_norm(vel);
        if inside > 0.0 {
            return inside;
        }
    }
    composed_norm(vel, mask)
}

/// The default composition, without the mask's branches: the same sum in the same order
/// as [`composed_norm`]'s (0 + x² is x² exactly).
#[inline(always)]
fn xyz_norm(d: &Axes) -> f64 {
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt()
}

fn composed_norm(d: &Axes, mask: u32) -> f64 {
    if mask == XYZ_MASK {
        let inside = xyz_norm(d);
        if inside > 0.0 {
            return inside;
        }
    }
    // Summed in axis order, as the iterator form summed: every tick computes this.
    let mut sum = 0.0;
    for (i, x) in d.iter().enumerate() {
        if mask >> i & 1 == 1 {
            sum += x * x;
        }
    }
    let inside = sum.sqrt();
    if inside > 0.0 {
        return inside;
    }
    (0..d.len())
        .filter(|&i| mask & (1 << i) == 0)
        .map(|i| d[i].abs())
        .fold(0.0, f64::max)
}

/// A line whose length is composed over `mask` ([`composed_length`]); the default mask
/// gives exactly [`Path::line`].
pub fn line(start: &Axes, end: &Axes, mask: u32) -> Path {
    if mask == XYZ_MASK {
        Path::line(start, end)
    } else {
        Path::line_with_length(start, end, composed_length(start, end, mask))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn composed_lengths_by_hand() {
        let a = [0.0; 8];
        let b = [3.0, 4.0, 0.0, 12.0, 0.0, 0.0, 0.0, 0.0];
        // X|Y|U: sqrt(9 + 16 + 144) = 13.
        assert_eq!(composed_length(&a, &b, 0b1011), 13.0);
        // X|Y|Z: 5 (U follows).
        assert_eq!(composed_length(&a, &b, XYZ_MASK), 5.0);
        // Only Z, which does not move: the longest other travel, U = 12.
        assert_eq!(composed_length(&a, &b, 0b100), 12.0);
        assert_eq!(composed_length(&a, &a, 0b1011), 0.0);
        assert_eq!(line(&a, &b, 0b1011).length(), 13.0);
        assert_eq!(line(&a, &b, XYZ_MASK).length(), Path::line(&a, &b).length());
    }
}
