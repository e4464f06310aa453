//! Which format a file is in: the one place that decides, for the CLI, the
//! ingest of files and uploads, and the server. A file is told by what was
//! said about it (its name's extension, else a declared media type) and by
//! its first bytes (PNG and Netpbm magic numbers, XML, JSON, map YAML
//! keys); a multipart field name is the weakest hint.
//!
//! When the two disagree within one family the bytes win (a `.pgm` holding
//! a PNG is a PNG; a `.json` holding a FeatureCollection is GeoJSON; a
//! `.yaml` holding JSON is still YAML, which JSON is a subset of). Across
//! families (a `.json` holding XML, a `.gml` holding a PNG) it is an error
//! naming the file, what its name says and what its bytes are. Bytes that
//! look like nothing known leave the name's word standing; the reader then
//! says what is wrong with them.
//!
//! ```
//! use nrgdb::format::{Declared, FileKind, ModelFormat, detect};
//! let kind = detect(&Declared::name("floor.json"), br#"{"type": "FeatureCollection", "features": []}"#)?;
//! assert_eq!(kind, FileKind::Model(ModelFormat::GeoJson));
//! assert!(detect(&Declared::name("floor.json"), b"<?xml version=\"1.0\"?>").is_err());
//! # Ok::<(), nrgdb::format::FormatError>(())
//! ```

use std::path::PathBuf;

use serde::Deserialize;

use super::{FormatError, ModelFormat};

/// An image format of map images.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ImageFormat {
    /// Netpbm: PGM as ROS map_server writes it (also PBM and PPM).
    Pgm,
    /// PNG.
    Png,
}

/// A ROS 2 recording's storage.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RecordingFormat {
    /// MCAP (rosbag2's default storage since ROS 2 Iron).
    Mcap,
    /// SQLite (`.db3`, rosbag2's storage before Iron).
    Db3,
}

/// What a file holds, as far as nrgdb reads it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    /// A ROS map_server YAML (resolution, origin, the image's name).
    MapYaml,
    /// A map image, the YAML's companion.
    Image(ImageFormat),
    /// A model file.
    Model(ModelFormat),
    /// A ROS 2 recording (rosbag2) holding maps.
    Recording(RecordingFormat),
    /// A building manifest (TOML): each level's map, elevation and the
    /// stairs and lifts between them.
    Building,
}

impl std::fmt::Display for FileKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            FileKind::MapYaml => "a map YAML",
            FileKind::Image(ImageFormat::Pgm) => "a PGM image",
            FileKind::Image(ImageFormat::Png) => "a PNG image",
            FileKind::Model(ModelFormat::IndoorGml) => "IndoorGML (XML)",
            FileKind::Model(ModelFormat::Json) => "model JSON",
            FileKind::Model(ModelFormat::GeoJson) => "GeoJSON",
            FileKind::Model(ModelFormat::IndoorJson) => "IndoorJSON2 (IndoorGML 2.0 draft)",
            FileKind::Recording(RecordingFormat::Mcap) => "a ROS 2 recording (MCAP)",
            FileKind::Recording(RecordingFormat::Db3) => "a ROS 2 bag (SQLite)",
            FileKind::Building => "a building manifest (TOML)",
        })
    }
}

/// What is said about a file besides its bytes; each part optional.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Declared<'a> {
    /// Its file name or path (the extension counts).
    pub name: Option<&'a str>,
    /// A declared media type (`Content-Type`), parameters allowed.
    pub media_type: Option<&'a str>,
    /// A multipart form field name (`yaml`, `image`, `model`, …).
    pub field: Option<&'a str>,
}

impl<'a> Declared<'a> {
    /// A file known by its name only.
    pub fn name(name: &'a str) -> Declared<'a> {
        Declared {
            name: Some(name),
            ..Declared::default()
        }
    }

    /// The label errors use: the name, else the field, else "upload".
    pub fn label(&self) -> &'a str {
        self.name.or(self.field).unwrap_or("upload")
    }
}

