//! Faces that lie on a tile boundary of an image map. Over a flat face
//! perpendicular to one of the map frame's axes, that coordinate is constant: a box's
//! faces, a capped cylinder's or cone's caps (along its axis under `cylindrical`, and
//! under `planar` when the axis is the object frame's x or y), a horizontal plane under
//! `cylindrical`. When the constant is a multiple of the map's Size, the hit points'
//! rounding (1 − 1e-16 here, 1 + 1e-16 there) used to pick rows or columns from both
//! ends of the image: noise over the whole face. Such a face now takes the tile on its
//! inner side (the solid's), at every point alike: the top face of a box from y 0 to 1
//! shows the image's top row, as its sides do just below the edge; the bottom face the
//! bottom row. Every other point keeps its (u, v) bit for bit.

use super::map_kind::MapKind;
use crate::shapes::{Local, Shape};
use glam::DVec3;

/// Where in the tile a face on a boundary is read: just inside its tile's edge (2^-30 of
/// a tile: past every pixel edge of the largest image, 16384 pixels, and well inside the
/// edge pixel).
const INSIDE: f64 = 1.0 / (1u64 << 30) as f64;

/// How near a multiple of Size, relative to it, a face counts as on the boundary: far
/// above the rounding of a face's coordinate, far below any modelled offset.
const ON_BOUNDARY: f64 = 1e-9;

/// A flat face through the point: the map coordinate constant over it (0 for u, 1 for
/// v), its value in the map frame, and the sign of its outward normal along that axis.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Flat {
    axis: usize,
    value: f64,
    outward: f64,
}

/// (u, v) with the coordinate a boundary face holds constant moved just inside its tile,
/// when the world point `p` of `shape` lies on such a face; `uv` unchanged otherwise.
pub(super) fn settle(
    map: MapKind,
    size: f64,
    shape: &Shape,
    p: DVec3,
    uv: (f64, f64),
) -> (f64, f64) {
    let Some(f) = flat(map, shape, p) else {
        return uv;
    };
    let c = f.value / size;
    let k = c.round();
    let on_boundary = (c - k).abs() <= ON_BOUNDARY * k.abs().max(1.0);
    if !on_boundary {
        return uv;
    }
    // A face facing +axis has its solid below: the top of the tile under the boundary.
    let inside = if f.outward > 0.0 {
        1.0 - INSIDE
    } else {
        INSIDE
    };
    match f.axis {
        0 => (inside, uv.1),
        _ => (uv.0, inside),
    }
}

