//! The page's files, compiled into the binary (`include_str!`): nothing is read from the
//! disk at run time, so the view serves the same page wherever it is started. The script
//! is split by idea: `app.js` the frames, slider, folder strip and pick; `direct.js` the
//! directing aids (the paths drawn over the picture, the camera copied as a key);
//! `ab.js` the A/B wipe. They share `window.view` and load in this order.

/// One embedded file: its path on the server, `Content-Type` and text.
pub struct Asset {
    /// The route, from `/`.
    pub path: &'static str,
    /// Its `Content-Type`.
    pub content_type: &'static str,
    /// Its text.
    pub text: &'static str,
}

const HTML: &str = "text/html; charset=utf-8";
const JS: &str = "text/javascript; charset=utf-8";
const CSS: &str = "text/css; charset=utf-8";

/// Every file of the page.
pub const ASSETS: [Asset; 6] = [
    Asset {
        path: "/",
        content_type: HTML,
        text: include_str!("index.html"),
    },
    Asset {
        path: "/index.html",
        content_type: HTML,
        text: include_str!("index.html"),
    },
    Asset {
        path: "/app.js",
        content_type: JS,
        text: include_str!("app.js"),
    },
    Asset {
        path: "/direct.js",
        content_type: JS,
        text: include_str!("direct.js"),
    },
    Asset {
        path: "/ab.js",
        content_type: JS,
        text: include_str!("ab.js"),
    },
    Asset {
        path: "/app.css",
        content_type: CSS,
        text: include_str!("app.css"),
    },
];

/// The embedded file served at `path`, if any.
pub fn find(path: &str) -> Option<&'static Asset> {
    ASSETS.iter().find(|a| a.path == path)
}
