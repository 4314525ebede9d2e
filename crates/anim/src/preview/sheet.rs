//! The contact sheet: every N-th preview frame (0, N, 2N, …) as a tile in a grid, in
//! reading order, each with its frame number in a band under it, on a dark background.
//!
//! For T tiles the grid has C = min(T, ⌈√(1.5·T)⌉) columns and ⌈T/C⌉ rows (24 tiles:
//! 6 × 4, wider than tall like a frame). Tiles are `PAD` pixels apart and from the edges;
//! a `BAND`-pixel band under each tile holds its label. N defaults to ⌈frames/24⌉, about
//! 24 tiles.

use super::font::{self, FontError, FAMILY};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use whitted::base::Frame;

/// Pixels between tiles and around the grid.
pub const PAD: u32 = 4;
/// Height of the label band under each tile.
pub const BAND: u32 = 16;
/// The tile count the default `--every` aims at.
pub const TARGET_TILES: u32 = 24;
/// The background, and the label colour.
pub const BACKGROUND: [u8; 3] = [32, 32, 32];
const LABEL: RGBColor = RGBColor(225, 225, 225);

/// The default step between tiles: ⌈frames/24⌉, at least 1.
pub fn default_every(frames: u32) -> u32 {
    frames.div_ceil(TARGET_TILES).max(1)
}

/// Where the tiles go.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layout {
    /// A tile's width in pixels (a preview frame's).
    pub tile_width: u32,
    /// A tile's height in pixels.
    pub tile_height: u32,
    /// The number of tiles: frames 0, every, 2·every, ...
    pub tiles: u32,
    /// The step between tiled frames, 1 or more.
    pub every: u32,
    /// Tiles per row.
    pub columns: u32,
    /// Rows of tiles.
    pub rows: u32,
}

impl Layout {
    /// The grid for every `every`-th of `frames` frames of `tile_width`×`tile_height`.
    pub fn new(frames: u32, every: u32, tile_width: u32, tile_height: u32) -> Layout {
        let every = every.max(1);
        let tiles = frames.div_ceil(every).max(1);
        let columns = ((1.5 * f64::from(tiles)).sqrt().ceil() as u32).clamp(1, tiles);
        Layout {
            tile_width,
            tile_height,
            tiles,
            every,
            columns,
            rows: tiles.div_ceil(columns),
        }
    }

    /// The sheet's size in pixels (u64, so that a huge grid can be refused, not wrapped).
    pub fn size(&self) -> (u64, u64) {
        let (c, r) = (u64::from(self.columns), u64::from(self.rows));
        let pad = u64::from(PAD);
        (
            c * u64::from(self.tile_width) + (c + 1) * pad,
            r * (u64::from(self.tile_height) + u64::from(BAND)) + (r + 1) * pad,
        )
    }

    /// The tile of frame `frame`, if it has one.
    pub fn tile_of(&self, frame: u32) -> Option<u32> {
        frame
            .is_multiple_of(self.every)
            .then_some(frame / self.every)
    }

    /// The top-left pixel of tile `k`.
    pub fn origin(&self, k: u32) -> (u32, u32) {
        let (col, row) = (k % self.columns, k / self.columns);
        (
            PAD + col * (self.tile_width + PAD),
            PAD + row * (self.tile_height + BAND + PAD),
        )
    }
}

/// A contact sheet being filled.
pub struct Sheet {
    layout: Layout,
    image: Frame,
}

impl Sheet {
    /// An empty sheet; `layout.size()` must have been checked to fit in memory.
    pub fn new(layout: Layout) -> Sheet {
        let (w, h) = layout.size();
        let (width, height) = (w as u32, h as u32);
        Sheet {
            layout,
            image: Frame {
                width,
                height,
                pixels: BACKGROUND.repeat(width as usize * height as usize),
            },
        }
    }

