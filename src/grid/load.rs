//! Image decoding and cell classification, from files or from bytes in
//! memory (an upload). Sizes that come from the input are bounded before
//! anything is allocated for them: the image's header dimensions against
//! [`LoadOptions::max_pixels`] (and the decoder's own limits set to what
//! was checked), the map YAML's size, and the resolution (one square
//! metre must fit the pixel limit, so that metre-sized structures of the
//! extraction stay bounded grids).

use std::io::{BufRead, Cursor, Seek};
use std::path::Path;

use image::{DynamicImage, ImageReader, Limits};

use super::{Cell, GridError, MapMode, MapYaml, OccupancyGrid};

/// Largest map YAML accepted, in bytes (a ROS map YAML is a few lines).
pub const MAX_YAML_BYTES: u64 = 1 << 20;

/// How to read and classify a map image.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadOptions {
    /// A pixel is free iff its grey (after negate) is at least this (default 250:
    /// the IPA benchmark's rule; ROS's `free_thresh` misreads many maps).
    pub free_min_grey: u8,
    /// Largest accepted image, in pixels (default 64 Mpx). Also bounds the
    /// resolution: one square metre may take at most this many pixels.
    pub max_pixels: u64,
}

impl Default for LoadOptions {
    fn default() -> Self {
        LoadOptions {
            free_min_grey: 250,
            max_pixels: 64 * 1024 * 1024,
        }
    }
}

/// Loads a map from its ROS map_server YAML.
pub fn load_map(yaml_path: &Path, options: &LoadOptions) -> Result<OccupancyGrid, GridError> {
    let yaml = MapYaml::read(yaml_path)?;
    let img = decode_image(&yaml.image, options).map_err(|e| match e {
        GridError::Io { path, source } if path == yaml.image => GridError::MapImage {
            yaml: yaml_path.to_path_buf(),
            image: path,
            source,
        },
        other => other,
    })?;
    check_resolution(yaml_path, yaml.resolution, options)?;
    classify(img, &yaml, options)
}

/// Loads a map from its YAML and image in memory: what [`load_map`] does
/// with files, for an upload. `yaml_name` and `image_name` name the two in
/// errors (the YAML's own `image:` field is not followed: the image is
/// `image`). The image's format is read from its first bytes (PGM or PNG).
///
/// ```
/// use std::path::Path;
/// use nrgdb::grid::{LoadOptions, load_map_bytes};
/// let yaml = b"image: m.pgm\nresolution: 0.5\norigin: [0, 0, 0]\n";
/// let pgm = b"P5\n2 1\n255\n\xff\x00";
/// let grid = load_map_bytes(Path::new("m.yaml"), yaml, Path::new("m.pgm"), pgm, &LoadOptions::default())?;
/// assert_eq!((grid.width, grid.height, grid.free_count()), (2, 1, 1));
/// # Ok::<(), nrgdb::grid::GridError>(())
/// ```
pub fn load_map_bytes(
    yaml_name: &Path,
    yaml: &[u8],
    image_name: &Path,
    image: &[u8],
    options: &LoadOptions,
) -> Result<OccupancyGrid, GridError> {
    if yaml.len() as u64 > MAX_YAML_BYTES {
        return Err(GridError::YamlTooLarge {
            path: yaml_name.to_path_buf(),
            size: yaml.len() as u64,
            limit: MAX_YAML_BYTES,
        });
    }
    let text = std::str::from_utf8(yaml).map_err(|e| GridError::Yaml {
        path: yaml_name.to_path_buf(),
        message: format!(
            "not UTF-8 text (invalid byte at offset {})",
            e.valid_up_to()
        ),
    })?;
    let mut map = MapYaml::parse(text, yaml_name)?;
    map.image = image_name.to_path_buf();
    let img = decode_image_bytes(image, image_name, options)?;
    check_resolution(yaml_name, map.resolution, options)?;
    classify(img, &map, options)
}

/// Loads a bare image (PGM or PNG) with the given resolution, origin `[0, 0, 0]`
/// and trinary interpretation.
pub fn load_image(
    image_path: &Path,
    resolution: f64,
    options: &LoadOptions,
) -> Result<OccupancyGrid, GridError> {
    if !(resolution.is_finite() && resolution > 0.0) {
        return Err(GridError::BadField {
            path: image_path.to_path_buf(),
            field: "resolution",
            value: resolution.to_string(),
            hint: "must be a finite number of metres per pixel > 0",
        });
    }
    let yaml = MapYaml {
        image: image_path.to_path_buf(),
        resolution,
        origin: [0.0; 3],
        negate: false,
        occupied_thresh: 0.65,
        free_thresh: 0.196,
        mode: MapMode::Trinary,
    };
    let img = decode_image(image_path, options)?;
    check_resolution(image_path, resolution, options)?;
    classify(img, &yaml, options)
}

