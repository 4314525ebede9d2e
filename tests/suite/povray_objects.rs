//! Objects of the POV-Ray comparisons (`shapes_povray`), each described once and written
//! both as our extension records and in POV-Ray's language: `box`, `cylinder`, `cone`,
//! `disc`, `torus`, `triangle`, `sphere`, `plane`, and CSG blocks, with z negated
//! (POV-Ray is left-handed) and an object's frame M written as POV-Ray's `matrix` of
//! P·M·P, P the mirror of z; a torus is turned from POV-Ray's y axis onto its own.

use glam::{DAffine3, DMat3, DVec3};

/// A shape, described once.
pub enum Kind {
    Sphere(DVec3, f64),
    Plane(DVec3, DVec3),
    Box(DVec3, DVec3),
    Cylinder(DVec3, DVec3, f64, bool),
    Cone(DVec3, f64, DVec3, f64),
    Disc(DVec3, DVec3, f64, f64),
    Torus(DVec3, DVec3, f64, f64),
    Triangle([DVec3; 3]),
    Csg(&'static str, Vec<Obj>),
}

/// A shape with its colour (Kd 0.7) and its frame (scale, rotate, translate).
pub struct Obj {
    pub kind: Kind,
    pub rgb: [f64; 3],
    pub frame: Option<(DVec3, DVec3, DVec3)>,
}

pub fn obj(kind: Kind, rgb: [f64; 3]) -> Obj {
    Obj {
        kind,
        rgb,
        frame: None,
    }
}

pub fn framed(kind: Kind, rgb: [f64; 3], s: [f64; 3], r: [f64; 3], t: [f64; 3]) -> Obj {
    Obj {
        kind,
        rgb,
        frame: Some((s.into(), r.into(), t.into())),
    }
}

pub fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

fn ours3(p: DVec3) -> String {
    format!("{} {} {}", p.x, p.y, p.z)
}

/// A point or a direction in POV-Ray's left-handed world (z negated).
fn pov3(p: DVec3) -> String {
    format!("<{}, {}, {}>", p.x, p.y, -p.z)
}

impl Obj {
    /// Our extension record(s).
    pub fn ours(&self) -> String {
        let tm = format!(
            "1 {} {} {}  0.7 0 0 1 0 0",
            self.rgb[0], self.rgb[1], self.rgb[2]
        );
        let mut s = match &self.kind {
            Kind::Sphere(c, r) => format!("sphere {} {r} {tm}", ours3(*c)),
            Kind::Plane(p, n) => format!("plane {} {} {tm}", ours3(*p), ours3(*n)),
            Kind::Box(a, b) => format!("box {} {} {tm}", ours3(*a), ours3(*b)),
            Kind::Cylinder(a, b, r, open) => {
                let open = if *open { " open" } else { "" };
                format!("cylinder {} {} {r} {tm}{open}", ours3(*a), ours3(*b))
            }
            Kind::Cone(a, ra, b, rb) => format!("cone {} {ra} {} {rb} {tm}", ours3(*a), ours3(*b)),
            Kind::Disc(c, n, r, h) => format!("disc {} {} {r} {h} {tm}", ours3(*c), ours3(*n)),
            Kind::Torus(c, a, big, small) => {
                format!("torus {} {} {big} {small} {tm}", ours3(*c), ours3(*a))
            }
            Kind::Triangle(p) => format!(
                "triangle {} {} {} {tm}",
                ours3(p[0]),
                ours3(p[1]),
                ours3(p[2])
            ),
            Kind::Csg(op, kids) => {
                let kids: Vec<String> = kids.iter().map(Obj::ours).collect();
                format!("{op}\n{}\nend", kids.join("\n"))
            }
        };
        if let Some((sc, r, t)) = self.frame {
            s += &format!(
                " scale {} rotate {} translate {}",
                ours3(sc),
                ours3(r),
                ours3(t)
            );
        }
        s
    }

    /// The same object in POV-Ray's language.
    pub fn pov(&self) -> String {
        let tex = format!(
            "pigment {{ color rgb <{}, {}, {}> }} Fin(0.7)",
            self.rgb[0], self.rgb[1], self.rgb[2]
        );
        let body = match &self.kind {
            Kind::Sphere(c, r) => format!("sphere {{ {}, {r} {tex}", pov3(*c)),
            Kind::Plane(p, n) => {
                let n = n.normalize();
                format!("plane {{ {}, {} {tex}", pov3(n), n.dot(*p))
            }
            Kind::Box(a, b) => format!("box {{ {}, {} {tex}", pov3(*a), pov3(*b)),
            Kind::Cylinder(a, b, r, open) => {
                let open = if *open { " open" } else { "" };
                format!("cylinder {{ {}, {}, {r}{open} {tex}", pov3(*a), pov3(*b))
            }
            Kind::Cone(a, ra, b, rb) => {
                format!("cone {{ {}, {ra}, {}, {rb} {tex}", pov3(*a), pov3(*b))
            }
            Kind::Disc(c, n, r, h) => format!("disc {{ {}, {}, {r}, {h} {tex}", pov3(*c), pov3(*n)),
            Kind::Torus(c, a, big, small) => {
                // POV-Ray's torus turns about y through the origin: y to the axis, then
                // moved to the centre (in its own, mirrored, world).
                let y = a.normalize();
                let (x, z) = y.any_orthonormal_pair();
                let m = DAffine3::from_mat3_translation(DMat3::from_cols(x, y, z), *c);
                format!("torus {{ {big}, {small} {} {tex}", pov_matrix(&m))
            }
            Kind::Triangle(p) => format!(
                "triangle {{ {}, {}, {} {tex}",
                pov3(p[0]),
                pov3(p[1]),
                pov3(p[2])
            ),
            Kind::Csg(op, kids) => {
                let kids: Vec<String> = kids.iter().map(Obj::pov).collect();
                format!("{op} {{\n{}\n", kids.join("\n"))
            }
        };
        match self.frame {
            Some((s, r, t)) => format!("{body} {} }}", pov_matrix(&affine(s, r, t))),
            None => format!("{body} }}"),
        }
    }
}

/// Our frame's map: T · Rz · Ry · Rx · S.
fn affine(s: DVec3, r: DVec3, t: DVec3) -> DAffine3 {
    let r = r * (std::f64::consts::PI / 180.0);
    let rot =
        DMat3::from_rotation_z(r.z) * DMat3::from_rotation_y(r.y) * DMat3::from_rotation_x(r.x);
    DAffine3::from_mat3_translation(rot * DMat3::from_diagonal(s), t)
}

/// POV-Ray's `matrix` for a map of ours: P·M·P, P the mirror of z, its rows the images
/// of x, y, z, then the translation.
fn pov_matrix(m: &DAffine3) -> String {
    let p = DMat3::from_diagonal(v(1.0, 1.0, -1.0));
    let a = p * m.matrix3 * p;
    let t = p * m.translation;
    let c = [a.x_axis, a.y_axis, a.z_axis, t];
    let vals: Vec<String> = c
        .iter()
        .flat_map(|c| [c.x, c.y, c.z])
        .map(|x| format!("{x}"))
        .collect();
    format!("matrix <{}>", vals.join(", "))
}
