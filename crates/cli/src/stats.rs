//! `--stats`: one JSON object on a line after a render, with the ray counts of the SPD's
//! table and the time taken (SPEC §17; the pipeline's per-frame costs use the same names):
//!
//! ```text
//! {"eye":263169,"eye_hits":263169,"reflect":175095,"refract":0,"shadow":954368,"wall_s":3.2,"cpu_s":6.1}
//! ```
//!
//! `cpu_s` is the process's user plus system time (Linux: `/proc/self/stat`, in clock
//! ticks of 1/100 s), `null` where it cannot be read.

use serde::Serialize;
use whitted::trace::RayCount;

/// The fields of the stats line, in order.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Stats {
    /// Camera rays.
    pub eye: u64,
    /// Camera rays that hit an object.
    pub eye_hits: u64,
    /// Reflection rays (total internal reflection included).
    pub reflect: u64,
    /// Refraction rays.
    pub refract: u64,
    /// Shadow rays.
    pub shadow: u64,
    /// Seconds of wall-clock time.
    pub wall_s: f64,
    /// Seconds of processor time, all threads.
    pub cpu_s: Option<f64>,
}

impl Stats {
    /// The stats of a render that cast `rays` in `wall_s` seconds and `cpu_s` of CPU.
    pub fn new(rays: &RayCount, wall_s: f64, cpu_s: Option<f64>) -> Stats {
        Stats {
            eye: rays.primary,
            eye_hits: rays.eye_hits,
            reflect: rays.reflect,
            refract: rays.refract,
            shadow: rays.shadow,
            wall_s,
            cpu_s,
        }
    }
}

/// The stats line (without its newline).
pub fn line(rays: &RayCount, wall_s: f64, cpu_s: Option<f64>) -> String {
    serde_json::to_string(&Stats::new(rays, wall_s, cpu_s)).unwrap_or_default()
}

/// Clock ticks per second of `/proc/self/stat` (USER_HZ, 100 on Linux).
const TICKS: f64 = 100.0;

/// The user and system time of this process so far, in seconds; `None` off Linux.
pub fn cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    parse_stat(&stat)
}

/// utime + stime (fields 14 and 15) of a `/proc/PID/stat` line, in seconds. The command
/// name (field 2) is in parentheses and may hold spaces: fields are counted after its
/// closing parenthesis.
fn parse_stat(stat: &str) -> Option<f64> {
    let rest = &stat[stat.rfind(')')? + 1..];
    let mut fields = rest.split_whitespace().skip(11);
    let utime: u64 = fields.next()?.parse().ok()?;
    let stime: u64 = fields.next()?.parse().ok()?;
    Some((utime + stime) as f64 / TICKS)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stat_line_by_hand() {
        // Fields 14 and 15 are 250 and 50 ticks: 3 seconds.
        let stat = "1234 (my prog) R 1 2 3 4 5 6 7 8 9 10 250 50 0 0 20 0 4 0";
        assert_eq!(parse_stat(stat), Some(3.0));
        assert_eq!(parse_stat("garbage"), None);
        assert!(cpu_seconds().is_some_and(|s| s >= 0.0));
    }

    #[test]
    fn the_line_by_hand() {
        let rays = RayCount {
            primary: 4,
            secondary: 3,
            shadow: 5,
            eye_hits: 2,
            reflect: 2,
            refract: 1,
        };
        assert_eq!(
            line(&rays, 1.5, Some(0.25)),
            r#"{"eye":4,"eye_hits":2,"reflect":2,"refract":1,"shadow":5,"wall_s":1.5,"cpu_s":0.25}"#
        );
    }
}
