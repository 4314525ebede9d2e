//! Reading back what a frame file records, and whether its bytes are the ones recorded,
//! without trusting anything that is not a regular file of a sane size (`input`):
//!
//! - PNG: the chunks are walked and every chunk's CRC-32 checked (cheap: no
//!   decompression); the record is the `whitted:*` text of the `tEXt` or `iTXt` chunks;
//!   the file must end with IEND;
//! - RAW: the record is `.whitted-record/NAME.txt`, `key: value` lines, whose
//!   `whitted:pixels: sha256 HEX` line must be the SHA-256 of the `.raw` file's bytes, so
//!   a record can never vouch for pixels it did not see (a record replaced after, or by
//!   another run than, its frame; a frame overwritten with other bytes);
//! - JPEG and PPM: the record in the header comment, and the end marker or exact size.
//!
//! With `verify`, the image is also decoded whole (PNG's zlib checksums, JPEG's
//! entropy-coded data). A frame that fails any of this is `Damaged` (to be rendered again).

use super::{raw_record_path, DIGEST_KEY};
use sha2::{Digest, Sha256};
use std::io::{BufReader, Read, Seek, SeekFrom};
use std::path::Path;
use whitted::input::open_regular;
use whitted::limits::MAX_FRAME_BYTES;
use whitted::output::ImageFormat;

/// The key of a RAW record's pixel hash.
pub(crate) const PIXELS_KEY: &str = "whitted:pixels";
/// The key of the manifest's file name in every record.
pub(crate) const MANIFEST_KEY: &str = "whitted:manifest";
/// The largest RAW record read (they are a few hundred bytes).
const MAX_RECORD_BYTES: u64 = 64 << 10;

/// What a frame file holds, as far as provenance goes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Inspection {
    /// No file of that name.
    Missing,
    /// The file cannot be what it claims: not a regular file, too large, cut short, a
    /// bad checksum or pixel hash, a record missing; the reason in words.
    Damaged(String),
    /// The file is whole and its bytes are those its record describes.
    Sound(Record),
}

/// The provenance a sound frame records.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Record {
    /// The digest of the inputs (`DIGEST_KEY`), if recorded.
    pub digest: Option<String>,
    /// The file name of the manifest that rendered it (`MANIFEST_KEY`), if recorded.
    pub manifest: Option<String>,
    /// Every key and value recorded (the stamp), in file order, to say what changed.
    pub pairs: Vec<(String, String)>,
}

impl Record {
    fn from_pairs<'a>(pairs: impl Iterator<Item = (&'a str, &'a str)>) -> Record {
        let mut r = Record::default();
        for (k, v) in pairs {
            r.pairs.push((k.to_string(), v.trim().to_string()));
            match k {
                DIGEST_KEY => r.digest = Some(v.trim().to_string()),
                MANIFEST_KEY => r.manifest = Some(v.trim().to_string()),
                _ => {}
            }
        }
        r
    }

    fn from_lines(text: &str, prefix: &str) -> Record {
        Record::from_pairs(text.lines().filter_map(|l| {
            l.strip_prefix(prefix)
                .and_then(|l| l.split_once(": "))
                .map(|(k, v)| (k.trim(), v))
        }))
    }
}

/// Inspects the frame file `path` of `format`, `width`×`height`.
pub(crate) fn inspect(
    path: &Path,
    format: ImageFormat,
    width: u32,
    height: u32,
    verify: bool,
) -> Inspection {
    if std::fs::symlink_metadata(path).is_err() {
        return Inspection::Missing;
    }
    match inspect_file(path, format, width, height, verify) {
        Ok(record) => Inspection::Sound(record),
        Err(why) => Inspection::Damaged(why),
    }
}

fn inspect_file(
    path: &Path,
    format: ImageFormat,
    width: u32,
    height: u32,
    verify: bool,
) -> Result<Record, String> {
    let (file, len) = open_regular(path, MAX_FRAME_BYTES, "frame").map_err(|e| e.to_string())?;
    let pixels = 3 * u64::from(width) * u64::from(height);
    let record = match format {
        ImageFormat::Png => png_record(BufReader::with_capacity(1 << 16, file))?,
        ImageFormat::Raw => {
            if len != pixels {
                return Err(format!("{len} bytes, not the {pixels} of its size"));
            }
            raw_record(path, file)?
        }
        ImageFormat::Jpeg { .. } | ImageFormat::Ppm => {
            let mut file = file;
            if !ends_whole(&mut file, len, format, width, height) {
                return Err("cut short".into());
            }
            let mut head = Vec::new();
            file.seek(SeekFrom::Start(0))
                .and_then(|_| file.take(70_000).read_to_end(&mut head))
                .map_err(|e| e.to_string())?;
            header_record(&head, format)
        }
        ImageFormat::Exr(_) => {
            // Every chunk must be there and readable; the record is in the header.
            let texts = whitted::output::exr::texts_if_whole(BufReader::new(file), width, height)
                .ok_or("cut short, or a chunk cannot be read")?;
            Record::from_pairs(texts.iter().map(|(k, v)| (k.as_str(), v.as_str())))
        }
    };
    if verify {
        decode(path, format, width, height)?;
    }
    Ok(record)
}

