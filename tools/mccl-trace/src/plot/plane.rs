//! The plane of the path panel and how axis positions project onto it.

/// The plane of the path panel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Plane {
    /// X horizontal, Y vertical.
    Xy,
    /// X horizontal, Z vertical.
    Xz,
    /// Y horizontal, Z vertical.
    Yz,
    /// Isometric view of X, Y, Z.
    Iso,
}

impl Plane {
    /// Parses `xy`, `xz`, `yz`, `3d`.
    pub fn parse(s: &str) -> Option<Plane> {
        match s.to_ascii_lowercase().as_str() {
            "xy" => Some(Plane::Xy),
            "xz" => Some(Plane::Xz),
            "yz" => Some(Plane::Yz),
            "3d" | "iso" => Some(Plane::Iso),
            _ => None,
        }
    }

    /// The point of the panel for axis positions `p`.
    pub fn project(self, p: &[f64; 8]) -> (f64, f64) {
        let c = 0.866_025_403_784_438_6; // cos 30°
        match self {
            Plane::Xy => (p[0], p[1]),
            Plane::Xz => (p[0], p[2]),
            Plane::Yz => (p[1], p[2]),
            Plane::Iso => ((p[0] - p[1]) * c, p[2] + (p[0] + p[1]) * 0.5),
        }
    }

    pub(super) fn labels(self) -> (&'static str, &'static str) {
        match self {
            Plane::Xy => ("x (UU)", "y (UU)"),
            Plane::Xz => ("x (UU)", "z (UU)"),
            Plane::Yz => ("y (UU)", "z (UU)"),
            Plane::Iso => ("isometric x-y (UU)", "isometric z (UU)"),
        }
    }
}
