//! `animate view` through HTTP: the Host check, no file of the disk served whatever the
//! path, 400 with a JSON reason for bad parameters, the whole frame equal to the frame
//! `animate` writes, a hundred requests at once, a newer request superseding an older
//! one, live reload (a bad edit located exactly as the command line prints it, the last
//! good frame still served, a deleted scene file), and Ctrl-C ending with status 130.

use crate::support;
use crate::view_common;

use std::time::Duration;
use support::*;
use view_common::*;

mod requests;
mod session;

fn viewer(extra: &str) -> (tempfile::TempDir, std::path::PathBuf, Viewer) {
    let (dir, manifest) = project(&circle_manifest(extra));
    let v = Viewer::start(&manifest, &[]);
    (dir, manifest, v)
}

/// A scene of one sphere of radius 1.5 on the point the circle camera looks at.
const ONE_SPHERE: &str = "64 48\n0 3 8\n0 1 0\n0 40\n1 0 0 1\n\
1.5  0 1 0   1 0.8 0.2 0.2   0.9 0 0 1 0 0\n5 10 5  1 1 1  0.9\n";
