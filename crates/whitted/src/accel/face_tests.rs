//! Shadow rays through meshes whose triangles carry their own materials (an OBJ's `.mtl`,
//! `d` giving Kt = 1 − d): each triangle stops or filters the ray by its own Kt and
//! colour, not by its record's, against a brute-force product over every triangle; on
//! the accelerator's two paths (few glass objects: the linear loop; many: the collecting
//! walk).

use super::mesh_tests::soup;
use super::tests::{object, Rng};
use super::*;
use crate::base::Color;
use crate::mesh::{Look, RECORD_LOOK};
use crate::optics::Ray;
use crate::shapes::{MeshRef, Sphere};
use crate::texture::Texture;

const RECORD: Color = Color::new(0.9, 0.5, 0.7);

/// Three file materials: red glass (d 0.5), opaque green, blue glass (d 0.7).
fn looks() -> Vec<Look> {
    let look = |kt: f64, c: Color| Look {
        texture: Texture::Uniform(c),
        material: object(
            Shape::Sphere(Sphere::new(DVec3::ZERO, 1.0)),
            kt,
            Texture::Uniform(c),
        )
        .material,
    };
    vec![
        look(0.5, Color::new(1.0, 0.2, 0.2)),
        look(0.0, Color::new(0.2, 1.0, 0.2)),
        look(0.3, Color::new(0.2, 0.2, 1.0)),
    ]
}

/// An opaque sphere, the mesh with its faces' materials drawn at random (a quarter of
/// them the record's of Kt `kt`), and `far` glass spheres no ray meets.
fn scene(kt: f64, far: usize) -> (Vec<Object>, Arc<Mesh>, Accel) {
    let mut mesh = soup(300, 17);
    mesh.looks = looks();
    let mut rng = Rng(5);
    mesh.face_looks = (0..mesh.triangles.len())
        .map(|_| match ((rng.next() + 1.0) * 2.0) as u32 {
            3 | 4 => RECORD_LOOK,
            k => k,
        })
        .collect();
    let mesh = Arc::new(mesh);
    let (lo, hi) = mesh.extent();
    let mut objects = vec![
        object(
            Shape::Sphere(Sphere::new(DVec3::new(0.5, 0.0, 0.0), 0.7)),
            0.0,
            Texture::Uniform(Color::ONE),
        ),
        object(
            Shape::Mesh(MeshRef { id: 0, lo, hi }),
            kt,
            Texture::Uniform(RECORD),
        ),
    ];
    for i in 0..far {
        let centre = DVec3::new(100.0, 100.0, 100.0 + i as f64);
        objects.push(object(
            Shape::Sphere(Sphere::new(centre, 0.1)),
            0.5,
            Texture::Uniform(Color::ONE),
        ));
    }
    let accel = Accel::with_meshes(&objects, std::slice::from_ref(&mesh), T_MIN);
    (objects, mesh, accel)
}

/// Every triangle the ray crosses before `dist`: blocked by an opaque one, else the
/// product of (Kt × colour) of the glass ones in t order.
fn brute(objects: &[Object], mesh: &Mesh, ray: &Ray, dist: f64) -> Color {
    if objects[0].shape.crossings(ray, dist).count() > 0 {
        return Color::ZERO;
    }
    let record = &objects[1].material;
    let mut hits = Vec::new();
    for k in 0..mesh.triangles.len() as u32 {
        let Some(t) = mesh.hit(k, ray, dist) else {
            continue;
        };
        let (kt, colour) = match mesh.face_looks[k as usize] {
            RECORD_LOOK => (record.kt, RECORD),
            i => {
                let look = &mesh.looks[i as usize];
                (look.material.kt, look.texture.color_at(DVec3::ZERO))
            }
        };
        if kt <= 0.0 {
            return Color::ZERO;
        }
        hits.push((t, k, kt * colour));
    }
    hits.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    hits.iter().fold(Color::ONE, |c, h| c * h.2)
}

#[test]
fn each_face_stops_or_filters_shadow_rays_by_its_own_material() {
    for (kt, far) in [(0.0, 0), (0.6, 0), (0.0, 6), (0.6, 6)] {
        let (objects, mesh, accel) = scene(kt, far);
        let mut rng = Rng(23);
        let (mut lit, mut dark, mut tinted) = (0, 0, 0);
        for k in 0..2000 {
            let (p, d) = (rng.vec(3.0), rng.vec(1.0).normalize());
            let ray = Ray::new(p, d).with_t_min(T_MIN);
            let want = brute(&objects, &mesh, &ray, 4.0);
            let got = accel.transmission(&objects, p, d, 4.0);
            assert_eq!(got, want, "record kt {kt}, {far} far spheres, ray {k}");
            match want {
                c if c == Color::ZERO => dark += 1,
                c if c == Color::ONE => lit += 1,
                _ => tinted += 1,
            }
        }
        assert!(
            lit > 50 && dark > 50 && tinted > 50,
            "{lit} {dark} {tinted}"
        );
    }
}

#[test]
fn a_face_of_d_1_in_a_glass_record_blocks() {
    // A glass record whose every face takes the opaque green material casts a full
    // shadow; an opaque record whose faces are red glass lets red through.
    let (mut objects, _, _) = scene(0.6, 0);
    let mut mesh = soup(1, 3);
    mesh.looks = looks();
    let [a, b, c] = mesh.corners(0);
    let centre = (a + b + c) / 3.0;
    let from = centre - (b - a).cross(c - a).normalize();
    let to = (centre - from).normalize();
    let (lo, hi) = mesh.extent();
    objects.truncate(1);
    objects[0].shape = Shape::Sphere(Sphere::new(DVec3::splat(50.0), 0.1));
    objects.push(object(
        Shape::Mesh(MeshRef { id: 0, lo, hi }),
        0.6,
        Texture::Uniform(RECORD),
    ));
    for (face, record_kt, want) in [
        (1, 0.6, Color::ZERO),
        (0, 0.0, Color::new(0.5, 0.1, 0.1)),
        (RECORD_LOOK, 0.6, 0.6 * RECORD),
    ] {
        let mut m = mesh.clone();
        m.face_looks = vec![face];
        objects[1].material.kt = record_kt;
        let accel = Accel::with_meshes(&objects, &[Arc::new(m)], T_MIN);
        let got = accel.transmission(&objects, from, to, 4.0);
        assert!(
            (got - want).abs().max_element() < 1e-12,
            "face {face}: {got} vs {want}"
        );
    }
}