impl FileKind {
    /// The kind a file name's extension names (case-insensitive).
    ///
    /// ```
    /// use nrgdb::format::{FileKind, ModelFormat};
    /// assert_eq!(FileKind::by_extension("maps/A.YML"), Some(FileKind::MapYaml));
    /// assert_eq!(FileKind::by_extension("b.xml"), Some(FileKind::Model(ModelFormat::IndoorGml)));
    /// assert_eq!(FileKind::by_extension("README"), None);
    /// ```
    pub fn by_extension(name: &str) -> Option<FileKind> {
        let file = name.rsplit(['/', '\\']).next().unwrap_or(name);
        if file.to_ascii_lowercase().ends_with(".indoor.json") {
            return Some(FileKind::Model(ModelFormat::IndoorJson));
        }
        let ext = file.rsplit_once('.')?.1.to_ascii_lowercase();
        Some(match ext.as_str() {
            "yaml" | "yml" => FileKind::MapYaml,
            "pgm" | "pnm" | "pbm" | "ppm" => FileKind::Image(ImageFormat::Pgm),
            "png" => FileKind::Image(ImageFormat::Png),
            "gml" | "xml" => FileKind::Model(ModelFormat::IndoorGml),
            "json" => FileKind::Model(ModelFormat::Json),
            "geojson" => FileKind::Model(ModelFormat::GeoJson),
            "mcap" => FileKind::Recording(RecordingFormat::Mcap),
            "db3" => FileKind::Recording(RecordingFormat::Db3),
            "toml" => FileKind::Building,
            _ => return None,
        })
    }

    /// The kind a media type names (`application/json; charset=utf-8`
    /// counts as `application/json`); generic types name none.
    pub fn by_media_type(media_type: &str) -> Option<FileKind> {
        let mime = media_type.split(';').next()?.trim().to_ascii_lowercase();
        Some(match mime.as_str() {
            "application/xml" | "text/xml" | "application/gml+xml" => {
                FileKind::Model(ModelFormat::IndoorGml)
            }
            "application/json" => FileKind::Model(ModelFormat::Json),
            "application/geo+json" => FileKind::Model(ModelFormat::GeoJson),
            "application/yaml" | "application/x-yaml" | "text/yaml" | "text/x-yaml" => {
                FileKind::MapYaml
            }
            "image/png" => FileKind::Image(ImageFormat::Png),
            "image/x-portable-graymap" | "image/x-portable-anymap" => {
                FileKind::Image(ImageFormat::Pgm)
            }
            _ => return None,
        })
    }

    /// The kind an upload's form field name suggests.
    pub fn by_field(field: &str) -> Option<FileKind> {
        Some(match field {
            "yaml" => FileKind::MapYaml,
            "image" => FileKind::Image(ImageFormat::Pgm),
            "indoorgml" | "gml" => FileKind::Model(ModelFormat::IndoorGml),
            "geojson" => FileKind::Model(ModelFormat::GeoJson),
            "indoorjson" => FileKind::Model(ModelFormat::IndoorJson),
            "model" | "json" => FileKind::Model(ModelFormat::Json),
            _ => return None,
        })
    }

    /// The kind the first bytes show, if they show one (a JSON object is
    /// GeoJSON when its top-level `type` is `FeatureCollection`, IndoorJSON2
    /// when it is `IndoorJSON2`, else model
    /// JSON).
    ///
    /// ```
    /// use nrgdb::format::{FileKind, ImageFormat};
    /// assert_eq!(FileKind::sniff(b"\x89PNG\r\n\x1a\n...."), Some(FileKind::Image(ImageFormat::Png)));
    /// assert_eq!(FileKind::sniff(b"resolution: 0.05\nimage: a.pgm\n"), Some(FileKind::MapYaml));
    /// assert_eq!(FileKind::sniff(b"hello"), None);
    /// ```
    pub fn sniff(bytes: &[u8]) -> Option<FileKind> {
        match content(bytes) {
            Content::Kind(k) => Some(k),
            Content::AnyJson => Some(FileKind::Model(ModelFormat::Json)),
            Content::Sqlite | Content::Unknown => None,
        }
    }
}

