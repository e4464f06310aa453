//! Query-string parameters: parsed strictly (an unknown or repeated
//! parameter is a 400 naming it), typed with errors that name the
//! parameter and say what would work.

use std::str::FromStr;

use axum::http::Uri;

use super::error::ApiError;

/// The parameters of one request.
#[derive(Debug, Clone, Default)]
pub struct Params {
    pairs: Vec<(String, String)>,
}

impl Params {
    /// Parses the query string of `uri`, refusing parameters not in `known`
    /// and parameters given twice.
    pub fn parse(uri: &Uri, known: &[&str]) -> Result<Params, ApiError> {
        let raw = uri.query().unwrap_or("");
        let pairs: Vec<(String, String)> = serde_urlencoded::from_str(raw)
            .map_err(|e| ApiError::bad("query string", e.to_string()))?;
        for (i, (k, _)) in pairs.iter().enumerate() {
            if !known.contains(&k.as_str()) {
                let hint = if known.is_empty() {
                    "this endpoint takes no parameters".to_string()
                } else {
                    format!("known parameters: {}", known.join(", "))
                };
                return Err(ApiError::bad(k, format!("unknown parameter ({hint})")));
            }
            if pairs[..i].iter().any(|(p, _)| p == k) {
                return Err(ApiError::bad(
                    k,
                    "given twice (give it once; lists are comma separated)",
                ));
            }
        }
        Ok(Params { pairs })
    }

    /// The raw value of `name`, if given.
    pub fn get(&self, name: &str) -> Option<&str> {
        self.pairs
            .iter()
            .find(|(k, _)| k == name)
            .map(|(_, v)| v.as_str())
    }

    /// The raw value of a required parameter.
    pub fn required(&self, name: &str) -> Result<&str, ApiError> {
        match self.get(name) {
            Some(v) if !v.trim().is_empty() => Ok(v),
            _ => Err(ApiError::bad(name, "missing (this parameter is required)")),
        }
    }

    /// A typed optional parameter; `what` describes valid values.
    pub fn opt<T: FromStr>(&self, name: &str, what: &str) -> Result<Option<T>, ApiError> {
        self.get(name)
            .map(|v| parse_value(name, v, what))
            .transpose()
    }

    /// A typed required parameter.
    pub fn req<T: FromStr>(&self, name: &str, what: &str) -> Result<T, ApiError> {
        parse_value(name, self.required(name)?, what)
    }

    /// The `rev` parameter: a revision number ≥ 1 or `latest` (`None`).
    pub fn rev(&self) -> Result<Option<u32>, ApiError> {
        self.get("rev")
            .map(|v| parse_rev("rev", v))
            .transpose()
            .map(Option::flatten)
    }
}

/// Parses `value` of parameter `name` as `T`.
pub fn parse_value<T: FromStr>(name: &str, value: &str, what: &str) -> Result<T, ApiError> {
    value
        .trim()
        .parse()
        .map_err(|_| ApiError::bad(name, format!("'{value}' is not {what}")))
}

/// A revision number ≥ 1, or `latest` (`None`).
pub fn parse_rev(name: &str, value: &str) -> Result<Option<u32>, ApiError> {
    if value.eq_ignore_ascii_case("latest") {
        return Ok(None);
    }
    match value.trim().parse::<u32>() {
        Ok(r) if r >= 1 => Ok(Some(r)),
        _ => Err(ApiError::bad(
            name,
            format!("'{value}' is not a revision (a number from 1, or 'latest')"),
        )),
    }
}

/// A finite number (metres).
pub fn parse_metres(name: &str, value: &str) -> Result<f64, ApiError> {
    match value.trim().parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(ApiError::bad(
            name,
            format!("'{value}' is not a finite number of metres"),
        )),
    }
}

/// A `level` parameter checked against the revision's levels: 404 naming
/// the levels it has, 400 on a map without levels.
pub fn level_param(
    raw: Option<&str>,
    rev: &crate::query::IndexedRevision,
) -> Result<Option<String>, ApiError> {
    let Some(raw) = raw.map(str::trim) else {
        return Ok(None);
    };
    let levels = rev.nrg.levels();
    if levels.is_empty() {
        return Err(ApiError::bad(
            "level",
            format!("map '{}' has no levels", rev.map),
        ));
    }
    if !levels.iter().any(|l| l.name == raw) {
        let names: Vec<&str> = levels.iter().map(|l| l.name.as_str()).collect();
        return Err(ApiError::not_found(
            "level",
            format!(
                "map '{}' has no level '{raw}' (it has {})",
                rev.map,
                names.join(", ")
            ),
        ));
    }
    Ok(Some(raw.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn uri(s: &str) -> Uri {
        s.parse().unwrap()
    }

    #[test]
    fn strict_and_typed() {
        let p = Params::parse(&uri("/x?depth=2&rev=latest"), &["depth", "rev"]).unwrap();
        assert_eq!(p.opt::<u32>("depth", "a number").unwrap(), Some(2));
        assert_eq!(p.rev().unwrap(), None);
        let e = Params::parse(&uri("/x?dpth=2"), &["depth"]).unwrap_err();
        assert_eq!(e.parameter(), Some("dpth"));
        let e = Params::parse(&uri("/x?depth=2&depth=3"), &["depth"]).unwrap_err();
        assert_eq!(e.parameter(), Some("depth"));
        let p = Params::parse(&uri("/x?depth=two&rev=0"), &["depth", "rev"]).unwrap();
        assert_eq!(
            p.opt::<u32>("depth", "a number").unwrap_err().parameter(),
            Some("depth")
        );
        assert_eq!(p.rev().unwrap_err().parameter(), Some("rev"));
        assert_eq!(p.required("from").unwrap_err().parameter(), Some("from"));
        assert!(parse_metres("x", "NaN").is_err());
    }
}
