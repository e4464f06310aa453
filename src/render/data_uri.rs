//! `data:` URIs for the SVG back end: a grey raster as an embedded PNG
//! (RFC 2397, base64 of RFC 4648 §4).

/// Base64 (standard alphabet, padded).
///
/// ```
/// assert_eq!(nrgdb::render::base64(b"Man"), "TWFu");
/// assert_eq!(nrgdb::render::base64(b"Ma"), "TWE=");
/// assert_eq!(nrgdb::render::base64(b""), "");
/// ```
pub fn base64(bytes: &[u8]) -> String {
    const ABC: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk.first().copied().unwrap_or(0),
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for (i, shift) in [18u32, 12, 6, 0].into_iter().enumerate() {
            if i <= chunk.len() {
                out.push(char::from(ABC[((n >> shift) & 63) as usize]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// A grey image (row 0 at the top) as a `data:image/png;base64,…` URI.
pub fn grey_png_uri(width: u32, height: u32, grey: &[u8]) -> Result<String, image::ImageError> {
    use image::ImageEncoder;
    let mut png = Vec::new();
    image::codecs::png::PngEncoder::new(&mut png).write_image(
        grey,
        width,
        height,
        image::ExtendedColorType::L8,
    )?;
    Ok(format!("data:image/png;base64,{}", base64(&png)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_rfc4648_vectors() {
        for (plain, coded) in [
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(plain.as_bytes()), coded);
        }
    }

    #[test]
    fn a_grey_png_uri_starts_with_the_png_signature() {
        let uri = grey_png_uri(2, 1, &[0, 255]).unwrap();
        // base64 of "\x89PNG" is "iVBORw".
        assert!(uri.starts_with("data:image/png;base64,iVBORw"));
    }
}
