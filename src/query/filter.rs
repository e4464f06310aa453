//! WHERE and ORDER BY: the value of a [`Field`] for a space, comparisons
//! and LIKE patterns.

use std::cmp::Ordering;

use super::ast::{CompareOp, Condition, Field, Value};
use super::error::QueryError;
use super::index::IndexedRevision;
use crate::model::{Space, doorway};

/// The value of `field` for `space` (`Null` when it has none).
pub fn field_value(field: &Field, space: &Space, rev: &IndexedRevision) -> Value {
    match field {
        Field::Id => Value::Number(space.id.0.into()),
        Field::Kind => Value::Text(space.kind.to_string()),
        Field::Name => Value::Text(space.label()),
        Field::Area => Value::Number(space.area_m2),
        Field::Degree => Value::Number(rev.graph.degree(space.id) as f64),
        Field::Width => doorway(space).map_or(Value::Null, |d| Value::Number(d.width_m)),
        Field::Level => space
            .level
            .as_ref()
            .map_or(Value::Null, |l| Value::Text(l.name.clone())),
        Field::Attr(key) => match space.attributes.get(key) {
            None | Some(serde_json::Value::Null) => Value::Null,
            Some(serde_json::Value::Bool(b)) => Value::Bool(*b),
            Some(serde_json::Value::Number(n)) => n.as_f64().map_or(Value::Null, Value::Number),
            Some(serde_json::Value::String(s)) => Value::Text(s.clone()),
            Some(other) => Value::Text(other.to_string()),
        },
    }
}

/// Whether `space` satisfies `cond`. Comparing a number field with text
/// (or the reverse) is an error; anything compared with a missing value is
/// false, except `= NULL` / `!= NULL`.
pub fn matches(cond: &Condition, space: &Space, rev: &IndexedRevision) -> Result<bool, QueryError> {
    Ok(match cond {
        Condition::And(a, b) => matches(a, space, rev)? && matches(b, space, rev)?,
        Condition::Or(a, b) => matches(a, space, rev)? || matches(b, space, rev)?,
        Condition::Not(a) => !matches(a, space, rev)?,
        Condition::Compare { field, op, value } => {
            let left = field_value(field, space, rev);
            compare(field, &left, *op, value)?
        }
    })
}

fn type_error(field: &Field, value: &Value, hint: &'static str) -> QueryError {
    QueryError::Type {
        field: field.to_string(),
        value: value.to_string(),
        hint,
    }
}

fn compare(field: &Field, left: &Value, op: CompareOp, right: &Value) -> Result<bool, QueryError> {
    use CompareOp::*;
    // Level names are text; `level = 1` means the level named "1".
    let as_name;
    let right = match (field, right) {
        (Field::Level, Value::Number(n)) if n.fract() == 0.0 && n.abs() < 1e15 => {
            as_name = Value::Text(format!("{}", *n as i64));
            &as_name
        }
        _ => right,
    };
    let fixed_numeric = matches!(
        field,
        Field::Id | Field::Area | Field::Degree | Field::Width
    );
    if fixed_numeric && matches!(right, Value::Text(_)) {
        return Err(type_error(field, right, "this field is a number"));
    }
    if matches!(field, Field::Kind | Field::Name) && matches!(right, Value::Number(_)) {
        return Err(type_error(
            field,
            right,
            "this field is text; quote the value",
        ));
    }
    if op == Like {
        let Value::Text(pattern) = right else {
            return Err(type_error(
                field,
                right,
                "LIKE takes a \"pattern\" with % and _",
            ));
        };
        // Matching is O(name × pattern) per row.
        let chars = pattern.chars().count();
        if chars > crate::model::MAX_NAME_CHARS {
            return Err(QueryError::PatternTooLong {
                chars,
                limit: crate::model::MAX_NAME_CHARS,
            });
        }
        return Ok(match left {
            Value::Text(s) => like(s, pattern),
            _ => false,
        });
    }
    match (left, right) {
        (Value::Null, Value::Null) => return Ok(op == Eq),
        (_, Value::Null) => return Ok(op == Ne),
        (Value::Null, _) => return Ok(false),
        _ => {}
    }
    let ordering = match (left, right) {
        (Value::Number(a), Value::Number(b)) => a.partial_cmp(b),
        (Value::Text(a), Value::Text(b)) => Some(a.to_lowercase().cmp(&b.to_lowercase())),
        (Value::Bool(a), Value::Bool(b)) => Some(a.cmp(b)),
        _ => None,
    };
    let Some(o) = ordering else {
        // Attributes of another type than the literal: not equal.
        return Ok(op == Ne);
    };
    Ok(match op {
        Eq => o == Ordering::Equal,
        Ne => o != Ordering::Equal,
        Lt => o == Ordering::Less,
        Le => o != Ordering::Greater,
        Gt => o == Ordering::Greater,
        Ge => o != Ordering::Less,
        Like => false,
    })
}

/// Orders values for ORDER BY: nulls last, numbers before text.
pub fn order_values(a: &Value, b: &Value) -> Ordering {
    let rank = |v: &Value| match v {
        Value::Number(_) => 0,
        Value::Bool(_) => 1,
        Value::Text(_) => 2,
        Value::Null => 3,
    };
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => x.total_cmp(y),
        (Value::Text(x), Value::Text(y)) => x.to_lowercase().cmp(&y.to_lowercase()),
        (Value::Bool(x), Value::Bool(y)) => x.cmp(y),
        _ => rank(a).cmp(&rank(b)),
    }
}

/// SQL-style LIKE, case-insensitive: `%` any run, `_` one character.
///
/// ```
/// use nrgdb::query::like;
/// assert!(like("Kitchen", "k%n"));
/// assert!(like("Room 12", "room __"));
/// assert!(!like("Kitchen", "%x%"));
/// ```
pub fn like(text: &str, pattern: &str) -> bool {
    let t: Vec<char> = text.to_lowercase().chars().collect();
    let p: Vec<char> = pattern.to_lowercase().chars().collect();
    // Classic two-pointer wildcard match with backtracking to the last '%'.
    let (mut i, mut j, mut star, mut mark) = (0, 0, None, 0);
    while i < t.len() {
        if j < p.len() && (p[j] == '_' || p[j] == t[i]) {
            i += 1;
            j += 1;
        } else if j < p.len() && p[j] == '%' {
            star = Some(j);
            mark = i;
            j += 1;
        } else if let Some(s) = star {
            j = s + 1;
            mark += 1;
            i = mark;
        } else {
            return false;
        }
    }
    p[j..].iter().all(|c| *c == '%')
}

/// The spaces of `rev` for which `cond` holds, in id order, leaving out
/// `except` (a route's own ends for `AVOID WHERE`).
pub fn matching_spaces(
    cond: &Condition,
    rev: &IndexedRevision,
    except: &[crate::model::SpaceId],
) -> Result<Vec<crate::model::SpaceId>, QueryError> {
    let mut out = Vec::new();
    for s in rev.nrg.spaces() {
        if !except.contains(&s.id) && matches(cond, s, rev)? {
            out.push(s.id);
        }
    }
    Ok(out)
}
