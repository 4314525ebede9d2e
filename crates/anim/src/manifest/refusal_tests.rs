//! Unit tests of the manifest's refusals: each located at the right line and column,
//! naming the key and, for unknown keys, the valid ones; and no input makes it panic.

use super::tests::{parse, refusal, with, CIRCLE, ORBIT, TOUR};
use super::*;

#[test]
fn unknown_keys_are_located_and_the_valid_ones_named() {
    assert_eq!(
        refusal(&with("bogus = 1")),
        "3:1: unknown key `bogus`; the top level takes `scene`, `frames`, `fps`, `loop`, `[camera]`, `[animation]`, `[output]`, `[render]`, `[check]`, `[[track]]`"
    );
    assert_eq!(
        refusal(&format!("scene = \"s\"\nframes = 3\n{CIRCLE}  spin = 2\n")),
        "8:3: camera: unknown key `spin`; [camera] with path = \"circle\" takes `path`, `name`, `center`, `radius`, `height`, `start_angle`, `turns`, `look_at`, `fov`, `roll`"
    );
    // A circle's key in a spline is unknown too, and the spline's keys are named.
    let src = TOUR.replace("closed = false", "radius = 3.0");
    assert_eq!(
        refusal(&src),
        "5:1: camera: unknown key `radius` (a key of path = \"circle\"); [camera] with path = \"spline\" takes `path`, `name`, `closed`, `constant_speed`, `look_at`, `fov`, `roll`, `keys`"
    );
    let src = TOUR.replace("{ frame = 120,", "{ frame = 120, fov = 2,");
    assert_eq!(
        refusal(&src),
        "10:18: camera.keys[1]: unknown key `fov`; a spline key takes `frame`, `time`, `position`, `ease`, `look_at`"
    );
}

#[test]
fn misspelt_tables_and_keys_are_all_located_with_the_nearest_name() {
    // Issue 16 item 5: `[camra]` was "missing the [camera] table" at 1:1; now it is
    // located at its name, with the nearest known name, and so is every other unknown
    // name of the file, in file order.
    let src = "scene = \"s\"\nframes = 3\n[outptu]\nfromat = \"png\"\n[camra]\npath = \"circle\"\n\
               [render]\nsamles = 2\nmotion_blur = { shuter = 0.5 }\n[[track]]\ntarget = \"light 1 intensity\"\n\
               keys = [{ frame = 0, vlaue = 1 }]\n";
    assert_eq!(
        refusal(src),
        "3:2: unknown table `[outptu]` (did you mean `[output]`?); the top level takes `scene`, `frames`, `fps`, `loop`, `[camera]`, `[animation]`, `[output]`, `[render]`, `[check]`, `[[track]]`\n\
         5:2: unknown table `[camra]` (did you mean `[camera]`?); the top level takes `scene`, `frames`, `fps`, `loop`, `[camera]`, `[animation]`, `[output]`, `[render]`, `[check]`, `[[track]]`\n\
         8:1: render: unknown key `samles` (did you mean `samples`?); [render] takes `width`, `height`, `samples`, `motion_blur`, `antialias`\n\
         9:17: render.motion_blur: unknown key `shuter` (did you mean `shutter`?); motion_blur takes `shutter`, `samples`\n\
         12:22: track[0].keys[0]: unknown key `vlaue` (did you mean `value`?); a track key takes `frame`, `time`, `value`, `ease`"
    );
    // A top-level key near a table's name is suggested as the table.
    assert!(refusal("scene = \"s\"\nframe = 3\n")
        .starts_with("2:1: unknown key `frame` (did you mean `frames`?)"));
    // Dotted keys are walked like tables.
    assert!(
        refusal("scene = \"s\"\nframes = 3\noutput.fromat = \"png\"\n")
            .starts_with("3:8: output: unknown key `fromat` (did you mean `format`?)")
    );
}

