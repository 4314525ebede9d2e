//! Reliability round three's property: random frame specs, sizes, shard counts and anti-aliasing settings
//! fed to the validators. Whatever they accept fits `whitted::limits`: frame lists within
//! the sequence and `MAX_FRAMES`, shard counts within `MAX_SHARDS`, sizes within
//! `size_ok`, adaptive lattices within `MAX_ADAPTIVE_BYTES`; and each case returns within
//! a deadline, so no validator loops over a number as typed. `PROPTEST_CASES` sets the
//! count.

use proptest::prelude::*;
use std::sync::mpsc;
use std::time::Duration;
use whitted::limits::{size_ok, MAX_ADAPTIVE_BYTES, MAX_FRAMES, MAX_SHARDS};
use whitted::render::adaptive::{worst_bytes, Adaptive};
use whitted_anim::select::{select, Shard};

/// Far above what any accepted case takes; a loop over a typed number never ends.
const DEADLINE: Duration = Duration::from_secs(20);

/// Runs `f` on its own thread, at most `DEADLINE`.
fn bounded<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> Result<T, String> {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(f());
    });
    rx.recv_timeout(DEADLINE)
        .map_err(|e| format!("no answer within {DEADLINE:?} ({e})"))
}

/// Numbers as a user types them: small, at the limits, past every integer type.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        (0u64..40).prop_map(|n| n.to_string()),
        (0u64..=u64::MAX).prop_map(|n| n.to_string()),
        Just("9999999999".to_string()),
        Just("4294967295".to_string()),
        Just("4294967296".to_string()),
        Just("18446744073709551616".to_string()),
        Just("1000000".to_string()),
        Just("1000001".to_string()),
        Just("0".to_string()),
        Just("-3".to_string()),
    ]
}

/// A frame spec of one to three items with random ends and steps.
fn spec() -> impl Strategy<Value = String> {
    let step = prop_oneof![Just(""), Just("x"), Just("y"), Just(":")];
    let item = (number(), number(), step, number()).prop_map(|(a, b, s, k)| match s {
        "" => format!("{a}-{b}"),
        s => format!("{a}-{b}{s}{k}"),
    });
    prop::collection::vec(prop_oneof![item, number()], 1..4).prop_map(|v| v.join(","))
}

fn config() -> ProptestConfig {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok());
    ProptestConfig {
        cases: cases.unwrap_or(400),
        max_shrink_iters: 500,
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn accepted_frame_specs_and_shards_fit_the_limits(
        total in prop_oneof![1u32..50, Just(MAX_FRAMES)],
        list in spec(),
        shard in (number(), number()).prop_map(|(k, n)| format!("{k}/{n}")),
    ) {
        let (l, s) = (list.clone(), shard.clone());
        let outcome = bounded(move || {
            let shard = s.parse::<Shard>().ok().and_then(|s| match s {
                Shard::Part { index, count } => Some((index, count)),
                Shard::Auto => None,
            });
            if let Some((_, n)) = shard {
                assert!((1..=MAX_SHARDS).contains(&n), "{s} accepted");
            }
            select(total, Some(&l), shard).map(|frames| frames.len())
        });
        match outcome {
            Ok(Ok(n)) => prop_assert!(n as u64 <= u64::from(total.min(MAX_FRAMES)), "{list}: {n}"),
            Ok(Err(_)) => {}
            Err(hang) => prop_assert!(false, "{list} / {shard}: {hang}"),
        }
    }

    #[test]
    fn accepted_sizes_and_anti_aliasing_fit_the_limits(
        width in prop_oneof![1u32..4000, Just(16384u32), 16385u32..=u32::MAX],
        height in prop_oneof![1u32..4000, Just(4096u32), 0u32..=u32::MAX],
        depth in prop_oneof![0i64..=6, -2i64..100],
        threshold in prop_oneof![0.0f64..=3.0, -1.0f64..10.0],
    ) {
        // The command line's spelling and the manifest's reach the same checks.
        let spelled = format!("adaptive:{threshold}:{depth}").parse::<Adaptive>();
        let given = Adaptive::with(Some(threshold), Some(depth));
        prop_assert_eq!(spelled.is_ok(), given.is_ok());
        if let Ok(aa) = given {
            let fits = aa.fits(width, height).is_ok();
            let bytes = worst_bytes(width.into(), height.into(), aa.depth);
            prop_assert_eq!(fits, bytes <= MAX_ADAPTIVE_BYTES);
        }
        let manifest = format!(
            "scene = \"s.txt\"\nframes = 2\n[render]\nwidth = {width}\nheight = {height}\n\
             antialias = {{ mode = \"adaptive\", threshold = {threshold:?}, depth = {depth} }}\n"
        );
        let parsed = whitted_anim::Manifest::parse(&manifest, std::path::Path::new("m.toml"));
        if let Ok(m) = parsed {
            prop_assert!(size_ok(width.into(), height.into()), "{width}×{height} accepted");
            let aa = m.render.antialias.expect("adaptive");
            let bytes = worst_bytes(width.into(), height.into(), aa.depth);
            prop_assert!(bytes <= MAX_ADAPTIVE_BYTES, "{width}×{height} at depth {depth}: {bytes} bytes");
        }
    }
}