    /// Copies `tile` (a preview frame) into the place of frame `frame`, if it has one.
    pub fn place(&mut self, frame: u32, tile: &Frame) {
        let Some(k) = self.layout.tile_of(frame) else {
            return;
        };
        let (x0, y0) = self.layout.origin(k);
        let w = tile.width.min(self.layout.tile_width) as usize;
        let stride = self.image.width as usize * 3;
        for y in 0..tile.height.min(self.layout.tile_height) as usize {
            let src = &tile.pixels[y * tile.width as usize * 3..][..w * 3];
            let at = (y0 as usize + y) * stride + x0 as usize * 3;
            self.image.pixels[at..at + w * 3].copy_from_slice(src);
        }
    }

    /// Writes every tile's frame number in its band and returns the picture.
    pub fn finish(mut self) -> Result<Frame, FontError> {
        font::ensure()?;
        let l = self.layout;
        let (w, h) = (self.image.width, self.image.height);
        {
            let area = BitMapBackend::with_buffer(&mut self.image.pixels, (w, h));
            let area = area.into_drawing_area();
            let size = (BAND as f64 * 0.8).round();
            let style = (FAMILY, size)
                .into_font()
                .color(&LABEL)
                .pos(Pos::new(HPos::Center, VPos::Top));
            for k in 0..l.tiles {
                let (x, y) = l.origin(k);
                let at = (
                    (x + l.tile_width / 2) as i32,
                    (y + l.tile_height + 2) as i32,
                );
                let text = (k * l.every).to_string();
                area.draw(&Text::new(text, at, style.clone()))
                    .map_err(|_| FontError)?;
            }
            area.present().map_err(|_| FontError)?;
        }
        Ok(self.image)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_every_aims_at_about_24_tiles() {
        assert_eq!(default_every(250), 11); // ⌈250/24⌉; 23 tiles
        assert_eq!(Layout::new(250, 11, 160, 120).tiles, 23);
        assert_eq!(default_every(24), 1);
        assert_eq!(default_every(12), 1);
        assert_eq!(default_every(1), 1);
        assert_eq!(default_every(1_000_000), 41_667);
    }

    #[test]
    fn grid_is_wider_than_tall() {
        // 24 tiles: √36 = 6 columns, 4 rows.
        let l = Layout::new(240, 10, 160, 120);
        assert_eq!((l.tiles, l.columns, l.rows), (24, 6, 4));
        // 6·160 + 7·4 = 988; 4·(120 + 16) + 5·4 = 564.
        assert_eq!(l.size(), (988, 564));
        // 4 tiles of 16×12 (12 frames, every 3): ⌈√6⌉ = 3 columns, 2 rows.
        let l = Layout::new(12, 3, 16, 12);
        assert_eq!((l.tiles, l.columns, l.rows), (4, 3, 2));
        assert_eq!(l.size(), (3 * 16 + 4 * 4, 2 * 28 + 3 * 4));
        // One tile: one column.
        let l = Layout::new(1, 5, 8, 8);
        assert_eq!((l.tiles, l.columns, l.rows), (1, 1, 1));
    }

    #[test]
    fn tiles_take_every_nth_frame_in_reading_order() {
        let l = Layout::new(12, 3, 16, 12);
        assert_eq!(l.tile_of(0), Some(0));
        assert_eq!(l.tile_of(9), Some(3));
        assert_eq!(l.tile_of(4), None);
        assert_eq!(l.origin(0), (4, 4));
        assert_eq!(l.origin(2), (4 + 2 * 20, 4));
        assert_eq!(l.origin(3), (4, 4 + 32));
    }

    #[test]
    fn a_placed_tile_lands_at_its_origin_and_others_stay_background() {
        let l = Layout::new(12, 3, 2, 2);
        let mut s = Sheet::new(l);
        let tile = Frame {
            width: 2,
            height: 2,
            pixels: [200, 100, 50].repeat(4),
        };
        s.place(3, &tile); // tile 1
        s.place(4, &tile); // no tile
        let img = s.finish().unwrap();
        let px = |x: u32, y: u32| {
            let i = ((y * img.width + x) * 3) as usize;
            [img.pixels[i], img.pixels[i + 1], img.pixels[i + 2]]
        };
        let (x, y) = l.origin(1);
        assert_eq!(px(x + 1, y + 1), [200, 100, 50]);
        let (x0, y0) = l.origin(0);
        assert_eq!(px(x0, y0), BACKGROUND);
        assert_eq!(px(0, 0), BACKGROUND);
    }
}
