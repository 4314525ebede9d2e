//! §16's bounds on the extension's values, in one place: the reader applies them to what
//! a file says and animation tracks to every frame's values, so a record that a track
//! pushes out of bounds is refused with the same words the reader would use. Each check
//! answers the field to blame and why.

use super::{ExtLight, Focus, LightKind, Modifiers};
use crate::scene::ShapeSpec;
use glam::DVec3;

/// A value out of §16's bounds: the field to blame (as the tables name it) and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Violation {
    /// The field as §16's tables name it (`Max`, `r`, `Falloff`).
    pub field: &'static str,
    /// Why, in the words of an error message.
    pub message: String,
}

fn fail<T>(field: &'static str, message: String) -> Result<T, Violation> {
    Err(Violation { field, message })
}

fn nonzero(v: DVec3, field: &'static str, what: &str) -> Result<(), Violation> {
    if crate::scene::direction(v).is_some() {
        Ok(())
    } else {
        fail(
            field,
            format!("the {what} ({} {} {}) has zero length", v.x, v.y, v.z),
        )
    }
}

fn positive(v: f64, field: &'static str) -> Result<(), Violation> {
    if v > 0.0 {
        Ok(())
    } else {
        fail(field, format!("{field} must be greater than 0, found {v}"))
    }
}

/// The bounds of a shape record's geometry.
pub fn shape(s: &ShapeSpec) -> Result<(), Violation> {
    match s {
        ShapeSpec::Sphere { radius, .. } => positive(*radius, "Radius"),
        ShapeSpec::Plane { normal, .. } => nonzero(*normal, "N", "normal"),
        ShapeSpec::Box { min, max } => {
            for (axis, (lo, hi)) in ["x", "y", "z"]
                .iter()
                .zip(min.to_array().into_iter().zip(max.to_array()))
            {
                if lo >= hi {
                    return fail("Max", format!("Min must be below Max on each axis, but on {axis} Min is {lo} and Max {hi}"));
                }
            }
            Ok(())
        }
        ShapeSpec::Cylinder { a, b, radius } => {
            nonzero(*b - *a, "B", "axis from A to B")?;
            positive(*radius, "Radius")
        }
        ShapeSpec::Cone { a, ra, b, rb } => {
            nonzero(*b - *a, "B", "axis from A to B")?;
            if *ra < 0.0 || *rb < 0.0 {
                return fail(
                    "Rb",
                    format!("Ra and Rb must be at least 0, found {ra} and {rb}"),
                );
            }
            if *ra == 0.0 && *rb == 0.0 {
                return fail("Rb", "Ra and Rb cannot both be 0".to_string());
            }
            Ok(())
        }
        ShapeSpec::Disc {
            normal,
            radius,
            hole,
            ..
        } => {
            nonzero(*normal, "N", "normal")?;
            positive(*radius, "Radius")?;
            if !(0.0..*radius).contains(hole) {
                return fail(
                    "Hole",
                    format!("Hole must be at least 0 and below Radius ({radius}), found {hole}"),
                );
            }
            Ok(())
        }
        ShapeSpec::Torus {
            axis, major, minor, ..
        } => {
            nonzero(*axis, "Axis", "axis")?;
            positive(*minor, "r")?;
            if minor >= major {
                return fail(
                    "r",
                    format!(
                        "the tube radius r ({minor}) must be below the major radius R ({major})"
                    ),
                );
            }
            Ok(())
        }
        ShapeSpec::Triangle { corners: [p, q, r] } => {
            if (*q - *p).cross(*r - *p).length_squared() > 0.0 {
                Ok(())
            } else {
                fail(
                    "P3",
                    "the triangle is degenerate: its corners are on one line".to_string(),
                )
            }
        }
        ShapeSpec::Mesh { .. } | ShapeSpec::Gltf { .. } => Ok(()),
        // The report's and an NFF's own records: their readers check them.
        ShapeSpec::InfiniteCylinder { .. }
        | ShapeSpec::OpenCone { .. }
        | ShapeSpec::Patch { .. } => Ok(()),
    }
}

/// The bounds of an object's modifiers: no zero scale.
pub fn modifiers(m: &Modifiers) -> Result<(), Violation> {
    if let Some(s) = m.scale {
        if s.x == 0.0 || s.y == 0.0 || s.z == 0.0 {
            return fail(
                "scale",
                format!(
                    "scale cannot be 0 on an axis, found {} {} {}",
                    s.x, s.y, s.z
                ),
            );
        }
    }
    if let Some(crate::mesh::Shading::Smooth(angle)) = m.shading {
        if !(angle > 0.0 && angle <= 180.0) {
            let msg =
                format!("the smooth Angle must be above 0 and at most 180 degrees, found {angle}");
            return fail("Angle", msg);
        }
    }
    if let Some(size) = m.placing.fit {
        positive(size, "Size")?;
    }
    if let Some((distance, power)) = m.fade {
        positive(distance, "Distance")?;
        if power < 0.0 {
            return fail("Power", format!("Power must be at least 0, found {power}"));
        }
    }
    Ok(())
}

