//! Tracks on the extension's records: each real-valued field of a shape, CSG block,
//! light or `focus` record, named by its field in lowercase (`box 2 min`, `cone 1 ra`,
//! `torus 1 major`, `spot 1 falloff`, `area 1 a1`, `directional 1 d`, `focus distance`,
//! `teapot rotate`, `csg 2 translate`). A value is written into the record, as if the
//! file said it, and the object is built again from its record; lights and the lens are
//! built by the tracer from the records at every frame. A record's bounds are those the
//! reader applies (`whitted::scene::ext::check`), held with every track of the record at
//! its value of the time.
//!
//! ```toml
//! target = "box 1 max"        # sphere: center radius; plane: point normal; box: min max
//!                             # cylinder: a b radius; cone: a ra b rb; torus: center axis
//!                             # major minor; disc: center normal radius hole;
//!                             # triangle: p1 p2 p3; every object: scale rotate translate
//! target = "spot 1 falloff"   # spot: p target color intensity radius falloff tightness
//!                             # area: p a1 a2 color intensity; directional: d color
//!                             # intensity; light N (a point record): p color intensity;
//!                             # with fade: distance power; p is also called position
//! target = "focus distance"   # focus: aperture distance
//! ```

use super::Kind;
use glam::DVec3;
use whitted::scene::ext::{build, check, ExtItem, Extension, LightKind, Modifiers};
use whitted::scene::{ObjectSpec, Scene, ShapeSpec};
use whitted::shapes::Shape;

/// The extension record a field belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Record {
    /// `scene.ext.objects[item]`.
    Object(usize),
    /// `scene.ext.lights[i]`.
    Light(usize),
    /// `scene.ext.focus`.
    Focus,
}

/// One real-valued field of an extension record.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ExtField {
    /// The record.
    pub record: Record,
    /// The field's name in lowercase, as the manifest writes it (`p` for `position`).
    pub name: &'static str,
    /// A number or a vector.
    pub kind: Kind,
}

const V: Kind = Kind::Vector;
const N: Kind = Kind::Number;
const FRAME: [(&str, Kind); 3] = [("scale", V), ("rotate", V), ("translate", V)];
const FADE: [(&str, Kind); 2] = [("distance", N), ("power", N)];
const SHINE: [(&str, Kind); 2] = [("color", V), ("intensity", N)];

/// The fields an object record's geometry and frame give (its TEXTURE and MATERIAL are
/// the report's fields, on the object).
pub fn object_fields(item: &ExtItem) -> Vec<(&'static str, Kind)> {
    let own: &[(&str, Kind)] = match item {
        // A glTF primitive moves with its node (`{ node = "…" }` tracks), not as a record.
        ExtItem::Shape(o) if matches!(o.shape, ShapeSpec::Gltf { .. }) => return Vec::new(),
        ExtItem::Csg(_) => &[],
        ExtItem::Shape(o) => match o.shape {
            ShapeSpec::Sphere { .. } => &[("center", V), ("radius", N)],
            ShapeSpec::Plane { .. } => &[("point", V), ("normal", V)],
            ShapeSpec::Box { .. } => &[("min", V), ("max", V)],
            ShapeSpec::Cylinder { .. } => &[("a", V), ("b", V), ("radius", N)],
            ShapeSpec::Cone { .. } => &[("a", V), ("ra", N), ("b", V), ("rb", N)],
            ShapeSpec::Disc { .. } => &[("center", V), ("normal", V), ("radius", N), ("hole", N)],
            ShapeSpec::Torus { .. } => &[("center", V), ("axis", V), ("major", N), ("minor", N)],
            ShapeSpec::Triangle { .. } => &[("p1", V), ("p2", V), ("p3", V)],
            ShapeSpec::Mesh { .. } | ShapeSpec::Gltf { .. } => &[],
            // The report's and an NFF's own records, which no extension record holds.
            ShapeSpec::InfiniteCylinder { .. }
            | ShapeSpec::OpenCone { .. }
            | ShapeSpec::Patch { .. } => &[],
        },
    };
    own.iter().chain(FRAME.iter()).copied().collect()
}

/// The fields a light record gives (`fade`'s only where the record has one).
pub fn light_fields(kind: &LightKind, mods: &Modifiers) -> Vec<(&'static str, Kind)> {
    let own: &[(&str, Kind)] = match kind {
        LightKind::Directional { .. } => &[("d", V)],
        LightKind::Point { .. } => &[("p", V), ("position", V)],
        LightKind::Spot { .. } => &[
            ("p", V),
            ("position", V),
            ("target", V),
            ("radius", N),
            ("falloff", N),
            ("tightness", N),
        ],
        LightKind::Area { .. } => &[("p", V), ("position", V), ("a1", V), ("a2", V)],
        LightKind::Punctual(..) => &[],
    };
    let fade: &[(&str, Kind)] = if mods.fade.is_some() { &FADE } else { &[] };
    own.iter()
        .chain(SHINE.iter())
        .chain(fade)
        .copied()
        .collect()
}

