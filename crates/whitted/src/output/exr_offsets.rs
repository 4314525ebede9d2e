//! The structure of a single-part scan-line EXR file, checked without decompressing
//! anything: what a PNG's chunk CRCs are to `status`, this is to an EXR frame. The header
//! is followed by the offset table, one little-endian u64 per block of lines, and then the
//! blocks, each `y: i32, size: u32, size bytes`:
//!
//! - offset j must point at the block of lines `y0 + j·L` (`L` the compression's lines per
//!   block), so an offset moved, or two swapped, points at the wrong block;
//! - taken in file order, the blocks must follow one another without a gap or an overlap,
//!   from the end of the table to the end of the file, so an offset past the end, a block
//!   cut short or bytes added are seen.
//!
//! Other layouts (tiles, several parts, deep data) are not checked here.

use exr::meta::{BlockDescription, MetaData};
use std::io::{Read, Seek, SeekFrom};

/// Whether the EXR file `file` (positioned at its start) holds a whole, consistent offset
/// table and chain of blocks; `Err` says what is wrong.
pub(super) fn check(mut file: impl Read + Seek) -> Result<(), String> {
    let len = file.seek(SeekFrom::End(0)).map_err(|e| e.to_string())?;
    file.seek(SeekFrom::Start(0)).map_err(|e| e.to_string())?;
    let meta = MetaData::read_from_buffered(&mut file, false).map_err(|e| e.to_string())?;
    // A single-part header ends with its null byte, which the reader consumed last.
    let table = file.stream_position().map_err(|e| e.to_string())?;
    let [header] = meta.headers.as_slice() else {
        return Ok(());
    };
    if header.deep || header.blocks != BlockDescription::ScanLines {
        return Ok(());
    }
    let count = header.chunk_count as u64;
    let first = table + 8 * count;
    if first > len {
        return Err("the offset table runs past the end of the file".into());
    }
    let mut offsets = Vec::with_capacity(count as usize);
    let mut bytes = [0u8; 8];
    for _ in 0..count {
        file.read_exact(&mut bytes).map_err(|e| e.to_string())?;
        offsets.push(u64::from_le_bytes(bytes));
    }
    let lines = header.compression.scan_lines_per_block() as i64;
    let y0 = i64::from(header.own_attributes.layer_position.y());
    // (offset, end) of each block, found at its offset.
    let mut blocks = Vec::with_capacity(offsets.len());
    for (j, &offset) in offsets.iter().enumerate() {
        if offset < first || offset.saturating_add(8) > len {
            return Err(format!("offset {j} ({offset}) is outside the blocks"));
        }
        file.seek(SeekFrom::Start(offset))
            .map_err(|e| e.to_string())?;
        file.read_exact(&mut bytes).map_err(|e| e.to_string())?;
        let y = i32::from_le_bytes([bytes[0], bytes[1], bytes[2], bytes[3]]);
        let size = u32::from_le_bytes([bytes[4], bytes[5], bytes[6], bytes[7]]);
        if i64::from(y) != y0 + j as i64 * lines {
            return Err(format!("offset {j} points at the block of line {y}"));
        }
        blocks.push((offset, offset + 8 + u64::from(size)));
    }
    blocks.sort_unstable();
    let mut at = first;
    for (offset, end) in blocks {
        if offset != at {
            return Err(format!(
                "a block at {offset} where the previous one ended at {at}"
            ));
        }
        at = end;
    }
    match at == len {
        true => Ok(()),
        false => Err(format!("the blocks end at {at}, the file at {len}")),
    }
}