/// Whether the open JPEG or PPM `file` of `len` bytes, `width`×`height`, ends where its
/// format ends: a JPEG with its end marker, a PPM of exactly its header and pixels. A copy
/// cut short keeps the record at its head, so the record alone does not make a frame.
/// Only the bytes looked at are read.
fn ends_whole(file: &mut std::fs::File, len: u64, format: ImageFormat, w: u32, h: u32) -> bool {
    let pixels = 3 * u64::from(w) * u64::from(h);
    let mut read_at = |at: u64, n: u64| -> Option<Vec<u8>> {
        file.seek(SeekFrom::Start(at)).ok()?;
        let mut bytes = Vec::new();
        (&mut *file).take(n).read_to_end(&mut bytes).ok()?;
        Some(bytes)
    };
    match format {
        ImageFormat::Ppm => {
            len >= pixels
                && read_at(0, len - pixels).is_some_and(|head| {
                    let head = String::from_utf8_lossy(&head);
                    head.starts_with("P6\n") && head.ends_with(&format!("\n{w} {h}\n255\n"))
                })
        }
        _ => len >= 2 && read_at(len - 2, 2).is_some_and(|b| b == [0xFF, 0xD9]),
    }
}

/// The record of a PNG read from its text chunks, every chunk's CRC checked.
fn png_record(mut r: impl Read) -> Result<Record, String> {
    let io = |e: std::io::Error| format!("cannot read it: {e}");
    let mut sig = [0u8; 8];
    r.read_exact(&mut sig)
        .map_err(|_| "cut short".to_string())?;
    if sig != *b"\x89PNG\r\n\x1a\n" {
        return Err("not a PNG file".into());
    }
    let mut texts: Vec<(String, String)> = Vec::new();
    let mut buf = vec![0u8; 1 << 16];
    loop {
        let mut head = [0u8; 8];
        r.read_exact(&mut head)
            .map_err(|_| "cut short".to_string())?;
        let len = u32::from_be_bytes([head[0], head[1], head[2], head[3]]) as usize;
        let kind = [head[4], head[5], head[6], head[7]];
        let mut crc = crc32fast::Hasher::new();
        crc.update(&kind);
        let text_chunk = &kind == b"tEXt" || &kind == b"iTXt";
        let mut data = Vec::new();
        let mut left = len;
        while left > 0 {
            let n = left.min(buf.len());
            r.read_exact(&mut buf[..n])
                .map_err(|_| "cut short".to_string())?;
            crc.update(&buf[..n]);
            if text_chunk && data.len() < MAX_RECORD_BYTES as usize {
                data.extend_from_slice(&buf[..n]);
            }
            left -= n;
        }
        let mut stored = [0u8; 4];
        r.read_exact(&mut stored)
            .map_err(|_| "cut short".to_string())?;
        if crc.finalize() != u32::from_be_bytes(stored) {
            let name = String::from_utf8_lossy(&kind);
            return Err(format!("a {name} chunk fails its CRC (damaged bytes)"));
        }
        if text_chunk {
            if let Some(pair) = text_pair(&kind, &data) {
                texts.push(pair);
            }
        }
        if &kind == b"IEND" {
            let mut rest = [0u8; 1];
            return match r.read(&mut rest).map_err(io)? {
                0 => Ok(Record::from_pairs(
                    texts.iter().map(|(k, v)| (k.as_str(), v.as_str())),
                )),
                _ => Err("bytes after its end".into()),
            };
        }
    }
}

/// The keyword and text of an uncompressed `tEXt` or `iTXt` chunk.
fn text_pair(kind: &[u8; 4], data: &[u8]) -> Option<(String, String)> {
    let nul = data.iter().position(|&b| b == 0)?;
    let key = String::from_utf8_lossy(&data[..nul]).into_owned();
    let rest = &data[nul + 1..];
    let text = if kind == b"tEXt" {
        rest.iter().map(|&b| char::from(b)).collect()
    } else {
        // compression flag, method, language\0, translated keyword\0, text
        let (&flag, rest) = rest.split_first()?;
        if flag != 0 {
            return None;
        }
        let rest = rest.get(1..)?;
        let lang = rest.iter().position(|&b| b == 0)?;
        let rest = &rest[lang + 1..];
        let tr = rest.iter().position(|&b| b == 0)?;
        String::from_utf8(rest[tr + 1..].to_vec()).ok()?
    };
    Some((key, text))
}

