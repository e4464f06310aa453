//! Geometry blob: a space's polygon and holes in a compact, exact binary
//! form (every coordinate as its f64 bits, little-endian).
//!
//! Layout: `u8` format (1), `u32` ring count, then per ring a `u32` point
//! count followed by `x, y` as `f64` pairs. The exterior ring comes first.

use crate::model::{Point, Ring};

const FORMAT: u8 = 1;

/// Encodes an exterior ring and its holes.
pub(crate) fn encode(polygon: &Ring, holes: &[Ring]) -> Vec<u8> {
    let points: usize = polygon.len() + holes.iter().map(Vec::len).sum::<usize>();
    let mut out = Vec::with_capacity(5 + 4 * (1 + holes.len()) + 16 * points);
    out.push(FORMAT);
    out.extend_from_slice(&len_u32(1 + holes.len()).to_le_bytes());
    for ring in std::iter::once(polygon).chain(holes) {
        out.extend_from_slice(&len_u32(ring.len()).to_le_bytes());
        for p in ring {
            out.extend_from_slice(&p[0].to_le_bytes());
            out.extend_from_slice(&p[1].to_le_bytes());
        }
    }
    out
}

fn len_u32(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

/// Decodes a blob made by [`encode`] into (exterior, holes); `Err` names
/// what is wrong when the blob is truncated or of an unknown format.
pub(crate) fn decode(blob: &[u8]) -> Result<(Ring, Vec<Ring>), String> {
    let mut reader = Reader { blob, at: 0 };
    let format = reader.take(1)?[0];
    if format != FORMAT {
        return Err(format!("unknown geometry format {format}"));
    }
    let rings = reader.u32()?;
    if rings == 0 {
        return Err("geometry without an exterior ring".into());
    }
    let mut out: Vec<Ring> = Vec::new();
    for _ in 0..rings {
        let n = reader.u32()? as usize;
        let bytes = n
            .checked_mul(16)
            .filter(|b| *b <= blob.len())
            .ok_or("ring longer than the blob")?;
        let raw = reader.take(bytes)?;
        let ring: Vec<Point> = raw
            .chunks_exact(16)
            .map(|c| [f64_at(c, 0), f64_at(c, 8)])
            .collect();
        out.push(ring);
    }
    if reader.at != blob.len() {
        return Err("trailing bytes after the geometry".into());
    }
    let exterior = out.remove(0);
    Ok((exterior, out))
}

fn f64_at(chunk: &[u8], at: usize) -> f64 {
    let mut b = [0u8; 8];
    b.copy_from_slice(&chunk[at..at + 8]);
    f64::from_le_bytes(b)
}

struct Reader<'a> {
    blob: &'a [u8],
    at: usize,
}

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize) -> Result<&'a [u8], String> {
        let end = self.at.checked_add(n).filter(|e| *e <= self.blob.len());
        let end = end.ok_or_else(|| format!("geometry truncated at byte {}", self.at))?;
        let out = &self.blob[self.at..end];
        self.at = end;
        Ok(out)
    }

    fn u32(&mut self) -> Result<u32, String> {
        let b = self.take(4)?;
        Ok(u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_is_bit_exact() {
        let poly = vec![[0.1, 0.2], [1.0 / 3.0, -0.0], [1e-300, 7.5e12]];
        let holes = vec![vec![[0.15, 0.1], [0.2, 0.1], [0.2, 0.11]]];
        let blob = encode(&poly, &holes);
        let (p, h) = decode(&blob).unwrap();
        assert_eq!(p, poly);
        assert_eq!(h, holes);
        assert!(p[1][1].is_sign_negative());
    }

    #[test]
    fn truncated_blob_is_an_error_not_a_panic() {
        let blob = encode(&vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]], &[]);
        for cut in 0..blob.len() {
            assert!(decode(&blob[..cut]).is_err(), "cut at {cut}");
        }
        let mut bad = blob.clone();
        bad[0] = 9;
        assert!(decode(&bad).unwrap_err().contains("format 9"));
        let mut huge = blob;
        huge[5..9].copy_from_slice(&u32::MAX.to_le_bytes());
        assert!(decode(&huge).is_err());
    }
}