/// What the bytes show.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Content {
    Kind(FileKind),
    /// Starts like a JSON object but does not parse: model JSON or GeoJSON.
    AnyJson,
    /// An SQLite database: a bag if its name says so.
    Sqlite,
    Unknown,
}

/// The top-level `type` of a JSON object, the rest skipped unparsed.
#[derive(Deserialize)]
struct TypeProbe {
    #[serde(rename = "type")]
    kind: Option<serde_json::Value>,
}

const PNG_MAGIC: &[u8] = b"\x89PNG\r\n\x1a\n";
/// MCAP's magic (format version 0).
const MCAP_MAGIC: &[u8] = b"\x89MCAP0\r\n";
/// SQLite's header: a `.db3` bag is one (an SQLite file is only called a
/// bag by its name: nrgdb's own database is SQLite too).
const SQLITE_MAGIC: &[u8] = b"SQLite format 3\0";

fn content(bytes: &[u8]) -> Content {
    if bytes.starts_with(PNG_MAGIC) {
        return Content::Kind(FileKind::Image(ImageFormat::Png));
    }
    if bytes.starts_with(MCAP_MAGIC) {
        return Content::Kind(FileKind::Recording(RecordingFormat::Mcap));
    }
    if bytes.starts_with(SQLITE_MAGIC) {
        return Content::Sqlite;
    }
    if let [b'P', b'1'..=b'7', next, ..] = bytes
        && next.is_ascii_whitespace()
    {
        return Content::Kind(FileKind::Image(ImageFormat::Pgm));
    }
    let text = bytes.strip_prefix(b"\xef\xbb\xbf").unwrap_or(bytes);
    let start = text.iter().position(|b| !b.is_ascii_whitespace());
    match start.and_then(|i| text.get(i)) {
        Some(b'<') => return Content::Kind(FileKind::Model(ModelFormat::IndoorGml)),
        Some(b'{') => {
            return match serde_json::from_slice::<TypeProbe>(text) {
                Ok(p) if p.kind.as_ref().and_then(|k| k.as_str()) == Some("FeatureCollection") => {
                    Content::Kind(FileKind::Model(ModelFormat::GeoJson))
                }
                Ok(p) if p.kind.as_ref().and_then(|k| k.as_str()) == Some("IndoorJSON2") => {
                    Content::Kind(FileKind::Model(ModelFormat::IndoorJson))
                }
                Ok(_) => Content::Kind(FileKind::Model(ModelFormat::Json)),
                Err(_) => Content::AnyJson,
            };
        }
        _ => {}
    }
    if looks_like_map_yaml(text) {
        return Content::Kind(FileKind::MapYaml);
    }
    if looks_like_manifest(text) {
        return Content::Kind(FileKind::Building);
    }
    Content::Unknown
}

/// A map YAML has `image:`, `resolution:` or `origin:` at the start of a
/// line, in its first few KiB.
fn looks_like_map_yaml(text: &[u8]) -> bool {
    let head = &text[..text.len().min(4096)];
    let Ok(head) = std::str::from_utf8(head).or_else(|e| {
        // A multi-byte character cut at 4 KiB: keep the valid part.
        std::str::from_utf8(head.get(..e.valid_up_to()).unwrap_or_default())
    }) else {
        return false;
    };
    head.lines().any(|l| {
        ["image:", "resolution:", "origin:"]
            .iter()
            .any(|k| l.starts_with(k))
    })
}

