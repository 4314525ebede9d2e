//! The four ways an image TEXTURE is wrapped around its object (SPEC §16 and §18), by
//! the keyword its record names: `planar`, `spherical`, `cylindrical`, `uv`. Both the
//! mapping (`map`) and the tile choice on boundary faces (`faces`) take it.

/// How an image is wrapped around an object.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MapKind {
    /// Projected along the frame's z onto its x-y plane.
    Planar,
    /// Longitude and latitude about the centre.
    Spherical,
    /// Angle about the axis and height along it.
    Cylindrical,
    /// A mesh's own texture coordinates, interpolated over the triangle (SPEC §18; the
    /// mesh answers: `Mesh::surface`).
    Uv,
}

impl MapKind {
    /// The keywords a TEXTURE record names them by.
    pub const NAMES: [&'static str; 4] = ["planar", "spherical", "cylindrical", "uv"];

    /// The kind a keyword names.
    pub fn from_name(word: &str) -> Option<MapKind> {
        match word {
            "planar" => Some(MapKind::Planar),
            "spherical" => Some(MapKind::Spherical),
            "cylindrical" => Some(MapKind::Cylindrical),
            "uv" => Some(MapKind::Uv),
            _ => None,
        }
    }

    /// Its keyword.
    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }
}
