//! The ROS map_server YAML file.

use std::path::{Path, PathBuf};

use serde::Deserialize;

use super::GridError;

/// How map_server interprets pixel values (`mode:` in the YAML).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum MapMode {
    /// Free, occupied or unknown by thresholds (the default).
    #[default]
    Trinary,
    /// Like trinary, with intermediate occupancies kept (treated as unknown here).
    Scale,
    /// Pixel value = occupancy 0..100, anything else unknown.
    Raw,
}

/// A parsed and validated map YAML.
#[derive(Debug, Clone, PartialEq)]
pub struct MapYaml {
    /// The image path, resolved against the YAML's directory.
    pub image: PathBuf,
    /// Metres per pixel (> 0).
    pub resolution: f64,
    /// Map-frame pose `[x, y, yaw]` of the lower-left pixel's corner.
    pub origin: [f64; 3],
    /// Whether white means occupied.
    pub negate: bool,
    /// Occupancy probability above which a cell is occupied.
    pub occupied_thresh: f64,
    /// Occupancy probability below which ROS calls a cell free.
    pub free_thresh: f64,
    /// Pixel interpretation.
    pub mode: MapMode,
}

#[derive(Deserialize)]
struct RawYaml {
    image: Option<String>,
    resolution: Option<f64>,
    origin: Option<Vec<f64>>,
    negate: Option<serde_yaml_ng::Value>,
    occupied_thresh: Option<f64>,
    free_thresh: Option<f64>,
    mode: Option<String>,
}

/// Deepest `[`/`{` nesting accepted in a map YAML.
const MAX_FLOW_DEPTH: usize = 16;