#[test]
fn wrong_types_are_located() {
    assert_eq!(
        refusal(&with("").replace("frames = 10", "frames = \"x\"")),
        "2:10: frames: invalid type: string \"x\", expected an integer"
    );
    let src = with("").replace("center = [0, 1, 0]", "center = [0, 1]");
    assert_eq!(
        refusal(&src),
        "6:10: camera.center: invalid length 2, expected an array of length 3"
    );
    assert_eq!(
        refusal("scene = \"s\"\nframes = 3\ncamera = 5\n"),
        "3:10: camera: invalid type: integer `5`, expected a [camera] table"
    );
    let src = with("").replace("radius = 2", "radius = \"big\"");
    assert_eq!(
        refusal(&src),
        "7:10: camera.radius: invalid type: string \"big\", expected a number"
    );
    let src = TOUR.replace(
        "{ frame = 120, position = [10.0, 6.0, 0.0] }",
        "{ frame = 120 }",
    );
    assert_eq!(
        refusal(&src),
        "10:3: camera.keys[1]: missing field `position`"
    );
    let src = with("").replace("height = 1", "");
    assert_eq!(refusal(&src), "4:1: camera: missing field `height`");
    let src = TOUR.replace(
        "position = [10.0, 6.0, 0.0]",
        "position = [10.0, true, 0.0]",
    );
    assert!(refusal(&src).starts_with("10:36: camera.keys[1].position[1]: invalid type: boolean"));
    assert_eq!(
        refusal(&with("[output]\nformat = \"gif\"")),
        "4:10: unknown format `gif`, expected one of png, jpeg, jpg, ppm, raw, exr"
    );
}

#[test]
fn columns_count_characters_and_lines_survive_crlf() {
    let src = with("output = { name = \"é\", bogus = 1 }");
    assert!(
        refusal(&src).starts_with("3:24: output: unknown key `bogus`"),
        "{}",
        refusal(&src)
    );
    let src = with("")
        .replace('\n', "\r\n")
        .replace("frames = 10", "frames = 0");
    assert!(refusal(&src).starts_with("2:10: `frames` must be between 1 and 1000000"));
}

#[test]
fn the_camera_path_is_checked() {
    // No [camera], or one without a path: the scene's eye holds still.
    assert!(parse("scene = \"s\"\nframes = 3\n")
        .unwrap()
        .camera
        .is_none());
    let src = "scene = \"s\"\nframes = 3\n[camera]\nradius = 1\n";
    assert_eq!(
        refusal(src),
        "4:1: camera: unknown key `radius` (a key of path = \"circle\"); [camera] without a path takes `path`, `name`, `look_at`, `fov`, `roll`"
    );
    let src = "scene = \"s\"\nframes = 3\n[camera]\npath = \"spiral\"\n";
    assert!(refusal(src)
        .starts_with("4:8: unknown camera path `spiral`, expected `circle` or `spline`"));
    let src = with("").replace("radius = 2", "radius = 0");
    assert_eq!(
        refusal(&src),
        "7:10: `radius` must be greater than 0, found 0"
    );
    let src = with("").replace("radius = 2", "radius = -inf");
    assert!(refusal(&src).starts_with("7:10: `radius` must be finite"));
    let src = with("").replace("center = [0, 1, 0]", "center = [0, nan, 0]");
    assert!(refusal(&src).starts_with("6:10: `center` coordinates must be finite"));
}

#[test]
fn spline_keys_are_checked_where_they_are() {
    let src = TOUR.replace("frame = 249", "frame = 100");
    assert_eq!(
        refusal(&src),
        "11:13: camera.keys[2]: frame 100 is not after the previous key's frame 120; keys must be in increasing frame order"
    );
    let single = "scene = \"s\"\nframes = 9\n[camera]\npath = \"spline\"\nkeys = [{ frame = 0, position = [0, 0, 0] }]\n";
    assert_eq!(
        refusal(single),
        "5:8: a spline needs at least two keys, found 1"
    );
    let src = TOUR.replace("frame = 249", "frame = 250");
    assert_eq!(
        refusal(&src),
        "11:13: key frame 250 is outside the sequence: frames run from 0 to 249"
    );
    let src = TOUR
        .replace("look_at = [0.0, 1.0, 0.0]", "")
        .replace("{ frame = 120,", "{ look_at = [1, 1, 1], frame = 120,");
    assert_eq!(
        refusal(&src),
        "10:3: camera.keys[1]: either every key has a look_at or none has"
    );
}

