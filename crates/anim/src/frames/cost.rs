//! What each frame cost: a small JSON record beside the frame, in the folder's hidden
//! `.whitted-record/` (`NAME.cost.json`), never in the frame's bytes and never read to
//! decide whether a frame is up to date. It names the frame's digest, so that a cost is
//! only believed for the picture it was measured on:
//!
//! ```text
//! {"frame":7,"digest":"3f…","wall_s":0.41,"cpu_s":0.79,"peak_memory_bytes":48234496,
//!  "eye":3072,"eye_hits":2811,"reflect":1204,"refract":0,"shadow":5622}
//! ```
//!
//! The rays are named as `raytrace --stats` names them. `cpu_s` is the process's CPU
//! time over the frame's wall interval divided by the mean number of frames in flight
//! at its start and end (frames render side by side and share the process's threads, so
//! a frame's own CPU time is an apportioned share; the shares add up to about the run's
//! CPU time). `peak_memory_bytes` is the process's peak resident size (`VmHWM`) when the
//! frame ended. Both are `null` where the system does not tell (off Linux). A record is
//! read only from a regular file of at most 64 KiB (`read`): a link to `/dev/zero` or a
//! FIFO under a record's name is no record.

use super::provenance::RAW_RECORDS;
use serde::{Deserialize, Serialize};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;
use whitted::output::temp_beside;
use whitted::trace::RayCount;

/// The suffix of a cost record after the frame's file name.
pub const COST_SUFFIX: &str = ".cost.json";

/// What one frame cost.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FrameCost {
    /// The frame's number.
    pub frame: u32,
    /// The digest of the frame the cost was measured on (its provenance).
    pub digest: String,
    /// Wall-clock seconds to render, encode and write it.
    pub wall_s: f64,
    /// Its share of the process's CPU seconds.
    pub cpu_s: Option<f64>,
    /// The process's peak resident memory when it ended, in bytes.
    pub peak_memory_bytes: Option<u64>,
    /// Camera rays.
    pub eye: u64,
    /// Camera rays that hit an object.
    pub eye_hits: u64,
    /// Reflection rays.
    pub reflect: u64,
    /// Refraction rays.
    pub refract: u64,
    /// Shadow rays.
    pub shadow: u64,
}

impl FrameCost {
    /// All its rays.
    pub fn rays(&self) -> u64 {
        self.eye + self.reflect + self.refract + self.shadow
    }

    /// The rays as a `RayCount` (secondary = reflect + refract).
    pub fn ray_count(&self) -> RayCount {
        RayCount {
            primary: self.eye,
            secondary: self.reflect + self.refract,
            shadow: self.shadow,
            eye_hits: self.eye_hits,
            reflect: self.reflect,
            refract: self.refract,
        }
    }
}

/// Where the cost record of the frame at `frame_path` lives.
pub fn cost_path(frame_path: &Path) -> PathBuf {
    let dir = frame_path.parent().unwrap_or(Path::new(""));
    let name = frame_path.file_name().unwrap_or_default().to_string_lossy();
    dir.join(RAW_RECORDS).join(format!("{name}{COST_SUFFIX}"))
}

/// Writes the cost record of the frame at `frame_path` atomically.
pub fn write(frame_path: &Path, cost: &FrameCost) -> std::io::Result<()> {
    let path = cost_path(frame_path);
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    let mut tmp = temp_beside(&path)?;
    let text = serde_json::to_string(cost).map_err(std::io::Error::other)?;
    writeln!(tmp, "{text}")?;
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}

/// The largest cost record read (they are about 250 bytes).
pub const MAX_COST_BYTES: u64 = 64 << 10;

/// The cost record of the frame at `frame_path`, if there is a readable one: a regular
/// file (not a link, a FIFO or a device) of at most `MAX_COST_BYTES`.
pub fn read(frame_path: &Path) -> Option<FrameCost> {
    let path = cost_path(frame_path);
    // The tool writes records as files, never as links.
    if !std::fs::symlink_metadata(&path).is_ok_and(|m| m.is_file()) {
        return None;
    }
    let bytes = whitted::input::read_regular(&path, MAX_COST_BYTES, "cost record").ok()?;
    serde_json::from_slice(&bytes).ok()
}

