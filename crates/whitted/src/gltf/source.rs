//! The bytes a glTF file names, read by the tracer's own bounded readers (never
//! `gltf::import`): each buffer from the GLB's binary chunk, a `data:` URI (base64) or a
//! file beside the glTF file; images the same way or from a buffer view.
//!
//! A URI that names a file must be relative, without a scheme and without a `..`
//! component (a glTF file reads only what lies in its own folder and below it); its
//! percent-escapes are decoded, and a bad one is a refusal, not a panic. Each file is
//! read only when it is a regular file within `MAX_MESH_BYTES`, and each buffer must
//! hold at least its `byteLength`. Every file read is recorded with its SHA-256, so a
//! frame's digest covers the glTF file and everything it names.

use super::error::{at, GltfError};
use crate::limits::MAX_MESH_BYTES;
use base64::Engine;
use std::path::{Component, Path, PathBuf};

pub use super::rig::Named;

/// Where the glTF file is, for what it names.
pub struct Origin<'a> {
    /// The glTF file's name, for messages.
    pub file: &'a str,
    /// Its folder: relative URIs resolve against it.
    pub dir: &'a Path,
}

impl Origin<'_> {
    /// The bytes of `uri` (a `data:` URI or a relative file), refused at `path`.
    pub fn uri(&self, uri: &str, path: &str, named: &mut Named) -> Result<Vec<u8>, GltfError> {
        if let Some(rest) = uri.strip_prefix("data:") {
            let Some((head, data)) = rest.split_once(',') else {
                return Err(at(self.file, path, "a data URI without a comma"));
            };
            if !head.ends_with(";base64") {
                return Err(at(self.file, path, "a data URI that is not base64"));
            }
            return base64::engine::general_purpose::STANDARD
                .decode(data.trim_end())
                .map_err(|e| at(self.file, path, format!("bad base64 in a data URI: {e}")));
        }
        let file = self.resolve(uri, path)?;
        let bytes = crate::input::read_regular(&file, MAX_MESH_BYTES, "glTF buffer or image")
            .map_err(|source| GltfError::Io {
                path: file.display().to_string(),
                what: format!("{path}'s file"),
                source,
            })?;
        named.push((file, crate::input::digest(&bytes)));
        Ok(bytes)
    }

    /// The file a relative URI names, or why it may not be read.
    fn resolve(&self, uri: &str, path: &str) -> Result<PathBuf, GltfError> {
        let refuse = |why: &str| Err(at(self.file, path, format!("the URI `{uri}` {why}")));
        let scheme = uri.split('/').next().unwrap_or("").contains(':');
        if scheme {
            return refuse("has a scheme: only data URIs and relative file names are read");
        }
        let decoded = match percent_encoding::percent_decode_str(uri).decode_utf8() {
            Ok(d) => d.into_owned(),
            Err(_) => return refuse("has a percent-escape that is not UTF-8"),
        };
        if decoded.contains('\0') {
            return refuse("has a NUL byte");
        }
        let rel = Path::new(&decoded);
        for c in rel.components() {
            match c {
                Component::Normal(_) | Component::CurDir => {}
                Component::ParentDir => return refuse("climbs out of the glTF file's folder"),
                _ => return refuse("is absolute: only relative file names are read"),
            }
        }
        Ok(self.dir.join(rel))
    }
}

/// Every buffer of `doc`, each at least its `byteLength` long (`blob`: a GLB's binary
/// chunk).
pub fn buffers(
    doc: &gltf::Document,
    blob: Option<&[u8]>,
    origin: &Origin,
    named: &mut Named,
) -> Result<Vec<Vec<u8>>, GltfError> {
    let mut out = Vec::new();
    for b in doc.buffers() {
        let path = format!("buffers[{}]", b.index());
        let bytes = match b.source() {
            gltf::buffer::Source::Bin => match blob {
                Some(blob) => blob.to_vec(),
                None => {
                    return Err(at(
                        origin.file,
                        path,
                        "names the GLB binary chunk, and the file has none",
                    ))
                }
            },
            gltf::buffer::Source::Uri(uri) => origin.uri(uri, &format!("{path}.uri"), named)?,
        };
        if bytes.len() < b.length() {
            return Err(at(
                origin.file,
                format!("{path}.byteLength"),
                format!(
                    "the buffer holds {} bytes, fewer than its byteLength {}",
                    bytes.len(),
                    b.length()
                ),
            ));
        }
        out.push(bytes);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uris_stay_in_their_folder() {
        let o = Origin {
            file: "a.gltf",
            dir: Path::new("models"),
        };
        let mut named = Named::new();
        for bad in [
            "../x.bin",
            "a/../../x.bin",
            "/etc/passwd",
            "file:///x",
            "http://h/x",
        ] {
            let e = o.uri(bad, "buffers[0].uri", &mut named).unwrap_err();
            assert!(e.to_string().contains("buffers[0].uri"), "{e}");
        }
        assert!(o.uri("%ff.bin", "p", &mut named).is_err());
        assert_eq!(
            o.resolve("sub/my%20file.bin", "p").unwrap(),
            Path::new("models/sub/my file.bin")
        );
        // "AQID" is base64 for 1 2 3.
        assert_eq!(
            o.uri("data:application/octet-stream;base64,AQID", "p", &mut named)
                .unwrap(),
            vec![1, 2, 3]
        );
        assert!(o.uri("data:text/plain,abc", "p", &mut named).is_err());
        assert!(named.is_empty());
    }
}