/// The face of constant map coordinate the world point `p` of `shape` lies on, if any.
fn flat(map: MapKind, shape: &Shape, p: DVec3) -> Option<Flat> {
    match (map, shape) {
        (MapKind::Spherical, _) => None,
        (MapKind::Cylindrical, Shape::Plane(pl)) => {
            let n = pl.normal();
            (n.x == 0.0 && n.z == 0.0).then_some(Flat {
                axis: 1,
                value: pl.point.y,
                outward: n.y,
            })
        }
        (_, Shape::Placed(pl)) => {
            let q = pl.frame.point_to_local(p);
            match &pl.local {
                Local::Box(b) => {
                    let n = b.normal(q);
                    let i = (0..3).find(|&i| n[i] != 0.0)?;
                    let value = if n[i] > 0.0 { b.max[i] } else { b.min[i] };
                    // Planar reads x and y; cylindrical's object frame reads y.
                    let read = match map {
                        MapKind::Planar => i < 2,
                        _ => i == 1,
                    };
                    read.then_some(Flat {
                        axis: i,
                        value,
                        outward: n[i],
                    })
                }
                Local::Capped(c) if c.caps => {
                    let a = c.side.axis();
                    let n = c.normal(q);
                    let apex = if n == a {
                        true
                    } else if n == -a {
                        false
                    } else {
                        return None;
                    };
                    if map == MapKind::Cylindrical {
                        // The frame's y runs along the axis from A: 0 and the height.
                        let value = if apex { c.side.height() } else { 0.0 };
                        let outward = if apex { 1.0 } else { -1.0 };
                        return Some(Flat {
                            axis: 1,
                            value,
                            outward,
                        });
                    }
                    let i = (0..2).find(|&i| a[i].abs() == 1.0)?;
                    let end = if apex {
                        c.side.base + c.side.height() * a
                    } else {
                        c.side.base
                    };
                    Some(Flat {
                        axis: i,
                        value: end[i],
                        outward: n[i],
                    })
                }
                _ => None,
            }
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::{AaBox, Capped, Placed, Plane, Transform};

    fn boxed(lo: DVec3, hi: DVec3) -> Shape {
        let b = AaBox::new(lo, hi).unwrap();
        Shape::Placed(Placed::new(Local::Box(b), Transform::IDENTITY))
    }

    #[test]
    fn a_box_face_on_a_boundary_reads_its_inner_tile() {
        let b = boxed(DVec3::ZERO, DVec3::ONE);
        // Top face y = 1 = 1·Size: v just under 1 (the top row), whichever side the
        // point's y rounded to; u untouched.
        for y in [1.0 - 1e-16, 1.0, 1.0 + 2e-16] {
            let p = DVec3::new(0.3, y, 0.6);
            let got = settle(MapKind::Planar, 1.0, &b, p, (0.3, y));
            assert_eq!(got, (0.3, 1.0 - INSIDE), "y = {y}");
        }
        // Bottom face y = 0: just over 0 (the bottom row). Right face x = 1: u under 1.
        let got = settle(
            MapKind::Planar,
            1.0,
            &b,
            DVec3::new(0.3, 0.0, 0.6),
            (0.3, 0.0),
        );
        assert_eq!(got, (0.3, INSIDE));
        let got = settle(
            MapKind::Planar,
            0.5,
            &b,
            DVec3::new(1.0, 0.4, 0.6),
            (2.0, 0.8),
        );
        assert_eq!(got, (1.0 - INSIDE, 0.8));
        // The front face z = 1 is projected along z: nothing to settle.
        let uv = (0.3, 0.4);
        assert_eq!(
            settle(MapKind::Planar, 1.0, &b, DVec3::new(0.3, 0.4, 1.0), uv),
            uv
        );
    }

    #[test]
    fn faces_off_the_boundary_and_other_maps_keep_their_uv() {
        let b = boxed(DVec3::ZERO, DVec3::new(1.0, 0.75, 1.0));
        // Top face y = 0.75 with Size 1: not a boundary.
        let uv = (0.3, 0.75 + 1e-16);
        assert_eq!(
            settle(MapKind::Planar, 1.0, &b, DVec3::new(0.3, 0.75, 0.5), uv),
            uv
        );
        // Size 0.25: 0.75 = 3·Size, on a boundary.
        let got = settle(
            MapKind::Planar,
            0.25,
            &b,
            DVec3::new(0.3, 0.75, 0.5),
            (1.2, 3.0),
        );
        assert_eq!(got, (1.2, 1.0 - INSIDE));
        // Spherical has no flat face.
        let uv = (0.1, 0.2);
        assert_eq!(
            settle(MapKind::Spherical, 1.0, &b, DVec3::new(0.3, 0.75, 0.5), uv),
            uv
        );
    }

    #[test]
    fn a_cylinder_cap_at_a_multiple_of_size_under_cylindrical() {
        // From (0,1,0) up 2: caps at s = 0 (always a boundary) and s = 2 (Size 1 and 2).
        let a = DVec3::Y;
        let cap = Capped::new(a, 0.5, DVec3::new(0.0, 3.0, 0.0), 0.5, true).unwrap();
        let c = Shape::Placed(Placed::new(Local::Capped(cap), Transform::IDENTITY));
        let top = DVec3::new(0.1, 3.0, 0.2);
        assert_eq!(
            settle(MapKind::Cylindrical, 2.0, &c, top, (0.7, 1.0)),
            (0.7, 1.0 - INSIDE)
        );
        let base = DVec3::new(0.1, 1.0, 0.2);
        assert_eq!(
            settle(MapKind::Cylindrical, 2.0, &c, base, (0.7, 0.0)),
            (0.7, INSIDE)
        );
        // Size 0.8: the top cap at 2 is not a multiple; the side is never settled.
        let uv = (0.7, 2.5);
        assert_eq!(settle(MapKind::Cylindrical, 0.8, &c, top, uv), uv);
        let side = DVec3::new(0.5, 2.0, 0.0);
        assert_eq!(
            settle(MapKind::Cylindrical, 1.0, &c, side, (0.0, 1.0)),
            (0.0, 1.0)
        );
        // Planar: the vertical axis is the frame's y, the top cap at y = 3.
        assert_eq!(
            settle(MapKind::Planar, 1.0, &c, top, (0.1, 3.0)),
            (0.1, 1.0 - INSIDE)
        );
    }

    #[test]
    fn a_horizontal_plane_under_cylindrical() {
        let floor = Shape::Plane(Plane::new(DVec3::new(0.0, 2.0, 0.0), DVec3::Y));
        let p = DVec3::new(3.0, 2.0, 1.0);
        assert_eq!(
            settle(MapKind::Cylindrical, 1.0, &floor, p, (0.1, 2.0)),
            (0.1, 1.0 - INSIDE)
        );
        // Planar on a plane projects along its normal: nothing constant.
        assert_eq!(
            settle(MapKind::Planar, 1.0, &floor, p, (0.5, 0.5)),
            (0.5, 0.5)
        );
    }
}
