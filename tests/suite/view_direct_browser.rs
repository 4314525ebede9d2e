//! `animate view`'s directing aids in a real browser (headless Chromium over the DevTools
//! protocol): "copy camera" fills (and selects) the key field with the server's key, and
//! puts it on the clipboard where the browser allows; the paths overlay draws the
//! server's points over the picture, and follows the frame; "hold A" and the wipe show A
//! left of the line and the live B right of it, pixel for pixel, and the line drags.
//! The screenshot of docs/view.md comes from here (`VIEW_SCREENSHOTS=docs`).

use crate::support;
use crate::view_common;

use serde_json::{json, Value};
use std::path::Path;
use std::time::Duration;
use support::*;
use view_common::cdp::{chromium, Browser};
use view_common::*;

const PATIENCE: Duration = Duration::from_secs(30);

fn rect(b: &mut Browser, id: &str) -> [f64; 4] {
    let r: Value = serde_json::from_str(
        b.eval(&format!(
            "JSON.stringify(document.getElementById('{id}').getBoundingClientRect())"
        ))
        .as_str()
        .unwrap(),
    )
    .unwrap();
    ["left", "top", "width", "height"].map(|k| r[k].as_f64().unwrap())
}

fn screenshot(b: &mut Browser) -> image::RgbImage {
    image::load_from_memory(&b.screenshot()).unwrap().to_rgb8()
}

/// The overlay's points as the page drew them: per path name, its polylines' points.
fn drawn_paths(b: &mut Browser) -> Value {
    let js = "JSON.stringify([...document.querySelectorAll('#paths g')].map(g => [g.dataset.name,
        [...g.querySelectorAll('polyline')].map(l => l.getAttribute('points').split(' ')
          .map(p => p.split(',').map(Number)))]))";
    serde_json::from_str(b.eval(js).as_str().unwrap()).unwrap()
}

/// The server's paths of frame `n` in the same shape as `drawn_paths`.
fn server_paths(v: &Viewer, n: u32) -> Value {
    let (status, got) = v.json(&format!("/api/paths?n={n}"));
    assert_eq!(status, 200, "{got}");
    let shaped: Vec<Value> = (got["paths"].as_array().unwrap().iter())
        .map(|p| {
            let segs: Vec<Value> = (p["segments"].as_array().unwrap().iter())
                .filter(|s| !s.as_array().unwrap().is_empty())
                .map(|s| {
                    let pts: Vec<Value> = (s.as_array().unwrap().iter())
                        .map(|q| json!([q[0], q[1]]))
                        .collect();
                    json!(pts)
                })
                .collect();
            json!([p["name"], segs])
        })
        .collect();
    json!(shaped)
}

/// Two path lists in the shape of `drawn_paths`, the same names and points within 1e-9
/// (JSON writes 160.0 where JavaScript writes 160).
fn same_paths(a: &Value, b: &Value) -> bool {
    type Flat = Vec<(String, Vec<Vec<(f64, f64)>>)>;
    let flat = |v: &Value| -> Flat {
        (v.as_array().unwrap().iter())
            .map(|p| {
                let segs = (p[1].as_array().unwrap().iter())
                    .map(|s| {
                        (s.as_array().unwrap().iter())
                            .map(|q| (q[0].as_f64().unwrap(), q[1].as_f64().unwrap()))
                            .collect()
                    })
                    .collect();
                (p[0].as_str().unwrap().to_string(), segs)
            })
            .collect()
    };
    let (a, b) = (flat(a), flat(b));
    a.len() == b.len()
        && a.iter().zip(&b).all(|((na, sa), (nb, sb))| {
            na == nb
                && sa.len() == sb.len()
                && sa.iter().zip(sb).all(|(x, y)| {
                    x.len() == y.len()
                        && (x.iter().zip(y))
                            .all(|(p, q)| (p.0 - q.0).abs() < 1e-9 && (p.1 - q.1).abs() < 1e-9)
                })
        })
}

fn set_wipe(b: &mut Browser, pc: f64) {
    b.eval(&format!("(() => {{ const w = document.getElementById('wipe'); w.value = {pc}; w.dispatchEvent(new Event('input')); }})()"));
    b.wait_for(&format!("document.body.dataset.wipe === '{pc}'"), PATIENCE);
}

fn shot_for_docs(b: &mut Browser) {
    let dir = match std::env::var("VIEW_SCREENSHOTS").as_deref() {
        Ok("docs") => Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/view"),
        _ => Path::new(env!("CARGO_TARGET_TMPDIR")).join("view"),
    };
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("direct.png"), b.screenshot()).unwrap();
}

