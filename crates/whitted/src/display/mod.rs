//! Showing frames in an outside viewer while they render: `--display tev[=HOST:PORT]`
//! (SPEC §13) on both binaries streams rows of pixels to a running
//! [tev](https://github.com/Tom94/tev) in its IPC protocol (`packet`), the viewer pbrt-v4
//! and Mitsuba speak to. Default address `127.0.0.1:14158`, tev's own.
//!
//! ```text
//! raytrace scene.txt --display tev              # 127.0.0.1:14158
//! animate orbit.toml --display tev=10.0.0.5:14158
//! ```
//!
//! A viewer that is not there, or goes away, is one warning on standard error and the
//! render goes on: `Tev` keeps no error, it only stops sending.

pub mod packet;

use crate::base::Transfer;
use std::io::Write;
use std::net::TcpStream;
#[cfg(feature = "display")]
use std::net::{SocketAddr, ToSocketAddrs};
use std::sync::Mutex;
use std::time::Duration;

/// tev's default IPC address.
pub const TEV_DEFAULT: &str = "127.0.0.1:14158";

/// Where `--display` sends pixels.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Display {
    /// A tev viewer at `HOST:PORT`.
    Tev(String),
}

impl std::str::FromStr for Display {
    type Err = String;
    /// `tev` or `tev=HOST:PORT`.
    fn from_str(s: &str) -> Result<Display, String> {
        match s.split_once('=') {
            None if s == "tev" => Ok(Display::Tev(TEV_DEFAULT.into())),
            Some(("tev", addr))
                if addr
                    .rsplit_once(':')
                    .is_some_and(|(h, p)| !h.is_empty() && p.parse::<u16>().is_ok()) =>
            {
                Ok(Display::Tev(addr.into()))
            }
            _ => Err(format!(
                "expected `tev` or `tev=HOST:PORT` (e.g. tev=127.0.0.1:14158), found {s:?}"
            )),
        }
    }
}

/// A connection to tev, or nothing once it failed (after one warning).
pub struct Tev {
    addr: String,
    conn: Mutex<Option<TcpStream>>,
    warn: Box<dyn Fn(&str) + Send + Sync>,
    colour: Transfer,
}

impl Tev {
    /// Connects to tev at `addr` (within a second); a failure is one warning through
    /// `warn` and a `Tev` that sends nothing.
    pub fn connect(addr: &str, warn: Box<dyn Fn(&str) + Send + Sync>) -> Tev {
        #[cfg(feature = "display")]
        let conn = resolve(addr).and_then(|a| {
            TcpStream::connect_timeout(&a, Duration::from_secs(1)).map_err(|e| e.to_string())
        });
        // A lean build (without the tracer's `display` feature) opens no connection.
        #[cfg(not(feature = "display"))]
        let conn: Result<TcpStream, String> =
            Err("this build has no viewer client: the tracer's `display` feature".into());
        let conn = match conn {
            Ok(s) => {
                let _ = s.set_nodelay(true);
                let _ = s.set_write_timeout(Some(SEND_LIMIT));
                Some(s)
            }
            Err(e) => {
                warn(&format!(
                    "no tev viewer at {addr} ({e}); rendering without it (start `tev` first to watch)"
                ));
                None
            }
        };
        Tev {
            addr: addr.into(),
            conn: Mutex::new(conn),
            warn,
            colour: Transfer::Srgb,
        }
    }

    /// This connection sending floats in `colour` (by default `Srgb`: the bytes' display
    /// values decoded to linear light, what an EXR frame holds; `packet`).
    pub fn with_colour(mut self, colour: Transfer) -> Tev {
        self.colour = colour;
        self
    }

    /// A `Tev` that warns on standard error, prefixed with the program's name.
    pub fn connect_stderr(addr: &str, program: &'static str) -> Tev {
        Tev::connect(
            addr,
            Box::new(move |m| eprintln!("{program}: warning: {m}")),
        )
    }

    /// Whether packets still go somewhere.
    pub fn connected(&self) -> bool {
        self.conn.lock().map(|c| c.is_some()).unwrap_or(false)
    }