/// The `focus` record's fields.
pub const FOCUS_FIELDS: [(&str, Kind); 2] = [("aperture", N), ("distance", N)];

/// A field's place in a record, to read or write.
enum Slot<'a> {
    Vector(&'a mut DVec3),
    Number(&'a mut f64),
}

fn object_slot<'a>(item: &'a mut ExtItem, name: &str) -> Option<Slot<'a>> {
    use Slot::{Number as Nu, Vector as Ve};
    let mods = match item {
        ExtItem::Csg(c) => &mut c.mods,
        ExtItem::Shape(o) => {
            let slot = match (&mut o.shape, name) {
                (ShapeSpec::Sphere { center, .. }, "center")
                | (ShapeSpec::Disc { center, .. }, "center")
                | (ShapeSpec::Torus { center, .. }, "center") => Some(Ve(center)),
                (ShapeSpec::Sphere { radius, .. }, "radius")
                | (ShapeSpec::Cylinder { radius, .. }, "radius")
                | (ShapeSpec::Disc { radius, .. }, "radius") => Some(Nu(radius)),
                (ShapeSpec::Plane { point, .. }, "point") => Some(Ve(point)),
                (ShapeSpec::Plane { normal, .. }, "normal")
                | (ShapeSpec::Disc { normal, .. }, "normal") => Some(Ve(normal)),
                (ShapeSpec::Box { min, .. }, "min") => Some(Ve(min)),
                (ShapeSpec::Box { max, .. }, "max") => Some(Ve(max)),
                (ShapeSpec::Cylinder { a, .. }, "a") | (ShapeSpec::Cone { a, .. }, "a") => {
                    Some(Ve(a))
                }
                (ShapeSpec::Cylinder { b, .. }, "b") | (ShapeSpec::Cone { b, .. }, "b") => {
                    Some(Ve(b))
                }
                (ShapeSpec::Cone { ra, .. }, "ra") => Some(Nu(ra)),
                (ShapeSpec::Cone { rb, .. }, "rb") => Some(Nu(rb)),
                (ShapeSpec::Disc { hole, .. }, "hole") => Some(Nu(hole)),
                (ShapeSpec::Torus { axis, .. }, "axis") => Some(Ve(axis)),
                (ShapeSpec::Torus { major, .. }, "major") => Some(Nu(major)),
                (ShapeSpec::Torus { minor, .. }, "minor") => Some(Nu(minor)),
                (ShapeSpec::Triangle { corners }, "p1") => Some(Ve(&mut corners[0])),
                (ShapeSpec::Triangle { corners }, "p2") => Some(Ve(&mut corners[1])),
                (ShapeSpec::Triangle { corners }, "p3") => Some(Ve(&mut corners[2])),
                _ => None,
            };
            if slot.is_some() {
                return slot;
            }
            &mut o.mods
        }
    };
    frame_slot(mods, name)
}

/// `scale`, `rotate`, `translate`: a record without the modifier has the identity's
/// value, and writing one gives the record the modifier.
fn frame_slot<'a>(mods: &'a mut Modifiers, name: &str) -> Option<Slot<'a>> {
    let (slot, identity) = match name {
        "scale" => (&mut mods.scale, DVec3::ONE),
        "rotate" => (&mut mods.rotate, DVec3::ZERO),
        "translate" => (&mut mods.translate, DVec3::ZERO),
        _ => return None,
    };
    Some(Slot::Vector(slot.get_or_insert(identity)))
}

fn light_slot<'a>(light: &'a mut whitted::scene::ext::ExtLight, name: &str) -> Option<Slot<'a>> {
    use Slot::{Number as Nu, Vector as Ve};
    match (&mut light.kind, name) {
        (_, "color") => Some(Ve(&mut light.color)),
        (_, "intensity") => Some(Nu(&mut light.intensity)),
        (_, "distance") => light.mods.fade.as_mut().map(|f| Nu(&mut f.0)),
        (_, "power") => light.mods.fade.as_mut().map(|f| Nu(&mut f.1)),
        (LightKind::Directional { direction }, "d") => Some(Ve(direction)),
        (LightKind::Point { position }, "p" | "position")
        | (LightKind::Spot { position, .. }, "p" | "position")
        | (LightKind::Area { position, .. }, "p" | "position") => Some(Ve(position)),
        (LightKind::Spot { target, .. }, "target") => Some(Ve(target)),
        (LightKind::Spot { radius, .. }, "radius") => Some(Nu(radius)),
        (LightKind::Spot { falloff, .. }, "falloff") => Some(Nu(falloff)),
        (LightKind::Spot { tightness, .. }, "tightness") => Some(Nu(tightness)),
        (LightKind::Area { a1, .. }, "a1") => Some(Ve(a1)),
        (LightKind::Area { a2, .. }, "a2") => Some(Ve(a2)),
        _ => None,
    }
}