/// A building manifest has a `[[level]]` table in its first few KiB.
fn looks_like_manifest(text: &[u8]) -> bool {
    let head = &text[..text.len().min(4096)];
    String::from_utf8_lossy(head)
        .lines()
        .any(|l| l.trim() == "[[level]]")
}

/// Decides what `bytes` are, given what was `declared` about them (see
/// the module docs for the rules). Errors name the file.
pub fn detect(declared: &Declared<'_>, bytes: &[u8]) -> Result<FileKind, FormatError> {
    let claim = declared
        .name
        .and_then(FileKind::by_extension)
        .or_else(|| declared.media_type.and_then(FileKind::by_media_type));
    let hint = declared.field.and_then(FileKind::by_field);
    let json = |k: FileKind| {
        matches!(
            k,
            FileKind::Model(ModelFormat::Json | ModelFormat::GeoJson | ModelFormat::IndoorJson)
        )
    };
    match (claim, content(bytes)) {
        (None, Content::Kind(found)) => Ok(found),
        (None, Content::AnyJson) => Ok(hint
            .filter(|h| json(*h))
            .unwrap_or(FileKind::Model(ModelFormat::Json))),
        (None, Content::Unknown | Content::Sqlite) => {
            hint.ok_or_else(|| FormatError::Unrecognised {
                path: PathBuf::from(declared.label()),
            })
        }
        (Some(said), Content::Unknown) => Ok(said),
        (Some(said @ FileKind::Recording(RecordingFormat::Db3)), Content::Sqlite) => Ok(said),
        (Some(said), Content::Sqlite) => Err(conflict(declared, said, "an SQLite database")),
        (Some(said), Content::AnyJson) if json(said) || said == FileKind::MapYaml => Ok(said),
        (Some(said), Content::AnyJson) => Err(conflict(declared, said, "JSON")),
        (Some(said), Content::Kind(found)) => {
            agree(said, found).ok_or_else(|| conflict(declared, said, &found.to_string()))
        }
    }
}

/// The kind when what was said and what was found can both be true.
fn agree(said: FileKind, found: FileKind) -> Option<FileKind> {
    use FileKind::{Image, MapYaml, Model};
    match (said, found) {
        _ if said == found => Some(found),
        (Image(_), Image(_)) => Some(found),
        // `.json` is any JSON; GeoJSON is JSON.
        (Model(ModelFormat::Json), Model(ModelFormat::GeoJson | ModelFormat::IndoorJson)) => {
            Some(found)
        }
        // YAML is a superset of JSON.
        (MapYaml, Model(ModelFormat::Json | ModelFormat::GeoJson | ModelFormat::IndoorJson)) => {
            Some(MapYaml)
        }
        _ => None,
    }
}

