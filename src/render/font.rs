//! Text for the PNG back end: the public-domain 8×8 bitmap font of the
//! `font8x8` crate (ASCII and Latin-1), scaled by whole pixels, with a one-pixel
//! white halo so labels stay readable over any fill. tiny-skia has no text;
//! a bitmap font keeps the output identical on every machine (no font
//! files, no hinting), which the golden-image tests rely on.

use font8x8::legacy::{BASIC_LEGACY, LATIN_LEGACY};
use tiny_skia::Pixmap;

use super::drawing::{Anchor, Rgba};

/// The whole-pixel scale of the 8 px font for a text `size` in pixels.
pub fn font_scale(size: f64) -> u32 {
    ((size / 10.0).round() as u32).max(1)
}

/// Width in pixels of `text` at `size`.
pub fn text_width_px(text: &str, size: f64) -> f64 {
    (text.chars().count() as u32 * 8 * font_scale(size)) as f64
}

/// The glyph rows of `c` (top row first, bit 0 = leftmost pixel): ASCII
/// and Latin-1 (ä, é, ß, …); `?` for anything else.
fn glyph(c: char) -> [u8; 8] {
    let code = c as usize;
    match c {
        ' '..='~' => BASIC_LEGACY.get(code).copied(),
        '\u{a0}'..='\u{ff}' => LATIN_LEGACY.get(code - 0xa0).copied(),
        _ => BASIC_LEGACY.get('?' as usize).copied(),
    }
    .unwrap_or([0; 8])
}

/// Draws `text` with its baseline at `at`.
pub fn draw_text(
    pixmap: &mut Pixmap,
    at: [f64; 2],
    text: &str,
    size: f64,
    colour: Rgba,
    anchor: Anchor,
) {
    let scale = font_scale(size) as i64;
    let width = text_width_px(text, size);
    let left = match anchor {
        Anchor::Start => at[0],
        Anchor::Middle => at[0] - width / 2.0,
    }
    .round() as i64;
    // The font's baseline is under row 6 of 8.
    let top = at[1].round() as i64 - 7 * scale;
    let white = Rgba::rgb(255, 255, 255);
    for (pass, colour) in [(0, white), (1, colour)] {
        for (i, c) in text.chars().enumerate() {
            let rows = glyph(c);
            let x0 = left + i as i64 * 8 * scale;
            for (r, bits) in rows.iter().enumerate() {
                for col in 0..8i64 {
                    if bits >> col & 1 == 0 {
                        continue;
                    }
                    let (px, py) = (x0 + col * scale, top + r as i64 * scale);
                    for dy in 0..scale {
                        for dx in 0..scale {
                            if pass == 0 {
                                for (hx, hy) in [(-1, 0), (1, 0), (0, -1), (0, 1)] {
                                    put(pixmap, px + dx + hx, py + dy + hy, colour);
                                }
                            } else {
                                put(pixmap, px + dx, py + dy, colour);
                            }
                        }
                    }
                }
            }
        }
    }
}

/// Blends `c` over the pixel at (x, y) (source-over, premultiplied).
fn put(pixmap: &mut Pixmap, x: i64, y: i64, c: Rgba) {
    let (w, h) = (i64::from(pixmap.width()), i64::from(pixmap.height()));
    if x < 0 || y < 0 || x >= w || y >= h {
        return;
    }
    let i = ((y * w + x) * 4) as usize;
    let Some(px) = pixmap.data_mut().get_mut(i..i + 4) else {
        return;
    };
    let a = u32::from(c.0[3]);
    for (dst, src) in px.iter_mut().zip(c.0).take(3) {
        let src = u32::from(src) * a / 255;
        *dst = (src + u32::from(*dst) * (255 - a) / 255) as u8;
    }
    px[3] = (a + u32::from(px[3]) * (255 - a) / 255) as u8;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_glyph_is_drawn_in_its_colour_inside_its_box() {
        let mut p = Pixmap::new(20, 12).unwrap();
        draw_text(
            &mut p,
            [2.0, 9.0],
            "I",
            10.0,
            Rgba::rgb(0, 0, 0),
            Anchor::Start,
        );
        let black: Vec<(u32, u32)> = (0..12)
            .flat_map(|y| (0..20).map(move |x| (x, y)))
            .filter(|&(x, y)| {
                p.pixel(x, y)
                    .is_some_and(|c| c.alpha() == 255 && c.red() == 0)
            })
            .collect();
        assert!(black.len() >= 6, "{black:?}");
        assert!(
            black
                .iter()
                .all(|&(x, y)| (2..10).contains(&x) && (2..10).contains(&y))
        );
        assert_eq!(text_width_px("abc", 10.0), 24.0);
        assert_eq!(font_scale(16.0), 2);
        assert_ne!(glyph('ü'), glyph('?'));
        assert_eq!(glyph('→'), glyph('?'));
    }
}