#[test]
fn numbers_out_of_range_are_located() {
    let cases = [
        (
            "fps = 0",
            "3:7: `fps` must be a number from 0.01 to 1000, found 0.0",
        ),
        (
            "fps = 5e-324",
            "3:7: `fps` must be a number from 0.01 to 1000, found 5e-324",
        ),
        (
            "fps = nan",
            "3:7: `fps` must be a number from 0.01 to 1000, found NaN",
        ),
        (
            "[output]\njpeg_quality = 101",
            "4:16: `jpeg_quality` must be between 1 and 100, found 101",
        ),
        (
            "[render]\nsamples = 17",
            "4:11: `samples` must be between 1 and 16, found 17",
        ),
        (
            "[render]\nwidth = 0",
            "4:9: `width` must be between 1 and 16384, found 0",
        ),
        (
            "[render]\nwidth = 16384\nheight = 8192",
            "5:10: 16384×8192 is more than 67108864 pixels (2^26): it would exhaust memory",
        ),
        (
            "[check]\nframes = [10]\nreferences = \"r\"",
            "4:11: `check frame` must be between 0 and 9, found 10",
        ),
        (
            "[check]\nframes = [1, 1]\nreferences = \"r\"",
            "4:14: frame 1 is listed twice",
        ),
        (
            "[check]\nframes = []\nreferences = \"r\"",
            "4:10: [check] `frames` must list at least one frame",
        ),
        (
            "[check]\nframes = [1]\nreferences = \"r\"\nfail = 256",
            "6:8: `fail` must be between 0 and 255, found 256",
        ),
        (
            "[check]\nframes = [1]\nreferences = \"r\"\nfail_percent = -1",
            "6:16: `fail_percent` must be between 0 and 100, found -1",
        ),
    ];
    for (extra, expected) in cases {
        assert_eq!(refusal(&with(extra)), expected, "for {extra:?}");
    }
    let src = with("").replace("frames = 10", "frames = 1000001");
    assert_eq!(
        refusal(&src),
        "2:10: `frames` must be between 1 and 1000000, found 1000001"
    );
}

#[test]
fn output_names_must_be_file_names() {
    for bad in ["\"\"", "\"a/b_####\"", "'a\\b'"] {
        let src = with(&format!("[output]\nname = {bad}"));
        assert!(
            refusal(&src).starts_with("4:8: `name` must be a plain file name"),
            "{bad}"
        );
    }
    let src = with("[output]\nname = \"shot_##\"\nformat = \"jpeg\"\njpeg_quality = 75");
    let out = parse(&src).unwrap().output;
    assert_eq!(
        (out.name.as_str(), out.format),
        ("shot_##", ImageFormat::Jpeg { quality: 75 })
    );
}

#[test]
fn no_input_makes_it_panic() {
    // Every prefix of both examples, and some hostile text.
    for text in [ORBIT, TOUR] {
        for (i, _) in text.char_indices() {
            let _ = parse(&text[..i]);
        }
    }
    for text in [
        "\u{0}",
        "[[camera]]",
        "camera.path = 'circle'\n",
        "frames = -9223372036854775808",
    ] {
        let _ = parse(text);
    }
    let deep = format!(
        "scene = {}1{}\n{CIRCLE}",
        "[".repeat(100_000),
        "]".repeat(100_000)
    );
    assert!(refusal(&deep).contains("recursion"));
    let at = |text: &str, offset: usize| {
        let loc = whitted::fileloc::FileLoc::of_offset("m", text, offset);
        (loc.line, loc.column)
    };
    assert_eq!(at("é", 1), (1, 1));
    assert_eq!(at("a\nb", 99), (2, 2));
}
