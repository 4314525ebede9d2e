//! The shadow cache (Haines and Greenberg's "last blocker", 1986): for each thread and
//! each of the scene's point lights (and each point of an extension light: an area
//! light's grid point has its own), the opaque primitive that stopped the thread's last
//! shadow ray towards that light. The next shadow ray to the same light tests it first,
//! and when it blocks again the walk through the tree is skipped.
//!
//! Exactness. A shadow ray's answer is black as soon as any opaque object meets it
//! within (ε, dist), whichever one it is (`shading::transmission`): the cached
//! primitive's own exact test, the same one the tree's walk would run on it, proves
//! that, so the cache changes which work is done and never the answer. What a thread
//! holds depends on the rows it drew (so on the thread count), which the answers never
//! do: the bytes stay the same on any thread count.
//!
//! The entries name the accelerator that filled them (`Accel::id`, unique per build and
//! shared by its clones, which hold the same primitives): an entry of another scene's
//! accelerator is ignored, so a thread that moves between the frames of an animation
//! never tests a primitive of another scene.

use super::{Prim, ShapePrim};
use std::cell::Cell;
use std::sync::atomic::{AtomicU64, Ordering};

/// Slots per thread: the report's point light k uses slot k mod `SLOTS` (one each for
/// the first `REPORT_SLOTS`), an extension light's ray of key j (`lights::ext_key`: the
/// light and its point on an area light's grid) slot `ext_slot(j)`.
const SLOTS: usize = 64;

/// The slots the report's first point lights have to themselves.
const REPORT_SLOTS: usize = 8;

/// The slot of an extension light's shadow rays of key `key`.
#[inline(always)]
pub(super) fn ext_slot(key: usize) -> usize {
    REPORT_SLOTS + key % (SLOTS - REPORT_SLOTS)
}

/// The primitive that blocked: a sphere of the spheres' tree, or a primitive of the
/// shapes' tree.
#[derive(Clone, Copy, Debug)]
pub(super) enum Blocker {
    /// Nothing cached.
    None,
    /// A sphere (a copy: its test needs nothing else).
    Sphere(Prim),
    /// A triangle, a shape or a mesh triangle (tested through its accelerator's tables),
    /// and its place in the shapes' tree's order.
    Shape(ShapePrim, u32),
}

#[derive(Clone, Copy, Debug)]
struct Entry {
    /// The `Accel::id` that filled it (0: none).
    owner: u64,
    blocker: Blocker,
}

const EMPTY: Entry = Entry {
    owner: 0,
    blocker: Blocker::None,
};

thread_local! {
    static LAST: [Cell<Entry>; SLOTS] = const { [const { Cell::new(EMPTY) }; SLOTS] };
}

static NEXT_ID: AtomicU64 = AtomicU64::new(1);

/// A new accelerator's id (never 0).
pub(super) fn new_id() -> u64 {
    NEXT_ID.fetch_add(1, Ordering::Relaxed)
}

/// The blocker this thread last cached for `light` in accelerator `owner`.
#[inline(always)]
pub(super) fn get(owner: u64, light: usize) -> Blocker {
    let e = LAST.with(|l| l[light % SLOTS].get());
    if e.owner == owner {
        e.blocker
    } else {
        Blocker::None
    }
}

/// Caches `blocker` as the last for `light` in accelerator `owner`.
#[inline(always)]
pub(super) fn put(owner: u64, light: usize, blocker: Blocker) {
    LAST.with(|l| l[light % SLOTS].set(Entry { owner, blocker }));
}

#[cfg(test)]
mod tests {
    use super::super::tests::{bits, scene, Rng};
    use super::super::Accel;
    use super::*;
    use crate::base::Color;
    use crate::optics::Ray;
    use crate::shading;
    use crate::shapes::Sphere;
    use glam::DVec3;

    fn sphere_prim(index: u32) -> Prim {
        Prim {
            sphere: Sphere::new(DVec3::ZERO, 1.0),
            index,
            glass: false,
            opaque: true,
        }
    }

    #[test]
    fn an_entry_is_read_back_by_its_owner_only() {
        let (a, b) = (new_id(), new_id());
        assert_ne!(a, b);
        assert_ne!(a, 0);
        put(a, 3, Blocker::Sphere(sphere_prim(7)));
        assert!(matches!(get(a, 3), Blocker::Sphere(p) if p.index == 7));
        assert!(matches!(get(b, 3), Blocker::None));
        // Another light's slot is its own; light 3 + SLOTS shares light 3's.
        assert!(matches!(get(a, 4), Blocker::None));
        assert!(matches!(get(a, 3 + SLOTS), Blocker::Sphere(_)));
        put(b, 3, Blocker::None);
        assert!(matches!(get(a, 3), Blocker::None));
    }

    #[test]
    fn extension_lights_have_slots_past_the_reports() {
        // Light 2's grid point 5: key 2 × 4096 + 5 = 8197; 8197 mod 56 = 21, slot 29.
        assert_eq!(crate::lights::ext_key(2, 5), 8197);
        assert_eq!(ext_slot(8197), 29);
        assert!((0..10_000).all(|key| (REPORT_SLOTS..SLOTS).contains(&ext_slot(key))));
    }

    #[test]
    fn each_thread_has_its_own_cache() {
        let a = new_id();
        put(a, 0, Blocker::Sphere(sphere_prim(1)));
        std::thread::spawn(move || assert!(matches!(get(a, 0), Blocker::None)))
            .join()
            .unwrap();
        assert!(matches!(get(a, 0), Blocker::Sphere(_)));
    }

