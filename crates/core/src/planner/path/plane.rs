//! The coordinate planes of arcs, circles and helices.

/// A coordinate plane for arcs, circles and helices.
///
/// Each plane has in-plane axes `(a, b)` and a normal axis `n`, forming a
/// right-handed frame: `XY = (X, Y; Z)`, `YZ = (Y, Z; X)`, `ZX = (Z, X; Y)`.
/// Note that in `ZX` the first plane coordinate is Z. A positive sweep is
/// counter-clockwise looking down the normal, i.e. from `+a` toward `+b`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Plane {
    /// Plane X-Y, normal Z.
    XY,
    /// Plane Y-Z, normal X.
    YZ,
    /// Plane Z-X, normal Y.
    ZX,
}

impl Plane {
    /// Axis indices `(a, b, n)`: the two plane coordinates and the normal.
    pub fn axes(self) -> (usize, usize, usize) {
        match self {
            Plane::XY => (0, 1, 2),
            Plane::YZ => (1, 2, 0),
            Plane::ZX => (2, 0, 1),
        }
    }
}
