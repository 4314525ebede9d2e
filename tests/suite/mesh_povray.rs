//! Meshes against POV-Ray 3.7's `mesh2` on a scene of our own: a grey floor and, read
//! from OBJ files written here, an icosphere (80 triangles) with vertex normals (smooth)
//! and without (flat), and a cube of six quads (fanned into triangles) scaled into a
//! pillar. Ours reads the OBJ through the `mesh` record; POV-Ray gets the same vertices,
//! normals and fanned triangles as `mesh2`, with the same `scale` and `translate` (z
//! negated: POV-Ray is left-handed). Bound: under 1 % of the pixels more than 6 levels
//! apart on a channel. Skips without POV-Ray (fails under CI).

use crate::skip;
use crate::support::povray::share_apart;
use whitted::trace::Tracer;
use whitted::Scene;

const W: u32 = 160;
const H: u32 = 120;

/// The report part: camera, floor, one light.
const BASE: &str = "160 120  0 3 7  0 0.9 0  0 0  0 1 0 1
0 0 0  0 1 0   1 0.8 0.8 0.8   1 0 0 1 0 0
4 8 6  1 1 1  1
";

const POV_BASE: &str = "#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 6 adc_bailout 1/256 }
camera { perspective location <0, 3, -7> direction <0, 0, 1> right <0.5, 0, 0>
  up <0, 0.35, 0> sky <0, 1, 0> look_at <0, 0.9, 0> }
#macro Fin(Kd) finish { ambient 0.2 diffuse Kd phong (1 - Kd) phong_size 20 } #end
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } Fin(1) }
light_source { <4, 8, -6> color rgb <1, 1, 1> }
";

