//! Point 9's estimate: frames with ten EXR passes were predicted at 1.40 s and took 0.73 to
//! 0.78 s (1.8 to 1.9 times). The timed frame is drawn on every thread but encoded on one,
//! and was taken whole for a frame of the run, where the other frames in flight overlap
//! its encoding. The estimate now shares the encoding among the frames in flight.

use super::{run, text};
use crate::support::*;
use std::process::Command;
use std::time::Instant;

/// The seconds `animate estimate`'s first line expects.
fn expected(first: &str) -> f64 {
    let before = first.split(" s expected").next().unwrap();
    before
        .rsplit(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap_or_else(|_| panic!("{first}"))
}

#[test]
fn estimate_of_frames_with_exr_passes_is_within_1_5x_of_the_run() {
    let passes = "format = \"exr\"\npasses = [\"depth\", \"position\", \"normal\", \"albedo\", \
                  \"ambient\", \"diffuse\", \"specular\", \"reflection\", \"transmission\", \"fog\"]\n";
    let size = "\n[render]\nwidth = 320\nheight = 240\n";
    let text_m = circle_manifest(size)
        .replace("format = \"png\"\n", passes)
        .replace("frames = 12", "frames = 16");
    let (_dir, m) = project(&text_m);
    // The smaller of two estimates: one timed frame is at the mercy of a loaded machine.
    let mut firsts: Vec<String> = (0..2)
        .map(|_| {
            let (code, out, err) = run(&[&"estimate", &m, &"--threads", &"2"]);
            assert_eq!(code, Some(0), "{err}");
            out.lines().next().unwrap().to_string()
        })
        .collect();
    firsts.sort_by(|a, b| expected(a).total_cmp(&expected(b)));
    let first = &firsts[0];
    let predicted = expected(first);
    let start = Instant::now();
    let mut cmd = Command::new(assert_cmd::cargo::cargo_bin("animate"));
    cmd.arg(&m).args(["-q", "--threads", "2"]);
    let done = output_within(&mut cmd, super::PROMPT * 4);
    let took = start.elapsed().as_secs_f64();
    assert!(done.status.success(), "{}", text(&done.stderr));
    let ratio = predicted / took;
    // Indicative on a shared machine: before, 1.89x (3.2 s for 1.7 s) with the machine
    // quiet, 1.2x to 2.8x as its load came and went; after, 1.0x to 1.2x quiet.
    println!("estimate of 16 EXR frames with ten passes: {predicted:.2} s expected, {took:.2} s taken: {ratio:.2}x (target within 1.5x); {first}");
    // The run's side is not bounded tightly: other work on the machine slows the run's
    // threads more than the one timed frame's (0.5x seen under the load of other builds).
    assert!((0.25..=1.5).contains(&ratio), "{first}: took {took:.2} s");
    assert!(first.contains(" and encoded "), "{first}");
}
