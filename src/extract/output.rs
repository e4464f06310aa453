//! Serialised forms of an [`Extraction`]: the graph JSON with pixel
//! centroids and the 16-bit label PNG.

use image::{ImageBuffer, ImageFormat, Luma};

use super::Extraction;

impl Extraction {
    /// The model's JSON form with each space's `pixel_centroid` `[col, row]` added.
    pub fn to_json(&self) -> String {
        let mut v: serde_json::Value =
            serde_json::from_str(&self.nrg.to_json()).unwrap_or(serde_json::Value::Null);
        if let Some(spaces) = v.get_mut("spaces").and_then(|s| s.as_array_mut()) {
            for s in spaces {
                let id = s.get("id").and_then(serde_json::Value::as_u64);
                let c =
                    id.and_then(|id| self.pixel_centroids.get(&crate::model::SpaceId(id as u32)));
                if let (Some(obj), Some(c)) = (s.as_object_mut(), c) {
                    obj.insert("pixel_centroid".into(), serde_json::json!([c[0], c[1]]));
                }
            }
        }
        serde_json::to_string_pretty(&v).unwrap_or_default()
    }

    /// The label image as a 16-bit grey PNG: each pixel the id of its space, 0 elsewhere.
    pub fn labels_png(&self) -> Result<Vec<u8>, image::ImageError> {
        let data: Vec<u16> = self
            .labels
            .data
            .iter()
            .map(|&l| l.min(u32::from(u16::MAX)) as u16)
            .collect();
        let img: ImageBuffer<Luma<u16>, Vec<u16>> =
            ImageBuffer::from_raw(self.labels.width, self.labels.height, data).ok_or_else(
                || {
                    image::ImageError::Parameter(image::error::ParameterError::from_kind(
                        image::error::ParameterErrorKind::DimensionMismatch,
                    ))
                },
            )?;
        let mut bytes = std::io::Cursor::new(Vec::new());
        img.write_to(&mut bytes, ImageFormat::Png)?;
        Ok(bytes.into_inner())
    }
}
