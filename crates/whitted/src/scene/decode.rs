//! Scene files are UTF-8 text: decoding their bytes, or saying where the first byte
//! that cannot be read is (the same for every scene format).

use super::error::{FileLoc, SceneError};

/// Decodes file bytes as UTF-8, or says where the first invalid byte is.
pub(crate) fn decode<'a>(bytes: &'a [u8], file: &str) -> Result<&'a str, SceneError> {
    std::str::from_utf8(bytes).map_err(|e| {
        let good = std::str::from_utf8(&bytes[..e.valid_up_to()]).unwrap_or_default();
        // As in the lexer, a leading byte-order mark is not a column.
        let good = good.strip_prefix('\u{feff}').unwrap_or(good);
        let line = good.matches('\n').count() + 1;
        let column = good.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        SceneError::Syntax {
            loc: FileLoc {
                file: file.to_string(),
                line,
                column,
            },
            message: "the file is not UTF-8 text".to_string(),
            context: "byte that cannot be read".to_string(),
        }
    })
}