/// An icosahedron subdivided once, on the unit sphere: vertices and triangles.
fn icosphere() -> (Vec<[f64; 3]>, Vec<Vec<usize>>) {
    let g = (1.0 + 5f64.sqrt()) / 2.0;
    let mut v: Vec<[f64; 3]> = [
        [-1.0, g, 0.0],
        [1.0, g, 0.0],
        [-1.0, -g, 0.0],
        [1.0, -g, 0.0],
        [0.0, -1.0, g],
        [0.0, 1.0, g],
        [0.0, -1.0, -g],
        [0.0, 1.0, -g],
        [g, 0.0, -1.0],
        [g, 0.0, 1.0],
        [-g, 0.0, -1.0],
        [-g, 0.0, 1.0],
    ]
    .to_vec();
    let faces: [[usize; 3]; 20] = [
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    let unit = |p: [f64; 3]| {
        let l = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
        p.map(|c| c / l)
    };
    v = v.into_iter().map(unit).collect();
    let mut tris = Vec::new();
    for [a, b, c] in faces {
        let mut mid = |i: usize, j: usize| {
            v.push(unit([0, 1, 2].map(|k| (v[i][k] + v[j][k]) / 2.0)));
            v.len() - 1
        };
        let (ab, bc, ca) = (mid(a, b), mid(b, c), mid(c, a));
        tris.extend([
            vec![a, ab, ca],
            vec![b, bc, ab],
            vec![c, ca, bc],
            vec![ab, bc, ca],
        ]);
    }
    (v, tris)
}

/// A cube of side 1.2 centred at the origin, as six quads.
fn cube() -> (Vec<[f64; 3]>, Vec<Vec<usize>>) {
    let v = (0..8)
        .map(|i| [0, 1, 2].map(|k| if i >> k & 1 == 1 { 0.6 } else { -0.6 }))
        .collect();
    let quads = [
        [0, 1, 3, 2],
        [4, 6, 7, 5],
        [0, 4, 5, 1],
        [2, 3, 7, 6],
        [0, 2, 6, 4],
        [1, 5, 7, 3],
    ];
    (v, quads.iter().map(|q| q.to_vec()).collect())
}

/// The OBJ text of a mesh, with `vn` (the unit positions: a sphere's normals) or without.
fn obj((v, faces): &(Vec<[f64; 3]>, Vec<Vec<usize>>), normals: bool) -> String {
    let mut s = String::from("# written by mesh_povray\n");
    for p in v {
        s += &format!("v {} {} {}\n", p[0], p[1], p[2]);
    }
    for p in v.iter().filter(|_| normals) {
        s += &format!("vn {} {} {}\n", p[0], p[1], p[2]);
    }
    for f in faces {
        let corner = |i: &usize| {
            if normals {
                format!("{0}//{0}", i + 1)
            } else {
                format!("{}", i + 1)
            }
        };
        s += &format!("f {}\n", f.iter().map(corner).collect::<Vec<_>>().join(" "));
    }
    s
}

/// The same mesh as POV-Ray's `mesh2`, polygons fanned as ours are, z negated.
fn mesh2((v, faces): &(Vec<[f64; 3]>, Vec<Vec<usize>>), normals: bool, rest: &str) -> String {
    let vec = |p: &[f64; 3]| format!("<{}, {}, {}>", p[0], p[1], -p[2]);
    let list = v.iter().map(vec).collect::<Vec<_>>().join(", ");
    let mut s = format!("mesh2 {{ vertex_vectors {{ {}, {list} }}\n", v.len());
    if normals {
        s += &format!("normal_vectors {{ {}, {list} }}\n", v.len());
    }
    let tris: Vec<String> = faces
        .iter()
        .flat_map(|f| (1..f.len() - 1).map(move |k| format!("<{}, {}, {}>", f[0], f[k], f[k + 1])))
        .collect();
    s + &format!(
        "face_indices {{ {}, {} }}\n{rest} }}\n",
        tris.len(),
        tris.join(", ")
    )
}

/// Renders `records` (extension records naming files of `files`, written beside the scene
/// for both) with us and `pov` with POV-Ray; the share of pixels apart, or none when POV-Ray is missing.
pub(crate) fn compare(files: &[(&str, Vec<u8>)], records: &str, pov: &str) -> Option<f64> {
    let povray = skip::which("povray", &["/usr/bin/povray"])?;
    let dir = tempfile::tempdir().unwrap();
    for (name, text) in files {
        std::fs::write(dir.path().join(name), text).unwrap();
    }
    let file = dir.path().join("meshes.txt");
    let scene = Scene::parse(&format!("{BASE}{records}"), &file.display().to_string()).unwrap();
    let tracer = Tracer::new(&scene);
    let grid = whitted::render::Options::grid(W, H, 1);
    let (frame, _) = whitted::render(
        &tracer,
        &scene.camera(),
        &grid,
        whitted::render::Picture::new(),
    );
    let ours = dir.path().join("ours.png");
    image::RgbImage::from_raw(W, H, frame.pixels)
        .unwrap()
        .save(&ours)
        .unwrap();
    let pov_file = dir.path().join("scene.pov");
    std::fs::write(&pov_file, format!("{POV_BASE}{pov}")).unwrap();
    let theirs = crate::support::povray::povray_png(&povray, dir.path(), &pov_file, W, H);
    if let Some(keep) = std::env::var_os("MESH_POVRAY_KEEP") {
        let keep = std::path::Path::new(&keep);
        std::fs::copy(&ours, keep.join("ours.png")).unwrap();
        std::fs::copy(&theirs, keep.join("pov.png")).unwrap();
    }
    Some(share_apart(&ours, &theirs, 6))
}

const RED: &str = "1 0.9 0.3 0.2  0.7 0 0 1 0 0";
const POV_RED: &str = "pigment { color rgb <0.9, 0.3, 0.2> } Fin(0.7)";
const BLUE: &str = "1 0.2 0.5 0.9  0.7 0 0 1 0 0";
const POV_BLUE: &str = "pigment { color rgb <0.2, 0.5, 0.9> } Fin(0.7)";

#[test]
fn smooth_icosphere_matches_mesh2() {
    let ico = icosphere();
    crate::support::povray::assert_close(compare(
        &[("ball.obj", obj(&ico, true).into_bytes())],
        &format!("mesh \"ball.obj\" {RED} scale 0.9 0.9 0.9 translate 0 0.9 0\n"),
        &mesh2(
            &ico,
            true,
            &format!("{POV_RED} scale 0.9 translate <0, 0.9, 0>"),
        ),
    ));
}

#[test]
fn flat_icosphere_and_quad_cube_match_mesh2() {
    let (ico, cube) = (icosphere(), cube());
    crate::support::povray::assert_close(compare(
        &[
            ("gem.obj", obj(&ico, false).into_bytes()),
            ("cube.obj", obj(&cube, false).into_bytes()),
        ],
        &format!(
            "mesh \"gem.obj\" {RED} scale 0.7 0.7 0.7 translate -0.9 0.8 0.5 flat\n\
             mesh \"cube.obj\" {BLUE} scale 0.8 1.2 0.8 translate 0.9 0.75 -0.5 flat\n"
        ),
        &format!(
            "{}{}",
            mesh2(
                &ico,
                false,
                &format!("{POV_RED} scale 0.7 translate <-0.9, 0.8, -0.5>")
            ),
            mesh2(
                &cube,
                false,
                &format!("{POV_BLUE} scale <0.8, 1.2, 0.8> translate <0.9, 0.75, 0.5>")
            )
        ),
    ));
}
