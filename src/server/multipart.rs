//! A small `multipart/form-data` reader (RFC 7578) for uploads that are
//! already in memory, size-checked: parts with their field name, file name,
//! content type and bytes.

use memchr::memmem;

/// One part of a multipart body.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Part<'a> {
    /// The form field name.
    pub name: Option<String>,
    /// The file name, for file fields.
    pub filename: Option<String>,
    /// The part's Content-Type.
    pub content_type: Option<String>,
    /// The bytes.
    pub data: &'a [u8],
}

/// The boundary of a `multipart/form-data; boundary=…` content type.
///
/// ```
/// use nrgdb::server::multipart::boundary;
/// assert_eq!(boundary("multipart/form-data; boundary=\"ab c\"").as_deref(), Some("ab c"));
/// assert_eq!(boundary("text/plain"), None);
/// ```
pub fn boundary(content_type: &str) -> Option<String> {
    let mut pieces = content_type.split(';');
    let mime = pieces.next()?.trim();
    if !mime.eq_ignore_ascii_case("multipart/form-data") {
        return None;
    }
    pieces
        .filter_map(|p| p.split_once('='))
        .find(|(k, _)| k.trim().eq_ignore_ascii_case("boundary"))
        .map(|(_, v)| v.trim().trim_matches('"').to_string())
        .filter(|b| !b.is_empty() && b.len() <= 70)
}

/// A `key="value"` parameter of a header like Content-Disposition.
fn header_param(header: &str, key: &str) -> Option<String> {
    header.split(';').skip(1).find_map(|p| {
        let (k, v) = p.split_once('=')?;
        k.trim()
            .eq_ignore_ascii_case(key)
            .then(|| v.trim().trim_matches('"').to_string())
    })
}

/// Splits `body` into its parts; an error says what is malformed.
pub fn parse<'a>(body: &'a [u8], boundary: &str) -> Result<Vec<Part<'a>>, String> {
    let delimiter = format!("--{boundary}");
    let next_delimiter = format!("\r\n--{boundary}");
    let start = memmem::find(body, delimiter.as_bytes())
        .ok_or("no multipart boundary found in the body")?;
    let mut at = start + delimiter.len();
    let mut parts = Vec::new();
    loop {
        let rest = body.get(at..).ok_or("multipart body ends early")?;
        if rest.starts_with(b"--") {
            return Ok(parts);
        }
        let rest = rest
            .strip_prefix(b"\r\n")
            .ok_or("multipart boundary not followed by a line break")?;
        let header_end = memmem::find(rest, b"\r\n\r\n")
            .ok_or("multipart part without a blank line after its headers")?;
        let headers = std::str::from_utf8(&rest[..header_end])
            .map_err(|_| "multipart part headers are not UTF-8")?;
        let data_start = header_end + 4;
        let data_len = memmem::find(&rest[data_start..], next_delimiter.as_bytes())
            .ok_or("multipart part is not closed by the boundary")?;
        let mut part = Part {
            name: None,
            filename: None,
            content_type: None,
            data: &rest[data_start..data_start + data_len],
        };
        for line in headers.split("\r\n") {
            let Some((key, value)) = line.split_once(':') else {
                continue;
            };
            if key.trim().eq_ignore_ascii_case("content-disposition") {
                part.name = header_param(value, "name");
                part.filename = header_param(value, "filename");
            } else if key.trim().eq_ignore_ascii_case("content-type") {
                part.content_type = Some(value.trim().to_string());
            }
        }
        parts.push(part);
        // Skip the data, then the CRLF and delimiter that close it.
        at = body.len() - rest.len() + data_start + data_len + next_delimiter.len();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_parts_and_malformed() {
        let body = b"preamble\r\n--XX\r\nContent-Disposition: form-data; name=\"yaml\"; filename=\"m.yaml\"\r\nContent-Type: text/yaml\r\n\r\nimage: m.pgm\r\n--XX\r\nContent-Disposition: form-data; name=\"message\"\r\n\r\nhi\r\n--XX--\r\n";
        let parts = parse(body, "XX").unwrap();
        assert_eq!(parts.len(), 2);
        assert_eq!(parts[0].filename.as_deref(), Some("m.yaml"));
        assert_eq!(parts[0].data, b"image: m.pgm");
        assert_eq!(parts[1].name.as_deref(), Some("message"));
        assert_eq!(parts[1].data, b"hi");
        assert!(parse(b"--XX\r\nno blank line", "XX").is_err());
        assert!(parse(b"nothing", "XX").is_err());
        assert!(parse(b"--XX\r\n\r\nunterminated", "XX").is_err());
    }
}