/// The record of a RAW frame, once the frame's bytes hash to the record's pixel hash.
fn raw_record(path: &Path, file: std::fs::File) -> Result<Record, String> {
    let record_path = raw_record_path(path);
    let (record_file, _) = open_regular(&record_path, MAX_RECORD_BYTES, "frame record")
        .map_err(|e| format!("its record {}: {e}", record_path.display()))?;
    let mut text = String::new();
    record_file
        .take(MAX_RECORD_BYTES)
        .read_to_string(&mut text)
        .map_err(|e| format!("its record {}: {e}", record_path.display()))?;
    let expected = text
        .lines()
        .find_map(|l| l.strip_prefix(&format!("{PIXELS_KEY}: sha256 ")))
        .map(str::trim)
        .ok_or("its record has no pixel hash (written by an older version or cut short)")?;
    if pixels_hash_of(file).map_err(|e| e.to_string())? != expected {
        return Err("its bytes are not the pixels its record describes".into());
    }
    Ok(Record::from_lines(&text, ""))
}

/// The SHA-256 of what `r` yields, lower-case hex, read in 64 KiB pieces.
fn pixels_hash_of(mut r: impl Read) -> std::io::Result<String> {
    let mut hasher = Sha256::new();
    let mut buf = vec![0u8; 1 << 16];
    loop {
        match r.read(&mut buf)? {
            0 => break,
            n => hasher.update(&buf[..n]),
        }
    }
    Ok(super::hex(&hasher.finalize()))
}

/// The RAW record's pixel line for `pixels`.
pub(crate) fn pixels_line(pixels: &[u8]) -> (String, String) {
    (
        PIXELS_KEY.into(),
        format!("sha256 {}", super::hex(&Sha256::digest(pixels))),
    )
}

/// The record in a JPEG comment or PPM header.
fn header_record(head: &[u8], format: ImageFormat) -> Record {
    match format {
        ImageFormat::Ppm => Record::from_lines(&String::from_utf8_lossy(head), "# "),
        _ => {
            if head.len() < 6 || head[..4] != [0xFF, 0xD8, 0xFF, 0xFE] {
                return Record::default();
            }
            let len = usize::from(u16::from_be_bytes([head[4], head[5]]));
            let text = head.get(6..(4 + len).min(head.len())).unwrap_or_default();
            Record::from_lines(&String::from_utf8_lossy(text), "")
        }
    }
}

/// Decodes the whole image (`status --verify`): its pixels must come out, at its size.
pub(crate) fn decode(
    path: &Path,
    format: ImageFormat,
    width: u32,
    height: u32,
) -> Result<(), String> {
    if format == ImageFormat::Raw {
        return Ok(()); // its bytes were hashed already
    }
    whitted::output::read_rgb(path, format, width, height)
        .map(drop)
        .map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_chunks_of_both_kinds() {
        let t = text_pair(b"tEXt", b"whitted:digest\0abc").unwrap();
        assert_eq!(t, ("whitted:digest".into(), "abc".into()));
        let i = text_pair(b"iTXt", b"whitted:manifest\0\0\0\0\0\xe6\x97\xa5.toml").unwrap();
        assert_eq!(i, ("whitted:manifest".into(), "日.toml".into()));
        assert_eq!(text_pair(b"iTXt", b"k\0\x01\0\0\0zz"), None); // compressed
    }

    #[test]
    fn the_pixel_line_is_the_sha256_of_the_bytes() {
        // SHA-256 of "abc" (FIPS 180-2, appendix B.1).
        let (k, v) = pixels_line(b"abc");
        assert_eq!(k, PIXELS_KEY);
        assert_eq!(
            v,
            "sha256 ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
        assert_eq!(pixels_hash_of(&b"abc"[..]).unwrap(), v[7..]);
    }

    #[test]
    fn png_chunks_are_checked() {
        let frame = whitted::base::Frame {
            width: 3,
            height: 2,
            pixels: (0..18).collect(),
        };
        let meta = vec![(DIGEST_KEY.to_string(), "d1".to_string())];
        let mut png = Vec::new();
        whitted::output::encode(&frame, ImageFormat::Png, &meta, &mut png).unwrap();
        let r = png_record(&png[..]).unwrap();
        assert_eq!(r.digest.as_deref(), Some("d1"));
        let idat = png.windows(4).position(|w| w == b"IDAT").unwrap();
        let mut bad = png.clone();
        bad[idat + 5] ^= 0x40;
        let e = png_record(&bad[..]).unwrap_err();
        assert!(e.contains("IDAT chunk fails its CRC"), "{e}");
        assert_eq!(png_record(&png[..png.len() - 1]).unwrap_err(), "cut short");
        let mut long = png.clone();
        long.push(0);
        assert_eq!(png_record(&long[..]).unwrap_err(), "bytes after its end");
    }
}