/// The deepest nesting of flow brackets in `text`, outside quotes and
/// comments (stops counting past [`MAX_FLOW_DEPTH`]).
fn flow_depth(text: &str) -> usize {
    let (mut depth, mut deepest) = (0usize, 0usize);
    let mut quote: Option<char> = None;
    let mut comment = false;
    for c in text.chars() {
        match (quote, c) {
            _ if comment => comment = c != '\n',
            (Some(q), c) if c == q => quote = None,
            (Some(_), _) => {}
            (None, '\'' | '"') => quote = Some(c),
            (None, '#') => comment = true,
            (None, '[' | '{') => {
                depth += 1;
                deepest = deepest.max(depth);
                if deepest > MAX_FLOW_DEPTH {
                    break;
                }
            }
            (None, ']' | '}') => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    deepest
}

impl MapYaml {
    /// Reads and validates a map YAML file (at most
    /// [`MAX_YAML_BYTES`](super::MAX_YAML_BYTES)).
    pub fn read(path: &Path) -> Result<MapYaml, GridError> {
        let io = |source| GridError::Io {
            path: path.to_path_buf(),
            source,
        };
        let size = std::fs::metadata(path).map_err(io)?.len();
        if size > super::MAX_YAML_BYTES {
            return Err(GridError::YamlTooLarge {
                path: path.to_path_buf(),
                size,
                limit: super::MAX_YAML_BYTES,
            });
        }
        let text = std::fs::read_to_string(path).map_err(io)?;
        MapYaml::parse(&text, path)
    }

    /// Parses YAML text; `path` names the file in errors and resolves `image`.
    pub fn parse(text: &str, path: &Path) -> Result<MapYaml, GridError> {
        let p = || path.to_path_buf();
        // The YAML parser's time grows steeply with flow nesting (100 000
        // brackets took 30 s; issue 21, defect 8); a map YAML has one level.
        let depth = flow_depth(text);
        if depth > MAX_FLOW_DEPTH {
            return Err(GridError::Yaml {
                path: p(),
                message: format!(
                    "brackets nested {depth} deep, more than {MAX_FLOW_DEPTH} (a map yaml has one list: origin)"
                ),
            });
        }
        let raw: RawYaml = serde_yaml_ng::from_str(text).map_err(|e| GridError::Yaml {
            path: p(),
            message: e.to_string(),
        })?;
        let image = raw.image.ok_or(GridError::MissingField {
            path: p(),
            field: "image",
        })?;
        let resolution = raw.resolution.ok_or(GridError::MissingField {
            path: p(),
            field: "resolution",
        })?;
        if !(resolution.is_finite() && resolution > 0.0) {
            return Err(GridError::BadField {
                path: p(),
                field: "resolution",
                value: resolution.to_string(),
                hint: "must be a finite number of metres per pixel > 0",
            });
        }
        let origin = raw.origin.ok_or(GridError::MissingField {
            path: p(),
            field: "origin",
        })?;
        if origin.len() != 3 || origin.iter().any(|v| !v.is_finite()) {
            return Err(GridError::BadField {
                path: p(),
                field: "origin",
                value: format!("{origin:?}"),
                hint: "must be three finite numbers [x, y, yaw]",
            });
        }
        let negate = match raw.negate {
            None => false,
            Some(serde_yaml_ng::Value::Bool(b)) => b,
            Some(serde_yaml_ng::Value::Number(n)) if n.as_i64() == Some(0) => false,
            Some(serde_yaml_ng::Value::Number(n)) if n.as_i64() == Some(1) => true,
            Some(other) => {
                return Err(GridError::BadField {
                    path: p(),
                    field: "negate",
                    value: format!("{other:?}"),
                    hint: "must be 0 or 1",
                });
            }
        };
        let occupied_thresh = raw.occupied_thresh.unwrap_or(0.65);
        let free_thresh = raw.free_thresh.unwrap_or(0.196);
        for (field, v) in [
            ("occupied_thresh", occupied_thresh),
            ("free_thresh", free_thresh),
        ] {
            if !(0.0..=1.0).contains(&v) {
                return Err(GridError::BadField {
                    path: p(),
                    field,
                    value: v.to_string(),
                    hint: "must be a probability in [0, 1]",
                });
            }
        }
        let mode = match raw.mode.as_deref() {
            None | Some("trinary") => MapMode::Trinary,
            Some("scale") => MapMode::Scale,
            Some("raw") => MapMode::Raw,
            Some(other) => {
                return Err(GridError::BadField {
                    path: p(),
                    field: "mode",
                    value: other.to_string(),
                    hint: "must be trinary, scale or raw",
                });
            }
        };
        let image_path = Path::new(&image);
        let image = if image_path.is_absolute() {
            image_path.to_path_buf()
        } else {
            path.parent().unwrap_or(Path::new("")).join(image_path)
        };
        Ok(MapYaml {
            image,
            resolution,
            origin: [origin[0], origin[1], origin[2]],
            negate,
            occupied_thresh,
            free_thresh,
            mode,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn issue_21_defect_8_deeply_nested_yaml_is_refused_at_once() {
        let text = format!(
            "image: a.pgm\nfoo: {}{}\n",
            "[".repeat(100_000),
            "]".repeat(100_000)
        );
        let e = MapYaml::parse(&text, Path::new("deep.yaml"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("deep.yaml") && e.contains("nested"), "{e}");
        // Brackets in quotes and comments are text.
        let ok = "image: '[[[[[[[[[[[[[[[[[[[[.pgm'\nresolution: 0.05 # [[[[[[[[[[[[[[[[[[[[\norigin: [0, 0, 0]\n";
        assert!(MapYaml::parse(ok, Path::new("ok.yaml")).is_ok());
    }

    #[test]
    fn parses_a_ros_yaml() {
        let y = MapYaml::parse(
            "image: m.pgm\nresolution: 0.05\norigin: [-1.0, 2.0, 0.0]\nnegate: 0\nmode: raw\n",
            Path::new("/maps/m.yaml"),
        )
        .unwrap();
        assert_eq!(y.image, Path::new("/maps/m.pgm"));
        assert_eq!(y.origin, [-1.0, 2.0, 0.0]);
        assert_eq!(y.mode, MapMode::Raw);
        assert!(!y.negate);
    }

    #[test]
    fn names_missing_and_bad_fields() {
        let e = MapYaml::parse("image: m.pgm\norigin: [0,0,0]\n", Path::new("a.yaml")).unwrap_err();
        assert!(e.to_string().contains("`resolution`"), "{e}");
        let e = MapYaml::parse(
            "image: m.pgm\nresolution: 0\norigin: [0,0,0]\n",
            Path::new("a.yaml"),
        )
        .unwrap_err();
        assert!(e.to_string().contains("a.yaml: field `resolution`"), "{e}");
        let e = MapYaml::parse(
            "image: m.pgm\nresolution: 0.1\norigin: [0,0]\n",
            Path::new("a.yaml"),
        )
        .unwrap_err();
        assert!(e.to_string().contains("`origin`"), "{e}");
    }
}