    /// Sends one packet; a write failure is one warning, then nothing more is sent.
    pub fn send(&self, packet: &[u8]) {
        let Ok(mut guard) = self.conn.lock() else {
            return;
        };
        if let Some(s) = guard.as_mut() {
            if let Err(e) = write_within(s, packet, SEND_LIMIT) {
                (self.warn)(&format!(
                    "the tev viewer at {} went away ({e}); rendering goes on without it",
                    self.addr
                ));
                *guard = None;
            }
        }
    }

    /// Opens (or replaces) image `name` of `width`×`height`, channels R G B.
    pub fn create(&self, name: &str, width: u32, height: u32) {
        self.send(&packet::close_image(name));
        self.send(&packet::create_image(
            name,
            true,
            width,
            height,
            &["R", "G", "B"],
        ));
    }

    /// Sends the rows `y0..` of image `name` (`rgb`: whole rows of `width` pixels), in
    /// packets of at most about 1 MiB.
    pub fn rows(&self, name: &str, width: u32, y0: u32, rgb: &[u8]) {
        let row = width as usize * 3;
        if row == 0 {
            return;
        }
        let per = ((1 << 20) / (row * 4)).max(1);
        for (k, chunk) in rgb.chunks(row * per).enumerate() {
            let h = (chunk.len() / row) as u32;
            let y = y0 + (k * per) as u32;
            let rect = (0, y, width, h);
            self.send(&packet::update_rgb(name, rect, chunk, self.colour));
        }
    }
}

/// The longest one packet may take to send: a viewer that reads nothing for this long is
/// given up for the rest of the run.
pub const SEND_LIMIT: Duration = Duration::from_secs(5);

/// Writes `buf` whole within `limit` in all. A write timeout alone bounds each `write`
/// call, and a viewer that reads a little now and then lets every call return a few
/// bytes just before its timeout: `write_all` then took a timeout per trickle (15.7 s
/// for six frames to a viewer that never read).
fn write_within(s: &mut TcpStream, mut buf: &[u8], limit: Duration) -> std::io::Result<()> {
    use std::io::{Error, ErrorKind};
    let start = std::time::Instant::now();
    while !buf.is_empty() {
        let left = limit.saturating_sub(start.elapsed());
        if left.is_zero() {
            let why = format!("it read nothing for {} s", limit.as_secs());
            return Err(Error::new(ErrorKind::TimedOut, why));
        }
        s.set_write_timeout(Some(left))?;
        match s.write(buf) {
            Ok(0) => return Err(Error::from(ErrorKind::WriteZero)),
            Ok(n) => buf = &buf[n..],
            Err(e) if e.kind() == ErrorKind::Interrupted => {}
            Err(e) => return Err(e),
        }
    }
    Ok(())
}

#[cfg(feature = "display")]
fn resolve(addr: &str) -> Result<SocketAddr, String> {
    addr.to_socket_addrs()
        .map_err(|e| e.to_string())?
        .next()
        .ok_or_else(|| "no address".to_string())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Arc;

    #[test]
    fn display_values() {
        assert_eq!("tev".parse(), Ok(Display::Tev("127.0.0.1:14158".into())));
        assert_eq!(
            "tev=localhost:9".parse(),
            Ok(Display::Tev("localhost:9".into()))
        );
        assert!("tev=nohost".parse::<Display>().is_err());
        assert!("tev=h:99999".parse::<Display>().is_err());
        assert!("x11".parse::<Display>().is_err());
    }

    #[test]
    fn a_missing_viewer_is_one_warning() {
        // A port nobody listens on: bind one, learn its number, close it.
        let port = std::net::TcpListener::bind("127.0.0.1:0")
            .unwrap()
            .local_addr()
            .unwrap()
            .port();
        let said = Arc::new(Mutex::new(Vec::<String>::new()));
        let log = Arc::clone(&said);
        let tev = Tev::connect(
            &format!("127.0.0.1:{port}"),
            Box::new(move |m| log.lock().unwrap().push(m.into())),
        );
        assert!(!tev.connected());
        tev.create("x", 2, 2);
        tev.rows("x", 2, 0, &[0; 12]);
        let said = said.lock().unwrap();
        assert_eq!(said.len(), 1, "{said:?}");
        assert!(
            said[0].starts_with("no tev viewer at 127.0.0.1:"),
            "{}",
            said[0]
        );
    }
}