fn conflict(declared: &Declared<'_>, said: FileKind, found: &str) -> FormatError {
    let by = if declared.name.and_then(FileKind::by_extension).is_some() {
        "its name"
    } else {
        "its Content-Type"
    };
    FormatError::Conflict {
        path: PathBuf::from(declared.label()),
        said: format!("{by} says {said}"),
        found: found.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use FileKind::{Image, MapYaml, Model};
    use ImageFormat::{Pgm, Png};
    use ModelFormat::{GeoJson, IndoorGml, IndoorJson, Json};

    const PNG: &[u8] = b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR";
    const PGM: &[u8] = b"P5\n2 1\n255\n\xff\0";
    const GML: &[u8] = b"\xef\xbb\xbf<?xml version=\"1.0\"?><core:IndoorFeatures/>";
    const GEO: &[u8] = br#"{"features": [], "type": "FeatureCollection"}"#;
    const MODEL: &[u8] = br#"{"spaces": [{"type": "FeatureCollection"}], "connections": []}"#;
    const YAML: &[u8] = b"image: m.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n";
    const BROKEN_JSON: &[u8] = b"{\"spaces\": [";
    const IJ2: &[u8] = br#"{"type": "IndoorJSON2", "version": "0.1", "layers": {}}"#;

    /// (name, media type, field, bytes) → kind, or the error's start.
    #[test]
    fn detection_table() {
        type Row = (
            Option<&'static str>,
            Option<&'static str>,
            Option<&'static str>,
            &'static [u8],
            Result<FileKind, &'static str>,
        );
        let rows: &[Row] = &[
            // By extension, bytes agreeing.
            (Some("a.yaml"), None, None, YAML, Ok(MapYaml)),
            (Some("dir.v2/A.YML"), None, None, YAML, Ok(MapYaml)),
            (Some("a.pgm"), None, None, PGM, Ok(Image(Pgm))),
            (Some("a.png"), None, None, PNG, Ok(Image(Png))),
            (Some("a.gml"), None, None, GML, Ok(Model(IndoorGml))),
            (Some("a.xml"), None, None, GML, Ok(Model(IndoorGml))),
            (Some("a.json"), None, None, MODEL, Ok(Model(Json))),
            (Some("a.geojson"), None, None, GEO, Ok(Model(GeoJson))),
            (
                Some("b.Indoor.JSON"),
                None,
                None,
                IJ2,
                Ok(Model(IndoorJson)),
            ),
            (Some("b.json"), None, None, IJ2, Ok(Model(IndoorJson))),
            (None, None, None, IJ2, Ok(Model(IndoorJson))),
            (
                Some("b.indoor.json"),
                None,
                None,
                BROKEN_JSON,
                Ok(Model(IndoorJson)),
            ),
            (
                Some("b.indoor.json"),
                None,
                None,
                MODEL,
                Err(
                    "b.indoor.json: its name says IndoorJSON2 (IndoorGML 2.0 draft) but its content is model JSON",
                ),
            ),
            // By content alone (no or an unknown extension).
            (None, None, None, GML, Ok(Model(IndoorGml))),
            (Some("upload.txt"), None, None, GEO, Ok(Model(GeoJson))),
            (Some("model"), None, None, MODEL, Ok(Model(Json))),
            (None, None, None, PNG, Ok(Image(Png))),
            (None, None, None, b"P2\n1 1\n255\n0\n", Ok(Image(Pgm))),
            (None, None, None, YAML, Ok(MapYaml)),
            (None, None, None, BROKEN_JSON, Ok(Model(Json))),
            // By media type, then by field name.
            (
                None,
                Some("application/geo+json"),
                None,
                BROKEN_JSON,
                Ok(Model(GeoJson)),
            ),
            (
                None,
                Some("application/xml; charset=utf-8"),
                None,
                b"junk",
                Ok(Model(IndoorGml)),
            ),
            (
                None,
                Some("application/octet-stream"),
                Some("yaml"),
                b"junk",
                Ok(MapYaml),
            ),
            (None, None, Some("image"), PNG, Ok(Image(Png))),
            (None, None, Some("geojson"), BROKEN_JSON, Ok(Model(GeoJson))),
            (
                Some("a.gml"),
                Some("application/json"),
                None,
                GML,
                Ok(Model(IndoorGml)),
            ),
            // Same family: the bytes win.
            (Some("a.pgm"), None, None, PNG, Ok(Image(Png))),
            (Some("a.png"), None, None, PGM, Ok(Image(Pgm))),
            (Some("a.json"), None, None, GEO, Ok(Model(GeoJson))),
            (
                None,
                Some("application/json"),
                None,
                GEO,
                Ok(Model(GeoJson)),
            ),
            (
                Some("a.yaml"),
                None,
                None,
                br#"{"image": "m.pgm"}"#,
                Ok(MapYaml),
            ),
            (
                Some("a.geojson"),
                None,
                None,
                BROKEN_JSON,
                Ok(Model(GeoJson)),
            ),
            // Bytes that show nothing: the name stands, the reader judges.
            (Some("a.gml"), None, None, b"", Ok(Model(IndoorGml))),
            (Some("a.png"), None, None, b"GIF89a", Ok(Image(Png))),
            // Conflicts across families, and nothing to go by.
            (
                Some("a.json"),
                None,
                None,
                GML,
                Err("a.json: its name says model JSON but its content is IndoorGML"),
            ),
            (
                Some("a.gml"),
                None,
                None,
                PNG,
                Err("a.gml: its name says IndoorGML (XML) but its content is a PNG"),
            ),
            (
                Some("a.geojson"),
                None,
                None,
                MODEL,
                Err("a.geojson: its name says GeoJSON but its content is model JSON"),
            ),
            (
                Some("a.pgm"),
                None,
                None,
                YAML,
                Err("a.pgm: its name says a PGM image but its content is a map YAML"),
            ),
            (
                Some("a.yaml"),
                None,
                None,
                GML,
                Err("a.yaml: its name says a map YAML but"),
            ),
            (
                None,
                Some("application/xml"),
                None,
                GEO,
                Err("upload: its Content-Type says IndoorGML (XML) but its content is GeoJSON"),
            ),
            (
                Some("a.png"),
                None,
                None,
                BROKEN_JSON,
                Err("a.png: its name says a PNG image but its content is JSON"),
            ),
            (
                None,
                None,
                None,
                b"GIF89a",
                Err("upload: cannot tell the format"),
            ),
            (
                Some("notes.txt"),
                None,
                Some("comment"),
                b"hello",
                Err("notes.txt: cannot tell the format"),
            ),
        ];
        for (name, media_type, field, bytes, want) in rows {
            let declared = Declared {
                name: *name,
                media_type: *media_type,
                field: *field,
            };
            let got = detect(&declared, bytes);
            match (want, &got) {
                (Ok(k), Ok(g)) => assert_eq!(g, k, "{declared:?}"),
                (Err(start), Err(e)) => {
                    assert!(e.to_string().starts_with(start), "{declared:?}: {e}")
                }
                _ => panic!("{declared:?}: want {want:?}, got {got:?}"),
            }
        }
    }

    #[test]
    fn sniffing_never_panics_on_short_or_odd_bytes() {
        for bytes in [
            &b""[..],
            b"P",
            b"P5",
            b"\x89PNG",
            b"   ",
            b"{",
            b"\xef\xbb\xbf",
            b"\xff\xfe\xfd",
        ] {
            let _ = FileKind::sniff(bytes);
            let _ = detect(&Declared::default(), bytes);
        }
        let mut cut = b"image: ".to_vec();
        cut.extend(std::iter::repeat_n("é".as_bytes(), 3000).flatten());
        assert_eq!(FileKind::sniff(&cut), Some(MapYaml));
    }

    #[test]
    fn recordings_by_name_and_magic() {
        let mcap = b"\x89MCAP0\r\n\x01....";
        let sqlite = b"SQLite format 3\0....";
        let kind = |name: Option<&str>, bytes: &[u8]| {
            let declared = Declared {
                name,
                ..Declared::default()
            };
            detect(&declared, bytes).ok()
        };
        let rec = |f| Some(FileKind::Recording(f));
        assert_eq!(kind(Some("run.mcap"), mcap), rec(RecordingFormat::Mcap));
        assert_eq!(kind(None, mcap), rec(RecordingFormat::Mcap));
        assert_eq!(kind(Some("bag_0.db3"), sqlite), rec(RecordingFormat::Db3));
        // An SQLite file is a bag only by its name (nrgdb's database is one too).
        assert!(detect(&Declared::default(), sqlite).is_err());
        let err = detect(&Declared::name("m.json"), sqlite)
            .unwrap_err()
            .to_string();
        assert!(err.contains("an SQLite database"), "{err}");
        let err = detect(&Declared::name("m.gml"), mcap)
            .unwrap_err()
            .to_string();
        assert!(err.contains("MCAP"), "{err}");
    }
}