/// The process's peak resident memory so far, in bytes (`VmHWM`); `None` off Linux.
pub fn peak_memory() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    parse_vm_hwm(&status)
}

/// `VmHWM:   12345 kB` of a `/proc/PID/status` text, in bytes.
fn parse_vm_hwm(status: &str) -> Option<u64> {
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let mut words = line["VmHWM:".len()..].split_whitespace();
    let n: u64 = words.next()?.parse().ok()?;
    match words.next() {
        Some("kB") => Some(n * 1024),
        _ => None,
    }
}

/// Measures frames that render side by side: each frame's wall time, and its share of
/// the process's CPU time.
#[derive(Debug, Default)]
pub struct Meter {
    in_flight: AtomicUsize,
}

/// One frame being measured.
pub struct Measuring {
    start: Instant,
    cpu: Option<f64>,
    flight: usize,
}

impl Meter {
    /// A frame starts.
    pub fn start(&self) -> Measuring {
        let flight = self.in_flight.fetch_add(1, Ordering::SeqCst) + 1;
        Measuring {
            start: Instant::now(),
            cpu: whitted_cmd::stats::cpu_seconds(),
            flight,
        }
    }

    /// The frame measured by `m`, with digest `digest`, has ended having cast `rays`.
    pub fn finish(&self, m: Measuring, frame: u32, digest: String, rays: &RayCount) -> FrameCost {
        let wall_s = m.start.elapsed().as_secs_f64();
        let flight_end = self.in_flight.fetch_sub(1, Ordering::SeqCst);
        let cpu_s = match (m.cpu, whitted_cmd::stats::cpu_seconds()) {
            (Some(a), Some(b)) => Some(share(b - a, m.flight, flight_end)),
            _ => None,
        };
        FrameCost {
            frame,
            digest,
            wall_s,
            cpu_s,
            peak_memory_bytes: peak_memory(),
            eye: rays.primary,
            eye_hits: rays.eye_hits,
            reflect: rays.reflect,
            refract: rays.refract,
            shadow: rays.shadow,
        }
    }
}

/// A frame's share of `cpu` seconds of the process, with `a` frames in flight at its
/// start and `b` at its end (itself included in both).
fn share(cpu: f64, a: usize, b: usize) -> f64 {
    let mean = (a.max(1) + b.max(1)) as f64 / 2.0;
    (cpu.max(0.0) / mean * 1000.0).round() / 1000.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vm_hwm_by_hand() {
        let status = "Name:\tanimate\nVmPeak:\t  9000 kB\nVmHWM:\t    2048 kB\nVmRSS:\t 1000 kB\n";
        assert_eq!(parse_vm_hwm(status), Some(2048 * 1024));
        assert_eq!(parse_vm_hwm("Name: x\n"), None);
        assert!(peak_memory().is_some_and(|b| b > 0));
    }

    #[test]
    fn cpu_is_shared_among_frames_in_flight() {
        // 3 s of CPU, 2 frames in flight at the start and 4 at the end: 3 / 3 = 1 s.
        assert_eq!(share(3.0, 2, 4), 1.0);
        assert_eq!(share(0.5, 1, 1), 0.5);
        assert_eq!(share(-0.1, 1, 1), 0.0);
    }

    #[test]
    fn a_record_sits_in_the_hidden_folder_and_reads_back() {
        let dir = tempfile::tempdir().unwrap();
        let frame = dir.path().join("frame_0003.png");
        assert_eq!(
            cost_path(&frame),
            dir.path().join(".whitted-record/frame_0003.png.cost.json")
        );
        let cost = FrameCost {
            frame: 3,
            digest: "ab".into(),
            wall_s: 0.5,
            cpu_s: Some(0.75),
            peak_memory_bytes: Some(4096),
            eye: 10,
            eye_hits: 8,
            reflect: 3,
            refract: 2,
            shadow: 20,
        };
        write(&frame, &cost).unwrap();
        assert_eq!(read(&frame), Some(cost.clone()));
        assert_eq!(cost.rays(), 35);
        assert_eq!(cost.ray_count().total(), 35);
    }
}