/// Refuses a resolution so fine that one square metre would exceed the
/// pixel limit: every length of the extraction is in metres, so at such a
/// resolution a door or a noise disk alone would be a grid above the limit
/// (and a typo like `resolution: 5e-9` would run for hours).
fn check_resolution(path: &Path, resolution: f64, options: &LoadOptions) -> Result<(), GridError> {
    let per_m2 = 1.0 / (resolution * resolution);
    if per_m2 > options.max_pixels as f64 {
        return Err(GridError::ResolutionTooFine {
            path: path.to_path_buf(),
            resolution,
            per_m2,
            limit: options.max_pixels,
        });
    }
    Ok(())
}

/// Opens an image file, guessing its format from its first bytes.
fn open_reader(path: &Path) -> Result<ImageReader<std::io::BufReader<std::fs::File>>, GridError> {
    let io = |source| GridError::Io {
        path: path.to_path_buf(),
        source,
    };
    ImageReader::open(path)
        .map_err(io)?
        .with_guessed_format()
        .map_err(io)
}

/// Decodes an image file, checking the pixel limit before decoding the pixels.
pub fn decode_image(path: &Path, options: &LoadOptions) -> Result<DynamicImage, GridError> {
    decode_bounded(|| open_reader(path), path, options)
}

/// Decodes an image held in memory (PGM or PNG, told by its first bytes),
/// checking the pixel limit before decoding the pixels; `name` names it
/// in errors.
pub fn decode_image_bytes(
    bytes: &[u8],
    name: &Path,
    options: &LoadOptions,
) -> Result<DynamicImage, GridError> {
    let open = || {
        ImageReader::new(Cursor::new(bytes))
            .with_guessed_format()
            .map_err(|source| GridError::Io {
                path: name.to_path_buf(),
                source,
            })
    };
    decode_bounded(open, name, options)
}

