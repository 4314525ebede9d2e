//! Every limit the library enforces, defined once: image sizes, counts, light intensity,
//! supersampling and motion-blur samples, frame counts and coordinate magnitudes. The
//! scene parser, the manifest and the animation pipeline all refer here.

/// The largest image side accepted.
pub const MAX_SIDE: u32 = 16384;
/// The largest pixel count accepted (2^26: 201 MB of RGB bytes, more in the float pipeline).
pub const MAX_PIXELS: u64 = 1 << 26;
/// The brightest light accepted. The report's intensities are 0..1 (IV.2); brighter ones
/// are allowed, within a bound that keeps every sum of light finite.
pub const MAX_INTENSITY: f64 = 1000.0;
/// The largest count of each kind of object or light.
pub const MAX_COUNT: u64 = 1_000_000;
/// The largest n of an n×n supersampling grid.
pub const MAX_SAMPLES: u32 = 16;
/// The most sub-frames a motion-blurred frame may average.
pub const MAX_BLUR_SAMPLES: u32 = 64;
/// The most frames a manifest may ask for.
pub const MAX_FRAMES: u32 = 1_000_000;
/// The largest coordinate magnitude a camera key, look-at point or circle accepts; keeps
/// every distance and knot finite.
pub const MAX_COORD: f64 = 1e9;
/// The largest number of turns a circle accepts (keeps turns·frame finite).
pub const MAX_TURNS: f64 = 1e6;
/// The lowest frame rate a manifest accepts: one frame every 100 s (ffmpeg's rational
/// rates and every duration stay finite and meaningful).
pub const MIN_FPS: f64 = 0.01;
/// The highest frame rate a manifest accepts.
pub const MAX_FPS: f64 = 1000.0;
/// The largest scene file read: 256 MiB (a million objects of each kind at about 100
/// bytes a record fit, with room for comments).
pub const MAX_SCENE_BYTES: u64 = 256 << 20;
/// The largest mesh file read (`mesh "file"`): 256 MiB, a million-triangle OBJ or ASCII
/// PLY (about 60 MB) with room to spare, a binary PLY of the triangle limit (about 80 MB).
pub const MAX_MESH_BYTES: u64 = 256 << 20;
/// The most triangles one mesh may have after its polygons are fanned: 2^22 (4,194,304),
/// a million-triangle model four times over; the tree's build needs about 150 bytes a
/// triangle at its peak, so the largest mesh stays under a gigabyte.
pub const MAX_MESH_TRIANGLES: u64 = 1 << 22;
/// The deepest CSG blocks nest (the outermost block is level 1): 1,000 levels, far past
/// any modelled object, few enough that a tree of alternating operations (which does not
/// flatten) stays a short walk on a worker thread's stack.
pub const MAX_CSG_DEPTH: usize = 1000;
/// The most vertices (or texture coordinates, or normals) one mesh file may list: 2^23
/// (8,388,608), two a triangle of the triangle budget, so a file of vertices alone cannot
/// take gigabytes before its faces are read.
pub const MAX_MESH_VERTICES: u64 = 1 << 23;
/// The largest manifest file read: 16 MiB.
pub const MAX_MANIFEST_BYTES: u64 = 16 << 20;
/// The largest frame file read by `status`, `--resume` and `encode`: the RGB bytes of
/// the largest image accepted (`MAX_PIXELS`) and 16 MiB for headers and metadata.
pub const MAX_FRAME_BYTES: u64 = 3 * MAX_PIXELS + (16 << 20);
/// The most memory one adaptively anti-aliased frame's lattice may need in the worst case
/// (every pixel splitting to the full depth): 2 GiB. 640×480 at depth 6, 1920×1080 at depth
/// 4 and 3840×2160 at depth 2 fit; 4096×2048 at depth 6 (33 GB) does not.
pub const MAX_ADAPTIVE_BYTES: u64 = 2 << 30;
/// The largest number of shards a set of frames may be split into (`--shard K/N`,
/// `estimate --shards N`, a scheduler's array size): as many as the most frames.
pub const MAX_SHARDS: u32 = MAX_FRAMES;
/// The longest piece of input an error message quotes, in characters; longer ones are
/// cut with "…".
pub const MAX_QUOTED: usize = 60;

/// Whether `width`×`height` is a size the renderer accepts.
pub fn size_ok(width: u64, height: u64) -> bool {
    (1..=u64::from(MAX_SIDE)).contains(&width)
        && (1..=u64::from(MAX_SIDE)).contains(&height)
        && width * height <= MAX_PIXELS
}

/// The largest area-light grid side (N1, N2): 64 × 64 = 4,096 shadow rays per hit.
pub const MAX_AREA_SIDE: u64 = 64;

/// The largest `focus` Samples: 32 × 32 = 1,024 lens rays per camera sample.
pub const MAX_LENS_SAMPLES: u64 = 32;

/// The largest side of an image texture's picture.
pub const MAX_TEXTURE_SIDE: u32 = 16384;
/// The most pixels an image texture may have (2^24: 4096 × 4096, 201 MB as floats).
pub const MAX_TEXTURE_PIXELS: u64 = 1 << 24;
/// The most pixels all the image textures of one scene may hold together: 2^24, what the
/// largest one may hold (201 MB as floats), so that a scene's images stay within it
/// however many files it names (25 files of 16384 × 1024 took 3.8 GB).
pub const MAX_SCENE_TEXTURE_PIXELS: u64 = MAX_TEXTURE_PIXELS;
/// The most objects one scene may have, of every kind together (Scene.txt's records,
/// extension shapes and CSG blocks, NFF's spheres, cones and polygons' triangles):
/// 300,000. An object takes about 1 KB once parsed and in the tree (200,000 spheres
/// rendered in 220 MB), so a scene at the budget, or a file refused past it (4 M spheres
/// in 79 MB of NFF), stays under 500 MB; a million objects took 1.1 GB. A mesh is one
/// object; its triangles have their own budget.
pub const MAX_SCENE_OBJECTS: u64 = 300_000;
/// The most triangles all the meshes of one scene may have together: what one mesh may
/// have.
pub const MAX_SCENE_TRIANGLES: u64 = MAX_MESH_TRIANGLES;
/// The largest image texture file read: 256 MiB.
pub const MAX_TEXTURE_BYTES: u64 = 256 << 20;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes() {
        assert!(size_ok(640, 480));
        assert!(size_ok(16384, 4096)); // exactly 2^26
        assert!(!size_ok(16384, 4097));
        assert!(!size_ok(0, 10));
        assert!(!size_ok(16385, 1));
    }
}