fn slot<'a>(ext: &'a mut Extension, field: &ExtField) -> Option<Slot<'a>> {
    match field.record {
        Record::Object(item) => object_slot(ext.objects.get_mut(item)?, field.name),
        Record::Light(i) => light_slot(ext.lights.get_mut(i)?, field.name),
        Record::Focus => {
            let focus = ext.focus.as_mut()?;
            match field.name {
                "aperture" => Some(Slot::Number(&mut focus.aperture)),
                "distance" => Some(Slot::Number(&mut focus.distance)),
                _ => None,
            }
        }
    }
}

/// Writes `v` (a number as `(x, 0, 0)`) into the record; `false` if it has no such field.
pub fn write(ext: &mut Extension, field: &ExtField, v: DVec3) -> bool {
    match slot(ext, field) {
        Some(Slot::Vector(s)) => *s = v,
        Some(Slot::Number(s)) => *s = v.x,
        None => return false,
    }
    true
}

/// The value the record holds (the identity's for a frame modifier it lacks).
pub fn read(ext: &Extension, field: &ExtField) -> DVec3 {
    let mut record = Extension::default();
    match field.record {
        Record::Object(item) => {
            record.objects = ext.objects.get(item).cloned().into_iter().collect()
        }
        Record::Light(i) => record.lights = ext.lights.get(i).cloned().into_iter().collect(),
        Record::Focus => record.focus = ext.focus,
    }
    let local = ExtField {
        record: match field.record {
            Record::Object(_) => Record::Object(0),
            Record::Light(_) => Record::Light(0),
            Record::Focus => Record::Focus,
        },
        ..*field
    };
    match slot(&mut record, &local) {
        Some(Slot::Vector(v)) => *v,
        Some(Slot::Number(x)) => DVec3::new(*x, 0.0, 0.0),
        None => DVec3::ZERO,
    }
}

/// The record's bounds (§16), as the reader words them, with the field to blame.
pub fn check_record(ext: &Extension, record: Record) -> Result<(), check::Violation> {
    let checked = match record {
        Record::Object(item) => match ext.objects.get(item) {
            Some(ExtItem::Shape(o)) => {
                check::shape(&o.shape).and_then(|()| check::modifiers(&o.mods))
            }
            Some(ExtItem::Csg(c)) => check::modifiers(&c.mods),
            None => Ok(()),
        },
        Record::Light(i) => ext.lights.get(i).map_or(Ok(()), check::light),
        Record::Focus => ext.focus.as_ref().map_or(Ok(()), check::focus),
    };
    checked
}

/// Builds the object of extension record `item` again from its record, as the reader
/// did, keeping the object's texture and material (which tracks of their own may have
/// changed). A record out of bounds keeps the shape it had: the timeline refuses such
/// values before any frame is drawn, and between two tracks of one record the record may
/// be passing through such a state.
pub fn rebuild(scene: &mut Scene, item: usize) {
    let Some(index) = scene.specs.iter().position(|s| s.item() == Some(item)) else {
        return;
    };
    if check_record(&scene.ext, Record::Object(item)).is_err() {
        return;
    }
    let one = Extension {
        objects: vec![scene.ext.objects[item].clone()],
        ..Extension::default()
    };
    let Ok(mut built) = build::objects(&one) else {
        return;
    };
    if built.objects.len() != 1 {
        return;
    }
    let (mut object, mut spec) = built.objects.remove(0);
    // A mesh's triangles go where its old ones were (its handle keeps its number).
    if let (Shape::Mesh(old), Shape::Mesh(new), Some(mesh)) = (
        &scene.objects[index].shape,
        &mut object.shape,
        built.meshes.pop(),
    ) {
        new.id = old.id;
        if let Some(slot) = scene.meshes.get_mut(old.id as usize) {
            *slot = mesh;
        }
    }
    if let ObjectSpec::Ext { item: i, .. } = &mut spec {
        *i = item as u32;
    }
    scene.objects[index].shape = object.shape;
    scene.specs[index] = spec;
}