/// Reads the header's dimensions, refuses an empty image or one above the
/// pixel limit, then decodes with the decoder's limits set to the checked
/// size (so a header that lies cannot make it allocate more).
fn decode_bounded<R: BufRead + Seek>(
    open: impl Fn() -> Result<ImageReader<R>, GridError>,
    path: &Path,
    options: &LoadOptions,
) -> Result<DynamicImage, GridError> {
    let image_error = |e: image::ImageError| GridError::Image {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let (w, h) = open()?.into_dimensions().map_err(image_error)?;
    let pixels = u64::from(w) * u64::from(h);
    if pixels > options.max_pixels {
        return Err(GridError::TooLarge {
            path: path.to_path_buf(),
            width: w,
            height: h,
            pixels,
            limit: options.max_pixels,
        });
    }
    if pixels == 0 {
        return Err(GridError::Image {
            path: path.to_path_buf(),
            message: "image is empty".into(),
        });
    }
    let mut limits = Limits::default();
    limits.max_image_width = Some(w);
    limits.max_image_height = Some(h);
    // 16-bit RGBA is 8 bytes a pixel; room for the decoder's own buffers.
    limits.max_alloc = Some(pixels.saturating_mul(8).saturating_add(64 << 20));
    let mut reader = open()?;
    reader.limits(limits);
    reader.decode().map_err(image_error)
}

/// Grey (0..255) and alpha per pixel, whatever the colour type and depth.
pub fn grey_and_alpha(img: &DynamicImage) -> (Vec<u8>, Option<Vec<u8>>) {
    let has_alpha = img.color().has_alpha();
    if img.color().has_color() {
        let rgba = img.to_rgba8();
        let grey = rgba
            .pixels()
            .map(|p| ((u16::from(p[0]) + u16::from(p[1]) + u16::from(p[2])) / 3) as u8)
            .collect();
        let alpha = has_alpha.then(|| rgba.pixels().map(|p| p[3]).collect());
        (grey, alpha)
    } else {
        let la = img.to_luma_alpha8();
        let grey = la.pixels().map(|p| p[0]).collect();
        let alpha = has_alpha.then(|| la.pixels().map(|p| p[1]).collect());
        (grey, alpha)
    }
}

fn classify(
    img: DynamicImage,
    yaml: &MapYaml,
    options: &LoadOptions,
) -> Result<OccupancyGrid, GridError> {
    let (width, height) = (img.width(), img.height());
    let (mut grey, alpha) = grey_and_alpha(&img);
    if yaml.negate {
        grey.iter_mut().for_each(|g| *g = 255 - *g);
    }
    // ROS: p = (255 - grey) / 255 is the occupancy probability.
    let occ_max_grey = ((1.0 - yaml.occupied_thresh) * 255.0).floor() as i32;
    if yaml.mode != MapMode::Raw {
        let warnings = super::image_warnings(
            &yaml.image,
            &img,
            &grey,
            alpha.as_deref(),
            options.free_min_grey,
            occ_max_grey,
        );
        for w in warnings {
            tracing::warn!("{w}");
        }
    }
    drop(img);
    let mut cells = Vec::with_capacity(grey.len());
    for (i, g) in grey.iter_mut().enumerate() {
        let transparent = alpha.as_ref().is_some_and(|a| a[i] == 0);
        let cell = if transparent {
            Cell::Unknown
        } else if yaml.mode == MapMode::Raw {
            // The stored value is the occupancy in percent; other values are unknown.
            let v = 255 - *g; // undo the grey convention: raw value as written
            let cell = match v {
                0..=100 => {
                    let p = f64::from(v) / 100.0;
                    if p > yaml.occupied_thresh {
                        Cell::Occupied
                    } else if p < yaml.free_thresh {
                        Cell::Free
                    } else {
                        Cell::Unknown
                    }
                }
                _ => Cell::Unknown,
            };
            *g = match cell {
                Cell::Free => 255,
                Cell::Occupied => 0,
                Cell::Unknown => 205,
            };
            cell
        } else if *g >= options.free_min_grey {
            Cell::Free
        } else if i32::from(*g) < occ_max_grey {
            Cell::Occupied
        } else {
            Cell::Unknown
        };
        if transparent {
            *g = 205;
        }
        cells.push(cell);
    }
    if cells.iter().all(|c| *c == Cell::Unknown) {
        return Err(GridError::AllUnknown {
            path: yaml.image.clone(),
        });
    }
    if !cells.contains(&Cell::Free) {
        return Err(GridError::NoFreeSpace {
            path: yaml.image.clone(),
            free_min_grey: options.free_min_grey,
        });
    }
    Ok(OccupancyGrid {
        width,
        height,
        resolution: yaml.resolution,
        origin: yaml.origin,
        grey,
        cells,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use image::{GrayImage, ImageBuffer, Luma, LumaA, Rgb};

    fn dir() -> tempfile::TempDir {
        tempfile::tempdir().unwrap()
    }

    fn yaml(d: &Path, image: &str, extra: &str) -> std::path::PathBuf {
        let p = d.join("map.yaml");
        std::fs::write(
            &p,
            format!("image: {image}\nresolution: 0.1\norigin: [0, 0, 0]\n{extra}"),
        )
        .unwrap();
        p
    }

    #[test]
    fn loads_pgm_and_png_variants() {
        let d = dir();
        let g = GrayImage::from_fn(4, 2, |x, _| Luma([if x < 2 { 255 } else { 0 }]));
        g.save(d.path().join("m.pgm")).unwrap();
        let m = load_map(&yaml(d.path(), "m.pgm", ""), &LoadOptions::default()).unwrap();
        assert_eq!(m.free_count(), 4);
        assert_eq!(m.cell(3, 1), Some(Cell::Occupied));

        let g16: ImageBuffer<Luma<u16>, Vec<u16>> =
            ImageBuffer::from_fn(4, 2, |x, _| Luma([if x < 1 { 65535 } else { 0 }]));
        g16.save(d.path().join("m16.png")).unwrap();
        let m = load_map(&yaml(d.path(), "m16.png", ""), &LoadOptions::default()).unwrap();
        assert_eq!(m.free_count(), 2);

        let la: ImageBuffer<LumaA<u8>, Vec<u8>> =
            ImageBuffer::from_fn(4, 2, |x, _| LumaA([255, if x == 0 { 0 } else { 255 }]));
        la.save(d.path().join("la.png")).unwrap();
        let m = load_map(&yaml(d.path(), "la.png", ""), &LoadOptions::default()).unwrap();
        assert_eq!(m.free_count(), 6);
        assert_eq!(m.cell(0, 0), Some(Cell::Unknown));

        let rgb: ImageBuffer<Rgb<u8>, Vec<u8>> = ImageBuffer::from_fn(4, 2, |x, _| {
            if x == 0 {
                Rgb([255, 255, 255])
            } else {
                Rgb([0, 0, 0])
            }
        });
        rgb.save(d.path().join("rgb.png")).unwrap();
        let m = load_map(
            &yaml(d.path(), "rgb.png", "negate: 1\n"),
            &LoadOptions::default(),
        )
        .unwrap();
        assert_eq!(m.free_count(), 6, "negate turns black into free");
    }

    #[test]
    fn bad_inputs_give_named_errors() {
        let d = dir();
        std::fs::write(d.path().join("t.png"), b"\x89PNG\r\n\x1a\n\0\0").unwrap();
        let e = load_map(&yaml(d.path(), "t.png", ""), &LoadOptions::default()).unwrap_err();
        assert!(matches!(e, GridError::Image { .. }), "{e}");
        assert!(e.to_string().contains("t.png"));

        let e = load_map(&yaml(d.path(), "missing.png", ""), &LoadOptions::default()).unwrap_err();
        assert!(e.to_string().contains("missing.png"), "{e}");

        let g = GrayImage::from_pixel(8, 8, Luma([205]));
        g.save(d.path().join("u.pgm")).unwrap();
        let e = load_map(&yaml(d.path(), "u.pgm", ""), &LoadOptions::default()).unwrap_err();
        assert!(matches!(e, GridError::AllUnknown { .. }), "{e}");

        let g = GrayImage::from_pixel(8, 8, Luma([0]));
        g.save(d.path().join("o.pgm")).unwrap();
        let e = load_map(&yaml(d.path(), "o.pgm", ""), &LoadOptions::default()).unwrap_err();
        assert!(matches!(e, GridError::NoFreeSpace { .. }), "{e}");

        let opts = LoadOptions {
            max_pixels: 10,
            ..LoadOptions::default()
        };
        let e = load_map(&yaml(d.path(), "o.pgm", ""), &opts).unwrap_err();
        assert!(matches!(e, GridError::TooLarge { pixels: 64, .. }), "{e}");

        let e = load_image(&d.path().join("o.pgm"), -1.0, &LoadOptions::default()).unwrap_err();
        assert!(e.to_string().contains("resolution"), "{e}");
    }

    #[test]
    fn bytes_load_like_files() {
        let d = dir();
        let g = GrayImage::from_fn(6, 4, |x, y| Luma([if x > 0 && y > 0 { 254 } else { 0 }]));
        g.save(d.path().join("m.pgm")).unwrap();
        let yaml_path = yaml(d.path(), "m.pgm", "negate: 0\n");
        let from_file = load_map(&yaml_path, &LoadOptions::default()).unwrap();
        let yaml_bytes = std::fs::read(&yaml_path).unwrap();
        let image = std::fs::read(d.path().join("m.pgm")).unwrap();
        let from_bytes = load_map_bytes(
            Path::new("up.yaml"),
            &yaml_bytes,
            Path::new("up.pgm"),
            &image,
            &LoadOptions::default(),
        )
        .unwrap();
        assert_eq!(from_bytes, from_file);
    }

    #[test]
    fn bytes_errors_name_the_part_and_bound_sizes() {
        let opts = LoadOptions::default();
        let yaml = b"image: x.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n";
        let (y, i) = (Path::new("floor.yaml"), Path::new("floor.pgm"));
        let e = load_map_bytes(y, yaml, i, b"P5\n999", &opts).unwrap_err();
        assert!(matches!(e, GridError::Image { .. }), "{e}");
        assert!(e.to_string().starts_with("floor.pgm: "), "{e}");
        // A header announcing 20000 x 20000 px is refused before decoding.
        let e = load_map_bytes(y, yaml, i, b"P5\n20000 20000\n255\n\0", &opts).unwrap_err();
        assert!(
            matches!(
                e,
                GridError::TooLarge {
                    pixels: 400_000_000,
                    ..
                }
            ),
            "{e}"
        );
        let e = load_map_bytes(y, b"image: [", i, b"P5\n1 1\n255\n\xff", &opts).unwrap_err();
        assert!(
            e.to_string().starts_with("floor.yaml: invalid map yaml"),
            "{e}"
        );
        let e = load_map_bytes(y, b"\xff\xfe", i, b"", &opts).unwrap_err();
        assert!(e.to_string().contains("not UTF-8"), "{e}");
        let big = vec![b'#'; MAX_YAML_BYTES as usize + 1];
        let e = load_map_bytes(y, &big, i, b"", &opts).unwrap_err();
        assert!(matches!(e, GridError::YamlTooLarge { .. }), "{e}");
        // One square metre at 1e-9 m/px would be 1e18 px.
        let fine = b"image: x.pgm\nresolution: 1e-9\norigin: [0, 0, 0]\n";
        let e = load_map_bytes(y, fine, i, b"P5\n2 1\n255\n\xff\0", &opts).unwrap_err();
        assert!(matches!(e, GridError::ResolutionTooFine { .. }), "{e}");
        assert!(
            e.to_string().contains("floor.yaml: field `resolution`"),
            "{e}"
        );
    }
}