/// The bounds of a light record (its modifiers included).
pub fn light(l: &ExtLight) -> Result<(), Violation> {
    match &l.kind {
        LightKind::Directional { direction } => {
            nonzero(*direction, "D", "direction")?;
            if l.mods.fade.is_some() {
                return fail(
                    "fade",
                    "fade does not apply to a directional light (it is infinitely far)".to_string(),
                );
            }
        }
        LightKind::Spot {
            position,
            target,
            radius,
            falloff,
            tightness,
        } => {
            nonzero(*target - *position, "Target", "axis from P to Target")?;
            positive(*radius, "Radius")?;
            if radius >= falloff {
                return fail(
                    "Falloff",
                    format!("Radius ({radius}) must be below Falloff ({falloff})"),
                );
            }
            if *falloff >= 90.0 {
                return fail(
                    "Falloff",
                    format!("Falloff must be below 90 degrees, found {falloff}"),
                );
            }
            if *tightness < 0.0 {
                return fail(
                    "Tightness",
                    format!("Tightness must be at least 0, found {tightness}"),
                );
            }
        }
        LightKind::Point { .. } | LightKind::Punctual(..) => {}
        LightKind::Area { n1, n2, .. } => {
            if *n1 == 0 || *n2 == 0 {
                return fail(
                    "N2",
                    format!("the area grid must be at least 1 × 1, found {n1} × {n2}"),
                );
            }
        }
    }
    if !(0.0..=crate::limits::MAX_INTENSITY).contains(&l.intensity) {
        let max = crate::limits::MAX_INTENSITY;
        return fail(
            "Intensity",
            format!("Intensity must be from 0 to {max}, found {}", l.intensity),
        );
    }
    modifiers(&l.mods)
}

/// The bounds of the `focus` record.
pub fn focus(f: &Focus) -> Result<(), Violation> {
    positive(f.aperture, "Aperture")?;
    positive(f.distance, "Distance")?;
    if f.samples == 0 {
        return fail("Samples", "Samples must be at least 1".to_string());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_min_must_be_below_max_on_every_axis() {
        let ok = ShapeSpec::Box {
            min: DVec3::ZERO,
            max: DVec3::ONE,
        };
        assert_eq!(shape(&ok), Ok(()));
        let flat = ShapeSpec::Box {
            min: DVec3::ZERO,
            max: DVec3::new(1.0, 0.0, 1.0),
        };
        let v = shape(&flat).unwrap_err();
        assert_eq!(v.field, "Max");
        assert!(v.message.contains("on y"), "{}", v.message);
    }

    #[test]
    fn torus_tube_must_be_thinner_than_its_ring() {
        let t = |major, minor| ShapeSpec::Torus {
            center: DVec3::ZERO,
            axis: DVec3::Y,
            major,
            minor,
        };
        assert_eq!(shape(&t(2.0, 0.5)), Ok(()));
        assert_eq!(shape(&t(2.0, 2.0)).unwrap_err().field, "r");
        assert_eq!(shape(&t(2.0, 0.0)).unwrap_err().field, "r");
    }

    #[test]
    fn spot_radius_below_falloff_below_ninety() {
        let spot = |radius, falloff| ExtLight {
            kind: LightKind::Spot {
                position: DVec3::Y,
                target: DVec3::ZERO,
                radius,
                falloff,
                tightness: 1.0,
            },
            color: DVec3::ONE,
            intensity: 1.0,
            mods: Modifiers::default(),
            loc: Default::default(),
        };
        assert_eq!(light(&spot(20.0, 30.0)), Ok(()));
        assert_eq!(light(&spot(30.0, 30.0)).unwrap_err().field, "Falloff");
        assert_eq!(light(&spot(20.0, 90.0)).unwrap_err().field, "Falloff");
    }

    #[test]
    fn fade_is_refused_on_a_directional_light() {
        let mods = Modifiers {
            fade: Some((5.0, 2.0)),
            ..Default::default()
        };
        let l = ExtLight {
            kind: LightKind::Directional {
                direction: -DVec3::Y,
            },
            color: DVec3::ONE,
            intensity: 1.0,
            mods,
            loc: Default::default(),
        };
        assert_eq!(light(&l).unwrap_err().field, "fade");
    }

    #[test]
    fn degenerate_triangle_and_zero_scale_are_refused() {
        let line = ShapeSpec::Triangle {
            corners: [DVec3::ZERO, DVec3::X, DVec3::X * 2.0],
        };
        assert_eq!(shape(&line).unwrap_err().field, "P3");
        let m = Modifiers {
            scale: Some(DVec3::new(1.0, 0.0, 1.0)),
            ..Default::default()
        };
        assert_eq!(modifiers(&m).unwrap_err().field, "scale");
    }
}
