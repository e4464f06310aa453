//! Writers of ROS maps (`map.yaml` + binary PGM) and grey PNGs, atomically.

use std::path::{Path, PathBuf};

use image::ImageEncoder;

use super::SimError;
use super::log_odds::GreyMap;

/// The ROS map_server YAML for `map`, naming `image` (a path relative to
/// the YAML). Thresholds match [`super::LogOddsMap::to_grey`].
///
/// ```
/// use nrgdb::sim::{GreyMap, map_yaml};
/// let m = GreyMap { width: 1, height: 1, resolution_m: 0.05, origin_m: [-1.0, 2.5], grey: vec![205] };
/// assert!(map_yaml("map.pgm", &m).contains("origin: [-1, 2.5, 0.0]"));
/// ```
pub fn map_yaml(image: &str, map: &GreyMap) -> String {
    format!(
        "image: {image}\nresolution: {}\norigin: [{}, {}, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: trinary\n",
        map.resolution_m, map.origin_m[0], map.origin_m[1]
    )
}

/// The map as a binary (P5) PGM, row 0 at the top.
pub fn encode_pgm(map: &GreyMap) -> Vec<u8> {
    let mut out = format!("P5\n{} {}\n255\n", map.width, map.height).into_bytes();
    out.extend_from_slice(&map.grey);
    out
}

/// A grey image as PNG bytes.
pub fn encode_grey_png(
    width: u32,
    height: u32,
    grey: &[u8],
    path: &Path,
) -> Result<Vec<u8>, SimError> {
    let mut buf = Vec::new();
    image::codecs::png::PngEncoder::new(&mut buf)
        .write_image(grey, width, height, image::ExtendedColorType::L8)
        .map_err(|source| SimError::Image {
            path: path.to_path_buf(),
            source,
        })?;
    Ok(buf)
}

/// Writes `bytes` to `path` atomically (temp file + rename).
pub fn write_file(path: &Path, bytes: &[u8]) -> Result<(), SimError> {
    crate::atomic::write(path, bytes).map_err(|source| SimError::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// Creates `dir` (and parents) if missing.
pub fn create_dir(dir: &Path) -> Result<(), SimError> {
    std::fs::create_dir_all(dir).map_err(|source| SimError::Io {
        path: dir.to_path_buf(),
        source,
    })
}

/// Writes `<dir>/<stem>.yaml` and `<dir>/<stem>.pgm`; returns their paths.
pub fn write_map(dir: &Path, stem: &str, map: &GreyMap) -> Result<[PathBuf; 2], SimError> {
    create_dir(dir)?;
    let yaml = dir.join(format!("{stem}.yaml"));
    let pgm = dir.join(format!("{stem}.pgm"));
    let pgm_bytes = encode_pgm(map);
    write_file(&pgm, &pgm_bytes)?;
    write_file(&yaml, map_yaml(&format!("{stem}.pgm"), map).as_bytes())?;
    Ok([yaml, pgm])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pgm_and_png_round_trip() {
        let m = GreyMap {
            width: 3,
            height: 2,
            resolution_m: 0.1,
            origin_m: [0.0, 0.0],
            grey: vec![0, 205, 254, 254, 205, 0],
        };
        let dir = tempfile::tempdir().unwrap();
        let [yaml, pgm] = write_map(dir.path(), "map", &m).unwrap();
        assert!(
            std::fs::read_to_string(yaml)
                .unwrap()
                .contains("mode: trinary")
        );
        let img = image::open(&pgm).unwrap().into_luma8();
        assert_eq!(img.as_raw(), &m.grey);
        let png = encode_grey_png(3, 2, &m.grey, &pgm).unwrap();
        let back = image::load_from_memory(&png).unwrap().into_luma8();
        assert_eq!(back.as_raw(), &m.grey);
    }
}