    #[test]
    fn cached_answers_are_the_linear_scans() {
        // Three scenes' accelerators used in turn by one thread, three lights each: shadow
        // rays from the points the camera-like rays meet, towards each light, as a
        // frame casts them (neighbours in turn, so the cache has something to reuse).
        let mut rng = Rng(0x5eed_0fca_11ab_1e57);
        let mut scenes: Vec<_> = [300, 700].map(|n| scene(&mut rng, n)).into();
        // A third with 400 triangles, smooth triangles and cones among the spheres (a
        // third of them glass): blockers of the shapes' tree, and their nodes' leaves.
        let spheres = scene(&mut rng, 60);
        scenes.push(super::super::tests::with_shapes(spheres, &mut rng, 400));
        let accels: Vec<_> = scenes.iter().map(|o| Accel::new(o)).collect();
        assert!(accels.iter().all(|a| a.cached));
        let before = super::super::shadow::HOLDER_FOUND.with(|n| n.get());
        let lights = [rng.vec(4.0), rng.vec(4.0), DVec3::new(0.0, 30.0, 0.0)];
        let (mut tried, mut shadowed) = (0, 0);
        for k in 0..60_000 {
            let which = k / 50 % 3;
            let (objects, accel) = (&scenes[which], &accels[which]);
            let (u, v) = (
                (k % 250) as f64 / 125.0 - 1.0,
                (k / 250) as f64 / 120.0 - 1.0,
            );
            let eye = DVec3::new(0.0, 0.0, 20.0);
            let ray = Ray::new(eye, DVec3::new(u, v, -2.0).normalize());
            let Some((t, _)) = accel.nearest(&ray) else {
                continue;
            };
            let p = eye + ray.dir * t;
            for (light, &at) in lights.iter().enumerate() {
                let (to, dist) = ((at - p).normalize(), (at - p).length());
                tried += !matches!(get(accel.id, light), Blocker::None) as usize;
                let want = shading::transmission(objects, p, to, dist);
                let got = accel.transmission_to(objects, light, p, to, dist);
                assert_eq!(bits(got), bits(want), "{k} {light} {p:?}");
                // An extension light's ray (an area light's grid point): its own slot.
                let key = crate::lights::ext_key(light, k % 3);
                tried += !matches!(get(accel.id, ext_slot(key)), Blocker::None) as usize;
                let keyed = accel.transmission_keyed(objects, key, p, to, dist);
                assert_eq!(bits(keyed), bits(want), "{k} {light} keyed {p:?}");
                shadowed += (want == Color::ZERO) as usize;
            }
        }
        assert!(tried > 10_000 && shadowed > 10_000, "{tried} {shadowed}");
        // Blockers found beside a cached shape (1,361 here).
        let found = super::super::shadow::HOLDER_FOUND.with(|n| n.get()) - before;
        assert!(found > 300, "{found}");
    }

    #[test]
    fn a_blocker_beside_the_cached_one_is_found_in_its_node() {
        // A slightly bumpy roof of 2 × 40 × 40 opaque triangles (cells 0.1 wide) at
        // y ≈ 1, shadow rays from points 0.03 apart in rows under it towards a light
        // above: every ray is blocked, often by a triangle near the last one but not
        // the same. Through the cache the answers are the linear scan's, and many
        // blockers are found in the node that holds the cached one's leaf.
        use crate::shapes::{Shape, Triangle};
        use crate::texture::Texture;
        let h = |x: f64, z: f64| DVec3::new(x, 1.0 + 0.03 * (7.0 * x).sin() * (5.0 * z).cos(), z);
        let mut objects = Vec::new();
        for i in 0..40 {
            for j in 0..40 {
                let (x, z) = (f64::from(i) * 0.1 - 2.0, f64::from(j) * 0.1 - 2.0);
                let [a, b, c, d] = [h(x, z), h(x + 0.1, z), h(x + 0.1, z + 0.1), h(x, z + 0.1)];
                for [p, q, r] in [[a, d, c], [a, c, b]] {
                    let t = Triangle::new(p, q, r).expect("a cell's half has an area");
                    let white = Texture::Uniform(Color::splat(0.9));
                    objects.push(super::super::tests::object(Shape::Triangle(t), 0.0, white));
                }
            }
        }
        let accel = Accel::new(&objects);
        assert!(accel.cached);
        let light = DVec3::new(0.31, 5.0, 0.23);
        let before = super::super::shadow::HOLDER_FOUND.with(|n| n.get());
        let mut blocked = 0;
        for row in 0..20 {
            for k in 0..100 {
                let (x, z) = (f64::from(k) * 0.03 - 1.6, f64::from(row) * 0.05 - 0.4713);
                let p = DVec3::new(x, 0.0, z);
                let (to, dist) = ((light - p).normalize(), (light - p).length());
                let want = shading::transmission(&objects, p, to, dist);
                let got = accel.transmission_to(&objects, 0, p, to, dist);
                assert_eq!(bits(got), bits(want), "{p:?}");
                blocked += (want == Color::ZERO) as usize;
            }
        }
        // (A ray through a shared edge may slip between its two triangles.)
        assert!(blocked > 1_950, "{blocked}");
        let found = super::super::shadow::HOLDER_FOUND.with(|n| n.get()) - before;
        // (580 of 2,000 here: about every other ray meets a triangle other than the
        // last one's.)
        assert!(found > blocked / 5, "{found} of {blocked}");
    }
}
