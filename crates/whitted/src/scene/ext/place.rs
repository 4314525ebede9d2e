//! `fit Size` and `pivot center | x y z` (SPEC §18's placing) on the bounded records
//! other than meshes (box, sphere, cylinder, cone, disc, torus, triangle, CSG blocks):
//! the same rule as a mesh's vertices (`mesh::place`), as a frame put before the
//! record's own. With f the fit's scale (1 without) and c the centre of the record's box
//! in its own units (its fields as written, before scale, rotate and translate), a point
//! p goes to c + f·(p − c) without a pivot, or to f·(p − q) with pivot q (c for
//! `center`); then the record's frame. A record without a box (a plane, a block whose
//! solids leave it unbounded) refuses them, at the record.
//!
//! ```text
//! box 10 20 30  12 22 32  …  fit 1 pivot center translate 0 0.5 0   → −0.5..0.5, lifted 0.5
//! ```

use super::{refused, Modifiers};
use crate::mesh::{Pivot, Placing};
use crate::scene::{FileLoc, SceneError};
use crate::shapes::Transform;
use glam::DVec3;

/// The frame of the placing `p` for a record whose box in its own units is `bounds`
/// (`None`: unbounded); the identity without `fit` or `pivot`. `what` is the record's
/// keyword for the error, at `loc`.
pub(super) fn prefix(
    p: &Placing,
    bounds: Option<(DVec3, DVec3)>,
    loc: &FileLoc,
    what: &str,
) -> Result<Transform, SceneError> {
    if *p == Placing::default() {
        return Ok(Transform::IDENTITY);
    }
    let Some((lo, hi)) = bounds else {
        let why = format!(
            "fit and pivot need an object with bounds, and this {what} is unbounded (a plane, or a block that holds one)"
        );
        return Err(refused(loc, what, &why));
    };
    let c = 0.5 * (lo + hi);
    let side = (hi - lo).max_element();
    let f = match p.fit {
        Some(size) if side > 0.0 && side.is_finite() => size / side,
        Some(_) => return Err(refused(loc, what, "fit: the object has no extent to scale")),
        None => 1.0,
    };
    let t = match p.pivot {
        None => c * (1.0 - f),
        Some(Pivot::Center) => -f * c,
        Some(Pivot::Point(q)) => -f * q,
    };
    Transform::new(DVec3::splat(f), DVec3::ZERO, t)
        .ok_or_else(|| refused(loc, what, "fit makes a singular frame"))
}

/// `m` without its frame and placing (its `open` kept): the record as written, whose box
/// the placing measures.
pub(super) fn unplaced(m: &Modifiers) -> Modifiers {
    Modifiers {
        open: m.open,
        ..Modifiers::default()
    }
}