#[test]
fn directing_aids_in_chromium() {
    let Some(binary) = chromium() else { return };
    let track = "\n[[track]]\ntarget = \"sphere 1 center\"\n\
                 keys = [{ frame = 0, value = [-1.3, 1.0, 0.0] }, { frame = 11, value = [1.5, 1.8, 1.0] }]\n";
    // A wide lens, so that the camera's own path (at its height) is on the picture.
    let text = circle_manifest(&format!("\n[render]\nwidth = 320\nheight = 240\n{track}"))
        .replace("turns = 1.0\n", "turns = 1.0\nfov = 60.0\n");
    let (_dir, manifest) = project(&text);
    let v = Viewer::start(&manifest, &[]);
    let mut b = Browser::start(&binary, 900, 900);
    let origin = v.url.trim_end_matches('/').to_string();
    b.call(
        "Browser.grantPermissions",
        json!({"origin": origin, "permissions": ["clipboardReadWrite", "clipboardSanitizedWrite"]}),
    );
    b.navigate(&v.url);
    b.wait_for("document.body.dataset.shown === '1:0:1'", PATIENCE);

    // Copy camera: a real click; the field holds the server's key, selected.
    let [l, t, w, h] = rect(&mut b, "copyCam");
    b.click(l + w / 2.0, t + h / 2.0);
    let how = b.wait_for("document.body.dataset.camera", PATIENCE);
    let (_, key) = v.json("/api/camera?n=0");
    let text = key["text"].as_str().unwrap();
    assert!(
        text.contains("{ frame = 0, position = [0.0, 3.0, 8.0], look_at = [0.0, 1.0, 0.0] },"),
        "{text}"
    );
    assert_eq!(b.eval("document.getElementById('camKey').value"), text);
    let selected = b.eval("(() => { const f = document.getElementById('camKey'); return document.activeElement === f && f.selectionStart === 0 && f.selectionEnd === f.value.length && !f.hidden; })()");
    assert_eq!(selected, true, "the key field is shown and selected");
    if how == "0:clipboard" {
        // Where the page says it reached the clipboard, the clipboard holds the key.
        match b.try_eval("navigator.clipboard.readText()") {
            Ok(got) => {
                assert_eq!(got, text);
                println!("the clipboard holds the key");
            }
            Err(e) => println!("the clipboard cannot be read back here: {e}"),
        }
    } else {
        assert_eq!(how, "0:field");
        println!("headless Chromium refused the clipboard: the key is in the selected field");
    }

    // Paths: the overlay draws the server's points, over the picture.
    b.eval("document.getElementById('showPaths').click()");
    b.wait_for("document.body.dataset.paths === '1:0'", PATIENCE);
    let server = server_paths(&v, 0);
    assert_eq!(server.as_array().unwrap().len(), 2, "{server}");
    let drawn = drawn_paths(&mut b);
    assert!(same_paths(&drawn, &server), "{drawn}\n{server}");
    assert_eq!(
        rect(&mut b, "paths"),
        rect(&mut b, "frame"),
        "the overlay covers the picture"
    );
    // The sphere's path meets the sphere: the camera ray through its point of frame 0
    // hits sphere 1.
    let (_, got) = v.json("/api/paths?n=0");
    let at = &got["paths"][1]["at"];
    let (x, y) = (
        at[0].as_f64().unwrap() as u32,
        at[1].as_f64().unwrap() as u32,
    );
    let (_, hit) = v.json(&format!("/api/pick?n=0&x={x}&y={y}"));
    assert_eq!(hit["hit"]["object"], "sphere 1", "{hit}");
    assert_eq!(
        b.eval("document.getElementById('paths').getAttribute('viewBox')"),
        "0 0 320 240"
    );
    // On the screen: a vertex of the camera's path, away from the sphere's, is yellow
    // with the overlay on and is the picture's own colour with it off.
    let [fl, ft, fw, _] = rect(&mut b, "frame");
    let k = fw / 320.0;
    let sphere: Vec<(f64, f64)> = (server[1][1].as_array().unwrap().iter())
        .flat_map(|s| s.as_array().unwrap().iter())
        .map(|p| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
        .collect();
    let vertex = (server[0][1].as_array().unwrap().iter())
        .flat_map(|s| s.as_array().unwrap().iter())
        .map(|p| (p[0].as_f64().unwrap(), p[1].as_f64().unwrap()))
        .find(|&(x, y)| {
            (8.0..312.0).contains(&x)
                && (8.0..232.0).contains(&y)
                && sphere.iter().all(|&(sx, sy)| (sx - x).hypot(sy - y) > 8.0)
        })
        .expect("a camera path vertex on the picture");
    let at = ((fl + vertex.0 * k) as u32, (ft + vertex.1 * k) as u32);
    let on = *screenshot(&mut b).get_pixel(at.0, at.1);
    assert!(
        on[0] > 200 && on[1] > 170 && on[2] < 120,
        "{on:?} at {at:?}"
    );
    b.eval("document.getElementById('showPaths').click()");
    let off = *screenshot(&mut b).get_pixel(at.0, at.1);
    assert_ne!(on, off, "the overlay off leaves the picture");
    // The overlay follows the frame shown.
    b.eval("document.getElementById('showPaths').click()");
    b.eval("(() => { const s = document.getElementById('slider'); s.value = 4; s.dispatchEvent(new Event('input')); })()");
    b.wait_for("document.body.dataset.paths === '1:4'", PATIENCE);
    assert_eq!(drawn_paths(&mut b), server_paths(&v, 4));
    assert_ne!(
        server_paths(&v, 4),
        server,
        "frame 4's camera sees the paths elsewhere"
    );
    b.eval("document.getElementById('showPaths').click()");

    // A/B: frame 0 held as A, frame 6 live as B.
    b.eval("(() => { const s = document.getElementById('slider'); s.value = 0; s.dispatchEvent(new Event('input')); })()");
    b.wait_for("document.body.dataset.shown === '1:0:1'", PATIENCE);
    b.eval("document.getElementById('holdA').click()");
    b.wait_for("document.body.dataset.held === '1:0:1'", PATIENCE);
    b.eval("(() => { const s = document.getElementById('slider'); s.value = 6; s.dispatchEvent(new Event('input')); })()");
    b.wait_for("document.body.dataset.shown === '1:6:1'", PATIENCE);
    let [fl, ft, fw, fh] = rect(&mut b, "frame");
    set_wipe(&mut b, 100.0);
    let only_a = screenshot(&mut b);
    set_wipe(&mut b, 0.0);
    let only_b = screenshot(&mut b);
    set_wipe(&mut b, 30.0);
    let wiped = screenshot(&mut b);
    let line = fl + 0.3 * fw;
    let (mut left_differs, mut right_differs) = (0, 0);
    for y in (ft as u32 + 1)..((ft + fh) as u32 - 1) {
        for x in (fl as u32 + 1)..((fl + fw) as u32 - 1) {
            let (a, bb, got) = (
                only_a.get_pixel(x, y),
                only_b.get_pixel(x, y),
                wiped.get_pixel(x, y),
            );
            if f64::from(x) < line - 4.0 {
                assert_eq!(got, a, "left of the line is A at ({x}, {y})");
                left_differs += usize::from(a != bb);
            } else if f64::from(x) > line + 4.0 {
                assert_eq!(got, bb, "right of the line is B at ({x}, {y})");
                right_differs += usize::from(a != bb);
            }
        }
    }
    assert!(
        left_differs > 500 && right_differs > 500,
        "{left_differs} {right_differs}"
    );
    // The line drags: from 30 % to 70 %.
    let y = ft + fh / 2.0;
    for (kind, x, buttons) in [
        ("mousePressed", line, 1),
        ("mouseMoved", fl + 0.5 * fw, 1),
        ("mouseMoved", fl + 0.7 * fw, 1),
        ("mouseReleased", fl + 0.7 * fw, 0),
    ] {
        b.call("Input.dispatchMouseEvent", json!({"type": kind, "x": x, "y": y, "button": "left", "buttons": buttons, "clickCount": 1}));
    }
    let wipe = b
        .eval("Number(document.body.dataset.wipe)")
        .as_f64()
        .unwrap();
    assert!((wipe - 70.0).abs() < 0.5, "dragged to {wipe} %");
    // An edit on disk: B is the new load, A stays what was held.
    let good = std::fs::read_to_string(&manifest).unwrap();
    std::fs::write(&manifest, good.replace("radius = 8.0", "radius = 6.0")).unwrap();
    b.wait_for("document.body.dataset.shown === '2:6:1'", RELOAD_BOUND);
    assert_eq!(b.eval("document.body.dataset.held"), "1:0:1");
    assert_eq!(
        b.eval("document.getElementById('abSaid').textContent"),
        "A: frame 0 · load 1 ◀ ▶ B: frame 6 · load 2 (live)"
    );
    b.eval("document.getElementById('showPaths').click()");
    set_wipe(&mut b, 50.0);
    b.wait_for("document.body.dataset.paths === '2:6'", PATIENCE);
    // The paths are the live frame's: over B only, right of the line.
    assert_eq!(
        b.eval("document.getElementById('paths').style.clipPath"),
        "inset(0px 0px 0px 50%)"
    );
    shot_for_docs(&mut b);
}
